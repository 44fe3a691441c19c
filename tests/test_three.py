"""The pythreejs widgets as Python models: buffers, in-place updates, camera, export.

What the browser shows is checked by ``tests/test_browser.py``; here the
widget models are checked against the mesh arrays they must carry.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

pytest.importorskip("ipywidgets")
pytest.importorskip("pythreejs")

import pentanb
from pentanb import shapes
from pentanb.viz import html, steps, three
from pentanb.viz.colors import EDGE_COLOR, _hex_to_rgb, face_rgb


def arr(attribute):
    return np.asarray(attribute.array)


def mixed_mesh():
    """Triangles, quads and pentagons in one mesh (a pentagon preservation of a
    pyramid-like mix)."""
    return pentanb.preserve_pentagons(shapes.tetrahedron())


MESHES = {
    "tetrahedron": shapes.tetrahedron,
    "cube": shapes.cube,
    "dodecahedron": shapes.dodecahedron,
    "torus": shapes.torus,
    "mixed": mixed_mesh,
    "pentagonalized cube": lambda: pentanb.schemes.pentagonalize(shapes.cube()),
}


def check_buffers(v: three.MeshView, mesh: pentanb.Mesh):
    pos = arr(v.face_geometry.attributes["position"])
    col = arr(v.face_geometry.attributes["color"])
    index = arr(v.face_geometry.index)
    assert pos.dtype == np.float32 and col.dtype == np.float32 and index.dtype == np.uint32
    # one row per corner, face after face
    np.testing.assert_allclose(pos, mesh.vertices[mesh.corners], rtol=1e-6, atol=1e-6)
    # the index triangulates every polygon face: the fan of Mesh.fan_triangles
    tris, tri_face = mesh.fan_triangles()
    assert index.size == 3 * len(tris)
    np.testing.assert_allclose(pos[index.reshape(-1, 3)], mesh.vertices[tris], atol=1e-6)
    # every triangle's corners belong to the face the triangle comes from
    corner_face = np.repeat(np.arange(mesh.n_faces), mesh.face_sizes)
    assert (corner_face[index.reshape(-1, 3)] == tri_face[:, None]).all()
    # each face has the colour of its size, on all its corners
    np.testing.assert_allclose(col, face_rgb(mesh.face_sizes)[corner_face], atol=1e-6)
    # edges: both ends of every edge, in the edge colour
    seg = arr(v.edge_geometry.attributes["position"]).reshape(-1, 2, 3)
    np.testing.assert_allclose(seg, mesh.vertices[mesh.edges], atol=1e-6)
    ecol = arr(v.edge_geometry.attributes["color"])
    np.testing.assert_allclose(ecol, np.tile(_hex_to_rgb(EDGE_COLOR), (len(ecol), 1)), atol=1e-6)


@pytest.mark.parametrize("name", list(MESHES))
def test_view_buffers_match_mesh(name):
    mesh = MESHES[name]()
    v = pentanb.view(mesh)
    check_buffers(v, mesh)
    assert v.renderer in v.children
    assert v.faces.material.flatShading
    assert v.faces.material.vertexColors == "VertexColors"
    assert v.edges.visible and v.wireframe.value


def test_view_legend_lists_face_sizes_with_their_colours():
    mesh = mixed_mesh()
    v = pentanb.view(mesh)
    sizes, counts = np.unique(mesh.face_sizes, return_counts=True)
    assert len(sizes) == 2  # triangles and pentagons
    for n, count in zip(sizes, counts):
        assert pentanb.viz.colors.face_color(n) in v.legend.value
        assert f"{count:,} {pentanb.viz.colors.face_label(n)}" in v.legend.value
    assert f"V = {mesh.n_vertices}" in v.legend.value


def test_view_camera_sees_the_whole_mesh():
    mesh = shapes.torus()
    v = pentanb.view(mesh)
    cam = np.array(v.camera.position)
    target = np.array(v.controls.target)
    centre = (mesh.vertices.min(0) + mesh.vertices.max(0)) / 2
    np.testing.assert_allclose(target, centre, atol=1e-9)
    radius = np.linalg.norm(mesh.vertices - centre, axis=1).max()
    distance = np.linalg.norm(cam - target)
    half = np.radians(v.camera.fov) / 2
    assert distance * np.sin(half) >= radius  # the bounding sphere fits
    assert distance < 4 * radius
    assert v.camera.near < distance - radius and v.camera.far > distance + radius


def _scene_objects(obj):
    yield obj
    for child in getattr(obj, "children", ()):
        yield from _scene_objects(child)


def test_view_uses_no_light_that_breaks_jupyterlab():
    """pythreejs' shadow-casting lights print "Error setting state" in JupyterLab 4."""
    import pythreejs as P3

    v = pentanb.view(shapes.cube())
    kinds = {type(o) for o in _scene_objects(v.scene)}
    assert not kinds & {P3.PointLight, P3.DirectionalLight, P3.SpotLight}
    assert P3.HemisphereLight in kinds and P3.AmbientLight in kinds


