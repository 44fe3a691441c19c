"""Exact arithmetic: the ordering of the leading eigenvalues, established.

The weights are rational: :func:`exact_local_matrix` assembles the local
matrix in fractions, and :func:`exact_ordering` establishes the ordering of
its leading eigenvalues (the characteristic polynomial, split by Fourier
modes; Schur-Cohn counts of roots in discs of rational radius; Sturm counts
of real roots; exact gcds), as an :class:`ExactSpectrum`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from ... import schemes as _schemes
from ...mesh import Mesh
from .. import _exact
from .local import LocalSpectrum, _Context

__all__ = [
    "ExactSpectrum",
    "exact_local_matrix",
    "exact_ordering",
]

# ---------------------------------------------------------------------------
# exact arithmetic: the ordering of the leading eigenvalues, established
# ---------------------------------------------------------------------------


class _DualRows:
    """The dual's exact rows, on demand: row ``f`` is ``1/n`` at each corner of face ``f``
    (what :func:`~pentanb.analysis.subdivision_matrix.exact_dual_matrix` holds, without
    building every row)."""

    def __init__(self, mesh: Mesh):
        self.offsets = mesh.offsets
        self.corners = mesh.corners

    def row(self, f: int) -> dict[int, Fraction]:
        a, b = int(self.offsets[f]), int(self.offsets[f + 1])
        w = Fraction(1, b - a)
        out: dict[int, Fraction] = {}
        for c in self.corners[a:b].tolist():
            out[c] = out.get(c, Fraction(0)) + w
        return out


def _exact_step_factors(mesh: Mesh, scheme, duals: int, options: dict, exact_options: dict):
    """The exact matrices of one step (the remeshing, then each dual), in order."""
    from ..subdivision_matrix import exact_remesh_matrix

    out = scheme(mesh, **options)
    factors: list[Any] = [exact_remesh_matrix(mesh, scheme, out, **exact_options)]
    for _ in range(duals):
        factors.append(_DualRows(out))
        out = _schemes.dual(out)
    return factors


def _exact_options(options: dict, scale) -> dict:
    """The scheme's options with the scale as a fraction (``scale`` overriding)."""
    out = {k: (Fraction(v) if k == "scale" else v) for k, v in options.items()}
    if scale is not None:
        out["scale"] = Fraction(scale)
    return out


def exact_local_matrix(
    spectrum: LocalSpectrum, scale=None, *, core: bool = True
) -> list[list[Fraction]]:
    """The local subdivision matrix of one identification step, in exact arithmetic.

    The rules of the scheme with :class:`~fractions.Fraction` weights
    (:func:`pentanb.analysis.subdivision_matrix.exact_remesh_matrix`),
    composed over the steps from the spectrum's level to the level it is
    identified with, restricted to the neighbourhood.  Its rounding equals
    ``spectrum.matrix`` (checked by the tests); the rotation is not taken
    out (:func:`exact_ordering` does that).

    Parameters
    ----------
    spectrum : LocalSpectrum
        From :func:`local_spectrum` (with its search context: not a
        detached copy).
    scale : rational, optional
        Another scale for the same scheme (pentagon preservation and the
        other scaled rules): the neighbourhood's connectivity does not
        depend on the scale, its weights do (affinely, over one step).  Any
        rational is accepted, 0 and 1 included (the weights are polynomials
        in the scale).
    core : bool
        The smallest neighbourhood mapped onto itself (default), or the
        analysed one (a ring more).

    Returns
    -------
    list of lists of Fraction
        Square, rows and columns in the spectrum's order.

    Raises
    ------
    ValueError
        Without a search context, or for a scheme without rules.
    """
    ctx = spectrum._context
    if ctx is None:
        raise ValueError(
            "the spectrum has no search context (a detached copy): recompute it with local_spectrum"
        )
    p = ctx.steps_per_match
    steps = ctx.steps
    opts = _exact_options(ctx.options, scale)
    chain = []
    for j in range(ctx.level, ctx.level + p):
        chain += _exact_step_factors(steps[j].mesh, ctx.scheme, ctx.duals, ctx.options, opts)
    positions = ctx.core if core and ctx.core is not None else np.arange(ctx.domain.size)
    dom = [int(v) for v in ctx.domain[positions]]
    img = [int(v) for v in ctx.image[positions]]
    where = {v: i for i, v in enumerate(dom)}
    rows = []
    cache: list[dict[int, dict[int, Fraction]]] = [{} for _ in chain]
    for v in img:
        vec: dict[int, Fraction] = {v: Fraction(1)}
        for t in range(len(chain) - 1, -1, -1):
            F = chain[t]
            nxt: dict[int, Fraction] = {}
            for c, x in vec.items():
                r = cache[t].get(c)
                if r is None:
                    r = cache[t][c] = F.row(c)
                for col, w in r.items():
                    nxt[col] = nxt.get(col, Fraction(0)) + x * w
            vec = {c: x for c, x in nxt.items() if x != 0}
        outside = [c for c in vec if c not in where]
        if outside:
            raise RuntimeError(  # pragma: no cover - the float search checked closedness
                "the exact rows leave the neighbourhood: it is not closed"
            )
        row = [Fraction(0)] * len(dom)
        for c, x in vec.items():
            row[where[c]] = x
        rows.append(row)
    return rows


