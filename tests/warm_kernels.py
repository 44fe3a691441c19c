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

from helpers import holed_grid

import pentanb
from pentanb import Mesh, shapes
from pentanb.viz import drawing


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
        Mesh(*holed_grid(90, 90, [(22, 22), (22, 67), (67, 22), (67, 67)], 6)),  # open quads
        pentanb.preserve_pentagons(Mesh(*holed_grid(40, 40, [(10, 10), (30, 30)], 6))),  # mixed
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
