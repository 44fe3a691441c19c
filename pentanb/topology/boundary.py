"""Surfaces with boundary (the paper's Section 4 is about closed ones): Euler's
characteristic with ``b`` boundary loops, equation (1) with boundary terms,
and which ``(n, m, g, b)`` admit meshes of ``n``-gons only.

See :mod:`pentanb.topology` for the whole section; every name here is
importable from there.  This module needs only numpy.
"""

from __future__ import annotations

import math

from .closed import Range, _as_count_array, _as_int

__all__ = [
    "euler_characteristic",
    "average_valence_with_boundary",
    "ngon_mesh_counts_with_boundary",
    "vertex_range_with_boundary",
    "can_tile_with_boundary",
    "min_boundary_edges",
    "ngonalization_exists_with_boundary",
]

# --------------------------------------------------------------------------
# Surfaces with boundary
# --------------------------------------------------------------------------
#
# With b boundary loops of e_b edges in all (e_b boundary vertices too: a loop
# has as many vertices as edges), Euler's formula is v - e + f = 2 - 2g - b,
# every interior edge has two faces and every boundary edge one, so
# n f = 2e - e_b; the valences (edges at a vertex) still add up to 2e.  Hence
#
#     f = (2 (v - chi) - e_b) / (n - 2),   e = f + v - chi,   chi = 2 - 2g - b,
#
# and the average valence m = 2e / v is equation (1) with two boundary terms.
# An interior vertex needs 3 edges and a boundary vertex 2 (the dual makes a
# face of the first's edges and closes the second's along the boundary), so
# on average 2e >= 3 (v - e_b) + 2 e_b, which is
#
#     (6 - n) v >= 2 n chi - (n - 4) e_b.


def euler_characteristic(g: int, b: int = 0) -> int:
    """``2 - 2g - b``: V - E + F of a connected surface of genus g with b boundary loops.

    Parameters
    ----------
    g : int
        Genus, ``>= 0``.
    b : int
        Number of boundary loops, ``>= 0`` (0: closed).

    Returns
    -------
    int

    Raises
    ------
    ValueError
        If ``g`` or ``b`` is negative or not an integer.

    Examples
    --------
    >>> euler_characteristic(0, 1)   # a disk
    1
    >>> euler_characteristic(0, 3)   # a pair of pants (shapes.open_disk())
    -1
    """
    return 2 - 2 * _as_int("g", g, 0) - _as_int("b", b, 0)


def _check_boundary(b: int, e_b: int) -> None:
    if (b == 0) != (e_b == 0):
        raise ValueError(f"b and e_b are both 0 (closed) or both positive, got b={b}, e_b={e_b}")
    if e_b < 3 * b:
        raise ValueError(f"each of the b={b} boundary loops has at least 3 edges, got e_b={e_b}")


def average_valence_with_boundary(n: int, g: int, b: int, v: float, e_b: int) -> float:
    """Average valence of a mesh of ``n``-gons with boundary: equation (1) extended.

    .. math::  m = \\frac{2n}{n - 2} \\left(1 + \\frac{2g - 2 + b}{v}\\right)
               - \\frac{2 e_b}{(n - 2)\\, v}

    from ``v - e + f = 2 - 2g - b``, ``n f = 2e - e_b`` (a boundary edge has
    one face) and ``m v = 2e``.  The valence of a boundary vertex is counted
    honestly: its number of edges, one more than its faces (the valences of
    :attr:`pentanb.Mesh.valences`).  ``b = e_b = 0`` gives equation (1).

    Parameters
    ----------
    n : int
        Sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    b : int
        Boundary loops, ``>= 0``.
    v : float
        Number of vertices, ``> 0``.
    e_b : int
        Number of boundary edges (= boundary vertices), ``>= 3b``; 0 iff ``b = 0``.

    Returns
    -------
    float
        ``m = 2e / v``.

    Raises
    ------
    ValueError
        For arguments out of range (the message names the argument).

    Examples
    --------
    >>> average_valence_with_boundary(4, 0, 1, 12, 10)   # a 3 x 2 grid of quads: 34/12
    2.8333333333333335
    >>> average_valence_with_boundary(6, 0, 1, 6, 6)     # one hexagon: six 2-valent vertices
    2.0
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    b = _as_int("b", b, 0)
    e_b = _as_int("e_b", e_b, 0)
    _check_boundary(b, e_b)
    vv = float(_as_count_array("v", v))
    chi = 2 - 2 * g - b
    # one division of two exact integers (when v is one): correctly rounded
    return (2.0 * (n * (vv - chi) - e_b)) / ((n - 2) * vv)


def ngon_mesh_counts_with_boundary(
    n: int, g: int, b: int, v: int, e_b: int
) -> tuple[int, int, int] | None:
    """``(v, e, f)`` of a mesh of ``n``-gons of genus ``g`` with ``b`` loops of ``e_b`` edges.

    .. math::  f = \\frac{2 (v - \\chi) - e_b}{n - 2}, \\qquad e = f + v - \\chi,
               \\qquad \\chi = 2 - 2g - b.

    Parameters
    ----------
    n : int
        Sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    b : int
        Boundary loops, ``>= 0``.
    v : int
        Vertices, ``>= 1``.
    e_b : int
        Boundary edges, ``>= 3b`` (0 iff ``b = 0``).

    Returns
    -------
    (int, int, int) or None
        None when ``f`` is not a positive integer or there are fewer
        vertices than boundary vertices (``v < e_b``).  Valence is not
        checked here: see :func:`can_tile_with_boundary`.

    Raises
    ------
    ValueError
        For arguments out of range.

    Examples
    --------
    >>> ngon_mesh_counts_with_boundary(5, 0, 1, 5, 5)    # one pentagon
    (5, 5, 1)
    >>> ngon_mesh_counts_with_boundary(4, 0, 1, 12, 10)  # a 3 x 2 grid of quads
    (12, 17, 6)
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    b = _as_int("b", b, 0)
    v = _as_int("v", v, 1)
    e_b = _as_int("e_b", e_b, 0)
    _check_boundary(b, e_b)
    chi = 2 - 2 * g - b
    k = 2 * (v - chi) - e_b
    if v < e_b or k <= 0 or k % (n - 2):
        return None
    f = k // (n - 2)
    return v, f + v - chi, f


