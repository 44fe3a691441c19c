"""Bad arguments get clear errors (issue 12, items 5, 6, 8 and 10).

Wrong types get a TypeError naming the argument; wrong values a
MeshError or ValueError that says what is wrong; sizes beyond memory a
MeshError before anything is built; the command line one line and exit 2.
"""

from __future__ import annotations

import os
import re
import sys

import numpy as np
import pytest
from helpers import face_lists

import pentanb
import pentanb.cli
import pentanb.subdivision
from pentanb import Mesh, MeshError, shapes
from pentanb.mesh.boundary import boundary_loops, describe_boundary


def cube_v():
    return shapes.cube().vertices


def cube_f():
    return face_lists(shapes.cube())


# ====================================================================== Mesh: types
@pytest.mark.parametrize("bad", [None, "abc", b"abc", 5, 2.5, {"v": 1}, {1, 2}, np.float64(1)])
def test_vertices_of_a_wrong_type(bad):
    with pytest.raises(
        TypeError,
        match=rf"^vertices must be an \(n, 3\) array of numbers, got {type(bad).__name__}$",
    ):
        Mesh(bad, cube_f())


def test_complex_vertices_are_refused():
    with pytest.raises(TypeError, match=r"^vertices must be real numbers, got complex numbers$"):
        Mesh(cube_v() + 1j, cube_f())


@pytest.mark.parametrize("bad", [None, "0123", 7, {0: [0, 1, 2]}, {(0, 1, 2)}])
def test_faces_of_a_wrong_type(bad):
    with pytest.raises(
        TypeError,
        match=r"^faces must be a sequence of vertex-index sequences or an \(m, k\) int array, "
        rf"got {type(bad).__name__}$",
    ):
        Mesh(cube_v(), bad)


def test_faces_from_a_generator():
    m = Mesh(cube_v(), (f for f in cube_f()))
    assert face_lists(m) == cube_f()


# ====================================================================== Mesh: values
@pytest.mark.parametrize(
    "faces",
    [[[], [], []], np.zeros((3, 0), dtype=int), [[0, 1, 2], []], np.zeros((2, 0))],
    ids=["lists", "int-array", "one-empty", "float-array"],
)
def test_empty_faces(faces):
    f = 1 if len(faces[0]) else 0
    with pytest.raises(
        MeshError, match=rf"^face {f} has 0 vertices \[\]; a face needs at least 3 distinct"
    ):
        Mesh(cube_v(), faces)


@pytest.mark.parametrize(
    "index",
    [2**63, 2**64, -(2**63) - 1, 10**30],
)
def test_indices_no_mesh_can_have_are_reported_as_given(index):
    faces = cube_f()
    faces[2] = [0, 4, index, 1]
    with pytest.raises(
        MeshError,
        match=rf"^face 2 uses vertex index {index}, out of range \(larger than any mesh\)$",
    ):
        Mesh(cube_v(), faces)


def test_huge_indices_in_arrays():
    faces = np.array(cube_f(), dtype=np.uint64)
    faces[3, 1] = 2**63
    with pytest.raises(
        MeshError, match=r"^face 3 uses vertex index 9223372036854775808, out of range"
    ):
        Mesh(cube_v(), faces)
    faces = np.array(cube_f(), dtype=float)
    faces[4, 0] = 1e30
    with pytest.raises(MeshError, match=r"^face 4 uses vertex index 1000000000000000019884624"):
        Mesh(cube_v(), faces)


@pytest.mark.parametrize("bad", [np.nan, np.inf, 0.5])
def test_non_integer_indices_in_float_arrays(bad):
    faces = np.array(cube_f(), dtype=float)
    faces[1, 2] = bad
    with pytest.raises(MeshError, match=r"^face 1 has non-integer vertex indices .*integers$"):
        Mesh(cube_v(), faces)


@pytest.mark.parametrize("bad", [["a", "b", "c"], [True, False, True], [0, 1, None]])
def test_non_integer_indices_in_lists(bad):
    faces = cube_f() + [bad]
    with pytest.raises(MeshError, match=r"^face 6 has non-integer vertex indices"):
        Mesh(cube_v(), faces)


