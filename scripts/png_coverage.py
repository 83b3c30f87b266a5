#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: png_coverage.py IMAGE.png [MIN_SHARE]

Prints the share of pixels that differ from the image's corner colour (the background), and
exits 1 when it is below MIN_SHARE: a check that a rendering is not blank. Standard library only:
decodes 8-bit RGB/RGBA PNGs (what VTK and pcl_viewer write)."""
import struct
import sys
import zlib


def pixels(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"{path}: only 8-bit RGB/RGBA, non-interlaced")
    step = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * step
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - step] if i >= step else 0
            b = previous[i]
            c = previous[i - step] if i >= step else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, step, rows


def main():
    path, minimum = sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
    width, height, step, rows = pixels(path)
    background = rows[0][:3]
    differing = sum(1 for row in rows for x in range(width) if row[x * step:x * step + 3] != background)
    share = differing / (width * height)
    print(f"{path}: {width}x{height}, {100 * share:.1f}% of pixels not background")
    sys.exit(0 if share >= minimum else 1)


if __name__ == "__main__":
    main()
