"""Closed surfaces: Section 4's equation (1), its limit, the counts and vertex
ranges it allows, the existence criteria, the chart of ``(n, m)`` pairs, and
the dual statements (``v`` replaced with ``f``).

See :mod:`pentanb.topology` for the whole section; every name here is
importable from there.  This module needs only numpy.
"""

from __future__ import annotations

import math
import numbers
import operator
from fractions import Fraction
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "average_valence",
    "limit_valence",
    "limit_valence_is_integer",
    "ngon_mesh_counts",
    "vertex_range",
    "min_vertices",
    "can_tile",
    "ngonalization_exists",
    "ngon_preservation_exists",
    "SchlafliRow",
    "SCHLAFLI_CHART",
    "schlafli_chart",
    "average_face_size",
    "limit_face_size",
    "mvalent_mesh_counts",
    "face_range",
    "min_faces",
]

FloatArray = NDArray[np.float64]

#: ``(v_min, v_max)``; ``v_max`` is :data:`math.inf` when unbounded.
Range = tuple[int, int | float]


# --------------------------------------------------------------------------
# Input checking
# --------------------------------------------------------------------------


def _as_int(name: str, value: object, minimum: int) -> int:
    """``value`` as a Python int ``>= minimum``, or a ValueError naming it.

    Integer-valued floats and Fractions (``5.0``) are accepted; bools,
    non-integers, NaN and infinities are not.
    """
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if isinstance(value, numbers.Integral):
        out = int(value)
    elif isinstance(value, numbers.Real) and math.isfinite(value) and value == math.floor(value):
        out = operator.index(math.floor(value))
    else:
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if out < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {out}")
    return out


def _as_int_array(name: str, value: ArrayLike, minimum: int) -> NDArray[np.int64]:
    """Array version of :func:`_as_int` (every entry integer-valued, ``>= minimum``)."""
    a = np.asarray(value)
    if a.dtype == np.bool_ or not (
        np.issubdtype(a.dtype, np.integer) or np.issubdtype(a.dtype, np.floating)
    ):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if np.issubdtype(a.dtype, np.floating):
        if not np.all(np.isfinite(a)) or np.any(a != np.round(a)):
            raise ValueError(f"{name} must be an integer, got {value!r}")
        a = a.astype(np.int64)
    if np.any(a < minimum):
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return a.astype(np.int64)


def _as_count_array(name: str, value: ArrayLike) -> FloatArray:
    """``value`` as a float array of positive reals (``inf`` allowed, NaN not)."""
    a = np.asarray(value)
    if a.dtype == np.bool_ or not (
        np.issubdtype(a.dtype, np.integer) or np.issubdtype(a.dtype, np.floating)
    ):
        raise ValueError(f"{name} must be a positive number, got {value!r}")
    a = a.astype(np.float64)
    if np.any(np.isnan(a)) or np.any(a <= 0):
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return a


# --------------------------------------------------------------------------
# Equation (1) and its limit
# --------------------------------------------------------------------------


def _equation_1(
    k: ArrayLike, g: ArrayLike, count: ArrayLike, names: tuple[str, str]
) -> float | FloatArray:
    """``2k/(k-2) (1 + (2g-2)/count)``, broadcast, with ``count = inf`` allowed."""
    k = _as_int_array(names[0], k, 3)
    g = _as_int_array("g", g, 0)
    c = _as_count_array(names[1], count)
    k, g, c = np.broadcast_arrays(k, g, c)
    kf, gf = k.astype(np.float64), g.astype(np.float64)
    limit = 2.0 * kf / (kf - 2.0)
    with np.errstate(invalid="ignore"):
        # One division of two exact integers: correctly rounded, so that for
        # instance the dodecahedron (n=5, g=0, v=20) gives exactly 3.0.
        finite = (2.0 * kf * (c + 2.0 * gf - 2.0)) / ((kf - 2.0) * c)
    out = np.where(np.isinf(c), limit, finite)
    return float(out) if out.ndim == 0 else out


