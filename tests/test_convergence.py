"""The convergence study (beyond the paper's "visually confirmed G1") and the
lateral-artifact study (Section 1).

The measures they use (spreads, crease angles, edge profiles) are tested on
exact inputs in :mod:`test_measures`; the claims built on them are
falsified in :mod:`test_claims`.
"""

from __future__ import annotations

import numpy as np
import pytest

import pentanb
from pentanb import shapes
from pentanb.analysis import convergence as cv
from pentanb.analysis import lateral as lt


def test_dual_convergence_shape_and_values():
    res = cv.dual_convergence(shapes.tetrahedron(), "pentagonalize", duals=8)
    assert list(res.steps) == [0, 1, 2, 3, 4]  # 0: the remeshing alone
    assert list(res.faces) == [12] * 5
    # Figure 7: with every pair of duals the dodecahedron gets rounder
    assert np.all(np.diff(res.radius_spread) < 0)
    assert np.all(np.diff(res.angle_spread) < 0)
    # ... but the pentagonalized tetrahedron starts equilateral: edge spread 0
    assert res.edge_spread[0] == pytest.approx(0.0, abs=1e-12) and res.edge_spread[1] > 0.02
    for field in ("max_normal_angle", "mean_normal_angle", "crease_at", "crease_elsewhere"):
        assert getattr(res, field).shape == (5,), field
    assert np.all(res.mean_normal_angle <= res.max_normal_angle)


def test_pentagon_preservation_makes_the_tetrahedron_less_round_with_more_duals():
    # the finding behind convergence.uniform.tetrahedron.preserve_pentagons
    res = cv.dual_convergence(shapes.tetrahedron(), "preserve_pentagons", duals=12)
    assert res.radius_spread[1] < 0.11 and res.radius_spread[6] > 0.25
    assert res.max_normal_angle[1] < 66 and res.max_normal_angle[6] > 98


def test_subdivision_convergence_angles_fall():
    res = cv.subdivision_convergence(shapes.cube(), "pentagonalize", iterations=3)
    assert list(res.faces) == [24, 120, 600]
    assert np.all(np.diff(res.max_normal_angle) < 0)
    assert np.all(np.diff(res.crease_at) < 0) and np.all(np.diff(res.crease_elsewhere) < 0)
    # the largest crease is the larger of the two
    assert np.allclose(res.max_normal_angle, np.fmax(res.crease_at, res.crease_elsewhere))


def test_extraordinary_vertices():
    cube = shapes.cube()
    m = pentanb.subdivide(cube, "pentagonalize", 1, 2)
    marked = cv.extraordinary(m, cube)
    assert np.flatnonzero(marked).tolist() == list(range(8))  # the cube's 3-valent corners
    torus = shapes.torus(8, 6)  # 4-valent everywhere: none
    assert not cv.extraordinary(pentanb.subdivide(torus, "pentagonalize", 1, 2), torus).any()
    # pentagon preservation keeps the torus's quads: their corners are marked
    q = pentanb.subdivide(torus, "preserve_pentagons", 1, 2)
    marked = cv.extraordinary(q, torus)
    quads = q.face_sizes[q.halfedge_face] == 4
    assert np.array_equal(np.flatnonzero(marked), np.unique(q.corners[quads]))


def test_options_reach_the_scheme():
    a = cv.subdivision_convergence(shapes.cube(), "preserve_pentagons", 1, scale=0.3)
    b = cv.subdivision_convergence(shapes.cube(), "preserve_pentagons", 1, scale=0.7)
    assert a.max_normal_angle[0] != b.max_normal_angle[0]


def test_bad_counts_are_refused():
    with pytest.raises(ValueError, match="duals"):
        cv.dual_convergence(shapes.cube(), duals=0)
    with pytest.raises(ValueError, match="even"):
        cv.dual_convergence(shapes.cube(), duals=3)  # measured in pairs of duals
    with pytest.raises(TypeError, match="duals"):
        cv.dual_convergence(shapes.cube(), duals=2.0)
    with pytest.raises(ValueError, match="iterations"):
        cv.subdivision_convergence(shapes.cube(), iterations=0)


@pytest.mark.slow
def test_study_covers_both_schemes_on_every_mesh():
    data = cv.study()
    keys = {(m, s) for m in cv.STUDY_MESHES for s in cv.STUDY_SCHEMES}
    assert set(data["duals"]) == keys and set(data["iterations"]) == keys
    assert cv.STUDY_MESHES["rabbit"] is shapes.rabbit
    for (m, _), res in data["iterations"].items():
        assert len(res.steps) == (5 if m == "rabbit" else 4)  # the rabbit: one level more
        assert np.isnan(res.radius_spread).all()  # iterations carry the creases only
        assert not np.isnan(res.max_normal_angle).any()


