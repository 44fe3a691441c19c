"""Conway notation (issue 10): the operators, the parser, the registry.

Expected values come from the literature, never from the code under test:

* the count formulas and the per-edge invariants (new vertices by valence,
  new faces by size) of every operator: B. Stewart's notes on Conway
  operators (antitile ``docs/conway.rst``, after Brinkmann, Goetschalckx and
  Schein, Proc. R. Soc. A 473, 2017), Hart's Conway-notation page and
  Antiprism's ``conway -H``;
* the named polyhedra: the Archimedean and Catalan solids, the Goldberg
  polyhedra GP(m, n) (V = 20T, E = 30T, F = 10T + 2 with T = m^2 + mn + n^2;
  octahedral GP_IV: 8T, 12T, 4T + 2) and Hart's and Antiprism's
  equivalences (jT = C, sT = I, dA3 = C, k5A5 = I, t5dA5 = D, aY4 = A4).
"""

from __future__ import annotations

import ast
import re
from collections import Counter
from pathlib import Path

import numpy as np
import pytest
from helpers import check_valid, corpus, face_lists, is_isomorphic

import pentanb
from pentanb import Mesh, shapes
from pentanb.notation import (
    OPERATORS,
    REDUCTIONS,
    SEEDS,
    NotationError,
    antiprism,
    conway,
    parse,
    prism,
    pyramid,
    reduce_notation,
    resolve,
)
from pentanb.notation import operators as ops
from pentanb.notation.build import _counts

SEED_NAMES = ["T", "C", "O", "I", "D", "P3", "P5", "P6", "A4", "A5", "Y4", "Y5", "Y6"]
LETTERS = list(OPERATORS)

# ---------------------------------------------------------------------- literature data
#: Count formulas (V', E', F') from (V, E, F): antitile's matrices M_x, Hart
#: and Antiprism (written out here, not read from the registry).
FORMULAS = {
    "d": lambda V, E, F: (F, E, V),
    "a": lambda V, E, F: (E, 2 * E, V + F),
    "t": lambda V, E, F: (2 * E, 3 * E, V + F),
    "k": lambda V, E, F: (V + F, 3 * E, 2 * E),
    "j": lambda V, E, F: (V + F, 2 * E, E),
    "e": lambda V, E, F: (2 * E, 4 * E, V + E + F),
    "o": lambda V, E, F: (V + E + F, 4 * E, 2 * E),
    "s": lambda V, E, F: (2 * E, 5 * E, V + 2 * E + F),
    "g": lambda V, E, F: (V + 2 * E + F, 5 * E, 2 * E),
    "p": lambda V, E, F: (V + 2 * E, 5 * E, F + 2 * E),
    "m": lambda V, E, F: (V + E + F, 6 * E, 4 * E),
    "b": lambda V, E, F: (4 * E, 6 * E, V + E + F),
    "c": lambda V, E, F: (V + 2 * E, 4 * E, F + E),
    "w": lambda V, E, F: (V + 4 * E, 7 * E, F + 2 * E),
    "q": lambda V, E, F: (V + 3 * E, 6 * E, F + 2 * E),
    "z": lambda V, E, F: (2 * E, 3 * E, V + F),
    "u": lambda V, E, F: (V + E, 4 * E, F + 2 * E),
    "n": lambda V, E, F: (V + F, 3 * E, 2 * E),
    "r": lambda V, E, F: (V, E, F),
}

#: Per-operator invariants (a, c, k, l, new vertices per edge by valence,
#: new faces per edge by size), antitile's tables (d, a, z, t, b, s, e from
#: the dual relations given there).
INVARIANTS = {
    "d": (0, 1, 1, 1, {}, {}),
    "a": (0, 0, 1, 1, {4: 1}, {}),
    "t": (0, 0, 1, 2, {3: 2}, {}),
    "k": (1, 1, 2, 1, {}, {3: 2}),
    "j": (1, 1, 1, 1, {}, {4: 1}),
    "e": (0, 0, 1, 1, {4: 2}, {4: 1}),
    "o": (1, 1, 1, 1, {4: 1}, {4: 2}),
    "s": (0, 0, 1, 1, {5: 2}, {3: 2}),
    "g": (1, 1, 1, 1, {3: 2}, {5: 2}),
    "p": (1, 0, 1, 1, {4: 2}, {4: 2}),
    "m": (1, 1, 2, 2, {4: 1}, {3: 4}),
    "b": (0, 0, 2, 2, {3: 4}, {4: 1}),
    "c": (1, 0, 1, 1, {3: 2}, {6: 1}),
    "w": (1, 0, 1, 1, {3: 4}, {6: 2}),
    "q": (1, 0, 1, 1, {3: 2, 4: 1}, {5: 2}),
    "z": (0, 0, 2, 1, {3: 2}, {}),
    "u": (1, 0, 1, 1, {6: 1}, {3: 2}),
    "n": (1, 1, 1, 2, {}, {3: 2}),
    "r": (1, 0, 1, 1, {}, {}),
}


