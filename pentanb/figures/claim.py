"""The claim framework: what the paper says, what we measure, and the verdict.

A :class:`Claim` quotes the paper (its words and the section they come
from), says what was measured on our meshes and gives one of three
verdicts:

* :data:`HOLDS`: the measurement agrees exactly (to rounding);
* :data:`WITHIN`: it agrees within a tolerance that the claim states;
* :data:`FAILS`: it does not hold as stated.

Every claim also records the verdict it had when it was written
(``recorded``).  A verdict other than the recorded one is a *regression*
(``python -m pentanb figures`` exits with status 1); a claim recorded as
not holding is a *finding*, printed as one, and no error.  Each claim must
be able to fail: ``tests/test_claims.py`` feeds every one a named wrong
input and sees it leave its recorded verdict.

The figure modules build their claims with :func:`exact` (the measurement
equals what the paper's words imply), :func:`bounded` (a number, zero when
the paper holds exactly, with a stated tolerance) and :func:`judged` (the
caller decides, from a stated criterion); :func:`format_report` writes them
as the text that ``python -m pentanb figures`` prints.

numpy only (no drawing).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

from ..analysis.measures import (
    canonical_configuration,
    configuration_counts,
    face_configurations,
    region_geometry,
)
from ..mesh import Mesh
from ..schemes import SCHEMES

__all__ = [
    "HOLDS",
    "WITHIN",
    "FAILS",
    "VERDICTS",
    "Claim",
    "exact",
    "bounded",
    "judged",
    "vef",
    "counts_claim",
    "add_counts",
    "configuration_claim",
    "classical_tile",
    "region_claim",
    "monotone_claim",
    "take",
    "format_report",
    "summary",
]

#: The measurement agrees with the paper (exactly, to rounding).
HOLDS = "holds"
#: It agrees within the tolerance the claim states.
WITHIN = "holds within tolerance"
#: It does not hold as stated: a finding.
FAILS = "does not hold as stated"
#: The three verdicts, best first.
VERDICTS = (HOLDS, WITHIN, FAILS)


@dataclass(frozen=True)
class Claim:
    """One statement of the paper, measured on our meshes.

    Attributes
    ----------
    key : str
        Unique name in the report, e.g. ``"fig07.radius"``; the tests name
        claims by it.
    section : str
        Where the paper says it, e.g. ``"Section 5.1, Figure 7"``.
    quote : str
        The paper's words.
    measured : str
        What was measured and the numbers.
    criterion : str
        When the claim counts as holding (and, if any, the tolerance).
    verdict : str
        One of :data:`VERDICTS`.
    recorded : str
        The verdict this claim had when it was written; a different
        ``verdict`` is a regression.
    """

    key: str
    section: str
    quote: str
    measured: str
    criterion: str
    verdict: str
    recorded: str = HOLDS

    def __post_init__(self) -> None:
        for name in ("verdict", "recorded"):
            if getattr(self, name) not in VERDICTS:
                raise ValueError(
                    f"claim {self.key!r}: {name} must be one of {VERDICTS}, "
                    f"got {getattr(self, name)!r}"
                )

    @property
    def holds(self) -> bool:
        """True when the verdict is :data:`HOLDS` or :data:`WITHIN`."""
        return self.verdict != FAILS

    @property
    def regressed(self) -> bool:
        """True when the verdict is not the recorded one."""
        return self.verdict != self.recorded

    @property
    def finding(self) -> bool:
        """True when the paper's statement does not hold as stated."""
        return self.verdict == FAILS

    def lines(self) -> list[str]:
        """The claim as report lines (no indentation).

        Returns
        -------
        list of str
            Four lines: the verdict and key, the paper's words, what was
            measured, and the criterion.
        """
        tag = "  FINDING" if self.finding else ""
        if self.regressed:
            tag = f"  REGRESSION (recorded: {self.recorded})"
        return [
            f"[{self.verdict}] {self.key}{tag}",
            f'    paper ({self.section}): "{self.quote}"',
            f"    measured: {self.measured}",
            f"    criterion: {self.criterion}",
        ]

    def __str__(self) -> str:
        return "\n".join(self.lines())


def fmt(x: object) -> str:
    """A value as the report writes it (floats to 4 significant digits)."""
    if isinstance(x, bool):
        return str(x)
    if isinstance(x, float):
        return "nan" if math.isnan(x) else f"{x:.4g}"
    if isinstance(x, Fraction):
        return str(x) if x.denominator == 1 else f"{x} = {float(x):.4g}"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{k}: {fmt(v)}" for k, v in x.items()) + "}"
    if isinstance(x, tuple):
        return "(" + ", ".join(fmt(v) for v in x) + ")"
    if isinstance(x, list):
        return "[" + ", ".join(fmt(v) for v in x) + "]"
    if hasattr(x, "item") and getattr(x, "ndim", None) == 0:  # numpy scalar
        return fmt(x.item())
    return str(x)


