"""PLY and STL: round trips, files made by hand and by trimesh, and every refusal."""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest
from helpers import corpus, face_lists, prism

import pentanb
from pentanb import Mesh, MeshError, read, shapes, write
from pentanb.io import IgnoredDataWarning, read_stl, write_ply, write_stl
from pentanb.io.stl import weld


def esc(path) -> str:
    return re.escape(str(path))


def cube_parts():
    c = shapes.cube()
    return c.vertices, face_lists(c)


def ply_header(encoding, vertex_props, face_props, n_v=8, n_f=6, extra=()):
    lines = ["ply", f"format {encoding} 1.0", "comment made by hand"]
    lines += [f"element vertex {n_v}"] + [f"property {p}" for p in vertex_props]
    lines += list(extra)
    lines += [f"element face {n_f}"] + [f"property {p}" for p in face_props]
    return ("\n".join(lines + ["end_header"]) + "\n").encode()


# ====================================================================== PLY round trips
@pytest.mark.parametrize(
    "options", [{}, {"byteorder": "big"}, {"ascii": True}], ids=["le", "be", "ascii"]
)
def test_ply_round_trip_is_exact(tmp_path, corpus_mesh, options):
    path = tmp_path / "m.ply"
    write(corpus_mesh, path, **options)
    back = read(path)
    assert back.vertices.tobytes() == corpus_mesh.vertices.tobytes()
    assert face_lists(back) == face_lists(corpus_mesh)


def test_ply_header_as_written(tmp_path):
    write_ply(shapes.cube(), tmp_path / "c.ply")
    head = (tmp_path / "c.ply").read_bytes().split(b"end_header\n")[0].decode().splitlines()
    assert head == [
        "ply",
        "format binary_little_endian 1.0",
        "comment written by pentanb",
        "element vertex 8",
        "property double x",
        "property double y",
        "property double z",
        "element face 6",
        "property list uchar int vertex_indices",
    ]
    write_ply(shapes.cube(), tmp_path / "a.ply", ascii=True)
    text = (tmp_path / "a.ply").read_text().splitlines()
    assert text[1] == "format ascii 1.0"
    assert text[10].split() == ["-1.0", "-1.0", "-1.0"]
    assert text[18].split()[0] == "4"


def test_ply_faces_of_more_than_255_sides_get_an_int_count(tmp_path):
    m = prism(300)
    write(m, tmp_path / "p.ply")
    assert b"property list int int vertex_indices" in (tmp_path / "p.ply").read_bytes()[:400]
    assert face_lists(read(tmp_path / "p.ply")) == face_lists(m)


# ====================================================================== PLY made by hand
def test_ascii_ply_with_extra_properties_warns_and_reads_positions(tmp_path):
    v, faces = cube_parts()
    head = ply_header(
        "ascii",
        ["float nx", "float x", "float y", "float z", "uchar red", "float ny"],
        ["uchar flag", "list uchar int vertex_indices", "float quality"],
    )
    rows = [f"0 {x!r} {y!r} {z!r} 255 0" for x, y, z in v.tolist()]
    rows += [f"7 {len(f)} " + " ".join(map(str, f)) + " 0.5" for f in faces]
    path = tmp_path / "c.ply"
    path.write_bytes(head + ("\n".join(rows) + "\n").encode())
    with pytest.warns(
        IgnoredDataWarning,
        match=r"ignored .*: vertex nx, vertex red, vertex ny, face flag, face quality$",
    ):
        m = read(path)
    assert np.array_equal(m.vertices, v)
    assert face_lists(m) == faces


def test_binary_big_endian_ply_with_floats_and_other_index_types(tmp_path):
    v, faces = cube_parts()
    head = ply_header(
        "binary_big_endian", ["float x", "float y", "float z"], ["list ushort uint vertex_index"]
    )
    verts = v.astype(">f4").tobytes()
    rows = np.zeros(6, dtype=[("n", ">u2"), ("i", ">u4", (4,))])
    rows["n"] = 4
    rows["i"] = faces
    path = tmp_path / "c.ply"
    path.write_bytes(head + verts + rows.tobytes())
    m = read(path)
    assert np.array_equal(m.vertices, v) and face_lists(m) == faces


