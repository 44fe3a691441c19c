"""The results table: every scheme + 2 duals at its extraordinary vertices and
faces (:func:`continuity_table`, rows :class:`ContinuityRow`, cases
:data:`TABLE_CASES`), and the table in Markdown (:func:`table_markdown`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ...schemes.registry import SCHEMES
from .characteristic import CharacteristicMap, characteristic_map
from .exact import ExactSpectrum, exact_ordering
from .local import LocalSpectrum, local_spectrum
from .neighbourhood import KINDS, element_fate

__all__ = [
    "ContinuityRow",
    "continuity_table",
    "table_markdown",
    "TABLE_CASES",
]

# ---------------------------------------------------------------------------
# the results table
# ---------------------------------------------------------------------------

#: (label, scheme, options) analysed by :func:`continuity_table`: the paper's
#: schemes first, then every other scheme of the registry.
TABLE_CASES: tuple[tuple[str, str, dict], ...] = (
    ("pentagonalize", "pentagonalize", {}),
    ("preserve_pentagons 0.75", "preserve_pentagons", {"scale": 0.75}),
    ("preserve_pentagons 0.5", "preserve_pentagons", {"scale": 0.5}),
    *((name, name, {}) for name in SCHEMES if name not in ("pentagonalize", "preserve_pentagons")),
)


@dataclass(frozen=True)
class ContinuityRow:
    """One row of the results table: a scheme (+ 2 duals) at one element type.

    Attributes
    ----------
    label : str
        Scheme and options, e.g. ``"preserve_pentagons 0.5"``.
    kind, size : the element
    spectrum : LocalSpectrum or None
    char_map : CharacteristicMap or None
        None where the element has no characteristic map (``map_note`` says
        why) or no spectrum.
    fate : str
        What the element becomes when it does not survive.
    map_note : str
        Why there is no characteristic map (:attr:`LocalSpectrum.map_obstruction`).
    exact : ExactSpectrum or None
        The leading eigenvalues established in exact arithmetic
        (:func:`exact_ordering`), when the table was asked for them.
    """

    label: str
    kind: str
    size: int
    spectrum: LocalSpectrum | None
    char_map: CharacteristicMap | None
    fate: str = ""
    map_note: str = ""
    exact: ExactSpectrum | None = None

    @property
    def element(self) -> str:
        return f"{self.kind} {self.size}"

    def lam(self, i: int) -> str:
        """Eigenvalue ``i`` as the table shows it: its modulus per step, and
        its argument in degrees when it is complex (``"0.3840∠20.2°"``).

        Parameters
        ----------
        i : int, >= 0
            Index into the spectrum's eigenvalues (sorted by modulus, decreasing).

        Returns
        -------
        str
            Empty when there is no stationary spectrum or no eigenvalue ``i``.
        """
        if self.spectrum is None or not self.spectrum.stationary:
            return ""
        sp = self.spectrum
        if i >= sp.eigenvalues.size:
            return ""
        z = sp.eigenvalues[i]
        mod = abs(z) ** (1.0 / sp.period)
        if abs(z.imag) > 1e-9 * max(abs(z), 1e-300):
            return f"{mod:.4f}∠{math.degrees(np.angle(z)):.1f}°"
        return f"{mod:.4f}" if z.real >= 0 else f"-{mod:.4f}"

    @property
    def standard(self) -> str:
        """``"holds"`` / ``"fails: <what>"`` for Reif's standard setting
        (:attr:`LocalSpectrum.standard`), ``"exact"`` added where
        :func:`exact_ordering` established it; ``"n/a"`` without a spectrum."""
        if self.spectrum is None or not self.spectrum.stationary:
            return "n/a"
        r = self.spectrum.standard_reason
        text = "holds" if not r else f"fails: {r}"
        if self.exact is not None and self.exact.decided:
            text += " (exact)" if self.exact.standard == (not r) else " (exact disagrees)"
        return text

    @property
    def necessary(self) -> str:
        """The old name of :attr:`standard`; kept for old code."""
        return self.standard

    @property
    def verdict(self) -> str:
        """The characteristic map's verdict, or ``"none: <why>"`` where there is none."""
        if self.char_map is not None:
            return self.char_map.verdict
        if self.map_note:
            return f"none: {self.map_note}"
        return "n/a"

    @property
    def c1(self) -> str:
        """``yes`` / ``no`` / ``undecided`` with the reason.

        ``no`` is said for generic control points: where no characteristic
        map exists (a simple ``lambda1`` of Fourier mode 0, or three or more
        eigenvalues of the subdominant modulus: no tangent plane, see
        :attr:`LocalSpectrum.map_obstruction`), or where the map is not
        injective.
        """
        sp = self.spectrum
        if sp is None:
            return "n/a"
        if not sp.stationary:
            return "undecided (no stationary neighbourhood)"
        n = sp.subdominant_count
        if n == 1:
            mode = int(sp.modes[1]) if sp.modes.size > 1 else -1
            if mode == 0:
                return (
                    "no tangent plane for generic control points "
                    "(lambda1 simple, of Fourier mode 0)"
                )
            return "undecided (lambda1 simple)"
        if n >= 3:
            return (
                f"no tangent plane for generic control points ({n} eigenvalues of the "
                "subdominant modulus)"
            )
        cm = self.char_map
        if cm is None:
            return "undecided"
        if not cm.injective:
            return "no (characteristic map not injective)"
        if sp.subdominant_complex:
            return "undecided (complex subdominant pair; Reif's criterion is for real ones)"
        if not _spline_background(self.label):
            return "undecided (no C1 spline away from the element; map injective numerically)"
        return "yes (Reif's criterion; map injective numerically)"