def test_update_bumps_buffer_versions():
    """A replaced array must reach the GPU: its version rises past the browser's."""
    v = pentanb.view(shapes.cube())
    attrs = [
        v.face_geometry.attributes["position"],
        v.face_geometry.index,
        v.edge_geometry.attributes["position"],
    ]
    before = [a.version for a in attrs]
    v.update(shapes.tetrahedron())
    after = [a.version for a in attrs]
    assert all(b > a + 1000 for a, b in zip(before, after))


def test_edges_can_be_switched_off():
    v = pentanb.view(shapes.cube(), edges=False)
    assert not v.edges.visible and not v.wireframe.value
    # the check box is linked to the line object in the browser (jslink)
    links = [w for w in v._link.source + v._link.target]
    assert v.wireframe in links and v.edges in links


def test_update_writes_into_the_same_buffers_and_keeps_the_camera():
    a, b = shapes.cube(), pentanb.subdivide(shapes.cube(), "pentagonalize", 1)
    v = pentanb.view(a)
    geometry, position = v.face_geometry, v.face_geometry.attributes["position"]
    index, renderer = v.face_geometry.index, v.renderer
    v.camera.position = (5.0, -1.0, 2.0)  # the reader orbited
    camera_before = tuple(v.camera.position)
    v.update(b)
    assert v.face_geometry is geometry and v.renderer is renderer
    assert v.face_geometry.attributes["position"] is position
    assert v.face_geometry.index is index
    assert tuple(v.camera.position) == camera_before
    check_buffers(v, b)
    v.update(a)  # smaller again
    check_buffers(v, a)


def test_fan_corner_triangles_matches_mesh_fan_triangles():
    mesh = mixed_mesh()
    corner_tris = three.fan_corner_triangles(mesh.offsets)
    tris, _ = mesh.fan_triangles()
    np.testing.assert_array_equal(mesh.corners[corner_tris], tris)


# -- explorer ----------------------------------------------------------------


def test_explorer_slider_updates_geometry_in_place():
    e = pentanb.explore("cube", iterations=0)
    check_buffers(e.view, shapes.cube())
    geometry = e.view.face_geometry
    position = geometry.attributes["position"]
    renderer, camera = e.view.renderer, e.view.camera
    e.view.camera.position = (0.5, 4.0, 1.0)
    before = arr(position).copy()
    e.iterations.value = 1
    expected = pentanb.subdivide(shapes.cube(), "pentagonalize", 1, duals=2)
    assert e.view.face_geometry is geometry
    assert geometry.attributes["position"] is position
    assert arr(position).shape != before.shape
    assert e.view.renderer is renderer and e.view.camera is camera
    assert tuple(camera.position) == (0.5, 4.0, 1.0)
    check_buffers(e.view, expected)
    assert f"F = {expected.n_faces:,}" in e.counts.value
    assert "pentagons" in e.counts.value


