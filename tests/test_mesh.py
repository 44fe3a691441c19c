"""Tests of :mod:`pentanb.mesh`: construction, validation messages, derived arrays.

Expected values are hand computations on tiny meshes (the cube [-1, 1]^3 of
:func:`pentanb.shapes.cube`, whose vertex ``4x + 2y + z`` sits at (x, y, z)
with x, y, z in {-1, 1} written as bits) or Euler's formula.
"""

from __future__ import annotations

import copy
import functools
import operator
import pickle
import re

import numpy as np
import pytest
from helpers import (
    OPERATORS,
    check_sealed,
    check_valid,
    corpus,
    face_lists,
    faces_sharing_two_edges,
    same_mesh,
    two_cubes,
)

from pentanb import Mesh, MeshError, dual, pentagonalize, shapes, subdivide
from pentanb.mesh import fan_triangle_corners

CUBE_FACES = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]


def cube_vertices() -> np.ndarray:
    # vertex 4x + 2y + z at (x, y, z), bits mapped 0 -> -1, 1 -> +1
    return np.array(
        [[2 * ((i >> 2) & 1) - 1, 2 * ((i >> 1) & 1) - 1, 2 * (i & 1) - 1] for i in range(8)],
        dtype=float,
    )


def tetra_faces(a, b, c, d):
    """The four faces of an outward tetrahedron whose vertices a, b, c, d sit
    like the origin, x, y and z of ``TETRA``."""
    return [[a, c, b], [a, b, d], [b, c, d], [a, d, c]]


TETRA = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)


# ====================================================================== construction
def test_cube_from_ragged_list():
    m = Mesh(cube_vertices(), CUBE_FACES)
    assert [f.tolist() for f in m.faces] == CUBE_FACES
    assert m.offsets.tolist() == [0, 4, 8, 12, 16, 20, 24]
    assert m.corners.tolist() == functools.reduce(operator.iadd, CUBE_FACES, [])


def test_faces_as_int_array_and_as_list_agree():
    a = Mesh(cube_vertices(), np.array(CUBE_FACES, dtype=np.int32))
    b = Mesh(cube_vertices().tolist(), CUBE_FACES)
    assert np.array_equal(a.corners, b.corners)
    assert np.array_equal(a.offsets, b.offsets)
    # index arrays are int32 whenever the counts fit (see test_index_dtype_*)
    assert a.corners.dtype == b.corners.dtype == np.int32
    assert a.offsets.dtype == b.offsets.dtype == np.int32
    assert np.array_equal(a.vertices, b.vertices)


def test_faces_as_float_array_of_whole_numbers_are_accepted():
    m = Mesh(cube_vertices(), np.array(CUBE_FACES, dtype=float))
    assert m.corners.tolist() == functools.reduce(operator.iadd, CUBE_FACES, [])


def test_non_integer_face_indices_are_refused():
    with pytest.raises(MeshError, match="integers"):
        Mesh(cube_vertices(), np.array(CUBE_FACES, dtype=float) + 0.5)
    faces = [list(f) for f in CUBE_FACES]
    faces[2] = [0, 4.5, 5, 1]
    with pytest.raises(MeshError, match=r"face 2 has non-integer vertex indices"):
        Mesh(cube_vertices(), faces)


def test_mixed_face_sizes_in_one_list():
    # a square pyramid: one quad and four triangles
    v = [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0], [0, 0, 1]]
    faces = [[3, 2, 1, 0], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    m = Mesh(v, faces)
    assert m.face_sizes.tolist() == [4, 3, 3, 3, 3]
    assert m.offsets.tolist() == [0, 4, 7, 10, 13, 16]
    assert m.valences.tolist() == [3, 3, 3, 3, 4]
    assert (m.n_vertices, m.n_edges, m.n_faces) == (5, 8, 5)


def test_mesh_error_is_a_value_error():
    assert issubclass(MeshError, ValueError)


# ====================================================================== validation messages
def test_error_index_out_of_range_names_face_and_index():
    faces = [list(f) for f in CUBE_FACES]
    faces[3] = [2, 3, 8, 6]
    with pytest.raises(
        MeshError,
        match=r"face 3 uses vertex index 8, out of range for 8 "
        r"vertices",
    ):
        Mesh(cube_vertices(), faces)


def test_error_negative_index_names_face_and_index():
    faces = [list(f) for f in CUBE_FACES]
    faces[1] = [4, 6, -1, 5]
    with pytest.raises(MeshError, match=r"face 1 uses vertex index -1"):
        Mesh(cube_vertices(), faces)


def test_error_face_with_fewer_than_3_vertices():
    with pytest.raises(MeshError, match=r"face 4 has 2 vertices \[0, 1\]"):
        Mesh(TETRA, tetra_faces(0, 1, 2, 3) + [[0, 1]])


def test_error_face_with_repeated_vertex():
    faces = [list(f) for f in CUBE_FACES]
    faces[5] = [1, 5, 5, 3]
    with pytest.raises(
        MeshError,
        match=r"face 5 \[1, 5, 5, 3\] repeats vertex 5 "
        r"\(3 distinct vertices\)",
    ):
        Mesh(cube_vertices(), faces)


def test_error_flipped_face_names_the_directed_edge_and_both_faces():
    faces = [list(f) for f in CUBE_FACES]
    faces[2] = faces[2][::-1]  # [1, 5, 4, 0]: every edge now runs like its neighbour's
    with pytest.raises(
        MeshError,
        match=r"directed edge \((\d+), (\d+)\) is used by faces "
        r"\[(\d+), (\d+)\]: inconsistent orientation",
    ) as info:
        Mesh(cube_vertices(), faces)
    u, w, f, g = map(
        int, re.search(r"\((\d+), (\d+)\).*\[(\d+), (\d+)\]", str(info.value)).groups()
    )
    assert 2 in (f, g)
    for k in (f, g):
        fk = faces[k]
        assert any(fk[i] == u and fk[(i + 1) % 4] == w for i in range(4))


def test_error_three_faces_on_one_edge():
    # three triangles hinge on edge {0, 1}: two of them run 0 -> 1
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    with pytest.raises(
        MeshError,
        match=r"directed edge \(0, 1\) is used by faces \[0, 2\]: "
        r".*non-manifold edge",
    ):
        Mesh(v, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])


