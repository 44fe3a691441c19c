"""Sphinx configuration of pentanb's documentation site.

Build it with ``python -m pentanb docs`` (into ``docs/_build/html``), or with the
``sphinx-build`` line it runs::

    sphinx-build -W -b html -c docs . docs/_build/html

The source folder is the repository itself (this file's parent's parent), not
``docs/``: the pages of ``docs/`` link to ``../figures/*.png`` and
``../notebooks/README.md`` as they do on GitHub, and the notebooks are read where
they are, in ``notebooks/``, so nothing is copied and those links work on the site
as they do in a clone.  ``include_patterns`` keeps the site to ``docs/``, the
notebooks and their README; the landing page is ``docs/index.md``
(``root_doc``) and ``index.html`` at the top of the output sends a reader there.

The tools, and why:

* **myst-nb** (not nbsphinx) reads the Markdown pages and the notebooks with the
  same parser (MyST), executes the notebooks at build time with nbclient, which
  saves their widget state (the 3D views and the sliders' first positions), and
  keeps executed notebooks in a jupyter-cache (``docs/_build/.jupyter_cache``),
  so a rebuild re-executes only the notebooks whose code changed.  nbsphinx
  needs the pandoc program for Markdown cells, and reads the Markdown pages
  with another parser than the notebooks.
* **numpydoc** renders the package's docstrings, which are written in its
  format (``tests/test_api_docs.py`` checks their sections).
* **autodoc + autosummary** make the API reference from ``__all__``: each page
  of ``docs/api/`` is one ``pentanb-module`` directive (defined below), which
  writes an autosummary table and an autodoc entry for every name of the
  module's ``__all__``, so a name added to ``__all__`` appears without editing a
  page, and no stub files are generated into the source tree.
* **pydata-sphinx-theme**: the theme of numpy, scipy, matplotlib and
  pythreejs' neighbours; its fonts and icons ship inside the package (no CDN).

Offline: the site loads nothing from the network, at build time or when read.
The widget scripts (requirejs, ``@jupyter-widgets/html-manager``'s
``embed-amd.js``, and pythreejs' ``jupyter-threejs`` and ``three``) are the ones
:func:`pentanb.export_html` inlines in its offline pages, found by
:func:`pentanb.viz.html.offline_scripts` (the npm cache that
``.ci/browser-setup.sh`` fills, and the installed pythreejs); they are copied
into ``_static/pentanb-widgets/`` and ``_static/pentanb-widgets.js`` points
requirejs at them.  Math is drawn by MathJax 3 (its SVG output, which needs no
web fonts) copied from the same npm cache into ``_static/pentanb-mathjax/``.

Two directives are defined here (``setup``): ``pentanb-module`` (an API page)
and ``pentanb-gallery`` (every image of ``figures/`` with its claims and
verdicts, measured when the site is built by
:func:`pentanb.figures.check_all`).

Executing the notebooks: myst-nb runs them one at a time; before Sphinx reads
them, :func:`_execute_notebooks` runs the ones missing from the cache several at
a time (``$PENTANB_DOCS_JOBS``, default the number of cores, at least 2), while
another process measures the gallery's claims.  A notebook that raises fails the
build, and so does one that writes to standard error (a warning shows there).
``$PENTANB_DOCS_EXECUTE`` chooses myst-nb's mode: ``cache`` (the default),
``force`` (re-execute every notebook, one at a time) or ``off`` (no outputs: a
quick look at the text).
"""

from __future__ import annotations

import importlib
import inspect
import json
import os
import re
import shutil
import sys
import types
import typing
from pathlib import Path
from typing import ClassVar

from docutils import nodes
from docutils.parsers.rst import directives
from docutils.statemachine import StringList
from sphinx.ext import autosummary
from sphinx.util.docutils import SphinxDirective
from sphinx.util.nodes import nested_parse_with_titles

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
# the package of this clone, for autodoc here and for the notebooks' kernels
sys.path.insert(0, str(ROOT))
os.environ["PYTHONPATH"] = os.pathsep.join(
    [str(ROOT)] + ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else [])
)
os.environ.setdefault("MPLBACKEND", "Agg")  # this process draws no window


