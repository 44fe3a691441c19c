"""OBJ and OFF read/write against trimesh on one 1,000,000-triangle mesh (issue 11, target 5).

Run from the repository root::

    PYTHONPATH=$PWD python benchmarks/bench_io.py [--triangles N] [--repeat R] [--check]

Times are medians of ``R`` alternating runs in one process (pentanb, then
trimesh, then pentanb ...), so machine noise hits both alike; the ratios are
what counts.  ``pentanb.read`` returns a validated :class:`pentanb.Mesh`
(closed manifold, orientation, ...); trimesh's ``load(..., process=False)``
checks nothing, so the read ratio includes our validation.  Memory: the
peak of numpy allocations during ``pentanb.read`` as ``tracemalloc`` sees
them, against the bytes of the arrays read (vertices, corners, offsets),
once for the parsing alone and once for the whole read (parsing plus the
mesh's validation, which derives its half-edge arrays).

Targets (OBJ and OFF): read and write at most 1.0x trimesh's time, peak
memory while parsing at most 3x the arrays read.  ``--check`` exits 1 when
one is missed.  PLY and STL are shown for information (trimesh's binary
readers are a single ``np.frombuffer``; our STL read welds the corners,
trimesh's with ``process=False`` does not).
"""

from __future__ import annotations

import argparse
import gc
import statistics
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

import numpy as np

import pentanb
from pentanb.io import _common


def torus_triangles(n_triangles: int) -> tuple[np.ndarray, np.ndarray]:
    """A torus grid of about ``n_triangles`` triangles (quads cut in two)."""
    rings = max(3, round((n_triangles / 4) ** 0.5))
    sides = max(3, n_triangles // (2 * rings))
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    t, p = 2 * np.pi * i / rings, 2 * np.pi * j / sides
    r = 1 + 0.4 * np.cos(p)
    v = np.stack([r * np.cos(t), r * np.sin(t), 0.4 * np.sin(p)], -1).reshape(-1, 3)

    def idx(a, b):
        return (a % rings) * sides + (b % sides)

    a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
    f = np.concatenate(
        [np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)]
    )
    return v, f


def timed(fn) -> float:
    gc.collect()
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def peak_bytes(fn) -> int:
    gc.collect()
    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--check", action="store_true", help="exit 1 when a target is missed")
    ap.add_argument(
        "--formats", default="obj,off,ply,stl", help="comma-separated (targets: obj, off)"
    )
    args = ap.parse_args(argv)
    import trimesh

    v, f = torus_triangles(args.triangles)
    mesh = pentanb.Mesh(v, f)
    tm = trimesh.Trimesh(v, f, process=False)
    arrays = mesh.vertices.nbytes + mesh.corners.nbytes + mesh.offsets.nbytes
    print(
        f"{mesh.n_faces:,} triangles, {mesh.n_vertices:,} vertices; arrays read: "
        f"{arrays / 1e6:.1f} MB; median of {args.repeat} alternating runs"
    )
    missed = []
    with tempfile.TemporaryDirectory() as tmp:
        for fmt in args.formats.split(","):
            missed += _compare(fmt, Path(tmp), mesh, tm, trimesh, arrays, args.repeat)
    if missed:
        print("missed:", ", ".join(missed))
    return 1 if (args.check and missed) else 0


def _compare(fmt, tmp, mesh, tm, trimesh, arrays, repeat) -> list[str]:
    """Time and measure one format; the targets it misses."""
    ours, theirs = tmp / f"p.{fmt}", tmp / f"t.{fmt}"
    keys = ("pw", "tw", "pr", "tr", "tp", "val")
    times: dict[str, list[float]] = {k: [] for k in keys}
    for _ in range(repeat):
        times["pw"].append(timed(lambda: pentanb.write(mesh, ours)))
        times["tw"].append(timed(lambda: tm.export(theirs)))
        times["pr"].append(timed(lambda: pentanb.read(ours)))
        times["tr"].append(timed(lambda: trimesh.load(theirs, process=False)))
        times["tp"].append(timed(lambda: trimesh.load(ours, process=False)))
        times["val"].append(
            timed(lambda: pentanb.Mesh.from_csr(mesh.vertices, mesh.corners, mesh.offsets))
        )
    med = {k: statistics.median(x) for k, x in times.items()}
    back = pentanb.read(ours)
    targets = fmt in ("obj", "off")
    if fmt != "stl":  # STL: float32 positions, vertices renumbered by the welding
        assert back.vertices.tobytes() == mesh.vertices.tobytes()
        assert np.array_equal(back.corners, mesh.corners)
    size, their_size = ours.stat().st_size, theirs.stat().st_size
    wr, rr = med["pw"] / med["tw"], med["pr"] / med["tr"]
    target = " (target <= 1.0)" if targets else ""
    print(
        f"{fmt.upper()} (ours {size / 1e6:.0f} MB; trimesh's {their_size / 1e6:.0f} MB): write "
        f"{med['pw']:.2f} s vs trimesh {med['tw']:.2f} s = {wr:.2f}x{target}; read "
        f"{med['pr']:.2f} s vs {med['tr']:.2f} s = {rr:.2f}x{target}"
    )
    print(
        f"    of our read, validation (Mesh.from_csr of the arrays) {med['val']:.2f} s; "
        f"trimesh reading our file: {med['tp']:.2f} s (ours {med['pr'] / med['tp']:.2f}x)"
    )
    spread = {k: f"{min(x):.2f}-{max(x):.2f}" for k, x in times.items()}
    print(
        f"    spread (min-max s): pentanb write {spread['pw']}, trimesh write {spread['tw']}, "
        f"pentanb read {spread['pr']}, trimesh read {spread['tr']}"
    )
    if fmt == "stl":
        return []
    parse = peak_bytes(lambda: _parse_only(ours))
    whole = peak_bytes(lambda: pentanb.read(ours))
    print(
        f"    read peak memory: parsing {parse / 1e6:.0f} MB = {parse / arrays:.2f}x the "
        f"arrays{' (target <= 3)' if targets else ''}; whole read with validation "
        f"{whole / 1e6:.0f} MB = {whole / arrays:.2f}x"
    )
    if not targets:
        return []
    return (
        [f"{fmt} write"] * (wr > 1.0)
        + [f"{fmt} read"] * (rr > 1.0)
        + [f"{fmt} parse memory"] * (parse > 3 * arrays)
    )


def _parse_only(path: Path) -> None:
    """Parse without building the mesh: the reader with ``finish`` replaced."""
    keep = _common.finish
    mods = [pentanb.io.obj, pentanb.io.off, pentanb.io.ply]
    try:
        for m in mods:
            m.finish = lambda path, v, c, o: (v, c, o)  # type: ignore[attr-defined]
        pentanb.read(path)
    finally:
        for m in mods:
            m.finish = keep  # type: ignore[attr-defined]


if __name__ == "__main__":
    sys.exit(main())
