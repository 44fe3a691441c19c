"""Beyond the paper: convergence under duals, measured instead of "visually confirmed".

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity"; Section 5.1 (of Figure 7): "the resulting shape becomes more and
more uniform with each application of dual operation".  The figure
``convergence`` plots :func:`pentanb.analysis.convergence.study`: after one
remeshing and each pair of duals, (A) the radius spread, (B) the spread of
the edge lengths and (C) the largest crease angle; after every iteration
(remesh + two duals), the largest crease angle (D) at the extraordinary
vertices and (E) elsewhere; dotted in (D), the fall per level a triangle's
spectrum predicts for pentagon preservation
(:func:`pentanb.analysis.convergence.predicted_crease_rate`), drawn through
the rabbit's last level.  Its panels are charts: :func:`panels` is empty.

A G1 limit needs the crease angles to tend to 0 (necessary, not
sufficient); an angle that falls at every level is evidence of that, but
neither necessary (it may fall unevenly and still tend to 0) nor enough (it
may fall towards a positive limit).  The claims here test that the largest
crease angle falls at every level, on every mesh of the study
(four levels; the rabbit five, its creases under pentagon preservation
falling at the slow rate the spectrum of a triangle predicts).  The
uniformity under more and more duals on fixed connectivity is measured on
other shapes than Figure 7's: observations, with no verdict on the paper.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..analysis import convergence as cv
from ..mesh import Mesh
from ..schemes import SCHEMES
from .claim import FAILS, HOLDS, OBSERVATION, Claim, falls, fmt, judged, monotone_claim

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Convergence under duals (beyond the paper)"
CAPTION = (
    "The paper 'visually confirmed that the algorithms converge with G1 continuity' and "
    "saw the shape become 'more and more uniform with each application of dual "
    "operation'; here the spreads of radii and edge lengths and the largest angle "
    "between neighbouring face normals are measured."
)
LABELS = ("A", "B", "C", "D", "E")

#: Colours of the study's meshes; line styles of the schemes.
COLORS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7")
STYLES = {"pentagonalize": "-", "preserve_pentagons": "--"}


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(
    meshes: Mapping[str, Mesh] | None = None,
    *,
    duals: int = 12,
    iterations: int = 4,
    max_faces: int | None = None,
) -> Figure:
    """Convergence measured: roundness, uniformity and creases per dual pair and per iteration.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.
    duals : int, even, >= 2
        Duals after one remeshing (panels A-C, measured after every pair).
    iterations : int, >= 1
        Iterations of remesh + two duals (panels D and E); the rabbit one more.
    max_faces : int, optional
        No mesh of more faces: every mesh's iterations stop before one
        (:func:`pentanb.analysis.convergence.study`).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FixedLocator, MaxNLocator, NullLocator

    from ..viz import mpl as vz

    data = cv.study(duals=duals, iterations=iterations, max_faces=max_faces)
    names = list(data["meshes"])
    with vz.style():
        fig = Figure(figsize=(10.5, 8.0), dpi=vz.DPI)
        grid = fig.subplots(2, 3)
        axes = [grid[0, 0], grid[0, 1], grid[0, 2], grid[1, 0], grid[1, 1]]
        grid[1, 2].set_axis_off()
        fig.subplots_adjust(left=0.07, right=0.98, bottom=0.12, top=0.93, wspace=0.3, hspace=0.62)
        fig.suptitle("Convergence under duals (beyond the paper)", fontsize=10.5)
        for (mesh_name, scheme), res in data["duals"].items():
            c, ls = COLORS[names.index(mesh_name)], STYLES[scheme]
            if mesh_name in cv.ROUND_MESHES:
                axes[0].plot(res.steps, res.radius_spread, ls, color=c, marker="o", ms=3)
            axes[1].plot(res.steps, res.edge_spread, ls, color=c, marker="o", ms=3)
            axes[2].plot(res.steps, res.max_normal_angle, ls, color=c, marker="o", ms=3)
        for (mesh_name, scheme), res in data["iterations"].items():
            c, ls = COLORS[names.index(mesh_name)], STYLES[scheme]
            axes[3].semilogy(res.steps, res.crease_at, ls, color=c, marker="o", ms=3)
            axes[4].semilogy(res.steps, res.crease_elsewhere, ls, color=c, marker="o", ms=3)
        # the rate a triangle's spectrum predicts, through the rabbit's last level
        rabbit = data["iterations"].get(("rabbit", "preserve_pentagons"))
        lam1, lam3, _ = cv.predicted_crease_rate()
        if rabbit is not None:
            k = rabbit.steps.astype(float)
            last = float(rabbit.crease_at[-1])
            axes[3].semilogy(k, last * (lam3 / lam1) ** (k - k[-1]), ":", color="#777777", lw=1.2)
        for ax in axes[:3]:
            ax.set_xlabel("pairs of duals after one remeshing")
        axes[0].set_ylabel("std / mean of vertex radii")
        axes[1].set_ylabel("std / mean of edge lengths")
        axes[2].set_ylabel("largest crease angle (deg)")
        for ax in axes[3:]:
            ax.set_xlabel("subdivision level (remesh + 2 duals)")
            ax.set_ylabel("largest crease angle (deg)")
            ax.yaxis.set_major_locator(FixedLocator([2, 5, 10, 20, 50, 100]))
            ax.yaxis.set_minor_locator(NullLocator())
            ax.set_yticklabels(["2", "5", "10", "20", "50", "100"])
            ax.set_ylim(2, 180)
        texts = [
            "(A) roundness (cube, tetrahedron)",
            "(B) uniformity of edge lengths",
            "(C) crease angle per dual pair",
            "(D) crease per level, extraordinary vertices",
            "(E) crease per level, elsewhere",
        ]
        for ax, text in zip(axes, texts):
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
            ax.grid(alpha=0.25)
            vz.label_panel(ax, text)
            ax.title.set_y(-0.3)
        handles = [Line2D([], [], color=COLORS[i], label=name) for i, name in enumerate(names)]
        handles += [
            Line2D([], [], color="#444444", ls=ls, label=SCHEMES[s].label)
            for s, ls in STYLES.items()
        ]
        handles.append(
            Line2D(
                [],
                [],
                color="#777777",
                ls=":",
                label=f"x{lam3 / lam1:.3f} per level: a triangle's\n"
                "spectrum (pentagon preservation)",
            )
        )
        grid[1, 2].legend(
            handles=handles,
            loc="center",
            frameon=False,
            fontsize=8.5,
            title="pair 0: the remeshing alone",
            title_fontsize=8,
        )
    return fig


