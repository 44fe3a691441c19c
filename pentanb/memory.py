"""How much memory a mesh holds, and how much this process may still take.

Kept apart from :mod:`pentanb.subdivision` (the memory guard) so that the
shapes can check their own size before building anything.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

__all__ = ["mesh_bytes", "default_max_bytes", "readable"]


def mesh_bytes(V: float, E: float, F: float) -> int:
    """What a mesh of these counts holds: positions, corners, twins, vertex rings, offsets."""
    return math.ceil(24 * V + itemsize(V, 2 * E) * (3 * 2 * E + F + V + 2))


def itemsize(V: float, H: float) -> int:
    """Bytes of an index: int32 while the counts allow, int64 beyond."""
    return 4 if max(V, H) < 2**31 else 8


def readable(n: float) -> str:
    """Bytes as "3.2 GB" (powers of 1000), for messages."""
    for unit, size in (("EB", 1e18), ("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n / 1e3:.3g} kB" if n >= 1e3 else f"{int(n)} bytes"


#: A cgroup v1 limit at least this large means no limit (the kernel writes
#: about 2**63 there when none is set).
_NO_CGROUP_LIMIT = 2**60


def default_max_bytes(
    meminfo: str | os.PathLike = "/proc/meminfo",
    cgroup: str | os.PathLike = "/sys/fs/cgroup",
    status: str | os.PathLike = "/proc/self/status",
) -> int:
    """The memory this process may still take: the default ``max_bytes``.

    The smallest of the memory the kernel says is available (``MemAvailable``
    in ``meminfo``), the room left under the container's limit (cgroup
    v2: ``memory.max`` minus ``memory.current`` in ``cgroup``; v1:
    ``memory.limit_in_bytes`` minus ``memory.usage_in_bytes``, in ``cgroup``
    or its ``memory`` directory) and the room left under this process's
    address-space limit (``ulimit -v``, ``RLIMIT_AS``, minus ``VmSize`` in
    ``status``), whichever can be read; where none can (not Linux), half of
    the physical memory, or 4 GiB.

    Parameters
    ----------
    meminfo, cgroup, status : path
        Where to read them (other paths for tests).

    Returns
    -------
    int
        Bytes, at least 0.
    """
    found = [
        x
        for x in (_meminfo_available(meminfo), _cgroup_room(cgroup), _address_space_room(status))
        if x is not None
    ]
    return max(min(found), 0) if found else _half_physical()


def _read(path: str | os.PathLike) -> str | None:
    """A file's text, or None when it cannot be read."""
    try:
        return Path(path).read_text()
    except (OSError, UnicodeDecodeError):
        return None


def _meminfo_available(path: str | os.PathLike) -> int | None:
    """Bytes of ``MemAvailable`` in a /proc/meminfo file (in kB there), or None."""
    for line in (_read(path) or "").splitlines():
        key, _, value = line.partition(":")
        if key.strip() == "MemAvailable":
            fields = value.split()
            if fields and fields[0].isdigit():
                unit = 1024 if fields[1:] == ["kB"] else 1
                return int(fields[0]) * unit
    return None


def _cgroup_room(root: str | os.PathLike) -> int | None:
    """Bytes left under a cgroup's memory limit, or None (no limit, or none found)."""
    root = Path(root)
    pairs = [(root, "memory.max", "memory.current")]  # v2
    pairs += [
        (d, "memory.limit_in_bytes", "memory.usage_in_bytes") for d in (root, root / "memory")
    ]
    for where, limit_file, usage_file in pairs:
        text = _read(where / limit_file)
        if text is None:
            continue
        text = text.strip()
        if not text.isdigit():  # "max": no limit
            return None
        limit = int(text)
        if limit >= _NO_CGROUP_LIMIT:
            return None
        usage = (_read(where / usage_file) or "0").strip()
        return limit - (int(usage) if usage.isdigit() else 0)
    return None


def _address_space_room(status: str | os.PathLike) -> int | None:
    """Bytes left under this process's address-space limit (``RLIMIT_AS``), or
    None (no limit, or none readable).  What the process has mapped is
    ``VmSize`` in ``status`` (/proc/self/status), 0 where it cannot be read."""
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    except (ImportError, OSError, ValueError, AttributeError):  # not POSIX
        return None
    if soft == resource.RLIM_INFINITY or soft < 0:
        return None
    used = 0
    for line in (_read(status) or "").splitlines():
        key, _, value = line.partition(":")
        fields = value.split()
        if key.strip() == "VmSize" and fields and fields[0].isdigit():
            used = int(fields[0]) * (1024 if fields[1:] == ["kB"] else 1)
    return soft - used


def _half_physical() -> int:
    """Half of this machine's physical memory (4 GiB where it cannot be read)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2
    except (ValueError, OSError, AttributeError):  # non-POSIX
        return 4 << 30
