"""One registry of every remeshing scheme, and ``subdivide``: remesh, then smooth.

:data:`SCHEMES` names every remeshing operator of the package once, so a
slider, the command line and the tests can list them all.  Each entry knows
its paper reference, its Conway name and how its output's counts follow from
its input's, which lets :func:`subdivide` refuse, before building anything,
a request that would not fit in memory.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from . import classic, pentagonal
from .dual import _check_count, dual
from .mesh import Mesh, MeshError

__all__ = [
    "Scheme",
    "SCHEMES",
    "subdivide",
    "predict_counts",
    "max_iterations",
    "estimate_bytes",
    "get_scheme",
]

Counts = tuple[int, int, int]


@dataclass(frozen=True)
class Scheme:
    """A named remeshing operator.

    Attributes
    ----------
    name : str
        Registry key (also the function's name).
    func : callable
        ``func(mesh, **options) -> Mesh``.
    label : str
        Human-readable name for menus and legends.
    paper : str
        Where the paper describes or shows it.
    conway : str or None
        The Conway operator with the same topology, if any.
    counts : callable
        ``counts(V, E, F) -> (V', E', F')`` (an upper bound for ``triangulate``).
    options : dict
        Keyword options and their defaults (e.g. ``{"scale": 0.75}``).
    family : str
        ``"pentagonal"`` for the paper's schemes, ``"comparison"`` otherwise.
    exact_counts : bool
        False when ``counts`` is only an upper bound (``triangulate``, which
        leaves triangles alone).
    """

    name: str
    func: Callable[..., Mesh]
    label: str
    paper: str
    conway: str | None
    counts: Callable[[int, int, int], Counts]
    options: Mapping[str, float] = field(default_factory=dict)
    family: str = "comparison"
    exact_counts: bool = True

    def __call__(self, mesh: Mesh, **options) -> Mesh:
        return self.func(mesh, **options)

    @property
    def formula(self) -> str:
        """The count formula as text, e.g. ``"(V+2E+F, 5E, 2E)"``.

        ``counts`` is evaluated on symbols (it is linear in V, E and F).
        """
        out = self.counts(_Linear((1, 0, 0)), _Linear((0, 1, 0)), _Linear((0, 0, 1)))
        text = "(" + ", ".join(str(x) for x in out) + ")"
        return text if self.exact_counts else text + " at most (when no face is a triangle)"


class _Linear:
    """A linear form in V, E, F, to print a scheme's count formula."""

    def __init__(self, c):
        self.c = tuple(c)

    def __add__(self, o):
        o = o if isinstance(o, _Linear) else _Linear((0, 0, 0))
        return _Linear(a + b for a, b in zip(self.c, o.c))

    __radd__ = __add__

    def __mul__(self, k):
        return _Linear(k * a for a in self.c)

    __rmul__ = __mul__

    def __str__(self):
        parts = [name if k == 1 else f"{k}{name}" for k, name in zip(self.c, "VEF") if k]
        return "+".join(parts) or "0"


_LIST = [
    Scheme(
        "pentagonalize",
        pentagonal.pentagonalize,
        "Pentagonalization",
        "Section 5.1, Figures 1, 6-9, 12",
        "gyro",
        lambda V, E, F: (V + 2 * E + F, 5 * E, 2 * E),
        family="pentagonal",
    ),
    Scheme(
        "preserve_pentagons",
        pentagonal.preserve_pentagons,
        "Pentagon preservation",
        "Section 5.2, Figures 1D, 10, 11",
        "quinto (scale 0.5)",
        lambda V, E, F: (V + 3 * E, 6 * E, F + 2 * E),
        {"scale": 0.75},
        family="pentagonal",
    ),
    Scheme(
        "triangulate",
        classic.triangulate,
        "Simplest triangulation",
        "Figure 2",
        None,
        lambda V, E, F: (V + F, 3 * E, 2 * E),
        exact_counts=False,
    ),
    Scheme(
        "loop_remesh",
        classic.loop_remesh,
        "Loop remeshing",
        "Section 3, Figure 3",
        "subdivide",
        lambda V, E, F: (V + E, 4 * E, F + 2 * E),
    ),
    Scheme(
        "sqrt3_remesh",
        classic.sqrt3_remesh,
        "sqrt(3) remeshing",
        "Section 3",
        None,
        lambda V, E, F: (V + F, 3 * E, 2 * E),
    ),
    Scheme(
        "vertex_insertion",
        classic.vertex_insertion,
        "Vertex insertion (Catmull-Clark)",
        "Section 3",
        "ortho",
        lambda V, E, F: (V + E + F, 4 * E, 2 * E),
    ),
    Scheme(
        "corner_cutting",
        classic.corner_cutting,
        "Corner cutting (Doo-Sabin)",
        "Section 3",
        "expand",
        lambda V, E, F: (2 * E, 4 * E, V + E + F),
        {"scale": 0.5},
    ),
    Scheme(
        "preserve_hexagons",
        classic.preserve_hexagons,
        "Hexagon preservation (dual of Loop)",
        "Section 4, Figures 4-5",
        "chamfer",
        lambda V, E, F: (V + 2 * E, 4 * E, F + E),
        {"scale": 0.5},
    ),
    Scheme(
        "honeycomb",
        classic.honeycomb,
        "Honeycomb (dual of sqrt(3))",
        "Section 6, Figure 13",
        "zip",
        lambda V, E, F: (2 * E, 3 * E, V + F),
    ),
]

#: Every remeshing scheme of the package, by name.
SCHEMES: dict[str, Scheme] = {s.name: s for s in _LIST}


def get_scheme(scheme: str | Scheme | Callable) -> Scheme | Callable:
    """Look a scheme up by name; a :class:`Scheme` or callable passes through.

    Raises
    ------
    ValueError
        For an unknown name; the message lists the known ones.
    """
    if isinstance(scheme, Scheme) or (callable(scheme) and not isinstance(scheme, str)):
        return scheme
    try:
        return SCHEMES[scheme]
    except (KeyError, TypeError):
        raise ValueError(
            f"unknown scheme {scheme!r}; known schemes: {', '.join(SCHEMES)}"
        ) from None


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
    mesh_or_counts, scheme: str | Scheme, duals: int = 2, max_faces: int = 100_000, cap: int = 8
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
        mesh_or_counts
        if isinstance(mesh_or_counts, tuple)
        else (mesh_or_counts.n_vertices, mesh_or_counts.n_edges, mesh_or_counts.n_faces)
    )
    steps = predict_counts(counts, scheme, cap, duals)
    per_iteration = 1 + duals
    for k in range(cap):
        if max(F for _, _, F in steps[k * per_iteration : (k + 1) * per_iteration]) > max_faces:
            return k
    return cap


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
    s = get_scheme(scheme)
    iterations = _check_count(iterations, "iterations")
    duals = _check_count(duals, "duals")
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            takes = ", ".join(s.options) or "no options"
            raise ValueError(f"scheme {s.name!r} takes {takes}; got {sorted(unknown)}")
        limit = default_max_bytes() if max_bytes is None else int(max_bytes)
        steps = predict_counts((mesh.n_vertices, mesh.n_edges, mesh.n_faces), s, iterations, duals)
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