def predicted_histograms(letter: str, m: Mesh) -> tuple[dict, dict]:
    """Valence and face-size histograms after ``letter``, from the invariants:
    V_i = a v_{i/k} + E b_i + c f_{i/l};  F_i = (1-a) v_{i/k} + E b'_i + (1-c) f_{i/l}."""
    a, c, k, l, b, b_faces = INVARIANTS[letter]
    E = m.n_edges
    v_hist = Counter(int(x) for x in m.valences)
    f_hist = Counter(int(x) for x in m.face_sizes)
    V, F = Counter(), Counter()
    for i, cnt in v_hist.items():
        (V if a else F)[i * k] += cnt
    for i, cnt in f_hist.items():
        (V if c else F)[i * l] += cnt
    for i, cnt in b.items():
        V[i] += E * cnt
    for i, cnt in b_faces.items():
        F[i] += E * cnt
    return dict(sorted(V.items())), dict(sorted(F.items()))


def seed_mesh(name: str) -> Mesh:
    return conway(name)


# ---------------------------------------------------------------------- counts
@pytest.mark.parametrize("seed", SEED_NAMES)
@pytest.mark.parametrize("letter", LETTERS)
def test_counts_match_the_literature_formula(letter, seed):
    m = seed_mesh(seed)
    out = conway(letter, seed=m)
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    got = (out.n_vertices, out.n_edges, out.n_faces)
    assert got == FORMULAS[letter](V, E, F)
    assert got == tuple(OPERATORS[letter].counts(V, E, F)), "registry formula"
    assert got == _counts(letter + seed)[0][-1]


@pytest.mark.parametrize("seed", SEED_NAMES)
@pytest.mark.parametrize("letter", LETTERS)
def test_histograms_match_the_invariants(letter, seed):
    m = seed_mesh(seed)
    out = conway(letter, seed=m)
    v_hist, f_hist = predicted_histograms(letter, m)
    assert out.valence_histogram() == v_hist
    assert out.face_size_histogram() == f_hist
    inv = OPERATORS[letter].invariants
    assert (inv.a, inv.c, inv.k, inv.l, dict(inv.b), dict(inv.b_faces)) == INVARIANTS[letter]
    assert out.n_edges == inv.g * m.n_edges


def test_formula_check_fails_on_a_wrong_formula():
    """The count check can fail: kis does not have truncate's counts."""
    m = shapes.cube()
    out = conway("k", seed=m)
    assert (out.n_vertices, out.n_edges, out.n_faces) != FORMULAS["t"](8, 12, 6)
    assert predicted_histograms("t", m)[1] != out.face_size_histogram()


def test_formula_text():
    assert OPERATORS["g"].formula == "(V+2E+F, 5E, 2E)"
    assert OPERATORS["d"].formula == "(F, E, V)"
    assert OPERATORS["w"].formula == "(V+4E, 7E, 2E+F)"


@pytest.mark.parametrize("letter", LETTERS)
@pytest.mark.parametrize("name", ["tetrahedron", "cube_split", "small_torus", "double_torus"])
def test_outputs_are_valid_oriented_meshes(letter, name):
    """Any genus: re-validated through Mesh(vertices, faces), Euler
    characteristic kept, orientation (volume sign) kept."""
    m = corpus(name)
    out = conway(letter, seed=m)
    check_valid(out)
    rebuilt = Mesh(out.vertices, face_lists(out))
    assert rebuilt.euler_characteristic == m.euler_characteristic
    assert np.sign(rebuilt.volume) == np.sign(m.volume) != 0


@pytest.mark.parametrize("seed", SEED_NAMES)
def test_seed_letters_give_closed_outward_meshes(seed):
    m = seed_mesh(seed)
    check_valid(m)
    assert m.volume > 0 and m.genus == 0


