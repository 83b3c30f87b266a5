#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/corpus.py OUT_DIR [--quick]

Writes a corpus of point clouds whose right answer is known, one .xyz file per case, and
OUT_DIR/manifest.json: per case its class, the expected number of components and total genus of
the surface, and the median spacing of its points. The classes are what a surface through the
points must get right: inner voids (a hollow ball keeps its inner shell), lost parts (coarse
objects side by side), holes (a plate with five bores, a thick torus, a mug, a thin-walled cup,
a coupling, a helmet), bridges (linked rings, a chain, thin cylinders a few spacings apart),
separate objects, noise (0.25, 0.5 and 1 times the spacing, and uneven density), the closed
development meshes of Debian's libcgal-demo resampled (with and without noise) and degenerate
data (outliers). Fixed seeds: the same files every time, each case drawn from its own seed.
--quick leaves out the largest clouds.
"""
import json
import sys
import zlib

import numpy as np

rng = np.random.default_rng(2026)


def unit(v):
    return v / np.linalg.norm(v, axis=1)[:, None]


def sphere(n, r=1.0, c=(0, 0, 0)):
    return np.asarray(c, float) + r * unit(rng.normal(size=(n, 3)))


def torus(n, R=1.0, r=0.3, c=(0, 0, 0), axis=2):
    """Uniform by area: the angle around the tube is drawn with density (R + r cos v)."""
    u = rng.uniform(0, 2 * np.pi, n)
    v = np.empty(0)
    while v.size < n:
        cand = rng.uniform(0, 2 * np.pi, 2 * n)
        keep = rng.uniform(0, R + r, 2 * n) < R + r * np.cos(cand)
        v = np.r_[v, cand[keep]]
    v = v[:n]
    p = np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]
    p = np.roll(p, axis - 2, axis=1)
    return np.asarray(c, float) + p


def capped_cylinder(n, r, h, c=(0, 0, 0)):
    """A closed cylinder along z: side and both caps, uniform by area."""
    side, cap = 2 * np.pi * r * h, np.pi * r * r
    k = rng.choice(3, size=n, p=np.array([side, cap, cap]) / (side + 2 * cap))
    t = rng.uniform(0, 2 * np.pi, n)
    rad = np.where(k == 0, r, r * np.sqrt(rng.uniform(0, 1, n)))
    z = np.where(k == 0, rng.uniform(-h / 2, h / 2, n), np.where(k == 1, -h / 2, h / 2))
    return np.asarray(c, float) + np.c_[rad * np.cos(t), rad * np.sin(t), z]


def plate_with_holes(n, size=(4.0, 2.0, 0.3), holes=5, hole_r=0.22):
    """A box plate with `holes` round bores through its thickness, in a row: genus `holes`. Its
    faces outside the bores and the bores' walls are sampled uniformly by area."""
    a, b, t = size
    centres = [(-a / 2 + a * (i + 1) / (holes + 1), 0.0) for i in range(holes)]

    def box_faces(k):
        out = []
        while sum(len(o) for o in out) < k:
            m = 2 * k
            x, y, z = rng.uniform(-a / 2, a / 2, m), rng.uniform(-b / 2, b / 2, m), rng.uniform(-t / 2, t / 2, m)
            f = rng.choice(6, size=m, p=np.array([a * b, a * b, a * t, a * t, b * t, b * t]) / (2 * a * b + 2 * (a + b) * t))
            z = np.where(f == 0, t / 2, np.where(f == 1, -t / 2, z))
            y = np.where(f == 2, b / 2, np.where(f == 3, -b / 2, y))
            x = np.where(f == 4, a / 2, np.where(f == 5, -a / 2, x))
            in_bore = np.zeros(m, bool)
            for cx, cy in centres:
                in_bore |= (f < 2) & ((x - cx) ** 2 + (y - cy) ** 2 < hole_r ** 2)
            out.append(np.c_[x, y, z][~in_bore])
        return np.concatenate(out)[:k]

    def bore_walls(k):
        which = rng.integers(holes, size=k)
        return tube(k, hole_r, -t / 2, t / 2) + np.c_[np.array(centres)[which], np.zeros(k)]

    faces = 2 * (a * b - holes * np.pi * hole_r ** 2) + 2 * (a + b) * t
    return area_sample([(faces, box_faces), (holes * 2 * np.pi * hole_r * t, bore_walls)], n)


def area_sample(parts, n):
    """n points over surface pieces [(area, sampler(k) -> (k, 3))], in proportion to their areas."""
    areas = np.array([a for a, _ in parts])
    counts = rng.multinomial(n, areas / areas.sum())
    return np.concatenate([f(k) for (_, f), k in zip(parts, counts) if k > 0])


