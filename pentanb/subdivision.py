"""``subdivide``: remesh, then smooth; and the counts that say in advance how large.

Every scheme of :data:`pentanb.SCHEMES` knows how its output's counts follow
from its input's, so :func:`subdivide` can refuse, before building anything,
a request that would not fit in memory, and :func:`max_iterations` can bound
a slider.

The memory guard
----------------
:func:`estimate_bytes` predicts the peak memory of one iteration (a
remeshing and its duals) from the counts ``(V, E, F)`` of its input and
what is known of its regularity (every face a k-gon, every vertex
d-valent), by :data:`MEMORY_MODEL`: linear forms per scheme and number of
duals, calibrated on numpy's allocations as :mod:`tracemalloc` counts them
(``benchmarks/calibrate_memory.py`` measures and fits them again).  The
promise, tested for every scheme on meshes of tens of thousands of
half-edges (tori, triangle, pentagonal and mixed meshes the forms were not
fitted on): the measured peak of :func:`subdivide` above its input is at
most the estimate, and the estimate at most 1.25 times the measured peak.
Smaller meshes need a few dozen kilobytes of Python objects besides, which
the estimate's fixed part covers.  With the default limit (half of the
physical memory) an allowed request therefore leaves at least the other
half.

A request is checked iteration by iteration, from the first, and refused at
the first iteration whose estimate is over the limit, before anything is
built: the check takes microseconds whatever the number of iterations.
"""

from __future__ import annotations

import math
import os
import sys
from collections.abc import Callable, Sequence

import numpy as np

from .mesh import Mesh, MeshError
from .schemes._build import check_count, check_mesh
from .schemes.registry import SCHEMES, Counts, Scheme, get_scheme
from .schemes.smoothing import dual

__all__ = [
    "subdivide",
    "predict_counts",
    "max_iterations",
    "estimate_bytes",
    "default_max_bytes",
    "MAX_STEPS",
    "MEMORY_MODEL",
    "SCHEMES",
    "Scheme",
    "get_scheme",
]

#: Most steps (remeshings and duals together) one call may take: more would
#: run for hours without the counts changing (duals, or triangulate after
#: its first pass, keep them).
MAX_STEPS = 100_000

#: Above this many bytes no request is possible, whatever ``max_bytes``
#: (2**62: the index arithmetic of 64-bit integers ends about there).
_ABSOLUTE = 2**62

Form = tuple[float, ...]

#: Bytes every estimate starts from: the Python objects of a call (a few
#: dozen kilobytes), negligible beside the arrays of any mesh worth guarding.
_FIXED = 64 * 1024

#: Room left above the fitted forms, for meshes unlike those of the calibration.
_MARGIN = 1.02

#: Half-edges beyond which the operators' block-wise temporaries stop growing.
_SATURATION = 2**15

#: What is known of a mesh's regularity: (k, d) with k the size of every
#: face (0: sizes differ, or not known) and d the number of edges at every
#: vertex (0 likewise).  Code paths for meshes of one face size need less
#: memory; the model knows it through :func:`regressors`.
Kind = tuple[int, int]

#: The kind of each scheme's output, from its input's.
_AFTER: dict[str, Callable[[int, int], Kind]] = {
    "pentagonalize": lambda k, d: (5, 3 if (k, d) == (3, 3) else 0),
    "preserve_pentagons": lambda k, d: (5 if k == 5 else 0, 0),
    "triangulate": lambda k, d: (3, d) if k == 3 else (3, 0),
    "loop_remesh": lambda k, d: (3 if k == 3 else 0, 6 if d == 6 else 0),
    "sqrt3_remesh": lambda k, d: (3, d if d and d == 2 * k else 0),
    "vertex_insertion": lambda k, d: (4, 4 if (k, d) == (4, 4) else 0),
    "corner_cutting": lambda k, d: (4 if (k, d) == (4, 4) else 0, 4),
    "preserve_hexagons": lambda k, d: (6 if k == 6 else 0, 3 if d == 3 else 0),
    "honeycomb": lambda k, d: (k if k and k == 2 * d else 0, 3),
}


