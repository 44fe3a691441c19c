"""Tests of :mod:`pentanb.subdivision`: the registry, ``subdivide`` and its guards,
and every operator of the registry (plus the dual) run over the whole corpus.
"""

from __future__ import annotations

import copy
import dataclasses
import inspect
import pickle
import re

import numpy as np
import pytest
from helpers import (
    OPERATORS,
    check_sealed,
    check_valid,
    corpus,
    expected_counts,
    expected_face_histogram,
    face_lists,
    same_mesh,
    two_cubes,
)

import pentanb
from pentanb import (
    SCHEMES,
    MeshError,
    Scheme,
    dual,
    memory,
    predict_counts,
    shapes,
    smooth,
    subdivide,
)

OPERATOR_NAMES = [
    "pentagonalize",
    "preserve_pentagons",
    "triangulate",
    "loop_remesh",
    "sqrt3_remesh",
    "vertex_insertion",
    "corner_cutting",
    "preserve_hexagons",
    "honeycomb",
]


# ====================================================================== every operator x corpus
def test_operator_output_is_valid(corpus_mesh, operator_name):
    check_valid(OPERATORS[operator_name](corpus_mesh))


def test_operator_keeps_euler_characteristic_and_genus(corpus_mesh, operator_name):
    m = corpus_mesh
    out = OPERATORS[operator_name](m)
    assert out.euler_characteristic == m.euler_characteristic
    assert out.genus == m.genus
    assert out.n_components == m.n_components


def test_operator_counts_follow_the_formulas(corpus_mesh, operator_name):
    m = corpus_mesh
    out = OPERATORS[operator_name](m)
    assert (out.n_vertices, out.n_edges, out.n_faces) == expected_counts(operator_name, m)
    assert out.face_size_histogram() == expected_face_histogram(operator_name, m)
    # (an operator may hand its output the histogram: it must be the faces')
    sizes, counts = np.unique(np.diff(out.offsets), return_counts=True)
    assert out.face_size_histogram() == dict(zip(sizes.tolist(), counts.tolist()))


def test_operator_keeps_orientation(corpus_mesh, operator_name):
    # the corpus is outward oriented; so are the results, and a flipped
    # input gives a flipped (negative-volume) output
    m = corpus_mesh
    op = OPERATORS[operator_name]
    assert m.volume > 0
    assert op(m).volume > 0
    flipped = pentanb.Mesh(m.vertices, [f[::-1] for f in face_lists(m)])
    assert op(flipped).volume < 0


def test_operator_output_pickles_and_copies_while_lazy(corpus_mesh, operator_name):
    # a fresh output: the twins and rings an operator knows are still producers
    out = OPERATORS[operator_name](corpus_mesh)
    back = pickle.loads(pickle.dumps(out))
    again = copy.deepcopy(OPERATORS[operator_name](corpus_mesh))
    same_mesh(back, out)
    same_mesh(again, out)
    check_sealed(back)
    check_sealed(again)


@pytest.mark.parametrize("name", list(OPERATORS))
def test_operator_on_two_components(name):
    m = two_cubes()
    out = OPERATORS[name](m)
    check_valid(out)
    assert out.n_components == 2
    assert (out.n_vertices, out.n_edges, out.n_faces) == expected_counts(name, m)


# ====================================================================== registry
def test_registry_lists_every_operator_exported_at_top_level():
    assert sorted(SCHEMES) == sorted(OPERATOR_NAMES)
    for name, scheme in SCHEMES.items():
        assert isinstance(scheme, Scheme)
        assert scheme.name == name
        assert scheme.func is getattr(pentanb, name)
        assert scheme.func.__name__ == name
        assert name in pentanb.__all__
    # and nothing exported at top level that maps meshes to meshes is missing
    drawing = {"view", "explore", "step_through", "export_html", "figures", "topology"}
    for name in set(pentanb.__all__) - drawing:  # (those import matplotlib & co.)
        obj = getattr(pentanb, name)
        if inspect.isfunction(obj) and obj.__module__ in (
            "pentanb.schemes.classic",
            "pentanb.schemes.pentagonal",
        ):
            assert name in SCHEMES


