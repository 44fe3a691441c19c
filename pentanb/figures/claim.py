"""The claim framework: what the paper says, what we measure, and the verdict.

A :class:`Claim` is one statement of the report, of one of three kinds
(:data:`KINDS`), never mixed:

* :data:`CLAIM`, *the paper's claim*: its words and the section they come
  from, the reading they are measured under (as their authors evidently
  meant them), the measurement on the input the sentence is about, and a
  verdict: :data:`HOLDS` (exactly, to rounding), :data:`WITHIN` (within a
  tolerance the claim states) or :data:`FAILS` (does not hold as stated: a
  *finding*);
* :data:`CHECK`, a *consistency check*: an identity or bookkeeping
  (equation (1) against Euler's formula with a known genus), shown as such
  and not counted as evidence for the paper;
* :data:`OBSERVATION`, an *observation beyond the paper*: a stricter
  reading, another shape, more duals; measured and shown, with no verdict
  on the paper.  Its ``verdict`` only says whether the property it states
  is seen (:data:`HOLDS`: yes).

Every statement names its ``cause`` (claims that one reason makes hold or
fail share it; the report counts causes as well as claims) and records the
verdict it had when it was written (``recorded``).  A verdict other than
the recorded one is a *regression* (``python -m pentanb figures`` exits
with status 1); a finding is printed as one, and no error.  Each statement
must be able to change: ``tests/test_claims.py`` feeds every one a named
wrong input and sees it leave its recorded verdict.

The figure modules build them with :func:`exact` (the measurement equals
what the paper's words imply), :func:`bounded` (a number, zero when the
paper holds exactly, with a stated tolerance) and :func:`judged` (the
caller decides, from a stated criterion), each taking ``kind``,
``reading`` and ``cause``; :func:`format_report` writes them as the text
that ``python -m pentanb figures`` prints, kind by kind.

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
    "CLAIM",
    "CHECK",
    "OBSERVATION",
    "KINDS",
    "Claim",
    "exact",
    "bounded",
    "judged",
    "observed",
    "vef",
    "counts_claim",
    "add_counts",
    "configuration_claim",
    "classical_tile",
    "region_claim",
    "monotone_claim",
    "falls",
    "take",
    "format_report",
    "totals_line",
    "summary",
    "KIND_HEADINGS",
]

#: The measurement agrees with the paper (exactly, to rounding).
HOLDS = "holds"
#: It agrees within the tolerance the claim states.
WITHIN = "holds within tolerance"
#: It does not hold as stated: a finding.
FAILS = "does not hold as stated"
#: The three verdicts, best first.
VERDICTS = (HOLDS, WITHIN, FAILS)

#: The paper's claim: a verdict on the paper's words, read as their authors meant them.
CLAIM = "claim"
#: A consistency check: an identity or bookkeeping, not evidence for the paper.
CHECK = "consistency check"
#: An observation beyond the paper: measured and shown, no verdict on the paper.
OBSERVATION = "observation"
#: The three kinds of statement, in the order the report shows them.
KINDS = (CLAIM, CHECK, OBSERVATION)


@dataclass(frozen=True)
class Claim:
    """One statement of the report: the paper's claim, a consistency check or an observation.

    Attributes
    ----------
    key : str
        Unique name in the report, e.g. ``"fig07.uniform.edge"``; the tests
        name statements by it.
    section : str
        Where the paper says it, e.g. ``"Section 5.1, Figure 7"``.
    quote : str
        The paper's words (for an observation: the words it goes beyond).
    measured : str
        What was measured and the numbers.
    criterion : str
        When the claim counts as holding (and, if any, the tolerance); for
        an observation, the property it states.
    verdict : str
        One of :data:`VERDICTS`; for an observation, :data:`HOLDS` when the
        stated property is seen, :data:`FAILS` when not.
    recorded : str
        The verdict this statement had when it was written; a different
        ``verdict`` is a regression.
    kind : str
        One of :data:`KINDS` (default :data:`CLAIM`).
    reading : str
        How the paper's words are read (as their authors evidently meant
        them); written beside the quote.
    cause : str
        What makes the verdict what it is; statements of one kind and
        verdict with the same cause are counted once as a cause (default:
        the key).
    """

    key: str
    section: str
    quote: str
    measured: str
    criterion: str
    verdict: str
    recorded: str = HOLDS
    kind: str = CLAIM
    reading: str = ""
    cause: str = ""

    def __post_init__(self) -> None:
        for name in ("verdict", "recorded"):
            if getattr(self, name) not in VERDICTS:
                raise ValueError(
                    f"claim {self.key!r}: {name} must be one of {VERDICTS}, "
                    f"got {getattr(self, name)!r}"
                )
        if self.kind not in KINDS:
            raise ValueError(f"claim {self.key!r}: kind must be one of {KINDS}, got {self.kind!r}")
        if self.kind == OBSERVATION and WITHIN in (self.verdict, self.recorded):
            raise ValueError(
                f"claim {self.key!r}: an observation is seen or not ({HOLDS!r} or {FAILS!r})"
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
        """True for a claim of the paper that does not hold as stated."""
        return self.kind == CLAIM and self.verdict == FAILS

    @property
    def cause_name(self) -> str:
        """:attr:`cause`, or the key when none is given."""
        return self.cause or self.key

    def tag(self) -> str:
        """The head of the statement as the report prints it.

        Returns
        -------
        str
            ``[holds]`` (a claim's verdict), ``[consistency check: holds]`` or
            ``[observation]``, then the key, then ``  FINDING`` for a claim that
            does not hold or ``  REGRESSION (recorded: ...)``.
        """
        if self.kind == CLAIM:
            head = f"[{self.verdict}]"
        elif self.kind == CHECK:
            head = f"[consistency check: {self.verdict}]"
        else:
            head = "[observation]"
        mark = "  FINDING" if self.finding else ""
        if self.regressed:
            mark = f"  REGRESSION (recorded: {self.recorded})"
        return f"{head} {self.key}{mark}"

    def lines(self) -> list[str]:
        """The statement as report lines (no indentation).

        Returns
        -------
        list of str
            A claim: the verdict and key, the paper's words, how they are
            read, what was measured, the criterion.  A consistency check:
            the same without the reading, the criterion marked as an
            identity.  An observation: the key, the paper's words it goes
            beyond, what was measured and the property it states, seen or
            not.
        """
        out = [self.tag()]
        if self.kind == OBSERVATION:
            out.append(f'    beyond the paper ({self.section}): "{self.quote}"')
        else:
            out.append(f'    paper ({self.section}): "{self.quote}"')
        if self.reading and self.kind != CHECK:
            out.append(f"    read as: {self.reading}")
        out.append(f"    measured: {self.measured}")
        if self.kind == OBSERVATION:
            seen = "yes" if self.verdict == HOLDS else "no"
            out.append(f"    observed: {self.criterion}: {seen}")
        elif self.kind == CHECK:
            out.append(f"    criterion: {self.criterion} (an identity: not evidence)")
        else:
            out.append(f"    criterion: {self.criterion}")
        return out

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


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def exact(
    key: str,
    section: str,
    quote: str,
    what: str,
    expected: object,
    measured: object,
    recorded: str = HOLDS,
    *,
    kind: str = CLAIM,
    reading: str = "",
    cause: str = "",
) -> Claim:
    """A statement that holds when ``measured == expected`` (else: does not hold).

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
        The verdict recorded for this statement.
    kind, reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
    """
    return Claim(
        key,
        section,
        quote,
        f"{what}: {fmt(measured)}",
        f"holds if equal to {fmt(expected)}",
        HOLDS if expected == measured else FAILS,
        recorded,
        kind,
        reading,
        cause,
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
    kind: str = CLAIM,
    reading: str = "",
    cause: str = "",
) -> Claim:
    """A statement measured by one number that is 0 when the paper holds exactly.

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
    kind, reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
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
    return Claim(key, section, quote, measured, crit, verdict, recorded, kind, reading, cause)


def judged(
    key: str,
    section: str,
    quote: str,
    measured: str,
    criterion: str,
    verdict: str,
    recorded: str = HOLDS,
    *,
    kind: str = CLAIM,
    reading: str = "",
    cause: str = "",
) -> Claim:
    """A statement whose verdict the caller decided by the stated ``criterion``.

    Parameters
    ----------
    key, section, quote, measured, criterion, verdict, recorded : str
    kind, reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
    """
    return Claim(key, section, quote, measured, criterion, verdict, recorded, kind, reading, cause)


def observed(
    key: str,
    section: str,
    quote: str,
    measured: str,
    statement: str,
    seen: bool,
    recorded: bool = True,
    *,
    cause: str = "",
) -> Claim:
    """An observation beyond the paper: what was measured and a property it shows.

    Parameters
    ----------
    key, section : str
        See :class:`Claim`.
    quote : str
        The paper's words the observation goes beyond.
    measured : str
    statement : str
        The property the measurement shows, e.g. ``"the spreads fall at every
        pair of duals"``; the report prints it with ``yes`` or ``no``.
    seen : bool
        Whether it is seen.
    recorded : bool
        Whether it was seen when the observation was written (a change is a
        regression).
    cause : str

    Returns
    -------
    Claim
        Of kind :data:`OBSERVATION`; verdict :data:`HOLDS` when seen.
    """
    return Claim(
        key,
        section,
        quote,
        measured,
        statement,
        HOLDS if seen else FAILS,
        HOLDS if recorded else FAILS,
        OBSERVATION,
        "",
        cause,
    )


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
    *,
    reading: str = "",
    cause: str = "",
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
    reading, cause : str
        See :class:`Claim`; the default reading is the construction counted.

    Returns
    -------
    Claim
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
        reading=reading
        or f"the construction, counted: {s.label.lower()} makes {s.formula} from (V, E, F)",
        cause=cause,
    )


