"""Tests of :mod:`pentanb.dual`: the dual and the paper's smoothing (Sections 3, 5).

The dual's documented numbering: vertex f of the dual is face f's centroid,
face v of the dual goes round vertex v counter-clockwise.  Expected values
come from that definition, computed here in plain Python.
"""

from __future__ import annotations

import itertools
from collections import defaultdict

import numpy as np
import pytest
from helpers import (
    check_valid,
    corpus,
    face_lists,
    is_isomorphic,
    same_faces_up_to_rotation,
    vertex_configurations,
)

from pentanb import (
    Mesh,
    MeshError,
    corner_cutting,
    dual,
    pentagonalize,
    preserve_pentagons,
    shapes,
    smooth,
)


def test_dual_is_valid_with_right_twins(corpus_mesh):
    check_valid(dual(corpus_mesh))


def test_dual_swaps_vertices_and_faces(corpus_mesh):
    m = corpus_mesh
    d = dual(m)
    assert (d.n_vertices, d.n_edges, d.n_faces) == (m.n_faces, m.n_edges, m.n_vertices)
    assert d.euler_characteristic == m.euler_characteristic
    assert d.genus == m.genus


def test_dual_maps_face_sizes_to_valences(corpus_mesh):
    m = corpus_mesh
    d = dual(m)
    # face v of the dual goes round vertex v; vertex f of the dual is face f
    assert np.array_equal(d.face_sizes, m.valences)
    assert np.array_equal(d.valences, m.face_sizes)


def test_dual_vertices_are_face_centroids(corpus_mesh):
    m = corpus_mesh
    d = dual(m)
    expected = np.array([m.vertices[f].mean(axis=0) for f in face_lists(m)])
    assert np.allclose(d.vertices, expected, rtol=0, atol=1e-13)


def test_dual_face_v_goes_round_vertex_v(corpus_mesh):
    m = corpus_mesh
    d = dual(m)
    faces = face_lists(m)
    around = defaultdict(set)
    for f, face in enumerate(faces):
        for v in face:
            around[v].add(f)
    # consecutive faces of the dual face share an edge at v
    edge_faces = defaultdict(set)
    for f, face in enumerate(faces):
        for i, v in enumerate(face):
            edge_faces[frozenset((v, face[(i + 1) % len(face)]))].add(f)
    for v, dface in enumerate(face_lists(d)):
        assert set(dface) == around[v]
        for f, g in zip(dface, dface[1:] + dface[:1]):
            shared = [e for e, fs in edge_faces.items() if fs == {f, g}]
            assert any(v in e for e in shared)


def test_dual_keeps_orientation(corpus_mesh):
    assert corpus_mesh.volume > 0
    assert dual(corpus_mesh).volume > 0
    flipped = Mesh(corpus_mesh.vertices, [f[::-1] for f in face_lists(corpus_mesh)])
    assert dual(flipped).volume < 0


def test_dual_dual_has_the_same_faces(corpus_mesh):
    m = corpus_mesh
    dd = dual(dual(m))
    assert np.array_equal(dd.offsets, m.offsets)
    assert same_faces_up_to_rotation(face_lists(dd), face_lists(m))
    check_valid(dd)


def test_dual_of_a_fresh_dual_has_the_same_faces(corpus_mesh):
    # the dual rebuilt from plain arrays (no cached provenance) dualises back to m
    m = corpus_mesh
    d = dual(m)
    fresh = Mesh(d.vertices, face_lists(d))
    dd = dual(fresh)
    assert np.array_equal(dd.offsets, m.offsets)
    assert same_faces_up_to_rotation(face_lists(dd), face_lists(m))
    check_valid(dd)
    assert np.allclose(dd.vertices, dual(d).vertices, rtol=0, atol=1e-13)


def test_dual_dual_moves_vertex_to_mean_of_face_centroids(corpus_mesh):
    # Section 5's smoothing: each vertex goes to the average of the centroids
    # of the faces around it
    m = corpus_mesh
    faces = face_lists(m)
    cent = [m.vertices[f].mean(axis=0) for f in faces]
    around = defaultdict(list)
    for f, face in enumerate(faces):
        for v in face:
            around[v].append(cent[f])
    expected = np.array([np.mean(around[v], axis=0) for v in range(m.n_vertices)])
    assert np.allclose(dual(dual(m)).vertices, expected, rtol=0, atol=1e-12)


