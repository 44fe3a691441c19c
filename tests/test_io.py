"""Tests of :mod:`pentanb.io`: OBJ and OFF, exact round trips and precise errors."""

from __future__ import annotations

import os
import pathlib
import re
import stat

import numpy as np
import pytest
from helpers import face_lists

import pentanb.io.off
from pentanb import MeshError, read, shapes, write
from pentanb.io import read_obj, read_off, write_obj, write_off

CUBE_OBJ_FACES = [
    [1, 2, 4, 3],
    [5, 7, 8, 6],
    [1, 5, 6, 2],
    [3, 4, 8, 7],
    [1, 3, 7, 5],
    [2, 6, 8, 4],
]


def cube_v_lines():
    return [f"v {x} {y} {z}" for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]


def esc(path) -> str:
    """A path as a regular expression matching itself."""
    return re.escape(str(path))


def write_text(path, lines):
    path.write_text("\n".join(lines) + "\n")
    return path


def expected_cube():
    return shapes.cube()


# ====================================================================== round trips
@pytest.mark.parametrize("ext", [".obj", ".off", ".OBJ", ".Off"])
def test_round_trip_is_exact(tmp_path, corpus_mesh, ext):
    m = corpus_mesh
    path = tmp_path / f"mesh{ext}"
    write(m, path)
    back = read(path)
    assert back.vertices.tobytes() == m.vertices.tobytes()  # bitwise
    assert face_lists(back) == face_lists(m)
    assert not list(tmp_path.glob("*.part"))


def test_round_trip_of_awkward_numbers(tmp_path):
    m = shapes.cube()
    v = m.vertices * np.array([1 / 3, 1e-300, 1e300]) + [0.1, -0.0, 5e-324]
    m = m.with_vertices(v)
    for ext in (".obj", ".off"):
        write(m, tmp_path / f"x{ext}")
        assert read(tmp_path / f"x{ext}").vertices.tobytes() == v.tobytes()


def test_write_accepts_str_paths(tmp_path):
    path = str(tmp_path / "c.obj")
    write(shapes.cube(), path)
    assert face_lists(read(path)) == face_lists(shapes.cube())


def test_written_obj_is_one_based_and_off_has_counts(tmp_path):
    write(shapes.tetrahedron(), tmp_path / "t.obj")
    lines = (tmp_path / "t.obj").read_text().splitlines()
    f_lines = [l for l in lines if l.startswith("f ")]
    assert len(f_lines) == 4
    assert min(int(x) for l in f_lines for x in l.split()[1:]) == 1
    write(shapes.cube(), tmp_path / "c.off")
    lines = (tmp_path / "c.off").read_text().splitlines()
    assert lines[0] == "OFF" and lines[1].split() == ["8", "6", "12"]
    assert lines[2 + 8].split()[0] == "4"


def test_write_obj_and_write_off_write_exactly_the_path_given(tmp_path):
    # the old write_obj(m, "model.v2") silently wrote model.obj
    write_obj(shapes.cube(), tmp_path / "model.v2")
    write_off(shapes.cube(), tmp_path / "b.txt")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.txt", "model.v2"]
    assert face_lists(read_obj(tmp_path / "model.v2")) == face_lists(shapes.cube())
    assert face_lists(read_off(tmp_path / "b.txt")) == face_lists(shapes.cube())
    assert (tmp_path / "model.v2").read_text().startswith("# pentanb")
    assert (tmp_path / "b.txt").read_text().startswith("OFF\n")


@pytest.mark.parametrize("fmt", ["obj", "off", "OBJ", ".off"])
def test_write_and_read_with_an_explicit_format(tmp_path, fmt):
    path = tmp_path / "model.v2"
    write(shapes.dodecahedron(), path, format=fmt)
    assert [p.name for p in tmp_path.iterdir()] == ["model.v2"]
    back = read(path, format=fmt)
    assert face_lists(back) == face_lists(shapes.dodecahedron())
    assert back.vertices.tobytes() == shapes.dodecahedron().vertices.tobytes()
    # the other format's reader refuses the file
    other = "off" if fmt.lower().lstrip(".") == "obj" else "obj"
    with pytest.raises(MeshError):
        read(path, format=other)


