"""The scale of pentagon preservation.

One remeshing step is affine in the scale, so the local matrix is too
(:func:`scale_family`, a :class:`ScaleFamily`); :func:`scale_threshold` and
:func:`scale_map` find where Reif's standard setting holds along the scale,
and :func:`scale_study` maps it for 2, 4 and 6 duals, each change established
exactly, and recommends a scale.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ... import schemes as _schemes
from ..subdivision_matrix import dual_matrix, remesh_matrix
from .eigen import TOL, _fourier_blocks
from .exact import ExactSpectrum, _certify, _core_perm, _period_matrix, exact_local_matrix
from .local import LocalSpectrum, local_spectrum
from .neighbourhood import KINDS

__all__ = [
    "ScaleFamily",
    "ScaleThreshold",
    "scale_family",
    "scale_threshold",
    "scale_map",
    "ScaleStudy",
    "scale_study",
    "SCALE_SCHEME",
    "SCALE_GRID",
]

# ---------------------------------------------------------------------------
# the scale of pentagon preservation
# ---------------------------------------------------------------------------

#: The scheme whose scale :func:`scale_family` and :func:`scale_map` study.
SCALE_SCHEME = "preserve_pentagons"
#: The reference scale the neighbourhoods are found at (any scale in (0, 1)
#: gives the same connectivity).
REFERENCE_SCALE = Fraction(3, 4)


@dataclass
class ScaleFamily:
    """Pentagon preservation's local matrix at one element, as a function of the scale.

    One step of the remeshing is affine in the scale ``s`` (the copies of
    the edge midpoints are ``s m + (1 - s) c``), the duals do not depend on
    it, and the neighbourhood's connectivity does not either; so the local
    matrix of one step is ``A(s) = base + s slope``.  In floating point the
    two pieces come from the matrices at two scales; in exact arithmetic
    (:meth:`exact`, computed on first use) from :func:`exact_local_matrix`
    at ``s = 0`` and ``s = 1``.

    Attributes
    ----------
    kind, size, duals
        The element and the duals after each remeshing.
    spectrum : LocalSpectrum
        At :data:`REFERENCE_SCALE`.
    base, slope : (n, n) float ndarray
        ``A(0)`` and ``A(1) - A(0)`` on the smallest neighbourhood mapped
        onto itself (floating point).
    perm : list of int or None
        The turn by one sector on that neighbourhood.
    """

    kind: str
    size: int
    duals: int
    spectrum: LocalSpectrum
    base: NDArray[np.float64]
    slope: NDArray[np.float64]
    perm: list[int] | None
    _exact_pieces: tuple | None = field(default=None, repr=False)
    _blocks: tuple | None = field(default=None, repr=False)
    # the last grid of several scales given to moduli_grid, with its answer
    _grid: tuple | None = field(default=None, repr=False, compare=False)

    def exact_matrix(self, s) -> list[list[Fraction]]:
        """``A(s)``, one step, exactly.

        Parameters
        ----------
        s : rational

        Returns
        -------
        list of lists of Fraction
        """
        if self._exact_pieces is None:
            a0 = exact_local_matrix(self.spectrum, Fraction(0))
            a1 = exact_local_matrix(self.spectrum, Fraction(1))
            d = [[y - x for x, y in zip(r0, r1)] for r0, r1 in zip(a0, a1)]
            self._exact_pieces = (a0, d)
        a0, d = self._exact_pieces
        s = Fraction(s)
        return [[b + s * x for b, x in zip(rb, rd)] for rb, rd in zip(a0, d)]

    def float_matrix(self, s: float) -> NDArray[np.float64]:
        """``A(s)`` in floating point.

        Parameters
        ----------
        s : float

        Returns
        -------
        (n, n) float ndarray
        """
        return self.base + float(s) * self.slope

    def moduli(self, s: float) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """The eigenvalue moduli per step at scale ``s`` (floating point), decreasing,
        the eigenvalue 1 first, with their Fourier modes (-1 when unknown).

        Parameters
        ----------
        s : float

        Returns
        -------
        moduli : (n,) float ndarray
        modes : (n,) int ndarray
        """
        m, modes = self.moduli_grid(np.array([float(s)]))
        return m[0], modes[0]

    def moduli_grid(self, scales) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """:meth:`moduli` at every scale of ``scales`` at once.

        The answer for the last grid of several scales is kept: the same grid
        again (a plot redrawn as a slider moves) costs a copy.

        Parameters
        ----------
        scales : (g,) float array

        Returns
        -------
        moduli : (g, n) float ndarray
            Per step, decreasing along each row.
        modes : (g, n) int ndarray
        """
        s = np.asarray(scales, dtype=np.float64)
        last = self._grid  # a plot's grid, asked for again at every move of a slider
        if last is not None and last[0].shape == s.shape and np.array_equal(last[0], s):
            return last[1].copy(), last[2].copy()
        if self._blocks is None:
            perm = None if self.perm is None else np.asarray(self.perm, dtype=np.int64)
            b0 = _fourier_blocks(self.base, perm, self.size) if perm is not None else None
            b1 = _fourier_blocks(self.slope, perm, self.size) if b0 is not None else None
            self._blocks = (b0, b1) if b0 is not None and b1 is not None else ()
        if self._blocks:
            vals, modes = [], []
            for (w, B0), (_, B1) in zip(*self._blocks):
                lam = np.linalg.eigvals(B0[None] + s[:, None, None] * B1[None])
                vals.append(lam)
                modes.append(np.full(lam.shape, w, dtype=np.int64))
            lam, mode = np.concatenate(vals, axis=1), np.concatenate(modes, axis=1)
        else:
            lam = np.linalg.eigvals(self.base[None] + s[:, None, None] * self.slope[None])
            mode = np.full(lam.shape, -1, dtype=np.int64)
        ctx = self.spectrum._context
        p = ctx.steps_per_match if ctx is not None else 1
        m = np.abs(lam) ** (1.0 / p)
        order = np.argsort(-np.round(m, 12), axis=1, kind="stable")
        moduli = np.take_along_axis(m, order, axis=1)
        sorted_modes = np.take_along_axis(mode, order, axis=1)
        if s.size > 1:  # (one scale: moduli(s), cheap; the grid stays)
            self._grid = (s.copy(), moduli, sorted_modes)
            return moduli.copy(), sorted_modes.copy()
        return moduli, sorted_modes

    def standard(self, s: float) -> bool:
        """Reif's standard setting at scale ``s``, in floating point (:data:`TOL`).

        Parameters
        ----------
        s : float

        Returns
        -------
        bool
        """
        return bool(_standard_rows(self.moduli(s)[0][None])[0])

    def standard_grid(self, scales) -> NDArray[np.bool_]:
        """:meth:`standard` at every scale of ``scales``.

        Parameters
        ----------
        scales : (g,) float array

        Returns
        -------
        (g,) bool ndarray
        """
        return _standard_rows(self.moduli_grid(scales)[0])

    def gap(self, s: float) -> float:
        """``(|lambda2| - |lambda3|) / |lambda2|`` where the standard setting holds, else
        ``-(|lambda1| - |lambda3|) / |lambda1|`` (how far it is from holding).

        Parameters
        ----------
        s : float

        Returns
        -------
        float
        """
        return float(self.gaps(np.array([float(s)]))[0])

    def gaps(self, scales) -> NDArray[np.float64]:
        """:meth:`gap` at every scale of ``scales``.

        Parameters
        ----------
        scales : (g,) float array

        Returns
        -------
        (g,) float ndarray
        """
        m, _ = self.moduli_grid(scales)
        ok = _standard_rows(m)
        return np.where(ok, (m[:, 2] - m[:, 3]) / m[:, 2], -(m[:, 1] - m[:, 3]) / m[:, 1])

    def exact(self, s) -> ExactSpectrum:
        """The leading eigenvalues at the rational scale ``s``, established exactly.

        Parameters
        ----------
        s : rational

        Returns
        -------
        ExactSpectrum
        """
        A = _period_matrix(self.spectrum, self.exact_matrix(s), self.perm)
        return _certify(A, self.perm, self.size, self.spectrum.period, Fraction(s))


def _standard_rows(m: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Reif's standard setting for every row of sorted moduli (the eigenvalue 1 first)."""
    if m.shape[1] < 4:
        return np.zeros(m.shape[0], dtype=bool)
    return (
        (np.abs(m[:, 0] - 1.0) <= 1e-9)
        & (m[:, 1] < 1 - 1e-9)
        & (np.abs(m[:, 1] - m[:, 2]) <= TOL * m[:, 1])
        & (m[:, 3] < m[:, 2] * (1 - TOL))
    )


