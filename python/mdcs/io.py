# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Mesh files: :func:`read_mesh` reads OFF, PLY, OBJ and STL files as vertex and triangle arrays."""

import os

from . import _mdcs

__all__ = ["read_mesh"]


def read_mesh(path):
    """Reads a mesh file (OFF, PLY, OBJ or STL) and returns ``(vertices, faces)``: a float64 ``(n, 3)`` array and
    an int64 ``(m, 3)`` array of triangles. Faces with more than three corners are triangulated (the file is then
    made into a surface mesh first, which may reorder faces). Unreadable files, missing files, faces with fewer
    than three corners, indices out of range or non-finite coordinates raise ``ValueError``."""
    return _mdcs.io.read_mesh(os.fspath(path))
