# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Progress callbacks, cancellation from a callback, and Ctrl-C (SIGINT) during a long computation."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import mdcs
from conftest import grid_mesh


@pytest.fixture(scope="module")
def big():
    """40,000 vertices: each fast-marching propagation takes about 0.1 s, each exact one seconds."""
    V, F = grid_mesh(200, 200, z=lambda x, y: 0.1 * np.sin(7 * x) * np.cos(6 * y))
    return mdcs.Mesh(V, F)


@pytest.fixture(scope="module")
def small():
    V, F = grid_mesh(40, 40, z=lambda x, y: 0.1 * np.sin(7 * x) * np.cos(6 * y))
    return mdcs.Mesh(V, F)


def test_progress_reports_stages_and_fractions(small):
    reports = []
    small.distance_matrix(np.arange(0, 1600, 20), threads=2, progress=lambda s, f: reports.append((s, f)))
    assert reports and all(s == "distance matrix" for s, _ in reports)
    fractions = [f for _, f in reports]
    assert fractions[0] == 0 and fractions[-1] == 1 and all(0 <= f <= 1 for f in fractions)
    assert fractions == sorted(fractions)
    stages = []
    mdcs.mwt.minimum_weight_triangulation(np.random.default_rng(0).random((50, 2)),
                                          progress=lambda s, f: stages.append(s))
    assert stages


def test_a_callback_returning_false_cancels(small):
    with pytest.raises(mdcs.OperationCancelled, match="cancelled"):
        small.distance_matrix(np.arange(0, 1600, 5), progress=lambda s, f: f < 0.1)
    with pytest.raises(mdcs.OperationCancelled, match="cancelled"):
        small.distances(0, progress=lambda s, f: f < 0.2)
    with pytest.raises(mdcs.OperationCancelled):
        mdcs.variational.minimal_curve("arc_length", interval=(0, 1), value_range=(0, 1), left=0.5, right=0.5,
                                       lines=300, progress=lambda s, f: False)
    # the mesh is still usable afterwards
    assert small.distances(0, progress=False)[0] == 0


def test_a_callback_exception_propagates(small):
    def broken(stage, fraction):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        small.distance_matrix(np.arange(0, 1600, 400), progress=broken)


@pytest.mark.parametrize("threads", [1, 2])
def test_ctrl_c_stops_a_long_run(big, threads):
    sources = np.arange(0, 40000, 20)  # 2,000 propagations: minutes
    sent = []

    def interrupt():
        time.sleep(0.3)
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Thread(target=interrupt)
    timer.start()
    start = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            big.distance_matrix(sources, method="fast_marching", threads=threads, progress=False)
    finally:
        timer.join()
    stopped = time.perf_counter()
    assert sent and stopped - sent[0] < 2.0, "the computation did not stop soon after SIGINT"
    assert stopped - start < 10