@pytest.mark.parametrize("name", ["model.v2", "model", "model.obj.bak", "model.3mf"])
def test_write_refuses_an_unknown_suffix_before_writing(tmp_path, name):
    suffix = pathlib.Path(name).suffix
    shown = repr(suffix) if suffix else "no suffix"
    with pytest.raises(ValueError, match=re.escape(shown) + r".*\.obj, \.off, \.ply, \.stl"):
        write(shapes.cube(), tmp_path / name)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "call",
    [
        lambda p: write(shapes.cube(), p / "x.off", format="obj"),
        lambda p: write(shapes.cube(), p / "x.OBJ", format="off"),
        lambda p: write_obj(shapes.cube(), p / "x.off"),
        lambda p: write_off(shapes.cube(), p / "x.obj"),
    ],
)
def test_write_refuses_a_format_that_contradicts_the_suffix(tmp_path, call):
    with pytest.raises(ValueError, match=r"the name ends in '\.(obj|off|OBJ)' but format="):
        call(tmp_path)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("fmt", ["3mf", "", "objx", 3])
def test_write_and_read_refuse_an_unknown_format(tmp_path, fmt):
    known = r"known formats: obj, off, ply, stl"
    with pytest.raises(ValueError, match=r"unknown mesh format .*" + known):
        write(shapes.cube(), tmp_path / "x.obj", format=fmt)
    assert list(tmp_path.iterdir()) == []
    write(shapes.cube(), tmp_path / "x.obj")
    with pytest.raises(ValueError, match=r"unknown mesh format .*" + known):
        read(tmp_path / "x.obj", format=fmt)


def test_write_refuses_a_non_mesh_before_writing(tmp_path):
    with pytest.raises(TypeError, match=r"write expects a pentanb\.Mesh, got list"):
        write([[0, 0, 0]], tmp_path / "x.obj")
    assert list(tmp_path.iterdir()) == []


# ====================================================================== OBJ reading
def test_obj_with_slashes_negative_indices_and_other_lines(tmp_path):
    lines = ["# a cube", "mtllib cube.mtl", "o cube", "g box", "s 1", ""]
    lines += cube_v_lines()
    lines += [
        "vn 0 0 1",
        "vt 0.5 0.5",
        "usemtl red",
        "f 1/1/1 2/2/2 4/3/3 3/4/4",  # v/vt/vn
        "f 5//1 7//1 8//1 6//1",  # v//vn
        "f 1/1 5/2 6/3 2/4  # an inline comment",
        "f -6 -5 -1 -2",  # relative: 3 4 8 7
        "f 1 3 7 5",
        "f 2 6 8 4",
        "",
        "   ",
    ]
    m = read(write_text(tmp_path / "cube.obj", lines))
    assert face_lists(m) == [[i - 1 for i in f] for f in CUBE_OBJ_FACES]
    assert np.array_equal(m.vertices, shapes.cube().vertices)


def test_obj_negative_indices_are_relative_to_vertices_so_far(tmp_path):
    lines = [
        "v 0 0 0",
        "v 1 0 0",
        "v 0 1 0",
        "f -3 -1 -2",  # (0, 2, 1)
        "v 0 0 1",
        "f -4 -3 -1",
        "f -3 -2 -1",
        "f -4 -1 -2",
    ]  # (0,1,3) (1,2,3) (0,3,2)
    m = read(write_text(tmp_path / "t.obj", lines))
    assert face_lists(m) == [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]


def test_obj_extra_vertex_components_are_ignored(tmp_path):
    # "v x y z w" and "v x y z r g b" (vertex colours) keep x, y, z
    lines = [l + " 1.0 0.5 0.25" for l in cube_v_lines()]
    lines += ["f " + " ".join(map(str, f)) for f in CUBE_OBJ_FACES]
    m = read(write_text(tmp_path / "c.obj", lines))
    assert np.array_equal(m.vertices, shapes.cube().vertices)


