"""Tests of :mod:`pentanb.schemes.pentagonal`: the paper's two schemes (Section 5).

Counts come from the schemes' steps: pentagonalization cuts every edge in
three and puts a centre in every face (V + 2E + F vertices); every n-gon
becomes n pentagons (2E faces, 5 sides each: 5E edges).  Pentagon
preservation adds a midpoint per edge and a copy vertex per half-edge
(V + 3E), keeps one n-gon per n-gon and adds a pentagon per half-edge
(F + 2E faces, (5 * 2E + 2E) / 2 = 6E edges).
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest
from helpers import (
    check_valid,
    corpus,
    cyclic_equal,
    darts,
    face_lists,
    is_isomorphic,
    valences,
    vertex_configurations,
)

from pentanb import Mesh, dual, pentagonalize, preserve_pentagons, shapes, smooth, subdivide

THIRD = 1.0 / 3.0


# ====================================================================== pentagonalize
def test_pentagonalize_counts_and_faces(corpus_mesh):
    m = corpus_mesh
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    p = pentagonalize(m)
    check_valid(p)
    assert (p.n_vertices, p.n_edges, p.n_faces) == (V + 2 * E + F, 5 * E, 2 * E)
    assert p.face_size_histogram() == {5: 2 * E}
    assert p.euler_characteristic == m.euler_characteristic
    assert p.volume > 0


def test_pentagonalize_numbering_and_placement(corpus_mesh):
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    p = pentagonalize(m)
    assert np.array_equal(p.vertices[:V], m.vertices)  # old vertices stay
    for e, (a, b) in enumerate(m.edges.tolist()):  # a < b
        pa, pb = m.vertices[a], m.vertices[b]
        assert np.allclose(p.vertices[V + 2 * e], pa + (pb - pa) / 3, rtol=0, atol=1e-14)
        assert np.allclose(p.vertices[V + 2 * e + 1], pa + 2 * (pb - pa) / 3, rtol=0, atol=1e-14)
    for f, face in enumerate(face_lists(m)):
        assert np.allclose(
            p.vertices[V + 2 * E + f], m.vertices[face].mean(axis=0), rtol=0, atol=1e-14
        )


def test_pentagonalize_face_of_each_halfedge(corpus_mesh):
    # docstring: the pentagon of h = (u, w) in face f is (t1, t2, w, t1', c_f)
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    faces = face_lists(m)
    tail, head, nxt, _ = darts(faces)
    edge_id = {tuple(e): k for k, e in enumerate(m.edges.tolist())}
    face_of = [f for f, face in enumerate(faces) for _ in face]

    def point(u, w, j):  # j-th trisection point from u towards w
        e = edge_id[(min(u, w), max(u, w))]
        return V + 2 * e + (j if u < w else 1 - j)

    expected = [
        [point(u, w, 0), point(u, w, 1), w, point(w, head[nxt[h]], 0), V + 2 * E + face_of[h]]
        for h, (u, w) in enumerate(zip(tail, head))
    ]
    assert face_lists(pentagonalize(m)) == expected


def test_pentagonalize_valences(corpus_mesh):
    # old vertices keep their valence, trisection points are 3-valent,
    # the centre of an n-gon is n-valent
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    val = valences(pentagonalize(m))
    assert val[:V] == valences(m)
    assert val[V : V + 2 * E] == [3] * (2 * E)
    assert val[V + 2 * E :] == [len(f) for f in face_lists(m)]


def test_pentagonalize_cube_by_hand():
    c = shapes.cube()
    p = pentagonalize(c)
    V, E = 8, 12
    # trisection points: one coordinate +-1/3, the two others +-1 (24 of them)
    pts = p.vertices[V : V + 2 * E]
    assert sorted(map(tuple, np.round(pts * 3).astype(int).tolist())) == sorted(
        t for axis in range(3) for t in _signs(axis)
    )
    assert np.allclose(pts * 3, np.round(pts * 3), rtol=0, atol=1e-14)
    # edge 0 is (0, 1): from (-1, -1, -1) to (-1, -1, 1)
    assert c.edges[0].tolist() == [0, 1]
    assert np.allclose(p.vertices[8], [-1, -1, -THIRD]) and np.allclose(
        p.vertices[9], [-1, -1, THIRD]
    )
    # centres: face 1 = [4, 6, 7, 5] is the face x = 1
    assert p.vertices[V + 2 * E + 1].tolist() == [1.0, 0.0, 0.0]
    assert p.vertices[V + 2 * E :].tolist() == [
        [-1, 0, 0],
        [1, 0, 0],
        [0, -1, 0],
        [0, 1, 0],
        [0, 0, -1],
        [0, 0, 1],
    ]
    # every new point lies in a face plane: the volume stays 8
    assert p.volume == pytest.approx(8.0, rel=1e-12)


def _signs(axis):
    out = []
    for a in (-3, 3):
        for b in (-3, 3):
            for t in (-1, 1):
                v = [a, b]
                v.insert(axis, t)
                out.append(tuple(v))
    return out


def test_pentagonalize_leaves_input_unchanged(corpus_mesh):
    m = corpus_mesh
    v, c = m.vertices.copy(), m.corners.copy()
    p = pentagonalize(m)
    assert p is not m
    assert np.array_equal(m.vertices, v) and np.array_equal(m.corners, c)


def test_pentagonalize_refuses_non_mesh():
    with pytest.raises(TypeError, match=r"pentagonalize expects a pentanb\.Mesh"):
        pentagonalize(np.zeros((4, 3)))


# ====================================================================== preserve_pentagons
@pytest.mark.parametrize("scale", [0.75, 0.5, 0.2])
def test_preserve_pentagons_counts_and_faces(corpus_mesh, scale):
    m = corpus_mesh
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    q = preserve_pentagons(m, scale)
    check_valid(q)
    assert (q.n_vertices, q.n_edges, q.n_faces) == (V + 3 * E, 6 * E, F + 2 * E)
    hist = Counter(len(f) for f in face_lists(m))
    hist[5] += 2 * E
    assert q.face_size_histogram() == dict(sorted(hist.items()))
    assert q.euler_characteristic == m.euler_characteristic
    assert q.volume > 0


def test_preserve_pentagons_numbering_and_placement(corpus_mesh):
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    s = 0.6
    q = preserve_pentagons(m, scale=s)
    assert np.array_equal(q.vertices[:V], m.vertices)
    for e, (a, b) in enumerate(m.edges.tolist()):
        assert np.allclose(
            q.vertices[V + e], (m.vertices[a] + m.vertices[b]) / 2, rtol=0, atol=1e-14
        )
    faces = face_lists(m)
    _tail, _head, _nxt, _ = darts(faces)
    h = 0
    for face in faces:
        mids = [
            (m.vertices[face[i]] + m.vertices[face[(i + 1) % len(face)]]) / 2
            for i in range(len(face))
        ]
        c = np.mean(mids, axis=0)
        for mid in mids:
            assert np.allclose(q.vertices[V + E + h], c + s * (mid - c), rtol=0, atol=1e-13)
            h += 1


def test_preserve_pentagons_faces(corpus_mesh):
    # inner copies first (same sizes, same order), then (m_h, w, m_next, q_next, q_h)
    m = corpus_mesh
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    faces = face_lists(m)
    tail, head, nxt, _ = darts(faces)
    edge_id = {tuple(e): k for k, e in enumerate(m.edges.tolist())}
    mid = [V + edge_id[(min(u, w), max(u, w))] for u, w in zip(tail, head)]
    out = face_lists(preserve_pentagons(m))
    h = 0
    for f, face in enumerate(faces):
        assert out[f] == [V + E + h + i for i in range(len(face))]
        h += len(face)
    assert out[F:] == [
        [mid[h], head[h], mid[nxt[h]], V + E + nxt[h], V + E + h] for h in range(len(tail))
    ]


def test_preserve_pentagons_valences(corpus_mesh):
    # old vertices keep their valence, midpoints 4, copy vertices 3
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    val = valences(preserve_pentagons(m))
    assert val[:V] == valences(m)
    assert val[V : V + E] == [4] * E
    assert val[V + E :] == [3] * (2 * E)


@pytest.mark.parametrize("scale, r", [(0.5, 0.5), (0.75, 0.75)])
def test_preserve_pentagons_cube_face_x1(scale, r):
    # face 1 = [4, 6, 7, 5] is x = 1; its edge midpoints (1, +-1, 0), (1, 0, +-1)
    # have mean (1, 0, 0): the copy sits at (1, +-r, 0), (1, 0, +-r)
    q = preserve_pentagons(shapes.cube(), scale=scale)
    copy = q.vertices[face_lists(q)[1]]
    expected = {(1.0, r, 0.0), (1.0, -r, 0.0), (1.0, 0.0, r), (1.0, 0.0, -r)}
    assert {tuple(p) for p in np.round(copy, 12).tolist()} == expected
    # the copy's first corner is the copy of the first half-edge (4, 6), whose
    # midpoint is (1, 0, -1)
    assert np.allclose(copy[0], [1, 0, -r])
    assert q.volume == pytest.approx(8.0, rel=1e-12)


def test_preserve_pentagons_default_scale_is_three_quarters():
    m = shapes.cube()
    assert np.array_equal(preserve_pentagons(m).vertices, preserve_pentagons(m, 0.75).vertices)


@pytest.mark.parametrize("scale", [0, 1, -0.5, 1.5, float("nan"), float("inf"), "big", None])
def test_preserve_pentagons_refuses_bad_scale(scale):
    with pytest.raises(ValueError, match="scale must be"):
        preserve_pentagons(shapes.cube(), scale)


def test_preserve_pentagons_leaves_input_unchanged(corpus_mesh):
    m = corpus_mesh
    v, c = m.vertices.copy(), m.corners.copy()
    q = preserve_pentagons(m)
    assert q is not m
    assert np.array_equal(m.vertices, v) and np.array_equal(m.corners, c)


def test_preserve_pentagons_refuses_non_mesh():
    with pytest.raises(TypeError, match=r"preserve_pentagons expects a pentanb\.Mesh"):
        preserve_pentagons("cube")


# ====================================================================== Conway
def test_pentagonalize_is_gyro_by_counts():
    # gyro(cube) = pentagonal icositetrahedron: 38 vertices, 60 edges, 24 pentagons,
    # 6 four-valent and 32 three-valent vertices
    p = pentagonalize(shapes.cube())
    assert (p.n_vertices, p.n_edges, p.n_faces) == (38, 60, 24)
    assert p.valence_histogram() == {3: 32, 4: 6}
    # gyro(dodecahedron) = pentagonal hexecontahedron: 92, 150, 60; 12 five-valent
    p = pentagonalize(shapes.dodecahedron())
    assert (p.n_vertices, p.n_edges, p.n_faces) == (92, 150, 60)
    assert p.valence_histogram() == {3: 80, 5: 12}


@pytest.mark.parametrize(
    "a, b",
    [("cube", "octahedron"), ("dodecahedron", "icosahedron"), ("tetrahedron", "tetrahedron")],
)
def test_pentagonalize_of_dual_pairs_agree(a, b):
    # gyro(X) and gyro(dual X) are the same polyhedron (up to mirror image)
    pa, pb = pentagonalize(shapes.get(a)), pentagonalize(shapes.get(b))
    assert is_isomorphic(pa, pb) or is_isomorphic(pa, pb, reflect=True)


def test_preserve_pentagons_half_is_quinto_by_counts():
    # quinto: V + 3E, 6E, F + 2E; on the dodecahedron 20 + 90, 180, 12 + 60
    q = preserve_pentagons(shapes.dodecahedron(), scale=0.5)
    assert (q.n_vertices, q.n_edges, q.n_faces) == (110, 180, 72)
    assert q.face_size_histogram() == {5: 72}
    assert q.valence_histogram() == {3: 20 + 60, 4: 30}


# ====================================================================== the paper's claims
def test_claim_tetrahedron_pentagonalized_is_dodecahedron():
    """Section 4 and Figure 7: pentagonalization converts the tetrahedron into
    the dodecahedron (V = 4 + 2*6 + 4 = 20, 12 pentagons, all 3-valent)."""
    p = pentagonalize(shapes.tetrahedron())
    assert (p.n_vertices, p.n_edges, p.n_faces) == (20, 30, 12)
    assert p.face_size_histogram() == {5: 12}
    assert p.valence_histogram() == {3: 20}
    assert is_isomorphic(p, shapes.dodecahedron())
    # Figure 7C: its dual is icosahedral, 7D: the dual of that dodecahedral again
    assert is_isomorphic(dual(p), shapes.icosahedron())
    assert is_isomorphic(dual(dual(p)), shapes.dodecahedron())
    # the tetrahedron's faces become 3 pentagons each, its edges 30 edges
    assert p.n_edges == 5 * 6


def test_claim_pentagonalization_gives_only_pentagons_for_any_mesh(corpus_mesh):
    """Section 5.1: "we will have only pentagons in the new mesh", whatever the input."""
    p = pentagonalize(corpus_mesh)
    assert set(p.face_sizes.tolist()) == {5}
    assert set(smooth(p, 2).face_sizes.tolist()) == {5}
    assert set(pentagonalize(p).face_sizes.tolist()) == {5}


def test_claim_each_ngon_becomes_n_pentagons(corpus_mesh):
    """Section 5.1: "Each face in the original mesh would now have been split
    into as many pentagons as the number of edges in the original face"."""
    m = corpus_mesh
    V, E = m.n_vertices, m.n_edges
    p = pentagonalize(m)
    per_face = Counter()
    for face in face_lists(p):
        centres = [x - V - 2 * E for x in face if x >= V + 2 * E]
        assert len(centres) == 1 and len(face) == 5
        per_face[centres[0]] += 1
    assert [per_face[f] for f in range(m.n_faces)] == [len(f) for f in face_lists(m)]


