"""The subdivision matrix S of "remesh, then duals" (issue 9, item 1).

S must reproduce :func:`pentanb.subdivide` on every scheme, on meshes with
mixed face sizes and on a higher-genus surface; its rows sum to 1; its
weights are non-negative for the registered (convex) rules; the probing
path agrees with the rules and refuses schemes that are not linear.  The
expected weights of the regular bicubic rule are written out by hand.
"""

from __future__ import annotations

import numpy as np
import pytest

import pentanb
from pentanb import Mesh, shapes

sp = pytest.importorskip("scipy.sparse")

from pentanb.analysis.subdivision_matrix import (  # noqa: E402
    RULE_SCHEMES,
    dual_matrix,
    matrix_checks,
    probe_matrix,
    remesh_matrix,
    subdivision_matrix,
)

SCHEMES = list(pentanb.SCHEMES)


def mixed_mesh() -> Mesh:
    """A pentagonal prism with one side split into two triangles:
    2 pentagons, 4 quads, 2 triangles (V = 10, E = 16, F = 8)."""
    t = 2 * np.pi * np.arange(5) / 5
    ring = np.stack([np.cos(t), np.sin(t), np.zeros(5)], axis=1)
    v = np.concatenate([ring + [0, 0, -1], ring + [0.1, 0, 1]])
    faces = [[4, 3, 2, 1, 0], [5, 6, 7, 8, 9]]
    faces += [[i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i] for i in range(1, 5)]
    faces += [[0, 1, 6], [0, 6, 5]]
    return Mesh(v, faces)


MESHES = {
    "cube": shapes.cube,
    "tetrahedron": shapes.tetrahedron,
    "dodecahedron": shapes.dodecahedron,
    "mixed": mixed_mesh,
    "triangulated_cube": lambda: pentanb.triangulate(shapes.cube()),
    "double_torus": shapes.double_torus,
}


@pytest.mark.parametrize("mesh_name", list(MESHES))
@pytest.mark.parametrize("scheme", SCHEMES)
def test_matrix_reproduces_subdivide(scheme, mesh_name):
    mesh = MESHES[mesh_name]()
    S, result = subdivision_matrix(mesh, scheme, 1, 2)
    ref = pentanb.subdivide(mesh, scheme, 1, 2)
    assert sp.issparse(S) and S.format == "csr"
    assert S.shape == (ref.n_vertices, mesh.n_vertices)
    # result is exactly subdivide's
    assert np.array_equal(result.corners, ref.corners)
    assert np.array_equal(result.offsets, ref.offsets)
    assert np.array_equal(result.vertices, ref.vertices)
    err = np.abs(S @ mesh.vertices - ref.vertices).max() / np.abs(ref.vertices).max()
    assert err <= 1e-12


@pytest.mark.parametrize("scheme", SCHEMES)
def test_rows_sum_to_one_and_weights_are_convex(scheme):
    mesh = mixed_mesh()
    S, result = subdivision_matrix(mesh, scheme, 2, 2)
    checks = matrix_checks(S, mesh, result)
    assert checks.affine, checks
    assert checks.convex, checks  # every registered rule is a convex combination
    assert checks.reproduces <= 1e-12


@pytest.mark.parametrize("duals", [0, 1, 3])
@pytest.mark.parametrize("scheme", ["pentagonalize", "corner_cutting", "sqrt3_remesh"])
def test_any_number_of_duals_and_iterations(scheme, duals):
    mesh = shapes.cube()
    S, _ = subdivision_matrix(mesh, scheme, 2, duals)
    ref = pentanb.subdivide(mesh, scheme, 2, duals)
    assert np.allclose(S @ mesh.vertices, ref.vertices, rtol=0, atol=1e-12)