def test_registry_families_and_references():
    assert {n for n, s in SCHEMES.items() if s.family == "pentagonal"} == {
        "pentagonalize",
        "preserve_pentagons",
    }
    assert SCHEMES["pentagonalize"].conway == "gyro"
    assert "quinto" in SCHEMES["preserve_pentagons"].conway
    for s in SCHEMES.values():
        assert s.label and s.paper


def test_registry_options_are_the_functions_keyword_defaults():
    for s in SCHEMES.values():
        params = inspect.signature(s.func).parameters
        defaults = {
            k: p.default for k, p in params.items() if p.default is not inspect.Parameter.empty
        }
        assert dict(s.options) == defaults


def test_registry_counts_agree_with_the_formulas(corpus_mesh):
    m = corpus_mesh
    for name, s in SCHEMES.items():
        got = s.counts(m.n_vertices, m.n_edges, m.n_faces)
        want = expected_counts(name, m)
        if name == "triangulate":  # documented as an upper bound
            assert all(g >= w for g, w in zip(got, want))
            if 3 not in m.face_sizes:
                assert got == want
        else:
            assert got == want


def test_scheme_is_callable_with_options():
    m = shapes.cube()
    s = SCHEMES["preserve_pentagons"]
    assert np.array_equal(s(m, scale=0.5).vertices, pentanb.preserve_pentagons(m, 0.5).vertices)


# ====================================================================== subdivide
@pytest.mark.parametrize("name", OPERATOR_NAMES)
@pytest.mark.parametrize("duals", [0, 1, 2])
def test_subdivide_equals_manual_composition(name, duals):
    m = corpus("cube_split")
    manual = m
    for _ in range(2):
        manual = OPERATORS[name](manual)
        for _ in range(duals):
            manual = dual(manual)
    got = subdivide(m, name, iterations=2, duals=duals)
    assert np.array_equal(got.vertices, manual.vertices)
    assert np.array_equal(got.corners, manual.corners)
    assert np.array_equal(got.offsets, manual.offsets)


def test_subdivide_defaults_are_one_pentagonalization_and_two_duals():
    m = shapes.cube()
    got = subdivide(m)
    want = dual(dual(pentanb.schemes.pentagonalize(m)))
    assert np.array_equal(got.vertices, want.vertices)
    assert np.array_equal(got.corners, want.corners)


def test_subdivide_passes_options():
    m = shapes.dodecahedron()
    got = subdivide(m, "preserve_pentagons", 1, duals=0, scale=0.3)
    assert np.array_equal(got.vertices, pentanb.preserve_pentagons(m, 0.3).vertices)


def test_subdivide_takes_a_scheme_or_a_callable():
    m = shapes.tetrahedron()
    a = subdivide(m, SCHEMES["loop_remesh"], 1, 0)
    b = subdivide(m, pentanb.loop_remesh, 1, 0)
    c = subdivide(m, lambda x: pentanb.loop_remesh(x), 1, 0)
    assert np.array_equal(a.corners, b.corners) and np.array_equal(b.corners, c.corners)


def test_subdivide_zero_iterations_returns_the_mesh():
    m = shapes.cube()
    assert subdivide(m, "pentagonalize", iterations=0) is m
    assert smooth(m, 0) is m


def test_subdivide_unknown_scheme_lists_the_known_ones():
    with pytest.raises(ValueError, match="unknown scheme 'pentagonalise'") as info:
        subdivide(shapes.cube(), "pentagonalise")
    for name in OPERATOR_NAMES:
        assert name in str(info.value)


@pytest.mark.parametrize("arg", ["iterations", "duals"])
@pytest.mark.parametrize(
    "bad, error",
    [(-1, ValueError), (1.5, TypeError), ("2", TypeError), (None, TypeError), (True, TypeError)],
)
def test_subdivide_refuses_bad_counts(arg, bad, error):
    with pytest.raises(error, match=f"^{arg} must be an integer >= 0, got "):
        subdivide(shapes.cube(), "pentagonalize", **{arg: bad})