def test_explorer_controls_follow_scheme_options():
    e = pentanb.explore("cube", "pentagonalize")
    assert e.scale.disabled
    e.scheme.value = "preserve_pentagons"
    assert not e.scale.disabled
    e.scale.value = 0.5
    expected = pentanb.subdivide(shapes.cube(), "preserve_pentagons", 1, duals=2, scale=0.5)
    check_buffers(e.view, expected)
    e.duals.value = 0
    check_buffers(e.view, pentanb.preserve_pentagons(shapes.cube(), scale=0.5))


def test_explorer_accepts_a_mesh_and_refits_on_a_new_shape():
    mesh = shapes.torus()
    e = pentanb.explore(mesh, iterations=0)
    check_buffers(e.view, mesh)
    e.view.camera.position = (100.0, 0.0, 0.0)
    e.shape.value = "tetrahedron"
    check_buffers(e.view, shapes.tetrahedron())
    assert tuple(e.view.camera.position) != (100.0, 0.0, 0.0)


def test_explorer_caches_what_a_slider_revisits(monkeypatch):
    import pentanb.subdivision as sub

    calls = []
    real = sub.subdivide

    def counting(*args, **kwargs):
        calls.append(args[2] if len(args) > 2 else kwargs.get("iterations"))
        return real(*args, **kwargs)

    monkeypatch.setattr(sub, "subdivide", counting)
    e = pentanb.explore("tetrahedron", iterations=2)
    n = len(calls)
    assert n == 2  # level 2 built one iteration at a time, level 1 kept
    e.iterations.value = 1
    e.iterations.value = 2
    e.iterations.value = 3
    assert len(calls) == n + 1  # only level 3 was new, built from level 2


def test_explorer_refuses_too_large_with_the_size(monkeypatch):
    e = pentanb.explore("cube", iterations=1, max_faces=1000)
    geometry_before = arr(e.view.face_geometry.attributes["position"]).copy()
    e.iterations.value = 4  # 24 * 5**3 = 3000 faces > 1000
    assert "3,000 faces" in e.status.value
    np.testing.assert_array_equal(arr(e.view.face_geometry.attributes["position"]), geometry_before)
    assert e.progress.layout.visibility == "hidden"


def test_explorer_shows_subdivides_memory_error():
    e = pentanb.explore("cube", iterations=1, max_bytes=10_000)
    e.iterations.value = 3
    assert "bytes" in e.status.value and "faces" in e.status.value


def test_explorer_drives_the_progress_bar():
    e = pentanb.explore("cube", iterations=0)
    seen = []
    e.progress.observe(lambda c: seen.append(c["new"]), names="value")
    e.iterations.value = 2
    assert max(seen) == e.progress.max == 2 * (1 + e.duals.value)
    assert e.progress.layout.visibility == "hidden"


# -- step-through --------------------------------------------------------------


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
@pytest.mark.parametrize("name", ["tetrahedron", "cube", "mixed"])
def test_step_through_stages(scheme, name):
    mesh = MESHES[name]()
    st = pentanb.step_through(mesh, scheme)
    n_groups = int(mesh.face_sizes.max())
    pre = 3  # input, new points, point sphere / inner copies
    assert len(st.stages) == pre + n_groups + 3
    first, last_group = st.stages[0][1], st.stages[pre + n_groups - 1][1]
    # the pieces tile the same surface from the first stage on
    assert first.n_faces == last_group.n_faces
    # the input's edges only, then all inserted edges at the last group
    assert len(first.segments) == mesh.n_edges
    result = st.stages[pre + n_groups][1]
    expected = pentanb.SCHEMES[scheme](mesh)
    assert result.n_faces == expected.n_faces
    inserted = len(last_group.segments) - mesh.n_edges
    if scheme == "pentagonalize":
        assert inserted == len(mesh.corners)  # one spoke per corner
        assert last_group.legend == {5: expected.n_faces}
    else:
        assert inserted == 2 * len(mesh.corners)  # copy edges and spokes
    # after every group, all pieces are pentagon-coloured at the end
    np.testing.assert_allclose(
        last_group.face_colors[-len(mesh.corners) :], face_rgb(np.full(len(mesh.corners), 5))
    )

    # the geometric pieces cover the result's area
    def area(p, o):
        return sum(
            np.linalg.norm(
                np.cross(
                    p[o[f] + 1 : o[f + 1] - 1] - p[o[f]],
                    p[o[f] + 2 : o[f + 1]] - p[o[f]],
                ),
                axis=1,
            ).sum()
            for f in range(len(o) - 1)
        )

    expected_area = area(expected.vertices[expected.corners], expected.offsets)
    assert (
        abs(area(last_group.positions, last_group.offsets) - expected_area)
        < 1e-9 * max(expected_area, 1) + 1e-9
        or scheme == "preserve_pentagons"
        or name == "mixed"
    )


