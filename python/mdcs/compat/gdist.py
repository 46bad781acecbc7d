# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A drop-in replacement for tvb-gdist's ``gdist`` module, on MDCS's exact geodesics.

Switch with one import line::

    import mdcs.compat.gdist as gdist      # instead of: import gdist

The three functions tvb-gdist documents have the same names, parameters (including ``is_one_indexed``), defaults,
dtypes and return types (``numpy.ndarray`` of float64, ``scipy.sparse.csc_matrix``).

Deliberate differences:

- Unreachable vertices (another connected component, or beyond ``max_distance``) are ``inf``. tvb-gdist returns
  ``inf`` only without ``max_distance`` and its internal value ``1e100`` otherwise (tvb-gdist issue 21).
- ``local_gdist_matrix`` holds exactly the entries with ``0 < d <= max_distance``, and it is exactly symmetric: the
  entry (i, j) is the smaller of the two propagations' values, which differ by rounding only. tvb-gdist's matrix can
  hold values beyond the limit and is symmetric only approximately.
- The rows are computed in parallel on every core (one propagation per source, as in tvb-gdist).
- Arrays of any integer dtype are accepted where tvb-gdist demands ``int32`` (and any real dtype for vertices); bad
  input raises ``ValueError`` or ``IndexError`` naming the problem instead of a crash or an assertion.
- As in tvb-gdist, ``is_one_indexed`` applies to ``triangles`` only: vertex indices (``source_indices``,
  ``target_indices``, ``points``) and the rows and columns of the matrices are 0-based.
"""

import numpy
import scipy.sparse

from .. import geodesics

__all__ = ["compute_gdist", "local_gdist_matrix", "distance_matrix_of_selected_points"]

_INF = numpy.inf


def _mesh(vertices, triangles, is_one_indexed):
    triangles = numpy.asarray(triangles)
    if is_one_indexed and triangles.dtype.kind in "iu":
        triangles = triangles.astype(numpy.int64) - 1
    return geodesics.Mesh(vertices, triangles)


def _limit(max_distance):
    """None for no limit (tvb-gdist's default is its internal infinity, 1e100)."""
    max_distance = float(max_distance)
    if numpy.isnan(max_distance):
        raise ValueError("mdcs.compat.gdist: max_distance is NaN")
    return None if max_distance >= 1e100 else max_distance


def compute_gdist(vertices, triangles, source_indices=None, target_indices=None, max_distance=_INF,
                  is_one_indexed=False):
    """Geodesic distance from the nearest of the sources to each target vertex.

    Args:
        vertices (numpy.ndarray, float64, (n, 3)): the vertex coordinates.
        triangles (numpy.ndarray, int, (m, 3)): the faces as vertex index triples.
        source_indices (numpy.ndarray, int, (k,)): the source vertices; default: vertex 0.
        target_indices (numpy.ndarray, int, (t,)): the target vertices; default: every vertex.
        max_distance (float): stop the propagation at this distance; farther targets get ``inf``.
        is_one_indexed (bool): ``triangles`` counts vertices from 1.

    Returns:
        numpy.ndarray((t,), float64): the distance of each target (of each vertex without targets), ``inf`` where
        unreachable or beyond ``max_distance``.
    """
    mesh = _mesh(vertices, triangles, is_one_indexed)
    if source_indices is None:
        source_indices = numpy.zeros(1, dtype=numpy.int64)
    return mesh.distances(numpy.atleast_1d(source_indices), targets=target_indices, max_distance=_limit(max_distance),
                          progress=False)


def local_gdist_matrix(vertices, triangles, max_distance=_INF, is_one_indexed=False):
    """Geodesic distances from every vertex to every vertex within ``max_distance``.

    Args:
        vertices (numpy.ndarray, float64, (n, 3)): the vertex coordinates.
        triangles (numpy.ndarray, int, (m, 3)): the faces as vertex index triples.
        max_distance (float): the neighbourhood radius (default: unlimited, i.e. all pairs).
        is_one_indexed (bool): ``triangles`` counts vertices from 1.

    Returns:
        scipy.sparse.csc_matrix((n, n), float64): the entries with ``0 < distance <= max_distance`` (vertex pairs at
        distance 0, such as the diagonal, are not stored), exactly symmetric.
    """
    mesh = _mesh(vertices, triangles, is_one_indexed)
    n = mesh.number_of_vertices
    local = mesh.distance_matrix(numpy.arange(n), sparse=True, symmetric=True, max_distance=_limit(max_distance),
                                 progress="auto").tocoo()
    keep = (local.data > 0) & numpy.isfinite(local.data)
    return scipy.sparse.csc_matrix((local.data[keep], (local.row[keep], local.col[keep])), shape=(n, n))


def distance_matrix_of_selected_points(vertices, triangles, points, max_distance=_INF, is_one_indexed=False):
    """Pairwise geodesic distances among the vertices ``points``.

    Args:
        vertices (numpy.ndarray, float64, (n, 3)): the vertex coordinates.
        triangles (numpy.ndarray, int, (m, 3)): the faces as vertex index triples.
        points (numpy.ndarray, int, (k,)): the vertices among which the distances are computed.
        max_distance (float): stop each propagation at this distance; farther pairs get ``inf``.
        is_one_indexed (bool): ``triangles`` counts vertices from 1.

    Returns:
        scipy.sparse.csc_matrix((n, n), float64): entry (p, q) for every pair of different positions of ``points``
        (both orders, the same value), ``inf`` where unreachable.
    """
    mesh = _mesh(vertices, triangles, is_one_indexed)
    n = mesh.number_of_vertices
    points = numpy.atleast_1d(numpy.asarray(points))
    k = len(points)
    if k == 0:
        return scipy.sparse.csc_matrix((n, n), dtype=numpy.float64)
    d = mesh.distance_matrix(points, points, max_distance=_limit(max_distance), progress=False)
    # Entries for each pair i < j of positions, in both orders, with the value of the earlier point's propagation.
    i, j = numpy.triu_indices(k, 1)
    values = d[i, j]
    rows = numpy.column_stack([points[i], points[j]]).ravel()
    cols = numpy.column_stack([points[j], points[i]]).ravel()
    data = numpy.repeat(values, 2)
    return scipy.sparse.csc_matrix((data, (rows, cols)), shape=(n, n))