def test_subdivide_refuses_unknown_options():
    with pytest.raises(ValueError, match=r"'pentagonalize' takes no options; got \['scale'\]"):
        subdivide(shapes.cube(), "pentagonalize", scale=0.5)
    with pytest.raises(ValueError, match=r"'preserve_pentagons' takes scale; got \['sclae'\]"):
        subdivide(shapes.cube(), "preserve_pentagons", sclae=0.5)


def test_subdivide_refuses_bad_option_values():
    with pytest.raises(ValueError, match="scale must be"):
        subdivide(shapes.cube(), "corner_cutting", scale=1.5)


@pytest.mark.parametrize("name", OPERATOR_NAMES)
def test_predict_counts_matches_the_built_meshes(name):
    m = corpus("cube_split")
    iterations, duals = 2, 2
    steps = predict_counts((m.n_vertices, m.n_edges, m.n_faces), name, iterations, duals)
    assert len(steps) == iterations * (1 + duals)
    built = []
    mesh = m
    for _ in range(iterations):
        mesh = OPERATORS[name](mesh)
        built.append((mesh.n_vertices, mesh.n_edges, mesh.n_faces))
        for _ in range(duals):
            mesh = dual(mesh)
            built.append((mesh.n_vertices, mesh.n_edges, mesh.n_faces))
    if name == "triangulate":  # an upper bound (triangles are kept)
        assert all(p >= b for ps, bs in zip(steps, built) for p, b in zip(ps, bs))
    else:
        assert steps == built


def test_predict_counts_by_hand():
    # cube, pentagonalize: (8 + 24 + 6, 60, 24), then duals swap V and F
    assert predict_counts((8, 12, 6), "pentagonalize", 1, 2) == [
        (38, 60, 24),
        (24, 60, 38),
        (38, 60, 24),
    ]
    assert predict_counts((8, 12, 6), "honeycomb", 2, 0) == [(24, 36, 14), (72, 108, 38)]
    # a mesh's counts, or the mesh itself
    assert predict_counts(shapes.cube(), "honeycomb", 2, 0) == [(24, 36, 14), (72, 108, 38)]


def test_predict_counts_needs_a_registered_scheme():
    with pytest.raises(ValueError, match="registered scheme"):
        predict_counts((8, 12, 6), pentanb.schemes.pentagonalize)


def test_memory_guard_refuses_before_building(monkeypatch):
    m = shapes.cube()

    def must_not_run(mesh, **options):
        raise AssertionError("the guard let subdivide start building")

    spy = dataclasses.replace(SCHEMES["pentagonalize"], func=must_not_run)
    monkeypatch.setitem(SCHEMES, "pentagonalize", spy)
    with pytest.raises(MeshError) as info:
        subdivide(m, "pentagonalize", iterations=12, max_bytes=10**6)
    msg = str(info.value)
    # the first iteration whose estimate is over the limit is named, with the
    # counts of its mesh: every pentagonalization multiplies E by 5 and makes
    # 2E faces; duals keep the counts after an even number
    k = next(
        i
        for i in range(1, 13)
        if pentanb.subdivision._iteration_bytes(
            SCHEMES["pentagonalize"], _cube_after(i - 1), 2, later=i > 1
        )
        > 10**6
    )
    assert f"iteration {k} of 12" in msg
    V, E, F = _cube_after(k)
    got = re.search(r"([\d,]+) faces \(([\d,]+) vertices, ([\d,]+) edges\)", msg)
    assert got, msg
    assert tuple(int(x.replace(",", "")) for x in got.groups()) == (F, V, E)
    need = int(re.search(r"([\d,]+) bytes \(", msg).group(1).replace(",", ""))
    assert need > 10**6
    assert need >= 8 * 2 * _cube_after(k - 1)[1]  # more than the input's corners, twins...
    assert "1,000,000" in msg


def _cube_after(k: int) -> tuple[int, int, int]:
    """(V, E, F) of the cube after k pentagonalizations (Euler: V = 2 + E - F)."""
    E = 12 * 5**k
    F = 6 if k == 0 else 2 * 12 * 5 ** (k - 1)
    return 2 + E - F, E, F