def exact(
    key: str,
    section: str,
    quote: str,
    what: str,
    expected: object,
    measured: object,
    recorded: str = HOLDS,
) -> Claim:
    """A claim that holds when ``measured == expected`` (else: does not hold).

    Parameters
    ----------
    key, section, quote : str
        See :class:`Claim`.
    what : str
        What is measured, e.g. ``"(B) faces by size"``.
    expected : object
        The value the paper's words imply.
    measured : object
        The value measured.
    recorded : str
        The verdict recorded for this claim.
    """
    return Claim(
        key,
        section,
        quote,
        f"{what}: {fmt(measured)}",
        f"holds if equal to {fmt(expected)}",
        HOLDS if expected == measured else FAILS,
        recorded,
    )


def bounded(
    key: str,
    section: str,
    quote: str,
    what: str,
    value: float,
    *,
    tolerance: float | None = None,
    why: str = "",
    detail: str = "",
    zero: float = 1e-9,
    recorded: str = HOLDS,
) -> Claim:
    """A claim measured by one number that is 0 when the paper holds exactly.

    Holds when ``value <= zero`` (rounding), holds within tolerance when
    ``value <= tolerance``, does not hold otherwise (and when ``value`` is
    NaN).

    Parameters
    ----------
    key, section, quote : str
        See :class:`Claim`.
    what : str
        What the number is.
    value : float
    tolerance : float, optional
        The stated tolerance; without it, only HOLDS or FAILS.
    why : str
        Why that tolerance (printed with it).
    detail : str
        More of the measurement (printed after the value).
    zero : float
        What counts as 0 (rounding).
    recorded : str
    """
    v = float(value)
    if v <= zero:
        verdict = HOLDS
    elif tolerance is not None and v <= tolerance:
        verdict = WITHIN
    else:
        verdict = FAILS
    crit = f"holds if <= {zero:g} (rounding)"
    if tolerance is not None:
        crit += f"; within tolerance if <= {tolerance:g}" + (f" ({why})" if why else "")
    measured = f"{what} = {fmt(v)}" + (f"; {detail}" if detail else "")
    return Claim(key, section, quote, measured, crit, verdict, recorded)


def judged(
    key: str,
    section: str,
    quote: str,
    measured: str,
    criterion: str,
    verdict: str,
    recorded: str = HOLDS,
) -> Claim:
    """A claim whose verdict the caller decided by the stated ``criterion``."""
    return Claim(key, section, quote, measured, criterion, verdict, recorded)


def vef(mesh: Mesh) -> tuple[int, int, int]:
    """``(V, E, F)`` of a mesh."""
    return mesh.n_vertices, mesh.n_edges, mesh.n_faces


def take(meshes: Mapping[str, Mesh] | None, key: str, build):
    """``meshes[key]`` if given, else ``build()``: how a claims function takes a
    wrong input for one of its meshes (a panel or a named source)."""
    if meshes is not None and key in meshes:
        return meshes[key]
    return build()


def counts_claim(
    key: str,
    section: str,
    quote: str,
    panel: str,
    before: Mesh,
    after: Mesh,
    scheme: str,
    iterations: int = 1,
    recorded: str = HOLDS,
) -> Claim:
    """V, E, F of ``after`` against the counts the scheme's construction gives.

    The construction (the paper's steps: edges cut in three, a point per
    face, ...) fixes how many vertices, edges and faces come out; the
    formula is :attr:`pentanb.Scheme.formula`.

    Parameters
    ----------
    key, section, quote : str
        See :class:`Claim`.
    panel : str
        E.g. ``"(B)"``.
    before, after : Mesh
        The input and the output of ``scheme`` applied ``iterations`` times.
    scheme : str
        A name of :data:`pentanb.SCHEMES`.
    iterations : int
    recorded : str
    """
    s = SCHEMES[scheme]
    counts = vef(before)
    for _ in range(iterations):
        counts = s.counts(*counts)
    times = "" if iterations == 1 else f" x{iterations}"
    return exact(
        key,
        section,
        quote,
        f"{panel} (V, E, F), against {s.label.lower()}{times} {s.formula} "
        f"from (V, E, F) = {vef(before)}",
        counts,
        vef(after),
        recorded,
    )