def _float_local_matrix(spectrum: LocalSpectrum, scale: float, positions) -> NDArray[np.float64]:
    """The local matrix of one identification step at another scale (floating point)."""
    ctx = spectrum._context
    assert ctx is not None
    S = None
    for j in range(ctx.level, ctx.level + ctx.steps_per_match):
        R, out = remesh_matrix(ctx.steps[j].mesh, ctx.scheme, scale=float(scale))
        T = R
        for _ in range(ctx.duals):
            T = dual_matrix(out) @ T
            out = _schemes.dual(out)
        S = T if S is None else T @ S
    assert S is not None
    S = S.tocsr()
    return S[ctx.image[positions]][:, ctx.domain[positions]].toarray()


def scale_family(kind: str, size: int, duals: int = 2) -> ScaleFamily:
    """Pentagon preservation's local matrix at one element as a function of the scale.

    Parameters
    ----------
    kind : {"vertex", "face"}
    size : int, >= 3
    duals : int
        Duals after each remeshing (the paper: an even number).

    Returns
    -------
    ScaleFamily

    Raises
    ------
    ValueError
        When no stationary neighbourhood is found.
    """
    ref = float(REFERENCE_SCALE)
    sp = local_spectrum(SCALE_SCHEME, kind, size, duals, scale=ref)
    if not sp.stationary or sp._context is None:
        raise ValueError(f"no stationary neighbourhood: {sp.note}")
    ctx = sp._context
    positions = ctx.core if ctx.core is not None else np.arange(ctx.domain.size)
    perm = _core_perm(ctx, positions)
    at_ref = sp.matrix[np.ix_(positions, positions)]
    at_quarter = _float_local_matrix(sp, 0.25, positions)
    slope = (at_ref - at_quarter) / (ref - 0.25)
    base = at_quarter - 0.25 * slope
    return ScaleFamily(kind, int(size), int(duals), sp, base, slope, perm)


