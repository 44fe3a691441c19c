"""The explorer for a class: a student's own mesh (argument, path, upload), refusals that
put the controls back, declared ranges kept, the predicted-cost progress rule, and the
kernel-free page that keeps every control within its size budget.

Expected meshes come from :func:`pentanb.subdivide` on meshes written here by hand
(or read back by :func:`pentanb.io.read`), never from the explorer itself; the
page's browser links are followed here in Python, as the browser would follow them.
"""

from __future__ import annotations

import datetime as dt
import json
import re

import numpy as np
import pytest

import pentanb
from pentanb import shapes
from pentanb.viz import explorer, html

# an open mesh written by hand: two triangles sharing an edge (a square, four
# boundary edges)
SQUARE_OBJ = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"
SQUARE = pentanb.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]])


def same_mesh(a: pentanb.Mesh, b: pentanb.Mesh) -> bool:
    return np.array_equal(a.vertices, b.vertices) and np.array_equal(a.corners, b.corners)


def settings(e) -> tuple:
    return (e.shape.value, e.scheme.value, e.iterations.value, e.duals.value, e.scale.value)


def shown_matches_controls(e) -> bool:
    """The picture is the mesh the controls describe (computed here, independently)."""
    base = e._base(e.shape.value)  # the explorer's own copy of the base mesh
    opts = {"scale": e.scale.value} if "scale" in pentanb.SCHEMES[e.scheme.value].options else {}
    expected = pentanb.subdivide(base, e.scheme.value, e.iterations.value, e.duals.value, **opts)
    return same_mesh(e.mesh, expected)


def upload_value(name: str, content: bytes) -> tuple:
    """What ipywidgets 8's FileUpload holds after a file is chosen: a tuple of dicts."""
    return (
        {
            "name": name,
            "type": "",
            "size": len(content),
            "content": memoryview(content),
            "last_modified": dt.datetime(2024, 1, 1, tzinfo=dt.timezone.utc),
        },
    )


# -- a mesh of your own -------------------------------------------------------------


def test_a_mesh_argument_is_listed_as_your_mesh_and_shown():
    e = pentanb.explore(SQUARE, iterations=1, duals=0)
    assert e.shape.value == explorer.YOUR_MESH == e.shape.options[0]
    assert "cube" in e.shape.options
    assert same_mesh(e.mesh, pentanb.subdivide(SQUARE, "pentagonalize", 1, 0))
    e.close()


def test_a_path_is_read_and_listed_under_its_file_name(tmp_path):
    path = tmp_path / "square.obj"
    path.write_bytes(SQUARE_OBJ)
    for shape in (path, str(path)):
        e = pentanb.explore(shape, iterations=0)
        assert e.shape.value == "square.obj"
        assert same_mesh(e.mesh, SQUARE)
        e.iterations.value = 1
        assert same_mesh(e.mesh, pentanb.subdivide(SQUARE, "pentagonalize", 1, 2))
        e.close()


