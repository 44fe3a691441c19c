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

Open meshes: every scheme's counts are written once, with the number B of
boundary edges and C of corners (:func:`pentanb.schemes.boundary_corners`,
the boundary vertices the dual keeps): :attr:`Scheme.open_counts`, ``(V, E,
F, B, C) -> (V', E', F', B', C')``; the closed counts are those with ``B = C
= 0``.  :func:`dual_counts` is the dual's, :func:`open_counts_after` the
counts after every step of :func:`pentanb.subdivide` on an open mesh.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ..mesh import Mesh
from . import classic, pentagonal
from .table import Table

__all__ = [
    "Scheme",
    "SCHEMES",
    "get_scheme",
    "count_formula",
    "Counts",
    "OpenCounts",
    "dual_counts",
    "open_counts_after",
    "from_table",
]

Counts = tuple[int, int, int]
#: (V, E, F, B, C): vertices, edges, faces, boundary edges and corners.
OpenCounts = tuple[int, int, int, int, int]


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
    open_counts : callable or None
        ``open_counts(V, E, F, B, C) -> (V', E', F', B', C')`` for a mesh
        with B boundary edges and C corners (B = C = 0: closed, and
        ``counts`` is its first three); None for a scheme whose open counts
        are not known.
    table : Table or None
        The scheme as data (:class:`~pentanb.schemes.table.Table`), where it
        is one: its points' weights and faces (what the analysis reads).
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
    open_counts: Callable[[int, int, int, int, int], OpenCounts] | None = None
    table: Table | None = None

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

    @property
    def open_formula(self) -> str:
        """The count formula with boundary terms, e.g. ``"(V+2E+F, 5E-B, 2E-B, 3B, C)"``.

        ``(V', E', F', B', C')`` from the input's (V, E, F), B boundary
        edges and C corners; empty when :attr:`open_counts` is None.
        """
        if self.open_counts is None:
            return ""
        text = count_formula(self.open_counts, boundary=True)
        if self.exact_counts:
            return text
        return text + " at most" + (f" ({self.bound})" if self.bound else "")


def from_table(table: Table, paper: str = "", family: str = "comparison") -> Scheme:
    """A :class:`Scheme` of a :class:`~pentanb.schemes.table.Table`, its counts the table's.

    Closed meshes: the table's counts; open ones (tables without faces round
    vertices): its boundary terms, the dual's corners C carried over (a
    boundary vertex of one face stays one).  A user's own table gets what
    the built-in schemes get: :func:`pentanb.subdivide`, the memory guard,
    :func:`pentanb.predict_counts`, the explorer, the analysis.
    """

    def open_counts(V: Any, E: Any, F: Any, B: Any, C: Any) -> OpenCounts:
        V2, E2, F2, B2 = table.open_counts(V, E, F, B)
        return V2, E2, F2, B2, C

    return Scheme(
        table.name,
        table,
        table.label,
        paper or "a table of your own",
        None,
        table.counts,
        options=dict(table.options),
        family=family,
        open_counts=None if table.compiled.open_rule else open_counts,
        table=table,
    )


def count_formula(counts: Callable[..., tuple], boundary: bool = False) -> str:
    """A count formula as text: ``"(V+2E+F, 5E, 2E)"`` for pentagonalization's.

    Parameters
    ----------
    counts : callable
        ``counts(V, E, F) -> (V', E', F')``, or with ``boundary``
        ``counts(V, E, F, B, C) -> (V', E', F', B', C')``, linear in its
        arguments (it is evaluated on symbols: sums, differences and
        integer multiples only).
    boundary : bool
        Whether ``counts`` also takes and gives B and C, the boundary edges
        and corners.

    Returns
    -------
    str
        The linear forms, their terms in the order V, E, F (, B, C).
    """
    k = 5 if boundary else 3
    symbols: list[Any] = [_Linear(tuple(int(i == j) for j in range(k))) for i in range(k)]
    return "(" + ", ".join(str(x) for x in counts(*symbols)) + ")"


class _Linear:
    """A linear form in V, E, F (and B, C), to print a scheme's count formula."""

    def __init__(self, c: Iterable[int]) -> None:
        self.c = tuple(c)

    def __add__(self, o: object) -> _Linear:
        if isinstance(o, _Linear):
            return _Linear(a + b for a, b in zip(self.c, o.c))
        if o == 0:  # sum() starts from 0
            return self
        return NotImplemented

    __radd__ = __add__

    def __neg__(self) -> _Linear:
        return _Linear(-a for a in self.c)

    def __sub__(self, o: object) -> _Linear:
        if isinstance(o, _Linear):
            return self + (-o)
        if o == 0:
            return self
        return NotImplemented

    def __mul__(self, k: int) -> _Linear:
        return _Linear(k * a for a in self.c)

    __rmul__ = __mul__

    def __str__(self) -> str:
        text = ""
        for k, name in zip(self.c, "VEFBC"):
            if k:
                term = name if abs(k) == 1 else f"{abs(k)}{name}"
                text += ("-" if k < 0 else "+" if text else "") + term
        return text or "0"


def _closed(open_counts: Callable[..., OpenCounts]) -> Callable[..., Counts]:
    """The closed counts ``(V, E, F) -> (V', E', F')``: ``open_counts`` at B = C = 0."""

    def counts(V: Any, E: Any, F: Any) -> Counts:
        V2, E2, F2, _, _ = open_counts(V, E, F, 0, 0)
        return V2, E2, F2

    return counts


def _scheme(*args: Any, open_counts: Callable[..., OpenCounts], **kw: Any) -> Scheme:
    """A :class:`Scheme` whose closed counts are its open counts at B = C = 0 (one formula)."""
    name, func, label, paper, conway = args
    return Scheme(
        name, func, label, paper, conway, _closed(open_counts), open_counts=open_counts, **kw
    )


def dual_counts(V: int, E: int, F: int, B: int = 0, C: int = 0) -> OpenCounts:
    """The counts of the dual: ``(F + B + C, E + B + C, V, B + C, C)``.

    A vertex per face, per boundary edge (its midpoint) and per corner
    (kept), a face per vertex (see :func:`pentanb.dual`); ``(F, E, V)``
    when closed.

    Parameters
    ----------
    V, E, F, B, C : int
        Vertices, edges, faces, boundary edges and corners of the input.

    Returns
    -------
    (int, int, int, int, int)
        ``(V', E', F', B', C')``.
    """
    return F + B + C, E + B + C, V, B + C, C


def open_counts_after(
    counts: OpenCounts, scheme: str | Scheme, iterations: int = 1, duals: int = 2
) -> list[OpenCounts]:
    """The (V, E, F, B) after every step of :func:`pentanb.subdivide`, boundary included.

    Parameters
    ----------
    counts : (V, E, F, B, C)
        The input's vertices, edges, faces, boundary edges
        (``mesh.n_boundary_edges``) and corners
        (``len(pentanb.schemes.boundary_corners(mesh))``).
    scheme : str or Scheme
        A registered scheme.
    iterations, duals : int
        As for :func:`pentanb.subdivide`.

    Returns
    -------
    list of (V, E, F, B, C)
        One entry per remeshing and per dual, in order.

    Raises
    ------
    ValueError
        A scheme that is not registered or whose open counts are not known.
    """
    s = get_scheme(scheme)
    if not isinstance(s, Scheme) or s.open_counts is None:
        raise ValueError(f"no open counts for {scheme!r}")
    out: list[OpenCounts] = []
    V, E, F, B, C = counts
    for _ in range(iterations):
        V, E, F, B, C = s.open_counts(V, E, F, B, C)
        out.append((V, E, F, B, C))
        for _ in range(duals):
            V, E, F, B, C = dual_counts(V, E, F, B, C)
            out.append((V, E, F, B, C))
    return out


_LIST = [
    _scheme(
        "pentagonalize",
        pentagonal.pentagonalize,
        "Pentagonalization",
        "Section 5.1, Figures 1, 6-9, 12",
        "gyro",
        # a pentagon per half-edge (2E - B), every edge in three (3B on the boundary)
        open_counts=lambda V, E, F, B, C: (V + 2 * E + F, 5 * E - B, 2 * E - B, 3 * B, C),
        family="pentagonal",
        table=pentagonal.PENTAGONALIZE,
    ),
    _scheme(
        "preserve_pentagons",
        pentagonal.preserve_pentagons,
        "Pentagon preservation",
        "Section 5.2, Figures 1D, 10, 11",
        "quinto (scale 0.5)",
        # midpoints, a copy vertex per half-edge; a copy per face, a pentagon per half-edge
        open_counts=lambda V, E, F, B, C: (V + 3 * E - B, 6 * E - 2 * B, F + 2 * E - B, 2 * B, C),
        options={"scale": 0.75},
        family="pentagonal",
        table=pentagonal.PRESERVE_PENTAGONS,
    ),
    _scheme(
        "triangulate",
        classic.triangulate,
        "Simplest triangulation",
        "Figure 2",
        None,
        # all triangles (2E - B = 3F): kept as they are; else at most (exact
        # without triangles); the boundary is kept
        open_counts=lambda V, E, F, B, C: (
            (V, E, F, B, C) if 2 * E - B == 3 * F else (V + F, 3 * E - B, 2 * E - B, B, 0)
        ),
        exact_counts=False,
        bound="when no face is a triangle",
    ),
    _scheme(
        "loop_remesh",
        classic.loop_remesh,
        "Loop remeshing",
        "Section 3, Figure 3",
        "subdivide",
        open_counts=lambda V, E, F, B, C: (V + E, 4 * E - B, F + 2 * E - B, 2 * B, C),
        table=classic.LOOP,
    ),
    _scheme(
        "sqrt3_remesh",
        classic.sqrt3_remesh,
        "sqrt(3) remeshing",
        "Section 3",
        "needle",
        # the boundary kept: a triangle (u, w, c_f) on every boundary half-edge
        # (which gives a corner a second face)
        open_counts=lambda V, E, F, B, C: (V + F, 3 * E - B, 2 * E - B, B, 0),
        table=classic.SQRT3,
    ),
    _scheme(
        "vertex_insertion",
        classic.vertex_insertion,
        "Vertex insertion (Catmull-Clark)",
        "Section 3",
        "ortho",
        open_counts=lambda V, E, F, B, C: (V + E + F, 4 * E - B, 2 * E - B, 2 * B, C),
        table=classic.VERTEX_INSERTION,
    ),
    _scheme(
        "corner_cutting",
        classic.corner_cutting,
        "Corner cutting (Doo-Sabin)",
        "Section 3",
        "expand",
        # a point per half-edge, two per boundary edge (Chaikin's), the corners kept
        open_counts=lambda V, E, F, B, C: (2 * E + B + C, 4 * E + B + C, V + E + F, 2 * B + C, C),
        options={"scale": 0.5},
        table=classic.CORNER_CUTTING,
    ),
    _scheme(
        "preserve_hexagons",
        classic.preserve_hexagons,
        "Hexagon preservation (dual of Loop)",
        "Section 4, Figures 4-5",
        "chamfer",
        # a copy point per half-edge and every boundary edge in three; a corner
        # gets a second face
        open_counts=lambda V, E, F, B, C: (V + 2 * E + B, 4 * E + B, F + E, 3 * B, 0),
        options={"scale": 0.5},
        table=classic.PRESERVE_HEXAGONS,
    ),
    _scheme(
        "honeycomb",
        classic.honeycomb,
        "Honeycomb (dual of sqrt(3))",
        "Section 6, Figure 13",
        "zip",
        # a point per half-edge and per boundary edge (its midpoint), the corners kept
        open_counts=lambda V, E, F, B, C: (2 * E + C, 3 * E + C, V + F, B + C, C),
        table=classic.HONEYCOMB,
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
    scheme : str, Scheme, Table or callable
        A key of :data:`SCHEMES`, a scheme, a table of one
        (:class:`~pentanb.schemes.table.Table`) or a ``Mesh -> Mesh`` callable.

    Returns
    -------
    Scheme or callable
        The registered :class:`Scheme`, a table's (:func:`from_table`), or
        ``scheme`` itself.

    Raises
    ------
    ValueError
        For a name that is not in :data:`SCHEMES`; the message lists the
        known names.
    TypeError
        For neither a string, a Scheme nor a callable (``5``, None, a list).
    """
    if isinstance(scheme, Table):
        return from_table(scheme)
    if isinstance(scheme, Scheme) or (callable(scheme) and not isinstance(scheme, str)):
        return scheme
    if not isinstance(scheme, str):
        raise TypeError(
            f"scheme must be a scheme's name ({', '.join(SCHEMES)}), a pentanb.Scheme or a "
            f"Mesh -> Mesh callable, got {type(scheme).__name__}"
        )
    if scheme in SCHEMES:
        return SCHEMES[scheme]
    raise ValueError(f"unknown scheme {scheme!r}; known schemes: {', '.join(SCHEMES)}")
