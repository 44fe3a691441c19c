"""pentanb.keep_freed_memory: malloc's settings while very large meshes are built."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time

import pytest

import pentanb
from pentanb import _malloc


class FakeLibc:
    """Records mallopt and malloc_trim calls; ``accept`` is what mallopt returns."""

    def __init__(self, accept: int = 1):
        self.calls: list[tuple] = []
        self.accept = accept

    def mallopt(self, param, value):
        self.calls.append(("mallopt", param, value))
        return self.accept

    def malloc_trim(self, pad):
        self.calls.append(("malloc_trim", pad))
        return 1


def _stop_reaper() -> None:
    """End the reaper thread, if one runs, without its switching anything."""
    reaper = _malloc._state["reaper"]
    if reaper is not None:
        with _malloc._wake:
            _malloc._state["until"] = 0.0
            _malloc._state["depth"] += 1  # it sees a block and only ends
            _malloc._wake.notify_all()
        reaper.join(5)
        with _malloc._wake:
            _malloc._state["depth"] -= 1
    assert _malloc._state["reaper"] is None


@pytest.fixture
def fake(monkeypatch):
    _stop_reaper()
    libc = FakeLibc()
    monkeypatch.setitem(_malloc._state, "libc", libc)
    monkeypatch.setitem(_malloc._state, "looked", True)
    monkeypatch.setitem(_malloc._state, "depth", 0)
    monkeypatch.setitem(_malloc._state, "on", False)
    monkeypatch.setitem(_malloc._state, "until", 0.0)
    monkeypatch.delenv("PENTANB_KEEP_FREED", raising=False)
    yield libc
    _stop_reaper()


KEEP = [("mallopt", -3, 2**31 - 1), ("mallopt", -1, -1)]
AFTER = [("mallopt", -3, 32 << 20), ("mallopt", -1, 64 << 20), ("malloc_trim", 0)]


def test_the_block_sets_keeps_then_restores_and_trims(fake):
    with pentanb.keep_freed_memory() as changed:
        assert changed is True
        assert fake.calls == KEEP
        with pentanb.keep_freed_memory():  # nested: the outermost decides
            pass
        assert fake.calls == KEEP
    assert fake.calls == KEEP + AFTER


def test_an_exception_in_the_block_still_restores(fake):
    with pytest.raises(ZeroDivisionError), pentanb.keep_freed_memory():
        1 / 0  # noqa: B018
    assert fake.calls == KEEP + AFTER
    assert _malloc._state["depth"] == 0


def test_a_refused_setting_is_an_oserror_naming_it(fake):
    fake.accept = 0
    with pytest.raises(OSError, match=r"glibc refused mallopt\(-3, 2147483647\)"):
        with pentanb.keep_freed_memory():
            pass
    assert fake.calls == [("mallopt", -3, 2**31 - 1)] + AFTER[:2]  # what was set, undone
    assert _malloc._state["depth"] == 0  # the next block tries again
    fake.accept = 1
    with pentanb.keep_freed_memory():
        assert fake.calls[-2:] == KEEP


def test_without_glibc_the_block_changes_nothing(monkeypatch):
    monkeypatch.setitem(_malloc._state, "libc", None)
    monkeypatch.setitem(_malloc._state, "looked", True)
    assert not _malloc.supported()
    with pentanb.keep_freed_memory() as changed:
        assert changed is False
        assert pentanb.subdivide(pentanb.shapes.cube(), "pentagonalize", 1).n_faces == 24


CHILD = textwrap.dedent(
    """
    import resource, numpy as np, pentanb

    def faults_of_a_reused_array():
        a = np.ones(8_000_000)  # 64 MB: above any threshold malloc sets by itself
        del a
        before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
        b = np.ones(8_000_000)
        return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before

    outside = faults_of_a_reused_array()
    with pentanb.keep_freed_memory():
        faults_of_a_reused_array()  # the heap grows once
        inside = faults_of_a_reused_array()
    print(outside, inside)
    """
)


def test_inside_the_block_a_freed_array_is_reused_without_fresh_pages():
    if not _malloc.supported():
        pytest.skip("malloc is not glibc's here")
    done = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    outside, inside = map(int, done.stdout.split())
    # outside, the 64 MB come back from the kernel as fresh pages (2 MB pages
    # at least: 32 faults); inside, the freed array's memory is reused
    assert outside >= 32, outside
    assert inside <= 4, inside


# ------------------------------------------------------------------ by itself


def _wait_for_reaper() -> None:
    reaper = _malloc._state["reaper"]
    assert reaper is not None, "no reaper thread was started"
    reaper.join(10)
    assert not reaper.is_alive()


def test_an_operator_below_the_threshold_changes_nothing(fake):
    pentanb.pentagonalize(pentanb.shapes.cube())
    _malloc.note_work(_malloc.AUTO_HALFEDGES - 1)
    assert fake.calls == []
    assert _malloc._state["reaper"] is None


def test_large_work_keeps_freed_memory_then_the_reaper_gives_it_back(fake, monkeypatch):
    monkeypatch.setenv("PENTANB_KEEP_FREED", "0.05")
    monkeypatch.setattr(_malloc, "_SECONDS_PER_HALFEDGE", 0.0)
    _malloc.note_work(_malloc.AUTO_HALFEDGES)
    assert fake.calls == KEEP
    _malloc.note_work(_malloc.AUTO_HALFEDGES)  # already on: nothing set twice
    assert fake.calls == KEEP
    _wait_for_reaper()
    assert fake.calls == KEEP + AFTER
    assert _malloc._state["on"] is False


def test_the_keeping_lasts_while_the_operator_is_expected_to_run(fake, monkeypatch):
    monkeypatch.setattr(_malloc, "AUTO_HALFEDGES", 10)
    before = time.monotonic()
    _malloc.note_work(10**6)
    until = _malloc._state["until"]
    # DEFAULT_SECONDS after the expected end of work on 10**6 half-edges
    assert until >= before + _malloc.DEFAULT_SECONDS + 10**6 * _malloc._SECONDS_PER_HALFEDGE
    assert until <= time.monotonic() + _malloc.DEFAULT_SECONDS + 1.0


@pytest.mark.parametrize(
    "op", ["constructor", "pentagonalize", "dual", "subdivide", "conway", "write", "canonical"]
)
def test_operators_and_the_constructor_announce_their_work(fake, monkeypatch, tmp_path, op):
    cube = pentanb.shapes.cube()
    monkeypatch.setattr(_malloc, "AUTO_HALFEDGES", 24)  # a cube has 24 half-edges
    run = {
        "constructor": lambda: pentanb.Mesh(cube.vertices, cube.faces),
        "pentagonalize": lambda: pentanb.pentagonalize(cube),
        "dual": lambda: pentanb.dual(cube),
        "subdivide": lambda: pentanb.subdivide(cube, "preserve_pentagons", 1),
        "conway": lambda: pentanb.conway("a", cube),
        "write": lambda: pentanb.write(cube, tmp_path / "cube.obj"),
        "canonical": lambda: pentanb.canonical(cube),
    }[op]
    run()
    assert fake.calls == KEEP


def test_zero_seconds_keeps_nothing(fake, monkeypatch):
    monkeypatch.setenv("PENTANB_KEEP_FREED", "0")
    _malloc.note_work(_malloc.AUTO_HALFEDGES)
    assert fake.calls == []
    assert _malloc._state["reaper"] is None


@pytest.mark.parametrize("value", ["ten", "-1", "nan", "inf", "1e400"])
def test_a_bad_keep_freed_setting_is_a_valueerror_naming_it(fake, monkeypatch, value):
    monkeypatch.setenv("PENTANB_KEEP_FREED", value)
    with pytest.raises(ValueError, match=r"PENTANB_KEEP_FREED must be a number of seconds >= 0"):
        _malloc.note_work(_malloc.AUTO_HALFEDGES)
    assert fake.calls == []


def test_seconds_reads_the_environment(monkeypatch):
    monkeypatch.delenv("PENTANB_KEEP_FREED", raising=False)
    assert _malloc.seconds() == _malloc.DEFAULT_SECONDS
    monkeypatch.setenv("PENTANB_KEEP_FREED", " 2.5 ")
    assert _malloc.seconds() == 2.5


def test_a_refused_setting_leaves_the_operator_running(fake):
    fake.accept = 0
    _malloc.note_work(_malloc.AUTO_HALFEDGES)  # no exception
    assert fake.calls == [("mallopt", -3, 2**31 - 1)] + AFTER[:2]
    assert _malloc._state["on"] is False
    assert _malloc._state["reaper"] is None


def test_release_gives_the_memory_back_at_once(fake):
    _malloc.note_work(_malloc.AUTO_HALFEDGES)
    assert fake.calls == KEEP
    assert pentanb.release_freed_memory() is True
    assert fake.calls == KEEP + AFTER
    _wait_for_reaper()  # it wakes, finds nothing to do, and ends
    assert fake.calls == KEEP + AFTER


def test_release_inside_a_block_waits_for_the_block(fake):
    with pentanb.keep_freed_memory():
        _malloc.note_work(_malloc.AUTO_HALFEDGES)
        assert pentanb.release_freed_memory() is False
        assert fake.calls == KEEP
    assert fake.calls == KEEP + AFTER


@pytest.mark.parametrize("ends_last", ["the large work", "the block"])
def test_whichever_of_a_block_and_large_work_ends_last_gives_the_memory_back(
    fake, monkeypatch, ends_last
):
    monkeypatch.setenv("PENTANB_KEEP_FREED", "0.2" if ends_last == "the large work" else "0.01")
    monkeypatch.setattr(_malloc, "_SECONDS_PER_HALFEDGE", 0.0)
    with pentanb.keep_freed_memory():
        _malloc.note_work(_malloc.AUTO_HALFEDGES)
        if ends_last == "the block":
            _wait_for_reaper()  # the reaper leaves a running block alone
        assert fake.calls == KEEP
    if ends_last == "the large work":
        assert fake.calls == KEEP  # kept: the operator asked for 0.2 s more
        _wait_for_reaper()
    assert fake.calls == KEEP + AFTER


def test_without_glibc_large_work_changes_nothing(monkeypatch):
    monkeypatch.setitem(_malloc._state, "libc", None)
    monkeypatch.setitem(_malloc._state, "looked", True)
    _malloc.note_work(_malloc.AUTO_HALFEDGES)
    assert _malloc._state["reaper"] is None
    assert pentanb.release_freed_memory() is False


AUTO_CHILD = textwrap.dedent(
    """
    import os, resource, sys, time
    import numpy as np, pentanb
    from pentanb import _malloc

    def faults_of_a_reused_array():
        a = np.ones(8_000_000)  # 64 MB
        del a
        before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
        b = np.ones(8_000_000)
        return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before

    _malloc.AUTO_HALFEDGES = 24
    pentanb.pentagonalize(pentanb.shapes.cube())  # "large" work
    reaper = _malloc._state["reaper"]  # (it forgets itself once it has ended)
    faults_of_a_reused_array()
    kept = faults_of_a_reused_array()
    pid = os.fork()
    if pid == 0:  # the child stops keeping, and can start again
        ok = _malloc._state["on"] is False and _malloc._state["reaper"] is None
        pentanb.pentagonalize(pentanb.shapes.cube())
        ok = ok and _malloc._state["on"] is True and _malloc._state["reaper"] is not None
        os._exit(0 if ok else 3)
    _, status = os.waitpid(pid, 0)
    reaper.join(10)  # PENTANB_KEEP_FREED=0.3 s later (or already over, on a slow machine)
    given_back = faults_of_a_reused_array()
    print(kept, given_back, os.waitstatus_to_exitcode(status))
    """
)


def test_large_work_reuses_freed_memory_until_the_reaper_gives_it_back():
    if not _malloc.supported():
        pytest.skip("malloc is not glibc's here")
    env = {**os.environ, "PENTANB_KEEP_FREED": "0.3", "PENTANB_JIT": "0"}
    done = subprocess.run(
        [sys.executable, "-c", AUTO_CHILD], capture_output=True, text=True, env=env, timeout=120
    )
    assert done.returncode == 0, done.stderr
    kept, given_back, child = map(int, done.stdout.split())
    assert kept <= 4, kept  # reused while kept
    assert given_back >= 32, given_back  # fresh pages again once given back
    assert child == 0, "a forked child kept the parent's keeping, or could not start its own"


def test_a_slider_move_keeps_freed_memory_whatever_its_size(fake, monkeypatch):
    pytest.importorskip("pythreejs")
    e = pentanb.explore(pentanb.shapes.cube(), "preserve_pentagons", iterations=0, duals=2)
    try:
        assert pentanb.release_freed_memory() is True  # what opening it kept, given back
        fake.calls.clear()
        e.iterations.value = 1  # 24 faces: far below AUTO_HALFEDGES
        assert fake.calls == KEEP
        assert _malloc._state["until"] > time.monotonic()
        pentanb.release_freed_memory()
        fake.calls.clear()
        monkeypatch.setenv("PENTANB_KEEP_FREED", "0")
        e.iterations.value = 2
        assert fake.calls == []
    finally:
        e.close()