def _cube_obj_lines():
    return cube_v_lines() + ["f " + " ".join(map(str, f)) for f in CUBE_OBJ_FACES]


def test_obj_bad_number_names_file_and_line(tmp_path):
    lines = _cube_obj_lines()
    lines[2] = "v 1 x 3"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:3: bad number in 'v 1 x 3'"):
        read(path)


def test_obj_short_vertex_line(tmp_path):
    lines = _cube_obj_lines()
    lines[4] = "v 1 2"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:5: a 'v' line needs 3 coordinates"):
        read(path)


def test_obj_face_index_out_of_range(tmp_path):
    lines = _cube_obj_lines()
    lines[10] = "f 5 7 9 6"  # line 11: only 8 vertices
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(
        MeshError,
        match=rf"{esc(path)}:11: face index 9 out of range "
        r"\(8 vertices in the file\)",
    ):
        read(path)


def test_obj_negative_index_out_of_range(tmp_path):
    lines = _cube_obj_lines()
    lines[9] = "f -9 -7 -5 -6"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:10: face index -9 out of range"):
        read(path)


def test_obj_zero_index(tmp_path):
    lines = _cube_obj_lines()
    lines[12] = "f 0 1 2 3"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:13: face index 0 \(OBJ counts from 1\)"):
        read(path)


def test_obj_bad_face_token(tmp_path):
    lines = _cube_obj_lines()
    lines[8] = "f 1 two 4 3"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:9: bad face index 'two'"):
        read(path)


def test_obj_without_faces(tmp_path):
    path = write_text(tmp_path / "empty.obj", cube_v_lines())
    with pytest.raises(MeshError, match=rf"{esc(path)}: no faces"):
        read(path)


def test_obj_non_manifold_raises_the_mesh_message_prefixed_with_the_file(tmp_path):
    lines = _cube_obj_lines()
    lines[-1] = "f " + " ".join(reversed(lines[-1].split()[1:]))  # the last face flipped
    path = write_text(tmp_path / "flipped.obj", lines)
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}: directed edge \(\d+, \d+\) is used by faces \[\d+, \d+\]: "
        r"inconsistent orientation",
    ):
        read(path)


def test_obj_with_a_nan_coordinate(tmp_path):
    lines = _cube_obj_lines()
    lines[6] = "v nan 1 -1"
    path = write_text(tmp_path / "nan.obj", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}:7: vertex 6 has a non-finite coordinate"):
        read(path)


def test_obj_with_a_two_vertex_face(tmp_path):
    lines = _cube_obj_lines() + ["f 1 2"]
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}: face 6 has 2 vertices"):
        read(path)


# ====================================================================== OFF reading
def _cube_off_lines():
    lines = ["OFF", "8 6 12"]
    lines += [l[2:] for l in cube_v_lines()]
    lines += ["4 " + " ".join(str(i - 1) for i in f) for f in CUBE_OBJ_FACES]
    return lines


def test_off_reads_the_cube(tmp_path):
    m = read(write_text(tmp_path / "c.off", _cube_off_lines()))
    assert face_lists(m) == face_lists(shapes.cube())
    assert np.array_equal(m.vertices, shapes.cube().vertices)


def test_off_counts_on_the_header_line_and_comments(tmp_path):
    lines = _cube_off_lines()
    lines = ["OFF 8 6 12  # counts here", "# a comment", ""] + lines[2:]
    lines[5] = lines[5] + "   # trailing comment"
    m = read(write_text(tmp_path / "c.off", lines))
    assert face_lists(m) == face_lists(shapes.cube())


def test_off_missing_header(tmp_path):
    path = write_text(tmp_path / "bad.off", _cube_off_lines()[1:])
    with pytest.raises(MeshError, match=rf"{esc(path)}:1: not an OFF file \(no 'OFF' header\)"):
        read(path)


def test_off_empty_file(tmp_path):
    path = write_text(tmp_path / "empty.off", [])
    with pytest.raises(MeshError, match="not an OFF file"):
        read(path)


