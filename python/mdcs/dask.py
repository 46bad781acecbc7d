# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Work beyond one machine: mdcs calls over a ``dask.distributed`` cluster (Debian: python3-distributed).

MDCS does not schedule anything itself: a distance matrix is split into blocks of sources, each block one task
(one ordinary :meth:`mdcs.geodesics.Mesh.distance_matrix` call on a worker), and Dask distributes the tasks.

>>> from dask.distributed import Client, LocalCluster            # doctest: +SKIP
>>> client = Client(LocalCluster(n_workers=2, threads_per_worker=1))
>>> D = mdcs.dask.distance_matrix(client, mesh, sources=range(200))                    # gathered in memory
>>> D = mdcs.dask.distance_matrix(client, mesh, sources=range(200), output="D.npy")    # written as blocks finish
>>> results = mdcs.dask.map(client, mdcs.mwt.minimum_weight_triangulation, point_sets, solver="clp")

- The prepared mesh is sent once to every worker (``client.scatter(..., broadcast=True)``; a :class:`Mesh` pickles
  as its arrays and is prepared again once on each worker), not once per task.
- Blocks are written as they finish: to a ``.npy`` file (each worker writes its rows into the file, which must be
  on a filesystem the workers share with the client, as with a ``LocalCluster``), to a Zarr array (a path ending
  in ``.zarr`` or a ``zarr.Array``; needs python3-zarr; one chunk per block), or gathered into one array.
- Every block is computed with ``threads_per_task`` threads (default 1: one task per Dask worker thread), so the
  cluster's workers and threads decide the parallelism. The values do not depend on how the work is split.
