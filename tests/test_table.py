"""Schemes as data: every table against connectivity derived from scratch, the
counts a table gives, malformed tables refused by slot, a table of one's own."""

from __future__ import annotations

import numpy as np
import pytest
from helpers import face_lists

import pentanb as pb
from pentanb import Mesh, MeshError, Table, shapes
from pentanb.schemes.registry import count_formula

TABLES = {n: s.table for n, s in pb.SCHEMES.items() if s.table is not None}
OPEN_TABLES = [n for n, t in TABLES.items() if t.compiled.open_rule is None]


def sheet() -> Mesh:
    """A 4 x 3 sheet of quads with one square hole: two boundary loops."""
    from helpers import holed_grid

    return Mesh(*holed_grid(4, 3, [(1, 1, 1)]))


@pytest.fixture(params=[False, True], ids=["numpy", "compiled"])
def path(request):
    from pentanb import _jit

    if request.param and not _jit.available():
        pytest.skip("numba is not installed")
    before = _jit.use_jit(request.param)
    yield
    _jit.use_jit(before)


def derived(out: Mesh) -> Mesh:
    """The same arrays, every connectivity derived from scratch (by sorting and walking)."""
    return Mesh(out.vertices, face_lists(out))


def same_connectivity(out: Mesh, again: Mesh) -> None:
    assert np.array_equal(out.twin, again.twin)
    for a, b in zip(out.vertex_ring, again.vertex_ring):
        assert np.array_equal(a, b)  # the one rule: every ring starts at its largest
    assert np.array_equal(out.boundary_halfedges, again.boundary_halfedges)


def test_the_built_in_tables_are_the_registrys():
    assert set(TABLES) == set(pb.SCHEMES) - {"triangulate"}
    assert {"pentagonalize", "preserve_pentagons", "loop_remesh"} <= set(OPEN_TABLES)


@pytest.mark.parametrize("name", list(TABLES))
def test_every_table_gives_the_connectivity_derived_from_scratch(name, corpus_mesh, path):
    out = TABLES[name](corpus_mesh)
    same_connectivity(out, derived(out))


@pytest.mark.parametrize("name", OPEN_TABLES)
@pytest.mark.parametrize("mesh", [sheet, shapes.open_disk], ids=["holed sheet", "open disk"])
def test_every_open_table_gives_the_connectivity_derived_from_scratch(name, mesh, path):
    out = TABLES[name](mesh())
    same_connectivity(out, derived(out))


def test_the_check_can_fail():
    # a twin array with two entries swapped is not what derivation finds
    out = pb.pentagonalize(shapes.cube())
    twin = np.array(out.twin)
    twin[[0, 1]] = twin[[1, 0]]
    assert not np.array_equal(twin, derived(out).twin)


def test_the_dual_of_a_pentagonalization_is_that_of_the_rebuilt_mesh(corpus_mesh):
    # one ring rule: the dual's faces start where the rings do, written or derived
    out = pb.pentagonalize(corpus_mesh)
    assert face_lists(pb.dual(out)) == face_lists(pb.dual(derived(out)))


@pytest.mark.parametrize("name", list(TABLES))
def test_a_tables_counts_are_the_registrys_formula(name):
    s = pb.SCHEMES[name]
    assert count_formula(s.table.counts) == count_formula(s.counts)
    if name in OPEN_TABLES and s.open_counts is not None:  # (C, the dual's corners: geometry)
        mine = count_formula(lambda V, E, F, B, C: (*s.table.open_counts(V, E, F, B), 0), True)
        theirs = count_formula(lambda V, E, F, B, C: (*s.open_counts(V, E, F, B, C)[:4], 0), True)
        assert mine == theirs


@pytest.mark.parametrize("name", list(TABLES))
def test_a_tables_counts_are_what_it_builds(name, corpus_mesh):
    m = corpus_mesh
    out = TABLES[name](m)
    assert TABLES[name].counts(m.n_vertices, m.n_edges, m.n_faces) == (
        out.n_vertices,
        out.n_edges,
        out.n_faces,
    )


@pytest.mark.parametrize("name", OPEN_TABLES)
def test_an_open_tables_counts_are_what_it_builds(name):
    m = sheet()
    out = TABLES[name](m)
    got = TABLES[name].open_counts(m.n_vertices, m.n_edges, m.n_faces, m.n_boundary_edges)
    assert got == (out.n_vertices, out.n_edges, out.n_faces, out.n_boundary_edges)


# ---------------------------------------------------------------- malformed tables
GYRO = ("E0", "E1", "n:V", "n:E0", "F")


