"""Figure 10: the pentagon preserving scheme on one face, drawn flat.

(A) a pentagon, the polygon of its edge midpoints scaled by 0.75 (this
package's default; the paper asks only for a factor below 1) and the edges
to insert; (B) five pentagons around a smaller pentagon.  Computed by
:func:`pentanb.preserve_pentagons` on a flat two-faced "pillow" (built
here, privately: the :class:`~pentanb.Mesh` constructor refuses its
2-valent vertices); only what became of the front face is drawn.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..mesh import Mesh
from ..schemes.pentagonal import preserve_pentagons
from ._flat import pillow
from .claim import Claim, bounded, exact

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagon preserving scheme"
CAPTION = "Pentagon preserving scheme. (A) is the initial mesh and (B) the resulting mesh."
LABELS = ("A", "B")

#: The scale of the midpoints' polygon drawn in Figure 10.
SCALE = 0.75


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 10: ``{"A": flat pentagon pillow, "B": pentagon preservation}``.

    (A) has two faces, the pentagon (face 0) and its back; in (B), face 0 is
    the front face's scaled copy and face ``F + h`` the pentagon of
    half-edge ``h``.  Neither is a mesh the constructor accepts: the
    pentagon's corners stay 2-valent in both.  They are the figure's
    teaching meshes.
    """
    a = pillow(5)
    return {"A": a, "B": preserve_pentagons(a, scale=SCALE)}


def _front(src: Mesh) -> np.ndarray:
    """Faces of the output that fill face 0 of ``src``: its inner copy, then one per half-edge."""
    return np.concatenate([[0], src.n_faces + np.arange(src.face_sizes[0])])


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 10: pentagon preservation of one polygon (a pentagon), drawn flat.

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
    from ._draw import NEW, OLD, flat_figure, flat_legend, flat_points

    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    front = _front(src)
    n = src.n_vertices
    pts = out.vertices
    mids = pts[n : n + src.n_edges]
    inner = pts[out.faces[0]]
    with vz.style():
        fig, (a, b) = flat_figure("Figure 10. Pentagon preserving scheme on one face")
        vz.draw_flat(a, src, np.array([0]))
        c = mids.mean(axis=0)
        vz.draw_segments(
            a,
            np.stack([np.repeat(c[None], n, 0), mids], 1)[:, :, :2],
            colors="#777777",
            linewidths=0.8,
            linestyles=(0, (1, 2)),
        )
        ring = np.concatenate([inner, inner[:1]])
        a.plot(ring[:, 0], ring[:, 1], color=EDGE_COLOR, lw=1.1, ls=(0, (3, 2.5)), zorder=3)
        # the edges from the scaled face to the midpoints
        q = out.corners.reshape(-1)[out.offsets[front[1]] : out.offsets[front[-1] + 1]]
        pent = q.reshape(-1, 5)  # (m_h, w, m_next, q_next, q_h)
        vz.draw_segments(
            a,
            np.stack([pts[pent[:, 0]], pts[pent[:, 4]]], 1)[:, :, :2],
            colors=EDGE_COLOR,
            linewidths=1.1,
            linestyles=(0, (3, 2.5)),
        )
        flat_points(a, pts[:n], **OLD)
        flat_points(a, mids, **NEW)
        flat_points(a, inner, **NEW)
        vz.label_panel(
            a, f"(A) the midpoints' polygon scaled\nby {SCALE}; dashed: the edges to insert"
        )
        vz.draw_flat(b, out, front)
        flat_points(b, pts[:n], **OLD)
        flat_points(b, mids, **NEW)
        flat_points(b, inner, **NEW)
        vz.label_panel(b, f"(B) {n} pentagons around a smaller pentagon")
        flat_legend(fig, [5])
    return fig


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 10, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    front = _front(src)
    n = int(src.face_sizes[0])
    pts = out.vertices
    mids = pts[n : n + src.n_edges][:n]  # the front face's edges are edges 0 .. n - 1
    c = mids.mean(axis=0)
    inner = pts[out.faces[0]]
    err = (
        float(np.abs(inner - (c + SCALE * (mids - c))).max())
        if inner.shape == mids.shape
        else float("inf")
    )
    sizes = out.face_sizes[front[front < out.n_faces]]
    return [
        exact(
            "fig10.pentagons",
            "Section 5.2, Figure 10",
            "Each face in the original mesh would now have been split into as many pentagons "
            "as the number of edges (or vertices) in the original face plus one central face "
            "with the same number of sides as the original face.",
            f"faces by size that fill the {n}-gon of (A)",
            {5: n + 1},
            {int(k): int(v) for k, v in zip(*np.unique(sizes, return_counts=True))},
        ),
        bounded(
            "fig10.scaled",
            "Section 5.2, Figure 10",
            "Scale the points in Pi around their centroid by a specified amount. The scale "
            "factor should be less than 1.",
            f"largest distance of a corner of the central face from the edge midpoints "
            f"scaled by {SCALE} (this package's default) about their centroid",
            err,
        ),
        exact(
            "fig10.joined",
            "Section 5.2, Figure 10",
            "For each vertex vi,j in fi, insert an edge between vi,j and the point in Vs "
            "corresponding to vi,j.",
            "corners of the central face by valence (each joined to its midpoint: 3)",
            {3: n},
            {
                int(k): int(v)
                for k, v in zip(*np.unique(out.valences[out.faces[0]], return_counts=True))
            },
        ),
    ]