def vertex_range_with_boundary(n: int, g: int, b: int, e_b: int) -> Range | None:
    """Range of ``v`` for meshes of ``n``-gons with boundary whose valences can be honest.

    Count-wise: :func:`ngon_mesh_counts_with_boundary` gives positive
    integer counts, and the edges suffice for 3 at every interior vertex
    and 2 at every boundary vertex on average,
    ``2e >= 3 (v - e_b) + 2 e_b``, that is

    .. math::  (6 - n)\\, v \\ge 2 n \\chi - (n - 4)\\, e_b .

    * ``n < 6``: a lower bound only.
    * ``n = 6``: no bound on ``v``, but ``e_b >= 6 chi`` (a disk needs 6
      boundary edges: one hexagon).
    * ``n > 6``: ``v <= ((n - 4) e_b - 2 n chi) / (n - 6)``: the interior
      is bounded by the boundary's length (one heptagon: ``v = e_b = 7``).

    Every ``v`` in the range with ``2v = 2 chi + e_b (mod n - 2)`` is
    admissible (and ``v >= e_b``, ``f > 0``), and no other.

    Parameters
    ----------
    n : int
        Sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    b : int
        Boundary loops, ``>= 1`` (0 is :func:`vertex_range`).
    e_b : int
        Boundary edges, ``>= 3b``.

    Returns
    -------
    (int, int or float) or None
        ``(v_min, v_max)``, ``v_max = math.inf`` when unbounded; None when
        no ``v`` is admissible.

    Raises
    ------
    ValueError
        For arguments out of range.

    Examples
    --------
    >>> vertex_range_with_boundary(7, 0, 1, 7)    # one heptagon, and nothing more
    (7, 7)
    >>> vertex_range_with_boundary(6, 0, 1, 5) is None   # a hexagonal disk needs 6
    True
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    b = _as_int("b", b, 1)
    e_b = _as_int("e_b", e_b, 3)
    _check_boundary(b, e_b)
    chi = 2 - 2 * g - b
    lo = max(1, e_b, chi + e_b // 2 + 1)  # v >= e_b and 2 (v - chi) > e_b
    hi: int | float = math.inf
    lhs, rhs = 6 - n, 2 * n * chi - (n - 4) * e_b
    if lhs > 0:
        lo = max(lo, -(-rhs // lhs))
    elif lhs == 0:
        if rhs > 0:
            return None
    else:
        hi = rhs // lhs  # v <= rhs / lhs (lhs < 0): floor, exact on ints
    # 2v = 2 chi + e_b (mod n - 2)
    p, t = n - 2, 2 * chi + e_b
    if p % 2 == 0:
        if t % 2:
            return None
        p, r = p // 2, (t // 2) % (p // 2)
    else:
        r = (t * pow(2, -1, p)) % p if p > 1 else 0
    v_min = lo + (r - lo) % p
    if hi != math.inf:
        v_max: int | float = int(hi) - (int(hi) - r) % p
        if v_min > v_max:
            return None
    else:
        v_max = math.inf
    return v_min, v_max


def can_tile_with_boundary(
    n: int, g: int, b: int, v: int | None = None, e_b: int | None = None
) -> bool:
    """Whether a mesh of only ``n``-gons of genus ``g`` with ``b`` boundary loops can exist.

    Count-wise (see :func:`vertex_range_with_boundary`): positive integer
    counts, 3 edges at every interior vertex and 2 at every boundary vertex
    on average.

    Parameters
    ----------
    n : int
        Sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    b : int
        Boundary loops, ``>= 1``.
    v : int, optional
        Vertices; when omitted, whether some ``v`` works.
    e_b : int, optional
        Boundary edges; when omitted, whether some ``e_b`` works.

    Returns
    -------
    bool
        With ``v`` and ``e_b`` omitted: True for every ``n``, ``g`` and
        ``b >= 1`` (a surface with boundary has room for any polygon,
        where a sphere has none for hexagons).

    Raises
    ------
    ValueError
        For arguments out of range.
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    b = _as_int("b", b, 1)
    if e_b is None:
        found = min_boundary_edges(n, g, b) is not None
        if v is None or not found:
            return found
        v = _as_int("v", v, 1)
        return any(
            _in_range(vertex_range_with_boundary(n, g, b, k), n, g, b, v, k)
            for k in range(3 * b, v + 1)
        )
    e_b = _as_int("e_b", e_b, 3)
    r = vertex_range_with_boundary(n, g, b, e_b)
    if v is None:
        return r is not None
    return _in_range(r, n, g, b, _as_int("v", v, 1), e_b)


