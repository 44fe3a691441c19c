"""Property tests (hypothesis) on random closed meshes.

Random meshes: tori and hexagonal tori of random sizes, chains of tori of
random genus, Platonic solids put through a random sequence of schemes, and
triangulated solids with random pairs of adjacent faces merged (see
:func:`helpers.merge_faces`), which gives mixed face sizes and valences.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from helpers import (
    OPERATORS,
    check_sealed,
    check_valid,
    expected_counts,
    expected_face_histogram,
    face_lists,
    kis,
    merge_faces,
    polyhedral,
    same_faces_up_to_rotation,
    same_mesh,
    valences,
)
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import pentanb
from pentanb import SCHEMES, Mesh, dual, predict_counts, shapes, subdivide

PLATONIC = ["tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"]
SCALED = {"preserve_pentagons", "corner_cutting", "preserve_hexagons"}
PROPS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _triangulated(name: str) -> Mesh:
    if name == "sqrt3_cube":
        return pentanb.sqrt3_remesh(shapes.cube())
    if name == "kis_dodecahedron":
        return kis(shapes.dodecahedron())
    if name == "loop_tetrahedron":
        return pentanb.loop_remesh(shapes.tetrahedron())
    return shapes.get(name)


@st.composite
def closed_meshes(draw) -> Mesh:
    kind = draw(st.sampled_from(["torus", "hexagonal_torus", "genus", "solid", "merged"]))
    if kind == "torus":
        return shapes.torus(draw(st.integers(3, 7)), draw(st.integers(3, 7)))
    if kind == "hexagonal_torus":
        return shapes.hexagonal_torus(draw(st.integers(3, 6)), draw(st.integers(3, 6)))
    if kind == "genus":
        g = draw(st.integers(1, 3))
        rings, sides = draw(st.sampled_from([4, 6])), draw(st.integers(3, 5))
        if draw(st.booleans()):
            return shapes.hexagonal_surface(g, rings, sides)
        return shapes.genus_surface(g, rings=rings, sides=sides)
    if kind == "solid":
        m = shapes.get(draw(st.sampled_from(PLATONIC)))
        for name in draw(st.lists(st.sampled_from(list(SCHEMES) + ["dual"]), max_size=2)):
            if m.n_edges > 300:
                break
            if name in SCALED:
                m = OPERATORS[name](m, scale=draw(st.floats(0.1, 0.9)))
            else:
                m = OPERATORS[name](m)
        return m
    base = _triangulated(
        draw(
            st.sampled_from(
                ["icosahedron", "octahedron", "sqrt3_cube", "kis_dodecahedron", "loop_tetrahedron"]
            )
        )
    )
    return merge_faces(base, draw(st.lists(st.integers(0, 10**6), min_size=1, max_size=12)))


@PROPS
@given(closed_meshes())
def test_random_meshes_are_valid_and_polyhedral(m):
    check_valid(m)
    assert polyhedral(face_lists(m), m.n_vertices)
    assert m.volume > 0


@PROPS
@given(closed_meshes(), st.sampled_from(list(OPERATORS)))
def test_every_operator_keeps_validity_euler_counts_and_orientation(m, name):
    out = OPERATORS[name](m)
    check_valid(out)
    assert out.euler_characteristic == m.euler_characteristic
    assert out.n_components == m.n_components
    assert (out.n_vertices, out.n_edges, out.n_faces) == expected_counts(name, m)
    assert out.face_size_histogram() == expected_face_histogram(name, m)
    assert np.sign(out.volume) == np.sign(m.volume) == 1


@PROPS
@given(closed_meshes(), st.sampled_from(sorted(SCALED)), st.floats(0.05, 0.95))
def test_scaled_operators_with_any_scale(m, name, scale):
    out = OPERATORS[name](m, scale=scale)
    check_valid(out)
    assert (out.n_vertices, out.n_edges, out.n_faces) == expected_counts(name, m)
    assert out.volume > 0


@PROPS
@given(closed_meshes())
def test_registry_counts_predict_every_scheme(m):
    for name, s in SCHEMES.items():
        if name == "triangulate":
            continue
        out = s(m)
        assert s.counts(m.n_vertices, m.n_edges, m.n_faces) == (
            out.n_vertices,
            out.n_edges,
            out.n_faces,
        )


@PROPS
@given(closed_meshes())
def test_dual_dual_is_the_identity_on_topology(m):
    d = dual(m)
    assert np.array_equal(d.face_sizes, m.valences)
    assert np.array_equal(d.valences, m.face_sizes)
    for dd in (dual(d), dual(Mesh(d.vertices, face_lists(d)))):
        assert np.array_equal(dd.offsets, m.offsets)
        assert same_faces_up_to_rotation(face_lists(dd), face_lists(m))


@PROPS
@given(closed_meshes())
def test_pentagonalize_valences_and_faces(m):
    V, E = m.n_vertices, m.n_edges
    p = pentanb.schemes.pentagonalize(m)
    assert p.face_size_histogram() == {5: 2 * E}
    val = valences(p)
    assert val[:V] == valences(m)
    assert val[V : V + 2 * E] == [3] * (2 * E)
    assert val[V + 2 * E :] == [len(f) for f in face_lists(m)]


@PROPS
@given(closed_meshes())
def test_conversion_schemes_give_their_type(m):
    assert set(pentanb.sqrt3_remesh(m).face_sizes.tolist()) == {3}
    assert set(pentanb.vertex_insertion(m).face_sizes.tolist()) == {4}
    assert set(pentanb.corner_cutting(m).valences.tolist()) == {4}
    assert set(pentanb.honeycomb(m).valences.tolist()) == {3}
    assert set(pentanb.triangulate(m).face_sizes.tolist()) == {3}
    q = pentanb.preserve_pentagons(m)
    assert int(np.sum(q.face_sizes != 5)) == int(np.sum(m.face_sizes != 5))


@pytest.mark.slow
@PROPS
@given(
    closed_meshes(),
    st.lists(st.tuples(st.sampled_from(list(SCHEMES)), st.integers(0, 2)), min_size=1, max_size=3),
)
def test_subdivide_random_scheme_sequences(m, steps):
    counts = (m.n_vertices, m.n_edges, m.n_faces)
    for name, duals in steps:
        pred = predict_counts(counts, name, 1, duals)
        assume(pred[-1][1] <= 6000)
        out = subdivide(m, name, 1, duals)
        got = (out.n_vertices, out.n_edges, out.n_faces)
        if name == "triangulate":
            assert all(p >= g for p, g in zip(pred[-1], got))
        else:
            assert got == pred[-1]
        assert out.euler_characteristic == m.euler_characteristic
        m, counts = out, got
    check_valid(m)
    assert m.volume > 0


@pytest.mark.slow
@PROPS
@given(closed_meshes(), st.lists(st.sampled_from(list(SCHEMES) + ["dual"]), max_size=3))
def test_pickled_meshes_equal_and_operate_like_the_originals(m, names):
    # a chain of fresh (lazy) outputs, each pickled: equal before and after,
    # and the next operator gives the same mesh from either
    for name in names:
        if m.n_edges > 2000:
            break
        out = OPERATORS[name](m)
        back = pickle.loads(pickle.dumps(out))
        same_mesh(back, out)
        check_sealed(back)
        same_mesh(dual(back), dual(out))
        m = back
    check_valid(m)


@PROPS
@given(
    st.sampled_from(["icosahedron", "octahedron", "sqrt3_cube", "kis_dodecahedron"]),
    st.lists(st.integers(0, 10**6), min_size=1, max_size=12),
)
def test_merge_faces_removes_one_edge_and_face_per_merge(base_name, picks):
    base = _triangulated(base_name)
    m = merge_faces(base, picks)
    merges = base.n_faces - m.n_faces
    assert 0 <= merges <= len(picks)
    assert base.n_edges - m.n_edges == merges
    assert m.n_vertices == base.n_vertices
    check_valid(m)


def _union_find_labels(faces, n):
    parent = list(range(n))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for f in faces:
        for x in f[1:]:
            a, b = find(x), find(f[0])
            parent[max(a, b)] = min(a, b)
    return [find(x) for x in range(n)]


@pytest.mark.slow
@PROPS
@given(st.lists(closed_meshes(), min_size=1, max_size=4), st.randoms(use_true_random=False))
def test_components_of_disjoint_unions(parts, rnd):
    # several meshes side by side, their vertices shuffled together
    verts, faces, shift = [], [], 0
    for k, p in enumerate(parts):
        verts.append(p.vertices + [10.0 * k, 0, 0])
        faces += [[v + shift for v in f] for f in face_lists(p)]
        shift += p.n_vertices
    perm = list(range(shift))
    rnd.shuffle(perm)
    inv = np.argsort(perm)
    m = Mesh(np.concatenate(verts)[perm], [[int(inv[v]) for v in f] for f in faces])
    assert m.n_components == len(parts)
    assert m.genus == sum(p.genus for p in parts)
    assert m.euler_characteristic == sum(p.euler_characteristic for p in parts)
    labels = _union_find_labels(face_lists(m), m.n_vertices)
    assert m.component_labels.tolist() == labels  # each component's smallest index
    d = dual(m)
    check_valid(d)
    assert d.n_components == len(parts)