def test_error_two_tetrahedra_sharing_an_edge():
    # closed, consistently oriented pieces, but edge {0, 1} has four faces
    v = np.concatenate([TETRA, [[0, -1, 0], [0, 0, -1]]])
    faces = tetra_faces(0, 1, 2, 3) + tetra_faces(0, 1, 4, 5)
    with pytest.raises(MeshError, match=r"directed edge \((0, 1|1, 0)\) is used by faces"):
        Mesh(v, faces)


def test_a_cube_without_a_face_is_an_open_box_with_one_loop():
    faces = [list(f) for f in CUBE_FACES]
    removed = faces.pop(5)  # [1, 5, 7, 3]
    m = Mesh(cube_vertices(), faces)
    assert not m.is_closed and m.n_boundary_loops == 1 and m.n_edges == 12
    (loop,) = m.boundary_loops
    # the loop runs opposite to the removed face's edges, each inside a kept face
    tail, head = m.corners[loop], m.head[loop]
    for u, w in zip(tail.tolist(), head.tolist()):
        assert any(removed[i] == w and removed[(i + 1) % 4] == u for i in range(4))
    assert sorted(tail.tolist()) == sorted(removed)


def test_error_vertex_with_two_fans():
    # two tetrahedra touching at vertex 3 = (0, 0, 1) only: the second is
    # the first moved up by 1, its vertex 0 landing on vertex 3
    v = np.concatenate([TETRA, TETRA[1:] + [0, 0, 1]])
    faces = tetra_faces(0, 1, 2, 3) + tetra_faces(3, 4, 5, 6)
    with pytest.raises(
        MeshError,
        match=r"vertex 3 is non-manifold: its faces form more than "
        r"one fan",
    ):
        Mesh(v, faces)


def test_error_unused_vertex_names_it_and_counts():
    v = np.concatenate([cube_vertices(), [[0, 0, 0], [5, 5, 5]]])
    with pytest.raises(
        MeshError,
        match=r"vertex 8 is not used by any face "
        r"\(2 unused vertices\)",
    ):
        Mesh(v, CUBE_FACES)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_error_non_finite_coordinate(bad):
    v = cube_vertices()
    v[3, 1] = bad
    with pytest.raises(MeshError, match=r"vertex 3 has a non-finite coordinate"):
        Mesh(v, CUBE_FACES)


@pytest.mark.parametrize("shape", [(8, 2), (8, 4), (24,), (2, 4, 3)])
def test_error_wrong_vertex_shape(shape):
    v = np.zeros(shape)
    with pytest.raises(
        MeshError,
        match=r"vertices must be an \(n, 3\) array, got shape "
        + repr(shape).replace("(", r"\(").replace(")", r"\)"),
    ):
        Mesh(v, CUBE_FACES)


def test_error_vertices_not_numbers():
    v = cube_vertices().tolist()
    v[0] = ["a", 0, 0]
    with pytest.raises(MeshError, match="vertices must be an"):
        Mesh(v, CUBE_FACES)


def test_error_no_faces():
    with pytest.raises(MeshError, match="no faces"):
        Mesh(cube_vertices(), [])


def test_error_faces_array_of_wrong_rank():
    with pytest.raises(MeshError, match="faces must be"):
        Mesh(cube_vertices(), np.zeros((2, 2, 3), dtype=int))


def test_valid_meshes_raise_nothing():
    Mesh(TETRA, tetra_faces(0, 1, 2, 3))
    Mesh(cube_vertices(), CUBE_FACES)
    two_cubes()