def _in_range(r: Range | None, n: int, g: int, b: int, v: int, e_b: int) -> bool:
    return (
        r is not None
        and r[0] <= v <= r[1]
        and ngon_mesh_counts_with_boundary(n, g, b, v, e_b) is not None
    )


def min_boundary_edges(n: int, g: int, b: int) -> int | None:
    """Fewest boundary edges of a mesh of ``n``-gons of genus ``g`` with ``b`` loops.

    Count-wise (see :func:`vertex_range_with_boundary`).  For a disk: one
    face, ``n`` edges, for every ``n``.

    Parameters
    ----------
    n : int
        Sides of every face, ``>= 3``.
    g : int
        Genus, ``>= 0``.
    b : int
        Boundary loops, ``>= 1``.

    Returns
    -------
    int or None
        The smallest ``e_b >= 3b`` for which some ``v`` is admissible.

    Raises
    ------
    ValueError
        For arguments out of range.

    Examples
    --------
    >>> min_boundary_edges(6, 0, 1)   # one hexagon
    6
    >>> min_boundary_edges(5, 1, 1)   # a torus with a hole, of pentagons
    3
    """
    n = _as_int("n", n, 3)
    g = _as_int("g", g, 0)
    b = _as_int("b", b, 1)
    # beyond 2n |chi| + n + 6 (n - 2) edges the conditions only get looser (each
    # residue of e_b mod 2 (n - 2) is met by then)
    chi = 2 - 2 * g - b
    for e_b in range(3 * b, 3 * b + 2 * n * abs(chi) + 8 * n + 16):
        if vertex_range_with_boundary(n, g, b, e_b) is not None:
            return e_b
    return None  # pragma: no cover - never reached: every (n, g, b) has one


def ngonalization_exists_with_boundary(n: int) -> bool:
    """Whether refinement into ``n``-gons can go on forever on surfaces with boundary.

    A conversion (or preservation) scheme used for subdivision multiplies
    the interior vertices faster than the boundary's (faces grow with the
    square of the refinement, boundary edges with it), so it needs
    ``n``-gon meshes with ``v / e_b`` as large as one likes, for every
    genus and every number ``b >= 1`` of loops.  In
    ``(6 - n) v >= 2 n chi - (n - 4) e_b`` that holds for ``n <= 6`` (for
    hexagons as soon as ``e_b >= 6 chi``) and fails for ``n > 6``, where
    ``v`` stays below a multiple of ``e_b``.  So with boundary the limit is
    ``n <= 6``, one more than on closed surfaces (:func:`ngonalization_exists`,
    whose hexagons fail on the sphere): a boundary absorbs what the sphere's
    curvature cannot.

    This is counting, not a scheme.  For ``n = 6`` it allows hexagon
    *preservation* on open surfaces, but no *local* hexagon conversion
    scheme can exist, open meshes or not: a local scheme makes each output
    face from a bounded neighbourhood of the input, so one that turned
    every open mesh into hexagons would, on a large sphere mesh, make every
    face as it does on the disk left by removing a face far from it, and
    give the sphere an all-hexagon mesh, which :func:`ngonalization_exists`
    rules out.

    Parameters
    ----------
    n : int
        Sides, ``>= 3``.

    Returns
    -------
    bool
        True for ``n <= 6``, False for ``n > 6``.

    Raises
    ------
    ValueError
        If ``n`` is not an integer ``>= 3``.
    """
    n = _as_int("n", n, 3)
    # v unbounded for a fixed, large enough e_b, at the largest chi (a disk)
    e_b = min_boundary_edges(n, 0, 1)
    assert e_b is not None
    for k in range(e_b, e_b + 2 * (n - 2) + 1):
        r = vertex_range_with_boundary(n, 0, 1, k)
        if r is not None and r[1] == math.inf:
            return True
    return False