def test_options_reach_the_rules():
    mesh = shapes.dodecahedron()
    for scale in (0.3, 0.75):
        S, _ = subdivision_matrix(mesh, "preserve_pentagons", 1, 2, scale=scale)
        ref = pentanb.subdivide(mesh, "preserve_pentagons", 1, 2, scale=scale)
        assert np.allclose(S @ mesh.vertices, ref.vertices, rtol=0, atol=1e-12)
    S1, _ = subdivision_matrix(mesh, "preserve_pentagons", scale=0.3)
    S2, _ = subdivision_matrix(mesh, "preserve_pentagons", scale=0.75)
    assert abs(S1 - S2).max() > 0.01  # the option changes the weights


def test_every_registered_scheme_has_rules():
    assert set(RULE_SCHEMES) == set(pentanb.SCHEMES)


@pytest.mark.parametrize("scheme", SCHEMES)
def test_probing_agrees_with_the_rules(scheme):
    mesh = mixed_mesh()
    R, out = remesh_matrix(mesh, scheme)
    P, out2 = remesh_matrix(mesh, scheme, probe=True)
    assert np.array_equal(out.corners, out2.corners)
    assert abs(R - P).max() < 1e-12


def test_dual_matrix_is_face_centroids():
    mesh = mixed_mesh()
    D = dual_matrix(mesh).toarray()
    for f, face in enumerate(mesh.faces):
        expected = np.zeros(mesh.n_vertices)
        expected[face] = 1.0 / len(face)
        assert np.allclose(D[f], expected)


def test_bicubic_rule_on_a_regular_quad_region():
    """Issue 9: smooth(vertex_insertion(m), duals=2) on regular quads places an
    old vertex at (36 v + 6 sum of edge neighbours + sum of diagonal ones) / 64."""
    mesh = shapes.torus(12, 8)  # every vertex 4-valent, every face a quad
    S, _ = subdivision_matrix(mesh, "vertex_insertion", 1, 2)
    S = S.toarray()
    for v in (0, 17, 50):
        edge = {int(w) for e in mesh.edges for w in e if v in e and w != v}
        faces = [f for f in mesh.faces if v in f]
        diagonal = {int(w) for f in faces for w in f} - edge - {v}
        expected = np.zeros(mesh.n_vertices)
        expected[v] = 36 / 64
        expected[list(edge)] = 6 / 64
        expected[list(diagonal)] = 1 / 64
        assert len(edge) == 4 and len(diagonal) == 4
        assert np.allclose(S[v], expected, rtol=0, atol=1e-15)


def test_a_users_linear_scheme_is_probed():
    def my_scheme(m):
        return pentanb.dual(pentanb.loop_remesh(m))

    mesh = shapes.octahedron()
    S, result = subdivision_matrix(mesh, my_scheme, 1, 2)
    ref = pentanb.subdivide(mesh, my_scheme, 1, 2)
    assert np.allclose(S @ mesh.vertices, ref.vertices, rtol=0, atol=1e-12)
    assert matrix_checks(S, mesh, result).affine


def test_a_nonlinear_scheme_is_refused():
    def onto_sphere(m):
        out = pentanb.loop_remesh(m)
        v = out.vertices / np.linalg.norm(out.vertices, axis=1, keepdims=True)
        return out.with_vertices(v)

    with pytest.raises(ValueError, match="not linear"):
        subdivision_matrix(shapes.octahedron(), onto_sphere, 1, 0)


def test_a_scheme_whose_connectivity_follows_the_positions_is_refused():
    def fickle(m):
        return pentanb.loop_remesh(m) if m.vertices[0, 0] < 1.5 else pentanb.sqrt3_remesh(m)

    with pytest.raises(ValueError, match="connectivity"):
        probe_matrix(shapes.octahedron(), fickle)


def test_probing_refuses_large_meshes():
    with pytest.raises(ValueError, match="max_vertices"):
        probe_matrix(shapes.animal(), pentanb.loop_remesh, max_vertices=100)