# ====================================================================== from_csr, with_vertices
def test_from_csr_validates_by_default():
    faces = [list(f) for f in CUBE_FACES]
    faces[2] = faces[2][::-1]
    c = np.array(functools.reduce(operator.iadd, faces, []))
    o = np.arange(0, 25, 4)
    with pytest.raises(MeshError, match="inconsistent orientation"):
        Mesh.from_csr(cube_vertices(), c, o)


@pytest.mark.parametrize("offsets", [[1, 4, 8], [0, 4, 9], [0, 5, 4, 8]])
def test_from_csr_refuses_bad_offsets(offsets):
    with pytest.raises(MeshError, match="offsets must start at 0"):
        Mesh.from_csr(cube_vertices(), np.arange(8) % 8, offsets)


def test_from_csr_equals_constructor():
    m = Mesh.from_csr(
        cube_vertices(), functools.reduce(operator.iadd, CUBE_FACES, []), np.arange(0, 25, 4)
    )
    n = Mesh(cube_vertices(), CUBE_FACES)
    assert np.array_equal(m.corners, n.corners) and np.array_equal(m.twin, n.twin)


def test_from_csr_copies_its_inputs():
    # a mesh is immutable: it must not alias (nor freeze) the caller's arrays
    base = np.array(functools.reduce(operator.iadd, CUBE_FACES, []), dtype=np.int64)
    offsets = np.arange(0, 25, 4, dtype=np.int64)
    view = base[:]
    m = Mesh.from_csr(cube_vertices(), view, offsets)
    assert base.flags.writeable and offsets.flags.writeable
    before = m.corners.copy()
    base[:] = 0
    offsets[:] = 0
    assert np.array_equal(m.corners, before)
    assert m.offsets.tolist() == [0, 4, 8, 12, 16, 20, 24]


def test_with_vertices_keeps_faces_and_leaves_original():
    m = shapes.cube()
    m2 = m.with_vertices(m.vertices * 2)
    assert np.array_equal(m2.corners, m.corners)
    assert np.array_equal(m2.twin, m.twin)
    assert np.array_equal(m2.vertices, 2 * m.vertices)
    assert np.array_equal(m.vertices, cube_vertices())
    assert m2.volume == pytest.approx(64.0)


def test_with_vertices_refuses_wrong_shape_and_nan():
    m = shapes.cube()
    with pytest.raises(MeshError, match=r"expected \(8, 3\) vertices, got \(7, 3\)"):
        m.with_vertices(np.zeros((7, 3)))
    v = m.vertices.copy()
    v[2, 0] = np.nan
    with pytest.raises(MeshError, match="vertex 2 has a non-finite"):
        m.with_vertices(v)


# ====================================================================== immutability
def test_arrays_are_read_only():
    m = Mesh(cube_vertices(), CUBE_FACES)
    for arr in (
        m.vertices,
        m.corners,
        m.offsets,
        m.twin,
        m.next,
        m.prev,
        m.head,
        m.face_sizes,
        m.valences,
        m.halfedge_edge,
        m.edges,
        m.face_centroids,
    ):
        with pytest.raises(ValueError):
            arr[0] = 1


def test_derived_arrays_are_read_only():
    # the mesh caches what it derives; nothing it hands out may be written to,
    # or the cache (and every later result) would be corrupted
    meshes = []
    for m0 in (shapes.cube(), corpus("cube_split"), shapes.torus(3, 4)):
        meshes += [m0, dual(m0), dual(dual(m0)), pentagonalize(m0)]
    for m in meshes:
        ring, ring_off = m.vertex_ring
        arrays = {
            "vertices": m.vertices,
            "corners": m.corners,
            "offsets": m.offsets,
            "twin": m.twin,
            "next": m.next,
            "prev": m.prev,
            "head": m.head,
            "rotation": m.rotation,
            "halfedge_face": m.halfedge_face,
            "halfedge_edge": m.halfedge_edge,
            "edge_halfedge": m.edge_halfedge,
            "edges": m.edges,
            "face_sizes": m.face_sizes,
            "valences": m.valences,
            "face_centroids": m.face_centroids,
            "face_normals": m.face_normals,
            "component_labels": m.component_labels,
            "face 0": m.faces[0],
            "vertex_ring": ring,
            "vertex_ring offsets": ring_off,
        }
        writable = [name for name, a in arrays.items() if a.flags.writeable]
        assert writable == [], repr(m)


def test_writing_to_a_vertex_ring_cannot_corrupt_the_mesh():
    m = shapes.cube()
    ring, _ = m.vertex_ring
    try:
        ring[:] = 0
    except ValueError:
        pass
    assert np.array_equal(np.sort(m.vertex_ring[0]), np.arange(24))
    check_valid(dual(m))


def test_constructor_copies_its_inputs():
    v = cube_vertices()
    f = np.array(CUBE_FACES)
    m = Mesh(v, f)
    v[:] = 0
    f[:] = 0
    assert np.array_equal(m.vertices, cube_vertices())
    assert m.corners.tolist() == functools.reduce(operator.iadd, CUBE_FACES, [])


