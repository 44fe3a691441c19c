"""Figure 7: conversion of a tetrahedron to a dodecahedron by pentagonalization.

(A) the tetrahedron, (B) pentagonalized (a dodecahedron), (C) its dual, (D)
the dual of (C), (E) the 5th and (F) the 6th dual.  The claims: the
dodecahedral and icosahedral counts, and the shape becoming rounder with
the duals (radius spread).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import radius_spread
from ..mesh import Mesh
from ..schemes.pentagonal import pentagonalize
from ..schemes.smoothing import dual
from .claim import Claim, check, eq, vef

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


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 7, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    b, c, d, e, f = (p[k] for k in "BCDEF")
    dodeca = ({5: 12}, {3: 20}, (20, 30, 12))
    icosa = ({3: 20}, {5: 12}, (12, 30, 20))

    def top(m: Mesh) -> tuple:
        return m.face_size_histogram(), m.valence_histogram(), vef(m)

    spreads = [radius_spread(m) for m in (b, d, f)]
    return [
        eq(
            "(B) the tetrahedron pentagonalized is a dodecahedron: 12 pentagons, "
            "20 3-valent vertices",
            dodeca,
            top(b),
        ),
        eq("(C) its dual is icosahedral", icosa, top(c)),
        eq("(D) the dual of (C) is dodecahedral", dodeca, top(d)),
        eq("(E) the 5th dual is icosahedral", icosa, top(e)),
        eq("(F) the 6th dual is dodecahedral", dodeca, top(f)),
        check(
            "the shape becomes more uniform with every dual: spread of vertex "
            "radii (std/mean) of (B), (D), (F) decreases",
            "decreasing",
            tuple(round(s, 4) for s in spreads),
            spreads[0] > spreads[1] > spreads[2],
        ),
    ]
