"""Beyond the paper's figures: Section 1's "lateral artifact", measured along every edge.

Section 1: "Although, the edge is straight, the first iteration can create a
wave pattern that does not exist in the original data and the final smooth
surface include a smooth wave pattern (see [15, 5]). As shown in Figure
1.C, the new subdivision does not create any lateral artifact."  Section 6
repeats it for "Figures 1 and 8".

The figure ``lateral`` draws :func:`pentanb.analysis.lateral.study`: (A)
the profile along an edge of the 10-cell box after 4 iterations, (B) the
wave's peak-to-peak height iteration by iteration on that box, (C) after 4
iterations against the number of cells per edge.  Its panels are charts:
:func:`panels` is empty.
Section 1's sentence is about Figure 1's own cube, which has no grid along
its edges: there the edge's distance from its axis varies by one bulge, no
wave, about five times smaller than honeycomb's (a claim that holds).  Section
6 says it of "meshes having hard edges", which the gridded boxes test.  The
finding: on boxes whose faces are grids, pentagonalization and pentagon
preservation (with two duals) leave a wave with the grid's period along a
straight edge, about 1.8 % and 2.2 % of a grid cell high, which does not
shrink with the iterations; honeycomb's is larger and shrinks; vertex
insertion leaves none.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..analysis import lateral as lt
from ..mesh import Mesh
from ..schemes import SCHEMES
from .claim import FAILS, HOLDS, Claim, fmt, judged

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Lateral artifact along straight edges (beyond the paper's figures)"
CAPTION = (
    "Section 1: 'the new subdivision does not create any lateral artifact'. Here the "
    "wave along every straight edge of boxes of 3, 6 and 10 cells per edge (and of "
    "Figure 1's cube) is measured, level by level, for every scheme with two duals."
)
LABELS = ("A", "B", "C")

#: The box whose profiles and iterations panels (A) and (B) draw.
BOX = "10 cells"
#: Schemes drawn in panel (A).
PROFILED = ("pentagonalize", "preserve_pentagons", "honeycomb", "vertex_insertion")
#: Colours and line styles of the schemes (the paper's two first).
STYLE = {
    "pentagonalize": ("#009E73", "-"),
    "preserve_pentagons": ("#0072B2", "-"),
    "honeycomb": ("#D55E00", "--"),
    "preserve_hexagons": ("#CC79A7", "--"),
    "loop_remesh": ("#E69F00", ":"),
    "sqrt3_remesh": ("#56B4E9", ":"),
    "vertex_insertion": ("#444444", "-."),
    "corner_cutting": ("#999999", "-."),
}
#: What counts as no wave at all (peak-to-peak, box size 2).
ZERO = 1e-6


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """The lateral-artifact study: profiles (A), level by level (B), box by box (C).

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ...
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    from ..viz import mpl as vz

    data = lt.study()
    iterations = np.arange(1, lt.ITERATIONS + 1)
    with vz.style():
        fig = Figure(figsize=(11.0, 4.8), dpi=vz.DPI)
        axes = list(fig.subplots(1, 3))
        fig.subplots_adjust(left=0.05, right=0.99, bottom=0.36, top=0.9, wspace=0.3)
        fig.suptitle(
            "Lateral artifact: the wave along a straight edge, measured (box size 2)",
            fontsize=10.5,
        )
        # (A) profiles along the edge y = z = 1 of the 10-cell box, level 4
        ax = axes[0]
        window, cell = lt.BOXES[BOX][1], lt.BOXES[BOX][2]
        for i, s in enumerate(PROFILED):
            x, r = data.profile[BOX, s]
            color, ls = STYLE[s]
            ax.plot(x, (r - r.mean()) * 1000 + 8 * (len(PROFILED) - 1 - i), color=color, lw=1.2)
            ax.text(-window, 8 * (len(PROFILED) - 1 - i) + 2.2, SCHEMES[s].label, fontsize=7)
        for k in np.arange(-window, window + 1e-9, cell):
            ax.axvline(k, color="#bbbbbb", lw=0.5, zorder=0)
        ax.plot([window * 1.04] * 2, [0, 5], color="#333333", lw=1.5, clip_on=False)
        ax.text(window * 1.06, 2.5, "0.005", fontsize=7, va="center", rotation=90)
        ax.set_xlabel("position along the edge (grey: grid lines)")
        ax.set_ylabel("distance from the edge's axis, mean removed")
        ax.set_yticks([])
        vz.label_panel(ax, f"(A) profiles, {BOX} per edge, level {lt.ITERATIONS}")
        # (B) level by level on the 10-cell box
        ax = axes[1]
        for s in lt.LATERAL_SCHEMES:
            color, ls = STYLE[s]
            y = np.maximum(data.worst(BOX, s), ZERO)
            ax.semilogy(iterations, y, ls, color=color, marker="o", ms=3)
        ax.axhline(ZERO, color="#777777", lw=0.6)
        ax.text(1.02, ZERO * 1.4, "no wave (< 1e-6)", fontsize=7, color="#555555")
        ax.set_xticks(iterations)
        ax.set_xlabel("subdivision level (remesh + 2 duals)")
        ax.set_ylabel("wave height, peak to peak (12 edges' largest)")
        vz.label_panel(ax, f"(B) level by level, {BOX} per edge")
        # (C) level 4 against the cells per edge
        ax = axes[2]
        boxes = [b for b in lt.BOXES if b.endswith("cells")]
        cells = [int(b.split()[0]) for b in boxes]
        for s in lt.LATERAL_SCHEMES:
            color, ls = STYLE[s]
            last = [max(float(data.worst(b, s)[-1]), ZERO) for b in boxes]
            ax.loglog(cells, last, ls, color=color, marker="o", ms=3)
        ax.axhline(ZERO, color="#777777", lw=0.6)
        ax.set_xticks(cells)
        ax.set_xticklabels([str(c) for c in cells])
        ax.minorticks_off()
        ax.set_xlabel("cells per edge")
        ax.set_ylabel(f"wave height at level {lt.ITERATIONS}")
        vz.label_panel(ax, f"(C) level {lt.ITERATIONS}, box by box")
        for ax in axes:
            ax.grid(alpha=0.25)
            ax.title.set_y(-0.3)
        handles = [
            Line2D([], [], color=STYLE[s][0], ls=STYLE[s][1], label=SCHEMES[s].label)
            for s in lt.LATERAL_SCHEMES
        ]
        fig.legend(handles=handles, loc="lower center", ncol=4, frameon=False, fontsize=7.5)
    return fig