# ====================================================================== counts
def test_cube_counts_by_hand():
    m = Mesh(cube_vertices(), CUBE_FACES)
    assert (m.n_vertices, m.n_edges, m.n_faces, m.n_halfedges) == (8, 12, 6, 24)
    assert m.valences.tolist() == [3] * 8
    assert m.face_sizes.tolist() == [4] * 6
    assert m.euler_characteristic == 2
    assert m.genus == 0 and m.n_components == 1
    assert m.face_size_histogram() == {4: 6}
    assert m.valence_histogram() == {3: 8}
    assert m.counts() == {
        "V": 8,
        "E": 12,
        "F": 6,
        "faces": {4: 6},
        "valences": {3: 8},
        "chi": 2,
        "genus": 0,
    }
    assert repr(m) == "Mesh(V=8, E=12, F=6, faces={4:6})"


def test_cube_edges_are_the_one_bit_pairs():
    m = Mesh(cube_vertices(), CUBE_FACES)
    # cube edges join vertices differing in one coordinate, i.e. one bit of 4x+2y+z
    expected = sorted((a, a | b) for a in range(8) for b in (1, 2, 4) if not a & b)
    assert sorted(map(tuple, m.edges.tolist())) == expected
    assert m.edges.shape == (12, 2)


def test_torus_genus_1():
    m = shapes.torus(5, 4)
    # a 5 x 4 grid of quads: V = 20, E = 40, F = 20
    assert (m.n_vertices, m.n_edges, m.n_faces) == (20, 40, 20)
    assert m.euler_characteristic == 0 and m.genus == 1


def test_double_torus_genus_2():
    assert shapes.double_torus().genus == 2
    assert shapes.double_torus().euler_characteristic == -2


def test_genus_surface_3():
    m = shapes.genus_surface(3)
    assert m.genus == 3 and m.euler_characteristic == -4 and m.n_components == 1


def test_hexagonal_genus_2_surface_equation_1():
    m = shapes.hexagonal_surface(2)
    assert m.face_size_histogram() == {6: m.n_faces}
    # all hexagons: 2E = 6F and V - E + F = 2 - 2g give sum(valence - 3) = 6(g - 1)
    assert int(np.sum(m.valences - 3)) == 6
    assert m.valence_histogram() == {3: m.n_vertices - 6, 4: 6}
    assert m.genus == 2


def test_two_disjoint_cubes():
    m = two_cubes()
    assert m.n_components == 2
    assert m.euler_characteristic == 4
    assert m.genus == 0
    # labels are each component's smallest vertex index
    assert m.component_labels.tolist() == [0] * 8 + [8] * 8
    assert m.component_labels_of_faces().tolist() == [0] * 6 + [8] * 6
    assert m.volume == pytest.approx(16.0)


def test_cube_with_torus_components_and_genus():
    c, t = shapes.cube(), shapes.torus(3, 3)
    v = np.concatenate([c.vertices, t.vertices + [10.0, 0, 0]])
    m = Mesh(v, face_lists(c) + [[i + 8 for i in f] for f in face_lists(t)])
    # chi = 2 + 0, two components: genus = (2 * 2 - 2) / 2 = 1
    assert m.n_components == 2 and m.genus == 1


# ====================================================================== half-edges
def test_next_prev_head_by_hand():
    m = Mesh(cube_vertices(), CUBE_FACES)
    # face 0 = corners 0..3 = [0, 1, 3, 2]
    assert m.next[:4].tolist() == [1, 2, 3, 0]
    assert m.prev[:4].tolist() == [3, 0, 1, 2]
    assert m.head[:4].tolist() == [1, 3, 2, 0]
    assert m.tail[:4].tolist() == [0, 1, 3, 2]
    assert m.halfedge_face.tolist() == [f for f in range(6) for _ in range(4)]


def test_next_and_prev_are_inverse(corpus_mesh):
    m = corpus_mesh
    H = np.arange(m.n_halfedges)
    assert np.array_equal(m.next[m.prev], H)
    assert np.array_equal(m.prev[m.next], H)
    assert np.array_equal(m.halfedge_face[m.next], m.halfedge_face)
    assert np.array_equal(m.head, m.corners[m.next])


def test_twin_is_an_involution_reversing_edges(corpus_mesh):
    m = corpus_mesh
    H = np.arange(m.n_halfedges)
    t = m.twin
    assert np.array_equal(t[t], H)
    assert not np.any(t == H)
    assert np.array_equal(m.tail[t], m.head)
    assert np.array_equal(m.head[t], m.tail)


