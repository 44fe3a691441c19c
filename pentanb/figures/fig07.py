"""Figure 7: conversion of a tetrahedron to a dodecahedron by pentagonalization.

(A) the tetrahedron, (B) pentagonalized (a dodecahedron), (C) its dual, (D)
the dual of (C), (E) the 5th and (F) the 6th dual.  The claims: (B) is a
dodecahedron, and the shape becomes more uniform with each pair of duals,
(B) -> (D) -> (F), by three measures: the spread of the edge lengths, of
the face angles and of the vertices' distances from the centre.  (That the
duals alternate between dodecahedral and icosahedral is the definition of
the dual, not a claim.)
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import angle_spread, edge_length_spread, radius_spread
from ..mesh import Mesh
from ..schemes.pentagonal import pentagonalize
from ..schemes.smoothing import dual
from .claim import FAILS, HOLDS, Claim, exact, monotone_claim, vef

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Tetrahedron to dodecahedron"
CAPTION = (
    "Conversion of a tetrahedron to a dodecahedron by the pentagonalization scheme. "
    "(A) is the original tetrahedron. (B) is the dodecahedral shape after the "
    "application of pentagonalization scheme. (C) is the icosahedral dual of (B). "
    "(D) is the dodecahedral shape that is the dual of (C). (E) is the 5th iteration "
    "of the dual and (F) is 6th iteration of the dual."
)
LABELS = ("A", "B", "C", "D", "E", "F")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 7: tetrahedron (A), pentagonalized (B), then its 1st (C),
    2nd (D), 5th (E) and 6th (F) duals."""
    a = shapes.tetrahedron()
    b = pentagonalize(a)
    c = dual(b)
    d = dual(c)
    e = dual(dual(dual(d)))
    return {"A": a, "B": b, "C": c, "D": d, "E": e, "F": dual(e)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 7: tetrahedron (A), pentagonalized (B), its dual (C), the dual of that
    (D), the 5th (E) and 6th (F) duals.  Each panel is scaled to fit.

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
    kw = {"elev": 22.0, "azim": 25.0}
    return mesh_figure(
        [
            (p["A"], "tetrahedron", kw),
            (p["B"], "pentagonalized", kw),
            (p["C"], "dual of (B)", kw),
            (p["D"], "dual of (C)", kw),
            (p["E"], "5th dual", kw),
            (p["F"], "6th dual", kw),
        ],
        ncols=3,
        suptitle="Figure 7. Conversion of a tetrahedron to a dodecahedron",
    )


UNIFORM = (
    "This set of images also show the role of dual operation; the resulting shape becomes "
    "more and more uniform with each application of dual operation."
)

#: The measures of "uniform" and the verdict recorded for each on (B), (D), (F).
MEASURES = {
    "edge": ("spread of edge lengths (std/mean)", edge_length_spread, FAILS),
    "angle": ("spread of face angles (std/mean)", angle_spread, HOLDS),
    "radius": ("spread of vertex radii (std/mean)", radius_spread, HOLDS),
}


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 7, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    b = p["B"]
    out = [
        exact(
            "fig07.B.dodecahedron",
            "Section 5.1, Figure 7",
            "This scheme can convert the simplest triangular mesh (tetrahedron) to the simplest "
            "pentagonal mesh (dodecahedron) as shown in Figure 7.",
            "(B) faces by size, valences, (V, E, F)",
            ({5: 12}, {3: 20}, (20, 30, 12)),
            (b.face_size_histogram(), b.valence_histogram(), vef(b)),
        )
    ]
    for name, (label, measure, recorded) in MEASURES.items():
        out.append(
            monotone_claim(
                f"fig07.uniform.{name}",
                "Section 5.1, Figure 7",
                UNIFORM,
                "after 0, 2 and 6 duals: (B), (D), (F)",
                {label: [measure(p[k]) for k in "BDF"]},
                ["(B)", "(D)", "(F)"],
                recorded,
            )
        )
    return out
