"""Helpers for the browser tests: headless Chromium, a JupyterLab server, pixels.

Used by ``tests/test_browser.py``, ``tests/test_browser_lab_{a,b}.py`` and
``tests/test_docs.py``; no pytest plugin, no conftest.

* :func:`require_browser` finds Debian's Chromium (``/usr/bin/chromium``, or
  ``$PENTANB_CHROMIUM``) and Python's playwright, and skips the test with a
  message when either is missing -- except under CI (``CI=true``), where a
  missing browser fails the run.
* :class:`JupyterLab` runs ``jupyter lab`` on 127.0.0.1 on a free port, with
  no token, in a scratch folder with its own config, data, settings and
  workspaces (a ``python3`` kernel spec for the running Python), and stops it.
* :class:`LabPage` keeps one page of that JupyterLab open in Chromium (the
  application loaded once) and opens notebooks in it in turn;
  :func:`check_notebook` is the browser test of one notebook.
* :func:`nonblank` and :func:`changed` compare screenshots.
"""

from __future__ import annotations

import io
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
import warnings
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: Flags for headless Chromium without a GPU, a sandbox or background traffic.
CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--no-first-run",
]

#: Console messages known to be harmless (substrings).  None comes from
#: pentanb; see the module docstring of :mod:`pentanb.viz.three`.
HARMLESS_CONSOLE = (
    "GPU stall due to ReadPixels",  # SwiftShader performance note
    "Automatic fallback to software WebGL",  # headless Chromium without GPU
    "WebGL-",  # other GL driver notes
    "allowUnionTypes",  # html-manager's JSON schema (ajv)
    "Unsatisfied version",  # pythreejs built for older Lumino
    "shared singleton module",
    "Failed to load resource: the server responded with a status of 404",  # favicon etc.
    "[Violation]",
    "already frozen",  # pythreejs log when a view is reused
    # pythreejs 2.4 under JupyterLab 4, for lights that cast shadows
    # (PointLight, DirectionalLight, SpotLight); pentanb's views use none
    "Error setting state: t.on is not a function",
)

#: Console text that fails a test whatever its level: WebGL errors mean a
#: buffer was drawn out of step with another (see ``MeshView.update``).
FORBIDDEN_CONSOLE = ("GL_INVALID",)


def in_ci() -> bool:
    return os.environ.get("CI", "").lower() == "true"


def skip_or_fail(message: str):
    """Skip with ``message``; under CI (CI=true) fail instead."""
    if in_ci():
        pytest.fail(f"CI=true but {message}", pytrace=False)
    pytest.skip(message)


def chromium_path() -> str | None:
    """$PENTANB_CHROMIUM when set (only it), else Debian's /usr/bin/chromium."""
    env = os.environ.get("PENTANB_CHROMIUM")
    candidates = (
        (env,)
        if env
        else ("/usr/bin/chromium", shutil.which("chromium"), shutil.which("chromium-browser"))
    )
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