def disk(k, r0, r1, z):
    t, rad = rng.uniform(0, 2 * np.pi, k), np.sqrt(rng.uniform(r0 * r0, r1 * r1, k))
    return np.c_[rad * np.cos(t), rad * np.sin(t), np.full(k, z)]


def tube(k, r, z0, z1):
    t = rng.uniform(0, 2 * np.pi, k)
    return np.c_[r * np.cos(t), r * np.sin(t), rng.uniform(z0, z1, k)]


def cup(n, wall, height=2.0, r=1.0):
    """An open cup of radius r with walls and bottom `wall` thick: a solid of genus 0."""
    q = r - wall
    return area_sample([(2 * np.pi * r * height, lambda k: tube(k, r, 0, height)),
                        (np.pi * r * r, lambda k: disk(k, 0, r, 0)),
                        (2 * np.pi * q * (height - wall), lambda k: tube(k, q, wall, height)),
                        (np.pi * q * q, lambda k: disk(k, 0, q, wall)),
                        (np.pi * (r * r - q * q), lambda k: disk(k, q, r, height))], n)


def coupling(n, radius=2.0, thickness=0.5, bore=0.5, holes=8, hole_r=0.25, ring=1.25):
    """A flange coupling: a disc `thickness` thick with a central bore and `holes` round holes on a
    ring around it: genus holes + 1. Its faces outside the holes, its rim and the holes' walls are
    sampled uniformly by area."""
    centres = np.array([(ring * np.cos(a), ring * np.sin(a)) for a in 2 * np.pi * np.arange(holes) / holes])
    h = thickness / 2

    def faces(k):
        out = []
        while sum(len(o) for o in out) < k:
            p = disk(2 * k, bore, radius, h)
            p[:, 2] *= np.where(rng.uniform(size=2 * k) < 0.5, -1, 1)
            in_hole = ((p[:, None, :2] - centres[None]) ** 2).sum(2).min(1) < hole_r ** 2
            out.append(p[~in_hole])
        return np.concatenate(out)[:k]

    def hole_walls(k):
        return tube(k, hole_r, -h, h) + np.c_[centres[rng.integers(holes, size=k)], np.zeros(k)]

    face_area = 2 * np.pi * (radius ** 2 - bore ** 2 - holes * hole_r ** 2)
    return area_sample([(face_area, faces), (2 * np.pi * radius * thickness, lambda k: tube(k, radius, -h, h)),
                        (2 * np.pi * bore * thickness, lambda k: tube(k, bore, -h, h)),
                        (holes * 2 * np.pi * hole_r * thickness, hole_walls)], n)


def helmet(n, outer=1.0, inner=0.9, hole_r=0.15, axes=((0.6, 0, 0.8), (-0.6, 0, 0.8), (0, 0.7, 0.71))):
    """A thick hemispherical shell (z >= 0) with round holes through it along `axes`: a solid of
    genus len(axes). Both spheres outside the holes, the rim and the holes' walls are sampled
    uniformly by area."""
    axes = unit(np.array(axes, float))

    def in_hole(p):
        along = p @ axes.T  # (k, holes)
        across = np.linalg.norm(p[:, None, :] - along[:, :, None] * axes[None], axis=2)
        return ((along > 0) & (across < hole_r)).any(1)

    def cap(r):
        def draw(k):
            out = []
            while sum(len(o) for o in out) < k:
                p = unit(rng.normal(size=(3 * k, 3)))
                p[:, 2] = np.abs(p[:, 2])
                out.append(r * p[~in_hole(r * p)])
            return np.concatenate(out)[:k]
        return draw

    def hole_walls(k):
        out = []
        while sum(len(o) for o in out) < k:
            a = axes[rng.integers(len(axes), size=3 * k)]
            u = unit(np.cross(a, [1.0, 0.0, 0.0]))
            v = np.cross(a, u)
            t = rng.uniform(0, 2 * np.pi, 3 * k)[:, None]
            p = rng.uniform(0.8 * inner, outer, 3 * k)[:, None] * a + hole_r * (np.cos(t) * u + np.sin(t) * v)
            r = np.linalg.norm(p, axis=1)
            out.append(p[(r >= inner) & (r <= outer)])
        return np.concatenate(out)[:k]

    return area_sample([(2 * np.pi * outer ** 2, cap(outer)), (2 * np.pi * inner ** 2, cap(inner)),
                        (np.pi * (outer ** 2 - inner ** 2), lambda k: disk(k, inner, outer, 0.0)),
                        (len(axes) * 2 * np.pi * hole_r * (outer - inner), hole_walls)], n)


