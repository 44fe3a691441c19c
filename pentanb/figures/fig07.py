"""Figure 7: conversion of a tetrahedron to a dodecahedron by pentagonalization.

(A) the tetrahedron, (B) pentagonalized (a dodecahedron), (C) its dual, (D)
the dual of (C), (E) the 5th and (F) the 6th dual.  The claims: (B) is a
dodecahedron, and the shape becomes more uniform with each pair of duals,
from the first pair on, (D) -> 4 duals -> (F), by three measures: the
spread of the edge lengths, of the face angles and of the vertices'
distances from the centre.  (B) itself, before any dual, is the
tetrahedron with its edges cut in three and its faces' centres added: it
has the dodecahedron's counts but corners of 180 degrees, so its equal
edges (all a third of the tetrahedron's) are not yet a uniform shape.
(That the duals alternate between dodecahedral and icosahedral is the
definition of the dual, not a claim.)
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import angle_spread, corner_angles, edge_length_spread, radius_spread
from ..mesh import Mesh
from ..schemes.pentagonal import pentagonalize
from ..schemes.smoothing import dual
from .claim import HOLDS, Claim, exact, fmt, monotone_claim, take, vef

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

#: The measures of "uniform".
MEASURES = {
    "edge": ("spread of edge lengths (std/mean)", edge_length_spread),
    "angle": ("spread of face angles (std/mean)", angle_spread),
    "radius": ("spread of vertex radii (std/mean)", radius_spread),
}


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 7, measured on :func:`panels` (and on (D) after one
    more pair of duals, ``meshes["4 duals"]``)."""
    p = panels() if meshes is None else meshes
    b = p["B"]
    four = take(meshes, "4 duals", lambda: dual(dual(p["D"])))
    steps = [("(D)", p["D"]), ("4 duals", four), ("(F)", p["F"])]
    before = {name: measure(b) for name, (_, measure) in MEASURES.items()}
    straight = float(corner_angles(b).max())
    out = [
        exact(
            "fig07.B.dodecahedron",
            "Section 5.1, Figure 7",
            "This scheme can convert the simplest triangular mesh (tetrahedron) to the simplest "
            "pentagonal mesh (dodecahedron) as shown in Figure 7.",
            "(B) faces by size, valences, (V, E, F)",
            ({5: 12}, {3: 20}, (20, 30, 12)),
            (b.face_size_histogram(), b.valence_histogram(), vef(b)),
            reading="the pentagonalized tetrahedron is a dodecahedron as a mesh: 12 pentagons, "
            "30 edges, 20 three-valent vertices",
            cause="pentagonalization's combinatorics",
        )
    ]
    for name, (label, measure) in MEASURES.items():
        out.append(
            monotone_claim(
                f"fig07.uniform.{name}",
                "Section 5.1, Figure 7",
                UNIFORM,
                f"(B), before any dual: {fmt(round(before[name], 4))} (corners up to "
                f"{straight:.1f} degrees); after 2, 4, 6 duals ((D), one more pair, (F))",
                {label: [measure(m) for _, m in steps]},
                [k for k, _ in steps],
                HOLDS,
                reading="the dodecahedral shapes (B), (D), (F) of the figure grow more uniform "
                "with every pair of duals, from the first pair on: (B), the tetrahedron with its "
                "edges cut in three, has the dodecahedron's counts but corners of 180 degrees, "
                "so its equal edges do not make it a uniform dodecahedron",
                cause="the pentagonalized tetrahedron evens out with every pair of duals",
            )
        )
    return out