def _kernel_for_this_python() -> None:
    """The notebooks name the kernel ``python3``: make it this Python (the one that
    has Sphinx and pentanb), whatever ``python3`` kernel a user has installed, with a
    kernel spec in a folder put first on ``JUPYTER_PATH`` (removed at exit)."""
    import atexit
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="pentanb-docs-kernel-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    spec = folder / "kernels" / "python3"
    spec.mkdir(parents=True)
    argv = [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"]
    kernel = {"argv": argv, "display_name": "Python 3 (ipykernel)", "language": "python"}
    (spec / "kernel.json").write_text(json.dumps(kernel), encoding="utf-8")
    os.environ["JUPYTER_PATH"] = os.pathsep.join(
        [str(folder)] + ([os.environ["JUPYTER_PATH"]] if os.environ.get("JUPYTER_PATH") else [])
    )


_kernel_for_this_python()
os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernels' debugger note

import pentanb  # noqa: E402

# -- project -----------------------------------------------------------------

project = "pentanb"
author = "the pentanb authors"
copyright = "the pentanb authors; the paper: Akleman, Srinivasan, Melek and Edmundson"
release = version = pentanb.__version__

root_doc = "docs/index"
include_patterns = [
    "docs/**",
    "notebooks/*.ipynb",
    "notebooks/README.md",
]
exclude_patterns = [
    "docs/_build",
    "docs/_build/**",
    "docs/_static/**",
    "docs/_templates/**",
    "**/.ipynb_checkpoints",
    ".venv",
    ".v",
    ".git",
]
templates_path = ["_templates"]
html_static_path = ["_static"]

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx.ext.mathjax",
]

# -- MyST and the notebooks -----------------------------------------------------

myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3  # GitHub's anchors: performance.md#the-optional-numba-kernels

# "cache": executed notebooks are kept (jupyter-cache, beside the output folder)
# and re-executed only when their code changes; "force" re-executes them all.
nb_execution_mode = os.environ.get("PENTANB_DOCS_EXECUTE", "cache")
nb_execution_timeout = 900  # a hang guard, per cell
nb_execution_raise_on_error = True  # a notebook that raises fails the build
nb_execution_show_tb = True
nb_merge_streams = True
# a warning a notebook prints is a warning of the build (-W: an error)
nb_output_stderr = "warn"
# the widget scripts, shipped with the site (see the module docstring):
# requirejs, where to find pythreejs, then html-manager, which draws the saved state
nb_ipywidgets_js = {
    "pentanb-widgets/require.js": {},
    "pentanb-widgets.js": {},
    "pentanb-widgets/embed-amd.js": {},
}

# -- MathJax, offline ---------------------------------------------------------------

mathjax_path = "pentanb-mathjax/tex-svg.js"
mathjax3_config = {"svg": {"fontCache": "global"}}

# -- autodoc, autosummary, numpydoc -------------------------------------------------

autodoc_typehints = "none"  # numpydoc's Parameters say the types; signatures stay short
autodoc_member_order = "bysource"
autosummary_generate = False  # the pentanb-module directive writes the entries
numpydoc_show_class_members = False  # autodoc's :members: lists them
numpydoc_class_members_toctree = False
numpydoc_attributes_as_param_list = True

# -- HTML -------------------------------------------------------------------------

html_theme = "pydata_sphinx_theme"
html_title = "pentanb"
html_css_files = ["pentanb.css"]
html_theme_options = {
    "navigation_with_keys": False,
    "header_links_before_dropdown": 5,
    "show_toc_level": 2,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "secondary_sidebar_items": ["page-toc"],
}
html_context = {"default_mode": "auto"}  # (unset, the theme logs an error on a first visit)
html_sidebars = {"**": ["pentanb-nav.html"]}  # docs/_templates: the whole site
html_show_sourcelink = False
html_copy_source = False

# -- the widget and MathJax scripts -------------------------------------------------

#: npm packages only the site needs (the widget bundles' versions are in
#: pentanb/viz/js_versions.json); .ci/browser-setup.sh installs them too.
DOCS_JS_VERSIONS = json.loads((DOCS / "js_versions.json").read_text(encoding="utf-8"))


