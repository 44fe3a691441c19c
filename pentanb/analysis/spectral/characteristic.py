"""The characteristic map (:func:`characteristic_map`): the limit of subdividing
the planar control net whose coordinates are the two subdominant eigenvectors.

It exists only when exactly two eigenvalues lead.  If it is regular (no fold)
and injective (one sheet), the scheme is C1 at the element -- Reif's
sufficient condition, stated for a real double subdominant eigenvalue.  The
map is drawn from its control net a few iterations down; the verdict on it
(all faces turn the same way, the boundary winds once) is numerical evidence,
not a proof of regularity or injectivity of the limit map.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ... import _checks
from ...mesh import Mesh, MeshError
from ...schemes.registry import Scheme
from .local import LocalSpectrum, _build_step, _Context, local_spectrum

__all__ = [
    "CharacteristicMap",
    "characteristic_map",
]

#: Largest mesh (faces) the characteristic map's levels may reach (the
#: figure's maps reach 40,000).
MAP_MAX_FACES = 1_000_000
# ---------------------------------------------------------------------------
# the characteristic map
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class CharacteristicMap:
    """The characteristic map's control net a few iterations down, and its verdict.

    Attributes
    ----------
    spectrum : LocalSpectrum
    points : (n, 2) float
        Planar positions (the two subdominant eigenvectors, or the real and
        imaginary parts of a complex one), subdivided ``iterations`` times.
    corners, offsets : int arrays
        The faces whose positions are all determined by the neighbourhood
        (CSR, indices into ``points``).
    centre : (2,) float
        Where the element itself goes (the origin).
    iterations : int
        Iterations of the scheme below the analysed neighbourhood.
    signs : (m,) int
        Orientation of every face's fan triangles (+1, -1, or 0 when mixed
        or degenerate).
    winding : int
        Winding number around the centre of the boundary of the faces
        around the element.
    complex_pair : bool
        The subdominant eigenvalues are a complex pair (Re, Im are drawn).
    defective : bool
        The two subdominant eigenvectors are (numerically) parallel.
    """

    spectrum: LocalSpectrum
    points: NDArray[np.float64]
    corners: NDArray[np.int64]
    offsets: NDArray[np.int64]
    centre: NDArray[np.float64]
    iterations: int
    signs: NDArray[np.int64]
    winding: int
    complex_pair: bool
    defective: bool

    @property
    def n_faces(self) -> int:
        return int(self.offsets.size - 1)

    @property
    def regular(self) -> bool:
        """No fold: every face turns the same way (all fan triangles one sign)."""
        return bool(self.n_faces and (np.all(self.signs == 1) or np.all(self.signs == -1)))

    @property
    def injective(self) -> bool:
        """Regular, and one sheet: the boundary around the element winds once."""
        return self.regular and abs(self.winding) == 1 and not self.defective

    @property
    def verdict(self) -> str:
        if self.defective:
            return "defective (one eigenvector)"
        if not self.regular:
            bad = int(np.sum(self.signs != np.sign(np.sum(self.signs))))
            return f"fold ({bad} of {self.n_faces} faces turned)"
        if abs(self.winding) != 1:
            return f"not injective (winds {abs(self.winding)} times)"
        return "regular, injective"


def _reference_row(x: np.ndarray) -> int:
    """The first entry of ``x`` at least half its largest modulus.

    A choice that rounding cannot move: the entries of a symmetric
    eigenvector come in orbits of equal modulus, so "the largest" would be
    decided by the last bits, but "the first of the large ones" is not.
    """
    a = np.abs(x)
    return int(np.flatnonzero(a >= 0.5 * a.max())[0]) if a.size and a.max() > 0 else 0


def _canonical_plane(v: np.ndarray, mode: int, k: int) -> np.ndarray:
    """(n, 2) real and imaginary parts of the eigenvector ``v`` of Fourier mode
    ``mode`` (of ``k``), in a basis that does not depend on the eigensolver.

    An eigenvector is defined up to a complex factor, which turns (and
    scales) the characteristic map, and a real double eigenvalue has the
    eigenvectors of modes w and k - w, conjugates, which mirror it.  Which
    one LAPACK returns changes with its version (the committed figure came
    out turned under another numpy build), so the mode is taken at most
    k / 2 (conjugating otherwise: the same plane, mirrored) and the factor
    makes the reference entry real and positive.
    """
    v = np.asarray(v, dtype=np.complex128)
    if 2 * mode > k:
        v = np.conj(v)
    r = _reference_row(v)
    if abs(v[r]) > 0:
        v = v * (np.conj(v[r]) / abs(v[r]))
    return np.stack([v.real, v.imag], axis=1)


def _canonical_sign(x: np.ndarray) -> np.ndarray:
    """A real eigenvector with its reference entry (:func:`_reference_row`) positive."""
    x = np.asarray(x, dtype=np.float64)
    return -x if x.size and x[_reference_row(x)] < 0 else x


def characteristic_map(
    spectrum: LocalSpectrum | str | Scheme | Callable = "pentagonalize",
    kind: str = "vertex",
    size: int = 3,
    duals: int = 2,
    *,
    iterations: int = 2,
    **options,
) -> CharacteristicMap:
    """The characteristic map around an extraordinary element, with its verdict.

    The two subdominant eigenvectors (or the real and imaginary parts of a
    complex one) are put on the analysed neighbourhood as planar positions
    and subdivided ``iterations`` more times with the real subdivision
    matrices; every vertex whose new position depends only on the
    neighbourhood is kept.  Its faces are the control net of the
    characteristic map (Reif 1995), which converges to the map as the
    iterations grow.

    Parameters
    ----------
    spectrum : LocalSpectrum, or a scheme
        A result of :func:`local_spectrum`, or the scheme to analyse (then
        ``kind``, ``size``, ``duals`` and ``options`` go to
        :func:`local_spectrum`).
    iterations : int, >= 0
        Iterations of the scheme (remesh + duals, as subdivision matrices)
        below the analysed neighbourhood.

    Returns
    -------
    CharacteristicMap

    Raises
    ------
    ValueError
        When the spectrum has no stationary neighbourhood (nothing to draw),
        or no characteristic map exists (:attr:`LocalSpectrum.map_obstruction`:
        a simple ``lambda1``, or three or more eigenvalues of the subdominant
        modulus).
    """
    iterations = _checks.count(iterations, "iterations", 0, _checks.MAX_STEPS)
    if not isinstance(spectrum, LocalSpectrum):
        spectrum = local_spectrum(spectrum, kind, size, duals, **options)
    if not spectrum.stationary or spectrum._context is None:
        raise ValueError(f"no characteristic map: {spectrum.note or 'no stationary neighbourhood'}")
    if spectrum.map_obstruction:
        raise ValueError(f"no characteristic map: {spectrum.map_obstruction}")
    ctx: _Context = spectrum._context
    _refuse_map_levels(ctx, iterations)
    w = spectrum.eigenvalues
    V = ctx.vectors
    complex_pair = spectrum.subdominant_complex
    if spectrum.modes.size > 1 and spectrum.modes[1] > 0:
        # a Fourier mode w != 0: its real and imaginary parts span the
        # (real double or complex pair) subdominant eigenspace
        psi = _canonical_plane(V[:, 1], int(spectrum.modes[1]), spectrum.size)
    else:
        psi = np.stack([_canonical_sign(V[:, 1].real), _canonical_sign(V[:, 2].real)], axis=1)
    sv = np.linalg.svd(psi, compute_uv=False)
    defective = bool(sv[1] < 1e-6 * sv[0]) or abs(w[1]) < 1e-12
    # positions on the whole level, NaN outside the neighbourhood
    steps = ctx.steps
    L = ctx.level
    while len(steps) <= L + iterations:
        last = steps[-1]
        steps.append(_build_step(last, ctx.scheme, ctx.duals, ctx.options))
    x = np.full((steps[L].mesh.n_vertices, 2), np.nan)
    x[ctx.domain] = psi
    for j in range(L, L + iterations):
        x = _propagate(steps[j].S, x)
    mesh = steps[L + iterations].mesh
    known = np.isfinite(x).all(axis=1)
    face_ok = np.logical_and.reduceat(known[mesh.corners], mesh.offsets[:-1])
    faces = np.flatnonzero(face_ok)
    # keep the faces connected to the element
    element = steps[L + iterations].element
    faces = _component(mesh, faces, element)
    sizes = mesh.face_sizes[faces]
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    corner_ids = (
        np.concatenate([mesh.corners[mesh.offsets[f] : mesh.offsets[f + 1]] for f in faces])
        if faces.size
        else np.zeros(0, dtype=np.int64)
    )
    used, local = np.unique(corner_ids, return_inverse=True)
    pts = x[used]
    if element is not None and element[0] == "vertex":
        centre = x[element[1]]
    elif element is not None:
        c = mesh.corners[mesh.offsets[element[1]] : mesh.offsets[element[1] + 1]]
        centre = x[c].mean(axis=0)
    else:  # pragma: no cover - the element survives by construction
        centre = np.zeros(2)
    signs = _face_signs(pts, local.astype(np.int64), offsets)
    winding = _winding(pts, local.astype(np.int64), offsets, centre)
    return CharacteristicMap(
        spectrum=spectrum,
        points=pts,
        corners=local.astype(np.int64),
        offsets=offsets,
        centre=np.asarray(centre, dtype=np.float64),
        iterations=int(iterations),
        signs=signs,
        winding=winding,
        complex_pair=complex_pair,
        defective=defective,
    )


def _refuse_map_levels(ctx: _Context, iterations: int) -> None:
    """Refuse (MeshError), before building any, levels of the characteristic map
    with more than :data:`MAP_MAX_FACES` faces at some step; predicted from
    the counts level by level, stopping at the first too large."""
    built = len(ctx.steps) - 1
    s = ctx.scheme
    if ctx.level + iterations <= built or not isinstance(s, Scheme):
        return
    last = ctx.steps[-1].mesh
    counts = (last.n_vertices, last.n_edges, last.n_faces)
    for level in range(built + 1, ctx.level + iterations + 1):
        V, E, F = s.counts(*counts)
        biggest = max(F, V) if ctx.duals else F  # a dual has a face per vertex
        if biggest > MAP_MAX_FACES:
            raise MeshError(
                f"iterations={iterations:,}: the characteristic map's level {level} would "
                f"have a mesh of {biggest:,} faces, over MAP_MAX_FACES={MAP_MAX_FACES:,}; "
                "lower iterations"
            )
        counts = (F, E, V) if ctx.duals % 2 else (V, E, F)


def _propagate(S, x):
    """``S @ x`` where any NaN input makes the output NaN (sparse pattern aware)."""
    bad = ~np.isfinite(x).all(axis=1)
    clean = np.where(bad[:, None], 0.0, x)
    y = S @ clean
    touched = (abs(S) @ bad.astype(np.float64)) > 0
    y[touched] = np.nan
    return y


def _component(mesh: Mesh, faces, element) -> NDArray[np.int64]:
    """The faces of ``faces`` edge-connected to the element."""
    if faces.size == 0 or element is None:
        return faces
    keep = np.zeros(mesh.n_faces, dtype=bool)
    keep[faces] = True
    hf = mesh.halfedge_face
    twin_face = hf[mesh.twin]
    kind, i = element
    if kind == "vertex":
        seeds = np.unique(hf[mesh.corners == i])
    else:
        seeds = np.unique(twin_face[mesh.offsets[i] : mesh.offsets[i + 1]])
        seeds = np.concatenate([seeds, [i]])
    seen = np.zeros(mesh.n_faces, dtype=bool)
    frontier = [int(f) for f in seeds if keep[f]]
    for f in frontier:
        seen[f] = True
    off = mesh.offsets
    while frontier:
        f = frontier.pop()
        for g in twin_face[off[f] : off[f + 1]]:
            g = int(g)
            if keep[g] and not seen[g]:
                seen[g] = True
                frontier.append(g)
    return np.flatnonzero(seen)


def _face_signs(pts, corners, offsets) -> NDArray[np.int64]:
    """+1 / -1 when every fan triangle (from the face centroid) of a face has that
    orientation, 0 when mixed or degenerate."""
    m = offsets.size - 1
    if m == 0:
        return np.zeros(0, dtype=np.int64)
    sizes = np.diff(offsets)
    face = np.repeat(np.arange(m), sizes)
    p = pts[corners]
    c = np.add.reduceat(p, offsets[:-1], axis=0) / sizes[:, None]
    nxt = np.arange(1, corners.size + 1)
    nxt[offsets[1:] - 1] = offsets[:-1]
    q = pts[corners[nxt]]
    a = p - c[face]
    b = q - c[face]
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    scale = np.abs(cross).max(initial=0.0)
    sgn = np.sign(np.where(np.abs(cross) > 1e-12 * scale, cross, 0.0)).astype(np.int64)
    lo = np.minimum.reduceat(sgn, offsets[:-1])
    hi = np.maximum.reduceat(sgn, offsets[:-1])
    return np.where(lo == hi, lo, 0).astype(np.int64)


def _winding(pts, corners, offsets, centre) -> int:
    """Winding number of the region's boundary around ``centre``.

    The boundary is the set of directed edges whose reverse is not in the
    region; the angles they sweep around the centre are summed.
    """
    m = offsets.size - 1
    if m == 0:
        return 0
    nxt = np.arange(1, corners.size + 1)
    nxt[offsets[1:] - 1] = offsets[:-1]
    a, b = corners, corners[nxt]
    pairs = set(zip(a.tolist(), b.tolist()))
    boundary = [(u, v) for u, v in zip(a.tolist(), b.tolist()) if (v, u) not in pairs]
    total = 0.0
    for u, v in boundary:
        p = pts[u] - centre
        q = pts[v] - centre
        total += math.atan2(p[0] * q[1] - p[1] * q[0], p[0] * q[0] + p[1] * q[1])
    return round(total / (2 * math.pi))
