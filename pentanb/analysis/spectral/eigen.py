"""Spectra and eigen-structure of a local subdivision matrix: eigenvalues by
Fourier mode, the rotation between levels, the half turn.

The starting half-edge at level l + p can be any of the element's ``size``
half-edges; the choice turns the identification of the two levels by whole
sectors (:func:`_rotation_perm`), which multiplies the eigenvalues of Fourier
mode w by ``exp(2 pi i a w / size)`` and leaves their moduli alone.  A scheme
that turns its neighbourhood by half a sector per step is analysed over the
two steps that bring it back (:func:`_half_turn`, read from the
neighbourhood).  :func:`_spectrum` sorts the eigenvalues by modulus, with
their Fourier modes (:func:`_fourier`, :func:`_fourier_blocks`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ...mesh import Mesh

#: Relative tolerance of "equal moduli" and of "same matrix".
TOL = 1e-8


@dataclass
class _Spec:
    values: NDArray[np.complex128]
    vectors: NDArray[np.complex128]
    modes: NDArray[np.int64]
    rotation: int
    period: int
    perm: NDArray[np.int64] | None


#: Relative imaginary part above which an eigenvalue counts as non-real when
#: the period and the turn are chosen (round-off of a double eigenvalue stays
#: far below it).
REAL_TOL = 1e-6


def _rotation_perm(img, rotated_orders) -> NDArray[np.int64] | None:
    """``perm[i]``: the position, in ``img``'s order, of the vertex one sector on
    from ``img[i]``."""
    pos = {int(v): i for i, v in enumerate(img)}
    if len(rotated_orders) < 2:
        return None
    order1 = rotated_orders[1]
    if order1.size != img.size or set(order1.tolist()) != set(pos):
        return None
    return np.array([pos[int(v)] for v in order1], dtype=np.int64)


def _nonreal(vals: NDArray[np.complex128]) -> int:
    """How many eigenvalues (of the significant ones) are not real."""
    mags = np.abs(vals)
    big = mags > 1e-8 * max(float(mags.max(initial=0.0)), 1e-300)
    return int(np.sum(np.abs(vals.imag[big]) > REAL_TOL * mags[big]))


def _ring(mesh: Mesh, element) -> NDArray[np.int64]:
    """The element's first ring in rotation order: a vertex's neighbours, a face's corners."""
    kind, i = element
    if kind == "vertex":
        ring, off = mesh.vertex_ring
        return np.asarray(mesh.head[ring[off[i] : off[i + 1]]], dtype=np.int64)
    return np.asarray(mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]], dtype=np.int64)


def _half_turn(S, mesh0: Mesh, el0, mesh1: Mesh, el1) -> bool:
    """Does one step turn the element's neighbourhood by half a sector?

    Structural, not spectral: the first vertex of the element's new ring
    (a corner of the face, a neighbour of the vertex) leans equally on two
    neighbouring members of the old ring, and more than on any other -- it
    sits over an old edge (or face), between two sectors.  Pentagon
    preservation's faces (a corner of the face copy is a scaled edge
    midpoint) and sqrt(3)'s vertices (a new neighbour is an old face's
    centroid) do; a chiral scheme leans unequally and is not a half turn.
    """
    old, new = _ring(mesh0, el0), _ring(mesh1, el1)
    k = old.size
    if k < 3 or new.size != k:
        return False
    w = np.asarray(S.tocsr()[int(new[0])].toarray()).ravel()[old]
    order = np.argsort(-w, kind="stable")
    a, b = int(order[0]), int(order[1])
    top, second = w[a], w[b]
    if top <= 1e-12 or abs(top - second) > 1e-9 * top:
        return False
    third = w[order[2]]
    return bool((a - b) % k in (1, k - 1) and third < top * (1 - 1e-9))


def _spectrum(A, perm, k: int, half_turn: bool = False) -> _Spec:
    """Eigenvalues of the local matrix by Fourier modes, rotation taken out.

    ``A`` maps the domain (ordered like the image) to the image; ``perm`` is
    the turn of the image by one sector (the rotation that
    block-diagonalizes ``A``).  Turning the identification by ``a`` sectors
    multiplies the eigenvalues of mode w by ``exp(2 pi i a w / k)``.

    The period is decided by the neighbourhood, whatever the leading
    eigenvalue: two steps when one step turns it by half a sector
    (``half_turn``, :func:`_half_turn`: pentagon preservation's faces,
    sqrt(3)'s vertices), which no relabelling of one step removes; one step
    otherwise.  The turn chosen leaves the fewest non-real eigenvalues over
    the whole spectrum, then the smallest argument of the subdominant ones,
    then is the smallest.  A chiral scheme keeps complex eigenvalues under
    every turn; they are reported with their argument.
    """
    blocks = _fourier(A, perm, k) if perm is not None else None
    if blocks is None:  # no rotational symmetry to use: dense, modes unknown
        w, V = np.linalg.eig(A)
        modes = np.full(w.size, -1, dtype=np.int64)
        perm = None
    else:
        w, V, modes = blocks
    # the subdominant: largest modulus after the eigenvalue 1
    order = np.argsort(-np.abs(w), kind="stable")
    unit = order[np.argmin(np.abs(w[order[:3]] - 1.0))] if w.size else 0
    rest = [i for i in order if i != unit]
    turnable = bool(modes.size) and bool((modes >= 0).all())

    def best_turn(vals):
        lead = abs(vals[rest[0]]) if rest else 0.0
        top = [i for i in rest if abs(abs(vals[i]) - lead) <= TOL * lead]
        if not turnable:
            return 0, vals
        cands = []
        for a in range(k):
            turned = vals * np.exp(2j * np.pi * a * modes / k)
            worst = max((abs(float(np.angle(turned[i]))) for i in top), default=0.0)
            cands.append(((_nonreal(turned), round(worst, 9), a), a, turned))
        _, a, turned = min(cands, key=lambda c: c[0])
        return a, turned

    period = 2 if half_turn else 1
    a, vals = best_turn(w**period)
    key = np.lexsort(
        (np.angle(vals), np.round(np.abs(np.angle(vals)), 9), -np.round(np.abs(vals), 12))
    )
    return _Spec(vals[key], V[:, key], modes[key], a, period, perm)


