"""Execute every notebook once, headless, and check what it leaves behind.

Each notebook (``notebooks/*.ipynb`` and ``tests/notebooks/*.ipynb``) runs
top to bottom, with the face guard first and the control sweep last (see
:mod:`notebook_support`), in one kernel started with the Python that runs
pytest (a kernel spec written on the fly for ``sys.executable``, so a
``python3`` spec pointing at another environment cannot be picked up by
accident), in the notebook's folder.  A cell that raises fails the test, so
does a mesh of more than 100,000 faces built by anything, a control the
sweep could not move, or a notebook that draws nothing.

When the browser tests (``tests/test_browser_lab_a.py``, ``_b.py``) execute
a notebook in JupyterLab in the same run, it is that run's one execution
and the test here is skipped (saying so); ``pytest -m "not browser"``
executes them all here.

The committed files are the notebooks' source: they must carry no outputs
and stay small.  (``ruff check`` and ``ruff format --check`` lint them.)
"""

from __future__ import annotations

import importlib.util
import json
import os
import sys
import time
from pathlib import Path

import notebook_support as ns
import pytest

# found, not imported: importing nbformat (jsonschema and its grammars) takes
# seconds, paid only by the tests that read or run notebooks with it
for _name in ("nbformat", "nbclient", "ipykernel", "ipywidgets"):
    if importlib.util.find_spec(_name) is None:
        pytest.skip(f"{_name} is not installed", allow_module_level=True)

NOTEBOOKS = ns.NOTEBOOKS

#: Seconds any single cell may take before the run is failed: a guard against
#: a hung kernel, not a speed limit (a busy machine must never reach it).
CELL_TIMEOUT = 900
#: Largest committed notebook, in bytes.
MAX_BYTES = 2 * 1024 * 1024
#: Output types that count as "the notebook drew something".
VISUAL_MIMETYPES = ("image/png", "image/svg+xml", "application/vnd.jupyter.widget-view+json")

KERNEL_NAME = "pentanb-test-python"


def _ids(paths):
    return [p.name for p in paths]


def test_notebooks_exist():
    names = [p.name for p in NOTEBOOKS]
    numbered = sorted(int(n[:2]) for n in names if n[:2].isdigit())
    # 01..08 reproduce the paper, 09 answers its open question on continuity
    assert numbered == list(range(1, len(numbered) + 1)) and len(numbered) >= 9, names
    assert "three_widgets.ipynb" in names


@pytest.fixture(scope="session")
def kernel_dir(tmp_path_factory) -> str:
    """A kernel spec directory whose only kernel runs ``sys.executable``."""
    from ipykernel.kernelspec import write_kernel_spec

    kernels = tmp_path_factory.mktemp("kernels")
    write_kernel_spec(
        kernels / KERNEL_NAME, overrides={"display_name": f"pentanb tests ({sys.executable})"}
    )
    return str(kernels)


def _kernel_env() -> dict:
    """The test's environment, minus settings that would hide inline figures."""
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)  # the kernel picks matplotlib's inline backend
    env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # quiet debugger warning on frozen modules
    root = str(ns.ROOT)
    env["PYTHONPATH"] = os.pathsep.join(
        [root] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
    )
    return env


def _quiet_output_widget():
    """nbclient's Output-widget mimic, minus its messages back to the kernel.

    The mimic sends every change of its outputs to the kernel on the shell
    socket while nbclient awaits the cell's reply on that same socket; now
    and then the reply is then only noticed when the cell's timeout expires
    (jupyter/nbclient#312), which made a 2-second notebook take 2 minutes.
    The notebooks never read an Output widget's outputs back in Python, so
    the mimic only needs to record them.
    """
    from nbclient.output_widget import OutputWidget

    class QuietOutputWidget(OutputWidget):
        def send(self, data=None, metadata=None, buffers=None) -> None:
            pass

    return QuietOutputWidget


