"""Keeping freed memory for reuse while meshes of millions of faces are built (glibc).

glibc's malloc hands arrays above its mmap threshold (at most 32 MiB by
default) to the kernel when they are freed, and gets fresh, zeroed pages for
the next one.  A pipeline over millions of faces frees and allocates
hundreds of such arrays, and on a virtual machine a fresh page costs about a
nanosecond per byte: at 5.2 million triangles that makes the time per face
1.3-1.9x what it is at 327,680 (``benchmarks/bench_pipeline.py``).

:func:`keep_freed_memory` serves every array from malloc's heap and keeps
what is freed for the next allocation while its block runs, then gives the
free memory back to the system (``malloc_trim``).  The settings are
process-wide, so pentanb never changes them on its own: this is an opt-in
for a notebook that builds very large meshes.  The environment variables
``MALLOC_MMAP_THRESHOLD_`` and ``MALLOC_TRIM_THRESHOLD_`` do the same for a
whole process, but must be set before Python starts, which a running
Jupyter kernel cannot do.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import platform
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["keep_freed_memory", "supported"]

# mallopt parameters (malloc.h)
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3

#: While the block runs: arrays below 2 GiB from the heap, freed memory never
#: trimmed (mallopt takes a C int: -1 is the largest size_t, "never")
_KEEP = {_M_MMAP_THRESHOLD: 2**31 - 1, _M_TRIM_THRESHOLD: -1}
#: After it: the values glibc's dynamic thresholds reach in a numpy session
#: (arrays up to 32 MiB from the heap, the heap trimmed beyond 64 MiB free).
_AFTER = {_M_MMAP_THRESHOLD: 32 << 20, _M_TRIM_THRESHOLD: 64 << 20}

_lock = threading.Lock()
_state: dict[str, Any] = {"depth": 0, "libc": None, "looked": False}


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
    """Whether :func:`keep_freed_memory` changes anything here (Linux with glibc)."""
    return _glibc() is not None


def _set(libc: Any, values: dict[int, int]) -> None:
    for param, value in values.items():
        if not libc.mallopt(param, value):
            raise OSError(f"glibc refused mallopt({param}, {value})")


@contextmanager
def keep_freed_memory() -> Iterator[bool]:
    """Within the block, malloc serves arrays from its heap and keeps freed memory.

    For building meshes of millions of faces: each large temporary reuses
    memory freed by the one before instead of pages the kernel must hand
    over fresh.  Measured (``benchmarks/bench_pipeline.py``): the time per
    face of the pipeline at 5.2 million triangles over that at 327,680 goes
    from 1.3-1.9x to about 1.0x.  On leaving the block (also by an
    exception) the free memory goes back to the system, and malloc keeps
    arrays up to 32 MiB on its heap, as its dynamic thresholds do in a
    numpy session.  Blocks may nest (the outermost one decides) and may be
    entered from several threads (the settings are the process's).

    Put the whole of the large work in one block, not each call in its
    own: leaving a block gives the memory back, so the next block starts
    with fresh pages again (and for small meshes, which malloc already
    serves from its heap, a block only adds that cost).

    Yields
    ------
    bool
        Whether anything changed: False where malloc is not glibc's (macOS,
        Windows, musl), where the block does nothing.

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
            try:
                _set(libc, _KEEP)
            except OSError:  # refused: undo what was set, enter nothing
                for param, value in _AFTER.items():
                    libc.mallopt(param, value)
                raise
        _state["depth"] += 1
    try:
        yield True
    finally:
        with _lock:
            _state["depth"] -= 1
            if _state["depth"] == 0:
                _set(libc, _AFTER)
                libc.malloc_trim(0)
