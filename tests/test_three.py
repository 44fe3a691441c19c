"""The 3D widgets as Python models: drawings, buffers, in-place updates, camera,
the explorer, the step-through, the notebooks' panel, export, and the layout of
``pentanb.viz``.

What the browser shows is checked by ``tests/test_browser.py``; here the
widget models are checked against the mesh arrays they must carry, and the
widgets' arguments against what :func:`pentanb.subdivide` refuses.
"""

from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("ipywidgets")
pytest.importorskip("pythreejs")

from helpers import face_lists

import pentanb
from pentanb import shapes
from pentanb.viz import drawing as drawing_module
from pentanb.viz import explorer, html, stages, steps, three, widgets
from pentanb.viz.colors import EDGE_COLOR, face_rgb, hex_to_rgb

ROOT = Path(__file__).resolve().parent.parent
VIZ = ROOT / "pentanb" / "viz"


def arr(attribute):
    return np.asarray(attribute.array)


def mixed_mesh():
    """Triangles and pentagons in one mesh (pentagon preservation of a tetrahedron)."""
    return pentanb.preserve_pentagons(shapes.tetrahedron())


MESHES = {
    "tetrahedron": shapes.tetrahedron,
    "cube": shapes.cube,
    "dodecahedron": shapes.dodecahedron,
    "torus": shapes.torus,
    "mixed": mixed_mesh,
    "pentagonalized cube": lambda: pentanb.pentagonalize(shapes.cube()),
}


def fan(mesh):
    """Fan triangles and their faces, in plain Python from the face lists."""
    tris, owner = [], []
    for f, face in enumerate(face_lists(mesh)):
        for k in range(len(face) - 2):
            tris.append([face[0], face[k + 1], face[k + 2]])
            owner.append(f)
    return np.array(tris), np.array(owner)


def newell(mesh):
    """Unit normal of every face by Newell's formula over its edges (no triangles)."""
    out = []
    for face in face_lists(mesh):
        p = mesh.vertices[face]
        q = np.roll(p, -1, axis=0)
        n = np.array(
            [
                ((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])).sum(),
                ((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])).sum(),
                ((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])).sum(),
            ]
        )
        out.append(n / np.linalg.norm(n))
    return np.array(out)


def smooth_normals(mesh):
    """Unit normal at every vertex: the sum of its faces' Newell vectors, normalised."""
    total = np.zeros((mesh.n_vertices, 3))
    for face in face_lists(mesh):
        p = mesh.vertices[face]
        q = np.roll(p, -1, axis=0)
        area = np.cross(p, q).sum(axis=0)
        for u in face:
            total[u] += area
    return total / np.linalg.norm(total, axis=1)[:, None]


def newell_in_order(mesh):
    """Every face's vector area, summed corner by corner in plain floats."""
    out = []
    for face in face_lists(mesh):
        p = [tuple(float(x) for x in mesh.vertices[u]) for u in face]
        a = [0.0, 0.0, 0.0]
        for i, (x, y, z) in enumerate(p):
            xj, yj, zj = p[(i + 1) % len(p)]
            a[0] += y * zj - z * yj
            a[1] += z * xj - x * zj
            a[2] += x * yj - y * xj
        out.append(a)
    return np.array(out)


@pytest.mark.parametrize("block", [1, 2, 3, 7, 8192])
@pytest.mark.parametrize("text", ["C", "tI", "open"])
def test_face_areas_in_blocks_are_newells_sums_bit_for_bit(monkeypatch, block, text):
    # the numpy path works out a block of faces at a time, faces of one size
    # together: whatever the blocks, every face's sum is the in-order one
    m = shapes.open_disk() if text == "open" else pentanb.conway(text)
    monkeypatch.setattr(drawing_module, "AREA_BLOCK", block)
    got = drawing_module.face_areas(m)
    assert got.tobytes() == newell_in_order(m).tobytes()


def check_buffers(v: three.MeshView, mesh: pentanb.Mesh):
    fa = v.face_geometry.attributes
    pos, idx = arr(fa["position"]), arr(fa["index"])
    col = arr(fa["color"]) / 255
    assert pos.dtype == np.float32 and arr(fa["color"]).dtype == np.uint8
    assert idx.dtype == np.uint32 and idx.ndim == 1  # WebGL's index: one flat uint32 array
    assert fa["color"].normalized  # bytes read as [0, 1]
    assert len(pos) == len(col) and int(idx.max()) < len(pos)
    tris, owner = fan(mesh)
    # every polygon is the fan of triangles from its first corner
    assert len(idx) == 3 * len(tris) == 3 * (len(mesh.corners) - 2 * mesh.n_faces)
    np.testing.assert_allclose(pos[idx], mesh.vertices[tris].reshape(-1, 3), atol=1e-6)
    # each triangle has the colour of its face's size, on its three corners
    sizes = np.array([len(f) for f in face_lists(mesh)])
    np.testing.assert_array_equal(col[idx], np.repeat(face_rgb(sizes[owner]), 3, axis=0))  # exact
    # indexed: the vertices once per face size present, not three rows per triangle
    assert len(pos) == len(set(sizes.tolist())) * mesh.n_vertices
    # every triangle corner carries its vertex's smooth normal (worked out here)
    nor = arr(fa["normal"])
    assert nor.dtype == np.float32 and len(nor) == len(pos)
    np.testing.assert_allclose(nor[idx], smooth_normals(mesh)[tris].reshape(-1, 3), atol=1e-6)
    # edges: both ends of every edge, in the edge colour
    ea = v.edge_geometry.attributes
    eidx = arr(ea["index"])
    assert eidx.dtype == np.uint32
    seg = arr(ea["position"])[eidx].reshape(-1, 2, 3)
    expected = {
        tuple(sorted((f[i], f[(i + 1) % len(f)]))) for f in face_lists(mesh) for i in range(len(f))
    }
    assert len(seg) == len(expected) == mesh.n_edges
    np.testing.assert_allclose(
        np.sort(seg.reshape(len(seg), -1), axis=0),
        np.sort(mesh.vertices[np.array(sorted(expected))].reshape(len(seg), -1), axis=0),
        atol=1e-6,
    )
    ecol = arr(ea["color"])[eidx] / 255
    np.testing.assert_array_equal(ecol, np.tile(hex_to_rgb(EDGE_COLOR), (len(ecol), 1)))