@pytest.mark.parametrize(
    "change, message",
    [
        (
            lambda c, o, t: (np.where(c == 5, -1, c), o, t),
            r"^corner 7 is vertex -1, outside the 8 ",
        ),
        (lambda c, o, t: (np.where(c == 5, 8, c), o, t), r"^corner 7 is vertex 8, outside the 8 "),
        (lambda c, o, t: (c, o[::-1], t), r"^offsets must start at 0, rise, and end at len"),
        (lambda c, o, t: (c, np.r_[0, 5, 3, o[3:]], t), r"^offsets must start at 0, rise,"),
        (lambda c, o, t: (c, o[:-1], t), r"^offsets must start at 0, rise, and end at len"),
        (
            lambda c, o, t: (c, o, np.r_[t[:-1], -1]),
            r"^twin of half-edge 23 is -1, outside the 24 ",
        ),
        (
            lambda c, o, t: (c, o, np.r_[t[:-1], 24]),
            r"^twin of half-edge 23 is 24, outside the 24 ",
        ),
        (lambda c, o, t: (c, o, t[:-1]), r"^twin must have one entry per corner \(24\), got 23$"),
    ],
    ids=[
        "negative",
        "past-the-end",
        "falling",
        "not-rising",
        "short",
        "twin-negative",
        "twin-past-the-end",
        "twin-short",
    ],
)
def test_unchecked_arrays_still_have_their_indices_checked(change, message):
    # from_csr(validate=False) trusts the mesh, not the indices: an index
    # outside the arrays would make the compiled kernels read outside them
    c = shapes.cube()
    corners, offsets, twin = change(c.corners.copy(), c.offsets.copy(), c.twin.copy())
    with pytest.raises(MeshError, match=message):
        Mesh.from_csr(c.vertices, corners, offsets, twin=twin, validate=False)
    # the same arrays with the index put back are taken
    Mesh.from_csr(c.vertices, c.corners, c.offsets, twin=c.twin, validate=False)


@pytest.mark.parametrize("validate", [True, False])
def test_from_csr_does_not_truncate_non_integers(validate):
    c = shapes.cube()
    with pytest.raises(MeshError, match=r"^corners has non-integer values \[0\.5, "):
        Mesh.from_csr(c.vertices, c.corners + 0.5, c.offsets, validate=validate)
    with pytest.raises(MeshError, match=r"^offsets has non-integer values"):
        Mesh.from_csr(c.vertices, c.corners, c.offsets + 0.25, validate=validate)
    big = c.corners.astype(np.uint64)
    big[0] = 2**63
    with pytest.raises(MeshError, match=r"^corners uses value 9223372036854775808, out of range"):
        Mesh.from_csr(c.vertices, big, c.offsets, validate=validate)
    with pytest.raises(TypeError, match=r"^corners must be an array of integers, got NoneType$"):
        Mesh.from_csr(c.vertices, None, c.offsets, validate=validate)
    # whole numbers as floats are taken
    m = Mesh.from_csr(c.vertices, c.corners.astype(float), c.offsets, validate=validate)
    assert face_lists(m) == face_lists(c)


# ====================================================================== boundary loops
def _without(m: Mesh, drop) -> list[list[int]]:
    return [f for i, f in enumerate(face_lists(m)) if i not in drop]


@pytest.mark.parametrize(
    "shape, drop, loops",
    [
        ("cube", [5], "1 boundary loop (4 edges)"),
        ("cube", [0, 1], "2 boundary loops (4 and 4 edges)"),
        ("cube", [0, 2], "1 boundary loop (6 edges)"),
    ],
)
def test_an_open_mesh_is_taken_and_a_closed_only_measure_counts_its_loops(shape, drop, loops):
    m = shapes.get(shape)
    open_mesh = Mesh(m.vertices, _without(m, drop))
    assert describe_boundary(open_mesh.corners, open_mesh.head) == loops
    with pytest.raises(
        MeshError, match=rf"^volume needs a closed mesh; this one is open: {re.escape(loops)}$"
    ):
        _ = open_mesh.volume


def test_boundary_loops_of_a_torus_cut_open_and_of_many_holes():
    t = shapes.torus(6, 4)
    ring = list(range(4))  # the faces of ring 0: a cylinder is left
    c, o = t.corners, t.offsets
    keep = np.concatenate([c[o[f] : o[f + 1]] for f in range(t.n_faces) if f not in ring])
    nxt = np.concatenate(
        [np.roll(c[o[f] : o[f + 1]], -1) for f in range(t.n_faces) if f not in ring]
    )
    assert boundary_loops(keep, nxt) == [4, 4]
    # three faces that share no corner removed: three loops (faces that touch at a
    # corner would make one chain)
    holes = [0, 10, 17]
    keep = np.concatenate([c[o[f] : o[f + 1]] for f in range(t.n_faces) if f not in holes])
    nxt = np.concatenate(
        [np.roll(c[o[f] : o[f + 1]], -1) for f in range(t.n_faces) if f not in holes]
    )
    assert boundary_loops(keep, nxt) == [4, 4, 4]
    assert describe_boundary(keep, nxt) == "3 boundary loops (4, 4 and 4 edges)"
    assert boundary_loops(t.corners, t.head) == []
    assert describe_boundary(t.corners, t.head) == "no boundary"