def execute(path: Path, kernel_dir: str, nb=None):
    """Run a notebook (by default ``path`` as committed) in its folder; return it."""
    import nbclient
    import nbformat
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import AsyncKernelManager

    nb = nbformat.read(path, as_version=4) if nb is None else nb
    ksm = KernelSpecManager(kernel_dirs=[kernel_dir], ensure_native_kernel=False)
    km = AsyncKernelManager(kernel_name=KERNEL_NAME, kernel_spec_manager=ksm)
    client = nbclient.NotebookClient(
        nb,
        km=km,
        kernel_name=KERNEL_NAME,
        timeout=CELL_TIMEOUT,
        resources={"metadata": {"path": str(path.parent)}},
        allow_errors=False,
        store_widget_state=True,
        shutdown_kernel="immediate",
    )
    client.widget_registry["@jupyter-widgets/output"]["OutputModel"] = _quiet_output_widget()
    # cleanup_kc: shut the kernel down afterwards although the client did not
    # create its manager
    client.execute(cwd=str(path.parent), env=_kernel_env(), cleanup_kc=True)
    return nb


def _outputs(nb):
    for cell in nb.cells:
        if cell.cell_type == "code":
            yield from cell.get("outputs", [])


def _widget_outputs(nb):
    """Outputs captured inside Output widgets (stored in the widget state)."""
    state = (
        nb.metadata.get("widgets", {})
        .get("application/vnd.jupyter.widget-state+json", {})
        .get("state", {})
    )
    for model in state.values():
        yield from model.get("state", {}).get("outputs", []) or []


def _stdout(cell) -> str:
    return "".join(
        out.get("text", "")
        for out in cell.get("outputs", [])
        if out.get("output_type") == "stream" and out.get("name") == "stdout"
    )


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=_ids(NOTEBOOKS))
def test_notebook_runs_and_every_control_moves(path: Path, kernel_dir: str, request):
    """The one execution of a notebook (unless the browser test does it):
    every cell runs, something is drawn, every control moves to both ends,
    no mesh passes 100,000 faces."""
    import nbclient
    import nbformat

    if ns.executed_by_browser(request.session, path):
        pytest.skip(f"{path.name} is executed once, in JupyterLab, by the browser tests")
    start = time.perf_counter()
    try:
        nb = execute(path, kernel_dir, ns.instrumented(nbformat.read(path, as_version=4)))
    except nbclient.exceptions.CellExecutionError as exc:
        pytest.fail(f"{path.name}: a cell raised\n{exc}", pytrace=False)
    elapsed = time.perf_counter() - start
    own = nb.cells[1:-1]
    mimetypes = {
        mime
        for out in [o for c in own if c.cell_type == "code" for o in c.get("outputs", [])]
        + list(_widget_outputs(nb))
        for mime in out.get("data", {})
    }
    drawn = mimetypes.intersection(VISUAL_MIMETYPES)
    assert drawn, (
        f"{path.name} produced no figure or widget output (output types: {sorted(mimetypes)})"
    )
    errors = [out for out in _outputs(nb) if out.get("output_type") == "error"]
    assert not errors, f"{path.name}: error outputs {errors}"
    summary = ns.check_sweep(
        path.name, ns.sweep_result(_stdout(nb.cells[-1])), _stdout(nb.cells[-1])
    )
    print(f"{summary}; executed in {elapsed:.1f} s")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=_ids(NOTEBOOKS))
def test_notebook_committed_clean(path: Path):
    size = path.stat().st_size
    assert size < MAX_BYTES, f"{path.name} is {size:,} bytes (limit {MAX_BYTES:,})"
    nb = json.loads(path.read_text(encoding="utf-8"))  # (nbformat validates it below)
    assert nb.get("nbformat") == 4, f"{path.name}: nbformat {nb.get('nbformat')}"
    for i, cell in enumerate(nb["cells"]):
        assert ns.ADDED not in cell.get("metadata", {}), (
            f"{path.name}: cell {i} was added by the tests"
        )
        if cell["cell_type"] != "code":
            continue
        assert not cell.get("outputs"), f"{path.name}: cell {i} has outputs"
        assert cell.get("execution_count") is None, f"{path.name}: cell {i} has an execution count"
    assert "widgets" not in nb.get("metadata", {}), f"{path.name}: saved widget state"


@pytest.mark.slow  # importing nbformat's validator alone takes seconds
def test_notebooks_are_valid_nbformat():
    import nbformat

    for path in NOTEBOOKS:
        nbformat.validate(nbformat.read(path, as_version=4))


