"""Beyond the paper: the characteristic maps of the paper's schemes, and what they show.

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity. However, there is still a need for theoretical proofs for
convergence."  Section 2 says the same of the pentagonal schemes: "we have
not theoretically validated this observation."

The *characteristic map* of an extraordinary element is the planar map
spanned by the two subdominant eigenvectors of its local subdivision
matrix (:func:`pentanb.analysis.spectral.characteristic_map`).  It exists
only where exactly two eigenvalues lead after the eigenvalue 1 (a real
double one or a complex pair): where ``lambda1`` is simple there is no
pair, and where its eigenvector has Fourier mode 0 (the same at the ``k``
turned copies of every point) no map built on it can be injective.  In
Reif's standard setting (figure ``spectra``) a regular (no fold) and
injective (one sheet) map makes the limit surface C1 at the element
(Reif 1995; Peters and Reif 2008), given a real double subdominant
eigenvalue and a C1 surface away from the element.

The figure ``characteristic_maps`` draws the maps' control nets two iterations
down, one row per scheme and kind of element, one panel per valence or
size (:func:`pentanb.viz.spectra.plot_characteristic_maps`): (A)
pentagonalization's vertices, (B)-(C) pentagon preservation with scale 0.75
(vertices, faces), (D)-(E) with scale 0.5 (the triangle has no map), and
(F) vertex insertion + 2 duals, a Catmull-Clark variant, for comparison.
Its claims (the paper's, with verdicts): the maps' control nets are regular
and injective everywhere except around triangles for scale 0.5, where no
characteristic map exists (the same cause as the spectrum's finding); the
injectivity is evidence from control nets, not a proof.  An observation
beyond the paper: C1 by Reif's criterion is established for the control
at every valence and for no element of the paper's schemes
(pentagonalization's subdominant pair is complex, and neither pentagonal
scheme is a known C1 spline away from its extraordinary elements), so the
paper's "need for theoretical proofs" stands.  The table is shared with
the figure ``spectra`` (:func:`pentanb.figures._continuity.table`).  Its
panels are charts: :func:`panels` is empty.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from ..analysis.spectral import KINDS, ContinuityRow
from ..mesh import Mesh
from ._continuity import G1, SIZES, key_label, plural, rows_of, scheme_name, sizes_text, table
from .claim import CLAIM, FAILS, HOLDS, Claim, judged, observed
from .spectra import READING, cause_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Characteristic maps and C1 (beyond the paper)"
CAPTION = (
    "Section 7: 'there is still a need for theoretical proofs for convergence'. The "
    "characteristic maps (the subdominant eigenvectors of the local subdivision matrix, "
    "two levels down) of the paper's schemes + 2 duals at vertices and faces of 3-8 sides, "
    "and of vertex insertion + 2 duals for comparison; in Reif's standard setting a regular, "
    "injective map is his sufficient condition for C1."
)

#: The claims on the maps, (table label, kind) -> recorded verdict: the paper's
#: two schemes at the elements they keep.
RECORDED = {
    ("pentagonalize", "vertex"): HOLDS,
    ("preserve_pentagons 0.75", "vertex"): HOLDS,
    ("preserve_pentagons 0.75", "face"): HOLDS,
    ("preserve_pentagons 0.5", "vertex"): HOLDS,
    ("preserve_pentagons 0.5", "face"): FAILS,  # no characteristic map around triangles
}
#: The paper's schemes (table labels).
PAPER = tuple(dict.fromkeys(label for label, _ in RECORDED))
#: The control of the C1 claim: a scheme that is a C1 spline away from its
#: extraordinary vertices (bicubic: bilinear subdivision and quad averaging,
#: Warren and Weimer 2001, Section 7.2), for which the analysis must prove C1.
CONTROL = "vertex_insertion"
#: One row of panels per (scheme, kind) of :data:`RECORDED`, then the control's vertices.
LABELS = tuple(chr(ord("A") + i) for i in range(len(RECORDED) + 1))

SECTION2 = (
    "Although, our practical results obtained by using dual as a smoothing operation "
    "strongly suggest that topological refinement together with appropriate smoothing "
    "rules yields a subdivision scheme based on pentagons, we have not theoretically "
    "validated this observation."
)
PROOFS = "However, there is still a need for theoretical proofs for convergence."


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(
    meshes: Mapping[str, Mesh] | None = None, rows: Sequence[ContinuityRow] | None = None
) -> Figure:
    """The characteristic maps of the paper's schemes and of the control, with verdicts.

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
        return vs.plot_characteristic_maps(rows, labels=(*PAPER, CONTROL))