def add_counts(a: Mapping[int, int], b: Mapping[int, int]) -> dict[int, int]:
    """The sum of two histograms ``{size: count}``, sorted by size."""
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + v
    return dict(sorted(out.items()))


def configuration_claim(
    key: str, section: str, quote: str, mesh: Mesh, expected: Mapping[str, int], paper: str
) -> Claim:
    """Section 5.1's semi-regular regions, counted: faces by the valences of their corners.

    Parameters
    ----------
    key, section, quote : str
    mesh : Mesh
        The panel (A) of Figures 8, 9 or 11.
    expected : dict
        ``{canonical face configuration: count}``.
    paper : str
        The configuration as the paper writes it, e.g. ``"4.3.3.4.3"``.
    """
    canon = canonical_configuration(paper)
    return exact(
        key,
        section,
        quote,
        f"(A) faces by the valences of their corners ({paper} = {canon} up to rotation)",
        dict(expected),
        configuration_counts(face_configurations(mesh)),
    )


def classical_tile(config: str | Sequence[int]) -> dict[str, object]:
    """The tile of the classical (Laves) tiling whose faces have these corner valences.

    The Laves tiling ``V k1.k2...`` is the dual of the Archimedean tiling
    ``k1.k2...``, built from regular polygons of unit side: a tile's corner
    sits at the centre of a regular ``k``-gon (its valence is ``k`` and its
    angle ``360 / k`` degrees) and its edges cross the polygons' shared
    sides at right angles (length: the sum of the two polygons' inradii
    ``1 / (2 tan(pi / k))``).  For Section 5.1's 4.3.3.4.3: angles 90 and
    120 degrees, edges 0.577 (once) and 0.789 (four times).

    Parameters
    ----------
    config : str or sequence of int
        E.g. ``"4.3.3.4.3"``.

    Returns
    -------
    dict
        ``"angles"``: ``{valence: degrees}``; ``"edges"``: list of lengths;
        ``"edge_spread"``: their std / mean; ``"planarity"``: 0.
    """
    ks = [int(x) for x in config.split(".")] if isinstance(config, str) else list(config)
    inr = [1 / (2 * math.tan(math.pi / k)) for k in ks]
    edges = [inr[i] + inr[(i + 1) % len(ks)] for i in range(len(ks))]
    mean = sum(edges) / len(edges)
    std = math.sqrt(sum((e - mean) ** 2 for e in edges) / len(edges))
    return {
        "angles": {k: 360.0 / k for k in sorted(set(ks))},
        "edges": edges,
        "edge_spread": std / mean,
        "planarity": 0.0,
    }


#: Tolerance of :func:`region_claim`: 5 % (of an edge length, of an angle).
REGION_TOLERANCE = 0.05


def region_claim(
    key: str,
    section: str,
    quote: str,
    meshes: Sequence[tuple[str, Mesh]],
    config: str,
    recorded: str,
) -> Claim:
    """Section 5.1's "classical (or geometrical) semi-regular regions", measured as geometry.

    The faces whose corner valences make ``config`` are compared, mesh by
    mesh (iteration by iteration), with the classical tile
    (:func:`classical_tile`): within every group of corners of one valence
    the angles should be equal (angle spread 0), their mean the tile's
    angle, and the faces flat (planarity 0, the largest distance of a
    corner from its face's least-squares plane over the region's mean edge
    length).  Holds when all three are 0
    to rounding; within tolerance when the angle spread and the planarity
    are at most :data:`REGION_TOLERANCE` and every mean angle is within 5 %
    of the tile's; the edge spread is reported next to the tile's.

    Parameters
    ----------
    key, section, quote : str
    meshes : sequence of (label, Mesh)
        The meshes to measure, e.g. after successive iterations:
        ``[("level 1", mesh)]``.
    config : str
        The paper's notation, e.g. ``"4.3.3.4.3"``.
    recorded : str
    """
    canon = canonical_configuration(config)
    tile = classical_tile(config)
    parts, worst = [], 0.0
    strict = True
    for label, mesh in meshes:
        fc = face_configurations(mesh)
        faces = [i for i, c in enumerate(fc) if c == canon]
        if not faces:
            parts.append(f"{label}: no {config} faces")
            worst = math.inf
            strict = False
            continue
        g = region_geometry(mesh, faces)
        angles: dict = g["angles"]  # type: ignore[assignment]
        ideal: dict = tile["angles"]  # type: ignore[assignment]
        dev = max(
            abs(angles.get(k, math.nan) - a) / a if k in angles else math.inf
            for k, a in ideal.items()
        )
        spread, flat = float(g["angle_spread"]), float(g["planarity"])  # type: ignore[arg-type]
        worst = max(worst, spread, flat, dev)
        strict = strict and max(spread, flat, dev) <= 1e-9
        parts.append(
            f"{label}: {g['faces']} faces, angle spread {fmt(spread)}, planarity "
            f"{fmt(flat)}, mean angles {fmt({k: round(v, 1) for k, v in angles.items()})}, "
            f"edge spread {fmt(float(g['edge_spread']))}"  # type: ignore[arg-type]
        )
    verdict = HOLDS if strict else WITHIN if worst <= REGION_TOLERANCE else FAILS
    ideal_angles = {k: round(v, 1) for k, v in tile["angles"].items()}  # type: ignore[attr-defined]
    return judged(
        key,
        section,
        quote,
        "; ".join(parts),
        f"the classical tile V{config}: angles {fmt(ideal_angles)} by corner valence, flat, "
        f"edge spread {fmt(float(tile['edge_spread']))}; holds if the angle spread and planarity "  # type: ignore[arg-type]
        f"are 0 and the mean angles the tile's (to rounding); within tolerance if each is "
        f"within {REGION_TOLERANCE:.0%}",
        verdict,
        recorded,
    )


