"""The analysis of open meshes: the subdivision matrix and the boundary curve's own rule.

* :func:`~pentanb.analysis.subdivision_matrix` on meshes with boundary: ``S @ V``
  against what the scheme itself computes (the scheme is run, the matrix
  applied, the two compared), rows summing to 1, the exact matrices equal to
  the float ones, and the dual's boundary rows written out by hand;
* :func:`~pentanb.analysis.boundary_spectrum`: the new boundary positions
  depend on the old boundary positions only (a zero block of ``S``, checked
  on the matrix itself), and the curve rule they follow, its mask and the
  spectrum of its local matrix, against references written here from the
  curve schemes' definitions (the cubic B-spline's mask ``(1, 4, 6, 4, 1) / 8``
  and its eigenvalues ``1, 1/2, 1/4, 1/8, 1/8``; pentagonalization's boundary
  as trisection then two rounds of midpoint averaging).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import pentanb
from pentanb import Mesh, shapes

sp = pytest.importorskip("scipy.sparse")

from pentanb.analysis.subdivision_matrix import (  # noqa: E402
    dual_matrix,
    exact_dual_matrix,
    exact_remesh_matrix,
    matrix_checks,
    remesh_matrix,
    subdivision_matrix,
)

SCHEMES = list(pentanb.SCHEMES)


# ====================================================================== open meshes
def grid(nx: int = 3, ny: int = 2) -> Mesh:
    """A planar nx x ny patch of unit quads, a little bent (z = x y / 10): four corners."""
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    v = np.stack([xs.ravel(), ys.ravel(), 0.1 * (xs * ys).ravel()], 1)
    faces = [
        [i * (ny + 1) + j, (i + 1) * (ny + 1) + j, (i + 1) * (ny + 1) + j + 1, i * (ny + 1) + j + 1]
        for i in range(nx)
        for j in range(ny)
    ]
    return Mesh(v, faces)


def annulus(n: int = 10, rings: int = 2) -> Mesh:
    """A ring of quads, one triangle fan in it: two boundary loops of n edges."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = np.linspace(0.5, 1.0, rings + 1)
    v = np.concatenate(
        [np.stack([ri * np.cos(t), ri * np.sin(t), ri**2 * 0.2 + 0 * t], 1) for ri in r]
    )
    faces = []
    for k in range(rings):
        for i in range(n):
            a, b = k * n + i, k * n + (i + 1) % n
            c, d = (k + 1) * n + (i + 1) % n, (k + 1) * n + i
            if k == 0 and i < 3:  # some triangles: boundary vertices of several kinds
                faces += [[a, b, c], [a, c, d]]
            else:
                faces.append([a, b, c, d])
    return Mesh(v, faces)


OPEN = {"grid": grid, "annulus": annulus, "open_disk": shapes.open_disk}


def test_the_open_meshes_here_are_open_and_the_grid_has_corners():
    for make in OPEN.values():
        assert not make().is_closed
    assert pentanb.schemes.boundary_corners(grid()).size == 4
    assert annulus().n_boundary_loops == 2


# ====================================================================== the matrix
@pytest.mark.parametrize("mesh_name", list(OPEN))
@pytest.mark.parametrize("scheme", SCHEMES)
def test_matrix_reproduces_the_scheme_on_open_meshes(scheme, mesh_name):
    mesh = OPEN[mesh_name]()
    S, result = subdivision_matrix(mesh, scheme, 1, 2)
    ref = pentanb.subdivide(mesh, scheme, 1, 2)  # the scheme, run
    assert np.array_equal(result.corners, ref.corners)
    assert np.array_equal(result.vertices, ref.vertices)
    assert S.shape == (ref.n_vertices, mesh.n_vertices)
    err = np.abs(S @ mesh.vertices - ref.vertices).max() / np.abs(ref.vertices).max()
    assert err <= 1e-12
    # and on other positions with the same connectivity (no corner made or lost)
    moved = mesh.with_vertices(mesh.vertices * [1.0, 1.3, 0.7] + [0.2, -0.1, 0.4])
    ref2 = pentanb.subdivide(moved, scheme, 1, 2)
    assert np.array_equal(ref2.corners, ref.corners)
    S2, _ = subdivision_matrix(moved, scheme, 1, 2)
    assert np.abs(S2 @ moved.vertices - ref2.vertices).max() <= 1e-12 * np.abs(ref2.vertices).max()