def _core_perm(ctx: _Context, positions) -> list[int] | None:
    """The turn by one sector on the given positions (indices into them), or None."""
    if ctx.perm is None:
        return None
    idx = {int(p): i for i, p in enumerate(positions)}
    out = []
    for p in positions:
        q = int(ctx.perm[int(p)])
        if q not in idx:
            return None
        out.append(idx[q])
    return out


def _period_matrix(spectrum: LocalSpectrum, A1: list[list[Fraction]], perm) -> list[list[Fraction]]:
    """The matrix of one period with the rotation taken out: ``Pi^a A^q``."""
    ctx = spectrum._context
    assert ctx is not None
    q = spectrum.period // ctx.steps_per_match
    A = A1
    for _ in range(q - 1):
        A = _exact.mat_mul(A, A1)
    a = spectrum.rotation % spectrum.size if perm is not None else 0
    if a:
        turn = list(range(len(A)))
        for _ in range(a):
            turn = [perm[t] for t in turn]
        A = [A[turn[i]] for i in range(len(A))]
    return A


def _cyclotomic(d: int) -> list[int]:
    """Coefficients of the cyclotomic polynomial Phi_d (lowest first)."""
    p = [-1] + [0] * (d - 1) + [1]  # x^d - 1
    for e in range(1, d):
        if d % e == 0:
            p = [int(c) for c in _exact.divmod_poly(p, _cyclotomic(e))[0]]
    return p


@dataclass(frozen=True)
class _Block:
    d: int  # the order of the turn on this invariant subspace
    modes: tuple[int, ...]  # the Fourier modes it holds
    matrix: list[list[Fraction]]


