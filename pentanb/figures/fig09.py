"""Figure 9: the 6.3.3.3.3 semi-regular tiling from pentagonalizing the hexagonal torus.

(A) Figure 4.A's hexagonal torus pentagonalized once with two duals, (B) its
dual; every pentagon of (A) has corner valences 6.3.3.3.3 (Section 5.1).
The claims: that count, and the geometry of the regions where the sentence
puts them, on a uniform flat (6, 3) region of regular hexagons
(:func:`flat_source`), against the classical tile after 2, 4 and 6 duals.
An observation: the regions on the curved torus, the figure's own panel,
against the same tile.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from .. import shapes
from ..mesh import Mesh
from ..schemes.classic import loop_remesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import HOLDS, OBSERVATION, WITHIN, Claim, configuration_claim, region_claim, take
from .fig08 import DUALS, READING, REGIONS, flat_steps

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


#: Loop remeshings of the tetrahedron before its dual (:func:`flat_source`): 16 x 16
#: equilateral triangles on each face, so the dual's hexagons are regular within it.
REFINE = 4


def flat_source() -> Mesh:
    """The input with uniform flat (6, 3) regions: the dual of a tetrahedron whose faces are
    cut into 16 x 16 equilateral triangles (Loop's remeshing four times, no smoothing).

    Within every face of the tetrahedron the dual's vertices are the triangles' centroids,
    so its hexagons are regular and flat there: the regular (6, 3) tiling.
    """
    m = shapes.tetrahedron()
    for _ in range(REFINE):
        m = loop_remesh(m)
    return dual(m)


def flat_plane() -> tuple[np.ndarray, np.ndarray, float]:
    """The flat region measured: a face of the tetrahedron (its centroid, its normal) and
    the largest distance of a corner from the centroid (0.6 of the face's inradius)."""
    t = shapes.tetrahedron()
    p = t.vertices[t.faces[3]]
    centre = p.mean(axis=0)
    normal = np.cross(p[1] - p[0], p[2] - p[0])
    inradius = float(np.linalg.norm(centre - (p[0] + p[1]) / 2))
    return centre, normal, 0.6 * inradius


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 9, measured on :func:`panels` and on the flat region
    the sentence is about (``meshes["flat source"]`` replaces :func:`flat_source`)."""
    p = panels() if meshes is None else meshes
    a = p["A"]
    flat = take(meshes, "flat source", flat_source)
    return [
        configuration_claim(
            "fig09.A.regions",
            "Section 5.1, Figure 9.A",
            REGIONS,
            a,
            {"3.3.3.3.6": a.n_faces},
            "6.3.3.3.3",
            reading="the pentagons made from a (6, 3) region have the corner valences "
            "6.3.3.3.3 (up to rotation): on the hexagonal torus, every pentagon",
            cause="pentagonalization's combinatorics",
        ),
        region_claim(
            "fig09.flat.geometry",
            "Section 5.1, Figure 9.A",
            REGIONS,
            flat_steps(flat, flat_plane()),
            "6.3.3.3.3",
            WITHIN,
            reading=READING.format(
                config="6.3.3.3.3",
                where="a face of a tetrahedron tiled by regular hexagons (the dual of 16 x 16 "
                "equilateral triangles per face)",
                duals=", ".join(map(str, DUALS)),
            ),
            cause="the regions' geometry after a few duals",
        ),
        region_claim(
            "fig09.A.geometry",
            "Section 5.1, Figure 9.A (the regions on the curved hexagonal torus)",
            REGIONS,
            [("level 1 (A)", a)],
            "6.3.3.3.3",
            HOLDS,
            kind=OBSERVATION,
            cause="the regions on curved or non-uniform inputs",
        ),
    ]
