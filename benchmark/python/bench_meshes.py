# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes of the Python benchmarks: CGAL's demo meshes (Debian's libcgal-demo: the folder CMake unpacks, given as
MDCS_CGAL_MESH_DIR or --mesh-dir, or read straight from /usr/share/doc/libcgal-dev/data.tar.gz), any mesh file, and
Loop subdivision (numpy) to reach a vertex count."""

import os
import tarfile
import tempfile

import numpy as np

import mdcs

CGAL_ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"


def demo_mesh(name, mesh_dir=None):
    """(vertices, faces) of CGAL's demo mesh `name` (e.g. "man.off"), or of the file `name` if it exists."""
    if os.path.exists(name):
        return mdcs.io.read_mesh(name)
    for folder in (mesh_dir, os.environ.get("MDCS_CGAL_MESH_DIR")):
        if folder and os.path.exists(os.path.join(folder, name)):
            return mdcs.io.read_mesh(os.path.join(folder, name))
    if os.path.exists(CGAL_ARCHIVE):
        with tarfile.open(CGAL_ARCHIVE) as archive:
            member = archive.extractfile(f"data/meshes/{name}")
            with tempfile.TemporaryDirectory() as tmp:
                path = os.path.join(tmp, name)
                with open(path, "wb") as f:
                    f.write(member.read())
                return mdcs.io.read_mesh(path)
    raise FileNotFoundError(f"{name}: not a file, and CGAL's demo meshes (libcgal-demo) are not installed")


def loop_subdivision(V, F):
    """One step of Loop subdivision of a triangle mesh (boundary edges and vertices by the boundary rules)."""
    n = len(V)
    half = F[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)           # face edges (a, b) in face order
    opposite = F[:, [2, 0, 1]].reshape(-1)                   # the third corner of each face edge
    key = np.sort(half, axis=1)
    edges, index = np.unique(key, axis=0, return_inverse=True)
    index = index.ravel()
    m = len(edges)
    count = np.bincount(index, minlength=m)
    opposite_sum = np.zeros((m, 3))
    np.add.at(opposite_sum, index, V[opposite])
    boundary = count == 1
    odd = np.where(boundary[:, None], 0.5 * (V[edges[:, 0]] + V[edges[:, 1]]),
                   0.375 * (V[edges[:, 0]] + V[edges[:, 1]]) + 0.125 * opposite_sum)
    # even vertices
    valence = np.bincount(edges.ravel(), minlength=n).astype(float)
    neighbour_sum = np.zeros((n, 3))
    np.add.at(neighbour_sum, edges[:, 0], V[edges[:, 1]])
    np.add.at(neighbour_sum, edges[:, 1], V[edges[:, 0]])
    k = np.maximum(valence, 1)
    beta = (0.625 - (0.375 + 0.25 * np.cos(2 * np.pi / k)) ** 2) / k
    even = (1 - k * beta)[:, None] * V + beta[:, None] * neighbour_sum
    on_boundary = np.zeros(n, dtype=bool)
    on_boundary[edges[boundary].ravel()] = True
    if on_boundary.any():
        boundary_sum = np.zeros((n, 3))
        np.add.at(boundary_sum, edges[boundary, 0], V[edges[boundary, 1]])
        np.add.at(boundary_sum, edges[boundary, 1], V[edges[boundary, 0]])
        even[on_boundary] = 0.75 * V[on_boundary] + 0.125 * boundary_sum[on_boundary]
    mid = (n + index).reshape(-1, 3)                          # the new vertex of each face edge: ab, bc, ca
    a, b, c = F[:, 0], F[:, 1], F[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    faces = np.concatenate([np.c_[a, ab, ca], np.c_[b, bc, ab], np.c_[c, ca, bc], np.c_[ab, bc, ca]])
    return np.vstack([even, odd]), faces


def subdivided(V, F, min_vertices):
    """Loop subdivision until the mesh has at least `min_vertices` vertices; returns (V, F, steps)."""
    steps = 0
    while len(V) < min_vertices:
        V, F = loop_subdivision(V, F)
        steps += 1
    return V, F, steps


def grid_sphere(levels):
    """A fallback when no demo mesh exists: an icosphere with a wavy radius."""
    import sys

    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python", "tests"))
    from conftest import bumpy_sphere

    return bumpy_sphere(levels)
