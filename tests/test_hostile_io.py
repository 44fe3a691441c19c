"""Hostile input to the readers and writers of :mod:`pentanb.io`.

Every case here was found by a review that fed the readers and writers what
a careless or malicious file can hold.  The rules they check
(docs/reliability.md, "Files"):

* bad input gets a MeshError (a ValueError) or a TypeError that names the
  problem and where it is, never a silently different mesh, a bare
  ``int()``/``OverflowError`` message or a crash;
* valid input is never refused: byte-order marks, any line breaks (LF,
  CRLF, CR, mixed), list properties anywhere, pipes and file objects;
* a write refuses before anything is written, and leaves nothing behind.

Cases that could hang (a FIFO without a writer) or need a real pipe run in
a child process with a timeout.
"""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from helpers import face_lists

import pentanb
from pentanb import Mesh, MeshError, read, shapes, write
from pentanb.io import _common, from_meshio

#: The directory the pentanb under test is imported from (for child processes).
SOURCE_ROOT = str(Path(pentanb.__file__).resolve().parent.parent)
SECONDS = 60


def esc(path) -> str:
    return re.escape(str(path))


def same_mesh(a: Mesh, b: Mesh) -> bool:
    return a.vertices.tobytes() == b.vertices.tobytes() and face_lists(a) == face_lists(b)


def float32_mesh() -> Mesh:
    """A polygon mesh whose coordinates are float32 numbers (binary STL keeps them)."""
    m = pentanb.triangulate(shapes.dodecahedron())
    return m.with_vertices(m.vertices.astype(np.float32).astype(np.float64))


def files_of(tmp_path: Path, mesh: Mesh) -> dict[str, tuple[Path, str]]:
    """The mesh written in every format and variant: name -> (path, format)."""
    out = {}
    for name, fmt, options in [
        ("obj", "obj", {}),
        ("off", "off", {}),
        ("ply-ascii", "ply", {"ascii": True}),
        ("ply-le", "ply", {}),
        ("ply-be", "ply", {"byteorder": "big"}),
        ("stl-ascii", "stl", {"ascii": True}),
        ("stl-binary", "stl", {}),
    ]:
        path = tmp_path / f"{name}.{fmt}"
        write(mesh, path, **options)
        out[name] = (path, fmt)
    return out


def quiet_read(source, **kw) -> Mesh:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pentanb.io.IgnoredDataWarning)
        return read(source, **kw)


def run_child(
    code: str, stdin: bytes | None = None, timeout: float = SECONDS
) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=SOURCE_ROOT)
    return subprocess.run(
        [sys.executable, "-c", code],
        input=stdin,
        capture_output=True,
        timeout=timeout,
        env=env,
        cwd=SOURCE_ROOT,
    )


# ====================================================================== PLY float indices
def _binary_ply(index_type: str, indices: list[list[float]], vertices: np.ndarray) -> bytes:
    head = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(vertices)}\n"
        "property double x\nproperty double y\nproperty double z\n"
        f"element face {len(indices)}\n"
        f"property list uchar {index_type} vertex_indices\nend_header\n"
    ).encode()
    body = vertices.astype("<f8").tobytes()
    code = pentanb.io.ply.TYPES[index_type]
    for face in indices:
        body += np.array([len(face)], "u1").tobytes() + np.array(face, "<" + code).tobytes()
    return head + body


def _cube_faces() -> list[list[int]]:
    return [f.tolist() for f in shapes.cube().faces]


@pytest.mark.parametrize("index_type", ["float", "double"])
def test_binary_ply_fractional_float_indices_are_refused(tmp_path, index_type):
    # 0.7, 1.7, ... used to be read as faces 0, 1, ...
    faces = [[i + 0.7 for i in f] for f in _cube_faces()]
    path = tmp_path / "frac.ply"
    path.write_bytes(_binary_ply(index_type, faces, shapes.cube().vertices))
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}: row 0 of element 'face' \(item 0\): vertex index 0\.7"
    ) as info:
        read(path)
    assert "is not an integer" in str(info.value)


