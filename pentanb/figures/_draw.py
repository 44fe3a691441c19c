"""Drawing helpers shared by the figure modules (matplotlib; imported by ``draw`` only).

:func:`mesh_figure` lays out 3-D mesh panels labelled (A), (B), ... with a
face-size legend (Figures 1-5, 7-9, 11-13); :func:`flat_figure`,
:func:`flat_points` and :func:`flat_legend` draw the single-polygon diagrams
(Figures 6 and 10).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from ..mesh import Mesh
from ..viz import mpl as vz
from ..viz.colors import EDGE_COLOR, face_color, face_label

__all__ = [
    "TORUS_VIEW",
    "GENUS2_VIEW",
    "OLD",
    "NEW",
    "CENTRE",
    "mesh_figure",
    "flat_figure",
    "flat_points",
    "flat_legend",
]

#: Camera of the genus-1 panels (Figures 4, 5, 9).
TORUS_VIEW = {"elev": 38.0, "azim": -60.0}
#: Camera of the genus-2 panels (Figures 4, 5).
GENUS2_VIEW = {"elev": 40.0, "azim": -75.0}

#: Marker styles of the flat diagrams: old vertices, new vertices, the point sphere.
OLD = {"s": 30, "color": EDGE_COLOR}
NEW = {"s": 34, "facecolor": "white", "edgecolor": EDGE_COLOR, "linewidths": 1.2}
CENTRE = {"s": 60, "color": "#D55E00", "marker": "o", "edgecolor": EDGE_COLOR}


def _panel_text(letter: str, text: str, mesh: Mesh | None = None) -> str:
    label = f"({letter}) {text}"
    if mesh is not None:
        label += f"\nV {mesh.n_vertices:,}  E {mesh.n_edges:,}  F {mesh.n_faces:,}"
    return label


def mesh_figure(
    panels: Sequence[tuple[Mesh, str, dict]],
    *,
    ncols: int | None = None,
    suptitle: str,
    panel_size: float = 3.0,
    counts: bool = True,
    aspect: float = 1.0,
) -> Figure:
    """A figure of 3-D mesh panels, labelled (A), (B), ..., with a face-size legend.

    Parameters
    ----------
    panels : sequence of (Mesh, str, dict)
        Every panel's mesh, its label text (after the letter) and keyword
        arguments of :func:`pentanb.viz.mpl.draw_mesh` (camera, wireframe).
    ncols : int, optional
    suptitle : str
    panel_size : float
        Inches per panel.
    counts : bool
        Whether the labels give V, E, F.
    aspect : float
        Height / width of a panel.
    """
    with vz.style():
        fig, axes = vz.panel_figure(
            len(panels),
            ncols,
            panel_size=panel_size,
            suptitle=suptitle,
            legend_space=0.55,
            aspect=aspect,
        )
        for i, (ax, (mesh, text, kw)) in enumerate(zip(axes, panels)):
            vz.draw_mesh(ax, mesh, **kw)
            vz.label_panel(ax, _panel_text("ABCDEFGH"[i], text, mesh if counts else None))
        vz.add_face_legend(fig, [m for m, _, _ in panels])
    return fig


def flat_figure(suptitle: str) -> tuple[Figure, list]:
    """Two empty 2-D panels for a single-polygon diagram (Figures 6 and 10)."""
    fig, axes = vz.panel_figure(
        2, panel_size=3.2, projection=None, suptitle=suptitle, legend_space=0.75
    )
    for ax in axes:
        ax.set_xlim(-1.18, 1.18)
        ax.set_ylim(-1.18, 1.18)
        ax.set_aspect("equal")
        ax.set_axis_off()
    return fig, axes


def flat_points(ax, pts: np.ndarray, **kw) -> None:
    """Scatter points ((k, 2 or 3) float, z ignored) above the faces."""
    ax.scatter(pts[:, 0], pts[:, 1], zorder=5, **kw)


def flat_legend(fig: Figure, sizes: Sequence[int]) -> None:
    """The legend of a flat diagram: the face sizes drawn, old and new vertices."""
    handles: list = [
        Patch(facecolor=face_color(n), edgecolor=EDGE_COLOR, label=f"{face_label(n)} ({n})")
        for n in sizes
    ]
    handles += [
        Line2D([], [], ls="none", marker="o", markersize=5, color=EDGE_COLOR, label="old vertex"),
        Line2D(
            [],
            [],
            ls="none",
            marker="o",
            markersize=5.5,
            mfc="white",
            color=EDGE_COLOR,
            label="new vertex",
        ),
    ]
    fig.legend(
        handles=handles, loc="lower center", ncol=4, frameon=False, bbox_to_anchor=(0.5, 0.0)
    )
