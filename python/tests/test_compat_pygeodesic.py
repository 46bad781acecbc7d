# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.compat.pygeodesic against pygeodesic's documented behaviour on meshes of our own (Euclidean distances and
straight paths on planar meshes), its file reader, and the documented deliberate differences."""

import numpy as np
import pytest

import mdcs.compat.pygeodesic as pygeodesic
import mdcs.compat.pygeodesic.geodesic as geodesic
from conftest import grid_mesh

V, F = grid_mesh(11, 11, size=(2.0, 2.0))


def test_version_and_names():
    assert isinstance(pygeodesic.__version__, str)
    assert pygeodesic.geodesic is geodesic
    assert pygeodesic.PyGeodesicAlgorithmExact is geodesic.PyGeodesicAlgorithmExact


def test_geodesic_distance_and_path():
    alg = geodesic.PyGeodesicAlgorithmExact(V, F)
    distance, path = alg.geodesicDistance(25, 97)
    assert distance == pytest.approx(np.linalg.norm(V[97] - V[25]), abs=1e-12)
    assert path.shape[1] == 3 and path.dtype == np.float64
    np.testing.assert_allclose(path[0], V[97], atol=1e-12)  # from the target ...
    np.testing.assert_allclose(path[-1], V[25], atol=1e-12)  # ... to the source
    assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(distance, rel=1e-9)
    d0, p0 = alg.geodesicDistance(4, 4)
    assert d0 == 0 and len(p0) == 1


def test_geodesic_distances_and_best_sources():
    alg = geodesic.PyGeodesicAlgorithmExact(V.tolist(), F.tolist())
    d, best = alg.geodesicDistances()
    np.testing.assert_allclose(d, np.linalg.norm(V - V[0], axis=1), atol=1e-12)
    assert d.dtype == np.float64 and best.dtype == np.int32 and np.all(best == 0)
    sources, targets = np.array([25, 100]), np.array([0, 10, 50])
    d, best = alg.geodesicDistances(sources, targets)
    euclid = np.linalg.norm(V[targets][:, None] - V[sources][None], axis=2)
    np.testing.assert_allclose(d, euclid.min(axis=1), atol=1e-12)
    assert best.tolist() == euclid.argmin(axis=1).tolist()
    limited, _ = alg.geodesicDistances(np.array([0]), max_distance=0.5)
    assert np.all(np.isinf(limited[np.linalg.norm(V - V[0], axis=1) > 0.5 + 1e-9]))


def test_unreachable_and_bad_input():
    V2 = np.vstack([V, V + [10, 0, 0]])
    F2 = np.vstack([F, F + len(V)])
    alg = geodesic.PyGeodesicAlgorithmExact(V2, F2)
    d, p = alg.geodesicDistance(0, 130)
    assert d == np.inf and p.shape == (0, 3)
    d, best = alg.geodesicDistances(np.array([0]), np.array([130]))
    assert np.isinf(d[0]) and best[0] == -1
    with pytest.raises(IndexError):
        alg.geodesicDistance(0, 10 ** 6)
    with pytest.raises(ValueError):
        alg.geodesicDistance(0, 1.5)
    with pytest.raises(ValueError):
        geodesic.PyGeodesicAlgorithmExact(V[:, :2], F)


def test_read_mesh_from_file(tmp_path):
    path = tmp_path / "mesh.txt"
    with open(path, "w") as f:
        f.write(f"{len(V)} {len(F)}\n")
        for p in V:
            f.write("\t".join(f"{x:.6f}" for x in p) + "\t\n")
        for t in F:
            f.write("\t".join(str(i) for i in t) + "\t\n")
    points, faces = geodesic.read_mesh_from_file(str(path))
    np.testing.assert_allclose(points, V, atol=1e-6)
    assert np.array_equal(faces, F)
    off = tmp_path / "mesh.off"
    off.write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
    points, faces = geodesic.read_mesh_from_file(off)
    assert points.shape == (4, 3) and faces.tolist() == [[0, 1, 2], [0, 2, 3]]
    bad = tmp_path / "bad.txt"
    bad.write_text("3 1\n0 0 0\n1 0\n0 1 0\n0 1 2\n")
    with pytest.raises(ValueError, match="point 1"):
        geodesic.read_mesh_from_file(bad)
    bad.write_text("3 1\n0 0 0\n1 0 0\n0 1 0\n0 1 3\n")
    with pytest.raises(IndexError):
        geodesic.read_mesh_from_file(bad)
