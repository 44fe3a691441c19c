"""The explorer's calibrated constants: seconds per face built, and bytes of an exported page.

Run from the repository root::

    PYTHONPATH=$PWD python benchmarks/bench_explorer.py [--pages]

1. ``Explorer.SECONDS_PER_FACE``: one level (two duals) of several schemes
   on meshes of 50,000 to 4,000,000 faces built, through the explorer's own
   path (``mesh_at`` and the view's buffers), timed and divided by the faces
   of every step (``predicted_seconds`` with one second per face).  The
   constant should stay above the medians, so that work predicted under
   half a second is under it.
2. ``--pages``: the size and time of ``export_html`` of ``explore("cube")``
   and ``explore("rabbit")``, offline and online, with the default budget.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import pentanb
from pentanb.viz import explorer, html

CASES = [
    ("torus", "pentagonalize", 4),
    ("torus", "pentagonalize", 5),
    ("torus", "preserve_pentagons", 4),
    ("torus", "preserve_pentagons", 5),
    ("rabbit", "loop_remesh", 5),
    ("rabbit", "vertex_insertion", 5),
    ("dodecahedron", "honeycomb", 8),
]


def per_face() -> None:
    # the compiled kernels' first use in the process (compiling) is not timed
    warm = pentanb.explore("torus", iterations=0, max_iterations=3)
    warm.iterations.value = 3
    warm.close()
    rows = []
    for shape, scheme, level in CASES:
        e = pentanb.explore(
            shape, scheme, iterations=level - 1, max_iterations=level, max_faces=10**8
        )
        e.seconds_per_face = 1.0
        faces = e.predicted_seconds(level)
        t = time.perf_counter()
        e.iterations.value = level
        dt = time.perf_counter() - t
        rows.append(dt / faces)
        print(
            f"{shape:>13} {scheme:>18} level {level}: {faces:>12,.0f} faces built, "
            f"{dt:6.3f} s, {dt / faces * 1e9:5.0f} ns per face"
        )
        e.close()
    print(
        f"median {statistics.median(rows) * 1e9:.0f} ns, max {max(rows) * 1e9:.0f} ns; "
        f"SECONDS_PER_FACE = {explorer.Explorer.SECONDS_PER_FACE * 1e9:.0f} ns"
    )


def pages() -> None:
    folder = Path(tempfile.mkdtemp())
    for shape in ("cube", "rabbit"):
        for offline in (True, False):
            e = pentanb.explore(shape)
            t = time.perf_counter()
            path = html.export_html(e, folder / f"{shape}-{offline}.html", offline=offline)
            dt = time.perf_counter() - t
            kind = "offline" if offline else "online"
            print(f"{shape:>6} {kind:>7}: {path.stat().st_size:>12,} bytes, {dt:5.1f} s")
            e.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pages", action="store_true", help="also export pages")
    args = parser.parse_args()
    per_face()
    if args.pages:
        pages()


if __name__ == "__main__":
    main()
