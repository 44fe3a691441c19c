"""The documentation site, built and then read as a reader would read it (issue 25).

Once per test run, the README's third command (``python -m pentanb docs``, which
runs ``sphinx-build -W``: a warning fails the build) builds the site into a
temporary folder, executing every notebook.  Then headless Chromium (Debian's, as
in ``tests/test_browser.py``), with every request that is not for a ``file://``
URL blocked and recorded, opens every page of it and checks:

* no request left the files of the site (network off, and none attempted);
* no console error and no uncaught exception (beyond the known harmless
  messages of :data:`browser_support.HARMLESS_CONSOLE`);
* every link inside the site leads to a file that exists, and its ``#anchor``
  to an element of that page; every image loads;
* every widget of an executed notebook is drawn, and every 3D view (one per
  pythreejs renderer in the saved widget state) shows a picture, not a blank
  canvas;
* every public name (``pentanb.__all__`` and the ``__all__`` of the public
  modules, as ``tests/test_api_docs.py`` lists them, and of the drawing modules)
  has its entry on its module's API page;
* the search page finds ``pentanb.pentagonalize``;
* the landing page shows the paper's figure and the README's commands, and the
  gallery every image of ``figures/`` with its claims and verdicts.

The whole file runs in one pytest-xdist worker (``--dist loadfile``), so the
build happens once.  Screenshots of the notebook pages go to
``$PENTANB_BROWSER_ARTIFACTS`` or a ``/tmp/pentanb-browser-*`` folder.  The build's
time is printed (``-s``) and written beside them (``docs-build.log``).
"""

from __future__ import annotations

import asyncio
import importlib
import importlib.util
import os
import pkgutil
import subprocess
import sys
import time
import types
from pathlib import Path
from urllib.parse import unquote, urlsplit

import browser_support as bs
import pytest

ROOT = Path(__file__).resolve().parent.parent

pytestmark = [pytest.mark.slow, pytest.mark.browser]

#: What the build needs besides the package (the docs extra, in the test extra too).
BUILD_MODULES = ("sphinx", "myst_nb", "numpydoc", "pydata_sphinx_theme", "jupyter_cache")
#: Seconds the build may take: a hang guard, not a speed limit.
BUILD_TIMEOUT = 1800
#: Seconds a page's widgets may take to draw.
DRAW_TIMEOUT = 90


def public_modules() -> list[str]:
    """The modules whose ``__all__`` is public API: pentanb, the modules
    ``tests/test_api_docs.py`` walks, and every module of ``pentanb.viz`` that has
    an ``__all__``."""
    from test_api_docs import MODULES

    import pentanb.viz

    viz = [
        f"pentanb.viz.{m.name}"
        for m in pkgutil.iter_modules(pentanb.viz.__path__)
        if not m.name.startswith("_")
    ]
    viz = [m for m in viz if hasattr(importlib.import_module(m), "__all__")]
    return ["pentanb", *MODULES, *sorted(viz)]


@pytest.fixture(scope="module")
def artifacts(tmp_path_factory):
    path = bs.artifact_dir(tmp_path_factory)
    print(f"\ndocs screenshots: {path}")
    return path


@pytest.fixture(scope="module")
def site(tmp_path_factory, artifacts) -> Path:
    """The built site's output folder (``.../html``): built once, in a temporary folder."""
    missing = [m for m in BUILD_MODULES if importlib.util.find_spec(m) is None]
    if missing:
        bs.skip_or_fail(
            f"{', '.join(missing)} not installed (pip install -e '.[docs]'); "
            "the documentation site cannot be built"
        )
    from pentanb.viz.html import js_dir, offline_scripts

    try:
        offline_scripts()
    except FileNotFoundError as exc:
        bs.skip_or_fail(f"the site's widget scripts are missing: {exc}")
    if not (js_dir() / "node_modules" / "mathjax" / "es5" / "tex-svg.js").is_file():
        bs.skip_or_fail(f"MathJax is missing from {js_dir()} (bash .ci/browser-setup.sh)")
    out = tmp_path_factory.mktemp("docs-site") / "html"
    log = artifacts / "docs-build.log"
    t0 = time.perf_counter()
    with open(log, "w") as f:
        proc = subprocess.run(
            [sys.executable, "-m", "pentanb", "docs", "--out", str(out)],
            cwd=ROOT,
            stdout=f,
            stderr=subprocess.STDOUT,
            timeout=BUILD_TIMEOUT,
        )
    seconds = time.perf_counter() - t0
    with open(log, "a") as f:
        f.write(f"\npentanb docs: exit {proc.returncode} after {seconds:.1f} s\n")
    print(f"\nthe documentation site built in {seconds:.1f} s (log: {log})")
    text = log.read_text(errors="replace")
    assert proc.returncode == 0, f"python -m pentanb docs failed:\n{text[-6000:]}"
    return out


