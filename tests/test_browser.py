"""The notebooks and the exported pages in a real browser, as a reader uses them.

* Every notebook (:data:`notebook_support.NOTEBOOKS`: ``notebooks/`` and the
  widget notebook of ``tests/notebooks/``) is opened in JupyterLab
  (``?reset``) with the face guard added first and the control sweep last
  (see :mod:`notebook_support`).  Its own cells are run: none may fail, no
  widget may fail to display, a pythreejs picture must not be blank, and
  moving a slider must change the picture next to it.  Then the sweep cell
  moves every control to both ends in the same kernel.  This is the
  notebook's one execution of the run (``tests/test_notebooks.py`` skips the
  notebooks executed here).
* A page written by :func:`pentanb.export_html` (offline) opens in Chromium
  with the network switched off, loads nothing but itself, shows the mesh,
  and its slider changes the picture without a kernel.

Needs Debian's ``chromium`` and Python's ``playwright`` (run
``.ci/browser-setup.sh``); without them the tests skip with a message, except
under CI (``CI=true``), where that is a failure.  Screenshots are saved in
``$PENTANB_BROWSER_ARTIFACTS`` (or a pytest temporary folder, printed with
``-s``).  The console must hold no error but the known harmless ones
(:data:`browser_support.HARMLESS_CONSOLE`).
"""

from __future__ import annotations

import re
import sys
import time
import warnings
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import browser_support as bs
import notebook_support as ns

# one JupyterLab and one Chromium: the whole file runs in one pytest-xdist worker
# (``--dist loadfile`` in pyproject.toml)
pytestmark = pytest.mark.browser

ROOT = bs.ROOT
NOTEBOOKS = ns.NOTEBOOKS

# The waits below poll for something the browser or the kernel must do and
# return as soon as it is done: their limits only end a test that hangs, so
# they are far above what a busy machine needs (a test never fails for being slow).
#: Seconds a notebook may take to run its cells, and the sweep.
RUN_TIMEOUT = 900
#: Seconds to wait for a picture to appear or to change.
DRAW_TIMEOUT = 180
#: seconds to wait for the sweep's stdout once the kernel is idle
SWEEP_GRACE = 180
#: Seconds to wait for JupyterLab to start, and for a notebook page to be ready.
START_TIMEOUT = 600


@pytest.fixture(scope="module")
def browser():
    sync_playwright, path = bs.require_browser()
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=path, args=bs.CHROMIUM_FLAGS)
        yield b
        b.close()


@pytest.fixture(scope="module")
def artifacts(tmp_path_factory):
    path = bs.artifact_dir(tmp_path_factory)
    print(f"\nbrowser screenshots: {path}")
    return path


@pytest.fixture(scope="module")
def lab(browser):
    with bs.JupyterLab(
        NOTEBOOKS, transform=ns.instrumented, startup_timeout=START_TIMEOUT
    ) as server:
        yield server


_poll = bs.poll


def _listen(page):
    messages = []
    page.on("console", lambda m: messages.append((m.type, m.text)))
    page.on("pageerror", lambda e: messages.append(("pageerror", str(e))))
    return messages


def _bad_console(messages):
    return [
        f"{kind}: {text[:500]}"
        for kind, text in messages
        if (kind in ("error", "pageerror") and not bs.harmless(text))
        or any(f in text for f in bs.FORBIDDEN_CONSOLE)
    ]


def _wait_picture(locator, timeout=DRAW_TIMEOUT):
    """Screenshot of an element once it is not blank (or the last one)."""
    shots = []

    def check():
        png = locator.screenshot()
        shots.append(png)
        return png if bs.nonblank(png) > 0.01 else None

    return _poll(check, timeout, 0.5), (shots[-1] if shots else None)


def _wait_change(locator, before, timeout=DRAW_TIMEOUT):
    """The element's picture once it differs from ``before`` and has settled."""

    def check():
        png = locator.screenshot()
        return png if bs.changed(before, png) > 0.0005 else None

    changed = _poll(check, timeout, 0.5)
    if changed is None:
        return None
    last = [changed]

    def settled():
        png = locator.screenshot()
        same = bs.changed(last[0], png) == 0.0
        last[0] = png
        return same

    _poll(settled, 10, 0.5)
    return last[0]


