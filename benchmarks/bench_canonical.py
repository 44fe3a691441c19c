"""Benchmark: canonical and planar positions of Conway polyhedra (issue 10).

Issue 10 asks that :func:`pentanb.notation.canonical` and
:func:`pentanb.notation.planarize` converge on every seed and on every
operator string of length up to 4 from the seeds, in under a second for
meshes of a few hundred faces.  This script

* times both on a table of named strings (median of several runs), and
* with ``--enumerate N`` runs both on *every* string of at most N operators
  (the issue's 18 letters, ``r`` left out: a mirror image has the mirror
  canonical form) on the given seeds, one string per class of the exact
  rewrites of ``pentanb.notation.REDUCTIONS``, results of at most
  ``--max-faces`` faces, and reports failures, timings and the slowest
  strings.

Run::

    python benchmarks/bench_canonical.py                       # the table
    python benchmarks/bench_canonical.py --enumerate 3         # ~8,000 strings
    python benchmarks/bench_canonical.py --enumerate 2 --check # exit 1 on a
        # failure or on a mesh of <= 500 faces taking more than a second
"""

from __future__ import annotations

import argparse
import itertools
import json
import platform
import sys
import time

import numpy as np

from pentanb.notation import OPERATORS, canonical, conway, planarize, reduce_notation
from pentanb.notation.build import _counts

TABLE = [
    "tI", "sC", "gC", "pT", "ddgT", "zD", "cD", "wD", "qgC", "ggD", "cwD", "gggC",
    "wwD", "ucD", "k4P12", "bY9",
]  # fmt: skip


def median_time(fn, runs: int) -> float:
    fn()
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return float(np.median(times))


def table(runs: int) -> list[dict]:
    rows = []
    for text in TABLE:
        m = conway(text)
        _, rep = canonical(m, report=True)
        _, rep2 = planarize(m, report=True)
        rows.append(
            {
                "string": text,
                "faces": m.n_faces,
                "canonical_s": median_time(lambda m=m: canonical(m), runs),
                "planarize_s": median_time(lambda m=m: planarize(m), runs),
                "canonical_newton_steps": rep.iterations,
                "planarize_steps": rep2.iterations,
                "planarize_max_move": rep2.max_move,
                "converged": rep.converged and rep2.converged,
            }
        )
    return rows


def enumerate_strings(depth: int, seeds: list[str], max_faces: int) -> dict:
    letters = [c for c in OPERATORS if c != "r"]
    seen: set[str] = set()
    failures, times, slow, slow_p = [], [], [], []
    start = time.perf_counter()
    for k in range(depth + 1):
        for ops in itertools.product(letters, repeat=k):
            for seed in seeds:
                text = "".join(ops) + seed
                if _counts(text)[0][-1][2] > max_faces:
                    continue
                key = reduce_notation(text)
                if key in seen:
                    continue
                seen.add(key)
                m = conway(text)
                t = time.perf_counter()
                _, rep = canonical(m, report=True)
                tc = time.perf_counter() - t
                t = time.perf_counter()
                _, rep2 = planarize(m, report=True)
                tp = time.perf_counter() - t
                times.append((m.n_faces, tc, tp))
                slow.append((tc, text, m.n_faces))
                slow_p.append((tp, text, m.n_faces, rep2.iterations, round(rep2.max_move, 3)))
                if not (rep.converged and rep2.converged):
                    failures.append((text, rep.message, rep2.message))
    t = np.array(times)
    bins = {}
    for lo, hi in [(0, 100), (100, 300), (300, 600), (600, 10**9)]:
        sel = (t[:, 0] > lo) & (t[:, 0] <= hi)
        if sel.any():
            bins[f"{lo}-{hi if hi < 10**9 else ''} faces"] = {
                "strings": int(sel.sum()),
                "canonical_median_s": float(np.median(t[sel, 1])),
                "canonical_max_s": float(t[sel, 1].max()),
                "planarize_median_s": float(np.median(t[sel, 2])),
                "planarize_max_s": float(t[sel, 2].max()),
            }
    slow.sort(reverse=True)
    slow_p.sort(reverse=True)
    return {
        "depth": depth,
        "seeds": seeds,
        "max_faces": max_faces,
        "strings": len(seen),
        "failures": failures,
        "wall_s": time.perf_counter() - start,
        "by_size": bins,
        "slowest_canonical": [(s, f, round(x, 3)) for x, s, f in slow[:10]],
        "slowest_planarize": [(s, f, round(x, 3), i, mv) for x, s, f, i, mv in slow_p[:10]],
        "over_1s_at_most_500_faces": [
            (s, f, round(x, 3)) for x, s, f in slow if x > 1.0 and f <= 500
        ]
        + [(s, f, round(x, 3)) for x, s, f, _, _ in slow_p if x > 1.0 and f <= 500],
    }


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--enumerate", type=int, default=0, metavar="N")
    p.add_argument("--seeds", default="T,C,O,I,D")
    p.add_argument("--max-faces", type=int, default=300)
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--json", action="store_true")
    p.add_argument("--check", action="store_true")
    args = p.parse_args(argv)
    out: dict = {"python": platform.python_version(), "machine": platform.machine()}
    canonical(conway("C"))  # imports scipy once, outside any timing
    if args.enumerate:
        out["enumeration"] = enumerate_strings(
            args.enumerate, args.seeds.split(","), args.max_faces
        )
    else:
        out["table"] = table(args.runs)
    if args.json:
        print(json.dumps(out, indent=1))
    elif "table" in out:
        print(f"{'string':>8} {'faces':>6} {'canonical':>10} {'planarize':>10} {'move':>6}")
        for r in out["table"]:
            print(
                f"{r['string']:>8} {r['faces']:>6} {1000 * r['canonical_s']:8.1f}ms "
                f"{1000 * r['planarize_s']:8.1f}ms {r['planarize_max_move']:6.3f}"
                + ("" if r["converged"] else "  NOT CONVERGED")
            )
    else:
        e = out["enumeration"]
        print(
            f"{e['strings']} strings (up to {e['depth']} operators on {','.join(e['seeds'])}, "
            f"<= {e['max_faces']} faces) in {e['wall_s']:.0f} s; failures: {len(e['failures'])}"
        )
        for k, v in e["by_size"].items():
            print(f"  {k:>14}: {v}")
        print("  slowest canonical:", e["slowest_canonical"])
        print("  slowest planarize:", e["slowest_planarize"])
        for f in e["failures"][:20]:
            print("  FAILED", f)
    if args.check:
        bad = []
        if "enumeration" in out:
            e = out["enumeration"]
            bad = e["failures"] + e["over_1s_at_most_500_faces"]
        else:
            bad = [r for r in out["table"] if not r["converged"]]
            bad += [r for r in out["table"] if r["faces"] <= 500 and r["canonical_s"] > 1.0]
        return 1 if bad else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
