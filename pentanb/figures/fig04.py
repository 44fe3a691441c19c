"""Figure 4: hexagonal meshes of genus 1 and 2 (Section 4: hexagons need g > 0).

(A) :func:`pentanb.shapes.hexagonal_torus`, every vertex 3-valent; (B)
:func:`pentanb.shapes.hexagonal_surface` of genus 2, where equation (1)
forces some vertices above valence 3.
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from .claim import Claim, check, eq

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


def _valence_claims(panel: str, mesh: Mesh, n: int) -> list[Claim]:
    """The average valence 2E/V of an n-gonal mesh against equation (1)."""
    g, v = mesh.genus, mesh.n_vertices
    eq1 = Fraction(2 * n, n - 2) * (1 + Fraction(2 * g - 2, v))
    return [
        eq(
            f"{panel} average valence 2E/V = equation (1) m = 2n/(n-2) (1 + (2g-2)/v) "
            f"with n={n}, g={g}, v={v}",
            eq1,
            Fraction(2 * mesh.n_edges, v),
        )
    ]


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 4, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a, b = p["A"], p["B"]
    out = []
    for panel, m, g in (("(A)", a, 1), ("(B)", b, 2)):
        out.append(
            eq(
                f"{panel} only hexagons, genus {g}",
                ([6], g),
                (sorted(m.face_size_histogram()), m.genus),
            )
        )
        out += _valence_claims(panel, m, 6)
    out.append(eq("(A) genus 1: every vertex 3-valent", {3: a.n_vertices}, a.valence_histogram()))
    out.append(
        check(
            "(B) genus 2: m > 3, so some vertices have valence > 3",
            "> 3",
            Fraction(2 * b.n_edges, b.n_vertices),
            Fraction(2 * b.n_edges, b.n_vertices) > 3,
        )
    )
    return out
