"""The limit surface at control vertices (pentanb.analysis.limit): positions and normals
from left eigenvectors, checked against actual subdivision; curvature measures."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pentanb import MeshError, shapes
from pentanb import analysis as an

PAPER = [("pentagonalize", {}), ("preserve_pentagons", {"scale": 0.75})]


def jiggled(mesh, seed=1, amount=0.1):
    """Generic control points: no symmetry puts a limit where it belongs by accident."""
    rng = np.random.default_rng(seed)
    return mesh.with_vertices(mesh.vertices + amount * rng.standard_normal(mesh.vertices.shape))


@pytest.fixture(scope="module")
def cube():
    return jiggled(shapes.cube())


@pytest.mark.parametrize("scheme, options", PAPER)
@pytest.mark.parametrize("kind, element", [("vertex", 0), ("vertex", 5), ("face", 2)])
def test_limit_follows_actual_subdivision_at_the_predicted_rate(
    cube, scheme, options, kind, element
):
    st = an.limit_stencil(cube, scheme, kind, element, **options)
    assert math.isclose(st.weights.sum(), 1.0, rel_tol=1e-12)
    cv = an.limit_convergence(st, cube, levels=3)
    # subdivision agrees with the local matrix's powers, level by level
    np.testing.assert_allclose(cv.distances, cv.predicted, rtol=1e-8, atol=1e-12 * cv.scale)
    assert cv.agrees
    if cv.rate > 0:
        # the subdominant pair (Fourier modes +-1) never reaches the element's point
        assert cv.rate < st.lambda1 * (1 - 1e-6)
        assert cv.distances[-1] < 0.02 * cv.distances[0]
        assert abs(cv.measured_rate - cv.rate) <= 0.05 * cv.rate
    else:
        # pentagon preservation keeps the centroid of its faces: the limit is there
        assert scheme == "preserve_pentagons" and kind == "face"
        assert cv.distances.max() <= 1e-12 * cv.scale
    assert cv.normals_agree


def test_the_rates_are_the_spectrum_s(cube):
    # pentagonalization at a 3-valent vertex: lambda1 = 0.3839 (a complex pair), the
    # distance falls with the mode-0 eigenvalue 2/9 = 0.2222
    st = an.limit_stencil(cube, "pentagonalize", "vertex", 0)
    assert st.lambda1 == pytest.approx(0.3839, abs=1e-4)
    cv = an.limit_convergence(st, cube, levels=3)
    assert cv.rate == pytest.approx(2 / 9, rel=1e-9)
    assert cv.measured_rate == pytest.approx(0.2222, abs=0.002)
    st = an.limit_stencil(cube, "preserve_pentagons", "vertex", 0, scale=0.75)
    assert an.limit_convergence(st, cube, levels=3).rate == pytest.approx(0.2267, abs=1e-4)


def perturbed(weights, seed=0, amount=0.05):
    """Weights that still sum to 1 but are not the left eigenvector."""
    rng = np.random.default_rng(seed)
    d = rng.standard_normal(weights.size)
    d -= d.mean()
    return weights + amount * d / np.abs(d).max()


@pytest.mark.parametrize("scheme, options", PAPER)
def test_limit_convergence_fails_on_a_wrong_eigenvector(cube, scheme, options):
    st = an.limit_stencil(cube, scheme, "vertex", 0, **options)
    assert an.limit_convergence(st, cube, levels=3).agrees
    for wrong in (perturbed(st.weights), np.full(st.weights.size, 1.0 / st.weights.size)):
        bad = dataclasses.replace(st, weights=wrong)
        cv = an.limit_convergence(bad, cube, levels=3)
        assert not cv.agrees
        assert cv.measured_rate > 0.9  # the distance no longer falls


@pytest.mark.parametrize("scheme, options", PAPER)
def test_limit_normals_fail_on_wrong_tangent_eigenvectors(cube, scheme, options):
    st = an.limit_stencil(cube, scheme, "vertex", 0, **options)
    assert an.limit_convergence(st, cube, levels=3).normals_agree
    # the left eigenvectors of the next eigenvalues instead of the subdominant pair
    w, VL = np.linalg.eig(st.matrix.T)
    order = np.argsort(-np.abs(w))
    nxt = VL[:, order[3:5]]
    wrong = np.stack(
        [
            nxt[:, 0].real,
            (nxt[:, 1].imag if np.abs(nxt[:, 1].imag).max() > 1e-9 else nxt[:, 1].real),
        ]
    )
    bad = dataclasses.replace(st, tangent_weights=wrong)
    assert not an.limit_convergence(bad, cube, levels=3).normals_agree
    # a perturbed matrix gives perturbed eigenvectors: the check sees that too
    A = st.matrix.copy()
    A[0] = perturbed(A[0], amount=0.02)
    bad = an.limit.limit_stencil(cube, scheme, "vertex", 0, **options)
    bad = dataclasses.replace(bad, matrix=A, weights=an.limit._left_spaces(A)[0])
    assert not an.limit_convergence(bad, cube, levels=3).agrees


def test_limit_points_and_normals_on_the_cube():
    c = shapes.cube()
    for scheme, options in PAPER:
        p = an.limit_points(c, scheme, elements=[0, 3], **options)
        n = an.limit_normals(c, scheme, elements=[0, 3], **options)
        assert p.shape == n.shape == (2, 3)
        # by symmetry the limit of a corner is on its diagonal, its normal along it
        for q, m, v in zip(p, n, c.vertices[[0, 3]], strict=True):
            np.testing.assert_allclose(np.abs(q), np.abs(q[0]), atol=1e-12)
            np.testing.assert_allclose(q / np.abs(q[0]), np.sign(v), atol=1e-12)
            np.testing.assert_allclose(m, np.sign(v) / math.sqrt(3), atol=1e-12)
            assert 0.5 < abs(q[0]) < 1.0  # inside the cube [-1, 1]^3, towards the corner
    pf = an.limit_points(c, "pentagonalize", kind="face", elements=[0])
    assert np.count_nonzero(np.abs(pf[0]) > 1e-9) == 1  # a face centre stays on its axis


def test_limits_are_affine_invariant(cube):
    M = np.array([[2.0, 0.3, 0.0], [0.0, 1.0, -0.4], [0.1, 0.0, 0.5]])
    t = np.array([1.0, -2.0, 0.5])
    moved = cube.with_vertices(cube.vertices @ M.T + t)
    for scheme, options in PAPER:
        a = an.limit_points(cube, scheme, elements=[1, 6], **options)
        b = an.limit_points(moved, scheme, elements=[1, 6], **options)
        np.testing.assert_allclose(b, a @ M.T + t, atol=1e-12)


def test_no_tangent_plane_at_triangles_with_scale_one_half():
    t = jiggled(shapes.tetrahedron())
    n = an.limit_normals(t, "preserve_pentagons", kind="face", elements=[0], scale=0.5)
    assert np.isnan(n).all()
    st = an.limit_stencil(t, "preserve_pentagons", "face", 0, scale=0.5)
    assert "simple" in st.note and st.tangents is None
    n = an.limit_normals(t, "preserve_pentagons", kind="face", elements=[0], scale=0.75)
    assert np.isfinite(n).all()


def test_limit_refuses_bad_input(cube):
    with pytest.raises(MeshError, match="closed mesh"):
        an.limit_points(shapes.open_disk(), "pentagonalize", elements=[0])
    with pytest.raises(ValueError, match="does not exist"):
        an.limit_stencil(cube, "pentagonalize", "vertex", 99)
    with pytest.raises(ValueError, match="kind"):
        an.limit_stencil(cube, "pentagonalize", "edge", 0)
    with pytest.raises(TypeError):
        an.limit_stencil("cube", "pentagonalize")
    st = an.limit_stencil(cube, "pentagonalize", "vertex", 0)
    with pytest.raises(ValueError, match="levels"):
        an.limit_convergence(st, cube, levels=1)
    with pytest.raises(ValueError, match="neighbourhood"):
        an.limit_convergence(st, jiggled(shapes.cube(), seed=2), levels=2)


# ------------------------------------------------------------------ curvature measures
def measures_of(scheme, kind, size, **options):
    return an.curvature_measures(an.local_spectrum(scheme, kind, size, **options))


def test_curvature_diverges_at_every_pentagonalization_vertex():
    for k in range(3, 9):
        c = measures_of("pentagonalize", "vertex", k)
        assert c.ratio > 1 and c.curvature == "diverges", (k, c)
        assert 0 < c.holder < 1
    c = measures_of("pentagonalize", "vertex", 3)
    assert c.lambda1 == pytest.approx(0.3839, abs=1e-4)
    assert c.lambda3 == pytest.approx(2 / 9, rel=1e-9)
    assert c.ratio == pytest.approx((2 / 9) / c.lambda1**2, rel=1e-12)
    assert c.holder == pytest.approx(math.log(c.lambda1 / (2 / 9)) / math.log(1 / c.lambda1))


def test_curvature_at_pentagon_preservation_faces():
    bounded = {
        n
        for n in range(3, 9)
        if measures_of("preserve_pentagons", "face", n, scale=0.75).ratio <= 1
    }
    assert bounded == {5, 6, 7}
    tri = measures_of("preserve_pentagons", "face", 3, scale=0.75)
    assert tri.lambda1 == pytest.approx(1 / 8) and tri.lambda3 == pytest.approx(29 / 240)
    assert tri.holder == pytest.approx(math.log(30 / 29) / math.log(8), rel=1e-9)  # 0.0163
    tri = measures_of("preserve_pentagons", "face", 3, scale=7 / 8)
    assert tri.holder == pytest.approx(math.log(62 / 53) / math.log(240 / 31), rel=1e-9)
    assert measures_of("preserve_pentagons", "face", 3, scale=0.5).curvature == "no tangent plane"


def test_curvature_bounded_where_the_surface_is_a_spline():
    # vertex insertion + 2 duals at a 4-valent vertex: 1/2, 1/2, 1/4: the bicubic spline
    c = measures_of("vertex_insertion", "vertex", 4)
    assert c.ratio == pytest.approx(1.0) and c.curvature == "bounded"
    assert c.holder == pytest.approx(1.0)


def test_curvature_measures_fail_on_wrong_eigenvalues():
    sp = an.local_spectrum("preserve_pentagons", "face", 6, scale=0.75)
    assert an.curvature_measures(sp).curvature == "tends to 0"
    w = sp.eigenvalues.copy()
    w[3] = 1.2 * abs(w[1]) ** 2  # a sub-subdominant eigenvalue above lambda1^2
    wrong = an.curvature_measures(dataclasses.replace(sp, eigenvalues=w))
    assert wrong.curvature == "diverges"
    w[2] = 0.9 * w[1]  # no longer a pair
    assert an.curvature_measures(dataclasses.replace(sp, eigenvalues=w)).curvature == (
        "no tangent plane"
    )


def test_curvature_markdown_lists_every_row():
    ms = [
        measures_of("pentagonalize", "vertex", 3),
        measures_of("preserve_pentagons", "face", 3, scale=0.5),
    ]
    text = an.curvature_markdown(ms)
    assert text.count("\n") == 3 and "diverges" in text and "no tangent plane" in text
