"""Stand-alone HTML pages of views and explorers: :func:`export_html`.

The page holds the widgets' state (``ipywidgets.embed.dependency_state``)
and is drawn by ``@jupyter-widgets/html-manager`` (its ``embed-amd.js``
bundle, loaded with ``requirejs``).  Explorers and step-throughs are
exported as :func:`pentanb.viz.three.slider_stack` copies: every iteration
(or stage) is precomputed and the slider is linked to a ``Stack`` in the browser
(``jslink``), so the page works without a kernel.

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
from ipywidgets.embed import dependency_state, escape_script

from ..mesh import Mesh
from .explorer import Explorer
from .steps import StepThrough
from .three import MeshView, view

__all__ = [
    "export_html",
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


def _exportable(obj) -> W.Widget:
    if isinstance(obj, Mesh):
        return view(obj)
    if isinstance(obj, (Explorer, StepThrough)):
        return obj.static_copy()
    if isinstance(obj, (MeshView, W.Widget)):
        return obj
    raise TypeError(f"export_html() takes a pentanb.Mesh or a widget, not {type(obj).__name__}")


def export_html(obj, path, offline: bool = True, *, title: str = "pentanb") -> Path:
    """Write a stand-alone HTML page of a view, an explorer or a step-through.

    Parameters
    ----------
    obj : Mesh, MeshView, Explorer, StepThrough or any ipywidget
        A mesh gets a :func:`pentanb.view`.  An explorer is exported with
        one precomputed view per iteration count (0 to its current value)
        and a step-through with one view per stage; their sliders are linked
        in the browser, so they work without a kernel.
    path : str or Path
        The file to write.
    offline : bool
        True: inline every script, so the page loads nothing from the
        network (needs the npm cache, see :func:`offline_scripts`).
        False: a small page loading its scripts from the jsDelivr CDN.
    title : str
        The page's title and heading.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    FileNotFoundError
        ``offline=True`` without the npm cache (the message says how to fill it).
    """
    widget = _exportable(obj)
    scripts = _script_block(offline)
    state = dependency_state(widget, drop_defaults=True)
    manager_state = W.Widget.get_manager_state(widgets=[])
    manager_state["state"] = state
    spec = widget.get_view_spec()
    page = _PAGE.format(
        title=escape(str(title)),
        scripts=scripts,
        heading=f"<h3>{escape(str(title))}</h3>" if title else "",
        state=escape_script(json.dumps(manager_state)),
        views='<script type="application/vnd.jupyter.widget-view+json">\n'
        + escape_script(json.dumps(spec))
        + "\n</script>",
    )
    path = Path(path)
    path.write_text(page, encoding="utf-8")
    return path
