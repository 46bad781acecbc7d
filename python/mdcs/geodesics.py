# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Geodesic distances and shortest paths on triangle meshes (the C++ package Polyhedral_geodesics_3).

Build a :class:`Mesh` once from a vertex array (float, shape ``(n, 3)``) and a face array (integer, shape
``(m, 3)``) and reuse it: every call below runs on the prepared mesh.

>>> import numpy as np, mdcs
>>> V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
>>> F = np.array([[0, 1, 3], [0, 3, 2]])
>>> mesh = mdcs.geodesics.Mesh(V, F)
>>> mesh.distances(0).round(6).tolist()
[0.0, 1.0, 1.0, 1.414214]

Methods (``method=``), all with the same sources, limits and queries:

- ``"exact"`` (default): interval (window) propagation, exact distances (``Exact_geodesic_distances_3``);
- ``"merged"``: windows merged within ``merge_tolerance`` (absolute, mesh units; 0 gives the exact result), never
  below the exact distances (``Merged_window_geodesic_distances_3``);
- ``"flat_exact"``: one interval per edge, exact on planar meshes (``Flat_exact_geodesic_distances_3``);
- ``"fast_marching"``: Kimmel-Sethian fast marching (``Fast_marching_geodesic_distances_3``);
- ``"dijkstra"``: shortest paths along the edges (``Dijkstra_geodesic_distances_3``).