def monotone_claim(
    key: str,
    section: str,
    quote: str,
    what: str,
    series: Mapping[str, Sequence[float]],
    steps: Sequence[str],
    recorded: str,
    rel: float = 1e-9,
) -> Claim:
    """A claim that some measures fall at every step (e.g. "more uniform with each dual").

    Holds when every series strictly decreases (each value below the one
    before by more than ``rel`` of it); otherwise the measured text names the
    first rise of each series.

    Parameters
    ----------
    key, section, quote : str
    what : str
        What the steps are, e.g. ``"after 0, 2, 6 duals (B, D, F)"``.
    series : dict
        ``{measure name: values, one per step}``.
    steps : sequence of str
        The name of every step (e.g. ``["(B)", "(D)", "(F)"]``).
    recorded : str
    rel : float
    """
    parts, ok = [], True
    for name, values in series.items():
        vals = [float(x) for x in values]
        rises = [
            i
            for i in range(1, len(vals))
            if not vals[i] < vals[i - 1] - rel * abs(vals[i - 1]) or math.isnan(vals[i])
        ]
        text = f"{name} {fmt([round(x, 4) for x in vals])}"
        if rises:
            ok = False
            text += " (rises at " + ", ".join(steps[i] for i in rises) + ")"
        parts.append(text)
    return judged(
        key,
        section,
        quote,
        f"{what}: " + "; ".join(parts),
        "holds if every measure falls at every step",
        HOLDS if ok else FAILS,
        recorded,
    )


def summary(results: Mapping[str, list[Claim]]) -> dict[str, int]:
    """Counts of the report: ``claims``, one per verdict, ``findings``, ``regressions``."""
    every = [c for cl in results.values() for c in cl]
    out = {"claims": len(every)}
    for v in VERDICTS:
        out[v] = sum(c.verdict == v for c in every)
    out["findings"] = sum(c.finding for c in every)
    out["regressions"] = sum(c.regressed for c in every)
    return out


def format_report(results: Mapping[str, list[Claim]], titles: Mapping[str, str]) -> str:
    """The claims as text: one block per figure, four lines per claim, then the totals.

    Parameters
    ----------
    results : dict
        ``{figure name: claims}``.
    titles : dict
        ``{figure name: title}``, printed after the name.

    Returns
    -------
    str
        The last line reads ``"N claims: a hold, b hold within a stated
        tolerance, c do not hold as stated (findings); all as recorded"``,
        or ends ``"; R REGRESSIONS: key (recorded ..., measured ...); ..."``.
    """
    lines = []
    for name, cl in results.items():
        lines.append(f"{name}  {titles[name]}")
        for c in cl:
            lines += [f"  {line}" for line in c.lines()]
    s = summary(results)
    regressions = [c for cl in results.values() for c in cl if c.regressed]
    findings = [c for cl in results.values() for c in cl if c.finding and not c.regressed]
    if findings:
        lines.append("findings (the paper's words do not hold as stated):")
        lines += [f"  {c.key}: {c.measured}" for c in findings]
    total = (
        f"{s['claims']} claims: {s[HOLDS]} hold, {s[WITHIN]} hold within a stated tolerance, "
        f"{s[FAILS]} do not hold as stated (findings); "
    )
    if regressions:
        total += f"{len(regressions)} REGRESSIONS: " + "; ".join(
            f"{c.key} (recorded: {c.recorded}, measured: {c.verdict})" for c in regressions
        )
    else:
        total += "all as recorded"
    lines.append(total)
    return "\n".join(lines)