@dataclass(frozen=True)
class ScaleThreshold:
    """Where Reif's standard setting changes along the scale, for one element.

    Attributes
    ----------
    kind, size, duals
    status : str
        ``"always"`` (at every scale sampled in (0, 1)), ``"never"``, or
        ``"above"`` / ``"below"`` (the setting holds above / below
        ``value``), or ``"mixed"`` (several changes).
    value : Fraction or None
        The threshold, when it is established exactly (the leading
        eigenvalues coincide there, exactly).
    bracket : (Fraction, Fraction) or None
        An interval of the threshold established exactly at its ends (the
        setting exactly fails at one end and holds at the other).
    exact_at : dict
        ``{scale: ExactSpectrum}``: the scales where the ordering was
        established exactly.
    note : str
    """

    kind: str
    size: int
    duals: int
    status: str
    value: Fraction | None = None
    bracket: tuple[Fraction, Fraction] | None = None
    exact_at: dict = field(default_factory=dict, compare=False)
    note: str = ""

    @property
    def text(self) -> str:
        """``"always"``, ``"never"``, ``"s > 5/7"``, ``"s > 0.7143 (in [a, b])"`` ..."""
        if self.status in ("always", "never", "mixed"):
            return self.status
        where = str(self.value) if self.value is not None else ""
        if not where and self.bracket is not None:
            lo, hi = self.bracket
            where = f"{float((lo + hi) / 2):.6f} (in [{lo}, {hi}])"
        return f"s {'>' if self.status == 'above' else '<'} {where}"


#: Scales sampled by :func:`scale_map`: 1/100 ... 99/100.
SCALE_GRID = tuple(Fraction(j, 100) for j in range(1, 100))


def _bisect(fam: ScaleFamily, lo: float, hi: float, at_lo: bool) -> tuple[float, float]:
    for _ in range(60):
        mid = (lo + hi) / 2
        if fam.standard(mid) == at_lo:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-13:
            break
    return lo, hi