@pytest.mark.parametrize("index_type", ["float", "double"])
def test_binary_ply_whole_float_indices_are_taken(tmp_path, index_type):
    path = tmp_path / "whole.ply"
    path.write_bytes(_binary_ply(index_type, _cube_faces(), shapes.cube().vertices))
    assert same_mesh(read(path), shapes.cube())


@pytest.mark.parametrize(
    ("value", "said"),
    [
        (float("nan"), r"vertex index nan \(not a number\)"),
        (float("inf"), r"vertex index inf \(an infinity\)"),
        (-float("inf"), r"vertex index -inf \(an infinity\)"),
        (1e30, r"vertex index 1e\+30 out of range"),
    ],
)
def test_binary_ply_nan_and_infinite_indices_are_named(tmp_path, value, said):
    # nan used to become "vertex index -9223372036854775808"
    faces = [[float(i) for i in f] for f in _cube_faces()]
    faces[2][1] = value
    path = tmp_path / "nan.ply"
    path.write_bytes(_binary_ply("double", faces, shapes.cube().vertices))
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}: row 2 of element 'face' \(item 1\): {said}"
    ):
        read(path)


@pytest.mark.parametrize(
    ("token", "said"),
    [
        ("nan", r"vertex index nan \(not a number\)"),
        ("inf", r"vertex index inf \(an infinity\)"),
        ("2.5", r"vertex index 2\.5 is not an integer"),
    ],
)
def test_ascii_ply_bad_float_indices_name_the_line(tmp_path, token, said):
    write(shapes.cube(), tmp_path / "c.ply", ascii=True)
    lines = (tmp_path / "c.ply").read_text().splitlines()
    at = lines.index("end_header") + 8 + 3  # the fourth face
    lines[at] = "4 " + token + " " + " ".join(lines[at].split()[2:])
    path = tmp_path / "bad.ply"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(MeshError, match=rf"^{esc(path)}:{at + 1}: {said}"):
        read(path)


# ====================================================================== from_meshio
def _meshio_like(points, cells):
    return SimpleNamespace(
        points=points, cells=[SimpleNamespace(type=t, data=np.asarray(d)) for t, d in cells]
    )


def test_from_meshio_refuses_fractional_cell_indices():
    c = shapes.cube()
    faces = np.array(_cube_faces(), dtype=float) + 0.25
    with pytest.raises(
        MeshError, match=r"cell block 0 \('quad'\), cell 0: index 0\.25 is not a whole"
    ):
        from_meshio(_meshio_like(c.vertices, [("quad", faces)]))
    faces = np.array(_cube_faces(), dtype=float)
    faces[3, 2] = np.nan
    with pytest.raises(MeshError, match=r"cell 3: index nan is not a whole number"):
        from_meshio(_meshio_like(c.vertices, [("quad", faces)]))


def test_from_meshio_takes_whole_float_indices():
    c = shapes.cube()
    got = from_meshio(_meshio_like(c.vertices, [("quad", np.array(_cube_faces(), dtype=float))]))
    assert same_mesh(got, c)


def test_from_meshio_refuses_non_numeric_indices_and_huge_points():
    c = shapes.cube()
    with pytest.raises(TypeError, match=r"holds <U\d+ values; cell indices must be integers"):
        from_meshio(_meshio_like(c.vertices, [("quad", np.array(_cube_faces()).astype(str))]))
    points = c.vertices.tolist()
    points[0][0] = 2**1100  # used to raise a bare OverflowError
    with pytest.raises(MeshError, match=r"point coordinate too large for float64"):
        from_meshio(_meshio_like(points, [("quad", _cube_faces())]))


# ====================================================================== BOMs and line breaks
BOM = b"\xef\xbb\xbf"
TEXT_VARIANTS = ["obj", "off", "ply-ascii", "stl-ascii"]


