"""Canonical and planar positions, and the planarity measure (issue 10).

The checks are computed here, with loops and numpy's SVD, not with the
package's measures: an edge is tangent when its line's distance from the
origin is 1, the tangency points are centred when their mean is 0, a face
is planar when its corners' smallest singular value (about their mean) is
0.  Geometry from the literature: the midradius of the Platonic and
Archimedean solids (their Wikipedia articles), which for a uniform solid
*is* the canonical form (every edge equally far from the centre, faces
regular), and the propello tetrahedron's canonical edge lengths 0.849 and
1.057 (Wikipedia, "Tetrahedrally diminished dodecahedron").
"""

from __future__ import annotations

import itertools
import random

import numpy as np
import pytest
from helpers import corpus, face_lists, two_cubes

import pentanb
from pentanb import Mesh, MeshError, shapes
from pentanb.analysis.measures import best_fit_planes, face_planarity, planarity
from pentanb.notation import (
    OPERATORS,
    ConvergenceError,
    canonical,
    conway,
    planarize,
    reduce_notation,
)
from pentanb.notation.build import _counts

PHI = (1 + 5**0.5) / 2
TOL = 1e-8


# ---------------------------------------------------------------------- independent checks
def edge_distances(m: Mesh) -> np.ndarray:
    out = []
    for u, w in m.edges:
        a, b = m.vertices[u], m.vertices[w]
        out.append(np.linalg.norm(np.cross(a, b)) / np.linalg.norm(a - b))
    return np.array(out)


def tangency_mean(m: Mesh) -> np.ndarray:
    pts = []
    for u, w in m.edges:
        a, b = m.vertices[u], m.vertices[w]
        d = b - a
        pts.append(a - (a @ d) / (d @ d) * d)
    return np.mean(pts, axis=0)


def flatness(m: Mesh) -> float:
    """Largest corner distance from its face's least-squares plane, over
    that face's mean edge length (SVD face by face)."""
    worst = 0.0
    for f in face_lists(m):
        p = m.vertices[f]
        q = p - p.mean(axis=0)
        normal = np.linalg.svd(q)[2][-1]
        edges = np.linalg.norm(p - np.roll(p, -1, axis=0), axis=1).mean()
        worst = max(worst, float(np.abs(q @ normal).max() / edges))
    return worst


def convex(m: Mesh) -> bool:
    """No vertex beyond the plane of a face."""
    for f in face_lists(m):
        p = m.vertices[f]
        n = np.cross(p[1] - p[0], p[2] - p[0])
        n /= np.linalg.norm(n)
        if np.max((m.vertices - p[0]) @ n) > 1e-9:
            return False
    return True


def assert_canonical(m: Mesh) -> None:
    assert np.abs(edge_distances(m) - 1).max() <= TOL
    assert np.linalg.norm(tangency_mean(m)) <= TOL
    assert flatness(m) <= TOL
    assert convex(m)
    assert m.volume > 0


def edge_lengths(m: Mesh) -> np.ndarray:
    return np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)


# ---------------------------------------------------------------------- canonical
SEEDS = ["T", "C", "O", "I", "D", "P3", "P5", "P8", "A4", "A5", "A7", "Y4", "Y5", "Y7"]


@pytest.mark.parametrize("seed", SEEDS)
def test_canonical_seeds(seed):
    m = conway(seed)
    out = canonical(m)
    assert_canonical(out)
    assert np.array_equal(out.corners, m.corners) and np.array_equal(out.offsets, m.offsets)


@pytest.mark.parametrize(
    "seed", ["T", "C", "P5", *(pytest.param(s, marks=pytest.mark.slow) for s in ("D", "A4", "Y5"))]
)
@pytest.mark.parametrize("letter", list(OPERATORS))
def test_canonical_every_operator(letter, seed):
    assert_canonical(conway(letter + seed, canonical=True))


#: Multi-operator strings: the paper's figures, the issue's examples, and
#: strings that defeat Hart's iteration or Newton from a sphere.
SAMPLE = [
    "ddgT",
    "dgT",
    "zD",
    "cD",
    "gC",
    "tI",
    "sC",
    "sD",
    "pT",
    "wD",
    "ggD",
    "qgC",
    "gqD",
    "pP5",
    "bY5",
    "cY5",
    "zY5",
    "sY5",
    "pY4",
    "k4P6",
    "t5dA5",
    "k5A5",
    "mgT",
    "wcC",
    "bpT",
    "qqT",
    "ucD",
    "nwT",
    "dtkC",
    "pagY6",
    "smA5",
    "gwP4",
    "ekzT",
]


@pytest.mark.parametrize("text", SAMPLE)
def test_canonical_sample(text):
    out, report = canonical(conway(text), report=True)
    assert report.converged, report
    assert_canonical(out)
    assert max(report.tangency, report.centring, report.planarity) <= TOL


