"""Beyond the paper: convergence under duals, measured instead of "visually confirmed".

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity".  The figure ``convergence`` plots the study of
:func:`pentanb.analysis.convergence.study`: (A) the radius spread and (B)
the largest crease angle after each pair of duals following one remeshing,
(C) the largest crease angle after every subdivision level.  Its panels are
charts, not meshes: :func:`panels` is empty.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..analysis import convergence as cv
from ..mesh import Mesh
from ..schemes import SCHEMES
from .claim import Claim, check

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Convergence under duals (beyond the paper)"
CAPTION = (
    "The paper 'visually confirmed that the algorithms converge with G1 continuity'; "
    "here the largest angle between neighbouring face normals is measured."
)
LABELS = ("A", "B", "C")


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(meshes: Mapping[str, Mesh] | None = None, *, pairs: int = 6, levels: int = 4) -> Figure:
    """Beyond the paper: G1 convergence measured instead of "visually confirmed".

    (A) spread of vertex radii and (B) largest angle between neighbouring
    face normals after each pair of duals following one remeshing
    (:func:`pentanb.analysis.convergence.dual_convergence`); (C) the largest angle
    after every subdivision level (remesh + two duals,
    :func:`pentanb.analysis.convergence.subdivision_convergence`): it falls,
    as a G1 limit surface requires (necessary, not sufficient).

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.
    pairs, levels : int
        Of :func:`pentanb.analysis.convergence.study`.
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FixedLocator, MaxNLocator, NullLocator

    from ..viz import mpl as vz

    data = cv.study(pairs=pairs, levels=levels)
    styles = {"pentagonalize": "-", "preserve_pentagons": "--"}
    with vz.style():
        fig = Figure(figsize=(10.5, 4.0), dpi=vz.DPI)
        axes = list(fig.subplots(1, 3))
        fig.subplots_adjust(left=0.065, right=0.99, bottom=0.3, top=0.9, wspace=0.3)
        fig.suptitle("Convergence under duals (beyond the paper)", fontsize=10.5)
        colors = ["#0072B2", "#D55E00", "#009E73", "#CC79A7"]
        for (mesh_name, scheme), res in data["pairs"].items():
            c = colors[list(data["meshes"]).index(mesh_name)]
            if mesh_name in cv.ROUND_MESHES:
                axes[0].plot(
                    res.steps, res.radius_spread, styles[scheme], color=c, marker="o", ms=3
                )
            axes[1].plot(res.steps, res.max_normal_angle, styles[scheme], color=c, marker="o", ms=3)
        for (mesh_name, scheme), res in data["levels"].items():
            c = colors[list(data["meshes"]).index(mesh_name)]
            axes[2].semilogy(
                res.steps, res.max_normal_angle, styles[scheme], color=c, marker="o", ms=3
            )
        axes[0].set_xlabel("pairs of duals after one remeshing")
        axes[0].set_ylabel("std / mean of vertex radii")
        axes[1].set_xlabel("pairs of duals after one remeshing")
        axes[1].set_ylabel("largest neighbour normal angle (deg)")
        axes[2].set_xlabel("subdivision level (remesh + 2 duals)")
        axes[2].set_ylabel("largest neighbour normal angle (deg)")
        axes[2].yaxis.set_major_locator(FixedLocator([5, 10, 20, 50, 100]))
        axes[2].yaxis.set_minor_locator(NullLocator())
        axes[2].set_yticklabels(["5", "10", "20", "50", "100"])
        axes[2].set_ylim(5, 100)
        for ax, text in zip(
            axes,
            [
                "(A) roundness (cube, tetrahedron)",
                "(B) crease angle per dual pair",
                "(C) crease angle per level: -> 0",
            ],
        ):
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
            ax.grid(alpha=0.25)
            vz.label_panel(ax, text)
            ax.title.set_y(-0.3)
        handles = [
            Line2D([], [], color=colors[i], label=name) for i, name in enumerate(data["meshes"])
        ]
        handles += [
            Line2D([], [], color="#444444", ls=ls, label=SCHEMES[s].label)
            for s, ls in styles.items()
        ]
        fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False)
    return fig


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """The largest crease angle falls at every level, for every mesh and scheme of the study.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    """
    data = cv.study()
    out = []
    for (mesh_name, scheme), res in data["levels"].items():
        a = res.max_normal_angle
        out.append(
            check(
                f"{SCHEMES[scheme].label} of the {mesh_name}: the largest "
                "angle between neighbouring normals falls at every level "
                "(G1 limit)",
                "decreasing",
                tuple(round(float(x), 2) for x in a),
                bool(np.all(np.diff(a) < 0)),
            )
        )
    return out
