"""The continuity results that the figures ``spectra``, ``characteristic_maps`` and
``scale`` share (private).

Section 7's open question, answered with subdivision theory by
:func:`pentanb.analysis.spectral.continuity_table`: every scheme + 2 duals,
at vertices of valence 3 to 8 and faces of 3 to 8 sides, the rows of the
paper's schemes with their leading eigenvalues established in exact
arithmetic (:func:`pentanb.analysis.spectral.exact_ordering`).  Both
figures draw it and both check claims on it, so :func:`table` computes it
once per process and keeps it (``functools.lru_cache(maxsize=1)``: one
table, about 10-15 s of one core): ``python -m pentanb figures`` (or
``--only spectra``) computes it once for the two drawings and their
claims.  Likewise :func:`scale_study` (pentagon preservation's scale, 2, 4
and 6 duals, about 15-20 s) for the figure ``scale``.  They are the only
things the figures package keeps between calls; ``table.cache_clear()``
and ``scale_study.cache_clear()`` free them.

The rows kept are *detached*: their spectra drop the search's context (the
hierarchy of meshes the neighbourhood was found in, about 300 MB for the
whole table), which only :func:`~pentanb.analysis.spectral.characteristic_map`
needs and which is computed already.  Everything the figures and the claims
read (eigenvalues, local matrices, characteristic maps and their verdicts,
:attr:`~pentanb.analysis.spectral.ContinuityRow.c1`) stays.  Treat the rows
as read-only.

numpy only (the analysis imports scipy where it needs it).
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Iterable, Sequence

from ..analysis.spectral import (
    TABLE_CASES,
    ContinuityRow,
    ScaleStudy,
    continuity_table,
    exact_ordering,
)
from ..analysis.spectral import scale_study as _scale_study
from ..schemes import SCHEMES

__all__ = [
    "SIZES",
    "G1",
    "PAPER_LABELS",
    "table",
    "scale_study",
    "detached",
    "rows_of",
    "fate_of",
    "plural",
    "sizes_text",
    "key_label",
    "scheme_name",
]

#: Valences and face sizes of the table (and of every claim on it).
SIZES = tuple(range(3, 9))

#: Section 7's words on continuity.
G1 = "we have visually confirmed that the algorithms converge with G1 continuity."

#: The table labels of the paper's schemes: their rows are established in exact arithmetic.
PAPER_LABELS = ("pentagonalize", "preserve_pentagons 0.75", "preserve_pentagons 0.5")


def detached(row: ContinuityRow) -> ContinuityRow:
    """The row without the search context of its spectrum (see the module's docstring).

    Parameters
    ----------
    row : ContinuityRow

    Returns
    -------
    ContinuityRow
        Equal in every field the figures read; its spectrum (and its
        characteristic map's) has no hierarchy of meshes attached.
    """
    sp = row.spectrum
    if sp is None:
        return row
    light = dataclasses.replace(sp, _context=None)
    cm = row.char_map
    if cm is not None:
        cm = dataclasses.replace(cm, spectrum=light)
    return dataclasses.replace(row, spectrum=light, char_map=cm)


@functools.lru_cache(maxsize=1)
def table() -> tuple[ContinuityRow, ...]:
    """:func:`~pentanb.analysis.spectral.continuity_table` with its defaults, computed once.

    Returns
    -------
    tuple of ContinuityRow
        Every scheme of :data:`~pentanb.analysis.spectral.TABLE_CASES` + 2
        duals at every element type of :data:`SIZES`, rows
        :func:`detached`; the rows of :data:`PAPER_LABELS` carry their
        exact ordering (:attr:`~pentanb.analysis.spectral.ContinuityRow.exact`).
        Kept for the process (``table.cache_clear()`` frees them).
    """
    # case by case, so that one case's search context is held at a time (not 300 MB)
    return tuple(
        detached(_with_exact(r) if case[0] in PAPER_LABELS else r)
        for case in TABLE_CASES
        for r in continuity_table([case], sizes=SIZES)
    )


def _with_exact(row: ContinuityRow) -> ContinuityRow:
    sp = row.spectrum
    if sp is None or not sp.stationary or sp._context is None:
        return row
    return dataclasses.replace(row, exact=exact_ordering(sp))


@functools.lru_cache(maxsize=1)
def scale_study() -> ScaleStudy:
    """:func:`~pentanb.analysis.spectral.scale_study` with its defaults, computed once.

    Returns
    -------
    ScaleStudy
        Pentagon preservation with 2, 4 and 6 duals at every element type of
        :data:`SIZES`, thresholds and the recommended scale established
        exactly; kept for the process (``scale_study.cache_clear()`` frees it).
    """
    return _scale_study(sizes=SIZES)


def rows_of(rows: Iterable[ContinuityRow], label: str, kind: str) -> list[ContinuityRow]:
    """The rows of one scheme (table label) at one kind of element that have a spectrum,
    by size (rows saying what a lost element becomes are left out: :func:`fate_of`)."""
    sel = [r for r in rows if r.label == label and r.kind == kind and r.spectrum is not None]
    return sorted(sel, key=lambda r: r.size)


def fate_of(rows: Iterable[ContinuityRow], label: str, kind: str) -> str:
    """What the scheme makes of the elements of ``kind`` that it does not keep ("" if none)."""
    return "; ".join(
        r.fate for r in rows if r.label == label and r.kind == kind and r.spectrum is None
    )


def plural(kind: str) -> str:
    """``"vertices"`` or ``"faces"``."""
    return "vertices" if kind == "vertex" else "faces"


def sizes_text(sizes: Sequence[int]) -> str:
    """``[3, 4, 5, 7]`` -> ``"3-5, 7"``."""
    out: list[str] = []
    run: list[int] = []
    for s in sorted(sizes):
        if run and s != run[-1] + 1:
            out.append(f"{run[0]}-{run[-1]}" if len(run) > 1 else str(run[0]))
            run = []
        run.append(s)
    if run:
        out.append(f"{run[0]}-{run[-1]}" if len(run) > 1 else str(run[0]))
    return ", ".join(out)


def key_label(label: str) -> str:
    """A table label as a part of a claim key: ``"preserve_pentagons 0.75"`` ->
    ``"preserve_pentagons_075"`` (no space, no dot)."""
    return label.replace(" ", "_").replace(".", "")


def scheme_name(label: str) -> str:
    """A table label as the report writes it: ``"preserve_pentagons 0.5"`` ->
    ``"Pentagon preservation (scale 0.5) + 2 duals"``."""
    for case, scheme, options in TABLE_CASES:
        if case == label:
            opts = ", ".join(f"{k} {v}" for k, v in options.items())
            return SCHEMES[scheme].label + (f" ({opts})" if opts else "") + " + 2 duals"
    return f"{label} + 2 duals"