@pytest.mark.parametrize("call", ["subdivide", "predict_counts", "max_iterations"])
@pytest.mark.parametrize("big", [10**9, 10**4, 5000, 2**64])
def test_memory_guard_answers_at_once_for_any_iteration_count(call, big, monkeypatch):
    # the default limit, fixed (not this machine's memory)
    monkeypatch.setattr(pentanb.subdivision, "default_max_bytes", lambda: 8 << 30)
    cube = shapes.cube()
    if call == "max_iterations":
        k = pentanb.max_iterations(cube, "pentagonalize", 2, max_faces=10**30, cap=big)
        assert k == 9  # stopped by the memory limit, level by level (12 * 5**10 edges: 79 GiB)
        return
    with pytest.raises(MeshError) as info:
        if call == "subdivide":
            subdivide(cube, "pentagonalize", iterations=big)
        else:
            predict_counts((8, 12, 6), "pentagonalize", big)
    msg = str(info.value)
    assert f"of {big:,}" in msg and "over the limit" in msg
    # sizes a reader can read: no 3,500-digit numbers
    assert max(len(x) for x in re.findall(r"[\d,]+", msg)) < 40
    assert re.search(r"\d(\.\d+)? (kB|MB|GB|TB|PB|EB)", msg)


def test_memory_guard_without_a_limit_still_refuses_what_no_computer_holds():
    with pytest.raises(MeshError, match="beyond what any computer can index"):
        subdivide(shapes.cube(), "pentagonalize", 10**9, max_bytes=float("inf"))
    with pytest.raises(MeshError, match="beyond what any computer can index"):
        predict_counts((8, 12, 6), "pentagonalize", 10**9, max_bytes=float("inf"))


def test_too_many_steps_are_refused_with_the_count():
    # duals and triangulate (after its first pass) do not grow the mesh: the
    # memory guard lets them through, the step limit does not
    with pytest.raises(ValueError, match=r"1,000,000,001 steps; at most 100,000"):
        subdivide(shapes.cube(), "pentagonalize", 1, duals=10**9)
    with pytest.raises(ValueError, match=r"at most 100,000"):
        predict_counts((8, 12, 6), "pentagonalize", 1, duals=10**9)
    tri = pentanb.triangulate(shapes.cube())
    with pytest.raises(ValueError, match=r"at most 100,000"):
        subdivide(tri, "triangulate", iterations=10**9)
    assert pentanb.max_iterations(tri, "triangulate", cap=10**9) == 10**9  # a fixed point


@pytest.mark.parametrize("bad", [-1, -0.5, float("nan")])
def test_max_bytes_must_be_a_positive_number(bad):
    with pytest.raises(ValueError, match="max_bytes must be a positive number"):
        subdivide(shapes.cube(), "pentagonalize", max_bytes=bad)


@pytest.mark.parametrize("bad", ["10", [10], True, object()])
def test_max_bytes_of_a_wrong_type_is_a_type_error(bad):
    with pytest.raises(TypeError, match="max_bytes must be a number"):
        subdivide(shapes.cube(), "pentagonalize", max_bytes=bad)


def test_max_bytes_infinite_means_no_limit():
    out = subdivide(shapes.cube(), "pentagonalize", 2, max_bytes=float("inf"))
    assert out.n_faces == 120
    assert subdivide(shapes.cube(), "pentagonalize", 1, max_bytes=np.float64(1e12)).n_faces == 24


def test_a_callable_scheme_is_guarded_from_its_first_iteration():
    calls = []

    def scheme(m):
        calls.append(m.n_faces)
        return pentanb.pentagonalize(m)

    with pytest.raises(MeshError) as info:
        subdivide(shapes.cube(), scheme, iterations=12)
    assert calls == [6]  # one iteration ran, then the guard refused the rest
    msg = str(info.value)
    assert "scheme" in msg and "if it grows as its last iteration did" in msg
    assert max(len(x) for x in re.findall(r"[\d,]+", msg)) < 40
    # the same request within the limit runs
    calls.clear()
    assert subdivide(shapes.cube(), scheme, 2, 2).n_faces == 120
    assert calls == [6, 24]