# -- the view -------------------------------------------------------------------------


@pytest.mark.parametrize("name", list(MESHES))
def test_view_buffers_match_mesh(name):
    mesh = MESHES[name]()
    v = pentanb.view(mesh)
    check_buffers(v, mesh)
    assert v.renderer in v.children
    # smooth normals, not flat shading (which shows every fan triangle)
    assert not v.faces.material.flatShading
    assert v.faces.material.vertexColors == "VertexColors"
    assert v.edges.visible and v.wireframe.value


def test_check_buffers_fails_on_a_wrong_mesh():
    v = pentanb.view(shapes.cube())
    with pytest.raises(AssertionError):
        check_buffers(v, shapes.tetrahedron())
    moved = shapes.cube().with_vertices(shapes.cube().vertices * 2)
    with pytest.raises(AssertionError):
        check_buffers(v, moved)


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


def test_camera_looks_at_its_target():
    eye, target = np.array([3.0, -2.0, 1.5]), np.array([0.5, 0.2, -0.1])
    x, y, z, w = drawing_module.look_at_quaternion(eye, target)
    # rotate the camera's -z axis by the quaternion: it must point at the target
    q = np.array([x, y, z])
    d = np.array([0.0, 0.0, -1.0])
    rotated = d + 2 * np.cross(q, np.cross(q, d) + w * d)
    np.testing.assert_allclose(rotated, (target - eye) / np.linalg.norm(target - eye), atol=1e-12)


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
        v.face_geometry.attributes["color"],
        v.edge_geometry.attributes["position"],
    ]
    before = [a.version for a in attrs]
    v.update(shapes.tetrahedron())
    after = [a.version for a in attrs]
    assert all(b > a + 1000 for a, b in zip(before, after))


@pytest.mark.parametrize(
    "first, second", [("tetrahedron", "dodecahedron"), ("dodecahedron", "tetrahedron")]
)
def test_update_never_leaves_positions_longer_than_colours(first, second):
    """The position buffer sets how many vertices WebGL reads: growing, the
    colours are replaced first; shrinking, the positions."""
    v = pentanb.view(shapes.get(first))
    attributes = v.face_geometry.attributes
    lengths = {kind: len(attributes[kind].array) for kind in ("position", "color")}
    order = []
    for kind in ("position", "color"):
        attributes[kind].observe(
            lambda change, kind=kind: order.append((kind, len(change["new"]))), names="array"
        )
    v.update(shapes.get(second))
    assert sorted(kind for kind, _ in order) == ["color", "position"]
    for kind, n in order:  # replay the replacements: positions never outnumber colours
        lengths[kind] = n
        assert lengths["position"] <= lengths["color"], order


def test_hidden_points_are_not_sent_again_and_shown_points_are():
    # mesh after mesh: no points either time, so the hidden placeholder row
    # is not replaced (two messages fewer a move); points to show, and the
    # move back to none, are written
    v = pentanb.view(shapes.cube())
    pa = v.point_geometry.attributes
    placeholder = (pa["position"].array, pa["color"].array)
    v.update(shapes.dodecahedron())
    assert pa["position"].array is placeholder[0] and pa["color"].array is placeholder[1]
    assert not v.points.visible
    d = drawing_module.drawing(shapes.cube(), points=np.eye(3))
    v.update(d)
    assert v.points.visible and len(pa["position"].array) == 3
    np.testing.assert_array_equal(pa["position"].array, np.eye(3, dtype=np.float32))
    v.update(shapes.tetrahedron())
    assert not v.points.visible and len(pa["position"].array) == 1


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
    renderer = v.renderer
    v.camera.position = (5.0, -1.0, 2.0)  # the reader orbited
    camera_before = tuple(v.camera.position)
    v.update(b)
    assert v.face_geometry is geometry and v.renderer is renderer
    assert v.face_geometry.attributes["position"] is position
    assert tuple(v.camera.position) == camera_before
    check_buffers(v, b)
    v.update(a)  # smaller again
    check_buffers(v, a)


def test_drawing_refuses_what_is_not_a_mesh():
    with pytest.raises(TypeError, match=r"pentanb\.Mesh or a Drawing, got list"):
        pentanb.view([[0, 0, 0]])
    with pytest.raises(TypeError, match=r"drawing\(\) expects a pentanb\.Mesh, got str"):
        drawing_module.drawing("cube")


# -- the explorer ------------------------------------------------------------------------


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


def test_explorer_close_frees_the_explorer_and_its_meshes():
    import gc
    import weakref

    e = pentanb.explore("cube", iterations=0)
    e.iterations.value = 1
    v = e.view
    inside = [e, e.shape, e.scheme, e.iterations, e.duals, e.scale, e.progress, e.status]
    inside += [e.counts, v, v.renderer, v.scene, v.camera, v.controls, v.legend, v.wireframe]
    inside += [v.faces, v.edges, v.points, v.face_geometry, v.face_material, v.headlight]
    inside += list(v.face_geometry.attributes.values()) + list(v.edge_geometry.attributes.values())
    assert all(w.comm is not None for w in inside)
    alive = weakref.ref(e), weakref.ref(e.mesh), weakref.ref(v.renderer)
    e.close()
    e.close()  # twice is harmless
    assert [type(w).__name__ for w in inside if w.comm is not None] == []
    del e, v, inside
    gc.collect()
    assert [r() for r in alive] == [None, None, None]


