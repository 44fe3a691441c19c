"""Tests of the test suite's own checking code (:mod:`helpers`).

A checker that cannot fail checks nothing: every helper is shown to
reject what it must reject, on cases worked out by hand.
"""

from __future__ import annotations

import numpy as np
import pytest
from helpers import (
    CORPUS_NAMES,
    check_sealed,
    check_valid,
    corpus,
    cyclic_equal,
    darts,
    expected_counts,
    face_lists,
    handed_out_arrays,
    is_isomorphic,
    kis,
    merge_faces,
    n_components,
    polyhedral,
    prism,
    reflect,
    same_faces_up_to_rotation,
    same_mesh,
    two_cubes,
    vertex_configurations,
)

from pentanb import Mesh, MeshError, pentagonalize, shapes
from pentanb.mesh.build import trusted


def relabelled(m: Mesh, seed: int) -> Mesh:
    """The same mesh with vertices and faces renumbered and faces rotated."""
    rng = np.random.default_rng(seed)
    perm = rng.permutation(m.n_vertices)
    inv = np.argsort(perm)
    faces = [[int(inv[v]) for v in f] for f in face_lists(m)]
    faces = [f[k:] + f[:k] for f, k in zip(faces, rng.integers(0, 3, len(faces)))]
    order = rng.permutation(len(faces))
    return Mesh(m.vertices[perm], [faces[i] for i in order])


def test_corpus_names_cover_shapes_and_extras():
    assert set(shapes.SHAPES) <= set(CORPUS_NAMES)
    assert len(CORPUS_NAMES) == len(set(CORPUS_NAMES))
    assert corpus("cube") is corpus("cube")


def test_corpus_extras_by_hand():
    m = corpus("cube_split")
    assert (m.n_vertices, m.n_edges, m.n_faces) == (10, 15, 7)
    assert m.face_size_histogram() == {3: 1, 4: 3, 5: 3}
    assert m.valence_histogram() == {3: 10}
    p = corpus("hexagonal_prism")
    assert (p.n_vertices, p.n_edges, p.n_faces) == (12, 18, 8)
    assert p.face_size_histogram() == {4: 6, 6: 2}
    y = corpus("pentagonal_pyramid")
    assert y.face_size_histogram() == {3: 5, 5: 1} and y.valence_histogram() == {3: 5, 5: 1}
    assert corpus("small_torus").n_faces == 15
    for name in CORPUS_NAMES:
        assert corpus(name).volume > 0


def test_check_valid_catches_a_wrong_twin():
    c = shapes.cube()
    bad = np.roll(c.twin, 1)
    with pytest.raises(MeshError, match="not its opposite"):  # from_csr checks twins
        Mesh.from_csr(c.vertices, c.corners, c.offsets, twin=bad, validate=False)
    m = trusted(c.vertices.copy(), c.corners.copy(), c.offsets.copy(), twin=bad)  # unchecked
    with pytest.raises(AssertionError):
        check_valid(m)
    check_valid(Mesh.from_csr(c.vertices, c.corners, c.offsets, twin=c.twin.copy(), validate=False))


def test_check_valid_catches_an_invalid_mesh():
    c = shapes.cube()
    corners = c.corners.copy()
    corners[1] = corners[0]  # face 0 uses its first vertex twice
    with pytest.raises(MeshError, match="repeats vertex"):  # from_csr refuses it
        Mesh.from_csr(c.vertices, corners, c.offsets, validate=False)
    m = trusted(c.vertices.copy(), corners, c.offsets.copy())
    with pytest.raises((MeshError, AssertionError)):
        check_valid(m)


class _Leaky(Mesh):
    """A mesh that lets attributes be set (what check_sealed must catch)."""

    __slots__ = ("__dict__",)

    def __setattr__(self, name, value):
        object.__setattr__(self, name, value)


def test_check_sealed_passes_a_mesh_and_catches_a_leaky_one():
    c = shapes.cube()
    check_sealed(c)
    leaky = _Leaky.from_csr(c.vertices, c.corners, c.offsets)
    with pytest.raises(AssertionError, match="could be set or deleted"):
        check_sealed(leaky)


def test_check_sealed_catches_a_writable_array():
    m = shapes.cube().with_vertices(shapes.cube().vertices)
    object.__setattr__(m, "_vertices", np.array(m.vertices))  # a bug: a writable array
    with pytest.raises(AssertionError, match=r"writable arrays handed out: \['vertices'\]"):
        check_sealed(m)


def test_handed_out_arrays_finds_properties_and_argument_free_methods():
    found = handed_out_arrays(shapes.cube())
    for name in ("vertices", "twin", "faces[5]", "vertex_ring[1]", "fan_triangles()[0]", "bounds"):
        assert name in found, name
    assert not any(k.startswith(("face_means", "with_vertices", "from_csr")) for k in found)


def test_same_mesh_sees_every_difference():
    c = shapes.cube()
    same_mesh(c, Mesh(c.vertices, face_lists(c)))
    with pytest.raises(AssertionError):
        same_mesh(c, c.with_vertices(np.nextafter(c.vertices, 2)))  # one ulp
    with pytest.raises(AssertionError):  # the faces started at another corner
        same_mesh(c, Mesh(c.vertices, [f[1:] + f[:1] for f in face_lists(c)]))


