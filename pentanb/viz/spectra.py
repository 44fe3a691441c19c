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
  verdict (``figures/characteristic_maps.png``);
* :func:`plot_subdivision_matrix` -- a local (or global) subdivision matrix
  as a picture of its weights (the notebook ``09_continuity``);
* :func:`plot_eigenvalues` and :func:`draw_characteristic_map` -- one case,
  for a slider.

Each figure has a ``*_claims`` function returning :class:`Claim` items
(the paper's words or the literature's closed form, the value expected,
the value measured, and whether they agree); every claim can fail, and
some do -- those are findings, printed as such.

Figures are plain :class:`matplotlib.figure.Figure` objects (no pyplot).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.figure import Figure

from ..analysis.spectral import (
    CharacteristicMap,
    ContinuityRow,
    LocalSpectrum,
    continuity_table,
)

__all__ = [
    "Claim",
    "plot_spectra",
    "plot_characteristic_maps",
    "plot_subdivision_matrix",
    "plot_eigenvalues",
    "draw_characteristic_map",
    "spectra_claims",
    "characteristic_map_claims",
    "catmull_clark_lambda",
    "PAPER_LABELS",
]

#: Table labels of the paper's schemes (Section 5).
PAPER_LABELS = ("pentagonalize", "preserve_pentagons 0.75", "preserve_pentagons 0.5")

_KIND_STYLE = {"vertex": ("#0072B2", "o"), "face": ("#D55E00", "s")}


@dataclass(frozen=True)
class Claim:
    """One statement, checked against the analysis.

    The same fields as the claims of :mod:`pentanb.figures`.

    Attributes
    ----------
    text : str
        The paper's words (with the section) or the literature's statement.
    expected : object
    measured : object
    holds : bool
        Whether the measurement agrees.  False is a finding, not a bug.
    """

    text: str
    expected: object
    measured: object
    holds: bool

    def __str__(self) -> str:
        mark = "ok  " if self.holds else "FAIL"
        return f"[{mark}] {self.text}: expected {self.expected}, measured {self.measured}"


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


def plot_spectra(rows: Sequence[ContinuityRow] | None = None, n_eigen: int = 4) -> Figure:
    """Moduli of lambda1..lambda4 per element type, one panel per scheme (+ 2 duals).

    Parameters
    ----------
    rows : list of ContinuityRow, optional
        From :func:`pentanb.analysis.spectral.continuity_table` (computed
        when not given).
    n_eigen : int
        How many eigenvalues after the eigenvalue 1 to draw.

    Returns
    -------
    Figure
        Vertices (blue circles) and faces (orange squares) of each size; the
        subdominant pair filled, the next ones smaller and hollow; a red
        cross where the necessary condition ``|lambda1| = |lambda2| >
        |lambda3|`` fails, a ring where the subdominant pair is complex.
    """
    rows = _rows(rows)
    labels = list(dict.fromkeys(r.label for r in rows if _stationary([r])))
    ncol = 3
    nrow = max(1, math.ceil(len(labels) / ncol))
    fig = Figure(figsize=(4.0 * ncol, 3.0 * nrow + 0.6), layout="constrained")
    axes = fig.subplots(nrow, ncol, squeeze=False, sharey=True)
    for ax, label in zip(axes.flat, labels):
        for kind, (color, marker) in _KIND_STYLE.items():
            sel = _stationary(rows, label, kind)
            if not sel:
                continue
            shift = -0.12 if kind == "vertex" else 0.12
            for r in sel:
                m = r.spectrum.moduli[1 : 1 + n_eigen]
                x = r.size + shift
                for i, val in enumerate(m):
                    ax.plot(
                        [x],
                        [val],
                        marker=marker,
                        ms=6 if i < 2 else 4,
                        mfc=color if i < 2 else "none",
                        mec=color,
                        ls="none",
                        alpha=1.0 if i < 2 else 0.7,
                    )
                if not r.spectrum.necessary:
                    ax.plot([x], [m[0]], marker="x", ms=11, mew=2, color="#CC0000", ls="none")
                elif r.spectrum.subdominant_complex:
                    ax.plot([x], [m[0]], marker="o", ms=12, mfc="none", mec="#555555", ls="none")
            ax.plot([], [], marker=marker, color=color, ls="none", label=_plural(kind))
        ax.set_title(f"{label} + 2 duals", fontsize=10)
        ax.set_xticks(range(3, 9))
        ax.set_xlim(2.5, 8.5)
        ax.set_ylim(0, 1)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower right")
    for ax in axes.flat[len(labels) :]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("valence / sides")
    for ax in axes[:, 0]:
        ax.set_ylabel("|λ| per step")
    fig.suptitle(
        "Leading eigenvalue moduli |λ1| ≥ |λ2| ≥ |λ3| ≥ |λ4| (filled: subdominant pair; "
        "× necessary condition fails; ○ complex pair)",
        fontsize=10,
    )
    return fig


