"""Keeping freed memory for reuse while meshes of millions of faces are built (glibc).

glibc's malloc hands arrays above its mmap threshold (at most 32 MiB by
default) to the kernel when they are freed, and gets fresh, zeroed pages for
the next one.  A pipeline over millions of faces frees and allocates
hundreds of such arrays, and on a virtual machine a fresh page costs about a
nanosecond per byte: at 5.2 million triangles that made the time per face
1.3-1.9x what it is at 327,680 (``benchmarks/bench_pipeline.py``), a third
of it spent in the kernel.

Two ways to keep freed memory for the next array, both through glibc's
``mallopt`` (process-wide settings) and both ending with ``malloc_trim``,
which gives the free memory back to the system:

* **by itself**: an operator that starts on a mesh of at least
  :data:`AUTO_HALFEDGES` half-edges (where numpy's temporaries pass glibc's
  own 32 MiB threshold) switches the settings on, and a background thread
  switches them back :data:`DEFAULT_SECONDS` seconds after the last such
  operator is expected to have ended, like the decay with which jemalloc
  returns dirty pages.  The interactive explorer does the same after every
  slider move, whatever its size (:func:`note_interaction`).
  ``PENTANB_KEEP_FREED`` sets those seconds (``0``: never by itself);
  :func:`release_freed_memory` gives the memory back at once.  Operators on
  meshes below the threshold never touch the settings.
* **on request**: :func:`keep_freed_memory`, a block that keeps freed memory
  while it runs and gives it back when it ends.

The environment variables ``MALLOC_MMAP_THRESHOLD_`` and
``MALLOC_TRIM_THRESHOLD_`` do the same for a whole process, but must be set
before Python starts, which a running Jupyter kernel cannot do.  Elsewhere
(macOS, Windows, musl) nothing changes.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import math
import os
import platform
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = [
    "AUTO_HALFEDGES",
    "DEFAULT_SECONDS",
    "keep_freed_memory",
    "note_interaction",
    "note_work",
    "release_freed_memory",
    "seconds",
    "supported",
]

# mallopt parameters (malloc.h)
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3

#: While freed memory is kept: arrays below 2 GiB from the heap, freed memory
#: never trimmed (mallopt takes a C int: -1 is the largest size_t, "never")
_KEEP = {_M_MMAP_THRESHOLD: 2**31 - 1, _M_TRIM_THRESHOLD: -1}
#: After: the values glibc's dynamic thresholds reach in a numpy session
#: (arrays up to 32 MiB from the heap, the heap trimmed beyond 64 MiB free).
_AFTER = {_M_MMAP_THRESHOLD: 32 << 20, _M_TRIM_THRESHOLD: 64 << 20}

#: An operator on at least this many half-edges keeps freed memory by itself:
#: its int64 temporaries of one entry per half-edge are 32 MiB, glibc's
#: largest own threshold, and come as fresh pages otherwise.
AUTO_HALFEDGES = 1 << 22
#: Seconds freed memory is kept after the last large operator, by default.
DEFAULT_SECONDS = 10.0
#: A generous bound on an operator's time per half-edge: the keeping lasts at
#: least this long per half-edge of its input, so that it does not end
#: while the operator is still running.
_SECONDS_PER_HALFEDGE = 1e-6
_ENV = "PENTANB_KEEP_FREED"

_lock = threading.Lock()
_wake = threading.Condition(_lock)
#: depth: keep_freed_memory blocks running; on: the keep settings are set;
#: until: (monotonic clock) when operators stop asking for them; reaper: the
#: thread that switches them off then.
_state: dict[str, Any] = {
    "depth": 0,
    "libc": None,
    "looked": False,
    "on": False,
    "until": 0.0,
    "reaper": None,
}


def _glibc() -> Any | None:
    """The C library, when it is glibc with ``mallopt`` and ``malloc_trim``; else None."""
    if not _state["looked"]:
        _state["looked"] = True
        if platform.system() == "Linux" and platform.libc_ver()[0] == "glibc":
            try:
                libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
                libc.mallopt.argtypes = [ctypes.c_int, ctypes.c_int]
                libc.malloc_trim.argtypes = [ctypes.c_size_t]
                _state["libc"] = libc
            except (OSError, AttributeError):
                _state["libc"] = None
    return _state["libc"]


def supported() -> bool:
    """Whether keeping freed memory changes anything here (Linux with glibc)."""
    return _glibc() is not None


def seconds() -> float:
    """Seconds freed memory is kept after the last large operator.

    ``PENTANB_KEEP_FREED`` when set (a number of seconds; ``0``: never keep
    freed memory by itself), else :data:`DEFAULT_SECONDS`.

    Raises
    ------
    ValueError
        ``PENTANB_KEEP_FREED`` is not a finite number of seconds >= 0.
    """
    flag = os.environ.get(_ENV, "").strip()
    if not flag:
        return DEFAULT_SECONDS
    try:
        value = float(flag)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value >= 0):
        raise ValueError(
            f"{_ENV} must be a number of seconds >= 0 (0: never keep freed memory "
            f"by itself), got {flag!r}"
        )
    return value


def _set(libc: Any, values: dict[int, int]) -> None:
    for param, value in values.items():
        if not libc.mallopt(param, value):
            raise OSError(f"glibc refused mallopt({param}, {value})")


def _switch_on(libc: Any) -> None:
    """The keep settings (lock held); refused: what was set undone, OSError."""
    if not _state["on"]:
        try:
            _set(libc, _KEEP)
        except OSError:
            for param, value in _AFTER.items():
                libc.mallopt(param, value)
            raise
        _state["on"] = True


def _switch_off(libc: Any) -> None:
    """Back to glibc's settings, the free memory given back (lock held)."""
    if _state["on"]:
        _state["on"] = False
        _set(libc, _AFTER)
        libc.malloc_trim(0)