def test_bad_input_is_refused():
    cube = shapes.cube()
    with pytest.raises(TypeError):
        subdivision_matrix("cube", "pentagonalize")
    with pytest.raises(ValueError, match="unknown scheme"):
        subdivision_matrix(cube, "pentagonise")
    with pytest.raises(ValueError, match="takes"):
        subdivision_matrix(cube, "pentagonalize", scale=0.5)
    with pytest.raises(ValueError, match="iterations"):
        subdivision_matrix(cube, "pentagonalize", -1)
    with pytest.raises(ValueError, match="scale"):
        subdivision_matrix(cube, "preserve_pentagons", scale=1.5)
    with pytest.raises(pentanb.MeshError):
        subdivision_matrix(cube, "pentagonalize", 3, max_bytes=1000)


def test_matrix_checks_can_fail():
    mesh = shapes.cube()
    S, result = subdivision_matrix(mesh, "vertex_insertion")
    bad = S.tolil()
    bad[0, 0] -= 0.5  # row 0 no longer sums to 1
    bad[1, 0] = -0.1  # a negative weight
    checks = matrix_checks(bad.tocsr(), mesh, result)
    assert not checks.affine
    assert not checks.convex
    assert checks.reproduces > 1e-3


# ---------------------------------------------------------------------- exact weights
from fractions import Fraction  # noqa: E402

from pentanb.analysis.subdivision_matrix import (  # noqa: E402
    ExactMatrix,
    exact_dual_matrix,
    exact_remesh_matrix,
)

SCALED = {"preserve_pentagons": 0.75, "corner_cutting": 0.5, "preserve_hexagons": 0.5}


@pytest.mark.parametrize("scheme", [s for s in SCHEMES if s in RULE_SCHEMES])
def test_exact_weights_round_to_the_float_rules(scheme):
    mesh = mixed_mesh()
    opts = {"scale": SCALED[scheme]} if scheme in SCALED else {}
    R, _ = remesh_matrix(mesh, scheme, **opts)
    E = exact_remesh_matrix(mesh, scheme, **opts)
    assert isinstance(E, ExactMatrix) and E.shape == R.shape
    assert np.abs(E.toarray() - R.toarray()).max() <= 1e-15
    # every weight is a fraction, every row sums to exactly 1 (affine invariance)
    assert all(isinstance(x, Fraction) for x in E.data)
    assert all(sum(E.row(i).values()) == 1 for i in range(E.shape[0]))


def test_exact_scale_is_taken_as_given():
    mesh = shapes.cube()
    E = exact_remesh_matrix(mesh, "preserve_pentagons", scale=Fraction(5, 7))
    # a copy of an edge midpoint: 5/14 on each end of the edge, 2/7 spread over the face
    row = E.row(mesh.n_vertices + mesh.n_edges)
    assert sorted(row.values()) == sorted(
        [Fraction(5, 14) + Fraction(2, 28)] * 2 + [Fraction(2, 28)] * 2
    )
    # a float scale is its binary fraction: 0.7 is not 7/10
    F = exact_remesh_matrix(mesh, "preserve_pentagons", scale=0.7)
    assert F.row(mesh.n_vertices + mesh.n_edges) != exact_remesh_matrix(
        mesh, "preserve_pentagons", scale=Fraction(7, 10)
    ).row(mesh.n_vertices + mesh.n_edges)


def test_exact_dual_is_one_over_the_face_size():
    mesh = mixed_mesh()
    E = exact_dual_matrix(mesh)
    for f in range(mesh.n_faces):
        n = int(mesh.face_sizes[f])
        assert E.row(f) == {int(c): Fraction(1, n) for c in mesh.faces[f]}


def test_exact_matrix_sums_duplicates_and_drops_zeros():
    E = ExactMatrix.from_coo(
        [0, 0, 1, 1],
        [1, 1, 0, 1],
        [Fraction(1, 3), Fraction(2, 3), Fraction(0), Fraction(1)],
        (2, 2),
    )
    assert E.row(0) == {1: Fraction(1)} and E.row(1) == {1: Fraction(1)} and E.nnz == 2


def test_a_probed_scheme_has_no_exact_matrix():
    def shrink(m):
        return m.with_vertices(0.5 * m.vertices)

    with pytest.raises(ValueError, match="no exact matrix"):
        exact_remesh_matrix(shapes.cube(), shrink)