def catmull_clark_lambda(k: int, w: int = 1) -> float:
    """Larger eigenvalue of Catmull-Clark's Fourier block w at valence k.

    ``(5 + cos(2 pi w/k) + cos(pi w/k) sqrt(2 (9 + cos(2 pi w/k)))) / 16``
    (Halstead, Kass and DeRose 1993; Stam 1998, "Exact evaluation of
    Catmull-Clark subdivision surfaces", Appendix).  Vertex insertion + 2
    duals is bilinear subdivision plus one quad averaging (Warren and Weimer
    2001, Section 7.2), whose edge and face rules are Catmull-Clark's, so
    its blocks w != 0 are Catmull-Clark's too; its vertex rule (9/16,
    3/(8k), 1/(16k)) differs and only changes block 0 (eigenvalues 1, 1/4,
    1/16 at every valence).
    """
    c = math.cos(2 * math.pi * w / k)
    return (5 + c + math.cos(math.pi * w / k) * math.sqrt(2 * (9 + c))) / 16


def spectra_claims(rows: Sequence[ContinuityRow] | None = None) -> list[Claim]:
    """Claims of ``figures/spectra.png``.

    The paper's claim (Section 7) as a necessary condition at every element
    type of its two schemes, and two validations against closed forms of
    the literature (which fail if the matrices are wrong).
    """
    rows = _rows(rows)
    out = []
    words = (
        'Section 7: "we have visually confirmed that the algorithms converge with G1 '
        'continuity" -> 1 > |λ1| = |λ2| > |λ3| at every {} of {} + 2 duals'
    )
    for label in PAPER_LABELS:
        for kind in ("vertex", "face"):
            sel = _stationary(rows, label, kind)
            if not sel:
                continue
            fails = [
                f"{r.kind} {r.size}: {r.spectrum.necessary_reason}"
                for r in sel
                if not r.spectrum.necessary
            ]
            out.append(
                Claim(
                    words.format(kind, label),
                    "holds at sizes " + ",".join(str(r.size) for r in sel),
                    "fails at " + "; ".join(fails) if fails else "holds everywhere",
                    not fails,
                )
            )
    complex_rows = [r for r in _stationary(rows, "pentagonalize") if r.spectrum.subdominant_complex]
    pent = _stationary(rows, "pentagonalize")
    if pent:
        out.append(
            Claim(
                "pentagonalization is chiral: its subdominant eigenvalues are a complex pair "
                "(Reif's criterion, stated for a real double one, does not apply as is)",
                f"complex at valences {','.join(str(r.size) for r in pent)}",
                "complex at valences "
                + ",".join(
                    f"{r.size} ({math.degrees(abs(np.angle(r.spectrum.lam(1)))):.1f}°)"
                    for r in complex_rows
                ),
                len(complex_rows) == len(pent),
            )
        )
    vi4 = [r for r in _stationary(rows, "vertex_insertion", "vertex") if r.size == 4]
    if vi4:
        m = vi4[0].spectrum.moduli[:7]
        expected = np.array([1, 1 / 2, 1 / 2, 1 / 4, 1 / 4, 1 / 4, 1 / 8])
        out.append(
            Claim(
                "vertex insertion + 2 duals at valence 4 is the bicubic B-spline: "
                "spectrum 1, 1/2, 1/2, 1/4, 1/4, 1/4, 1/8",
                "1, 0.5, 0.5, 0.25, 0.25, 0.25, 0.125",
                ", ".join(f"{x:.6g}" for x in m),
                m.size == 7 and bool(np.allclose(m, expected, atol=1e-9)),
            )
        )
    vi = _stationary(rows, "vertex_insertion", "vertex")
    if vi:
        err = max(abs(r.spectrum.moduli[1] - catmull_clark_lambda(r.size)) for r in vi)
        out.append(
            Claim(
                "vertex insertion + 2 duals has Catmull-Clark's subdominant eigenvalue "
                "(Stam 1998) at valences " + ",".join(str(r.size) for r in vi),
                "error < 1e-9",
                f"largest error {err:.1e}",
                err < 1e-9,
            )
        )
    return out