def test_darts_by_hand():
    tail, head, nxt, twin = darts([[0, 1, 2], [0, 2, 1]])
    assert tail == [0, 1, 2, 0, 2, 1] and head == [1, 2, 0, 2, 1, 0]
    assert nxt == [1, 2, 0, 4, 5, 3]
    assert twin == [5, 4, 3, 2, 1, 0]
    with pytest.raises(AssertionError):
        darts([[0, 1, 2], [0, 1, 3]])


def test_same_faces_up_to_rotation():
    assert same_faces_up_to_rotation([[1, 2, 3], [4, 5, 6, 7]], [[2, 3, 1], [7, 4, 5, 6]])
    assert not same_faces_up_to_rotation([[1, 2, 3]], [[1, 3, 2]])  # reversed
    assert not same_faces_up_to_rotation([[1, 2, 3], [4, 5, 6]], [[4, 5, 6], [1, 2, 3]])
    assert not same_faces_up_to_rotation([[1, 2, 3]], [[1, 2, 3, 4]])


def test_n_components():
    assert n_components(face_lists(two_cubes())) == 2
    assert n_components(face_lists(shapes.cube())) == 1


@pytest.mark.parametrize("name", ["cube", "dodecahedron", "cube_split", "small_torus"])
def test_isomorphic_to_a_relabelled_copy(name):
    m = corpus(name)
    assert is_isomorphic(m, relabelled(m, 1))
    assert is_isomorphic(relabelled(m, 2), m)


def test_isomorphism_rejects_different_maps_with_equal_counts():
    # 4 x 6 and 3 x 8 quad tori: 24 vertices, 48 edges, 24 quads, all 4-valent,
    # but the shortest loops round the torus have 4 and 3 edges
    a, b = shapes.torus(4, 6), shapes.torus(3, 8)
    assert a.counts() == b.counts()
    assert not is_isomorphic(a, b)
    assert is_isomorphic(shapes.torus(4, 6), shapes.torus(6, 4))
    assert not is_isomorphic(shapes.cube(), shapes.octahedron())


def test_isomorphism_sees_chirality():
    # gyro(cube) (the pentagonal icositetrahedron) is chiral; the cube is not
    p = pentagonalize(shapes.cube())
    assert not is_isomorphic(p, reflect(p))
    assert is_isomorphic(p, reflect(p), reflect=True)
    assert is_isomorphic(shapes.cube(), reflect(shapes.cube()))


def test_prism_4_is_a_cube():
    assert is_isomorphic(prism(4), shapes.cube())


def test_kis_counts():
    for name in ("cube", "tetrahedron", "small_torus"):
        m = corpus(name)
        k = kis(m)
        assert (k.n_vertices, k.n_edges, k.n_faces) == (
            m.n_vertices + m.n_faces,
            3 * m.n_edges,
            2 * m.n_edges,
        )
    # kis(cube) is the tetrakis hexahedron: 6 four-valent and 8 six-valent vertices
    assert kis(shapes.cube()).valence_histogram() == {4: 6, 6: 8}


def test_polyhedral():
    assert polyhedral(face_lists(shapes.cube()), 8)
    assert not polyhedral([[0, 1, 2], [0, 2, 1]], 3)  # 2-valent
    assert not polyhedral(face_lists(shapes.cube()), 9)  # unused vertex


def test_merge_faces_by_hand():
    o = shapes.octahedron()
    m = merge_faces(o, [0])
    # one edge gone: 6 vertices, 11 edges, 7 faces, one of them a quad
    assert (m.n_vertices, m.n_edges, m.n_faces) == (6, 11, 7)
    assert m.face_size_histogram() == {3: 6, 4: 1}
    check_valid(m)
    # merging on the tetrahedron would make 2-valent vertices: skipped
    t = shapes.tetrahedron()
    assert face_lists(merge_faces(t, [0, 1, 2, 3, 4, 5])) == face_lists(t)


def test_vertex_configurations_by_hand():
    assert vertex_configurations(shapes.cube()) == [(4, 4, 4)] * 8
    v = [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0], [0, 0, 1]]
    pyr = Mesh(v, [[3, 2, 1, 0], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
    conf = vertex_configurations(pyr)
    assert conf[4] == (3, 3, 3, 3)
    assert all(cyclic_equal(c, (4, 3, 3)) for c in conf[:4])


def test_cyclic_equal():
    assert cyclic_equal((3, 3, 4, 3, 4), (4, 3, 3, 4, 3))
    assert cyclic_equal((3, 4, 3, 3, 4), (4, 3, 3, 4, 3))
    assert not cyclic_equal((3, 3, 3, 3, 4), (4, 3, 3, 4, 3))
    assert not cyclic_equal((4, 3, 3, 4), (4, 3, 3, 4, 3))
    assert cyclic_equal((1, 2, 3), (3, 2, 1))  # reversed


def test_expected_counts_by_hand():
    c = shapes.cube()
    assert expected_counts("pentagonalize", c) == (38, 60, 24)
    assert expected_counts("honeycomb", c) == (24, 36, 14)
    assert expected_counts("triangulate", c) == (14, 36, 24)
    assert expected_counts("triangulate", shapes.tetrahedron()) == (4, 6, 4)
    assert expected_counts("dual", c) == (6, 12, 8)