NO_ARTIFACT = "As shown in Figure 1.C, the new subdivision does not create any lateral artifact."
#: Section 6's sentence, the one about meshes with hard edges that the gridded boxes test.
HARD_EDGES = (
    "even meshes having hard edges can be effectively smoothed without creating any lateral "
    "artifacts (wave patterns) [15, 5]"
)
WAVE = (
    "if a non-quadrilateral or non-triangular subdivision is applied to such a cube, it is "
    "hard to represent boundary edges. Although, the edge is straight, the first iteration "
    "can create a wave pattern that does not exist in the original data and the final "
    "smooth surface include a smooth wave pattern (see [15, 5])."
)


#: The box of the study without a grid along its edges.
FIGURE1 = "Figure 1's cube"


def _boxes(data: lt.Lateral) -> list[str]:
    """The boxes of a study whose faces are grids, in the order of
    :data:`~pentanb.analysis.lateral.BOXES`."""
    have = {b for b, _ in data.amplitude}
    return [b for b in lt.BOXES if b in have and b != FIGURE1]


def _table(data: lt.Lateral, scheme: str) -> str:
    rows = []
    for b in _boxes(data):
        w = data.worst(b, scheme)
        cell = lt.BOXES[b][2]
        rows.append(
            f"{b}: " + ", ".join(f"{v:.4f}" for v in w) + f" ({w[-1] / cell:.1%} of a cell)"
        )
    return "; ".join(rows)


def _period(data: lt.Lateral, scheme: str) -> str:
    box = BOX if BOX in _boxes(data) else _boxes(data)[-1]
    x, r = data.profile[box, scheme]
    wl = lt.wavelength(x, r)
    cell = lt.BOXES[box][2]
    where = f"{box}, last level"
    return (
        f"{where}: no wave" if np.isnan(wl) else f"{where}: period {wl:.3f} = {wl / cell:.2f} cells"
    )


def _bumps(data: lt.Lateral, scheme: str) -> int:
    """How many periods of the strongest wave fit the stretch measured on Figure 1's cube
    (1: one bulge; 0: flat)."""
    x, r = data.profile[FIGURE1, scheme]
    wl = lt.wavelength(x, r)
    return 0 if np.isnan(wl) else round(float((x[-1] - x[0]) / wl))


