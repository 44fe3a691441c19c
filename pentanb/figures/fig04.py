"""Figure 4: hexagonal meshes of genus 1 and 2 (Section 4: hexagons need g > 0).

(A) :func:`pentanb.shapes.hexagonal_torus`, every vertex 3-valent; (B)
:func:`pentanb.shapes.hexagonal_surface` of genus 2, where equation (1)
forces some vertices above valence 3.  Equation (1) is used with the genus
each mesh was built with (a torus; two tori glued), so the claims can fail
on a mesh of another genus.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from .claim import CHECK, Claim, exact

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Hexagonal meshes"
CAPTION = "Examples of hexagonal meshes for g>0."
LABELS = ("A", "B")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 4: ``{"A": hexagonal torus, "B": hexagonal genus 2}``."""
    return {"A": shapes.hexagonal_torus(), "B": shapes.hexagonal_surface(2)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 4: hexagonal meshes of genus 1 (A) and 2 (B).

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
            (p["A"], "genus 1", TORUS_VIEW),
            (p["B"], "genus 2", GENUS2_VIEW),
        ],
        suptitle="Figure 4. Hexagonal meshes for g > 0",
        panel_size=4.0,
        aspect=0.6,
    )


#: The genus every panel was built with (a torus; two tori glued in a chain).
BUILT_GENUS = {"A": 1, "B": 2}


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 4, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a, b = p["A"], p["B"]
    out = [
        exact(
            f"fig04.{k}.hexagons",
            "Section 4, Figure 4",
            "This also shows that for g > 0, it is always possible to create hexagonal "
            "meshes; two examples are shown in Figure 4.",
            f"({k}) face sizes and genus",
            ([6], BUILT_GENUS[k]),
            (sorted(m.face_size_histogram()), m.genus),
            reading="closed meshes of hexagons exist on surfaces of genus 1 and 2",
            cause="hexagonal meshes of genus 1 and 2",
        )
        for k, m in (("A", a), ("B", b))
    ]
    # equation (1) with n = 6, g = 1: m = 3 whatever v; with g = 2: 2E = 3V + 6,
    # so the valences above 3 add up to 6 (g - 1) = 6
    out.append(
        exact(
            "fig04.A.valence",
            "Section 4, equation (1)",
            "m = 2n/(n-2) (1 + (2g-2)/v) [...] This is the same as the value of the m for g = 1",
            "(A) (n = 6, built with g = 1) valences, against m = 3 for every v: all 3-valent",
            {3: a.n_vertices},
            a.valence_histogram(),
            kind=CHECK,
            cause="equation (1) is Euler's formula with 2E = nF and 2E = mV",
        )
    )
    out.append(
        exact(
            "fig04.B.valence",
            "Section 4, equation (1)",
            "In other words, 2n/(n-2) should be larger than 3 to be able to avoid "
            "less-than-3-valent vertices",
            "(B) (n = 6, built with g = 2) sum over vertices of (valence - 3), against "
            "2E - 3V = 6 (g - 1) = 6 from equation (1); smallest valence",
            (6, 3),
            (int((b.valences - 3).sum()), int(b.valences.min())),
            kind=CHECK,
            cause="equation (1) is Euler's formula with 2E = nF and 2E = mV",
        )
    )
    return out
