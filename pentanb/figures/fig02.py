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
from .claim import Claim, exact, vef

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

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
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
    a, b, c = p["A"], p["B"], p["C"]
    same = (
        b.n_vertices == c.n_vertices
        and b.n_halfedges == c.n_halfedges
        and np.array_equal(b.vertices, c.vertices)
        and np.array_equal(b.corners, c.corners)
        and np.array_equal(b.offsets, c.offsets)
    )
    n_tri = a.face_size_histogram().get(3, 0)
    fanned = int(a.face_sizes[a.face_sizes > 3].sum())
    return [
        exact(
            "fig02.B.triangles",
            "Figure 2.B",
            "(B) is obtained by subdividing each non-triangular face into triangles",
            "(B) (V, E, F) and faces by size, against a centre in every non-triangle of (A) "
            "and a triangle on each of its sides",
            (
                (
                    a.n_vertices + int((a.face_sizes > 3).sum()),
                    a.n_edges + fanned,
                    n_tri + fanned,
                ),
                {3: n_tri + fanned},
            ),
            (vef(b), b.face_size_histogram()),
            reading="every face that is not a triangle gets a vertex inside, joined to its "
            "corners; triangles stay",
            cause="the simplest triangulation",
        ),
        exact(
            "fig02.C.null",
            "Section 3, Figure 2",
            "after the first iteration it does not change the mesh (i.e., it becomes null "
            "algorithm)",
            "(C) = the triangulation of (B) is (B) itself (same positions and faces)",
            True,
            bool(same),
            reading="applied again to its own output, the triangulation changes nothing",
            cause="the simplest triangulation",
        ),
    ]