def test_describe_boundary_of_many_loops():
    # seven separate triangles: seven loops of 3
    tail = np.arange(21)
    head = tail.reshape(7, 3)[:, [1, 2, 0]].ravel()
    assert describe_boundary(tail, head) == "7 boundary loops (3, 3, 3, 3, 3, ... 21 in all edges)"


# ====================================================================== subdivide, counts
def test_a_callable_scheme_must_return_a_mesh():
    with pytest.raises(
        TypeError, match=r"^scheme '<lambda>' returned NoneType, not a pentanb\.Mesh"
    ):
        pentanb.subdivide(shapes.cube(), lambda m: None, 1, 0)

    def halve(m):
        return m.n_faces // 2

    with pytest.raises(TypeError, match=r"^scheme 'halve' returned int, not a pentanb\.Mesh"):
        pentanb.subdivide(shapes.cube(), halve, 1, 0)


def test_max_iterations_takes_the_counts_its_docs_promise():
    cube = shapes.cube()
    expected = pentanb.max_iterations(cube, "pentagonalize")
    for counts in [(8, 12, 6), [8, 12, 6], np.array([8, 12, 6]), (np.int64(8), 12, 6)]:
        assert pentanb.max_iterations(counts, "pentagonalize") == expected


@pytest.mark.parametrize(
    "counts, error, message",
    [
        (None, TypeError, r"^max_iterations expects a pentanb\.Mesh or its counts \(V, E, F\), "),
        ("cube", TypeError, r"^max_iterations expects a pentanb\.Mesh or its counts"),
        ((8, 12), ValueError, r"^counts must be \(V, E, F\), three numbers; got 2$"),
        (("a", 12, 6), TypeError, r"^V must be an integer >= 0, got str 'a'$"),
        ((8, -12, 6), ValueError, r"^E must be an integer >= 0, got -12$"),
        ((8, 12, 6.5), TypeError, r"^F must be an integer >= 0, got float 6\.5$"),
    ],
)
def test_max_iterations_refuses_bad_counts(counts, error, message):
    with pytest.raises(error, match=message):
        pentanb.max_iterations(counts, "pentagonalize")


def test_predict_counts_refuses_a_non_sequence():
    with pytest.raises(
        TypeError,
        match=r"^predict_counts expects a pentanb\.Mesh or its counts \(V, E, F\), got NoneType",
    ):
        pentanb.predict_counts(None, "pentagonalize")


# ====================================================================== shapes
@pytest.mark.parametrize("inset", [1.5, -0.5, 2, 0, 1, 0.0, 1.0, float("nan"), float("inf")])
def test_hard_edged_cube_refuses_an_inset_outside_0_1(inset):
    with pytest.raises(
        ValueError, match=rf"^inset must be in \(0, 1\), got {re.escape(repr(inset))}"
    ):
        shapes.hard_edged_cube(inset)


@pytest.mark.parametrize("inset", ["0.5", None, True, [0.5]])
def test_hard_edged_cube_refuses_a_non_number(inset):
    with pytest.raises(TypeError, match=r"^inset must be a number in \(0, 1\), got "):
        shapes.hard_edged_cube(inset)


@pytest.mark.parametrize("inset", [0.01, 1 / 3, 0.8, 0.99])
def test_hard_edged_cube_faces_all_point_outwards(inset):
    m = shapes.hard_edged_cube(inset)
    outward = np.einsum("ij,ij->i", m.face_normals, m.face_centroids)
    assert np.all(outward > 0) and m.volume == pytest.approx(8.0)


def test_genus_surface_refuses_a_base_that_is_not_a_torus():
    with pytest.raises(
        TypeError, match=r"^base must be a pentanb\.Mesh \(a torus\) or None, got str"
    ):
        shapes.genus_surface(2, base="torus")
    with pytest.raises(ValueError, match=r"^base must be a connected torus \(genus 1\): .*genus 0"):
        shapes.genus_surface(2, base=shapes.cube())
    with pytest.raises(ValueError, match=r"^base must be a connected torus .*genus 2 with 1"):
        shapes.genus_surface(2, base=shapes.double_torus())
    with pytest.raises(ValueError, match=r"^base must be a connected torus .*genus 0"):
        shapes.genus_surface(1, base=shapes.cube())  # returned the cube as "genus 1" before
    assert shapes.genus_surface(3, base=shapes.torus(6, 4)).genus == 3


@pytest.mark.parametrize(
    "build, what",
    [
        (lambda: shapes.torus(10**5, 10**5), "torus(100000, 100000)"),
        (lambda: shapes.hexagonal_torus(10**5, 10**5), "hexagonal_torus(100000, 100000)"),
        (lambda: shapes.genus_surface(10**6), "genus_surface(1000000)"),
        (lambda: shapes.torus(10**20, 3), "torus(100000000000000000000, 3)"),
    ],
)
def test_shapes_too_large_for_memory_are_refused_before_building(build, what):
    with pytest.raises(
        MeshError,
        match=rf"^{re.escape(what)} would build a mesh of [\d,]+ faces .* over the limit of "
        r"[\d,]+ bytes \(the memory available\)$",
    ):
        build()