def _is_complex(z) -> bool:
    return bool(abs(complex(z).imag) > 1e-9 * max(abs(z), 1e-300))


def _fourier(A, perm, k):
    """Block-diagonalize ``A`` by the rotation ``perm`` (k-fold); None if it does not commute."""
    n = A.shape[0]
    if not np.allclose(A[np.ix_(perm, perm)], A, rtol=0, atol=1e-12):
        return None
    fixed = np.flatnonzero(perm == np.arange(n))
    seen = np.zeros(n, dtype=bool)
    seen[fixed] = True
    orbits = []
    for i in range(n):
        if seen[i]:
            continue
        orb = [i]
        j = int(perm[i])
        while j != i:
            orb.append(j)
            j = int(perm[j])
        if len(orb) != k:
            return None
        seen[orb] = True
        orbits.append(orb)
    O = np.array(orbits, dtype=np.int64).reshape(-1, k)  # O[r, j] = perm^j(O[r, 0])
    m = O.shape[0]
    values, vectors, modes = [], [], []
    for w in range(k):
        z = np.exp(2j * np.pi * w * np.arange(k) / k)
        # B[s, r] = sum_j A[O[s, 0], O[r, j]] z^j
        B = (A[O[:, 0]][:, O] * z[None, None, :]).sum(axis=2) if m else np.zeros((0, 0))
        if w == 0 and fixed.size:
            top = np.concatenate([B, A[np.ix_(O[:, 0], fixed)]], axis=1)
            bottom = np.concatenate([A[fixed][:, O].sum(axis=2), A[np.ix_(fixed, fixed)]], axis=1)
            B = np.concatenate([top, bottom], axis=0)
        if B.size == 0:
            continue
        lam, C = np.linalg.eig(B)
        X = np.zeros((n, lam.size), dtype=complex)
        X[O.reshape(-1)] = (C[:m, None, :] * z[None, :, None]).reshape(m * k, lam.size)
        if w == 0 and fixed.size:
            X[fixed] = C[m:]
        X /= np.linalg.norm(X, axis=0, keepdims=True)
        values.append(lam)
        vectors.append(X)
        modes.append(np.full(lam.size, w, dtype=np.int64))
    return np.concatenate(values), np.concatenate(vectors, axis=1), np.concatenate(modes)


def _fourier_blocks(A, perm, k) -> list[tuple[int, NDArray[Any]]] | None:
    """The Fourier blocks ``B_w`` of ``A`` (the matrices :func:`_fourier` diagonalizes),
    without their eigenvalues; linear in ``A``.  None without k-fold symmetry."""
    n = A.shape[0]
    if not np.allclose(A[np.ix_(perm, perm)], A, rtol=0, atol=1e-12):
        return None
    fixed = np.flatnonzero(perm == np.arange(n))
    seen = np.zeros(n, dtype=bool)
    seen[fixed] = True
    orbits = []
    for i in range(n):
        if seen[i]:
            continue
        orb = [i]
        j = int(perm[i])
        while j != i:
            orb.append(j)
            j = int(perm[j])
        if len(orb) != k:
            return None
        seen[orb] = True
        orbits.append(orb)
    O = np.array(orbits, dtype=np.int64).reshape(-1, k)
    m = O.shape[0]
    out = []
    for w in range(k):
        z = np.exp(2j * np.pi * w * np.arange(k) / k)
        B = (A[O[:, 0]][:, O] * z[None, None, :]).sum(axis=2) if m else np.zeros((0, 0))
        if w == 0 and fixed.size:
            top = np.concatenate([B, A[np.ix_(O[:, 0], fixed)]], axis=1)
            bottom = np.concatenate([A[fixed][:, O].sum(axis=2), A[np.ix_(fixed, fixed)]], axis=1)
            B = np.concatenate([top, bottom], axis=0)
        if B.size:
            out.append((w, B))
    return out