def test_no_notebook_generator_is_left():
    """The .ipynb files are the source: nothing writes them from strings."""
    assert not list((ns.ROOT / "notebooks").glob("*.py"))


# -- the guard and the sweep, in this process ---------------------------------------------


@pytest.fixture
def guarded(monkeypatch):
    """The namespace of GUARD executed here (Mesh._init restored afterwards)."""
    from pentanb.mesh import Mesh

    monkeypatch.setattr(Mesh, "_init", Mesh._init)
    namespace: dict = {}
    exec(ns.GUARD, namespace)
    return namespace


def test_guard_stops_any_mesh_over_the_limit(guarded, monkeypatch):
    import pentanb

    big = pentanb.shapes.torus(250, 100)  # 25,000 quads, 50,000 edges: allowed
    assert guarded["_pentanb_largest"]["faces"] == big.n_faces == 25_000
    # direct operator calls, no subdivide involved
    assert pentanb.vertex_insertion(big).n_faces == 100_000  # 2E quads: at the limit
    wider = pentanb.shapes.torus(251, 100)  # 25,100 quads, 50,200 edges
    with pytest.raises(guarded["_PentanbMeshTooLarge"], match="a mesh of 100,400 faces"):
        pentanb.pentagonalize(wider)  # 2E pentagons
    assert guarded["_pentanb_largest"]["faces"] == ns.MAX_FACES


def test_guard_catches_what_a_widget_builds(guarded):
    """The explorer refuses by its own count; without that, the guard stops it."""
    import pentanb
    from pentanb.viz import explorer

    e = pentanb.explore("cube", iterations=0, max_iterations=8, max_faces=10**9)
    e.scheme.value = "vertex_insertion"
    with pytest.raises(guarded["_PentanbMeshTooLarge"]):
        e.iterations.value = 8  # 6 * 4**8 = 393,216 quads
    assert isinstance(e, explorer.Explorer)


def _run_sweep(namespace):
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(ns.SWEEP, namespace)
    return ns.sweep_result(out.getvalue())


def test_sweep_moves_every_control_including_ones_enabled_later(guarded):
    import ipywidgets as W
    from ipywidgets.widgets.widget import _instances

    import pentanb
    from pentanb.viz.widgets import panel

    for w in list(_instances.values()):  # only this test's widgets
        w.close()
    seen = []

    def draw(scheme="pentagonalize", scale=0.5, edges=True):
        seen.append((scheme, scale, edges))
        return pentanb.subdivide(pentanb.shapes.tetrahedron(), scheme, 1, 0)

    p = panel(
        draw,
        scheme=["preserve_pentagons", "pentagonalize"],  # the last option disables scale
        scale=(0.25, 0.75),
        edges=W.Checkbox(value=True),
        active={"scale": lambda v: "scale" in pentanb.SCHEMES[v["scheme"]].options},
    )
    result = _run_sweep(guarded)
    summary = ns.check_sweep("test", result)
    assert {0.25, 0.75} <= {s for _, s, _ in seen}, seen
    assert {True, False} <= {e for _, _, e in seen}
    assert "positions" in summary and result["unswept"] == []
    assert p.view is not None and p.view.wireframe in [w for w in _instances.values()]


def test_sweep_reports_a_control_it_cannot_enable(guarded):
    import ipywidgets as W
    from ipywidgets.widgets.widget import _instances

    for w in list(_instances.values()):
        w.close()
    W.IntSlider(value=1, min=0, max=3, disabled=True, description="stuck")
    result = _run_sweep(guarded)
    assert result["unswept"] == ["IntSlider 'stuck'"]
    with pytest.raises(AssertionError, match="controls never enabled"):
        ns.check_sweep("test", {**result, "meshes": 1})


def test_check_sweep_fails_without_the_guard():
    result = {"meshes": 0, "faces": 0, "controls": 1, "positions": 2, "unswept": [], "slowest": 0}
    with pytest.raises(AssertionError, match="face guard saw no mesh"):
        ns.check_sweep("test", result)
    with pytest.raises(AssertionError, match="the sweep printed nothing"):
        ns.check_sweep("test", None)