def _spline_background(label: str) -> bool:
    """Is the surface away from extraordinary elements a known C1 spline?

    Only vertex insertion + 2 duals: bilinear subdivision plus quad
    averaging (Warren and Weimer 2001, Section 7.2), the bicubic B-spline
    on regular quads.
    """
    return label == "vertex_insertion"


def continuity_table(
    cases=TABLE_CASES,
    sizes=range(3, 9),
    duals: int = 2,
    *,
    map_iterations: int = 2,
    progress: Callable[[str], None] | None = None,
    exact: bool | Callable[[str], bool] = False,
) -> list[ContinuityRow]:
    """The results table: every scheme + ``duals`` duals at every element type.

    Parameters
    ----------
    cases : sequence of (label, scheme, options)
        Default :data:`TABLE_CASES`.
    sizes : iterable of int
        Valences and face sizes (default 3 to 8).
    duals : int
    map_iterations : int
        Iterations of the characteristic map's control net
        (:func:`characteristic_map`'s ``iterations``).
    progress : callable, optional
        Called with a line of text after every row.
    exact : bool or callable
        Establish the leading eigenvalues of every row in exact arithmetic
        (:func:`exact_ordering`, in :attr:`ContinuityRow.exact`); a callable
        ``exact(label) -> bool`` chooses the cases.

    Returns
    -------
    list of ContinuityRow
        For each case, a row per vertex valence, then per face size, for the
        elements that survive the scheme; an element that does not survive
        gets one row saying what it becomes (``spectrum`` None).
    """
    rows: list[ContinuityRow] = []
    sizes = list(sizes)
    for label, scheme, options in cases:
        want_exact = exact(label) if callable(exact) else bool(exact)
        for kind in KINDS:
            fates = {n: element_fate(scheme, kind, n, **options) for n in sizes}
            lost = {n: f for n, f in fates.items() if not f.startswith(kind)}
            if lost:
                rows.append(ContinuityRow(label, kind, min(lost), None, None, _fate_rule(lost)))
            kept = [n for n in sizes if n not in lost]
            for n in kept:
                sp = local_spectrum(scheme, kind, n, duals, **options)
                if not sp.refines:
                    rows.append(ContinuityRow(label, kind, n, None, None, sp.note))
                    break
                cm, why = None, ""
                if sp.stationary:
                    why = sp.map_obstruction
                    if not why:
                        cm = characteristic_map(sp, iterations=map_iterations)
                ex = exact_ordering(sp) if want_exact and sp.stationary else None
                row = ContinuityRow(label, kind, n, sp, cm, map_note=why, exact=ex)
                rows.append(row)
                if progress:
                    progress(f"{label} {kind} {n}: {row.lam(1)} {row.c1}")
    return rows


def _fate_rule(lost: dict[int, str]) -> str:
    """``"3: becomes a vertex of valence 3; 4: ..."`` condensed."""
    return "; ".join(f"{n}: {text}" for n, text in sorted(lost.items()))


def table_markdown(rows: list[ContinuityRow]) -> str:
    """The table as markdown (for the README).

    Parameters
    ----------
    rows : list of ContinuityRow
        From :func:`continuity_table`.

    Returns
    -------
    str
        A header and one table line per row, ending with a newline.
    """
    head = (
        "| scheme + 2 duals | element | period | N | λ1 | λ2 | λ3 | λ4 | "
        "standard setting | characteristic map | C1 |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n"
    )
    lines = []
    for r in rows:
        sp = r.spectrum
        if sp is None:
            what = "vertices" if r.kind == "vertex" else "faces"
            lines.append(f"| {r.label} | {what} | | | | | | | | | {r.fate} |")
            continue
        period = str(sp.period) if sp.stationary else ""
        size = f"{sp.neighbourhood}/{sp.analysis_size}" if sp.stationary else ""
        lines.append(
            f"| {r.label} | {r.element} | {period} | {size} | {r.lam(1)} | {r.lam(2)} | "
            f"{r.lam(3)} | {r.lam(4)} | {r.standard} | {r.verdict} | {r.c1} |"
        )
    return head + "\n".join(lines) + "\n"