# ---------------------------------------------------------------------- numeric forms
@pytest.mark.parametrize(
    "text, seed, n",
    [("k4", "P6", 4), ("k6", "P6", 6), ("k3", "P6", 3), ("k5", "Y5", 5), ("k7", "C", 7)],
)
def test_kis_n_raises_pyramids_on_n_gons_only(text, seed, n):
    m = seed_mesh(seed)
    out = conway(text, seed=m)
    fn = int(np.count_nonzero(m.face_sizes == n))
    assert (out.n_vertices, out.n_edges, out.n_faces) == (
        m.n_vertices + fn,
        m.n_edges + n * fn,
        m.n_faces + (n - 1) * fn,
    )
    hist = Counter(int(s) for s in m.face_sizes if s != n)
    hist[3] += n * fn
    assert out.face_size_histogram() == {k: v for k, v in sorted(hist.items()) if v}
    assert OPERATORS["k"].counts_on(m, n) == (out.n_vertices, out.n_edges, out.n_faces)
    check_valid(out)


@pytest.mark.parametrize(
    "text, seed, n", [("t3", "Y4", 3), ("t4", "Y4", 4), ("t5", "A5", 5), ("t3", "P5", 3)]
)
def test_truncate_n_cuts_n_valent_vertices_only(text, seed, n):
    m = seed_mesh(seed)
    out = conway(text, seed=m)
    vn = int(np.count_nonzero(m.valences == n))
    assert (out.n_vertices, out.n_edges, out.n_faces) == (
        m.n_vertices + (n - 1) * vn,
        m.n_edges + n * vn,
        m.n_faces + vn,
    )
    assert out.face_size_histogram().get(n, 0) >= vn
    check_valid(out)


def test_numeric_forms_without_a_match_change_nothing():
    c = shapes.cube()
    assert conway("k5", seed=c) is c
    assert conway("t4", seed=c) is c


