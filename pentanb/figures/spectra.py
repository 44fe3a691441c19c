"""Beyond the paper: the spectra of the local subdivision matrices (Section 7's open question).

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity. However, there is still a need for theoretical proofs for
convergence."  Around an extraordinary vertex or face that survives every
level, one step "remesh, then 2 duals" maps a small neighbourhood onto
itself by a fixed local subdivision matrix
(:func:`pentanb.analysis.spectral.local_spectrum`).  Its eigenvalues, by
modulus, are in Reif's *standard setting* when ``1 = lambda0 > |lambda1| =
|lambda2| > |lambda3|`` (Reif 1995; Peters and Reif, *Subdivision
Surfaces*, 2008, Ch. 5): the setting in which a regular, injective
characteristic map makes the surface C1 there, given a C1 surface on the
rings.  It is a hypothesis of Reif's sufficient condition, not sufficient by
itself (the condition needs the map and the rings too), and not necessary;
what rules a tangent plane out, for generic control
points, is a simple ``lambda1`` whose eigenvector is invariant under the
turn by one sector (Fourier mode 0), or three or more eigenvalues of the
subdominant modulus.

The figure ``spectra`` draws ``|lambda1|`` to ``|lambda4|`` of every scheme
+ 2 duals at vertices of valence 3 to 8 and faces of 3 to 8 sides, one
panel per scheme, the paper's first (:func:`pentanb.viz.spectra.plot_spectra`).
Its claims (the paper's, with verdicts) test Section 7's G1 on the spectra
of the paper's two schemes, the leading eigenvalues established in exact
rational arithmetic (:func:`pentanb.analysis.spectral.exact_ordering`).
What they find: pentagon preservation with scale 0.5 has, at a triangle,
a simple ``lambda1 = 17/120`` (Fourier mode 0) above the pair ``7/60``
(exact, per step), so for generic control points its limit surface has no
tangent plane at a triangle's centre; with 2 duals this holds for every
scale below 5/7 (figure ``scale``).  The table is computed once per process
and shared with the figure ``characteristic_maps``
(:func:`pentanb.figures._continuity.table`).  Its panels are charts:
:func:`panels` is empty.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from ..analysis.spectral import TABLE_CASES, TOL, ContinuityRow
from ..mesh import Mesh
from ._continuity import G1, SIZES, fate_of, key_label, plural, rows_of, scheme_name, table
from .claim import CLAIM, FAILS, HOLDS, Claim, judged

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Spectra of the local subdivision matrices (beyond the paper)"
CAPTION = (
    "Section 7: 'we have visually confirmed that the algorithms converge with G1 "
    "continuity. However, there is still a need for theoretical proofs for convergence.' "
    "The moduli of the leading eigenvalues of the local subdivision matrix of every "
    "scheme + 2 duals at vertices of valence 3-8 and faces of 3-8 sides; Reif's standard "
    "setting is 1 > |lambda1| = |lambda2| > |lambda3|."
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

#: How Section 7's words are read by the claims of this figure and of
#: ``characteristic_maps``.
READING = (
    "'converge with G1 continuity': the limit surface has a tangent plane at every point, "
    "in particular at the centre of every extraordinary vertex and face the scheme keeps "
    "(valence or sides 3-8), with 2 duals; pentagon preservation at the package's default "
    "scale 0.75 and at 0.5 (Conway's quinto): the paper asks only for a scale below 1"
)


def cause_of(label: str, kind: str) -> str:
    """The cause the spectrum claim and the characteristic-map claim of one scheme and
    kind share (one reason makes both hold or both fail).

    Parameters
    ----------
    label : str
        A table label.
    kind : {"vertex", "face"}

    Returns
    -------
    str
    """
    return f"G1 at the {plural(kind)} of {scheme_name(label)}"


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


def _size_text(row: ContinuityRow) -> tuple[str, bool, str]:
    """``(text, standard, how)`` for one element: the moduli, whether the standard
    setting holds (exactly where the row carries its exact ordering), and ``"exact arithmetic"``
    or ``"floating point"``."""
    sp = row.spectrum
    assert sp is not None
    m = sp.moduli[1:4]
    text = f"{row.size}: " + ", ".join(f"{x:.4f}" for x in m)
    if sp.subdominant_complex:
        text += " (complex pair)"
    ex = row.exact
    if ex is not None and ex.decided:
        ok, how = ex.standard, "exact arithmetic"
        if ex.group == 1:
            sv = ex.step_value
            text += f" (lambda1 simple{f' = {sv}' if sv is not None else ''}, exact)"
        elif ex.group >= 3:
            text += f" ({ex.group} of one modulus, exact)"
    else:
        ok, how = sp.standard, "floating point"
    if not ok:
        mode = int(sp.modes[1]) if sp.modes.size > 1 else -1
        if sp.subdominant_count == 1 and mode == 0:
            text += " [Fourier mode 0: no tangent plane for generic control points]"
        elif sp.subdominant_count >= 3:
            text += " [no tangent plane for generic control points]"
    return text, ok, how


def standard_claim(
    rows: Sequence[ContinuityRow], label: str, kind: str, recorded: str = HOLDS
) -> Claim:
    """Section 7's G1, read on the spectra at every element of one kind of one scheme.

    Holds when Reif's standard setting ``1 = lambda0 > |lambda1| = |lambda2|
    > |lambda3|`` holds at every size of
    :data:`~pentanb.figures._continuity.SIZES` -- established in exact
    arithmetic where the row carries its exact ordering
    (:attr:`~pentanb.analysis.spectral.ContinuityRow.exact`), else in
    floating point to :data:`~pentanb.analysis.spectral.TOL`; a size without
    a stationary neighbourhood (or without a row) does not hold.

    Parameters
    ----------
    rows : sequence of ContinuityRow
    label : str
        A table label, e.g. ``"preserve_pentagons 0.5"``.
    kind : {"vertex", "face"}
    recorded : str

    Returns
    -------
    Claim
        Of kind :data:`~pentanb.figures.claim.CLAIM`.
    """
    by_size = {r.size: r for r in rows_of(rows, label, kind)}
    parts, bad, hows = [], [], set()
    for n in SIZES:
        r = by_size.get(n)
        if r is None or r.spectrum is None:
            bad.append(f"{n}: no row")
            continue
        sp = r.spectrum
        if not sp.stationary:
            bad.append(f"{n}: {sp.note}")
            continue
        text, ok, how = _size_text(r)
        parts.append(text)
        hows.add(how)
        if not ok:
            reason = sp.standard_reason or (r.exact.describe() if r.exact else "")
            bad.append(f"{kind} {n}: {reason}")
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
    if hows:
        measured += "; ordering established in " + " and ".join(sorted(hows))
    if bad:
        measured += "; the standard setting fails at " + "; ".join(bad)
    other = "face" if kind == "vertex" else "vertex"
    lost = fate_of(rows, label, other)
    if lost and not rows_of(rows, label, other):
        measured += f"; {plural(other)} are not kept ({lost})"
    return judged(
        f"spectra.{key_label(label)}.{plural(kind)}",
        "Section 7",
        G1,
        measured,
        "holds if Reif's standard setting 1 = lambda0 > |lambda1| = |lambda2| > |lambda3| "
        f"holds at every {every} (exact arithmetic; in floating point, moduli equal to "
        f"{TOL:g} relative) -- the setting in which an injective characteristic map gives C1: "
        "evidence for G1, not a proof; does not hold where it fails, and where lambda1 is "
        "simple of Fourier mode 0 (or three or more eigenvalues share its modulus) there is "
        "no tangent plane for generic control points",
        HOLDS if not bad else FAILS,
        recorded,
        kind=CLAIM,
        reading=READING,
        cause=cause_of(label, kind),
    )


def claims(
    meshes: Mapping[str, Mesh] | None = None, rows: Sequence[ContinuityRow] | None = None
) -> list[Claim]:
    """Section 7's G1 read on the spectra, at every element type of the paper's schemes.

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
    return [standard_claim(rows, label, kind, rec) for (label, kind), rec in RECORDED.items()]