@pytest.mark.parametrize("variant", TEXT_VARIANTS)
def test_a_utf8_byte_order_mark_is_skipped_in_every_text_format(tmp_path, variant):
    m = float32_mesh()
    path, fmt = files_of(tmp_path, m)[variant]
    expected = read(path)
    bom = tmp_path / f"bom.{fmt}"
    bom.write_bytes(BOM + path.read_bytes())
    # ASCII STL with a BOM used to be taken for "a binary STL whose header says 774,974,752
    # triangles"
    assert same_mesh(read(bom), expected)


def _relined(data: bytes, style: str, rng: np.random.Generator) -> bytes:
    lines = data.split(b"\n")
    assert lines[-1] == b""
    lines = lines[:-1]
    if style == "mixed":
        breaks = rng.choice([b"\n", b"\r\n", b"\r"], size=len(lines))
        return b"".join(line + brk for line, brk in zip(lines, breaks))
    if style == "cr-final-lf":
        return b"\r".join(lines) + b"\n"
    brk = {"lf": b"\n", "crlf": b"\r\n", "cr": b"\r"}[style]
    return brk.join(lines) + brk


@pytest.mark.parametrize("style", ["lf", "crlf", "cr", "cr-final-lf", "mixed"])
@pytest.mark.parametrize("variant", TEXT_VARIANTS)
def test_any_line_breaks_in_every_text_format(tmp_path, variant, style):
    m = float32_mesh()
    path, fmt = files_of(tmp_path, m)[variant]
    expected = read(path)
    other = tmp_path / f"relined.{fmt}"
    other.write_bytes(_relined(path.read_bytes(), style, np.random.default_rng(7)))
    assert same_mesh(read(other), expected)


@pytest.mark.parametrize("style", ["crlf", "cr"])
@pytest.mark.parametrize("variant", ["ply-le", "ply-be"])
def test_binary_ply_header_with_cr_or_crlf_line_breaks(tmp_path, variant, style):
    m = float32_mesh()
    path, _ = files_of(tmp_path, m)[variant]
    data = path.read_bytes()
    cut = data.index(b"end_header\n") + len(b"end_header\n")
    head = _relined(data[:cut], style, np.random.default_rng(0))
    other = tmp_path / "crlf.ply"
    other.write_bytes(head + data[cut:])
    assert same_mesh(read(other), m)


def test_binary_ply_with_cr_lines_whose_body_starts_with_a_line_feed(tmp_path):
    # lines that end in a bare CR: the LF after "end_header\r" is the body's first byte
    v = shapes.cube().vertices.copy()
    head = (
        b"ply\rformat binary_little_endian 1.0\relement vertex 8\rproperty uchar tag\r"
        b"property double x\rproperty double y\rproperty double z\relement face 6\r"
        b"property list uchar int vertex_indices\rend_header\r"
    )
    rows = np.zeros(8, dtype=[("tag", "u1"), ("xyz", "<f8", (3,))])
    rows["tag"] = 10  # b"\n"
    rows["xyz"] = v
    body = rows.tobytes()
    for f in _cube_faces():
        body += np.array([4], "u1").tobytes() + np.array(f, "<i4").tobytes()
    path = tmp_path / "cr.ply"
    path.write_bytes(head + body)
    assert same_mesh(quiet_read(path), shapes.cube())


@pytest.mark.parametrize("ext", [".obj", ".off"])
def test_crlf_split_across_blocks_keeps_line_numbers(tmp_path, monkeypatch, ext):
    # every block boundary falls somewhere in a "\r\n": the line numbers must not drift
    monkeypatch.setattr(_common, "BLOCK_BYTES", 7)
    m = shapes.cube()
    path = tmp_path / f"c{ext}"
    write(m, path)
    lines = path.read_bytes().split(b"\n")[:-1]
    bad = len(lines) - 2
    lines[bad] = b"f 1 2 x" if ext == ".obj" else b"4 0 1 x 3"
    path.write_bytes(b"\r\n".join(lines) + b"\r\n")
    with pytest.raises(MeshError, match=rf"^{esc(path)}:{bad + 1}: bad face"):
        read(path)