def site_scripts() -> dict[str, Path]:
    """``{path under _static: file}`` for every script the site ships.

    Raises
    ------
    FileNotFoundError
        When one is missing; the message says how to fetch it.
    """
    from pentanb.viz.html import js_dir, offline_scripts

    found = offline_scripts()  # raises, saying how to fill the npm cache
    mathjax = js_dir() / "node_modules" / "mathjax" / "es5" / "tex-svg.js"
    if not mathjax.is_file():
        wanted = " ".join(f"{k}@{v}" for k, v in DOCS_JS_VERSIONS.items())
        raise FileNotFoundError(
            f"the site needs {mathjax}, which is missing. Fetch it with: "
            f"npm install --prefix {js_dir()} {wanted} (or run .ci/browser-setup.sh)"
        )
    files = {
        "pentanb-widgets/require.js": found["requirejs"],
        "pentanb-widgets/embed-amd.js": found["html-manager"],
        "pentanb-widgets/jupyter-threejs.js": found["jupyter-threejs"],
        "pentanb-widgets/three.js": found["three"],
        "pentanb-mathjax/tex-svg.js": mathjax,
    }
    # the web fonts html-manager's stylesheet names, beside embed-amd.js
    for font in sorted(found["html-manager"].parent.iterdir()):
        if font.suffix in (".woff2", ".woff", ".ttf", ".eot", ".svg"):
            files[f"pentanb-widgets/{font.name}"] = font
    return files


def _check_scripts(app) -> None:
    if app.builder.format == "html":
        site_scripts()  # fail early, before executing the notebooks


def _copy_scripts(app, exception) -> None:
    """Copy the scripts into ``_static`` and write the top ``index.html``."""
    if exception is not None or app.builder.format != "html":
        return
    static = Path(app.outdir) / "_static"
    for target, source in site_scripts().items():
        dest = static / target
        dest.parent.mkdir(parents=True, exist_ok=True)
        if not dest.is_file() or dest.stat().st_size != source.stat().st_size:
            shutil.copyfile(source, dest)
    landing = app.builder.get_target_uri(app.config.root_doc)
    (Path(app.outdir) / "index.html").write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f'<meta http-equiv="refresh" content="0; url={landing}">'
        f"<title>pentanb</title></head><body>"
        f'<p><a href="{landing}">pentanb documentation</a></p></body></html>\n',
        encoding="utf-8",
    )


# -- executing the notebooks, several at a time -------------------------------------

#: The gallery's claims, measured in a forked process while the notebooks run:
#: ``{process id of the build: (process, pickle file)}``.
_CLAIMS: dict = {}


def _jobs() -> int:
    """How many notebooks run at once: ``$PENTANB_DOCS_JOBS``, else the cores (at least
    2: a notebook's kernel waits on its client part of the time)."""
    env = os.environ.get("PENTANB_DOCS_JOBS", "").strip()
    return max(1, int(env)) if env else max(2, os.cpu_count() or 1)


def _measure_claims(out: str) -> None:
    """In a forked process: :func:`pentanb.figures.check_all`, pickled into ``out``."""
    import pickle

    from pentanb import figures

    Path(out).write_bytes(pickle.dumps(figures.check_all()))


def _execute_one(path: str, timeout: int, out: str) -> None:
    """In a forked process: jupyter-cache's execution of one notebook (in its folder,
    widget state saved), written to ``out`` as JSON with the time or the error.

    The kernel talks over Unix sockets named after ``out`` (IPC), not TCP ports:
    kernels started at the same moment by separate processes can draw the same free
    TCP ports, and a client then waits forever on another's kernel.
    """
    import nbformat
    from jupyter_cache.executors.utils import single_nb_execution
    from jupyter_client.manager import KernelManager

    notebook = nbformat.read(path, as_version=4)
    kernel = notebook.metadata.get("kernelspec", {}).get("name", "python3")
    km = KernelManager(kernel_name=kernel, transport="ipc", ip=str(Path(out).with_suffix("")))
    result = single_nb_execution(
        notebook, cwd=str(Path(path).parent), timeout=timeout, allow_errors=False, km=km
    )
    report = {"time": result.time, "error": result.exc_string if result.err else None}
    if result.err is None:
        report["notebook"] = nbformat.writes(notebook)
    Path(out).write_text(json.dumps(report), encoding="utf-8")