# -- one pass of Chromium over every page ---------------------------------------------

_PAGE_FACTS = """() => {
  const state = document.querySelector('script[type="application/vnd.jupyter.widget-state+json"]');
  const models = state ? Object.values(JSON.parse(state.textContent).state) : [];
  return {
    ids: Array.from(document.querySelectorAll('[id]'), e => e.id),
    text: document.body.innerText,
    links: Array.from(document.querySelectorAll('a[href]'), a => a.href),
    brokenImages: Array.from(document.images)
      .filter(i => !i.complete || i.naturalWidth === 0).map(i => i.src),
    views: document.querySelectorAll(
      'script[type="application/vnd.jupyter.widget-view+json"]').length,
    renderers: models.filter(m => m.model_name === 'RendererModel').length,
  };
}"""

_DRAWN = """() => ({
  canvases: document.querySelectorAll('.jupyter-threejs canvas').length,
  drawn: document.querySelectorAll('.widget-subarea').length,
})"""


_poll = bs.poll


def _html_pages(out: Path) -> list[Path]:
    return sorted(
        p
        for p in out.rglob("*.html")
        if not p.relative_to(out).parts[0].startswith(("_static", "_images", "_sources"))
    )


#: Pages read at once (tabs of one Chromium): page loads wait on files and scripts.
TABS = 4


@pytest.fixture(scope="module")
def reading(site, artifacts) -> dict:
    """Every page opened in Chromium, network off: ``{"pages": {relative path: facts},
    "network": [url, ...]}``.  A notebook page's facts include each 3D view's inked
    fraction (``inked``) once its widgets are drawn."""
    bs.require_browser()  # skips (fails under CI) without Chromium or playwright
    return asyncio.run(_read_site(site, artifacts, bs.chromium_path()))


async def _read_site(site: Path, artifacts: Path, chromium: str) -> dict:
    from playwright.async_api import async_playwright

    pages: dict[str, dict] = {}
    network: list[str] = []

    async def route(r):
        url = r.request.url
        if url.startswith(("file:", "data:", "blob:")):
            await r.continue_()
        else:
            network.append(url)
            await r.abort()

    async with async_playwright() as p:
        browser = await p.chromium.launch(executable_path=chromium, args=bs.CHROMIUM_FLAGS)
        try:
            context = await browser.new_context(
                offline=True, viewport={"width": 1280, "height": 900}
            )
            context.set_default_timeout(DRAW_TIMEOUT * 1000)
            await context.route("**/*", route)
            context.on(
                "request",
                lambda r: (
                    None if r.url.startswith(("file:", "data:", "blob:")) else network.append(r.url)
                ),
            )
            top = await context.new_page()  # index.html: a redirect to the landing page
            await top.goto((site / "index.html").as_uri())
            await top.wait_for_url("**/docs/index.html", timeout=30_000)
            await top.close()
            queue = [p for p in _html_pages(site) if p != site / "index.html"]

            async def tab():
                page = await context.new_page()
                messages: list[tuple[str, str]] = []
                page.on("console", lambda m: messages.append((m.type, m.text)))
                page.on("pageerror", lambda e: messages.append(("pageerror", str(e))))
                while queue:
                    path = queue.pop(0)
                    rel = path.relative_to(site).as_posix()
                    t0 = time.perf_counter()
                    messages.clear()
                    await page.goto(path.as_uri(), wait_until="load")
                    facts = await page.evaluate(_PAGE_FACTS)
                    facts["inked"] = []
                    if facts["views"]:
                        facts.update(await _read_widgets(page, facts, rel, artifacts))
                        facts["brokenImages"] = (await page.evaluate(_PAGE_FACTS))["brokenImages"]
                    facts["console"] = [
                        f"{kind}: {text[:400]}"
                        for kind, text in messages
                        if (kind in ("error", "pageerror") and not bs.harmless(text))
                        or any(f in text for f in bs.FORBIDDEN_CONSOLE)
                    ]
                    facts["seconds"] = time.perf_counter() - t0
                    pages[rel] = facts
                await page.close()

            t0 = time.perf_counter()
            await asyncio.gather(*(tab() for _ in range(TABS)))
            seconds = time.perf_counter() - t0
            await context.close()
        finally:
            await browser.close()
    slowest = sorted(pages, key=lambda r: -pages[r]["seconds"])[:3]
    print(
        f"\n{len(pages)} pages read in {seconds:.1f} s, {TABS} at a time; slowest: "
        + ", ".join(f"{r} {pages[r]['seconds']:.1f} s" for r in slowest)
    )
    return {"pages": pages, "network": network}


