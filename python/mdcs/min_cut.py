# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Minimum s-t cuts (maximum flows) of networks given as arrays (the C++ package Min_cut).

A network has ``number_of_nodes`` nodes, interior edges ``edges[i] = (u, v)`` with capacity ``capacities[i]`` in
both directions or ``capacities[i] = (c_uv, c_vu)``, and terminal edges: from the source to each of
``source_nodes`` and from each of ``sink_nodes`` to the sink (capacity ``inf`` unless given). Infinite capacities
express constraints ("u may not be on the source side while v is on the sink side").

>>> import numpy as np, mdcs
>>> cut = mdcs.min_cut.min_cut(3, edges=[[0, 1], [1, 2]], capacities=[2.0, 1.0], source_nodes=[0], sink_nodes=[2])
>>> cut.value, cut.source_side.tolist(), cut.cut_edges.tolist()
(1.0, [True, True, False], [1])
"""

import dataclasses

import numpy as np

from . import _mdcs
from ._progress import progress_callback

__all__ = ["min_cut", "MinCut", "ENGINES"]

#: Max-flow engines: pseudoflow (default, fastest on the library's networks), Boost's push-relabel and
#: Boykov-Kolmogorov.
ENGINES = ("pseudoflow", "push_relabel", "boykov_kolmogorov")


@dataclasses.dataclass
class MinCut:
    """A minimum s-t cut.

    Attributes:
        value: the capacity of the cut (``inf`` when every cut crosses an infinite capacity).
        finite: whether the cut is finite (the constraints of infinite capacities can all hold).
        source_side: ``(n,)`` bool, the nodes on the source side (the minimal source side).
        cut_edges: indices of the interior edges the cut crosses; ``cut_forward[i]`` tells whether it is crossed
            from ``edges[i][0]`` (source side) to ``edges[i][1]`` (sink side), otherwise the other way.
        cut_source_edges, cut_sink_edges: indices into ``source_nodes`` / ``sink_nodes`` of the cut terminal
            edges.
    """

    value: float
    finite: bool
    source_side: np.ndarray
    cut_edges: np.ndarray
    cut_forward: np.ndarray
    cut_source_edges: np.ndarray
    cut_sink_edges: np.ndarray


def min_cut(number_of_nodes, edges, capacities, source_nodes, sink_nodes, *, source_capacities=None,
            sink_capacities=None, engine="pseudoflow", progress="auto"):
    """A minimum s-t cut of the network (see the module documentation).

    Parameters:
        number_of_nodes: the number of nodes (>= 1).
        edges: ``(k, 2)`` integer node pairs (no self-loops).
        capacities: ``(k,)`` (both directions) or ``(k, 2)`` (``u -> v``, ``v -> u``), >= 0, ``inf`` allowed.
        source_nodes, sink_nodes: node indices tied to the source / the sink.
        source_capacities, sink_capacities: capacities of those terminal edges (default ``inf``).
        engine: one of :data:`ENGINES`.
        progress: as everywhere in mdcs (see :mod:`mdcs._progress`).

    Returns:
        :class:`MinCut`.
    """
    edges = np.zeros((0, 2), dtype=np.int64) if edges is None else edges
    with progress_callback(progress, "min-cut") as callback:
        d = _mdcs.min_cut.min_cut(int(number_of_nodes), edges, capacities, np.atleast_1d(source_nodes),
                                  source_capacities, np.atleast_1d(sink_nodes), sink_capacities, engine, callback)
    d["source_side"] = d["source_side"].astype(bool)
    d["cut_forward"] = d["cut_forward"].astype(bool)
    return MinCut(**d)
