"""Calibrate the memory guard: measure every scheme's peak memory and fit its model.

:func:`pentanb.subdivide` refuses, before building anything, a request whose
peak memory would exceed ``max_bytes``.  The peak it predicts comes from
:data:`pentanb.subdivision.MEMORY_MODEL`, two linear forms per scheme and
number of duals (0, 1, 2 or more) in the counts ``(1, V, E, F)`` of the
input of an iteration:

* ``step``: the peak of one iteration (remesh, then the duals) above its
  input, the input being a mesh as the constructor leaves it;
* ``hold``: what the input of a later iteration (built by the earlier ones,
  inside the same call) adds to that, in the counts of that input.

This script measures those peaks (numpy's allocations, as ``tracemalloc``
counts them) on tori (quads), icospheres (triangles), pentagonal and mixed
meshes of several sizes, fits the forms by least squares, raises each just
enough to bound every measurement, and prints the table to paste into
``pentanb/subdivision.py``, with the worst ratios of estimate to measured
peak (the guard's promise: ``peak <= estimate <= 1.25 peak``).

Run::

    python benchmarks/calibrate_memory.py            # about ten minutes
"""

from __future__ import annotations

import gc
import sys
import tracemalloc

import numpy as np

import pentanb as pb
from pentanb import shapes, subdivision
from pentanb.subdivision import predict_counts, regressors


def peak(fn, mesh=None) -> int:
    """Peak of numpy's (and Python's) allocations during ``fn(mesh)``, above what was held before.

    ``mesh`` is built before the measure starts (its own validation not counted).
    """
    gc.collect()
    tracemalloc.start()
    base = tracemalloc.get_traced_memory()[0]
    tracemalloc.reset_peak()
    out = fn() if mesh is None else fn(mesh)
    p = tracemalloc.get_traced_memory()[1] - base
    tracemalloc.stop()
    del out
    return p


def fresh(m: pb.Mesh) -> pb.Mesh:
    """The same mesh as the constructor leaves it (twins and vertex rings derived)."""
    return pb.Mesh.from_csr(m.vertices, m.corners, m.offsets)


def icosphere(k: int) -> pb.Mesh:
    m = shapes.icosahedron()
    for _ in range(k):
        m = pb.loop_remesh(m)
    return fresh(m.with_vertices(m.vertices / np.linalg.norm(m.vertices, axis=1)[:, None]))


def corpus() -> dict[str, pb.Mesh]:
    """Meshes of 20,000 to 250,000 half-edges: quads, triangles, pentagons, mixed."""
    return {
        "torus 80x60": shapes.torus(80, 60),
        "torus 150x100": shapes.torus(150, 100),
        "torus 300x200": shapes.torus(300, 200),
        "icosphere 5": icosphere(5),
        "icosphere 6": icosphere(6),
        "cube, vertex insertion x5": fresh(pb.subdivide(shapes.cube(), "vertex_insertion", 5, 0)),
        "pentagonal 4": fresh(pb.subdivide(shapes.dodecahedron(), "pentagonalize", 4)),
        "pentagonal 5": fresh(pb.subdivide(shapes.dodecahedron(), "pentagonalize", 5)),
        "mixed 4": fresh(pb.subdivide(shapes.cube(), "preserve_pentagons", 4, 0)),
        "mixed 5": fresh(pb.subdivide(shapes.cube(), "preserve_pentagons", 5, 0)),
        "triangles 100x80": fresh(pb.triangulate(shapes.torus(100, 80))),
        "triangles 300x200": fresh(pb.triangulate(shapes.torus(300, 200))),
        "dodecahedron, honeycomb x6": fresh(pb.subdivide(shapes.dodecahedron(), "honeycomb", 6, 0)),
    }


def small_corpus() -> dict[str, pb.Mesh]:
    """Smaller meshes, for two iterations (their second input is 3 to 6 times larger)."""
    return {
        "torus 60x50": shapes.torus(60, 50),
        "icosphere 4": icosphere(4),
        "pentagonal 3": fresh(pb.subdivide(shapes.dodecahedron(), "pentagonalize", 3)),
        "mixed 3": fresh(pb.subdivide(shapes.cube(), "preserve_pentagons", 3, 0)),
        "triangles 60x50": fresh(pb.triangulate(shapes.torus(60, 50))),
    }


def is_triangles(m: pb.Mesh) -> bool:
    return 2 * m.n_edges == 3 * m.n_faces


def fit(A: np.ndarray, y: np.ndarray, fixed: float = 0.0) -> np.ndarray:
    """Non-negative least squares, then raised just enough to bound every ``y``.

    Fitted on ``y`` minus ``fixed``, the part every estimate has already
    (:data:`pentanb.subdivision._FIXED` for the step forms).
    """
    from scipy.optimize import nnls

    if len(y) == 0:
        return np.zeros(A.shape[1])
    y = np.maximum(y - fixed, 0)
    # relative errors: every mesh counts alike, whatever its size
    w = 1.0 / np.maximum(y, 1.0)
    scale = np.maximum((A * w[:, None]).max(axis=0), 1e-30)  # columns of similar size for nnls
    coef = nnls(A * w[:, None] / scale, np.ones_like(y) * (y > 0))[0] / scale
    est = A @ coef
    uncovered = (est <= 0) & (y > 0)
    if uncovered.any():  # nothing fitted there: the edges pay for it
        coef[1] += float(np.max(y[uncovered] / A[uncovered, 1]))
        est = A @ coef
    ok = est > 0
    if ok.any():
        coef *= max(1.0, float(np.max(y[ok] / est[ok])))
    return coef