def _kind_after(s: Scheme, kind: Kind, duals: int) -> Kind:
    """The kind of the mesh after one iteration (the duals swap faces and vertices)."""
    if s.name not in _AFTER:  # a Conway string: its kind is not tracked
        return (0, 0)
    k, d = _AFTER[s.name](*kind)
    return (d, k) if duals % 2 else (k, d)


def _kind_of(mesh: Mesh) -> Kind:
    valences = mesh.valences
    top = int(valences.max()) if valences.size else 0
    return mesh._uniform_size, top if valences.size and int(valences.min()) == top else 0


def regressors(counts: Counts, scheme: str | Scheme | None = None, kind: Kind = (0, 0)) -> tuple:
    """What :data:`MEMORY_MODEL`'s forms are linear in, for an input of ``counts``.

    ``(V, E, F, min(2E, 2**15), 2E [input faces of several sizes],
    2E [output faces of several sizes], 2E [output vertices of several
    valences])``: the counts; the operators' temporaries, computed in
    blocks (they grow with the mesh up to a block's size, then stay); and
    the extra arrays (next, head, face of every half-edge) that meshes with
    faces of several sizes need.  ``kind`` is the input's (see
    :data:`Kind`); unknown, it is taken as irregular (an upper bound).
    """
    V, E, F = counts
    H = 2 * E
    k_out, d_out = (0, 0)
    if scheme is not None:
        k_out, d_out = _AFTER[get_scheme(scheme).name](*kind)  # type: ignore[union-attr]
    return (
        V,
        E,
        F,
        min(H, _SATURATION),
        H if not kind[0] else 0,
        H if not k_out else 0,
        H if not d_out else 0,
    )


