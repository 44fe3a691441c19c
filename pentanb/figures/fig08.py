"""Figure 8: the 4.3.3.4.3 semi-regular tiling from pentagonalizing a cube.

(A) the hard-edged cube pentagonalized once with two duals (the same mesh
as Figure 1.B), (B) its dual.  The claims: the pentagons of (A) counted by
the valences of their corners (Section 5.1's 4.3.3.4.3 regions), and the
geometry of those regions against the classical tile.  (That the vertices
of (B) have (A)'s face configurations is the definition of the dual, not a
claim.)  The regions exist after the first pentagonalization of a (4, 4)
region only: a second one makes 3.3.3.3.5 and 3.3.4.3.5 faces.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import FAILS, Claim, configuration_claim, region_claim, take

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "4.3.3.4.3 semi-regular tiling"
CAPTION = (
    "4.3.3.4.3 semi-regular tiling created by pentagon conversion scheme that is "
    "applied to a cube. (A) is one iteration with two dual, (B) is the dual of (A)."
)
LABELS = ("A", "B")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 8: the hard-edged cube pentagonalized with two duals (A)
    and its dual (B)."""
    a = subdivide(shapes.hard_edged_cube(), "pentagonalize", 1, 2)
    return {"A": a, "B": dual(a)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 8: pentagonalization of the hard-edged cube with two duals (A) and its dual (B).

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
            (p["A"], "one iteration, two duals", {}),
            (p["B"], "dual of (A)", {}),
        ],
        suptitle="Figure 8. 4.3.3.4.3 semi-regular tiling from pentagonalizing a cube",
        panel_size=3.6,
    )


REGIONS = (
    "If this subdivision is applied to a mesh that includes either (4, 4) or (6, 3) "
    "regular regions, the resulting mesh [...] will have classical (or geometrical) "
    "semi-regular "
    "regions 4.3.3.4.3 (see Figure 8.A) or 6.3.3.3.3 (see Figures 9.A)"
)


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 8, measured on :func:`panels` and the cube they
    come from (``meshes["source"]`` replaces it)."""
    p = panels() if meshes is None else meshes
    a = p["A"]
    src = take(meshes, "source", shapes.hard_edged_cube)
    # every pentagon belongs to a half-edge (u, w) of the cube and has w as a
    # corner: 4.3.3.4.3 when w is a 4-valent grid vertex, 4.3.3.3.3 at the 8 corners
    corners3 = int(src.valences[src.valences == 3].sum())
    expected = {"3.3.4.3.4": 2 * src.n_edges - corners3, "3.3.3.3.4": corners3}
    return [
        configuration_claim(
            "fig08.A.regions", "Section 5.1, Figure 8.A", REGIONS, a, expected, "4.3.3.4.3"
        ),
        region_claim(
            "fig08.A.geometry",
            "Section 5.1, Figure 8.A",
            REGIONS,
            [("level 1 (A)", a)],
            "4.3.3.4.3",
            FAILS,
        ),
    ]