def test_binary_ply_mixed_face_sizes_extra_lists_and_other_elements(tmp_path):
    m = corpus("cube_split")  # a triangle, quads and pentagons
    head = ply_header(
        "binary_little_endian",
        ["double x", "double y", "double z", "uchar alpha"],
        ["uchar flag", "list uchar int vertex_indices", "list uchar float texcoord"],
        n_v=m.n_vertices,
        n_f=m.n_faces,
        extra=["element material 2", "property uchar red", "property list uchar uchar name"],
    )
    body = b""
    for x in m.vertices:
        body += x.astype("<f8").tobytes() + b"\x07"
    body += b"\x01\x00" + b"\x02\x03\x04\x05\x06"  # material 1: red 1, name of 0 bytes
    body += b"\x02\x02" + b"ab"  # material 2
    for f in face_lists(m):
        body += b"\x09" + bytes([len(f)]) + np.array(f, "<i4").tobytes()
        body += bytes([2 * len(f)]) + np.arange(2 * len(f), dtype="<f4").tobytes()
    path = tmp_path / "m.ply"
    path.write_bytes(head + body.replace(b"\x02\x03\x04\x05\x06", b""))
    with pytest.warns(IgnoredDataWarning, match=r"vertex alpha, face flag, face texcoord, element"):
        back = read(path)
    assert back.vertices.tobytes() == m.vertices.tobytes()
    assert face_lists(back) == face_lists(m)


def test_ply_written_by_trimesh(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    ico = shapes.icosahedron()
    trimesh.Trimesh(ico.vertices, face_lists(ico), process=False).export(tmp_path / "t.ply")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IgnoredDataWarning)  # trimesh adds colours
        m = read(tmp_path / "t.ply")
    assert np.allclose(m.vertices, ico.vertices) and face_lists(m) == face_lists(ico)


# ====================================================================== PLY refusals
def _valid_ascii_ply() -> bytes:
    v, faces = cube_parts()
    head = ply_header(
        "ascii", ["double x", "double y", "double z"], ["list uchar int vertex_indices"]
    )
    rows = [f"{x!r} {y!r} {z!r}" for x, y, z in v.tolist()]
    rows += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return head + ("\n".join(rows) + "\n").encode()


@pytest.mark.parametrize(
    "old, new, message",
    [
        (b"ply\n", b"plx\n", r":1: not a PLY file \(the first line is not 'ply'\)"),
        (b"format ascii 1.0", b"format middle 1.0", r":2: bad header line 'format middle 1.0'"),
        (b"format ascii 1.0\n", b"", r": the header has no 'format' line"),
        (b"element vertex 8", b"element vertex eight", r":4: bad header line .*COUNT"),
        (b"property double z", b"property quad z", r":7: bad header line .*TYPE one of"),
        (
            b"property double x",
            b"property list float int x",
            r":5: bad header line 'property list float int x': a list's count must be an "
            r"integer type$",
        ),
        (b"comment made by hand\n", b"property int q\n", r":3: .*a property before any element"),
        (b"comment made", b"remark made", r":3: bad header line .*unknown keyword 'remark'"),
        (b"element face 6", b"element faces 6", r": no 'face' element \(elements: vertex, faces\)"),
        (b"property double z\n", b"", r":4: the vertex element has no property 'z'"),
        (b"vertex_indices", b"vertex_ids", r":8: the face element has no list .*'vertex_indices'"),
        (b"end_header\n", b"", r":10: bad header line '-1.0 -1.0 -1.0': unknown keyword '-1.0'$"),
    ],
)
def test_ply_damaged_headers(tmp_path, old, new, message):
    path = tmp_path / "bad.ply"
    data = _valid_ascii_ply()
    assert old in data
    path.write_bytes(data.replace(old, new, 1))
    with pytest.raises(MeshError, match="^" + esc(path) + message):
        read(path)


@pytest.mark.parametrize(
    "edit, message",
    [
        (lambda r: r[:-1], r": the header announces 8 vertex, 6 face rows, the file has 13$"),
        (
            lambda r: r + ["4 0 1 2 3"],
            r":25: more rows than the header announces \(14\): '4 0 1 2 3'$",
        ),
        (lambda r: r[:3] + ["1 one 1"] + r[4:], r":14: bad number in a vertex row: '1 one 1'$"),
        (lambda r: r[:3] + ["1 1"] + r[4:], r":14: a vertex row needs 3 numbers, this one has 2$"),
        (lambda r: r[:9] + ["4 0 1 3"] + r[10:], r":20: a face row that does not match"),
        (lambda r: r[:9] + ["4 0 1 3 1.5"] + r[10:], r":20: vertex index 1.5 is not an integer"),
        (lambda r: r[:9] + ["4 0 1 3 9"] + r[10:], r": face 1 uses vertex index 9, out of range"),
    ],
)
def test_ply_damaged_ascii_rows(tmp_path, edit, message):
    data = _valid_ascii_ply()
    head, body = data.split(b"end_header\n")
    rows = body.decode().splitlines()
    path = tmp_path / "bad.ply"
    path.write_bytes(head + b"end_header\n" + ("\n".join(edit(rows)) + "\n").encode())
    with pytest.raises(MeshError, match="^" + esc(path) + message):
        read(path)


