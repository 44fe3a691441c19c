"""Figure 5: two iterations of hexagon preservation (dual of Loop) on Figure 4's meshes.

(A) the hexagonal torus and (B) the hexagonal genus-2 surface, each refined
twice by :func:`pentanb.preserve_hexagons` with two duals after each round.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import Claim, counts_claims, eq

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Hexagon preservation"
CAPTION = (
    "Two iterations of an hexagon preserving scheme applied to the hexagonal meshes "
    "shown in Figure 4."
)
LABELS = ("A", "B")


def _sources() -> tuple[Mesh, Mesh]:
    """Figure 4's meshes: the hexagonal torus and the hexagonal genus-2 surface."""
    return shapes.hexagonal_torus(), shapes.hexagonal_surface(2)


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 5: Figure 4's (A) and (B) after two rounds of hexagon
    preservation with two duals each."""
    a, b = _sources()
    return {
        "A": subdivide(a, "preserve_hexagons", 2, 2),
        "B": subdivide(b, "preserve_hexagons", 2, 2),
    }


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 5: two rounds of hexagon preservation (two duals each) on Figure 4's meshes.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.
    """
    from ._draw import GENUS2_VIEW, TORUS_VIEW, mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "genus 1, two iterations", TORUS_VIEW),
            (p["B"], "genus 2, two iterations", GENUS2_VIEW),
        ],
        suptitle="Figure 5. Two iterations of hexagon preservation (dual of Loop)",
        panel_size=4.0,
        aspect=0.6,
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 5, measured on :func:`panels` and Figure 4's meshes."""
    p = panels() if meshes is None else meshes
    src_a, src_b = _sources()

    def extra(x: Mesh) -> int:
        return int((x.valences != 3).sum())

    out = []
    for panel, src, m in (("(A)", src_a, p["A"]), ("(B)", src_b, p["B"])):
        out += counts_claims(panel, src, m, "preserve_hexagons", 2)
        out.append(
            eq(
                f"{panel} hexagonal meshes stay hexagonal, genus kept",
                ([6], src.genus),
                (sorted(m.face_size_histogram()), m.genus),
            )
        )
        out.append(
            eq(f"{panel} the number of non-3-valent vertices stays constant", extra(src), extra(m))
        )
    return out
