"""Beyond the paper: the scale of pentagon preservation, and the number of duals.

Section 5.2, step 2(b): "Scale the points in Pi around their centroid by a
specified amount. The scale factor should be less than 1."  Step 4: "Apply
dual operation an even number of times."  The paper fixes neither.  The
local subdivision matrices of pentagon preservation depend on the scale
``s`` affinely, one step at a time
(:class:`pentanb.analysis.spectral.ScaleFamily`), so Reif's standard setting
(``1 = lambda0 > |lambda1| = |lambda2| > |lambda3|``, figure ``spectra``)
can be mapped along the scale, at vertices of valence 3-8 and faces of 3-8
sides, with 2, 4 and 6 duals (:func:`pentanb.analysis.spectral.scale_study`):
sampled at the scales 1/100 ... 99/100 in floating point, every change of
the setting located by bisection and established in exact rational
arithmetic (the leading eigenvalues coincide at the threshold; the setting
fails and holds on either side).

What it finds: with 2 duals the setting holds everywhere for scales above
5/7 -- at a triangle the leading eigenvalues are ``11/60 - s/12`` (Fourier
mode 0, simple) and ``(s + 3)/30`` (a pair of modes +-1) per step, which
cross at ``s = 5/7`` -- and at every other element for every scale sampled;
with 4 or 6 duals it fails at triangles at every scale sampled (exactly at
3/4): a finding, since the paper allows "an even number" of duals (the
other statements are observations).  The recommended scale, 7/8 with 2 duals, maximizes the smallest
relative gap ``(|lambda2| - |lambda3|) / |lambda2|`` over the elements (the
rate at which the rings settle to the characteristic map), which at the
package's default 0.75 is 1/30 at triangles.

The figure ``scale`` draws ``|lambda1|`` and ``|lambda3|`` against the scale
(:func:`pentanb.viz.spectra.plot_scale`).  Its statements are observations
beyond the paper (no verdict on it), but for the one on 4 and 6 duals, a
claim.  The study is computed once per
process (:func:`pentanb.figures._continuity.scale_study`).  Its panels are
charts: :func:`panels` is empty.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..analysis.spectral import KINDS, ScaleStudy
from ..mesh import Mesh
from ._continuity import G1, SIZES, plural, scale_study, sizes_text
from .claim import CLAIM, FAILS, HOLDS, Claim, judged, observed

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "The scale of pentagon preservation (beyond the paper)"
CAPTION = (
    "Section 5.2: 'The scale factor should be less than 1'; 'Apply dual operation an even "
    "number of times.' Pentagon preservation's leading eigenvalue moduli |lambda1| and "
    "|lambda3| per step against the scale, with 2, 4 and 6 duals, at faces and vertices of "
    "3-8 sides; Reif's standard setting 1 > |lambda1| = |lambda2| > |lambda3| fails where "
    "shaded."
)

#: Numbers of duals drawn, one row of panels each (faces, then vertices).
DUALS = (2, 4, 6)
LABELS = tuple(chr(ord("A") + i) for i in range(2 * len(DUALS)))

SECTION = "Section 5.2, steps 2(b) and 4"
QUOTE = (
    "Scale the points in Pi around their centroid by a specified amount. The scale factor "
    "should be less than 1. [...] Apply dual operation an even number of times."
)

#: The statements, key -> recorded (seen when written, for the observations; the
#: verdict, for the claim).
RECORDED: dict[str, bool | str] = {
    "scale.triangles.2_duals": True,
    "scale.triangles.more_duals": FAILS,
    "scale.elsewhere": True,
    "scale.recommended": True,
}

#: How the claim on more duals reads Section 7 with Section 5.2's "an even number of times".
MORE_DUALS_READING = (
    "'converge with G1 continuity' for the schemes as Section 5.2 states them, which allows "
    "any even number of duals: with 4 and with 6 duals, pentagon preservation has a tangent "
    "plane at the centre of a triangle for some scale below 1 (the paper fixes none). Like "
    "the claim at scale 0.5 (figure spectra), a choice the paper's words allow"
)


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def draw(meshes: Mapping[str, Mesh] | None = None, data: ScaleStudy | None = None) -> Figure:
    """Leading eigenvalue moduli against the scale, one row per number of duals.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.
    data : ScaleStudy, optional
        The study (default: the shared one,
        :func:`pentanb.figures._continuity.scale_study`).

    Returns
    -------
    matplotlib.figure.Figure
        Panels (A)-(F): faces and vertices with 2, 4 and 6 duals.
    """
    from ..viz import mpl as vz
    from ..viz import spectra as vs

    study = scale_study() if data is None else data
    with vz.style():
        return vs.plot_scale(study, DUALS)


def _exact_text(study: ScaleStudy, key) -> str:
    th = study.thresholds[key]
    return "; ".join(f"at s = {s}: {ex.describe()}" for s, ex in sorted(th.exact_at.items()))


def _triangles(study: ScaleStudy, recorded: bool) -> Claim:
    key = (2, "face", 3)
    th = study.thresholds[key]
    at = th.exact_at
    seen = (
        th.status == "above"
        and th.value == Fraction(5, 7)
        and at.get(Fraction(5, 7)) is not None
        and at[Fraction(5, 7)].group == 3
        and at[Fraction(5, 7)].equal is True
    )
    return observed(
        "scale.triangles.2_duals",
        SECTION,
        QUOTE,
        f"pentagon preservation + 2 duals at triangles, standard setting by scale: {th.text} "
        f"(sampled at {len(study.grid)} scales; the change located by bisection); "
        + _exact_text(study, key),
        "with 2 duals the standard setting at a triangle holds above s = 5/7 and fails below: "
        "at 5/7 three leading eigenvalues coincide, established exactly",
        seen,
        recorded,
    )


def _more_duals(study: ScaleStudy, recorded: str) -> Claim:
    parts, none = [], True
    for d in DUALS[1:]:
        key = (d, "face", 3)
        th = study.thresholds[key]
        parts.append(
            f"{d} duals: {th.text}" + (f" ({_exact_text(study, key)})" if th.exact_at else "")
        )
        exacts = list(th.exact_at.values())
        none = none and th.status == "never" and bool(exacts) and all(e.group == 1 for e in exacts)
    return judged(
        "scale.triangles.more_duals",
        "Section 7; Section 5.2, step 4",
        f"{G1} [...] Apply dual operation an even number of times.",
        "pentagon preservation at triangles, standard setting by scale: " + "; ".join(parts),
        f"holds if with each of {', '.join(map(str, DUALS[1:]))} duals some sampled scale puts "
        "a triangle in the standard setting; does not hold if none does (sampled at "
        f"{len(study.grid)} scales in floating point; lambda1 simple of mode 0, established "
        "exactly, at the scales listed)",
        FAILS if none else HOLDS,
        recorded,
        kind=CLAIM,
        reading=MORE_DUALS_READING,
        cause="no tangent plane at triangles with 4 or 6 duals, at any scale sampled",
    )


def _elsewhere(study: ScaleStudy, recorded: bool) -> Claim:
    groups: dict[str, list[str]] = {}
    seen = True
    for d in DUALS:
        for kind in KINDS:
            for n in SIZES:
                if kind == "face" and n == 3:
                    continue
                th = study.thresholds.get((d, kind, n))
                text = th.text if th is not None else "no row"
                groups.setdefault(text, []).append(f"{d}/{kind} {n}")
                seen = seen and text == "always"
    measured = "; ".join(f"{text}: {len(els)} elements" for text, els in groups.items())
    bad = [e for text, els in groups.items() if text != "always" for e in els]
    if bad:
        measured += " (not always: " + ", ".join(bad) + ")"
    return observed(
        "scale.elsewhere",
        SECTION,
        QUOTE,
        f"pentagon preservation with {', '.join(map(str, DUALS))} duals at vertices of valence "
        f"{sizes_text(SIZES)} and faces of {sizes_text(SIZES[1:])} sides, standard setting "
        f"at the {len(study.grid)} sampled scales (floating point): {measured}",
        f"at vertices of valence {sizes_text(SIZES)} and faces of {sizes_text(SIZES[1:])} "
        "sides the standard setting holds at every scale sampled, with 2, 4 and 6 duals",
        seen,
        recorded,
    )


def _recommended(study: ScaleStudy, recorded: bool) -> Claim:
    r = study.recommended
    exact = study.exact_at_recommended
    ok = [f"{k} {n}" for (k, n), e in exact.items() if e.standard]
    missing = [f"{k} {n}" for k in KINDS for n in SIZES if (k, n) not in exact]
    failing = [f"{k} {n}" for (k, n), e in exact.items() if not e.standard]
    limiting = ", ".join(f"{plural(k)} {n}" for k, n in study.limiting)
    seen = (
        not missing
        and not failing
        and study.worst_gap > study.worst_gap_default
        and abs(float(r) - study.optimum) <= 0.01
    )
    measured = (
        f"{study.recommended_duals} duals; the smallest relative gap (|lambda2| - |lambda3|) / "
        f"|lambda2| over the elements is largest at s = {study.optimum:.4f} (where {limiting} "
        f"limit it); at {r} it is {study.worst_gap:.4f}, at the default 0.75 "
        f"{study.worst_gap_default:.4f}; standard setting at {r} established exactly at "
        f"{len(ok)} of {len(KINDS) * len(SIZES)} elements"
    )
    if failing or missing:
        measured += " (not at: " + ", ".join(failing + missing) + ")"
    return observed(
        "scale.recommended",
        SECTION,
        QUOTE,
        measured,
        f"the recommended scale {r} (with {study.recommended_duals} duals) maximizes the "
        "smallest relative spectral gap to within 0.01, beats the default 0.75 on it, and is "
        "in the standard setting at every element, established exactly",
        seen,
        recorded,
    )


def claims(meshes: Mapping[str, Mesh] | None = None, data: ScaleStudy | None = None) -> list[Claim]:
    """Observations on pentagon preservation's scale and number of duals.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels).
    data : ScaleStudy, optional
        The study (default: the shared one); the tests pass wrong ones.

    Returns
    -------
    list of Claim
        One per entry of :data:`RECORDED`: of kind
        :data:`~pentanb.figures.claim.OBSERVATION`, but for
        ``scale.triangles.more_duals``, a claim of the paper.
    """
    study = scale_study() if data is None else data
    makers: dict[str, Callable[[ScaleStudy, Any], Claim]] = {
        "scale.triangles.2_duals": _triangles,
        "scale.triangles.more_duals": _more_duals,
        "scale.elsewhere": _elsewhere,
        "scale.recommended": _recommended,
    }
    return [makers[k](study, rec) for k, rec in RECORDED.items()]