def test_off_missing_counts(tmp_path):
    path = write_text(tmp_path / "bad.off", ["OFF"])
    with pytest.raises(MeshError, match=rf"{esc(path)}: missing the vertex and face counts"):
        read(path)


def test_off_bad_counts_line(tmp_path):
    lines = _cube_off_lines()
    lines[1] = "8 six 12"
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:2: bad counts line '8 six 12'"):
        read(path)


def test_off_count_mismatch(tmp_path):
    lines = _cube_off_lines()[:-1]  # header says 6 faces, 5 given
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(
        MeshError,
        match=rf"{esc(path)}: header says 8 vertices and 6 faces "
        r"\(14 lines\) but the file has 13 data lines",
    ):
        read(path)


def test_off_bad_vertex_line(tmp_path):
    lines = _cube_off_lines()
    lines[4] = "1.0 nope 1.0"  # line 5
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:5: bad vertex line '1.0 nope 1.0'"):
        read(path)


def test_off_short_vertex_line(tmp_path):
    lines = _cube_off_lines()
    lines[3] = "1.0 1.0"  # line 4
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:4: bad vertex line"):
        read(path)


def test_off_bad_face_line(tmp_path):
    lines = _cube_off_lines()
    lines[11] = "4 0 x 3 2"  # line 12
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:12: bad face line '4 0 x 3 2'"):
        read(path)


def test_off_face_with_too_few_indices(tmp_path):
    lines = _cube_off_lines()
    lines[10] = "4 0 1 3"  # line 11
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"{esc(path)}:11: face says 4 vertices but lists 3"):
        read(path)


def test_off_face_index_out_of_range(tmp_path):
    lines = _cube_off_lines()
    lines[13] = "4 1 5 8 3"  # line 14
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(
        MeshError,
        match=rf"{esc(path)}:14: face index 8 out of range "
        r"\(8 vertices\)",
    ):
        read(path)


def test_off_non_manifold_raises_the_mesh_message_prefixed_with_the_file(tmp_path):
    lines = _cube_off_lines()
    lines[-1] = "4 " + " ".join(reversed(lines[-1].split()[1:]))  # the last face flipped
    path = write_text(tmp_path / "flipped.off", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}: directed edge .* inconsistent"):
        read(path)


# ====================================================================== file names, failures
@pytest.mark.parametrize("name", ["mesh.3mf", "mesh", "mesh.obj.bak"])
def test_unknown_extension(tmp_path, name):
    path = tmp_path / name
    path.write_text("")
    with pytest.raises(ValueError, match="unknown mesh format"):
        read(path)
    with pytest.raises(ValueError, match="unknown mesh format"):
        write(shapes.cube(), path)


def test_write_into_a_missing_directory_leaves_nothing(tmp_path):
    target = tmp_path / "no" / "such" / "dir" / "m.obj"
    with pytest.raises(OSError):
        write(shapes.cube(), target)
    assert not (tmp_path / "no").exists()
    assert list(tmp_path.iterdir()) == []


def test_write_over_a_directory_leaves_no_partial_file(tmp_path):
    target = tmp_path / "m.obj"
    target.mkdir()
    with pytest.raises(ValueError, match="is not a regular file"):
        write(shapes.cube(), target)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.obj"]
    assert target.is_dir()


def test_write_leaves_a_file_named_like_its_temporary_alone(tmp_path):
    (tmp_path / "model.obj.part").write_text("notes")
    (tmp_path / "model.obj.tmp").write_text("more notes")
    write(shapes.cube(), tmp_path / "model.obj")
    assert (tmp_path / "model.obj.part").read_text() == "notes"
    assert (tmp_path / "model.obj.tmp").read_text() == "more notes"
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "model.obj",
        "model.obj.part",
        "model.obj.tmp",
    ]


