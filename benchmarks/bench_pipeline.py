"""Benchmark: what a user pays, from raw arrays, against trimesh; memory; the slider.

Prints one table of the speed and memory targets, each
measured in this run, as a ratio or a per-face figure with its target:

1. ``pentagonalize(Mesh(V, F))`` from raw arrays, validation included, against
   trimesh ``Trimesh(V, F, process=False).subdivide()`` on a 327,680-triangle
   icosphere (target: at most 1.0x);
2. ``smooth(pentagonalize(Mesh(V, F)), duals=2)`` against
   ``trimesh.remesh.subdivide_loop(V, F)``, both warm (at most 0.25x), with
   the spread of the per-run ratios;
3. one slider move of the interactive explorer at 20,480 faces: every scheme
   plus two duals on an existing mesh, the explorer's real path including the
   buffer update it sends to the view (at most 10 ms for the paper's two
   schemes, 15 ms for the others);
4. linearity: the pipeline's time per input face at 5,242,880 triangles over
   that at 327,680 (at most 1.3x), each path measured in a fresh child
   process that builds both inputs and runs them alternately; and its peak
   memory above the input, numpy's allocations as ``tracemalloc`` counts
   them, per output face (at most 250 bytes);
5. reading and writing OBJ and OFF files of 1,000,000 triangles against
   trimesh's ``export`` and ``load`` (at most 1.0x), and the peak memory while
   reading over the size of the arrays read (at most 3x);
6. open meshes: the paper's two schemes + two duals, from raw arrays, on a
   planar grid of 1,000,000 quads with 500 square holes (24,200 boundary
   edges, 501 boundary loops) against a closed torus grid of 1,000,000 quads,
   time per face, open over closed (at most 1.25x; each path on its own,
   open and closed alternating in an order drawn at random every round), with
   the same runs' ratio in CPU time (user mode, all threads: the work done,
   without the time the kernel spends handing over fresh memory) beside it,
   without a target; and ``Mesh(V, F)`` alone, without a target (the part of
   it that validation takes).  On a virtual machine whose kernel counts its
   free page reporting passes (handing free memory back to the host), every
   run of the targets starts once a few seconds have passed without one: the
   memory the runs before freed is back with the host, as after a pause
   between a user's calls (back-to-back runs would depend on where they fall
   between the passes);

When numba is installed (``pip install -e .[jit]``), the rows of 2., 3., 4.'s
time ratio and 6. are measured twice, alternating run by run: the numpy path
and the optional compiled kernels (:mod:`pentanb._jit`), the latter marked
"compiled kernels".  Every other row is the numpy path.

Two diagnoses ride along, without targets: page faults (memory the kernel
hands over fresh) per slider move and per 1,000 faces of the pipeline, with
the per-face ratio of 4. again in fresh child processes started with glibc's
tunables set to keep freed memory (``GLIBC_TUNABLES``, see
``docs/performance.md``), each with the resident peak of its runs; and
trimesh's ``subdivide()`` of the slider's mesh, the machine's speed.

then, for every scheme, the memory guard's estimate against the measured peak
and the largest mesh that the default limit (the memory available) lets
through one iteration with two duals.

Timings alternate between the two sides of every ratio, run after run, in one
process (this machine is shared and noisy: a ratio of two medians taken
minutes apart would measure the neighbours), and report medians; a slider
move takes at least 15 runs (a move and trimesh's ``subdivide()`` both
fall into a fast and a slow group on a shared machine, and the median of 9
lands in either).  Every
pentanb call starts from the raw arrays ``V`` and ``F`` (validation
included); trimesh gets a fresh ``Trimesh`` or the raw arrays likewise.

Run::

    pip install -e .[bench]
    python benchmarks/bench_pipeline.py             # the table
    python benchmarks/bench_pipeline.py --check     # exit 1 when a target is missed
    python benchmarks/bench_pipeline.py --quick     # without the 5-million-face rows
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import json
import os
import platform
import sys
import tempfile
import time
import tracemalloc
from collections.abc import Callable
from pathlib import Path

import numpy as np

import pentanb as pb
from pentanb import _jit
from pentanb.subdivision import default_max_bytes

#: the optional compiled kernels (numba) can be measured beside the numpy path
COMPILED = _jit.available()

CLOCKS = {"wall": time.perf_counter, "cpu": time.process_time}


class Table:
    """The rows of the report: label, measured value, target, verdict."""

    def __init__(self) -> None:
        self.rows: list[dict] = []

    def add(self, section, label, value, unit, target=None, *, note=""):
        ok = None if target is None else bool(value <= target)
        self.rows.append(
            dict(
                section=section,
                label=label,
                value=value,
                unit=unit,
                target=target,
                ok=ok,
                note=note,
            )
        )
        shown = f"{value:,.2f} {unit}" if unit != "x" else f"{value:.2f}x"
        aim = "" if target is None else (f"<= {target:.3g}{'x' if unit == 'x' else ' ' + unit}")
        verdict = "" if ok is None else ("PASS" if ok else "MISS")
        print(f"  {label:62s} {shown:>16s}  {aim:>12s}  {verdict}  {note}", flush=True)

    @property
    def missed(self) -> list[str]:
        return [r["label"] for r in self.rows if r["ok"] is False]

    def markdown(self) -> str:
        lines = ["| measure | value | target | |", "|---|---|---|---|"]
        section = None
        for r in self.rows:
            if r["section"] != section:
                section = r["section"]
                lines.append(f"| **{section}** | | | |")
            unit = r["unit"]
            value = f"{r['value']:.2f}x" if unit == "x" else f"{r['value']:,.1f} {unit}"
            target = (
                ""
                if r["target"] is None
                else f"<= {r['target']:.3g}" + ("x" if unit == "x" else f" {unit}")
            )
            verdict = {None: "", True: "pass", False: "**missed**"}[r["ok"]]
            note = f" ({r['note']})" if r["note"] else ""
            lines.append(f"| {r['label']}{note} | {value} | {target} | {verdict} |")
        return "\n".join(lines)


def alternate(
    cases: dict[str, Callable[[], object]],
    runs: int,
    clock,
    user: dict[str, list[float]] | None = None,
    balanced: bool = False,
    settled: dict[str, list[int]] | None = None,
) -> dict[str, list[float]]:
    """Time every case once per round, ``runs`` rounds, after one untimed warm-up round.

    Returns the seconds of every run of every case, in round order, so that
    ratios can be taken run by run.  ``user``, when given, receives the CPU
    time in user mode of the same runs (all threads, from ``getrusage``):
    the work done, without the time the kernel spends handing over memory.
    ``balanced`` runs every other round in the reverse order (A B, B A, A B,
    ...), so that every case follows itself as often as another one: what
    the run before freed, and the kernel still holds, is then no more one
    case's than another's.

    ``settled``, when given, starts every run once the host has taken back
    the memory the runs before freed (:func:`settle`: where the kernel
    counts its free page reporting passes, none for a few seconds), as a
    call after a pause starts, and receives the passes made during every
    run.  The cases then run in an order drawn at random every round
    (seeded).  On a virtual machine that hands free memory back to its
    host, back-to-back runs find that memory in whatever state the last
    pass left it: a run that a pass overtakes, or one that starts just
    after one, takes a second or more longer, so that back-to-back times
    depend on where the runs fall between the passes (see
    ``docs/performance.md``).
    """
    times: dict[str, list[float]] = {k: [] for k in cases}
    if user is not None:
        user.update({k: [] for k in cases})
    if settled is not None:
        settled.update({k: [] for k in cases})
    for fn in cases.values():
        fn()
    draw = np.random.default_rng(0)
    for r in range(runs):
        order = list(cases.items())
        if settled is not None:
            order = [order[i] for i in draw.permutation(len(order))]
        elif balanced and r % 2:
            order = order[::-1]
        for name, fn in order:
            gc.collect()
            if settled is not None:
                settle()
            passes = reporting_passes()
            u = user_seconds()
            t = clock()
            fn()
            took = clock() - t
            if user is not None:
                user[name].append(user_seconds() - u)
            if settled is not None and passes is not None:
                settled[name].append((reporting_passes() or 0) - passes)
            times[name].append(took)
    return times


#: Seconds without a free page reporting pass after which the host is taken
#: to have taken back the memory the last run freed (:func:`settle`).
SETTLED_AFTER = 2.5


def settle(
    quiet: float = SETTLED_AFTER, limit: float = 30.0, sleep=time.sleep, now=time.monotonic
) -> float:
    """Wait until the kernel has made no free page reporting pass for ``quiet``
    seconds, at most ``limit`` seconds; returns the seconds waited (0 where
    the kernel does not count its passes).

    The kernel reports free memory to the host about every two seconds while
    the process frees it; once a few seconds pass without a report, what the
    last run freed is back with the host, as after a pause between a user's
    calls, and every run starts from that same state.
    """
    if reporting_passes() is None:
        return 0.0
    began = last = now()
    seen = reporting_passes()
    while now() - began < limit:
        sleep(0.1)
        got = reporting_passes()
        if got != seen:
            seen, last = got, now()
        elif now() - last >= quiet:
            break
    return now() - began


#: where a Linux kernel that hands free memory back to its host (a virtual
#: machine's free page reporting) counts its passes, when it does
REPORTING_PASSES = Path("/sys/module/page_reporting/parameters/passes")


def reporting_passes() -> int | None:
    """The free page reporting passes the kernel has made so far, or None
    where it does not count them.

    On a virtual machine that reports its free memory to the host, a pass
    that runs during a timed run adds a second or more of kernel time to it,
    whichever case it is (see ``docs/performance.md``).
    """
    try:
        return int(REPORTING_PASSES.read_text())
    except (OSError, ValueError):
        return None


def user_seconds() -> float:
    """CPU time this process has spent in user mode so far, all threads."""
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_utime


def median(xs) -> float:
    return float(np.median(xs))


def peak_bytes(fn: Callable[[], object]) -> tuple[int, object]:
    """Peak of numpy's allocations (tracemalloc) during ``fn()`` above what was held before."""
    gc.collect()
    tracemalloc.start()
    base = tracemalloc.get_traced_memory()[0]
    tracemalloc.reset_peak()
    out = fn()
    peak = tracemalloc.get_traced_memory()[1] - base
    tracemalloc.stop()
    return peak, out