G1 = (
    "We have applied pentagonal conversion and preservation schemes with dual on wide "
    "variety of meshes; and we have visually confirmed that the algorithms converge with "
    "G1 continuity."
)
UNIFORM = (
    "the resulting shape becomes more and more uniform with each application of dual operation."
)

#: The verdicts recorded for the study's claims (as measured when they were written).
RECORDED_CREASE = {
    ("cube", "pentagonalize"): HOLDS,
    ("cube", "preserve_pentagons"): HOLDS,
    ("tetrahedron", "pentagonalize"): HOLDS,
    ("tetrahedron", "preserve_pentagons"): HOLDS,
    ("torus", "pentagonalize"): HOLDS,
    ("torus", "preserve_pentagons"): HOLDS,
    ("rabbit", "pentagonalize"): HOLDS,
    ("rabbit", "preserve_pentagons"): HOLDS,
}
#: Whether every spread falls at every pair of duals from the first (the observations,
#: as seen when they were written).
RECORDED_UNIFORM = {
    ("cube", "pentagonalize"): True,
    ("cube", "preserve_pentagons"): False,
    ("tetrahedron", "pentagonalize"): True,
    ("tetrahedron", "preserve_pentagons"): False,
    ("torus", "pentagonalize"): False,
    ("torus", "preserve_pentagons"): False,
    ("rabbit", "pentagonalize"): True,
    ("rabbit", "preserve_pentagons"): True,
}

CREASE_READING = (
    "a G1 limit needs the angle between neighbouring faces to tend to 0 everywhere as the "
    "levels go on; read as the part of it that can be measured: the largest crease angle of "
    "the mesh (at the extraordinary vertices or elsewhere) falls at every level (evidence "
    "that it tends to 0, which G1 needs; neither necessary nor sufficient for G1)"
)