# ---------------------------------------------------------------------------
# characteristic maps
# ---------------------------------------------------------------------------


def draw_characteristic_map(ax, cmap: CharacteristicMap, *, title: str | None = None) -> None:
    """Draw a characteristic map's control net on a matplotlib axis.

    Faces turning the majority's way are light blue, the others red (a
    fold); the element's centre is a black dot.
    """
    pts = cmap.points
    off = cmap.offsets
    polys = [pts[cmap.corners[off[i] : off[i + 1]]] for i in range(cmap.n_faces)]
    major = 1 if np.sum(cmap.signs) >= 0 else -1
    colors = ["#A6CEE3" if s == major else "#E31A1C" for s in cmap.signs]
    ax.add_collection(
        PolyCollection(polys, facecolors=colors, edgecolors="#333333", linewidths=0.3)
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
    """
    rows = _rows(rows)
    lines = []
    for label in labels:
        for kind in ("vertex", "face"):
            sel = [r for r in _stationary(rows, label, kind) if r.char_map is not None]
            if sel:
                lines.append((label, kind, sel))
    ncol = max((len(sel) for _, _, sel in lines), default=1)
    nrow = max(1, len(lines))
    fig = Figure(figsize=(1.7 * ncol + 1.2, 1.8 * nrow + 0.5), layout="constrained")
    axes = fig.subplots(nrow, ncol, squeeze=False)
    for i, (label, kind, sel) in enumerate(lines):
        for j in range(ncol):
            ax = axes[i, j]
            if j >= len(sel):
                ax.set_visible(False)
                continue
            draw_characteristic_map(ax, sel[j].char_map)
        axes[i, 0].set_ylabel(f"{label}\n{_plural(kind)}", fontsize=7)
    fig.suptitle(
        "Characteristic maps (subdominant eigenvectors, 2 levels down); red: folded faces",
        fontsize=9,
    )
    return fig


def characteristic_map_claims(rows: Sequence[ContinuityRow] | None = None) -> list[Claim]:
    """Claims of ``figures/characteristic_maps.png``: regular and injective everywhere?"""
    rows = _rows(rows)
    out = []
    for label in (*PAPER_LABELS, "vertex_insertion"):
        sel = [r for r in _stationary(rows, label) if r.char_map is not None]
        if not sel:
            continue
        bad = [f"{r.element}: {r.char_map.verdict}" for r in sel if not r.char_map.injective]
        source = (
            'Section 7: "converge with G1 continuity"'
            if label in PAPER_LABELS
            else "Catmull-Clark's characteristic map is injective (Peters and Reif 2008)"
        )
        out.append(
            Claim(
                f"{source} -> characteristic map of {label} + 2 duals regular and injective "
                "(control net 2 levels down)",
                "at " + ", ".join(r.element for r in sel),
                "fails at " + "; ".join(bad) if bad else "everywhere",
                not bad,
            )
        )
    return out


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
        reason = spectrum.necessary_reason
        ax.set_title(
            f"{spectrum.scheme} {spectrum.kind} {spectrum.size}: |λ1| = {np.abs(z[1]):.4f}\n"
            + ("necessary condition holds" if not reason else f"fails: {reason}"),
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