def test_rewriting_a_file_keeps_its_permissions(tmp_path):
    target = tmp_path / "m.off"
    write(shapes.tetrahedron(), target)
    target.chmod(0o600)
    write(shapes.cube(), target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o600
    assert read(target).n_faces == 6


def test_a_fifo_is_refused_not_replaced(tmp_path):
    fifo = tmp_path / "pipe.obj"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match="is not a regular file"):
        write(shapes.cube(), fifo)
    assert stat.S_ISFIFO(fifo.stat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe.obj"]


def test_a_name_at_the_length_limit_is_written(tmp_path):
    target = tmp_path / ("m" * 251 + ".obj")  # 255 bytes, the usual limit
    write(shapes.cube(), target)
    assert read(target).n_faces == 6
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]


def test_failed_write_keeps_the_old_file_and_leaves_no_part(tmp_path, monkeypatch):
    target = tmp_path / "m.off"
    write(shapes.tetrahedron(), target)
    old = target.read_text()

    def half_then_fail(fh, vertices, prefix):
        fh.write(b"1.0 2.0")
        raise OSError("disk full")

    monkeypatch.setattr(pentanb.io.off, "write_vertices", half_then_fail)
    with pytest.raises(OSError, match="disk full"):
        write(shapes.cube(), target)
    monkeypatch.undo()
    assert target.read_text() == old
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.off"]


def test_write_replaces_an_existing_file(tmp_path):
    target = tmp_path / "m.obj"
    write(shapes.tetrahedron(), target)
    write(shapes.cube(), target)
    assert face_lists(read(target)) == face_lists(shapes.cube())
    assert os.listdir(tmp_path) == ["m.obj"]


def test_obj_face_may_refer_to_a_vertex_defined_later(tmp_path):
    # OBJ readers commonly accept faces before the vertices they use
    lines = [
        "f 1 2 3",
        "f 1 3 4",
        "f 1 4 2",
        "f 2 4 3",
        "v 1 1 1",
        "v 1 -1 -1",
        "v -1 1 -1",
        "v -1 -1 1",
    ]
    path = write_text(tmp_path / "late.obj", lines)
    m = read(path)
    assert (m.n_vertices, m.n_edges, m.n_faces) == (4, 6, 4)
    assert m.faces[0].tolist() == [0, 1, 2]


def test_obj_relative_index_before_first_vertex(tmp_path):
    path = write_text(tmp_path / "rel.obj", ["v 0 0 0", "f -1 -2 -3"])
    with pytest.raises(MeshError, match=rf"{esc(path)}:2: face index -2 out of range"):
        read(path)


# ====================================================================== paths and options
@pytest.mark.parametrize("bad", [None, 3, ["x.obj"]])
def test_read_and_write_refuse_a_non_path(tmp_path, bad):
    with pytest.raises(TypeError, match=r"read expects a file path \(str or os.PathLike\), got"):
        read(bad)
    with pytest.raises(TypeError, match=r"write expects a file path \(str or os.PathLike\), got"):
        write(shapes.cube(), bad)


def test_write_checks_the_mesh_before_the_path(tmp_path):
    with pytest.raises(TypeError, match=r"write expects a pentanb\.Mesh, got NoneType"):
        write(None, tmp_path / "x.obj")
    with pytest.raises(TypeError, match=r"write expects a pentanb\.Mesh, got str"):
        write("cube", None)


def test_options_a_format_does_not_take_are_refused_before_writing(tmp_path):
    with pytest.raises(TypeError, match=r"write: format 'obj' takes no options; got ascii"):
        write(shapes.cube(), tmp_path / "x.obj", ascii=True)
    with pytest.raises(TypeError, match=r"format 'ply' takes ascii, byteorder; got binary"):
        write(shapes.cube(), tmp_path / "x.ply", binary=True)
    assert list(tmp_path.iterdir()) == []
    write(shapes.cube(), tmp_path / "x.obj")
    with pytest.raises(TypeError, match=r"read: format 'obj' takes no options; got tolerance"):
        read(tmp_path / "x.obj", tolerance=0.1)


def test_a_read_mesh_pickles_and_deep_copies_sealed(tmp_path):
    import copy
    import pickle

    from helpers import check_sealed

    write(shapes.dodecahedron(), tmp_path / "d.off")
    m = read(tmp_path / "d.off")
    for back in (pickle.loads(pickle.dumps(m)), copy.deepcopy(m)):
        assert back.vertices.tobytes() == m.vertices.tobytes()
        assert face_lists(back) == face_lists(m)
        check_sealed(back)


