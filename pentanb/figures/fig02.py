"""Figure 2: the simplest triangulation cannot be used iteratively.

(A) a cube, (B) every non-triangle fanned into triangles
(:func:`pentanb.triangulate`), (C) the same applied again: nothing changes.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from .. import shapes
from ..mesh import Mesh
from ..schemes.classic import triangulate
from .claim import Claim, eq, vef

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Simplest triangulation"
CAPTION = (
    "An example of simplest triangulization that cannot be used iteratively. (A) is "
    "the initial mesh and (B) is obtained by subdividing each non-triangular face "
    "into triangles."
)
LABELS = ("A", "B", "C")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 2: ``{"A": cube, "B": triangulated, "C": triangulated again}``."""
    a = shapes.cube()
    b = triangulate(a)
    return {"A": a, "B": b, "C": triangulate(b)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 2: the simplest triangulation (A -> B) and a second application (C).

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.
    """
    from ._draw import mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "initial mesh", {}),
            (p["B"], "non-triangles split", {}),
            (p["C"], "applied again: no change", {}),
        ],
        suptitle="Figure 2. The simplest triangulation cannot be used iteratively",
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 2, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    b, c = p["B"], p["C"]
    same = (
        np.array_equal(b.vertices, c.vertices)
        and np.array_equal(b.corners, c.corners)
        and np.array_equal(b.offsets, c.offsets)
    )
    return [
        eq(
            "(B) every non-triangle of the cube fanned into triangles: (V, E, F), faces",
            ((8 + 6, 12 + 24, 24), {3: 24}),
            (vef(b), b.face_size_histogram()),
        ),
        eq(
            "(C) a second application changes nothing (null algorithm): identical mesh",
            True,
            bool(same),
        ),
        eq("(C) the number of vertices stops growing", b.n_vertices, c.n_vertices),
    ]