@pytest.mark.parametrize(
    ("kw", "says"),
    [
        (dict(faces=(("halfedge", ("E0", "X", "F")),)), r"faces\[0\]: 'X' is not a point"),
        (dict(faces=(("corner", GYRO),)), "kind 'corner' is not one of"),
        (dict(faces=(("halfedge", ("E0", "F")),)), "needs at least 3 corners"),
        (
            dict(faces=(("halfedge", ("E0", "E1", "E2", "F")),)),
            "names edge point 2, the table has 2",
        ),
        (dict(faces=(("halfedge", GYRO),), face_points=False), "set face_points=True"),
        (dict(faces=(("halfedge", ("E0", "C", "F")),)), "give corner_points"),
        (dict(faces=(("halfedge", ("E0", "E0", "n:V")),)), "repeats a corner"),
        (dict(faces=(("halfedge", GYRO[::-1]),)), "turn clockwise seen from outside"),
        (dict(faces=(("halfedge", ("E0", "n:V", "F")),)), r"slot 0 .*twins do not pair"),
        (dict(faces=(("halfedge", GYRO),), edge_points=(0.3, 0.5)), "must be symmetric"),
        (
            dict(faces=(("halfedge", ("V", "n:V", "F")),)),
            "the edge points of the table are in no face",
        ),
        (dict(faces=(("halfedge", GYRO),), edge_points=(2 / 3, 1 / 3)), "must increase"),
        (
            dict(faces=(("halfedge", GYRO),), corner_points={"V": 0.5, "n:V": 0.4}),
            "sum to 1, they sum to 0.9",
        ),
        (dict(faces=(("halfedge", GYRO),), corner_points=("E0", "size")), "not one of its options"),
        (dict(faces=(("edge", ("V", "t:F", "n:V", "F", "F")),)), "repeats a corner"),
        (dict(faces=(("edge", ("V", "t:F", "n:V", "n:E0")),)), "twins do not pair"),
    ],
)
def test_a_malformed_table_is_refused_naming_the_slot(kw, says):
    kw = {"edge_points": (1 / 3, 2 / 3), "face_points": True, **kw}
    with pytest.raises(ValueError, match=says):
        Table("mine", **kw)


def test_a_point_that_is_not_a_string_is_a_type_error():
    with pytest.raises(TypeError, match="named by a string"):
        Table("mine", face_points=True, faces=(("halfedge", ("V", 3, "F")),))


def test_an_open_mesh_a_table_cannot_remesh_is_refused_before_work():
    ambo = Table(
        "ambo", vertices=False, edge_points=(0.5,), faces=(("face", "E0"), ("vertex", "E0"))
    )
    assert ambo(shapes.cube()).n_faces == 14  # the cuboctahedron
    with pytest.raises(MeshError, match="ambo needs a closed mesh: its faces round vertices"):
        ambo(shapes.open_disk())
    with pytest.raises(TypeError, match="unexpected keyword argument 'scale'"):
        ambo(shapes.cube(), scale=0.5)


# ---------------------------------------------------------------- a table of one's own
#: Hexagons from any mesh with 3-valent vertices: each face's corners cut, the
#: old vertices gone: "truncate" as a table of four lines.
TRUNCATE = Table(
    "my_truncate",
    vertices=False,
    edge_points=(1 / 3, 2 / 3),
    faces=(("face", ("p:E1", "E0")), ("vertex", ("E0",))),
)


def test_a_table_of_ones_own_gets_subdivide_counts_and_the_guard():
    out = pb.subdivide(shapes.icosahedron(), TRUNCATE, 1, 0)
    assert out.face_size_histogram() == {5: 12, 6: 20}  # the soccerball
    steps = pb.predict_counts(shapes.icosahedron(), TRUNCATE, 2, 2)
    assert steps[-1] == (
        pb.subdivide(shapes.icosahedron(), TRUNCATE, 2, 2).n_vertices,
        *steps[-1][1:],
    )
    with pytest.raises(MeshError, match="my_truncate"):
        pb.subdivide(shapes.icosahedron(), TRUNCATE, 12, 0, max_bytes=10**7)


def test_a_table_of_ones_own_gets_its_matrix_from_its_weights():
    from pentanb import analysis

    m = shapes.cube()
    S, out = analysis.subdivision_matrix(m, TRUNCATE, 1, 0)
    assert np.allclose(S @ m.vertices, out.vertices, atol=1e-12)
    assert np.allclose(S.sum(axis=1), 1)  # affine: the weights of every row sum to 1


def test_a_table_of_ones_own_runs_on_open_meshes():
    sqrt3ish = Table("mine", face_points=True, faces=(("halfedge", ("V", "t:F|n:V", "F")),))
    out = pb.subdivide(sheet(), sqrt3ish, 1, 2)
    assert not out.is_closed and out.n_boundary_loops == 2