def fit_hold(B: np.ndarray, z: np.ndarray) -> np.ndarray:
    """One term, in the edges of the later input, bounding every ``z`` (with 1% room).

    Of either sign (an input built by the call may have derived arrays
    already, and cost less than a fresh one), and deliberately simple:
    the few two-iteration measurements cannot pin more terms down, and
    more would extrapolate wildly.
    """
    coef = np.zeros(B.shape[1])
    if len(z):
        coef[1] = float(np.max((z + 0.01 * np.abs(z)) / np.maximum(B[:, 1], 1)))
    return coef


def main() -> int:
    meshes, small = corpus(), small_corpus()
    entries = [*pb.SCHEMES, "triangulate (triangles)"]
    model = {e: {d: [np.zeros(7), np.zeros(7)] for d in (0, 1, 2)} for e in entries}
    fits = {}

    def entry_of(name, counts):
        return subdivision._model_name(pb.SCHEMES[name], counts)

    # the loops below bind name and d through default arguments of their lambdas

    # one iteration: the step forms
    for name in pb.SCHEMES:
        for d in (0, 1, 2):
            by_entry: dict = {}
            for m in meshes.values():
                counts = (m.n_vertices, m.n_edges, m.n_faces)
                p = peak(
                    lambda x, n=name, d=d: pb.subdivide(x, n, 1, d, max_bytes=np.inf), fresh(m)
                )
                rows, y = by_entry.setdefault(entry_of(name, counts), ([], []))
                rows.append(regressors(counts, name, subdivision._kind_of(m)))
                y.append(p)
            for entry, (rows, y) in by_entry.items():
                A, y = np.array(rows, float), np.array(y, float)
                model[entry][d][0] = fit(A, y, subdivision._FIXED)
                fits[entry, d] = [
                    (subdivision._MARGIN * (A @ model[entry][d][0]) + subdivision._FIXED) / y
                ]
    install(model)
    # two iterations: the hold forms, in the counts of the second input
    for name in pb.SCHEMES:
        for d in (0, 1, 2):
            by_entry = {}
            for m in small.values():
                counts = (m.n_vertices, m.n_edges, m.n_faces)
                later = predict_counts(counts, name, 1, d, max_bytes=np.inf)[-1]
                kind = subdivision._kind_after(pb.SCHEMES[name], subdivision._kind_of(m), d)
                p2 = peak(
                    lambda x, n=name, d=d: pb.subdivide(x, n, 2, d, max_bytes=np.inf), fresh(m)
                )
                step2 = subdivision._iteration_bytes(
                    pb.SCHEMES[name], later, d, later=False, kind=kind
                )
                rows, z = by_entry.setdefault(entry_of(name, later), ([], []))
                rows.append(regressors(later, name, kind))
                z.append(p2 - step2)
            for entry, (rows, z) in by_entry.items():
                B, z = np.array(rows, float), np.array(z, float)
                model[entry][d][1] = fit_hold(B, z)
    install(model)
    for name in pb.SCHEMES:
        for d in (0, 1, 2):
            r2 = []
            for m in small.values():
                counts = (m.n_vertices, m.n_edges, m.n_faces)
                est = subdivision._request_bytes(
                    pb.SCHEMES[name], counts, 2, d, subdivision._kind_of(m)
                )
                p2 = peak(
                    lambda x, n=name, d=d: pb.subdivide(x, n, 2, d, max_bytes=np.inf), fresh(m)
                )
                r2.append(est / p2)
            r1 = np.concatenate(
                [fits[e, d][0] for e in entries if (e, d) in fits and e.split()[0] == name]
            )
            print(
                f"{name:20s} duals {d}: estimate/peak one iteration {r1.min():.3f}-{r1.max():.3f},"
                f" two {min(r2):.3f}-{max(r2):.3f}",
                flush=True,
            )
    print("\nMEMORY_MODEL: dict[str, dict[int, tuple[Form, Form]]] = {")
    for entry, per in model.items():
        print(f"    {entry!r}: {{")
        for d, (step, hold) in per.items():
            a = ", ".join(f"{c:.1f}" for c in step)
            b = ", ".join(f"{c:.1f}" for c in hold)
            print(f"        {d}: (({a}), ({b})),")
        print("    },")
    print("}")
    return 0


def install(model) -> None:
    """Use ``model`` in this process (for the second round of the fit)."""
    for entry, per in model.items():
        subdivision.MEMORY_MODEL[entry] = {
            d: (tuple(float(c) for c in step), tuple(float(c) for c in hold))
            for d, (step, hold) in per.items()
        }


if __name__ == "__main__":
    sys.exit(main())
