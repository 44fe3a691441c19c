"""Benchmark: the continuity table of issue 9 (target: under 30 s on 2 cores).

Times :func:`pentanb.analysis.spectral.continuity_table` -- every scheme of
``pentanb.SCHEMES`` (pentagon preservation at scales 0.75 and 0.5) with two
duals, at vertices of valence 3 to 8 and faces of 3 to 8 sides, each with its
characteristic map -- and prints the slowest rows.

OpenBLAS may start threads for the small eigenproblems; on a loaded machine
run with ``OPENBLAS_NUM_THREADS=1`` for steadier numbers.

Run::

    python benchmarks/bench_continuity.py            # prints the timings
    python benchmarks/bench_continuity.py --check    # exit 1 when over 30 s
    python benchmarks/bench_continuity.py --table    # also print the markdown table
"""

from __future__ import annotations

import sys
import time

from pentanb.analysis.spectral import continuity_table, table_markdown

TARGET_SECONDS = 30.0


def main(argv: list[str]) -> int:
    times: list[tuple[float, str]] = []
    last = [time.perf_counter()]

    def tick(line: str) -> None:
        now = time.perf_counter()
        times.append((now - last[0], line.split(":")[0]))
        last[0] = now

    start = time.perf_counter()
    rows = continuity_table(progress=tick)
    total = time.perf_counter() - start
    print(f"continuity table: {len(rows)} rows in {total:.1f} s (target {TARGET_SECONDS:.0f} s)")
    for seconds, what in sorted(times, reverse=True)[:5]:
        print(f"  {seconds:6.2f} s  {what}")
    if "--table" in argv:
        print(table_markdown(rows))
    return int("--check" in argv and total > TARGET_SECONDS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