def _execute_notebooks(app, env, docnames) -> None:
    """Execute the notebooks to be read that are missing from the jupyter cache,
    :func:`_jobs` at a time, before Sphinx reads them (one by one) from the cache;
    meanwhile measure the gallery's claims, if the gallery is to be read.

    myst-nb executes one notebook at a time, and ``sphinx-build -j`` puts them all in
    one process; this runs the same execution (jupyter-cache's, in the notebook's
    folder, the widget state saved) in forked processes (nbclient does not run in
    threads), then stores the results in the cache as myst-nb does.  A notebook that
    fails here is left out of the cache, so that myst-nb executes it again and
    reports the error (the build fails).
    """
    import multiprocessing
    import tempfile
    import time

    from sphinx.util import logging as sphinx_logging

    logger = sphinx_logging.getLogger("pentanb.docs")
    fork = multiprocessing.get_context("fork")
    scratch = Path(tempfile.mkdtemp(prefix="pentanb-docs-"))
    started = []

    def clean_up(*_):
        for proc in started:
            if proc.is_alive():
                proc.kill()
            proc.join()
        shutil.rmtree(scratch, ignore_errors=True)

    app.connect("build-finished", clean_up)
    if "docs/gallery" in docnames:
        claims = fork.Process(target=_measure_claims, args=(str(scratch / "claims.pickle"),))
        claims.start()
        started.append(claims)
        _CLAIMS[os.getpid()] = (claims, scratch / "claims.pickle")

    config = env.mystnb_config
    if config.execution_mode != "cache":
        return
    import nbformat
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    cache = get_cache(config.execution_cache_path)
    todo = []
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        if f"notebooks/{path.stem}" not in docnames:
            continue
        try:
            cache.match_cache_notebook(nbformat.read(path, as_version=4))
        except KeyError:
            todo.append(path)
    if not todo:
        return
    jobs = min(_jobs(), len(todo))
    logger.info(f"pentanb: executing {len(todo)} notebooks, {jobs} at a time")
    t0 = time.perf_counter()
    waiting, running = list(todo), []
    while waiting or running:
        while waiting and len(running) < jobs:
            path = waiting.pop(0)
            out = scratch / f"{path.stem}.json"
            proc = fork.Process(
                target=_execute_one, args=(str(path), config.execution_timeout, str(out))
            )
            proc.start()
            started.append(proc)
            running.append((path, proc, out))
        for item in list(running):
            path, proc, out = item
            proc.join(timeout=0.2)
            if proc.exitcode is None:
                continue
            running.remove(item)
            name = path.relative_to(ROOT)
            report = json.loads(out.read_text(encoding="utf-8")) if out.is_file() else {}
            if not report.get("notebook"):
                logger.info(f"pentanb: {name} failed; myst-nb runs it again to report it")
                continue
            logger.info(f"pentanb: {name} executed in {report['time']:.1f} s")
            cache.cache_notebook_bundle(
                CacheBundleIn(
                    nbformat.reads(report["notebook"], as_version=4),
                    str(path),
                    data={"execution_seconds": report["time"]},
                ),
                check_validity=False,
                overwrite=True,
            )
    logger.info(f"pentanb: notebooks executed in {time.perf_counter() - t0:.1f} s")


def _claims_measured():
    """The claims measured while the notebooks ran, or None (e.g. in a process that
    ``sphinx-build -j`` forked, or if the measuring process failed)."""
    import pickle

    started = _CLAIMS.get(os.getpid())
    if started is None:
        return None
    proc, out = started
    proc.join()
    return pickle.loads(out.read_bytes()) if proc.exitcode == 0 and out.is_file() else None


# -- the API pages: the pentanb-module directive --------------------------------------


def public_names(module_name: str) -> list[str]:
    """The module's ``__all__``, in its order.

    Parameters
    ----------
    module_name : str
        A module of pentanb, e.g. ``"pentanb.io"``.

    Returns
    -------
    list of str
    """
    return list(importlib.import_module(module_name).__all__)