def average_valence(n: ArrayLike, g: ArrayLike, v: ArrayLike) -> float | FloatArray:
    """Average vertex valence of a closed mesh of ``n``-gons: equation (1).

    .. math::  m = \\frac{2n}{n - 2} \\left(1 + \\frac{2g - 2}{v}\\right)

    It follows from Euler's formula ``v - e + f = 2 - 2g`` with ``2e = n f``
    and ``2e = m v`` (Section 4).  For ``g = 0`` it is below the limit
    ``2n/(n-2)`` and increases with ``v``; for ``g = 1`` it equals the limit
    for every ``v``; for ``g >= 2`` it is above the limit and decreases
    with ``v``.

    Parameters
    ----------
    n : int or (...) int array
        Number of sides of every face, ``>= 3``.  The paper: "since we
        enforce use of the same type of polygon everywhere, n should be
        integer".
    g : int or (...) int array
        Genus, ``>= 0``.
    v : number or (...) float array
        Number of vertices, ``> 0``.  Real values are accepted so that the
        curve ``m(v)`` can be drawn, and ``v = inf`` gives the limit
        :func:`limit_valence`.  Values ``v <= 2 - 2g`` give ``m <= 0``: no
        mesh has so few vertices.

    Returns
    -------
    float or (...) float
        ``m``, broadcast over the inputs; a float when all inputs are scalars.

    Raises
    ------
    ValueError
        If ``n < 3``, ``g < 0``, ``v <= 0``, ``n`` or ``g`` is not an integer,
        or ``v`` is NaN.

    Examples
    --------
    >>> average_valence(5, 0, 20)   # the dodecahedron is 3-valent
    3.0
    >>> average_valence(6, 0, 12)   # m = 3 (1 - 2/v) < 3: no hexagonal sphere
    2.5
    """
    return _equation_1(n, g, v, ("n", "v"))


def limit_valence(n: int) -> Fraction:
    """Limit of equation (1) as ``v -> inf``: ``2n / (n - 2)``, exactly.

    Section 4: "Another interesting case occurs when v goes to infinity ...
    This is the same as the value of the m for g = 1, which corresponds to
    planar tesselations."  It is a monotone decreasing function of ``n``
    that equals 3 at ``n = 6`` and is below 3 for every ``n > 6``.

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.

    Returns
    -------
    fractions.Fraction
        6 for triangles, 4 for quads, 10/3 for pentagons, 3 for hexagons.
        For arrays, use ``average_valence(n, 1, v)`` (any ``v``) or
        ``average_valence(n, g, numpy.inf)``.

    Raises
    ------
    ValueError
        If ``n`` is not an integer ``>= 3``.
    """
    n = _as_int("n", n, 3)
    return Fraction(2 * n, n - 2)


def limit_valence_is_integer(n: int) -> bool:
    """Whether ``n``-gon meshes have an integer average valence in the limit.

    Section 2: "The average valence of vertices (vertex degree) in a
    pentagonal meshes is necessarily rational, while triangular and
    quadrilateral meshes can have integer vertex degree."  The statement is
    about the limit ``v -> inf`` (equivalently genus 1, the planar
    tessellations) where ``m = 2n/(n-2)``: 6 for ``n = 3``, 4 for ``n = 4``,
    3 for ``n = 6`` but 10/3 for ``n = 5``.  Hence the chart's remark that
    ``(5, 10/3)`` "can only have semi-regular tesselations": no pentagonal
    mesh of genus 1 has all vertices of one valence.

    A finite pentagonal mesh of another genus *can* have an integer average
    valence: the dodecahedron (``g = 0``, ``v = 20``) has ``m = 3``.

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.

    Returns
    -------
    bool
        True exactly for ``n`` in ``(3, 4, 6)``: ``(n - 2)`` divides ``2n``,
        i.e. ``n - 2`` divides 4.

    Raises
    ------
    ValueError
        If ``n`` is not an integer ``>= 3``.
    """
    return limit_valence(n).denominator == 1


# --------------------------------------------------------------------------
# Counts, vertex ranges, existence
# --------------------------------------------------------------------------


