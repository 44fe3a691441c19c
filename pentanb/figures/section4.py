"""Section 4: equation (1), ``m = 2n/(n-2) (1 + (2g-2)/v)``, and the (n, m) chart.

The figure ``equation1`` plots the average valence m of an n-gonal mesh
against its number of vertices v for genus 0, 1, 2 (panels A-C, with dots
for meshes of this package) and the chart of the limits ``(n, 2n/(n-2))``
(panel D).  Its panels are charts, not meshes: :func:`panels` is empty.

(The module is called ``section4`` so that ``pentanb.figures.equation1``
stays the drawing function.)
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np

from .. import shapes, topology
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import Claim, eq

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

TITLE = "Section 4: equation (1) and the (n, m) chart"
CAPTION = (
    "m = 2n/(n-2) (1 + (2g-2)/v), the average valence of an n-gonal mesh of genus g with "
    "v vertices; n-gonal meshes need m >= 3."
)
LABELS = ("A", "B", "C", "D")


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def _samples() -> list[tuple[int, int, int, str, float]]:
    """(n, g, v, name, label offset) of meshes of the package drawn on equation (1)."""
    rows = []
    for name, mesh, dy in (
        ("tetrahedron", shapes.tetrahedron(), -2.2),
        ("cube", shapes.cube(), -1.6),
        ("dodecahedron", shapes.dodecahedron(), -1.0),
        ("gyro(cube)", subdivide(shapes.cube(), "pentagonalize", 1, 2), 0.9),
        ("hexagonal torus", shapes.hexagonal_torus(), 0.8),
        ("hexagonal genus 2", shapes.hexagonal_surface(2), 0.9),
    ):
        n = int(mesh.face_sizes[0])
        rows.append((n, mesh.genus, mesh.n_vertices, name, dy))
    return rows


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Section 4: equation (1), ``m = 2n/(n-2) (1 + (2g-2)/v)``, and the (n, m) chart.

    Panels (A)-(C) plot the average valence m against v for n = 3..8 and
    g = 0, 1, 2 with the line m = 3 (an n-gonal mesh needs m >= 3); dots
    mark meshes of the package.  Panel (D) is the chart of the limits
    ``(n, 2n/(n-2))``.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.
    """
    from matplotlib.figure import Figure

    from ..viz import mpl as vz
    from ..viz.colors import EDGE_COLOR, face_color

    v = np.arange(1, 201, dtype=float)
    samples = _samples()
    with vz.style():
        fig = Figure(figsize=(7.6, 7.4), dpi=vz.DPI)
        axes = list(fig.subplots(2, 2).ravel())
        fig.subplots_adjust(left=0.08, right=0.98, bottom=0.1, top=0.93, hspace=0.45, wspace=0.22)
        fig.suptitle(
            "Section 4. Equation (1): average valence m of an n-gonal mesh with "
            "v vertices and genus g",
            fontsize=10.5,
        )
        for g, ax in zip((0, 1, 2), axes):
            for n in range(3, 9):
                m = topology.average_valence(n, g, v)
                ax.plot(
                    v, np.where(m >= 3, m, np.nan), color=face_color(n), lw=1.7, label=f"n = {n}"
                )
                ax.plot(v, m, color=face_color(n), lw=1.2, alpha=0.35)
            ax.axhline(3, color=EDGE_COLOR, lw=1.0, ls="--", label="m = 3")
            for n, gg, vv, name, dy in samples:
                if gg == g:
                    mm = topology.average_valence(n, g, vv)
                    ax.plot(vv, mm, "o", ms=5, mfc=face_color(n), mec=EDGE_COLOR, mew=0.8, zorder=5)
                    ax.annotate(
                        name,
                        (vv, mm),
                        xytext=(vv + 12 if vv < 120 else vv - 75, mm + dy),
                        fontsize=7.5,
                        arrowprops={"arrowstyle": "-", "lw": 0.6, "color": "#555555"},
                        va="center",
                    )
            ax.set_xlim(0, 200)
            ax.set_ylim(0, 8.2)
            ax.set_xlabel("v (vertices)")
            ax.set_ylabel("m (average valence)")
            ax.grid(alpha=0.25)
            vz.label_panel(ax, f"({'ABC'[g]}) genus g = {g}")
            ax.title.set_y(-0.2)
        axes[1].legend(
            ncol=4,
            fontsize=7.5,
            loc="upper center",
            frameon=True,
            title="faint where m < 3",
            title_fontsize=7.5,
            columnspacing=1.0,
            handlelength=1.6,
        )
        _chart_panel(axes[3])
        vz.label_panel(axes[3], "(D) the (n, m) chart: limits v -> inf (= g = 1)")
        axes[3].title.set_y(-0.2)
    return fig