# ====================================================================== encodings
def test_obj_with_a_utf8_byte_order_mark_keeps_its_first_vertex(tmp_path):
    # the BOM used to glue itself to the first "v", which was then skipped
    path = tmp_path / "bom.obj"
    path.write_bytes(b"\xef\xbb\xbf" + "\n".join(_cube_obj_lines()).encode() + b"\n")
    m = read(path)
    assert np.array_equal(m.vertices, shapes.cube().vertices)
    assert face_lists(m) == face_lists(shapes.cube())


def test_off_with_a_utf8_byte_order_mark(tmp_path):
    path = tmp_path / "bom.off"
    path.write_bytes(b"\xef\xbb\xbf" + "\n".join(_cube_off_lines()).encode())
    assert face_lists(read(path)) == face_lists(shapes.cube())


def test_latin1_bytes_in_comments_and_names_are_fine(tmp_path):
    obj = b"# mod\xe8le \xe9t\xe9\no cub\xe9\ng gr\xfcn\nusemtl m\xe9tal\n"
    obj += "\n".join(_cube_obj_lines()).encode() + b"  # fin \xff\n"
    (tmp_path / "l.obj").write_bytes(obj)
    off = b"OFF # \xe9\n" + "\n".join(_cube_off_lines()[1:]).encode() + b" # \xe9\xff\n"
    (tmp_path / "l.off").write_bytes(off)
    for name in ("l.obj", "l.off"):
        assert face_lists(read(tmp_path / name)) == face_lists(shapes.cube())


def test_undecodable_bytes_in_a_bad_line_are_shown_replaced(tmp_path):
    lines = [l.encode() for l in _cube_obj_lines()]
    lines[3] = b"v 1 \xff\xfe 3"
    path = tmp_path / "bad.obj"
    path.write_bytes(b"\n".join(lines) + b"\n")
    with pytest.raises(MeshError, match=rf"^{esc(path)}:4: bad number in 'v 1 \ufffd\ufffd 3'$"):
        read(path)


@pytest.mark.parametrize("ext", [".obj", ".off"])
def test_binary_garbage_names_the_file_and_line(tmp_path, ext):
    path = tmp_path / f"garbage{ext}"
    rng = np.random.default_rng(1)
    junk = rng.integers(1, 256, 3000, dtype=np.uint8).tobytes()
    junk = junk.replace(b"\n", b" ").replace(b"\r", b" ")  # CR, too, ends a line
    head = b"OFF\n8 6 12\n" if ext == ".off" else b"# junk\nv 1 2 3\n"
    path.write_bytes(head + junk + b"\x00\x01\x02\n" + junk)
    kind = ext[1:].upper()
    what = r"a NUL byte: a binary file \(or UTF-16 text\), not "
    with pytest.raises(MeshError, match=rf"^{esc(path)}:3: {what}{kind} text$"):
        read(path)


def test_utf16_text_is_named_as_such(tmp_path):
    path = tmp_path / "u16.obj"
    path.write_bytes("\n".join(_cube_obj_lines()).encode("utf-16"))
    with pytest.raises(MeshError, match=rf"^{esc(path)}:1: a NUL byte: .*UTF-16"):
        read(path)


def test_a_line_too_long_for_a_text_mesh_file(tmp_path, monkeypatch):
    monkeypatch.setattr(pentanb.io._common, "MAX_LINE_BYTES", 10_000)
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", 4096)
    path = tmp_path / "long.obj"
    path.write_bytes(b"v 1 2 3\n" + b"v 1 2 3 " * 5000)
    with pytest.raises(MeshError, match=rf"^{esc(path)}:2: a line longer than 10,000 bytes"):
        read(path)


