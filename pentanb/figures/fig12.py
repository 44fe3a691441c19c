"""Figure 12: pentagonalization of a low-poly animal.

(A) :func:`pentanb.shapes.animal`, a rabbit of 178 unit-cube quads standing
in for the paper's model, (B) pentagonalized twice with two duals after
each, (C) the same mesh shaded without wireframe.
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

TITLE = "Pentagonalized animal"
CAPTION = (
    "(A) An initial mesh (B) pentagonalization scheme applied twice to the initial "
    "mesh, (C) shaded model without wireframe."
)
LABELS = ("A", "B", "C")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 12: the rabbit (A), pentagonalized twice with two duals
    each (B), and (C), the same mesh as (B) (drawn shaded)."""
    a = shapes.animal()
    b = subdivide(a, "pentagonalize", 2, 2)
    return {"A": a, "B": b, "C": b}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 12: a low-poly animal (A), pentagonalized twice with two duals after each
    (B), and (B) shaded without wireframe (C).

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.
    """
    from ._draw import mesh_figure

    p = panels() if meshes is None else meshes
    kw = {"elev": 18.0, "azim": -55.0}
    return mesh_figure(
        [
            (p["A"], "initial mesh", kw),
            (p["B"], "pentagonalized twice", kw),
            (p["C"], "shaded, no wireframe", dict(kw, wireframe=False)),
        ],
        suptitle="Figure 12. Pentagonalization of a low-poly rabbit",
        panel_size=3.4,
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 12, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a, b = p["A"], p["B"]
    out = [
        eq(
            "(A) the initial mesh: quads only, genus 0",
            ({4: a.n_faces}, 0),
            (a.face_size_histogram(), a.genus),
        )
    ]
    out += counts_claims("(B)", a, b, "pentagonalize", 2)
    out.append(
        eq("(B) only pentagons, genus kept", ([5], 0), (sorted(b.face_size_histogram()), b.genus))
    )
    return out