def test_claim_each_ngon_becomes_ngon_plus_n_pentagons(corpus_mesh):
    """Section 5.2: each face is "split into as many pentagons as the number of
    edges in the original face plus one central face with the same number of
    sides"."""
    m = corpus_mesh
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    q = preserve_pentagons(m)
    sizes = [len(f) for f in face_lists(m)]
    owner = [f for f, n in enumerate(sizes) for _ in range(n)]  # copy vertex -> face
    central, pentagons = Counter(), Counter()
    for face in face_lists(q):
        mine = {owner[x - V - E] for x in face if x >= V + E}
        assert len(mine) == 1  # every face lies in one old face
        f = mine.pop()
        if all(x >= V + E for x in face):
            central[f] += 1
            assert len(face) == sizes[f]
        else:
            pentagons[f] += 1
            assert len(face) == 5
    assert [central[f] for f in range(F)] == [1] * F
    assert [pentagons[f] for f in range(F)] == sizes


@pytest.mark.parametrize(
    "name", ["dodecahedron", "cube", "cube_split", "torus", "hexagonal_genus2"]
)
def test_claim_preservation_keeps_pentagonal_meshes_pentagonal(name):
    """Section 5.2 and Figure 1D: "If we start with a pentagonal mesh, the new
    mesh will contain only pentagons"."""
    m = corpus(name)
    start = m if name == "dodecahedron" else pentagonalize(m)  # Figure 1B
    mesh = start
    for _ in range(3):
        mesh = preserve_pentagons(mesh)
        assert set(mesh.face_sizes.tolist()) == {5}
    assert set(subdivide(start, "preserve_pentagons", 2).face_sizes.tolist()) == {5}