def test_ply_file_ending_inside_its_header(tmp_path):
    path = tmp_path / "short.ply"
    path.write_bytes(_valid_ascii_ply().split(b"end_header")[0])
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}:10: the file ends inside the header \(no 'end_header'\)$"
    ):
        read(path)


def test_ply_truncated_binary_elements(tmp_path):
    write(shapes.cube(), tmp_path / "c.ply")
    data = (tmp_path / "c.ply").read_bytes()
    head = len(data.split(b"end_header\n")[0]) + len(b"end_header\n")
    path = tmp_path / "short.ply"
    path.write_bytes(data[: head + 8 * 24 + 6 * 17 - 3])  # the last face cut
    with pytest.raises(
        MeshError, match=rf"^{esc(path)}: the file ends inside element 'face', at row 5 of 6$"
    ):
        read(path)
    path.write_bytes(data[: head + 7 * 24] + b"\x00" * 10)
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}: the header announces 8 vertex, 6 face rows; that needs at "
        r"least 198 bytes but the file has 178 after the header$",
    ):
        read(path)


def test_ply_trailing_bytes_warn(tmp_path):
    write(shapes.cube(), tmp_path / "c.ply")
    path = tmp_path / "c.ply"
    path.write_bytes(path.read_bytes() + b"junk")
    with pytest.warns(IgnoredDataWarning, match=r"4 bytes after the last element ignored"):
        assert face_lists(read(path)) == face_lists(shapes.cube())


def test_ply_write_options_are_checked_before_writing(tmp_path):
    with pytest.raises(TypeError, match=r"write_ply: ascii must be True or False, got 'yes'"):
        write_ply(shapes.cube(), tmp_path / "c.ply", ascii="yes")
    with pytest.raises(ValueError, match=r"byteorder must be 'little' or 'big', got 'middle'"):
        write_ply(shapes.cube(), tmp_path / "c.ply", byteorder="middle")
    assert list(tmp_path.iterdir()) == []


# ====================================================================== STL
def _float32(m: Mesh) -> Mesh:
    return m.with_vertices(m.vertices.astype(np.float32).astype(np.float64))


def _as_original(back: Mesh, m: Mesh) -> list[list[int]]:
    """``back``'s faces in ``m``'s vertex numbering (matched by position)."""
    where = {tuple(p): i for i, p in enumerate(m.vertices.tolist())}
    assert len(where) == m.n_vertices
    rename = [where[tuple(p)] for p in back.vertices.tolist()]
    return [[rename[i] for i in f] for f in face_lists(back)]


@pytest.mark.parametrize("ascii", [False, True], ids=["binary", "ascii"])
def test_stl_round_trip_of_triangle_meshes(tmp_path, ascii):
    for m in (shapes.icosahedron(), pentanb.triangulate(shapes.torus(5, 4)), corpus("small_torus")):
        m = _float32(pentanb.triangulate(m)) if max(m.face_sizes) > 3 else _float32(m)
        path = tmp_path / "t.stl"
        write_stl(m, path, ascii=ascii)
        back = read(path)
        assert back.n_vertices == m.n_vertices
        assert _as_original(back, m) == face_lists(m)


def test_stl_of_polygons_is_their_fan_triangles(tmp_path):
    m = shapes.dodecahedron()
    write(m, tmp_path / "d.stl", ascii=True)
    back = read(tmp_path / "d.stl")
    tris, _ = m.fan_triangles()
    assert _as_original(back, m) == tris.tolist()
    assert (tmp_path / "d.stl").read_text().startswith("solid pentanb\nfacet normal ")


