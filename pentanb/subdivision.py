"""``subdivide``: remesh, then smooth; and the counts that say in advance how large.

Every scheme of :data:`pentanb.SCHEMES` knows how its output's counts follow
from its input's, so :func:`subdivide` can refuse, before building anything,
a request that would not fit in memory, and :func:`max_iterations` can bound
a slider.
"""

from __future__ import annotations

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
    "SCHEMES",
    "Scheme",
    "get_scheme",
]


def predict_counts(
    counts: Counts, scheme: str | Scheme, iterations: int = 1, duals: int = 2
) -> list[Counts]:
    """The (V, E, F) after every step of :func:`subdivide`, without building anything.

    Parameters
    ----------
    counts : (V, E, F)
    scheme, iterations, duals : as for :func:`subdivide`

    Returns
    -------
    list of (V, E, F)
        One entry per remeshing and per dual, in order.
    """
    s = get_scheme(scheme)
    if not isinstance(s, Scheme):
        raise ValueError("counts can only be predicted for a registered scheme")
    V, E, F = _as_counts(counts, "predict_counts")
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
) -> int:
    """The most iterations of ``scheme`` whose meshes all stay within ``max_faces``.

    Predicted from the counts (nothing is built): the bound a slider over
    iterations should have.

    Parameters
    ----------
    mesh_or_counts : Mesh or (V, E, F)
    scheme : str or Scheme
    duals : int
        Duals after each remeshing (as in :func:`subdivide`).
    max_faces : int
        Largest number of faces any step may have.
    cap : int
        Never more than this many iterations.

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
    steps = predict_counts(counts, scheme, cap, duals)
    per_iteration = 1 + duals
    for k in range(cap):
        if max(F for _, _, F in steps[k * per_iteration : (k + 1) * per_iteration]) > max_faces:
            return k
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


def estimate_bytes(V: int, E: int, F: int) -> int:
    """Bytes a mesh of these counts needs while operators work on it.

    Positions (24 bytes a vertex), faces (8 bytes a corner plus 8 a face)
    and about six derived int64 arrays per half-edge.
    """
    return 24 * V + 8 * F + 8 * 2 * E * 7


def default_max_bytes() -> int:
    """Half of this machine's physical memory (4 GiB where it cannot be read)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2
    except (ValueError, OSError, AttributeError):  # pragma: no cover - non-POSIX
        return 4 << 30


def subdivide(
    mesh: Mesh,
    scheme: str | Scheme | Callable = "pentagonalize",
    iterations: int = 1,
    duals: int = 2,
    *,
    progress=None,
    max_bytes: int | None = None,
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
    max_bytes : int, optional
        Refuse (with :class:`MeshError`) a request whose largest mesh would
        need more; default: half of the physical memory.
    **options
        Options of the scheme, e.g. ``scale=0.6`` for ``preserve_pentagons``.

    Returns
    -------
    Mesh

    Raises
    ------
    ValueError
        An unknown scheme name (the message lists the known ones), a bad
        count, or an option the scheme does not take.
    MeshError
        When the result would not fit in ``max_bytes``; the message gives
        the number of faces and bytes it would need.
    """
    check_mesh(mesh, "subdivide")
    s = get_scheme(scheme)
    iterations = check_count(iterations, "iterations")
    duals = check_count(duals, "duals")
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            takes = ", ".join(s.options) or "no options"
            raise ValueError(f"scheme {s.name!r} takes {takes}; got {sorted(unknown)}")
        limit = default_max_bytes() if max_bytes is None else _as_limit(max_bytes)
        steps = predict_counts(_vef(mesh), s, iterations, duals)
        if steps:
            V, E, F = max(steps, key=lambda c: estimate_bytes(*c))
            need = estimate_bytes(V, E, F)
            if need > limit:
                raise MeshError(
                    f"{s.name} x{iterations} with {duals} duals would build a mesh of "
                    f"{F:,} faces ({V:,} vertices, {E:,} edges) needing about "
                    f"{need:,} bytes, over the limit of {limit:,} bytes "
                    "(lower iterations or raise max_bytes)"
                )
    report = _progress_printer if progress is True else progress
    total = iterations * (1 + duals)
    done = 0
    name = getattr(s, "name", getattr(s, "__name__", "scheme"))
    for i in range(iterations):
        mesh = s(mesh, **options)
        if not isinstance(mesh, Mesh):
            raise TypeError(
                f"scheme {name!r} returned {type(mesh).__name__}, not a pentanb.Mesh "
                "(a callable scheme maps a Mesh to a Mesh)"
            )
        done += 1
        if report:
            report(done, total, f"{name} {i + 1}/{iterations}: {mesh.n_faces:,} faces")
        for d in range(duals):
            mesh = dual(mesh)
            done += 1
            if report:
                report(done, total, f"dual {d + 1}/{duals}: {mesh.n_faces:,} faces")
    return mesh


def _progress_printer(done: int, total: int, message: str) -> None:
    width = 20
    filled = width * done // max(total, 1)
    print(
        f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} {message}",
        end="\n" if done == total else "",
        file=sys.stderr,
        flush=True,
    )
