"""Benchmark: pentagonalize (and + two duals) against trimesh's subdivision.

Times, in one run on the same input, medians of several runs:

* ``pentagonalize`` against ``trimesh.Trimesh.subdivide()`` on a
  327,680-triangle sphere (target: within 2x);
* ``pentagonalize`` followed by two duals against
  ``trimesh.remesh.subdivide_loop`` on the same sphere (target: half the time
  or less);
* ``pentagonalize`` + two duals on a 20,480-face sphere (target: under 30 ms,
  the budget of one slider move);
* and, for reference, every scheme of ``pentanb.SCHEMES`` on the 20,480-face
  sphere.

Every timed call starts from a mesh with no cached connectivity (pentanb
derives its half-edges inside the timer; trimesh gets a fresh ``Trimesh``),
so both sides pay for their edge tables.  Before timing, the script touches
a few GB of memory once: on a freshly booted virtual machine the first touch
of every page is several times slower than later ones, which would otherwise
penalise whichever side runs first.

Run::

    pip install -e .[bench]
    python benchmarks/bench_pipeline.py            # prints a table and the ratios
    python benchmarks/bench_pipeline.py --check    # exit 1 when a target is missed
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time

import numpy as np

import pentanb as pb


def median_time(fn, setup, runs):
    """Median wall time of ``fn(setup())`` over ``runs`` runs (setup untimed)."""
    times = []
    fn(setup())  # warm-up
    for _ in range(runs):
        arg = setup()
        t = time.perf_counter()
        fn(arg)
        times.append(time.perf_counter() - t)
    return float(np.median(times))


def fresh(mesh: pb.Mesh):
    """A setup function: the mesh's arrays with nothing derived yet."""
    return lambda: pb.Mesh.from_csr(mesh.vertices, mesh.corners, mesh.offsets, validate=False)


def pipeline(mesh):
    return pb.dual(pb.dual(pb.pentagonalize(mesh)))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=7, help="timed runs per case (median)")
    ap.add_argument("--json", help="also write the results to this JSON file")
    ap.add_argument("--check", action="store_true", help="exit 1 when a target is missed")
    ap.add_argument("--no-warm", action="store_true", help="skip the memory warm-up")
    args = ap.parse_args(argv)
    try:
        import trimesh
        from trimesh import remesh
    except ImportError:
        print("trimesh is needed for this benchmark: pip install -e .[bench]", file=sys.stderr)
        return 2

    if not args.no_warm:
        np.ones(400_000_000).sum()  # 3.2 GB, touched once and freed

    big_tm = trimesh.creation.icosphere(subdivisions=7)
    small_tm = trimesh.creation.icosphere(subdivisions=5)
    big = pb.Mesh(big_tm.vertices, big_tm.faces)
    small = pb.Mesh(small_tm.vertices, small_tm.faces)
    assert big.n_faces == 327_680 and small.n_faces == 20_480
    v, f = np.asarray(big_tm.vertices), np.asarray(big_tm.faces)

    def fresh_trimesh():
        return trimesh.Trimesh(v, f, process=False)

    r = args.runs
    t = {
        "trimesh_subdivide": median_time(lambda m: m.subdivide(), fresh_trimesh, r),
        "trimesh_subdivide_loop": median_time(
            lambda m: remesh.subdivide_loop(m.vertices, m.faces), fresh_trimesh, r
        ),
        "pentagonalize": median_time(pb.pentagonalize, fresh(big), r),
        "pentagonalize_2duals": median_time(pipeline, fresh(big), r),
        "pentagonalize_2duals_20480": median_time(pipeline, fresh(small), max(r, 15)),
    }
    per_scheme = {
        name: median_time(lambda m, s=s: pb.dual(pb.dual(s(m))), fresh(small), r)
        for name, s in pb.SCHEMES.items()
    }

    ratios = {
        "pentagonalize / trimesh subdivide": (t["pentagonalize"] / t["trimesh_subdivide"], 2.0),
        "pentagonalize+2 duals / trimesh subdivide_loop": (
            t["pentagonalize_2duals"] / t["trimesh_subdivide_loop"],
            0.5,
        ),
    }
    print(
        f"pentanb {pb.__version__}, trimesh {trimesh.__version__}, numpy {np.__version__}, "
        f"Python {platform.python_version()}, {platform.machine()}; median of {r} runs"
    )
    print("\n327,680-triangle sphere")
    for key in (
        "trimesh_subdivide",
        "trimesh_subdivide_loop",
        "pentagonalize",
        "pentagonalize_2duals",
    ):
        print(f"  {key:32s} {1000 * t[key]:9.1f} ms")
    print("\nratios (target)")
    missed = []
    for label, (value, target) in ratios.items():
        ok = value <= target
        missed += [] if ok else [label]
        print(f"  {label:48s} {value:6.2f}  (<= {target})  {'PASS' if ok else 'MISS'}")
    ms = 1000 * t["pentagonalize_2duals_20480"]
    ok = ms < 30.0
    missed += [] if ok else ["20,480-face pipeline"]
    print(
        f"\n20,480-face pentagonalize + 2 duals: {ms:.1f} ms (< 30 ms) {'PASS' if ok else 'MISS'}"
    )
    print("\nevery scheme + 2 duals on the 20,480-face sphere")
    for name, sec in per_scheme.items():
        print(f"  {name:20s} {1000 * sec:8.1f} ms")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(
                {
                    "seconds": t,
                    "per_scheme_20480": per_scheme,
                    "ratios": {k: v for k, (v, _) in ratios.items()},
                },
                fh,
                indent=2,
            )
    if missed and args.check:
        print("missed: " + ", ".join(missed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