def test_the_callable_guard_uses_the_first_iterations_growth():
    # pentagonalize multiplies E by 5: 1,500 edges after iteration 3 need about
    # 0.4 MB as an unknown scheme's, 7,500 after iteration 4 about 1.6 MB
    with pytest.raises(MeshError, match="iteration 4 of 5 would build a mesh of about"):
        subdivide(shapes.cube(), pentanb.pentagonalize, 5, max_bytes=10**6)
    assert subdivide(shapes.cube(), pentanb.pentagonalize, 3, max_bytes=10**6).n_edges == 1500


@pytest.mark.parametrize("result", [None, "mesh", 3])
def test_a_callable_scheme_that_returns_no_mesh_is_a_type_error(result):
    def returns_something_else(m):
        return result

    with pytest.raises(
        TypeError, match=rf"scheme 'returns_something_else' returned {type(result).__name__}"
    ):
        subdivide(shapes.cube(), returns_something_else, 1, 0)


def test_estimate_bytes_without_a_scheme_is_what_a_mesh_holds():
    m = pentanb.pentagonalize(shapes.torus(10, 8))
    held = m.vertices.nbytes + m.corners.nbytes + m.offsets.nbytes + m.twin.nbytes
    held += sum(a.nbytes for a in m.vertex_ring)
    assert pentanb.subdivision.estimate_bytes(m) >= held
    assert pentanb.subdivision.estimate_bytes((m.n_vertices, m.n_edges, m.n_faces)) >= held


def test_memory_guard_lets_small_requests_through():
    m = shapes.cube()
    out = subdivide(m, "pentagonalize", iterations=1, max_bytes=10**9)
    assert out.n_faces == 24
    with pytest.raises(MeshError, match=r"iteration 1 of 1 would build a mesh of 24 faces"):
        subdivide(m, "pentagonalize", iterations=1, max_bytes=100)


def test_progress_callback_is_called_after_every_step():
    calls = []
    m = shapes.cube()
    subdivide(m, "pentagonalize", iterations=2, duals=2, progress=lambda *a: calls.append(a))
    assert [c[0] for c in calls] == [1, 2, 3, 4, 5, 6]
    assert all(c[1] == 6 for c in calls)
    assert all(isinstance(c[2], str) for c in calls)
    assert "pentagonalize" in calls[0][2] and "24 faces" in calls[0][2]
    assert "dual" in calls[1][2] and "38 faces" in calls[1][2]
    # second pentagonalization: 2 * 60 = 120 faces
    assert "120 faces" in calls[3][2]


def test_progress_true_prints_to_stderr(capsys):
    subdivide(shapes.tetrahedron(), "loop_remesh", iterations=1, duals=1, progress=True)
    err = capsys.readouterr().err
    assert "2/2" in err and "loop_remesh" in err


def test_progress_with_zero_duals():
    calls = []
    subdivide(
        shapes.cube(), "honeycomb", iterations=3, duals=0, progress=lambda *a: calls.append(a[:2])
    )
    assert calls == [(1, 3), (2, 3), (3, 3)]


@pytest.mark.parametrize("bad", [5, None, ["pentagonalize"]])
def test_subdivide_refuses_non_scheme_values(bad):
    with pytest.raises(TypeError, match=r"^scheme must be a scheme's name"):
        subdivide(shapes.cube(), bad)


# ---------------------------------------------------------------- max_iterations
@pytest.mark.parametrize(
    "call",
    [
        lambda: subdivide([[0, 0, 0]]),
        lambda: subdivide("cube", "pentagonalize"),
        lambda: smooth(np.zeros((4, 3)), 0),
        lambda: pentanb.max_iterations("cube", "pentagonalize"),
    ],
)
def test_subdivide_smooth_and_max_iterations_refuse_a_non_mesh(call):
    with pytest.raises(
        TypeError, match=r"(subdivide|smooth|max_iterations) expects a pentanb\.Mesh"
    ):
        call()