def test_the_shape_size_guard_uses_the_default_limit(monkeypatch):
    monkeypatch.setattr(pentanb.shapes, "default_max_bytes", lambda: 100_000)
    assert shapes.torus(10, 10).n_faces == 100  # 100 quads: about 8 kB
    with pytest.raises(MeshError, match=r"torus\(40, 40\) would build .* limit of 100,000 bytes"):
        shapes.torus(40, 40)
    with pytest.raises(MeshError, match=r"genus_surface\(20\) would build"):
        shapes.genus_surface(20)


@pytest.mark.parametrize("radius, tube", [("1", 0.4), (1.0, None), (True, 0.4)])
def test_torus_radii_must_be_numbers(radius, tube):
    with pytest.raises(TypeError, match=r"^(radius|tube) must be a number, got "):
        shapes.torus(radius=radius, tube=tube)


# ====================================================================== the command line
def _one_line_error(capsys, argv, match, progress=0):
    """Exit 2 and one line of error (after ``progress`` lines of progress), no traceback."""
    code = pentanb.cli.main(argv)
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.strip().splitlines()) == 1 + progress, err
    assert "Traceback" not in err
    assert re.search(match, err.strip().splitlines()[-1]), err


def test_figures_out_empty_is_refused(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _one_line_error(
        capsys,
        ["figures", "--out", "", "--only", "7"],
        r"^pentanb figures: --out needs a folder name \(use --out \. for the current folder\)$",
    )
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="needs Linux /proc")
@pytest.mark.parametrize("folder", ["/proc/self", "/sys"])
def test_figures_into_a_virtual_file_system(capsys, folder):
    _one_line_error(
        capsys, ["figures", "--out", folder, "--only", "7"], rf"cannot write into {folder}: "
    )


def test_figures_into_a_read_only_folder(capsys, tmp_path, monkeypatch):
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o555)
    if os.access(folder, os.W_OK):  # root writes anyway: make the refusal happen
        import tempfile

        def refuse(*args, **kwargs):
            raise PermissionError(13, "Permission denied")

        monkeypatch.setattr(tempfile, "TemporaryFile", refuse)
    _one_line_error(
        capsys,
        ["figures", "--out", str(folder), "--only", "7"],
        rf"^pentanb figures: cannot write into {re.escape(str(folder))}: Permission denied$",
    )
    assert list(folder.iterdir()) == []


def test_figures_a_write_failure_while_drawing(capsys, tmp_path, monkeypatch):
    import pentanb.figures

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(pentanb.figures, "render_all", full)
    _one_line_error(
        capsys,
        ["figures", "--out", str(tmp_path), "--only", "7"],
        r"cannot write into .*: No space left on device$",
        progress=1,
    )


@pytest.mark.parametrize("name", ["²", "fig99", "7.5", ""])
def test_figures_only_an_unknown_name(capsys, tmp_path, name):
    _one_line_error(
        capsys,
        ["figures", "--out", str(tmp_path), "--only", name],
        r"^pentanb figures: unknown figure '.*'; known: fig01, ",
    )
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_figures_errors_in_a_subprocess_are_one_line(tmp_path):
    import subprocess

    done = subprocess.run(
        [sys.executable, "-m", "pentanb", "figures", "--only", "²", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": os.getcwd()},
    )
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize(
    "max_bytes, error, message",
    [
        (float("nan"), ValueError, r"^max_bytes must be a positive number of bytes, got nan$"),
        (-1, ValueError, r"^max_bytes must be a positive number of bytes, got -1$"),
        (0, ValueError, r"^max_bytes must be a positive number of bytes, got 0$"),
        ("1e9", TypeError, r"^max_bytes must be a number of bytes, got str$"),
        (True, TypeError, r"^max_bytes must be a number of bytes, got bool$"),
    ],
)
def test_subdivide_max_bytes_must_be_a_positive_number(max_bytes, error, message):
    with pytest.raises(error, match=message):
        pentanb.subdivide(shapes.cube(), "pentagonalize", 1, max_bytes=max_bytes)


def test_subdivide_max_bytes_infinite_means_no_limit():
    # float("inf") raised OverflowError (int(inf)); now it lifts the limit
    m = pentanb.subdivide(shapes.cube(), "pentagonalize", 2, max_bytes=float("inf"))
    assert m.n_faces == 120
    with pytest.raises(MeshError, match=r"over the limit of 1,000 bytes"):
        pentanb.subdivide(shapes.cube(), "pentagonalize", 2, max_bytes=1e3)