def add_counts(a: Mapping[int, int], b: Mapping[int, int]) -> dict[int, int]:
    """The sum of two histograms ``{size: count}``, sorted by size."""
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + v
    return dict(sorted(out.items()))


def configuration_claim(
    key: str,
    section: str,
    quote: str,
    mesh: Mesh,
    expected: Mapping[str, int],
    paper: str,
    *,
    reading: str = "",
    cause: str = "",
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
    reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
    """
    canon = canonical_configuration(paper)
    return exact(
        key,
        section,
        quote,
        f"(A) faces by the valences of their corners ({paper} = {canon} up to rotation)",
        dict(expected),
        configuration_counts(face_configurations(mesh)),
        reading=reading,
        cause=cause,
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
    steps: Sequence[tuple],
    config: str,
    recorded: str,
    *,
    kind: str = CLAIM,
    reading: str = "",
    cause: str = "",
) -> Claim:
    """Section 5.1's "classical (or geometrical) semi-regular regions", measured as geometry.

    At every step (a mesh, e.g. after 2, 4, 6 duals), the faces whose corner
    valences make ``config`` (among the given candidate faces, e.g. those of
    a flat region) are compared with the classical tile
    (:func:`classical_tile`): within every group of corners of one valence
    the angles should be equal (angle spread 0), their mean the tile's angle
    (relative deviation 0), and the faces flat (planarity 0, the largest
    distance of a corner from its face's least-squares plane over the
    region's mean edge length); the largest angle off the tile's and the
    edge spread are reported next to the tile's.

    A claim (``kind`` :data:`CLAIM`) holds when all three are 0 to rounding
    at every step; holds within tolerance when at the first step each is at
    most :data:`REGION_TOLERANCE` and no later step has a larger one (the
    duals do not take the regions away from it); does not hold otherwise.  An
    observation (``kind`` :data:`OBSERVATION`) states that the regions are
    further than :data:`REGION_TOLERANCE` from the flat tile at every step.

    Parameters
    ----------
    key, section, quote : str
    steps : sequence of (label, Mesh) or (label, Mesh, faces)
        The meshes to measure, e.g. ``[("2 duals", mesh, region)]``;
        ``faces`` (int array) restricts the regions to these faces.
    config : str
        The paper's notation, e.g. ``"4.3.3.4.3"``.
    recorded : str
    kind, reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
    """
    canon = canonical_configuration(config)
    tile = classical_tile(config)
    ideal: dict = tile["angles"]  # type: ignore[assignment]
    parts, worsts = [], []
    for step in steps:
        label, mesh = step[0], step[1]
        fc = face_configurations(mesh)
        allowed = None if len(step) < 3 else {int(f) for f in step[2]}
        faces = [i for i, c in enumerate(fc) if c == canon and (allowed is None or i in allowed)]
        if not faces:
            parts.append(f"{label}: no {config} faces")
            worsts.append((math.inf, math.inf, math.inf))
            continue
        g = region_geometry(mesh, faces, ideal)
        angles: dict = g["angles"]  # type: ignore[assignment]
        dev = max(abs(angles[k] - a) / a if k in angles else math.inf for k, a in ideal.items())
        spread, flat = float(g["angle_spread"]), float(g["planarity"])  # type: ignore[arg-type]
        worsts.append((spread, flat, dev))
        parts.append(
            f"{label}: {g['faces']} faces, angle spread {fmt(spread)}, planarity "
            f"{fmt(flat)}, mean angles {fmt({k: round(v, 3) for k, v in angles.items()})}, "
            f"largest angle off the tile's {float(g['angle_error']):.2f} degrees, "  # type: ignore[arg-type]
            f"edge spread {fmt(float(g['edge_spread']))}"  # type: ignore[arg-type]
        )
    ideal_angles = {k: round(v, 1) for k, v in ideal.items()}
    tile_text = (
        f"the classical tile V{config}: angles {fmt(ideal_angles)} by corner valence, flat, "
        f"edge spread {fmt(float(tile['edge_spread']))}"  # type: ignore[arg-type]
    )
    if kind == OBSERVATION:
        far = all(max(w) > REGION_TOLERANCE for w in worsts)
        return observed(
            key,
            section,
            quote,
            "; ".join(parts),
            f"against {tile_text}: at every step the angle spread, the planarity or a mean "
            f"angle is more than {REGION_TOLERANCE:.0%} off",
            far,
            recorded == HOLDS,
            cause=cause,
        )
    strict = all(max(w) <= 1e-9 for w in worsts)
    first = worsts[0] if worsts else (math.inf,) * 3
    near = max(first) <= REGION_TOLERANCE and all(
        all(x <= f + 1e-9 for x, f in zip(w, first)) for w in worsts[1:]
    )
    verdict = HOLDS if strict else WITHIN if near else FAILS
    return judged(
        key,
        section,
        quote,
        "; ".join(parts),
        f"{tile_text}; holds if the angle spread and planarity are 0 and the mean angles "
        f"the tile's (to rounding) at every step; within tolerance if at the first step each "
        f"is within {REGION_TOLERANCE:.0%} and no later step has a larger one",
        verdict,
        recorded,
        kind=kind,
        reading=reading,
        cause=cause,
    )


def falls(values: Sequence[float], rel: float = 1e-9) -> list[int]:
    """The indices ``i >= 1`` where ``values[i]`` does not fall below ``values[i - 1]``
    (by more than ``rel`` of it), or is NaN; empty when the series strictly falls."""
    vals = [float(x) for x in values]
    return [
        i
        for i in range(1, len(vals))
        if not vals[i] < vals[i - 1] - rel * abs(vals[i - 1]) or math.isnan(vals[i])
    ]


def monotone_claim(
    key: str,
    section: str,
    quote: str,
    what: str,
    series: Mapping[str, Sequence[float]],
    steps: Sequence[str],
    recorded: str,
    rel: float = 1e-9,
    *,
    kind: str = CLAIM,
    reading: str = "",
    cause: str = "",
) -> Claim:
    """A statement that some measures fall at every step (e.g. "more uniform with each dual").

    Holds when every series strictly decreases (each value below the one
    before by more than ``rel`` of it); otherwise the measured text names the
    first rise of each series.  As an observation (``kind``
    :data:`OBSERVATION`), it states that every measure falls at every step.

    Parameters
    ----------
    key, section, quote : str
    what : str
        What the steps are, e.g. ``"after 2, 4, 6 duals"``.
    series : dict
        ``{measure name: values, one per step}``.
    steps : sequence of str
        The name of every step (e.g. ``["(D)", "4 duals", "(F)"]``).
    recorded : str
    rel : float
    kind, reading, cause : str
        See :class:`Claim`.

    Returns
    -------
    Claim
    """
    parts, ok = [], True
    for name, values in series.items():
        vals = [float(x) for x in values]
        rises = falls(vals, rel)
        text = f"{name} {fmt([round(x, 4) for x in vals])}"
        if rises:
            ok = False
            text += " (rises at " + ", ".join(steps[i] for i in rises) + ")"
        parts.append(text)
    if kind == OBSERVATION:
        return observed(
            key,
            section,
            quote,
            f"{what}: " + "; ".join(parts),
            "every measure falls at every step",
            ok,
            recorded == HOLDS,
            cause=cause,
        )
    return judged(
        key,
        section,
        quote,
        f"{what}: " + "; ".join(parts),
        "holds if every measure falls at every step",
        HOLDS if ok else FAILS,
        recorded,
        kind=kind,
        reading=reading,
        cause=cause,
    )


def summary(results: Mapping[str, list[Claim]]) -> dict[str, int]:
    """Counts of the report, by kind and verdict, as claims and as causes.

    Parameters
    ----------
    results : dict
        ``{figure name: claims}``.

    Returns
    -------
    dict
        ``"claims"``: the paper's claims; one entry per verdict (claims of
        that verdict) and ``"causes"``, ``"causes " + verdict`` (the causes
        among them); ``"checks"`` and ``"check causes"``; ``"observations"``
        and ``"observation causes"``; ``"statements"``: all three kinds;
        ``"findings"``, ``"regressions"``.
    """
    every = [c for cl in results.values() for c in cl]
    claims = [c for c in every if c.kind == CLAIM]
    checks = [c for c in every if c.kind == CHECK]
    obs = [c for c in every if c.kind == OBSERVATION]

    def causes(cs: list[Claim]) -> int:
        return len({c.cause_name for c in cs})

    out = {"statements": len(every), "claims": len(claims), "causes": causes(claims)}
    for v in VERDICTS:
        these = [c for c in claims if c.verdict == v]
        out[v] = len(these)
        out[f"causes {v}"] = causes(these)
    out["checks"] = len(checks)
    out["check causes"] = causes(checks)
    out["checks holding"] = sum(c.holds for c in checks)
    out["observations"] = len(obs)
    out["observation causes"] = causes(obs)
    out["findings"] = sum(c.finding for c in every)
    out["regressions"] = sum(c.regressed for c in every)
    return out


#: The report's heading of every kind of statement.
KIND_HEADINGS = {
    CLAIM: "THE PAPER'S CLAIMS: each read as its authors evidently meant it, measured on the "
    "input the sentence is about",
    CHECK: "CONSISTENCY CHECKS: identities and bookkeeping, shown as such and not counted as "
    "evidence",
    OBSERVATION: "OBSERVATIONS BEYOND THE PAPER: stricter readings, other shapes, more duals; "
    "measured, with no verdict on the paper",
}


def totals_line(results: Mapping[str, list[Claim]]) -> str:
    """The last line of the report: every kind counted as statements and as causes.

    Parameters
    ----------
    results : dict
        ``{figure name: claims}``.

    Returns
    -------
    str
        ``"C consistency checks (k causes; not evidence), O observations beyond
        the paper (k causes); the paper's claims: N in K causes: a hold in k,
        b hold within a stated tolerance in k, c do not hold as stated in k
        (findings); all as recorded"``, or ending ``"; R REGRESSIONS: key
        (recorded ..., measured ...); ..."``.
    """
    s = summary(results)
    regressions = [c for cl in results.values() for c in cl if c.regressed]
    checks = f"{s['checks']} consistency checks ({_plural(s['check causes'], 'cause')}"
    if s["checks holding"] != s["checks"]:
        checks += f", {s['checks'] - s['checks holding']} failing"
    total = (
        f"{checks}; not evidence), {s['observations']} observations beyond the paper "
        f"({_plural(s['observation causes'], 'cause')}); the paper's claims: {s['claims']} in "
        f"{_plural(s['causes'], 'cause')}: {s[HOLDS]} hold in {s['causes ' + HOLDS]}, "
        f"{s[WITHIN]} hold within a stated tolerance in {s['causes ' + WITHIN]}, {s[FAILS]} do "
        f"not hold as stated in {s['causes ' + FAILS]} (findings); "
    )
    if regressions:
        total += f"{len(regressions)} REGRESSIONS: " + "; ".join(
            f"{c.key} (recorded: {c.recorded}, measured: {c.verdict})" for c in regressions
        )
    else:
        total += "all as recorded"
    return total


def format_report(results: Mapping[str, list[Claim]], titles: Mapping[str, str]) -> str:
    """The statements as text, kind by kind, then the findings by cause, then the totals.

    Parameters
    ----------
    results : dict
        ``{figure name: claims}``.
    titles : dict
        ``{figure name: title}``, printed after the name.

    Returns
    -------
    str
        Three parts, one per kind of :data:`KINDS`, each headed by
        :data:`KIND_HEADINGS` and holding one block per figure (a line
        ``"<name>  <title>"``, then its statements of that kind); then the
        findings grouped by cause; the last line is :func:`totals_line`.
    """
    lines = []
    for kind in KINDS:
        blocks = [(name, [c for c in cl if c.kind == kind]) for name, cl in results.items()]
        blocks = [(name, cl) for name, cl in blocks if cl]
        if not blocks:
            continue
        lines.append(KIND_HEADINGS[kind])
        for name, cl in blocks:
            lines.append(f"{name}  {titles[name]}")
            for c in cl:
                lines += [f"  {line}" for line in c.lines()]
    findings = [c for cl in results.values() for c in cl if c.finding and not c.regressed]
    if findings:
        by_cause: dict[str, list[Claim]] = {}
        for c in findings:
            by_cause.setdefault(c.cause_name, []).append(c)
        lines.append(
            f"findings: the paper's claims that do not hold as stated, {len(findings)} in "
            f"{_plural(len(by_cause), 'cause')}:"
        )
        for cause, cs in by_cause.items():
            lines.append(f"  cause: {cause}")
            lines += [f"    {c.key}: {c.measured}" for c in cs]
    lines.append(totals_line(results))
    return "\n".join(lines)