def require_browser():
    """(sync_playwright, chromium path), or skip (fail under CI) saying what is missing."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        skip_or_fail(
            "Python's playwright is not installed (pip install playwright); "
            "browser tests need it and Debian's chromium"
        )
    path = chromium_path()
    if path is None:
        skip_or_fail(
            "no Chromium found at "
            f"{os.environ.get('PENTANB_CHROMIUM') or '/usr/bin/chromium'} "
            "(apt-get install chromium, or bash .ci/browser-setup.sh); "
            "browser tests skipped"
        )
    return sync_playwright, path


def artifact_dir(tmp_path_factory) -> Path:
    """Folder for screenshots: $PENTANB_BROWSER_ARTIFACTS or a new temporary folder
    (kept after the run, so the pictures can be looked at)."""
    env = os.environ.get("PENTANB_BROWSER_ARTIFACTS")
    path = Path(env) if env else Path(tempfile.mkdtemp(prefix="pentanb-browser-"))
    path.mkdir(parents=True, exist_ok=True)
    return path


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class JupyterLab:
    """``jupyter lab`` in a scratch folder (a context manager).

    Parameters
    ----------
    notebooks : list of Path
        Copied into the server's root folder (their kernelspec set to
        ``python3``, which is this Python); files beside them (helper
        modules) are copied too.
    transform : callable, optional
        Applied to each notebook's JSON (a dict) before it is written there,
        e.g. to add cells.
    """

    def __init__(self, notebooks, *, transform=None, startup_timeout: float = 90.0):
        self.notebooks = [Path(p) for p in notebooks]
        self.transform = transform
        self.startup_timeout = startup_timeout
        self.proc = None
        self.scratch = Path(tempfile.mkdtemp(prefix="pentanb-lab-"))
        self.root = self.scratch / "root"
        self.log_path = self.scratch / "server.log"

    def __enter__(self) -> JupyterLab:
        self.root.mkdir()
        for folder in {p.parent for p in self.notebooks}:
            for f in folder.iterdir():
                if f.is_file() and f.suffix in (".py", ".ipynb", ".obj", ".off", ".json"):
                    shutil.copy2(f, self.root / f.name)
        for nb in self.notebooks:
            data = json.loads(nb.read_text())
            if self.transform is not None:
                data = self.transform(data)
            data.setdefault("metadata", {})["kernelspec"] = {
                "name": "python3",
                "display_name": "Python 3 (ipykernel)",
                "language": "python",
            }
            (self.root / nb.name).write_text(json.dumps(data))
        env = self._env()
        self.port = free_port()
        cmd = [
            sys.executable,
            "-m",
            "jupyterlab",
            "--no-browser",
            f"--port={self.port}",
            "--ip=127.0.0.1",
            "--ServerApp.port_retries=0",
            "--IdentityProvider.token=",
            "--ServerApp.password=",
            "--ServerApp.disable_check_xsrf=True",
            f"--ServerApp.root_dir={self.root}",
            "--LabApp.expose_app_in_browser=True",
            "--LabApp.news_url=None",
            "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
            "--LabApp.extension_manager=readonly",
        ]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            cmd.append("--allow-root")  # CI runs as root
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            cmd, stdout=self.log, stderr=subprocess.STDOUT, env=env, cwd=self.root
        )
        self.url = f"http://127.0.0.1:{self.port}"
        deadline = time.monotonic() + self.startup_timeout
        while True:
            if self.proc.poll() is not None:
                raise RuntimeError(f"jupyter lab exited: {self.log_path.read_text()[-3000:]}")
            try:
                with urllib.request.urlopen(self.url + "/api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline:
                self.__exit__(None, None, None)
                raise RuntimeError(
                    f"jupyter lab did not answer within {self.startup_timeout:.0f} s"
                )
            time.sleep(0.25)
        return self

    def server_errors(self) -> str:
        """The server log's tracebacks and error lines so far (for a failure's message)."""
        try:
            text = self.log_path.read_text(errors="replace")
        except OSError:
            return ""
        lines = text.splitlines()
        keep = [
            i
            for i, line in enumerate(lines)
            if "Traceback" in line or " 500 " in line or "[E " in line or "Error" in line
        ]
        if not keep:
            return ""
        shown = "\n".join(lines[max(keep[0] - 2, 0) : keep[-1] + 20][-80:])
        return f"\nthe server's log:\n{shown}"

    def _env(self) -> dict:
        env = dict(os.environ)
        for name in ("config", "data", "runtime", "settings", "workspaces", "ipython"):
            (self.scratch / name).mkdir()
        env.update(
            JUPYTER_CONFIG_DIR=str(self.scratch / "config"),
            JUPYTER_DATA_DIR=str(self.scratch / "data"),
            JUPYTER_RUNTIME_DIR=str(self.scratch / "runtime"),
            JUPYTERLAB_SETTINGS_DIR=str(self.scratch / "settings"),
            JUPYTERLAB_WORKSPACES_DIR=str(self.scratch / "workspaces"),
            IPYTHONDIR=str(self.scratch / "ipython"),
            PYTHONPATH=os.pathsep.join(
                [str(ROOT)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
            ),
        )
        env.pop("JUPYTER_PATH", None)
        # the kernel is this Python (a user-level spec wins over any other)
        spec = self.scratch / "data" / "kernels" / "python3"
        spec.mkdir(parents=True)
        (spec / "kernel.json").write_text(
            json.dumps(
                {
                    "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
                    "display_name": "Python 3 (ipykernel)",
                    "language": "python",
                }
            )
        )
        # no autosave (nothing is written back), no news or update pop-ups
        settings = self.scratch / "settings"
        for plugin, values in {
            "@jupyterlab/docmanager-extension/plugin": {"autosave": False},
            "@jupyterlab/apputils-extension/notification": {
                "fetchNews": "false",
                "checkForUpdates": False,
            },
        }.items():
            path = settings / (plugin + ".jupyterlab-settings")
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(json.dumps(values))
        return env

    def __exit__(self, *exc):
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=5)
        if getattr(self, "log", None):
            self.log.close()
        shutil.rmtree(self.scratch, ignore_errors=True)
        return False


# -- pixels -------------------------------------------------------------------


def image(png: bytes):
    from PIL import Image

    return Image.open(io.BytesIO(png)).convert("RGB")


def nonblank(png: bytes, *, min_fraction: float = 0.01) -> float:
    """Fraction of pixels that differ from the picture's corner (background) colour."""
    import numpy as np

    a = np.asarray(image(png), dtype=np.int16)
    background = a[1, 1]
    differs = np.abs(a - background).max(axis=2) > 16
    return float(differs.mean())


