"""Figure 1: pentagonal subdivision examples on a hard-edged cube.

(A) the hard-edged cube (:func:`pentanb.shapes.hard_edged_cube`, this
package's reading of the paper's cube), (B) one and (C) two
pentagonalizations, (D) pentagon preservation applied to (B); every step
followed by two duals.  The claims: the counts the constructions give, only
pentagons, and both remeshings (before their duals) leaving the cube's
shape alone: its vertices where they were, every new vertex on its faces,
found by position.  Section 1's "no lateral artifact" is measured on boxes
in :mod:`~pentanb.figures.lateral`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..analysis.measures import nearest_distance, surface_distance
from ..mesh import Mesh
from ..schemes.pentagonal import pentagonalize, preserve_pentagons
from ..subdivision import subdivide
from .claim import Claim, bounded, counts_claim, exact, take

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagonal subdivision examples"
CAPTION = (
    "(A) is the initial mesh, (B) is one application of pentagonalization scheme, "
    "(C) is two iterations of pentagonalization scheme, (D) is obtained by applying "
    "pentagonal preserving scheme to the pentagonal mesh in (B)."
)
LABELS = ("A", "B", "C", "D")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 1, by panel: ``{"A": hard-edged cube, "B", "C", "D"}``."""
    a = shapes.hard_edged_cube()
    b = subdivide(a, "pentagonalize", 1, 2)
    c = subdivide(b, "pentagonalize", 1, 2)
    d = subdivide(b, "preserve_pentagons", 1, 2)
    return {"A": a, "B": b, "C": c, "D": d}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 1: a hard-edged cube (A), one (B) and two (C) pentagonalizations,
    pentagon preservation applied to (B) (D); each smoothed by two duals.

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
            (p["A"], "hard-edged cube", {}),
            (p["B"], "one pentagonalization", {}),
            (p["C"], "two pentagonalizations", {}),
            (p["D"], "pentagon preservation of (B)", {}),
        ],
        ncols=4,
        suptitle="Figure 1. Pentagonal subdivision examples (each step followed by two duals)",
    )


S51 = "Section 5.1"
S52 = "Section 5.2"
SPLIT5 = (
    "Each face in the original mesh would now have been split into as many pentagons as "
    "the number of edges (or vertices) in the original face. So we will have only "
    "pentagons in the new mesh."
)
STEPS5 = (
    "Subdivide all edges in the mesh into 3 equal parts. [...] Create a point sphere [4, 14] "
    "at the centroid of the face. [...] Insert an edge between the point sphere and every other "
    "newly created point in that face"
)
STEPS_P = (
    "Each face in the original mesh would now have been split into as many pentagons as "
    "the number of edges (or vertices) in the original face plus one central face with "
    "the same number of sides as the original face."
)
PRESERVE = (
    "If we start with a pentagonal mesh, the new mesh will contain only pentagons, thus "
    "preserving the pentagonal nature of the original mesh."
)
SHAPE = (
    "Our remeshing operations do not change positions of existing vertices and newly "
    "created vertices do not change the shape of the initial mesh."
)


SHAPE_READING = (
    "the remeshing itself, before the duals that smooth it, keeps every vertex of the input "
    "where it was and puts every new vertex on the input's surface (on its faces or edges): "
    "measured by position on the hard-edged cube (A), whose faces are planar"
)


def _shape_claim(key: str, label: str, source: Mesh, remeshed: Mesh, also=()) -> Claim:
    """Old vertices kept and new ones on the input's surface, found by position.

    ``also``: more ``(input, remeshed)`` pairs whose old vertices are checked.
    """
    moved = float(nearest_distance(source.vertices, remeshed.vertices).max())
    for before, after in also:
        moved = max(moved, float(nearest_distance(before.vertices, after.vertices).max()))
    off = float(surface_distance(remeshed.vertices, source).max())
    more = " (and of (B), remeshed likewise)" if also else ""
    return bounded(
        key,
        "Section 3",
        SHAPE,
        f"{label} of (A), no duals: largest distance of a vertex of (A){more} from the "
        "nearest remeshed vertex, and of a remeshed vertex from (A)'s faces",
        max(moved, off),
        detail=f"old vertices moved {moved:.3g}, new ones off the faces {off:.3g}",
        reading=SHAPE_READING,
        cause=f"{label}'s positions",
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 1, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a, b, c, d = (p[k] for k in LABELS)
    out = [
        counts_claim(
            "fig01.B.counts",
            f"{S51}, Figure 1.B",
            STEPS5,
            "(B)",
            a,
            b,
            "pentagonalize",
            cause="pentagonalization's combinatorics",
        ),
        exact(
            "fig01.B.pentagons",
            f"{S51}, Figure 1.B",
            SPLIT5,
            "(B) faces by size, against 2E pentagons for the E edges of (A)",
            {5: 2 * a.n_edges},
            b.face_size_histogram(),
            reading="every n-gon becomes n pentagons, one per half-edge: 2E pentagons and "
            "nothing else",
            cause="pentagonalization's combinatorics",
        ),
        counts_claim(
            "fig01.C.counts",
            "Figure 1.C",
            "(C) is two iterations of pentagonalization scheme",
            "(C)",
            a,
            c,
            "pentagonalize",
            2,
            cause="pentagonalization's combinatorics",
        ),
        exact(
            "fig01.C.pentagons",
            f"{S51}, Figure 1.C",
            SPLIT5,
            "(C) face sizes",
            [5],
            sorted(c.face_size_histogram()),
            reading="a second pentagonalization of a pentagonal mesh makes only pentagons again",
            cause="pentagonalization's combinatorics",
        ),
        counts_claim(
            "fig01.D.counts",
            f"{S52}, Figure 1.D",
            STEPS_P,
            "(D)",
            b,
            d,
            "preserve_pentagons",
            cause="pentagon preservation's combinatorics",
        ),
        exact(
            "fig01.D.pentagons",
            f"{S52}, Figure 1.D",
            PRESERVE,
            "(D) face sizes",
            [5],
            sorted(d.face_size_histogram()),
            reading="pentagon preservation of the pentagonal mesh (B) makes only pentagons",
            cause="pentagon preservation's combinatorics",
        ),
    ]
    # the remeshings themselves (before the duals) keep the cube: old vertices
    # stay, new ones lie on its faces (found by position, not by the operators' numbering)
    raw_b = take(meshes, "pentagonalized A", lambda: pentagonalize(a))
    raw_d = take(meshes, "preserved A", lambda: preserve_pentagons(a))
    raw_bd = take(meshes, "preserved B", lambda: preserve_pentagons(b))
    out.append(_shape_claim("fig01.remesh.shape", "pentagonalization", a, raw_b))
    out.append(
        _shape_claim("fig01.preserve.shape", "pentagon preservation", a, raw_d, [(b, raw_bd)])
    )
    return out