@pytest.mark.parametrize("scheme", SCHEMES)
def test_open_rows_sum_to_one_and_weights_are_convex(scheme):
    mesh = shapes.open_disk()
    S, result = subdivision_matrix(mesh, scheme, 2, 2)
    checks = matrix_checks(S, mesh, result)
    assert checks.affine, checks
    assert checks.convex, checks
    assert checks.reproduces <= 1e-12
    # affine invariance, seen from the positions: translate, and the result translates
    shift = np.array([3.0, -2.0, 5.0])
    assert np.allclose(S @ (mesh.vertices + shift), result.vertices + shift, rtol=0, atol=1e-12)


@pytest.mark.parametrize("duals", [0, 1, 3])
@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons", "corner_cutting"])
def test_open_any_number_of_duals_and_iterations(scheme, duals):
    mesh = grid(3, 3)
    S, _ = subdivision_matrix(mesh, scheme, 2, duals)
    ref = pentanb.subdivide(mesh, scheme, 2, duals)
    assert np.allclose(S @ mesh.vertices, ref.vertices, rtol=0, atol=1e-12)


@pytest.mark.parametrize("scheme", SCHEMES)
def test_open_exact_matrices_round_to_the_float_ones(scheme):
    mesh = grid(2, 2)
    R, out = remesh_matrix(mesh, scheme)
    E = exact_remesh_matrix(mesh, scheme, out)
    assert all(isinstance(x, Fraction) for x in E.data)
    assert np.abs(E.toarray() - R.toarray()).max() <= 1e-15
    assert np.abs(exact_dual_matrix(out).toarray() - dual_matrix(out).toarray()).max() <= 1e-15


def test_the_duals_rows_on_a_grid_written_by_hand():
    # a 2 x 1 grid: vertices 0..5 at (i, j), i = 0..2, j = 0..1 (index 2 i + j);
    # faces (0, 2, 3, 1) and (2, 4, 5, 3); corners: 0, 1, 4, 5 (one face, 90 degrees)
    mesh = grid(2, 1)
    D = dual_matrix(mesh).toarray()
    B = mesh.n_boundary_edges
    assert D.shape == (2 + B + 4, 6)
    q = 1 / 4
    assert np.allclose(D[0], [q, q, q, q, 0, 0]) and np.allclose(D[1], [0, 0, q, q, q, q])
    # the midpoints, one per boundary half-edge in the mesh's order
    tails = mesh.corners[mesh.boundary_halfedges]
    heads = mesh.head[mesh.boundary_halfedges]
    for j, (a, b) in enumerate(zip(tails.tolist(), heads.tolist())):
        expected = np.zeros(6)
        expected[[a, b]] = 0.5
        assert np.allclose(D[2 + j], expected)
    assert np.allclose(D[2 + B :], np.eye(6)[[0, 1, 4, 5]])  # the corners, kept
    assert np.allclose(D @ mesh.vertices, pentanb.dual(mesh).vertices)


def test_a_closed_mesh_still_has_no_boundary_rows():
    cube = shapes.cube()
    assert dual_matrix(cube).shape == (6, 8)
    for scheme, rows in [("corner_cutting", 24), ("honeycomb", 24), ("preserve_hexagons", 32)]:
        R, out = remesh_matrix(cube, scheme)
        assert R.shape == (rows, 8) == (out.n_vertices, 8)


# ====================================================================== the boundary's own rule
from pentanb.analysis import boundary_spectrum, boundary_test_mesh  # noqa: E402

REFINING = ["pentagonalize", "preserve_pentagons", "loop_remesh", "vertex_insertion"]
REFINING += ["corner_cutting", "preserve_hexagons"]


def boundary_vertices(m: Mesh) -> np.ndarray:
    return np.unique(m.corners[m.boundary_halfedges])


@pytest.mark.parametrize("mesh_name", ["annulus", "open_disk", "grid"])
@pytest.mark.parametrize("scheme", SCHEMES)
def test_new_boundary_points_lean_on_old_boundary_points_only(scheme, mesh_name):
    mesh = OPEN[mesh_name]()
    S, out = subdivision_matrix(mesh, scheme, 1, 2)
    old_b = np.zeros(mesh.n_vertices, dtype=bool)
    old_b[boundary_vertices(mesh)] = True
    new_b = boundary_vertices(out)
    assert S[new_b][:, ~old_b].nnz == 0  # the zero block: the boundary decouples
    assert S[new_b][:, old_b].nnz > 0
    inner = np.setdiff1d(np.arange(out.n_vertices), new_b)
    assert S[inner][:, ~old_b].nnz > 0  # (the interior does lean on the interior)