def minor_faults() -> int:
    """Page faults this process has taken so far (pages the kernel had to hand over)."""
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt


def reset_resident_peak() -> None:
    """Linux: start this process's resident peak (VmHWM) again from what it holds now."""
    with contextlib.suppress(OSError):
        Path("/proc/self/clear_refs").write_text("5")


def resident_peak() -> int:
    """This process's resident peak in bytes (Linux: VmHWM; else ru_maxrss)."""
    with contextlib.suppress(OSError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                return 1024 * int(line.split()[1])
    import resource

    return 1024 * resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def icosphere(subdivisions: int):
    import trimesh

    m = trimesh.creation.icosphere(subdivisions=subdivisions)
    return np.ascontiguousarray(m.vertices), np.ascontiguousarray(m.faces)


def torus_triangles(n: int, m: int) -> tuple[np.ndarray, np.ndarray]:
    """A torus grid of n x m quads, each split into two triangles (2nm triangles)."""
    u = 2 * np.pi * np.arange(n) / n
    w = 2 * np.pi * np.arange(m) / m
    uu, ww = np.meshgrid(u, w, indexing="ij")
    r = 3.0 + np.cos(ww)
    v = np.stack([r * np.cos(uu), r * np.sin(uu), np.sin(ww)], axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    a = i * m + j
    b = ((i + 1) % n) * m + j
    c = ((i + 1) % n) * m + (j + 1) % m
    d = i * m + (j + 1) % m
    f = np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], axis=2).reshape(-1, 3)
    return v, f