def test_stl_written_by_trimesh(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    tm = trimesh.creation.icosphere(subdivisions=2)
    tm.export(tmp_path / "t.stl")
    m = read(tmp_path / "t.stl")
    assert (m.n_vertices, m.n_faces, m.genus) == (162, 320, 0)
    assert np.isclose(m.volume, tm.volume, rtol=1e-6)


def test_binary_stl_whose_header_starts_with_solid(tmp_path):
    m = _float32(shapes.octahedron())
    write_stl(m, tmp_path / "o.stl")
    data = bytearray((tmp_path / "o.stl").read_bytes())
    data[:80] = b"solid but binary".ljust(80)
    (tmp_path / "o.stl").write_bytes(bytes(data))
    assert _as_original(read(tmp_path / "o.stl"), m) == face_lists(m)


def _tetra_stl(corners) -> str:
    lines = ["solid t"]
    for tri in corners:
        lines += ["facet normal 0 0 0", "outer loop"]
        lines += [f"vertex {x!r} {y!r} {z!r}" for x, y, z in tri]
        lines += ["endloop", "endfacet"]
    return "\n".join(lines + ["endsolid t"]) + "\n"


def _tetra_corners():
    t = shapes.tetrahedron()
    return t.vertices[np.array(face_lists(t))].tolist()


def test_stl_welds_equal_corners_and_minus_zero(tmp_path):
    corners = _tetra_corners()
    corners[0][0] = [0.0, 0.0, 0.0]
    for tri in corners:
        for p in tri:
            if p == [1.0, 1.0, 1.0]:
                p[:] = [0.0, 0.0, 0.0]
    corners[1] = [[-0.0, 0.0, -0.0] if p == [0.0, 0.0, 0.0] else p for p in corners[1]]
    (tmp_path / "t.stl").write_text(_tetra_stl(corners))
    m = read(tmp_path / "t.stl")
    assert (m.n_vertices, m.n_faces) == (4, 4)
    assert m.vertices[0].tolist() == [0.0, 0.0, 0.0]


def test_stl_tolerance_welds_near_corners(tmp_path):
    corners = _tetra_corners()
    rng = np.random.default_rng(3)
    noisy = (np.array(corners) + rng.uniform(-1e-9, 1e-9, (4, 3, 3))).tolist()
    path = tmp_path / "t.stl"
    path.write_text(_tetra_stl(noisy))
    with pytest.warns(UserWarning, match="no two of the 4 facets share a corner"):
        apart = read(path)  # not welded: four separate triangles, each with its boundary
    assert (apart.n_vertices, apart.n_components, apart.n_boundary_loops) == (12, 4, 4)
    m = read(path, tolerance=1e-6)
    assert (m.n_vertices, m.n_faces) == (4, 4)
    # each vertex at its first corner in the file, in the order of first appearance
    flat = np.array(face_lists(shapes.tetrahedron())).ravel()
    first = np.sort(np.unique(flat, return_index=True)[1])
    assert m.vertices.tolist() == np.array(noisy).reshape(-1, 3)[first].tolist()


def test_weld_merges_chains_within_the_tolerance():
    pts = np.array([[0, 0, 0], [0.6, 0, 0], [1.2, 0, 0], [5, 0, 0], [0.6, 0, 0]], dtype=float)
    v, index = weld(pts, 0.0)
    assert v.tolist() == pts[:4].tolist() and index.tolist() == [0, 1, 2, 3, 1]
    v, index = weld(pts, 0.7)
    assert v.tolist() == [[0, 0, 0], [5, 0, 0]] and index.tolist() == [0, 0, 0, 1, 0]


@pytest.mark.parametrize(
    "tolerance, error, message",
    [
        (-1.0, ValueError, r"tolerance must be a finite number >= 0, got -1\.0"),
        (float("nan"), ValueError, r"tolerance must be a finite number >= 0, got nan"),
        ("0.1", TypeError, r"tolerance must be a number >= 0, got str"),
        (True, TypeError, r"tolerance must be a number >= 0, got bool"),
    ],
)
def test_stl_bad_tolerance(tmp_path, tolerance, error, message):
    write_stl(shapes.octahedron(), tmp_path / "o.stl")
    with pytest.raises(error, match=message):
        read_stl(tmp_path / "o.stl", tolerance=tolerance)


def test_stl_open_surface_is_read_with_its_boundary_loop(tmp_path):
    m = pentanb.triangulate(shapes.cube())
    path = tmp_path / "c.stl"
    write_stl(m, path, ascii=True)
    text = path.read_text().split("facet normal")
    path.write_text("facet normal".join(text[:3] + text[4:]))  # drop facet 2
    m = read(path)
    assert (m.n_vertices, m.n_faces) == (14, 23)
    assert [len(loop) for loop in m.boundary_loops] == [3]


def test_stl_of_loose_facets_warns_and_reads_as_loose_triangles(tmp_path):
    # two triangles whose shared edge was written with rounded coordinates
    path = tmp_path / "soup.stl"
    path.write_text(
        "solid s\n"
        "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
        "endloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 1.0000001 0 0\nvertex 1 1 0\n"
        "vertex 0 1.0000001 0\nendloop\nendfacet\nendsolid s\n"
    )
    with pytest.warns(UserWarning, match=r"no two of the 2 facets share a corner.*tolerance="):
        m = read(path)
    assert (m.n_vertices, m.n_faces, m.n_boundary_loops) == (6, 2, 2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        welded = read(path, tolerance=1e-5)
    assert (welded.n_vertices, welded.n_faces, welded.n_boundary_loops) == (4, 2, 1)


def test_stl_of_one_facet_does_not_warn(tmp_path):
    path = tmp_path / "one.stl"
    path.write_text(
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
        "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n"
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read(path).n_faces == 1


def test_stl_degenerate_facet(tmp_path):
    corners = _tetra_corners()
    corners.append([corners[0][0], corners[0][0], corners[0][1]])
    path = tmp_path / "t.stl"
    path.write_text(_tetra_stl(corners))
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}: facet 4 \(line 30\) has two corners at the same point after "
        r"welding .*\(1 such facets\)",
    ):
        read(path)


@pytest.mark.parametrize(
    "edit, message",
    [
        (
            lambda t: t.replace("endloop", "vertex 1 2 3\nendloop", 1),
            r":7: facet 0 .*expected "
            r"'endloop', found 'vertex' \(STL facets are triangles\)$",
        ),
        (lambda t: t.replace("outer loop", "outr loop", 1), r":3: not an STL line: 'outr loop'$"),
        (
            lambda t: t.replace("vertex 1.0 1.0 1.0", "vertex 1.0 x 1.0", 1),
            r":4: a vertex line needs 3 numbers: 'vertex 1\.0 x 1\.0'$",
        ),
        (lambda t: t.rsplit("endloop", 1)[0], r":27: facet 3 .*found 'the end of the file'"),
        (lambda t: t.replace("solid t\n", ""), r":1: text that does not start with 'solid'"),
    ],
)
def test_stl_damaged_ascii(tmp_path, edit, message):
    path = tmp_path / "t.stl"
    path.write_text(edit(_tetra_stl(_tetra_corners())))
    with pytest.raises(MeshError, match="^" + esc(path) + message):
        read(path)


def test_stl_binary_size_mismatch_and_nan(tmp_path):
    path = tmp_path / "t.stl"
    write_stl(shapes.tetrahedron(), path)
    data = path.read_bytes()
    path.write_bytes(data[:-10])
    with pytest.raises(
        MeshError,
        match=rf"^{esc(path)}: a binary STL whose header says 4 triangles \(284 bytes\) but the "
        r"file has 274 bytes$",
    ):
        read(path)
    rows = np.frombuffer(data[84:], dtype=pentanb.io.stl._BINARY).copy()
    rows["corners"][2, 1, 0] = np.nan
    path.write_bytes(data[:84] + rows.tobytes())
    with pytest.raises(MeshError, match=rf"^{esc(path)}: facet 2 has a non-finite coordinate"):
        read(path)


def test_stl_write_options(tmp_path):
    with pytest.raises(TypeError, match=r"write_stl: ascii must be True or False, got 1"):
        write_stl(shapes.cube(), tmp_path / "c.stl", ascii=1)
    assert list(tmp_path.iterdir()) == []


def test_ascii_ply_numbers_numpy_does_not_parse_are_read_line_by_line(tmp_path):
    # "1_0.0" is a Python float literal numpy's parsers refuse: the block is read again
    # line by line, as the OBJ and OFF readers do, instead of failing
    write_ply(shapes.cube(), tmp_path / "c.ply", ascii=True)
    text = (tmp_path / "c.ply").read_text().replace("\n1.0 1.0 1.0\n", "\n1_0.0 1.0 1.0\n")
    (tmp_path / "c.ply").write_text(text)
    assert read(tmp_path / "c.ply").vertices[-1].tolist() == [10.0, 1.0, 1.0]


def test_weld_when_every_hash_collides(monkeypatch):
    rng = np.random.default_rng(5)
    base = rng.standard_normal((50, 3))
    pts = base[rng.integers(0, 50, 400)]
    v, index = weld(pts)
    monkeypatch.setattr(pentanb.io.stl, "_hash", lambda cols: np.zeros(cols.shape[1], np.uint64))
    v2, index2 = weld(pts)
    assert np.array_equal(v, v2) and np.array_equal(index, index2)
    assert np.array_equal(v[index], pts)
    first = [int(np.flatnonzero(index == k)[0]) for k in range(v.shape[0])]
    assert first == sorted(first)  # vertices in the order of first appearance
