"""The convergence study (beyond the paper's "visually confirmed G1").

The measures it uses (radius spread, crease angles, edge waviness) are
tested on exact inputs in :mod:`test_measures`.
"""

from __future__ import annotations

import numpy as np
import pytest

import pentanb
from pentanb import shapes
from pentanb.analysis import convergence as cv
from pentanb.analysis import edge_waviness


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


def test_pentagonalization_makes_smaller_waves_than_honeycomb():
    # Section 1: no lateral artifact on the hard-edged cube of Figure 1
    from pentanb.shapes import hard_edged_cube

    cube = hard_edged_cube()
    ours = edge_waviness(pentanb.subdivide(cube, "pentagonalize", 1, 2))
    theirs = edge_waviness(pentanb.subdivide(cube, "honeycomb", 1, 2))
    assert ours < theirs / 2