def test_plain_close_would_keep_the_explorer_alive():
    # what Explorer.close mends: ipywidgets' own close() leaves the sliders
    # open, and their observers keep the explorer (and its cache) alive
    import gc
    import weakref

    import ipywidgets

    e = pentanb.explore("cube", iterations=0)
    alive = weakref.ref(e)
    ipywidgets.Widget.close(e)
    del e
    gc.collect()
    assert alive() is not None
    alive().close()


def test_view_close_leaves_a_shared_camera_open(tmp_path):
    like = pentanb.view(shapes.cube())
    box = three.slider_stack([shapes.cube(), shapes.tetrahedron()], ["a", "b"], like)
    first, second = box.children[3].children
    assert first.camera is second.camera
    first.close()
    assert first.renderer.comm is None and first.face_geometry.comm is None
    assert second.camera.comm is not None and second.renderer.comm is not None
    assert first.mesh is None
    # its links are closed with it: a link left open with a closed end makes
    # every later export fail ('NoneType' object has no attribute 'comm_id')
    html.export_html(pentanb.view(shapes.cube()), tmp_path / "after.html", offline=False)
    # the whole box closes the camera too (nothing else holds it)
    assert three.close_tree(box) > 0
    assert second.camera.comm is None and second.renderer.comm is None
    assert three.close_tree(box) == 0  # nothing left open


def test_step_through_and_panel_close_everything_inside():
    s = pentanb.step_through(shapes.cube())
    inside = [s.step, s.caption, s.view, s.view.renderer, s.view.face_geometry]
    s.close()
    assert [w for w in inside if w.comm is not None] == []

    def draw(n=1):
        return pentanb.subdivide(shapes.cube(), "pentagonalize", n)

    p = widgets.panel(draw, n=(0, 2))
    assert p.view is not None
    inside = [*p.controls.values(), p.output, p.view, p.view.renderer, p.view.points]
    p.close()
    assert [w for w in inside if w.comm is not None] == []


def test_close_tree_refuses_what_is_not_a_widget():
    with pytest.raises(TypeError, match=r"ipywidgets\.Widget, got Mesh"):
        three.close_tree(shapes.cube())


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
    calls = []
    real = explorer.subdivide

    def counting(*args, **kwargs):
        calls.append(args[2] if len(args) > 2 else kwargs.get("iterations"))
        return real(*args, **kwargs)

    monkeypatch.setattr(explorer, "subdivide", counting)
    e = pentanb.explore("tetrahedron", iterations=2)
    n = len(calls)
    assert n == 2  # level 2 built one iteration at a time, level 1 kept
    e.iterations.value = 1
    e.iterations.value = 2
    e.iterations.value = 3
    assert len(calls) == n + 1  # only level 3 was new, built from level 2


def test_explorer_refuses_too_large_with_the_size():
    e = pentanb.explore("cube", iterations=1, max_faces=1000)
    geometry_before = arr(e.view.face_geometry.attributes["position"]).copy()
    # level 3: 600 pentagons, 1,500 edges, 902 vertices; level 4: 3,000
    # pentagons with 902 + 3,000 + 600 = 4,502 vertices, so its first dual
    # has 4,502 faces, the largest step
    e.iterations.value = 4
    assert "4,502 faces" in e.status.value and "at iteration 4" in e.status.value
    np.testing.assert_array_equal(arr(e.view.face_geometry.attributes["position"]), geometry_before)
    assert e.progress.layout.visibility == "hidden"


def test_explorer_counts_every_step_not_only_the_last():
    """Pentagonalizing the cube makes 24 pentagons, whose dual has 38 faces,
    whose dual has 24 again: with 30 faces allowed, the middle step is too
    large although the result is not."""
    e = pentanb.explore("cube", iterations=0, max_faces=30)
    e.iterations.value = 1
    assert "38 faces" in e.status.value and "at iteration 1" in e.status.value
    assert e.mesh.n_faces == 6  # still the cube


def test_explorer_refuses_a_huge_level_at_once():
    e = pentanb.explore("cube", iterations=0, max_iterations=1000, max_faces=1000)
    with pytest.raises(pentanb.MeshError, match="at iteration 4"):
        e.mesh_at(1000)  # stops at the first level too large, builds nothing


def test_explorer_shows_subdivides_memory_error():
    e = pentanb.explore("cube", iterations=0, max_bytes=10_000)
    e.iterations.value = 3
    assert "bytes" in e.status.value and "faces" in e.status.value
    assert e.iterations.value == 0  # back to the mesh shown
    # a first request refused is an error at once (no picture the controls do not describe)
    with pytest.raises(pentanb.MeshError, match="10,000 bytes"):
        pentanb.explore("cube", iterations=1, max_bytes=10_000)


class FakeClock:
    """The explorer's clock (:attr:`Explorer.clock`): each reading ``step``
    seconds after the last, whatever the machine's load (0: time stands still)."""

    def __init__(self, step: float = 0.0):
        self.now, self.step = 0.0, step

    def __call__(self) -> float:
        t = self.now
        self.now += self.step
        return t


def test_the_explorer_measures_its_progress_delay_on_the_real_clock():
    import time

    assert explorer.Explorer.clock is time.perf_counter
    assert pentanb.explore("cube", iterations=0).clock is time.perf_counter


def test_explorer_drives_the_progress_bar():
    e = pentanb.explore("cube", iterations=0)
    e.progress_seconds = -1.0  # every request counts as long: the bar from the start
    seen, shown = [], []
    e.progress.observe(lambda c: seen.append(c["new"]), names="value")
    e.progress.layout.observe(lambda c: shown.append(c["new"]), names="visibility")
    e.iterations.value = 2
    assert max(seen) == e.progress.max == 2 * (1 + e.duals.value)
    assert shown == ["visible", "hidden"]


