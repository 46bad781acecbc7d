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