def test_edges_unique_and_halfedge_edge_consistent(corpus_mesh):
    m = corpus_mesh
    E = m.n_edges
    edges = m.edges
    assert edges.shape == (E, 2)
    assert np.all(edges[:, 0] < edges[:, 1])
    assert len({tuple(e) for e in edges.tolist()}) == E
    he = m.halfedge_edge
    assert np.array_equal(he[m.twin], he)  # twins share their edge
    assert np.bincount(he, minlength=E).tolist() == [2] * E  # each edge twice
    lo = np.minimum(m.tail, m.head)
    hi = np.maximum(m.tail, m.head)
    assert np.array_equal(edges[he], np.stack([lo, hi], axis=1))
    eh = m.edge_halfedge
    assert np.array_equal(he[eh], np.arange(E))
    assert np.all(m.tail[eh] < m.head[eh])


def test_rotation_orbits_have_valence_length(corpus_mesh):
    m = corpus_mesh
    rot = m.rotation
    assert np.array_equal(m.tail[rot], m.tail)
    # walk every orbit in plain Python
    seen = np.zeros(m.n_halfedges, dtype=bool)
    for h in range(m.n_halfedges):
        if seen[h]:
            continue
        length, x = 0, h
        while True:
            seen[x] = True
            length += 1
            x = int(rot[x])
            if x == h:
                break
        assert length == m.valences[m.tail[h]]


def test_vertex_ring_is_csr_of_rotation_orbits(corpus_mesh):
    m = corpus_mesh
    ring, off = m.vertex_ring
    assert off[0] == 0 and off[-1] == m.n_halfedges
    assert np.array_equal(np.diff(off), m.valences)
    assert np.array_equal(np.sort(ring), np.arange(m.n_halfedges))
    for v in range(m.n_vertices):
        r = ring[off[v] : off[v + 1]]
        assert np.all(m.tail[r] == v)
        assert np.array_equal(m.rotation[r], np.roll(r, -1))


@pytest.mark.parametrize(
    "name", ["tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"]
)
def test_rotation_is_counter_clockwise_seen_from_outside(name):
    # convex solids centred at the origin: consecutive outgoing edges turn
    # counter-clockwise about the outward direction (the vertex position)
    m = shapes.get(name)
    ring, off = m.vertex_ring
    for v in range(m.n_vertices):
        r = ring[off[v] : off[v + 1]]
        d = m.vertices[m.head[r]] - m.vertices[v]
        turn = np.cross(d, np.roll(d, -1, axis=0)) @ m.vertices[v]
        assert np.all(turn > 0)


@pytest.mark.parametrize("k", [3, 4, 5, 8])
@pytest.mark.parametrize("faces", [1, 2, 1000])
def test_a_value_per_corner_moved_round_its_face_is_the_next_or_previous_corners(k, faces):
    from pentanb.mesh.halfedge import shifted

    a = np.random.default_rng(k).permutation(k * faces).astype(np.int32)
    forward = [a[f * k + (i + 1) % k] for f in range(faces) for i in range(k)]
    back = [a[f * k + (i - 1) % k] for f in range(faces) for i in range(k)]
    assert shifted(a, k, 1).tolist() == forward
    assert shifted(a, k, -1).tolist() == back


# ====================================================================== geometry
def test_cube_face_centroids_and_normals():
    m = Mesh(cube_vertices(), CUBE_FACES)
    # face [4, 6, 7, 5] is the face x = 1, and so on
    expected = [[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]]
    assert np.array_equal(m.face_centroids, np.array(expected, dtype=float))
    assert np.allclose(m.face_normals, expected)


def test_degenerate_face_normal_is_zero():
    v = np.zeros((4, 3))
    m = Mesh(v, tetra_faces(0, 1, 2, 3))
    assert np.array_equal(m.face_normals, np.zeros((4, 3)))
    assert m.volume == 0.0


@pytest.mark.parametrize(
    "name, volume",
    [
        ("cube", 8.0),
        ("tetrahedron", 8.0 - 4 * (8.0 / 6.0)),  # cube minus 4 corner tetrahedra
        ("octahedron", 4.0 / 3.0),  # 2 pyramids of base 2, height 1
        ("icosahedron", 5.0 / 12.0 * (3 + 5**0.5) * 8),  # edge length 2
    ],
)
def test_volume_of_platonic_solids(name, volume):
    assert shapes.get(name).volume == pytest.approx(volume, rel=1e-12)


def test_volume_is_signed_and_translation_invariant():
    m = shapes.cube()
    assert m.with_vertices(m.vertices + [3.0, -7.0, 11.0]).volume == pytest.approx(8.0)
    flipped = Mesh(m.vertices, [f[::-1] for f in face_lists(m)])
    assert flipped.volume == pytest.approx(-8.0)


def test_bounds():
    m = shapes.cube()
    assert m.bounds.tolist() == [[-1, -1, -1], [1, 1, 1]]


