"""Figure 8: the 4.3.3.4.3 semi-regular tiling from pentagonalizing a cube.

(A) the hard-edged cube pentagonalized once with two duals (the same mesh
as Figure 1.B), (B) its dual.  The claims count the pentagons of (A) by the
valences of their corners and the vertices of (B) by the sizes of their
faces (Section 5.1).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import Claim, configuration_claims

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


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 8, measured on :func:`panels` and the cube they
    come from."""
    p = panels() if meshes is None else meshes
    a, b, src = p["A"], p["B"], shapes.hard_edged_cube()
    # every pentagon belongs to a half-edge (u, w) of the cube and has w as a
    # corner: 4.3.3.4.3 when w is a 4-valent grid vertex, 4.3.3.3.3 at the 8 corners
    corners3 = int(src.valences[src.valences == 3].sum())
    expected = {"3.3.4.3.4": a.n_faces - corners3, "3.3.3.3.4": corners3}
    return configuration_claims(a, b, "4.3.3.4.3", expected, "semi-regular")
