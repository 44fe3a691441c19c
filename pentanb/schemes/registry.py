"""The registry of remeshing schemes: one table that names every operator once.

:data:`SCHEMES` names every remeshing operator of the package, so a slider,
the command line and the tests can list them all.  Each entry knows its
paper reference, its Conway name and how its output's counts follow from its
input's (which lets :func:`pentanb.subdivide` refuse, before building
anything, a request that would not fit in memory).  :func:`get_scheme` is
the one place where a registered name is checked.

The count formulas are written here once: the Conway operators that are
these schemes (:data:`pentanb.notation.OPERATORS`: ``g q e o c z u n``)
take theirs from :data:`SCHEMES`.  Nothing in :mod:`pentanb.schemes`
imports :mod:`pentanb.notation`; Conway strings used as scheme names
(``"dg"``) are resolved by :func:`pentanb.notation.as_scheme`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ..mesh import Mesh
from . import classic, pentagonal

__all__ = ["Scheme", "SCHEMES", "get_scheme", "count_formula", "Counts"]

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
        ``counts(V, E, F) -> (V', E', F')`` (for ``triangulate`` exact on
        all-triangle meshes, which it keeps, and on meshes without
        triangles; an upper bound between).
    options : dict
        Keyword options and their defaults (e.g. ``{"scale": 0.75}``).
    family : str
        ``"pentagonal"`` for the paper's schemes, ``"comparison"`` otherwise.
    exact_counts : bool
        False when ``counts`` is only an upper bound (``triangulate``, which
        leaves triangles alone; Conway strings with ``kN`` or ``tN``).
    bound : str
        When the upper bound is reached, printed after "at most" by
        :attr:`formula` (e.g. ``"when no face is a triangle"``).
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
    bound: str = ""

    def __call__(self, mesh: Mesh, **options) -> Mesh:
        return self.func(mesh, **options)

    @property
    def formula(self) -> str:
        """The count formula as text, e.g. ``"(V+2E+F, 5E, 2E)"``.

        ``counts`` is evaluated on symbols (it is linear in V, E and F).
        """
        text = count_formula(self.counts)
        if self.exact_counts:
            return text
        return text + " at most" + (f" ({self.bound})" if self.bound else "")


def count_formula(counts: Callable[..., tuple]) -> str:
    """A count formula as text: ``"(V+2E+F, 5E, 2E)"`` for pentagonalization's.

    Parameters
    ----------
    counts : callable
        ``counts(V, E, F) -> (V', E', F')``, linear in V, E and F (it is
        evaluated on symbols: sums and integer multiples only).

    Returns
    -------
    str
        The three linear forms, their terms in the order V, E, F.
    """
    symbols: list[Any] = [_Linear((1, 0, 0)), _Linear((0, 1, 0)), _Linear((0, 0, 1))]
    return "(" + ", ".join(str(x) for x in counts(*symbols)) + ")"


class _Linear:
    """A linear form in V, E, F, to print a scheme's count formula."""

    def __init__(self, c: Iterable[int]) -> None:
        self.c = tuple(c)

    def __add__(self, o: object) -> _Linear:
        if isinstance(o, _Linear):
            return _Linear(a + b for a, b in zip(self.c, o.c))
        if o == 0:  # sum() starts from 0
            return self
        return NotImplemented

    __radd__ = __add__

    def __mul__(self, k: int) -> _Linear:
        return _Linear(k * a for a in self.c)

    __rmul__ = __mul__

    def __str__(self) -> str:
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
        # all triangles (2E = 3F): kept as they are; else at most (exact
        # without triangles)
        lambda V, E, F: (V, E, F) if 2 * E == 3 * F else (V + F, 3 * E, 2 * E),
        exact_counts=False,
        bound="when no face is a triangle",
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
    """Look a registered scheme up by name; a :class:`Scheme` or callable passes through.

    Conway strings (``"dg"``) are not read here (:mod:`pentanb.schemes`
    does not import :mod:`pentanb.notation`): :func:`pentanb.notation.as_scheme`
    accepts everything this function does, and Conway operators too.

    Parameters
    ----------
    scheme : str, Scheme or callable
        A key of :data:`SCHEMES`, or a scheme or ``Mesh -> Mesh`` callable.

    Returns
    -------
    Scheme or callable
        The registered :class:`Scheme`, or ``scheme`` itself.

    Raises
    ------
    ValueError
        For a name that is not in :data:`SCHEMES`; the message lists the
        known names.
    """
    if isinstance(scheme, Scheme) or (callable(scheme) and not isinstance(scheme, str)):
        return scheme
    if isinstance(scheme, str) and scheme in SCHEMES:
        return SCHEMES[scheme]
    raise ValueError(f"unknown scheme {scheme!r}; known schemes: {', '.join(SCHEMES)}")
