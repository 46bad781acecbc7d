# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Progress reporting of long computations.

Every long call of mdcs takes ``progress=``:

- ``"auto"`` (the default): a tqdm progress bar on stderr that appears only when the call runs longer than a second
  and stderr is a terminal (nothing in logs, pipes or when tqdm is not installed);
- ``True``: a tqdm progress bar from the start;
- ``False`` or ``None``: nothing;
- a callable ``progress(stage: str, fraction: float)``: called with the stage name and the completed fraction of
  that stage, a few times per second at most; returning ``False`` cancels the computation, which then raises
  :class:`mdcs.OperationCancelled`.

Whatever is chosen, Ctrl-C (SIGINT) stops a running computation within a fraction of a second and raises
``KeyboardInterrupt``: the C++ code checks for signals while it works, without the GIL.
"""

import contextlib
import sys

try:  # optional dependency (Debian: python3-tqdm)
    from tqdm import tqdm as _tqdm
except ImportError:  # pragma: no cover - depends on the machine
    _tqdm = None

__all__ = ["progress_callback"]


class _TqdmStages:
    """A tqdm bar per stage of a computation, in percent."""

    def __init__(self, description, delay):
        self._description = description
        self._delay = delay
        self._stage = None
        self._bar = None

    def __call__(self, stage, fraction):
        if stage != self._stage:
            self.close()
            self._stage = stage
            label = f"{self._description}: {stage}" if self._description else stage
            self._bar = _tqdm(total=100, desc=label, unit="%", delay=self._delay, leave=False,
                              bar_format="{l_bar}{bar}| {elapsed}<{remaining}")
        done = min(100, max(0, int(fraction * 100)))
        if done > self._bar.n:
            self._bar.update(done - self._bar.n)
        return True

    def close(self):
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _stderr_is_terminal():
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


@contextlib.contextmanager
def progress_callback(progress, description=""):
    """The callable handed to the C++ core for ``progress`` (see the module documentation), as a context manager
    that closes the progress bars when the call ends."""
    if progress is None or progress is False:
        yield None
        return
    if callable(progress) and not isinstance(progress, (bool, str)):
        yield progress
        return
    if progress is True or progress == "auto":
        if _tqdm is None or (progress == "auto" and not _stderr_is_terminal()):
            yield None
            return
        bars = _TqdmStages(description, 0.0 if progress is True else 1.0)
        try:
            yield bars
        finally:
            bars.close()
        return
    raise ValueError(f"mdcs: progress must be 'auto', True, False, None or a callable, got {progress!r}")
