"""Figure 8: the 4.3.3.4.3 semi-regular tiling from pentagonalizing a cube.

(A) the hard-edged cube pentagonalized once with two duals (the same mesh
as Figure 1.B), (B) its dual.  The claims: the pentagons of (A) counted by
the valences of their corners (Section 5.1's 4.3.3.4.3 regions), and the
geometry of the regions where the sentence puts them, on a uniform flat
(4, 4) region (:func:`flat_source`), against the classical tile after 2, 4
and 6 duals.  An observation: the regions on the hard-edged cube's thin
strips, the figure's own panel, against the same tile.  (That the vertices
of (B) have (A)'s face configurations is the definition of the dual, not a
claim.)  The regions exist after the first pentagonalization of a (4, 4)
region only: a second one makes 3.3.3.3.5 and 3.3.4.3.5 faces.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import flat_region
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import HOLDS, OBSERVATION, WITHIN, Claim, configuration_claim, region_claim, take

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

#: The duals after the pentagonalization at which the regions' geometry is measured
#: (Section 5.1: "Apply dual operation an even number of times").
DUALS = (2, 4, 6)
#: Cells per edge of the box whose faces are the uniform flat (4, 4) regions.
CELLS = 10
#: The flat region measured: a point of the plane (its centre), the plane's normal and
#: the largest distance of a corner from the centre (half the face's half-width: the
#: pentagons there are 2.5 cells or more from the box's edges).
PLANE = ((0.0, 0.0, 1.0), (0.0, 0.0, 1.0), 0.5)

#: How Section 5.1's regions are read (the claim's reading, shared with Figure 9).
READING = (
    "'classical (or geometrical) semi-regular regions' names the pattern of the classical "
    "tilings (Section 4 calls its own looser tilings 'semi-regular'): where the input has a "
    "uniform regular region, the pentagons made there have the corner valences {config} and "
    "the geometry of the classical tile V{config}, the closer the more duals are applied "
    "(the paper applies them 'an even number of times'); measured on {where}, away from "
    "its rim, after {duals} duals"
)


def flat_source() -> Mesh:
    """The input with uniform flat (4, 4) regions: a box whose faces are 10 x 10 grids of
    squares (:func:`pentanb.shapes.box`)."""
    return shapes.box(CELLS)


def flat_steps(source: Mesh, plane=PLANE, duals=DUALS) -> list[tuple]:
    """``[(label, mesh, faces of the flat region)]``: ``source`` pentagonalized, after each
    number of ``duals``, and the faces of the flat round region ``plane`` (centre, normal,
    radius; :func:`pentanb.analysis.flat_region`)."""
    out = []
    m = subdivide(source, "pentagonalize", 1, 0)
    done = 0
    for d in duals:
        for _ in range(d - done):
            m = dual(m)
        done = d
        out.append((f"{d} duals", m, flat_region(m, *plane)))
    return out


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 8, measured on :func:`panels`, the cube they come
    from and the flat region the sentence is about (``meshes["source"]`` and
    ``meshes["flat source"]`` replace them)."""
    p = panels() if meshes is None else meshes
    a = p["A"]
    src = take(meshes, "source", shapes.hard_edged_cube)
    flat = take(meshes, "flat source", flat_source)
    # every pentagon belongs to a half-edge (u, w) of the cube and has w as a
    # corner: 4.3.3.4.3 when w is a 4-valent grid vertex, 4.3.3.3.3 at the 8 corners
    corners3 = int(src.valences[src.valences == 3].sum())
    expected = {"3.3.4.3.4": 2 * src.n_edges - corners3, "3.3.3.3.4": corners3}
    return [
        configuration_claim(
            "fig08.A.regions",
            "Section 5.1, Figure 8.A",
            REGIONS,
            a,
            expected,
            "4.3.3.4.3",
            reading="the pentagons made from a (4, 4) region have the corner valences "
            "4.3.3.4.3 (up to rotation): on the cube of (A), every pentagon but those at its "
            "eight 3-valent corners",
            cause="pentagonalization's combinatorics",
        ),
        region_claim(
            "fig08.flat.geometry",
            "Section 5.1, Figure 8.A",
            REGIONS,
            flat_steps(flat),
            "4.3.3.4.3",
            WITHIN,
            reading=READING.format(
                config="4.3.3.4.3",
                where=f"the middle of a face of a box of {CELLS} x {CELLS} squares per face",
                duals=", ".join(map(str, DUALS)),
            ),
            cause="the regions' geometry after a few duals",
        ),
        region_claim(
            "fig08.A.geometry",
            "Section 5.1, Figure 8.A (the regions on the hard-edged cube's strips)",
            REGIONS,
            [("level 1 (A)", a)],
            "4.3.3.4.3",
            HOLDS,
            kind=OBSERVATION,
            cause="the regions on curved or non-uniform inputs",
        ),
    ]
