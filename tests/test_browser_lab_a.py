"""Share a of the notebooks in a real JupyterLab, as a reader runs them.

The notebooks (:data:`notebook_support.NOTEBOOKS`: ``notebooks/`` and the
widget notebook of ``tests/notebooks/``) are split between this file and
``tests/test_browser_lab_b.py`` by :func:`notebook_support.browser_share`
(about equal measured times): each file has its own JupyterLab and Chromium,
so the two run side by side in two pytest-xdist workers.

The file's notebooks are opened in turn in one JupyterLab page (the
application loaded once, ``?reset``; see :class:`browser_support.LabPage`),
each with the face guard added first and the control sweep last (see
:mod:`notebook_support`), in a tab of its own; after its checks its kernel is
shut down and its tab closed (after a failure the page is loaded again).  Its
own cells are run: none may fail, no widget may fail to display, a pythreejs
picture must not be blank, and moving a slider must change the picture next
to it.  Then the sweep cell moves every control to both ends in the same
kernel.  This is the notebook's one execution of the run
(``tests/test_notebooks.py`` skips the notebooks executed here).  The
console messages logged since the notebook was opened must hold no error but
the known harmless ones (:data:`browser_support.HARMLESS_CONSOLE`); see
:func:`browser_support.check_notebook`.

Needs Debian's ``chromium`` and Python's ``playwright`` (run
``.ci/browser-setup.sh``); without them the tests skip with a message, except
under CI (``CI=true``), where that is a failure.  Screenshots are saved in
``$PENTANB_BROWSER_ARTIFACTS`` (or a temporary folder, printed with ``-s``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import browser_support as bs
import notebook_support as ns

# one JupyterLab and one Chromium: the whole file runs in one pytest-xdist worker
# (``--dist loadfile`` in pyproject.toml)
pytestmark = pytest.mark.browser

NOTEBOOKS = ns.browser_share(0)

browser, lab, lab_page, artifacts = bs.module_fixtures(NOTEBOOKS)


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_runs_and_draws_in_jupyterlab(notebook, lab_page, artifacts):
    bs.check_notebook(notebook, lab_page, artifacts)
