"""The corpus of test meshes: every shape of :data:`pentanb.shapes.SHAPES` plus
a few mixed-face meshes (see :mod:`helpers`), and the operators under test."""

from __future__ import annotations

import os
import sys

import pytest
from hypothesis import settings

sys.path.insert(0, os.path.dirname(__file__))

# The suite checks the numpy path, pentanb's reference, everywhere (notebook
# kernels inherit this); tests/test_jit.py switches the optional compiled
# kernels on and compares them with it.  PENTANB_JIT=1 runs everything compiled.
os.environ.setdefault("PENTANB_JIT", "0")

# Under CI the property tests draw the same examples on every run (a failure
# there is reproducible, never luck); elsewhere they explore new ones.
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

from helpers import CORPUS_NAMES, OPERATORS, SMALL_NAMES, corpus  # noqa: E402


@pytest.fixture(params=CORPUS_NAMES)
def corpus_name(request) -> str:
    """The name of a corpus mesh (every shape and every mixed mesh)."""
    return request.param


@pytest.fixture
def corpus_mesh(corpus_name):
    """A corpus mesh (built once per session: meshes are immutable)."""
    return corpus(corpus_name)


@pytest.fixture(params=SMALL_NAMES)
def small_mesh(request):
    """A small corpus mesh, for the pure-Python isomorphism checks."""
    return corpus(request.param)


@pytest.fixture(params=list(OPERATORS))
def operator_name(request) -> str:
    """Every registered scheme and ``dual``."""
    return request.param


# ------------------------------------------------------------------ pytest-xdist
#: Files run whole in one worker: the browser tests share one JupyterLab and one
#: Chromium; these others build expensive module or session fixtures once.
WHOLE_FILES = ("test_browser.py", "test_figures.py", "test_claims.py", "test_cli.py")

try:
    from xdist.scheduler import LoadScopeScheduling
except ImportError:  # pragma: no cover - xdist is in the test extra
    LoadScopeScheduling = None

if LoadScopeScheduling is not None:

    class _Scheduling(LoadScopeScheduling):
        """Load balancing test by test, except :data:`WHOLE_FILES` (a file each).

        The browser file is collected first, so one worker starts it at once
        while the other works through the rest, test by test.  (xdist's
        ``loadgroup`` would do this with a mark, but its grouping is lost
        under pytest 9.)
        """

        def _split_scope(self, nodeid: str) -> str:
            path = nodeid.split("::", 1)[0]
            return path if path.endswith(WHOLE_FILES) else nodeid

    def pytest_xdist_make_scheduler(config, log):
        return _Scheduling(config, log)
