# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.silhouettes: the silhouette separates front- from back-facing faces, a convex surface has one closed loop,
and the simple silhouette is made of fine mesh edges."""

import numpy as np

import mdcs
from conftest import bumpy_sphere, icosphere


def facing(V, F, direction):
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    return n @ -np.asarray(direction) > 0


def test_silhouette_edges_separate_front_and_back():
    V, F = icosphere(3)
    direction = np.array([0.3, -0.2, -1.0])
    edges = mdcs.silhouettes.silhouette_edges(V, F, direction=direction)
    front = facing(V, F, direction)
    # each directed silhouette edge (a, b) is an edge of a front face (a -> b in its order) and of a back face
    edge_face = {}
    for f, (a, b, c) in enumerate(F):
        for u, v in ((a, b), (b, c), (c, a)):
            edge_face[(u, v)] = f
    assert len(edges) > 0
    for a, b in edges:
        assert front[edge_face[(a, b)]] and not front[edge_face[(b, a)]]
    expected = sum(1 for (u, v), f in edge_face.items() if front[f] and not front[edge_face[(v, u)]])
    assert len(edges) == expected


def test_convex_surface_has_one_closed_loop_and_the_simple_silhouette_uses_mesh_edges():
    V, F = bumpy_sphere(3, amplitude=0.05)
    simplifier = mdcs.silhouettes.Simplifier(V, F, target_faces=200, progress=False)
    assert simplifier.number_of_fine_faces == len(F) and simplifier.number_of_coarse_faces <= 210
    loops = simplifier.silhouette(eye=[0.2, 0.1, 6.0])
    assert loops.fine_silhouette_edges > 0 and loops.coarse_silhouette_edges > 0
    assert len(loops.mapped) >= 1
    edges = {tuple(sorted(e)) for f in F for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    for vertices, closed in loops.mapped:
        assert closed
        for a, b in zip(vertices, np.roll(vertices, -1)):
            assert tuple(sorted((a, b))) in edges
    cv, cf, face_map = simplifier.coarse_mesh()
    assert cv.shape[1] == 3 and cf.shape[1] == 3 and len(face_map) == len(F) and face_map.max() < len(cf)


def torus(n_major=40, n_minor=16, R=1.0, r=0.4):
    """A torus of radii R and r, outward faces: a surface with saddles, so a view has several silhouette loops."""
    u, v = np.meshgrid(np.arange(n_major) * 2 * np.pi / n_major, np.arange(n_minor) * 2 * np.pi / n_minor,
                       indexing="ij")
    V = np.c_[((R + r * np.cos(v)) * np.cos(u)).ravel(), ((R + r * np.cos(v)) * np.sin(u)).ravel(),
              (r * np.sin(v)).ravel()]
    F = []
    for i in range(n_major):
        for j in range(n_minor):
            a, b = i * n_minor + j, ((i + 1) % n_major) * n_minor + j
            c, d = ((i + 1) % n_major) * n_minor + (j + 1) % n_minor, i * n_minor + (j + 1) % n_minor
            F += [[a, b, c], [a, c, d]]
    return V, np.array(F, dtype=np.int64)


def views(seed, count):
    """Perspective eyes (outside, near and inside the mesh) and orthographic directions, axis-aligned ones among
    them (faces seen edge-on, where the exact predicate decides)."""
    rng = np.random.default_rng(seed)
    out = [dict(direction=d) for d in ([0, 0, 1], [0, 0, -1], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 0.5])]
    while len(out) < count:
        d = rng.normal(size=3)
        if len(out) % 2:
            out.append(dict(direction=d))
        else:
            out.append(dict(eye=d * rng.choice([0.3, 1.2, 3.0, 50.0])))
    return out


def test_the_hierarchy_finds_the_silhouette_edges_of_the_scan():
    # The scan (silhouette_edges) classifies every face; the hierarchy skips groups of faces proven to face one way:
    # the same edges, in the same order, for every view (26 views per mesh, half orthographic).
    for V, F, seed in (icosphere(3) + (1,), torus() + (2,)):
        edges = mdcs.silhouettes.SilhouetteEdges(V, F)
        assert edges.number_of_faces == len(F) and edges.number_of_nodes > 1
        counts = []
        for view in views(seed, 26):
            expected = mdcs.silhouettes.silhouette_edges(V, F, **view)
            got = edges.edges(**view)
            assert got.dtype == np.int64 and got.shape == expected.shape
            assert np.array_equal(got, expected), view
            counts.append(len(got))
        assert sum(c > 0 for c in counts) > len(counts) // 2  # the views see silhouettes (eyes inside may not)


def test_the_simplifier_with_a_hierarchy_gives_the_same_frames():
    V, F = bumpy_sphere(3, amplitude=0.05)
    plain = mdcs.silhouettes.Simplifier(V, F, target_faces=200, progress=False)
    fast = mdcs.silhouettes.Simplifier(V, F, target_faces=200, hierarchy=True, progress=False)
    assert fast.uses_hierarchy and not plain.uses_hierarchy
    for view in views(3, 8):
        a, b = plain.silhouette(**view), fast.silhouette(**view)
        assert a.fine_silhouette_edges == b.fine_silhouette_edges > 0
        assert a.coarse_silhouette_edges == b.coarse_silhouette_edges
        assert a.picking_error == b.picking_error
        for name in ("fine", "picked", "mapped", "coarse"):
            la, lb = getattr(a, name), getattr(b, name)
            assert len(la) == len(lb)
            for (va, ca), (vb, cb) in zip(la, lb):
                assert ca == cb and np.array_equal(va, vb)
