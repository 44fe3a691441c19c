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
  where the numpy path sorts packed keys), refusing exactly what it refuses,
  on closed and open meshes alike (an edge of one face is a boundary edge);
  the boundary half-edges chained into loops, and every vertex's ring walked
  once (the validation of :class:`pentanb.Mesh`);
* on open meshes, the rings the paper's two schemes write for their outputs,
  and the dual's faces, boundary vertices' included.

They run only on meshes of at least :data:`MIN_CORNERS` corners, where a
compiled loop pays for itself; smaller meshes never load numba.  The first
use in a process compiles the kernels it needs (about 2 s for an explorer's
first move with an empty cache); numba caches the machine code on disk, so
later processes load it.

Every kernel runs on the calling thread: pentanb starts no thread.

Switch them with the environment variable ``PENTANB_JIT`` (``0``: off,
``1``: on, refused without numba), read when first needed, or at run time
with :func:`pentanb.use_jit`.  ``benchmarks/bench_pipeline.py`` reports both paths.
"""

from __future__ import annotations

import importlib.util
import os
import types
import warnings
from typing import Any

import numpy as np

__all__ = ["MIN_CORNERS", "available", "enabled", "use_jit", "kernels"]

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


def _compile() -> Any:
    """The kernels (:mod:`pentanb._kernels`; numba compiles each on its first
    call per argument types, or loads it from its disk cache)."""
    import numba  # noqa: F401  (first: a numba that cannot load fails here)

    from . import _kernels

    return types.SimpleNamespace(**{name: getattr(_kernels, name) for name in _kernels.__all__})
