"""Figure 11: a semi-regular tiling from pentagon preservation of a cube.

(A) pentagon preservation (scale 0.75) with two duals of a cube whose faces
are even 3x3 grids (:func:`pentanb.shapes.hard_edged_cube` with inset 1/3),
(B) its dual.  The claims: the count formula, the semi-regular regions by
corner valences, and the number of non-pentagons staying constant.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import (
    configuration_counts,
    face_configurations,
    vertex_configurations,
)
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import Claim, counts_claims, eq

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagon preservation on a cube"
CAPTION = (
    "A semi-regular tiling created by pentagon preserving scheme that is applied to "
    "a cube. (A) is one iteration with two dual, (B) is the dual of (A)."
)
LABELS = ("A", "B")


def _source() -> Mesh:
    """The cube of Figure 11: every face an even 3x3 grid of quads."""
    return shapes.hard_edged_cube(1 / 3)


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 11: the 3x3-grid cube after pentagon preservation with two
    duals (A) and its dual (B)."""
    a = subdivide(_source(), "preserve_pentagons", 1, 2)
    return {"A": a, "B": dual(a)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 11: pentagon preservation (scale 0.75) of a cube whose faces are 3x3 grids,
    with two duals (A), and its dual (B).

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.
    """
    from ._draw import mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "3x3-grid cube: one iteration, two duals", {}),
            (p["B"], "dual of (A)", {}),
        ],
        suptitle="Figure 11. A semi-regular tiling from pentagon preservation of a cube",
        panel_size=3.6,
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 11, measured on :func:`panels`, the cube they come
    from and (A) refined once more."""
    p = panels() if meshes is None else meshes
    src, a, b = _source(), p["A"], p["B"]
    a2 = subdivide(a, "preserve_pentagons", 1, 2)

    def non5(m: Mesh) -> int:
        return int((m.face_sizes != 5).sum())

    corners3 = int(src.valences[src.valences == 3].sum())
    out = counts_claims("(A)", src, a, "preserve_pentagons")
    fa = configuration_counts(face_configurations(a))
    vb = configuration_counts(vertex_configurations(b))
    out += [
        eq(
            "(A) every n-gon gives n pentagons and a central n-gon",
            {4: src.n_faces, 5: 2 * src.n_edges},
            a.face_size_histogram(),
        ),
        eq(
            "the number of non-pentagons stays constant after the first refinement",
            non5(a),
            non5(a2),
        ),
        eq(
            "(A) semi-regular regions: pentagons with corner valences 3.3.4.4.4 (grid) "
            "or 3.3.4.3.4 (at the cube's corners), centre quads 3.3.3.3",
            {
                "3.3.4.4.4": 2 * src.n_edges - corners3,
                "3.3.3.3": src.n_faces,
                "3.3.4.3.4": corners3,
            },
            fa,
        ),
        eq("(B) the dual: vertex configurations are (A)'s face configurations", fa, vb),
    ]
    return out
