"""Optional compiled kernels (numba) for the loops a slider move and a large pipeline spend most in.

pentanb's reference path is numpy.  When `numba <https://numba.pydata.org>`_
is installed (``pip install pentanb[jit]``), a few kernels replace whole-array
passes by one loop each, giving the *same results bit for bit*:

* the mean of the corners of every face (:meth:`pentanb.Mesh.face_centroids`,
  the dual's vertices), summed in the order the numpy path sums them
  (numpy's pairwise bracket for faces of 9 to 129 corners);
* the explorer's WebGL index arrays: the fan triangles of every face and
  the edges, written straight into uint32 (:func:`pentanb.viz.drawing.mesh_buffers`);
* the vertex rings five schemes write for their outputs (the paper's two,
  corner cutting, hexagon preservation, honeycomb), rings turned to start at
  their largest half-edge, the points that split edges,
  pentagon preservation's scaled copies, the new points of corner cutting,
  hexagon preservation and honeycomb, the face of every half-edge and the
  dual's faces gathered from it;
* twin pairing, by a counting sort of the half-edges on their tails (linear,
  where the numpy path sorts packed keys), refusing exactly what it refuses.

They run only on meshes of at least :data:`MIN_CORNERS` corners, where a
compiled loop pays for itself; smaller meshes never load numba.  The first
use in a process compiles the kernels it needs (about 2 s for an explorer's
first move with an empty cache); numba caches the machine code on disk, so
later processes load it.

Kernels whose items are independent (faces, edges, vertices, ring
entries) release the GIL and cut their items into one part per CPU
(:func:`threads`: at most 8, or ``PENTANB_THREADS``), run at once by worker threads
(:func:`split`; fewer than :data:`MIN_SPLIT` items stay on one thread).
Each part writes its own rows, so the results do not depend on the number
of threads.  A forked child starts threads of its own.

Switch them with the environment variable ``PENTANB_JIT`` (``0``: off,
``1``: on, refused without numba), read when first needed, or at run time
with :func:`pentanb.use_jit`.  ``benchmarks/bench_pipeline.py`` reports both paths.
"""

from __future__ import annotations

import atexit
import importlib.util
import os
import threading
import types
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = ["MIN_CORNERS", "MIN_SPLIT", "available", "enabled", "use_jit", "kernels", "threads"]

#: Meshes with fewer corners than this keep the numpy path.
MIN_CORNERS = 1 << 14

_state: dict[str, Any] = {"on": None, "kernels": None}


def available() -> bool:
    """True when numba is installed (found, not imported: importing it takes a while)."""
    try:
        return importlib.util.find_spec("numba") is not None
    except (ImportError, ValueError):  # a module "numba" set to None, or without a spec
        return False


def _require() -> None:
    if not available():
        raise ImportError(
            "the compiled kernels need numba, which is not installed: "
            "pip install 'pentanb[jit]' (or set PENTANB_JIT=0)"
        )


def enabled() -> bool:
    """Whether the kernels are used (default: when numba is installed)."""
    if _state["on"] is None:
        flag = os.environ.get("PENTANB_JIT", "").strip().lower()
        if flag in ("0", "false", "no", "off"):
            _state["on"] = False
        elif flag in ("1", "true", "yes", "on"):
            _require()
            _state["on"] = True
        elif flag == "":
            _state["on"] = available()
        else:
            raise ValueError(f"PENTANB_JIT must be 0 or 1, got {flag!r}")
    return bool(_state["on"])


def use_jit(on: bool) -> bool:
    """Use the compiled kernels (True) or the numpy path (False), from now on.

    The kernels give the same results bit for bit; they run on meshes of at
    least :data:`MIN_CORNERS` corners (smaller ones always take numpy).

    Parameters
    ----------
    on : bool

    Returns
    -------
    bool
        The previous choice (to restore it: ``use_jit(previous)``).

    Raises
    ------
    TypeError
        ``on`` is not a bool.
    ImportError
        ``on`` is True and numba is not installed (the message says what to
        install).
    """
    if not isinstance(on, (bool, np.bool_)):
        raise TypeError(f"use_jit() expects True or False, got {type(on).__name__}")
    try:
        before = enabled()
    except ValueError:  # a PENTANB_JIT that is neither 0 nor 1: the call overrides it
        before = False
    if on:
        _require()
    _state["on"] = bool(on)
    return before


def kernels(corners: int) -> Any | None:
    """The compiled kernels for a mesh of ``corners`` corners, or None (use numpy)."""
    if corners < MIN_CORNERS or not enabled():
        return None
    if _state["kernels"] is None:
        try:
            _state["kernels"] = _compile()
        except ImportError as err:  # installed but broken (e.g. built for another numpy)
            warnings.warn(
                f"numba is installed but could not be loaded ({err}); pentanb uses its "
                "numpy path (set PENTANB_JIT=0 to skip the attempt)",
                RuntimeWarning,
                stacklevel=2,
            )
            _state["on"] = False
            return None
    return _state["kernels"]