def _split(A: list[list[Fraction]], perm, k: int) -> list[_Block]:
    """``A`` restricted to the rational invariant subspaces ``ker Phi_d(Pi)``, ``d | k``.

    The turn ``Pi`` by one sector commutes with ``A``; on every orbit of
    ``k`` points, ``ker Phi_d(Pi)`` is spanned by the integer vectors
    ``Pi^t Psi_d(Pi) e`` (``Psi_d = (x^k - 1) / Phi_d``, ``t < phi(d)``);
    fixed points belong to d = 1.  Each restriction is a rational matrix
    whose eigenvalues are those of the Fourier modes ``w`` of order ``d``
    (``gcd(w, k) = k / d``).  Without a turn (or if ``A`` does not commute
    with it, checked exactly) there is one block, ``A`` itself.
    """
    n = len(A)
    whole = [_Block(1, tuple(range(k)), A)]
    if perm is None or n == 0:
        return whole
    if any(A[perm[i]][perm[j]] != A[i][j] for i in range(n) for j in range(n) if A[i][j]):
        return whole
    # integers: A = N / den
    den = 1
    for row in A:
        for x in row:
            if x.denominator != 1:
                den = den * x.denominator // math.gcd(den, x.denominator)
    N = [[int(x * den) for x in row] for row in A]
    seen = [False] * n
    orbits, fixed = [], []
    for i in range(n):
        if seen[i]:
            continue
        orb = [i]
        j = perm[i]
        while j != i:
            orb.append(j)
            j = perm[j]
        for j in orb:
            seen[j] = True
        if len(orb) == 1:
            fixed.append(i)
        elif len(orb) == k:
            orbits.append(orb)
        else:
            return whole
    blocks = []
    xk1 = [-1] + [0] * (k - 1) + [1]
    for d in range(1, k + 1):
        if k % d:
            continue
        cyc = _cyclotomic(d)
        psi = [int(c) for c in _exact.divmod_poly(xk1, cyc)[0]]
        phi = len(cyc) - 1
        cols: list[dict[int, int]] = []
        for orb in orbits:
            for t in range(phi):
                cols.append({orb[(i + t) % k]: c for i, c in enumerate(psi) if c})
        if d == 1:
            cols += [{f: 1} for f in fixed]
        if not cols:
            continue
        m = len(cols)
        NB = [[sum(N[r][i] * c for i, c in col.items()) for col in cols] for r in range(n)]
        BtNB = [[sum(NB[i][j] * c for i, c in col.items()) for j in range(m)] for col in cols]
        gram = [[sum(c * b.get(i, 0) for i, c in a.items()) for b in cols] for a in cols]
        M = _exact.solve(gram, [[Fraction(x, den) for x in row] for row in BtNB])
        # the subspace is invariant: N B == B (den M), exactly
        for j in range(m):
            for r in range(n):
                bm = sum(cols[t].get(r, 0) * M[t][j] for t in range(m) if M[t][j] and r in cols[t])
                if bm * den != NB[r][j]:  # pragma: no cover - guarded by the commuting check
                    return whole
        modes = tuple(w for w in range(k) if math.gcd(w, k) == k // d)
        blocks.append(_Block(d, modes, M))
    return blocks


@dataclass(frozen=True)
class ExactSpectrum:
    """The leading eigenvalues of a local matrix, established in exact arithmetic.

    The matrix is rational (:func:`exact_local_matrix`); its characteristic
    polynomial is computed exactly, split by the rational subspaces of the
    Fourier modes (:func:`_split`), and the eigenvalues are located by
    exact tests on it: the Schur-Cohn count of roots in a disc of rational
    radius, Sturm's count of real roots, and exact greatest common divisors
    (:mod:`pentanb.analysis._exact`).  Floating point only *suggests* the
    radii tried; every statement here is decided in rational arithmetic.

    Attributes
    ----------
    period : int
        Steps of the matrix analysed (eigenvalues over one period).
    scale : Fraction or None
        The scale the matrix was built with (schemes with a scale).
    size : int
        Vertices of the neighbourhood (the smallest one mapped onto itself).
    blocks : tuple of (d, modes, polynomial)
        The characteristic polynomial of each invariant subspace (``d`` the
        order of the turn on it, the Fourier modes it holds), coefficients
        lowest first; their product is the matrix's.
    unit_simple : bool
        1 is an eigenvalue (of mode 0) of multiplicity one.
    upper : Fraction or None
        Every other eigenvalue has modulus below ``upper`` (< 1).
    lower : Fraction or None
        Exactly ``group`` eigenvalues (with multiplicity) have modulus in
        ``[lower, upper)``; every other one has modulus below ``lower``.
    group : int
        The size of the leading group (0 when not established).
    equal : bool or None
        The group's moduli are equal (True), not all equal (False), or the
        tests could not tell (None).  True for a single eigenvalue.
    real : bool or None
        The group is real (a simple or multiple real root, or two opposite
        ones), a conjugate pair (False), or mixed / unknown (None).
    value : Fraction or None
        The group's eigenvalue over the period when it is rational.
    note : str
        What was established, in words (:meth:`describe`).
    """

    period: int
    scale: Fraction | None
    size: int
    blocks: tuple[tuple[int, tuple[int, ...], tuple[Fraction, ...]], ...]
    unit_simple: bool
    upper: Fraction | None
    lower: Fraction | None
    group: int
    equal: bool | None
    real: bool | None
    value: Fraction | None
    note: str = ""

    @property
    def decided(self) -> bool:
        """The leading group and the equality of its moduli were established."""
        return self.unit_simple and self.group > 0 and self.equal is not None

    @property
    def standard(self) -> bool:
        """``1 = lambda0`` simple ``> |lambda1| = |lambda2| > |lambda3|``, established exactly."""
        return self.unit_simple and self.group == 2 and self.equal is True

    @property
    def step_value(self) -> Fraction | None:
        """The group's eigenvalue per step when it is rational and its period-th root is too
        (e.g. ``17/120`` for ``(17/120)**2`` over two steps); else None."""
        v = self.value
        if v is None:
            return None
        if self.period == 1:
            return v
        if self.period == 2 and v >= 0:
            n, d = math.isqrt(v.numerator), math.isqrt(v.denominator)
            if n * n == v.numerator and d * d == v.denominator:
                return Fraction(n, d)
        return None

    def describe(self) -> str:
        """The established facts as one sentence.

        Returns
        -------
        str
        """
        if not self.unit_simple:
            return "exact: the eigenvalue 1 is not simple" + (
                f" ({self.note})" if self.note else ""
            )
        if not self.group or self.upper is None or self.lower is None:
            return f"exact: leading group not established ({self.note})"
        per = "" if self.period == 1 else f" over {self.period} steps"
        val = ""
        if self.value is not None:
            sv = self.step_value
            val = f" = {self.value}" + (
                f" = ({sv})^{self.period}" if sv is not None and self.period > 1 else ""
            )
        if self.group == 1:
            what = f"lambda1{val} is simple and real"
        elif self.equal is True:
            kind = {
                True: "a real eigenvalue",
                False: "a complex-conjugate pair",
                None: "eigenvalues",
            }[self.real]
            mult = "" if self.real is False else f" of multiplicity {self.group}"
            what = f"|lambda1| = ... = |lambda{self.group}|: {kind}{mult}{val}"
        elif self.equal is False:
            what = f"{self.group} eigenvalues of unequal moduli"
        else:
            what = f"{self.group} eigenvalues, equality of moduli not decided"
        return (
            f"exact{per}: 1 simple; {what}, modulus in [{self.lower}, {self.upper}); "
            f"every other eigenvalue below {self.lower}"
        )


def _radius_between(a: float, b: float) -> Fraction:
    """A simple rational strictly between two moduli ``a > b`` (or just below ``a``)."""
    mid = (a + b) / 2 if b >= 0 else a / 2
    gap = (a - b) / 4 if b >= 0 else a / 4
    for den in (10, 100, 1000, 10**4, 10**6, 10**9, 10**12):
        r = Fraction(mid).limit_denominator(den)
        if abs(float(r) - mid) < gap:
            return r
    return Fraction(mid)


def _count(polys: list[list[Fraction]], rho: Fraction) -> int | None:
    total = 0
    for p in polys:
        c = _exact.count_inside(p, rho)
        if c is None:
            return None
        total += c
    return total


def _nudged_count(polys, rho: Fraction, lo: float, hi: float) -> tuple[int, Fraction] | None:
    """Root count inside ``rho``, moving ``rho`` within ``(lo, hi)`` if a root lies on it."""
    for j in range(12):
        if j:
            t = Fraction(j, 13)
            rho = Fraction(lo) + (Fraction(hi) - Fraction(lo)) * t
        c = _count(polys, rho)
        if c is not None:
            return c, rho
    return None


def exact_ordering(spectrum: LocalSpectrum, scale=None) -> ExactSpectrum:
    """Establish the leading eigenvalues of a local matrix in exact arithmetic.

    The matrix of one period with the rotation taken out (as
    :func:`local_spectrum` analyses it), on the smallest neighbourhood
    mapped onto itself, built exactly (:func:`exact_local_matrix`); then, with
    its characteristic polynomial split by Fourier modes:

    * 1 is a root of multiplicity one (of mode 0);
    * every other root has modulus below a rational ``upper < 1``
      (Schur-Cohn);
    * exactly ``group`` roots have modulus in ``[lower, upper)``, all the
      others below ``lower`` (Schur-Cohn at both radii);
    * their moduli are equal: one real root of multiplicity ``group``
      (a common root of the blocks, found by exact gcds), or a pair of
      non-real roots of one real polynomial (Sturm: no real root in the
      annulus), which are conjugates.

    Parameters
    ----------
    spectrum : LocalSpectrum
        With its search context (from :func:`local_spectrum`).
    scale : rational, optional
        Another scale of the same scheme (see :func:`exact_local_matrix`).

    Returns
    -------
    ExactSpectrum
        ``standard`` is the exact counterpart of :attr:`LocalSpectrum.standard`.
    """
    ctx = spectrum._context
    if ctx is None or not spectrum.stationary:
        raise ValueError("exact_ordering needs a stationary spectrum with its search context")
    positions = ctx.core if ctx.core is not None else np.arange(ctx.domain.size)
    perm = _core_perm(ctx, positions)
    A1 = exact_local_matrix(spectrum, scale)
    A = _period_matrix(spectrum, A1, perm)
    return _certify(A, perm, spectrum.size, spectrum.period, _scale_of(ctx, scale))


def _scale_of(ctx: _Context, scale) -> Fraction | None:
    if scale is not None:
        return Fraction(scale)
    s = ctx.options.get("scale")
    return Fraction(s) if s is not None else None


def _certify(A, perm, k: int, period: int, scale: Fraction | None) -> ExactSpectrum:
    blocks = _split(A, perm, k)
    polys = [_exact.charpoly(b.matrix) for b in blocks]
    info = tuple((b.d, b.modes, tuple(p)) for b, p in zip(blocks, polys))
    common: dict[str, Any] = dict(period=period, scale=scale, size=len(A), blocks=info)
    # the eigenvalue 1: a simple root, of the block of mode 0 only
    ones = [_multiplicity_at_one(p) for p in polys]
    unit_simple = sum(ones) == 1 and blocks[0].d == 1 and ones[0] == 1
    if not unit_simple:
        return ExactSpectrum(
            **common,
            unit_simple=False,
            upper=None,
            lower=None,
            group=0,
            equal=None,
            real=None,
            value=None,
            note=f"multiplicity of 1: {sum(ones)}",
        )
    reduced = [list(p) for p in polys]
    reduced[0] = _exact.divmod_poly(reduced[0], [Fraction(-1), Fraction(1)])[0]
    # floating point suggests the radii; the counts decide
    floats = []
    for b in blocks:
        M = (
            np.array([[float(x) for x in row] for row in b.matrix])
            if b.matrix
            else np.zeros((0, 0))
        )
        w = np.linalg.eigvals(M) if M.size else np.zeros(0)
        floats.append(w)
    allw = np.concatenate(floats) if floats else np.zeros(0)
    # drop the eigenvalue 1 (the closest to 1 of mode 0)
    if allw.size:
        j = int(np.argmin(np.abs(floats[0] - 1.0)))
        floats[0] = np.delete(floats[0], j)
        allw = np.concatenate(floats)
    mods = np.sort(np.abs(allw))[::-1]
    n_rest = sum(len(p) - 1 for p in reduced)
    if n_rest == 0:
        return ExactSpectrum(
            **common,
            unit_simple=True,
            upper=None,
            lower=None,
            group=0,
            equal=None,
            real=None,
            value=None,
            note="no eigenvalue besides 1",
        )
    m1 = float(mods[0])
    guess = int(np.sum(np.abs(mods - m1) <= 1e-7 * max(m1, 1e-300)))
    nxt = float(mods[guess]) if guess < mods.size else -1.0
    up = _nudged_count(reduced, _radius_between(1.0, m1), m1, 1.0)
    low = _nudged_count(reduced, _radius_between(m1, nxt), max(nxt, 0.0), m1) if m1 > 0 else None
    if up is None or low is None or up[0] != n_rest:
        return ExactSpectrum(
            **common,
            unit_simple=True,
            upper=None,
            lower=None,
            group=0,
            equal=None,
            real=None,
            value=None,
            note="the radii could not separate the moduli",
        )
    upper, lower = up[1], low[1]
    group = n_rest - low[0]
    try:
        equal, real, value = _group_equal(reduced, lower, upper, floats, m1)
    except _Undecided:
        equal, real, value = None, None, None
    return ExactSpectrum(
        **common,
        unit_simple=True,
        upper=upper,
        lower=lower,
        group=group,
        equal=equal,
        real=real,
        value=value,
    )


def _multiplicity_at_one(p) -> int:
    m = 0
    q = list(p)
    while q and _exact.evaluate(q, 1) == 0:
        q = _exact.divmod_poly(q, [Fraction(-1), Fraction(1)])[0]
        m += 1
    return m


class _Undecided(Exception):
    """A Schur-Cohn count hit a singular case: the equality of moduli is left undecided."""


def _in_annulus(p, lower: Fraction, upper: Fraction) -> int:
    """Roots of ``p`` with modulus in ``[lower, upper)`` (the radii free of roots)."""
    hi, lo = _exact.count_inside(p, upper), _exact.count_inside(p, lower)
    if hi is None or lo is None:  # a singular case of the test, not a root on the circle
        raise _Undecided
    return hi - lo


def _group_equal(polys, lower: Fraction, upper: Fraction, floats, m1: float):
    """Are the moduli of the roots in ``[lower, upper)`` equal?  (equal, real, value)."""
    inside = []  # (poly, roots with multiplicity, its float eigenvalues)
    for p, w in zip(polys, floats):
        # the floats only choose which polynomials to test; the counts decide
        near = np.abs(np.abs(w) - m1) <= 1e-6 * max(m1, 1e-300) if len(w) else np.zeros(0, bool)
        if not near.any() and len(w) and np.abs(w).max() < float(lower):
            continue
        c = _in_annulus(p, lower, upper)
        if c:
            inside.append((p, c, w))
    total = sum(c for _, c, _ in inside)
    if total == 1:
        p, _, w = inside[0]
        return True, True, _rational_value(p, w, m1)
    annulus = [(lower, upper), (-upper, -lower)]
    if len(inside) == 1:
        p, c, w = inside[0]
        sq = _exact.squarefree(p)
        dc = _in_annulus(sq, lower, upper)
        if dc == 1:  # one distinct root of multiplicity c: real (a non-real one has its conjugate)
            return True, True, _rational_value(p, w, m1)
        if dc == 2 and c == 2:
            if sum(_exact.real_roots_in(sq, annulus)) == 0:
                return True, False, None  # two non-real roots of a real polynomial: conjugates
            mirror = [x * (-1) ** i for i, x in enumerate(sq)]
            g = _exact.gcd(sq, mirror)
            if len(g) > 1 and sum(_exact.real_roots_in(g, annulus)) > 0:
                return True, True, None  # alpha and -alpha
            return False, True, None
        return None, None, None
    # several blocks: one common real root carries the whole group
    sqs = [_exact.squarefree(p) for p, _, _ in inside]
    if all(_in_annulus(q, lower, upper) == 1 for q in sqs):
        g = sqs[0]
        for q in sqs[1:]:
            g = _exact.gcd(g, q)
        if len(g) > 1 and sum(_exact.real_roots_in(g, annulus)) > 0:
            return True, True, _rational_value(inside[0][0], inside[0][2], m1)
        return False, True, None
    return None, None, None


def _rational_value(p, w, m1: float) -> Fraction | None:
    """The leading real root of ``p`` when it is rational (exact check), else None."""
    if len(w) == 0:
        return None
    j = int(np.argmin(np.abs(np.abs(w) - m1)))
    return _exact.rational_root(p, float(np.real(w[j])))