# ---------------------------------------------------------------------- named polyhedra
#: name -> (V, E, F, face-size histogram, valence histogram or None).
#: Archimedean and Catalan solids (their Wikipedia articles); Goldberg
#: polyhedra (GP(m, n): icosahedral V = 20T, E = 30T, F = 10T + 2 with 12
#: pentagons; octahedral GP_IV: 8T, 12T, 4T + 2 with 6 squares); the
#: geodesic icosahedron {3,5+}_{2,0} (dual of GP(2,0)); the propello
#: tetrahedron ("tetrahedrally diminished dodecahedron": 16, 30, 16 with 4
#: triangles and 12 quads); Hart's propello-icosahedron (each triangle
#: surrounded by a propeller of quads).
NAMED = {
    # truncations
    "tT": (12, 18, 8, {3: 4, 6: 4}, {3: 12}),  # truncated tetrahedron
    "tC": (24, 36, 14, {3: 8, 8: 6}, {3: 24}),  # truncated cube
    "tO": (24, 36, 14, {4: 6, 6: 8}, {3: 24}),  # truncated octahedron
    "tI": (60, 90, 32, {5: 12, 6: 20}, {3: 60}),  # truncated icosahedron = GP(1,1)
    "tD": (60, 90, 32, {3: 20, 10: 12}, {3: 60}),  # truncated dodecahedron
    "zD": (60, 90, 32, {5: 12, 6: 20}, {3: 60}),  # zip = dk: truncated icosahedron
    "zC": (24, 36, 14, {4: 6, 6: 8}, {3: 24}),  # truncated octahedron
    # rectification and expansion
    "aC": (12, 24, 14, {3: 8, 4: 6}, {4: 12}),  # cuboctahedron
    "aD": (30, 60, 32, {3: 20, 5: 12}, {4: 30}),  # icosidodecahedron
    "aT": (6, 12, 8, {3: 8}, {4: 6}),  # octahedron
    "eC": (24, 48, 26, {3: 8, 4: 18}, {4: 24}),  # rhombicuboctahedron
    "eD": (60, 120, 62, {3: 20, 4: 30, 5: 12}, {4: 60}),  # rhombicosidodecahedron
    "bC": (48, 72, 26, {4: 12, 6: 8, 8: 6}, {3: 48}),  # truncated cuboctahedron
    "bD": (120, 180, 62, {4: 30, 6: 20, 10: 12}, {3: 120}),  # truncated icosidodecahedron
    # snubs and gyros
    "sC": (24, 60, 38, {3: 32, 4: 6}, {5: 24}),  # snub cube
    "sD": (60, 150, 92, {3: 80, 5: 12}, {5: 60}),  # snub dodecahedron
    "sT": (12, 30, 20, {3: 20}, {5: 12}),  # icosahedron (Hart: sT = I)
    "gC": (38, 60, 24, {5: 24}, {3: 32, 4: 6}),  # pentagonal icositetrahedron
    "gD": (92, 150, 60, {5: 60}, {3: 80, 5: 12}),  # pentagonal hexecontahedron
    "gT": (20, 30, 12, {5: 12}, {3: 20}),  # dodecahedron (Hart: gT = D)
    # Catalan solids
    "kT": (8, 18, 12, {3: 12}, {3: 4, 6: 4}),  # triakis tetrahedron
    "kC": (14, 36, 24, {3: 24}, {4: 6, 6: 8}),  # tetrakis hexahedron
    "kO": (14, 36, 24, {3: 24}, {3: 8, 8: 6}),  # triakis octahedron
    "kD": (32, 90, 60, {3: 60}, {5: 12, 6: 20}),  # pentakis dodecahedron
    "kI": (32, 90, 60, {3: 60}, {3: 20, 10: 12}),  # triakis icosahedron
    "nI": (32, 90, 60, {3: 60}, {5: 12, 6: 20}),  # needle = kd: pentakis dodecahedron
    "jC": (14, 24, 12, {4: 12}, {3: 8, 4: 6}),  # rhombic dodecahedron
    "jD": (32, 60, 30, {4: 30}, {3: 20, 5: 12}),  # rhombic triacontahedron
    "jT": (8, 12, 6, {4: 6}, {3: 8}),  # cube (Hart: jT = C)
    "oC": (26, 48, 24, {4: 24}, {3: 8, 4: 18}),  # deltoidal icositetrahedron
    "oD": (62, 120, 60, {4: 60}, {3: 20, 4: 30, 5: 12}),  # deltoidal hexecontahedron
    "mC": (26, 72, 48, {3: 48}, {4: 12, 6: 8, 8: 6}),  # disdyakis dodecahedron
    "mD": (62, 180, 120, {3: 120}, {4: 30, 6: 20, 10: 12}),  # disdyakis triacontahedron
    # Goldberg polyhedra and geodesic spheres
    "cD": (80, 120, 42, {5: 12, 6: 30}, {3: 80}),  # GP(2,0), T = 4
    "cC": (32, 48, 18, {4: 6, 6: 12}, {3: 32}),  # GP_IV(2,0), T = 4
    "wD": (140, 210, 72, {5: 12, 6: 60}, {3: 140}),  # GP(2,1), T = 7
    "wC": (56, 84, 30, {4: 6, 6: 24}, {3: 56}),  # GP_IV(2,1), T = 7
    "uI": (42, 120, 80, {3: 80}, {5: 12, 6: 30}),  # geodesic {3,5+}_{2,0}
    # propellers
    "pT": (16, 30, 16, {3: 4, 4: 12}, None),  # propello tetrahedron
    "pI": (72, 150, 80, {3: 20, 4: 60}, None),  # propello-icosahedron (Hart)
    # Hart's and Antiprism's equivalences, and the seeds
    "dA3": (8, 12, 6, {4: 6}, {3: 8}),  # cube
    "k5A5": (12, 30, 20, {3: 20}, {5: 12}),  # icosahedron
    "t5dA5": (20, 30, 12, {5: 12}, {3: 20}),  # dodecahedron
    "aY4": (8, 16, 10, {3: 8, 4: 2}, {4: 8}),  # square antiprism (Hart: aY = A)
    "P5": (10, 15, 7, {4: 5, 5: 2}, {3: 10}),  # pentagonal prism
    "A4": (8, 16, 10, {3: 8, 4: 2}, {4: 8}),  # square antiprism
    "Y5": (6, 10, 6, {3: 5, 5: 1}, {3: 5, 5: 1}),  # pentagonal pyramid
    # quinto dodecahedron (Antiprism: t5daaD = qD); valences from quinto's invariants
    "qD": (110, 180, 72, {5: 72}, {3: 80, 4: 30}),
}


@pytest.mark.parametrize("name", list(NAMED))
def test_named_polyhedra(name):
    V, E, F, faces, valences = NAMED[name]
    m = conway(name)
    assert (m.n_vertices, m.n_edges, m.n_faces) == (V, E, F)
    assert m.face_size_histogram() == faces
    if valences is not None:
        assert m.valence_histogram() == valences


def test_the_issue_examples():
    """Issue 10: tI = 60/90/32, sC = 24/60/38, gC = 38/60/24."""
    for text, counts in [("tI", (60, 90, 32)), ("sC", (24, 60, 38)), ("gC", (38, 60, 24))]:
        m = conway(text)
        assert (m.n_vertices, m.n_edges, m.n_faces) == counts


