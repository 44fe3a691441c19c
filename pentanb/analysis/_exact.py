"""Exact rational algebra for the continuity analysis (private; ``fractions`` only).

The local subdivision matrices of every registered scheme have rational
entries (edge points at 1/2 or 1/3, centroids 1/n, a rational scale), so
what their eigenvalues do can be *established* rather than computed in
floating point:

* :func:`charpoly`: the characteristic polynomial of a rational matrix
  (Berkowitz's division-free algorithm on the integer matrix ``D M``);
* :func:`count_inside`: how many roots of a rational polynomial lie in the
  open disc ``|z| < rho`` (the Schur-Cohn test; Marden, *Geometry of
  Polynomials*, 1966, Ch. X), for a rational ``rho``;
* :func:`real_roots`: how many distinct real roots lie in ``(a, b]``
  (Sturm's theorem);
* :func:`gcd`, :func:`squarefree`: exact Euclid, with every remainder made a
  primitive integer polynomial so that the numbers stay small.

Polynomials are lists of :class:`~fractions.Fraction` (or ``int``),
coefficient of ``x**0`` first, without trailing zeros (``[]`` is the zero
polynomial).  No floating-point number enters any decision here.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from fractions import Fraction

__all__ = [
    "Poly",
    "trim",
    "degree",
    "evaluate",
    "derivative",
    "mul",
    "divmod_poly",
    "gcd",
    "squarefree",
    "primitive",
    "charpoly",
    "count_inside",
    "real_roots",
    "real_roots_in",
    "rational_root",
    "solve",
    "mat_mul",
]

Poly = list[Fraction]


def trim(p: Sequence) -> Poly:
    """``p`` as fractions without trailing zeros."""
    out = [Fraction(c) for c in p]
    while out and out[-1] == 0:
        out.pop()
    return out


def degree(p: Sequence) -> int:
    """Degree of ``p`` (-1 for the zero polynomial)."""
    return len(trim(p)) - 1


def evaluate(p: Sequence, x) -> Fraction:
    """``p(x)`` by Horner's rule (exact for rational ``x``)."""
    acc = Fraction(0)
    for c in reversed(p):
        acc = acc * x + c
    return acc


def derivative(p: Sequence) -> Poly:
    """``p'``."""
    return trim([i * Fraction(c) for i, c in enumerate(p)][1:])


def mul(p: Sequence, q: Sequence) -> Poly:
    """``p q``."""
    if not p or not q:
        return []
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        if a:
            for j, b in enumerate(q):
                out[i + j] += a * b
    return trim(out)


