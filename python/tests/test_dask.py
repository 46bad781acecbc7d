# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.dask on a LocalCluster with 2 worker processes: the results equal the in-process calls, gathered, written
to a .npy file or to a Zarr store; map over point sets."""

import numpy as np
import pytest

import mdcs
from conftest import bumpy_sphere

distributed = pytest.importorskip("distributed")
import mdcs.dask  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address="127.0.0.1:0", silence_logs=40)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def mesh():
    V, F = bumpy_sphere(3)
    return mdcs.Mesh(V, F)


def test_distance_matrix_gathered_equals_in_process(client, mesh):
    sources = np.arange(0, 642, 9)
    expected = mesh.distance_matrix(sources, progress=False)
    got = mdcs.dask.distance_matrix(client, mesh, sources, block_size=10, progress=False)
    assert np.array_equal(got, expected)
    targets = np.array([1, 2, 3, 500])
    got = mdcs.dask.distance_matrix(client, (mesh.vertices, mesh.faces), sources, targets, progress=False)
    assert np.array_equal(got, expected[:, targets])
    sparse = mdcs.dask.distance_matrix(client, mesh, sources, max_distance=0.5, sparse=True, block_size=16,
                                       progress=False)
    dense = mesh.distance_matrix(sources, max_distance=0.5, progress=False)
    assert np.array_equal(sparse.toarray(), np.where(np.isfinite(dense), dense, 0))


def test_distance_matrix_written_to_files(client, mesh, tmp_path):
    sources = np.arange(0, 642, 13)
    expected = mesh.distance_matrix(sources, method="fast_marching", progress=False)
    npy = mdcs.dask.distance_matrix(client, mesh, sources, method="fast_marching", block_size=7,
                                    output=tmp_path / "d.npy", progress=False)
    assert np.array_equal(np.load(tmp_path / "d.npy"), expected) and np.array_equal(npy, expected)
    zarr = pytest.importorskip("zarr")
    z = mdcs.dask.distance_matrix(client, mesh, sources, method="fast_marching", block_size=7,
                                  output=str(tmp_path / "d.zarr"), progress=False)
    assert np.array_equal(z[:], expected)
    assert np.array_equal(zarr.open(str(tmp_path / "d.zarr"), mode="r")[:], expected)


def test_map_over_point_sets(client):
    rng = np.random.default_rng(5)
    sets = [rng.random((25, 2)) for _ in range(4)]
    results = mdcs.dask.map(client, mdcs.mwt.minimum_weight_triangulation, sets, progress=False)
    for points, r in zip(sets, results):
        local = mdcs.mwt.minimum_weight_triangulation(points, progress=False)
        assert r.weight == local.weight and np.array_equal(r.triangles, local.triangles)


def test_task_errors_reach_the_client(client, mesh):
    with pytest.raises(IndexError):
        mdcs.dask.distance_matrix(client, mesh, [0, 10 ** 6], progress=False)
    with pytest.raises(ValueError):
        mdcs.dask.map(client, mdcs.mwt.minimum_weight_triangulation, [np.zeros((2, 2))], progress=False)