def _chart_panel(ax: Axes) -> None:
    from ..viz.colors import EDGE_COLOR, face_color

    n = np.linspace(3, 8, 200)
    ax.plot(n, 2 * n / (n - 2), color="#555555", lw=1.2, label="m = 2n / (n - 2)")
    ax.axhline(3, color=EDGE_COLOR, lw=1.0, ls="--")
    ax.axvspan(6, 8.2, color="#999999", alpha=0.18, lw=0)
    ax.text(7.1, 4.8, "n > 6:\nm < 3,\nno n-gonal\nschemes", ha="center", fontsize=7.5)
    for row in topology.SCHLAFLI_CHART:
        nn, mm = float(row.n), float(row.m)
        color = face_color(int(row.n)) if row.n.denominator == 1 else "#777777"
        ax.plot(nn, mm, "o", ms=7, mfc=color, mec=EDGE_COLOR, mew=0.8, zorder=4)
        ax.annotate(
            f"({_frac(row.n)}, {_frac(row.m)})",
            (nn, mm),
            xytext=(7, 3),
            textcoords="offset points",
            fontsize=8,
        )
    ax.set_xlim(2.8, 8.2)
    ax.set_ylim(0, 8.2)
    ax.set_xlabel("n (sides of a face)")
    ax.set_ylabel("m (valence)")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=7.5, loc="upper right")


def _frac(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What Section 4 says, computed by :mod:`pentanb.topology` and measured on meshes.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    """
    av = topology.average_valence
    out = []
    for name, n, g, v in (("tetrahedron", 3, 0, 4), ("cube", 4, 0, 8), ("dodecahedron", 5, 0, 20)):
        out.append(
            eq(
                f"n = {n}, g = 0: the simplest mesh ({name}) has v = {v} and m = 3 by equation (1)",
                (v, 3.0),
                (topology.min_vertices(n, 0), av(n, g, v)),
            )
        )
    big = np.arange(3, 100000)
    out.append(
        eq(
            "n = 6, g = 0: m = 3 (1 - 2/v) < 3 for every v: no hexagonalization "
            "(values of v < 100000 with m >= 3)",
            0,
            int(np.sum(av(6, 0, big) >= 3)),
        )
    )
    out.append(
        eq(
            "n = 5, g = 0: m = 10/3 (1 - 2/v) >= 3 exactly when v >= 20",
            20,
            int(big[np.argmax(av(5, 0, big) >= 3)]),
        )
    )
    lim = {n: topology.limit_valence(n) for n in range(3, 9)}
    out.append(
        eq(
            "limit of m as v -> inf: 2n/(n-2) for n = 3..8",
            {n: Fraction(2 * n, n - 2) for n in range(3, 9)},
            lim,
        )
    )
    out.append(
        eq(
            "2n/(n-2) < 3 exactly for n > 6 (no n-gonal schemes)",
            [7, 8],
            [n for n, x in lim.items() if x < 3],
        )
    )
    out.append(
        eq(
            "the limit valence of pentagonal meshes is not an integer (10/3); "
            "of triangles, quads, hexagons it is",
            {3: True, 4: True, 5: False, 6: True},
            {n: lim[n].denominator == 1 for n in (3, 4, 5, 6)},
        )
    )
    chart = [(r.n, r.m) for r in topology.SCHLAFLI_CHART]
    out.append(
        eq(
            "the (n, m) chart",
            [
                (Fraction(6), Fraction(3)),
                (Fraction(5), Fraction(10, 3)),
                (Fraction(4), Fraction(4)),
                (Fraction(10, 3), Fraction(5)),
                (Fraction(3), Fraction(6)),
            ],
            chart,
        )
    )
    # equation (1) on real meshes: measured 2E/V against the formula
    for name, m in (
        ("pentagonalized hard cube", subdivide(shapes.hard_edged_cube(), "pentagonalize", 1, 2)),
        ("rabbit x2", subdivide(shapes.animal(), "pentagonalize", 2, 2)),
        ("hexagonal genus 2", shapes.hexagonal_surface(2)),
        ("gyro(hex. torus)", subdivide(shapes.hexagonal_torus(), "pentagonalize", 1, 2)),
    ):
        n = int(m.face_sizes[0])
        eq1 = Fraction(2 * n, n - 2) * (1 + Fraction(2 * m.genus - 2, m.n_vertices))
        out.append(
            eq(
                f"equation (1) = measured 2E/V on the {name} (n={n}, "
                f"g={m.genus}, v={m.n_vertices})",
                eq1,
                Fraction(2 * m.n_edges, m.n_vertices),
            )
        )
    return out
