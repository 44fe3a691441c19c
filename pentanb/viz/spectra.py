"""Pictures of the continuity analysis: spectra, characteristic maps, subdivision matrices.

Section 7 of the paper: "we have visually confirmed that the algorithms
converge with G1 continuity. However, there is still a need for theoretical
proofs for convergence."  The drawings here show what
:mod:`pentanb.analysis.spectral` finds:

* :func:`plot_spectra` -- the moduli of the leading eigenvalues of every
  scheme (+ 2 duals) at vertices of valence 3 to 8 and faces of 3 to 8
  sides (``figures/spectra.png``);
* :func:`plot_characteristic_maps` -- the characteristic maps of the
  paper's schemes (and of vertex insertion for comparison), each with its
  verdict, or why none exists (``figures/characteristic_maps.png``);
* :func:`plot_scale` -- pentagon preservation's leading eigenvalues against
  its scale, with 2, 4 and 6 duals (``figures/scale.png``), and
  :func:`plot_scale_family` for one element (a slider in the notebook);
* :func:`plot_subdivision_matrix` -- a local (or global) subdivision matrix
  as a picture of its weights (the notebook ``09_continuity``);
* :func:`plot_eigenvalues` and :func:`draw_characteristic_map` -- one case,
  for a slider.

What the paper's words become on these pictures -- the claims, with their
verdicts -- is in the figure modules :mod:`pentanb.figures.spectra` and
:mod:`pentanb.figures.characteristic_maps` (the one claim framework,
:class:`pentanb.figures.Claim`); this module only draws.

Figures are plain :class:`matplotlib.figure.Figure` objects (no pyplot).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.figure import Figure

from ..analysis.spectral import (
    CharacteristicMap,
    ContinuityRow,
    LocalSpectrum,
    ScaleFamily,
    ScaleStudy,
    continuity_table,
)

__all__ = [
    "plot_spectra",
    "plot_characteristic_maps",
    "plot_scale",
    "plot_scale_family",
    "plot_subdivision_matrix",
    "plot_eigenvalues",
    "draw_characteristic_map",
    "PAPER_LABELS",
]

#: Table labels of the paper's schemes (Section 5).
PAPER_LABELS = ("pentagonalize", "preserve_pentagons 0.75", "preserve_pentagons 0.5")

_KIND_STYLE = {"vertex": ("#0072B2", "o"), "face": ("#D55E00", "s")}


def _plural(kind: str) -> str:
    return "vertices" if kind == "vertex" else "faces"


def _rows(rows: Sequence[ContinuityRow] | None) -> list[ContinuityRow]:
    return list(continuity_table() if rows is None else rows)


def _stationary(rows, label=None, kind=None):
    return [
        r
        for r in rows
        if r.spectrum is not None
        and r.spectrum.stationary
        and (label is None or r.label == label)
        and (kind is None or r.kind == kind)
    ]


# ---------------------------------------------------------------------------
# figures/spectra.png
# ---------------------------------------------------------------------------


def _letter(i: int) -> str:
    """The panel label of the ``i``-th panel: ``"(A)"``, ``"(B)"``, ..."""
    return f"({chr(ord('A') + i)})"


def plot_spectra(
    rows: Sequence[ContinuityRow] | None = None,
    n_eigen: int = 4,
    labels: Sequence[str] | None = None,
) -> Figure:
    """Moduli of lambda1..lambda4 per element type, one panel per scheme (+ 2 duals).

    Parameters
    ----------
    rows : list of ContinuityRow, optional
        From :func:`pentanb.analysis.spectral.continuity_table` (computed
        when not given).
    n_eigen : int
        How many eigenvalues after the eigenvalue 1 to draw.
    labels : sequence of str, optional
        The schemes (table labels) to draw, one panel each, lettered (A),
        (B), ... in this order; default every label of ``rows`` with a
        stationary neighbourhood somewhere.

    Returns
    -------
    Figure
        Vertices (blue circles) and faces (orange squares) of each size; the
        subdominant pair filled, the next ones smaller and hollow; a red
        cross where Reif's standard setting ``|lambda1| = |lambda2| >
        |lambda3|`` fails, a ring where the subdominant pair is complex.
    """
    rows = _rows(rows)
    if labels is None:
        labels = list(dict.fromkeys(r.label for r in rows if _stationary([r])))
    ncol = 3
    nrow = max(1, math.ceil(len(labels) / ncol))
    fig = Figure(figsize=(4.0 * ncol, 3.0 * nrow + 0.6), layout="constrained")
    axes = fig.subplots(nrow, ncol, squeeze=False, sharey=True)
    for i, (ax, label) in enumerate(zip(axes.flat, labels)):
        for kind, (color, marker) in _KIND_STYLE.items():
            sel = _stationary(rows, label, kind)
            if not sel:
                continue
            shift = -0.12 if kind == "vertex" else 0.12
            for r in sel:
                m = r.spectrum.moduli[1 : 1 + n_eigen]
                x = r.size + shift
                for j, val in enumerate(m):
                    ax.plot(
                        [x],
                        [val],
                        marker=marker,
                        ms=6 if j < 2 else 4,
                        mfc=color if j < 2 else "none",
                        mec=color,
                        ls="none",
                        alpha=1.0 if j < 2 else 0.7,
                    )
                if not r.spectrum.standard:
                    ax.plot([x], [m[0]], marker="x", ms=11, mew=2, color="#CC0000", ls="none")
                elif r.spectrum.subdominant_complex:
                    ax.plot([x], [m[0]], marker="o", ms=12, mfc="none", mec="#555555", ls="none")
            ax.plot([], [], marker=marker, color=color, ls="none", label=_plural(kind))
        ax.set_title(f"{_letter(i)} {label} + 2 duals", fontsize=10)
        ax.set_xticks(range(3, 9))
        ax.set_xlim(2.5, 8.5)
        ax.set_ylim(0, 1)
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, loc="lower right")
    for ax in axes.flat[len(labels) :]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("valence / sides")
    for ax in axes[:, 0]:
        ax.set_ylabel("|λ| per step")
    fig.suptitle(
        "Leading eigenvalue moduli |λ1| ≥ |λ2| ≥ |λ3| ≥ |λ4| (filled: subdominant pair; "
        "× standard setting fails; ○ complex pair)",
        fontsize=10,
    )
    return fig


# ---------------------------------------------------------------------------
# characteristic maps
# ---------------------------------------------------------------------------


def draw_characteristic_map(
    ax,
    cmap: CharacteristicMap,
    *,
    title: str | None = None,
    antialiased: bool = True,
    edgecolor: str = "#333333",
) -> None:
    """Draw a characteristic map's control net on a matplotlib axis.

    Faces turning the majority's way are light blue, the others red (a
    fold); the element's centre is a black dot.

    Parameters
    ----------
    ax : matplotlib axis
    cmap : CharacteristicMap
    title : str, optional
        Default ``"<kind> <size>: <verdict>"`` (red unless regular and
        injective).
    antialiased : bool
        Smooth polygon edges; a figure of many nets is drawn without (its PNG
        is a quarter of the size).
    edgecolor : str
        Colour of the faces' edges.
    """
    pts = cmap.points
    off = cmap.offsets
    polys = [pts[cmap.corners[off[i] : off[i + 1]]] for i in range(cmap.n_faces)]
    major = 1 if np.sum(cmap.signs) >= 0 else -1
    colors = ["#A6CEE3" if s == major else "#E31A1C" for s in cmap.signs]
    ax.add_collection(
        PolyCollection(
            polys,
            facecolors=colors,
            edgecolors=edgecolor,
            linewidths=0.3,
            antialiased=antialiased,
        )
    )
    ax.plot([cmap.centre[0]], [cmap.centre[1]], "k.", ms=4)
    if pts.size:
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        pad = 0.05 * float((hi - lo).max() or 1.0)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    if title is None:
        sp = cmap.spectrum
        title = f"{sp.kind} {sp.size}: {cmap.verdict}"
    ax.set_title(title, fontsize=7, color="black" if cmap.injective else "#CC0000")


def plot_characteristic_maps(
    rows: Sequence[ContinuityRow] | None = None,
    labels: Sequence[str] = (*PAPER_LABELS, "vertex_insertion"),
) -> Figure:
    """The characteristic maps of the given schemes, one row of panels per scheme and kind.

    Parameters
    ----------
    rows : list of ContinuityRow, optional
        From :func:`~pentanb.analysis.spectral.continuity_table`.
    labels : sequence of str
        Schemes (table labels) to draw; default the paper's two schemes and
        vertex insertion (Catmull-Clark-like) for comparison.

    Returns
    -------
    Figure
        One row per scheme and kind of element (vertices, then faces, where
        the scheme keeps them), lettered (A), (B), ... in the title of its
        first panel; one panel per valence or size, its verdict under it
        (red where the map is not regular and injective).
    """
    rows = _rows(rows)
    lines = []
    for label in labels:
        for kind in ("vertex", "face"):
            sel = [
                r for r in _stationary(rows, label, kind) if r.char_map is not None or r.map_note
            ]
            if sel:
                lines.append((label, kind, sel))
    ncol = max((len(sel) for _, _, sel in lines), default=1)
    nrow = max(1, len(lines))
    fig = Figure(figsize=(1.7 * ncol + 1.2, 1.9 * nrow + 0.5), layout="constrained")
    axes = fig.subplots(nrow, ncol, squeeze=False)
    for i, (label, kind, sel) in enumerate(lines):
        for j in range(ncol):
            ax = axes[i, j]
            if j >= len(sel):
                ax.set_visible(False)
                continue
            cm = sel[j].char_map
            head = f"{kind} {sel[j].size}"
            title = f"{_letter(i)} {head}" if j == 0 else head
            if cm is None:
                _no_map(ax, sel[j], title)
                continue
            draw_characteristic_map(
                ax,
                cm,
                title=title,
                antialiased=False,  # 36 nets of ~200 faces: 0.3 MB instead of 1.25 MB
                edgecolor="#5A7D96",
            )
            ax.title.set_color("black")
            ax.set_xlabel(cm.verdict, fontsize=6.5, color="black" if cm.injective else "#CC0000")
        axes[i, 0].set_ylabel(f"{label}\n{_plural(kind)}", fontsize=7)
    fig.suptitle(
        "Characteristic maps (subdominant eigenvectors, 2 levels down); red: folded faces "
        "or no map",
        fontsize=9,
    )
    return fig


def _no_map(ax, row: ContinuityRow, title: str) -> None:
    """An empty panel saying why the element has no characteristic map."""
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=7)
    sp = row.spectrum
    mode = int(sp.modes[1]) if sp is not None and sp.modes.size > 1 else -1
    if sp is not None and sp.subdominant_count == 1:
        text = "λ1 simple" + (f"\n(mode {mode})" if mode >= 0 else "")
    elif sp is not None and sp.subdominant_count >= 3:
        text = f"{sp.subdominant_count} eigenvalues\nof one modulus"
    else:
        text = "no map"
    ax.text(0.5, 0.5, text, ha="center", va="center", fontsize=7, color="#CC0000")
    ax.set_xlabel("no characteristic map", fontsize=6.5, color="#CC0000")


# ---------------------------------------------------------------------------
# one case: eigenvalues, matrices
# ---------------------------------------------------------------------------


def plot_eigenvalues(spectrum: LocalSpectrum, ax=None, n: int = 12) -> Figure:
    """The leading eigenvalues of one local matrix in the complex plane (per step).

    Parameters
    ----------
    spectrum : LocalSpectrum
    ax : matplotlib axis, optional
    n : int
        How many eigenvalues to draw (by decreasing modulus).
    """
    if ax is None:
        fig = Figure(figsize=(4.2, 4.0), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(np.cos(t), np.sin(t), color="#BBBBBB", lw=0.8)
    if spectrum.stationary and spectrum.eigenvalues.size:
        lam = spectrum.eigenvalues[:n]
        # per-step values: the p-th root with the smallest argument
        z = np.abs(lam) ** (1 / spectrum.period) * np.exp(1j * np.angle(lam) / spectrum.period)
        ax.plot(z.real[2:], z.imag[2:], "o", mfc="none", mec="#555555", label="λ3, λ4, ...")
        ax.plot(z.real[1:2], z.imag[1:2], "o", color="#0072B2", ms=8, label="λ1")
        ax.plot(z.real[2:3], z.imag[2:3], "o", color="#56B4E9", ms=8, label="λ2")
        ax.plot([1], [0], "k*", ms=10, label="λ0 = 1")
        r = float(np.abs(z[1]))
        ax.plot(r * np.cos(t), r * np.sin(t), ":", color="#0072B2", lw=0.8)
        ax.legend(fontsize=7, loc="upper left")
        reason = spectrum.standard_reason
        ax.set_title(
            f"{spectrum.scheme} {spectrum.kind} {spectrum.size}: |λ1| = {np.abs(z[1]):.4f}\n"
            + ("standard setting holds" if not reason else f"fails: {reason}"),
            fontsize=8,
        )
    else:
        ax.set_title(
            f"{spectrum.scheme} {spectrum.kind} {spectrum.size}: {spectrum.note}", fontsize=8
        )
    ax.set_aspect("equal")
    ax.set_xlim(-1.1, 1.1)
    ax.set_ylim(-1.1, 1.1)
    ax.axhline(0, color="#DDDDDD", lw=0.5)
    ax.axvline(0, color="#DDDDDD", lw=0.5)
    return fig


def plot_subdivision_matrix(matrix, ax=None, *, title: str = "", log: bool = True) -> Figure:
    """A subdivision matrix as a picture of its weights (zeros white).

    Parameters
    ----------
    matrix : (m, n) array or scipy.sparse matrix
        E.g. ``LocalSpectrum.matrix`` or the ``S`` of
        :func:`~pentanb.analysis.subdivision_matrix.subdivision_matrix`.
    log : bool
        Colour by log10 of the weight (the weights span orders of magnitude).
    """
    A = matrix.toarray() if hasattr(matrix, "toarray") else np.asarray(matrix, dtype=float)
    if ax is None:
        fig = Figure(figsize=(5.0, 4.4), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    shown = np.where(A > 0, np.log10(np.where(A > 0, A, 1.0)) if log else A, np.nan)
    neg = A < 0
    im = ax.imshow(shown, cmap="viridis", interpolation="nearest")
    if neg.any():
        r, c = np.nonzero(neg)
        ax.plot(c, r, "r.", ms=2, label="negative")
    fig.colorbar(im, ax=ax, shrink=0.8, label="log10 weight" if log else "weight")
    ax.set_xlabel(f"old vertices ({A.shape[1]})")
    ax.set_ylabel(f"new vertices ({A.shape[0]})")
    ax.set_title(title or f"{A.shape[0]} x {A.shape[1]}, {int((A != 0).sum())} weights", fontsize=9)
    return fig


# ---------------------------------------------------------------------------
# figures/scale.png: pentagon preservation's scale
# ---------------------------------------------------------------------------

_SIZE_COLORS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9")


def plot_scale(study: ScaleStudy, duals: Sequence[int] = (2, 4, 6)) -> Figure:
    """Pentagon preservation's leading eigenvalue moduli against the scale.

    Parameters
    ----------
    study : ScaleStudy
        From :func:`pentanb.analysis.spectral.scale_study`.
    duals : sequence of int
        One row of panels per number of duals.

    Returns
    -------
    Figure
        One row per number of duals, faces left and vertices right, lettered
        (A), (B), ...: ``|lambda1|`` (solid) and ``|lambda3|`` (dashed) per
        step for every size; Reif's standard setting ``|lambda1| = |lambda2|
        > |lambda3|`` holds where the solid line lies above the dashed one of
        its colour, and fails where the solid line is overdrawn in red; the
        thresholds (red), the package's default 0.75 (grey) and the
        recommended scale (green) marked; each panel's title gives every
        size's status.
    """
    g = study.grid
    sizes = sorted({key[2] for key in study.moduli})
    fig = Figure(figsize=(10.0, 2.9 * len(duals) + 0.6), layout="constrained")
    axes = fig.subplots(len(duals), 2, squeeze=False, sharex=True)
    letter = 0
    for i, d in enumerate(duals):
        for j, kind in enumerate(("face", "vertex")):
            ax = axes[i, j]
            statuses: dict[str, list[int]] = {}
            handles = {}
            # the largest sizes first, so the triangle's lines are drawn on top
            for c, n in reversed(list(enumerate(sizes))):
                key = (d, kind, n)
                if key not in study.moduli:
                    continue
                m = study.moduli[key]
                color = _SIZE_COLORS[c % len(_SIZE_COLORS)]
                (handles[n],) = ax.plot(g, m[:, 0], color=color, lw=1.2, label=f"{n}")
                ax.plot(g, m[:, 2], color=color, lw=0.9, ls="--")
                bad = ~study.standard[key]
                if bad.any():
                    ax.plot(g, np.where(bad, m[:, 0], np.nan), color="#CC0000", lw=3.5, alpha=0.35)
                th = study.thresholds[key]
                statuses.setdefault(th.text, []).append(n)
                if th.value is not None:
                    ax.axvline(float(th.value), color="#CC0000", lw=0.8)
                    ax.annotate(
                        f"{kind} {n}: s = {th.value}",
                        (float(th.value), 0.02),
                        xycoords=("data", "axes fraction"),
                        fontsize=7,
                        color="#CC0000",
                        ha="right",
                        rotation=90,
                        va="bottom",
                    )
            ax.axvline(0.75, color="#888888", lw=0.8, ls=":")
            if d == study.recommended_duals:
                ax.axvline(float(study.recommended), color="#009E73", lw=1.0)
            what = "; ".join(
                f"{_sizes(sorted(ns))}: {text}"
                for text, ns in sorted(statuses.items(), key=lambda kv: min(kv[1]))
            )
            ax.set_title(f"{_letter(letter)} {_plural(kind)}, {d} duals -- {what}", fontsize=8)
            letter += 1
            ax.set_xlim(0, 1)
            ax.set_ylim(bottom=0)
            ax.grid(alpha=0.3)
            ax.legend(
                [handles[n] for n in sorted(handles)],
                [str(n) for n in sorted(handles)],
                title="sides" if kind == "face" else "valence",
                fontsize=6,
                title_fontsize=6,
                ncol=2,
                loc="upper left",
            )
    for ax in axes[-1]:
        ax.set_xlabel("scale s")
    for ax in axes[:, 0]:
        ax.set_ylabel("|λ| per step")
    fig.suptitle(
        "Pentagon preservation: |λ1| (solid) and |λ3| (dashed) against the scale; red: the "
        f"standard setting fails; grey: 0.75; green: recommended {study.recommended} "
        f"({study.recommended_duals} duals)",
        fontsize=9,
    )
    return fig


def _sizes(ns: list[int]) -> str:
    """``[3, 4, 5, 7]`` -> ``"3-5, 7"``."""
    out, run = [], [ns[0]]
    for n in ns[1:]:
        if n == run[-1] + 1:
            run.append(n)
        else:
            out.append(run)
            run = [n]
    out.append(run)
    return ", ".join(f"{r[0]}-{r[-1]}" if len(r) > 1 else str(r[0]) for r in out)


def plot_scale_family(fam: ScaleFamily, s: float | None = None, ax=None, n: int = 4) -> Figure:
    """The leading eigenvalue moduli of one element against the scale, by Fourier mode.

    Parameters
    ----------
    fam : ScaleFamily
        From :func:`pentanb.analysis.spectral.scale_family`.
    s : float, optional
        A scale to mark (a slider's value).
    ax : matplotlib axis, optional
    n : int
        How many eigenvalues after the eigenvalue 1 to draw.

    Returns
    -------
    Figure
    """
    if ax is None:
        fig = Figure(figsize=(5.2, 3.6), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    g = np.linspace(0.005, 0.995, 199)
    m, _ = fam.moduli_grid(g)
    for i in range(1, 1 + n):
        ax.plot(g, m[:, i], lw=1.4 if i <= 2 else 0.9, ls="-" if i <= 2 else "--", label=f"|λ{i}|")
    bad = ~fam.standard_grid(g)
    if bad.any():
        ax.fill_between(
            g,
            0,
            1,
            where=bad,
            color="#CC0000",
            alpha=0.08,
            lw=0,
            transform=ax.get_xaxis_transform(),
        )
    if s is not None:
        ax.axvline(float(s), color="black", lw=0.8)
        ms, md = fam.moduli(float(s))
        ax.set_title(
            f"{fam.kind} {fam.size}, {fam.duals} duals, s = {float(s):.3f}: |λ1..3| = "
            + ", ".join(f"{x:.4f} (mode {w})" for x, w in zip(ms[1:4], md[1:4]))
            + ("" if fam.standard(float(s)) else "\nstandard setting fails"),
            fontsize=7,
        )
    ax.set_xlim(0, 1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("scale s")
    ax.set_ylabel("|λ| per step")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return fig
