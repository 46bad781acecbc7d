# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A drop-in replacement for ``pygeodesic.geodesic``, on MDCS's exact geodesics.

``PyGeodesicAlgorithmExact(points, faces)`` prepares the mesh once; ``geodesicDistance(source, target)`` returns the
distance and the path (an ``(k, 3)`` array of points from the target to the source: vertices and edge crossings);
``geodesicDistances(source_indices=None, target_indices=None, max_distance=inf)`` returns the distance of every
target (default: every vertex) to the nearest source (default: vertex 0) and the index of that source in
``source_indices``. ``read_mesh_from_file(filename)`` reads the text format of the original C++ library's examples
(a line "<points> <faces>", then one point and one triangle per line); OFF, PLY, OBJ and STL files are read too.

Deliberate differences:

- Bad input raises ``ValueError`` or ``IndexError`` naming the problem; pygeodesic prints a message and returns
  ``None`` (or ``(None, None)``), or crashes on indices it does not check.
- Unreachable targets (another connected component, or beyond ``max_distance``) have distance ``inf`` and best
  source ``-1``; ``geodesicDistance`` returns ``(inf, empty (0, 3) array)`` for them (pygeodesic issues 11, 14).
- ``max_distance`` stops the propagation; farther targets get ``inf`` (pygeodesic issue 13).
- ``geodesicDistance`` returns the geodesic distance computed by the propagation; the length of the returned path
  equals it up to rounding.
- Meshes whose vertices are not all used by faces are accepted (unused vertices are unreachable).
"""

import os

import numpy

from ... import geodesics

__all__ = ["PyGeodesicAlgorithmExact", "read_mesh_from_file"]


class PyGeodesicAlgorithmExact:
    """Exact geodesic distances and paths on a triangle mesh.

    Usage::

        >>> import mdcs.compat.pygeodesic.geodesic as geodesic
        >>> geoalg = geodesic.PyGeodesicAlgorithmExact(points, faces)
        >>> distance, path = geoalg.geodesicDistance(0, 100)

    Args:
        points (array-like, float, (n, 3)): the vertex coordinates.
        faces (array-like, int, (m, 3)): the triangles as vertex index triples.
    """

    def __init__(self, points, faces):
        self._mesh = geodesics.Mesh(points, faces)

    def _vertex(self, index, name):
        if isinstance(index, (bool, numpy.bool_)) or not isinstance(index, (int, numpy.integer)):
            raise ValueError(f"mdcs.compat.pygeodesic: '{name}' must be an integer vertex index, got {index!r}")
        index = int(index)
        if not 0 <= index < self._mesh.number_of_vertices:
            raise IndexError(f"mdcs.compat.pygeodesic: '{name}' = {index} is outside the limits of the mesh "
                             f"(0..{self._mesh.number_of_vertices - 1})")
        return index

    def geodesicDistance(self, sourceIndex, targetIndex):
        """The geodesic distance from vertex ``sourceIndex`` to vertex ``targetIndex`` and the path between them.

        Returns:
            path_length (float): the geodesic distance (``inf`` when the target is unreachable);
            path_points (numpy.ndarray, (k, 3)): the points of the path from the target to the source (vertices and
            edge crossings; empty when unreachable).
        """
        source = self._vertex(sourceIndex, "sourceIndex")
        target = self._vertex(targetIndex, "targetIndex")
        field = self._mesh.field(source, progress=False)
        distance = float(field.distances[target])
        if not numpy.isfinite(distance):
            return distance, numpy.zeros((0, 3))
        path = field.shortest_path(target)
        return distance, numpy.array(path.points)

    def geodesicDistances(self, source_indices=None, target_indices=None, max_distance=numpy.inf):
        """The distance of each target vertex to the nearest source vertex, and which source that is.

        Args:
            source_indices (array-like, int): the source vertices (default: vertex 0).
            target_indices (array-like, int): the target vertices (default: every vertex).
            max_distance (float): stop the propagation at this distance; farther targets get ``inf``.

        Returns:
            distances (numpy.ndarray, float64): the distance of each target (``inf`` where unreachable);
            best_source (numpy.ndarray, int32): the index into ``source_indices`` of each target's nearest source
            (-1 where unreachable).
        """
        sources = numpy.zeros(1, dtype=numpy.int64) if source_indices is None else numpy.atleast_1d(source_indices)
        max_distance = float(max_distance)
        limit = None if max_distance >= 1e100 else max_distance
        distances, best = self._mesh.distances(sources, targets=target_indices, max_distance=limit,
                                               return_nearest=True, progress=False)
        return distances, best.astype(numpy.int32)


def _read_text_mesh(filename):
    with open(filename, "r") as f:
        lines = [line.split() for line in f]
    lines = [line for line in lines if line]
    if not lines:
        raise ValueError(f"mdcs.compat.pygeodesic: {filename} is empty")
    try:
        numpoints, numfaces = (int(v) for v in lines[0])
    except ValueError:
        raise ValueError(f"mdcs.compat.pygeodesic: the first line of {filename} must hold the number of points and "
                         f"the number of faces, got {' '.join(lines[0])!r}") from None
    if numpoints < 3 or numfaces < 1:
        raise ValueError(f"mdcs.compat.pygeodesic: {filename} declares {numpoints} points and {numfaces} faces "
                         "(at least 3 points and 1 face are needed)")
    if len(lines) < 1 + numpoints + numfaces:
        raise ValueError(f"mdcs.compat.pygeodesic: {filename} declares {numpoints} points and {numfaces} faces but "
                         f"has only {len(lines) - 1} data lines")

    def rows(first, count, kind, convert):
        out = []
        for i in range(first, first + count):
            if len(lines[i]) != 3:
                raise ValueError(f"mdcs.compat.pygeodesic: {filename}: {kind} {i - first} has {len(lines[i])} values, "
                                 "3 expected")
            try:
                out.append([convert(v) for v in lines[i]])
            except ValueError:
                raise ValueError(f"mdcs.compat.pygeodesic: {filename}: cannot read {kind} {i - first}: "
                                 f"{' '.join(lines[i])!r}") from None
        return out

    points = numpy.array(rows(1, numpoints, "point", float), dtype=numpy.float64)
    faces = numpy.array(rows(1 + numpoints, numfaces, "face", int), dtype=numpy.int64)
    if not numpy.isfinite(points).all():
        raise ValueError(f"mdcs.compat.pygeodesic: {filename} has a point that is not finite")
    if faces.min() < 0 or faces.max() >= numpoints:
        raise IndexError(f"mdcs.compat.pygeodesic: {filename} has a face with a vertex index outside 0..{numpoints - 1}")
    return points, faces


def read_mesh_from_file(filename):
    """Reads a mesh file: the text format of the original C++ library's examples ("<points> <faces>" on the first
    line, then one point "x y z" and one triangle "i j k" per line, 0-based), or an OFF, PLY, OBJ or STL file.

    Returns:
        (points, faces): a float64 ``(n, 3)`` array and an integer ``(m, 3)`` array.
    """
    extension = os.path.splitext(str(filename))[1].lower()
    if extension in (".off", ".ply", ".obj", ".stl"):
        from ... import io

        return io.read_mesh(filename)
    return _read_text_mesh(filename)