def pipeline(v, f):
    return pb.smooth(pb.pentagonalize(pb.Mesh(v, f)), duals=2)


def on_path(compiled: bool, fn: Callable[[], object]) -> Callable[[], object]:
    """``fn`` run with the compiled kernels on or off (the switch is not timed apart)."""

    def run():
        _jit.use_jit(compiled)
        try:
            return fn()
        finally:
            _jit.use_jit(False)

    return run


def ratio_rows(table, sec, t, case, reference, target, label, note) -> None:
    """A target's rows: ``case`` over ``reference`` run by run, numpy path and compiled."""
    for name, suffix in ((case, ""), (case + ", compiled", ", compiled kernels")):
        if name not in t:
            continue
        r = np.array(t[name]) / np.array(t[reference])
        table.add(sec, label + suffix, median(r), "x", target, note=note(r))


# ---------------------------------------------------------------------- sections
def speed(table: Table, runs: int, clock) -> dict:
    import trimesh
    from trimesh import remesh

    v, f = icosphere(7)
    assert len(f) == 327_680
    print("\n327,680-triangle icosphere, from raw arrays (median of alternating runs)")
    t = alternate(
        {
            "trimesh subdivide": lambda: trimesh.Trimesh(v, f, process=False).subdivide(),
            "pentagonalize(Mesh(V, F))": lambda: pb.pentagonalize(pb.Mesh(v, f)),
            "Mesh(V, F)": lambda: pb.Mesh(v, f),
            **(
                {
                    "pentagonalize(Mesh(V, F)), compiled": on_path(
                        True, lambda: pb.pentagonalize(pb.Mesh(v, f))
                    )
                }
                if COMPILED
                else {}
            ),
        },
        runs,
        clock,
    )
    t2 = alternate(
        {
            "trimesh subdivide_loop": lambda: remesh.subdivide_loop(v, f),
            "pipeline": lambda: pipeline(v, f),
            **({"pipeline, compiled": on_path(True, lambda: pipeline(v, f))} if COMPILED else {}),
        },
        runs,
        clock,
    )
    t.update(t2)
    sec = "speed (327,680 triangles)"
    for name in ("trimesh subdivide", "trimesh subdivide_loop", "Mesh(V, F)"):
        table.add(sec, name, 1000 * median(t[name]), "ms")
    table.add(sec, "pentagonalize(Mesh(V, F))", 1000 * median(t["pentagonalize(Mesh(V, F))"]), "ms")
    table.add(
        sec,
        "smooth(pentagonalize(Mesh(V, F)), duals=2)",
        1000 * median(t["pipeline"]),
        "ms",
    )
    ratio_rows(
        table,
        sec,
        t,
        "pentagonalize(Mesh(V, F))",
        "trimesh subdivide",
        1.0,
        "1. pentagonalize(Mesh(V, F)) / trimesh subdivide()",
        lambda r: f"runs {r.min():.2f}-{r.max():.2f}",
    )
    ratio_rows(
        table,
        sec,
        t,
        "pipeline",
        "trimesh subdivide_loop",
        0.25,
        "2. smooth(pentagonalize(Mesh(V, F)), 2) / subdivide_loop",
        lambda r: f"{len(r)} runs: {', '.join(f'{x:.3f}' for x in sorted(r))}",
    )
    # a diagnosis of target 1 on the numpy path: the validation's one sort
    # (the twin pairing's packed keys), here and with numpy's AVX-512 sorts
    # switched off (on AMD Zen 4 they are slow: a microcoded compress-store)
    here, avx2 = sort_ms(), sort_ms({"NPY_DISABLE_CPU_FEATURES": "X86_V4 AVX512_ICL AVX512_SPR"})
    if here is not None:
        note = (
            ""
            if avx2 is None
            else f"{avx2:.1f} ms with numpy's AVX-512 sorts off (a child process)"
        )
        table.add(
            sec,
            f"np.sort of {3 * len(f):,} int64 keys (Mesh(V, F)'s twin pairing)",
            here,
            "ms",
            note=note,
        )
    return {k: [float(x) for x in xs] for k, xs in t.items()}