@pytest.mark.parametrize("newline", [b"\r\n", b"\r", b"\n"])
@pytest.mark.parametrize("ext", [".obj", ".off"])
def test_line_endings(tmp_path, ext, newline):
    lines = _cube_obj_lines() if ext == ".obj" else _cube_off_lines()
    path = tmp_path / f"c{ext}"
    path.write_bytes(newline.join(l.encode() for l in lines) + newline)
    m = read(path)
    assert face_lists(m) == face_lists(shapes.cube())
    assert np.array_equal(m.vertices, shapes.cube().vertices)


# ====================================================================== large and damaged files
def _count_blocks(monkeypatch, module):
    """Count the blocks ``module`` reads (its ``line_blocks`` wrapped)."""
    seen = []
    real = module.line_blocks

    def counting(*args, **kwargs):
        for item in real(*args, **kwargs):
            seen.append(item[0])
            yield item

    monkeypatch.setattr(module, "line_blocks", counting)
    return seen


def test_off_with_more_data_than_its_header_fails_at_the_first_extra_line(tmp_path, monkeypatch):
    # a tetrahedron announced as "4 4 6", followed by 8 MB of a larger mesh
    lines = ["OFF", "4 4 6", "1 1 1", "1 -1 -1", "-1 1 -1", "-1 -1 1"]
    lines += ["3 0 1 2", "3 0 3 1", "3 1 3 2", "3 0 2 3"]
    path = tmp_path / "big.off"
    with open(path, "wb") as fh:
        fh.write(("\n".join(lines) + "\n").encode())
        fh.write(b"3 0 1 2\n" * 1_000_000)
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", 1 << 16)
    seen = _count_blocks(monkeypatch, pentanb.io.off)
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}:11: the header says 4 vertices and 4 faces \(8 lines\) but "
        r"the file has more data lines, from this one on: '3 0 1 2'$",
    ):
        read(path)
    assert len(seen) == 1  # of 123 blocks


def test_off_counts_the_file_cannot_hold_fail_at_the_header(tmp_path):
    path = write_text(tmp_path / "huge.off", ["OFF", "1000000000 2000000000 0", "0 0 0"])
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}:2: the header says 1,000,000,000 vertices and 2,000,000,000 "
        r"faces, more than a file of 34 bytes can hold$",
    ):
        read(path)


@pytest.mark.parametrize("counts", ["-8 6 12", "8 -6 12", "8", "8.0 6 12"])
def test_off_bad_counts(tmp_path, counts):
    lines = _cube_off_lines()
    lines[1] = counts
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}:2: bad counts line '{re.escape(counts)}'$"):
        read(path)


def test_binary_off_is_refused_by_name(tmp_path):
    path = tmp_path / "b.off"
    path.write_bytes(b"OFF BINARY\n" + np.array([8, 6, 0], ">i4").tobytes())
    with pytest.raises(MeshError, match=rf"^{esc(path)}:1: a binary OFF file; only text OFF"):
        read(path)


@pytest.mark.parametrize("block", [64, 200, 1000])
@pytest.mark.parametrize("ext", [".obj", ".off"])
def test_small_blocks_give_the_same_mesh(tmp_path, monkeypatch, corpus_mesh, ext, block):
    path = tmp_path / f"m{ext}"
    write(corpus_mesh, path)
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", block)
    back = read(path)
    assert back.vertices.tobytes() == corpus_mesh.vertices.tobytes()
    assert face_lists(back) == face_lists(corpus_mesh)


def test_obj_errors_in_later_blocks_name_their_line(tmp_path, monkeypatch):
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", 64)
    lines = [f"# comment {i}" for i in range(40)] + _cube_obj_lines()
    lines[45] = "v 1 1 one"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}:46: bad number in 'v 1 1 one'$"):
        read(path)


def test_obj_relative_and_forward_indices_across_blocks(tmp_path, monkeypatch):
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", 48)
    v = [l for l in cube_v_lines()]
    # faces first (forward references), then vertices, then relative faces
    lines = ["f 1 2 4 3", "f 5 7 8 6", "f 1 5 6 2"] + v + ["f -6 -5 -1 -2", "f -8 -6 -2 -4"]
    lines += ["f 2 6 8 4"]
    m = read(write_text(tmp_path / "mixed.obj", lines))
    assert face_lists(m) == [[i - 1 for i in f] for f in CUBE_OBJ_FACES]