def test_ascii_ply_vertex_element_with_a_list_property(tmp_path):
    # the binary reader skipped it; the ASCII reader refused the row
    c = shapes.cube()
    rows = [
        f"{x!r} 2 7 8 {y!r} {z!r}" if i % 2 else f"{x!r} 0 {y!r} {z!r}"
        for i, (x, y, z) in enumerate(c.vertices.tolist())
    ]
    text = (
        "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\n"
        "property list uchar int neighbours\nproperty double y\nproperty double z\n"
        "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
        + "\n".join(rows)
        + "\n"
        + "\n".join("4 " + " ".join(map(str, f)) for f in _cube_faces())
        + "\n"
    )
    path = tmp_path / "lists.ply"
    path.write_text(text)
    with pytest.warns(pentanb.io.IgnoredDataWarning, match="vertex neighbours"):
        m = read(path)
    assert same_mesh(m, c)
    # a row whose list does not fit the header is named
    path.write_text(text.replace("2 7 8", "5 7 8", 1))
    with pytest.raises(MeshError, match=rf"^{esc(path)}:12: a vertex row that does not match"):
        quiet_read(path)


# ====================================================================== pipes and file objects
ALL_VARIANTS = ["obj", "off", "ply-ascii", "ply-le", "ply-be", "stl-ascii", "stl-binary"]


@pytest.mark.parametrize("variant", ALL_VARIANTS)
def test_every_format_reads_from_a_pipe_through_dev_stdin(tmp_path, variant):
    # OFF, PLY and binary STL used to fail with "OSError: Illegal seek"
    m = float32_mesh()
    path, fmt = files_of(tmp_path, m)[variant]
    expected = read(path)
    code = (
        "import sys, pentanb as pb\n"
        f"m = pb.read('/dev/stdin', format={fmt!r})\n"
        "sys.stdout.buffer.write(m.vertices.tobytes())\n"
        "sys.stdout.buffer.write(m.corners.tobytes())\n"
    )
    done = run_child(code, stdin=path.read_bytes())
    assert done.returncode == 0, done.stderr.decode()
    assert done.stdout == expected.vertices.tobytes() + expected.corners.tobytes()


class _Unseekable(io.RawIOBase):
    """A binary stream that cannot seek and returns short reads (like a socket)."""

    def __init__(self, data: bytes, step: int = 4093) -> None:
        self._data, self._at, self._step = data, 0, step

    def readable(self) -> bool:
        return True

    def readinto(self, b) -> int:
        n = min(len(b), self._step, len(self._data) - self._at)
        b[:n] = self._data[self._at : self._at + n]
        self._at += n
        return n


@pytest.mark.parametrize("variant", ALL_VARIANTS)
def test_every_format_reads_binary_file_objects(tmp_path, variant):
    m = float32_mesh()
    path, fmt = files_of(tmp_path, m)[variant]
    expected = read(path)
    data = path.read_bytes()
    assert same_mesh(read(io.BytesIO(data), format=fmt), expected)
    assert same_mesh(read(_Unseekable(data), format=fmt), expected)
    assert same_mesh(read(io.BufferedReader(_Unseekable(data)), format=fmt), expected)
    with open(path, "rb") as fh:
        assert same_mesh(read(fh), expected)  # the format from the file's name
        assert not fh.closed  # a file object is the caller's: left open
    with open(path, "rb") as fh:
        fh.read(0)
        assert same_mesh(read(fh, format=fmt), expected)
    reader = getattr(pentanb.io, f"read_{fmt}")
    assert same_mesh(reader(io.BytesIO(data)), expected)


