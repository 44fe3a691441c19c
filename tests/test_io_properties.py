"""Property tests (hypothesis): random closed meshes through every file format.

The meshes are those of :mod:`test_properties` (tori, chains of tori,
solids through random schemes, triangulations with merged faces), with
awkward coordinates (subnormals, huge values, -0.0, many digits).  Files are
read in random block sizes, so that lines fall across block boundaries.
"""

from __future__ import annotations

import re
import tempfile
from pathlib import Path

import numpy as np
import pytest
from helpers import face_lists
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_properties import closed_meshes

import pentanb
import pentanb.io._common
from pentanb import Mesh, MeshError, read, write

PROPS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def awkward(m: Mesh, seed: int) -> Mesh:
    """``m`` with coordinates of every kind a file must keep exactly."""
    rng = np.random.default_rng(seed)
    v = m.vertices * rng.uniform(0.5, 2.0)
    kind = rng.integers(0, 6, v.shape)
    v = np.where(kind == 1, v * 1e-310, v)  # subnormal
    v = np.where(kind == 2, v * 1e300, v)
    v = np.where(kind == 3, v + rng.standard_normal(v.shape) / 3, v)  # 17 digits
    v = np.where(kind == 4, -0.0 * np.abs(v), v)  # some -0.0 and +-0.0
    v = np.where(kind == 5, np.round(v, 2), v)
    return m.with_vertices(v)


@PROPS
@given(closed_meshes(), st.integers(0, 2**32), st.sampled_from([None, 37, 256, 4096]))
def test_every_format_keeps_a_random_mesh_exactly(m, seed, block):
    m = awkward(m, seed)
    cases = [("m.obj", {}), ("m.off", {}), ("m.ply", {}), ("m.ply", {"ascii": True})]
    cases += [("m.ply", {"byteorder": "big"})]
    with tempfile.TemporaryDirectory() as tmp, pytest.MonkeyPatch.context() as mp:
        if block:
            mp.setattr(pentanb.io._common, "BLOCK_BYTES", block)
        for name, options in cases:
            path = Path(tmp) / name
            write(m, path, **options)
            back = read(path)
            assert back.vertices.tobytes() == m.vertices.tobytes(), (name, options)
            assert face_lists(back) == face_lists(m), (name, options)


@PROPS
@given(closed_meshes(), st.booleans())
def test_stl_keeps_a_random_triangle_mesh(m, ascii):
    m = pentanb.triangulate(m)
    m = m.with_vertices(m.vertices.astype(np.float32).astype(np.float64))
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "m.stl"
        write(m, path, ascii=ascii)
        back = read(path)
    where = {tuple(p): i for i, p in enumerate(m.vertices.tolist())}
    rename = [where[tuple(p)] for p in back.vertices.tolist()]
    assert back.n_vertices == m.n_vertices
    assert [[rename[i] for i in f] for f in face_lists(back)] == face_lists(m)


@st.composite
def styled_obj(draw):
    """A random mesh as OBJ text in a random style, with the faces it must give."""
    m = draw(closed_meshes())
    rng = np.random.default_rng(draw(st.integers(0, 2**32)))
    v = m.vertices.tolist()
    faces = face_lists(m)
    sep = lambda: " " if rng.random() < 0.7 else rng.choice([" \t", "  ", "\t"])  # noqa: E731
    vlines = []
    for x, y, z in v:
        line = "v" + sep() + sep().join(repr(c) for c in (x, y, z))
        if rng.random() < 0.2:
            line += " 1.0 0.5 0.25"
        if rng.random() < 0.1:
            line = "  " + line
        if rng.random() < 0.1:
            line += "  # a comment, 1/2/3"
        vlines.append(line)
    # faces: some written before all vertices (absolute indices), the rest after
    # (absolute or relative), in v, v/vt, v//vn or v/vt/vn form
    split = int(rng.integers(0, len(faces) + 1))
    lines = ["# styled", "mtllib x.mtl", "o caf\u00e9"]
    flines = []
    for k, f in enumerate(faces):
        relative = k >= split and rng.random() < 0.5
        tokens = []
        for i in f:
            n = i - len(v) if relative else i + 1
            form = rng.integers(0, 4)
            tokens.append([f"{n}", f"{n}/{abs(n)}", f"{n}//1", f"{n}/1/{abs(n)}"][form])
        flines.append("f" + sep() + sep().join(tokens))
    lines += flines[:split] + ["g part", "vn 0 0 1", "vt 0.5 0.5"] + vlines
    lines += ["usemtl a", "s 1"] + flines[split:] + ["", "# end"]
    newline = rng.choice(["\n", "\r\n"])
    text = newline.join(lines) + (newline if rng.random() < 0.8 else "")
    return m, text.encode("utf-8")