def test_study_is_shared_however_its_arguments_are_passed():
    small = cv.study(2, 1)
    assert cv.study(duals=2, iterations=1) is small
    assert len(small["iterations"]["rabbit", "pentagonalize"].steps) == 2
    assert len(small["iterations"]["cube", "pentagonalize"].steps) == 1


def test_spreads_can_be_left_out():
    full = cv.subdivision_convergence(shapes.cube(), "pentagonalize", 2)
    light = cv.subdivision_convergence(shapes.cube(), "pentagonalize", 2, spreads=False)
    assert np.isnan(light.edge_spread).all() and not np.isnan(full.edge_spread).any()
    assert np.array_equal(full.max_normal_angle, light.max_normal_angle)
    assert np.array_equal(full.crease_at, light.crease_at)


def test_unit_normals_agree_with_the_mesh():
    from pentanb.analysis.measures import _unit_normals

    m = pentanb.subdivide(shapes.rabbit(), "preserve_pentagons", 1, 2)
    assert np.abs(_unit_normals(m, block=1000) - m.face_normals).max() < 1e-12
    tiny = m.with_vertices(m.vertices * 1e-200)  # the mesh's own safe path takes over
    assert np.abs(_unit_normals(tiny) - m.face_normals).max() < 1e-12


@pytest.mark.slow
def test_predicted_crease_rate_of_a_triangle():
    pytest.importorskip("scipy")
    lam1, lam3, source = cv.predicted_crease_rate()
    assert source == "local_spectrum"
    assert lam1 == pytest.approx(0.125, rel=1e-9) and lam3 == pytest.approx(29 / 240, rel=1e-9)


# ---------------------------------------------------------------------- lateral artifact
def test_lateral_study_small():
    data = lt.study(2, ("3 cells",), ("vertex_insertion", "pentagonalize"))
    assert set(data.amplitude) == {("3 cells", "vertex_insertion"), ("3 cells", "pentagonalize")}
    vi = data.amplitude["3 cells", "vertex_insertion"]
    assert vi.shape == (2, 12) and vi.max() < 1e-12  # vertex insertion keeps the edges straight
    gyro = data.worst("3 cells", "pentagonalize")
    assert np.all(gyro > 0.01)  # pentagonalization does not (see the lateral claims)
    x, r = data.profile["3 cells", "pentagonalize"]
    assert np.all(np.abs(x) <= 1 / 3 + 1e-12) and r.shape == x.shape


def test_lateral_wave_has_the_grid_period_on_every_edge():
    data = lt.study(2, ("6 cells",), ("pentagonalize",))
    amp = data.amplitude["6 cells", "pentagonalize"]
    assert np.ptp(amp, axis=1).max() < 1e-12  # the same on all 12 edges (the cube's symmetry)
    x, r = data.profile["6 cells", "pentagonalize"]  # iteration 2 (at 1: half a cell)
    assert lt.wavelength(x, r) == pytest.approx(2 / 6, rel=0.02)


def test_wavelength_by_hand():
    x = np.linspace(-1, 1, 401)
    assert lt.wavelength(x, np.sin(2 * np.pi * x / 0.25)) == pytest.approx(0.25, rel=0.01)
    assert np.isnan(lt.wavelength(x, np.ones_like(x)))


def test_lateral_study_refuses_unknown_names():
    with pytest.raises(ValueError, match="unknown box"):
        lt.study(1, ("7 cells",))
    with pytest.raises(ValueError, match="unknown scheme"):
        lt.study(1, ("3 cells",), ("gyro",))
    with pytest.raises(ValueError, match="iterations"):
        lt.study(0)


def test_study_stops_before_max_faces():
    # the notebooks' cap: every mesh stops before one of more than 100,000 faces
    capped = cv.study(2, 4, max_faces=100_000)
    levels = {k: len(res.steps) for k, res in capped["iterations"].items()}
    assert levels[("rabbit", "pentagonalize")] == 3  # 20,050 faces; 100,250 at the 4th
    assert levels[("rabbit", "preserve_pentagons")] == 3  # 34,717; 207,949 at the 4th
    assert levels[("cube", "pentagonalize")] == 4
    assert max(int(res.faces.max()) for res in capped["iterations"].values()) <= 100_000
    assert cv.study(2, 4, max_faces=10) is not capped  # at least one iteration each
    assert all(len(r.steps) == 1 for r in cv.study(2, 4, max_faces=10)["iterations"].values())