def test_file_objects_that_read_cannot_take(tmp_path):
    with pytest.raises(ValueError, match=r"a BytesIO has no file name to tell its format by"):
        read(io.BytesIO(b"v 0 0 0\n"))
    with pytest.raises(TypeError, match=r"a binary file object .*got a text file object"):
        read(io.StringIO("v 0 0 0\n"), format="obj")
    write(shapes.cube(), tmp_path / "c.obj")
    with open(tmp_path / "c.obj") as text, pytest.raises(TypeError, match="text file object"):
        read(text)


def test_a_pipe_with_a_header_that_lies_allocates_only_what_arrives():
    # from a pipe there is no size to check the counts against: nothing is allocated from them
    head = b"OFF\n100000000000 100000000000 0\n0 0 0\n"
    with pytest.raises(MeshError, match=r"header says 100000000000 vertices .* file has 1 data"):
        read(_Unseekable(head), format="off")
    ply = b"ply\nformat ascii 1.0\nelement vertex 100000000000000\nproperty float x\n"
    ply += b"property float y\nproperty float z\nelement face 0\n"
    ply += b"property list uchar int vertex_indices\nend_header\n0 0 0\n"
    with pytest.raises(MeshError, match=r"announces 100,000,000,000,000 vertex, 0 face rows"):
        read(_Unseekable(ply), format="ply")
    huge = ply.replace(b"100000000000000", str(2**1100).encode())
    with pytest.raises(MeshError, match=r":3: bad header line .*more than any file holds"):
        read(_Unseekable(huge), format="ply")
    stl = b"x" * 80 + np.array([10**9], "<u4").tobytes() + bytes(100)
    with pytest.raises(MeshError, match=r"says 1,000,000,000 triangles .* the file has 184 bytes"):
        read(_Unseekable(stl), format="stl")


def test_a_fifo_without_a_writer_does_not_block(tmp_path):
    # open() used to wait forever for a writer
    fifo = tmp_path / "pipe.obj"
    os.mkfifo(fifo)
    code = (
        "import pentanb as pb\n"
        "try:\n"
        f"    pb.read({str(fifo)!r})\n"
        "except pb.MeshError as e:\n"
        "    print('MeshError', e)\n"
    )
    try:
        done = run_child(code, timeout=20)
    except subprocess.TimeoutExpired:  # pragma: no cover - the old behaviour
        pytest.fail("reading a FIFO without a writer blocked")
    assert done.returncode == 0, done.stderr.decode()
    assert done.stdout.decode().startswith(f"MeshError {fifo}: no faces")


def test_a_fifo_with_a_writer_is_read(tmp_path):
    write(shapes.cube(), tmp_path / "c.ply")
    fifo = tmp_path / "pipe.ply"
    os.mkfifo(fifo)
    # the writer writes first and closes (a spare read end keeps the bytes in the pipe);
    # then pb.read opens it: it reads what is there, never waiting for a writer
    code = f"""
import os, threading, pentanb as pb
data = open({str(tmp_path / "c.ply")!r}, "rb").read()
spare = os.open({str(fifo)!r}, os.O_RDONLY | os.O_NONBLOCK)
def feed():
    with open({str(fifo)!r}, "wb") as fh:
        fh.write(data)
writer = threading.Thread(target=feed)
writer.start()
writer.join()
m = pb.read({str(fifo)!r})
print(m.n_vertices, m.n_faces)
"""
    try:
        done = run_child(code, timeout=20)
    except subprocess.TimeoutExpired:  # pragma: no cover - the old behaviour
        pytest.fail("reading a FIFO blocked")
    assert done.returncode == 0, done.stderr.decode()
    assert done.stdout.split() == [b"8", b"6"]


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/null"])
def test_a_device_is_refused(device):
    if not os.path.exists(device):  # pragma: no cover
        pytest.skip(f"no {device}")
    with pytest.raises(ValueError, match=rf"^{device} is a character device .*not a file"):
        read(device, format="obj")


def test_a_directory_is_refused(tmp_path):
    (tmp_path / "d.obj").mkdir()
    with pytest.raises(IsADirectoryError):
        read(tmp_path / "d.obj")