@PROPS
@given(styled_obj(), st.sampled_from([None, 23, 100, 1000]))
def test_styled_obj_reads_alike_on_the_fast_and_the_slow_path(case, block):
    m, data = case
    with tempfile.TemporaryDirectory() as tmp, pytest.MonkeyPatch.context() as mp:
        path = Path(tmp) / "s.obj"
        path.write_bytes(data)
        if block:
            mp.setattr(pentanb.io._common, "BLOCK_BYTES", block)
        fast = read(path)
        mp.setattr(pentanb.io.obj, "_fast", lambda *args: None)
        slow = read(path)
    for back in (fast, slow):
        assert back.vertices.tobytes() == m.vertices.tobytes()
        assert face_lists(back) == face_lists(m)


@PROPS
@given(closed_meshes(), st.integers(0, 2**32), st.sampled_from([None, 29, 300]))
def test_styled_off_reads_the_mesh(m, seed, block):
    rng = np.random.default_rng(seed)
    lines = ["OFF # a comment", "", f"{m.n_vertices} {m.n_faces} {m.n_edges}"]
    for x, y, z in m.vertices.tolist():
        line = f"{x!r} {y!r}\t{z!r}"
        lines.append(line + (" 0.1 0.2 0.3 1.0" if rng.random() < 0.3 else ""))
        if rng.random() < 0.1:
            lines.append("# between vertices")
    for f in face_lists(m):
        line = f"{len(f)} " + " ".join(map(str, f))
        lines.append(line + (" 255 0 0" if rng.random() < 0.3 else ""))
        if rng.random() < 0.1:
            lines.append("")
    with tempfile.TemporaryDirectory() as tmp, pytest.MonkeyPatch.context() as mp:
        path = Path(tmp) / "s.off"
        path.write_text("\n".join(lines) + "\n")
        if block:
            mp.setattr(pentanb.io._common, "BLOCK_BYTES", block)
        back = read(path)
    assert back.vertices.tobytes() == m.vertices.tobytes()
    assert face_lists(back) == face_lists(m)


@PROPS
@given(
    closed_meshes(),
    st.sampled_from([".obj", ".off", ".ply"]),
    st.integers(0, 2**32),
    st.sampled_from([None, 41, 500]),
)
def test_a_damaged_line_is_named(m, ext, seed, block):
    """One number of a random line replaced by a word: the error names that line."""
    rng = np.random.default_rng(seed)
    with tempfile.TemporaryDirectory() as tmp, pytest.MonkeyPatch.context() as mp:
        path = Path(tmp) / f"m{ext}"
        write(m, path, **({"ascii": True} if ext == ".ply" else {}))
        lines = path.read_text().splitlines()
        first = lines.index("end_header") + 1 if ext == ".ply" else {".obj": 1, ".off": 2}[ext]
        k = int(rng.integers(first, len(lines)))
        parts = lines[k].split()
        j = int(rng.integers(1 if ext == ".obj" else 0, len(parts)))
        parts[j] = "x1"
        lines[k] = " ".join(parts)
        path.write_text("\n".join(lines) + "\n")
        if block:
            mp.setattr(pentanb.io._common, "BLOCK_BYTES", block)
        with pytest.raises(MeshError, match="^" + re.escape(f"{path}:{k + 1}: ")):
            read(path)