SORT_CODE = (
    "import numpy as np, time; x = np.random.default_rng(1).integers(0, 2**62, {n});"
    "ts = []\n"
    "for _ in range(5):\n"
    "    y = x.copy(); t = time.perf_counter(); y.sort(); ts.append(time.perf_counter() - t)\n"
    "print(1000 * sorted(ts)[2])"
)


def sort_ms(env: dict[str, str] | None = None, n: int = 983_040) -> float | None:
    """Median ms of numpy's sort of ``n`` random int64 in a child process (None if it fails)."""
    import subprocess

    try:
        out = subprocess.run(
            [sys.executable, "-c", SORT_CODE.format(n=n)],
            env={**os.environ, **(env or {})},
            capture_output=True,
            text=True,
            timeout=120,
            check=True,
        )
        return float(out.stdout.strip().splitlines()[-1])
    except (subprocess.SubprocessError, ValueError, IndexError, OSError):
        return None


# trimesh subdivide() of the 20,480-triangle icosphere in the issue's table (ms)
ISSUE_TRIMESH_MS = 11.0


def slider(table: Table, runs: int, clock) -> dict:
    try:
        import ipywidgets  # noqa: F401
        import pythreejs  # noqa: F401
    except ImportError:
        print("\n(slider rows skipped: ipywidgets and pythreejs are not installed)")
        return {}
    v, f = icosphere(5)
    base = pb.Mesh(v, f)
    assert base.n_faces == 20_480
    print("\none slider move at 20,480 faces: iterations 0 -> 1 in explore(), two duals")
    import trimesh

    out = {}
    sec = "slider move (20,480 faces, explorer)"
    paths = (False, True) if COMPILED else (False,)
    # trimesh's subdivide() of the same mesh runs between the moves, so that
    # every scheme's ratio to it is measured on the same machine state (the
    # issue's targets were set where it took ISSUE_TRIMESH_MS)
    ref: list[float] = []
    for name, scheme in pb.SCHEMES.items():
        times: dict[bool, list[float]] = {p: [] for p in paths}
        faults: dict[bool, list[int]] = {p: [] for p in paths}
        ref_here: list[float] = []
        for r in range(runs + 1):
            for compiled in paths:  # numpy and compiled alternate, run after run
                _jit.use_jit(compiled)
                e = pb.explore(base, name, iterations=0, duals=2, max_faces=10**6)
                gc.collect()
                a = minor_faults()
                t = clock()
                e.iterations.value = 1  # the explorer's own path: compute, buffers, legend
                dt = clock() - t
                b = minor_faults()
                assert e.mesh is not None and e.mesh is not base, "no new mesh shown"
                if r:  # the first is a warm-up
                    times[compiled].append(dt)
                    faults[compiled].append(b - a)
                e.close()
                _jit.use_jit(False)
            gc.collect()
            t = clock()
            trimesh.Trimesh(v, f, process=False).subdivide()
            dt = clock() - t
            if r:
                ref_here.append(dt)
        ref += ref_here
        target = 10.0 if scheme.family == "pentagonal" else 15.0
        for compiled in paths:
            label = f"3. {name} + 2 duals" + (", compiled kernels" if compiled else "")
            ms = 1000 * median(times[compiled])
            note = f"{median(faults[compiled]):,.0f} page faults"
            table.add(sec, label, ms, "ms", target, note=note)
            table.add(
                sec,
                label + " / trimesh subdivide()",
                median(times[compiled]) / median(ref_here),
                "x",
                target / ISSUE_TRIMESH_MS,
                note=f"{target:g} ms on the issue's machine, where subdivide() took "
                f"{ISSUE_TRIMESH_MS:g} ms",
            )
        out[name] = [float(x) for x in times[False]]
        if COMPILED:
            out[name + ", compiled"] = [float(x) for x in times[True]]
        out[name + ", trimesh subdivide"] = [float(x) for x in ref_here]
    # what a move sends to the browser: the indexed buffers against the three
    # rows per triangle (and two per edge) of the unindexed drawing
    from pentanb.viz.drawing import buffers, drawing, mesh_buffers

    for name in pb.SCHEMES:
        m = pb.subdivide(base, name, 1, 2)
        sent = mesh_buffers(m)
        flat = buffers(drawing(m))
        fields = ("position", "color", "normal", "index", "edge_position", "edge_color")
        fields += ("edge_index",)
        indexed = sum(getattr(sent, k).nbytes for k in fields)
        unindexed = sum(getattr(flat, k).nbytes for k in fields[:3] + fields[4:6])
        table.add(
            sec,
            f"bytes sent per move, {name}",
            indexed / 1e6,
            "MB",
            note=f"three rows per triangle: {unindexed / 1e6:.2f} MB ({unindexed / indexed:.2f}x)",
        )
    # the machine's speed: the issue's table has trimesh's subdivide() of this
    # mesh at 11 ms (and 170 ms at 327,680 triangles) where its targets were set
    ref_ms = 1000 * median(ref)
    table.add(
        sec,
        "trimesh subdivide(), same mesh, this machine (all runs)",
        ref_ms,
        "ms",
        note=f"{ref_ms / ISSUE_TRIMESH_MS:.1f}x the {ISSUE_TRIMESH_MS:g} ms of the issue's machine",
    )
    out["trimesh subdivide"] = [float(x) for x in ref]
    return out