# ====================================================================== clear errors
@pytest.mark.parametrize(
    "digit",
    ["\u00b2".encode("latin-1"), "\u00b9".encode("latin-1"), "\u00b2".encode(), "\u0663".encode()],
)
def test_ply_element_count_in_ascii_digits_only(tmp_path, digit):
    write(shapes.cube(), tmp_path / "c.ply", ascii=True)
    data = (
        (tmp_path / "c.ply").read_bytes().replace(b"element vertex 8", b"element vertex " + digit)
    )
    path = tmp_path / "sup.ply"
    path.write_bytes(data)
    # "\xb2".isdigit() is True: int() used to fail with a bare message
    with pytest.raises(MeshError, match=rf"^{esc(path)}:4: bad header line .*ASCII digits 0-9"):
        read(path)


def test_truncated_binary_stl_with_a_solid_header_says_so(tmp_path):
    write(float32_mesh(), tmp_path / "b.stl")
    data = bytearray((tmp_path / "b.stl").read_bytes())
    data[:80] = b"solid exported by some CAD tool".ljust(80)
    path = tmp_path / "cut.stl"
    path.write_bytes(bytes(data[:-30]))
    count = (len(data) - 84) // 50
    # used to be "a NUL byte: a binary file (or UTF-16 text), not STL text"
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}: a binary STL \(its header begins with 'solid'.*says {count} "
        rf"triangles \({len(data):,} bytes\) but the file has {len(data) - 30:,} bytes: a "
        "truncated",
    ):
        read(path)
    with pytest.raises(
        MeshError, match=r"a binary STL \(its header begins with 'solid'.*truncated"
    ):
        read(_Unseekable(bytes(data[:-30])), format="stl")


BIG = str(2**1100)


@pytest.mark.parametrize("variant", TEXT_VARIANTS)
@pytest.mark.parametrize(
    ("token", "said"),
    [
        (BIG, r"has a coordinate '1358298529.*' that overflows float64"),
        ("1e999", r"has a coordinate '1e999' that overflows float64"),
        ("-1e400", r"has a coordinate '-1e400' that overflows float64"),
        ("nan", r"has a non-finite coordinate \(nan\)"),
        ("-inf", r"has a non-finite coordinate \(-inf\)"),
    ],
)
def test_overflowing_and_non_finite_coordinates_name_the_line(tmp_path, variant, token, said):
    m = shapes.cube()
    path, fmt = files_of(tmp_path, m)[variant]
    lines = path.read_bytes().split(b"\n")
    first = b"-1.0 -1.0 -1.0"
    at = next(i for i, line in enumerate(lines) if first in line)
    lines[at] = lines[at].replace(first, token.encode() + b" -1.0 -1.0", 1)
    bad = tmp_path / f"bad.{fmt}"
    bad.write_bytes(b"\n".join(lines))
    what = "facet 0" if fmt == "stl" else "vertex 0"
    with pytest.raises(MeshError, match=rf"^{esc(bad)}:{at + 1}: {what} {said}"):
        read(bad)


def test_binary_non_finite_coordinates_are_named(tmp_path):
    c = shapes.cube()
    write(c, tmp_path / "c.ply")
    data = bytearray((tmp_path / "c.ply").read_bytes())
    at = data.index(b"end_header\n") + len(b"end_header\n") + 3 * 8 * 5
    data[at : at + 8] = np.array([np.inf]).tobytes()
    (tmp_path / "inf.ply").write_bytes(bytes(data))
    with pytest.raises(MeshError, match=r"inf\.ply: vertex 5 has a non-finite coordinate"):
        read(tmp_path / "inf.ply")


# ====================================================================== writes
def _nothing_written(tmp_path: Path, keep: set[str]) -> None:
    assert {p.name for p in tmp_path.iterdir()} == keep