def _kind(obj) -> str:
    if typing.get_origin(obj) is not None:  # tuple[...], list[...]: a type alias
        return "alias"
    if isinstance(obj, types.ModuleType):
        return "module"
    if inspect.isclass(obj):
        return "exception" if issubclass(obj, BaseException) else "class"
    if inspect.isroutine(obj):
        return "function"
    return "data"


#: The modules with an API page: ``docs/api/<module>.rst``.
API_MODULES = sorted(p.stem for p in (DOCS / "api").glob("pentanb*.rst"))


def _home_page(module_name: str, obj) -> str | None:
    """Another API module whose ``__all__`` holds the class ``obj``, when
    ``module_name`` is the top-level package re-exporting it (its entry there is
    an alias, so the class has one full description and one canonical name)."""
    if module_name != "pentanb":
        return None
    for other in API_MODULES:
        if other == module_name:
            continue
        mod = importlib.import_module(other)
        for n in getattr(mod, "__all__", ()):
            if getattr(mod, n, None) is obj:
                return f"{other}.{n}"
    return None


class ModuleDirective(SphinxDirective):
    """``.. pentanb-module:: pentanb.io``: the module's docstring, a summary table of
    its ``__all__`` and an entry for every name (a module in ``__all__`` is linked
    to its own page)."""

    required_arguments = 1
    has_content = False

    def run(self):
        name = self.arguments[0]
        module = importlib.import_module(name)
        self.env.note_dependency(inspect.getsourcefile(module))
        rst = [f".. automodule:: {name}", "   :no-members:", ""]
        names = public_names(name)
        rst += [".. rubric:: Contents", "", ".. pentanb-autosummary::", ""]
        rst += [f"   {n}" for n in names]
        rst.append("")
        for n in names:
            obj = getattr(module, n)
            kind = _kind(obj)
            if kind == "module":
                continue  # its own page; the summary row links there
            if kind == "alias":  # autodoc cannot sign these: written out
                rst += [f".. py:data:: {n}", ""]
                rst += [f"   {line}" for line in _attribute_doc(f"{name}.{n}", obj)]
                rst += ["", f"   A type alias: ``{_alias_text(f'{name}.{n}', obj)}``.", ""]
                continue
            home = _home_page(name, obj) if kind in ("class", "exception") else None
            if home is not None:
                rst += [
                    f".. py:{kind}:: {n}",
                    "",
                    f"   The same {kind} as :class:`{home}` (documented there).",
                    "",
                ]
                continue
            rst.append(f".. auto{kind}:: {name}.{n}")
            if kind == "class":
                rst += ["   :members:", "   :show-inheritance:"]
            elif kind == "exception":
                rst += ["   :show-inheritance:"]
            elif kind == "data":
                rst += ["   :no-value:"]
            rst.append("")
        node = nodes.section()
        node.document = self.state.document
        nested_parse_with_titles(self.state, StringList(rst, source=name), node)
        return node.children


def _first_paragraph(doc: str) -> str:
    out = []
    for line in inspect.cleandoc(doc).splitlines():
        if not line.strip():
            break
        out.append(line.strip())
    return " ".join(out)


def _alias_text(name: str, obj) -> str:
    """A type alias as its module writes it (``tuple[NDArray[np.float64], int]``)."""
    import ast

    short = name.rsplit(".", 1)[1]
    for modname in sorted(m for m in sys.modules if m.startswith("pentanb")):
        module = sys.modules[modname]
        if module is None or getattr(module, short, None) is not obj:
            continue
        try:
            source = inspect.getsource(module)
        except (OSError, TypeError):
            continue
        for node in ast.parse(source).body:
            if isinstance(node, ast.Assign):
                targets, value = node.targets, node.value
            elif isinstance(node, ast.AnnAssign) and node.value is not None:
                targets, value = [node.target], node.value
            else:
                continue
            if any(isinstance(t, ast.Name) and t.id == short for t in targets):
                return ast.get_source_segment(source, value) or repr(obj)
    return repr(obj)


