"""``subdivide``: remesh, then smooth; and the counts that say in advance how large.

Every scheme of :data:`pentanb.SCHEMES` knows how its output's counts follow
from its input's, so :func:`subdivide` can refuse, before building anything,
a request that would not fit in memory, and :func:`max_iterations` can bound
a slider.

The memory guard
----------------
A mesh of counts ``(V, E, F)`` holds :func:`mesh_bytes` of them: 24 bytes
of float64 positions per vertex, and one index per corner, twin and
vertex-ring entry (2E each) and per face and vertex offset (4 bytes, 8 when
the counts need int64 indices: 2**31 corners or vertices).  The peak memory
of one iteration is bounded by multiples of that, from the predicted counts
alone:

* the remeshing: ``REMESH[scheme]`` times the bytes of its output;
* each dual (all read the same two meshes: the remeshing's output and its
  dual): ``DUAL`` times the bytes of its input and its output together (the
  mesh it reads is held while it builds the next);
* an iteration after the first also holds its input, built by the call:
  plus the bytes of that input;
* plus ``FIXED`` bytes for a call's Python objects and the operators'
  block-wise temporaries, which stop growing beyond a few thousand faces;
* a scheme without its own factor (Conway notation) or a callable:
  ``UNKNOWN`` times the bytes of the largest mesh of its edge count
  (vertices and faces at most 2E/3 each).

How the constants were chosen: the peaks of :func:`subdivide` were measured
once with :mod:`tracemalloc` (numpy's allocations above the input, a fresh
mesh as the constructor leaves it, after a first run that loads the compiled
kernels: numba's one-time loading, a few MB per process, is not counted), on
both the numpy path and the compiled kernels, for every scheme with 0 to 3
duals and one or two iterations, on tori of quads, triangles and pentagons
of 200 to 240,000 half-edges, an octahedron after six Loop steps, and
pentagonal and mixed meshes.  ``REMESH[s]`` is the largest peak without
duals over the bytes of the output, on meshes of at least 16,384
half-edges, plus 10 % and rounded up to a tenth; ``DUAL`` likewise the
largest peak with duals over the bytes of a dual's input and output;
``FIXED`` is twice the largest shortfall left on the smaller meshes (64
kB); ``UNKNOWN`` is above every Conway operator and a few strings ("dg",
"tk", ...) measured the same way (3.5 at most).  On meshes of at least
16,384 half-edges the estimate is 1.1 to 2.6 times the measured peak (the
looser end: meshes whose duals are cheap, the factor serving the costliest;
tested below 3x in ``tests/test_scale.py``).  With int64 indices the index
bytes double, and the temporaries (mostly indices) are taken to grow in
proportion.  ``triangulate`` hands an all-triangle mesh back
as it is (the predicted counts are the input's): its remeshing is then
counted as free, but its duals, cheaper on such meshes than the factor
allows for, make the estimate 2.5 to 5.5 times their measured peak.

A request is checked iteration by iteration, from the first, and refused at
the first iteration whose estimate is over the limit (or at a fixed point
of the counts, let through), before anything is built: microseconds
whatever the number of iterations.  The default limit is the memory this
process may still take (:func:`default_max_bytes`).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable, Sequence

import numpy as np

from . import _checks
from ._checks import MAX_STEPS
from .memory import default_max_bytes, mesh_bytes, readable
from .mesh import Mesh, MeshError
from .notation import as_scheme as get_scheme
from .schemes._build import check_count, check_mesh
from .schemes.registry import SCHEMES, Counts, Scheme
from .schemes.smoothing import dual

__all__ = [
    "subdivide",
    "predict_counts",
    "max_iterations",
    "estimate_bytes",
    "mesh_bytes",
    "default_max_bytes",
    "MAX_STEPS",
    "SCHEMES",
    "Scheme",
    "get_scheme",
]

#: Above this many bytes no request is possible, whatever ``max_bytes``
#: (2**62: the index arithmetic of 64-bit integers ends about there).
_ABSOLUTE = 2**62

#: Peak of a remeshing per byte of its output (:func:`mesh_bytes`); see the
#: module's docstring for how these were measured.
REMESH: dict[str, float] = {
    "pentagonalize": 1.2,
    "preserve_pentagons": 1.2,
    "triangulate": 1.5,
    "loop_remesh": 1.4,
    "sqrt3_remesh": 1.2,
    "vertex_insertion": 1.4,
    "corner_cutting": 1.6,
    "preserve_hexagons": 1.9,
    "honeycomb": 1.6,
}

#: Peak of one iteration of a table of one's own (:class:`pentanb.Table`) per
#: byte of its output: the engine's, the largest factor of the built-in tables
#: (1.9) and a margin.
TABLE = 2.2

#: Peak of a dual per byte of its input and output together.
DUAL = 1.7

#: Peak of one iteration of a scheme without its own factor (Conway
#: notation, callables) per byte of the largest mesh of its edge count.
UNKNOWN = 4.0

#: Bytes every estimate adds: a call's Python objects and block-wise temporaries.
FIXED = 128 * 1024


def _largest_mesh_bytes(E: float) -> int:
    """The most a mesh of ``E`` edges holds: no vertex of fewer than 3 edges and no
    face of fewer than 3 sides leave at most 2E/3 vertices and 2E/3 faces."""
    return mesh_bytes(2 * E / 3, E, 2 * E / 3)


def _iteration_bytes(s: Scheme, counts: Counts, duals: int, later: bool) -> int:
    """Peak bytes of one iteration on a mesh of ``counts`` (``later``: built by this call)."""
    V2, E2, F2 = s.counts(*counts)
    held = mesh_bytes(*counts) if later else 0
    factor = REMESH.get(s.name, TABLE if s.table is not None else None)
    if factor is None:  # Conway notation: several operators, not measured one by one
        return math.ceil(FIXED + held + UNKNOWN * _largest_mesh_bytes(max(E2, counts[1])))
    out = mesh_bytes(V2, E2, F2)
    # the same counts: the mesh is handed back as it is (triangulate, all triangles)
    need = 0.0 if (V2, E2, F2) == tuple(counts) else factor * out
    if duals:
        need = max(need, DUAL * (out + mesh_bytes(F2, E2, V2)))
    return math.ceil(FIXED + held + need)


def _next_counts(s: Scheme, counts: Counts, duals: int) -> Counts:
    """The counts after one iteration (an odd number of duals swaps V and F)."""
    V, E, F = s.counts(*counts)
    return (F, E, V) if duals % 2 else (V, E, F)


def predict_counts(
    mesh_or_counts: Mesh | Counts,
    scheme: str | Scheme,
    iterations: int = 1,
    duals: int = 2,
    *,
    max_bytes: float | None = None,
) -> list[Counts]:
    """The (V, E, F) after every step of :func:`subdivide`, without building anything.

    Parameters
    ----------
    mesh_or_counts : Mesh or (V, E, F)
    scheme, iterations, duals : as for :func:`subdivide`
    max_bytes : float, optional
        As for :func:`subdivide`: a request that would not fit is refused
        (default: :func:`default_max_bytes`; ``float("inf")``: no limit).

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
    counts = _counts_of(mesh_or_counts, "predict_counts")
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("counts can only be predicted for a registered scheme")
    iterations = check_count(iterations, "iterations")
    duals = check_count(duals, "duals")
    _guard(counts, s, iterations, duals, _limit(max_bytes))
    if isinstance(mesh_or_counts, Mesh) and not mesh_or_counts.is_closed:
        # an open mesh: the counts with its boundary edges and corners
        from .schemes import boundary_corners
        from .schemes.registry import open_counts_after

        m = mesh_or_counts
        start = (*counts, m.n_boundary_edges, len(boundary_corners(m)))
        return [c[:3] for c in open_counts_after(start, s, iterations, duals)]
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
        Also within this memory (as for :func:`subdivide`; default:
        :func:`default_max_bytes`).

    Returns
    -------
    int
        0 when even one iteration would be too large.
    """
    counts = _counts_of(mesh_or_counts, "max_iterations")
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("max_iterations needs a registered scheme")
    duals = check_count(duals, "duals")
    max_faces = check_count(max_faces, "max_faces")
    cap = check_count(cap, "cap")
    limit = _limit(max_bytes)
    for k in range(cap):
        V2, _, F2 = s.counts(*counts)
        biggest = max(F2, V2) if duals else F2
        if biggest > max_faces or _iteration_bytes(s, counts, duals, later=k > 0) > limit:
            return k
        after = _next_counts(s, counts, duals)
        if after == counts and k > 0:
            return cap  # a fixed point: every later iteration is the same
        counts = after
    return cap


def _counts_of(mesh_or_counts: object, caller: str) -> Counts:
    """``(V, E, F)`` of a Mesh, or from a tuple, list or array of three non-negative integers.

    Raises
    ------
    TypeError
        Neither a Mesh nor a sequence (the message names ``caller``).
    ValueError
        Not three non-negative integers.
    """
    if isinstance(mesh_or_counts, Mesh):
        return _vef(mesh_or_counts)
    counts = mesh_or_counts
    if isinstance(counts, (str, bytes)) or not isinstance(counts, (Sequence, np.ndarray)):
        raise TypeError(
            f"{caller} expects a pentanb.Mesh or its counts (V, E, F), got {type(counts).__name__}"
        )
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
    mesh_or_counts: Mesh | Counts, scheme: str | Scheme | None = None, duals: int = 2
) -> int:
    """Bytes of memory for a mesh, or for one iteration on it.

    Parameters
    ----------
    mesh_or_counts : Mesh or (V, E, F)
    scheme : str or Scheme, optional
        With a scheme: the peak memory of one iteration (``scheme``, then
        ``duals`` duals) on a mesh of these counts, above that mesh.
        Without: what a mesh of these counts holds (:func:`mesh_bytes`).
    duals : int
        Duals after the remeshing.

    Returns
    -------
    int
    """
    counts = _counts_of(mesh_or_counts, "estimate_bytes")
    if scheme is None:
        return mesh_bytes(*counts)
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("memory can only be estimated for a registered scheme")
    return _iteration_bytes(s, counts, check_count(duals, "duals"), later=False)


def _limit(max_bytes: object) -> float:
    """``max_bytes`` checked: None -> the default; ``float("inf")`` -> no limit."""
    return float(default_max_bytes()) if max_bytes is None else float(_as_limit(max_bytes))


def _guard(counts: Counts, s: Scheme, iterations: int, duals: int, limit: float) -> None:
    """Refuse (MeshError) at the first iteration over ``limit``; then too many steps (ValueError).

    Walks the iterations one by one, from the first: stops at the first
    over the limit (or at a fixed point of the counts), so it answers in
    microseconds for any ``iterations``.
    """
    for i in range(iterations):
        need = _iteration_bytes(s, counts, duals, later=i > 0)
        if need > limit or need > _ABSOLUTE:
            V2, E2, F2 = s.counts(*counts)
            over = (
                f"over the limit of {limit:,.0f} bytes ({readable(limit)})"
                if need > limit
                else f"beyond what any computer can index ({readable(_ABSOLUTE)})"
            )
            raise MeshError(
                f"{_label(s.name)} iteration {i + 1} of {iterations:,} would build a mesh of "
                f"{F2:,} faces ({V2:,} vertices, {E2:,} edges); with {duals} duals it "
                f"needs about {need:,} bytes ({readable(need)}) at its peak, {over}. "
                "Lower iterations or raise max_bytes."
            )
        after = _next_counts(s, counts, duals)
        if after == counts and i > 0:
            break  # a fixed point: every later iteration is the same (as the second)
        counts = after
    steps = iterations * (1 + duals)
    if steps > MAX_STEPS:
        raise ValueError(
            f"{iterations:,} iterations with {duals:,} duals is {steps:,} steps; at most "
            f"{MAX_STEPS:,} are taken in one call (the counts no longer change, and it "
            "would run for hours)"
        )


# ---------------------------------------------------------------- the default limit
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
        ``"preserve_pentagons"``, ...), a :class:`Scheme` (e.g.
        :func:`pentanb.notation.as_scheme` of Conway operators, ``"dg"``) or
        any ``Mesh -> Mesh`` callable.
    iterations : int, >= 0
        How many times to remesh.
    duals : int, >= 0
        Duals after each remeshing; even keeps the mesh's type (Section 5:
        "Apply dual operation an even number of times").
    progress : callable, True or None
        ``progress(done, total, message)`` after every step; True prints
        the steps to standard error.  Checked before the first step.
    max_bytes : float, optional
        Refuse (with :class:`MeshError`) a request whose peak memory would
        be more than this many bytes (:func:`estimate_bytes`); default:
        :func:`default_max_bytes`; ``float("inf")``: no limit (still
        refused beyond 2**62 bytes, which no computer indexes).
    **options
        Options of the scheme, e.g. ``scale=0.6`` for ``preserve_pentagons``.

    Returns
    -------
    Mesh

    Raises
    ------
    ValueError
        An unknown scheme name (the message lists the known ones), a
        negative count, an option the scheme does not take, a negative or
        NaN ``max_bytes``, or more than :data:`MAX_STEPS` steps.
    TypeError
        ``mesh`` is not a Mesh; a scheme that is neither a string, a Scheme
        nor a callable; a count that is not an integer (``1.5``, ``"2"``,
        None, True); ``max_bytes`` is not a number; ``progress`` is neither
        callable, True nor None; a callable scheme returned something other
        than a Mesh (the message names it).
    MeshError
        Before building anything, when an iteration would not fit in
        ``max_bytes``: the message names the first such iteration, the
        sizes of its mesh and the bytes it would need.

    Notes
    -----
    A callable scheme's growth is not known in advance, so it is guarded
    at every iteration: its first runs (refused when its input alone would
    be over the limit), and before each later one, that one and the rest
    are predicted from the growth of the last (each is assumed to grow the
    mesh as the last did, and to need what a scheme without its own factor
    does, :data:`UNKNOWN`); its duals, whose counts are known, are checked
    before they run.  A request over ``max_bytes`` is refused as soon as
    the growth seen predicts it, also when a callable hands its input back
    once and grows later.
    """
    check_mesh(mesh, "subdivide")
    s = get_scheme(scheme)
    iterations = check_count(iterations, "iterations")
    duals = check_count(duals, "duals")
    limit = _limit(max_bytes)
    progress = _checks.callback(
        progress,
        "progress",
        (None, True, False),
        "a callable progress(done, total, message), True or None",
    )
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            takes = ", ".join(s.options) or "no options"
            raise ValueError(
                f"scheme {_label(s.name, quote=True)} takes {takes}; got {sorted(unknown)}"
            )
        _guard(_vef(mesh), s, iterations, duals, limit)
    else:
        _checks.steps(iterations * (1 + duals), f"{iterations:,} iterations with {duals:,} duals")
        if iterations and mesh_bytes(*_vef(mesh)) > limit:
            raise MeshError(
                f"the input mesh alone ({mesh.n_faces:,} faces) is over the limit of "
                f"{limit:,.0f} bytes ({readable(limit)}); raise max_bytes"
            )
    report = _progress_printer if progress is True else progress
    total = iterations * (1 + duals)
    done = 0
    raw = getattr(s, "name", getattr(s, "__name__", None)) or _checks.shown(s)
    name = _label(raw)
    growth: Counts | None = None  # a callable's: the counts' ratios in its last iteration
    for i in range(iterations):
        before = _vef(mesh)
        if not isinstance(s, Scheme) and i > 0:
            # a callable, guarded at every iteration: this one and every later
            # one predicted from the growth of the last (a callable may hand its
            # input back once and grow the next time)
            _guard_callable(name, before, growth, i, iterations, duals, limit)
        out = s(mesh, **options)
        if not isinstance(out, Mesh):
            raise TypeError(
                f"scheme {_label(raw, quote=True)} returned {type(out).__name__}, not a "
                "pentanb.Mesh "
                "(a callable scheme maps a Mesh to a Mesh)"
            )
        mesh = out
        del out  # so that the duals below free it as soon as they are done with it
        if not isinstance(s, Scheme):
            after = _vef(mesh)
            growth = tuple(a / b if b else 1.0 for a, b in zip(after, before))  # type: ignore[assignment]
            _guard_callable_duals(name, after, i, iterations, duals, limit)
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
    name: str,
    counts: Counts,
    growth: Counts | None,
    i: int,
    iterations: int,
    duals: int,
    limit: float,
) -> None:
    """Before a callable's iteration ``i`` (from 0) on a mesh of ``counts``: refuse
    (MeshError) if it, or a later one, would be over the limit.

    Each iteration is assumed to multiply the counts as the last one did
    (``growth``; None: not known yet, taken as 1), and to need what a scheme
    without its own factor needs (:data:`UNKNOWN`) on top of the mesh it
    reads.  Stops at the first iteration over the limit, or as soon as the
    counts stop growing: microseconds for any ``iterations``.
    """
    g = (1.0, 1.0, 1.0) if growth is None else tuple(float(x) for x in growth)
    V, E, F = (float(x) for x in counts)
    for j in range(i, iterations):
        held = mesh_bytes(V, E, F)
        V, E, F = V * g[0], E * g[1], F * g[2]
        need = FIXED + held + UNKNOWN * _largest_mesh_bytes(max(E, counts[1]))
        if need > limit or need > _ABSOLUTE:
            raise MeshError(
                f"{name} iteration {j + 1} of {iterations:,} would build a mesh of about "
                f"{F:,.0f} faces ({V:,.0f} vertices, {E:,.0f} edges), if it grows as its "
                f"last iteration did; that needs about {need:,.0f} bytes ({readable(need)}), "
                f"over the limit of {limit:,.0f} bytes ({readable(limit)}). Lower iterations "
                "or raise max_bytes."
            )
        if all(x <= 1.0 for x in g):
            break  # not growing: a later iteration needs no more than this one


