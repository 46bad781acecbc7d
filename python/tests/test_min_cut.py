# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.min_cut against the C++ example's grid (value 9.5, the cut follows the target curve) and against SciPy's
maximum flow (an independent implementation, integer capacities) on random networks."""

import numpy as np
import pytest
import scipy.sparse
import scipy.sparse.csgraph

import mdcs


def test_grid_curve_of_the_example():
    width, height = 8, 7
    target = [2, 2, 3, 3, 4, 4, 3, 3]
    cell = lambda x, y: y * width + x  # noqa: E731
    edges, caps = [], []
    for y in range(height):
        for x in range(width):
            if y + 1 < height:
                edges.append((cell(x, y), cell(x, y + 1)))
                caps.append((1.0 if y == target[x] else 5.0, np.inf))
            if x + 1 < width:
                edges.append((cell(x, y), cell(x + 1, y)))
                caps.append((0.5, 0.5))
    sources = [cell(x, 0) for x in range(width)]
    sinks = [cell(x, height - 1) for x in range(width)]
    for engine in mdcs.min_cut.ENGINES:
        cut = mdcs.min_cut.min_cut(width * height, edges, caps, sources, sinks, engine=engine, progress=False)
        assert cut.finite and cut.value == pytest.approx(9.5)
        heights = [sum(cut.source_side[cell(x, y)] for y in range(height)) - 1 for x in range(width)]
        assert heights == target


@pytest.mark.parametrize("seed", range(5))
def test_random_networks_against_scipy(seed):
    rng = np.random.default_rng(seed)
    n = 40
    edges = rng.integers(0, n, size=(160, 2))
    edges = edges[edges[:, 0] != edges[:, 1]]
    caps = rng.integers(0, 10, size=(len(edges), 2)).astype(float)
    cut = mdcs.min_cut.min_cut(n, edges, caps, [0], [n - 1], progress=False)
    # SciPy: one arc per direction, parallel arcs summed
    rows = np.r_[edges[:, 0], edges[:, 1]]
    cols = np.r_[edges[:, 1], edges[:, 0]]
    graph = scipy.sparse.csr_matrix((np.r_[caps[:, 0], caps[:, 1]].astype(np.int32), (rows, cols)), shape=(n, n))
    flow = scipy.sparse.csgraph.maximum_flow(graph, 0, n - 1).flow_value
    assert cut.value == pytest.approx(flow)
    # the reported cut is a cut of that value
    side = cut.source_side
    crossing = caps[:, 0][side[edges[:, 0]] & ~side[edges[:, 1]]].sum() + caps[:, 1][side[edges[:, 1]] & ~side[edges[:, 0]]].sum()
    assert crossing == pytest.approx(flow)
    assert side[0] and not side[n - 1]
    assert sorted(cut.cut_edges.tolist()) == sorted(np.flatnonzero(side[edges[:, 0]] != side[edges[:, 1]]).tolist())


def test_infinite_cut_is_reported():
    cut = mdcs.min_cut.min_cut(2, [[0, 1]], [[np.inf, np.inf]], [0], [1], progress=False)
    assert not cut.finite and cut.value == np.inf
    cut = mdcs.min_cut.min_cut(2, [[0, 1]], [3.0], [0], [1], source_capacities=[1.0], progress=False)
    assert cut.finite and cut.value == 1.0 and cut.cut_source_edges.tolist() == [0]
