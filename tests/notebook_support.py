"""What every notebook execution of the test suite adds to the notebook, and checks.

Each notebook is executed once per test run, in one kernel, with two cells
added:

* :data:`GUARD` first: every :class:`pentanb.Mesh` that has vertices is
  initialised through ``Mesh._init(self, vertices, corners, offsets, ...)``
  (a contract of ``pentanb/mesh.py``); the guard wraps it, so building a mesh
  of more than :data:`MAX_FACES` faces raises, whoever builds it: a figure,
  ``subdivide``, an operator called directly, a widget.  It also records the
  largest mesh built.
* :data:`SWEEP` last: every slider and drop-down of every widget the notebook
  made, in the order they were made, moved to both ends (a drop-down through
  every option, a check box both ways), each left at its last value so that
  later controls meet the largest earlier ones.  A control disabled at its
  turn is swept once an earlier drop-down enables it.  It prints one line,
  ``SWEEP {json}``, read by :func:`sweep_result`.

Who executes: ``tests/test_browser_lab_a.py`` or ``tests/test_browser_lab_b.py``
(in JupyterLab, headless Chromium; :func:`browser_share` says which) when it is
selected and a browser is available, else ``tests/test_notebooks.py``
(nbclient); :func:`executed_by_browser` decides.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: Every notebook executed by the tests: the teaching notebooks, then the
#: widget notebook of the browser tests.
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb")) + sorted(
    (ROOT / "tests" / "notebooks").glob("*.ipynb")
)

#: Seconds each notebook's browser test took (its run, the slider, the sweep),
#: the browser test files run side by side on 2 cores, to deal the notebooks into
#: shares of about equal time (:func:`browser_share`); a notebook not listed
#: counts as the mean of these.  Measure again (``--durations``) when a notebook
#: changes much.
BROWSER_SECONDS = {
    "01_topology.ipynb": 70,
    "02_tetrahedron_to_dodecahedron.ipynb": 47,
    "03_cube_tilings.ipynb": 102,
    "04_torus_hexagons.ipynb": 55,
    "05_soccerball.ipynb": 53,
    "06_schemes_compared.ipynb": 89,
    "07_complex_model.ipynb": 57,
    "08_convergence.ipynb": 124,
    "09_continuity.ipynb": 107,
    "10_conway.ipynb": 60,
    "11_open_surfaces.ipynb": 63,
    "three_widgets.ipynb": 47,
}

#: The browser test files, each with its own JupyterLab and Chromium (so its own
#: pytest-xdist worker): ``tests/test_browser_lab_{a,b}.py`` run share 0 and 1 of
#: :func:`browser_share`.
BROWSER_FILES = ("test_browser_lab_a.py", "test_browser_lab_b.py")


def browser_share(index: int, shares: int = len(BROWSER_FILES)) -> list[Path]:
    """The notebooks of one browser test file: :data:`NOTEBOOKS` dealt into
    ``shares`` lists of about equal :data:`BROWSER_SECONDS`, the longest first,
    each to the share with the fewest seconds so far (ties: the lower index).

    Parameters
    ----------
    index : int
        Which share, ``0 <= index < shares``.
    shares : int
        How many.

    Returns
    -------
    list of Path
        That share's notebooks, in :data:`NOTEBOOKS` order.
    """
    if not 0 <= index < shares:
        raise ValueError(f"share {index} of {shares}")
    mean = sum(BROWSER_SECONDS.values()) / len(BROWSER_SECONDS)
    cost = {p: BROWSER_SECONDS.get(p.name, mean) for p in NOTEBOOKS}
    loads = [0.0] * shares
    dealt: list[list[Path]] = [[] for _ in range(shares)]
    for p in sorted(NOTEBOOKS, key=lambda p: (-cost[p], p.name)):
        k = loads.index(min(loads))
        loads[k] += cost[p]
        dealt[k].append(p)
    return [p for p in NOTEBOOKS if p in dealt[index]]


#: Largest mesh (faces) a notebook may build, at any step, with any control anywhere.
MAX_FACES = 100_000

#: Marks the cells the tests add (in the cell's metadata).
ADDED = "pentanb-test"

GUARD = f"""\
# added by the tests: no mesh of more than {MAX_FACES:,} faces, whoever builds it
import pentanb.mesh as _pentanb_mesh


class _PentanbMeshTooLarge(RuntimeError):
    pass


_pentanb_largest = {{"faces": 0, "meshes": 0}}
_pentanb_init = _pentanb_mesh.Mesh._init


def _pentanb_guarded_init(self, *args, **kwargs):
    offsets = kwargs["offsets"] if "offsets" in kwargs else args[2]
    faces = len(offsets) - 1
    if faces > {MAX_FACES}:
        raise _PentanbMeshTooLarge(
            f"a mesh of {{faces:,}} faces was built; the notebooks stop at {MAX_FACES:,}"
        )
    _pentanb_largest["faces"] = max(_pentanb_largest["faces"], faces)
    _pentanb_largest["meshes"] += 1
    return _pentanb_init(self, *args, **kwargs)


_pentanb_mesh.Mesh._init = _pentanb_guarded_init
"""

SWEEP = """\
# added by the tests: every slider and drop-down to both ends
import json as _json
import time as _time