def test_fan_triangles_of_cube_cover_faces_and_volume():
    m = Mesh(cube_vertices(), CUBE_FACES)
    tris, tf = m.fan_triangles()
    # 24 corners - 2 * 6 faces = 12 triangles, 2 per quad: (0,1,2), (0,2,3)
    assert tris.shape == (12, 3)
    assert tf.tolist() == [0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5]
    assert tris[:2].tolist() == [[0, 1, 3], [0, 3, 2]]
    p = m.vertices[tris]
    vol = np.einsum("ij,ij->", p[:, 0], np.cross(p[:, 1], p[:, 2])) / 6
    assert vol == pytest.approx(8.0)


def test_fan_triangles_count_and_cover(corpus_mesh):
    m = corpus_mesh
    tris, tf = m.fan_triangles()
    assert tris.shape == (m.n_halfedges - 2 * m.n_faces, 3)
    assert np.array_equal(np.bincount(tf, minlength=m.n_faces), m.face_sizes - 2)
    faces = face_lists(m)
    covered = [set() for _ in faces]
    for t, f in zip(tris.tolist(), tf.tolist()):
        assert t[0] == faces[f][0]
        assert set(t) <= set(faces[f])
        covered[f] |= set(t)
    assert all(c == set(f) for c, f in zip(covered, faces))


def test_faces_property_round_trips(corpus_mesh):
    m = corpus_mesh
    again = Mesh(m.vertices, m.faces)
    assert np.array_equal(again.corners, m.corners)
    assert np.array_equal(again.offsets, m.offsets)


# ---------------------------------------------------------------- meshes the dual cannot take
def test_two_valent_vertex_is_refused():
    # the "dihedron": two triangles glued along their whole boundary
    with pytest.raises(
        MeshError,
        match=r"vertex 0 has only 2 edges; every vertex needs "
        r"at least 3",
    ):
        Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 1]])


def test_faces_sharing_two_edges_are_refused():
    vertices, faces = faces_sharing_two_edges()
    with pytest.raises(
        MeshError,
        match=r"faces 0 and 7 share more than one edge "
        r"\(\(2, 5\) and \(0, 3\)\)",
    ):
        Mesh(vertices, faces)


def test_face_means_of_scalar_and_vector_values():
    c = shapes.cube()
    # the mean of each face's vertex indices, computed by hand from the faces
    by_hand = [sum(f) / len(f) for f in face_lists(c)]
    assert np.allclose(c.face_means(np.arange(8.0)), by_hand)
    assert np.allclose(c.face_means(c.vertices), c.face_centroids)
    # a mesh of quads and pentagons (the reduceat path), against a per-face loop
    from pentanb import preserve_pentagons

    p = preserve_pentagons(c)
    by_hand = [p.vertices[f, 0].mean() for f in face_lists(p)]
    assert np.allclose(p.face_means(p.vertices[:, 0]), by_hand)


def test_from_csr_without_validation_leaves_the_callers_arrays_writable():
    c = shapes.cube()
    v = c.vertices.copy()
    corners = c.corners.copy()
    offsets = c.offsets.copy()
    m = Mesh.from_csr(v, corners, offsets, validate=False)
    assert v.flags.writeable and corners.flags.writeable and offsets.flags.writeable
    assert not m.vertices.flags.writeable and not m.corners.flags.writeable
    assert m.counts() == c.counts()


def test_fan_triangle_corners_by_hand():
    # a triangle, a pentagon, a quad: corners 0-2, 3-7, 8-11
    tris, tf = fan_triangle_corners([0, 3, 8, 12])
    assert tris.tolist() == [[0, 1, 2], [3, 4, 5], [3, 5, 6], [3, 6, 7], [8, 9, 10], [8, 10, 11]]
    assert tf.tolist() == [0, 1, 1, 1, 2, 2]


def test_fan_triangles_are_the_corner_fan_of_the_corners(corpus_mesh):
    m = corpus_mesh
    tris, tf = fan_triangle_corners(m.offsets)
    assert np.array_equal(m.corners[tris], m.fan_triangles()[0])
    assert np.array_equal(tf, m.fan_triangles()[1])


def test_halfedge_slot_by_hand():
    m = corpus("cube_split")  # sizes 5, 4, 5, 5, 4, 3 and 4 in some order
    sizes = m.face_sizes.tolist()
    assert m.halfedge_slot.tolist() == [j for k in sizes for j in range(k)]
    h = np.arange(m.n_halfedges)
    assert np.array_equal(m.offsets[m.halfedge_face] + m.halfedge_slot, h)


# ====================================================================== sealed
def meshes_of_every_origin() -> dict[str, Mesh]:
    """A mesh made by every path that makes one (each built fresh: nothing derived yet)."""
    c = shapes.cube()
    m = Mesh(c.vertices, face_lists(c))
    return {
        "constructor": m,
        "from_csr": Mesh.from_csr(c.vertices, c.corners, c.offsets),
        "from_csr unvalidated": Mesh.from_csr(c.vertices, c.corners, c.offsets, validate=False),
        "with_vertices": m.with_vertices(2 * c.vertices),
        **{name: op(m) for name, op in OPERATORS.items()},
        "dual of dual": dual(dual(m)),
        "dual of dual of pentagonalize": dual(dual(pentagonalize(m))),
        "subdivide": subdivide(m, "preserve_pentagons", 2, 1),
        "unpickled": pickle.loads(pickle.dumps(pentagonalize(m))),
        "deepcopy": copy.deepcopy(dual(m)),
        "copy": copy.copy(dual(m)),
    }


