# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared fixtures of the pytest suite: generated meshes (every machine), CGAL's demo meshes (when the build found
libcgal-demo: MDCS_CGAL_MESH_DIR), and the ``long`` marker (skipped unless ``--run-long``)."""

import os

import numpy as np
import pytest


def pytest_addoption(parser):
    parser.addoption("--run-long", action="store_true", default=False, help="also run the tests marked long")


def pytest_configure(config):
    config.addinivalue_line("markers", "long: a long test, skipped unless --run-long is given")
    # Debian 12's distributed and tornado warn about their own dependencies' deprecations.
    config.addinivalue_line("filterwarnings", "ignore::DeprecationWarning:distributed.*")
    config.addinivalue_line("filterwarnings", "ignore::DeprecationWarning:tornado.*")


def pytest_collection_modifyitems(config, items):
    if config.getoption("--run-long"):
        return
    skip = pytest.mark.skip(reason="long test: run with --run-long")
    for item in items:
        if "long" in item.keywords:
            item.add_marker(skip)


def grid_mesh(nx, ny, size=(1.0, 1.0), diagonal="alternate", z=None):
    """A planar triangulated grid of nx x ny vertices on [0, size[0]] x [0, size[1]] (optionally lifted by z(x, y))."""
    xs, ys = np.meshgrid(np.linspace(0, size[0], nx), np.linspace(0, size[1], ny), indexing="ij")
    V = np.c_[xs.ravel(), ys.ravel(), np.zeros(nx * ny) if z is None else z(xs.ravel(), ys.ravel())]
    faces = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            a, b, c, d = i * ny + j, (i + 1) * ny + j, (i + 1) * ny + j + 1, i * ny + j + 1
            if diagonal == "alternate" and (i + j) % 2:
                faces += [[a, b, d], [b, c, d]]
            else:
                faces += [[a, b, c], [a, c, d]]
    return V, np.array(faces, dtype=np.int64)


def icosphere(levels=2):
    """The unit icosphere (an icosahedron with each triangle split in four, ``levels`` times), outward faces."""
    t = (1 + 5 ** 0.5) / 2
    V = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    V = [list(np.array(v) / np.linalg.norm(v)) for v in V]
    F = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    for _ in range(levels):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = np.add(V[a], V[b])
                V.append(list(p / np.linalg.norm(p)))
                middle[key] = len(V) - 1
            return middle[key]

        G = []
        for a, b, c in F:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            G += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        F = G
    return np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


def bumpy_sphere(levels=3, amplitude=0.1):
    """An icosphere with a wavy radius: a curved surface with saddle vertices."""
    V, F = icosphere(levels)
    r = 1 + amplitude * np.sin(5 * V[:, 0]) * np.sin(4 * V[:, 1]) * np.sin(3 * V[:, 2] + 0.5)
    return V * r[:, None], F


@pytest.fixture(scope="session")
def cgal_mesh_dir():
    """CGAL's demo meshes (libcgal-demo), unpacked by CMake; None on machines without them."""
    d = os.environ.get("MDCS_CGAL_MESH_DIR", "")
    return d if d and os.path.isdir(d) else None


@pytest.fixture(scope="session")
def elephant(cgal_mesh_dir):
    """CGAL's elephant.off (2,775 vertices), or a skip on machines without CGAL's data."""
    if cgal_mesh_dir is None or not os.path.exists(os.path.join(cgal_mesh_dir, "elephant.off")):
        pytest.skip("CGAL's demo meshes (libcgal-demo) are not available")
    import mdcs

    return mdcs.io.read_mesh(os.path.join(cgal_mesh_dir, "elephant.off"))