def _move_slider(handle, target, before):
    """One step right (left when at the maximum); the target's new picture or None."""
    at_max = handle.get_attribute("aria-valuenow") == handle.get_attribute("aria-valuemax")
    handle.focus()
    handle.press("ArrowLeft" if at_max else "ArrowRight")
    return _wait_change(target, before)


JS_READY = """() => {
  const app = window.jupyterapp;
  const w = app && app.shell.currentWidget;
  return !!(w && w.sessionContext && w.content && w.content.widgets
            && w.content.widgets.length && w.context && w.context.isReady);
}"""

#: Run every cell above the last one (the sweep), or only the last one.
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

JS_SHUTDOWN = """async () => {
  const w = window.jupyterapp.shell.currentWidget;
  if (w && w.sessionContext) await w.sessionContext.shutdown();
}"""

#: What the notebook must have shown, by output type (as tests/test_notebooks.py).
VISUAL_MIMETYPES = ("image/png", "image/svg+xml", "application/vnd.jupyter.widget-view+json")


def _run(page, last: bool, name: str) -> dict:
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
        late = _poll(arrived, SWEEP_GRACE)
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


def _movable_slider(cell):
    """The first slider of a cell that is not pinned (min < max), or None."""
    handles = cell.locator(".jp-OutputArea-output .widget-slider .noUi-handle")
    for i in range(handles.count()):
        h = handles.nth(i)
        if h.get_attribute("aria-valuemin") != h.get_attribute("aria-valuemax"):
            return h
    return None


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_runs_and_draws_in_jupyterlab(notebook, browser, lab, artifacts):
    stem = notebook.stem
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.set_default_timeout(START_TIMEOUT * 1000)  # (playwright's own default: 30 s)
    messages = _listen(page)
    t0 = time.monotonic()
    try:
        page.goto(f"{lab.url}/lab/tree/{notebook.name}?reset")
        page.wait_for_function(JS_READY, timeout=START_TIMEOUT * 1000)
        result = _run(page, last=False, name=notebook.name)
        page.screenshot(path=str(artifacts / f"{stem}-run.png"), full_page=True)
        t_run = time.monotonic() - t0
        drawn = set(result["mimetypes"]).intersection(VISUAL_MIMETYPES)
        assert drawn, f"{notebook.name}: nothing drawn (output types {result['mimetypes']})"
        failed = page.locator("text=Error displaying widget")
        assert not failed.count(), f"{notebook.name}: a widget failed to display"

        # every pythreejs picture shown: the first one is not blank
        pictures = page.locator(".jupyter-threejs")
        n_pictures = pictures.count()
        if n_pictures:
            renderer = page.locator(".jupyter-threejs >> visible=true").first
            renderer.wait_for(timeout=DRAW_TIMEOUT * 1000)
            png, last = _wait_picture(renderer)
            if last:
                (artifacts / f"{stem}-3d.png").write_bytes(last)
            assert png, f"{notebook.name}: the pythreejs picture stayed blank"

        # move a slider: the picture beside it changes
        moved = False
        cells = page.locator(".jp-Cell").filter(
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
            png, _ = _wait_picture(target)
            before = png or target.screenshot()
            after = _move_slider(handle, target, before)
            (artifacts / f"{stem}-slider.png").write_bytes(target.screenshot())
            assert after, f"{notebook.name}: moving the slider did not change the picture"
            moved = True
            break
        assert moved, f"{notebook.name}: found no slider beside a picture"

        # the sweep, in the same kernel: every control to both ends
        t_sweep = time.monotonic()
        result = _run(page, last=True, name=notebook.name)
        sweep = ns.sweep_result(result["last"])
        summary = ns.check_sweep(notebook.name, sweep, result["last"])
        assert n_pictures or not sweep["renderers"], (
            f"{notebook.name}: the kernel made {sweep['renderers']} 3D views, the page shows none"
        )
        bad = _bad_console(messages)
        assert not bad, f"{notebook.name}: console errors: {bad}"
        print(
            f"\n{summary}; ran in {t_run:.1f} s, swept in {time.monotonic() - t_sweep:.1f} s, "
            f"checked in {time.monotonic() - t0:.1f} s"
        )
    finally:
        try:
            page.evaluate(JS_SHUTDOWN)
        except Exception:
            pass
        page.close()


# -- exported pages -------------------------------------------------------------


def _offline_page(kind):
    import pentanb
    from pentanb.viz import html

    try:
        html.offline_scripts()
    except FileNotFoundError as err:
        bs.skip_or_fail(str(err))
    if kind == "explorer":
        return pentanb.explore("cube", iterations=2)
    return pentanb.step_through(pentanb.shapes.tetrahedron())


@pytest.mark.parametrize("kind", ["explorer", "step_through"])
def test_offline_html_works_without_network_or_kernel(kind, browser, artifacts, tmp_path):
    from pentanb.viz.html import export_html

    widget = _offline_page(kind)
    # an explorer's page: every control, within a smaller budget than the
    # default (a quicker test); the logic is tested in tests/test_explorer.py
    budget = {"max_bytes": 8_000_000} if kind == "explorer" else {}
    path = export_html(widget, tmp_path / f"{kind}.html", offline=True, **budget)
    context = browser.new_context(offline=True, viewport={"width": 1000, "height": 1000})
    context.set_default_timeout(START_TIMEOUT * 1000)  # (playwright's own default: 30 s)
    page = context.new_page()
    requests = []
    page.on("request", lambda r: requests.append(r.url))
    messages = _listen(page)
    try:
        page.goto(path.as_uri())
        renderer = page.locator(".jupyter-threejs >> visible=true").first
        renderer.wait_for(timeout=DRAW_TIMEOUT * 1000)
        before, _last = _wait_picture(renderer)
        page.screenshot(path=str(artifacts / f"offline-{kind}-0.png"))
        assert before, f"offline {kind}: the picture stayed blank"
        after = _move_slider(
            page.locator(".widget-slider .noUi-handle").first,
            page.locator(".jupyter-threejs >> visible=true").first,
            before,
        )
        page.screenshot(path=str(artifacts / f"offline-{kind}-1.png"))
        assert after, f"offline {kind}: the slider did not change the picture"
        assert bs.nonblank(after) > 0.01, f"offline {kind}: blank after the slider moved"
        # orbit (drag on the picture), then go back a step: the views share
        # one camera, so the other level shows the mesh from the new side
        visible = page.locator(".jupyter-threejs >> visible=true").first
        box = visible.bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        for k in range(1, 11):
            page.mouse.move(x + 12 * k, y + 4 * k)
        page.mouse.up()
        turned = _wait_change(visible, after)
        assert turned, f"offline {kind}: dragging did not turn the mesh"
        handle = page.locator(".widget-slider .noUi-handle").first
        handle.focus()
        handle.press("ArrowLeft")
        back = _wait_change(page.locator(".jupyter-threejs >> visible=true").first, turned)
        page.screenshot(path=str(artifacts / f"offline-{kind}-2.png"))
        assert back and bs.nonblank(back) > 0.01, f"offline {kind}: blank after orbit + slider"
        assert bs.changed(before, back) > 0.0005, (
            f"offline {kind}: the turned camera was not kept for the other step"
        )
        if kind == "explorer":
            # the shape drop-down chooses another shape without a kernel, and
            # the values the budget left out are named on the page
            assert page.locator(".pentanb-left-out").is_visible()
            shape = page.locator(".widget-dropdown select").first
            shape.select_option(index=0)  # the tetrahedron (the cube is shown)
            other = _wait_change(page.locator(".jupyter-threejs >> visible=true").first, back)
            page.screenshot(path=str(artifacts / f"offline-{kind}-3.png"))
            assert other and bs.nonblank(other) > 0.01, "offline explorer: the shape did not change"
        network = [u for u in requests if not u.startswith(("file:", "data:", "blob:"))]
        assert not network, f"offline {kind}: the page asked the network for {network}"
        bad = _bad_console(messages)
        assert not bad, f"offline {kind}: console errors: {bad}"
    finally:
        context.close()