Sources are vertex indices (``sources=``) and/or surface points (``source_points=(faces, barycentric)``: face
indices and barycentric coordinates in the order of each face's corners). When both are given, vertex sources are
numbered first, then the surface points; "nearest source" results refer to that numbering.

Unreachable vertices (another connected component than every source, or beyond ``max_distance``) have distance
``+inf`` and nearest source ``-1``; paths to them are empty.

The GIL is released while the C++ code runs; Ctrl-C stops a long call (``KeyboardInterrupt``); ``progress=``
shows a progress bar or calls a function (see :mod:`mdcs._progress`).

Meshes that are not an oriented 2-manifold (a triangle soup with faces in both orientations, non-manifold edges
or vertices, a non-orientable surface) are oriented first, splitting non-manifold vertices into copies
(``was_oriented``, ``number_of_split_vertices``): a path then does not pass through a pinched vertex from one of its
sheets to another, and on a non-orientable surface the cut that orientation needs is not crossed. The distance
of a split vertex is the smallest over its copies.
"""

import dataclasses

import numpy as np

from . import _mdcs
from ._progress import progress_callback

__all__ = ["Mesh", "GeodesicField", "GeodesicPath", "SurfacePoints", "IsoCurve", "METHODS"]

_core = _mdcs.geodesics

#: The geodesic methods, for ``method=``.
METHODS = ("exact", "merged", "flat_exact", "fast_marching", "dijkstra")


@dataclasses.dataclass(frozen=True)
class SurfacePoints:
    """Points on the surface: ``faces[i]`` is a face index, ``barycentric[i]`` the point's barycentric coordinates
    with respect to that face's corners in the order of the mesh's face array (>= 0, summing to 1)."""

    faces: np.ndarray
    barycentric: np.ndarray

    @classmethod
    def of(cls, value):
        """A :class:`SurfacePoints` from itself, a pair ``(faces, barycentric)``, or ``None``."""
        if value is None or isinstance(value, cls):
            return value
        try:
            faces, barycentric = value
        except (TypeError, ValueError):
            raise ValueError("mdcs: surface points must be given as (faces, barycentric) or SurfacePoints") from None
        faces = np.atleast_1d(np.asarray(faces))
        barycentric = np.asarray(barycentric)
        if barycentric.ndim == 1:
            barycentric = barycentric.reshape(1, -1)
        return cls(faces, barycentric)


@dataclasses.dataclass(frozen=True)
class GeodesicPath:
    """A shortest path on the surface, from its query point (the target) to the nearest source.

    Every node is a vertex, an edge crossing or a point inside a face:

    - ``points``: ``(k, 3)`` coordinates;
    - ``kind``: ``(k,)`` 0 = vertex, 1 = edge crossing, 2 = point inside a face;
    - ``vertex``: the vertex index of vertex nodes, -1 otherwise;
    - ``edge``, ``t``: for edge crossings the edge's two vertices and the position ``t`` on it (the point is
      ``(1 - t) * V[edge[0]] + t * V[edge[1]]``), -1 and NaN otherwise;
    - ``face``, ``barycentric``: for points inside a face, the face and the barycentric coordinates in the order of
      its corners, -1 and NaN otherwise.

    An unreachable target gives an empty path (``len(path) == 0``).
    """

    points: np.ndarray
    kind: np.ndarray
    vertex: np.ndarray
    edge: np.ndarray
    t: np.ndarray
    face: np.ndarray
    barycentric: np.ndarray

    VERTEX = 0
    EDGE = 1
    FACE = 2

    @property
    def length(self):
        """The length of the polyline (``inf`` for an empty path, the target being unreachable)."""
        if len(self.points) == 0:
            return float("inf")
        return float(np.linalg.norm(np.diff(self.points, axis=0), axis=1).sum())

    def __len__(self):
        return len(self.points)

    def reversed(self):
        """The same path from the source to the target."""
        return GeodesicPath(*(np.ascontiguousarray(getattr(self, f.name)[::-1]) for f in dataclasses.fields(self)))


@dataclasses.dataclass(frozen=True)
class IsoCurve:
    """An iso-distance curve (:meth:`Mesh.iso_distance_curves`): ``points`` ``(k, 3)`` on the mesh's edges, in
    order; ``closed``: the last point joins the first (which is not repeated); open curves end on the border."""

    level: float
    closed: bool
    points: np.ndarray


def _path(d):
    return GeodesicPath(d["points"], d["kind"], d["vertex"], d["edge"], d["t"], d["face"], d["barycentric"])


def _split_sources(sources, source_points):
    points = SurfacePoints.of(source_points)
    if sources is None and points is None:
        raise ValueError("mdcs: give sources (vertex indices) and/or source_points (faces, barycentric)")
    if points is None:
        return sources, None, None
    return sources, points.faces, points.barycentric


class GeodesicField:
    """Distances from a set of sources, kept for queries: vertex distances and nearest sources, distances at surface
    points, and shortest paths. Made by :meth:`Mesh.field`.

    Attributes: ``distances`` (``(n,)`` float, ``inf`` where unreachable), ``nearest_sources`` (``(n,)`` int, -1
    where unreachable), ``mesh``.
    """

    def __init__(self, mesh, core_field, method):
        self.mesh = mesh
        self._field = core_field
        self.method = method

    @property
    def distances(self):
        """``(n,)`` geodesic distance of every vertex to the nearest source (read-only)."""
        return self._field.distances

    @property
    def nearest_sources(self):
        """``(n,)`` index of each vertex's nearest source (-1 where unreachable; read-only)."""
        return self._field.nearest_sources

    def statistics(self):
        """Counters of the propagation (windows created, propagated, ...), as a dict."""
        return self._field.statistics()

    def distance_at(self, points):
        """Distances and nearest sources at surface points ``(faces, barycentric)``; returns two ``(k,)`` arrays."""
        p = SurfacePoints.of(points)
        return self._field.point_distances(p.faces, p.barycentric)

    def shortest_path(self, target):
        """The shortest path from ``target`` (a vertex index, or a surface point ``(face, barycentric)``) to its
        nearest source, as a :class:`GeodesicPath` (empty when the target is unreachable)."""
        if isinstance(target, (tuple, list, SurfacePoints)) and not np.isscalar(target):
            p = SurfacePoints.of(target)
            return _path(self._field.point_paths(p.faces, p.barycentric)[0])
        return _path(self._field.paths(target)[0])

    def shortest_paths(self, targets):
        """The shortest paths from several vertices (a 1-D integer array) to their nearest sources: a list of
        :class:`GeodesicPath`."""
        return [_path(d) for d in self._field.paths(np.atleast_1d(targets))]

    def iso_distance_curves(self, levels):
        """The iso-distance curves of the field at ``levels`` (see :meth:`Mesh.iso_distance_curves`)."""
        return self.mesh.iso_distance_curves(self.distances, levels)

    def __repr__(self):
        return f"<mdcs.geodesics.GeodesicField {self.method}, {self._field.number_of_sources} source(s) on {self.mesh!r}>"