def map_claim(rows: Sequence[ContinuityRow], label: str, kind: str, recorded: str = HOLDS) -> Claim:
    """Section 7's G1, seen on the characteristic maps at every element of one kind.

    Holds when the map's control net is regular and injective
    (:attr:`~pentanb.analysis.spectral.CharacteristicMap.injective`) at every
    size of :data:`~pentanb.figures._continuity.SIZES`; a size without a map
    (none exists, :attr:`~pentanb.analysis.spectral.ContinuityRow.map_note`)
    does not hold.

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
        Of kind :data:`~pentanb.figures.claim.CLAIM`, with the cause of the
        spectrum claim of the same scheme and kind.
    """
    by_size = {r.size: r for r in rows_of(rows, label, kind)}
    groups: dict[str, list[int]] = {}
    ok, iterations = True, 2
    for n in SIZES:
        r = by_size.get(n)
        if r is None or r.char_map is None:
            if r is not None and r.map_note:
                text = f"no characteristic map ({r.map_note})"
            else:
                note = r.spectrum.note if r is not None and r.spectrum is not None else "no row"
                text = f"no characteristic map ({note})"
            ok = False
        else:
            iterations = r.char_map.iterations
            text = r.char_map.verdict
            if not r.char_map.injective:
                ok = False
            if r.spectrum is not None and not r.spectrum.standard:
                text += " (outside the standard setting)"
        groups.setdefault(text, []).append(n)
    word = "valence" if kind == "vertex" else "sides"
    every = (
        f"vertex of valence {SIZES[0]}-{SIZES[-1]}"
        if kind == "vertex"
        else (f"face of {SIZES[0]}-{SIZES[-1]} sides")
    )
    return judged(
        f"characteristic_maps.{key_label(label)}.{plural(kind)}",
        "Section 7",
        G1,
        f"{scheme_name(label)}, characteristic map's control net {iterations} levels down at "
        f"{plural(kind)} by {word}: "
        + "; ".join(f"{text} at {sizes_text(ns)}" for text, ns in groups.items()),
        "holds if a characteristic map exists at every "
        f"{every} and its control net is regular (every face turns the same way) and "
        "injective (its boundary winds once around the element): evidence from control nets "
        "for G1, not a proof of the limit map's injectivity; does not hold where no map "
        "exists (lambda1 simple, or three or more eigenvalues of the subdominant modulus) or "
        "the net folds",
        HOLDS if ok else FAILS,
        recorded,
        kind=CLAIM,
        reading=READING,
        cause=cause_of(label, kind),
    )


def _c1_text(rows: Sequence[ContinuityRow], label: str) -> tuple[str, list[str]]:
    """``"<scheme>: <C1 verdict> at vertex 3-8, face 3-8; ..."`` and the elements proven C1."""
    groups: dict[str, dict[str, list[int]]] = {}
    proven = []
    for kind in KINDS:
        for r in rows_of(rows, label, kind):
            groups.setdefault(r.c1, {}).setdefault(kind, []).append(r.size)
            if r.c1.startswith("yes"):
                proven.append(f"{label} {r.element}")
    parts = [
        f"{c1} at " + ", ".join(f"{kind} {sizes_text(ns)}" for kind, ns in kinds.items())
        for c1, kinds in groups.items()
    ]
    return f"{scheme_name(label)}: " + ("; ".join(parts) or "no rows"), proven


def c1_claim(rows: Sequence[ContinuityRow], recorded: str = HOLDS) -> Claim:
    """Beyond Sections 2 and 7: is C1 established by Reif's criterion, and where?

    An observation (no verdict on the paper): the property stated is that
    the analysis establishes C1 (:attr:`~pentanb.analysis.spectral.
    ContinuityRow.c1` is "yes") for the control, :data:`CONTROL`, at every
    valence of :data:`~pentanb.figures._continuity.SIZES`, and at no
    element of the paper's schemes (:data:`PAPER`) -- the proof the paper
    asks for is not supplied here.  The control keeps the observation from
    being seen on an analysis that proves nothing.

    Parameters
    ----------
    rows : sequence of ContinuityRow
    recorded : str
        :data:`~pentanb.figures.claim.HOLDS` when the property was seen when
        the observation was written.

    Returns
    -------
    Claim
        Of kind :data:`~pentanb.figures.claim.OBSERVATION`.
    """
    texts, proven = [], []
    for label in PAPER:
        text, yes = _c1_text(rows, label)
        texts.append(text)
        proven += yes
    control, _ = _c1_text(rows, CONTROL)
    control_yes = tuple(r.size for r in rows_of(rows, CONTROL, "vertex") if r.c1.startswith("yes"))
    measured = (
        "C1 by Reif's criterion, per element: "
        + " | ".join(texts)
        + f" | control, a bicubic spline away from its extraordinary vertices: {control}"
        + " (the control's C1 rests on the literature, not on these numerics: Zorin and "
        "Schroeder 2001 identify it as bilinear subdivision plus averaging, Peters and Reif "
        "2008 prove Catmull-Clark's characteristic map injective; the numerics, which check "
        "the map's control net two levels down, agree with it)"
    )
    if proven:
        measured += "; established for the paper's schemes at " + ", ".join(proven)
    return observed(
        "characteristic_maps.c1",
        "Section 2 (main results); Section 7",
        f"{SECTION2} [...] {PROOFS}",
        measured,
        "Reif's criterion (the standard setting, a real double subdominant eigenvalue, a "
        "regular and injective characteristic map, a C1 spline away from the element) "
        f"establishes C1 for the control at every valence {SIZES[0]}-{SIZES[-1]} and at no "
        "element of the paper's schemes",
        control_yes == SIZES and not proven,
        recorded == HOLDS,
    )


def claims(
    meshes: Mapping[str, Mesh] | None = None, rows: Sequence[ContinuityRow] | None = None
) -> list[Claim]:
    """The characteristic maps of the paper's schemes, then the C1 verdict.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    rows : sequence of ContinuityRow, optional
        The table (default: the shared one); the tests pass one with wrong
        rows (a scheme without its duals, another scale).

    Returns
    -------
    list of Claim
        One per entry of :data:`RECORDED`, then ``characteristic_maps.c1``.
    """
    rows = table() if rows is None else rows
    out = [map_claim(rows, label, kind, rec) for (label, kind), rec in RECORDED.items()]
    out.append(c1_claim(rows))
    return out