def test_claim_preservation_number_of_non_pentagons_constant(corpus_mesh):
    """Sections 1 and 5.2: "the number of non-pentagonal faces remains constant
    after the first refinement" (with or without the duals)."""
    m = corpus_mesh
    before = sum(1 for f in face_lists(m) if len(f) != 5)
    mesh = m
    for _ in range(3):
        mesh = preserve_pentagons(mesh)
        assert int(np.sum(mesh.face_sizes != 5)) == before
    for k in (1, 2):
        s = subdivide(m, "preserve_pentagons", k, duals=2)
        assert int(np.sum(s.face_sizes != 5)) == before


def test_claim_cube_pentagonalization_4_3_3_4_3():
    """Figure 8: pentagonalization of a cube (one iteration, two duals) makes
    the semi-regular pattern 4.3.3.4.3, and its dual the tiling 4.3.3.4.3.

    The pattern belongs to (4, 4) regular regions.  The pentagon of half-edge
    (u, w) in an n-gon has vertices (t1, t2, w, t1', c) of valences
    (3, 3, val(w), 3, n): with n = 4 and a 4-valent w that is 3.3.4.3.4, a
    rotation of 4.3.3.4.3 (the Cairo pentagon, dual of the snub square
    tiling).  The bare cube has only 3-valent corners, so all its 24
    pentagons are 3.3.3.3.4; the paper's cube (Figure 1A) has grids on its
    faces: here a 3 x 3 x 3 block of voxels, whose 8 corners are 3-valent
    and whose 48 other vertices are 4-valent.  Half-edges ending at a
    4-valent vertex: 48 * 4 = 192 pentagons 4.3.3.4.3; at a corner: 8 * 3 =
    24 pentagons 3.3.3.3.4.  In the dual (Figure 8B) a pentagon is a vertex
    and the sizes of its faces are those valences.
    """
    block = shapes.voxels(np.ones((3, 3, 3), dtype=bool))
    assert block.valence_histogram() == {3: 8, 4: 48}
    fig8a = smooth(pentagonalize(block), 2)
    val = valences(fig8a)
    faces = [[val[v] for v in f] for f in face_lists(fig8a)]
    assert sum(cyclic_equal(f, (4, 3, 3, 4, 3)) for f in faces) == 192
    assert sum(cyclic_equal(f, (3, 3, 3, 3, 4)) for f in faces) == 24
    fig8b = dual(fig8a)
    configs = vertex_configurations(fig8b)
    assert sum(cyclic_equal(c, (4, 3, 3, 4, 3)) for c in configs) == 192
    assert sum(cyclic_equal(c, (3, 3, 3, 3, 4)) for c in configs) == 24
    # the bare cube: no (4, 4) region, every vertex of the dual is 3.3.3.3.4
    bare = dual(smooth(pentagonalize(shapes.cube()), 2))
    assert all(cyclic_equal(c, (3, 3, 3, 3, 4)) for c in vertex_configurations(bare))
    # a regular (4, 4) mesh, the quad torus: 4.3.3.4.3 everywhere
    tor = dual(pentagonalize(shapes.torus(6, 5)))
    assert all(cyclic_equal(c, (4, 3, 3, 4, 3)) for c in vertex_configurations(tor))