def test_a_path_that_cannot_be_read_is_refused_at_once(tmp_path):
    with pytest.raises(FileNotFoundError):
        pentanb.explore(tmp_path / "missing.obj")
    bad = tmp_path / "bad.off"
    bad.write_bytes(b"OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(pentanb.MeshError, match=r"bad\.off"):
        pentanb.explore(bad)
    with pytest.raises(ValueError, match=r"unknown shape 'sphere'.*path of a \.obj"):
        pentanb.explore("sphere")


def test_the_upload_control_accepts_the_four_formats():
    e = pentanb.explore("cube", iterations=0)
    assert isinstance(e.upload, __import__("ipywidgets").FileUpload)
    assert set(e.upload.accept.split(",")) == {".obj", ".off", ".ply", ".stl"}
    assert e.upload in e.children[0].children  # shown in the panel
    e.close()


def test_an_uploaded_file_becomes_the_current_shape(tmp_path):
    e = pentanb.explore("cube", iterations=1, duals=0)
    camera = tuple(e.view.camera.position)
    e.upload.value = upload_value("square.obj", SQUARE_OBJ)
    assert e.shape.value == "square.obj" and "square.obj" in e.shape.options
    assert same_mesh(e.mesh, pentanb.subdivide(SQUARE, "pentagonalize", 1, 0))
    assert tuple(e.view.camera.position) != camera  # refitted to the new shape
    assert e.status.value == ""
    assert e.upload.value == ()  # the bytes are not kept
    # back to the cube and to the upload again: the entry is the same
    e.shape.value = "cube"
    assert shown_matches_controls(e)
    e.shape.value = "square.obj"
    assert same_mesh(e.mesh, pentanb.subdivide(SQUARE, "pentagonalize", 1, 0))
    # a binary format too (PLY written by pentanb.write, read back from the upload)
    pentanb.write(shapes.tetrahedron(), tmp_path / "t.ply")
    e.upload.value = upload_value("T.PLY", (tmp_path / "t.ply").read_bytes())
    assert e.shape.value == "T.PLY"
    assert same_mesh(e.mesh, pentanb.subdivide(shapes.tetrahedron(), "pentagonalize", 1, 0))
    e.close()


def test_an_upload_of_the_same_name_replaces_the_entry_and_its_cache():
    e = pentanb.explore("cube", iterations=0)
    e.upload.value = upload_value("m.obj", SQUARE_OBJ)
    triangle = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    e.upload.value = upload_value("m.obj", triangle)
    assert list(e.shape.options).count("m.obj") == 1
    assert e.mesh.n_faces == 1 and e.mesh.n_vertices == 3
    # a replacement too large for the view: refused, the name keeps the mesh shown
    e.max_faces = 100
    assert e.add_mesh(pentanb.subdivide(shapes.cube(), "pentagonalize", 2, 0), "m.obj") is False
    assert "120 faces" in e.status.value
    e.iterations.value = 0
    e.shape.value = "cube"
    e.shape.value = "m.obj"
    assert e.mesh.n_faces == 1 and e.mesh.n_vertices == 3
    e.close()


@pytest.mark.parametrize(
    "name, content, message",
    [
        ("broken.obj", b"v 0 0 0\nv 1 0 0\nf 1 2 7\n", "broken.obj"),
        ("nan.off", b"OFF\n3 1 0\n0 0 0\n1 0 0\n", "nan.off"),
        ("notes.txt", b"hello", "reads .obj, .off, .ply, .stl files, not .txt"),
        ("noending", SQUARE_OBJ, "not a file without an ending"),
    ],
    ids=["bad index", "short OFF", "wrong ending", "no ending"],
)
def test_a_file_that_cannot_be_read_changes_nothing(name, content, message):
    e = pentanb.explore("cube", iterations=1)
    before = settings(e), list(e.shape.options), e.mesh
    positions = e.view.face_geometry.attributes["position"].array.copy()
    e.upload.value = upload_value(name, content)
    assert "could not read the file" in e.status.value
    assert message in e.status.value.replace("&#x27;", "'")
    assert (settings(e), list(e.shape.options), e.mesh) == before
    np.testing.assert_array_equal(e.view.face_geometry.attributes["position"].array, positions)
    e.close()


def test_the_reader_message_is_the_readers_own():
    with pytest.raises(pentanb.MeshError) as caught:
        explorer.read_upload("broken.obj", b"v 0 0 0\nv 1 0 0\nf 1 2 7\n")
    e = pentanb.explore("cube", iterations=0)
    assert e.load_upload({"name": "broken.obj", "content": b"v 0 0 0\nv 1 0 0\nf 1 2 7\n"}) is False
    assert str(caught.value).replace("'", "&#x27;") in e.status.value
    e.close()


# -- refusals put the controls back ----------------------------------------------------


def test_a_refused_shape_puts_the_drop_down_back():
    # the cube three times: 600 pentagons (their first dual 902 faces); the
    # rabbit three times is far over 3,000 faces
    e = pentanb.explore("cube", iterations=3, max_faces=3_000)
    e.shape.value = "rabbit"
    assert "faces" in e.status.value
    assert settings(e)[:3] == ("cube", "pentagonalize", 3)
    assert e.key() == e.shown_key
    assert same_mesh(e.mesh, pentanb.subdivide(shapes.cube(), "pentagonalize", 3, 2))
    e.close()


@pytest.mark.parametrize(
    "control, value",
    [("iterations", 5), ("scheme", "preserve_pentagons"), ("shape", "rabbit")],
)
def test_after_any_refusal_the_controls_describe_the_picture(control, value):
    e = pentanb.explore("cube", iterations=3, max_faces=1_000)
    getattr(e, control).value = value
    assert e.status.value  # refused, with why
    assert e.key() == e.shown_key
    assert settings(e) == ("cube", "pentagonalize", 3, 2, e.scale.value)
    assert shown_matches_controls(e)
    assert e.scale.disabled  # pentagonalize takes no scale
    e.close()


def test_an_upload_too_large_for_the_view_keeps_the_controls():
    e = pentanb.explore("cube", iterations=2, max_faces=500)
    e.upload.value = upload_value(
        "t.off", b"OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    )
    assert e.shape.value == "t.off" and e.status.value == ""
    big = pentanb.subdivide(shapes.cube(), "pentagonalize", 3, 0)  # 600 faces > 500
    e.add_mesh(big, "big mesh")
    assert "600 faces" in e.status.value
    assert e.shape.value == "t.off" and "big mesh" in e.shape.options
    assert shown_matches_controls(e)
    e.close()


# -- declared ranges are kept -----------------------------------------------------------


@pytest.mark.parametrize("top", [0, 1, 2, 7])
def test_a_declared_max_iterations_is_kept(top):
    e = pentanb.explore("cube", max_iterations=top)
    assert e.iterations.max == top
    assert e.iterations.value == min(1, top)
    e.upload.value = upload_value("s.obj", SQUARE_OBJ)
    assert e.iterations.max == top
    e.close()


def test_an_inconsistent_request_names_both_arguments():
    with pytest.raises(ValueError, match=r"iterations=4 is more than max_iterations=3"):
        pentanb.explore("cube", iterations=4, max_iterations=3)


# -- progress: a predicted cost over half a second ---------------------------------------


def test_predicted_cost_counts_every_face_built():
    e = pentanb.explore("cube", iterations=0)
    e.seconds_per_face = 1.0
    # pentagonalize on the cube: 24 pentagons (38 vertices), its dual 38
    # faces, its dual 24: 86 faces built
    assert e.predicted_seconds(1) == 86.0
    e.duals.value = 0
    assert e.predicted_seconds(1) == 24.0
    assert e.predicted_seconds(2) == 24.0 + 120.0  # 24 pentagons -> 120
    e.iterations.value = 1  # now cached: nothing left to build below level 2
    assert e.predicted_seconds(1) == 0.0
    assert e.predicted_seconds(2) == 120.0
    e.close()


def test_a_count_keeping_scheme_costs_every_level():
    e = pentanb.explore("tetrahedron", "triangulate", iterations=0, duals=0, max_iterations=50)
    e.seconds_per_face = 1.0
    assert e.predicted_seconds(50) == 50 * 4.0  # 4 triangles, 50 times
    e.close()


@pytest.mark.parametrize("duals", [0, 2])
def test_predicted_cost_of_an_open_mesh_counts_its_boundary(duals):
    e = pentanb.explore(SQUARE, iterations=0, duals=duals)
    e.seconds_per_face = 1.0
    built, mesh = 0, SQUARE  # the faces of every step, built here one step at a time
    for _ in range(2):
        mesh = pentanb.subdivide(mesh, "pentagonalize", 1, 0)
        built += mesh.n_faces
        for _ in range(duals):
            mesh = pentanb.dual(mesh)
            built += mesh.n_faces
    assert e.predicted_seconds(2) == built
    e.close()


@pytest.mark.parametrize("cost, shown", [(0.4 / 86, False), (0.6 / 86, True)])
def test_the_bar_shows_from_the_start_over_half_a_second(cost, shown):
    e = pentanb.explore("cube", iterations=0)
    assert e.progress_seconds == 0.5
    e.clock = lambda: 0.0  # time stands still: only the prediction can show the bar
    e.seconds_per_face = cost
    seen = []
    e.progress.layout.observe(lambda c: seen.append(c["new"]), names="visibility")
    e.iterations.value = 1
    assert seen == (["visible", "hidden"] if shown else [])
    e.close()


# -- the kernel-free page ---------------------------------------------------------------


def follow_links(copy: html.StaticExplorer) -> None:
    """Do what the browser does with the page's links: copy each source value to its target."""
    import ipywidgets as W

    for link in copy._links:
        assert isinstance(link, W.widgets.widget_link.DirectionalLink)
        (source, a), (target, b) = link.source, link.target
        setattr(target, b, getattr(source, a))


def leaf_of(copy: html.StaticExplorer):
    """The widget the page shows: down the Stacks by their selected_index."""
    import ipywidgets as W

    node = copy.children[1]
    while isinstance(node, W.Stack):
        node = node.children[node.selected_index]
    return node


def test_the_page_keeps_every_control_and_its_values_select_the_right_mesh():
    e = pentanb.explore("cube", iterations=1)
    copy = html.explorer_copy(e, max_bytes=1_500_000, max_faces=2_000)
    plan = copy.plan
    # every control is kept, several of them with more than one value
    assert set(copy.controls) == {"shape", "scheme", "iterations", "duals", "scale", "edges"}
    assert sum(len(plan.values[c]) > 1 for c in explorer.CONTROLS) >= 3
    assert plan.estimate <= 1_500_000
    rng = np.random.default_rng(1)
    checked = 0
    for _ in range(12):
        chosen = {c: int(rng.integers(len(plan.values[c]))) for c in explorer.CONTROLS}
        for c, k in chosen.items():
            copy.controls[c].index = k
        follow_links(copy)
        values = {c: plan.values[c][chosen[c]] for c in explorer.CONTROLS}
        shown = leaf_of(copy)
        scheme = pentanb.SCHEMES[values["scheme"]]
        opts = {"scale": values["scale"]} if "scale" in scheme.options else {}
        expected = pentanb.subdivide(
            shapes.get(values["shape"]), scheme.name, values["iterations"], values["duals"], **opts
        )
        if expected.n_faces > 2_000:  # named in text, not drawn
            assert (
                "Not in this page" in shown.value and f"{expected.n_faces:,} faces" in shown.value
            )
            continue
        view = shown.children[0]
        assert same_mesh(view.mesh, expected)
        assert f"F = {expected.n_faces:,}" in shown.children[1].value
        checked += 1
    assert checked >= 3
    # the current values are shown first
    for c in explorer.CONTROLS:
        copy.controls[c].index = plan.values[c].index(plan.current[c])
    follow_links(copy)
    assert same_mesh(
        leaf_of(copy).children[0].mesh, pentanb.subdivide(shapes.cube(), "pentagonalize", 1, 2)
    )
    # the edges box reaches every view
    copy.controls["edges"].value = False
    follow_links(copy)
    assert not any(v.edges.visible for v in copy.views.values())
    copy.close()
    e.close()


def _page_state(text: str) -> dict:
    m = re.search(
        r'<script type="application/vnd.jupyter.widget-state\+json">\n(.*?)\n</script>', text, re.S
    )
    return json.loads(m.group(1))["state"]


def test_the_page_lists_what_the_budget_leaves_out(tmp_path):
    e = pentanb.explore("cube", iterations=1)
    path = html.export_html(e, tmp_path / "p.html", offline=False, max_bytes=800_000)
    text = path.read_text(encoding="utf-8")
    assert len(text.encode()) <= 800_000
    body = text.split("<body>")[1]
    notes = re.search(r'<div class="pentanb-left-out">(.*?)</div>', body, re.S).group(1)
    # every value of every control is offered by the page's control, or named in the text
    offered: dict[str, set] = {}
    for s in _page_state(text).values():
        st = s["state"]
        if s["model_name"] in ("DropdownModel", "SelectionSliderModel"):
            offered[st["description"]] = set(st["_options_labels"])
    every = {
        "shape": list(shapes.SHAPES),
        "scheme": [s.label for s in pentanb.SCHEMES.values()],
        "iterations": [str(k) for k in range(6)],
        "duals": [str(k) for k in range(5)],
        "scale": [f"{0.05 * k:.2f}" for k in range(1, 20)],
    }
    lines = {m.group(1): m.group(2) for m in re.finditer(r"<li>(\w+): (.*?)</li>", notes)}
    for control, values in every.items():
        missing = [v for v in values if v not in offered[control]]
        if missing:
            listed = [x.strip() for x in lines[control].split(", ")]
            assert [html_unescape(x) for x in listed] == missing, control
        else:
            assert control not in lines
    assert "800,000 bytes" in notes
    e.close()


def html_unescape(text: str) -> str:
    import html as h

    return h.unescape(text)


def test_page_sizes_stay_within_their_budget(tmp_path):
    e = pentanb.explore("tetrahedron", iterations=2)
    for budget in (300_000, 1_200_000):
        path = html.export_html(e, tmp_path / f"{budget}.html", offline=False, max_bytes=budget)
        assert path.stat().st_size <= budget
    with pytest.raises(ValueError, match="leaves no room"):
        html.export_html(e, tmp_path / "x.html", offline=False, max_bytes=10_000)
    with pytest.raises(ValueError, match=r"max_bytes must be an integer >= 1"):
        html.export_html(e, tmp_path / "x.html", offline=False, max_bytes=0)
    e.close()


def test_export_closes_the_copy_it_made(tmp_path):
    import ipywidgets as W
    from ipywidgets.widgets.widget import _instances as active

    e = pentanb.explore("tetrahedron", iterations=0)
    before = set(active)
    html.export_html(e, tmp_path / "p.html", offline=False, max_bytes=300_000)
    left = [active[k] for k in set(active) - before]
    assert [type(w).__name__ for w in left if not isinstance(w, (W.Layout, W.Style))] == []
    e.close()