class Mesh:
    """A triangle mesh prepared once for geodesic computations.

    ``Mesh(vertices, faces)``: ``vertices`` a float array ``(n, 3)`` of finite coordinates, ``faces`` an integer
    array ``(m, 3)`` of vertex indices (three distinct corners each). Bad input raises ``ValueError`` (dtype, shape,
    NaN, repeated corners, non-triangle faces) or ``IndexError`` (an index out of range), naming the entry.

    The mesh is immutable, can be shared by threads (calls on it run concurrently without the GIL), and pickles
    (its arrays are sent; the receiver prepares it again), which :mod:`mdcs.dask` uses to send it once per worker.
    """

    def __init__(self, vertices, faces):
        self._surface = _core.Surface(vertices, faces)  # validates
        self.vertices = np.array(vertices, dtype=np.float64, order="C")
        self.faces = np.array(faces, dtype=np.int64, order="C")
        self.vertices.setflags(write=False)
        self.faces.setflags(write=False)

    @classmethod
    def from_file(cls, path):
        """A mesh read from an OFF, PLY, OBJ or STL file (see :func:`mdcs.io.read_mesh`)."""
        from .io import read_mesh

        return cls(*read_mesh(path))

    def __reduce__(self):
        return (Mesh, (self.vertices, self.faces))

    def __repr__(self):
        extra = ", oriented" if self.was_oriented else ""
        return f"<mdcs.geodesics.Mesh {self.number_of_vertices} vertices, {self.number_of_faces} faces{extra}>"

    @property
    def number_of_vertices(self):
        return self._surface.number_of_vertices

    @property
    def number_of_faces(self):
        return self._surface.number_of_faces

    @property
    def mean_edge_length(self):
        """The mean length of the edges (a scale for ``max_distance`` and ``merge_tolerance``)."""
        return self._surface.mean_edge_length

    @property
    def was_oriented(self):
        """Whether the faces had to be oriented (or non-manifold vertices split) to build the surface."""
        return self._surface.was_oriented

    @property
    def number_of_split_vertices(self):
        """How many vertices were split into copies (non-manifold vertices, cuts of non-orientable surfaces)."""
        return self._surface.number_of_split_vertices

    @property
    def number_of_isolated_vertices(self):
        """Vertices of no face: unreachable from every other vertex."""
        return self._surface.number_of_isolated_vertices

    def distances(self, sources=None, *, source_points=None, method="exact", merge_tolerance=0.0,
                  max_distance=None, targets=None, stop_at_targets=False, return_nearest=False, threads=1,
                  progress="auto"):
        """Geodesic distances from the sources to every vertex (or to ``targets``).

        Parameters:
            sources: a vertex index or a 1-D integer array of vertex indices.
            source_points: surface points ``(faces, barycentric)`` or :class:`SurfacePoints` as further sources.
            method: one of :data:`METHODS` (default ``"exact"``).
            merge_tolerance: for ``method="merged"``: absolute tolerance in mesh units (>= 0).
            max_distance: stop at this geodesic distance; farther vertices get ``inf``.
            targets: return the distances of these vertices only (a 1-D integer array), in that order.
            stop_at_targets: stop the propagation as soon as the targets' distances are final (faster for near
                targets; the default runs the faster complete schedule).
            return_nearest: also return each vertex's nearest source.
            threads: ``method="exact"`` only (the others run on one thread): 1 (default) runs the sequential
                propagation; 0 (every core) or N > 1 runs the parallel single-source propagation on that many
                threads. Its distances are identical, bit for bit, for every thread count, and equal to the
                sequential ones up to rounding (about 1e-15 relative). Runs with ``stop_at_targets`` stay
                sequential. For many sources, :meth:`distance_matrix` (one source per thread) scales better.
            progress: ``"auto"``, ``True``, ``False``/``None`` or a callable (see :mod:`mdcs._progress`).

        Returns:
            ``(n,)`` (or ``(len(targets),)``) float64 distances, ``inf`` where unreachable; with ``return_nearest``
            the pair ``(distances, nearest)``, ``nearest`` int64 with -1 where unreachable.
        """
        vs, pf, pb = _split_sources(sources, source_points)
        with progress_callback(progress, "geodesics") as callback:
            d, nearest = self._surface.distances(vs, pf, pb, method, float(merge_tolerance), max_distance, targets,
                                                 bool(stop_at_targets), bool(return_nearest), threads, callback)
        return (d, nearest) if return_nearest else d

    def field(self, sources=None, *, source_points=None, method="exact", merge_tolerance=0.0, max_distance=None,
              shorten_paths=False, progress="auto"):
        """The distance field of the sources, kept for point queries and shortest paths (:class:`GeodesicField`).

        Keeps the whole field (every window of every edge for ``"exact"`` and ``"merged"``), which takes more memory
        than :meth:`distances`. ``shorten_paths=True`` makes every path locally shortest (for the approximate
        methods, whose traced paths bend where a geodesic does not). Other parameters as in :meth:`distances`.
        """
        vs, pf, pb = _split_sources(sources, source_points)
        with progress_callback(progress, "geodesics") as callback:
            core = _core.Field(self._surface, vs, pf, pb, method, float(merge_tolerance), max_distance,
                               bool(shorten_paths), callback)
        return GeodesicField(self, core, method)

    def shortest_path(self, target, sources=None, *, source_points=None, method="exact", merge_tolerance=0.0,
                      shorten_paths=False, progress="auto"):
        """The shortest path from ``target`` (a vertex index, or a surface point ``(face, barycentric)``) to the
        nearest of the sources, as a :class:`GeodesicPath` (target first). For many paths from the same sources,
        use :meth:`field` once and query it."""
        field = self.field(sources, source_points=source_points, method=method, merge_tolerance=merge_tolerance,
                           shorten_paths=shorten_paths, progress=progress)
        return field.shortest_path(target)

    def locate(self, points):
        """The surface points closest to 3D points (``(k, 3)`` or ``(3,)``), as :class:`SurfacePoints` (the
        counterpart of CGAL's ``Surface_mesh_shortest_path::locate``): ready for ``source_points=`` and
        :meth:`GeodesicField.distance_at`. An AABB tree of the faces is built at the first call and kept."""
        p = np.asarray(points, dtype=np.float64)
        faces, barycentric = self._surface.locate(p.reshape(1, -1) if p.ndim == 1 else p)
        return SurfacePoints(faces, barycentric)

    def locate_rays(self, origins, directions):
        """The first surface point hit by each ray (``origins`` and ``directions`` ``(k, 3)`` or ``(3,)``), as
        :class:`SurfacePoints`; a ray that misses the surface gets face -1 and NaN coordinates."""
        o, d = (np.asarray(a, dtype=np.float64) for a in (origins, directions))
        faces, barycentric = self._surface.locate_rays(o.reshape(1, -1) if o.ndim == 1 else o,
                                                       d.reshape(1, -1) if d.ndim == 1 else d)
        return SurfacePoints(faces, barycentric)

    def iso_distance_curves(self, distances, levels):
        """The iso-distance curves of per-vertex ``distances`` (``(n,)``, ``inf`` where unreachable) at ``levels``:
        the level sets of the linear interpolation on each face, chained into polylines.

        Returns a list of :class:`IsoCurve` by increasing level (a level may have several curves, or none)."""
        curves = _core.iso_distance_curves(self.vertices, self.faces, distances, np.atleast_1d(levels))
        return [IsoCurve(level, closed, points) for level, closed, points in curves]

    def distance_matrix(self, sources=None, targets=None, *, source_points=None, method="exact",
                        merge_tolerance=0.0, max_distance=None, sparse=False, symmetric=False, threads=0,
                        progress="auto"):
        """Distances from every source (a row each) to every target vertex (a column each).

        Each source is a separate propagation; the rows are computed in parallel (``threads``: 0 = every core,
        1 = sequential) with one solver per thread, and the result does not depend on the thread count.

        Parameters:
            sources: vertex indices (default: every vertex); ``source_points`` adds surface points as further rows.
            targets: vertex indices for the columns (default: every vertex).
            max_distance: entries farther than this are ``inf`` (dense) or absent (sparse).
            sparse: return a ``scipy.sparse.csr_matrix`` holding the entries ``<= max_distance`` (explicit zeros
                included, e.g. a source's own column); absent entries mean "farther than max_distance".
            symmetric: for square matrices whose rows and columns are the same vertices, make the result exactly
                symmetric by taking the smaller of ``D[i, j]`` and ``D[j, i]`` (they differ by rounding only).
            method, merge_tolerance, progress: as in :meth:`distances`.

        Returns:
            A ``(rows, columns)`` float64 array (``inf`` where unreachable) or a ``scipy.sparse.csr_matrix``.
        """
        if sources is None and source_points is None:
            sources = np.arange(self.number_of_vertices)
        vs, pf, pb = _split_sources(sources, source_points)
        if symmetric:
            rows = np.arange(self.number_of_vertices) if vs is None else np.atleast_1d(np.asarray(vs))
            cols = np.arange(self.number_of_vertices) if targets is None else np.atleast_1d(np.asarray(targets))
            if pf is not None or not np.array_equal(rows, cols):
                raise ValueError("mdcs: symmetric=True needs the same vertices as sources and targets")
        with progress_callback(progress, "geodesics") as callback:
            result = self._surface.distance_matrix(vs, pf, pb, targets, method, float(merge_tolerance), max_distance,
                                                   bool(sparse), threads, callback)
        if not sparse:
            if symmetric:
                np.minimum(result, result.T, out=result)
            return result
        import scipy.sparse

        indptr, indices, data, shape = result
        matrix = scipy.sparse.csr_matrix((data, indices, indptr), shape=shape)
        if symmetric:
            matrix = symmetric_minimum(matrix)
        return matrix


def symmetric_minimum(matrix):
    """The sparse matrix whose entry (i, j) is the smaller of the stored entries (i, j) and (j, i), or the one that is
    stored (absent entries mean "unknown", not 0). Explicit zeros are kept. Returns a ``csr_matrix``."""
    import scipy.sparse

    coo = matrix.tocoo()
    rows = np.concatenate([coo.row, coo.col])
    cols = np.concatenate([coo.col, coo.row])
    vals = np.concatenate([coo.data, coo.data])
    order = np.lexsort((cols, rows))
    rows, cols, vals = rows[order], cols[order], vals[order]
    if len(rows) == 0:
        return scipy.sparse.csr_matrix(matrix.shape, dtype=np.float64)
    first = np.ones(len(rows), dtype=bool)
    first[1:] = (rows[1:] != rows[:-1]) | (cols[1:] != cols[:-1])
    starts = np.flatnonzero(first)
    reduced = np.minimum.reduceat(vals, starts)
    out = scipy.sparse.csr_matrix((reduced, (rows[starts], cols[starts])), shape=matrix.shape)
    return out