- Ctrl-C in the client cancels the outstanding tasks.
"""

import math
import os

import numpy as np

from . import geodesics
from ._progress import _stderr_is_terminal, _tqdm

__all__ = ["distance_matrix", "map"]


def _as_mesh(mesh):
    if isinstance(mesh, geodesics.Mesh):
        return mesh
    vertices, faces = mesh
    return geodesics.Mesh(vertices, faces)


def _compute_block(mesh, start, sources, targets, method, merge_tolerance, max_distance, sparse, threads, output):
    rows = mesh.distance_matrix(sources, targets, method=method, merge_tolerance=merge_tolerance,
                                max_distance=max_distance, sparse=sparse, threads=threads, progress=False)
    stop = start + len(sources)
    if output is None:
        return start, rows
    kind, path = output
    if kind == "npy":
        target = np.load(path, mmap_mode="r+")
        target[start:stop] = rows
        target.flush()
        del target
    else:
        import zarr

        zarr.open(path, mode="r+")[start:stop] = rows
    return start, None


class _Progress:
    def __init__(self, progress, total, description):
        self.callback = None
        self.bar = None
        self.total = total
        self.done = 0
        if progress is None or progress is False:
            return
        if callable(progress) and not isinstance(progress, (bool, str)):
            self.callback = progress
        elif progress is True or progress == "auto":
            if _tqdm is not None and (progress is True or _stderr_is_terminal()):
                self.bar = _tqdm(total=total, desc=description, delay=0.0 if progress is True else 1.0, leave=False)
        else:
            raise ValueError(f"mdcs: progress must be 'auto', True, False, None or a callable, got {progress!r}")

    def advance(self, stage):
        self.done += 1
        if self.bar is not None:
            self.bar.update(1)
        if self.callback is not None and self.callback(stage, self.done / self.total) is False:
            from . import OperationCancelled

            raise OperationCancelled("mdcs.dask: cancelled by the progress callback")

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _gather_as_completed(client, futures, progress, stage, handle):
    from distributed import as_completed

    reporter = _Progress(progress, len(futures), stage)
    try:
        for future in as_completed(futures):
            handle(future.result())
            reporter.advance(stage)
    except BaseException:
        client.cancel(futures)
        raise
    finally:
        reporter.close()


def distance_matrix(client, mesh, sources=None, targets=None, *, method="exact", merge_tolerance=0.0,
                    max_distance=None, sparse=False, block_size=None, output=None, threads_per_task=1,
                    progress="auto"):
    """The distance matrix of :meth:`mdcs.geodesics.Mesh.distance_matrix` (rows: sources, columns: targets),
    computed over a Dask cluster in blocks of ``block_size`` sources.

    Parameters:
        client: a ``dask.distributed.Client``.
        mesh: a :class:`mdcs.geodesics.Mesh`, or ``(vertices, faces)``.
        sources, targets: vertex indices (default: every vertex).
        method, merge_tolerance, max_distance: as in :meth:`Mesh.distance_matrix`.
        sparse: blocks as ``scipy.sparse.csr_matrix`` (entries ``<= max_distance``), stacked; only with
            ``output=None``.
        block_size: sources per task (default: about four tasks per worker thread, at most 256 sources each).
        output: ``None`` (gather into memory), a path ending in ``.npy`` (a NumPy file, returned opened as a
            memory map), a path ending in ``.zarr`` or a ``zarr.Array`` of the right shape (returned).
        threads_per_task: threads of each block's computation (0: all cores of the worker).
        progress: a progress bar over the blocks (``"auto"``, ``True``, ``False``/``None``) or a callable
            ``progress("blocks", fraction)`` returning False to cancel.

    Returns:
        A ``(len(sources), len(targets))`` float64 array (``inf`` where unreachable or beyond ``max_distance``), a
        ``numpy.memmap`` of the ``.npy`` file, a ``zarr.Array``, or a ``scipy.sparse.csr_matrix``.
    """
    mesh = _as_mesh(mesh)
    n = mesh.number_of_vertices
    sources = np.arange(n) if sources is None else np.atleast_1d(np.asarray(sources))
    columns = n if targets is None else len(np.atleast_1d(targets))
    rows = len(sources)
    if rows == 0:
        raise ValueError("mdcs.dask: no source was given")
    # Validate everything once, here, rather than in every task.
    mesh.distances(sources[:1], targets=targets, method=method, merge_tolerance=merge_tolerance,
                   max_distance=max_distance, progress=False)
    if sources.dtype.kind not in "iu" or sources.min() < 0 or sources.max() >= n:
        raise IndexError(f"mdcs.dask: sources must be vertex indices in 0..{n - 1}")
    if sparse and output is not None:
        raise ValueError("mdcs.dask: sparse blocks are gathered in memory (output=None)")
    if block_size is None:
        workers = max(1, sum(client.nthreads().values()))
        block_size = min(256, max(1, math.ceil(rows / (4 * workers))))
    block_size = int(block_size)
    if block_size < 1:
        raise ValueError("mdcs.dask: block_size must be at least 1")

    result, spec = None, None
    if output is not None:
        if hasattr(output, "shape") and hasattr(output, "chunks"):  # a zarr.Array
            if tuple(output.shape) != (rows, columns):
                raise ValueError(f"mdcs.dask: the Zarr array has shape {output.shape}, ({rows}, {columns}) needed")
            store_path = getattr(output.store, "path", None)
            if store_path is None:
                raise ValueError("mdcs.dask: the workers write the Zarr array in place: it must live in a directory "
                                 "store (zarr.open(path, ...)) on a filesystem they share")
            if output.path:
                store_path = os.path.join(store_path, output.path)
            result, spec = output, ("zarr", store_path)
        else:
            path = os.fspath(output)
            if path.endswith(".npy"):
                np.lib.format.open_memmap(path, mode="w+", dtype=np.float64, shape=(rows, columns)).flush()
                spec = ("npy", os.path.abspath(path))
            elif path.endswith(".zarr"):
                try:
                    import zarr
                except ImportError:
                    raise ImportError("mdcs.dask: Zarr output needs the zarr package (Debian: python3-zarr)") from None
                result = zarr.open(path, mode="w", shape=(rows, columns), chunks=(block_size, columns),
                                   dtype=np.float64)
                spec = ("zarr", os.path.abspath(path))
            else:
                raise ValueError("mdcs.dask: output must end in .npy or .zarr, or be a zarr.Array")

    mesh_future = client.scatter(mesh, broadcast=True)
    futures = []
    for start in range(0, rows, block_size):
        block = sources[start:start + block_size]
        futures.append(client.submit(_compute_block, mesh_future, start, block, targets, method, merge_tolerance,
                                     max_distance, sparse, int(threads_per_task), spec, pure=False))

    blocks = {}
    if output is None and not sparse:
        result = np.empty((rows, columns), dtype=np.float64)

    def handle(done):
        start, values = done
        if values is None:
            return
        if sparse:
            blocks[start] = values
        else:
            result[start:start + values.shape[0]] = values

    _gather_as_completed(client, futures, progress, "blocks", handle)
    if sparse:
        import scipy.sparse

        return scipy.sparse.vstack([blocks[s] for s in sorted(blocks)], format="csr")
    if spec is not None and spec[0] == "npy":
        return np.load(spec[1], mmap_mode="r")
    return result


def map(client, function, *iterables, progress="auto", **kwargs):
    """Runs ``function(*args, **kwargs)`` for every tuple of ``args`` from ``iterables`` on the cluster and returns
    the results in order (a list), e.g. ``mdcs.dask.map(client, mdcs.mwt.minimum_weight_triangulation, point_sets)``
    or a function of your own that builds a :class:`mdcs.geodesics.Mesh` from each input. The results must pickle
    (the result classes of mdcs do; :class:`mdcs.geodesics.GeodesicField` does not). An exception of a task is
    raised here; Ctrl-C cancels the outstanding tasks."""
    futures = client.map(function, *iterables, pure=False, **kwargs)
    index = {f.key: i for i, f in enumerate(futures)}
    results = [None] * len(futures)
    if not futures:
        return results

    from distributed import as_completed

    reporter = _Progress(progress, len(futures), "tasks")
    try:
        for future in as_completed(futures):
            results[index[future.key]] = future.result()
            reporter.advance("tasks")
    except BaseException:
        client.cancel(futures)
        raise
    finally:
        reporter.close()
    return results