def changed(before: bytes, after: bytes) -> float:
    """Fraction of pixels that differ between two screenshots of the same size."""
    import numpy as np

    a = np.asarray(image(before), dtype=np.int16)
    b = np.asarray(image(after), dtype=np.int16)
    if a.shape != b.shape:
        return 1.0
    return float((np.abs(a - b).max(axis=2) > 16).mean())


def harmless(text: str) -> bool:
    return any(h in text for h in HARMLESS_CONSOLE)


def poll(fn, timeout, interval=0.25):
    """fn() until it returns something truthy, or None after timeout seconds (a hang guard)."""
    deadline = time.monotonic() + timeout
    while True:
        value = fn()
        if value:
            return value
        if time.monotonic() > deadline:
            return None
        time.sleep(interval)


# -- driving a page -------------------------------------------------------------
# The waits below poll for something the browser or the kernel must do and
# return as soon as it is done: their limits only end a test that hangs, so
# they are far above what a busy machine needs (a test never fails for being slow).

#: Seconds a notebook may take to run its cells, and the sweep.
RUN_TIMEOUT = 900
#: Seconds to wait for a picture to appear or to change.
DRAW_TIMEOUT = 180
#: Seconds to wait for the sweep's stdout once the kernel is idle.
SWEEP_GRACE = 180
#: Seconds to wait for JupyterLab to start, and for a notebook page to be ready.
START_TIMEOUT = 600


def listen(page) -> list:
    """The page's console messages and uncaught errors, as ``(kind, text)``, from now on."""
    messages = []
    page.on("console", lambda m: messages.append((m.type, m.text)))
    page.on("pageerror", lambda e: messages.append(("pageerror", str(e))))
    # the address of a server error, which the console message leaves out
    page.on(
        "response",
        lambda r: (
            r.status >= 500
            and messages.append(("error", f"HTTP {r.status}: {r.request.method} {r.url}"))
        ),
    )
    return messages


def bad_console(messages) -> list[str]:
    """The messages of :func:`listen` that fail a test."""
    return [
        f"{kind}: {text[:500]}"
        for kind, text in messages
        if (kind in ("error", "pageerror") and not harmless(text))
        or any(f in text for f in FORBIDDEN_CONSOLE)
    ]


def wait_picture(locator, timeout=DRAW_TIMEOUT):
    """Screenshot of an element once it is not blank (or None), and the last one taken."""
    shots = []

    def check():
        png = locator.screenshot()
        shots.append(png)
        return png if nonblank(png) > 0.01 else None

    return poll(check, timeout, 0.5), (shots[-1] if shots else None)