class Autosummary(autosummary.Autosummary):
    """autosummary, with two summaries mended: a constant's is its ``#:`` comment
    (not its type's docstring), and a first sentence that autosummary would cut
    inside an inline literal (``k i1 .. ik``) is the first paragraph whole."""

    def get_items(self, names):
        prefixes = autosummary.get_import_prefixes_from_env(self.env)
        items = []
        for name in names:
            try:
                real_name, obj, _parent, _mod = autosummary.import_by_name(name, prefixes)
            except ImportError:
                obj = None
            if obj is not None and _kind(obj) == "alias":  # autodoc cannot sign these
                summary = _first_paragraph("\n".join(_attribute_doc(real_name, obj)))
                items.append((name, "", summary or "A type alias.", real_name))
            else:
                items += self._items([name])
        return items

    def _items(self, names):
        items = []
        for display, sig, summary, real_name in super().get_items(names):
            try:
                obj = autosummary.import_by_name(real_name)[1]
            except ImportError:
                items.append((display, sig, summary, real_name))
                continue
            if not (inspect.isclass(obj) or inspect.isroutine(obj) or inspect.ismodule(obj)):
                summary = _first_paragraph("\n".join(_attribute_doc(real_name, obj)))
            elif summary.count("``") % 2:
                summary = _first_paragraph(inspect.getdoc(obj) or "")
            items.append((display, sig, summary, real_name))
        return items


def _attribute_doc(name: str, obj) -> list[str]:
    """The ``#:`` comment of a constant, found in the module that defines it."""
    from sphinx.pycode import ModuleAnalyzer

    short = name.rsplit(".", 1)[1]
    for modname in sorted(m for m in sys.modules if m.startswith("pentanb")):
        module = sys.modules[modname]
        if module is None or getattr(module, short, None) is not obj:
            continue
        try:
            docs = ModuleAnalyzer.for_module(modname).find_attr_docs()
        except Exception:  # no source: try the next module
            continue
        if ("", short) in docs:
            return [*docs["", short]]
    return []


def _data_docstring(app, what, name, obj, options, lines) -> None:
    """A constant re-exported from another module gets the ``#:`` comment written
    where it is defined, instead of its type's docstring (``dict() -> new empty
    dictionary``)."""
    if what not in ("data", "attribute") or "." not in name:
        return
    type_doc = inspect.getdoc(type(obj)) or ""
    if lines and "\n".join(lines).strip() != type_doc.strip():
        return
    lines[:] = _attribute_doc(name, obj)


# -- the gallery: the pentanb-gallery directive ---------------------------------------

_RST_SPECIAL = re.compile(r"([\\`*_|\[\]<>])")


def _esc(text: str) -> str:
    """Plain text as reStructuredText inline text (one line)."""
    return _RST_SPECIAL.sub(r"\\\1", " ".join(str(text).split()))


_VERDICT_ROLE = {"holds": "v-holds", "holds within tolerance": "v-within"}


def _notebooks_of_figures() -> dict[str, list[str]]:
    """``{figure name: [notebook stems that draw or check it]}``."""
    from pentanb import figures

    out: dict[str, list[str]] = {}
    calls = {
        **{f"figure{int(k[3:])}": k for k in figures.FIGURES if k.startswith("fig")},
        "equation1": "equation1",
        "lateral_figure": "lateral",
        "convergence_figure": "convergence",
        "spectra_figure": "spectra",
        "characteristic_maps_figure": "characteristic_maps",
    }
    for nb in sorted((ROOT / "notebooks").glob("*.ipynb")):
        source = "\n".join(
            "".join(c.get("source", ""))
            for c in json.loads(nb.read_text(encoding="utf-8")).get("cells", [])
            if c.get("cell_type") == "code"
        )
        seen = set()
        for call in re.findall(r"figures\.(\w+)\(", source):
            if call in calls:
                seen.add(calls[call])
        for arg in re.findall(r"figures\.claims\(\s*([\w\"']+)\s*\)", source):
            arg = arg.strip("\"'")
            key = f"fig{int(arg):02d}" if arg.isdigit() else arg
            if key in figures.FIGURES:
                seen.add(key)
        for key in seen:
            out.setdefault(key, []).append(nb.stem)
    return out


def _gallery_title(key: str, title: str) -> str:
    """``"Figure 7: Tetrahedron to dodecahedron"`` for the paper's figures, else the title."""
    number = re.fullmatch(r"fig(\d+)", key)
    return f"Figure {int(number.group(1))}: {title}" if number else title