def test_a_quick_move_sends_no_progress_but_a_slow_one_does():
    e = pentanb.explore("cube", iterations=0)
    e.clock = clock = FakeClock()  # time stands still: every move is quick
    changes = []
    for label, w in (("steps", e.progress), ("status", e.status)):
        w.observe(lambda c, label=label: changes.append((label, c["new"])), names="value")
    e.progress.layout.observe(lambda c: changes.append(("bar", c["new"])), names="visibility")
    e.iterations.value = 1  # three steps, no time passes: no message at all
    assert changes == []
    assert e.mesh.n_faces > 6
    # a move that takes longer than PROGRESS_AFTER shows the bar from then on:
    # each step's report comes 0.6 PROGRESS_AFTER after the last, so the
    # first comes too early and the second shows the bar
    clock.step = 0.6 * e.PROGRESS_AFTER
    e.iterations.value = 2
    assert changes[:2] == [("bar", "visible"), ("status", "<i>computing...</i>")]
    assert [v for k, v in changes if k == "steps"] == [2, 3]  # (not 0 or 1)
    assert changes[-2:] == [("bar", "hidden"), ("status", "")]
    # a step reported just before the delay passes sends nothing
    clock.step = 0.3 * e.PROGRESS_AFTER  # reports at 0.3, 0.6, 0.9 of the delay
    changes.clear()
    e.iterations.value = 3
    assert changes == []
    # and a request predicted to take over progress_seconds shows it before the first step
    clock.step = 0.0
    e.progress_seconds = 0.0
    e.iterations.value = 4
    assert changes[:3] == [("steps", 0), ("bar", "visible"), ("status", "<i>computing...</i>")]
    assert [v for k, v in changes if k == "steps"] == [0, 1, 2, 3]


@pytest.mark.slow  # (the compiled kernels' first use in a process)
def test_a_slider_move_of_a_hundred_thousand_faces_sends_no_progress():
    # pentagon preservation of 16,384 quads: 114,688 faces at its first
    # dual, some ten milliseconds of work: predicted under progress_seconds, so no bar
    # and no status message (time stands still: the delay is tested above)
    e = pentanb.explore(
        shapes.torus(128, 128), "preserve_pentagons", iterations=0, max_faces=200_000
    )
    e.clock = FakeClock()
    changes = []
    for w in (e.progress, e.status):
        w.observe(lambda c: changes.append(c["new"]), names="value")
    e.progress.layout.observe(lambda c: changes.append(c["new"]), names="visibility")
    # 16,384 quads -> 81,920 faces -> 114,688 -> 81,920: 278,528 faces built
    assert e.predicted_seconds(1) == pytest.approx(278_528 * e.seconds_per_face)
    assert e.predicted_seconds(1) < e.progress_seconds
    e.iterations.value = 1
    assert max(F for _, (_, _, F) in e._largest_steps(e._base(e.shape.value), 1)) == 114_688
    assert e.mesh.n_faces == 16_384 + 4 * 16_384 and changes == []


#: (arguments of explore, exception, message): what subdivide refuses, the
#: explorer refuses too, naming the argument and its range (issue 12, item 7).
def _stable_id(kwargs: dict) -> str:
    """A test id without memory addresses (the same in every pytest-xdist worker)."""
    return ",".join(f"{k}={getattr(v, '__name__', None) or v!r}" for k, v in kwargs.items())


EXPLORE_REFUSALS = [
    ({"iterations": -1}, ValueError, r"iterations must be an integer >= 0, got -1"),
    (
        {"iterations": 10**9},
        ValueError,
        r"iterations=1000000000 is more than max_iterations=5",
    ),
    ({"iterations": 1.5}, TypeError, r"iterations must be an integer >= 0, got float 1.5"),
    ({"iterations": 2.0}, TypeError, r"iterations must be an integer >= 0, got float 2.0"),
    ({"iterations": "2"}, TypeError, r"iterations must be an integer >= 0, got str '2'"),
    ({"iterations": True}, TypeError, r"iterations must be an integer >= 0, got bool"),
    ({"duals": -1}, ValueError, r"duals must be an integer in \[0, 4\], got -1"),
    ({"duals": 5}, ValueError, r"duals must be an integer in \[0, 4\], got 5"),
    ({"scale": 2}, ValueError, r"scale must be a number in \[0.05, 0.95\], got 2"),
    ({"scale": 0.0}, ValueError, r"scale must be a number in \[0.05, 0.95\], got 0.0"),
    ({"scale": "0.5"}, TypeError, r"scale must be a number in \[0.05, 0.95\], got str"),
    (
        {"max_iterations": -1},
        ValueError,
        r"max_iterations must be an integer in \[0, 1,000\], got -1",
    ),
    ({"max_iterations": 2}, ValueError, r"iterations=3 is more than max_iterations=2"),
    ({"max_faces": 0}, ValueError, r"max_faces must be an integer >= 1, got 0"),
    ({"scheme": "pentagonalise"}, ValueError, r"unknown scheme 'pentagonalise'; known schemes"),
    ({"scheme": pentanb.dual}, TypeError, r"scheme must be the name of a scheme"),
    ({"mesh": None}, TypeError, r"shape must be a pentanb.Mesh, a shape name or the path"),
    ({"mesh": "sphere"}, ValueError, r"unknown shape 'sphere'"),
]