@pytest.mark.parametrize("via", ["write", "write_stl"])
def test_binary_stl_refuses_coordinates_float32_cannot_hold(tmp_path, via):
    c = shapes.cube()
    big = c.with_vertices(c.vertices * 1e300)
    target = tmp_path / "big.stl"
    target.write_bytes(b"keep me")
    writer = write if via == "write" else pentanb.io.write_stl
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # not even numpy's overflow warning
        with pytest.raises(
            MeshError, match=r"vertex 0 at \[-1e\+300, .*beyond the range of float32"
        ):
            writer(big, target)
    assert target.read_bytes() == b"keep me"
    _nothing_written(tmp_path, {"big.stl"})
    # ASCII STL holds them exactly
    write(big, tmp_path / "a.stl", ascii=True)
    assert read(tmp_path / "a.stl").n_faces == 12


@pytest.mark.parametrize(
    "scaled",
    [
        lambda v: v * 1e-50,  # every corner underflows to 0 in float32
        lambda v: v + 1e10,  # float32 spacing at 1e10 is 1024: the cube collapses
    ],
)
def test_binary_stl_refuses_triangles_that_collapse_in_float32(tmp_path, scaled):
    c = shapes.cube()
    m = c.with_vertices(scaled(c.vertices))
    with pytest.raises(
        MeshError, match=r"^write: face 0 \(vertices \[.*\]\): its fan triangle .* float32 point"
    ):
        write(m, tmp_path / "flat.stl")
    with pytest.raises(MeshError, match=r"^write_stl: face 0 "):
        pentanb.io.write_stl(m, tmp_path / "flat.stl")
    _nothing_written(tmp_path, set())
    write(m, tmp_path / "flat.stl", ascii=True)  # exact: reads back
    assert read(tmp_path / "flat.stl").n_faces == 12


def test_binary_stl_refuses_vertices_that_meet_in_float32(tmp_path):
    # the two apexes of a flat octahedron share no triangle but meet in float32
    o = shapes.octahedron()
    v = o.vertices.copy()
    apex = np.flatnonzero(np.abs(v[:, 2]) > 0.5)
    v[apex, 2] *= 1e-50
    m = o.with_vertices(v)
    i, j = sorted(apex.tolist())
    with pytest.raises(MeshError, match=rf"^write: vertices {i} and {j} .* one float32 point"):
        write(m, tmp_path / "o.stl")
    _nothing_written(tmp_path, set())


# ====================================================================== round trips
@pytest.mark.parametrize("variant", ALL_VARIANTS)
def test_good_files_round_trip(tmp_path, variant):
    m = float32_mesh()
    path, _ = files_of(tmp_path, m)[variant]
    back = read(path)
    if variant.startswith("stl"):  # triangles, vertices renumbered by the welding
        triangles, _ = m.fan_triangles()
        assert np.array_equal(back.vertices[back.corners], m.vertices[triangles.ravel()])
    else:
        assert same_mesh(back, m)


def test_binary_stl_write_checks_exactly_when_the_quick_check_is_unsure(tmp_path, monkeypatch):
    # a hash collision in the quick distinctness check sends the write to the exact checks,
    # which let a good mesh through
    monkeypatch.setattr(pentanb.io.stl, "_distinct", lambda points: False)
    m = float32_mesh()
    write(m, tmp_path / "m.stl")
    triangles, _ = m.fan_triangles()
    back = read(tmp_path / "m.stl")
    assert np.array_equal(back.vertices[back.corners], m.vertices[triangles.ravel()])


# ---------------------------------------------------------------- bounded messages
def test_a_huge_face_that_repeats_a_vertex_gets_a_bounded_message():
    """Issue 38, item 13: a face of 10**6 indices once gave a message of megabytes."""
    face = " ".join(["1 2 3 4"] * 250_000)
    text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf " + face + "\n"
    with pytest.raises(MeshError) as info:
        read(io.BytesIO(text.encode()), format="obj")
    message = str(info.value)
    assert len(message) < 2_200
    assert message.startswith("<BytesIO>: face 0")
    assert "characters in all]" in message
