"""The boundary curve of an open mesh: its own subdivision rule and spectrum.

On an open mesh every scheme of :data:`pentanb.SCHEMES` and the dual place
the new boundary points from the old boundary points alone (edge points on
boundary edges, midpoints of boundary edges; see
:mod:`pentanb.schemes.smoothing`).  Then the boundary polygon is refined by
a *curve* subdivision scheme of its own, whatever the surface does inside,
and that scheme decides whether the boundary curve is smooth.

:func:`boundary_spectrum` reads that rule from the subdivision matrix of
one step ("remesh, then the duals") on an open test mesh (by default an
annulus of quads and triangles whose boundary has no corner):

1. the **decoupling**: the block of the matrix from the old interior
   vertices to the new boundary vertices is zero;
2. the **arity** r: every boundary loop of n edges becomes one of r n;
3. the **mask** ``a``: ``q_i = sum_j a[i - r j] p_j`` for the old boundary
   points p and the new ones q, read from the matrix, and checked to hold
   at every point of every loop (a *uniform* rule, the same whatever the
   faces inside);
4. the **local subdivision matrix** around the point that the refinement
   keeps fixed (a vertex of the boundary for a symmetric mask of odd
   length): the control points whose basic functions do not vanish near
   it; its eigenvalues, in exact arithmetic where they are rational;
5. whether the curve is **C1** there: 1 is a simple eigenvalue, a single
   real subdominant ``lambda1 > 0`` with every other eigenvalue smaller in
   modulus, and a regular characteristic map (for a curve: the
   ``lambda1``-eigenvector's entries strictly increase along the boundary);
   and, since the rule is uniform, C1 everywhere along the boundary by the
   difference-scheme test (Dyn, *Subdivision schemes in CAGD*, 1992): the
   mask's symbol divisible by ``(1 + z + ... + z^(r-1))**2`` and the scheme
   of the quotient, times r, contractive.

Corners (boundary vertices of one face where the boundary turns by more
than 30 degrees) are kept where they are by every scheme that makes a face
of every vertex; the rule read here is that of a boundary without corners.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .. import _checks
from .. import schemes as _schemes
from ..mesh import Mesh, MeshError
from ..subdivision import get_scheme
from . import _exact
from .subdivision_matrix import exact_dual_matrix, exact_remesh_matrix, subdivision_matrix

__all__ = [
    "BoundarySpectrum",
    "boundary_spectrum",
    "boundary_test_mesh",
    "boundary_table",
    "BoundaryRow",
    "boundary_markdown",
]

#: Most iterations of the difference scheme tried by the C1 test.
MAX_DIFFERENCE_STEPS = 8


def boundary_test_mesh(n: int = 24) -> Mesh:
    """The open mesh the boundary rule is read on: a ring of n quads and triangles.

    Two circles of n vertices (radii 1 and 2, the outer lifted a little),
    joined by quads, four of them split into two triangles, so that the
    boundary's vertices have one, two and three faces; two boundary loops
    of n edges, turning by ``360 / n`` degrees at every vertex (no corner
    for ``n >= 13``).

    Parameters
    ----------
    n : int
        Vertices on each circle, at least 13.

    Returns
    -------
    Mesh
        2 n vertices, n + 4 faces.
    """
    n = _checks.count(n, "n", 13, 100_000)
    t = 2 * np.pi * np.arange(n) / n
    inner = np.stack([np.cos(t), np.sin(t), np.zeros(n)], axis=1)
    outer = np.stack([2 * np.cos(t), 2 * np.sin(t), np.full(n, 0.3)], axis=1)
    faces: list[list[int]] = []
    for i in range(n):
        a, b, c, d = i, (i + 1) % n, n + (i + 1) % n, n + i
        if i % 6 == 0 and i < 24:
            faces += [[a, b, c], [a, c, d]] if i % 12 == 0 else [[a, b, d], [b, c, d]]
        else:
            faces.append([a, b, c, d])
    return Mesh(np.concatenate([inner, outer]), faces)


@dataclass(frozen=True)
class BoundarySpectrum:
    """The boundary curve's own subdivision rule and its spectrum (:func:`boundary_spectrum`).

    Attributes
    ----------
    scheme : str
    duals : int
    options : dict
    decoupled : bool
        New boundary positions depend on old boundary positions only.
    arity : int
        r: a boundary loop of n edges becomes one of r n (0 when the loops
        do not scale so, or the boundary does not decouple).
    uniform : bool
        One mask gives every new boundary point of every loop.
    mask : tuple of Fraction
        ``a[mask_start], a[mask_start + 1], ...``: ``q_i = sum_j a[i - r j] p_j``.
        Empty when there is no uniform rule.
    mask_start : int
        The index of the mask's first weight, chosen so that the mask is
        centred on 0 (``mask_start + mask_end`` is 0 or 1).
    centre : str
        Where the point kept fixed by the refinement lies: ``"vertex"``,
        ``"edge midpoint"`` or a fraction of an edge.
    window : tuple of int
        The control points (relative indices j) of the local matrix.
    local_matrix : list of list of Fraction
        ``L[a][b] = mask[window[a] - r window[b]]``.
    eigenvalues : (m,) complex
        Of the local matrix, by decreasing modulus.
    exact : dict
        What was established in exact arithmetic: ``"lambda1"`` (Fraction
        or None), ``"one_simple"``, ``"others_below"`` (bool or None).
    eigenvector : (m,) float
        The ``lambda1``-eigenvector (the characteristic map of a curve),
        scaled so that its last entry minus its first is positive; empty
        when there is none.
    difference_steps : int or None
        The L at which the L-fold difference scheme contracts (C1 of the
        uniform rule everywhere, Dyn's test); None when it does not within
        :data:`MAX_DIFFERENCE_STEPS` or the mask is not divisible.
    is_c1 : bool
    reason : str
        Why (or why not), in words.
    """

    scheme: str
    duals: int
    options: dict
    decoupled: bool
    arity: int = 0
    uniform: bool = False
    mask: tuple[Fraction, ...] = ()
    mask_start: int = 0
    centre: str = ""
    window: tuple[int, ...] = ()
    local_matrix: list[list[Fraction]] = field(default_factory=list, repr=False)
    eigenvalues: NDArray[np.complex128] = field(
        default_factory=lambda: np.zeros(0, dtype=complex), repr=False
    )
    exact: dict = field(default_factory=dict, repr=False)
    eigenvector: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0), repr=False)
    difference_steps: int | None = None
    is_c1: bool = False
    reason: str = ""

    @property
    def mask_text(self) -> str:
        """The mask as ``(1, 4, 6, 4, 1) / 8`` (its weights over their common denominator)."""
        if not self.mask:
            return "-"
        den = math.lcm(*(w.denominator for w in self.mask))
        return "(" + ", ".join(str(int(w * den)) for w in self.mask) + f") / {den}"

    @property
    def eigenvalue_text(self) -> str:
        """The eigenvalues, exact where the characteristic polynomial has them rational."""
        if not self.local_matrix:
            return "-"
        p = _exact.charpoly(self.local_matrix)
        out = []
        for z in self.eigenvalues:
            if abs(z.imag) <= 1e-12 and (x := _exact.rational_root(p, z.real, 10_000)) is not None:
                out.append(str(x))
            else:
                out.append(f"{z.real:.4f}" if abs(z.imag) <= 1e-12 else f"{z:.4f}")
        return ", ".join(out)

    def summary(self) -> str:
        """One line: scheme, arity, mask, eigenvalues and the verdict.

        Returns
        -------
        str
        """
        head = f"{self.scheme} + {self.duals} duals, boundary"
        if not self.mask:
            return f"{head}: {self.reason}"
        return (
            f"{head}: arity {self.arity}, mask {self.mask_text}, eigenvalues "
            f"{self.eigenvalue_text}; {'C1' if self.is_c1 else 'not C1'}: {self.reason}"
        )


# ---------------------------------------------------------------------------
# reading the rule from the matrix
# ---------------------------------------------------------------------------


def _loop_vertices(mesh: Mesh) -> list[np.ndarray]:
    return [np.asarray(mesh.corners[h], dtype=np.int64) for h in mesh.boundary_loops]


def _exact_rows(mesh: Mesh, scheme, duals: int, options: dict, rows) -> list[dict[int, Fraction]]:
    """Rows ``rows`` of one step's matrix, in exact arithmetic (sparse products row by row)."""
    exact_options = {k: (Fraction(v) if k == "scale" else v) for k, v in options.items()}
    out = scheme(mesh, **options)
    factors = [exact_remesh_matrix(mesh, scheme, out, **exact_options)]
    for _ in range(duals):
        factors.append(exact_dual_matrix(out))
        out = _schemes.dual(out)
    result = []
    for i in rows:
        vec: dict[int, Fraction] = {int(i): Fraction(1)}
        for M in reversed(factors):
            nxt: dict[int, Fraction] = {}
            for k, w in vec.items():
                for c, x in M.row(k).items():
                    nxt[c] = nxt.get(c, Fraction(0)) + w * x
            vec = {c: x for c, x in nxt.items() if x != 0}
        result.append(vec)
    return result


def _unwrap(j: int, ref: int, n: int) -> int:
    """``j - ref`` on a loop of n, in ``(-n/2, n/2]``."""
    d = (j - ref) % n
    return d - n if d > n // 2 else d


def _read_mask(rows: list[dict[int, Fraction]], old: np.ndarray, r: int):
    """The mask of the rule ``rows`` (new loop, in order) follow on ``old`` (old loop, in order).

    Returns ``(mask dict k -> weight, uniform)``: the mask read from the first r
    rows, then checked on every row (the rule shifted by one old point every r
    new ones).
    """
    n = old.size
    where = {int(v): i for i, v in enumerate(old.tolist())}
    local = [{where[c]: w for c, w in row.items()} for row in rows]
    ref = max(local[0], key=lambda c: (local[0][c], -c))
    mask: dict[int, Fraction] = {}
    for i in range(r):
        for j, w in local[i].items():
            mask[i - r * _unwrap(j, ref, n)] = w
    for i, row in enumerate(local):
        t, rho = divmod(i, r)
        want = {(ref + t + (rho - k) // r) % n: w for k, w in mask.items() if (rho - k) % r == 0}
        if row != want:
            return mask, False
    return mask, True


def boundary_spectrum(
    scheme="pentagonalize", duals: int = 2, *, mesh: Mesh | None = None, **options
) -> BoundarySpectrum:
    """The boundary curve's own subdivision rule under ``scheme`` + duals, and its spectrum.

    Parameters
    ----------
    scheme : str or Scheme
        A registered scheme (or a Conway string :func:`pentanb.subdivide`
        takes, or a callable: its matrix is then probed).
    duals : int
        Duals after every remeshing.
    mesh : Mesh, optional
        The open mesh to read the rule on; its boundary should have no
        corner.  Default :func:`boundary_test_mesh`.
    **options
        The scheme's options (``scale=...``).

    Returns
    -------
    BoundarySpectrum
        With ``decoupled``, ``arity``, ``mask``, ``eigenvalues``, ``is_c1``
        and ``reason``; a scheme whose boundary does not decouple, is not
        refined (arity 1: the polygon keeps its number of points and is
        only averaged) or follows no uniform rule gets a result that says
        so, with an empty mask.

    Raises
    ------
    MeshError
        When ``mesh`` is closed.
    """
    s = get_scheme(scheme)
    name = str(getattr(s, "name", getattr(s, "__name__", repr(s))))
    mesh = boundary_test_mesh() if mesh is None else mesh
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh must be a pentanb.Mesh, got {type(mesh).__name__}")
    if mesh.is_closed:
        raise MeshError("boundary_spectrum needs an open mesh (one with a boundary)")
    S, out = subdivision_matrix(mesh, s, 1, duals, **options)
    base: dict[str, Any] = {"scheme": name, "duals": int(duals), "options": dict(options)}
    old_loops, new_loops = _loop_vertices(mesh), _loop_vertices(out)
    on_boundary = np.zeros(mesh.n_vertices, dtype=bool)
    on_boundary[np.concatenate(old_loops)] = True
    new_b = np.concatenate(new_loops) if new_loops else np.zeros(0, dtype=np.int64)
    leak = S[new_b][:, ~on_boundary]
    if leak.nnz:
        return BoundarySpectrum(
            **base,
            decoupled=False,
            reason=(
                "the boundary does not decouple: new boundary points lean on interior "
                f"vertices (weights up to {abs(leak).max():.3g}), so it is no curve scheme "
                "of its own"
            ),
        )
    sizes = sorted(v.size for v in old_loops), sorted(v.size for v in new_loops)
    ratios = {b // a if b % a == 0 else 0 for a, b in zip(*sizes)}
    r = ratios.pop() if len(ratios) == 1 and len(sizes[0]) == len(sizes[1]) else 0
    if r == 0:
        return BoundarySpectrum(
            **base,
            decoupled=True,
            reason=f"the boundary loops of {sizes[0]} edges become loops of {sizes[1]}: "
            "no uniform arity",
        )
    if r == 1:
        kept = all(row.nnz == 1 for row in S[new_b])
        what = (
            "kept as it is"
            if kept
            else "only averaged, so that repeated steps draw every loop towards its centroid"
        )
        return BoundarySpectrum(
            **base,
            decoupled=True,
            arity=1,
            reason="the boundary is not refined: every loop keeps its number of points, "
            f"{what}; no curve subdivision scheme",
        )
    masks = []
    for new in new_loops:
        rows = _exact_rows(mesh, s, duals, options, new.tolist())
        cols = set().union(*(set(row) for row in rows))
        old = next((o for o in old_loops if cols <= set(o.tolist())), None)
        mask, uniform = _read_mask(rows, old, r) if old is not None else ({}, False)
        if not uniform:
            return BoundarySpectrum(
                **base,
                decoupled=True,
                arity=r,
                reason="the boundary rule differs from point to point: no uniform mask",
            )
        masks.append(mask)
    k0, k1 = min(masks[0]), max(masks[0])
    shift = (k0 + k1) // 2  # centre the mask: k0 + k1 in {0, 1}
    mask = {k - shift: w for k, w in masks[0].items()}
    for other in masks[1:]:  # every loop follows the same rule, up to a relabelling
        o0, o1 = min(other), max(other)
        if {k - (o0 + o1) // 2: w for k, w in other.items()} != mask:
            return BoundarySpectrum(
                **base,
                decoupled=True,
                arity=r,
                reason="the loops follow different rules: no uniform mask",
            )
    return _analyse(base, r, mask)


# ---------------------------------------------------------------------------
# the curve scheme's analysis
# ---------------------------------------------------------------------------


def _centre(k0: int, k1: int, r: int) -> str:
    c = Fraction(k0 + k1, 2 * (r - 1))
    c -= math.floor(c)
    if c == 0:
        return "vertex"
    if c == Fraction(1, 2):
        return "edge midpoint"
    return f"{c} of an edge from a vertex"


def _nullvector(A: list[list[Fraction]], lam: Fraction) -> list[Fraction] | None:
    """A non-zero x with (A - lam I) x = 0, exactly (None when the kernel is not one line)."""
    n = len(A)
    M = [[A[i][j] - (lam if i == j else 0) for j in range(n)] for i in range(n)]
    pivots: list[int] = []
    row = 0
    for c in range(n):
        piv = next((i for i in range(row, n) if M[i][c] != 0), None)
        if piv is None:
            continue
        M[row], M[piv] = M[piv], M[row]
        inv = 1 / M[row][c]
        M[row] = [x * inv for x in M[row]]
        for i in range(n):
            if i != row and M[i][c] != 0:
                f = M[i][c]
                M[i] = [x - f * y for x, y in zip(M[i], M[row])]
        pivots.append(c)
        row += 1
    free = [c for c in range(n) if c not in pivots]
    if len(free) != 1:
        return None
    x = [Fraction(0)] * n
    x[free[0]] = Fraction(1)
    for i, c in enumerate(pivots):
        x[c] = -M[i][free[0]]
    return x


def _difference_steps(mask: dict[int, Fraction], r: int) -> int | None:
    """The least L <= MAX_DIFFERENCE_STEPS with the L-fold scheme of ``r a / sigma^2``
    contractive (sup-norm < 1), sigma = 1 + z + ... + z^(r-1); None if none (or not divisible)."""
    k0 = min(mask)
    a = [mask.get(k, Fraction(0)) for k in range(k0, max(mask) + 1)]
    sigma = [Fraction(1)] * r
    q, rem = _exact.divmod_poly(a, sigma)
    if rem:
        return None
    q, rem = _exact.divmod_poly(q, sigma)
    if rem:
        return None
    q = [r * c for c in q]
    power = q
    for L in range(1, MAX_DIFFERENCE_STEPS + 1):
        step = r**L
        norm = max(sum(abs(c) for c in power[rho::step]) for rho in range(step))
        if norm < 1:
            return L
        spread = [Fraction(0)] * ((len(q) - 1) * step + 1)
        spread[::step] = q
        power = _exact.mul(power, spread)
    return None


def _analyse(base: dict, r: int, mask: dict[int, Fraction]) -> BoundarySpectrum:
    k0, k1 = min(mask), max(mask)
    # control points whose basic function (support [j + k0/(r-1), j + k1/(r-1)]) meets 0
    lo, hi = -math.floor(Fraction(k1, r - 1)), math.floor(Fraction(-k0, r - 1))
    window = tuple(range(lo, hi + 1))
    # (the window is mapped into itself: row i in it leans on columns j in it only)
    assert all(
        lo <= j <= hi
        for i in window
        for j in range(lo - 2 * r, hi + 2 * r + 1)
        if mask.get(i - r * j, 0)
    )
    L = [[mask.get(i - r * j, Fraction(0)) for j in window] for i in window]
    vals = np.linalg.eigvals(np.array([[float(x) for x in row] for row in L]))
    vals = vals[np.lexsort((-vals.real, -np.round(np.abs(vals), 12)))]
    p = _exact.charpoly(L)
    one_simple = _exact.evaluate(p, 1) == 0 and _exact.evaluate(_exact.derivative(p), 1) != 0
    exact: dict = {"one_simple": one_simple, "lambda1": None, "others_below": None}
    common: dict[str, Any] = dict(
        base,
        decoupled=True,
        arity=r,
        uniform=True,
        mask=tuple(mask.get(k, Fraction(0)) for k in range(k0, k1 + 1)),
        mask_start=k0,
        centre=_centre(k0, k1, r),
        window=window,
        local_matrix=L,
        eigenvalues=vals.astype(complex),
        difference_steps=_difference_steps(mask, r),
    )
    if not one_simple:
        return BoundarySpectrum(
            **common, exact=exact, reason="1 is not a simple eigenvalue: the rule does not converge"
        )
    lam1 = vals[1] if vals.size > 1 else 0j
    lam = None
    if abs(lam1.imag) <= 1e-12 and lam1.real > 0:
        lam = _exact.rational_root(p, lam1.real, 1_000_000)
    if lam is None:
        return BoundarySpectrum(
            **common,
            exact=exact,
            reason=f"the subdominant eigenvalue {lam1:.4g} is not a positive rational "
            "(complex, negative or irrational): not the standard setting of a C1 curve",
        )
    exact["lambda1"] = lam
    rest, remainder = _exact.divmod_poly(p, _exact.mul([-1, 1], [-lam, 1]))
    assert not remainder  # 1 and lam are roots, distinct
    inside = _exact.count_inside(rest, lam) if _exact.degree(rest) > 0 else 0
    below = inside == _exact.degree(rest) if inside is not None else False
    exact["others_below"] = below
    x = _nullvector(L, lam)
    if x is not None and x[-1] < x[0]:
        x = [-c for c in x]
    vec = np.array([float(c) for c in x]) if x is not None else np.zeros(0)
    monotone = x is not None and all(b > a for a, b in itertools.pairwise(x))
    steps = common["difference_steps"]
    if not below:
        why = f"another eigenvalue is as large as lambda1 = {lam} in modulus"
        ok = False
    elif not monotone:
        why = f"the eigenvector of lambda1 = {lam} is not monotone: no regular characteristic map"
        ok = False
    elif steps is None:
        why = (
            f"lambda1 = {lam} is the single subdominant eigenvalue and its eigenvector is "
            "monotone, but the difference scheme is not shown contractive: undecided"
        )
        ok = False
    else:
        why = (
            f"1 simple, lambda1 = {lam} single and real, every other eigenvalue smaller, a "
            f"monotone eigenvector (regular characteristic map); the difference scheme "
            f"contracts in {steps} step{'s' if steps > 1 else ''} (C1 everywhere)"
        )
        ok = True
    return BoundarySpectrum(**common, exact=exact, eigenvector=vec, is_c1=ok, reason=why)


# ---------------------------------------------------------------------------
# the table: boundary beside interior
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class BoundaryRow:
    """One row of :func:`boundary_table`: a scheme's boundary rule beside its interior spectra.

    Attributes
    ----------
    boundary : BoundarySpectrum
    interior : dict
        ``"vertex 3"`` (and so on) -> the leading eigenvalue moduli
        ``(1, |lambda1|, |lambda2|, ...)`` of the local matrix there
        (:func:`pentanb.analysis.local_spectrum`), as a tuple of floats.
    """

    boundary: BoundarySpectrum
    interior: dict


def boundary_table(
    schemes: Sequence[str] = ("pentagonalize", "preserve_pentagons"),
    duals: int = 2,
    interior: Sequence[tuple[str, int]] = (("vertex", 3), ("vertex", 4)),
) -> list[BoundaryRow]:
    """The boundary rule of every scheme beside the interior spectra at some elements.

    Parameters
    ----------
    schemes : sequence of str
        Default: the paper's two schemes.
    duals : int
    interior : sequence of (kind, size)
        The interior elements whose spectra stand beside the boundary's
        (default: 3- and 4-valent vertices, those of the pentagonal meshes).

    Returns
    -------
    list of BoundaryRow
    """
    from .spectral import local_spectrum

    rows = []
    for name in schemes:
        inner = {}
        for kind, size in interior:
            spec = local_spectrum(name, kind, size, duals=duals)
            inner[f"{kind} {size}"] = tuple(float(x) for x in spec.moduli[:4])
        rows.append(BoundaryRow(boundary_spectrum(name, duals), inner))
    return rows


def boundary_markdown(rows: Sequence[BoundaryRow]) -> str:
    """A markdown table of :func:`boundary_table`'s rows.

    Parameters
    ----------
    rows : sequence of BoundaryRow

    Returns
    -------
    str
    """
    labels = list(rows[0].interior) if rows else []
    head = "| scheme | boundary mask | boundary eigenvalues | boundary C1 |"
    head += "".join(f" interior {x}: 1, abs lambda1.. |" for x in labels)
    lines = [head, "|" + " --- |" * (4 + len(labels))]
    for row in rows:
        b = row.boundary
        cells = [
            f"{b.scheme} + {b.duals} duals",
            b.mask_text,
            b.eigenvalue_text,
            ("yes" if b.is_c1 else "no") if b.mask else b.reason,
        ]
        cells += [", ".join(f"{m:.4f}" for m in row.interior[x]) for x in labels]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)