def wait_change(locator, before, timeout=DRAW_TIMEOUT):
    """The element's picture once it differs from ``before`` and has settled, or None."""

    def check():
        png = locator.screenshot()
        return png if changed(before, png) > 0.0005 else None

    after = poll(check, timeout, 0.5)
    if after is None:
        return None
    last = [after]

    def settled():
        png = locator.screenshot()
        same = changed(last[0], png) == 0.0
        last[0] = png
        return same

    poll(settled, 10, 0.5)
    return last[0]


def move_slider(handle, target, before):
    """One step right (left when at the maximum); the target's new picture or None."""
    at_max = handle.get_attribute("aria-valuenow") == handle.get_attribute("aria-valuemax")
    handle.focus()
    handle.press("ArrowLeft" if at_max else "ArrowRight")
    return wait_change(target, before)


# -- the fixtures of a browser test file ------------------------------------------


def module_fixtures(notebooks=()):
    """The fixtures of one browser test file, each made once for the file.

    Parameters
    ----------
    notebooks : sequence of Path
        The notebooks the file's JupyterLab serves (none: no ``lab`` needed).

    Returns
    -------
    browser, lab, lab_page, artifacts : pytest fixtures
        Headless Chromium; a :class:`JupyterLab` serving ``notebooks``
        instrumented by :func:`notebook_support.instrumented`; a
        :class:`LabPage` of that JupyterLab in that Chromium (the application
        loaded once, the notebooks opened in it in turn); the folder of the
        screenshots.  Assign them to these names in the test file: each file
        (one pytest-xdist worker) has its own Chromium and JupyterLab.
    """
    import notebook_support as ns

    @pytest.fixture(scope="module")
    def browser():
        sync_playwright, path = require_browser()
        with sync_playwright() as p:
            b = p.chromium.launch(executable_path=path, args=CHROMIUM_FLAGS)
            yield b
            b.close()

    @pytest.fixture(scope="module")
    def lab(browser):
        with JupyterLab(
            notebooks, transform=ns.instrumented, startup_timeout=START_TIMEOUT
        ) as server:
            yield server

    @pytest.fixture(scope="module")
    def lab_page(browser, lab):
        page = LabPage(browser, lab)
        yield page
        page.close()

    @pytest.fixture(scope="module")
    def artifacts(tmp_path_factory):
        path = artifact_dir(tmp_path_factory)
        print(f"\nbrowser screenshots: {path}")
        return path

    return browser, lab, lab_page, artifacts


# -- a notebook in JupyterLab -----------------------------------------------------

#: The application is there and can open documents (then await its ``restored``).
JS_APP = """() => {
  const app = window.jupyterapp;
  return !!(app && app.commands.hasCommand('docmanager:open'));
}"""

#: Open a notebook (a path in the server's root) in a tab of its own; its id.
JS_OPEN = """async (path) => {
  const app = window.jupyterapp;
  const w = await app.commands.execute('docmanager:open', {path: path, factory: 'Notebook'});
  app.shell.activateById(w.id);
  return w.id;
}"""

#: The current widget is the notebook ``path``, its cells shown and its file read.
JS_READY = """(path) => {
  const app = window.jupyterapp;
  const w = app && app.shell.currentWidget;
  return !!(w && w.sessionContext && w.content && w.content.widgets
            && w.content.widgets.length && w.context && w.context.isReady
            && w.context.path === path);
}"""

JS_RUN = """async (last) => {
  const app = window.jupyterapp;
  const w = app.shell.currentWidget;
  await w.sessionContext.ready;
  window.__pentanbRun = null;
  w.content.activeCellIndex = w.content.widgets.length - 1;
  app.commands.execute(last ? 'notebook:run-cell' : 'notebook:run-all-above').then(
      ok => { window.__pentanbRun = {ok: ok}; },
      err => { window.__pentanbRun = {ok: false, error: String(err)}; });
  const k = w.sessionContext.session && w.sessionContext.session.kernel;
  return k ? k.name : null;
}"""