def mug(n, handle_x=1.45):
    """A thick cup with a handle: a torus in the xz plane, centred handle_x from the axis, whose
    ends sink into the cup's wall (at 1.45 the tube reaches 0.9 from the axis, the wall is 0.85 to
    1, and the handle's axis meets the wall's outside at a grazing angle; at 1.15 it meets it at
    about 70 degrees): its points inside the wall and the wall's inside the tube left out. Genus 1."""
    body = cup(int(0.8 * n), 0.15)
    body = body[~(((np.hypot(body[:, 0] - handle_x, body[:, 2] - 1.0) - 0.45) ** 2 + body[:, 1] ** 2 < 0.1 ** 2))]
    handle = torus(n - len(body), 0.45, 0.1, c=(handle_x, 0, 1.0), axis=1)
    handle = handle[np.hypot(handle[:, 0], handle[:, 1]) > 1.0]
    return np.r_[body, handle]


def median_spacing(p):
    from scipy.spatial import cKDTree

    d, _ = cKDTree(p).query(p, k=2)
    return float(np.median(d[:, 1]))


def noisy(p, sigma):
    return p + sigma * rng.normal(size=p.shape)


CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"  # Debian's libcgal-demo
# Closed development meshes of that archive (the others are held back for evaluation).
DEVELOPMENT_MESHES = ("knot1", "anchor_dense", "blobby", "dino", "fandisk", "triceratops", "bunny00")


def read_off(text):
    """Vertices and triangles (polygons split into fans) of an OFF file's text."""
    words = [line.split("#")[0].split() for line in text.splitlines()]
    words = [w for w in words if w]
    if words[0][0] == "OFF" and len(words[0]) > 1:
        words[0:1] = [["OFF"], words[0][1:]]
    nv, nf = int(words[1][0]), int(words[1][1])
    vertices = np.array([[float(x) for x in w[:3]] for w in words[2:2 + nv]])
    triangles = []
    for w in words[2 + nv:2 + nv + nf]:
        k = int(w[0])
        corners = [int(x) for x in w[1:1 + k]]
        triangles += [(corners[0], corners[i], corners[i + 1]) for i in range(1, k - 1)]
    return vertices, np.array(triangles)


def on_mesh(vertices, triangles, n):
    """n points uniformly by area on a triangle mesh."""
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    pick = rng.choice(len(triangles), size=n, p=area / area.sum())
    u, v = rng.uniform(size=(2, n))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    return a[pick] + u[:, None] * (b - a)[pick] + v[:, None] * (c - a)[pick]


def genus_of(vertices, triangles):
    """The genus of a closed connected triangle mesh, from its Euler characteristic."""
    edges = np.unique(np.sort(np.r_[triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]], axis=1), axis=0)
    used = len(np.unique(triangles))
    return (2 - (used - len(edges) + len(triangles))) // 2


def development_meshes():
    """(name, vertices, triangles) of the development meshes, when the archive is installed."""
    import os
    import tarfile

    if not os.path.exists(CGAL_DATA):
        print("corpus.py: no %s (libcgal-demo): no resampled meshes" % CGAL_DATA, file=sys.stderr)
        return []
    out = []
    with tarfile.open(CGAL_DATA) as archive:
        for name in DEVELOPMENT_MESHES:
            text = archive.extractfile("data/meshes/%s.off" % name).read().decode()
            out.append((name,) + read_off(text))
    return out


