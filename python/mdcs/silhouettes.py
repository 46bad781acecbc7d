# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Silhouettes of triangle meshes for a view, and simple silhouettes through a coarse mesh
(the C++ package Silhouette_simplification_3).

A view is perspective (``eye=(x, y, z)``) or orthographic (``direction=(dx, dy, dz)``, from the viewer towards the
scene). A face is front-facing when the eye sees its outer side (exact orientation predicate).

- :func:`silhouette_edges`: the edges between a front-facing and a back-facing face (or the border), directed with
  the front-facing side on the left, as vertex pairs (a scan of every face).
- :class:`SilhouetteEdges`: the same for many views of one mesh: a bounding-cone hierarchy over its edges is built
  once, and each view skips the groups of faces that provably all face the same way (the same edges in the same
  order as :func:`silhouette_edges`, far quicker per view on large meshes).
- :class:`Simplifier`: built once per mesh (a coarse mesh by edge collapses, the fine-to-coarse face map); then
  :meth:`Simplifier.silhouette` gives for any view the fine silhouette's loops, the loops picked among them to
  follow the coarse silhouette (method A), and the coarse loops mapped onto the fine mesh by minimum cuts (method B,
  the simple silhouette: few long loops, made of fine mesh edges).

Loops are ``(vertices, closed)`` pairs: the fine mesh's vertex indices along the loop.
"""

import dataclasses

import numpy as np

from . import _mdcs
from ._progress import progress_callback

__all__ = ["silhouette_edges", "SilhouetteEdges", "Simplifier", "SilhouetteLoops"]

_core = _mdcs.silhouettes


def silhouette_edges(vertices, faces, *, eye=None, direction=None):
    """The silhouette edges of the mesh for a view: an ``(k, 2)`` int64 array of directed vertex pairs (the
    front-facing face on the left). Give ``eye`` (perspective) or ``direction`` (orthographic)."""
    return _core.silhouette_edges(vertices, faces, eye, direction)


class SilhouetteEdges:
    """Silhouette edges of one triangle mesh (``vertices (n, 3)``, ``faces (m, 3)``) for many views.

    The constructor builds a bounding-cone hierarchy over the mesh's edges (the C++
    ``Silhouette_edge_hierarchy_3``, thesis 5.1 after Sander et al. 2000); :meth:`edges` then returns for a view
    exactly what :func:`silhouette_edges` returns (the same directed vertex pairs in the same order: leaves are
    classified with the same exact predicate) without classifying every face, and without copying the mesh again
    (which :func:`silhouette_edges` does at every call). Worth it from two views on: the build costs about as much
    as two calls of :func:`silhouette_edges`. Queries release the GIL and may run from several threads at once.

    Raises ValueError for the inputs :func:`silhouette_edges` refuses and for a mesh whose coordinates are not
    finite or whose bounding box diagonal is outside [1e-30, 1e30].
    """

    def __init__(self, vertices, faces):
        self._core = _core.SilhouetteEdges(vertices, faces)

    @property
    def number_of_faces(self):
        """Faces of the mesh as built (vertices of non-manifold input may be split, faces are not)."""
        return self._core.number_of_faces

    @property
    def number_of_nodes(self):
        """Nodes of the hierarchy."""
        return self._core.number_of_nodes

    def edges(self, *, eye=None, direction=None):
        """The silhouette edges for a view: an ``(k, 2)`` int64 array of directed vertex pairs (the front-facing
        face on the left), equal to ``silhouette_edges(vertices, faces, eye=eye, direction=direction)``. Give
        ``eye`` (perspective) or ``direction`` (orthographic)."""
        return self._core.edges(eye, direction)


@dataclasses.dataclass
class SilhouetteLoops:
    """The silhouettes of one view.

    Attributes:
        fine: the loops of the fine mesh's silhouette, as ``(vertex indices, closed)`` pairs.
        picked: method A: the fine loops picked to follow the coarse silhouette.
        mapped: method B: the coarse loops mapped onto fine mesh edges (the simple silhouette).
        coarse: the coarse silhouette's loops as ``(points (k, 3), closed)`` pairs.
        picking_error: method A's final sum of squared distances.
        fine_silhouette_edges, coarse_silhouette_edges: edge counts of the two silhouettes.
    """

    fine: list
    picked: list
    mapped: list
    coarse: list
    picking_error: float
    fine_silhouette_edges: int
    coarse_silhouette_edges: int


class Simplifier:
    """Simple silhouettes of a fine mesh (``vertices (n, 3)``, ``faces (m, 3)``, a closed or open triangle mesh)
    through a coarse mesh of about ``target_faces`` faces, built once (``smoothing_iterations`` of Taubin
    smoothing afterwards).

    With ``hierarchy=True`` a bounding-cone hierarchy over the fine mesh's edges is built as well (as
    :class:`SilhouetteEdges` does) and every view finds its fine silhouette through it instead of classifying
    every fine face: the silhouettes are identical, each view is quicker on a large fine mesh."""

    def __init__(self, vertices, faces, *, target_faces=1000, smoothing_iterations=3, hierarchy=False,
                 progress="auto"):
        if not isinstance(hierarchy, (bool, np.bool_)):
            raise ValueError(f"mdcs: hierarchy must be True or False, got {hierarchy!r}")
        with progress_callback(progress, "coarse mesh") as callback:
            self._core = _core.Simplifier(vertices, faces, int(target_faces), int(smoothing_iterations),
                                          bool(hierarchy), callback)

    @property
    def uses_hierarchy(self):
        """Whether the fine silhouettes are found through the bounding-cone hierarchy (``hierarchy=True``)."""
        return self._core.uses_hierarchy

    @property
    def number_of_fine_faces(self):
        return self._core.number_of_fine_faces

    @property
    def number_of_coarse_faces(self):
        return self._core.number_of_coarse_faces

    def coarse_mesh(self):
        """``(vertices, faces, coarse_face_of_fine_face)`` of the coarse mesh."""
        return self._core.coarse_mesh()

    def silhouette(self, *, eye=None, direction=None, alpha=0.1, min_loop_edges=8, threshold=0.004,
                   min_relative_gain=0.002):
        """The silhouettes of one view (:class:`SilhouetteLoops`).

        ``alpha`` (0 < alpha <= 1) is the weight factor of fine silhouette edges in loop mapping (cheaper edges
        attract the mapped loops); ``min_loop_edges``, ``threshold`` and ``min_relative_gain`` control loop
        picking (loops shorter than ``min_loop_edges`` are ignored; picking stops when the RMS distance to the
        coarse silhouette is below ``threshold`` times the bounding box diagonal or improves by less than
        ``min_relative_gain``)."""
        return SilhouetteLoops(**self._core.frame(eye, direction, float(alpha), int(min_loop_edges), float(threshold),
                                                  float(min_relative_gain)))