def test_dual_of_cube_is_octahedron():
    c = shapes.cube()
    d = dual(c)
    assert is_isomorphic(d, shapes.octahedron())
    # vertices are the face centres: +-1 on the axes, like the octahedron's
    assert sorted(map(tuple, d.vertices.tolist())) == sorted(
        map(tuple, shapes.octahedron().vertices.tolist())
    )


@pytest.mark.parametrize(
    "name, dual_name",
    [
        ("tetrahedron", "tetrahedron"),
        ("cube", "octahedron"),
        ("octahedron", "cube"),
        ("icosahedron", "dodecahedron"),
        ("dodecahedron", "icosahedron"),
    ],
)
def test_duals_of_platonic_solids(name, dual_name):
    assert is_isomorphic(dual(shapes.get(name)), shapes.get(dual_name))


def test_dual_of_torus_grid_is_a_torus_grid():
    # the dual of an r x s grid of quads on the torus is again an r x s grid
    t = shapes.torus(5, 4)
    assert is_isomorphic(dual(t), t)


def test_dual_leaves_input_unchanged(corpus_mesh):
    m = corpus_mesh
    v, c, o = m.vertices.copy(), m.corners.copy(), m.offsets.copy()
    d = dual(m)
    assert d is not m
    assert np.array_equal(m.vertices, v) and np.array_equal(m.corners, c)
    assert np.array_equal(m.offsets, o)


def test_dual_refuses_non_mesh():
    with pytest.raises(TypeError, match=r"dual expects a pentanb\.Mesh"):
        dual([[0, 0, 0]])


def flat_pillow(n: int) -> Mesh:
    """Two n-gons glued along their boundary: every vertex has 2 edges.

    The constructor refuses it; only ``from_csr(validate=False)`` builds it.
    """
    t = 2 * np.pi * np.arange(n) / n
    v = np.stack([np.cos(t), np.sin(t), np.zeros(n)], axis=1)
    poly = np.arange(n)
    return Mesh.from_csr(v, np.concatenate([poly, poly[::-1]]), [0, n, 2 * n], validate=False)


def cube_with_a_vertex_on_an_edge() -> Mesh:
    """The cube with vertex 8 inserted on edge (4, 6): vertex 8 has 2 edges."""
    c = shapes.cube()
    faces = []
    for f in face_lists(c):
        out = []
        for x, y in zip(f, f[1:] + f[:1]):
            out += [x, 8] if {x, y} == {4, 6} else [x]
        faces.append(out)
    v = np.concatenate([c.vertices, [(c.vertices[4] + c.vertices[6]) / 2]])
    corners = np.concatenate(faces)
    offsets = np.cumsum([0] + [len(f) for f in faces])
    return Mesh.from_csr(v, corners, offsets, validate=False)


@pytest.mark.parametrize("n", [3, 5, 6])
def test_dual_refuses_the_flat_pillow(n):
    # its dual would have n faces of 2 sides: refused, with the vertex named
    with pytest.raises(
        MeshError, match=rf"^dual: vertex 0 has only 2 edges \(and {n - 1} more such vertices\)"
    ):
        dual(flat_pillow(n))
    with pytest.raises(MeshError, match=r"^corner_cutting: vertex 0 has only 2 edges"):
        corner_cutting(flat_pillow(n))


def test_dual_names_the_one_2_valent_vertex():
    m = cube_with_a_vertex_on_an_edge()
    with pytest.raises(MeshError, match="vertex 8 has only 2 edges"):
        Mesh(m.vertices, face_lists(m))  # the constructor refuses it too
    with pytest.raises(
        MeshError,
        match=r"^dual: vertex 8 has only 2 edges; its face in the result would have 2 sides",
    ):
        dual(m)
    with pytest.raises(MeshError, match=r"^dual: vertex 8 has only 2 edges"):
        smooth(m, 2)


def test_dual_takes_what_the_check_lets_through():
    # the same construction without the 2-valent vertex is dualised as usual
    c = shapes.cube()
    m = Mesh.from_csr(c.vertices, c.corners, c.offsets, validate=False)
    check_valid(dual(m))
    assert dual(m).face_size_histogram() == {3: 8}