def _guard_callable_duals(
    name: str, counts: Counts, i: int, iterations: int, duals: int, limit: float
) -> None:
    """Before the duals of a callable's iteration ``i``, on its output of ``counts``:
    refuse (MeshError) when they would be over the limit (their counts are known)."""
    if not duals:
        return
    V, E, F = counts
    need = FIXED + DUAL * (mesh_bytes(V, E, F) + mesh_bytes(F, E, V))
    if need > limit:
        raise MeshError(
            f"the duals of {name} iteration {i + 1} of {iterations:,} (a mesh of {F:,} faces, "
            f"{V:,} vertices, {E:,} edges) need about {need:,} bytes ({readable(need)}), over "
            f"the limit of {limit:,.0f} bytes ({readable(limit)}). Lower iterations or raise "
            "max_bytes."
        )


def _label(name: object, quote: bool = False) -> str:
    """A scheme's name for a message (quoted if ``quote``), cut when long (a Conway string)."""
    text = str(name)
    if len(text) > 60:
        return _checks.shown(text)
    return repr(text) if quote else text


def _progress_printer(done: int, total: int, message: str) -> None:
    width = 20
    filled = width * done // max(total, 1)
    print(
        f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} {message}",
        end="\n" if done == total else "",
        file=sys.stderr,
        flush=True,
    )
