# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.compat.gdist against tvb-gdist's documented behaviour (signatures, dtypes, return types) on meshes of our
own, with Euclidean distances on planar meshes as the oracle; and the documented deliberate differences."""

import inspect

import numpy as np
import pytest
import scipy.sparse

import mdcs.compat.gdist as gdist
from conftest import bumpy_sphere, grid_mesh

V, F = grid_mesh(11, 11, size=(2.0, 2.0))
F32 = F.astype(np.int32)


def test_signatures_match_the_originals():
    assert list(inspect.signature(gdist.compute_gdist).parameters) == [
        "vertices", "triangles", "source_indices", "target_indices", "max_distance", "is_one_indexed"]
    assert list(inspect.signature(gdist.local_gdist_matrix).parameters) == [
        "vertices", "triangles", "max_distance", "is_one_indexed"]
    assert list(inspect.signature(gdist.distance_matrix_of_selected_points).parameters) == [
        "vertices", "triangles", "points", "max_distance", "is_one_indexed"]


def test_compute_gdist_distances_and_types():
    src, trg = np.array([1], dtype=np.int32), np.array([2, 30], dtype=np.int32)
    d = gdist.compute_gdist(V, F32, source_indices=src, target_indices=trg)
    assert isinstance(d, np.ndarray) and d.dtype == np.float64 and d.shape == (2,)
    np.testing.assert_allclose(d, np.linalg.norm(V[trg] - V[1], axis=1), atol=1e-12)
    every = gdist.compute_gdist(V, F32)  # default source: vertex 0, targets: every vertex
    np.testing.assert_allclose(every, np.linalg.norm(V - V[0], axis=1), atol=1e-12)
    one = gdist.compute_gdist(V, F32 + 1, src, trg, is_one_indexed=True)
    np.testing.assert_allclose(one, d, atol=1e-15)


def test_max_distance_gives_inf_beyond_the_limit():
    d = gdist.compute_gdist(V, F32, np.array([0], np.int32), max_distance=1.0)
    euclid = np.linalg.norm(V - V[0], axis=1)
    assert np.all(np.isinf(d[euclid > 1.0 + 1e-9]))
    np.testing.assert_allclose(d[euclid < 1.0 - 1e-9], euclid[euclid < 1.0 - 1e-9], atol=1e-12)


def test_local_gdist_matrix_is_exact_symmetric_and_local():
    Vb, Fb = bumpy_sphere(2)
    m = gdist.local_gdist_matrix(Vb, Fb.astype(np.int32), max_distance=0.6)
    assert type(m) is scipy.sparse.csc_matrix and m.shape == (len(Vb), len(Vb)) and m.dtype == np.float64
    assert (m != m.T).nnz == 0
    assert m.data.max() <= 0.6 and m.data.min() > 0
    full = gdist.local_gdist_matrix(Vb, Fb)
    assert full.nnz == len(Vb) * (len(Vb) - 1)
    row = gdist.compute_gdist(Vb, Fb, np.array([5]))
    np.testing.assert_allclose(full.toarray()[5], row, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(gdist.local_gdist_matrix(V, F32 + 1, 0.5, True).toarray(),
                               gdist.local_gdist_matrix(V, F32, 0.5).toarray())


def test_distance_matrix_of_selected_points():
    points = np.array([2, 5, 10, 12, 14, 16], dtype=np.int32)
    m = gdist.distance_matrix_of_selected_points(V, F32, points)
    assert type(m) is scipy.sparse.csc_matrix and m.shape == (121, 121)
    assert m.nnz == len(points) ** 2 - len(points)
    expected = np.linalg.norm(V[points][:, None] - V[points][None], axis=2)
    np.testing.assert_allclose(m.toarray()[np.ix_(points, points)], expected, atol=1e-12)
    assert (abs(m - m.T) > 0).nnz == 0


def test_unreachable_vertices_are_inf():
    V2 = np.vstack([V, V + [10, 0, 0]])
    F2 = np.vstack([F, F + len(V)])
    d = gdist.compute_gdist(V2, F2, np.array([0]), np.array([1, 130]))
    assert np.isfinite(d[0]) and np.isinf(d[1])


def test_bad_input_raises_instead_of_crashing():
    with pytest.raises(IndexError):
        gdist.compute_gdist(V, F32, np.array([500], np.int32))
    with pytest.raises(IndexError):
        gdist.compute_gdist(V, F32, is_one_indexed=True)  # 0 in a one-indexed face
    with pytest.raises(ValueError):
        gdist.local_gdist_matrix(V, F32, max_distance=np.nan)