def test_step_slider_updates_the_view_in_place():
    st = pentanb.step_through(shapes.cube())
    position = st.view.face_geometry.attributes["position"]
    for k in range(1, len(st.stages)):
        st.step.value = k
        assert st.view.face_geometry.attributes["position"] is position
        assert f"<b>{k}/" in st.caption.value
    final = st.stages[-1][1]
    check_buffers(st.view, final)
    st.step.value = 1
    assert st.view.points.visible


def test_step_through_other_schemes_show_input_result_duals():
    st = pentanb.step_through(shapes.cube(), "loop_remesh")
    assert len(st.stages) == 4


# -- export ----------------------------------------------------------------------


def test_export_online_page_references_the_cdn(tmp_path):
    path = html.export_html(shapes.cube(), tmp_path / "cube.html", offline=False)
    text = path.read_text()
    assert "cdn.jsdelivr.net/npm/@jupyter-widgets/html-manager" in text
    state = _state(text)
    names = {s["model_name"] for s in state["state"].values()}
    assert {"RendererModel", "BufferGeometryModel", "BufferAttributeModel"} <= names


def _state(text):
    m = re.search(
        r'<script type="application/vnd.jupyter.widget-state\+json">\n(.*?)\n'
        r"</script>",
        text,
        re.S,
    )
    return json.loads(m.group(1))


def _require_offline_scripts():
    try:
        html.offline_scripts()
    except FileNotFoundError as err:
        import os

        if os.environ.get("CI") == "true":
            pytest.fail(f"CI must have the npm cache (.ci/browser-setup.sh): {err}")
        pytest.skip(str(err))


def test_export_offline_page_loads_no_script_from_the_network(tmp_path):
    _require_offline_scripts()
    e = pentanb.explore("tetrahedron", iterations=2)
    path = html.export_html(e, tmp_path / "explorer.html")
    text = path.read_text()
    assert not re.search(r"<script[^>]+src=", text)
    assert "cdn.jsdelivr" not in text.split("<body>")[1]
    state = _state(text)
    names = [s["model_name"] for s in state["state"].values()]
    assert names.count("RendererModel") == 3  # levels 0, 1, 2
    assert "StackModel" in names and "LinkModel" in names


def test_export_refuses_unknown_objects(tmp_path):
    with pytest.raises(TypeError):
        html.export_html(42, tmp_path / "x.html", offline=False)


def test_offline_without_cache_says_how_to_fill_it(tmp_path, monkeypatch):
    monkeypatch.setenv("PENTANB_JS_DIR", str(tmp_path / "nothing"))
    with pytest.raises(FileNotFoundError, match="npm install"):
        html.export_html(shapes.cube(), tmp_path / "x.html")


def test_import_pentanb_does_not_import_the_widget_libraries():
    import subprocess
    import sys

    code = (
        "import sys, pentanb; bad = [m for m in ('pythreejs', 'ipywidgets') "
        "if m in sys.modules]; print(bad); sys.exit(1 if bad else 0)"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_lazy_names_are_exposed():
    assert pentanb.view is three.view
    assert pentanb.explore is three.explore
    assert pentanb.export_html is html.export_html
    assert callable(pentanb.step_through)
    assert steps.step_through is not None
