"""Stand-alone HTML pages of views and explorers: :func:`export_html`.

The page holds the widgets' state (``ipywidgets.embed.dependency_state``)
and is drawn by ``@jupyter-widgets/html-manager`` (its ``embed-amd.js``
bundle, loaded with ``requirejs``).  A step-through is exported as a
:func:`pentanb.viz.three.slider_stack` copy: every stage is precomputed and
the slider is linked to a ``Stack`` in the browser (``jslink``), so the page
works without a kernel.  An explorer keeps every control
(:func:`explorer_copy`): the meshes of the combinations of their values
that fit in the page's size budget (``max_bytes``, values nearest the
current ones first, :meth:`pentanb.viz.explorer.Explorer.export_plan`) are
precomputed, each in its own view, and chosen by nested ``Stack`` widgets
that the controls select in the browser (``jsdlink`` of each control's
``index`` to the ``selected_index`` of every Stack at its level).  What the
budget leaves out is listed on the page, in its text.

Offline pages (``offline=True``, the default) load nothing from the
network: the pythreejs JavaScript (``jupyter-threejs`` and ``three``) is
read from the installed pythreejs package and the html-manager and
requirejs bundles from an npm cache, all inlined into the page.  The cache
is the folder ``$PENTANB_JS_DIR`` (default ``~/.cache/pentanb/js``) holding
``node_modules/@jupyter-widgets/html-manager`` and ``node_modules/requirejs``;
fill it once with::

    npm install --prefix ~/.cache/pentanb/js @jupyter-widgets/html-manager@1.0.15 requirejs@2.3.8

(``.ci/browser-setup.sh`` does this).  Online pages (``offline=False``) are
small and load those scripts from the jsDelivr CDN instead.  The two npm
versions are written once, in ``pentanb/viz/js_versions.json``, which
``.ci/browser-setup.sh`` reads too.
"""

from __future__ import annotations

import base64
import json
import os
from html import escape
from pathlib import Path

import ipywidgets as W
import numpy as np
import pythreejs as P3
from ipywidgets.embed import dependency_state, escape_script

from ..io._common import as_path, check_force, writable_target, write_atomically
from ..mesh import Mesh
from ..subdivision import get_scheme
from .drawing import camera_fit, counts_text, in_frame, look_at_quaternion, view_frame
from .explorer import CONTROLS, Explorer, ExportPlan, Key
from .steps import StepThrough
from .three import MeshView, close_tree, view
from .widgets import integer_argument

__all__ = [
    "export_html",
    "explorer_copy",
    "StaticExplorer",
    "MAX_PAGE_BYTES",
    "PAGE_MAX_FACES",
    "js_dir",
    "offline_scripts",
    "js_versions",
    "HTML_MANAGER_VERSION",
    "REQUIREJS_VERSION",
]

#: The file naming the npm packages offline pages inline and their versions.
JS_VERSIONS_FILE = Path(__file__).with_name("js_versions.json")


def js_versions() -> dict[str, str]:
    """The npm packages of exported pages and their versions (from ``js_versions.json``)."""
    return dict(json.loads(JS_VERSIONS_FILE.read_text(encoding="utf-8")))


#: Versions fetched by ``.ci/browser-setup.sh`` and used by online pages.
HTML_MANAGER_VERSION = js_versions()["@jupyter-widgets/html-manager"]
REQUIREJS_VERSION = js_versions()["requirejs"]

_CDN = "https://cdn.jsdelivr.net/npm"

#: Default size budget of a page of an explorer, in bytes, scripts included
#: (an offline page's scripts take about 4.6 MB of it).
MAX_PAGE_BYTES = 20_000_000
#: Default largest mesh (faces) a page of an explorer draws for one
#: combination of its controls' values.
PAGE_MAX_FACES = 5_000

