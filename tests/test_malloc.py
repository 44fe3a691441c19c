"""pentanb.keep_freed_memory: malloc's settings while very large meshes are built."""

from __future__ import annotations

import subprocess
import sys
import textwrap

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


@pytest.fixture
def fake(monkeypatch):
    libc = FakeLibc()
    monkeypatch.setitem(_malloc._state, "libc", libc)
    monkeypatch.setitem(_malloc._state, "looked", True)
    monkeypatch.setitem(_malloc._state, "depth", 0)
    return libc


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
