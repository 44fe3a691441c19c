"""The convergence measurements (beyond the paper's "visually confirmed G1")."""

from __future__ import annotations

import numpy as np
import pytest

import pentanb
from pentanb.analysis import convergence as cv
from pentanb import shapes


def test_normal_angles_of_a_cube_are_right_angles():
    a = cv.normal_angles(shapes.cube())
    assert a.shape == (12,)
    assert np.allclose(a, 90.0)


def test_normal_angles_of_an_icosahedron():
    # dihedral angle of the icosahedron: 138.19 deg, so normals differ by 41.81 deg
    a = cv.normal_angles(shapes.icosahedron())
    assert np.allclose(a, 180.0 - np.degrees(np.arccos(-np.sqrt(5) / 3)))


def test_normal_angles_match_a_loop_over_edges():
    mesh = pentanb.preserve_pentagons(shapes.torus(6, 4))
    n = mesh.face_normals
    slow = {}
    for h in range(mesh.n_halfedges):
        e = int(mesh.halfedge_edge[h])
        f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
        slow[e] = np.degrees(np.arccos(np.clip(n[f] @ n[g], -1, 1)))
    fast = cv.normal_angles(mesh)
    # (arccos amplifies rounding next to 0 degrees)
    assert np.allclose(fast, [slow[e] for e in range(mesh.n_edges)], atol=1e-5)


def test_radius_spread():
    assert cv.radius_spread(shapes.icosahedron()) == pytest.approx(0.0, abs=1e-12)
    assert cv.radius_spread(shapes.cube()) == pytest.approx(0.0, abs=1e-12)
    assert cv.radius_spread(shapes.torus()) > 0.1


def test_dual_convergence_shape_and_values():
    res = cv.dual_convergence(shapes.tetrahedron(), "pentagonalize", pairs=4)
    assert list(res.steps) == [1, 2, 3, 4]
    assert list(res.faces) == [12] * 4
    # Figure 7: with every pair of duals the dodecahedron gets rounder
    assert np.all(np.diff(res.radius_spread) < 0)
    assert res.max_normal_angle.shape == res.mean_normal_angle.shape == (4,)
    assert np.all(res.mean_normal_angle <= res.max_normal_angle)


def test_subdivision_convergence_angles_fall():
    res = cv.subdivision_convergence(shapes.cube(), "pentagonalize", levels=3)
    assert list(res.faces) == [24, 120, 600]
    assert np.all(np.diff(res.max_normal_angle) < 0)


def test_options_reach_the_scheme():
    a = cv.subdivision_convergence(shapes.cube(), "preserve_pentagons", 1, scale=0.3)
    b = cv.subdivision_convergence(shapes.cube(), "preserve_pentagons", 1, scale=0.7)
    assert a.max_normal_angle[0] != b.max_normal_angle[0]


def test_bad_counts_are_refused():
    with pytest.raises(ValueError, match="pairs"):
        cv.dual_convergence(shapes.cube(), pairs=0)
    with pytest.raises(ValueError, match="levels"):
        cv.subdivision_convergence(shapes.cube(), levels=0)


def test_study_covers_both_schemes_on_every_mesh():
    data = cv.study()
    keys = {(m, s) for m in cv.STUDY_MESHES for s in cv.STUDY_SCHEMES}
    assert set(data["pairs"]) == keys and set(data["levels"]) == keys
    for res in data["levels"].values():
        assert np.all(np.diff(res.max_normal_angle) < 0)


def test_ray_distances_on_a_cube():
    cube = shapes.cube()
    d = np.array([1.0, 0.3, 0.2])
    d /= np.linalg.norm(d)
    got = cv.ray_distances(cube, np.zeros((1, 3)), d)
    assert got == pytest.approx([1.0 / d[0]])
    # from two points, straight up: the top face at z = 1
    got = cv.ray_distances(cube, [[0.1, 0.2, 0.0], [0.0, 0.0, 0.5]], [0.0, 0.0, 1.0])
    assert got == pytest.approx([1.0, 0.5])


def test_edge_waviness_is_zero_on_a_straight_edge_and_sees_a_wave():
    from pentanb.shapes import hard_edged_cube

    cube = hard_edged_cube(1 / 3)
    assert cv.edge_waviness(cube) == pytest.approx(0.0, abs=1e-9)
    v = cube.vertices.copy()
    ridge = (v[:, 1] == 1) & (v[:, 2] == 1)
    v[ridge, 1:] += 0.05 * np.cos(np.pi * v[ridge, 0])[:, None]  # bend the edge
    assert cv.edge_waviness(cube.with_vertices(v)) > 0.02


def test_pentagonalization_makes_smaller_waves_than_honeycomb():
    # Section 1: no lateral artifact on the hard-edged cube of Figure 1
    from pentanb.shapes import hard_edged_cube

    cube = hard_edged_cube()
    ours = cv.edge_waviness(pentanb.subdivide(cube, "pentagonalize", 1, 2))
    theirs = cv.edge_waviness(pentanb.subdivide(cube, "honeycomb", 1, 2))
    assert ours < theirs / 2