class GalleryDirective(SphinxDirective):
    """``.. pentanb-gallery::``: every image of ``figures/`` (the registry's order),
    its caption, and its claims with their verdicts, measured now."""

    has_content = False
    option_spec: ClassVar[dict] = {"only": directives.unchanged}

    def run(self):
        from pentanb import figures

        names = list(figures.FIGURES)
        if "only" in self.options:
            names = [figures.get(n).name for n in self.options["only"].split()]
        measured = _claims_measured() if names == list(figures.FIGURES) else None
        results = measured if measured is not None else figures.check_all(names)
        for path in (ROOT / "pentanb" / "figures").glob("*.py"):
            self.env.note_dependency(str(path))
        drawn_in = _notebooks_of_figures()
        rst = [
            ".. role:: v-holds",
            "   :class: pentanb-verdict pentanb-holds",
            ".. role:: v-within",
            "   :class: pentanb-verdict pentanb-within",
            ".. role:: v-fails",
            "   :class: pentanb-verdict pentanb-fails",
            "",
        ]
        # the summary: one row per image
        rst += [
            ".. list-table:: Every image, its claims and their verdicts",
            "   :header-rows: 1",
            "   :class: pentanb-gallery-summary",
            "",
            "   * - image",
            "     - claims",
            "     - hold",
            "     - within tolerance",
            "     - do not hold as stated",
        ]
        for key in [*names, "schemes"]:
            claims = results[key]
            title = (
                _gallery_title(key, figures.FIGURES[key].title)
                if key in figures.FIGURES
                else "The schemes"
            )
            counts = [sum(c.verdict == v for c in claims) for v in figures.VERDICTS]
            rst += [
                f"   * - :ref:`{_esc(title)} <gallery-{key}>`",
                f"     - {len(claims)}",
                *[f"     - {n}" for n in counts],
            ]
        rst.append("")
        for key in [*names, "schemes"]:
            rst += self._entry(key, results[key], drawn_in.get(key, []))
        node = nodes.section()
        node.document = self.state.document
        nested_parse_with_titles(self.state, StringList(rst, source="pentanb-gallery"), node)
        return node.children

    def _entry(self, key: str, claims, notebooks) -> list[str]:
        from pentanb import figures

        if key in figures.FIGURES:
            spec = figures.FIGURES[key]
            title, caption = _gallery_title(key, spec.title), spec.caption
        else:
            from pentanb.figures import formulas

            title, caption = formulas.TITLE, None
        heading = _esc(title)
        rst = [f".. _gallery-{key}:", "", heading, "-" * max(len(heading), 3), ""]
        if caption is not None:
            rst += [
                f".. figure:: /figures/{spec.filename}",
                f"   :alt: {_esc(title)}",
                "   :class: pentanb-gallery-figure",
                "",
                f"   \\{_esc(caption)}",  # "(A) is ..." is no enumerated list
                "",
            ]
        where = [f"``figures/{spec.filename}``"] if caption is not None else []
        where += [f":doc:`/notebooks/{nb}`" for nb in notebooks]
        if where:
            rst += ["Drawn in: " + ", ".join(where) + ".", ""]
        for c in claims:
            role = _VERDICT_ROLE.get(c.verdict, "v-fails")
            tag = " (a finding)" if c.finding else ""
            if c.regressed:
                tag += f" (REGRESSION: recorded as {_esc(c.recorded)})"
            rst += [
                f"* :{role}:`{_esc(c.verdict)}`{tag} ``{c.key}``, {_esc(c.section)}",
                "",
                f"  | **The paper:** “{_esc(c.quote)}”",
                f"  | **Measured:** {_esc(c.measured)}",
                f"  | **Criterion:** {_esc(c.criterion)}",
                "",
            ]
        return rst


def setup(app):
    app.add_directive("pentanb-module", ModuleDirective)
    app.add_directive("pentanb-autosummary", Autosummary)
    app.add_directive("pentanb-gallery", GalleryDirective)
    app.connect("autodoc-process-docstring", _data_docstring, priority=400)
    app.connect("builder-inited", _check_scripts)
    app.connect("env-before-read-docs", _execute_notebooks)
    app.connect("build-finished", _copy_scripts)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
