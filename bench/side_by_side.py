#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/side_by_side.py OUT.png IMAGE:CAPTION...

Puts the pictures in a row, each cropped to what is drawn on it, scaled to one height and
captioned below: one picture to compare surfaces by."""
import sys

from PIL import Image, ImageChops, ImageDraw

HEIGHT = 320


def cropped(path):
    image = Image.open(path).convert("RGB")
    # The background is the top-left pixel's colour; keep the box of everything else.
    background = Image.new("RGB", image.size, image.getpixel((0, 0)))
    box = ImageChops.difference(image, background).getbbox() or (0, 0) + image.size
    image = image.crop(box)
    return image.resize((max(1, image.width * HEIGHT // image.height), HEIGHT))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    pictures = [(cropped(a.split(":", 1)[0]), a.split(":", 1)[1]) for a in sys.argv[2:]]
    pad, caption = 16, 24
    width = sum(p.width for p, _ in pictures) + pad * (len(pictures) + 1)
    sheet = Image.new("RGB", (width, HEIGHT + caption + 2 * pad), pictures[0][0].getpixel((0, 0)))
    draw = ImageDraw.Draw(sheet)
    x = pad
    for picture, text in pictures:
        sheet.paste(picture, (x, pad))
        draw.text((x, HEIGHT + pad + 6), text, fill=(255, 255, 255))
        x += picture.width + pad
    sheet.save(sys.argv[1], optimize=True)


if __name__ == "__main__":
    main()
