# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Silhouettes of triangle meshes for a view, and simple silhouettes through a coarse mesh
(the C++ package Silhouette_simplification_3).

A view is perspective (``eye=(x, y, z)``) or orthographic (``direction=(dx, dy, dz)``, from the viewer towards the
scene). A face is front-facing when the eye sees its outer side (exact orientation predicate).

- :func:`silhouette_edges`: the edges between a front-facing and a back-facing face (or the border), directed with
  the front-facing side on the left, as vertex pairs.
- :class:`Simplifier`: built once per mesh (a coarse mesh by edge collapses, the fine-to-coarse face map); then
  :meth:`Simplifier.silhouette` gives for any view the fine silhouette's loops, the loops picked among them to
  follow the coarse silhouette (method A), and the coarse loops mapped onto the fine mesh by minimum cuts (method B,
  the simple silhouette: few long loops, made of fine mesh edges).

Loops are ``(vertices, closed)`` pairs: the fine mesh's vertex indices along the loop.
"""

import dataclasses

from . import _mdcs
from ._progress import progress_callback

__all__ = ["silhouette_edges", "Simplifier", "SilhouetteLoops"]

_core = _mdcs.silhouettes


def silhouette_edges(vertices, faces, *, eye=None, direction=None):
    """The silhouette edges of the mesh for a view: an ``(k, 2)`` int64 array of directed vertex pairs (the
    front-facing face on the left). Give ``eye`` (perspective) or ``direction`` (orthographic)."""
    return _core.silhouette_edges(vertices, faces, eye, direction)


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
    smoothing afterwards)."""

    def __init__(self, vertices, faces, *, target_faces=1000, smoothing_iterations=3, progress="auto"):
        with progress_callback(progress, "coarse mesh") as callback:
            self._core = _core.Simplifier(vertices, faces, int(target_faces), int(smoothing_iterations), callback)

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
