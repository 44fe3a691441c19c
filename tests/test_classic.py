"""Tests of :mod:`pentanb.schemes.classic`: the remeshings the paper compares with (Sections 3, 6).

Expected counts, face sizes, valences and placements are derived from each
scheme's construction in the comments; Conway counts are the known
polyhedra's (e.g. expand(cube) is the rhombicuboctahedron: 24 vertices, 48
edges, 8 triangles and 18 squares).
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest
from helpers import (
    check_valid,
    corpus,
    darts,
    expected_counts,
    face_lists,
    is_isomorphic,
    kis,
    valences,
)

from pentanb import (
    corner_cutting,
    dual,
    honeycomb,
    loop_remesh,
    pentagonalize,
    preserve_hexagons,
    preserve_pentagons,
    shapes,
    sqrt3_remesh,
    triangulate,
    vertex_insertion,
)

CLASSIC = {
    "triangulate": triangulate,
    "loop_remesh": loop_remesh,
    "sqrt3_remesh": sqrt3_remesh,
    "vertex_insertion": vertex_insertion,
    "corner_cutting": corner_cutting,
    "preserve_hexagons": preserve_hexagons,
    "honeycomb": honeycomb,
}


def edge_index(m):
    return {tuple(e): k for k, e in enumerate(m.edges.tolist())}


def mid_index(m):
    """Index (V + e) of the midpoint of every half-edge's edge."""
    faces = face_lists(m)
    tail, head, _, _ = darts(faces)
    eid = edge_index(m)
    return [m.n_vertices + eid[(min(u, w), max(u, w))] for u, w in zip(tail, head)]


@pytest.mark.parametrize("name", list(CLASSIC))
def test_classic_valid_counts_orientation(corpus_mesh, name):
    m = corpus_mesh
    out = CLASSIC[name](m)
    check_valid(out)
    assert (out.n_vertices, out.n_edges, out.n_faces) == expected_counts(name, m)
    assert out.euler_characteristic == m.euler_characteristic
    assert out.volume > 0


@pytest.mark.parametrize("name", list(CLASSIC))
def test_classic_leaves_input_unchanged(corpus_mesh, name):
    m = corpus_mesh
    v, c, o = m.vertices.copy(), m.corners.copy(), m.offsets.copy()
    out = CLASSIC[name](m)
    assert np.array_equal(m.vertices, v) and np.array_equal(m.corners, c)
    assert np.array_equal(m.offsets, o)
    if not (name == "triangulate" and set(m.face_sizes.tolist()) == {3}):
        assert out is not m


@pytest.mark.parametrize("name", list(CLASSIC))
def test_classic_refuses_non_mesh(name):
    with pytest.raises(TypeError, match=f"{name} expects a pentanb.Mesh"):
        CLASSIC[name](None)


@pytest.mark.parametrize(
    "name", ["triangulate", "loop_remesh", "sqrt3_remesh", "vertex_insertion", "preserve_hexagons"]
)
def test_old_vertices_do_not_move(corpus_mesh, name):
    m = corpus_mesh
    out = CLASSIC[name](m)
    assert np.array_equal(out.vertices[: m.n_vertices], m.vertices)


@pytest.mark.parametrize("name", ["triangulate", "loop_remesh", "vertex_insertion"])
def test_face_plane_remeshings_keep_the_cube_volume(name):
    # every new point and face lies in a face plane of the cube
    assert CLASSIC[name](shapes.cube()).volume == pytest.approx(8.0, rel=1e-12)