def test_canonical_fails_the_checks_before():
    """The checks can fail: the package's own positions are not canonical."""
    m = conway("gC")
    assert np.abs(edge_distances(m) - 1).max() > 0.1
    assert flatness(m) < TOL  # gC's pentagons lie in the cube's faces
    m2 = conway("jC")
    assert flatness(m2) > 0.1
    assert not convex(conway("ddgT").with_vertices(conway("ddgT").vertices * [1, 1, -1]))


@pytest.mark.parametrize(
    "text, edge",
    [
        ("T", 2 * 2**0.5),
        ("C", 2**0.5),
        ("O", 2.0),
        ("I", 2 / PHI),
        ("D", 2 / PHI**2),
        ("aC", 2 / 3**0.5),
        ("tI", 2 / (3 * PHI)),
        ("aD", 2 / (5 + 2 * 5**0.5) ** 0.5),
    ],
)
def test_canonical_edge_lengths_from_the_midradius(text, edge):
    """With midradius 1 the edge length is 1 / (midradius of the unit-edge
    solid): tetrahedron 1/(2 sqrt 2), cube 1/sqrt 2, octahedron 1/2,
    icosahedron phi/2, dodecahedron phi^2/2, cuboctahedron sqrt(3)/2,
    truncated icosahedron 3 phi/2, icosidodecahedron sqrt(5 + 2 sqrt 5)/2."""
    lengths = edge_lengths(canonical(conway(text)))
    assert np.allclose(lengths, edge, rtol=0, atol=1e-9)


@pytest.mark.parametrize(
    "text", ["aC", "aD", "tT", "tC", "tO", "tI", "tD", "eC", "eD", "bC", "bD", "sC", "sD"]
)
def test_archimedean_solids_come_out_uniform(text):
    """The uniform Archimedean solid has a midsphere, so it is the canonical
    form: every edge has the same length."""
    lengths = edge_lengths(canonical(conway(text)))
    assert np.ptp(lengths) < 1e-9 * lengths.mean()


def test_snub_cube_midradius():
    """Snub cube: midradius 1.247223 for unit edges (Wikipedia)."""
    lengths = edge_lengths(canonical(conway("sC")))
    assert 1 / lengths.mean() == pytest.approx(1.2472232, abs=2e-7)


def test_propello_tetrahedron_edge_lengths():
    """Canonical pT: edge lengths 0.849 and 1.057 with midradius 1."""
    lengths = np.unique(edge_lengths(canonical(conway("pT"))).round(3))
    assert lengths.tolist() == [0.849, 1.057]


@pytest.mark.parametrize("text", ["C", "tI", "gC", "pT", "Y5", "k4P6", "wT"])
def test_canonical_dual_is_the_polar_reciprocal(text):
    """Vertex f of canonical(dual(m)) is the pole of face f's plane in
    canonical(m): |x'_f| = 1 / distance(plane f, origin), face by face."""
    m = conway(text)
    primal = canonical(m)
    dual = canonical(pentanb.dual(m))
    centres, normals = best_fit_planes(primal)
    dist = np.abs(np.einsum("ij,ij->i", centres, normals))
    assert np.allclose(np.linalg.norm(dual.vertices, axis=1), 1 / dist, atol=1e-8)


@pytest.mark.parametrize("text", ["C", "tI", "gC", "sC", "ggT", "cD"])
def test_two_methods_agree(text):
    """The circle-pattern construction and Newton from a sphere reach the same
    polyhedron (up to rotation: same vertex radii and edge lengths)."""
    m = conway(text)
    a = canonical(m, method="koebe")
    b = canonical(m, method="newton")
    assert np.allclose(
        np.linalg.norm(a.vertices, axis=1), np.linalg.norm(b.vertices, axis=1), atol=1e-8
    )
    assert np.allclose(edge_lengths(a), edge_lengths(b), atol=1e-8)


def test_canonical_does_not_depend_on_the_positions():
    m = conway("qgC")
    rng = np.random.default_rng(1)
    moved = m.with_vertices(m.vertices + rng.normal(scale=0.05, size=m.vertices.shape))
    a, b = canonical(m), canonical(moved)
    assert np.allclose(
        np.linalg.norm(a.vertices, axis=1), np.linalg.norm(b.vertices, axis=1), atol=1e-8
    )


def test_newton_alone_can_end_non_convex():
    """Newton from a sphere can satisfy tangency and planarity on a
    non-convex solution: that is reported, not returned as canonical."""
    m = conway("pY5")
    _, report = canonical(m, method="newton", report=True)
    assert not report.converged and not report.convex
    assert report.message
    with pytest.raises(ConvergenceError, match="not reached"):
        canonical(m, method="newton")
    assert_canonical(canonical(m))