def cases(quick):
    """(class, name, make, components, genus): make() draws the points after the generator is
    seeded from the name, so that each case is the same whatever the others are."""
    c = []
    # inner voids: nested spheres keep both shells; a solid ball's sample has none
    c.append(("voids", "hollow_ball", lambda: np.r_[sphere(6000), sphere(2500, 0.6)], 2, 0))
    c.append(("voids", "three_nested", lambda: np.r_[sphere(6000), sphere(3000, 0.7), sphere(1200, 0.4)], 3, 0))
    # lost parts: coarse objects side by side
    c.append(("parts", "two_coarse_tori", lambda: np.r_[torus(400, 1, 0.35), torus(400, 1, 0.35, c=(3.0, 0, 0))],
              2, 2))
    c.append(("parts", "coarse_sphere_and_torus", lambda: np.r_[sphere(300), torus(500, 1, 0.35, c=(2.6, 0, 0))],
              2, 1))
    # holes and tunnels wider than a few spacings stay open
    c.append(("holes", "plate_five_holes", lambda: plate_with_holes(12000), 1, 5))
    c.append(("holes", "thick_torus", lambda: torus(3000, 1, 0.6), 1, 1))
    c.append(("holes", "mug", lambda: mug(15000), 1, 1))
    c.append(("holes", "thin_walled_cup", lambda: cup(15000, 0.06), 1, 0))
    # a coupling's bore and eight holes (0.5 across: 7 spacings at 1,500 points, whose holes' walls
    # have about 34 points each), a helmet's three holes through a wall 6 spacings thick
    c.append(("holes", "coupling", lambda: coupling(10000), 1, 9))
    c.append(("holes", "coupling_coarse", lambda: coupling(1500), 1, 9))
    c.append(("holes", "helmet_three_holes", lambda: helmet(10000), 1, 3))
    # bridges: linked rings (a chain: each linked with the next), thin cylinders a few spacings
    # apart (radius 0.15, spacing about 0.016: gaps of 2.5 spacings)
    c.append(("bridges", "three_linked_rings",
              lambda: np.r_[torus(2500, 1, 0.15), torus(2500, 1, 0.15, c=(1.2, 0, 0), axis=1),
                            torus(2500, 1, 0.15, c=(2.4, 0, 0))], 3, 3))
    # a chain of five rings (tubes 0.26 apart where they link: 10 spacings, and 4 at 1,500 points)
    for n in (10000, 1500):
        c.append(("bridges", "chain_of_five_rings" + ("" if n == 10000 else "_coarse"),
                  lambda n=n: np.concatenate([torus(n // 5, 1, 0.12, c=(1.5 * i, 0, 0), axis=2 - i % 2)
                                              for i in range(5)]), 5, 5))
    c.append(("bridges", "four_thin_cylinders",
              lambda: np.concatenate([capped_cylinder(2500, 0.15, 3.0, c=(0.34 * i, 0, 0)) for i in range(4)]), 4, 0))
    # separate objects stay separate
    for gap in (0.5, 2.0):
        c.append(("separate", "two_spheres_gap_%g" % gap,
                  lambda gap=gap: np.r_[sphere(5000), sphere(5000, c=(2 + gap, 0, 0))], 2, 0))
    c.append(("separate", "three_spheres_row",
              lambda: np.r_[sphere(3000), sphere(3000, c=(2.5, 0, 0)), sphere(3000, c=(5.0, 0, 0))], 3, 0))
    c.append(("separate", "nine_spheres_grid",
              lambda: np.concatenate([sphere(1111, c=(2.3 * i, 2.3 * j, 0)) for i in range(3) for j in range(3)]), 9, 0))
    c.append(("separate", "sphere_beside_torus", lambda: np.r_[sphere(4000), torus(5000, 1, 0.35, c=(3.0, 0, 0))],
              2, 1))

    # uneven density: one half of a sphere sampled ten times as densely as the other
    def uneven():
        s = sphere(20000)
        return np.r_[s[s[:, 0] > 0], s[s[:, 0] <= 0][::10]]

    c.append(("noise", "sphere_uneven_density", uneven, 1, 0))

    # noise of 0.25, 0.5 and 1 times the spacing
    def noisy_shape(shape, n, k):
        p = sphere(n) if shape == "sphere" else torus(n, 1, 0.4)
        return noisy(p, k * median_spacing(p))

    for n in (10000,) if quick else (10000, 100000):
        for shape, genus in (("sphere", 0), ("torus", 1)):
            for k in (0.25, 0.5, 1.0):
                c.append(("noise", "%s_%dk_noise_%g" % (shape, n // 1000, k),
                          lambda shape=shape, n=n, k=k: noisy_shape(shape, n, k), 1, genus))
    # the development meshes resampled: 20,000 points by area, without noise and with noise of
    # half the spacing
    for name, vertices, triangles in development_meshes():
        genus = genus_of(vertices, triangles)

        def resampled(vertices=vertices, triangles=triangles, k=0.0):
            p = on_mesh(vertices, triangles, 20000)
            return noisy(p, k * median_spacing(p)) if k else p

        c.append(("resampled", "%s_20k" % name, resampled, 1, genus))
        c.append(("resampled", "%s_20k_noise_0.5" % name,
                  lambda vertices=vertices, triangles=triangles: resampled(vertices, triangles, 0.5), 1, genus))
    # degenerate data: a far outlier stays out of the surface's shape
    c.append(("degenerate", "sphere_and_far_outlier", lambda: np.r_[sphere(3000), [[1e3, 0, 0]]], 1, 0))
    c.append(("degenerate", "sphere_and_five_outliers",
              lambda: np.r_[sphere(5000), 3 * unit(rng.normal(size=(5, 3)))], 1, 0))
    return c


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    quick = "--quick" in sys.argv[2:]
    import os

    os.makedirs(out, exist_ok=True)
    manifest = []
    global rng
    for klass, name, make, components, genus in cases(quick):
        rng = np.random.default_rng(zlib.crc32(name.encode()))
        points = make()
        np.savetxt("%s/%s.xyz" % (out, name), points, fmt="%.9g")
        manifest.append({"class": klass, "name": name, "points": len(points), "components": components,
                         "genus": genus, "spacing": median_spacing(points)})
    with open("%s/manifest.json" % out, "w") as f:
        json.dump(manifest, f, indent=1)


if __name__ == "__main__":
    main()
