"""Figure 5: two iterations of hexagon preservation (dual of Loop) on Figure 4's meshes.

(A) the hexagonal torus and (B) the hexagonal genus-2 surface, each refined
twice by :func:`pentanb.preserve_hexagons` with two duals after each iteration.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import Claim, counts_claim, exact

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
    """The meshes of Figure 5: Figure 4's (A) and (B) after two iterations of hexagon
    preservation with two duals each."""
    a, b = _sources()
    return {
        "A": subdivide(a, "preserve_hexagons", 2, 2),
        "B": subdivide(b, "preserve_hexagons", 2, 2),
    }


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 5: two iterations of hexagon preservation (two duals each) on Figure 4's meshes.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
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
    """What the paper says of Figure 5, measured on :func:`panels` and Figure 4's meshes
    (``meshes["source A"]``, ``meshes["source B"]`` replace them)."""
    p = panels() if meshes is None else meshes
    srcs = dict(zip("AB", _sources()))
    if meshes is not None:
        srcs.update({k: meshes[f"source {k}"] for k in "AB" if f"source {k}" in meshes})

    def irregular(x: Mesh) -> tuple[int, int]:
        return int((x.face_sizes != 6).sum()), int((x.valences != 3).sum())

    out = []
    for k in "AB":
        src, m, panel = srcs[k], p[k], f"({k})"
        out.append(
            counts_claim(
                f"fig05.{k}.counts",
                "Figure 5",
                "Two iterations of an hexagon preserving scheme applied to the hexagonal "
                "meshes shown in Figure 4.",
                panel,
                src,
                m,
                "preserve_hexagons",
                2,
                cause="hexagon preservation",
            )
        )
        out.append(
            exact(
                f"fig05.{k}.hexagons",
                "Section 4",
                "it is possible to develop an hexagonal preservation scheme since hexagonal "
                "meshes exist for g > 0",
                f"{panel} face sizes and genus, against Figure 4's",
                ([6], src.genus),
                (sorted(m.face_size_histogram()), m.genus),
                reading="hexagon preservation of a hexagonal mesh of genus 1 or 2 makes only "
                "hexagons, on the same surface",
                cause="hexagon preservation",
            )
        )
        out.append(
            exact(
                f"fig05.{k}.irregular",
                "Section 3",
                "(6, 3) The schemes that are the dual of sqrt(3) [5, 8, 19, 6] and dual of Loop "
                "subdivision [12] create regular regions that consist 3-valent vertices and "
                "6-sided faces. In this case, the number of non-6-sided faces remains constant "
                "after the first refinement.",
                f"{panel} (non-hexagons, non-3-valent vertices), against Figure 4's",
                irregular(src),
                irregular(m),
                reading="the non-hexagons and the vertices of valence other than 3 stay as many "
                "as in the input",
                cause="hexagon preservation",
            )
        )
    return out