def test_non_convergence_is_reported():
    m = conway("gC")
    out, report = canonical(m, tolerance=1e-30, report=True)
    assert not report.converged and report.iterations > 0
    assert isinstance(out, Mesh)
    with pytest.raises(ConvergenceError) as info:
        canonical(m, tolerance=1e-30)
    assert info.value.report.tolerance == 1e-30
    assert isinstance(info.value.mesh, Mesh)
    assert isinstance(info.value, RuntimeError)


def test_canonical_refuses_other_topologies():
    with pytest.raises(MeshError, match="genus 1"):
        canonical(shapes.torus())
    with pytest.raises(MeshError, match="2 component"):
        canonical(two_cubes())
    with pytest.raises(TypeError, match=r"pentanb\.Mesh"):
        canonical("C")
    with pytest.raises(ValueError, match="tolerance"):
        canonical(shapes.cube(), tolerance=0)
    with pytest.raises(ValueError, match="method"):
        canonical(shapes.cube(), method="hart")


def test_conway_canonical_option():
    a = conway("ddgT", canonical=True)
    b = canonical(conway("gT"))
    assert_canonical(a)
    assert np.allclose(
        np.sort(np.linalg.norm(a.vertices, axis=1)),
        np.sort(np.linalg.norm(b.vertices, axis=1)),
        atol=1e-8,
    )


# ---------------------------------------------------------------------- planarize
PLANARIZE = {
    "figure 1B (ddg of the hard-edged cube)": lambda: conway("ddg", seed=shapes.hard_edged_cube()),
    "figure 8A (ddgC)": lambda: conway("ddgC"),
    "figure 9A (ddg of the hexagonal torus)": lambda: conway("ddg", seed=shapes.hexagonal_torus()),
    "jC": lambda: conway("jC"),
    "cD": lambda: conway("cD"),
    "torus, gyro, two duals": lambda: pentanb.smooth(pentanb.pentagonalize(shapes.torus())),
    "hexagonal torus": lambda: shapes.hexagonal_torus(),
    "double torus, gyro, two duals": lambda: pentanb.smooth(
        pentanb.pentagonalize(shapes.double_torus())
    ),
    "animal, gyro, two duals": lambda: pentanb.smooth(pentanb.pentagonalize(shapes.animal())),
    "cube_split": lambda: corpus("cube_split"),
    "merged_icosahedron, chamfer": lambda: conway("c", seed=corpus("merged_icosahedron")),
}


@pytest.mark.parametrize("name", list(PLANARIZE))
def test_planarize(name):
    m = PLANARIZE[name]()
    out, report = planarize(m, report=True)
    assert report.converged, report
    assert flatness(out) <= TOL
    assert np.array_equal(out.corners, m.corners)
    mean_edge = edge_lengths(m).mean()
    move = np.linalg.norm(out.vertices - m.vertices, axis=1).max() / mean_edge
    assert report.max_move == pytest.approx(move, rel=1e-9, abs=1e-12)
    assert move < 1.0, "the shape stays close"
    assert np.sign(out.volume) == np.sign(m.volume)


def test_planarize_leaves_planar_meshes_alone():
    for text in ("C", "D", "tI", "gC", "pT"):
        m = conway(text)
        out, report = planarize(m, report=True)
        assert report.max_move < 1e-12
        assert np.allclose(out.vertices, m.vertices, atol=1e-12)


def test_planarize_does_not_collapse_faces():
    """The nearest planar mesh to the folded ``atjT`` (the centroid join of the
    tetrahedron is folded inwards) collapses its triangles to points; planarize
    keeps the edge lengths first and returns a mesh with no collapsed edge."""
    from pentanb.notation.positions import _collapsed, _solve_planar

    for text in ("atjT", "utjT"):
        m = conway(text)
        x0 = (m.vertices - m.vertices.mean(axis=0)) / edge_lengths(m).mean()
        big = np.flatnonzero(m.face_sizes > 3)
        nearest, _, _ = _solve_planar(m, x0, big, 100, TOL)
        assert _collapsed(nearest, m, x0), "the check can fail"
        out, report = planarize(m, report=True)
        assert report.converged, report
        assert flatness(out) <= TOL
        lengths = edge_lengths(out)
        assert lengths.min() > 0.1 * lengths.mean()


def test_planarize_reports_failure():
    m = conway("jC")
    with pytest.raises(ConvergenceError, match="planar positions not reached"):
        planarize(m, tolerance=1e-30)
    _, report = planarize(m, tolerance=1e-30, report=True)
    assert not report.converged
    with pytest.raises(TypeError):
        planarize(np.zeros((3, 3)))


@pytest.mark.parametrize("text", ["jC", "ddgC", "cC", "wD", "qeT", "oY5"])
def test_planarize_sample(text):
    out = planarize(conway(text))
    assert flatness(out) <= TOL