def ngon_mesh_counts(n: int, g: int, v: int) -> tuple[int, int, int] | None:
    """``(v, e, f)`` of a closed mesh of only ``n``-gons with ``v`` vertices.

    Solving Euler's formula ``v - e + f = 2 - 2g`` together with ``2e = n f``
    (Section 4) gives

    .. math::  f = \\frac{2 (v + 2g - 2)}{n - 2}, \\qquad
               e = \\frac{n (v + 2g - 2)}{n - 2} = \\frac{n f}{2}.

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    v : int
        Number of vertices, ``>= 1``.

    Returns
    -------
    (int, int, int) or None
        ``(v, e, f)``, or None when ``e`` or ``f`` would not be a positive
        integer.  Valence is not checked here: see :func:`can_tile`.

    Raises
    ------
    ValueError
        If ``n < 3``, ``g < 0``, ``v <= 0`` or any of them is not an integer.

    Examples
    --------
    >>> ngon_mesh_counts(5, 0, 20)   # dodecahedron
    (20, 30, 12)
    >>> ngon_mesh_counts(5, 0, 21) is None   # f = 38/3
    True
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    v = _as_int("v", v, 1)
    k = v + 2 * g - 2
    if k <= 0 or (2 * k) % (n - 2):
        return None
    f = 2 * k // (n - 2)
    e = n * k // (n - 2)  # = n f / 2 = k + f, an integer once f is
    return v, e, f


def _counts_ok_and_3valent(n: int, g: int, v: int) -> bool:
    """Counts exist and the average valence ``2e / v`` is ``>= 3``."""
    counts = ngon_mesh_counts(n, g, v)
    return counts is not None and 2 * counts[1] >= 3 * v


def vertex_range(n: int, g: int) -> Range | None:
    """Range of ``v`` for which an ``n``-gon mesh of genus ``g`` can have ``m >= 3``.

    Section 4 asks for the ``v`` at which equation (1) gives an average
    valence ``m >= 3``, "If not, it means that ... more and more vertices
    with less than valence 3 will be created."  With ``L = 2n/(n-2)``,
    ``m >= 3`` is ``L (v + 2g - 2) >= 3 v``; multiplying by ``n - 2 > 0``,

    .. math::  (6 - n)\\, v \\ge 4 n (1 - g).

    * ``n < 6``: ``v >= 4n(1-g)/(6-n)``, bounded below only.  For ``g = 0``
      this is ``v >= 4n/(6-n)``: 4 for triangles (tetrahedron), 8 for quads
      (cube), 20 for pentagons (dodecahedron).  For ``g >= 1`` every ``v``
      passes.
    * ``n = 6``: ``0 >= 24(1 - g)``, never for ``g = 0`` (equation (1) is
      ``m = 3(1 - 2/v) < 3``), always for ``g >= 1``.
    * ``n > 6``: ``v <= 4n(g-1)/(n-6) = (2g-2) 2n/(n-6)``, finitely many
      ``v`` and only for ``g >= 2``: "there can be some special n-gonal
      meshes for a small values of v and large values of g".

    Integrality is then imposed: ``e`` and ``f`` of :func:`ngon_mesh_counts`
    must be positive integers, i.e. ``v + 2g - 2 > 0`` and
    ``v = 2 - 2g (mod p)`` with ``p = (n - 2) / gcd(n - 2, 2)``.  Every ``v``
    in the returned range with that residue is admissible, and no other.

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.

    Returns
    -------
    (int, int or float) or None
        ``(v_min, v_max)``, the smallest and largest admissible ``v``, with
        ``v_max = math.inf`` when unbounded; None when no ``v`` is
        admissible.

    Raises
    ------
    ValueError
        If ``n < 3``, ``g < 0`` or either is not an integer.

    Examples
    --------
    >>> vertex_range(5, 0)
    (20, inf)
    >>> vertex_range(6, 0) is None
    True
    >>> vertex_range(8, 2)   # up to the (8, 3) mesh with 16 vertices
    (1, 16)
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    lhs, rhs = 6 - n, 4 * n * (1 - g)  # m >= 3  <=>  lhs * v >= rhs
    lo = max(1, 3 - 2 * g)  # v >= 1 and v + 2g - 2 > 0
    hi: int | float = math.inf
    if lhs > 0:
        lo = max(lo, -(-rhs // lhs))  # ceil(rhs / lhs)
    elif lhs == 0:
        if rhs > 0:
            return None
    else:
        if rhs > 0:  # v <= rhs / lhs < 0
            return None
        hi = rhs // lhs  # floor(4n(g-1)/(n-6)), exact on ints
    p = (n - 2) // math.gcd(n - 2, 2)
    r = (2 - 2 * g) % p
    v_min = lo + (r - lo) % p
    if hi != math.inf:
        hi = int(hi)
        v_max: int | float = hi - (hi - r) % p
        if v_min > v_max:
            return None
    else:
        v_max = math.inf
    return v_min, v_max


def min_vertices(n: int, g: int) -> int | None:
    """Smallest ``v`` of an ``n``-gon mesh of genus ``g`` with ``m >= 3``.

    Section 4 for ``g = 0``: pentagons need ``v >= 20`` ("v = 20 corresponds
    to a dodecahedron"), quads ``v >= 8`` ("an hexahedron (generalized
    cube)"), triangles ``v >= 4`` ("a tetrahedron"), and hexagons never.
    See :func:`vertex_range` for the derivation.

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.

    Returns
    -------
    int or None
        None when no such mesh exists count-wise.

    Raises
    ------
    ValueError
        If ``n < 3``, ``g < 0`` or either is not an integer.
    """
    r = vertex_range(n, g)
    return None if r is None else r[0]


def can_tile(n: int, g: int, v: int | None = None) -> bool:
    """Whether a genus-``g`` mesh of only ``n``-gons with ``m >= 3`` can exist.

    Count-wise (Section 4): Euler's formula must give positive integer
    ``e`` and ``f`` and equation (1) must give an average valence ``m >= 3``
    (no accumulation of 1- and 2-valent vertices).

    Parameters
    ----------
    n : int
        Number of sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    v : int, optional
        Number of vertices, ``>= 1``.  When omitted: whether *some* ``v``
        works.

    Returns
    -------
    bool
        For instance False for ``(6, 0)`` (no hexagonal sphere), True for
        ``(6, 1)``, False for ``(5, 0, 19)`` and True for ``(5, 0, 20)``.

    Raises
    ------
    ValueError
        If ``n < 3``, ``g < 0``, ``v <= 0`` or any of them is not an integer.
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    if v is None:
        return vertex_range(n, g) is not None
    return _counts_ok_and_3valent(n, g, _as_int("v", v, 1))


def ngonalization_exists(n: int) -> bool:
    """Whether an ``n``-gonalization (conversion) scheme can exist.

    Such a scheme turns *any* mesh into a mesh of only ``n``-gons and, as a
    subdivision, increases ``v`` at every iteration.  So it needs ``n``-gon
    meshes with ``m >= 3`` for every genus ``g``, ``g = 0`` included, and
    arbitrarily large ``v``.  Section 4: ``2n/(n-2)`` "becomes smaller than
    3 for values of n larger than 6", so "no n-gonalization scheme exists
    for n > 6"; and for ``n = 6`` and ``g = 0``, ``m = 3(1 - 2/v) < 3``, so
    "it is not possible to develop an hexagonalization scheme since such a
    scheme must also work for g = 0 case".  For ``n <= 5`` it exists (the
    abstract: "it is possible to represent any 2-manifold with a mesh that
    is made up of only pentagons").

    Computed from :func:`vertex_range` at ``g = 0``: ``v`` is unbounded at
    ``g = 0`` exactly when ``n < 6``, and then the lower bound
    ``4n(1-g)/(6-n)`` only falls as ``g`` grows, so ``v`` is unbounded for
    every genus.

    Parameters
    ----------
    n : int
        Number of sides, ``>= 3``.

    Returns
    -------
    bool
        True for ``n`` in ``(3, 4, 5)``, False for ``n >= 6``.

    Raises
    ------
    ValueError
        If ``n`` is not an integer ``>= 3``.
    """
    r = vertex_range(n, 0)
    return r is not None and r[1] == math.inf


def ngon_preservation_exists(n: int) -> bool:
    """Whether an ``n``-gon preservation scheme can exist.

    A preservation scheme maps ``n``-gon meshes to ``n``-gon meshes with
    more vertices, so it needs, for some genus, ``n``-gon meshes with
    ``m >= 3`` and arbitrarily large ``v``.  Section 4: "non-gon
    preservation scheme exists for n > 6 since a preservation scheme that
    can be used in subdivision must increase v", while "it is possible to
    develop an hexagonal preservation scheme since hexagonal meshes exist
    for g > 0"; pentagonal preservation is one of the paper's schemes.

    Computed from :func:`vertex_range` at ``g = 1``: unbounded for every
    ``n <= 6``, while for ``n > 6`` ``v`` is bounded (or empty) at every
    genus.

    Parameters
    ----------
    n : int
        Number of sides, ``>= 3``.

    Returns
    -------
    bool
        True for ``n <= 6``, False for ``n > 6``.

    Raises
    ------
    ValueError
        If ``n`` is not an integer ``>= 3``.
    """
    r = vertex_range(n, 1)
    return r is not None and r[1] == math.inf


# --------------------------------------------------------------------------
# The chart of Section 4
# --------------------------------------------------------------------------


class SchlafliRow(NamedTuple):
    """One row of the paper's chart of ``(n, m)`` Schlafli pairs (Section 4).

    Attributes
    ----------
    n : Fraction
        Average number of sides of a face.
    m : Fraction
        Average valence of a vertex, ``2n/(n-2)``.
    description : str
        The chart's "type" column, as printed in the paper.
    admits_regular : bool
        Whether both ``n`` and ``m`` are integers, so that a regular
        tessellation (every face an ``n``-gon, every vertex ``m``-valent) is
        possible.  "(5, 10/3) can only have semi-regular tesselations."
    dual_of : (Fraction, Fraction) or None
        For ``(10/3, 5)``: ``(5, 10/3)``, whose analysis it repeats "by
        replacing v with f".  None otherwise.
    """

    n: Fraction
    m: Fraction
    description: str
    admits_regular: bool
    dual_of: tuple[Fraction, Fraction] | None


def _chart_number(x: Fraction) -> str:
    """The chart's spelling: ``6`` for 6, ``3.3`` for 10/3 (truncated)."""
    return str(x.numerator) if x.denominator == 1 else f"{math.floor(x * 10) / 10:.1f}"


def schlafli_chart() -> tuple[SchlafliRow, ...]:
    """The paper's chart of ``(n, m)`` pairs in the limit ``v -> inf`` (Section 4).

    Rows in the paper's order: ``(6, 3)``, ``(5, 10/3)``, ``(4, 4)``,
    ``(10/3, 5)``, ``(3, 6)``.  Each ``m`` is :func:`limit_valence` of ``n``;
    ``(10/3, 5)`` is the dual of ``(5, 10/3)``: the same analysis with ``v``
    replaced by ``f`` (:func:`limit_face_size` of ``m = 5``).

    Returns
    -------
    tuple of SchlafliRow
    """
    pairs: list[tuple[Fraction, Fraction, tuple[Fraction, Fraction] | None]] = [
        (Fraction(n), limit_valence(n), None) for n in (6, 5, 4, 3)
    ]
    # The dual of (5, 10/3): 5-valent vertices, faces of average size 10/3.
    pentagon = pairs[1]
    pairs.append((limit_face_size(5), Fraction(5), (pentagon[0], pentagon[1])))
    pairs.sort(key=lambda row: -row[0])
    return tuple(
        SchlafliRow(
            n=n,
            m=m,
            description=(
                f"Average {_chart_number(n)}-sided faces with average "
                f"{_chart_number(m)}-valent vertices"
            ),
            admits_regular=n.denominator == 1 and m.denominator == 1,
            dual_of=dual,
        )
        for n, m, dual in pairs
    )


# --------------------------------------------------------------------------
# Dual statements: replace v with f
# --------------------------------------------------------------------------


def average_face_size(m: ArrayLike, g: ArrayLike, f: ArrayLike) -> float | FloatArray:
    """Average face size of a closed mesh whose vertices are all ``m``-valent.

    The dual of equation (1) (Section 4: "the same analysis can be repeated
    just by replacing v with f"; Section 2: the results "are also applicable
    to dual schemes"):

    .. math::  n = \\frac{2m}{m - 2} \\left(1 + \\frac{2g - 2}{f}\\right).

    Parameters
    ----------
    m : int or (...) int array
        Valence of every vertex, ``>= 3``.
    g : int or (...) int array
        Genus, ``>= 0``.
    f : number or (...) float array
        Number of faces, ``> 0``; ``inf`` gives :func:`limit_face_size`.

    Returns
    -------
    float or (...) float
        Average number of sides ``n``.

    Raises
    ------
    ValueError
        If ``m < 3``, ``g < 0``, ``f <= 0``, ``m`` or ``g`` is not an
        integer, or ``f`` is NaN.
    """
    return _equation_1(m, g, f, ("m", "f"))


def limit_face_size(m: int) -> Fraction:
    """Limit of :func:`average_face_size` as ``f -> inf``: ``2m/(m-2)``, exactly.

    For ``m = 5`` it is 10/3: the chart's ``(10/3, 5)``, "the dual of
    ``(5, 10/3)``".

    Parameters
    ----------
    m : int, >= 3
        The valence of every vertex.

    Returns
    -------
    Fraction
        ``2m / (m - 2)``.

    Raises
    ------
    ValueError
        If ``m`` is not an integer ``>= 3``.
    """
    m = _as_int("m", m, 3)
    return Fraction(2 * m, m - 2)


def mvalent_mesh_counts(m: int, g: int, f: int) -> tuple[int, int, int] | None:
    """``(v, e, f)`` of a closed mesh of genus ``g`` with only ``m``-valent vertices.

    The dual of :func:`ngon_mesh_counts`: ``2e = m v`` and Euler's formula
    give ``v = 2(f + 2g - 2)/(m - 2)`` and ``e = m v / 2``.

    Parameters
    ----------
    m : int
        Valence of every vertex, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    f : int
        Number of faces, ``>= 1``.

    Returns
    -------
    (int, int, int) or None
        ``(v, e, f)``; None when ``v`` or ``e`` would not be a positive
        integer.  E.g. ``(5, 0, 20)`` gives the icosahedron ``(12, 30, 20)``.

    Raises
    ------
    ValueError
        If ``m < 3``, ``g < 0``, ``f <= 0`` or any is not an integer.
    """
    _as_int("m", m, 3)
    _as_int("g", g, 0)
    _as_int("f", f, 1)
    dual = ngon_mesh_counts(m, g, f)  # the dual mesh: m-gons, f vertices
    return None if dual is None else (dual[2], dual[1], dual[0])


def face_range(m: int, g: int) -> Range | None:
    """Range of ``f`` for which an ``m``-valent mesh of genus ``g`` has ``n >= 3``.

    The dual of :func:`vertex_range` (swap ``v`` and ``f``, ``n`` and ``m``):
    faces must have 3 or more sides on average.

    Parameters
    ----------
    m : int, >= 3
        The valence of every vertex.
    g : int, >= 0
        The genus.

    Returns
    -------
    (int, int or float) or None
        ``(f_min, f_max)``, ``f_max = math.inf`` when unbounded; None when
        empty.

    Raises
    ------
    ValueError
        If ``m < 3``, ``g < 0`` or either is not an integer.
    """
    _as_int("m", m, 3)
    return vertex_range(m, g)


def min_faces(m: int, g: int) -> int | None:
    """Smallest ``f`` of an ``m``-valent mesh of genus ``g`` with ``n >= 3``.

    The dual of :func:`min_vertices`: for ``g = 0``, 4 faces for ``m = 3``
    (tetrahedron), 8 for ``m = 4`` (octahedron), 20 for ``m = 5``
    (icosahedron), none for ``m = 6``.

    Parameters
    ----------
    m : int, >= 3
        The valence of every vertex.
    g : int, >= 0
        The genus.

    Returns
    -------
    int or None
        The smallest number of faces; None when no such mesh exists.

    Raises
    ------
    ValueError
        If ``m < 3``, ``g < 0`` or either is not an integer.
    """
    r = face_range(m, g)
    return None if r is None else r[0]


#: The paper's chart (Section 4), computed by :func:`schlafli_chart`.
SCHLAFLI_CHART: tuple[SchlafliRow, ...] = schlafli_chart()