JS_DONE = """() => {
  const w = window.jupyterapp.shell.currentWidget;
  const k = w.sessionContext.session && w.sessionContext.session.kernel;
  return window.__pentanbRun !== null && k && k.status === 'idle';
}"""

#: Errors, cells not run (up to ``upto``), output types, and the last cell's stdout.
JS_RESULT = """(upto) => {
  const w = window.jupyterapp.shell.currentWidget;
  const errors = [], missing = [], mimetypes = new Set();
  let last = '';
  w.content.widgets.forEach((c, i) => {
    if (c.model.type !== 'code') return;
    if (i < upto && c.model.sharedModel.getSource().trim() && c.model.executionCount === null)
      missing.push(i);
    for (const o of c.model.outputs.toJSON()) {
      if (o.output_type === 'error')  // with the traceback's last frames, to diagnose
        errors.push(`cell ${i}: ${o.ename}: ${o.evalue}\\n`
                    + (o.traceback || []).slice(-6).join('\\n'));
      for (const m of Object.keys(o.data || {})) mimetypes.add(m);
      if (i === w.content.widgets.length - 1 && o.output_type === 'stream'
          && o.name === 'stdout')
        last += Array.isArray(o.text) ? o.text.join('') : o.text;
    }
  });
  const tail = w.content.widgets[w.content.widgets.length - 1].model;
  return {run: window.__pentanbRun, errors: errors, missing: missing,
          mimetypes: [...mimetypes], cells: w.content.widgets.length, last: last,
          tail: {count: tail.executionCount,
                 outputs: tail.outputs.toJSON().map(o => o.output_type + ' ' + (o.name || ''))}};
}"""

#: Shut down the kernels of the main area's tabs and close the tabs (without
#: saving); how many tabs are left.
JS_CLOSE_ALL = """async () => {
  const app = window.jupyterapp;
  for (const w of [...app.shell.widgets('main')]) {
    if (w.sessionContext) await w.sessionContext.shutdown();
    w.dispose();
  }
  return [...app.shell.widgets('main')].length;
}"""

#: What the notebook must have shown, by output type (as tests/test_notebooks.py).
VISUAL_MIMETYPES = ("image/png", "image/svg+xml", "application/vnd.jupyter.widget-view+json")


def run_cells(page, last: bool, name: str) -> dict:
    """Run the notebook's cells but the sweep (``last`` False) or the sweep alone;
    wait until the kernel is idle; assert that no cell failed or was left out;
    return :data:`JS_RESULT`'s facts."""
    kernel = page.evaluate(JS_RUN, last)
    assert kernel, f"{name}: the notebook got no kernel"
    page.wait_for_function(JS_DONE, timeout=RUN_TIMEOUT * 1000, polling=500)
    cells = page.evaluate(JS_RESULT, 10**6)["cells"]
    result = page.evaluate(JS_RESULT, cells if last else cells - 1)
    if last and not result["errors"] and "SWEEP " not in result["last"]:
        # the kernel is idle, but its stdout may still be on its way to the
        # page (seen twice in a busy suite: the sweep's line missing at first)
        def arrived():
            r = page.evaluate(JS_RESULT, cells)
            return r if "SWEEP " in r["last"] else None

        t = time.monotonic()
        late = poll(arrived, SWEEP_GRACE)
        result = late or page.evaluate(JS_RESULT, cells)
        if late:  # in the warnings summary: how often, and how late
            warnings.warn(
                f"{name}: the sweep's line reached the page "
                f"{time.monotonic() - t:.1f} s after the kernel went idle",
                stacklevel=1,
            )
        assert late, (
            f"{name}: the sweep's line never reached the page; its cell: {result['tail']}, "
            f"the last cell's stdout: {result['last'][-500:]!r}"
        )
    errors = [re.sub(r"\x1b\[[0-9;]*m", "", e) for e in result["errors"]]  # no ANSI colours
    assert not errors, f"{name}: cells failed:\n" + "\n".join(errors)
    assert result["run"]["ok"], f"{name}: run failed: {result['run']}"
    assert not result["missing"], f"{name}: cells not run: {result['missing']}"
    return result