ORIGINS = list(meshes_of_every_origin())


@pytest.mark.parametrize("origin", ORIGINS)
def test_a_mesh_of_every_origin_is_sealed(origin):
    m = meshes_of_every_origin()[origin]
    check_sealed(m)  # nothing settable or deletable, every array read-only
    check_valid(m)


@pytest.mark.parametrize("name", ["_vertices", "_corners", "twin", "vertices", "foo", "__dict__"])
def test_setting_or_deleting_says_meshes_are_immutable(name):
    m = shapes.cube()
    before = m.vertices.copy()
    with pytest.raises(
        AttributeError,
        match=rf"cannot set '{name}': a Mesh is immutable \(use mesh\.with_vertices",
    ):
        setattr(m, name, np.zeros((8, 3)))
    with pytest.raises(AttributeError, match=rf"cannot delete '{name}': a Mesh is immutable"):
        delattr(m, name)
    assert np.array_equal(m.vertices, before)


def test_a_mesh_has_no_instance_dict_to_write_into():
    for m in meshes_of_every_origin().values():
        with pytest.raises(AttributeError):
            m.__dict__  # noqa: B018
        with pytest.raises(TypeError):
            vars(m)


def test_a_mesh_is_initialised_once():
    m = shapes.cube()
    with pytest.raises(AttributeError, match="initialised once"):
        m._init(np.zeros((8, 3)), m.corners, m.offsets)
    with pytest.raises(AttributeError, match="initialised once"):
        m.__init__(np.zeros((8, 3)), face_lists(m))
    assert np.array_equal(m.vertices, cube_vertices())


@pytest.mark.parametrize("validate", [True, False])
def test_from_csr_never_aliases_the_callers_arrays(validate):
    c = shapes.cube()
    v, corners, offsets, twin = (np.array(a) for a in (c.vertices, c.corners, c.offsets, c.twin))
    m = Mesh.from_csr(v, corners, offsets, twin=twin, validate=validate)
    for mine, theirs in ((m.vertices, v), (m.corners, corners), (m.offsets, offsets)):
        assert not np.shares_memory(mine, theirs)
    assert not np.shares_memory(m.twin, twin)
    assert all(a.flags.writeable for a in (v, corners, offsets, twin))
    v[:] = 0
    corners[:] = 0
    offsets[:] = 0
    twin[:] = 0
    same_mesh(m, c)


def test_with_vertices_copies_the_positions_and_shares_what_faces_give():
    m = shapes.cube()
    twin, ring = m.twin, m.vertex_ring
    v = 2 * m.vertices
    m2 = m.with_vertices(v)
    assert not np.shares_memory(m2.vertices, v)
    v[:] = 0
    assert np.array_equal(m2.vertices, 2 * m.vertices)
    # derived from the faces alone: derived once, the very same arrays
    assert m2.twin is twin and m2.vertex_ring is ring
    # derived from the positions: the mesh's own
    assert np.allclose(m2.face_centroids, 2 * m.face_centroids)


# ====================================================================== pickling and copying
@pytest.mark.parametrize("origin", ORIGINS)
@pytest.mark.parametrize("how", ["pickle 2", "pickle highest", "deepcopy", "copy"])
def test_pickle_and_copies_give_an_equal_sealed_mesh(origin, how):
    m = meshes_of_every_origin()[origin]  # fresh: its derived arrays may still be lazy
    if how.startswith("pickle"):
        protocol = 2 if how == "pickle 2" else pickle.HIGHEST_PROTOCOL
        back = pickle.loads(pickle.dumps(m, protocol=protocol))
    else:
        back = (copy.deepcopy if how == "deepcopy" else copy.copy)(m)
    assert type(back) is Mesh and back is not m
    same_mesh(back, m)
    check_sealed(back)
    check_valid(back)
    if how != "copy":
        assert not np.shares_memory(back.vertices, m.vertices)


def test_pickling_a_lazy_output_keeps_its_twins_and_rings_and_drops_its_input():
    big = shapes.torus(24, 16)
    p = pentagonalize(big)  # twins and rings not written yet: producers holding `big`
    data = pickle.dumps(p, protocol=pickle.HIGHEST_PROTOCOL)
    H, V, F = p.n_halfedges, p.n_vertices, p.n_faces
    # positions, faces, twins, rings, and nothing of the input mesh
    assert len(data) < 24 * V + 8 * (H + F + 1) + 8 * H + 8 * (H + V + 1) + 2000
    back = pickle.loads(data)
    same_mesh(back, p)
    assert np.array_equal(back.twin, Mesh(p.vertices, face_lists(p)).twin)