@pytest.mark.parametrize(
    "text, seed",
    [
        ("jT", "C"),
        ("sT", "I"),
        ("dA3", "C"),
        ("k5A5", "I"),
        ("t5dA5", "D"),
        ("gT", "D"),
        ("aT", "O"),
        ("aY4", "A4"),
        ("P4", "C"),
        ("A3", "O"),
        ("Y3", "T"),
        ("zD", "tI"),
    ],
)
def test_harts_equivalences_are_isomorphisms(text, seed):
    """Hart's and Antiprism's equivalent forms are the same oriented maps
    (checked combinatorially, a reflection allowed for the chiral ones)."""
    a, b = conway(text), conway(seed)
    assert is_isomorphic(a, b) or is_isomorphic(a, b, reflect=True)


# ---------------------------------------------------------------------- the literature's identities
@pytest.mark.parametrize(
    "letter, expression",
    [
        ("e", "aa"),
        ("o", "jj"),
        ("z", "dk"),
        ("n", "kd"),
        ("t", "dkd"),
        ("j", "da"),
        ("b", "ta"),
        ("m", "kj"),
        ("s", "dg"),
        ("u", "dcd"),
        ("c", "dud"),
        ("g", "ds"),
        ("k", "dtd"),
        ("a", "dj"),
        ("p", "dpd"),
    ],
)
@pytest.mark.parametrize("seed", ["T", "C", "D", "P5", "Y4"])
def test_operator_identities_hold_combinatorially(letter, expression, seed):
    """e = aa, o = jj, z = dk, ... (Hart, Antiprism): same oriented map."""
    a = conway(letter + seed)
    b = conway(expression + seed)
    assert is_isomorphic(a, b)


def test_identity_check_fails_on_a_wrong_identity():
    assert not is_isomorphic(conway("eC"), conway("jjC"))
    assert not is_isomorphic(conway("sC"), conway("rsC"))  # the two snub cubes
    assert is_isomorphic(conway("sC"), conway("rsC"), reflect=True)


# ---------------------------------------------------------------------- existing functions
@pytest.mark.parametrize(
    "letter, func",
    [
        ("g", pentanb.pentagonalize),
        ("e", pentanb.corner_cutting),
        ("o", pentanb.vertex_insertion),
        ("c", pentanb.preserve_hexagons),
        ("z", pentanb.honeycomb),
        ("u", pentanb.loop_remesh),
        ("n", pentanb.sqrt3_remesh),
        ("d", pentanb.dual),
    ],
)
def test_letters_call_the_existing_schemes(letter, func):
    assert OPERATORS[letter].func is func


@pytest.mark.parametrize("name", ["cube", "dodecahedron", "torus", "cube_split"])
def test_g_is_exactly_pentagonalize(name):
    m = corpus(name)
    a, b = conway("g", seed=m), pentanb.pentagonalize(m)
    for attr in ("vertices", "corners", "offsets"):
        assert np.array_equal(getattr(a, attr), getattr(b, attr))


@pytest.mark.parametrize("name", ["cube", "dodecahedron", "torus"])
def test_q_is_exactly_preserve_pentagons(name):
    m = corpus(name)
    for options, scale in [({}, 0.5), ({"scale": 0.75}, 0.75), ({"scale": 0.3}, 0.3)]:
        a = conway("q", seed=m, **options)
        b = pentanb.preserve_pentagons(m, scale=scale)
        for attr in ("vertices", "corners", "offsets"):
            assert np.array_equal(getattr(a, attr), getattr(b, attr))
    assert not np.array_equal(conway("q", seed=m).vertices, pentanb.preserve_pentagons(m).vertices)


def test_string_letters_match_function_composition():
    """``"gC"`` is pentagonalize(cube()); ``"ddgT"`` the paper's Figure 7(D)."""
    a = conway("ddgT")
    b = pentanb.dual(pentanb.dual(pentanb.pentagonalize(shapes.tetrahedron())))
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.corners, b.corners)
    assert not np.allclose(
        np.sort(conway("ddgT").vertices, axis=0), np.sort(conway("gT").vertices, axis=0)
    ), "with the package's positions dd is the paper's smoothing, not the identity"


# ---------------------------------------------------------------------- default positions
def test_zip_positions_are_dual_of_kis():
    """honeycomb's point (u + w + c_f)/3 is the dual vertex of kis's triangle:
    zip = dk holds for the positions too."""
    for m in (shapes.cube(), shapes.dodecahedron(), corpus("cube_split")):
        a = np.sort(pentanb.honeycomb(m).vertices.round(12), axis=0)
        b = np.sort(pentanb.dual(ops.kis(m)).vertices.round(12), axis=0)
        assert np.allclose(a, b)