def primitive(p: Sequence) -> Poly:
    """``p`` times the positive rational that makes it a primitive integer polynomial
    (the same roots, and the same sign wherever it is evaluated)."""
    p = trim(p)
    if not p:
        return []
    den = 1
    for c in p:
        den = den * c.denominator // math.gcd(den, c.denominator)
    nums = [int(c * den) for c in p]
    g = 0
    for n in nums:
        g = math.gcd(g, n)
    return [Fraction(n // g) for n in nums]


def divmod_poly(p: Sequence, q: Sequence) -> tuple[Poly, Poly]:
    """Quotient and remainder of ``p / q`` (``q`` not zero)."""
    p, q = trim(p), trim(q)
    if not q:
        raise ZeroDivisionError("polynomial division by zero")
    r = list(p)
    dq = len(q) - 1
    quot = [Fraction(0)] * max(len(p) - dq, 0)
    lead = q[-1]
    while len(r) - 1 >= dq and r:
        shift = len(r) - 1 - dq
        c = r[-1] / lead
        quot[shift] = c
        for i, b in enumerate(q):
            r[shift + i] -= c * b
        r = trim(r)
    return trim(quot), r


def gcd(p: Sequence, q: Sequence) -> Poly:
    """The monic greatest common divisor of ``p`` and ``q`` (``[1]`` when coprime)."""
    a, b = primitive(p), primitive(q)
    while b:
        _, r = divmod_poly(a, b)
        a, b = b, primitive(r)
    if not a:
        return []
    return [c / a[-1] for c in a]


def squarefree(p: Sequence) -> Poly:
    """``p`` divided by ``gcd(p, p')``: the same roots, each simple."""
    p = trim(p)
    if len(p) <= 2:
        return p
    g = gcd(p, derivative(p))
    return trim(divmod_poly(p, g)[0]) if len(g) > 1 else p


def charpoly(matrix: Sequence[Sequence]) -> Poly:
    """The characteristic polynomial ``det(x I - M)`` of a square rational matrix.

    ``M = N / D`` with ``N`` an integer matrix (``D`` the common
    denominator); Berkowitz's division-free algorithm gives ``N``'s
    polynomial in integers, and ``p_M(x) = D**-n p_N(D x)``.

    Parameters
    ----------
    matrix : sequence of sequences of Fraction (or int)

    Returns
    -------
    list of Fraction
        Monic, of degree ``n``, coefficient of ``x**0`` first.
    """
    rows = [[Fraction(x) for x in row] for row in matrix]
    n = len(rows)
    if any(len(row) != n for row in rows):
        raise ValueError("charpoly needs a square matrix")
    if n == 0:
        return [Fraction(1)]
    den = 1
    for row in rows:
        for x in row:
            if x.denominator != 1:
                den = den * x.denominator // math.gcd(den, x.denominator)
    N = [[int(x * den) for x in row] for row in rows]
    high = _berkowitz(N)  # det(y I - N), highest coefficient first
    low = high[::-1]  # c_i: coefficient of y**i
    return trim([Fraction(c * den**i, den**n) for i, c in enumerate(low)])


def _berkowitz(A: list[list[int]]) -> list[int]:
    """Coefficients of ``det(x I - A)``, highest first, for an integer matrix (no division)."""
    N = len(A)
    transforms: list[list[list[int]]] = []
    M = [row[:] for row in A]
    for n in range(N, 1, -1):
        k = n - 1
        R = [-x for x in M[k][:k]]
        C = [M[i][k] for i in range(k)]
        a = -M[k][k]
        M = [row[:k] for row in M[:k]]
        items = [C]
        for _ in range(n - 2):
            v = items[-1]
            items.append([sum(M[i][j] * v[j] for j in range(k) if v[j]) for i in range(k)])
        scal = [1, a] + [sum(r * b for r, b in zip(R, vec) if r and b) for vec in items]
        T = [[0] * n for _ in range(n + 1)]
        for i in range(n):
            for r in range(i, n + 1):
                T[r][i] = scal[r - i]
        transforms.append(T)
    poly = [1, -M[0][0]]
    for T in reversed(transforms):
        poly = [sum(t * p for t, p in zip(row, poly) if t and p) for row in T]
    return poly


def count_inside(p: Sequence, rho) -> int | None:
    """How many roots of ``p`` (with multiplicity) lie in the open disc ``|z| < rho``.

    The Schur-Cohn test on ``p(rho z)``: with ``f_0 = p(rho z)`` of degree
    n and ``f_{j+1} = f_j(0) f_j - lead_j f_j^*`` (``f_j^*`` the reversal
    of ``f_j`` at its nominal degree ``n - j``), ``delta_j = f_j(0)``; when
    no ``delta_j`` vanishes, no root lies on the circle and the number
    inside is the number of negative products ``delta_1 ... delta_k``
    (the Schur-Cohn theorem; Marden 1966, Ch. X).  Exact for rational
    ``rho > 0``; checked against numpy's roots by the tests.

    Returns
    -------
    int or None
        None when a ``delta_j`` vanishes (a root on the circle, or a
        singular case): try another radius.
    """
    rho = Fraction(rho)
    if rho <= 0:
        raise ValueError("rho must be positive")
    p = trim(p)
    n = len(p) - 1
    if n < 0:
        raise ValueError("the zero polynomial has no count of roots")
    f = primitive([c * rho**i for i, c in enumerate(p)])
    negative = 0
    sign = 1
    for k in range(1, n + 1):
        m = n - k + 1  # nominal degree of f
        f = f + [Fraction(0)] * (m + 1 - len(f))
        a0, am = f[0], f[m]
        g = [a0 * f[i] - am * f[m - i] for i in range(m)]
        delta = g[0]
        if delta == 0:
            return None
        sign *= 1 if delta > 0 else -1
        if sign < 0:
            negative += 1
        f = primitive(g)
        if not f:  # pragma: no cover - delta != 0 keeps g non-zero
            return None
    return negative


def _sturm_chain(p: Poly) -> list[Poly]:
    chain = [primitive(p), primitive(derivative(p))]
    while chain[-1] and len(chain[-1]) > 1:
        _, r = divmod_poly(chain[-2], chain[-1])
        if not r:
            break
        chain.append(primitive([-c for c in r]))
    return [c for c in chain if c]


def _variations(chain: list[Poly], x: Fraction) -> int:
    signs = [s for s in (evaluate(q, x) for q in chain) if s != 0]
    return sum(1 for a, b in itertools.pairwise(signs) if (a > 0) != (b > 0))


def real_roots(p: Sequence, a, b) -> int:
    """The number of distinct real roots of ``p`` in ``(a, b]`` (Sturm's theorem).

    Parameters
    ----------
    p : polynomial, not zero
    a, b : rational, ``a < b``
    """
    return real_roots_in(p, [(a, b)])[0]


def real_roots_in(p: Sequence, intervals: Sequence[tuple]) -> list[int]:
    """:func:`real_roots` for several intervals ``(a, b]``, with one Sturm chain."""
    p = squarefree(p)
    if len(p) <= 1:
        return [0 for _ in intervals]
    chain = _sturm_chain(p)
    return [_variations(chain, Fraction(a)) - _variations(chain, Fraction(b)) for a, b in intervals]


def rational_root(p: Sequence, guess: float, max_den: int = 100_000) -> Fraction | None:
    """The rational root of ``p`` nearest ``guess`` with denominator at most ``max_den``,
    if there is one (checked exactly), else None."""
    if not math.isfinite(guess):
        return None
    x = Fraction(guess).limit_denominator(max_den)
    return x if evaluate(p, x) == 0 else None


def mat_mul(A: Sequence[Sequence], B: Sequence[Sequence]) -> list[list[Fraction]]:
    """The exact product of two rational matrices (lists of rows)."""
    cols = list(zip(*B)) if B else []
    return [
        [sum((a * b for a, b in zip(row, col) if a and b), Fraction(0)) for col in cols]
        for row in A
    ]


def solve(G: Sequence[Sequence], R: Sequence[Sequence]) -> list[list[Fraction]]:
    """``X`` with ``G X = R`` for an invertible rational ``G`` (Gauss-Jordan)."""
    n = len(G)
    M = [[Fraction(x) for x in G[i]] + [Fraction(x) for x in R[i]] for i in range(n)]
    width = len(M[0]) if M else 0
    for c in range(n):
        piv = next((r for r in range(c, n) if M[r][c] != 0), None)
        if piv is None:
            raise ZeroDivisionError("singular matrix")
        M[c], M[piv] = M[piv], M[c]
        inv = 1 / M[c][c]
        M[c] = [x * inv for x in M[c]]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c]
                Mr, Mc = M[r], M[c]
                M[r] = [x - f * y for x, y in zip(Mr, Mc)]
    return [row[n:width] for row in M]