def conv(*masks) -> list[Fraction]:
    out = [Fraction(1)]
    for m in masks:
        out = [
            sum((out[i] * m[k - i] for i in range(len(out)) if 0 <= k - i < len(m)), Fraction(0))
            for k in range(len(out) + len(m) - 1)
        ]
    return out


def upsampled(mask, r: int) -> list[Fraction]:
    """The mask of "refine by r (linear interpolation), then apply ``mask`` at the fine level"."""
    hat = [Fraction(r - abs(k), r) for k in range(-r + 1, r)]
    return conv(hat, mask)


F = Fraction
AVERAGE = [F(1, 2), F(1, 2)]  # one dual: the midpoints of the boundary's edges


def test_reference_masks_written_from_the_rules():
    # pentagonalization trisects every boundary edge; two duals average twice
    assert upsampled(conv(AVERAGE, AVERAGE), 3) == [F(x, 12) for x in (1, 4, 8, 10, 8, 4, 1)]
    # midpoint insertion, then twice averaging: Lane and Riesenfeld's cubic B-spline
    assert upsampled(conv(AVERAGE, AVERAGE), 2) == [F(x, 8) for x in (1, 4, 6, 4, 1)]


@pytest.mark.parametrize(
    "scheme, r, mask, den",
    [
        ("pentagonalize", 3, (1, 4, 8, 10, 8, 4, 1), 12),
        ("preserve_hexagons", 3, (1, 4, 8, 10, 8, 4, 1), 12),
        ("preserve_pentagons", 2, (1, 4, 6, 4, 1), 8),
        ("loop_remesh", 2, (1, 4, 6, 4, 1), 8),
        ("vertex_insertion", 2, (1, 4, 6, 4, 1), 8),
        ("corner_cutting", 2, (1, 5, 10, 10, 5, 1), 16),  # Chaikin, then twice averaging
    ],
)
def test_the_boundary_rule_read_from_the_matrix(scheme, r, mask, den):
    b = boundary_spectrum(scheme, 2)
    assert b.decoupled and b.uniform and b.arity == r
    assert b.mask == tuple(F(x, den) for x in mask)
    assert b.mask_start == -((len(mask) - 1) // 2)  # centred: first + last index is 0 or 1
    # the same rule read on other meshes: the rule is the boundary's, not the mesh's
    for mesh in (annulus(16), boundary_test_mesh(15)):
        assert boundary_spectrum(scheme, 2, mesh=mesh).mask == b.mask


def test_cubic_bspline_boundary_has_the_known_spectrum():
    b = boundary_spectrum("preserve_pentagons", 2)
    # the 5 x 5 local matrix of (1, 4, 6, 4, 1) / 8 around a vertex, by hand:
    # L[i][j] = a[i - 2 j], i, j = -2..2
    a = {-2: 1, -1: 4, 0: 6, 1: 4, 2: 1}
    L = [[F(a.get(i - 2 * j, 0), 8) for j in range(-2, 3)] for i in range(-2, 3)]
    assert b.window == (-2, -1, 0, 1, 2) and b.local_matrix == L
    assert b.centre == "vertex"
    assert np.allclose(np.sort(b.eigenvalues.real)[::-1], [1, 1 / 2, 1 / 4, 1 / 8, 1 / 8])
    assert np.allclose(b.eigenvalues.imag, 0)
    assert b.exact["lambda1"] == F(1, 2) and b.exact["others_below"] is True
    assert np.allclose(b.eigenvector / b.eigenvector[-1], [-1, -1 / 2, 0, 1 / 2, 1])  # linear
    assert b.is_c1 and b.difference_steps == 1
    assert b.eigenvalue_text == "1, 1/2, 1/4, 1/8, 1/8"


def test_pentagonalization_boundary_is_a_c1_ternary_curve():
    b = boundary_spectrum("pentagonalize", 2)
    # the 3 x 3 local matrix of (1, 4, 8, 10, 8, 4, 1) / 12 around a vertex, by hand
    L = [[F(4, 12), F(8, 12), F(0)], [F(1, 12), F(10, 12), F(1, 12)], [F(0), F(8, 12), F(4, 12)]]
    assert b.local_matrix == L and b.centre == "vertex"
    # (1, 1, 1) -> 1; (-1, 0, 1) -> 1/3; the trace 3/2 leaves 1/6
    assert np.allclose(np.sort(b.eigenvalues.real)[::-1], [1, 1 / 3, 1 / 6])
    assert b.exact["lambda1"] == F(1, 3)
    assert np.allclose(b.eigenvector / b.eigenvector[-1], [-1, 0, 1])
    assert b.is_c1 and b.arity == 3


def test_the_c1_verdict_fails_on_piecewise_linear_boundaries():
    # no duals: the boundary is the refined polygon itself, C0 and not C1
    for scheme, r in [("pentagonalize", 3), ("loop_remesh", 2)]:
        b = boundary_spectrum(scheme, 0)
        assert b.arity == r and b.mask == tuple(upsampled([F(1)], r))
        assert not b.is_c1
        assert b.exact["others_below"] is False  # lambda1 = 1/r is double
        assert b.difference_steps is None
    # and Chaikin's corner cutting alone is C1 (quadratic B-spline, around an edge midpoint)
    chaikin = boundary_spectrum("corner_cutting", 0)
    assert chaikin.mask == (F(1, 4), F(3, 4), F(3, 4), F(1, 4))
    assert chaikin.is_c1 and chaikin.centre == "edge midpoint"


@pytest.mark.parametrize("scheme", ["triangulate", "sqrt3_remesh", "honeycomb"])
def test_schemes_that_do_not_refine_the_boundary_say_so(scheme):
    b = boundary_spectrum(scheme, 2)
    assert b.decoupled and b.arity == 1 and b.mask == () and not b.is_c1
    assert "not refined" in b.reason and "not refined" in b.summary()


def test_a_rule_that_does_not_decouple_says_so():
    def smooth_all(m: Mesh) -> Mesh:  # every vertex to the mean of its faces' centroids
        acc = np.zeros_like(m.vertices)
        count = np.zeros(m.n_vertices)
        np.add.at(acc, m.corners, m.face_centroids[m.halfedge_face])
        np.add.at(count, m.corners, 1)
        return m.with_vertices(acc / count[:, None])

    b = boundary_spectrum(smooth_all, 0, mesh=annulus())  # (its middle circle is inside)
    assert not b.decoupled and b.mask == () and not b.is_c1
    assert "does not decouple" in b.reason


def test_boundary_spectrum_refuses_a_closed_mesh():
    with pytest.raises(pentanb.MeshError, match="needs an open mesh"):
        boundary_spectrum("pentagonalize", mesh=shapes.cube())
    with pytest.raises(TypeError, match=r"pentanb\.Mesh"):
        boundary_spectrum("pentagonalize", mesh="cube")


# ====================================================================== pairing the twins
def reference_twins(tail, head) -> np.ndarray:
    """The opposite of every half-edge by a dictionary of directed edges (-1: none)."""
    where = {(int(t), int(h)): i for i, (t, h) in enumerate(zip(tail, head))}
    return np.array([where.get((int(h), int(t)), -1) for t, h in zip(tail, head)])


@pytest.mark.parametrize("mesh_name", list(OPEN))
@pytest.mark.parametrize("n_extra", [0, 2**28])  # a vertex count that splits the keys in parts
def test_pair_open_matches_a_dictionary_of_directed_edges(mesh_name, n_extra):
    from pentanb.mesh.boundary import pair_open

    m = OPEN[mesh_name]()
    tail, head = np.asarray(m.corners), np.asarray(m.head)
    twin = pair_open(tail, head, m.n_vertices + n_extra)
    assert np.array_equal(twin, reference_twins(tail, head))
    assert (twin < 0).sum() == m.n_boundary_edges
    # a directed edge used twice, a half-edge from a vertex to itself: refused
    assert pair_open(np.append(tail, tail[0]), np.append(head, head[0]), m.n_vertices) is None
    assert pair_open(np.append(tail, 0), np.append(head, 0), m.n_vertices) is None


@pytest.mark.parametrize("block", [2, 6])
@pytest.mark.parametrize("n_extra", [0, 2**28])  # a vertex count that splits the keys in parts
@pytest.mark.parametrize("first", [0, 10])  # vertex 0 on the inner rim, or inside
def test_pairing_in_small_blocks_finds_the_boundary_and_every_third_half_edge(
    block, n_extra, first, monkeypatch
):
    # the sorted keys are read block by block: with blocks of a few keys the
    # boundary half-edges and the edges of three half-edges fall at, and
    # across, the blocks' ends (and, vertex 0 inside, after blocks of
    # interior edges only)
    from pentanb.mesh import halfedge
    from pentanb.mesh.boundary import pair_halfedges, pair_open

    monkeypatch.setattr(halfedge, "BLOCK", block)
    m = annulus()
    label = (np.arange(m.n_vertices) - first) % m.n_vertices
    tail, head = label[m.corners], label[m.head]
    n = m.n_vertices + n_extra
    want = reference_twins(tail, head)
    assert np.array_equal(pair_open(tail, head, n), want)
    twin, alone = pair_halfedges(tail, head, n)
    assert np.array_equal(twin, want) and alone.tolist() == np.flatnonzero(want < 0).tolist()
    v = m.n_vertices
    lone = [[], [v, v + 1]]  # an odd number of half-edges, or an even one
    for h in range(tail.size):
        u, w = int(tail[h]), int(head[h])
        for t, hd in ([u], [w]), ([w], [u]), ([u], [u]):
            for extra in lone:
                more_t = np.append(tail, t + extra[:1])
                more_h = np.append(head, hd + extra[1:])
                got = pair_open(more_t, more_h, n + 2)
                if want[h] < 0 and (t, hd) == ([w], [u]):  # the boundary edge's other half
                    assert np.array_equal(got, reference_twins(more_t, more_h))
                else:  # a directed edge twice, three half-edges on one edge, a loop
                    assert got is None, (h, t, hd, extra)


@pytest.mark.parametrize("block", [4, 12])
def test_pairing_quads_in_small_blocks_reads_the_heads_from_the_tails(block, monkeypatch):
    # faces of 4 corners, their heads read from the tails (also where the
    # sorted keys stop falling into pairs after blocks of interior edges)
    from helpers import holed_grid

    from pentanb.mesh import halfedge
    from pentanb.mesh.boundary import pair_halfedges

    monkeypatch.setattr(halfedge, "BLOCK", block)
    v, q = holed_grid(4, 4, [(1, 1, 1)])
    n = len(v)
    inner = int(np.flatnonzero(~Mesh(v, q).is_boundary_vertex)[0])
    quads = (q - inner) % n  # vertex 0 inside: the first edges are interior ones
    tail, head = quads.reshape(-1), quads[:, [1, 2, 3, 0]].reshape(-1)
    want = reference_twins(tail, head)
    twin, alone = pair_halfedges(tail, None, n, 4)
    assert np.array_equal(twin, want) and alone.tolist() == np.flatnonzero(want < 0).tolist()
    for h in range(tail.size):
        u, w = int(tail[h]), int(head[h])
        for quad in [u, w, n, n + 1], [w, u, n, n + 1]:  # a quad on the edge, either way
            got = pair_halfedges(np.append(tail, quad), None, n + 2, 4)
            if want[h] < 0 and quad[0] == w:  # the boundary edge's other half
                more_h = np.append(head, quad[1:] + quad[:1])
                assert got is not None
                assert np.array_equal(got[0], reference_twins(np.append(tail, quad), more_h))
            else:  # a directed edge twice: three half-edges on one edge
                assert got is None, (h, quad)


@pytest.mark.parametrize("n_extra", [0, 2**28])  # a vertex count that splits the keys in parts
def test_pair_twins_of_a_closed_mesh_in_parts_or_whole(n_extra):
    from pentanb.mesh.halfedge import pair_twins

    m = pentanb.subdivide(shapes.cube(), "pentagonalize", 2, 0)  # 5 corners a face
    tail, head = np.asarray(m.corners), np.asarray(m.head)
    expected = reference_twins(tail, head)
    assert np.array_equal(pair_twins(tail, head, m.n_vertices + n_extra), expected)
    assert np.array_equal(pair_twins(tail, None, m.n_vertices + n_extra, 5), expected)
    # a directed edge used twice: no pairing
    assert pair_twins(np.append(tail, tail[:5]), None, m.n_vertices + n_extra, 5) is None
