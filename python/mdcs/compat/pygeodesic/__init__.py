# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A drop-in replacement for pygeodesic, on MDCS's exact geodesics.

Switch with one import line::

    import mdcs.compat.pygeodesic.geodesic as geodesic   # instead of: import pygeodesic.geodesic as geodesic
    import mdcs.compat.pygeodesic as pygeodesic           # instead of: import pygeodesic

``geodesic.PyGeodesicAlgorithmExact`` (``geodesicDistance``, ``geodesicDistances``) and
``geodesic.read_mesh_from_file`` behave as pygeodesic documents them; see :mod:`mdcs.compat.pygeodesic.geodesic`
for the deliberate differences. ``__version__`` is the pygeodesic version whose API this module follows.
"""

from . import geodesic
from .geodesic import PyGeodesicAlgorithmExact, read_mesh_from_file

#: The pygeodesic release whose API this module follows (MDCS's own version is mdcs.__version__).
__version__ = "0.1.11"

__all__ = ["geodesic", "PyGeodesicAlgorithmExact", "read_mesh_from_file", "__version__"]