def scale_threshold(fam: ScaleFamily, grid=SCALE_GRID, *, exact: bool = True) -> ScaleThreshold:
    """Where the standard setting holds along the scale, for one element.

    Sampled in floating point on ``grid``; each change is located by
    bisection and, with ``exact``, established in exact arithmetic: the
    rational nearest the change (denominator at most 1000) is tried as the
    threshold (the leading eigenvalues must coincide there exactly, and the
    setting must fail and hold exactly on either side, 1/10000 away);
    otherwise the bisection's interval is established at its ends.

    Parameters
    ----------
    fam : ScaleFamily
    grid : sequence of rationals in (0, 1)
    exact : bool

    Returns
    -------
    ScaleThreshold
    """
    flags = [bool(x) for x in _standard_rows(fam.moduli_grid([float(s) for s in grid])[0])]
    common: dict[str, Any] = dict(kind=fam.kind, size=fam.size, duals=fam.duals)
    if all(flags):
        return ScaleThreshold(**common, status="always")
    if not any(flags):
        return ScaleThreshold(**common, status="never")
    changes = [j for j in range(len(flags) - 1) if flags[j] != flags[j + 1]]
    if len(changes) != 1:
        return ScaleThreshold(**common, status="mixed", note=f"{len(changes)} changes on the grid")
    j = changes[0]
    lo, hi = _bisect(fam, float(grid[j]), float(grid[j + 1]), flags[j])
    status = "above" if flags[j + 1] else "below"
    if not exact:
        return ScaleThreshold(
            **common,
            status=status,
            bracket=(Fraction(lo), Fraction(hi)),
            note="floating point",
        )
    guess = Fraction((lo + hi) / 2).limit_denominator(1000)
    eps = Fraction(1, 10_000)
    at = {s: fam.exact(s) for s in (guess - eps, guess, guess + eps)}
    below, on, above = at[guess - eps], at[guess], at[guess + eps]
    flips = below.standard == flags[j] and above.standard == flags[j + 1]
    if flips and on.unit_simple and on.group >= 3 and on.equal is True:
        return ScaleThreshold(**common, status=status, value=guess, exact_at=at)
    a, b = Fraction(lo).limit_denominator(10**9), Fraction(hi).limit_denominator(10**9)
    if a >= b:
        a, b = Fraction(lo), Fraction(hi)
    at = {a: fam.exact(a), b: fam.exact(b)}
    ok = at[a].standard == flags[j] and at[b].standard == flags[j + 1]
    return ScaleThreshold(
        **common,
        status=status,
        bracket=(a, b),
        exact_at=at,
        note="" if ok else "the exact ordering at the bracket's ends disagrees",
    )


def scale_map(
    duals=(2, 4, 6),
    sizes=range(3, 9),
    kinds=KINDS,
    grid=SCALE_GRID,
    *,
    exact: bool = True,
) -> list[ScaleThreshold]:
    """Where pentagon preservation is in Reif's standard setting, by scale.

    For every number of duals, kind of element and size: the thresholds of
    :func:`scale_threshold` (an element of ``"never"`` or ``"always"`` has
    none on the grid).

    Parameters
    ----------
    duals : iterable of int
    sizes : iterable of int
    kinds : iterable of {"vertex", "face"}
    grid : sequence of rationals in (0, 1)
    exact : bool
        Establish each threshold in exact arithmetic.

    Returns
    -------
    list of ScaleThreshold
        Ordered by duals, kind, size.
    """
    out = []
    for d in duals:
        for kind in kinds:
            for n in sizes:
                out.append(scale_threshold(scale_family(kind, n, d), grid, exact=exact))
    return out


@dataclass(frozen=True)
class ScaleStudy:
    """Pentagon preservation's scale, studied: where the standard setting holds, and a
    recommended scale (:func:`scale_study`).

    Attributes
    ----------
    grid : (g,) float ndarray
        The scales sampled.
    moduli : dict
        ``{(duals, kind, size): (g, 4) array}``: ``|lambda1|`` to ``|lambda4|``
        per step at every scale of the grid.
    standard : dict
        ``{(duals, kind, size): (g,) bool array}``: the standard setting at
        every scale (floating point).
    thresholds : dict
        ``{(duals, kind, size): ScaleThreshold}``.
    recommended : Fraction
        The recommended scale (with :attr:`recommended_duals` duals).
    recommended_duals : int
    optimum : float
        The scale that maximizes the smallest relative gap
        ``(|lambda2| - |lambda3|) / |lambda2|`` over the elements.
    gaps : dict
        ``{(kind, size): gap}`` at the recommended scale, and
        ``worst_gap``: the smallest of them.
    worst_gap_default : float
        The smallest gap at the package's default scale, 3/4.
    exact_at_recommended : dict
        ``{(kind, size): ExactSpectrum}`` at the recommended scale.
    limiting : tuple of (kind, size)
        The elements whose gap at the recommended scale is within 5 % of the
        smallest, smallest first (those that fix the optimum).
    """

    grid: NDArray[np.float64]
    moduli: dict
    standard: dict
    thresholds: dict
    recommended: Fraction
    recommended_duals: int
    optimum: float
    gaps: dict
    worst_gap: float
    worst_gap_default: float
    exact_at_recommended: dict = field(default_factory=dict)
    limiting: tuple = ()

    def status(self, duals: int, kind: str, size: int) -> str:
        """The threshold's text for one element.

        Parameters
        ----------
        duals : int
        kind : {"vertex", "face"}
        size : int

        Returns
        -------
        str
            ``"always"``, ``"never"``, ``"s > 5/7"``, ...
        """
        return self.thresholds[(duals, kind, size)].text