def test_obj_forward_index_beyond_the_file_names_its_line(tmp_path, monkeypatch):
    monkeypatch.setattr(pentanb.io._common, "BLOCK_BYTES", 48)
    lines = ["f 1 2 4 3", "f 5 7 8 6", "f 1 5 6 12"] + _cube_obj_lines()
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}:3: face index 12 out of range \(8 vertices in the file\)$"
    ):
        read(path)


@pytest.mark.parametrize(
    "token, message",
    [
        ("9223372036854775808", "face index 9223372036854775808 out of range"),
        ("18446744073709551616", "face index 18446744073709551616 out of range"),
        ("-9223372036854775809", "face index -9223372036854775809 out of range"),
        ("1.5", "bad face index '1.5'"),
        ("1e3", "bad face index '1e3'"),
        ("/2/3", "bad face index '/2/3'"),
    ],
)
def test_obj_face_indices_no_mesh_can_have(tmp_path, token, message):
    lines = _cube_obj_lines()
    lines[9] = f"f 1 3 {token} 5"
    path = write_text(tmp_path / "bad.obj", lines)
    with pytest.raises(MeshError, match=rf"^{esc(path)}:10: {re.escape(message)}"):
        read(path)


@pytest.mark.parametrize("token", ["9223372036854775808", "18446744073709551616", "-1"])
def test_off_face_indices_out_of_range_are_reported_as_written(tmp_path, token):
    lines = _cube_off_lines()
    lines[12] = f"4 0 1 {token} 2"
    path = write_text(tmp_path / "bad.off", lines)
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}:13: face index {token} out of range \(8 vertices\)$"
    ):
        read(path)


def _odd_but_valid_obj() -> list[str]:
    v = [
        "v\t-1 -1 -1",
        "  v -1 -1 1",
        "v -1 1 -1 1.0",  # w
        "v -1 1 1 0.5 0.5 0.5",  # colour
        "v +1e0 -1 -1",
        "v 1. -1 1  # trailing",
        "v 1 1 -1.000",
        "v 1 1 1",
    ]
    f = [
        "f 1/1/1 2/2/2 4/3/3 3/4/4",
        "f\t5//1 7//1\t8//1 6//1",
        "  f 1/1 5/2 6/3 2/4  # 1/2/3",
        "f -6 -5 -1 -2",
        "f 1 3 7 5",
        "f 2 6 8 4",
    ]
    return ["# odd", "mtllib x.mtl", "vn 0 0 1", "vt 0.5 0.5"] + v + ["usemtl a", "s off"] + f


def test_odd_but_valid_obj_lines_read_alike_on_the_fast_and_the_slow_path(tmp_path, monkeypatch):
    path = write_text(tmp_path / "odd.obj", _odd_but_valid_obj())
    fast = read(path)
    monkeypatch.setattr(pentanb.io.obj, "_fast", lambda *args: None)
    slow = read(path)
    assert face_lists(fast) == face_lists(slow) == [[i - 1 for i in f] for f in CUBE_OBJ_FACES]
    assert fast.vertices.tobytes() == slow.vertices.tobytes()
    assert np.array_equal(fast.vertices, shapes.cube().vertices)


def test_off_colour_columns_ints_and_floats(tmp_path):
    lines = _cube_off_lines()
    lines[0] = "COFF"
    lines[2] += " 255 0 0 255"  # one vertex with a colour (the others without)
    lines[10] += " 0.5 0.25 1.0"  # a face colour as floats
    lines[11] += " 255 255 0"
    m = read(write_text(tmp_path / "c.off", lines))
    assert face_lists(m) == face_lists(shapes.cube())
    assert np.array_equal(m.vertices, shapes.cube().vertices)


def test_obj_vertices_with_and_without_colours(tmp_path):
    lines = _cube_obj_lines()
    lines[0] += " 1 0 0"
    lines[5] += " 0.5 0.5 0.5"
    m = read(write_text(tmp_path / "c.obj", lines))
    assert np.array_equal(m.vertices, shapes.cube().vertices)