def _settled() -> bool:
    """Nothing asks to keep freed memory any longer (lock held)."""
    return _state["depth"] == 0 and time.monotonic() >= _state["until"]


def _reap() -> None:
    """The reaper thread: switch off once operators stopped asking, then end."""
    with _wake:
        while True:
            wait = _state["until"] - time.monotonic()
            if wait > 0:
                _wake.wait(wait)
                continue
            libc = _state["libc"]
            if _state["depth"] == 0 and libc is not None:
                _switch_off(libc)
            _state["reaper"] = None
            return


def note_work(n_halfedges: int) -> None:
    """An operator starts on a mesh of ``n_halfedges`` half-edges.

    From :data:`AUTO_HALFEDGES` on, malloc keeps freed memory from now until
    :func:`seconds` after the operator is expected to end (a background
    thread then gives it back).  Below, or with ``PENTANB_KEEP_FREED=0``, or
    without glibc, nothing happens.  A setting glibc refuses is left as it
    was: the operator runs on as it would have.

    Raises
    ------
    ValueError
        ``PENTANB_KEEP_FREED`` is not a number of seconds >= 0 (only read
        from :data:`AUTO_HALFEDGES` on).
    """
    if n_halfedges >= AUTO_HALFEDGES:
        _keep_for(seconds(), n_halfedges * _SECONDS_PER_HALFEDGE)


def note_interaction() -> None:
    """A widget starts work the user waits for (a slider move), whatever its size.

    Malloc keeps freed memory until :func:`seconds` after it, so that the
    next move reuses this one's arrays instead of pages the kernel hands
    over fresh (a few MB per move at 20,480 faces, ~2,000 page faults for
    pentagon preservation).

    Raises
    ------
    ValueError
        ``PENTANB_KEEP_FREED`` is not a number of seconds >= 0.
    """
    _keep_for(seconds(), 0.0)


def _keep_for(keep: float, expected: float) -> None:
    """Keep freed memory from now until ``expected + keep`` seconds from now."""
    libc = _glibc() if keep > 0 else None
    if libc is None:
        return
    with _wake:
        _state["until"] = max(_state["until"], time.monotonic() + expected + keep)
        try:
            _switch_on(libc)
        except OSError:
            return
        if _state["reaper"] is None:
            reaper = threading.Thread(target=_reap, name="pentanb-keep-freed", daemon=True)
            _state["reaper"] = reaper
            reaper.start()


def release_freed_memory() -> bool:
    """Give the memory kept for reuse back to the system now.

    Ends what large operators switched on by themselves (see
    :func:`note_work`); inside a :func:`keep_freed_memory` block the memory
    is kept until the block ends.

    Returns
    -------
    bool
        Whether the memory went back now: False inside a block, or where
        malloc is not glibc's.

    Examples
    --------
    After building (and dropping) a mesh of millions of faces, to see the
    process's memory fall at once rather than some seconds later::

        import pentanb as pb
        pb.release_freed_memory()
    """
    libc = _glibc()
    if libc is None:
        return False
    with _wake:
        _state["until"] = 0.0
        _wake.notify_all()
        if _state["depth"]:
            return False
        _switch_off(libc)
        return True


@contextmanager
def keep_freed_memory() -> Iterator[bool]:
    """Within the block, malloc serves arrays from its heap and keeps freed memory.

    For building meshes of millions of faces: each large temporary reuses
    memory freed by the one before instead of pages the kernel must hand
    over fresh.  Operators on meshes of at least :data:`AUTO_HALFEDGES`
    half-edges already do this by themselves for the few seconds around
    them (see :func:`note_work`); a block also covers the work between
    them, and a mesh below that size.  Measured
    (``benchmarks/bench_pipeline.py``): the time per face of the pipeline
    at 5.2 million triangles over that at 327,680 goes from 1.3-1.9x,
    keeping nothing, to about 1.0x.  On leaving the block (also by an
    exception) the free memory goes back to the system, unless a large
    operator asked to keep it a while longer, and malloc keeps arrays up to
    32 MiB on its heap, as its dynamic thresholds do in a numpy session.
    Blocks may nest (the outermost one decides) and may be entered from
    several threads (the settings are the process's).

    Put the whole of the large work in one block, not each call in its
    own: leaving a block gives the memory back, so the next block starts
    with fresh pages again.

    Yields
    ------
    bool
        Whether anything changed: False where malloc is not glibc's (macOS,
        Windows, musl), where the block does nothing.

    Raises
    ------
    OSError
        glibc refused a setting (what was set is undone first).

    Examples
    --------
    >>> import pentanb as pb
    >>> with pb.keep_freed_memory():
    ...     m = pb.subdivide(pb.shapes.cube(), "pentagonalize", 2)
    >>> m.n_faces
    120
    """
    libc = _glibc()
    if libc is None:
        yield False
        return
    with _lock:
        if _state["depth"] == 0:
            _switch_on(libc)
        _state["depth"] += 1
    try:
        yield True
    finally:
        with _lock:
            _state["depth"] -= 1
            if _settled():
                _switch_off(libc)


def _after_fork_in_child() -> None:
    """A forked child has no reaper and a fresh lock; it stops keeping unless in a block."""
    global _lock, _wake
    _lock = threading.Lock()
    _wake = threading.Condition(_lock)
    _state["reaper"] = None
    _state["until"] = 0.0
    libc = _state["libc"]
    if libc is not None and _state["depth"] == 0 and _state["on"]:
        _state["on"] = False
        for param, value in _AFTER.items():
            libc.mallopt(param, value)


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_after_fork_in_child)