NO_ARTIFACT_READING = (
    "'meshes having hard edges': on cubes whose faces are grids crossing their straight "
    "edges (boxes of 3, 6 and 10 cells per edge: Section 6's sentence, not Section 1's, which "
    "is about Figure 1's own cube), the smoothed surface keeps no wave along a straight "
    "edge: away from the corners, the edge's distance from its axis does not vary with the "
    "grid's period, at any level"
)
FIGURE1_READING = (
    "Section 1's sentence is about Figure 1's cube (as this package reads it, "
    "shapes.hard_edged_cube(): one quad across the middle of each face, thin strips along "
    "the edges): there the smoothed straight edges show no wave pattern, at most one bulge "
    "between the corners' roundings"
)


def claims(meshes: Mapping[str, Mesh] | None = None, data: lt.Lateral | None = None) -> list[Claim]:
    """Section 1's lateral artifact, measured on every gridded box of the study; Figure 1's
    cube, whose edges cross no grid, as an observation.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    data : Lateral, optional
        The study (default: :func:`pentanb.analysis.lateral.study`); the tests
        pass a wrong one.

    Returns
    -------
    list of Claim
    """
    data = lt.study() if data is None else data
    out = []
    for s in ("pentagonalize", "preserve_pentagons"):
        peak = max(float(data.worst(b, s).max()) for b in _boxes(data))
        out.append(
            judged(
                f"lateral.{s}",
                "Section 6",
                HARD_EDGES,
                f"{SCHEMES[s].label} + two duals, peak-to-peak height of the wave along the 12 "
                f"straight edges (largest), levels 1-{lt.ITERATIONS}, box size 2: "
                f"{_table(data, s)}; {_period(data, s)}",
                f"holds if every height is below {ZERO:g} (no wave) on every box at every level",
                HOLDS if peak <= ZERO else FAILS,
                FAILS,
                reading=NO_ARTIFACT_READING,
                cause="a wave with the grid's period along straight edges",
            )
        )
    s = "honeycomb"
    low = min(float(data.worst(b, s).min()) for b in _boxes(data))
    out.append(
        judged(
            "lateral.honeycomb",
            "Section 1",
            WAVE,
            f"{SCHEMES[s].label} ([5]) + two duals, peak-to-peak height along the 12 edges "
            f"(largest), levels 1-{lt.ITERATIONS}: {_table(data, s)}; smallest {fmt(low)}",
            f"holds if there is a wave (height above {ZERO:g}) on every box at every level",
            HOLDS if low > ZERO else FAILS,
            reading="a scheme the paper cites for the artifact ([5]: honeycomb, the dual of "
            "sqrt(3)) leaves a wave along the straight edges of such a cube, at every level",
            cause="honeycomb's wave along straight edges",
        )
    )
    if FIGURE1 in {b for b, _ in data.amplitude}:
        parts, one = [], True
        for s in ("pentagonalize", "preserve_pentagons"):
            w = data.worst(FIGURE1, s)
            bumps = _bumps(data, s)
            one = one and bumps == 1
            parts.append(
                f"{SCHEMES[s].label}: " + ", ".join(f"{v:.4f}" for v in w) + f" ({w[-1] / 2:.2%} "
                f"of the box), the strongest period fitting the stretch {bumps} time(s)"
            )
        if (FIGURE1, "honeycomb") in data.amplitude:
            h = data.worst(FIGURE1, "honeycomb")
            p = data.worst(FIGURE1, "pentagonalize")
            parts.append(
                f"for comparison honeycomb ([5]): {h[-1]:.4f} at the last level, "
                f"{h[-1] / max(p[-1], 1e-300):.1f} times pentagonalization's"
            )
        out.append(
            judged(
                "lateral.bulge",
                "Section 1, Figure 1.C",
                NO_ARTIFACT,
                "peak-to-peak variation of the distance from the axis along the 12 straight "
                f"edges (largest), levels 1-{lt.ITERATIONS}, box size 2, the middle 1.2 of "
                "every edge: " + "; ".join(parts),
                "holds if along each straight edge the variation is one bulge (the strongest "
                "period is the stretch measured) for both schemes, no wave",
                HOLDS if one else FAILS,
                reading=FIGURE1_READING,
                cause="the corners' rounding along Figure 1's cube's edges",
            )
        )
    return out