@pytest.mark.parametrize(
    "kwargs, error, message", EXPLORE_REFUSALS, ids=[_stable_id(k) for k, _, _ in EXPLORE_REFUSALS]
)
def test_explore_refuses_what_its_controls_cannot_show(kwargs, error, message):
    kwargs = {"mesh": "cube", **kwargs}
    if "max_iterations" in kwargs and kwargs["max_iterations"] == 2:
        kwargs["iterations"] = 3
    mesh = kwargs.pop("mesh")
    with pytest.raises(error, match=message):
        pentanb.explore(mesh, **kwargs)


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda e: e.mesh_at(-1), ValueError, r"iterations must be an integer in \[0, 5\], got -1"),
        (lambda e: e.mesh_at(6), ValueError, r"iterations must be an integer in \[0, 5\], got 6"),
        (lambda e: e.mesh_at(1.0), TypeError, r"iterations must be an integer in \[0, 5\]"),
        (lambda e: e.export_plan(max_bytes=0), ValueError, r"max_bytes must be an integer >= 1"),
        (lambda e: e.export_plan(max_faces=1.5), TypeError, r"max_faces must be an integer >= 1"),
    ],
    ids=["mesh_at(-1)", "mesh_at(6)", "mesh_at(1.0)", "export_plan(max_bytes=0)", "max_faces=1.5"],
)
def test_explorer_methods_refuse_levels_the_slider_cannot_show(call, error, message):
    e = pentanb.explore("cube", iterations=0)
    with pytest.raises(error, match=message):
        call(e)


def test_explorer_accepts_its_range_ends():
    e = pentanb.explore("cube", iterations=0, duals=4, scale=0.95, max_iterations=0)
    assert (e.iterations.value, e.duals.value, e.scale.value) == (0, 4, 0.95)
    assert e.mesh_at(0) is e.mesh_at(np.int64(0))


# -- the step-through ------------------------------------------------------------


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
@pytest.mark.parametrize("name", ["tetrahedron", "cube", "mixed"])
def test_step_through_stages(scheme, name):
    mesh = MESHES[name]()
    st = pentanb.step_through(mesh, scheme)
    n_groups = int(mesh.face_sizes.max())
    pre = 3  # input, new points, point sphere / inner copies
    assert len(st.stages) == pre + n_groups + 3
    first, last_group = st.stages[0][1], st.stages[pre + n_groups - 1][1]
    result = st.stages[pre + n_groups][1]
    expected = pentanb.SCHEMES[scheme](mesh)
    E, F, H = mesh.n_edges, mesh.n_faces, len(mesh.corners)
    # the pieces are the result's faces from the first stage on
    assert (
        first.n_faces == last_group.n_faces == (2 * E if scheme == "pentagonalize" else F + 2 * E)
    )
    np.testing.assert_allclose(first.vertices, expected.vertices)
    np.testing.assert_array_equal(first.triangles, fan(expected)[0])
    assert result.n_faces == expected.n_faces
    # the input's edges only, then all inserted edges at the last group
    assert len(first.segments) == E
    inserted = len(last_group.segments) - E
    if scheme == "pentagonalize":
        assert inserted == H  # one spoke per corner
        assert last_group.legend == {5: expected.n_faces}
    else:
        assert inserted == 2 * H  # copy edges and spokes
    # every inserted segment is an edge of the result (before its duals)

    def keys(segments):
        return {tuple(sorted(map(tuple, np.round(seg, 9)))) for seg in segments}

    assert keys(last_group.segments[E:]) <= keys(expected.vertices[expected.edges])
    assert not keys(last_group.segments[:E]) & keys(expected.vertices[expected.edges])
    # after the last group, every piece around a corner is a pentagon
    np.testing.assert_allclose(last_group.face_colors[-H:], face_rgb(np.full(H, 5)))
    # at first, the pieces of a non-pentagon are not pentagon-coloured
    parent_sizes = np.repeat(mesh.face_sizes, mesh.face_sizes)
    green = np.isclose(first.face_colors[-H:], face_rgb(np.full(H, 5))).all(axis=1)
    assert (parent_sizes != 5).any()
    assert not green[parent_sizes != 5].any()


def test_pentagonalize_step_one_marks_the_trisection_points():
    mesh = shapes.cube()
    st = pentanb.step_through(mesh)
    caption, d = st.stages[1]
    assert "three equal parts" in caption
    expected = []
    for face in face_lists(mesh):
        for i, u in enumerate(face):
            w = face[(i + 1) % len(face)]
            if u < w:
                a, b = mesh.vertices[u], mesh.vertices[w]
                expected += [a + (b - a) / 3, a + 2 * (b - a) / 3]
    np.testing.assert_allclose(np.sort(d.points, axis=0), np.sort(expected, axis=0), atol=1e-12)


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


def test_step_through_preservation_honours_scale():
    cube = shapes.cube()
    st = pentanb.step_through(cube, "preserve_pentagons", scale=0.5, duals=0)
    result = st.stages[-1][1]
    np.testing.assert_allclose(
        result.vertices, pentanb.preserve_pentagons(cube, scale=0.5).vertices
    )
    assert "scaled by 0.5" in st.stages[2][0]
    default = pentanb.step_through(cube, "preserve_pentagons", duals=0).stages[-1][1]
    assert not np.allclose(default.vertices, result.vertices)


STEP_REFUSALS = [
    ((None,), {}, TypeError, r"mesh must be a pentanb.Mesh, got NoneType"),
    (("cube",), {}, TypeError, r"mesh must be a pentanb.Mesh, got str \(for a shape by name"),
    ((shapes.cube(),), {"duals": -1}, ValueError, r"duals must be an integer in \[0, 12\], got -1"),
    ((shapes.cube(),), {"duals": 13}, ValueError, r"duals must be an integer in \[0, 12\], got 13"),
    ((shapes.cube(),), {"duals": 1.0}, TypeError, r"duals must be an integer in \[0, 12\]"),
    (
        (shapes.cube(), "pentagonalize"),
        {"scale": 0.5},
        ValueError,
        r"scheme 'pentagonalize' takes no options; got scale",
    ),
    ((shapes.cube(), "quintify"), {}, ValueError, r"unknown scheme 'quintify'"),
    ((shapes.cube(), "preserve_pentagons"), {"scale": 1.5}, ValueError, r"scale must be in"),
]