def test_claim_hex_torus_pentagonalization_6_3_3_3_3():
    """Figure 9: pentagonalization of the hexagonal torus of Figure 4A makes
    6.3.3.3.3 everywhere: every pentagon has vertices of valences
    (3, 3, 3, 3, 6) (its centre is a hexagon's), so every vertex of the dual
    has faces 6, 3, 3, 3, 3 around it."""
    h = shapes.hexagonal_torus()
    fig9a = smooth(pentagonalize(h), 2)
    val = valences(fig9a)
    assert all(cyclic_equal([val[v] for v in f], (6, 3, 3, 3, 3)) for f in face_lists(fig9a))
    configs = vertex_configurations(dual(fig9a))
    assert len(configs) == 2 * h.n_edges
    assert all(cyclic_equal(c, (6, 3, 3, 3, 3)) for c in configs)


def test_claim_figure_11_preservation_on_cube():
    """Figure 11: pentagon preservation on a cube: the 6 squares stay, 24 pentagons."""
    q = preserve_pentagons(shapes.cube())
    assert q.face_size_histogram() == {4: 6, 5: 24}
    assert (q.n_vertices, q.n_edges) == (8 + 3 * 12, 6 * 12)


def test_claim_figure_12_pentagonalization_twice_on_the_animal():
    """Figure 12: pentagonalization applied twice to a mesh with hard features."""
    m = shapes.animal()
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    p = subdivide(m, "pentagonalize", 2)
    V1, E1, F1 = V + 2 * E + F, 5 * E, 2 * E
    assert (p.n_vertices, p.n_edges, p.n_faces) == (V1 + 2 * E1 + F1, 25 * E, 10 * E)
    assert p.face_size_histogram() == {5: 10 * E}
    assert p.genus == 0 and p.volume > 0


def test_pentagonalize_of_flipped_mesh_stays_flipped():
    m = shapes.cube()
    flipped = Mesh(m.vertices, [f[::-1] for f in face_lists(m)])
    assert pentagonalize(flipped).volume == pytest.approx(-8.0)
    assert preserve_pentagons(flipped).volume == pytest.approx(-8.0)