# ---------------------------------------------------------------------- planarity measure
def test_planarity_of_planar_meshes():
    assert planarity(shapes.cube()) < 1e-15
    assert planarity(shapes.dodecahedron()) < 1e-15
    assert planarity(shapes.icosahedron()) < 1e-15


def test_planarity_of_a_bent_quad():
    """A unit square with one corner lifted by h: the corners are h/4 off
    the least-squares plane (to first order in h)."""
    h = 1e-4
    base = shapes.cube()
    v = base.vertices.copy()
    # face x = 1 is [4, 6, 7, 5]; lift vertex 7 along x (the face's normal),
    # keeping the other faces through vertex 7 planar is not needed here
    v[7] += [h, 0, 0]
    m = base.with_vertices(v)
    per_face = face_planarity(m, relative_to="face")
    face = next(i for i, f in enumerate(face_lists(m)) if sorted(f) == [4, 5, 6, 7])
    assert per_face[face] == pytest.approx(h / 4 / 2, rel=1e-3)  # edges of length 2
    assert planarity(m) == pytest.approx(per_face.max() * 2 / edge_lengths(m).mean(), rel=1e-6)


@pytest.mark.slow
def test_planarity_of_the_papers_figures():
    """Issue 10: "after two duals the faces here are not planar (6-15 % of an
    edge length off the best-fit plane on Figures 1B, 9A, 12B)".  Measured:
    9A and 12B are in that range; 1B is not (its hard-edged cube keeps most
    faces nearly flat): the 6 % is Figure 8A's plain cube.  Planarize brings
    every one to rounding level."""
    fig1b = conway("ddg", seed=shapes.hard_edged_cube())
    fig8a = conway("ddgC")
    fig9a = conway("ddg", seed=shapes.hexagonal_torus())
    fig12b = conway("ddgddg", seed=shapes.animal())
    assert planarity(fig1b) < 0.06, "does not hold as stated for Figure 1B"
    for m in (fig8a, fig9a, fig12b):
        assert 0.06 <= planarity(m) <= 0.16
    for m in (fig1b, fig8a, fig9a):
        assert planarity(planarize(m)) < 1e-12
    assert planarity(canonical(fig8a)) < 1e-12


def test_face_planarity_arguments():
    with pytest.raises(ValueError, match="relative_to"):
        face_planarity(shapes.cube(), relative_to="edge")


def test_best_fit_normals_follow_the_faces():
    m = conway("tI")
    _, normals = best_fit_planes(m)
    assert np.allclose(normals, m.face_normals, atol=1e-12)


# ---------------------------------------------------------------------- the full enumeration
def _strings(depth: int, seeds, letters):
    for k in range(depth + 1):
        for ops in itertools.product(letters, repeat=k):
            for s in seeds:
                yield "".join(ops) + s


@pytest.mark.slow
def test_canonical_and_planarize_on_short_strings():
    """Every string of at most two of the issue's operators on T, C, D and a
    pyramid (duplicates under the exact rewrites of REDUCTIONS dropped;
    results of at most 300 faces), plus 60 strings of three or four
    operators drawn at random: canonical and planarize both converge.

    (The strings of up to four operators on T C O I D are about 690,000,
    136,000 of them with at most 300 faces: too many for a test;
    ``benchmarks/bench_canonical.py`` runs those of up to three.)"""
    letters = [c for c in OPERATORS if c != "r"]
    seeds = ["T", "C", "D", "Y5"]
    strings = list(_strings(2, seeds, letters))
    longer = [s for s in _strings(4, ["T", "C", "D", "Y4"], letters) if len(s) >= 4]
    strings += random.Random(10).sample(longer, 60)
    seen, failures = set(), []
    for text in strings:
        if _counts(text)[0][-1][2] > 300:
            continue
        key = reduce_notation(text)
        if key in seen:
            continue
        seen.add(key)
        m = conway(text)
        _, rep = canonical(m, report=True)
        _, rep2 = planarize(m, report=True)
        if not (rep.converged and rep2.converged):
            failures.append((text, rep.message, rep2.message))
    assert not failures, failures[:20]
    assert len(seen) > 800


def test_importing_needs_numpy_only():
    """The new modules import scipy only when a function needs it, and
    ``import pentanb`` loads no analysis (the notation never imports it)."""
    import subprocess
    import sys

    code = (
        "import sys, pentanb;"
        "assert not [m for m in sys.modules if m.startswith('pentanb.analysis')];"
        "import pentanb.notation, pentanb.notation.positions, pentanb.analysis.measures;"
        "assert 'scipy' not in sys.modules, 'scipy imported';"
        "pentanb.notation.conway('gC');"
        "assert 'scipy' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