@pytest.mark.parametrize(
    "args, kwargs, error, message",
    STEP_REFUSALS,
    ids=["None", "'cube'", "duals=-1", "duals=13", "duals=1.0", "scale", "unknown", "scale=1.5"],
)
def test_step_through_refuses_bad_arguments(args, kwargs, error, message):
    with pytest.raises(error, match=message):
        pentanb.step_through(*args, **kwargs)


# -- the notebooks' panel -------------------------------------------------------------


def test_panel_calls_the_function_with_the_controls_values():
    calls = []

    def draw(scheme="pentagonalize", dual_passes=2, scale=0.75):
        calls.append((scheme, dual_passes, scale))
        return pentanb.subdivide(shapes.tetrahedron(), scheme, 1, dual_passes)

    p = widgets.panel(
        draw,
        scheme=["pentagonalize", "honeycomb"],
        dual_passes=(0, 4),
        scale=(0.1, 0.9, 0.05),
    )
    import ipywidgets as W

    assert isinstance(p.controls["scheme"], W.Dropdown)
    assert isinstance(p.controls["dual_passes"], W.IntSlider)
    assert isinstance(p.controls["scale"], W.FloatSlider)
    assert p.controls["dual_passes"].description == "dual passes"
    assert calls == [("pentagonalize", 2, 0.75)]  # the function's defaults come first
    check_buffers(p.view, p.mesh)
    view = p.view
    p.controls["dual_passes"].value = 1
    assert calls[-1] == ("pentagonalize", 1, 0.75)
    assert p.view is view and p.mesh.n_faces == 20  # the dual: an icosahedral mesh
    check_buffers(p.view, p.mesh)


def test_panel_limits_active_and_refit():
    def draw(shape="cube", iterations=1, scale=0.5):
        return pentanb.subdivide(shapes.get(shape), "pentagonalize", iterations, 0)

    p = widgets.panel(
        draw,
        shape=["cube", "tetrahedron"],
        iterations=(0, 5),
        scale=(0.1, 0.9),
        limits={"iterations": lambda v: 2 if v["shape"] == "cube" else 3},
        active={"scale": lambda v: v["iterations"] > 1},
        refit=["shape"],
    )
    assert p.controls["iterations"].max == 2
    assert p.controls["scale"].disabled and p.values["scale"] is None
    p.controls["iterations"].value = 2
    assert not p.controls["scale"].disabled and p.values["scale"] == 0.5
    p.view.camera.position = (50.0, 0.0, 0.0)
    p.controls["iterations"].value = 1
    assert tuple(p.view.camera.position) == (50.0, 0.0, 0.0)  # kept
    p.controls["shape"].value = "tetrahedron"
    assert p.controls["iterations"].max == 3
    assert tuple(p.view.camera.position) != (50.0, 0.0, 0.0)  # refitted


def test_panel_without_a_mesh_has_no_view():
    seen = []
    p = widgets.panel(lambda n=5: seen.append(n), n=(3, 10))
    p.controls["n"].value = 10
    assert seen == [5, 10] and p.view is None


def test_panel_passes_on_the_functions_errors():
    def draw(n=1):
        if n > 1:
            raise RuntimeError("no such mesh")

    p = widgets.panel(draw, n=(1, 3))
    with pytest.raises(RuntimeError, match="no such mesh"):
        p.controls["n"].value = 2


@pytest.mark.parametrize(
    "draw, controls, error, message",
    [
        (
            lambda n=11: None,
            {"n": (3, 10)},
            ValueError,
            r"n must be an integer in \[3, 10\], got 11",
        ),
        (lambda s="x": None, {"s": ["a", "b"]}, ValueError, r"s must be one of \['a', 'b'\]"),
        (lambda n: None, {"m": (1, 2)}, TypeError, r"takes no argument m"),
        (lambda n, m=1: None, {"m": (1, 2)}, TypeError, r"no control for the argument n"),
        (lambda n=1: None, {"n": "1 to 3"}, TypeError, r"control 'n': expected \(low, high"),
        (lambda n=1: None, {"n": (3, 1)}, ValueError, r"need low <= high"),
    ],
    ids=["default out of range", "default not an option", "unknown", "missing", "spec", "range"],
)
def test_panel_refuses_bad_controls(draw, controls, error, message):
    with pytest.raises(error, match=message):
        widgets.panel(draw, **controls)


# -- export ----------------------------------------------------------------------


def test_export_online_page_references_the_cdn(tmp_path):
    path = html.export_html(shapes.cube(), tmp_path / "cube.html", offline=False)
    text = path.read_text()
    versions = json.loads((VIZ / "js_versions.json").read_text())
    assert (
        "cdn.jsdelivr.net/npm/@jupyter-widgets/html-manager@"
        + versions["@jupyter-widgets/html-manager"]
    ) in text
    assert f"requirejs@{versions['requirejs']}/require.js" in text
    state = _state(text)
    names = {s["model_name"] for s in state["state"].values()}
    assert {"RendererModel", "BufferGeometryModel", "BufferAttributeModel"} <= names


def test_export_escapes_the_title(tmp_path):
    path = html.export_html(shapes.cube(), tmp_path / "c.html", offline=False, title="<b>&")
    text = path.read_text()
    assert "<title>&lt;b&gt;&amp;</title>" in text and "<h3>&lt;b&gt;&amp;</h3>" in text