def test_an_unpickled_mesh_operates_like_the_original(corpus_mesh):
    m = corpus_mesh
    for op in (pentagonalize, dual):
        out = op(m)
        back = pickle.loads(pickle.dumps(out))
        same_mesh(dual(back), dual(out))
        same_mesh(pentagonalize(back), pentagonalize(out))


def test_dual_chains_survive_pickling(corpus_mesh):
    chain = [corpus_mesh]
    for _ in range(4):
        chain.append(dual(chain[-1]))
    for k, x in enumerate(chain):
        back = pickle.loads(pickle.dumps(x))
        same_mesh(back, x)
        # the dual of a dual built after loading is the one built before
        same_mesh(dual(back), chain[k + 1] if k + 1 < len(chain) else dual(x))
        same_mesh(dual(dual(back)), dual(dual(x)))
        check_valid(dual(back))


# ====================================================================== the one initialiser
def test_every_new_mesh_goes_through_Mesh_init(monkeypatch):
    calls = []
    original = Mesh._init

    def counting(self, vertices, corners, offsets, **kwargs):
        calls.append(len(offsets) - 1)
        return original(self, vertices, corners, offsets, **kwargs)

    monkeypatch.setattr(Mesh, "_init", counting)
    c = shapes.cube()
    made = {
        "constructor": lambda: Mesh(c.vertices, face_lists(c)),
        "from_csr": lambda: Mesh.from_csr(c.vertices, c.corners, c.offsets),
        "from_csr unvalidated": lambda: Mesh.from_csr(
            c.vertices, c.corners, c.offsets, validate=False
        ),
        "with_vertices": lambda: c.with_vertices(c.vertices),
        "pickle": lambda: pickle.loads(pickle.dumps(c)),
        "deepcopy": lambda: copy.deepcopy(c),
        **{name: (lambda op=op: op(c)) for name, op in OPERATORS.items()},
    }
    for name, make in made.items():
        calls.clear()
        out = make()
        assert calls == [out.n_faces], name
    d = dual(c)
    calls.clear()
    assert dual(d).n_faces == 6 and calls == [6]  # the dual of a dual too
    calls.clear()
    subdivide(c, "pentagonalize", 2, 2)
    assert calls == [24, 38, 24, 120, 182, 120]


def test_a_wrapper_on_Mesh_init_can_refuse_large_meshes(monkeypatch):
    # how the notebook tests cap every mesh, whatever builds it
    original = Mesh._init

    def capped(self, vertices, corners, offsets, **kwargs):
        if len(offsets) - 1 > 100:
            raise MeshError(f"{len(offsets) - 1} faces: over the cap")
        return original(self, vertices, corners, offsets, **kwargs)

    big = shapes.torus(12, 10)  # 120 faces, built before the cap
    small = pentagonalize(shapes.cube())  # 24 faces
    data = pickle.dumps(big)
    monkeypatch.setattr(Mesh, "_init", capped)
    for attempt in (
        lambda: subdivide(shapes.cube(), "pentagonalize", 2),
        lambda: dual(dual(small)),  # 38, then 24 faces: allowed
        lambda: pickle.loads(data),
        lambda: big.with_vertices(big.vertices),
        lambda: copy.deepcopy(big),
        lambda: Mesh(big.vertices, face_lists(big)),
    ):
        try:
            out = attempt()
        except MeshError as exc:
            assert "over the cap" in str(exc)
        else:
            assert out.n_faces <= 100
    with pytest.raises(MeshError, match="120 faces: over the cap"):
        big.with_vertices(big.vertices)


def test_a_producer_may_write_two_connectivity_arrays_in_one_pass():
    # an operator's rings producer may hand back the face of every ring
    # entry too (the dual's corners): both are cached from the one call
    from pentanb.mesh import Several as _Several

    m = shapes.cube()
    ring, off = m.vertex_ring
    faces = m.halfedge_face[ring]
    calls = []

    def rings():
        calls.append(1)
        return _Several(vertex_ring=(ring.copy(), off.copy()), _ring_faces=faces.copy())

    out = Mesh._new(m.vertices.copy(), m.corners.copy(), m.offsets.copy(), rings=rings)
    assert np.array_equal(out.vertex_ring[0], ring) and calls == [1]
    given = out._shared.values["_ring_faces"]
    assert not given.flags.writeable
    d = dual(out)  # takes them as its corners: not kept by `out` as well
    assert d.corners is given and "_ring_faces" not in out._shared.values
    assert np.array_equal(d.corners, dual(m).corners) and calls == [1]
    assert np.array_equal(dual(out).corners, faces)  # again: derived from the rings
    # a plain producer: the faces are derived from the rings
    plain = Mesh._new(m.vertices.copy(), m.corners.copy(), m.offsets.copy(), rings=(ring, off))
    assert np.array_equal(plain._ring_faces(), faces)
    assert np.array_equal(m._ring_faces(), faces)