def _worst_gap(families: list[ScaleFamily], s: float) -> tuple[float, tuple[str, int]]:
    gaps = [(fam.gap(s), (fam.kind, fam.size)) for fam in families]
    return min(gaps)


def _worst_gaps(families: list[ScaleFamily], scales) -> NDArray[np.float64]:
    return np.min(np.stack([fam.gaps(scales) for fam in families]), axis=0)


def scale_study(
    duals=(2, 4, 6),
    sizes=range(3, 9),
    grid_points: int = 99,
    *,
    exact: bool = True,
) -> ScaleStudy:
    """Pentagon preservation's scale: the standard setting at every element, by scale
    and number of duals, and the scale this analysis recommends.

    The recommendation is made for the smallest number of duals at which
    the setting holds at every element for some scale (2): the scale that
    maximizes the smallest relative gap ``(|lambda2| - |lambda3|) /
    |lambda2|`` over vertices and faces of ``sizes`` -- the rate at which
    the rings around an element settle to the characteristic map's shape
    -- rounded to the simplest fraction within 0.01, and established
    exactly there (:func:`exact_ordering`, with ``exact``).

    Parameters
    ----------
    duals : iterable of int
    sizes : iterable of int
    grid_points : int
        Scales ``j / (grid_points + 1)``, ``j = 1 .. grid_points``.
    exact : bool
        Establish the thresholds and the recommended scale in exact arithmetic.

    Returns
    -------
    ScaleStudy
    """
    sizes = list(sizes)
    grid = tuple(Fraction(j, grid_points + 1) for j in range(1, grid_points + 1))
    g = np.array([float(x) for x in grid])
    fams: dict[tuple[int, str, int], ScaleFamily] = {}
    moduli, standard, thresholds = {}, {}, {}
    for d in duals:
        for kind in KINDS:
            for n in sizes:
                fam = scale_family(kind, n, d)
                key = (d, kind, n)
                fams[key] = fam
                mods, _ = fam.moduli_grid(g)
                moduli[key] = mods[:, 1:5]
                standard[key] = _standard_rows(mods)
                thresholds[key] = scale_threshold(fam, grid, exact=exact)
                if exact and thresholds[key].status == "never":
                    ex = fam.exact(REFERENCE_SCALE)
                    thresholds[key] = dataclasses.replace(
                        thresholds[key], exact_at={REFERENCE_SCALE: ex}
                    )
    # the recommendation: the fewest duals at which every element has a working scale
    ok_duals = [
        d
        for d in duals
        if all(thresholds[(d, kind, n)].status != "never" for kind in KINDS for n in sizes)
    ]
    rec_duals = min(ok_duals) if ok_duals else min(duals)
    family = [fams[(rec_duals, kind, n)] for kind in KINDS for n in sizes]
    coarse = np.round(np.arange(0.5, 0.995, 0.005), 3)
    best = float(coarse[int(np.argmax(_worst_gaps(family, coarse)))])
    lo, hi = max(best - 0.005, 1e-3), min(best + 0.005, 1 - 1e-3)
    for _ in range(40):  # golden-section refinement of max-min
        a, b = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        if _worst_gap(family, a)[0] < _worst_gap(family, b)[0]:
            lo = a
        else:
            hi = b
    optimum = (lo + hi) / 2
    recommended = _simplest_fraction(optimum, 0.01)
    gaps = {(fam.kind, fam.size): fam.gap(float(recommended)) for fam in family}
    worst, _ = _worst_gap(family, float(recommended))
    default, _ = _worst_gap(family, 0.75)
    exact_at = {}
    if exact:
        exact_at = {(fam.kind, fam.size): fam.exact(recommended) for fam in family}
    return ScaleStudy(
        grid=g,
        moduli=moduli,
        standard=standard,
        thresholds=thresholds,
        recommended=recommended,
        recommended_duals=rec_duals,
        optimum=optimum,
        gaps=gaps,
        worst_gap=worst,
        worst_gap_default=default,
        exact_at_recommended=exact_at,
        limiting=tuple(
            sorted(
                (k for k, v in gaps.items() if v <= worst * (1 + 0.05)),
                key=lambda k: gaps[k],
            )
        ),
    )


def _simplest_fraction(x: float, within: float) -> Fraction:
    """The fraction of smallest denominator within ``within`` of ``x``."""
    for den in range(1, 1000):
        num = round(x * den)
        if abs(num / den - x) <= within:
            return Fraction(num, den)
    return Fraction(x).limit_denominator(1000)  # pragma: no cover