import ipywidgets as _widgets
from ipywidgets.widgets.widget import _instances as _all_widgets

_sweep = {"positions": 0, "slowest": 0.0, "unswept": []}
_CHOICES = (_widgets.Dropdown, _widgets.Select, _widgets.RadioButtons, _widgets.ToggleButtons)
_RANGES = (_widgets.IntSlider, _widgets.FloatSlider)


def _ends(w):
    if isinstance(w, _RANGES):
        return [lambda w: w.min, lambda w: w.max]  # read when used: a limit may move them
    if isinstance(w, _CHOICES):
        return [lambda w, v=v: v[1] if isinstance(v, tuple) else v for v in w.options]
    if isinstance(w, _widgets.Checkbox):
        return [lambda w: not w.value, lambda w: not w.value]
    return []


def _move(w):
    for end in _ends(w):
        if getattr(w, "disabled", False):
            return False
        t = _time.perf_counter()
        w.value = end(w)
        _sweep["slowest"] = max(_sweep["slowest"], _time.perf_counter() - t)
        _sweep["positions"] += 1
    return True


_controls = [w for w in list(_all_widgets.values()) if _ends(w)]
_skipped = [w for w in _controls if not _move(w)]
for _w in _skipped:  # disabled at its turn: an earlier drop-down may enable it
    for _r in (r for r in _controls[: _controls.index(_w)] if isinstance(r, _RANGES)):
        _r.value = _r.min  # (the smallest request: an explorer refuses a large one whole)
    _earlier = [d for d in _controls[: _controls.index(_w)] if isinstance(d, _CHOICES)]
    for _d in _earlier:
        for _end in _ends(_d):
            if not getattr(_w, "disabled", False):
                break
            _d.value = _end(_d)
        if not getattr(_w, "disabled", False):
            break
    if not _move(_w):
        _sweep["unswept"].append(f"{type(_w).__name__} {_w.description!r}")
_sweep["controls"] = len(_controls)
_sweep["renderers"] = sum(type(w).__name__ == "Renderer" for w in _all_widgets.values())
_sweep.update(_pentanb_largest)
print("SWEEP", _json.dumps(_sweep))
"""


def instrumented(nb):
    """A copy of a notebook with :data:`GUARD` first and :data:`SWEEP` last.

    ``nb`` is an nbformat node or the plain dict of a notebook's JSON; the
    copy is of the same kind.
    """
    import copy

    import nbformat

    out = copy.deepcopy(nb)
    guard = nbformat.v4.new_code_cell(GUARD, metadata={ADDED: "guard"})
    sweep = nbformat.v4.new_code_cell(SWEEP, metadata={ADDED: "sweep"})
    if not isinstance(out, nbformat.NotebookNode):
        guard, sweep = dict(guard), dict(sweep)
        guard["metadata"], sweep["metadata"] = dict(guard["metadata"]), dict(sweep["metadata"])
    out["cells"] = [guard, *out["cells"], sweep]
    return out


def sweep_result(text: str) -> dict | None:
    """The dict printed by :data:`SWEEP` in ``text`` (its stdout), or None."""
    lines = [ln for ln in text.splitlines() if ln.startswith("SWEEP ")]
    return json.loads(lines[-1][len("SWEEP ") :]) if lines else None


def check_sweep(name: str, result: dict | None, text: str = "") -> str:
    """Assert what the sweep found; return a one-line summary."""
    assert result is not None, f"{name}: the sweep printed nothing:\n{text[-2000:]}"
    assert result["meshes"] > 0, (
        f"{name}: the face guard saw no mesh being built (is Mesh._init still the "
        "one place meshes are initialised?)"
    )
    assert result["faces"] <= MAX_FACES, f"{name}: a mesh of {result['faces']:,} faces"
    assert not result["unswept"], f"{name}: controls never enabled: {result['unswept']}"
    assert result["controls"] > 0 and result["positions"] >= result["controls"], (
        f"{name}: {result['controls']} controls but {result['positions']} positions"
    )
    return (
        f"{name}: {result['controls']} controls, {result['positions']} positions, largest mesh "
        f"{result['faces']:,} faces, slowest move {result['slowest']:.2f} s"
    )


def browser_available() -> bool:
    """Python's playwright and a Chromium (see ``browser_support``) are both there."""
    import importlib.util
    import os

    if importlib.util.find_spec("playwright") is None:
        return False
    env = os.environ.get("PENTANB_CHROMIUM")
    candidates = [env] if env else ["/usr/bin/chromium", shutil.which("chromium")]
    return any(c and os.path.isfile(c) and os.access(c, os.X_OK) for c in candidates)


#: The browser test that executes a notebook (in :data:`BROWSER_FILES`), by its name.
BROWSER_TEST = "test_notebook_runs_and_draws_in_jupyterlab"


def executed_by_browser(session, path: Path) -> bool:
    """True when this run's browser test executes ``path`` (so nbclient must not).

    That is when the browser test of this notebook is among the selected
    tests and playwright and Chromium are installed (without them the
    browser test skips, or fails under CI, without executing anything).
    """
    wanted = f"{BROWSER_TEST}[{path.name}]"
    selected = any(
        item.name == wanted and Path(item.nodeid.split("::")[0]).name in BROWSER_FILES
        for item in session.items
    )
    return selected and browser_available()