# ====================================================================== smooth
def test_smooth_zero_is_identity():
    m = shapes.cube()
    assert smooth(m, 0) is m


def test_smooth_one_and_two(corpus_mesh):
    m = corpus_mesh
    assert np.array_equal(smooth(m, 1).vertices, dual(m).vertices)
    assert np.array_equal(smooth(m, 1).corners, dual(m).corners)
    s2 = smooth(m)
    assert np.array_equal(s2.vertices, dual(dual(m)).vertices)
    assert np.array_equal(s2.corners, dual(dual(m)).corners)


@pytest.mark.parametrize(
    "bad, error",
    [
        (-1, ValueError),
        (10**5 + 1, ValueError),
        (1.5, TypeError),
        (True, TypeError),
        ("2", TypeError),
        (None, TypeError),
    ],
)
def test_smooth_refuses_bad_counts(bad, error):
    with pytest.raises(error, match=r"^duals must be an integer in \[0, 100,000\], got "):
        smooth(shapes.cube(), bad)


def test_smooth_accepts_numpy_integers():
    m = shapes.cube()
    assert np.array_equal(smooth(m, np.int64(2)).vertices, smooth(m, 2).vertices)


# ====================================================================== the paper's claims
@pytest.mark.parametrize("k", [1, 2, 3])
def test_claim_dual_even_keeps_type(corpus_name, k):
    """Section 5: "Apply dual operation an even number of times": an even
    number of duals keeps the faces and valences (and the connectivity)."""
    m = corpus(corpus_name)
    s = smooth(m, 2 * k)
    assert s.face_size_histogram() == m.face_size_histogram()
    assert s.valence_histogram() == m.valence_histogram()
    assert same_faces_up_to_rotation(face_lists(s), face_lists(m))
    # an odd number swaps them (type (n, m) -> (m, n))
    o = smooth(m, 2 * k - 1)
    assert o.face_size_histogram() == m.valence_histogram()


def test_claim_dual_even_keeps_pentagonal_meshes_pentagonal():
    for m in (
        shapes.dodecahedron(),
        pentagonalize(shapes.cube()),
        preserve_pentagons(shapes.dodecahedron()),
    ):
        for duals in (2, 4):
            assert smooth(m, duals).face_size_histogram() == {5: m.n_faces}


def test_claim_duals_of_pentagonal_meshes_are_5_valent(corpus_name):
    """Section 2: "the duals of our remeshing algorithms create 5-valent meshes"."""
    m = corpus(corpus_name)
    d = dual(pentagonalize(m))
    assert d.valence_histogram() == {5: d.n_vertices}


def test_claim_duals_make_tetrahedron_dodecahedron_rounder():
    """Figure 7: "the resulting shape becomes more and more uniform with each
    application of dual operation".  The dodecahedral shapes B, D, ... (an
    even number of duals) get rounder: the spread of their vertices'
    distances from the centre shrinks at every step; the icosahedral ones
    (odd) get more even edges."""
    b = pentagonalize(shapes.tetrahedron())

    def radius_spread(m):
        r = np.linalg.norm(m.vertices - m.vertices.mean(axis=0), axis=1)
        return r.std() / r.mean()

    def edge_spread(m):
        e = np.linalg.norm(m.vertices[m.edges[:, 0]] - m.vertices[m.edges[:, 1]], axis=1)
        return e.std() / e.mean()

    even = [radius_spread(smooth(b, 2 * k)) for k in range(4)]
    odd = [edge_spread(smooth(b, 2 * k + 1)) for k in range(4)]
    assert all(x > y for x, y in itertools.pairwise(even))
    assert all(x > y for x, y in itertools.pairwise(odd))
    # (B) is dodecahedral: every dual of it alternates icosahedron, dodecahedron
    for k in range(4):
        assert is_isomorphic(smooth(b, 2 * k + 1), shapes.icosahedron())
        assert is_isomorphic(smooth(b, 2 * k), shapes.dodecahedron())


def test_vertex_configuration_helper_agrees_with_dual_face_sizes(small_mesh):
    # around vertex v of dual(m) lie the faces of m's vertices round face v
    d = dual(small_mesh)
    faces = face_lists(small_mesh)
    for v, conf in enumerate(vertex_configurations(d)):
        assert sorted(conf) == sorted(small_mesh.valences[faces[v]].tolist())