_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="UTF-8">
<title>{title}</title>
<style>body {{ font-family: sans-serif; margin: 16px; }}</style>
{scripts}
</head>
<body>
{heading}
{notes}
<script type="application/vnd.jupyter.widget-state+json">
{state}
</script>
{views}
</body>
</html>
"""


def js_dir() -> Path:
    """The npm cache folder that offline pages take their scripts from."""
    env = os.environ.get("PENTANB_JS_DIR")
    if env:
        return Path(env)
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(cache) / "pentanb" / "js"


def _pythreejs_static() -> Path:
    import pythreejs

    return Path(pythreejs.__file__).parent / "static"


def offline_scripts() -> dict[str, Path]:
    """Paths of the JavaScript files an offline page inlines.

    Raises
    ------
    FileNotFoundError
        When one is missing; the message says how to fetch it.
    """
    base = js_dir() / "node_modules"
    static = _pythreejs_static()
    files = {
        "requirejs": base / "requirejs" / "require.js",
        "html-manager": base / "@jupyter-widgets" / "html-manager" / "dist" / "embed-amd.js",
        "jupyter-threejs": static / "index.js",
        "three": static / "three.js",
    }
    missing = [str(p) for p in files.values() if not p.is_file()]
    if missing:
        raise FileNotFoundError(
            "an offline page needs these files, which are missing: "
            + ", ".join(missing)
            + f". Fetch them with: npm install --prefix {js_dir()} "
            f"@jupyter-widgets/html-manager@{HTML_MANAGER_VERSION} "
            f"requirejs@{REQUIREJS_VERSION} (or run .ci/browser-setup.sh; "
            "PENTANB_JS_DIR chooses the folder), or export with offline=False"
        )
    return files


def _inline(text: str) -> str:
    """JavaScript made safe inside a <script> element (same meaning)."""
    return text.replace("</script", "<\\/script").replace("<!--", "<\\!--")


def _data_url(path: Path) -> str:
    return "data:text/javascript;base64," + base64.b64encode(path.read_bytes()).decode()


def _script_block(offline: bool) -> str:
    if not offline:
        return (
            f'<script src="{_CDN}/requirejs@{REQUIREJS_VERSION}/require.js" '
            'crossorigin="anonymous"></script>\n'
            f'<script src="{_CDN}/@jupyter-widgets/html-manager@{HTML_MANAGER_VERSION}'
            '/dist/embed-amd.js" crossorigin="anonymous"></script>'
        )
    f = offline_scripts()
    # pythreejs' AMD modules are anonymous; requirejs loads them from data:
    # URLs under their names, so html-manager finds them without a CDN
    paths = {"jupyter-threejs": _data_url(f["jupyter-threejs"]), "three": _data_url(f["three"])}
    return "\n".join(
        [
            "<script>" + _inline(f["requirejs"].read_text(encoding="utf-8")) + "</script>",
            "<script>require.config({paths: " + json.dumps(paths) + "});</script>",
            # data-jupyter-widgets-cdn-only is absent: html-manager asks requirejs first
            "<script>" + _inline(f["html-manager"].read_text(encoding="utf-8")) + "</script>",
        ]
    )


class StaticExplorer(W.VBox):
    """A kernel-free copy of an explorer (:func:`explorer_copy`).

    Attributes
    ----------
    controls : dict of str to ipywidgets.Widget
        The copy's controls, by the names of
        :data:`pentanb.viz.explorer.CONTROLS`: drop-downs for shape and
        scheme, selection sliders for scale, duals and iterations (each
        offering the values the plan keeps); and ``edges``, a check box.
    plan : ExportPlan
        What is kept (:meth:`pentanb.viz.explorer.Explorer.export_plan`).
    views : dict of Key to MeshView
        The view of every combination drawn.
    notes : str
        HTML naming what the size budget left out (empty when nothing).
    """

    plan: ExportPlan
    controls: dict[str, W.Widget]
    views: dict[Key, MeshView]
    notes: str
    _links: list[W.Widget]
    _cameras: list[W.Widget]

    def close(self) -> None:
        """Close the copy, its views, their cameras and the browser links."""
        for link in self._links:
            W.Widget.close(link)
        for v in self.views.values():  # (their edge switches are not shown)
            close_tree(v.wireframe)
        close_tree(self)
        for camera in self._cameras:
            close_tree(camera)
        self._links, self._cameras = [], []


def _label(control: str, value: object, plan: ExportPlan) -> str:
    if control == "scheme":
        return plan.labels.get(str(value), str(value))
    if control == "scale":
        return f"{float(value):.2f}"  # type: ignore[arg-type]
    return str(value)


def _notes(plan: ExportPlan, max_bytes: int, max_faces: int) -> str:
    """HTML listing what the page leaves out of the explorer."""
    items = []
    for control in CONTROLS:
        dropped = plan.dropped.get(control, [])
        if dropped:
            shown = ", ".join(escape(_label(control, v, plan)) for v in dropped)
            items.append(f"<li>{control}: {shown}</li>")
    if plan.left_out:
        items.append(
            f"<li>{len(plan.left_out):,} combinations of the values offered are not drawn "
            f"(over {max_faces:,} faces, or refused by the explorer); choosing one "
            "says why</li>"
        )
    if not items:
        return ""
    return (
        '<div class="pentanb-left-out"><p>This page keeps every control of the explorer, '
        f"but not every value: within its size budget of {max_bytes:,} bytes it "
        "leaves out</p><ul>" + "".join(items) + "</ul></div>"
    )


def _camera(meshes: list[Mesh], like: MeshView):
    """(camera, target, frame) for the views of one shape: fitted to all its meshes."""
    points = [m.vertices for m in meshes]
    frame = view_frame(*points)
    drawn = np.concatenate([in_frame(p, frame).reshape(-1, 3) for p in points])
    cam = like.camera
    centre, radius, eye = camera_fit(drawn, cam.fov, cam.aspect)
    camera = P3.PerspectiveCamera(
        position=tuple(float(c) for c in eye),
        up=(0.0, 0.0, 1.0),
        fov=cam.fov,
        aspect=cam.aspect,
        near=radius / 100,
        far=radius * 100,
        quaternion=look_at_quaternion(eye, centre),
    )
    return camera, tuple(float(c) for c in centre), frame


def explorer_copy(
    explorer: Explorer,
    *,
    max_bytes: int = MAX_PAGE_BYTES - 5_000_000,
    max_faces: int = PAGE_MAX_FACES,
    plan: ExportPlan | None = None,
) -> StaticExplorer:
    """A kernel-free copy of an explorer, with every one of its controls.

    The values of each control kept within ``max_bytes`` are chosen by
    :meth:`~pentanb.viz.explorer.Explorer.export_plan`; every combination
    of them gets its own precomputed view (sharing one camera per shape),
    or a line of text when its mesh has more than ``max_faces`` faces.
    The views sit in nested ``Stack`` widgets, one level per control
    (shape, scheme, scale for the schemes that take one, duals,
    iterations); each control's ``index`` is linked in the browser
    (``jsdlink``) to the ``selected_index`` of every Stack of its level,
    so the copy works in a stand-alone page.  The edges check box is linked
    to every view's edges.

    Parameters
    ----------
    explorer : Explorer
    max_bytes : int >= 1
        Bytes of widget state the copy may hold (predicted).
    max_faces : int >= 1
        Largest mesh drawn for one combination.
    plan : ExportPlan, optional
        What to keep (default: ``explorer.export_plan(max_bytes, max_faces)``).

    Returns
    -------
    StaticExplorer
        Close it (:meth:`StaticExplorer.close`) when done with it.

    Raises
    ------
    TypeError
        ``explorer`` is not an :class:`~pentanb.viz.explorer.Explorer`, or a
        bound is not an integer.
    ValueError
        A bound below 1.
    """
    if not isinstance(explorer, Explorer):
        raise TypeError(f"explorer_copy() takes an Explorer, not {type(explorer).__name__}")
    max_bytes = integer_argument(max_bytes, "max_bytes", 1)
    max_faces = integer_argument(max_faces, "max_faces", 1)
    if plan is None:
        plan = explorer.export_plan(max_bytes, max_faces)
    like = explorer.view
    width, height = like.renderer.width, like.renderer.height
    edges = bool(explorer.wireframe.value)
    style = {"description_width": "80px"}
    wide = W.Layout(width="300px")
    controls: dict[str, W.Widget] = {}
    for control in CONTROLS:
        values = plan.values[control]
        options = [(_label(control, v, plan), k) for k, v in enumerate(values)]
        current = values.index(plan.current[control])
        kind = W.Dropdown if control in ("shape", "scheme") else W.SelectionSlider
        extra = {} if kind is W.Dropdown else {"continuous_update": True}
        controls[control] = kind(
            options=options,
            index=current,
            description=control,
            style=style,
            layout=wide,
            **extra,
        )
    # the explorer's order: shape, scheme, iterations, duals, scale
    controls["edges"] = W.Checkbox(value=edges, description="edges", indent=False)
    links: list[W.Widget] = []
    cameras: list[W.Widget] = []
    views: dict[Key, MeshView] = {}
    shared: dict[str, tuple] = {}
    for shape in plan.values["shape"]:
        meshes = [m for k, m in plan.meshes.items() if k[0] == shape]
        if meshes:
            shared[shape] = _camera(meshes, like)
            cameras.append(shared[shape][0])

    def leaf(key: Key) -> W.Widget:
        if key not in plan.meshes:
            shape, scheme, duals, opts, it = key
            scale = f", scale {opts[0][1]:.2f}" if opts else ""
            return W.HTML(
                f"<p><i>Not in this page: {escape(shape)}, "
                f"{escape(plan.labels.get(scheme, scheme))}{scale}, {duals} duals, "
                f"{it} iterations: {escape(plan.left_out.get(key, ''))}</i></p>",
                layout=W.Layout(width=f"{width}px", height=f"{height}px"),
            )
        mesh = plan.meshes[key]
        camera, target, frame = shared[key[0]]
        v = MeshView(
            mesh,
            width=width,
            height=height,
            edges=edges,
            fov=like.camera.fov,
            toggle=False,
            camera=camera,
            target=target,
            frame=frame,
        )
        views[key] = v
        links.append(W.jsdlink((controls["edges"], "value"), (v.edges, "visible")))
        return W.VBox([v, W.HTML(counts_text(mesh))])

    def node(level: int, prefix: tuple) -> W.Widget:
        if level == len(CONTROLS):
            shape, scheme, scale, duals, it = prefix
            opts = () if scale is None else (("scale", float(scale)),)
            return leaf((shape, scheme, duals, opts, it))
        control = CONTROLS[level]
        if control == "scale" and "scale" not in get_scheme(prefix[1]).options:  # type: ignore[union-attr]
            return node(level + 1, prefix + (None,))
        values = plan.values[control]
        children = [node(level + 1, prefix + (v,)) for v in values]
        stack = W.Stack(children, selected_index=values.index(plan.current[control]))
        links.append(W.jsdlink((controls[control], "index"), (stack, "selected_index")))
        return stack

    tree = node(0, ())
    title = W.HTML(
        "<b>Semiregular pentagonal subdivision</b> (a copy without a kernel: "
        "the meshes are precomputed)"
    )
    order = ["shape", "scheme", "iterations", "duals", "scale", "edges"]
    panel = W.VBox([title] + [controls[c] for c in order], layout=W.Layout(width="320px"))
    box = StaticExplorer([panel, tree])
    box.add_class("pentanb-static")
    box.plan, box.controls, box.views = plan, controls, views
    box.notes = _notes(plan, max_bytes, max_faces)
    box._links, box._cameras = links, cameras
    return box


def _exportable(obj, max_bytes: int, max_faces: int):
    """(widget, made here) of what export_html writes."""
    if isinstance(obj, Mesh):
        return view(obj), True
    if isinstance(obj, Explorer):
        return explorer_copy(obj, max_bytes=max_bytes, max_faces=max_faces), True
    if isinstance(obj, StepThrough):
        return obj.static_copy(), True
    if isinstance(obj, (MeshView, W.Widget)):
        return obj, False
    raise TypeError(f"export_html() takes a pentanb.Mesh or a widget, not {type(obj).__name__}")


def _page(widget: W.Widget, scripts: str, title: str) -> str:
    state = dependency_state(widget, drop_defaults=True)
    manager_state = W.Widget.get_manager_state(widgets=[])
    manager_state["state"] = state
    spec = widget.get_view_spec()
    return _PAGE.format(
        title=escape(str(title)),
        scripts=scripts,
        heading=f"<h3>{escape(str(title))}</h3>" if title else "",
        notes=getattr(widget, "notes", ""),
        state=escape_script(json.dumps(manager_state)),
        views='<script type="application/vnd.jupyter.widget-view+json">\n'
        + escape_script(json.dumps(spec))
        + "\n</script>",
    )


def export_html(
    obj,
    path,
    offline: bool = True,
    *,
    title: str = "pentanb",
    max_bytes: int = MAX_PAGE_BYTES,
    max_faces: int = PAGE_MAX_FACES,
    force: bool = False,
) -> Path:
    """Write a stand-alone HTML page of a view, an explorer or a step-through.

    Parameters
    ----------
    obj : Mesh, MeshView, Explorer, StepThrough or any ipywidget
        A mesh gets a :func:`pentanb.view`.  An explorer keeps every control
        (shape, scheme, iterations, duals, scale, edges): the meshes of the
        combinations of their values that fit in ``max_bytes`` are
        precomputed (:func:`explorer_copy`), values nearest the current
        ones first, and the values left out are listed on the page.  A
        step-through gets one view per stage.  Their controls are linked in
        the browser, so they work without a kernel.
    path : str or Path
        The file to write.
    offline : bool
        True: inline every script, so the page loads nothing from the
        network (needs the npm cache, see :func:`offline_scripts`).
        False: a small page loading its scripts from the jsDelivr CDN.
    title : str
        The page's title and heading.
    max_bytes : int >= 1
        Size budget of an explorer's page, in bytes, its scripts included
        (an offline page's take about 4.6 MB); the page is written within
        it.  Other objects are written whole.
    max_faces : int >= 1
        Largest mesh (faces) an explorer's page draws for one combination
        of its controls.
    force : bool
        Replace a read-only page too (as :func:`pentanb.write`).

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    FileNotFoundError
        ``offline=True`` without the npm cache (the message says how to fill it).
    TypeError, ValueError
        ``max_bytes`` or ``max_faces`` not an integer >= 1; ``max_bytes``
        smaller than an explorer's page without any mesh; ``path`` names
        something other than a regular file (a folder, a FIFO, a device),
        or a read-only file without ``force=True``: refused before the
        page is made.

    Notes
    -----
    The page is written as :func:`pentanb.write` writes a mesh: into a new
    temporary file beside ``path``, then renamed over it, so a full disk
    leaves the old page whole; a symbolic link is kept and the file it
    points to replaced.
    """
    max_bytes = integer_argument(max_bytes, "max_bytes", 1)
    max_faces = integer_argument(max_faces, "max_faces", 1)
    force = check_force(force, "export_html")
    path = as_path(path, "export_html")
    writable_target(path, force=force, caller="export_html")  # refused before the work
    scripts = _script_block(offline)
    if not isinstance(obj, Explorer):
        widget, made = _exportable(obj, max_bytes, max_faces)
        page = _page(widget, scripts, title)
    else:
        # the state's budget: the page less its scripts and frame, then
        # lowered while the page comes out larger than the prediction
        fixed = len(_PAGE.encode()) + len(scripts.encode()) + 4 * len(str(title)) + 20_000
        budget = max_bytes - fixed
        if budget < obj.TEXT_BYTES * 10:
            raise ValueError(
                f"max_bytes={max_bytes:,} leaves no room for the explorer's meshes: its "
                f"page's scripts alone take {fixed:,} bytes"
                + ("" if not offline else " (offline=False makes them small)")
            )
        for _ in range(4):
            widget, made = _exportable(obj, budget, max_faces)
            widget.notes = _notes(widget.plan, max_bytes, max_faces)
            page = _page(widget, scripts, title)
            size = len(page.encode())
            if size <= max_bytes:
                break
            widget.close()
            budget = int(budget * (max_bytes - fixed) / (size - fixed) * 0.95)
        else:
            raise ValueError(f"could not fit the explorer's page in max_bytes={max_bytes:,}")
    data = page.encode("utf-8")

    def write(fh) -> None:
        fh.write(data)

    try:
        write_atomically(path, write, force=force, caller="export_html")
    finally:
        if made:
            widget.close()
    return path