def linear_times(runs: int, clock, compiled: bool = False, inputs_built=None) -> dict:
    """Seconds and page faults of the pipeline, small and large alternating, one process.

    ``inputs_built()``, if given, is called once the input arrays are built.
    """
    v1, f1 = icosphere(7)
    v2, f2 = icosphere(9)
    assert len(f1) == 327_680 and len(f2) == 5_242_880
    if inputs_built is not None:
        inputs_built()
    faults: dict[str, list[int]] = {"small": [], "large": []}

    def counted(name, v, f):
        def run():
            a = minor_faults()
            on_path(compiled, lambda: pipeline(v, f))()
            faults[name].append(minor_faults() - a)

        return run

    # alternate small and large, so that both see the same machine
    t = alternate(
        {"small": counted("small", v1, f1), "large": counted("large", v2, f2)}, runs, clock
    )
    return {
        "seconds": {k: [float(x) for x in xs] for k, xs in t.items()},
        "faults": {k: xs[1:] for k, xs in faults.items()},  # the warm-up round left out
        "faces": {"small": len(f1), "large": len(f2)},
    }


def per_face(run: dict) -> tuple[float, float]:
    """Median seconds per input face, small and large."""
    return tuple(  # type: ignore[return-value]
        median(run["seconds"][k]) / run["faces"][k] for k in ("small", "large")
    )


def linear_child(runs: int, clock_name: str, compiled: bool, env: dict[str, str]) -> dict | None:
    """``linear_times`` in a fresh child process with ``env``, and the resident peak of its runs."""
    import subprocess

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "linear.json"
        cmd = [sys.executable, __file__, "--runs", str(runs), "--clock", clock_name]
        cmd += ["--linear-times", str(out)] + (["--compiled"] if compiled else [])
        done = subprocess.run(cmd, env={**os.environ, **env}, capture_output=True)
        if done.returncode or not out.exists():
            print(done.stderr.decode()[-2000:], file=sys.stderr)
            return None
        return json.loads(out.read_text())


#: glibc's tunables that keep freed memory for reuse (set before Python starts):
#: arrays of any size from the heap, and the heap never trimmed.
KEEP_FREED = {
    "GLIBC_TUNABLES": "glibc.malloc.mmap_threshold=2147483647:"
    "glibc.malloc.trim_threshold=18446744073709551615"
}