async def _apoll(fn, timeout, interval=0.25):
    """``await fn()`` until it returns something truthy, or None after timeout seconds."""
    deadline = time.monotonic() + timeout
    while True:
        value = await fn()
        if value:
            return value
        if time.monotonic() > deadline:
            return None
        await asyncio.sleep(interval)


async def _read_widgets(page, facts: dict, rel: str, artifacts: Path) -> dict:
    """Wait until every widget view is drawn and every renderer has its canvas; then
    screenshot each canvas (scrolled into view) and measure its ink."""

    async def drawn():
        d = await page.evaluate(_DRAWN)
        return d if d["drawn"] >= facts["views"] and d["canvases"] >= facts["renderers"] else None

    done = await _apoll(drawn, DRAW_TIMEOUT, 0.25)
    result = await page.evaluate(_DRAWN)
    inked = []
    canvases = page.locator(".jupyter-threejs canvas")
    for i in range(await canvases.count()):
        canvas = canvases.nth(i)
        await canvas.scroll_into_view_if_needed()
        shots = []

        async def picture(canvas=canvas, shots=shots):
            png = await canvas.screenshot()
            shots.append(png)
            return bs.nonblank(png) > 0.01

        await _apoll(picture, 30, 0.25)
        inked.append(bs.nonblank(shots[-1]))
        if i == 0:
            name = rel.replace("/", "_").removesuffix(".html")
            (artifacts / f"docs-{name}.png").write_bytes(shots[-1])
    return {
        "drawn": result["drawn"],
        "canvases": result["canvases"],
        "inked": inked,
        "timedOut": done is None,
    }


# -- the tests ------------------------------------------------------------------------


def test_site_builds_with_warnings_as_errors(site):
    landing = site / "docs" / "index.html"
    assert landing.is_file(), "no docs/index.html: the landing page is missing"
    assert "docs/index.html" in (site / "index.html").read_text(), (
        "the top index.html does not send a reader to the landing page"
    )
    for nb in sorted((ROOT / "notebooks").glob("*.ipynb")):
        assert (site / "notebooks" / f"{nb.stem}.html").is_file(), f"{nb.name} has no page"
    static = site / "_static"
    for script in (
        "pentanb-widgets/embed-amd.js",
        "pentanb-widgets/jupyter-threejs.js",
        "pentanb-mathjax/tex-svg.js",
    ):
        assert (static / script).is_file(), f"the site does not ship {script}"


def test_no_page_asks_the_network(reading):
    assert not reading["network"], f"pages asked the network for {sorted(set(reading['network']))}"


def test_no_console_error_on_any_page(reading):
    bad = {rel: f["console"] for rel, f in reading["pages"].items() if f["console"]}
    assert not bad, f"console errors: {bad}"


def test_every_internal_link_and_image_resolves(site, reading):
    pages = reading["pages"]
    broken = []
    for rel, facts in pages.items():
        for href in facts["links"]:
            url = urlsplit(href)
            if url.scheme != "file":
                continue  # an outside link: not followed (the network is off)
            target = Path(unquote(url.path))
            if not target.exists():
                broken.append(f"{rel} -> {href} (no such file)")
                continue
            if url.fragment and target.suffix == ".html":
                key = target.relative_to(site).as_posix()
                if key in pages and unquote(url.fragment) not in pages[key]["ids"]:
                    broken.append(f"{rel} -> {href} (no #{url.fragment} there)")
        broken += [f"{rel}: image {src} does not load" for src in facts["brokenImages"]]
    assert not broken, "broken links or images:\n" + "\n".join(broken[:50])


