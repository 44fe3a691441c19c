"""Exported pages in a real browser, as a reader opens them; the notebooks' shares.

* A page written by :func:`pentanb.export_html` (offline) opens in Chromium
  with the network switched off, loads nothing but itself, shows the mesh,
  and its slider changes the picture without a kernel.
* The notebooks run in JupyterLab in ``tests/test_browser_lab_a.py`` and
  ``tests/test_browser_lab_b.py`` (two files: two JupyterLabs side by side);
  here, that the two shares hold every notebook once.

Needs Debian's ``chromium`` and Python's ``playwright`` (run
``.ci/browser-setup.sh``); without them the tests skip with a message, except
under CI (``CI=true``), where that is a failure.  Screenshots are saved in
``$PENTANB_BROWSER_ARTIFACTS`` (or a pytest temporary folder, printed with
``-s``).  The console must hold no error but the known harmless ones
(:data:`browser_support.HARMLESS_CONSOLE`).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import browser_support as bs
import notebook_support as ns

# one Chromium: the whole file runs in one pytest-xdist worker
# (``--dist loadfile`` in pyproject.toml)
pytestmark = pytest.mark.browser

browser, _lab, _lab_page, artifacts = bs.module_fixtures()


def test_the_shares_hold_every_notebook_once():
    shares = [ns.browser_share(k) for k in range(len(ns.BROWSER_FILES))]
    dealt = sorted(p for share in shares for p in share)
    assert dealt == sorted(ns.NOTEBOOKS), "a notebook is in no share, or in two"
    assert all(shares), f"an empty share: {shares}"
    seconds = [sum(ns.BROWSER_SECONDS.get(p.name, 0) for p in share) for share in shares]
    # dealt longest first to the lighter share: no share exceeds another by more
    # than its longest notebook
    longest = max(ns.BROWSER_SECONDS.values())
    assert max(seconds) - min(seconds) <= longest, seconds
    for k, name in enumerate(ns.BROWSER_FILES):
        assert (Path(__file__).parent / name).is_file(), f"no {name} for share {k}"
        assert f"ns.browser_share({k})" in (Path(__file__).parent / name).read_text()


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
    context.set_default_timeout(bs.START_TIMEOUT * 1000)  # (playwright's own default: 30 s)
    page = context.new_page()
    requests = []
    page.on("request", lambda r: requests.append(r.url))
    messages = bs.listen(page)
    try:
        page.goto(path.as_uri())
        renderer = page.locator(".jupyter-threejs >> visible=true").first
        renderer.wait_for(timeout=bs.DRAW_TIMEOUT * 1000)
        before, _last = bs.wait_picture(renderer)
        page.screenshot(path=str(artifacts / f"offline-{kind}-0.png"))
        assert before, f"offline {kind}: the picture stayed blank"
        after = bs.move_slider(
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
        turned = bs.wait_change(visible, after)
        assert turned, f"offline {kind}: dragging did not turn the mesh"
        handle = page.locator(".widget-slider .noUi-handle").first
        handle.focus()
        handle.press("ArrowLeft")
        back = bs.wait_change(page.locator(".jupyter-threejs >> visible=true").first, turned)
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
            other = bs.wait_change(page.locator(".jupyter-threejs >> visible=true").first, back)
            page.screenshot(path=str(artifacts / f"offline-{kind}-3.png"))
            assert other and bs.nonblank(other) > 0.01, "offline explorer: the shape did not change"
        network = [u for u in requests if not u.startswith(("file:", "data:", "blob:"))]
        assert not network, f"offline {kind}: the page asked the network for {network}"
        bad = bs.bad_console(messages)
        assert not bad, f"offline {kind}: console errors: {bad}"
    finally:
        context.close()


def test_only_a_server_error_is_told_apart():
    failed = "error: Failed to load resource: the server responded with a status of 500 (x)"
    where = "error: HTTP 500: GET http://127.0.0.1:1/lab/api/workspaces/default"
    assert bs.server_error_only([failed, where])
    assert not bs.server_error_only([failed, "pageerror: TypeError: t is undefined"])
    assert not bs.server_error_only(["error: the server responded with a status of 403"])
    assert not bs.server_error_only([])


def test_a_notebook_is_checked_again_once_after_a_server_error(monkeypatch):
    a, b, c = (Path(n) for n in ("a.ipynb", "b.ipynb", "c.ipynb"))
    calls = []

    def once(notebook, lab_page, artifacts, fail_times):
        calls.append(notebook)
        if len(calls) <= fail_times:
            raise bs.ServerError(f"{notebook}: console errors: HTTP 500")

    monkeypatch.setattr(bs, "check_notebook_once", lambda *a: once(*a, fail_times=1))
    bs.check_notebook(a, None, None)
    assert calls == [a, a]
    calls.clear()
    monkeypatch.setattr(bs, "check_notebook_once", lambda *a: once(*a, fail_times=2))
    with pytest.raises(bs.ServerError):
        bs.check_notebook(b, None, None)
    assert calls == [b, b]
    calls.clear()

    def broken(*a):
        calls.append(a[0])
        raise AssertionError("a widget failed to display")

    monkeypatch.setattr(bs, "check_notebook_once", broken)
    with pytest.raises(AssertionError, match="widget"):
        bs.check_notebook(c, None, None)
    assert calls == [c]