#: The size of the JupyterLab page, in CSS pixels.
VIEWPORT = {"width": 1400, "height": 1000}


class LabPage:
    """One JupyterLab page in Chromium, in which notebooks are opened in turn.

    The application is loaded once (``/lab?reset``, every tab closed) and
    kept: :meth:`open` opens a notebook in a tab of its own and starts its
    kernel; :meth:`close_notebook` shuts the kernel down and closes the tab,
    so the next notebook starts in a shell with no other notebook (JupyterLab
    shows its launcher when no tab is left).  After a failure, :meth:`discard`
    closes the page and the next :meth:`open` loads the application again.

    Parameters
    ----------
    browser : playwright Browser
    lab : JupyterLab
    """

    def __init__(self, browser, lab: JupyterLab):
        self.browser = browser
        self.lab = lab
        self.page = None
        #: The page's console messages (see :func:`listen`) since the last
        #: :meth:`open`, or since the page was loaded if it loaded for it.
        self.messages: list = []

    def _load(self):
        page = self.browser.new_page(viewport=VIEWPORT)
        page.set_default_timeout(START_TIMEOUT * 1000)  # (playwright's own default: 30 s)
        self.messages = listen(page)
        self.page = page
        page.goto(f"{self.lab.url}/lab?reset")
        page.wait_for_function(JS_APP, timeout=START_TIMEOUT * 1000, polling=250)
        page.evaluate("async () => { await window.jupyterapp.restored; }")
        left = page.evaluate(JS_CLOSE_ALL)  # the launcher
        assert not left, f"JupyterLab: {left} tabs left open at the start"

    def open(self, name: str):
        """Open the notebook ``name`` and wait until it is the current widget,
        its file read; the console messages start afresh (a page loaded for
        this notebook: with the messages of its loading).  Returns the page and
        a locator of the notebook's panel."""
        if self.page is None:
            self._load()
        else:
            self.messages.clear()
        widget = self.page.evaluate(JS_OPEN, name)
        self.page.wait_for_function(JS_READY, arg=name, timeout=START_TIMEOUT * 1000, polling=250)
        return self.page, self.page.locator(f"[id='{widget}']")

    def close_notebook(self):
        """Shut the notebook's kernel down and close its tab; on any trouble
        (a tab left open), :meth:`discard` the page."""
        if self.page is None:
            return
        try:
            left = self.page.evaluate(JS_CLOSE_ALL)
        except Exception:
            left = -1
        if left:
            self.discard()

    def discard(self):
        """Shut the kernels down and close the page (the next notebook loads a new one)."""
        if self.page is None:
            return
        try:
            self.page.evaluate(JS_CLOSE_ALL)
        except Exception:
            pass
        try:
            self.page.close()
        except Exception:
            pass
        self.page = None

    close = discard


def _movable_slider(cell):
    """The first slider of a cell that is not pinned (min < max), or None."""
    handles = cell.locator(".jp-OutputArea-output .widget-slider .noUi-handle")
    for i in range(handles.count()):
        h = handles.nth(i)
        if h.get_attribute("aria-valuemin") != h.get_attribute("aria-valuemax"):
            return h
    return None


class ServerError(AssertionError):
    """The Jupyter server answered a request of the page with an error (HTTP 5xx),
    and the notebook nothing else wrong."""


def server_error_only(bad: list[str]) -> bool:
    """Whether the console errors of :func:`bad_console` are all a server's HTTP 5xx."""
    return bool(bad) and all(
        "HTTP 5" in m or re.search(r"responded with a status of 5\d\d", m) for m in bad
    )


def check_notebook(notebook: Path, lab_page: LabPage, artifacts: Path) -> None:
    """:func:`check_notebook_once`, again in a new page when the only trouble was a
    server error (:class:`ServerError`): the Jupyter server's, not the notebook's
    (a second one fails the test)."""
    try:
        check_notebook_once(notebook, lab_page, artifacts)
    except ServerError as first:
        print(f"\n{notebook.name}: checked again after a server error: {first}")
        check_notebook_once(notebook, lab_page, artifacts)