#: Peak memory per scheme and number of duals (0, 1, or 2 and more):
#: ``(step, hold)``, two linear forms in :func:`regressors` of the counts of
#: the input of an iteration.  ``step``: the peak of the iteration above its
#: input (a mesh as the constructor leaves it: twins and vertex rings
#: derived).  ``hold``: what an input built by the earlier iterations of the
#: same call adds (one term, in its edges; negative when such an input,
#: having derived arrays already, costs less than a fresh one).  Measured
#: with int32 indices; twice the whole when meshes need int64 (more than
#: 2**31 corners).  Calibrated by ``benchmarks/calibrate_memory.py``.
MEMORY_MODEL: dict[str, dict[int, tuple[Form, Form]]] = {
    "pentagonalize": {
        0: ((0.0, 158.1, 32.0, 19.4, 0.0, 0.0, 0.0), (0.0, 20.5, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 281.3, 48.3, 8.9, 0.0, 0.0, 0.0), (0.0, -24.9, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 363.4, 54.1, 13.6, 0.0, 0.0, 0.0), (0.0, -31.2, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "preserve_pentagons": {
        0: ((201.4, 0.0, 189.3, 20.4, 0.0, 0.0, 0.0), (0.0, 32.9, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 362.0, 88.8, 12.8, 0.0, 7.3, 0.0), (0.0, 19.2, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 439.2, 70.8, 19.9, 0.0, 16.3, 0.0), (0.0, 36.5, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "triangulate": {
        0: ((0.0, 67.2, 175.5, 0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 171.8, 157.1, 7.9, 0.0, 0.0, 0.0), (0.0, 8.5, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 229.9, 115.6, 7.9, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "loop_remesh": {
        0: ((0.0, 43.2, 134.3, 19.4, 0.0, 15.0, 0.0), (0.0, 22.1, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 139.3, 190.9, 11.3, 0.0, 39.7, 0.0), (0.0, 46.5, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((196.8, 0.0, 356.2, 12.3, 0.0, 34.6, 0.0), (0.0, 20.2, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "sqrt3_remesh": {
        0: ((72.1, 0.0, 102.5, 7.1, 0.0, 0.0, 0.0), (0.0, 33.6, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 285.6, 84.5, 0.0, 0.0, 0.0, 0.0), (0.0, 28.6, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 285.6, 84.5, 0.0, 0.0, 0.0, 0.0), (0.0, 11.7, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "vertex_insertion": {
        0: ((0.0, 115.1, 93.8, 17.6, 0.0, 0.0, 0.0), (0.0, 31.3, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 253.5, 138.0, 1.8, 0.0, 0.0, 0.0), (0.0, 18.1, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((278.7, 0.0, 394.2, 16.4, 0.0, 0.0, 0.8), (0.0, 17.9, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "corner_cutting": {
        0: ((0.0, 158.1, 92.8, 1.4, 0.0, 0.0, 0.0), (0.0, 46.9, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((221.9, 0.0, 336.3, 16.0, 0.0, 17.7, 0.0), (0.0, 15.7, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((276.6, 0.0, 391.0, 9.9, 0.0, 10.0, 0.0), (0.0, 17.2, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "preserve_hexagons": {
        0: ((0.0, 237.9, 54.3, 1.5, 0.0, 0.0, 5.8), (0.0, 42.6, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 247.2, 90.7, 13.0, 0.0, 0.0, 9.5), (0.0, 57.1, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 304.3, 68.8, 15.0, 0.0, 0.0, 17.4), (0.0, 24.5, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "honeycomb": {
        0: ((0.0, 135.3, 94.8, 1.4, 0.0, 0.0, 0.0), (0.0, 61.8, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((0.0, 209.5, 128.7, 0.0, 0.0, 0.0, 0.0), (0.0, 103.1, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((0.0, 221.1, 117.9, 10.3, 0.0, 0.0, 0.0), (0.0, 28.3, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
    "triangulate (triangles)": {
        0: ((0.0, 3.2, 0.0, 0.0, 0.0, 0.0, 0.0), (0.0, 42.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        1: ((29.3, 0.0, 25.4, 6.1, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        2: ((108.7, 0.0, 0.0, 9.3, 0.0, 0.0, 0.0), (0.0, 47.2, 0.0, 0.0, 0.0, 0.0, 0.0)),
    },
}


def predict_counts(
    counts: Counts,
    scheme: str | Scheme,
    iterations: int = 1,
    duals: int = 2,
    *,
    max_bytes: float | None = None,
) -> list[Counts]:
    """The (V, E, F) after every step of :func:`subdivide`, without building anything.

    Parameters
    ----------
    counts : (V, E, F)
    scheme, iterations, duals : as for :func:`subdivide`
    max_bytes : float, optional
        As for :func:`subdivide`: a request that would not fit is refused
        (default: half of the physical memory; ``float("inf")``: no limit).

    Returns
    -------
    list of (V, E, F)
        One entry per remeshing and per dual, in order.

    Raises
    ------
    MeshError
        At the first iteration whose meshes would not fit in ``max_bytes``
        (or could not be indexed at all), naming its sizes: found in
        microseconds, whatever ``iterations``.
    ValueError
        A scheme that is not registered, a bad count, more than
        :data:`MAX_STEPS` steps.
    """
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("counts can only be predicted for a registered scheme")
    counts = _as_counts(counts, "predict_counts")
    iterations = check_count(iterations, "iterations")
    duals = check_count(duals, "duals")
    _guard(counts, s, iterations, duals, _limit(max_bytes))
    V, E, F = counts
    out = []
    for _ in range(iterations):
        V, E, F = s.counts(V, E, F)
        out.append((V, E, F))
        for _ in range(duals):
            V, F = F, V
            out.append((V, E, F))
    return out


def max_iterations(
    mesh_or_counts: Mesh | Counts,
    scheme: str | Scheme,
    duals: int = 2,
    max_faces: int = 100_000,
    cap: int = 8,
    *,
    max_bytes: float | None = None,
) -> int:
    """The most iterations of ``scheme`` whose meshes all stay within ``max_faces``.

    Predicted from the counts (nothing is built), level by level, stopping
    at the first too large: the bound a slider over iterations should have.

    Parameters
    ----------
    mesh_or_counts : Mesh or (V, E, F)
    scheme : str or Scheme
    duals : int
        Duals after each remeshing (as in :func:`subdivide`).
    max_faces : int
        Largest number of faces any step may have.
    cap : int
        Never more than this many iterations (any size: the answer comes
        in microseconds).
    max_bytes : float, optional
        Also within this memory (as for :func:`subdivide`; default: half of
        the physical memory).

    Returns
    -------
    int
        0 when even one iteration would be too large.
    """
    counts = (
        _vef(mesh_or_counts)
        if isinstance(mesh_or_counts, Mesh)
        else _as_counts(mesh_or_counts, "max_iterations")
    )
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("max_iterations needs a registered scheme")
    duals = check_count(duals, "duals")
    cap = check_count(cap, "cap")
    limit = _limit(max_bytes)
    V, E, F = counts
    kind = _kind_of(mesh_or_counts) if isinstance(mesh_or_counts, Mesh) else (0, 0)
    for k in range(cap):
        need = _iteration_bytes(s, (V, E, F), duals, later=k > 0, kind=kind)
        V2, E2, F2 = s.counts(V, E, F)
        biggest = max(F2, V2) if duals else F2
        if biggest > max_faces or need > limit:
            return k
        after = ((F2, E2, V2) if duals % 2 else (V2, E2, F2)), _kind_after(s, kind, duals)
        if after == ((V, E, F), kind) and k > 0:
            return cap  # a fixed point: every later iteration is the same
        (V, E, F), kind = after
    return cap


def _as_counts(counts: object, caller: str) -> Counts:
    """``(V, E, F)`` from a tuple, list or array of three non-negative integers.

    Raises
    ------
    TypeError
        Neither a Mesh nor a sequence (the message names ``caller``).
    ValueError
        Not three non-negative integers.
    """
    if isinstance(counts, (str, bytes)) or not isinstance(counts, (Sequence, np.ndarray)):
        what = "a pentanb.Mesh or its counts" if caller == "max_iterations" else "counts"
        raise TypeError(f"{caller} expects {what} (V, E, F), got {type(counts).__name__}")
    if len(counts) != 3:
        raise ValueError(f"counts must be (V, E, F), three numbers; got {len(counts)}")
    V, E, F = (check_count(x, name) for x, name in zip(counts, "VEF"))
    return V, E, F


def _as_limit(max_bytes: object) -> float:
    """``max_bytes`` as a number of bytes (``float("inf")``: no limit).

    Raises
    ------
    TypeError
        Not a number.
    ValueError
        NaN or not positive.
    """
    if isinstance(max_bytes, bool) or not isinstance(
        max_bytes, (int, float, np.integer, np.floating)
    ):
        raise TypeError(f"max_bytes must be a number of bytes, got {type(max_bytes).__name__}")
    if not max_bytes > 0:  # NaN too
        raise ValueError(f"max_bytes must be a positive number of bytes, got {max_bytes!r}")
    return float(max_bytes) if np.isinf(max_bytes) else int(max_bytes)


def _vef(mesh: Mesh) -> Counts:
    return mesh.n_vertices, mesh.n_edges, mesh.n_faces


def estimate_bytes(
    V: int,
    E: int,
    F: int,
    scheme: str | Scheme | None = None,
    duals: int = 2,
    *,
    kind: Kind = (0, 0),
) -> int:
    """Bytes of memory for a mesh of these counts, or for one iteration on it.

    Parameters
    ----------
    V, E, F : int
        The counts of a mesh.
    scheme : str or Scheme, optional
        With a scheme: the peak memory of one iteration (``scheme``, then
        ``duals`` duals) on a mesh of these counts, above that mesh
        (:data:`MEMORY_MODEL`).  Without: what a mesh of these counts holds
        (positions, faces, twins and vertex rings).
    duals : int
        Duals after the remeshing.
    kind : (k, d)
        Every face a k-gon, every vertex d-valent, when known (0: not, or
        not known: the estimate then bounds the irregular case).

    Returns
    -------
    int
    """
    if scheme is None:
        itemsize = _itemsize(V, 2 * E)
        return 24 * V + itemsize * (3 * 2 * E + F + V + 2)
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("memory can only be estimated for a registered scheme")
    return _iteration_bytes(s, (V, E, F), check_count(duals, "duals"), later=False, kind=kind)


def _itemsize(V: int, H: int) -> int:
    return 4 if max(V, H) < 2**31 else 8


def _iteration_bytes(
    s: Scheme, counts: Counts, duals: int, later: bool, kind: Kind = (0, 0)
) -> int:
    """Peak bytes of one iteration on a mesh of ``counts`` (``later``: built by this call)."""
    V, E, F = counts
    if _model_name(s, counts) not in MEMORY_MODEL:
        # a scheme written in Conway notation: no calibrated model, so the
        # callable schemes' bound per output edge (their largest mesh)
        V2, E2, _ = s.counts(V, E, F)
        wide = 2 if _itemsize(max(V2, V), 2 * E2) == 8 else 1
        return math.ceil(_FIXED + wide * CALLABLE_BYTES_PER_EDGE * max(E2, E))
    step, hold = MEMORY_MODEL[_model_name(s, counts)][min(duals, 2)]
    x = regressors(counts, s, kind)
    stepped = sum(a * b for a, b in zip(step, x))
    need = _FIXED + _MARGIN * stepped
    if later:  # and the same room again: later inputs vary more
        need += sum(a * b for a, b in zip(hold, x)) + (_MARGIN - 1) * stepped
        need = max(need, _FIXED + stepped / 2)
    V2, E2, _ = s.counts(V, E, F)
    if _itemsize(max(V2, V), 2 * E2) == 8:
        need *= 2  # int64 indices: about twice the memory (an upper bound)
    return math.ceil(need)


def _request_bytes(
    s: Scheme, counts: Counts, iterations: int, duals: int, kind: Kind = (0, 0)
) -> int:
    """The peak bytes of a whole request: the largest of its iterations' (no limit)."""
    need, V, E, F = 0, *counts
    for i in range(iterations):
        need = max(need, _iteration_bytes(s, (V, E, F), duals, later=i > 0, kind=kind))
        V2, E2, F2 = s.counts(V, E, F)
        after = ((F2, E2, V2) if duals % 2 else (V2, E2, F2)), _kind_after(s, kind, duals)
        if after == ((V, E, F), kind) and i > 0:
            break  # a fixed point: every later iteration is the same (as the second)
        (V, E, F), kind = after
    return need


def _model_name(s: Scheme, counts: Counts) -> str:
    """The entry of :data:`MEMORY_MODEL` for ``s`` on a mesh of ``counts``.

    ``triangulate`` gives back an all-triangle mesh (2E = 3F) as it is: only
    its duals cost memory then.
    """
    _, E, F = counts
    if s.name == "triangulate" and 2 * E == 3 * F:
        return "triangulate (triangles)"
    return s.name


def _limit(max_bytes: object) -> float:
    """``max_bytes`` checked: None -> the default; ``float("inf")`` -> no limit."""
    return float(default_max_bytes()) if max_bytes is None else float(_as_limit(max_bytes))


def _readable(n: float) -> str:
    """Bytes as "3.2 GB" (powers of 1000), for messages."""
    for unit, size in (("EB", 1e18), ("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n / 1e3:.3g} kB" if n >= 1e3 else f"{int(n)} bytes"


def _guard(
    counts: Counts, s: Scheme, iterations: int, duals: int, limit: float, kind: Kind = (0, 0)
) -> None:
    """Refuse (MeshError) at the first iteration over ``limit``; then too many steps (ValueError).

    Walks the iterations one by one, from the first: stops at the first
    over the limit (or at a fixed point of the counts), so it answers in
    microseconds for any ``iterations``.
    """
    V, E, F = counts
    for i in range(iterations):
        need = _iteration_bytes(s, (V, E, F), duals, later=i > 0, kind=kind)
        V2, E2, F2 = s.counts(V, E, F)
        if need > limit or need > _ABSOLUTE:
            over = (
                f"over the limit of {limit:,.0f} bytes ({_readable(limit)})"
                if need > limit
                else f"beyond what any computer can index ({_readable(_ABSOLUTE)})"
            )
            raise MeshError(
                f"{s.name} iteration {i + 1} of {iterations:,} would build a mesh of "
                f"{F2:,} faces ({V2:,} vertices, {E2:,} edges); with {duals} duals it "
                f"needs about {need:,} bytes ({_readable(need)}) at its peak, {over}. "
                "Lower iterations or raise max_bytes."
            )
        after = ((F2, E2, V2) if duals % 2 else (V2, E2, F2)), _kind_after(s, kind, duals)
        if after == ((V, E, F), kind) and i > 0:
            break  # a fixed point: every later iteration is the same (as the second)
        (V, E, F), kind = after
    steps = iterations * (1 + duals)
    if steps > MAX_STEPS:
        raise ValueError(
            f"{iterations:,} iterations with {duals:,} duals is {steps:,} steps; at most "
            f"{MAX_STEPS:,} are taken in one call (the counts no longer change, and it "
            "would run for hours)"
        )


def default_max_bytes() -> int:
    """Half of this machine's physical memory (4 GiB where it cannot be read)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2
    except (ValueError, OSError, AttributeError):  # pragma: no cover - non-POSIX
        return 4 << 30


#: Bytes per output edge that a user's callable scheme is assumed to need at
#: the peak of one iteration with its duals: more than any registered scheme
#: needs (their estimates stay below it, tested), twice with int64 indices.
CALLABLE_BYTES_PER_EDGE = 160


def subdivide(
    mesh: Mesh,
    scheme: str | Scheme | Callable = "pentagonalize",
    iterations: int = 1,
    duals: int = 2,
    *,
    progress=None,
    max_bytes: float | None = None,
    **options,
) -> Mesh:
    """Repeat: one remeshing, then ``duals`` duals (the paper's subdivision).

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        A name from :data:`SCHEMES` (``"pentagonalize"``,
        ``"preserve_pentagons"``, ...) or any ``Mesh -> Mesh`` callable.
    iterations : int, >= 0
        How many times to remesh.
    duals : int, >= 0
        Duals after each remeshing; even keeps the mesh's type (Section 5:
        "Apply dual operation an even number of times").
    progress : callable, True or None
        ``progress(done, total, message)`` after every step; True prints
        the steps to standard error.
    max_bytes : float, optional
        Refuse (with :class:`MeshError`) a request whose peak memory would
        be more than this many bytes (:func:`estimate_bytes`); default:
        half of the physical memory; ``float("inf")``: no limit (still
        refused beyond 2**62 bytes, which no computer indexes).
    **options
        Options of the scheme, e.g. ``scale=0.6`` for ``preserve_pentagons``.

    Returns
    -------
    Mesh

    Raises
    ------
    ValueError
        An unknown scheme name (the message lists the known ones), a bad
        count, an option the scheme does not take, a negative or NaN
        ``max_bytes``, or more than :data:`MAX_STEPS` steps.
    TypeError
        ``mesh`` is not a Mesh; ``max_bytes`` is not a number; a callable
        scheme returned something other than a Mesh (the message names it).
    MeshError
        Before building anything, when an iteration would not fit in
        ``max_bytes``: the message names the first such iteration, the
        sizes of its mesh and the bytes it would need.

    Notes
    -----
    A callable scheme's growth is not known in advance: its first
    iteration runs, and the later ones are predicted from it (each is
    assumed to grow the mesh as the first did, and to need
    :data:`CALLABLE_BYTES_PER_EDGE` bytes per edge of its output); a request
    over ``max_bytes`` is refused before the second.  Its first iteration is
    refused when its input alone would be over the limit.
    """
    check_mesh(mesh, "subdivide")
    s = get_scheme(scheme)
    iterations = check_count(iterations, "iterations")
    duals = check_count(duals, "duals")
    limit = _limit(max_bytes)
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            takes = ", ".join(s.options) or "no options"
            raise ValueError(f"scheme {s.name!r} takes {takes}; got {sorted(unknown)}")
        _guard(_vef(mesh), s, iterations, duals, limit, _kind_of(mesh) if iterations else (0, 0))
    else:
        if iterations * (1 + duals) > MAX_STEPS:
            raise ValueError(
                f"{iterations * (1 + duals):,} steps; at most {MAX_STEPS:,} are taken in one call"
            )
        if iterations and estimate_bytes(*_vef(mesh)) > limit:
            raise MeshError(
                f"the input mesh alone ({mesh.n_faces:,} faces) is over the limit of "
                f"{limit:,.0f} bytes ({_readable(limit)}); raise max_bytes"
            )
    report = _progress_printer if progress is True else progress
    total = iterations * (1 + duals)
    done = 0
    name = getattr(s, "name", getattr(s, "__name__", repr(s)))
    for i in range(iterations):
        before = _vef(mesh)
        out = s(mesh, **options)
        if not isinstance(out, Mesh):
            raise TypeError(
                f"scheme {name!r} returned {type(out).__name__}, not a pentanb.Mesh "
                "(a callable scheme maps a Mesh to a Mesh)"
            )
        mesh = out
        if i == 0 and not isinstance(s, Scheme) and iterations > 1:
            _guard_callable(name, before, _vef(mesh), iterations, duals, limit)
        done += 1
        if report:
            report(done, total, f"{name} {i + 1}/{iterations}: {mesh.n_faces:,} faces")
        for d in range(duals):
            mesh = dual(mesh)
            done += 1
            if report:
                report(done, total, f"dual {d + 1}/{duals}: {mesh.n_faces:,} faces")
    return mesh


def _guard_callable(
    name: str, before: Counts, after: Counts, iterations: int, duals: int, limit: float
) -> None:
    """After a callable's first iteration: refuse if a later one would be over the limit.

    Each iteration is assumed to multiply the counts as the first did.
    """
    growth = [a / b if b else 1.0 for a, b in zip(after, before)]
    V, E, F = (float(x) for x in after)
    for i in range(1, iterations):
        V, E, F = V * growth[0], E * growth[1], F * growth[2]
        need = CALLABLE_BYTES_PER_EDGE * E * (2 if max(V, 2 * E) >= 2**31 else 1)
        if need > limit or need > _ABSOLUTE:
            raise MeshError(
                f"{name} iteration {i + 1} of {iterations:,} would build a mesh of about "
                f"{F:,.0f} faces ({V:,.0f} vertices, {E:,.0f} edges), if it grows as its "
                f"first iteration did; that needs about {need:,.0f} bytes ({_readable(need)}), "
                f"over the limit of {limit:,.0f} bytes ({_readable(limit)}). Lower iterations "
                "or raise max_bytes."
            )
        if growth == [1.0, 1.0, 1.0]:
            break


def _progress_printer(done: int, total: int, message: str) -> None:
    width = 20
    filled = width * done // max(total, 1)
    print(
        f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} {message}",
        end="\n" if done == total else "",
        file=sys.stderr,
        flush=True,
    )
