"""Tests of :mod:`pentanb.shapes`: every shape is valid, outward, and has the
counts and geometry its construction implies.

Counts of glued surfaces: a chain of g tori (r x s faces each) loses one
face at each end torus and two in the middle ones (2(g - 1) in all) and
identifies the vertices and edges of the g - 1 glued faces: for quads,
V = g rs - 4(g - 1), E = 2 g rs - 4(g - 1); for hexagons (2rs vertices and
3rs edges per torus) V = 2 g rs - 6(g - 1), E = 3 g rs - 6(g - 1).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from helpers import check_valid, face_lists

from pentanb import MeshError, shapes

PHI = (1 + 5**0.5) / 2


def edge_lengths(m):
    return np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)


@pytest.mark.parametrize("name", list(shapes.SHAPES))
def test_every_shape_is_valid_outward_and_connected(name):
    m = shapes.get(name)
    check_valid(m)
    assert m.volume > 0
    assert m.n_components == 1


@pytest.mark.parametrize(
    "name, counts, faces, valences, genus",
    [
        ("tetrahedron", (4, 6, 4), {3: 4}, {3: 4}, 0),
        ("cube", (8, 12, 6), {4: 6}, {3: 8}, 0),
        ("octahedron", (6, 12, 8), {3: 8}, {4: 6}, 0),
        ("dodecahedron", (20, 30, 12), {5: 12}, {3: 20}, 0),
        ("icosahedron", (12, 30, 20), {3: 20}, {5: 12}, 0),
        ("torus", (96, 192, 96), {4: 96}, {4: 96}, 1),  # 12 x 8
        ("hexagonal_torus", (144, 216, 72), {6: 72}, {3: 144}, 1),  # 12 x 6
        ("double_torus", (96 - 4, 192 - 4, 96 - 2), {4: 94}, {4: 88, 6: 4}, 2),
        ("hexagonal_genus2", (192 - 6, 288 - 6, 96 - 2), {6: 94}, {3: 180, 4: 6}, 2),
        ("genus3", (144 - 8, 288 - 8, 144 - 4), {4: 140}, {4: 128, 6: 8}, 3),
    ],
)
def test_shape_counts_by_hand(name, counts, faces, valences, genus):
    m = shapes.get(name)
    assert (m.n_vertices, m.n_edges, m.n_faces) == counts
    assert m.face_size_histogram() == faces
    assert m.valence_histogram() == valences
    assert m.genus == genus


def test_get_unknown_shape_lists_names():
    with pytest.raises(ValueError, match="unknown shape 'sphere'") as info:
        shapes.get("sphere")
    for name in shapes.SHAPES:
        assert name in str(info.value)


def test_shapes_are_fresh_and_equal_each_call():
    a, b = shapes.get("cube"), shapes.get("cube")
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.corners, b.corners)


# ====================================================================== Platonic solids
def test_tetrahedron_is_regular_and_inscribed_in_the_cube():
    m = shapes.tetrahedron()
    assert np.array_equal(np.abs(m.vertices), np.ones((4, 3)))
    assert np.allclose(edge_lengths(m), 2 * 2**0.5)


def test_cube_vertex_numbering():
    m = shapes.cube()
    for i, p in enumerate(m.vertices.tolist()):
        x, y, z = ((c + 1) // 2 for c in p)
        assert 4 * x + 2 * y + z == i
    assert np.allclose(edge_lengths(m), 2)


def test_octahedron_vertices_on_axes():
    m = shapes.octahedron()
    assert sorted(map(tuple, m.vertices.tolist())) == sorted(
        map(tuple, np.concatenate([np.eye(3), -np.eye(3)]).tolist())
    )
    assert np.allclose(edge_lengths(m), 2**0.5)


def test_icosahedron_vertices_and_edges():
    m = shapes.icosahedron()
    expected = {
        p
        for s1, s2 in itertools.product((-1, 1), repeat=2)
        for p in [(0.0, s1, s2 * PHI), (s2 * PHI, 0.0, s1), (s1, s2 * PHI, 0.0)]
    }
    assert {tuple(np.round(p, 12)) for p in m.vertices.tolist()} == {
        tuple(np.round(p, 12)) for p in expected
    }
    assert np.allclose(edge_lengths(m), 2)


def test_dodecahedron_is_regular():
    m = shapes.dodecahedron()
    assert np.allclose(edge_lengths(m), edge_lengths(m)[0])
    r = np.linalg.norm(m.vertices, axis=1)
    assert np.allclose(r, r[0])
    # planar faces: every corner on its face's plane
    for f, n, c in zip(face_lists(m), m.face_normals, m.face_centroids):
        assert np.allclose((m.vertices[f] - c) @ n, 0, atol=1e-12)


@pytest.mark.parametrize(
    "name", ["tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"]
)
def test_platonic_normals_point_outwards(name):
    m = shapes.get(name)
    assert np.all(np.einsum("ij,ij->i", m.face_normals, m.face_centroids) > 0)


# ====================================================================== tori
@pytest.mark.parametrize("rings, sides", [(3, 3), (3, 5), (4, 7), (12, 8)])
def test_torus_counts_and_surface(rings, sides):
    R, r = 1.0, 0.4
    m = shapes.torus(rings, sides)
    n = rings * sides
    assert (m.n_vertices, m.n_edges, m.n_faces) == (n, 2 * n, n)
    assert m.valence_histogram() == {4: n} and m.genus == 1
    x, y, z = m.vertices.T
    assert np.allclose((np.hypot(x, y) - R) ** 2 + z**2, r**2)
    # face 0 is centred on the outer equator at +x: its corners sit at angles
    # +-pi/rings round the axis and +-pi/sides round the tube
    c = m.face_centroids[0]
    x0 = (R + r * np.cos(np.pi / sides)) * np.cos(np.pi / rings)
    assert np.allclose(c, [x0, 0, 0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("rings, sides", [(3, 3), (5, 4), (12, 6)])
def test_hexagonal_torus_counts_and_surface(rings, sides):
    R, r = 2.0, 0.5
    m = shapes.hexagonal_torus(rings, sides, radius=R, tube=r)
    check_valid(m)
    n = rings * sides
    assert (m.n_vertices, m.n_edges, m.n_faces) == (2 * n, 3 * n, n)
    assert m.face_size_histogram() == {6: n} and m.valence_histogram() == {3: 2 * n}
    x, y, z = m.vertices.T
    assert np.allclose((np.hypot(x, y) - R) ** 2 + z**2, r**2)
    # face 0 surrounds grid point (0, 0) = (R + r, 0, 0)
    d = np.linalg.norm(m.face_centroids - [R + r, 0, 0], axis=1)
    assert np.argmin(d) == 0
    assert m.volume > 0


@pytest.mark.parametrize(
    "kwargs",
    [
        {"rings": 2},
        {"sides": 2},
        {"rings": 4.0},
        {"rings": True},
        {"tube": 1.0},
        {"tube": 0.0},
        {"tube": -0.1},
        {"radius": 0.3},
    ],
)
@pytest.mark.parametrize("builder", [shapes.torus, shapes.hexagonal_torus])
def test_torus_refuses_bad_sizes(builder, kwargs):
    wrong_type = isinstance(next(iter(kwargs.values())), (bool, float)) and (
        "rings" in kwargs or "sides" in kwargs
    )
    with pytest.raises(TypeError if wrong_type else ValueError):
        builder(**kwargs)


# ====================================================================== higher genus
@pytest.mark.parametrize("genus", [1, 2, 3, 4])
@pytest.mark.parametrize("rings, sides", [(8, 6), (6, 4), (4, 3)])
def test_genus_surface_counts(genus, rings, sides):
    m = shapes.genus_surface(genus, rings=rings, sides=sides)
    check_valid(m)
    n, g = rings * sides, genus
    assert (m.n_vertices, m.n_edges, m.n_faces) == (
        g * n - 4 * (g - 1),
        2 * g * n - 4 * (g - 1),
        g * n - 2 * (g - 1),
    )
    assert m.genus == g and m.n_components == 1 and m.volume > 0
    # the glued squares' corners: 4 + 4 - 2 = 6 edges each
    expected = {4: m.n_vertices - 4 * (g - 1)}
    if g > 1:
        expected[6] = 4 * (g - 1)
    assert m.valence_histogram() == expected


@pytest.mark.parametrize("genus", [1, 2, 3])
@pytest.mark.parametrize("rings, sides", [(8, 6), (6, 4)])
def test_hexagonal_surface_counts_and_equation_1(genus, rings, sides):
    m = shapes.hexagonal_surface(genus, rings, sides)
    check_valid(m)
    n, g = rings * sides, genus
    assert (m.n_vertices, m.n_edges, m.n_faces) == (
        2 * g * n - 6 * (g - 1),
        3 * g * n - 6 * (g - 1),
        g * n - 2 * (g - 1),
    )
    assert m.face_size_histogram() == {6: m.n_faces}
    assert m.genus == g and m.volume > 0
    # equation (1) for hexagons: sum(valence - 3) = 6(g - 1)
    assert int(np.sum(m.valences - 3)) == 6 * (g - 1)
    assert set(m.valences.tolist()) <= {3, 4}


def test_genus_surface_1_is_the_torus():
    a, b = shapes.genus_surface(1), shapes.torus(8, 6)
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.corners, b.corners)


def test_double_torus_is_genus_surface_2():
    a, b = shapes.double_torus(), shapes.genus_surface(2)
    assert np.array_equal(a.corners, b.corners)


@pytest.mark.parametrize(
    "genus, error",
    [(0, ValueError), (-1, ValueError), (1.5, TypeError), (True, TypeError), ("2", TypeError)],
)
def test_genus_surface_refuses_bad_genus(genus, error):
    with pytest.raises(error, match="genus must be an integer >= 1"):
        shapes.genus_surface(genus)


@pytest.mark.parametrize("rings, sides", [(6, 4), (10, 6)])
def test_genus_surface_with_a_base_of_another_size(rings, sides):
    # a base torus whose size differs from the rings/sides defaults (8, 6):
    # chained from its own +x and -x faces, or refused with a ValueError
    base = shapes.torus(rings, sides)
    try:
        m = shapes.genus_surface(2, base=base)
    except ValueError:
        return
    check_valid(m)
    n = rings * sides
    assert (m.n_vertices, m.n_faces, m.genus) == (2 * n - 4, 2 * n - 2, 2)
    # the glued square lies on the mirror plane between the two copies, at
    # the largest |x| of the base's vertices on its outer equator
    a = float(np.abs(base.vertices[face_lists(base)[0], 0]).mean())
    assert np.sum(np.isclose(m.vertices[:, 0], a)) == 4


def test_genus_surface_with_odd_rings():
    # the glued faces are found by position (+x-most, -x-most), so any torus works
    m = shapes.genus_surface(2, rings=7, sides=5)
    assert m.genus == 2
    assert m.n_faces == 2 * (7 * 5 - 1)


def test_genus_surface_refuses_a_base_whose_end_faces_touch():
    # a torus of 3 rings: its +x-most and -x-most faces are neighbours
    with pytest.raises(MeshError, match="share a vertex"):
        shapes.genus_surface(2, base=shapes.torus(3, 3))


# ====================================================================== voxels, animal
def test_voxels_single_cell_is_a_unit_cube():
    m = shapes.voxels(np.ones((1, 1, 1)))
    assert (m.n_vertices, m.n_edges, m.n_faces) == (8, 12, 6)
    assert m.volume == pytest.approx(1.0)


def test_voxels_two_cells_in_a_row():
    m = shapes.voxels([[[1]], [[1]]])
    # a 2 x 1 x 1 box: 12 corners, 10 unit squares, 20 edges
    assert (m.n_vertices, m.n_edges, m.n_faces) == (12, 20, 10)
    assert m.volume == pytest.approx(2.0)


def test_voxels_block_3x3x3():
    m = shapes.voxels(np.ones((3, 3, 3), dtype=bool))
    # 6 faces of 9 squares; the 4^3 - 2^3 grid points on the surface
    assert (m.n_vertices, m.n_edges, m.n_faces) == (56, 108, 54)
    assert m.valence_histogram() == {3: 8, 4: 48}
    assert m.volume == pytest.approx(27.0)


def test_voxels_ring_is_a_torus():
    occ = np.ones((3, 3, 1), dtype=bool)
    occ[1, 1, 0] = False
    m = shapes.voxels(occ)
    # 8 top + 8 bottom + 12 outer + 4 inner squares; 2 layers of 4 x 4 points
    assert (m.n_vertices, m.n_edges, m.n_faces) == (32, 64, 32)
    assert m.genus == 1 and m.volume == pytest.approx(8.0)


def test_voxels_touching_along_an_edge_is_refused():
    occ = np.zeros((2, 2, 1), dtype=bool)
    occ[0, 0, 0] = occ[1, 1, 0] = True
    with pytest.raises(MeshError):
        shapes.voxels(occ)


def test_voxels_touching_at_a_corner_is_refused():
    occ = np.zeros((2, 2, 2), dtype=bool)
    occ[0, 0, 0] = occ[1, 1, 1] = True
    with pytest.raises(MeshError, match="non-manifold"):
        shapes.voxels(occ)


@pytest.mark.parametrize("occ", [np.zeros((2, 2, 2)), np.ones((2, 2))])
def test_voxels_refuses_empty_or_flat_input(occ):
    with pytest.raises(MeshError, match="voxels need a 3-D array"):
        shapes.voxels(occ)


def test_animal():
    m = shapes.animal()
    check_valid(m)
    assert m.genus == 0 and m.n_components == 1
    assert m.face_size_histogram() == {4: 178}  # as its docstring says
    assert set(m.valence_histogram()) == {3, 4, 5}
    assert np.abs(m.vertices).max() == pytest.approx(1.0)
    assert m.volume > 0


def test_outward_turns_every_face_outwards():
    # a square pyramid given with its faces in both orientations, mixed sizes
    v = [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0], [0, 0, 1.5]]
    faces = [[0, 1, 2, 3], [0, 4, 1], [1, 2, 4], [2, 4, 3], [3, 0, 4]]
    m = shapes.outward(v, faces)
    assert m.volume == pytest.approx(4 * 1.5 / 3)  # base 4, height 1.5
    centre = m.vertices.mean(axis=0)
    assert np.all(np.einsum("ij,ij->i", m.face_normals, m.face_centroids - centre) > 0)
    # faces already outward are kept as given ([1, 2, 4] on the x = -1 side,
    # [3, 0, 4] on the x = +1 side); the others are reversed (the base seen
    # from below, [0, 4, 1] and [2, 4, 3] whose normals point in y towards the apex)
    assert face_lists(m) == [[3, 2, 1, 0], [1, 4, 0], [1, 2, 4], [3, 4, 2], [3, 0, 4]]


def test_outward_of_a_solid_off_the_origin():
    # the centroid, not the origin, is the inside: the same cube moved far away
    cube = shapes.cube()
    moved = shapes.outward(cube.vertices + 10.0, [f[::-1] for f in cube.faces])
    assert moved.volume == pytest.approx(8.0)
    assert face_lists(moved) == face_lists(cube)


def test_outward_refuses_faces_that_are_not_a_closed_surface():
    v = [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0], [0, 0, 1.5]]
    with pytest.raises(MeshError):
        shapes.outward(v, [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])  # no base


def test_hard_edged_cube_inset():
    # the default keeps the edges sharp (thin outer rows); inset 1/3 is an even grid
    coords = np.unique(shapes.hard_edged_cube().vertices)
    assert coords.tolist() == [-1.0, -0.8, 0.8, 1.0]
    even = np.unique(shapes.hard_edged_cube(1 / 3).vertices)
    assert np.allclose(np.diff(even), 2 / 3)


# ====================================================================== boxes and the rabbit
@pytest.mark.parametrize("cells", [1, 2, 3, 6])
def test_box_counts_and_grid(cells):
    m = shapes.box(cells)
    check_valid(m)
    n = cells
    assert (m.n_vertices, m.n_faces) == (6 * n * n + 2, 6 * n * n)
    assert m.face_size_histogram() == {4: 6 * n * n}
    assert np.allclose(np.unique(m.vertices), np.linspace(-1, 1, n + 1))
    assert m.volume == pytest.approx(8.0)
    # a 3-box is the hard-edged cube with inset 1/3
    if n == 3:
        assert np.allclose(
            np.sort(m.vertices, axis=0), np.sort(shapes.hard_edged_cube(1 / 3).vertices, axis=0)
        )


@pytest.mark.parametrize(
    "bad, error",
    [(0, ValueError), (-2, ValueError), (2.0, TypeError), (True, TypeError), ("3", TypeError)],
)
def test_box_refuses_bad_sizes(bad, error):
    with pytest.raises(error, match="cells must be an integer >= 1"):
        shapes.box(bad)


def test_rabbit_is_an_irregular_low_polygon_model():
    # issue 8: closed, genus 0, a few hundred faces at most, triangles and
    # quadrilaterals at least, valences from 3 to 7 or more
    m = shapes.rabbit()
    check_valid(m)
    assert m.genus == 0 and m.n_components == 1 and m.volume > 0
    assert (m.n_vertices, m.n_edges, m.n_faces) == (172, 401, 231)
    assert m.face_size_histogram() == {3: 136, 4: 81, 5: 14}
    assert min(m.valence_histogram()) == 3 and max(m.valence_histogram()) == 7
    assert shapes.get("rabbit").n_faces == 231


def test_rabbit_is_star_shaped_around_its_centre():
    # every face seen from the centre the builder pushed the directions out from
    from pentanb.data.make_rabbit import CENTRE

    m = shapes.rabbit()
    c = m.face_centroids - CENTRE
    assert np.all(np.einsum("ij,ij->i", m.face_normals, c) > 0)


def test_shipped_rabbit_is_what_the_builder_writes(tmp_path):
    pytest.importorskip("scipy")
    from importlib import resources

    from pentanb.data import make_rabbit

    out = tmp_path / "rabbit.obj"
    assert make_rabbit.main([str(out)]) == 0
    shipped = resources.files("pentanb.data").joinpath("rabbit.obj").read_text()
    assert out.read_text() == shipped