def _rate(values: np.ndarray, scheme: str) -> str:
    """The measured factors per level, and the spectrum's prediction for the slowest
    element (a triangle) of pentagon preservation."""
    v = values[~np.isnan(values)]
    ratios = v[1:] / v[:-1]
    mean = float((v[-1] / v[0]) ** (1 / (len(v) - 1)))
    text = "; per level x" + ", x".join(f"{r:.3f}" for r in ratios) + f" (mean x{mean:.3f})"
    if scheme != "preserve_pentagons":
        return text
    lam1, lam3, source = cv.predicted_crease_rate()
    q = lam3 / lam1
    return text + (
        f"; a triangle's spectrum (scale 0.75, {source}) predicts x{q:.4f} per level once "
        f"the levels are many (|lambda3| / |lambda1| = {lam3:.4f} / {lam1:.4f}): a slow fall, "
        f"halving the crease every {np.log(0.5) / np.log(q):.0f} levels"
    )


def claims(meshes: Mapping[str, Mesh] | None = None, data: dict | None = None) -> list[Claim]:
    """The crease angle per iteration (its largest value over the mesh, at the extraordinary
    vertices and elsewhere), then the uniformity per pair of duals (observations), for every
    mesh and scheme of the study.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    data : dict, optional
        The study (default: :func:`pentanb.analysis.convergence.study`); the
        tests pass one made from wrong meshes.

    Returns
    -------
    list of Claim
    """
    data = cv.study() if data is None else data
    out = []
    for (mesh_name, scheme), res in data["iterations"].items():
        largest = np.fmax(res.crease_at, res.crease_elsewhere)
        ok = not falls(largest)
        rate = _rate(largest, scheme) if mesh_name == "rabbit" else ""
        out.append(
            judged(
                f"convergence.crease.{mesh_name}.{scheme}",
                "Section 7",
                G1,
                f"{SCHEMES[scheme].label} of the {mesh_name}, largest crease angle of the mesh "
                f"(degrees) at levels 1-{len(res.steps)}: "
                f"{fmt([round(float(x), 1) for x in largest])}; at the extraordinary vertices "
                f"{fmt([round(float(x), 1) for x in res.crease_at])}, elsewhere "
                f"{fmt([round(float(x), 1) for x in res.crease_elsewhere])} (nan: no such edge)"
                + rate,
                "holds if the largest crease angle falls at every level",
                HOLDS if ok else FAILS,
                RECORDED_CREASE.get((mesh_name, scheme), HOLDS),  # unknown: as the paper says
                reading=CREASE_READING,
                cause="the crease angle falls level by level",
            )
        )
    for (mesh_name, scheme), res in data["duals"].items():
        series = {
            "edge-length spread": res.edge_spread[1:],
            "face-angle spread": res.angle_spread[1:],
        }
        if mesh_name in cv.ROUND_MESHES:
            series["radius spread"] = res.radius_spread[1:]
        before = ", ".join(
            f"{k.split()[0]} {float(v[0]):.4f}"
            for k, v in {
                "edge": res.edge_spread,
                "angle": res.angle_spread,
                "radius": res.radius_spread,
            }.items()
            if k != "radius" or mesh_name in cv.ROUND_MESHES
        )
        seen = RECORDED_UNIFORM.get((mesh_name, scheme), True)
        out.append(
            monotone_claim(
                f"convergence.uniform.{mesh_name}.{scheme}",
                "Section 5.1, said of Figure 7's tetrahedron; here other shapes and schemes, "
                "and more duals without refinement",
                UNIFORM,
                f"{SCHEMES[scheme].label} of the {mesh_name} (pair 0, the remeshing alone: "
                f"{before}), then pairs of duals 1-{int(res.steps[-1])}",
                series,
                [f"pair {int(k)}" for k in res.steps[1:]],
                HOLDS if seen else FAILS,
                kind=OBSERVATION,
                cause="more pairs of duals on one connectivity",
            )
        )
    return out