def check_notebook_once(notebook: Path, lab_page: LabPage, artifacts: Path) -> None:
    """The browser test of one notebook (see ``tests/test_browser_lab_a.py``).

    Opens ``notebook`` in the JupyterLab of ``lab_page`` (a tab of its own in
    an otherwise empty shell), runs its cells but the sweep: none fails,
    something is drawn, no widget fails to display, the first pythreejs
    picture is not blank, and moving a slider changes the picture beside it.
    Then runs the sweep in the same kernel and checks its line
    (:func:`notebook_support.check_sweep`), and the console messages logged
    since the notebook was opened (and while the page loaded, if it loaded for
    this notebook).  Last, shuts its kernel down and closes its
    tab; after a failure, the page is closed (the next notebook loads the
    application again).
    """
    import notebook_support as ns

    stem = notebook.stem
    t0 = time.monotonic()
    passed = False
    try:
        page, panel = lab_page.open(notebook.name)
        result = run_cells(page, last=False, name=notebook.name)
        page.screenshot(path=str(artifacts / f"{stem}-run.png"), full_page=True)
        t_run = time.monotonic() - t0
        drawn = set(result["mimetypes"]).intersection(VISUAL_MIMETYPES)
        assert drawn, f"{notebook.name}: nothing drawn (output types {result['mimetypes']})"
        failed = page.locator("text=Error displaying widget")
        assert not failed.count(), f"{notebook.name}: a widget failed to display"

        # every pythreejs picture shown: the first one is not blank
        pictures = panel.locator(".jupyter-threejs")
        n_pictures = pictures.count()
        if n_pictures:
            renderer = panel.locator(".jupyter-threejs >> visible=true").first
            renderer.wait_for(timeout=DRAW_TIMEOUT * 1000)
            png, last = wait_picture(renderer)
            if last:
                (artifacts / f"{stem}-3d.png").write_bytes(last)
            assert png, f"{notebook.name}: the pythreejs picture stayed blank"

        # move a slider: the picture beside it changes
        moved = False
        cells = panel.locator(".jp-Cell").filter(
            has=page.locator(".jp-OutputArea-output .widget-slider")
        )
        for c in range(cells.count()):
            cell = cells.nth(c)
            handle = _movable_slider(cell)
            target = None
            for selector in (
                ".jupyter-threejs >> visible=true",
                ".widget-output >> visible=true",  # an Output widget (ipywidgets 8)
            ):
                candidate = cell.locator(selector).first
                if candidate.count():
                    target = candidate
                    break
            if handle is None or target is None:
                continue
            target.scroll_into_view_if_needed()
            png, _ = wait_picture(target)
            before = png or target.screenshot()
            after = move_slider(handle, target, before)
            (artifacts / f"{stem}-slider.png").write_bytes(after or target.screenshot())
            assert after, f"{notebook.name}: moving the slider did not change the picture"
            moved = True
            break
        assert moved, f"{notebook.name}: found no slider beside a picture"

        # the sweep, in the same kernel: every control to both ends
        t_sweep = time.monotonic()
        result = run_cells(page, last=True, name=notebook.name)
        sweep = ns.sweep_result(result["last"])
        summary = ns.check_sweep(notebook.name, sweep, result["last"])
        assert n_pictures or not sweep["renderers"], (
            f"{notebook.name}: the kernel made {sweep['renderers']} 3D views, the page shows none"
        )
        bad = bad_console(lab_page.messages)
        if bad:
            raise (ServerError if server_error_only(bad) else AssertionError)(
                f"{notebook.name}: console errors: {bad}" + lab_page.lab.server_errors()
            )
        print(
            f"\n{summary}; ran in {t_run:.1f} s, swept in {time.monotonic() - t_sweep:.1f} s, "
            f"checked in {time.monotonic() - t0:.1f} s"
        )
        passed = True
    finally:
        if passed:
            lab_page.close_notebook()
        else:
            lab_page.discard()