# ====================================================================== triangulate
def test_triangulate_faces_and_centres(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    big = [f for f, face in enumerate(faces) if len(face) > 3]
    centre = {f: m.n_vertices + k for k, f in enumerate(big)}
    expected = [face for face in faces if len(face) == 3]
    for f in big:
        face = faces[f]
        expected += [[face[i], face[(i + 1) % len(face)], centre[f]] for i in range(len(face))]
    t = triangulate(m)
    assert face_lists(t) == expected
    for f in big:
        assert np.allclose(
            t.vertices[centre[f]], m.vertices[faces[f]].mean(axis=0), rtol=0, atol=1e-14
        )
    # old vertices gain an edge to each non-triangle round them; a centre is n-valent
    around = Counter(v for f in big for v in faces[f])
    val = valences(t)
    assert val[: m.n_vertices] == [k + around[v] for v, k in enumerate(valences(m))]
    assert val[m.n_vertices :] == [len(faces[f]) for f in big]


def test_triangulate_cube_by_hand():
    t = triangulate(shapes.cube())
    # 8 + 6 vertices, 12 + 24 edges, 24 triangles: the tetrakis hexahedron
    assert (t.n_vertices, t.n_edges, t.n_faces) == (14, 36, 24)
    assert t.valence_histogram() == {4: 6, 6: 8}


def test_claim_simplest_triangulation_not_iterable(corpus_mesh):
    """Figure 2: "after the first iteration it does not change the mesh (i.e.,
    it becomes null algorithm)"."""
    once = triangulate(corpus_mesh)
    assert set(once.face_sizes.tolist()) == {3}
    twice = triangulate(once)
    assert np.array_equal(twice.vertices, once.vertices)
    assert np.array_equal(twice.corners, once.corners)
    assert np.array_equal(twice.offsets, once.offsets)
    assert twice.n_vertices == once.n_vertices  # no vertex added: not a refinement


def test_triangulate_keeps_triangle_meshes():
    ico = shapes.icosahedron()
    assert np.array_equal(triangulate(ico).corners, ico.corners)
    assert np.array_equal(triangulate(ico).vertices, ico.vertices)


# ====================================================================== loop_remesh
def test_loop_remesh_faces_and_midpoints(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    tail, head, nxt, _ = darts(faces)
    mid = mid_index(m)
    out = loop_remesh(m)
    expected = [[mid[h] for h in range(m.offsets[f], m.offsets[f + 1])] for f in range(m.n_faces)]
    expected += [[mid[h], head[h], mid[nxt[h]]] for h in range(len(tail))]
    assert face_lists(out) == expected
    for e, (a, b) in enumerate(m.edges.tolist()):
        assert np.allclose(
            out.vertices[m.n_vertices + e], (m.vertices[a] + m.vertices[b]) / 2, rtol=0, atol=1e-14
        )
    # a midpoint joins its edge's ends and two midpoints in each of its two faces
    val = valences(out)
    assert val[: m.n_vertices] == valences(m)
    assert val[m.n_vertices :] == [6] * m.n_edges


def test_claim_loop_remeshing_preserves_triangles_on_mixed_mesh():
    """Section 3 and Figure 3: Loop's remeshing works on any mesh, a triangle
    mesh stays triangular, but "if the original mesh has some non-triangles,
    the resulting mesh does not become a triangular mesh": each non-triangle
    keeps a central copy, every corner becomes a triangle."""
    m = corpus("cube_split")  # 1 triangle, 3 quads, 3 pentagons; E = 15
    out = loop_remesh(m)
    assert out.face_size_histogram() == {3: 1 + 2 * 15, 4: 3, 5: 3}
    again = loop_remesh(out)
    assert int(np.sum(again.face_sizes != 3)) == 6
    for name in ("tetrahedron", "octahedron", "icosahedron"):
        tri = loop_remesh(shapes.get(name))
        assert set(tri.face_sizes.tolist()) == {3}


def test_claim_36_schemes_keep_non_6_valent_count_after_first_refinement():
    """Section 3: for (3, 6) schemes such as Loop and sqrt(3) "the number of
    non-6-valent vertices remains constant after the first refinement"."""
    for name in ("tetrahedron", "icosahedron", "cube_split", "torus"):
        for op in (loop_remesh, sqrt3_remesh):
            mesh = op(corpus(name))
            first = int(np.sum(mesh.valences != 6))
            for _ in range(2):
                mesh = op(mesh)
                assert int(np.sum(mesh.valences != 6)) == first


# ====================================================================== sqrt3_remesh
def test_sqrt3_faces_and_valences(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    tail, _head, _, twin = darts(faces)
    face_of = [f for f, face in enumerate(faces) for _ in face]
    V = m.n_vertices
    out = sqrt3_remesh(m)
    assert face_lists(out) == [
        [u, V + face_of[twin[h]], V + face_of[h]] for h, u in enumerate(tail)
    ]
    assert np.allclose(
        out.vertices[V:], [m.vertices[f].mean(axis=0) for f in faces], rtol=0, atol=1e-14
    )
    # an old vertex joins the centres of its k faces; a centre its n corners and
    # its n neighbours' centres
    val = valences(out)
    assert val[:V] == valences(m)
    assert val[V:] == [2 * len(f) for f in faces]


def test_sqrt3_of_cube_is_triakis_octahedron_by_counts():
    out = sqrt3_remesh(shapes.cube())
    assert (out.n_vertices, out.n_edges, out.n_faces) == (14, 36, 24)
    assert out.valence_histogram() == {3: 8, 8: 6}


def test_claim_sqrt3_dual_is_3_valent(corpus_mesh):
    """Section 3: the dual of sqrt(3) "is a 3-valent conversion scheme that
    converts any manifold mesh to a mesh with only 3-valent vertices"."""
    d = dual(sqrt3_remesh(corpus_mesh))
    assert d.valence_histogram() == {3: d.n_vertices}


# ====================================================================== vertex_insertion
def test_vertex_insertion_faces_and_valences(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    tail, head, nxt, _ = darts(faces)
    face_of = [f for f, face in enumerate(faces) for _ in face]
    V, E = m.n_vertices, m.n_edges
    mid = mid_index(m)
    out = vertex_insertion(m)
    assert face_lists(out) == [
        [mid[h], head[h], mid[nxt[h]], V + E + face_of[h]] for h in range(len(tail))
    ]
    assert np.allclose(
        out.vertices[V + E :], [m.vertices[f].mean(axis=0) for f in faces], rtol=0, atol=1e-14
    )
    val = valences(out)
    assert val[:V] == valences(m)
    assert val[V : V + E] == [4] * E
    assert val[V + E :] == [len(f) for f in faces]


def test_vertex_insertion_is_ortho_by_counts():
    # ortho(cube) = deltoidal icositetrahedron: 26 vertices, 48 edges, 24 kites
    out = vertex_insertion(shapes.cube())
    assert (out.n_vertices, out.n_edges, out.n_faces) == (26, 48, 24)
    assert out.valence_histogram() == {3: 8, 4: 18}


def test_claim_44_schemes_keep_irregular_count_after_first_refinement():
    """Section 3: for (4, 4) schemes "depending on the scheme either the number
    of non-4-valent vertices or the number of non-4-sided faces remains
    constant": vertex insertion keeps the first, corner cutting the second."""
    for name in ("tetrahedron", "cube_split", "pentagonal_pyramid", "double_torus"):
        m = corpus(name)
        vi, cc = vertex_insertion(m), corner_cutting(m)
        n_vi, n_cc = int(np.sum(vi.valences != 4)), int(np.sum(cc.face_sizes != 4))
        for _ in range(2):
            vi, cc = vertex_insertion(vi), corner_cutting(cc)
            assert int(np.sum(vi.valences != 4)) == n_vi
            assert int(np.sum(cc.face_sizes != 4)) == n_cc


# ====================================================================== corner_cutting
@pytest.mark.parametrize("scale", [0.5, 0.3])
def test_corner_cutting_faces_points_valences(corpus_mesh, scale):
    m = corpus_mesh
    faces = face_lists(m)
    tail, _head, _nxt, _twin = darts(faces)
    face_of = [f for f, face in enumerate(faces) for _ in face]
    out = corner_cutting(m, scale)
    cent = [m.vertices[f].mean(axis=0) for f in faces]
    expected_pts = [
        cent[face_of[h]] + scale * (m.vertices[u] - cent[face_of[h]]) for h, u in enumerate(tail)
    ]
    assert np.allclose(out.vertices, expected_pts, rtol=0, atol=1e-13)
    got = face_lists(out)
    F, E = m.n_faces, m.n_edges
    assert got[:F] == [list(range(m.offsets[f], m.offsets[f + 1])) for f in range(F)]
    # one quad per edge: the corners at both ends of the edge, in both its faces
    pairs = []
    for quad in got[F : F + E]:
        assert len(quad) == 4
        assert len({face_of[h] for h in quad}) == 2
        ends = sorted({tail[h] for h in quad})
        assert len(ends) == 2
        pairs.append(tuple(ends))
    assert sorted(pairs) == sorted(map(tuple, m.edges.tolist()))
    # one k-gon per k-valent vertex, made of the corners at that vertex
    for v, vface in enumerate(got[F + E :]):
        assert {tail[h] for h in vface} == {v}
        assert len(vface) == m.valences[v]
    assert out.valence_histogram() == {4: 2 * E}


def test_corner_cutting_cube_face_x1():
    # corners of face 1 (x = 1, centre (1, 0, 0)) at (1, +-1/2, +-1/2)
    out = corner_cutting(shapes.cube())
    copy = out.vertices[face_lists(out)[1]]
    assert {tuple(p) for p in copy.tolist()} == {
        (1.0, a, b) for a in (-0.5, 0.5) for b in (-0.5, 0.5)
    }


def test_corner_cutting_is_expand_by_counts():
    # expand(cube) = rhombicuboctahedron: 24 vertices, 48 edges, 8 triangles + 18 squares
    out = corner_cutting(shapes.cube())
    assert (out.n_vertices, out.n_edges) == (24, 48)
    assert out.face_size_histogram() == {3: 8, 4: 18}
    assert is_isomorphic(out, corner_cutting(shapes.octahedron()))


def test_claim_corner_cutting_makes_all_vertices_4_valent(corpus_mesh):
    """Section 3: "After one application of corner cutting the valence of all
    the vertices become 4"."""
    out = corner_cutting(corpus_mesh)
    assert out.valence_histogram() == {4: out.n_vertices}


@pytest.mark.parametrize("op", [corner_cutting, preserve_hexagons])
@pytest.mark.parametrize("scale", [0, 1, -1, 2, float("nan"), "half"])
def test_scale_is_checked(op, scale):
    with pytest.raises(ValueError, match="scale must be"):
        op(shapes.cube(), scale=scale)


# ====================================================================== preserve_hexagons
def test_preserve_hexagons_faces_points_valences(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    tail, _head, _nxt, _twin = darts(faces)
    face_of = [f for f, face in enumerate(faces) for _ in face]
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    s = 0.4
    out = preserve_hexagons(m, scale=s)
    cent = [m.vertices[f].mean(axis=0) for f in faces]
    assert np.allclose(
        out.vertices[V:],
        [cent[face_of[h]] + s * (m.vertices[u] - cent[face_of[h]]) for h, u in enumerate(tail)],
        rtol=0,
        atol=1e-13,
    )
    got = face_lists(out)
    assert got[:F] == [[V + h for h in range(m.offsets[f], m.offsets[f + 1])] for f in range(F)]
    # hexagon of edge (a, b): copies of a and b in both faces, a and b
    for hexagon in got[F:]:
        old = [x for x in hexagon if x < V]
        assert len(hexagon) == 6 and len(old) == 2
        copies = [x - V for x in hexagon if x >= V]
        assert {tail[h] for h in copies} == set(old)
        assert len({face_of[h] for h in copies}) == 2
    assert sorted(tuple(sorted(x for x in hx if x < V)) for hx in got[F:]) == sorted(
        map(tuple, m.edges.tolist())
    )
    val = valences(out)
    assert val[:V] == valences(m)
    assert val[V:] == [3] * (2 * E)


def test_preserve_hexagons_is_chamfer_by_counts():
    # chamfer(cube): 32 vertices, 48 edges, 6 squares + 12 hexagons
    out = preserve_hexagons(shapes.cube())
    assert (out.n_vertices, out.n_edges) == (32, 48)
    assert out.face_size_histogram() == {4: 6, 6: 12}


def test_preserve_hexagons_is_dual_of_loop(small_mesh):
    """Section 3: hexagon preservation "is the dual of Loop subdivision"."""
    a = preserve_hexagons(small_mesh)
    b = dual(loop_remesh(dual(small_mesh)))
    assert a.counts() == b.counts()
    assert is_isomorphic(a, b)


def test_claim_hexagon_preservation_keeps_63_meshes():
    """Figures 4-5: two iterations of hexagon preservation on the hexagonal
    meshes of genus 1 and 2 give hexagonal meshes again; the torus stays a
    (6, 3) mesh, the genus-2 surface keeps its 6 four-valent vertices
    (equation 1: sum(valence - 3) = 6(g - 1))."""
    t = shapes.hexagonal_torus()
    for _ in range(2):
        t = preserve_hexagons(t)
        assert t.face_size_histogram() == {6: t.n_faces}
        assert t.valence_histogram() == {3: t.n_vertices}
    s = shapes.hexagonal_surface(2)
    for _ in range(2):
        s = preserve_hexagons(s)
        assert s.face_size_histogram() == {6: s.n_faces}
        assert s.valence_histogram() == {3: s.n_vertices - 6, 4: 6}
        assert s.genus == 2


def test_claim_63_schemes_keep_non_hexagon_count_after_first_refinement():
    """Section 3: for (6, 3) schemes (duals of sqrt(3) and of Loop) "the number
    of non-6-sided faces remains constant after the first refinement"."""
    for name in ("tetrahedron", "dodecahedron", "cube_split", "genus3"):
        for op in (honeycomb, preserve_hexagons):
            mesh = op(corpus(name))
            first = int(np.sum(mesh.face_sizes != 6))
            for _ in range(2):
                mesh = op(mesh)
                assert int(np.sum(mesh.face_sizes != 6)) == first


# ====================================================================== honeycomb
def test_honeycomb_faces_points_valences(corpus_mesh):
    m = corpus_mesh
    faces = face_lists(m)
    tail, head, _nxt, _twin = darts(faces)
    face_of = [f for f, face in enumerate(faces) for _ in face]
    out = honeycomb(m)
    cent = [m.vertices[f].mean(axis=0) for f in faces]
    expected = [
        (m.vertices[u] + m.vertices[w] + cent[face_of[h]]) / 3
        for h, (u, w) in enumerate(zip(tail, head))
    ]
    assert np.allclose(out.vertices, expected, rtol=0, atol=1e-13)
    got = face_lists(out)
    F = m.n_faces
    assert got[:F] == [list(range(m.offsets[f], m.offsets[f + 1])) for f in range(F)]
    # the 2k-gon of vertex v: the points of the k half-edges leaving v and
    # of the k arriving at v
    for v, vface in enumerate(got[F:]):
        assert len(vface) == 2 * m.valences[v]
        assert all(tail[h] == v or head[h] == v for h in vface)
    assert out.valence_histogram() == {3: out.n_vertices}


def test_honeycomb_cube_point_by_hand():
    # half-edge (4, 6) of face x = 1: ((1,-1,-1) + (1,1,-1) + (1,0,0)) / 3
    c = shapes.cube()
    h = face_lists(c)[1].index(4) + 4
    assert face_lists(c)[1] == [4, 6, 7, 5] and h == 4
    assert np.allclose(honeycomb(c).vertices[h], [1, 0, -2 / 3])


def test_honeycomb_is_zip_by_counts():
    # zip(cube) = truncated octahedron: 24 vertices, 36 edges, 6 squares + 8 hexagons
    out = honeycomb(shapes.cube())
    assert (out.n_vertices, out.n_edges) == (24, 36)
    assert out.face_size_histogram() == {4: 6, 6: 8}


def test_honeycomb_is_dual_of_sqrt3_and_of_kis(small_mesh):
    """Sections 3 and 6: honeycomb is the dual of sqrt(3) (Conway's zip = dual of kis)."""
    a = honeycomb(small_mesh)
    b = dual(sqrt3_remesh(dual(small_mesh)))
    c = dual(kis(small_mesh))
    assert a.counts() == b.counts() == c.counts()
    assert is_isomorphic(a, b)
    assert is_isomorphic(a, c)


def test_claim_honeycomb_on_pentagonal_mesh_has_no_triangles_or_quads():
    """Section 6 and Figure 13: honeycomb on a pentagonal mesh gives a
    "soccerball": no triangle or quad, every vertex 3-valent.  The
    dodecahedron becomes the truncated icosahedron: 60 vertices, 90 edges,
    12 pentagons and 20 hexagons."""
    ball = honeycomb(shapes.dodecahedron())
    assert (ball.n_vertices, ball.n_edges) == (60, 90)
    assert ball.face_size_histogram() == {5: 12, 6: 20}
    assert ball.valence_histogram() == {3: 60}
    assert is_isomorphic(ball, dual(kis(shapes.dodecahedron())))
    for m in (
        pentagonalize(shapes.cube()),
        pentagonalize(shapes.torus(4, 3)),
        preserve_pentagons(shapes.dodecahedron()),
        pentagonalize(shapes.animal()),
    ):
        sizes = set(honeycomb(m).face_sizes.tolist())
        assert not sizes & {3, 4}
        # a k-valent vertex becomes a 2k-gon: 3-valent -> hexagons
        assert 6 in sizes and 5 in sizes
