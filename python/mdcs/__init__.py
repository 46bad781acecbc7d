# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""MDCS: Minimal Discrete Curves and Surfaces, from Python.

NumPy in and out, the C++ library underneath (pybind11):

- :mod:`mdcs.geodesics`: exact and approximate geodesic distances, shortest paths, distance matrices
  (:class:`mdcs.geodesics.Mesh`);
- :mod:`mdcs.mwt`: minimum weight triangulations of point sets, with certificates;
- :mod:`mdcs.variational`: globally minimal curves and surfaces of variational problems (min-cut on arrangements);
- :mod:`mdcs.silhouettes`: silhouettes of a mesh for a view, simplified through a coarse mesh;
- :mod:`mdcs.min_cut`: minimum s-t cuts / maximum flows of networks given as edge arrays;
- :mod:`mdcs.compat`: drop-in replacements for tvb-gdist (``mdcs.compat.gdist``) and pygeodesic
  (``mdcs.compat.pygeodesic``);
- :mod:`mdcs.dask` (imported on request): distance matrices and any mdcs call over a ``dask.distributed`` cluster.

Long computations release the GIL, stop on Ctrl-C (``KeyboardInterrupt``) and take ``progress=`` (a tqdm bar by
default when tqdm is installed and the call takes more than a second; see :mod:`mdcs._progress`). Bad input raises
``ValueError`` or ``IndexError`` with a message naming the problem.
"""

from . import _mdcs
from ._mdcs import OperationCancelled
from . import geodesics, io, mwt, variational, silhouettes, min_cut
from .geodesics import Mesh

__version__ = _mdcs.__version__

__all__ = ["Mesh", "OperationCancelled", "geodesics", "mwt", "variational", "silhouettes", "min_cut", "io",
           "__version__"]
