"""Share b of the notebooks in a real JupyterLab: as ``tests/test_browser_lab_a.py``
(which says what is checked), for the other notebooks.

The notebooks are split between the two files by
:func:`notebook_support.browser_share` (about equal measured times): each file
has its own JupyterLab and Chromium, so the two run side by side in two
pytest-xdist workers.
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

NOTEBOOKS = ns.browser_share(1)

browser, lab, lab_page, artifacts = bs.module_fixtures(NOTEBOOKS)


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_runs_and_draws_in_jupyterlab(notebook, lab_page, artifacts):
    bs.check_notebook(notebook, lab_page, artifacts)
