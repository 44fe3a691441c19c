"""Compile pentanb's numba kernels into numba's disk cache, once, before a test run.

``tests/conftest.py`` runs this script (two processes, each half of the work)
before pytest-xdist starts its workers, when numba is installed.  Each kernel
is compiled for the argument types a test run gives it: every scheme with
its duals, on closed and open meshes of each face size, the constructor's
pairing, the drawings' buffers.  Without it, every worker and every notebook
kernel of a fresh clone compiles the same kernels side by side.  (The cache is
the one the package uses anyway: ``__pycache__`` beside ``pentanb/_kernels.py``;
nothing else is written.)

Usage: ``python tests/warm_kernels.py [PART PARTS]`` (default: all of it).
"""

from __future__ import annotations

import sys

import numpy as np

import pentanb
from pentanb import Mesh, shapes
from pentanb.viz import drawing


def holed_grid(n: int = 90, hole: int = 6) -> Mesh:
    """An open n x n grid of quads with a square hole in each quarter."""
    xs, ys = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0), indexing="ij")
    vertices = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    cut = np.zeros((n, n), dtype=bool)
    for a in (n // 4, 3 * n // 4):
        for b in (n // 4, 3 * n // 4):
            cut[a : a + hole, b : b + hole] = True
    i, j = i[~cut], j[~cut]
    v = i * (n + 1) + j
    faces = np.stack([v, v + n + 1, v + n + 2, v + 1], axis=1)
    used = np.unique(faces)
    renumber = np.full(vertices.shape[0], -1)
    renumber[used] = np.arange(used.size)
    return Mesh(vertices[used], renumber[faces])


def inputs() -> list[Mesh]:
    """Closed and open meshes of every face size the schemes meet, large enough for the kernels."""
    tri = shapes.icosahedron()
    for _ in range(4):
        tri = pentanb.loop_remesh(tri)
    return [
        shapes.torus(120, 80),  # quads
        tri,  # triangles
        pentanb.subdivide(shapes.cube(), "preserve_pentagons", 4, 0),  # mixed faces
        shapes.hexagonal_torus(60, 50),  # hexagons
        holed_grid(),  # open quads
        pentanb.subdivide(holed_grid(40), "preserve_pentagons", 1, 0),  # open, mixed
    ]


def warm(part: int = 0, parts: int = 1) -> None:
    """Run every scheme with two duals on :func:`inputs`, and draw their outputs
    (``part`` of ``parts``: the schemes dealt round)."""
    meshes = inputs()
    names = list(pentanb.SCHEMES)[part::parts]
    for m in meshes:
        again = Mesh.from_csr(m.vertices, m.corners, m.offsets)  # validated: the pairing
        for name in names:
            out = pentanb.subdivide(again, name, 1, 2)
            if name == names[0]:
                drawing.mesh_buffers(out)
                drawing.vertex_normals(out)
                drawing.frame_fits(drawing.IDENTITY, out.vertices)


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:3]]
    warm(*args)
