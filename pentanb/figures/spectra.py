"""Beyond the paper: the spectra of the local subdivision matrices (Section 7's open question).

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity. However, there is still a need for theoretical proofs for
convergence."  Around an extraordinary vertex or face that survives every
level, one step "remesh, then 2 duals" maps a small neighbourhood onto
itself by a fixed local subdivision matrix
(:func:`pentanb.analysis.spectral.local_spectrum`).  A tangent plane (G1)
at the element needs its eigenvalues, by modulus, to satisfy ``1 = lambda0
> |lambda1| = |lambda2| > |lambda3|`` (Reif 1995; Peters and Reif,
*Subdivision Surfaces*, 2008): the *necessary condition*.

The figure ``spectra`` draws ``|lambda1|`` to ``|lambda4|`` of every scheme
+ 2 duals at vertices of valence 3 to 8 and faces of 3 to 8 sides, one
panel per scheme, the paper's first (:func:`pentanb.viz.spectra.plot_spectra`).
Its claims check the necessary condition for the paper's two schemes; the
finding: pentagon preservation with scale 0.5 fails it around triangles
(``|lambda1|`` = 0.1417 real, ``|lambda2|`` = 0.1167 a complex pair), so its
limit surface has no tangent plane at a triangle's centre.  The table is
computed once per process and shared with the figure
``characteristic_maps`` (:func:`pentanb.figures._continuity.table`).  Its
panels are charts: :func:`panels` is empty.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from ..analysis.spectral import TABLE_CASES, TOL, ContinuityRow
from ..mesh import Mesh
from ._continuity import G1, SIZES, fate_of, key_label, plural, rows_of, scheme_name, table
from .claim import FAILS, HOLDS, Claim, judged

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Spectra of the local subdivision matrices (beyond the paper)"
CAPTION = (
    "Section 7: 'we have visually confirmed that the algorithms converge with G1 "
    "continuity. However, there is still a need for theoretical proofs for convergence.' "
    "The moduli of the leading eigenvalues of the local subdivision matrix of every "
    "scheme + 2 duals at vertices of valence 3-8 and faces of 3-8 sides; a tangent plane "
    "needs 1 > |lambda1| = |lambda2| > |lambda3|."
)

#: The schemes (table labels) drawn, one panel each: every case of the table
#: but triangulation, which stops refining after its first step (Figure 2) and
#: so has no spectrum.
SCHEMES_DRAWN = tuple(label for label, _, _ in TABLE_CASES if label != "triangulate")
LABELS = tuple(chr(ord("A") + i) for i in range(len(SCHEMES_DRAWN)))

#: The claims, (table label, kind) -> recorded verdict: the paper's two schemes
#: at the elements they keep (pentagonalization turns every face into a vertex).
RECORDED = {
    ("pentagonalize", "vertex"): HOLDS,
    ("preserve_pentagons 0.75", "vertex"): HOLDS,
    ("preserve_pentagons 0.75", "face"): HOLDS,
    ("preserve_pentagons 0.5", "vertex"): HOLDS,
    ("preserve_pentagons 0.5", "face"): FAILS,  # around triangles
}


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(
    meshes: Mapping[str, Mesh] | None = None, rows: Sequence[ContinuityRow] | None = None
) -> Figure:
    """Eigenvalue moduli per element type, one panel per scheme + 2 duals.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.
    rows : sequence of ContinuityRow, optional
        The table (default: the shared one,
        :func:`pentanb.figures._continuity.table`).

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ...
    """
    from ..viz import mpl as vz
    from ..viz import spectra as vs

    rows = table() if rows is None else rows
    with vz.style():
        return vs.plot_spectra(rows, labels=SCHEMES_DRAWN)


def _moduli(row: ContinuityRow) -> str:
    sp = row.spectrum
    assert sp is not None
    m = sp.moduli[1:4]
    text = f"{row.size}: " + ", ".join(f"{x:.4f}" for x in m)
    return text + (" (complex pair)" if sp.subdominant_complex else "")


def necessary_claim(
    rows: Sequence[ContinuityRow], label: str, kind: str, recorded: str = HOLDS
) -> Claim:
    """Section 7's G1, its necessary condition at every element of one kind of one scheme.

    Holds when ``1 = lambda0 > |lambda1| = |lambda2| > |lambda3|`` (moduli
    per step, equal to :data:`~pentanb.analysis.spectral.TOL` relative) at
    every size of :data:`~pentanb.figures._continuity.SIZES`; a size without
    a stationary neighbourhood (or without a row) does not hold.

    Parameters
    ----------
    rows : sequence of ContinuityRow
    label : str
        A table label, e.g. ``"preserve_pentagons 0.5"``.
    kind : {"vertex", "face"}
    recorded : str
    """
    by_size = {r.size: r for r in rows_of(rows, label, kind)}
    parts, bad = [], []
    for n in SIZES:
        r = by_size.get(n)
        if r is None or r.spectrum is None:
            bad.append(f"{n}: no row")
            continue
        sp = r.spectrum
        if not sp.stationary:
            bad.append(f"{n}: {sp.note}")
            continue
        parts.append(_moduli(r))
        if not sp.necessary:
            bad.append(f"{kind} {n}: {sp.necessary_reason}")
    word = "valence" if kind == "vertex" else "sides"
    every = (
        f"vertex of valence {SIZES[0]}-{SIZES[-1]}"
        if kind == "vertex"
        else (f"face of {SIZES[0]}-{SIZES[-1]} sides")
    )
    measured = (
        f"{scheme_name(label)}, local subdivision matrix at {plural(kind)} by {word}, "
        f"|lambda1|, |lambda2|, |lambda3| per step: " + "; ".join(parts)
    )
    if bad:
        measured += "; fails at " + "; ".join(bad)
    other = "face" if kind == "vertex" else "vertex"
    lost = fate_of(rows, label, other)
    if lost and not rows_of(rows, label, other):
        measured += f"; {plural(other)} are not kept ({lost})"
    return judged(
        f"spectra.{key_label(label)}.{plural(kind)}",
        "Section 7",
        G1,
        measured,
        "necessary for a tangent plane (G1) at the element, not sufficient (Reif 1995): holds "
        f"if 1 = lambda0 > |lambda1| = |lambda2| > |lambda3| (moduli equal to {TOL:g} "
        f"relative) at every {every}",
        HOLDS if not bad else FAILS,
        recorded,
    )


def claims(
    meshes: Mapping[str, Mesh] | None = None, rows: Sequence[ContinuityRow] | None = None
) -> list[Claim]:
    """The necessary condition for G1 at every element type of the paper's schemes.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    rows : sequence of ContinuityRow, optional
        The table (default: the shared one); the tests pass one with wrong
        rows (a scheme without its duals, a perturbed matrix, another scale).

    Returns
    -------
    list of Claim
        One per entry of :data:`RECORDED`.
    """
    rows = table() if rows is None else rows
    return [necessary_claim(rows, label, kind, rec) for (label, kind), rec in RECORDED.items()]