def test_every_notebook_is_drawn_with_its_3d_views_inked(reading):
    notebooks = {r: f for r, f in reading["pages"].items() if r.startswith("notebooks/")}
    assert len(notebooks) >= len(list((ROOT / "notebooks").glob("*.ipynb")))
    problems = []
    for rel, f in notebooks.items():
        if not f["views"]:
            continue
        if f["drawn"] < f["views"]:
            problems.append(f"{rel}: {f['drawn']} of {f['views']} widgets drawn")
        if f["canvases"] < f["renderers"]:
            problems.append(f"{rel}: {f['canvases']} canvases for {f['renderers']} 3D views")
        for i, ink in enumerate(f["inked"]):
            if ink <= 0.01:
                problems.append(f"{rel}: 3D view {i} is blank ({ink:.4f} of its pixels inked)")
    views = sum(f["renderers"] for f in notebooks.values())
    assert views >= 5, f"only {views} 3D views in the executed notebooks: widget state lost?"
    assert not problems, "\n".join(problems)


def test_every_public_name_has_its_api_entry(reading):
    pages = reading["pages"]
    all_ids = {i for f in pages.values() for i in f["ids"]}
    missing = []
    modules = public_modules()
    for name in modules:
        page = f"docs/api/{name}.html"
        if page not in pages:
            missing.append(f"{name}: no page {page} (add docs/api/{name}.rst)")
            continue
        ids = set(pages[page]["ids"])
        module = importlib.import_module(name)
        for attr in module.__all__:
            obj = getattr(module, attr)
            if isinstance(obj, types.ModuleType):
                if f"module-{obj.__name__}" not in all_ids:
                    missing.append(f"{name}.{attr}: module {obj.__name__} has no page")
            elif f"{name}.{attr}" not in ids:
                missing.append(f"{name}.{attr}: no entry on {page}")
    index = set(pages["docs/api/index.html"]["links"])
    for name in modules:
        if not any(link.split("#")[0].endswith(f"/docs/api/{name}.html") for link in index):
            missing.append(f"the API index does not link {name}")
    assert not missing, "\n".join(missing)


def test_search_finds_pentagonalize(site):
    sync_playwright, chromium = bs.require_browser()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=bs.CHROMIUM_FLAGS)
        try:
            page = browser.new_page()
            page.goto((site / "search.html").as_uri() + "?q=pentagonalize")
            hits = _poll(
                lambda: page.evaluate(
                    "Array.from(document.querySelectorAll('#search-results li a'), a => a.href)"
                ),
                60,
                0.5,
            )
        finally:
            browser.close()
    assert hits, "the search page found nothing for 'pentagonalize'"
    assert any(h.endswith("#pentanb.pentagonalize") for h in hits), (
        f"no hit leads to pentanb.pentagonalize's API entry: {hits[:10]}"
    )


def test_landing_page_shows_the_paper_a_figure_and_the_commands(site, reading):
    facts = reading["pages"]["docs/index.html"]
    assert "Semiregular pentagonal subdivisions" in facts["text"]
    html = (site / "docs" / "index.html").read_text()
    assert "fig07" in html and not facts["brokenImages"]
    readme = (ROOT / "README.md").read_text()
    venv = "python3 -m venv .venv && .venv/bin/"
    for command in (
        venv + "pip install -e . && .venv/bin/python -m pentanb figures",
        venv + 'pip install -e ".[test]" && .venv/bin/python -m pytest',
    ):
        assert command in readme, f"the README lost its command {command!r}"
        assert command in facts["text"], f"the landing page does not show {command!r}"
    assert "python -m pentanb docs" in readme, "the README does not name the docs command"


def test_gallery_shows_every_figure_with_its_claims(site, reading):
    from pentanb import figures

    facts = reading["pages"]["docs/gallery.html"]
    ids = set(facts["ids"])
    html = (site / "docs" / "gallery.html").read_text()
    for name, spec in figures.FIGURES.items():
        anchor = "gallery-" + name.replace("_", "-")  # as Sphinx makes a label's id
        assert anchor in ids, f"the gallery has no section for {name}"
        assert spec.filename in html, f"the gallery does not show {spec.filename}"
    assert "gallery-schemes" in ids
    assert not facts["brokenImages"], facts["brokenImages"]
    verdicts = html.count('class="pentanb-verdict')
    assert verdicts >= 2 * len(figures.FIGURES), f"only {verdicts} verdicts shown"
    for verdict in figures.VERDICTS:
        assert verdict in html
    assert any(link.split("#")[0].endswith("/docs/claims.html") for link in facts["links"])
    assert any(link.split("#")[0].endswith("/docs/continuity.html") for link in facts["links"])


if os.environ.get("PENTANB_DOCS_SITE"):  # pragma: no cover - a maintainer's shortcut
    # read an already built site instead of building one: PENTANB_DOCS_SITE=docs/_build/html
    @pytest.fixture(scope="module")
    def site():
        return Path(os.environ["PENTANB_DOCS_SITE"]).resolve()
