"""Conway polyhedron notation: strings such as ``"gC"`` or ``"ddgT"`` (issue 10).

A string is read right to left, as in the literature (Hart, "Conway
notation for polyhedra"; polyHedronisme; Antiprism's ``conway``): the
rightmost letter is a *seed*, every letter to its left an *operator*
applied to what stands to its right.  ``"dgT"`` is the dual of the
pentagonalized (gyro) tetrahedron, Figure 7(C) of the paper; ``"ddgT"``
is Figure 7(D).

Seeds: ``T C O I D`` (the Platonic solids of :mod:`pentanb.shapes`),
``Pn An Yn`` (prism, antiprism, pyramid on an n-gon, n >= 3), or any
:class:`~pentanb.Mesh` passed as ``seed`` (the string then holds operators
only).

Operators (:data:`OPERATORS`, one table: letter, name, function, count
formula, literature):

* the paper's and its comparison schemes, called as they are:
  ``g`` = :func:`~pentanb.pentagonalize` (gyro), ``q`` =
  :func:`~pentanb.preserve_pentagons` (quinto, scale 0.5), ``e`` =
  :func:`~pentanb.corner_cutting` (expand), ``o`` =
  :func:`~pentanb.vertex_insertion` (ortho), ``c`` =
  :func:`~pentanb.preserve_hexagons` (chamfer), ``z`` =
  :func:`~pentanb.honeycomb` (zip), ``u`` = :func:`~pentanb.loop_remesh`
  (subdivide), ``n`` = :func:`~pentanb.sqrt3_remesh` (needle), ``d`` =
  :func:`~pentanb.dual`;
* the others from :mod:`pentanb.schemes.conway`: ``a t k j s p w m b r``
  (ambo, truncate, kis, join, snub, propeller, whirl, meta, bevel,
  reflect); ``kN`` raises pyramids on N-sided faces only, ``tN`` cuts
  N-valent vertices only (Hart).

Positions follow the package's conventions (edge midpoints and thirds, face
centroids, old vertices kept), so the dual is the paper's smoothing and
``"ddgT"`` is *not* ``"gT"``.  ``canonical=True`` puts the result in
canonical form (:func:`pentanb.positions.canonical`), which depends only on
the topology; there the rewrite table :data:`REDUCTIONS` (``dd`` -> nothing,
``ad`` -> ``a``, ``dk`` -> ``z``, ..., polyHedronisme's and Hart's
substitutions) is applied before any work, because it then changes nothing
but the time.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from . import shapes
from .mesh import Mesh
from .schemes import classic, pentagonal
from .schemes import conway as ops
from .schemes.registry import Scheme
from .schemes.smoothing import dual

__all__ = [
    "conway",
    "resolve",
    "parse",
    "Notation",
    "Token",
    "reduce_notation",
    "predict_counts",
    "NotationError",
    "Operator",
    "Invariants",
    "Seed",
    "OPERATORS",
    "SEEDS",
    "REDUCTIONS",
    "prism",
    "antiprism",
    "pyramid",
]

Counts = tuple[int, int, int]

#: Refuse a string whose predicted result has more faces than this.
MAX_FACES = 1_000_000


class NotationError(ValueError):
    """A malformed Conway string.

    Attributes
    ----------
    notation : str
    position : int
        0-based index of the offending character (``len(notation)`` when
        something is missing at the end).
    """

    def __init__(self, message: str, notation: str, position: int):
        pointer = f"\n  {notation}\n  {' ' * position}^" if notation else ""
        super().__init__(message + pointer)
        self.notation = notation
        self.position = position


# ---------------------------------------------------------------------- the registry
@dataclass(frozen=True)
class Invariants:
    """How an operator turns seed elements into new ones, per seed element.

    The local-symmetry-preserving operations of Brinkmann, Goetschalckx and
    Schein ("Comparing the constructions of Goldberg, Fuller, Caspar, Klug
    and Coxeter, and a general approach to local symmetry-preserving
    operations", Proc. R. Soc. A 473, 2017), in the notation of B.
    Stewart's notes on Conway operators (antitile, ``docs/conway.rst``):
    with ``v_i`` the i-valent vertices, ``f_i`` the i-sided faces and E the
    edges of the seed, the result has

    * ``V_i = a v_{i/k} + E b[i] + c f_{i/l}`` vertices of valence i,
    * ``F_i = (1-a) v_{i/k} + E b'[i] + (1-c) f_{i/l}`` faces of i sides,
    * ``g E`` edges, ``g = 1 + sum(b) + sum(b')``.

    Attributes
    ----------
    a : int
        1 when a seed vertex stays a vertex, 0 when it becomes a face.
    c : int
        1 when a seed face becomes a vertex, 0 when it stays a face.
    k, l : int
        The valence (or size) of what a seed vertex (face) becomes, over its own.
    b : dict
        New vertices per seed edge, by valence.
    b_faces : dict
        New faces per seed edge, by number of sides.
    """

    a: int
    c: int
    k: int
    l: int
    b: Mapping[int, int] = field(default_factory=dict)
    b_faces: Mapping[int, int] = field(default_factory=dict)

    @property
    def g(self) -> int:
        """Edge multiplier (Brinkmann's inflation rate)."""
        return 1 + sum(self.b.values()) + sum(self.b_faces.values())


@dataclass(frozen=True)
class Operator:
    """One letter of Conway notation.

    Attributes
    ----------
    letter : str
    name : str
    func : callable
        ``func(mesh, **options) -> Mesh`` (and ``func(mesh, n)`` for the
        numeric forms ``kN``, ``tN``).
    counts : callable
        ``counts(V, E, F) -> (V', E', F')``: exact for the plain letter, an
        upper bound for the numeric forms.
    invariants : Invariants
        The counts by valence and face size (for the tests and for
        :func:`predict_counts`).
    reference : str
        Where the literature defines it.
    positions : str
        Where the package puts new vertices, against the literature.
    options : dict
        Keyword options and their defaults *in the notation* (``q`` is
        quinto: ``scale=0.5``, not preserve_pentagons' default 0.75).
    number : str or None
        What a number after the letter selects (``"face size"`` for ``kN``,
        ``"valence"`` for ``tN``), or None when it takes none.
    identity : str
        The literature's expression in other operators, if any (``"dg"``).
    """

    letter: str
    name: str
    func: Callable[..., Mesh]
    counts: Callable[..., tuple]
    invariants: Invariants
    reference: str
    positions: str
    options: Mapping[str, float] = field(default_factory=dict)
    number: str | None = None
    identity: str = ""

    @property
    def formula(self) -> str:
        """The count formula as text, e.g. ``"(V+2E+F, 5E, 2E)"``."""
        return _formula_text(self.counts)

    def exact_counts(self, mesh: Mesh, n: int | None = None) -> Counts:
        """``(V', E', F')`` of ``func(mesh, n)``, exact also for ``kN`` / ``tN``."""
        V, E, F = mesh.n_vertices, mesh.n_edges, mesh.n_faces
        if n is None:
            return tuple(int(x) for x in self.counts(V, E, F))  # type: ignore[return-value]
        if self.number == "face size":
            m = int(np.count_nonzero(mesh.face_sizes == n))
            return V + m, E + n * m, F + (n - 1) * m
        m = int(np.count_nonzero(mesh.valences == n))
        return V + (n - 1) * m, E + n * m, F + m


def _formula_text(counts: Callable[..., tuple]) -> str:
    cols = [counts(*e) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    parts = []
    for row in range(3):
        terms = []
        for k, sym in zip((cols[0][row], cols[1][row], cols[2][row]), "VEF"):
            if k:
                terms.append(sym if k == 1 else f"{k}{sym}")
        parts.append("+".join(terms) or "0")
    return "(" + ", ".join(parts) + ")"


def _quinto(mesh: Mesh, scale: float = 0.5) -> Mesh:
    return pentagonal.preserve_pentagons(mesh, scale=scale)


_quinto.__doc__ = "preserve_pentagons with quinto's scale 0.5 as default."

_HART = "Hart, 'Conway notation for polyhedra' (georgehart.com)"
_ANTIPRISM = "Antiprism conway (extended operators)"

_OPERATORS = [
    Operator(
        "d",
        "dual",
        dual,
        lambda V, E, F: (F, E, V),
        Invariants(0, 1, 1, 1),
        f"Conway; {_HART}",
        "vertices at face centroids (the paper's smoothing), so dd is not the "
        "identity; Hart reciprocates in canonical form, where dd = identity",
        identity="",
    ),
    Operator(
        "a",
        "ambo",
        ops.ambo,
        lambda V, E, F: (E, 2 * E, V + F),
        Invariants(0, 0, 1, 1, {4: 1}),
        f"Conway; {_HART}",
        "edge midpoints (Hart: 'truncating to the edge midpoints')",
        identity="dj",
    ),
    Operator(
        "t",
        "truncate",
        ops.truncate,
        lambda V, E, F: (2 * E, 3 * E, V + F),
        Invariants(0, 0, 1, 2, {3: 2}),
        f"Conway; tN: {_HART}",
        "cuts at 1/3 of each edge (the regular tT, tO, tI); Hart: dkd, canonical",
        number="valence",
        identity="dkd",
    ),
    Operator(
        "k",
        "kis",
        ops.kis,
        lambda V, E, F: (V + F, 3 * E, 2 * E),
        Invariants(1, 1, 2, 1, {}, {3: 2}),
        f"Conway; kN: {_HART}",
        "apex at the face centroid (flat pyramids); Hart raises it (canonical)",
        number="face size",
        identity="dtd",
    ),
    Operator(
        "j",
        "join",
        ops.join,
        lambda V, E, F: (V + F, 2 * E, E),
        Invariants(1, 1, 1, 1, {}, {4: 1}),
        f"Conway; {_HART}",
        "old vertices and face centroids; the quads are folded until canonical",
        identity="da",
    ),
    Operator(
        "e",
        "expand",
        classic.corner_cutting,
        lambda V, E, F: (2 * E, 4 * E, V + E + F),
        Invariants(0, 0, 1, 1, {4: 2}, {4: 1}),
        f"Conway (Stott's expansion); {_HART}",
        "corner_cutting: corner (v, f) halfway from v to the centroid of f; aa with "
        "midpoint ambo would put it at (u + 2v + w) / 4",
        options={"scale": 0.5},
        identity="aa",
    ),
    Operator(
        "o",
        "ortho",
        classic.vertex_insertion,
        lambda V, E, F: (V + E + F, 4 * E, 2 * E),
        Invariants(1, 1, 1, 1, {4: 1}, {4: 2}),
        f"Conway; {_HART}",
        "vertex_insertion: edge midpoints and face centroids (Hart: 'new vertices in "
        "the middle of each face ... connected to the edge midpoints'); jj with "
        "centroid join would put the edge vertex at the mean of u, w, c_f, c_g",
        identity="jj",
    ),
    Operator(
        "s",
        "snub",
        ops.snub,
        lambda V, E, F: (2 * E, 5 * E, V + 2 * E + F),
        Invariants(0, 0, 1, 1, {5: 2}, {3: 2}),
        f"Conway; {_HART}",
        "dual(pentagonalize(mesh)): centroids of the gyro pentagons",
        identity="dg",
    ),
    Operator(
        "g",
        "gyro",
        pentagonal.pentagonalize,
        lambda V, E, F: (V + 2 * E + F, 5 * E, 2 * E),
        Invariants(1, 1, 1, 1, {3: 2}, {5: 2}),
        f"Conway; {_HART}; the paper's pentagonalization (Section 5.1)",
        "pentagonalize: edge thirds and face centroids, exactly Hart's 'like k but "
        "with the new edges connecting the face centers to the 1/3 points'",
        identity="ds",
    ),
    Operator(
        "p",
        "propeller",
        ops.propeller,
        lambda V, E, F: (V + 2 * E, 5 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {4: 2}, {4: 2}),
        "Hart, 'Sculpture based on propellorized polyhedra', MOSAIC 2000",
        "edge thirds (as pentagonalize); flat until canonical",
        identity="dpd",
    ),
    Operator(
        "m",
        "meta",
        ops.meta,
        lambda V, E, F: (V + E + F, 6 * E, 4 * E),
        Invariants(1, 1, 2, 2, {4: 1}, {3: 4}),
        f"Conway; {_HART}",
        "edge midpoints and face centroids (flat until canonical)",
        identity="kj",
    ),
    Operator(
        "b",
        "bevel",
        ops.bevel,
        lambda V, E, F: (4 * E, 6 * E, V + E + F),
        Invariants(0, 0, 2, 2, {3: 4}, {4: 1}),
        f"Conway; {_HART}",
        "truncate(ambo(mesh)): thirds of the ambo edges",
        identity="ta",
    ),
    Operator(
        "c",
        "chamfer",
        classic.preserve_hexagons,
        lambda V, E, F: (V + 2 * E, 4 * E, F + E),
        Invariants(1, 0, 1, 1, {3: 2}, {6: 1}),
        f"{_ANTIPRISM}; Goldberg-Coxeter GP(m, n) -> GP(2m, 2n)",
        "preserve_hexagons: old vertices kept, face copies halfway to the centroid "
        "in the face's plane, so the new hexagons are folded along the old edge "
        "(planar only in canonical form)",
        options={"scale": 0.5},
        identity="dud",
    ),
    Operator(
        "w",
        "whirl",
        ops.whirl,
        lambda V, E, F: (V + 4 * E, 7 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {3: 4}, {6: 2}),
        f"{_ANTIPRISM} ('gyro followed by truncation of vertices centered on original faces')",
        "edge thirds; inner points 1/3 from the centroid along the gyro spokes",
    ),
    Operator(
        "q",
        "quinto",
        _quinto,
        lambda V, E, F: (V + 3 * E, 6 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {3: 2, 4: 1}, {5: 2}),
        f"{_ANTIPRISM}; the paper's pentagon preservation (Section 5.2)",
        "preserve_pentagons with scale 0.5 (the inner face halfway between the "
        "centroid of the edge midpoints and the midpoints); its own default is 0.75",
        options={"scale": 0.5},
    ),
    Operator(
        "z",
        "zip",
        classic.honeycomb,
        lambda V, E, F: (2 * E, 3 * E, V + F),
        Invariants(0, 0, 2, 1, {3: 2}),
        f"{_ANTIPRISM} (zip = dk, bitruncation); the paper's honeycomb (Figure 13)",
        "honeycomb: centroid of (u, w, c_f), exactly dual(kis(mesh)) with the package's centroids",
        identity="dk",
    ),
    Operator(
        "u",
        "subdivide",
        classic.loop_remesh,
        lambda V, E, F: (V + E, 4 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {6: 1}, {3: 2}),
        f"{_ANTIPRISM} ('ambo while retaining original vertices'); Loop's remeshing (Figure 3)",
        "loop_remesh: old vertices and edge midpoints (not pushed to a sphere)",
        identity="dcd",
    ),
    Operator(
        "n",
        "needle",
        classic.sqrt3_remesh,
        lambda V, E, F: (V + F, 3 * E, 2 * E),
        Invariants(1, 1, 1, 2, {}, {3: 2}),
        f"{_ANTIPRISM} (needle = kd = dt); the sqrt(3) remeshing (Section 3)",
        "sqrt3_remesh: old vertices and face centroids, two triangles across every edge",
        identity="kd",
    ),
    Operator(
        "r",
        "reflect",
        ops.reflect,
        lambda V, E, F: (V, E, F),
        Invariants(1, 0, 1, 1),
        f"Hart; {_HART}",
        "x -> -x, faces reversed",
    ),
]

#: Every operator letter, in the order of the table above.
OPERATORS: dict[str, Operator] = {op.letter: op for op in _OPERATORS}


# ---------------------------------------------------------------------- seeds
@dataclass(frozen=True)
class Seed:
    """A seed letter: ``build(n)`` gives the mesh, ``counts(n)`` its (V, E, F)."""

    letter: str
    name: str
    build: Callable[..., Mesh]
    counts: Callable[..., Counts]
    needs_number: bool = False


def _regular_polygon(n: int, z: float = 0.0, turn: float = 0.0) -> np.ndarray:
    t = 2.0 * np.pi * (np.arange(n) + turn) / n
    return np.stack([np.cos(t), np.sin(t), np.full(n, z)], axis=1)


def _check_n(n, what: str) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"{what} needs an integer number of sides, got {n!r}")
    if n < 3:
        raise ValueError(f"{what} needs at least 3 sides, got {n}")
    return int(n)


def prism(n: int) -> Mesh:
    """The prism ``Pn`` on a regular n-gon of circumradius 1, with square sides.

    Returns
    -------
    Mesh
        2n vertices (bottom ring, then top ring), 3n edges, n + 2 faces
        (bottom, top, then the n quads).  ``P4`` is a cube.
    """
    n = _check_n(n, "a prism")
    side = 2.0 * np.sin(np.pi / n)
    v = np.concatenate([_regular_polygon(n, -side / 2), _regular_polygon(n, side / 2)])
    i = np.arange(n)
    j = (i + 1) % n
    quads = np.stack([i, j, n + j, n + i], axis=1)
    faces = [i[::-1], n + i] + list(quads)
    return Mesh(v, faces)


def antiprism(n: int) -> Mesh:
    """The antiprism ``An`` on a regular n-gon of circumradius 1, with
    equilateral triangles (the uniform antiprism).

    Returns
    -------
    Mesh
        2n vertices, 4n edges, 2n + 2 faces (bottom, top, then 2n
        triangles).  ``A3`` is an octahedron.
    """
    n = _check_n(n, "an antiprism")
    h = np.sqrt(2.0 * np.cos(np.pi / n) - 2.0 * np.cos(2.0 * np.pi / n))
    v = np.concatenate([_regular_polygon(n, -h / 2), _regular_polygon(n, h / 2, turn=0.5)])
    i = np.arange(n)
    j = (i + 1) % n
    down = np.stack([i, j, n + i], axis=1)
    up = np.stack([n + i, j, n + j], axis=1)
    faces = [i[::-1], n + i] + list(down) + list(up)
    return Mesh(v, faces)


def pyramid(n: int) -> Mesh:
    """The pyramid ``Yn`` on a regular n-gon of circumradius 1.

    Equilateral triangles where they exist (n <= 5: the tetrahedron and
    Johnson's J1, J2), height 1 otherwise; centred on its vertices' mean.

    Returns
    -------
    Mesh
        n + 1 vertices (the base ring, then the apex), 2n edges, n + 1
        faces (the base, then the n triangles).  ``Y3`` is a tetrahedron.
    """
    n = _check_n(n, "a pyramid")
    side2 = (2.0 * np.sin(np.pi / n)) ** 2
    h = np.sqrt(side2 - 1.0) if n < 6 else 1.0
    v = np.concatenate([_regular_polygon(n), [[0.0, 0.0, h]]])
    v -= v.mean(axis=0)
    i = np.arange(n)
    tris = np.stack([i, (i + 1) % n, np.full(n, n)], axis=1)
    return Mesh(v, [i[::-1]] + list(tris))


_SEEDS = [
    Seed("T", "tetrahedron", shapes.tetrahedron, lambda: (4, 6, 4)),
    Seed("C", "cube", shapes.cube, lambda: (8, 12, 6)),
    Seed("O", "octahedron", shapes.octahedron, lambda: (6, 12, 8)),
    Seed("I", "icosahedron", shapes.icosahedron, lambda: (12, 30, 20)),
    Seed("D", "dodecahedron", shapes.dodecahedron, lambda: (20, 30, 12)),
    Seed("P", "prism", prism, lambda n: (2 * n, 3 * n, n + 2), True),
    Seed("A", "antiprism", antiprism, lambda n: (2 * n, 4 * n, 2 * n + 2), True),
    Seed("Y", "pyramid", pyramid, lambda n: (n + 1, 2 * n, n + 1), True),
]

#: Every seed letter.
SEEDS: dict[str, Seed] = {s.letter: s for s in _SEEDS}


# ---------------------------------------------------------------------- parsing
@dataclass(frozen=True)
class Token:
    """One letter of a string, with its number (``k4``) and 0-based position."""

    letter: str
    number: int | None
    position: int

    def __str__(self) -> str:
        return self.letter + ("" if self.number is None else str(self.number))


@dataclass(frozen=True)
class Notation:
    """A parsed string: the operators left to right, and the seed (or None)."""

    text: str
    operators: tuple[Token, ...]
    seed: Token | None

    def __str__(self) -> str:
        return "".join(str(t) for t in self.operators) + (str(self.seed) if self.seed else "")


_DIGITS = "0123456789"


def _known() -> str:
    return f"operators {' '.join(OPERATORS)} (kN, tN take a number); seeds T C O I D Pn An Yn"


def parse(notation: str, *, seed_given: bool = False) -> Notation:
    """Check and split a Conway string.

    Parameters
    ----------
    notation : str
    seed_given : bool
        A mesh is passed as the seed: the string must hold operators only.

    Returns
    -------
    Notation

    Raises
    ------
    TypeError
        ``notation`` is not a string.
    NotationError
        (a ValueError) naming the character and its 0-based position: an
        empty string, an unknown letter, a number where none may stand or a
        missing one (``P``), a number out of range (``P2``, ``k2``), no
        seed, a seed that is not the rightmost letter, a seed both in the
        string and passed as a mesh.
    """
    if not isinstance(notation, str):
        raise TypeError(f"a Conway notation must be a string, got {type(notation).__name__}")
    s = notation
    if not s:
        raise NotationError(
            "empty notation: write operators then a seed, e.g. 'gC' (" + _known() + ")", s, 0
        )
    tokens: list[Token] = []
    i = 0
    while i < len(s):
        ch = s[i]
        if ch in _DIGITS:
            raise NotationError(f"number {ch!r} at position {i} does not follow a letter", s, i)
        op, seed = OPERATORS.get(ch), SEEDS.get(ch)
        if op is None and seed is None:
            raise NotationError(
                f"unknown letter {ch!r} at position {i} in {s!r}; " + _known(), s, i
            )
        j = i + 1
        while j < len(s) and s[j] in _DIGITS:
            j += 1
        digits = s[i + 1 : j]
        number = None
        if digits:
            takes = op.number if op is not None else (seed is not None and seed.needs_number)
            if not takes:
                name = op.name if op is not None else seed.name  # type: ignore[union-attr]
                raise NotationError(
                    f"{ch!r} ({name}) at position {i} takes no number, "
                    f"but {digits!r} follows it at position {i + 1}",
                    s,
                    i + 1,
                )
            number = int(digits)
            if number < 3:
                what = op.number if op is not None else "number of sides"
                name = op.name if op is not None else seed.name  # type: ignore[union-attr]
                raise NotationError(
                    f"{ch}{digits} at position {i}: {name} needs a {what} of at least 3",
                    s,
                    i + 1,
                )
        elif seed is not None and seed.needs_number:
            raise NotationError(
                f"seed {ch!r} ({seed.name}) at position {i} needs a number of sides "
                f"(at least 3), e.g. {ch}5",
                s,
                j,
            )
        tokens.append(Token(ch, number, i))
        i = j
    seeds = [t for t in tokens if t.letter in SEEDS]
    if seed_given:
        if seeds:
            t = seeds[0]
            raise NotationError(
                f"seed given twice: {str(t)!r} at position {t.position} and the seed "
                "argument (with a mesh as seed the string holds operators only)",
                s,
                t.position,
            )
        return Notation(s, tuple(tokens), None)
    if not seeds:
        raise NotationError(
            f"no seed in {s!r}: end the string with T, C, O, I, D, Pn, An or Yn, "
            "or pass a Mesh as seed",
            s,
            len(s),
        )
    first = seeds[0]
    if first is not tokens[-1]:
        raise NotationError(
            f"seed {str(first)!r} at position {first.position} is not at the right end: "
            "operators stand left of the one seed, e.g. 'dkC'",
            s,
            first.position,
        )
    return Notation(s, tuple(tokens[:-1]), tokens[-1])


# ---------------------------------------------------------------------- reductions
#: Rewrites that keep the oriented topology: (pattern, replacement), read
#: like the notation (``("a", "d") -> ("a",)`` is ``ad -> a``).  From Hart's
#: and polyHedronisme's substitutions (dd -> "", ad -> a, ...) and the
#: operators' definitions (z = dk, n = kd, t = dkd, s = dg, j = da, o = de,
#: b = dm, c = dud, p = dpd).  Every rule shortens the string.
REDUCTIONS: tuple[tuple[str, str], ...] = (
    ("dd", ""),
    ("rr", ""),
    ("ad", "a"),
    ("jd", "j"),
    ("ed", "e"),
    ("od", "o"),
    ("bd", "b"),
    ("md", "m"),
    ("da", "j"),
    ("dj", "a"),
    ("de", "o"),
    ("do", "e"),
    ("db", "m"),
    ("dm", "b"),
    ("dk", "z"),
    ("dz", "k"),
    ("kd", "n"),
    ("nd", "k"),
    ("td", "z"),
    ("zd", "t"),
    ("dt", "n"),
    ("dn", "t"),
    ("dg", "s"),
    ("ds", "g"),
    ("dpd", "p"),
    ("dud", "c"),
    ("dcd", "u"),
)

#: Seed rewrites (Hart): a dual seed is another seed; P4 = C, A3 = O, Y3 = T.
SEED_REDUCTIONS: dict[str, str] = {
    "dT": "T",
    "dC": "O",
    "dO": "C",
    "dI": "D",
    "dD": "I",
    "P4": "C",
    "A3": "O",
    "Y3": "T",
}


def _reduce(n: Notation) -> Notation:
    toks = list(n.operators)
    seed = n.seed
    changed = True
    while changed:
        changed = False
        for pattern, repl in REDUCTIONS:
            k = len(pattern)
            for i in range(len(toks) - k + 1):
                window = toks[i : i + k]
                if all(t.number is None and t.letter == c for t, c in zip(window, pattern)):
                    pos = window[0].position
                    toks[i : i + k] = [Token(c, None, pos) for c in repl]
                    changed = True
                    break
            if changed:
                break
        if not changed and seed is not None:
            key = str(seed)
            if key in SEED_REDUCTIONS:
                seed = Token(SEED_REDUCTIONS[key], None, seed.position)
                changed = True
            elif toks and toks[-1].letter == "d" and "d" + key in SEED_REDUCTIONS:
                seed = Token(SEED_REDUCTIONS["d" + key], None, seed.position)
                toks.pop()
                changed = True
    return Notation(n.text, tuple(toks), seed)


def reduce_notation(notation: str) -> str:
    """The string after the rewrites of :data:`REDUCTIONS` (same topology).

    Examples
    --------
    >>> reduce_notation("ddgT")
    'gT'
    >>> reduce_notation("dkdC")
    'tC'
    """
    seedless = not any(c in SEEDS for c in notation) if isinstance(notation, str) else False
    return str(_reduce(parse(notation, seed_given=seedless)))


# ---------------------------------------------------------------------- applying
def _check_options(n: Notation, options: Mapping) -> None:
    takes = {k for t in n.operators for k in OPERATORS[t.letter].options}
    unknown = sorted(set(options) - takes)
    if unknown:
        offer = (
            "; ".join(
                f"{op.letter} ({op.name}) takes {', '.join(op.options)}"
                for op in _OPERATORS
                if op.options
            )
            or "none"
        )
        raise TypeError(f"option(s) {unknown} are taken by no operator of {n.text!r} ({offer})")


def _apply(tokens, mesh: Mesh, options: Mapping) -> Mesh:
    for tok in reversed(tokens):
        op = OPERATORS[tok.letter]
        kwargs = {k: options.get(k, default) for k, default in op.options.items()}
        mesh = (
            op.func(mesh, tok.number, **kwargs)
            if tok.number is not None
            else op.func(mesh, **kwargs)
        )
    return mesh


def _upper_counts(tokens, counts: Counts) -> list[Counts]:
    out = [counts]
    for tok in reversed(tokens):
        counts = OPERATORS[tok.letter].counts(*counts)
        out.append(counts)
    return out


def predict_counts(notation: str, seed: Mesh | None = None) -> tuple[Counts, bool]:
    """``(V, E, F)`` of ``conway(notation, seed)`` without building it.

    Returns
    -------
    counts : (V, E, F)
    exact : bool
        False when the string holds ``kN`` or ``tN``: the counts are then an
        upper bound (every face or vertex counted as chosen).
    """
    n = parse(notation, seed_given=seed is not None)
    start = _seed_counts(n, seed)
    steps = _upper_counts(n.operators, start)
    return steps[-1], not any(t.number is not None for t in n.operators)


def _seed_counts(n: Notation, seed: Mesh | None) -> Counts:
    if seed is not None:
        return seed.n_vertices, seed.n_edges, seed.n_faces
    assert n.seed is not None
    s = SEEDS[n.seed.letter]
    return s.counts(n.seed.number) if s.needs_number else s.counts()


def conway(
    notation: str,
    seed: Mesh | None = None,
    *,
    canonical: bool = False,
    reduce: bool | None = None,
    max_faces: int = MAX_FACES,
    **options,
) -> Mesh:
    """Build the polyhedron a Conway string names (issue 10).

    Parameters
    ----------
    notation : str
        Operators then a seed, read right to left: ``"gC"``, ``"ddgT"``,
        ``"t5dA5"``, ``"k4P6"``; operators only when ``seed`` is given.
    seed : Mesh, optional
        Any mesh to start from instead of a seed letter.
    canonical : bool
        Put the result in canonical form (:func:`pentanb.positions.canonical`;
        genus 0 only).  Otherwise the package's positions (centroids, edge
        midpoints and thirds; the dual is the paper's smoothing).
    reduce : bool, optional
        Apply :data:`REDUCTIONS` first.  Default: only with ``canonical``,
        where it changes nothing but the time (with the package's positions
        ``dd`` is two smoothing steps, Figure 7, not the identity).
    max_faces : int
        Refuse, before building anything, a string whose predicted result
        (an upper bound with ``kN``/``tN``) has more faces.
    **options
        Options of the operators in the string, given to every operator that
        takes them: ``scale`` for ``q`` (default 0.5), ``e`` and ``c`` (0.5).

    Returns
    -------
    Mesh

    Raises
    ------
    NotationError
        (a ValueError) a malformed string; the message names the character
        and its position.
    TypeError
        ``notation`` is not a string, ``seed`` not a Mesh, or an option no
        operator of the string takes.
    ValueError
        The predicted result exceeds ``max_faces``; an option's value is
        out of range.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.notation import conway
    >>> m = conway("tI")
    >>> m.n_vertices, m.n_edges, m.n_faces, m.face_size_histogram()
    (60, 90, 32, {5: 12, 6: 20})
    """
    if seed is not None and not isinstance(seed, Mesh):
        raise TypeError(f"seed must be a pentanb.Mesh or None, got {type(seed).__name__}")
    n = parse(notation, seed_given=seed is not None)
    _check_options(n, options)
    if reduce is None:
        reduce = bool(canonical)
    if reduce:
        n = _reduce(n)
    start = _seed_counts(n, seed)
    for V, E, F in _upper_counts(n.operators, start):
        if F > max_faces or V > 2 * max_faces:
            raise ValueError(
                f"{notation!r} would build a mesh of about {F:,} faces ({V:,} vertices, "
                f"{E:,} edges), over max_faces={max_faces:,}"
            )
    if seed is None:
        assert n.seed is not None
        s = SEEDS[n.seed.letter]
        seed = s.build(n.seed.number) if s.needs_number else s.build()
    mesh = _apply(n.operators, seed, options)
    if canonical:
        from .positions import canonical as _canonical

        mesh = _canonical(mesh)
    return mesh


def resolve(text: str) -> Scheme:
    """An operator string as a :class:`~pentanb.schemes.registry.Scheme`.

    For the explorer and :func:`pentanb.subdivide`, which take a scheme
    name: ``resolve("dgd")`` is a scheme whose ``func(mesh, **options)``
    applies the operators right to left, with the package's positions, and
    whose ``counts(V, E, F)`` composes the operators' formulas (an upper
    bound, ``exact_counts=False``, when ``kN`` or ``tN`` occur).

    Raises
    ------
    NotationError
        A malformed string, or one holding a seed letter.
    """
    n = parse(text, seed_given=True)
    tokens = n.operators
    opts: dict[str, float] = {}
    for t in reversed(tokens):
        for k, v in OPERATORS[t.letter].options.items():
            opts.setdefault(k, v)

    def func(mesh: Mesh, **options) -> Mesh:
        _check_options(n, options)
        return _apply(tokens, mesh, options)

    def counts(V, E, F):
        for tok in reversed(tokens):
            V, E, F = OPERATORS[tok.letter].counts(V, E, F)
        return V, E, F

    func.__name__ = f"conway_{text}"
    names = " of ".join(
        OPERATORS[t.letter].name + (str(t.number) if t.number else "") for t in tokens
    )
    return Scheme(
        name=text,
        func=func,
        label=f"Conway {text} ({names})",
        paper="issue 10: Conway notation",
        conway=text,
        counts=counts,
        options=opts,
        family="conway",
        exact_counts=not any(t.number is not None for t in tokens),
    )