def test_max_iterations_bounds_a_slider():
    # cube: pentagonalize gives 2E faces; E grows 12 -> 60 -> 300 -> 1500 -> 7500,
    # so the faces after k iterations are 24, 120, 600, 3000, 15000 (duals swap V and F
    # in between: the duals' face counts are V' = V + 2E + F = 38, 158, ...)
    cube = shapes.cube()
    counts = (8, 12, 6)
    v, e, f = counts
    biggest = []
    for _ in range(6):
        v, e, f = v + 2 * e + f, 5 * e, 2 * e
        biggest.append(max(f, v))  # the dual in between has V faces
    for limit in (30, 200, 1000, 5000, 20000):
        expected = (
            sum(1 for b in biggest if b <= limit)
            if all(biggest[i] <= biggest[i + 1] for i in range(5))
            else None
        )
        assert pentanb.max_iterations(cube, "pentagonalize", 2, max_faces=limit) == expected
        assert pentanb.max_iterations(counts, "pentagonalize", 2, max_faces=limit) == expected


def test_max_iterations_zero_and_cap():
    cube = shapes.cube()
    assert pentanb.max_iterations(cube, "pentagonalize", max_faces=10) == 0
    assert pentanb.max_iterations(cube, "triangulate", max_faces=10**9, cap=3) == 3


def test_scheme_formula_text():
    # the paper's counts: pentagonalization V+2E+F vertices, 5E edges, 2E faces (Sec 5.1)
    assert SCHEMES["pentagonalize"].formula == "(V+2E+F, 5E, 2E)"
    assert SCHEMES["preserve_pentagons"].formula == "(V+3E, 6E, 2E+F)"
    assert SCHEMES["honeycomb"].formula == "(2E, 3E, V+F)"
    # triangulate leaves triangles alone: its formula is a bound
    assert SCHEMES["triangulate"].formula.endswith("at most (when no face is a triangle)")


@pytest.mark.parametrize("name", OPERATOR_NAMES)
def test_a_registered_schemes_estimate_is_below_an_unknown_schemes(name):
    # what a callable or a Conway string is assumed to need bounds every
    # registered scheme's estimate, from a thousand to a billion edges
    from pentanb import subdivision

    s = SCHEMES[name]
    for E in (10**3, 10**6, 10**9):
        for V, F in ((E // 3, 2 * E // 3), (E // 2, E // 2), (2 * E // 3, 2 * E // 5)):
            E2 = s.counts(V, E, F)[1]
            unknown = subdivision.FIXED + subdivision.UNKNOWN * memory.mesh_bytes(
                2 * E2 / 3, E2, 2 * E2 / 3
            )
            for duals in (0, 1, 2):
                assert subdivision.estimate_bytes((V, E, F), name, duals) <= unknown


def test_conway_notation_is_a_scheme_name():
    """Issue 10 item 5: wherever a scheme name is taken, Conway operators are too."""
    from pentanb.subdivision import get_scheme

    s = get_scheme("dg")
    assert s.name == "dg" and s.formula == "(2E, 5E, V+2E+F)"
    snub = subdivide(shapes.cube(), "dg", iterations=1, duals=0)
    assert (snub.n_vertices, snub.n_edges, snub.n_faces) == (24, 60, 38)  # snub cube sC
    assert get_scheme("k4").formula.endswith(" at most")
    with pytest.raises(ValueError, match=r"unknown scheme 'pentagonalise'.*Conway operators"):
        get_scheme("pentagonalise")


def test_a_scheme_in_conway_notation_is_guarded_too():
    # no factor of its own for "dg": an unknown scheme's, per byte of its output
    from pentanb import subdivision
    from pentanb.notation import as_scheme

    dg = as_scheme("dg")
    with pytest.raises(MeshError, match=r"^dg iteration \d+ of 1,000,000,000 would build"):
        subdivide(shapes.cube(), dg, iterations=10**9)
    need = subdivision.estimate_bytes((8, 12, 6), dg, duals=0)
    assert need >= subdivision.UNKNOWN * memory.mesh_bytes(24, 60, 38)  # sC
    assert pentanb.max_iterations(shapes.cube(), dg, duals=0, max_bytes=need) == 1