def linear(table: Table, runs: int, clock, clock_name: str) -> dict:
    """Target 4: the pipeline's time per input face, 5,242,880 over 327,680 triangles.

    Each path (numpy, and compiled kernels where numba is installed) is
    measured in a fresh child process, as a user's script would run: both
    sizes built once, then run alternately ``runs`` times; the medians'
    ratio is the target's row.  The same again in children started with
    :data:`KEEP_FREED` (glibc's tunables) is a diagnosis row without target.
    """
    print("\nlinearity and memory: the pipeline at 327,680 and 5,242,880 triangles")
    sec = "linear and memory"
    run: dict = {}
    paths = [(False, "")] + ([(True, ", compiled kernels")] if COMPILED else [])
    for compiled, label in paths:
        for key, env, target in (("default", {}, 1.3), ("keep_freed", KEEP_FREED, None)):
            child = linear_child(runs, clock_name, compiled, env)
            if child is None:
                continue
            small, large = per_face(child)
            faults = 1000 * median(child["faults"]["large"]) / child["faces"]["large"]
            how = "fresh process" if not env else "fresh process with GLIBC_TUNABLES"
            name = f"4. per-face time 5,242,880 / 327,680{label}"
            if target is None:
                name = f"per-face time 5,242,880 / 327,680{label}, GLIBC_TUNABLES kept freed"
            table.add(
                sec,
                name,
                large / small,
                "x",
                target,
                note=f"{how}: {1e6 * small:.2f} and {1e6 * large:.2f} us per face; "
                f"{faults:.1f} page faults per 1,000 faces at 5,242,880; "
                f"resident peak {child['resident_peak'] / 2**30:.2f} GiB",
            )
            run[("compiled " if compiled else "") + key] = child
    mem = {}
    v2, f2 = icosphere(9)
    for label, (v, f) in {"1,310,720": icosphere(8), "5,242,880": (v2, f2)}.items():
        peak, out = peak_bytes(lambda v=v, f=f: pipeline(v, f))
        per = peak / out.n_faces
        mem[label] = peak
        table.add(
            sec,
            f"4. peak memory above the input, {label} triangles",
            per,
            "B/face",
            250.0,
            note=f"{peak / 2**20:,.0f} MiB for {out.n_faces:,} pentagons",
        )
        del out
    run["peak"] = mem
    return run


def guard(table: Table) -> dict:
    """Estimate against measured peak, per scheme, and the largest mesh allowed by default."""
    from pentanb import subdivision

    print("\nmemory guard: estimate / measured peak (subdivide, 1 iteration, 2 duals)")
    v, f = icosphere(6)
    limit = default_max_bytes()
    sec = f"memory guard (default limit {limit / 2**30:.1f} GiB: the memory available)"
    out = {}
    for name, s in pb.SCHEMES.items():
        base = pb.Mesh(v, f)
        est = subdivision.estimate_bytes(base, s, 2)
        peak, mesh = peak_bytes(lambda base=base, name=name: pb.subdivide(base, name, 1, 2))
        # the estimate is linear in the counts: scale the input until it reaches the limit
        scale = (limit - subdivision.FIXED) / (est - subdivision.FIXED)
        faces_out = mesh.n_faces * scale
        table.add(
            sec,
            f"{name} + 2 duals: estimate / measured peak",
            est / peak,
            "x",
            # triangulate keeps the icosphere's triangles: only its duals cost,
            # less than the dual's factor allows for (see pentanb.subdivision)
            None if name == "triangulate" else 3.0,
            note=f"largest by default: about {faces_out / 1e6:,.0f} M faces out, "
            f"{len(f) * scale / 1e6:,.1f} M triangles in",
        )
        out[name] = {"peak": peak, "estimate": est, "largest_output_faces": faces_out}
        del mesh
    return out


def io_rows(table: Table, runs: int, clock) -> dict:
    import trimesh

    v, f = torus_triangles(1000, 500)
    assert len(f) == 1_000_000
    mesh = pb.Mesh(v, f)
    tm = trimesh.Trimesh(v, f, process=False)
    print("\nOBJ and OFF, 1,000,000 triangles")
    sec = "files (1,000,000 triangles)"
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for fmt in ("obj", "off"):
            ours, theirs = Path(tmp, f"a.{fmt}"), Path(tmp, f"b.{fmt}")
            t = alternate(
                {
                    "write": lambda ours=ours: pb.write(mesh, ours),
                    "trimesh export": lambda theirs=theirs: tm.export(theirs),
                },
                runs,
                clock,
            )
            t.update(
                alternate(
                    {
                        "read": lambda ours=ours: pb.read(ours),
                        "trimesh load": lambda theirs=theirs: trimesh.load(
                            theirs, process=False, force="mesh"
                        ),
                    },
                    runs,
                    clock,
                )
            )
            w = median(t["write"]) / median(t["trimesh export"])
            r = median(t["read"]) / median(t["trimesh load"])
            table.add(
                sec,
                f"5. write {fmt.upper()} / trimesh export",
                w,
                "x",
                1.0,
                note=f"{1000 * median(t['write']):,.0f} ms",
            )
            table.add(
                sec,
                f"5. read {fmt.upper()} / trimesh load",
                r,
                "x",
                1.0,
                note=f"{1000 * median(t['read']):,.0f} ms",
            )
            peak, back = peak_bytes(lambda ours=ours: pb.read(ours))
            arrays = back.vertices.nbytes + back.corners.nbytes + back.offsets.nbytes
            table.add(
                sec,
                f"5. peak memory reading {fmt.upper()} / arrays read",
                peak / arrays,
                "x",
                3.0,
                note=f"{peak / 2**20:,.0f} MiB",
            )
            out[fmt] = {k: [float(x) for x in xs] for k, xs in t.items()}
    return out