def test_expand_positions_differ_from_ambo_twice():
    """corner_cutting's corner points are not those of aa (documented)."""
    m = shapes.tetrahedron()
    a = np.sort(conway("e", seed=m).vertices.round(12), axis=0)
    b = np.sort(conway("aa", seed=m).vertices.round(12), axis=0)
    assert a.shape == b.shape and not np.allclose(a, b)


def test_truncate_cuts_at_a_third():
    """tI with cuts at 1/3: every edge of the regular truncated icosahedron is equal."""
    m = conway("tI")
    lengths = np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)
    assert np.ptp(lengths) < 1e-12
    tc = conway("tC")  # a third is not the regular truncated cube
    lengths = np.linalg.norm(tc.vertices[tc.edges[:, 0]] - tc.vertices[tc.edges[:, 1]], axis=1)
    assert np.ptp(lengths) > 0.1


def test_reflect_is_a_mirror_image():
    m = conway("sC")
    r = conway("rsC")
    assert np.allclose(r.vertices, m.vertices * [-1, 1, 1])
    assert r.volume == pytest.approx(m.volume)
    assert np.array_equal(conway("rrsC").corners, m.corners)


@pytest.mark.parametrize("op", [ops.truncate, ops.kis])
def test_numeric_argument_is_checked(op):
    with pytest.raises(ValueError, match="must be an integer >= 3, got 2"):
        op(shapes.cube(), 2)
    with pytest.raises(TypeError):
        op(shapes.cube(), 3.5)


def test_truncate_ratio_is_checked():
    with pytest.raises(ValueError, match="ratio"):
        ops.truncate(shapes.cube(), ratio=0.5)
    with pytest.raises(TypeError, match=r"pentanb\.Mesh"):
        ops.ambo("C")


# ---------------------------------------------------------------------- seeds
@pytest.mark.parametrize("n", [3, 4, 5, 8, 12])
def test_prisms_and_antiprisms_are_uniform(n):
    for build, counts in [(prism, (2 * n, 3 * n, n + 2)), (antiprism, (2 * n, 4 * n, 2 * n + 2))]:
        m = build(n)
        assert (m.n_vertices, m.n_edges, m.n_faces) == counts
        lengths = np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)
        assert np.ptp(lengths) < 1e-12, "every edge the same length"
        assert m.volume > 0


@pytest.mark.parametrize("n", [3, 4, 5, 6, 9])
def test_pyramids(n):
    m = pyramid(n)
    assert (m.n_vertices, m.n_edges, m.n_faces) == (n + 1, 2 * n, n + 1)
    assert m.face_size_histogram() == ({3: 4} if n == 3 else {3: n, n: 1})
    assert m.volume > 0
    lengths = np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)
    assert (np.ptp(lengths) < 1e-12) == (n <= 5), "equilateral where it exists"


@pytest.mark.parametrize("build", [prism, antiprism, pyramid])
def test_seed_builders_check_n(build):
    with pytest.raises(
        ValueError, match=r"^n \(the sides of an? [a-z]+\) must be an integer >= 3, got 2$"
    ):
        build(2)
    with pytest.raises(TypeError):
        build("5")


def test_seed_table():
    assert set(SEEDS) == set("TCOIDPAY")
    assert SEEDS["P"].counts(7) == (14, 21, 9)


# ---------------------------------------------------------------------- malformed strings
MALFORMED = [
    # (notation, seed?, position, words in the message)
    ("", False, 0, "empty"),
    ("x", False, 0, "unknown letter 'x'"),
    ("dxC", False, 1, "unknown letter 'x' at position 1"),
    ("GC", False, 0, "unknown letter 'G'"),
    (" gC", False, 0, "unknown letter ' '"),
    ("gC ", False, 2, "unknown letter ' ' at position 2"),
    ("g C", False, 1, "position 1"),
    ("k²C", False, 1, "unknown letter '²'"),
    ("3C", False, 0, "number '3' at position 0"),
    ("d3C", False, 1, "'d' (dual) at position 0 takes no number"),
    ("g12C", False, 1, "takes no number, but '12'"),
    ("C3", False, 1, "'C' (cube) at position 0 takes no number"),
    ("P", False, 1, "needs a number of sides"),
    ("dP", False, 2, "seed 'P' (prism) at position 1 needs a number"),
    ("P2", False, 1, "P2 at position 0"),
    ("A2", False, 1, "antiprism needs a number of sides of at least 3"),
    ("Y2", False, 1, "pyramid"),
    ("A1", False, 1, "at least 3"),
    ("P0", False, 1, "at least 3"),
    ("k2C", False, 1, "kis needs a face size of at least 3"),
    ("t0C", False, 1, "truncate needs a valence of at least 3"),
    ("dk", False, 2, "no seed"),
    ("gk4", False, 3, "no seed"),
    ("dCk", False, 1, "seed 'C' at position 1 is not at the right end"),
    ("CT", False, 0, "seed 'C' at position 0 is not at the right end"),
    ("P5gC", False, 0, "seed 'P5' at position 0"),
    ("gC", True, 1, "seed given twice: 'C' at position 1"),
    ("gP5", True, 1, "seed given twice: 'P5'"),
]


