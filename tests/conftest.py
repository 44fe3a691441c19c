"""The corpus of test meshes: every shape of :data:`pentanb.shapes.SHAPES` plus
a few mixed-face meshes (see :mod:`helpers`), and the operators under test."""

from __future__ import annotations

import os
import sys
from collections import Counter

import pytest
from hypothesis import HealthCheck, settings

sys.path.insert(0, os.path.dirname(__file__))

# The suite runs the path users get by default: the compiled kernels when
# numba is installed (it is in the test extra), else the numpy path.
# tests/test_jit.py switches between the two explicitly and compares them;
# PENTANB_JIT=0 runs everything else on the numpy path.

# No property test depends on the machine's speed: hypothesis's deadline (200
# ms an example) and its too_slow health check are timings, so both are off.
# Under CI the property tests draw the same examples on every run (a failure
# there is reproducible, never luck); elsewhere they explore new ones.
_UNTIMED = {"deadline": None, "suppress_health_check": [HealthCheck.too_slow]}
settings.register_profile("untimed", **_UNTIMED)
settings.register_profile("ci", derandomize=True, print_blob=True, **_UNTIMED)
settings.load_profile("ci" if os.environ.get("CI") else "untimed")

from helpers import CORPUS_NAMES, OPERATORS, SMALL_NAMES, corpus  # noqa: E402

#: The corpus meshes the fast selection (``-m "not slow"``) runs the corpus-wide
#: tests on: genus 0 to 2, every face size from 3 to 6, valences 3 to 6, mixed
#: faces.  The others, each like one of these, are marked slow: the full suite
#: runs every test on every corpus mesh.
FAST_CORPUS = (
    "tetrahedron",
    "cube",
    "icosahedron",
    "dodecahedron",
    "hexagonal_torus",
    "small_torus",
    "double_torus",
    "cube_split",
    "pentagonal_pyramid",
    "merged_icosahedron",
)


@pytest.fixture(
    params=[
        name if name in FAST_CORPUS else pytest.param(name, marks=pytest.mark.slow)
        for name in CORPUS_NAMES
    ]
)
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


def pytest_xdist_auto_num_workers(config) -> int:
    """``-n auto``: one worker per core, plus one.

    The browser tests (one file, one worker) spend most of their time waiting
    for JupyterLab's kernel and Chromium to draw, which run in processes of
    their own; one more worker keeps the cores busy meanwhile.  Set
    ``PYTEST_XDIST_AUTO_NUM_WORKERS`` to choose another number.
    """
    env = os.environ.get("PYTEST_XDIST_AUTO_NUM_WORKERS")
    if env:
        return int(env)
    return (
        len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    ) + 1


#: Seconds the kernels' warm-up may take: a hang guard, not a speed limit (a minute
#: on a fresh clone of a busy 2-core machine).
WARM_TIMEOUT = 900


def pytest_sessionstart(session):
    """Before pytest-xdist starts its workers: the compiled kernels built once.

    With numba installed and the kernels on, two processes run
    ``tests/warm_kernels.py`` (half the schemes each), which compiles the
    kernels into numba's disk cache for the argument types a run gives them.
    The workers and the notebooks' kernels then load them, instead of each
    compiling the same kernels side by side on a fresh clone (about a
    minute of the run on 2 cores).  With a warm cache this takes a few
    seconds.  A failure there is left to the tests to find (they run the same
    code).  Not in a worker, and not without workers (``-n 0``).
    """
    import subprocess

    from pentanb import _jit

    config = session.config
    if hasattr(config, "workerinput") or not getattr(config.option, "numprocesses", None):
        return
    if not _jit.available() or not _jit.enabled():
        return
    script = os.path.join(os.path.dirname(__file__), "warm_kernels.py")
    runs = [
        subprocess.Popen(
            [sys.executable, script, str(part), "2"],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        for part in range(2)
    ]
    for run in runs:
        try:
            run.wait(timeout=WARM_TIMEOUT)
        except subprocess.TimeoutExpired:  # a hang guard: the tests compile what is missing
            run.kill()
            run.wait()


#: The test files that take longest, longest first (measured with ``--durations``
#: in a full run on 2 cores; each runs whole in one pytest-xdist worker).  They
#: are started first, so that none is left to start while the others finish;
#: every other file follows, the files with the most tests first.
LONG_FILES = (
    "test_docs.py",
    "test_browser_lab_a.py",
    "test_browser_lab_b.py",
    "test_figures.py",
    "test_scale.py",
    "test_canonical.py",
)

#: Files that run in the worker of another file (every other file runs whole in
#: one worker): ``test_claims.py`` feeds wrong inputs to the studies that
#: ``test_figures.py``'s run of the figures command measures (the continuity
#: table, the scale study...), which are computed once per process, so the two
#: files share them.
SAME_WORKER = {"test_claims.py": "test_figures.py"}


def pytest_xdist_make_scheduler(config, log):
    """pytest-xdist's ``--dist loadfile``, with the files of :data:`SAME_WORKER` joined.

    A test file is dealt whole to one worker, in the order of the collection
    (:func:`pytest_collection_modifyitems`); a file of :data:`SAME_WORKER`
    goes with its partner.  (pytest-xdist's ``xdist_group`` marks would do
    this, but their group names do not reach the scheduler under pytest 9.2.)
    """
    if config.getvalue("dist") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class Scheduling(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            path = nodeid.split("::", 1)[0]
            name = path.rsplit("/", 1)[-1]
            return path[: len(path) - len(name)] + SAME_WORKER.get(name, name)

    return Scheduling(config, log)


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(session, config, items):
    """Order the test files as pytest-xdist should hand them out.

    xdist's ``--dist loadfile`` deals whole files to the workers (see
    :func:`pytest_xdist_make_scheduler`) in the order of the collection
    (``--no-loadscope-reorder`` in pyproject.toml: its own order, most tests
    first, would start the browser and docs files, few tests but minutes each,
    last): :data:`LONG_FILES` first, then the other files by their number of
    tests, most first; a file of :data:`SAME_WORKER` right after its partner.
    The tests of a file keep their order.
    """
    counts = Counter(item.nodeid.split("::")[0] for item in items)

    def rank(path: str):
        name = path.rsplit("/", 1)[-1]
        group = SAME_WORKER.get(name, name)
        partner = path[: -len(name)] + group
        if group in LONG_FILES:
            return (0, LONG_FILES.index(group), 0, group != name, path)
        return (1, -counts.get(partner, counts[path]), partner, group != name, path)

    order = {path: rank(path) for path in counts}
    items.sort(key=lambda item: order[item.nodeid.split("::")[0]])
