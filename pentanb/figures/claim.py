"""The claim framework: what the paper says of a figure, next to what we measure.

A :class:`Claim` is one statement, the value it predicts, the value
measured on our meshes and whether they agree.  The figure modules build
their claims with :func:`eq` (holds when measured == expected),
:func:`check` (holds when a test the caller computed passes) and
:func:`counts_claims` (a scheme's count formula, Section 3's tables);
:func:`format_report` writes them as the text that ``python -m pentanb
figures`` prints.

numpy only (no drawing).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

from ..analysis.measures import (
    canonical_configuration,
    configuration_counts,
    face_configurations,
    vertex_configurations,
)
from ..mesh import Mesh
from ..schemes import SCHEMES

__all__ = [
    "Claim",
    "eq",
    "check",
    "vef",
    "counts_claims",
    "add_counts",
    "configuration_claims",
    "format_report",
]


@dataclass(frozen=True)
class Claim:
    """One statement of the paper, checked on our meshes.

    Attributes
    ----------
    text : str
        What the paper says (or what follows from it), naming the panel.
    expected : object
        The value the statement predicts.
    measured : object
        The value measured on the mesh.
    holds : bool
        Whether the measurement agrees.
    """

    text: str
    expected: object
    measured: object
    holds: bool

    def __str__(self) -> str:
        mark = "ok  " if self.holds else "FAIL"
        return (
            f"[{mark}] {self.text}: expected {_fmt(self.expected)}, measured {_fmt(self.measured)}"
        )


def _fmt(x: object) -> str:
    if isinstance(x, float):
        return f"{x:.4g}"
    if isinstance(x, Fraction):
        return str(x) if x.denominator == 1 else f"{x} = {float(x):.4g}"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{k}: {_fmt(v)}" for k, v in x.items()) + "}"
    if isinstance(x, tuple):
        return "(" + ", ".join(_fmt(v) for v in x) + ")"
    if isinstance(x, list):
        return "[" + ", ".join(_fmt(v) for v in x) + "]"
    return str(x)


def eq(text: str, expected: object, measured: object) -> Claim:
    """A claim that holds when ``measured == expected``."""
    return Claim(text, expected, measured, bool(expected == measured))


def check(text: str, expected: object, measured: object, holds: object) -> Claim:
    """A claim whose verdict the caller computed (``holds``, made a bool)."""
    return Claim(text, expected, measured, bool(holds))


def vef(mesh: Mesh) -> tuple[int, int, int]:
    """``(V, E, F)`` of a mesh."""
    return mesh.n_vertices, mesh.n_edges, mesh.n_faces


def counts_claims(
    panel: str, before: Mesh, after: Mesh, scheme: str, iterations: int = 1
) -> list[Claim]:
    """V, E, F of ``after`` against the scheme's count formula applied to ``before``.

    Parameters
    ----------
    panel : str
        E.g. ``"(B)"``.
    before, after : Mesh
        The input and the output of ``iterations`` rounds of ``scheme``.
    scheme : str
        A name of :data:`pentanb.SCHEMES`.
    iterations : int

    Returns
    -------
    list of Claim
        One claim.
    """
    s = SCHEMES[scheme]
    counts = vef(before)
    for _ in range(iterations):
        counts = s.counts(*counts)
    times = "" if iterations == 1 else f" x{iterations}"
    return [
        eq(
            f"{panel} (V, E, F) = {s.label.lower()}{times} formula "
            f"{s.formula} from (V, E, F) = {vef(before)}",
            counts,
            vef(after),
        )
    ]


def add_counts(a: Mapping[int, int], b: Mapping[int, int]) -> dict[int, int]:
    """The sum of two histograms ``{size: count}``, sorted by size."""
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + v
    return dict(sorted(out.items()))


def configuration_claims(
    a: Mesh, b: Mesh, paper: str, expected: Mapping[str, int], kind: str
) -> list[Claim]:
    """Section 5.1's semi-regular regions of a pentagonal mesh (A) and its dual (B).

    Parameters
    ----------
    a : Mesh
        A pentagonal mesh (Figures 8.A, 9.A).
    b : Mesh
        Its dual.
    paper : str
        The configuration as the paper writes it, e.g. ``"4.3.3.4.3"``.
    expected : dict
        ``{canonical face configuration: count}`` expected of (A) (and as
        vertex configurations of (B)).
    kind : str
        E.g. ``"semi-regular"``.

    Returns
    -------
    list of Claim
        (A) only pentagons; (A) by face configuration; (B) by vertex configuration.
    """
    canon = canonical_configuration(paper)
    fa = configuration_counts(face_configurations(a))
    vb = configuration_counts(vertex_configurations(b))
    pent = {5: a.n_faces}
    return [
        eq("(A) only pentagons", pent, a.face_size_histogram()),
        eq(
            f"(A) {paper} {kind} regions: pentagons by the valences of their corners "
            f"({paper} = {canon} up to rotation)",
            expected,
            fa,
        ),
        eq(
            f"(B) the dual has {paper} semi-regular regions: vertices by the sizes of "
            "the faces around them",
            expected,
            vb,
        ),
    ]


def format_report(results: Mapping[str, list[Claim]], titles: Mapping[str, str]) -> str:
    """The claims as text: one block per figure, one line per claim, then a total.

    Parameters
    ----------
    results : dict
        ``{figure name: claims}``.
    titles : dict
        ``{figure name: title}``, printed after the name.

    Returns
    -------
    str
        The last line reads ``"N of N claims hold"``, followed by
        ``"; FAILED: ..."`` naming every claim that does not.
    """
    lines = []
    for name, cl in results.items():
        lines.append(f"{name}  {titles[name]}")
        lines += [f"  {c}" for c in cl]
    total = sum(len(c) for c in results.values())
    failed = [(n, c) for n, cl in results.items() for c in cl if not c.holds]
    lines.append(
        f"{total - len(failed)} of {total} claims hold"
        + ("" if not failed else "; FAILED: " + "; ".join(f"{n}: {c.text}" for n, c in failed))
    )
    return "\n".join(lines)