def test_npm_versions_are_written_once():
    """pentanb/viz/js_versions.json is the one place: html.py and
    .ci/browser-setup.sh read it and write no version of their own."""
    versions = json.loads((VIZ / "js_versions.json").read_text())
    assert set(versions) == {"@jupyter-widgets/html-manager", "requirejs"}
    assert html.js_versions() == versions
    assert html.HTML_MANAGER_VERSION == versions["@jupyter-widgets/html-manager"]
    assert html.REQUIREJS_VERSION == versions["requirejs"]
    script = (ROOT / ".ci" / "browser-setup.sh").read_text()
    assert "pentanb/viz/js_versions.json" in script
    source = (VIZ / "html.py").read_text()
    for version in versions.values():
        pattern = re.escape(version)
        assert not re.search(pattern, script), f".ci/browser-setup.sh writes {version} itself"
        assert not re.search(rf"=\s*['\"]{pattern}['\"]", source), f"html.py assigns {version}"


def test_browser_setup_reads_the_versions_file(tmp_path):
    """The script's version reader, run on a cache missing one package, asks for it."""
    script = (ROOT / ".ci" / "browser-setup.sh").read_text()
    reader = script[script.index("<<'PYTHON'\n") + len("<<'PYTHON'\n") : script.index("\nPYTHON\n")]
    cache = tmp_path / "js"
    (cache / "node_modules" / "requirejs").mkdir(parents=True)
    versions = json.loads((VIZ / "js_versions.json").read_text())
    (cache / "node_modules" / "requirejs" / "package.json").write_text(
        json.dumps({"version": versions["requirejs"]})
    )
    out = subprocess.run(
        [sys.executable, "-", str(VIZ / "js_versions.json"), str(cache)],
        input=reader,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    manager = "@jupyter-widgets/html-manager"
    assert out == [f"{manager}@{versions[manager]}"]


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
    # a small budget: a few dozen meshes besides the inlined scripts
    path = html.export_html(e, tmp_path / "explorer.html", max_bytes=5_500_000)
    text = path.read_text()
    assert len(text.encode()) <= 5_500_000
    assert not re.search(r"<script[^>]+src=", text)
    assert "cdn.jsdelivr" not in text.split("<body>")[1]
    state = _state(text)
    names = [s["model_name"] for s in state["state"].values()]
    assert names.count("RendererModel") >= 3  # at least levels 0, 1, 2
    assert "StackModel" in names and "DirectionalLinkModel" in names


def test_export_refuses_unknown_objects(tmp_path):
    with pytest.raises(TypeError, match=r"takes a pentanb\.Mesh or a widget, not int"):
        html.export_html(42, tmp_path / "x.html", offline=False)


def test_offline_without_cache_says_how_to_fill_it(tmp_path, monkeypatch):
    monkeypatch.setenv("PENTANB_JS_DIR", str(tmp_path / "nothing"))
    with pytest.raises(FileNotFoundError, match="npm install"):
        html.export_html(shapes.cube(), tmp_path / "x.html")


# -- the layout of pentanb.viz -------------------------------------------------------

#: pentanb.viz from the bottom up: a module imports only modules before it.
LAYERS = [
    "colors",
    "camera",
    "drawing",
    "stages",
    "controls",
    "mpl",
    "spectra",
    "three",
    "widgets",
    "explorer",
    "steps",
    "html",
]
#: What each module may import besides the standard library, numpy and pentanb's core.
THIRD_PARTY = {
    "colors": set(),
    "camera": set(),
    "drawing": set(),
    "stages": set(),
    "controls": set(),
    "mpl": {"matplotlib", "mpl_toolkits"},
    "spectra": {"matplotlib"},
    "three": {"ipywidgets", "pythreejs"},
    "widgets": {"ipywidgets", "IPython"},
    "explorer": {"ipywidgets"},
    "steps": {"ipywidgets"},
    "html": {"ipywidgets", "pythreejs"},
}


def _imports(module: str):
    """(sibling modules, names taken from siblings, third-party packages) of a viz module."""
    tree = ast.parse((VIZ / f"{module}.py").read_text())
    siblings, names, packages = set(), [], set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            siblings.add(node.module)
            names += [(node.module, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            packages.add(node.module.split(".")[0])
        elif isinstance(node, ast.Import):
            packages.update(a.name.split(".")[0] for a in node.names)
    return siblings, names, packages - set(sys.stdlib_module_names) - {"numpy", "pentanb"}


def test_viz_modules_are_the_listed_ones():
    present = {p.stem for p in VIZ.glob("*.py")} - {"__init__"}
    assert present == set(LAYERS)


@pytest.mark.parametrize("module", LAYERS)
def test_viz_modules_import_one_way_and_no_private_names(module):
    siblings, names, packages = _imports(module)
    below = set(LAYERS[: LAYERS.index(module)])
    assert siblings <= below, f"viz.{module} imports {sorted(siblings - below)} (not below it)"
    private = [f"{m}.{n}" for m, n in names if n.startswith("_")]
    assert not private, f"viz.{module} takes private names {private}"
    assert packages <= THIRD_PARTY[module], f"viz.{module} imports {sorted(packages)}"


def test_layout_check_fails_on_an_upward_import(tmp_path, monkeypatch):
    fake = tmp_path / "viz"
    fake.mkdir()
    for name in LAYERS:
        (fake / f"{name}.py").write_text((VIZ / f"{name}.py").read_text())
    (fake / "three.py").write_text("from .steps import StepThrough\nfrom .colors import _x\n")
    monkeypatch.setattr(sys.modules[__name__], "VIZ", fake)
    with pytest.raises(AssertionError, match="imports \\['steps'\\]"):
        test_viz_modules_import_one_way_and_no_private_names("three")


def test_drawing_data_needs_numpy_only():
    code = (
        "import sys, pentanb.viz.stages, pentanb.viz.drawing, pentanb.viz.colors; "
        "bad = [m for m in ('matplotlib', 'ipywidgets', 'pythreejs', 'IPython') "
        "if m in sys.modules]; print(bad); sys.exit(1 if bad else 0)"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_import_pentanb_does_not_import_the_widget_libraries():
    code = (
        "import sys, pentanb; bad = [m for m in ('pythreejs', 'ipywidgets') "
        "if m in sys.modules]; print(bad); sys.exit(1 if bad else 0)"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_lazy_names_are_exposed():
    assert pentanb.view is three.view
    assert pentanb.explore is explorer.explore
    assert pentanb.step_through is steps.step_through
    assert pentanb.export_html is html.export_html
    assert stages.stages is not None


def test_explore_accepts_conway_notation():
    """Issue 10 item 5: a notation string wherever a scheme name is taken."""
    e = pentanb.explore("cube", "dg", iterations=1, duals=0)
    assert e.scheme.value == "dg"
    m = e.mesh_at(1)
    assert (m.n_vertices, m.n_edges, m.n_faces) == (24, 60, 38)  # the snub cube, sC
    assert m.face_size_histogram() == {3: 32, 4: 6}
    with pytest.raises(ValueError, match="Conway operators"):
        pentanb.explore("cube", "dgX")


def _same_buffers(a, b):
    """``b`` draws what ``a`` draws: the same triangles, colours and segments, in order."""
    drawn = {
        "triangles": lambda x: x.triangles(),
        "triangle colors": lambda x: x.triangle_colors(),
        "triangle normals": lambda x: x.triangle_normals(),
        "segments": lambda x: x.segments(),
        "boundary": lambda x: x.boundary(),
        "segment colors": lambda x: x.edge_color[x.edge_index][: 2 * x.edge_count],
        "point_position": lambda x: x.point_position,
        "point_color": lambda x: x.point_color,
    }
    for name, what in drawn.items():
        x, y = what(a), what(b)
        assert x.dtype == y.dtype and x.shape == y.shape, name
        assert np.array_equal(x, y), name
    for name in ("edge_count", "point_count", "boundary_count"):
        assert getattr(a, name) == getattr(b, name), name
    for name in ("position", "color", "index", "edge_position", "edge_color", "edge_index"):
        x, y = getattr(a, name), getattr(b, name)
        assert x.dtype == y.dtype, name
        assert y.flags.writeable and y.flags.c_contiguous, name
    assert int(b.index.max()) < len(b.position) == len(b.color)
    assert int(b.edge_index.max()) < len(b.edge_position) == len(b.edge_color)


def test_mesh_buffers_are_the_drawings_buffers(corpus_mesh):
    # the explorer's fast path gives, bit for bit, what the general path gives
    _same_buffers(
        drawing_module.buffers(drawing_module.drawing(corpus_mesh)),
        drawing_module.mesh_buffers(corpus_mesh),
    )


@pytest.mark.parametrize("text", ["dgC", "k4P6", "ddgT", "tI", "bbP5"])
def test_mesh_buffers_of_mixed_and_uniform_faces(text):
    m = pentanb.conway(text)
    _same_buffers(drawing_module.buffers(drawing_module.drawing(m)), drawing_module.mesh_buffers(m))


def test_mesh_buffers_hold_the_vertices_once_per_face_size():
    m = pentanb.conway("dgC")  # 32 triangles and 6 squares on 24 vertices
    b = drawing_module.mesh_buffers(m)
    assert b.position.shape == (2 * 24, 3) and b.index.shape == (3 * (32 + 2 * 6),)
    v = m.vertices.astype(np.float32)
    assert np.array_equal(b.position, np.concatenate([v, v]))
    triangle, square = (drawing_module._bytes(face_rgb(k)) for k in (3, 4))
    assert (b.color[:24] == triangle).all() and (b.color[24:] == square).all()
    # every copy carries the vertices' smooth normals (worked out in the test)
    np.testing.assert_allclose(b.normal, np.tile(smooth_normals(m), (2, 1)), atol=1e-6)
    assert b.edge_position.shape == (24, 3) and b.edge_index.shape == (2 * 60,)
    one = drawing_module.mesh_buffers(shapes.dodecahedron())  # one size: one copy
    assert one.position.shape == (20, 3) and one.normal.shape == (20, 3)
    # six face sizes on 360 vertices: six copies would be more rows than three
    # per triangle corner (716 triangles), so the rows are per corner
    many = pentanb.conway("bbP5")
    assert len(set(many.face_sizes.tolist())) == 6 and many.n_vertices == 360
    fallback = drawing_module.mesh_buffers(many)
    assert fallback.position.shape == (3 * 716, 3)
    assert np.array_equal(fallback.index, np.arange(3 * 716))


def test_mesh_buffers_comparison_fails_on_a_moved_vertex_or_other_faces():
    m = pentanb.conway("dgC")  # triangles and quads
    general = drawing_module.buffers(drawing_module.drawing(m))
    moved = m.with_vertices(m.vertices + np.eye(len(m.vertices), 3)[::-1] * 1e-3)
    with pytest.raises(AssertionError, match="triangles"):
        _same_buffers(general, drawing_module.mesh_buffers(moved))
    with pytest.raises(AssertionError):  # the gyro of the cube: other faces, other colours
        _same_buffers(general, drawing_module.mesh_buffers(pentanb.conway("gC")))


def test_a_view_updated_with_a_mesh_carries_its_drawing_and_legend():
    m, n = shapes.cube(), pentanb.conway("dgC")
    v = pentanb.view(m)
    v.update(n)
    assert v.mesh is n
    assert np.array_equal(v.drawing.vertices, n.vertices)
    assert "32 triangles" in v.legend.value and "V = 24, E = 60, F = 38" in v.legend.value
    assert arr(v.face_geometry.attributes["index"]).shape == (3 * (32 + 12),)
    assert arr(v.face_geometry.attributes["position"]).shape == (2 * 24, 3)  # two face sizes
    assert arr(v.face_geometry.attributes["normal"]).shape == (2 * 24, 3)
    with pytest.raises(TypeError, match=r"expected a pentanb\.Mesh or a Drawing, got str"):
        v.update("cube")
