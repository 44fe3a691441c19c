"""Tests of :mod:`pentanb.topology`: Section 4 of the paper, claim by claim.

Expected values come from the paper's text or are computed by hand in the
comments next to them (and the Platonic solids' counts are written out).
The brute-force oracle :func:`_meshes_by_face_count` enumerates meshes by
their number of faces, independently of the module's algebra.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pentanb.topology import (
    SCHLAFLI_CHART,
    SchlafliRow,
    average_face_size,
    average_valence,
    can_tile,
    face_range,
    limit_face_size,
    limit_valence,
    limit_valence_is_integer,
    min_faces,
    min_vertices,
    mvalent_mesh_counts,
    ngon_mesh_counts,
    ngon_preservation_exists,
    ngonalization_exists,
    schlafli_chart,
    vertex_range,
)

# (name, n = sides of every face, m = valence of every vertex, v, e, f), genus 0.
PLATONIC = [
    ("tetrahedron", 3, 3, 4, 6, 4),
    ("cube", 4, 3, 8, 12, 6),
    ("octahedron", 3, 4, 6, 12, 8),
    ("dodecahedron", 5, 3, 20, 30, 12),
    ("icosahedron", 3, 5, 12, 30, 20),
]


def _meshes_by_face_count(n: int, g: int, v_stop: int) -> dict[int, tuple[int, int, int]]:
    """Oracle: all count-wise n-gon meshes of genus g with v < v_stop, keyed by v.

    Enumerates f = 1, 2, ...: e = n f / 2 must be an integer and Euler's
    formula fixes v = 2 - 2g + e - f.
    """
    out = {}
    f = 1
    while True:
        if n * f % 2 == 0:
            e = n * f // 2
            v = 2 - 2 * g + e - f
            if v >= v_stop:
                return out
            if v >= 1:
                out[v] = (v, e, f)
        f += 1


def _admissible(n: int, g: int, v_stop: int) -> list[int]:
    """Oracle: the v < v_stop whose counts exist and have 2e >= 3v (m >= 3)."""
    return sorted(
        v for v, (_, e, _) in _meshes_by_face_count(n, g, v_stop).items() if 2 * e >= 3 * v
    )


# --------------------------------------------------------------------------
# Claims of Section 4, one test each
# --------------------------------------------------------------------------


def test_claim_equation_1_from_euler_with_platonic_solids():
    # m = 2e / v for each solid, by hand: 12/4, 24/8, 24/6, 60/20, 60/12.
    for name, n, m, v, e, f in PLATONIC:
        assert v - e + f == 2, name  # sanity of the hand-written table
        assert 2 * e == n * f == m * v, name
        assert average_valence(n, 0, v) == m, name


def test_claim_no_hexagonal_mesh_of_genus_0():
    # Paper: for g = 0 and n = 6, m = 3 (1 - 2/v), "always smaller than 3".
    assert average_valence(6, 0, 12) == 2.5  # 3 * 10/12
    assert average_valence(6, 0, 1000) == 2.994  # 3 * 998/1000
    for v in range(1, 2000):
        assert average_valence(6, 0, v) < 3
        assert not can_tile(6, 0, v)
    assert not can_tile(6, 0)
    assert vertex_range(6, 0) is None
    assert min_vertices(6, 0) is None
    # Counts alone can exist (v=4, e=3, f=1: 4 - 3 + 1 = 2, 2*3 = 6*1) but the
    # average valence is 6/4 < 3.
    assert ngon_mesh_counts(6, 0, 4) == (4, 3, 1)


def test_claim_hexagonal_meshes_exist_for_positive_genus():
    # Paper: "for g > 0, it is always possible to create hexagonal meshes".
    # g = 1: f = 2v/4 = v/2, so v even; the hexagonal torus has v=2, e=3, f=1.
    assert ngon_mesh_counts(6, 1, 2) == (2, 3, 1)
    assert vertex_range(6, 1) == (2, math.inf)
    assert average_valence(6, 1, 2) == 3
    # g = 2: f = 2(v + 2)/4, v even again; v = 2 gives e = 6, f = 2, m = 6.
    assert ngon_mesh_counts(6, 2, 2) == (2, 6, 2)
    for g in range(1, 10):
        assert can_tile(6, g)
        assert vertex_range(6, g)[1] == math.inf


def test_claim_pentagonal_genus0_needs_20_vertices_dodecahedron():
    # Paper: m = 10/3 (1 - 2/v); "v = 20 corresponds to a dodecahedron".
    assert average_valence(5, 0, 20) == 3  # 10/3 * 18/20
    assert min_vertices(5, 0) == 20
    assert vertex_range(5, 0) == (20, math.inf)
    assert ngon_mesh_counts(5, 0, 20) == (20, 30, 12)
    # v = 17: f = 2*15/3 = 10, e = 25 exist, but m = 50/17 < 3.
    assert ngon_mesh_counts(5, 0, 17) == (17, 25, 10)
    assert not can_tile(5, 0, 17)
    # v = 19: f = 34/3 is not an integer.
    assert ngon_mesh_counts(5, 0, 19) is None
    assert not can_tile(5, 0, 19)
    assert can_tile(5, 0, 20)
    # v = 23: f = 2*21/3 = 14, e = 35, m = 70/23 > 3.
    assert ngon_mesh_counts(5, 0, 23) == (23, 35, 14)
    assert can_tile(5, 0, 23)


def test_claim_pentagonal_genus0_equation():
    # The paper's special form of equation (1): m = 10/3 (1 - 2/v).
    for v in (3, 5, 20, 50, 1234):
        assert average_valence(5, 0, v) == pytest.approx(10 / 3 * (1 - 2 / v), rel=1e-14)


def test_claim_quad_genus0_needs_8_vertices_cube():
    # Paper: "v must be larger than 8 and the simplest case v = 8 corresponds
    # to an hexahedron". m = 4 (1 - 2/v) >= 3 iff v >= 8.
    assert min_vertices(4, 0) == 8
    assert vertex_range(4, 0) == (8, math.inf)
    assert ngon_mesh_counts(4, 0, 8) == (8, 12, 6)
    assert average_valence(4, 0, 8) == 3
    # v = 7: f = 5, e = 10, m = 20/7 < 3.
    assert ngon_mesh_counts(4, 0, 7) == (7, 10, 5)
    assert not can_tile(4, 0, 7)


def test_claim_triangle_genus0_needs_4_vertices_tetrahedron():
    # Paper: "v must be larger than 4 and the simplest case v = 4 corresponds
    # to a tetrahedron". m = 6 (1 - 2/v) >= 3 iff v >= 4.
    assert min_vertices(3, 0) == 4
    assert vertex_range(3, 0) == (4, math.inf)
    assert ngon_mesh_counts(3, 0, 4) == (4, 6, 4)
    # v = 3: two triangles glued along their boundary, 2-valent vertices.
    assert ngon_mesh_counts(3, 0, 3) == (3, 3, 2)
    assert not can_tile(3, 0, 3)


def test_claim_limit_is_planar_g1_value():
    # Paper: m -> 2n/(n-2) as v -> inf, "the same as the value of the m for g = 1".
    assert limit_valence(3) == 6
    assert limit_valence(4) == 4
    assert limit_valence(5) == Fraction(10, 3)
    assert limit_valence(6) == 3
    for n in range(3, 20):
        expected = 2 * n / (n - 2)
        assert average_valence(n, 0, np.inf) == pytest.approx(expected, rel=1e-15)
        assert average_valence(n, 3, np.inf) == pytest.approx(expected, rel=1e-15)
        for v in (1, 2, 7, 100, 10**6):
            assert average_valence(n, 1, v) == pytest.approx(expected, rel=1e-15)
        # From below for g = 0, from above for g = 2.
        assert average_valence(n, 0, 10**6) < expected < average_valence(n, 2, 10**6)
        assert average_valence(n, 0, 10**9) == pytest.approx(expected, rel=1e-8)


def test_claim_2n_over_n_minus_2_monotone_decreasing_below_3_after_6():
    # Hand: 6, 4, 10/3, 3, 14/5, 8/3, 18/7 for n = 3 .. 9.
    hand = [
        Fraction(6),
        Fraction(4),
        Fraction(10, 3),
        Fraction(3),
        Fraction(14, 5),
        Fraction(8, 3),
        Fraction(18, 7),
    ]
    assert [limit_valence(n) for n in range(3, 10)] == hand
    values = [limit_valence(n) for n in range(3, 200)]
    assert all(a > b for a, b in itertools.pairwise(values))
    for n in range(3, 200):
        assert (limit_valence(n) > 3) == (n < 6)
        assert (limit_valence(n) < 3) == (n > 6)


def test_claim_no_ngonalization_for_n_above_6():
    # Paper: "no n-gonalization scheme exists for n > 6" and "no n-gon
    # preservation scheme exists for n > 6 since a preservation scheme ...
    # must increase v".
    for n in range(7, 40):
        assert not ngonalization_exists(n)
        assert not ngon_preservation_exists(n)
        for g in range(0, 12):
            r = vertex_range(n, g)
            assert r is None or r[1] < math.inf


def test_claim_ngon_meshes_above_6_only_small_v_large_g():
    # Paper: "there can be some special n-gonal meshes for a small values of v
    # and large values of g". m >= 3 iff v <= (2g - 2) 2n / (n - 6).
    for n in range(7, 20):
        assert vertex_range(n, 0) is None
        assert vertex_range(n, 1) is None
    # n = 8, g = 2: v <= 2 * 16/2 = 16, f = (v + 2)/3, so v = 1 (mod 3).
    # v = 1: the genus-2 octagon with one vertex (e = 4, f = 1);
    # v = 16: 6 octagons, 24 edges, 3-valent.
    assert vertex_range(8, 2) == (1, 16)
    assert ngon_mesh_counts(8, 2, 1) == (1, 4, 1)
    assert ngon_mesh_counts(8, 2, 16) == (16, 24, 6)
    assert not can_tile(8, 2, 19)  # counts (19, 28, 7) but m = 56/19 < 3
    # n = 7, g = 2: v <= 2 * 14 = 28, f = 2 (v + 2)/5, v = 3 (mod 5).
    assert vertex_range(7, 2) == (3, 28)
    assert ngon_mesh_counts(7, 2, 28) == (28, 42, 12)
    # n = 12, g = 2: v <= 2 * 24/6 = 8, f = (v + 2)/5: v = 3 or 8.
    assert vertex_range(12, 2) == (3, 8)
    # n = 20, g = 2: v <= 80/14, f = (v + 2)/9 needs v = 7 > 5: none.
    assert vertex_range(20, 2) is None
    assert not can_tile(20, 2)
    # n = 20, g = 3: v <= 160/14, f = (v + 4)/9: only v = 5 (e = 10, m = 4).
    assert vertex_range(20, 3) == (5, 5)
    assert ngon_mesh_counts(20, 3, 5) == (5, 10, 1)


def test_claim_pentagonalization_exists_for_every_genus():
    # Abstract: "it is possible to represent any 2-manifold with a mesh that
    # is made up of only pentagons".
    assert ngonalization_exists(5)
    assert ngon_preservation_exists(5)
    # g = 1: f = 2v/3, v = 0 (mod 3), smallest v = 3 (e = 5, f = 2).
    assert vertex_range(5, 1) == (3, math.inf)
    assert ngon_mesh_counts(5, 1, 3) == (3, 5, 2)
    for g in range(0, 30):
        r = vertex_range(5, g)
        assert r is not None and r[1] == math.inf
        assert can_tile(5, g)


def test_claim_triangulation_and_quadrangulation_exist():
    for n in (3, 4):
        assert ngonalization_exists(n)
        assert ngon_preservation_exists(n)
        for g in range(0, 30):
            assert vertex_range(n, g)[1] == math.inf


def test_claim_no_hexagonalization_but_hexagon_preservation():
    # Paper: no hexagonalization "since such a scheme must also work for g = 0
    # case", but "it is possible to develop an hexagonal preservation scheme
    # since hexagonal meshes exist for g > 0".
    assert not ngonalization_exists(6)
    assert ngon_preservation_exists(6)


def test_claim_existence_table():
    # Abstract/Section 2: pentagons for all 2-manifolds, polygons with more
    # than five sides not.
    assert [n for n in range(3, 30) if ngonalization_exists(n)] == [3, 4, 5]
    assert [n for n in range(3, 30) if ngon_preservation_exists(n)] == [3, 4, 5, 6]


def test_claim_pentagonal_average_valence_not_integer_in_limit():
    # Section 2: pentagonal average valence "is necessarily rational, while
    # triangular and quadrilateral meshes can have integer vertex degree":
    # limits 10/3 versus 6 and 4. 2n/(n-2) is an integer iff (n-2) | 4.
    assert not limit_valence_is_integer(5)
    assert limit_valence_is_integer(3)
    assert limit_valence_is_integer(4)
    assert limit_valence_is_integer(6)
    assert [n for n in range(3, 100) if limit_valence_is_integer(n)] == [3, 4, 6]
    # On the torus (the planar tessellations) m = 10/3 for every pentagonal mesh.
    for v in range(3, 300, 3):
        assert ngon_mesh_counts(5, 1, v) is not None
        assert average_valence(5, 1, v) == pytest.approx(10 / 3, rel=1e-15)
    # Caveat: a finite genus-0 pentagonal mesh can be 3-valent (dodecahedron).
    assert average_valence(5, 0, 20) == 3


# --------------------------------------------------------------------------
# The chart
# --------------------------------------------------------------------------

# The paper's chart, copied: (n, m) to two decimals and the "type" column.
PAPER_CHART = [
    (6.00, 3.00, "Average 6-sided faces with average 3-valent vertices"),
    (5.00, 3.33, "Average 5-sided faces with average 3.3-valent vertices"),
    (4.00, 4.00, "Average 4-sided faces with average 4-valent vertices"),
    (3.33, 5.00, "Average 3.3-sided faces with average 5-valent vertices"),
    (3.00, 6.00, "Average 3-sided faces with average 6-valent vertices"),
]


def test_chart_rows_match_paper():
    assert len(SCHLAFLI_CHART) == len(PAPER_CHART)
    for row, (n, m, text) in zip(SCHLAFLI_CHART, PAPER_CHART):
        assert isinstance(row, SchlafliRow)
        assert round(float(row.n), 2) == n
        assert round(float(row.m), 2) == m
        assert row.description == text


def test_chart_values_exact():
    pairs = [(row.n, row.m) for row in SCHLAFLI_CHART]
    assert pairs == [(6, 3), (5, Fraction(10, 3)), (4, 4), (Fraction(10, 3), 5), (3, 6)]
    assert all(isinstance(x, Fraction) for pair in pairs for x in pair)
    # Every row is a planar (g = 1) tessellation: 1/n + 1/m = 1/2.
    for n, m in pairs:
        assert 1 / n + 1 / m == Fraction(1, 2)


def test_chart_dual_symmetry_10_3_and_5():
    # Paper: "we included (10/3, 5), the dual of (5, 10/3)": swap v and f.
    rows = {(row.n, row.m): row for row in SCHLAFLI_CHART}
    dual = rows[(Fraction(10, 3), Fraction(5))]
    assert dual.dual_of == (Fraction(5), Fraction(10, 3))
    assert sum(row.dual_of is not None for row in SCHLAFLI_CHART) == 1
    # The chart is closed under swapping n and m.
    assert {(m, n) for n, m in rows} == set(rows)
    assert limit_face_size(5) == Fraction(10, 3)


def test_chart_regular_versus_semiregular():
    # Paper: "(4, 4), (6, 3) and (3, 6) can have both regular and
    # semi-regular tesselations, but (5, 10/3) can only have semi-regular".
    regular = {(int(row.n), int(row.m)) for row in SCHLAFLI_CHART if row.admits_regular}
    assert regular == {(4, 4), (6, 3), (3, 6)}
    assert not next(row for row in SCHLAFLI_CHART if row.n == 5).admits_regular


def test_schlafli_chart_function_matches_constant():
    assert schlafli_chart() == SCHLAFLI_CHART


# --------------------------------------------------------------------------
# Dual statements (replace v with f)
# --------------------------------------------------------------------------


def test_dual_platonic_counts():
    # The m-valent solid with f faces: swap (v, f) of its dual.
    for name, n, m, v, e, f in PLATONIC:
        assert mvalent_mesh_counts(m, 0, f) == (v, e, f), name
        assert average_face_size(m, 0, f) == n, name


def test_dual_min_faces_octahedron_icosahedron():
    # n = 2m/(m-2) (1 - 2/f) >= 3: f >= 4 (m=3), 8 (m=4), 20 (m=5), never (m=6).
    assert min_faces(3, 0) == 4  # tetrahedron
    assert min_faces(4, 0) == 8  # octahedron
    assert min_faces(5, 0) == 20  # icosahedron
    assert min_faces(6, 0) is None
    assert face_range(5, 0) == (20, math.inf)
    assert mvalent_mesh_counts(5, 0, 20) == (12, 30, 20)
    assert mvalent_mesh_counts(4, 0, 8) == (6, 12, 8)


def test_dual_limit_face_size():
    assert limit_face_size(3) == 6
    assert limit_face_size(4) == 4
    assert limit_face_size(6) == 3
    assert average_face_size(5, 1, 7) == pytest.approx(10 / 3, rel=1e-15)
    assert average_face_size(5, 0, np.inf) == pytest.approx(10 / 3, rel=1e-15)


# --------------------------------------------------------------------------
# Exact values, tori, arrays
# --------------------------------------------------------------------------


def test_platonic_counts():
    for name, n, _m, v, e, f in PLATONIC:
        assert ngon_mesh_counts(n, 0, v) == (v, e, f), name


def test_torus_counts():
    # One-vertex quad torus: v=1, e=2, f=1. One-vertex triangle torus: v=1,
    # e=3, f=2. Seven-vertex (Csaszar) torus: v=7, e=21, f=14. 4x4 quad torus.
    assert ngon_mesh_counts(4, 1, 1) == (1, 2, 1)
    assert ngon_mesh_counts(3, 1, 1) == (1, 3, 2)
    assert ngon_mesh_counts(3, 1, 7) == (7, 21, 14)
    assert ngon_mesh_counts(4, 1, 16) == (16, 32, 16)
    assert ngon_mesh_counts(5, 1, 4) is None  # f = 8/3


def test_counts_none_when_not_positive():
    assert ngon_mesh_counts(5, 0, 2) is None  # f = 0
    assert ngon_mesh_counts(3, 0, 1) is None  # f = -2
    assert ngon_mesh_counts(4, 0, 2) is None  # f = 0
    assert ngon_mesh_counts(5, 0, 21) is None  # f = 38/3


def test_average_valence_hand_values():
    # 6 (1 - 2/6) = 4 and 6 (1 - 2/12) = 5: octahedron and icosahedron.
    assert average_valence(3, 0, 6) == 4
    assert average_valence(3, 0, 12) == 5
    # 2*8/6 (1 + 2/1) = 8: one-vertex genus-2 octagon.
    assert average_valence(8, 2, 1) == 8
    # Below the feasible range the formula still evaluates: 6 (1 - 2/1) = -6.
    assert average_valence(3, 0, 1) == -6


def test_average_valence_broadcasts():
    n = np.array([3, 4, 5, 6])[:, None]
    v = np.array([4, 8, 20, 12])
    m = average_valence(n, 0, v)
    assert m.shape == (4, 4)
    # Diagonal: tetrahedron, cube, dodecahedron 3; hexagons 3 * 10/12.
    np.testing.assert_allclose(np.diag(m), [3, 3, 3, 2.5])
    np.testing.assert_allclose(average_valence(5, [0, 1, 2], 10), [8 / 3, 10 / 3, 4])
    v = np.linspace(1, 100, 50)  # real v for plotting
    assert average_valence(6, 0, v).shape == (50,)


def test_scalar_returns_float_and_accepts_integer_valued_numbers():
    assert type(average_valence(5, 0, 20)) is float
    assert average_valence(5.0, np.int64(0), 20) == 3
    assert ngon_mesh_counts(np.int32(5), 0.0, 20.0) == (20, 30, 12)
    assert limit_valence(Fraction(5)) == Fraction(10, 3)


# --------------------------------------------------------------------------
# Properties and brute force
# --------------------------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(n=st.integers(3, 40), g=st.integers(0, 10), v=st.integers(1, 5000))
def test_property_counts_satisfy_euler_and_equation_1(n, g, v):
    counts = ngon_mesh_counts(n, g, v)
    oracle = _meshes_by_face_count(n, g, v + 1).get(v)
    assert counts == oracle
    if counts is None:
        return
    vv, e, f = counts
    assert vv == v and e > 0 and f > 0
    assert v - e + f == 2 - 2 * g
    assert 2 * e == n * f
    # m v = 2e; both sides are the correctly rounded value of 2e/v.
    assert average_valence(n, g, v) == float(Fraction(2 * e, v))
    assert can_tile(n, g, v) == (2 * e >= 3 * v)
    # The dual mesh: f vertices, each n-valent, v faces.
    assert mvalent_mesh_counts(n, g, v) == (f, e, v)


@settings(max_examples=200, deadline=None)
@given(
    n=st.integers(3, 40), g=st.integers(0, 10), v1=st.integers(1, 10**6), v2=st.integers(1, 10**6)
)
def test_property_monotone_in_v(n, g, v1, v2):
    if v1 > v2:
        v1, v2 = v2, v1
    m1, m2 = average_valence(n, g, v1), average_valence(n, g, v2)
    if g == 0:
        assert m1 <= m2 and (v1 == v2 or m1 < m2)
    elif g == 1:
        assert m1 == pytest.approx(m2, rel=1e-15)
    else:
        assert m1 >= m2 and (v1 == v2 or m1 > m2)


@settings(max_examples=200, deadline=None)
@given(n=st.integers(3, 16), g=st.integers(0, 5))
def test_property_vertex_range_matches_brute_force(n, g):
    v_stop = 600  # above every finite bound 4n(g-1)/(n-6) <= 4*7*4 = 112 here
    brute = _admissible(n, g, v_stop)
    r = vertex_range(n, g)
    if r is None:
        assert brute == []
        assert not can_tile(n, g)
        assert min_vertices(n, g) is None
        return
    v_min, v_max = r
    assert can_tile(n, g)
    assert min_vertices(n, g) == v_min == brute[0]
    p = (n - 2) // math.gcd(n - 2, 2)  # step between admissible v
    if v_max == math.inf:
        assert n < 6 or (n == 6 and g >= 1)
        assert brute == list(range(v_min, v_stop, p))
    else:
        assert n > 6 and g >= 2
        assert v_max == brute[-1]
        assert v_max <= (2 * g - 2) * 2 * n / (n - 6)
        assert brute == list(range(v_min, v_max + 1, p))


@settings(max_examples=100, deadline=None)
@given(n=st.integers(3, 30), g=st.integers(0, 6), f=st.integers(1, 3000))
def test_property_dual_formula_swaps_v_and_f(n, g, f):
    # average_face_size(m, g, f) is equation (1) with n -> m, v -> f.
    assert average_face_size(n, g, f) == average_valence(n, g, f)
    assert face_range(n, g) == vertex_range(n, g)
    assert min_faces(n, g) == min_vertices(n, g)


# --------------------------------------------------------------------------
# Errors
# --------------------------------------------------------------------------


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: average_valence(2, 0, 10), r"n must be an integer >= 3, got 2"),
        (lambda: average_valence(5.5, 0, 10), r"n must be an integer"),
        (lambda: average_valence(True, 0, 10), r"n must be an integer"),
        (lambda: average_valence("5", 0, 10), r"n must be an integer"),
        (lambda: average_valence([5, 2], 0, 10), r"n must be an integer >= 3"),
        (lambda: average_valence(5, -1, 10), r"g must be an integer >= 0"),
        (lambda: average_valence(5, 0.5, 10), r"g must be an integer"),
        (lambda: average_valence(5, 0, 0), r"v must be > 0"),
        (lambda: average_valence(5, 0, -3), r"v must be > 0"),
        (lambda: average_valence(5, 0, [20, 0]), r"v must be > 0"),
        (lambda: average_valence(5, 0, np.nan), r"v must be > 0"),
        (lambda: average_valence(5, 0, "20"), r"v must be a positive number"),
        (lambda: limit_valence(2), r"n must be an integer >= 3"),
        (lambda: limit_valence(4.5), r"n must be an integer"),
        (lambda: limit_valence(math.inf), r"n must be an integer"),
        (lambda: limit_valence_is_integer(1), r"n must be an integer >= 3"),
        (lambda: ngon_mesh_counts(2, 0, 4), r"n must be an integer >= 3"),
        (lambda: ngon_mesh_counts(5, -1, 20), r"g must be an integer >= 0"),
        (lambda: ngon_mesh_counts(5, 0, 0), r"v must be an integer >= 1, got 0"),
        (lambda: ngon_mesh_counts(5, 0, -20), r"v must be an integer >= 1"),
        (lambda: ngon_mesh_counts(5, 0, 20.5), r"v must be an integer"),
        (lambda: vertex_range(2, 0), r"n must be an integer >= 3"),
        (lambda: vertex_range(5, -2), r"g must be an integer >= 0"),
        (lambda: vertex_range(5, 1.5), r"g must be an integer"),
        (lambda: min_vertices(0, 0), r"n must be an integer >= 3"),
        (lambda: min_vertices(5, -1), r"g must be an integer >= 0"),
        (lambda: can_tile(2, 0), r"n must be an integer >= 3"),
        (lambda: can_tile(5, -1), r"g must be an integer >= 0"),
        (lambda: can_tile(5, 0, 0), r"v must be an integer >= 1"),
        (lambda: can_tile(5, 0, 2.5), r"v must be an integer"),
        (lambda: ngonalization_exists(2), r"n must be an integer >= 3"),
        (lambda: ngonalization_exists(5.5), r"n must be an integer"),
        (lambda: ngon_preservation_exists(2), r"n must be an integer >= 3"),
        (lambda: ngon_preservation_exists(None), r"n must be an integer"),
        (lambda: average_face_size(2, 0, 10), r"m must be an integer >= 3"),
        (lambda: average_face_size(5, -1, 10), r"g must be an integer >= 0"),
        (lambda: average_face_size(5, 0, 0), r"f must be > 0"),
        (lambda: limit_face_size(2), r"m must be an integer >= 3"),
        (lambda: mvalent_mesh_counts(2, 0, 4), r"m must be an integer >= 3"),
        (lambda: mvalent_mesh_counts(5, -1, 4), r"g must be an integer >= 0"),
        (lambda: mvalent_mesh_counts(5, 0, 0), r"f must be an integer >= 1"),
        (lambda: face_range(2, 0), r"m must be an integer >= 3"),
        (lambda: face_range(5, -1), r"g must be an integer >= 0"),
        (lambda: min_faces(1, 0), r"m must be an integer >= 3"),
    ],
)
def test_errors(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_module_needs_only_numpy():
    # Load the topology package on its own (not through pentanb/__init__) in a
    # fresh interpreter and check that it did not pull in matplotlib.
    import subprocess
    import sys
    from pathlib import Path

    import pentanb.topology

    path = Path(pentanb.topology.__file__)
    code = (
        "import importlib.util, sys; "
        f"spec = importlib.util.spec_from_file_location('topology', {str(path)!r}, "
        f"submodule_search_locations=[{str(path.parent)!r}]); "
        "module = importlib.util.module_from_spec(spec); "
        "sys.modules['topology'] = module; "
        "spec.loader.exec_module(module); "
        "assert not any(m.startswith('pentanb') for m in sys.modules), 'pentanb imported'; "
        "assert 'matplotlib' not in sys.modules, 'matplotlib imported'; "
        "assert module.min_vertices(5, 0) == 20"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
