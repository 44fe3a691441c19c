"""Figure 6: the pentagonalization scheme on one face, drawn flat.

(A) a hexagon, its edges cut in three and its "point sphere" (the centre);
(B) the hexagon become six pentagons.  Computed by
:func:`pentanb.pentagonalize` on a flat two-faced "pillow" (built here,
privately: the :class:`~pentanb.Mesh` constructor refuses its 2-valent
vertices); only what became of the front face is drawn.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..mesh import Mesh
from ..schemes.pentagonal import pentagonalize
from ._flat import pillow
from .claim import Claim, bounded, exact

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagonalization scheme"
CAPTION = "Pentagonalization scheme. (A) is the initial mesh and (B) the resulting mesh."
LABELS = ("A", "B")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 6: ``{"A": flat hexagon pillow, "B": pentagonalized}``.

    (A) has two faces, the hexagon (face 0) and its back; face ``h`` of (B)
    is the pentagon of half-edge ``h``, so faces 0-5 of (B) fill the front
    hexagon.  Neither is a mesh the constructor accepts: the hexagon's
    corners stay 2-valent in both.  They are the figure's teaching meshes.
    """
    a = pillow(6)
    return {"A": a, "B": pentagonalize(a)}


def _front(src: Mesh) -> np.ndarray:
    """Faces of the output that fill face 0 of ``src``: the pentagon of half-edge h is face h."""
    return np.arange(src.face_sizes[0])


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 6: pentagonalization of one polygon (a hexagon), drawn flat.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
    """
    from ..viz import mpl as vz
    from ..viz.colors import EDGE_COLOR
    from ._draw import CENTRE, NEW, OLD, flat_figure, flat_legend, flat_points

    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    front = _front(src)
    n = src.n_vertices
    with vz.style():
        fig, (a, b) = flat_figure("Figure 6. Pentagonalization scheme on one face")
        vz.draw_flat(a, src, np.array([0]))
        faces = out.corners.reshape(-1, 5)[front]  # (t1, t2, w, t1', c)
        pts = out.vertices
        centre = pts[faces[0, 4]]
        seg = np.stack([np.repeat(centre[None], len(front), 0), pts[faces[:, 0]]], 1)
        vz.draw_segments(
            a, seg[:, :, :2], colors=EDGE_COLOR, linewidths=1.1, linestyles=(0, (3, 2.5)), zorder=3
        )
        flat_points(a, pts[:n], **OLD)
        flat_points(a, pts[np.unique(faces[:, :2])], **NEW)
        flat_points(a, centre[None], **CENTRE)
        a.annotate(
            "point sphere",
            centre[:2],
            xytext=(0.28, -0.3),
            fontsize=8,
            arrowprops={"arrowstyle": "-", "lw": 0.7},
        )
        vz.label_panel(a, "(A) edges cut in three, a point sphere;\ndashed: the edges to insert")
        vz.draw_flat(b, out, front)
        flat_points(b, pts[:n], **OLD)
        flat_points(b, pts[np.unique(faces[:, :2])], **NEW)
        flat_points(b, centre[None], **CENTRE)
        vz.label_panel(b, f"(B) the hexagon becomes {len(front)} pentagons")
        flat_legend(fig, [6, 5])
    return fig


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 6, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    front = _front(src)
    n = int(src.face_sizes[0])
    pts = out.vertices
    old = src.vertices
    sizes = out.face_sizes[front] if out.n_faces >= n else np.zeros(0, dtype=np.int64)
    if sizes.size == n and np.all(sizes == 5):
        # the pentagon of half-edge h: (t1, t2, w, t1', c), t1 and t2 on h
        faces = out.corners[out.offsets[front][:, None] + np.arange(5)]
        u, w = old[np.arange(n)], old[(np.arange(n) + 1) % n]
        err = max(
            float(np.abs(pts[faces[:, 0]] - (2 * u + w) / 3).max()),
            float(np.abs(pts[faces[:, 1]] - (u + 2 * w) / 3).max()),
        )
        centre_err = float(np.linalg.norm(pts[faces[0, 4]] - old.mean(axis=0)))
        corners = (
            int(np.isin(faces, np.arange(n)).sum(axis=1).max()),
            int((faces[:, :4] >= n).sum(axis=1).min()),
            int(np.unique(faces[:, 4]).size),
        )
    else:  # not the n pentagons the figure draws: nothing to measure on them
        err = centre_err = float("inf")
        corners = (-1, -1, -1)
    return [
        exact(
            "fig06.pentagons",
            "Section 5.1, Figure 6",
            "Each face in the original mesh would now have been split into as many pentagons "
            "as the number of edges (or vertices) in the original face.",
            f"faces by size that fill the {n}-gon of (A)",
            {5: n},
            {int(k): int(v) for k, v in zip(*np.unique(sizes, return_counts=True))},
            reading=f"the {n}-gon becomes {n} pentagons",
            cause="pentagonalization's combinatorics",
        ),
        bounded(
            "fig06.thirds",
            "Section 5.1, Figure 6",
            "Subdivide all edges in the mesh into 3 equal parts.",
            "largest distance of a new edge point from 1/3 or 2/3 of its edge",
            err,
            reading="the new points on every edge are at a third and two thirds of it",
            cause="pentagonalization's positions",
        ),
        exact(
            "fig06.corners",
            "Section 5.1, Figure 6",
            "Insert an edge between the point sphere and every other newly created point in "
            "that face",
            "per pentagon: old vertices (most), edge points (fewest), distinct point spheres",
            (1, 3, 1),
            corners,
            reading="each pentagon has one old vertex, three edge points and the point sphere: "
            "the point sphere is joined to every other edge point around the face",
            cause="pentagonalization's combinatorics",
        ),
        bounded(
            "fig06.centroid",
            "Section 5.1, Figure 6",
            "Create a point sphere [4, 14] at the centroid of the face.",
            "distance of the point sphere from the face's centroid",
            centre_err,
            reading="the new vertex inside the face is the mean of its corners",
            cause="pentagonalization's positions",
        ),
    ]
