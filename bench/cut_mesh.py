#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/cut_mesh.py IN.obj OUT.obj

Drops the triangles whose centre lies below the middle of the mesh's z range, so that a camera
looking along the z axis from below (pcl_viewer's, reset) sees into it: inner shells, walls and
voids."""
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    vertices, faces = [], []
    with open(sys.argv[1]) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                vertices.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                faces.append([int(x.split("/")[0]) for x in w[1:]])
    z = [v[2] for v in vertices]
    middle = (min(z) + max(z)) / 2
    with open(sys.argv[2], "w") as out:
        for v in vertices:
            out.write("v %r %r %r\n" % v)
        for face in faces:
            if sum(vertices[i - 1][2] for i in face) / len(face) >= middle:
                out.write("f %s\n" % " ".join(map(str, face)))


if __name__ == "__main__":
    main()