def threads() -> int:
    """Threads the kernels split their work over.

    ``PENTANB_THREADS`` (a positive integer, at most 64 used) when set, else
    the CPUs this process may use, at most 8.

    Raises
    ------
    ValueError
        ``PENTANB_THREADS`` is set to anything but a positive integer.
    """
    flag = os.environ.get("PENTANB_THREADS", "").strip()
    if flag:
        if not flag.isdigit() or int(flag) < 1:
            raise ValueError(f"PENTANB_THREADS must be a positive integer, got {flag!r}")
        return min(int(flag), 64)
    try:
        n = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not Linux
        n = os.cpu_count() or 1
    return max(1, min(n, 8))


#: Work items (faces, edges, vertices) below which a kernel runs on one thread.
#: Below about 100,000 items a kernel takes well under a millisecond, and a
#: second thread costs more than it saves: it starts some 50 µs late and
#: reads from a cold cache what the calling thread has just written.
#: Measured on a 2-core VM: every kernel of a slider move at 20,480 faces
#: (at most 102,402 items) as fast or faster on one thread, the pipeline
#: at 81,920 triangles 24.6 ms against 26.2 ms with parts from 2^14 items,
#: and at 327,680 and 1,310,720 triangles as fast as then (the threads save
#: 5 and 12 % there).
MIN_SPLIT = 1 << 17


class _Worker:
    """One thread that runs the parts handed to it, one at a time.

    Work is handed over through two locks (held while there is nothing to
    run, and until the part is done): about 30 µs a part on a small
    machine, where a ``concurrent.futures`` pool takes about 100.
    """

    def __init__(self, name: str):
        self._go = threading.Lock()
        self._go.acquire()
        self._done = threading.Lock()
        self._done.acquire()
        self._job: tuple[Callable[..., None], tuple] | None = None
        self._error: BaseException | None = None
        threading.Thread(target=self._run, name=name, daemon=True).start()

    def _run(self) -> None:
        while True:
            self._go.acquire()
            job, self._job = self._job, None
            try:
                if job is not None:
                    job[0](*job[1])
            except BaseException as err:  # handed to the caller by wait()
                self._error = err
            finally:
                self._done.release()

    def start(self, kernel: Callable[..., None], args: tuple) -> None:
        self._job = (kernel, args)
        self._go.release()

    def wait(self) -> BaseException | None:
        """Wait for the part to end; its exception, if it raised one."""
        self._done.acquire()
        err, self._error = self._error, None
        return err


_crew: dict[str, Any] = {"workers": [], "pid": None, "closed": False}
#: Held by the thread whose parts the workers run (another thread meanwhile
#: runs its parts itself).
_busy = threading.Lock()


def _workers(k: int) -> list[_Worker] | None:
    """``k`` idle worker threads, started on first use (again in a forked child).

    None once the interpreter is exiting (a daemon thread may then be
    stopped with a part unfinished).  The caller holds :data:`_busy`.
    """
    if _crew["closed"]:
        return None
    if _crew["pid"] != os.getpid():  # (a forked child has none of its parent's threads)
        _crew["workers"], _crew["pid"] = [], os.getpid()
    workers = _crew["workers"]
    try:
        while len(workers) < k:
            workers.append(_Worker(f"pentanb-kernel-{len(workers)}"))
    except RuntimeError:  # no new thread now (say, at interpreter exit)
        pass
    return workers[:k] if len(workers) >= k else None


def _close_crew() -> None:
    _crew["closed"] = True


atexit.register(_close_crew)


def split(n: int, kernel: Callable[..., None], *args: Any) -> None:
    """Run ``kernel(*args, lo, hi)`` over ``range(n)`` cut into one part per thread.

    The kernels release the GIL and write disjoint parts of their output,
    so the parts run at once; the calling thread runs the first, worker
    threads (:class:`_Worker`) the others.  Below :data:`MIN_SPLIT` items,
    or with one CPU, it is one call.  While another thread's parts are
    running, or once the interpreter is exiting, every part runs on the
    calling thread, one after the other.  An exception of any part reaches
    the caller, once every part has ended.
    """
    parts = min(threads(), n // MIN_SPLIT)
    if parts <= 1:
        kernel(*args, 0, n)
        return
    cuts = [n * i // parts for i in range(parts + 1)]
    held = _busy.acquire(blocking=False)
    try:
        workers = _workers(parts - 1) if held else None
        if workers is None:  # busy, or exiting: every part here
            for i in range(parts):
                kernel(*args, cuts[i], cuts[i + 1])
            return
        for i, worker in enumerate(workers, 1):
            worker.start(kernel, args + (cuts[i], cuts[i + 1]))
        try:
            kernel(*args, cuts[0], cuts[1])
        finally:
            errors = _wait(workers)
        if errors:
            raise errors[0]
    finally:
        if held:
            _busy.release()


def _wait(workers: list[_Worker]) -> list[BaseException]:
    """Wait for every worker's part; the exceptions they raised."""
    errors = []
    for worker in workers:
        try:
            err = worker.wait()
        except BaseException:  # interrupted (Ctrl-C): some parts may still be running;
            _crew["workers"] = []  # later calls get new threads, never these
            raise
        if err is not None:
            errors.append(err)
    return errors


def _compile() -> Any:
    """The kernels (:mod:`pentanb._kernels`; numba compiles each on its first
    call per argument types, or loads it from its disk cache)."""
    import numba  # noqa: F401  (first: a numba that cannot load fails here)

    from . import _kernels

    return types.SimpleNamespace(**{name: getattr(_kernels, name) for name in _kernels.__all__})
