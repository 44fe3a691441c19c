"""Figure 9: the 6.3.3.3.3 semi-regular tiling from pentagonalizing the hexagonal torus.

(A) Figure 4.A's hexagonal torus pentagonalized once with two duals, (B) its
dual; every pentagon of (A) has corner valences 6.3.3.3.3 (Section 5.1).
The claims: that count, and the geometry of the regions against the
classical tile.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import FAILS, Claim, configuration_claim, region_claim
from .fig08 import REGIONS

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "6.3.3.3.3 semi-regular tiling"
CAPTION = (
    "6.3.3.3.3 semi-regular tiling created by pentagon conversion scheme that is "
    "applied to the toroidal shape shown in Figure 4.A. (A) is one iteration with two "
    "dual, (B) is the dual of (A)."
)
LABELS = ("A", "B")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 9: the hexagonal torus pentagonalized with two duals (A)
    and its dual (B)."""
    a = subdivide(shapes.hexagonal_torus(), "pentagonalize", 1, 2)
    return {"A": a, "B": dual(a)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 9: pentagonalization of the hexagonal torus with two duals (A) and its dual (B).

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
    """
    from ._draw import TORUS_VIEW, mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "one iteration, two duals", TORUS_VIEW),
            (p["B"], "dual of (A)", TORUS_VIEW),
        ],
        suptitle="Figure 9. 6.3.3.3.3 semi-regular tiling from pentagonalizing the hexagonal torus",
        panel_size=4.0,
        aspect=0.6,
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 9, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a = p["A"]
    return [
        configuration_claim(
            "fig09.A.regions",
            "Section 5.1, Figure 9.A",
            REGIONS,
            a,
            {"3.3.3.3.6": a.n_faces},
            "6.3.3.3.3",
        ),
        region_claim(
            "fig09.A.geometry",
            "Section 5.1, Figure 9.A",
            REGIONS,
            [("level 1 (A)", a)],
            "6.3.3.3.3",
            FAILS,
        ),
    ]