@pytest.mark.parametrize("text, with_seed, position, words", MALFORMED)
def test_malformed_strings(text, with_seed, position, words):
    seed = shapes.cube() if with_seed else None
    with pytest.raises(NotationError) as info:
        conway(text, seed=seed)
    err = info.value
    assert isinstance(err, ValueError)
    assert words in str(err)
    assert err.position == position
    assert err.notation == text


def test_error_message_points_at_the_character():
    with pytest.raises(NotationError) as info:
        conway("dgxC")
    lines = str(info.value).splitlines()
    assert lines[-2].strip() == "dgxC"
    assert lines[-1].index("^") - lines[-2].index("d") == 2


def test_wrong_types():
    with pytest.raises(TypeError, match="string"):
        conway(5)
    with pytest.raises(TypeError, match="string"):
        parse(["g", "C"])
    with pytest.raises(TypeError, match=r"seed must be a pentanb\.Mesh"):
        conway("g", seed="C")


def test_options():
    with pytest.raises(TypeError, match=r"\['foo'\] are taken by no operator"):
        conway("gC", foo=1)
    with pytest.raises(TypeError, match="scale"):
        conway("gC", scale=0.5)  # g takes no option
    with pytest.raises(ValueError, match="scale must be in"):
        conway("qC", scale=1.5)
    a = conway("eC", scale=0.3)
    assert np.array_equal(a.vertices, pentanb.corner_cutting(shapes.cube(), scale=0.3).vertices)


def test_size_guard_refuses_before_building():
    with pytest.raises(ValueError, match="max_faces"):
        conway("wwwwwwwD")
    with pytest.raises(ValueError, match="over max_faces=50"):
        conway("kD", max_faces=50)
    with pytest.raises(ValueError, match="max_faces"):
        conway("P100000000")


def test_numbers_with_many_digits():
    m = conway("k12P12")
    assert m.face_size_histogram() == {3: 24, 4: 12}


# ---------------------------------------------------------------------- reductions
@pytest.mark.parametrize(
    "text, reduced",
    [
        ("ddgT", "gT"),
        ("ddddC", "C"),
        ("dkdC", "tC"),
        ("dadC", "jC"),
        ("dC", "O"),
        ("dgdC", "sO"),
        ("P4", "C"),
        ("A3", "O"),
        ("Y3", "T"),
        ("rrsC", "sC"),
        ("k4dC", "k4O"),
        ("adD", "aD"),
        ("dd", ""),
        ("gdd", "g"),
        ("dpd", "p"),
    ],
)
def test_reduce_notation(text, reduced):
    assert reduce_notation(text) == reduced


@pytest.mark.parametrize("pattern, replacement", REDUCTIONS)
def test_every_reduction_keeps_the_topology(pattern, replacement):
    for seed in ("C", "D", "Y5"):
        a = conway(pattern + seed)
        b = conway(replacement + seed)
        assert is_isomorphic(a, b), (pattern, seed)


def test_reductions_apply_only_for_canonical_positions_by_default():
    plain = conway("ddC")
    assert not np.allclose(plain.vertices, shapes.cube().vertices)  # two smoothing steps
    assert np.allclose(conway("ddC", reduce=True).vertices, shapes.cube().vertices)


# ---------------------------------------------------------------------- resolve (for the explorer)
def test_resolve_gives_a_scheme():
    s = resolve("dg")
    assert isinstance(s, pentanb.Scheme)
    assert s.formula == "(2E, 5E, V+2E+F)"
    m = s(shapes.cube())
    assert np.array_equal(m.vertices, conway("dgC").vertices)
    assert s.exact_counts and s.options == {}
    q = resolve("qe")
    assert q.options == {"scale": 0.5}
    assert np.array_equal(q(shapes.cube(), scale=0.4).vertices, conway("qeC", scale=0.4).vertices)
    assert not resolve("k4").exact_counts


