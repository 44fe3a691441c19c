"""trimesh and meshio: conversions both ways, each package imported only when called."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from helpers import face_lists

import pentanb.io.convert
from pentanb import MeshError, shapes
from pentanb.io import IgnoredDataWarning, from_meshio, from_trimesh, to_meshio, to_trimesh

trimesh = pytest.importorskip("trimesh")
meshio = pytest.importorskip("meshio")


def test_importing_pentanb_io_imports_neither_trimesh_nor_meshio():
    code = (
        "import sys, pentanb, pentanb.io; print('trimesh' in sys.modules, 'meshio' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]


# ====================================================================== trimesh
def test_trimesh_round_trip_of_a_triangle_mesh():
    m = shapes.icosahedron()
    t = to_trimesh(m)
    assert isinstance(t, trimesh.Trimesh) and t.is_watertight and t.is_winding_consistent
    assert np.array_equal(t.vertices, m.vertices) and t.faces.tolist() == face_lists(m)
    back = from_trimesh(t)
    assert back.vertices.tobytes() == m.vertices.tobytes() and face_lists(back) == face_lists(m)
    assert face_lists(from_trimesh(to_trimesh(m))) == face_lists(m)


def test_to_trimesh_fans_polygons_and_says_where_each_triangle_comes_from(corpus_mesh):
    t = to_trimesh(corpus_mesh)
    tris, face = corpus_mesh.fan_triangles()
    assert t.faces.tolist() == tris.tolist()
    assert t.face_attributes["polygon"].tolist() == face.tolist()
    a, b, c = (corpus_mesh.vertices[tris[:, i]] for i in range(3))
    assert np.isclose(t.volume, np.einsum("ij,ij->", a, np.cross(b, c)) / 6)


def test_from_trimesh_of_trimesh_shapes():
    m = from_trimesh(trimesh.creation.torus(1.0, 0.3))
    assert m.genus == 1 and m.face_size_histogram().keys() == {3}
    m = from_trimesh(trimesh.creation.box())
    assert (m.n_vertices, m.n_edges, m.n_faces) == (8, 18, 12)


def test_from_trimesh_refusals():
    with pytest.raises(TypeError, match=r"from_trimesh expects a trimesh\.Trimesh, got Mesh"):
        from_trimesh(shapes.cube())
    with pytest.raises(TypeError, match=r"from_trimesh expects a trimesh\.Trimesh, got str"):
        from_trimesh("cube.obj")
    box = trimesh.creation.box()
    flipped = box.faces.copy()
    flipped[0] = flipped[0][::-1]
    with pytest.raises(MeshError, match=r"^the trimesh is not .*inconsistent orientation"):
        from_trimesh(trimesh.Trimesh(box.vertices, flipped, process=False))
    # an open surface is a mesh with boundary
    open_box = from_trimesh(trimesh.Trimesh(box.vertices, box.faces[1:], process=False))
    assert [len(loop) for loop in open_box.boundary_loops] == [3]
    # a triangle soup (corners not shared) is 12 separate triangles; trimesh's
    # process=True merges them
    soup = trimesh.Trimesh(
        box.triangles.reshape(-1, 3), np.arange(36).reshape(-1, 3), process=False
    )
    assert (from_trimesh(soup).n_components, from_trimesh(soup).n_boundary_loops) == (12, 12)
    merged = trimesh.Trimesh(box.triangles.reshape(-1, 3), np.arange(36).reshape(-1, 3))
    assert from_trimesh(merged).n_vertices == 8


@pytest.mark.parametrize("call", [to_trimesh, to_meshio])
def test_to_refuses_a_non_mesh(call):
    with pytest.raises(TypeError, match=rf"{call.__name__} expects a pentanb\.Mesh, got NoneType"):
        call(None)


@pytest.mark.parametrize("call, package", [(to_trimesh, "trimesh"), (to_meshio, "meshio")])
def test_a_missing_package_is_named_with_how_to_install_it(monkeypatch, call, package):
    def missing(name):
        raise ImportError(f"No module named {name!r}")

    monkeypatch.setattr(pentanb.io.convert.importlib, "import_module", missing)
    with pytest.raises(
        ImportError,
        match=rf"{call.__name__} needs the {package} package: pip install {package} "
        r"\(or pip install pentanb\[convert\]\)",
    ):
        call(shapes.cube())


# ====================================================================== meshio
def test_meshio_round_trip_keeps_face_order(corpus_mesh):
    mm = to_meshio(corpus_mesh)
    types = {b.type for b in mm.cells}
    assert types <= {"triangle", "quad", "polygon"}
    back = from_meshio(mm)
    assert back.vertices.tobytes() == corpus_mesh.vertices.tobytes()
    assert face_lists(back) == face_lists(corpus_mesh)


@pytest.mark.parametrize("ext", [".vtk", ".vtu", ".obj"])
def test_meshio_files(tmp_path, ext):
    m = shapes.dodecahedron() if ext != ".obj" else shapes.cube()
    meshio.write(tmp_path / f"m{ext}", to_meshio(m))
    back = from_meshio(meshio.read(tmp_path / f"m{ext}"))
    assert np.allclose(back.vertices, m.vertices) and face_lists(back) == face_lists(m)


def test_from_meshio_refusals():
    c = shapes.cube()
    with pytest.raises(TypeError, match=r"from_meshio expects a meshio\.Mesh, got Mesh"):
        from_meshio(c)
    tet = meshio.Mesh(
        c.vertices, [("tetra", np.array([[0, 1, 2, 3]])), ("quad", c.corners.reshape(-1, 4))]
    )
    with pytest.raises(MeshError, match=r"^the meshio mesh has tetra cells; a pentanb mesh is a "):
        from_meshio(tet)
    flat = meshio.Mesh(c.vertices[:, :2], [("quad", c.corners.reshape(-1, 4))])
    with pytest.raises(MeshError, match=r"points must be \(n, 3\), got shape \(8, 2\)"):
        from_meshio(flat)
    lines = meshio.Mesh(c.vertices, [("line", np.array([[0, 1]]))])
    with pytest.warns(IgnoredDataWarning, match=r"line cells skipped"):
        with pytest.raises(MeshError, match=r"^the meshio mesh has no triangle, quad or polygon"):
            from_meshio(lines)
    open_cube = meshio.Mesh(c.vertices, [("quad", c.corners.reshape(-1, 4)[1:])])
    assert [len(loop) for loop in from_meshio(open_cube).boundary_loops] == [4]
    quads = c.corners.reshape(-1, 4).copy()
    quads[0] = quads[0][::-1]
    with pytest.raises(MeshError, match=r"^the meshio mesh is not .*inconsistent orientation"):
        from_meshio(meshio.Mesh(c.vertices, [("quad", quads)]))


def test_from_meshio_skips_lines_and_points_with_a_warning():
    c = shapes.cube()
    mm = meshio.Mesh(
        c.vertices,
        [
            ("vertex", np.array([[0]])),
            ("quad", c.corners.reshape(-1, 4)),
            ("line", np.array([[0, 1]])),
        ],
    )
    with pytest.warns(IgnoredDataWarning, match=r"from_meshio: line, vertex cells skipped"):
        m = from_meshio(mm)
    assert face_lists(m) == face_lists(c)
