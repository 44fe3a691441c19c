"""Figure 12: pentagonalization of an irregular low-polygon rabbit.

(A) :func:`pentanb.shapes.rabbit`, an irregular low-polygon model
(triangles, quadrilaterals and pentagons, valences 3 to 7) standing in for
the paper's, (B) pentagonalized twice with two duals after each, (C) the
same mesh shaded without wireframe.  The claims: the counts, only pentagons
(any mesh becomes pentagonal), and the model smoothed.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import normal_angles
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import FAILS, HOLDS, Claim, counts_claim, exact, fmt, judged, take

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagonalized rabbit"
CAPTION = (
    "(A) An initial mesh (B) pentagonalization scheme applied twice to the initial "
    "mesh, (C) shaded model without wireframe."
)
LABELS = ("A", "B", "C")

#: The camera of the three panels.
VIEW = {"elev": 18.0, "azim": -60.0}


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 12: the rabbit (A), pentagonalized twice with two duals
    each (B), and (C), the same mesh as (B) (drawn shaded)."""
    a = shapes.rabbit()
    b = subdivide(a, "pentagonalize", 2, 2)
    return {"A": a, "B": b, "C": b}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 12: an irregular low-polygon rabbit (A), pentagonalized twice with two
    duals after each (B), and (B) shaded without wireframe (C).

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
            (p["A"], "initial mesh", VIEW),
            (p["B"], "pentagonalized twice", VIEW),
            (p["C"], "shaded, no wireframe", dict(VIEW, wireframe=False)),
        ],
        suptitle="Figure 12. Pentagonalization of a low-polygon rabbit",
        panel_size=3.4,
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 12, measured on :func:`panels` (the model, (A), can
    be replaced through ``meshes["A"]``; (B) through ``meshes["B"]``)."""
    p = panels() if meshes is None else meshes
    a = take(meshes, "A", shapes.rabbit)
    b = p["B"]
    crease_a, crease_b = normal_angles(a), normal_angles(b)
    smoother = crease_b.max() < crease_a.max() and crease_b.mean() < crease_a.mean()
    return [
        counts_claim(
            "fig12.B.counts",
            "Section 6, Figure 12",
            "(B) pentagonalization scheme applied twice to the initial mesh",
            "(B)",
            a,
            b,
            "pentagonalize",
            2,
            cause="pentagonalization's combinatorics",
        ),
        exact(
            "fig12.B.pentagons",
            "Section 5.1",
            "We present a pentagonalization (or pentagonal conversion) scheme that can create a "
            "pentagonal mesh from any arbitrary mesh structure.",
            f"(B) face sizes and genus, from (A) with faces {fmt(a.face_size_histogram())} "
            f"and valences {min(a.valence_histogram())}-{max(a.valence_histogram())}",
            ([5], a.genus),
            (sorted(b.face_size_histogram()), b.genus),
            reading="any closed mesh, of mixed faces and valences, becomes a mesh of pentagons "
            "only, on the same surface",
            cause="pentagonalization's combinatorics",
        ),
        judged(
            "fig12.B.smoothed",
            "Section 6, Figure 12",
            "As it can be seen in this example, such complicated models can effectively be "
            "smoothed by our approach.",
            f"crease angle between neighbouring faces, largest and mean: (A) "
            f"{crease_a.max():.1f}, {crease_a.mean():.1f} degrees; (B) {crease_b.max():.1f}, "
            f"{crease_b.mean():.1f} degrees",
            "holds if (B)'s largest and mean crease angles are below (A)'s",
            HOLDS if smoother else FAILS,
            reading="the subdivided model is smoother than the initial one: the angles between "
            "neighbouring faces, largest and mean, are smaller",
            cause="the rabbit smoothed",
        ),
    ]