def holed_grid(nx: int = 1050, ny: int = 1000, holes=(25, 20), size: int = 10):
    """A planar grid of nx x ny quads with ``holes[0] x holes[1]`` square holes of
    ``size`` x ``size`` quads, spread evenly (an open mesh; raw arrays)."""
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    v = np.stack([xs.ravel(), ys.ravel(), 0.01 * np.sin(xs.ravel() / 7.0)], axis=1)
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    keep = np.ones((nx, ny), dtype=bool)
    px, py = nx // holes[0], ny // holes[1]
    for a in range(holes[0]):
        for b in range(holes[1]):
            x0, y0 = a * px + (px - size) // 2, b * py + (py - size) // 2
            keep[x0 : x0 + size, y0 : y0 + size] = False
    i, j = i[keep], j[keep]
    a = i * (ny + 1) + j
    f = np.stack([a, a + ny + 1, a + ny + 2, a + 1], axis=1)
    used, f = np.unique(f, return_inverse=True)  # the vertices inside the holes left out
    return np.ascontiguousarray(v[used]), f.reshape(-1, 4)


def torus_quads(n: int, m: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed torus grid of n x m quads."""
    v, f = torus_triangles(n, m)
    # the triangles (a, b, c), (a, c, d) of every quad, merged back
    return v, np.stack([f[0::2, 0], f[0::2, 1], f[0::2, 2], f[1::2, 2]], axis=1)


def open_rows(table: Table, runs: int, clock) -> dict:
    """Target 6: the paper's two schemes + two duals on an open mesh against a closed one."""
    vo, fo = holed_grid()
    vc, fc = torus_quads(1000, 1000)
    assert len(fo) == len(fc) == 1_000_000
    m = pb.Mesh(vo, fo)
    assert not m.is_closed and pb.Mesh(vc, fc).is_closed
    print(
        f"\nopen against closed, 1,000,000 quads: a grid with {m.n_boundary_loops - 1} holes "
        f"({m.n_boundary_edges:,} boundary edges) and a torus; from raw arrays"
    )
    sec = "open meshes (1,000,000 quads)"
    out = {}
    # the constructor alone (validation: pairing, boundary loops, rings), a
    # diagnosis; then the target: a scheme + 2 duals from raw arrays; each on
    # the numpy path and, with numba, the compiled kernels, alternating
    jobs = {
        "Mesh(V, F)": (lambda v, f: pb.Mesh(v, f), None),
        "pentagonalize + 2 duals": (
            lambda v, f: pb.subdivide(pb.Mesh(v, f), "pentagonalize", 1, 2),
            1.25,
        ),
        "preserve_pentagons + 2 duals": (
            lambda v, f: pb.subdivide(pb.Mesh(v, f), "preserve_pentagons", 1, 2),
            1.25,
        ),
    }
    for name, (job, target) in jobs.items():
        # each path on its own, open and closed alternating: with the paths
        # interleaved, every open run followed a run of the other path and
        # every closed run the open run of its own, whose memory it took over
        # (see docs/performance.md); the targets' runs start from settled
        # memory, in an order drawn at random every round (see alternate)
        t: dict[str, list[float]] = {}
        user: dict[str, list[float]] = {}
        passes: dict[str, list[int]] = {}
        for compiled in (False, True) if COMPILED else (False,):
            suffix = ", compiled" if compiled else ""
            cases = {
                "open" + suffix: on_path(compiled, lambda job=job: job(vo, fo)),
                "closed" + suffix: on_path(compiled, lambda job=job: job(vc, fc)),
            }
            more: dict[str, list[float]] = {}
            seen: dict[str, list[int]] | None = {} if target is not None else None
            t.update(alternate(cases, runs, clock, more, balanced=True, settled=seen))
            user.update(more)
            passes.update(seen or {})
        for suffix in ("", ", compiled"):
            if "open" + suffix not in t:
                continue
            label = f"6. {name}, open / closed, per face" + (suffix and ", compiled kernels")
            to, tc = t["open" + suffix], t["closed" + suffix]
            po, pc = median(to) / len(fo), median(tc) / len(fc)
            caught = [sum(x > 0 for x in passes.get(k + suffix, ())) for k in ("open", "closed")]
            table.add(
                sec,
                label,
                po / pc,
                "x",
                target,
                note=f"{1e9 * po:,.0f} and {1e9 * pc:,.0f} ns per face; runs "
                f"{min(to) / median(tc):.2f}-{max(to) / median(tc):.2f} of the closed median"
                + (
                    f"; from settled memory, a reporting pass during {caught[0]} and "
                    f"{caught[1]} of {len(to)} and {len(tc)} runs"
                    if passes.get("open" + suffix)
                    else ""
                ),
            )
            if target is None:
                continue
            # a diagnosis without target: the same runs in CPU time (user mode),
            # the work without the kernel's handing over of fresh memory
            uo = median(user["open" + suffix]) / len(fo)
            uc = median(user["closed" + suffix]) / len(fc)
            table.add(
                sec,
                label + ", CPU time (user)",
                uo / uc,
                "x",
                note=f"{1e9 * uo:,.0f} and {1e9 * uc:,.0f} ns per face in the same runs",
            )
        out[name] = {k: [float(x) for x in xs] for k, xs in t.items()}
        out[name + ", CPU time (user)"] = {k: [float(x) for x in xs] for k, xs in user.items()}
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=7, help="timed runs per case (median)")
    ap.add_argument(
        "--clock",
        choices=sorted(CLOCKS),
        default="wall",
        help="wall time (default) or this process's CPU time",
    )
    ap.add_argument(
        "--quick",
        action="store_true",
        help="skip the 5-million-face rows (linearity, memory at that size)",
    )
    ap.add_argument(
        "--only",
        nargs="*",
        choices=["speed", "slider", "linear", "guard", "io", "open"],
        help="run only these sections",
    )
    ap.add_argument("--json", help="also write the measurements to this JSON file")
    ap.add_argument("--markdown", help="also write the table as markdown to this file")
    ap.add_argument("--check", action="store_true", help="exit 1 when a target is missed")
    ap.add_argument("--no-warm", action="store_true", help="skip the memory warm-up")
    ap.add_argument("--linear-times", help=argparse.SUPPRESS)  # the child of linear()
    ap.add_argument("--compiled", action="store_true", help=argparse.SUPPRESS)  # its path
    args = ap.parse_args(argv)
    try:
        import trimesh
    except ImportError:
        print("trimesh is needed for this benchmark: pip install -e .[bench]", file=sys.stderr)
        return 2
    if not args.no_warm:
        np.ones(400_000_000).sum()  # 3.2 GB, touched once and freed
    clock = CLOCKS[args.clock]
    _jit.use_jit(False)  # the numpy path, except where a row says "compiled kernels"
    if args.linear_times:  # linear()'s child process: the runs it was given
        done = linear_times(args.runs, clock, args.compiled, inputs_built=reset_resident_peak)
        done["resident_peak"] = resident_peak()
        Path(args.linear_times).write_text(json.dumps(done))
        return 0
    sections = set(args.only or ["speed", "slider", "linear", "guard", "io", "open"])
    if args.quick:
        sections.discard("linear")
    print(
        f"pentanb {pb.__version__}, trimesh {trimesh.__version__}, numpy {np.__version__}, "
        f"Python {platform.python_version()}, {platform.machine()}, {os.cpu_count()} cores, "
        f"{os.sysconf('SC_PAGE_SIZE') * os.sysconf('SC_PHYS_PAGES') / 2**30:.0f} GiB; "
        f"{args.clock} clock, "
        f"median of {args.runs} runs"
    )
    table = Table()
    results: dict = {}
    if "speed" in sections:
        results["speed"] = speed(table, args.runs, clock)
    if "slider" in sections:
        results["slider"] = slider(table, max(args.runs, 15), clock)
    if "linear" in sections:
        results["linear"] = linear(table, max(3, args.runs // 2), clock, args.clock)
    if "guard" in sections:
        results["guard"] = guard(table)
    if "io" in sections:
        results["io"] = io_rows(table, max(3, args.runs // 2), clock)
    if "open" in sections:
        results["open"] = open_rows(table, max(5, args.runs), clock)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"rows": table.rows, "runs": results}, fh, indent=2)
    if args.markdown:
        Path(args.markdown).write_text(table.markdown() + "\n")
    missed = table.missed
    print("\n" + ("every target met" if not missed else "missed: " + "; ".join(missed)))
    return 1 if (missed and args.check) else 0


if __name__ == "__main__":
    sys.exit(main())
