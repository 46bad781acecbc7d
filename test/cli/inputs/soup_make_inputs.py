#!/usr/bin/env python3
"""Writes the soup_*.off inputs of test/cli/cases_soups.txt: surfaces that are not oriented manifold meshes, used
as given by `mdcs geodesics`, and the oracles' meshes. Run it from anywhere; it writes next to itself.

  soup_moebius.off        a Moebius strip (24 x 2 quads, reversed gluing across the seam)
  soup_moebius_cover.off  its orientable double cover: the same triangles twice, the second sheet's vertices
                          numbered after the first (vertex k of the strip is vertex k of the cover, its other lift
                          is vertex k + 72), orientations chosen so that the cover is an oriented manifold mesh
  soup_fan3.off           three flat 1 x 1 sheets (2 x 2 quads each) sharing the edge x = y = 0, 0 <= z <= 1, at
                          angles 0, 100 and 220 degrees around the z axis; the third sheet oriented against the others
  soup_pinched.off        two open cones (6 sides, base radius 0.5 at z = -1 and z = +1) touching at their apex
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write_off(name, points, triangles):
    with open(os.path.join(HERE, name), "w", encoding="utf-8") as f:
        f.write(f"OFF\n{len(points)} {len(triangles)} 0\n")
        for p in points:
            f.write(" ".join(repr(float(c)) for c in p) + "\n")
        for t in triangles:
            f.write("3 " + " ".join(str(i) for i in t) + "\n")


def check_oriented_manifold(triangles):
    directed = set()
    for t in triangles:
        for k in range(3):
            e = (t[k], t[(k + 1) % 3])
            assert e not in directed, f"directed edge {e} twice"
            directed.add(e)


def moebius():
    nu, nv, width = 24, 3, 0.4
    points = []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            v = width * (2 * j / (nv - 1) - 1)
            r = 1 + v * math.cos(u / 2)
            points.append((r * math.cos(u), r * math.sin(u), v * math.sin(u / 2)))
    # Triangles by (column, row) corners; column nu is column 0 with the rows reversed (the twist).
    grid = []
    for i in range(nu):
        for j in range(nv - 1):
            grid.append([(i, j), (i + 1, j), (i + 1, j + 1)])
            grid.append([(i, j), (i + 1, j + 1), (i, j + 1)])

    def strip_index(c, j):
        return (0 * nv + (nv - 1 - j)) if c == nu else c * nv + j

    strip = [[strip_index(c, j) for c, j in t] for t in grid]
    # The double cover: sheet s of each triangle; a corner on column nu changes sheet; sheet 1 reversed.
    n = nu * nv

    def cover_index(c, j, sheet):
        if c == nu:
            c, j, sheet = 0, nv - 1 - j, 1 - sheet
        return sheet * n + c * nv + j

    cover = []
    for sheet in (0, 1):
        for t in grid:
            tri = [cover_index(c, j, sheet) for c, j in t]
            cover.append(tri if sheet == 0 else tri[::-1])
    check_oriented_manifold(cover)
    write_off("soup_moebius.off", points, strip)
    write_off("soup_moebius_cover.off", points + points, cover)


def fan():
    angles = (0.0, 100.0, 220.0)
    points = [(0.0, 0.0, 0.5 * k) for k in range(3)]  # the shared edge: vertices 0, 1, 2
    triangles = []
    for s, a in enumerate(angles):
        c, d = math.cos(math.radians(a)), math.sin(math.radians(a))
        index = {}
        for i in range(3):  # r = 0, 0.5, 1
            for k in range(3):  # z
                if i == 0:
                    index[i, k] = k
                else:
                    index[i, k] = len(points)
                    points.append((0.5 * i * c, 0.5 * i * d, 0.5 * k))
        for i in range(2):
            for k in range(2):
                for t in ([(i, k), (i + 1, k), (i + 1, k + 1)], [(i, k), (i + 1, k + 1), (i, k + 1)]):
                    tri = [index[x] for x in t]
                    triangles.append(tri if s < 2 else tri[::-1])
    write_off("soup_fan3.off", points, triangles)


def pinched():
    points = [(0.0, 0.0, 0.0)]
    triangles = []
    for z in (-1.0, 1.0):
        first = len(points)
        for k in range(6):
            a = 2 * math.pi * k / 6
            points.append((0.5 * math.cos(a), 0.5 * math.sin(a), z))
        for k in range(6):
            tri = [0, first + k, first + (k + 1) % 6]
            triangles.append(tri if z > 0 else tri[::-1])
    write_off("soup_pinched.off", points, triangles)


if __name__ == "__main__":
    moebius()
    fan()
    pinched()