def test_resolved_scheme_works_with_subdivide():
    m = pentanb.subdivide(shapes.cube(), resolve("gd"), iterations=1, duals=2)
    ref = pentanb.smooth(conway("gdC"), 2)
    assert np.allclose(m.vertices, ref.vertices)
    counts = pentanb.predict_counts((8, 12, 6), resolve("gd"), iterations=1, duals=0)
    assert counts == [(conway("gdC").n_vertices, conway("gdC").n_edges, conway("gdC").n_faces)]


def test_resolve_refuses_a_seed():
    with pytest.raises(NotationError, match="seed given twice"):
        resolve("gC")
    with pytest.raises(NotationError, match="unknown letter"):
        resolve("pentagonalize")


def test_counts_flag_numeric_forms():
    # conway's size check: the seed's counts, then after every operator
    assert _counts("k4P6") == ([(12, 18, 8), (20, 54, 36)], False)
    assert _counts("gC") == ([(8, 12, 6), (38, 60, 24)], True)
    assert _counts("g", seed=shapes.dodecahedron()) == ([(20, 30, 12), (92, 150, 60)], True)
    assert _counts("dgT")[0] == [(4, 6, 4), (20, 30, 12), (12, 30, 20)]  # gT = D, dgT = I


def test_truncate_n_counts_on_a_mesh():
    m = seed_mesh("Y4")  # one 4-valent vertex (the apex), four 3-valent ones
    for n in (3, 4):
        out = conway(f"t{n}", seed=m)
        assert OPERATORS["t"].counts_on(m, n) == (out.n_vertices, out.n_edges, out.n_faces)
    assert OPERATORS["t"].counts_on(m) == OPERATORS["t"].counts(5, 8, 5)


def test_as_scheme_takes_names_schemes_callables_and_notation():
    from pentanb.notation import as_scheme
    from pentanb.schemes.registry import SCHEMES, get_scheme

    assert as_scheme("pentagonalize") is SCHEMES["pentagonalize"]
    assert as_scheme(SCHEMES["honeycomb"]) is SCHEMES["honeycomb"]
    assert as_scheme(pentanb.dual) is pentanb.dual
    s = as_scheme("dg")
    assert s.name == "dg" and s.formula == "(2E, 5E, V+2E+F)" and s.family == "conway"
    assert as_scheme("k4").formula.endswith(" at most")
    with pytest.raises(ValueError, match=r"unknown scheme 'pentagonalise'.*Conway operators"):
        as_scheme("pentagonalise")
    # the registry itself reads no notation
    with pytest.raises(ValueError, match=r"^unknown scheme 'dg'; known schemes: pentagonalize"):
        get_scheme("dg")


ROOT = Path(pentanb.__file__).resolve().parent.parent


def _imports(path: Path) -> set[str]:
    """The modules a source file imports (at load time or inside functions),
    relative imports made absolute."""
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = parts[: len(parts) - node.level] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            found.add(module)
            found.update(f"{module}.{a.name}" for a in node.names)
    return found


@pytest.mark.parametrize(
    "package, forbidden",
    [("schemes", "pentanb.notation"), ("notation", "pentanb.analysis")],
)
def test_imports_go_one_way(package, forbidden):
    """analysis -> notation -> schemes, never back (deferred imports included)."""
    for path in sorted((ROOT / "pentanb" / package).glob("*.py")):
        bad = sorted(m for m in _imports(path) if m == forbidden or m.startswith(forbidden + "."))
        assert not bad, f"{path.name} imports {bad}"


def test_registered_letters_share_the_schemes_count_formulas():
    """Each count formula is written once: the letters that are registered
    schemes take the scheme's function."""
    from pentanb.schemes.registry import SCHEMES

    pairs = {
        "g": "pentagonalize",
        "q": "preserve_pentagons",
        "e": "corner_cutting",
        "o": "vertex_insertion",
        "c": "preserve_hexagons",
        "z": "honeycomb",
        "u": "loop_remesh",
        "n": "sqrt3_remesh",
    }
    for letter, name in pairs.items():
        assert OPERATORS[letter].counts is SCHEMES[name].counts, letter
        assert OPERATORS[letter].formula == SCHEMES[name].formula, letter


def test_registry_is_complete():
    """Every operator the issue lists, with a reference and a position note."""
    assert set("datkjesgpombcwqzun") <= set(OPERATORS)
    for op in OPERATORS.values():
        assert op.reference and op.positions and op.name
        assert re.fullmatch(r"[a-z]", op.letter)
