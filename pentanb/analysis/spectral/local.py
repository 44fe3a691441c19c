"""The local subdivision matrix around an extraordinary element and its spectrum:
the search for a stationary neighbourhood (:func:`local_spectrum`) and its
result (:class:`LocalSpectrum`).

Candidate neighbourhoods grow by half rings (edge neighbours, then whole
faces); the smallest one whose image depends only on itself, at a level where
the next two levels match and give the same matrix, is the stationary
neighbourhood, and its local subdivision matrix is one fixed matrix.  See
:mod:`pentanb.analysis.spectral` for the whole method.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ... import _checks
from ... import schemes as _schemes
from ...mesh import Mesh
from ...schemes.registry import Scheme
from ...subdivision import get_scheme, predict_counts
from ..subdivision_matrix import _name, dual_matrix, remesh_matrix
from .contraction import _measured_contraction
from .eigen import TOL, _half_turn, _rotation_perm, _spectrum
from .neighbourhood import (
    MAX_DUALS,
    _check_kind,
    _check_size,
    _refuse_pyramid,
    _starts,
    _Step,
    _Topo,
    _track,
    _Walk,
    _walk,
    element_fate,
    pyramid,
)

__all__ = [
    "LocalSpectrum",
    "local_spectrum",
]

#: Largest mesh (faces) the search for a stationary neighbourhood builds.
MAX_FACES = 60_000
# ---------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class LocalSpectrum:
    """The local subdivision matrix around an extraordinary element and its spectrum.

    Attributes
    ----------
    scheme : str
    kind : {"vertex", "face"}
    size : int
        Valence of the vertex or number of sides of the face.
    duals : int
    options : dict
    stationary : bool
        False when no neighbourhood became stationary (or the element does
        not survive the scheme); ``note`` says why, and ``contraction``
        holds the measured ring contraction instead.
    period : int
        Steps ("remesh + duals") one analysed map takes: 1, or 2 when a
        single step cannot be identified with itself.
    neighbourhood : int
        Vertices of the smallest neighbourhood mapped onto itself.
    analysis_size : int
        Vertices of the neighbourhood whose matrix is analysed (one ring
        more than ``neighbourhood``, enough for the characteristic map);
        its spectrum contains that of the smaller one.
    level : int
        The level (from the pyramid) where the neighbourhood was found.
    rotation : int
        Sectors by which the identification of level ``level + period``
        with level ``level`` was turned ("rotation taken out").
    eigenvalues : (m,) complex
        Of the analysed matrix over one period, sorted by decreasing
        modulus (ties: real before complex, then by argument).
    matrix : (m, m) float
        The analysed local subdivision matrix (one step).
    modes : (m,) int
        Fourier mode w of every eigenvalue (its eigenvector turns by
        ``exp(2 pi i w / size)`` when the neighbourhood turns by one
        sector); -1 where the neighbourhood has no rotational symmetry.
    note : str
    contraction : float or None
        Measured ring contraction (extrapolated), when not stationary.
    refines : bool
        False for a scheme that stops refining (``triangulate`` after its
        first step: Figure 2's "null algorithm").
    """

    scheme: str
    kind: str
    size: int
    duals: int
    options: dict
    stationary: bool
    period: int = 1
    neighbourhood: int = 0
    analysis_size: int = 0
    level: int = 0
    rotation: int = 0
    eigenvalues: NDArray[np.complex128] = field(
        default_factory=lambda: np.zeros(0, dtype=complex), repr=False
    )
    matrix: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 0)), repr=False)
    modes: NDArray[np.int64] = field(
        default_factory=lambda: np.zeros(0, dtype=np.int64), repr=False
    )
    note: str = ""
    contraction: float | None = None
    refines: bool = True
    _context: Any = field(default=None, repr=False, compare=False)

    # -- derived ------------------------------------------------------------
    @property
    def moduli(self) -> NDArray[np.float64]:
        """Per-step moduli ``|lambda| ** (1 / period)``, decreasing."""
        return np.abs(self.eigenvalues) ** (1.0 / self.period)

    @property
    def arguments(self) -> NDArray[np.float64]:
        """Arguments (radians) of the eigenvalues over one period."""
        return np.angle(self.eigenvalues)

    def lam(self, i: int) -> complex:
        """Eigenvalue ``i`` (0 = the eigenvalue 1) over one period.

        Parameters
        ----------
        i : int, >= 0
            Index into :attr:`eigenvalues` (sorted by modulus, decreasing).

        Returns
        -------
        complex
            The eigenvalue of the matrix of one period (``period`` steps).
        """
        return complex(self.eigenvalues[i])

    @property
    def subdominant_complex(self) -> bool:
        """The subdominant eigenvalues are a complex (non-real) pair."""
        if self.eigenvalues.size < 3:
            return False
        lam1 = self.eigenvalues[1]
        return bool(abs(lam1.imag) > 1e-9 * max(abs(lam1), 1e-300))

    @property
    def subdominant_count(self) -> int:
        """How many eigenvalues share the largest modulus after the eigenvalue 1
        (to :data:`TOL` relative): 1 for a simple ``lambda1``, 2 for a double
        one or a complex pair, 3 or more otherwise; 0 without a spectrum."""
        if not self.stationary or self.eigenvalues.size < 2:
            return 0
        m = self.moduli
        return int(np.sum(np.abs(m[1:] - m[1]) <= TOL * m[1]))

    @property
    def standard(self) -> bool:
        """``1 = lambda0 > |lambda1| = |lambda2| > |lambda3|``: Reif's standard setting.

        The setting in which a regular, injective characteristic map makes
        the scheme C1 at the element (Reif 1995; Peters and Reif 2008,
        Ch. 5) -- a *sufficient* setting, not a necessary condition for a
        tangent plane.  What is necessary, for generic control points, is a
        pair of leading eigenvectors whose planar map can be regular and
        injective; where ``lambda1`` is simple and its eigenvector is
        invariant under the turn by one sector (Fourier mode 0), or where
        three or more eigenvalues share the subdominant modulus, there is no
        such pair (:attr:`map_obstruction`).  Floating point, to :data:`TOL`;
        :func:`exact_ordering` establishes it in exact arithmetic.
        """
        return self.standard_reason == ""

    @property
    def standard_reason(self) -> str:
        """Empty when the standard setting holds, else what fails."""
        if not self.stationary:
            return "no stationary neighbourhood"
        m = self.moduli
        if m.size < 4:
            return "neighbourhood too small"
        if abs(self.eigenvalues[0] - 1.0) > 1e-9:
            return f"dominant eigenvalue {self.eigenvalues[0]:.6g} is not 1"
        if m[1] >= 1.0 - 1e-9:
            return f"eigenvalue 1 is not simple (|lambda1| = {m[1]:.6g})"
        if abs(m[1] - m[2]) > TOL * m[1]:
            return f"|lambda1| = {m[1]:.6g} != |lambda2| = {m[2]:.6g}"
        if m[3] >= m[2] * (1 - TOL):
            return f"|lambda2| = |lambda3| = {m[2]:.6g} (subdominant eigenvalue not double)"
        return ""

    @property
    def necessary(self) -> bool:
        """The old name of :attr:`standard` (which is a sufficient setting, not a
        necessary condition); kept for old code."""
        return self.standard

    @property
    def necessary_reason(self) -> str:
        """The old name of :attr:`standard_reason`; kept for old code."""
        return self.standard_reason

    @property
    def map_obstruction(self) -> str:
        """Why the element has no characteristic map ("" when it has one).

        A characteristic map needs exactly two leading eigenvalues after the
        eigenvalue 1 (a real double eigenvalue with two eigenvectors, or a
        complex pair).  With a *simple* ``lambda1`` there is no pair: the map
        drawn from ``lambda1``'s eigenvector and one of the next would be a
        choice, not the scheme's; when that eigenvector has Fourier mode 0 it
        takes one value on the ``k`` turned copies of every point, so no map
        built on it is injective, and for generic control points the limit
        normal turns around the element with the next (mode +-1) terms: no
        tangent plane.  With three or more eigenvalues of the subdominant
        modulus the leading term maps the rings into space, not a plane: for
        generic control points the rings it leaves are not flat: no tangent
        plane.
        """
        if not self.stationary:
            return self.note or "no stationary neighbourhood"
        n = self.subdominant_count
        m = self.moduli
        if self.eigenvalues.size < 3:
            return "neighbourhood too small"
        if n == 1:
            mode = int(self.modes[1]) if self.modes.size > 1 else -1
            what = f" of Fourier mode {mode}" if mode >= 0 else ""
            return (
                f"lambda1 is simple{what} (|lambda1| = {m[1]:.6g} > |lambda2| = {m[2]:.6g}): "
                "no pair of subdominant eigenvectors"
            )
        if n >= 3:
            return f"{n} eigenvalues share the subdominant modulus {m[1]:.6g}: no planar pair"
        return ""

    def summary(self) -> str:
        """One line: the scheme, the element, the period, the neighbourhood and
        the leading eigenvalues (or why there is no stationary neighbourhood).

        Returns
        -------
        str
        """
        if not self.stationary:
            return f"{self.scheme} {self.kind} {self.size}: {self.note}"
        lam = ", ".join(_fmt(z) for z in self.eigenvalues[:5])
        return (
            f"{self.scheme} {self.kind} {self.size}: period {self.period}, "
            f"neighbourhood {self.neighbourhood} ({self.analysis_size} analysed), "
            f"eigenvalues {lam}"
        )


def _fmt(z: complex, digits: int = 4) -> str:
    z = complex(z)
    if abs(z.imag) <= 1e-9 * max(abs(z), 1e-300):
        return f"{z.real:.{digits}f}"
    return f"{abs(z):.{digits}f}∠{math.degrees(math.atan2(z.imag, z.real)):.1f}°"


# ---------------------------------------------------------------------------
# the search for a stationary neighbourhood
# ---------------------------------------------------------------------------


@dataclass
class _Context:
    """What the characteristic map needs: the hierarchy and the identification."""

    steps: list[_Step]
    level: int
    period: int
    domain: NDArray[np.int64]  # analysed neighbourhood at `level`, in order
    image: NDArray[np.int64]  # its counterpart at `level + period`, in order
    vectors: NDArray[np.complex128]  # eigenvectors of the analysed matrix (columns)
    scheme: Any
    options: dict
    duals: int
    steps_per_match: int = 1  # steps from `level` to the matched level (1, or 2 for sqrt(3))
    core: NDArray[np.int64] | None = None  # the smallest closed neighbourhood, positions in domain
    perm: NDArray[np.int64] | None = None  # one sector's turn, positions in domain
    rotation: int = 0  # sectors the identification is turned by (over one period)


def _build_step(step: _Step, scheme, duals: int, options: dict) -> _Step:
    mesh = step.mesh
    R, out = remesh_matrix(mesh, scheme, **options)
    element = step.element
    if element is not None:
        element = _track(element, mesh, out, R)
    S = R
    for _ in range(duals):
        S = dual_matrix(out) @ S
        out = _schemes.dual(out)
        if element is not None:
            element = ("face" if element[0] == "vertex" else "vertex", element[1])
    step.S = S.tocsr()
    return _Step(out, None, element)


def _composite(steps: list[_Step], a: int, p: int):
    S = steps[a].S
    for j in range(a + 1, a + p):
        S = steps[j].S @ S
    return S.tocsr()


def _candidate(walk: _Walk, t: float) -> NDArray[np.int64]:
    return walk.verts[walk.level <= t + 1e-9]


def _closed(S, image_idx, domain_idx) -> tuple[bool, NDArray[np.float64]]:
    """Do the rows ``image_idx`` of S depend on ``domain_idx`` only?  Then the block."""
    sub = S[image_idx]
    total = np.abs(sub).sum()
    block = sub[:, domain_idx]
    inside = np.abs(block).sum()
    if total - inside > 1e-12 * max(total, 1.0):
        return False, np.zeros(0)
    return True, block.toarray()


#: Half-ring thresholds tried for the stationary neighbourhood.
THRESHOLDS = (0.5, 1.0, 1.5, 2.0, 2.5, 3.0)


def local_spectrum(
    scheme: str | Scheme | Callable = "pentagonalize",
    kind: str = "vertex",
    size: int = 3,
    duals: int = 2,
    *,
    mesh: Mesh | None = None,
    element: int | None = None,
    max_faces: int = MAX_FACES,
    **options,
) -> LocalSpectrum:
    """The local subdivision matrix around an extraordinary vertex or face, and its spectrum.

    Parameters
    ----------
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    kind : {"vertex", "face"}
        A vertex of valence ``size`` or a face of ``size`` sides.
    size : int, >= 3
    duals : int
        Duals after each remeshing (2: the paper's smoothing).
    mesh : Mesh, optional
        Plant the element here instead of in :func:`pyramid` ``(size)``
        (e.g. a vertex of the cube); ``element`` names it (a vertex index
        for ``"vertex"``, a face index for ``"face"``).  The stationary
        matrix does not depend on where the element was planted, once the
        levels around it have become regular.
    element : int, optional
    max_faces : int
        Largest mesh the search may build.
    **options
        The scheme's options (``scale=...``).

    Returns
    -------
    LocalSpectrum
        ``stationary`` is False, with a ``note`` saying why and the measured
        ring ``contraction`` as a fallback, when the element does not
        survive the scheme or no neighbourhood becomes stationary within
        ``max_faces``.

    Raises
    ------
    TypeError
        A size, count or ``max_faces`` that is not an integer.
    ValueError
        A bad kind, size, count, scheme or option; a ``max_faces`` < 1, or
        smaller than the mesh the element is planted in (refused before
        that mesh is built).
    MeshError
        The first step would not fit in memory (refused before it is built).
    """
    kind = _check_kind(kind)
    size = _check_size(size)
    max_faces = _checks.count(max_faces, "max_faces", 1)
    s = get_scheme(scheme)
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            raise ValueError(f"scheme {s.name!r} takes {', '.join(s.options) or 'no options'}")
    duals = _checks.count(duals, "duals", 0, MAX_DUALS)
    name = _name(s)
    if mesh is None:
        _refuse_pyramid(size, max_faces)
        start = (size + 1, 2 * size, size + 1)
    else:
        _planted(mesh, kind, size, element)
        if mesh.n_faces > max_faces:
            raise ValueError(f"the mesh has {mesh.n_faces:,} faces, over max_faces={max_faces:,}")
        start = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    if isinstance(s, Scheme):
        predict_counts(start, s, 1, duals)  # the first step is always built: does it fit?
    if mesh is None:
        base = pyramid(size)
        el = ("vertex", 0) if kind == "vertex" else ("face", size)
    else:
        base, el = _planted(mesh, kind, size, element)
    steps = [_Step(base, None, el)]
    common: dict[str, Any] = dict(
        scheme=name, kind=kind, size=size, duals=duals, options=dict(options)
    )

    def extend() -> bool:
        last = steps[-1]
        if last.mesh.n_faces > max_faces:
            return False
        steps.append(_build_step(last, s, duals, options))
        return True

    extend()
    if steps[1].element is None:
        fate = element_fate(s, kind, size, **options)
        return LocalSpectrum(
            **common, stationary=False, note=f"the {kind} does not survive the scheme: {fate}"
        )
    # processing every vertex closer than the largest threshold discovers (and
    # orders) every vertex of every candidate
    depth = math.ceil(THRESHOLDS[-1])
    walks: dict[tuple[int, int], _Walk] = {}
    topos: dict[int, _Topo] = {}

    def walk(level: int, start: int) -> _Walk:
        key = (level, start)
        if key not in walks:
            if level not in topos:
                topos[level] = _Topo(steps[level].mesh)
            walks[key] = _walk(topos[level], steps[level].element, start, depth)
        return walks[key]

    def matching_start(level: int, ref: _Walk) -> int | None:
        for h in _starts(steps[level].mesh, steps[level].element):
            if walk(level, h).signature == ref.signature:
                return h
        return None

    reason = "no level matched"
    for p in (1, 2):  # two steps only when single steps never match
        level = 1
        while True:
            while len(steps) <= level + 2 * p and extend():
                pass
            if len(steps) <= level + 2 * p:
                break
            if steps[level + p].mesh.n_vertices <= steps[level].mesh.n_vertices:
                return LocalSpectrum(
                    **common,
                    stationary=False,
                    refines=False,
                    note="the scheme does not refine the mesh any more (Figure 2: "
                    "'after the first iteration it does not change the mesh')",
                )
            els = [steps[level + j * p].element for j in range(3)]
            level += 1
            if any(e is None or e[0] != kind for e in els):
                reason = f"the {kind} turns into a {'face' if kind == 'vertex' else 'vertex'}"
                continue
            L = level - 1
            start0 = _starts(steps[L].mesh, els[0])[0]
            w0 = walk(L, start0)
            start1 = matching_start(L + p, w0)
            start2 = matching_start(L + 2 * p, w0) if start1 is not None else None
            if start1 is None or start2 is None:
                reason = "the neighbourhood keeps changing"
                continue
            w1, w2 = walk(L + p, start1), walk(L + 2 * p, start2)
            found = _smallest_closed(
                w0, w1, w2, _composite(steps, L, p), _composite(steps, L + p, p)
            )
            if found is None:
                reason = "no candidate neighbourhood is closed and repeats"
                continue
            t_min, t_ana, A, dom, img = found
            if img.size == steps[L + p].mesh.n_vertices:
                reason = "the neighbourhood is the whole mesh"
                continue
            rot = _rotations(steps, L + p, els[1], start1, walk)
            perm = _rotation_perm(img, [_candidate(wk, t_ana) for wk in rot])
            half = _half_turn(
                _composite(steps, L, p), steps[L].mesh, els[0], steps[L + p].mesh, els[1]
            )
            spec = _spectrum(A, perm, size, half)
            level_ana = w0.level[w0.level <= t_ana + 1e-9]
            ctx = _Context(
                steps,
                L,
                p * spec.period,
                dom,
                img,
                spec.vectors,
                s,
                dict(options),
                duals,
                steps_per_match=p,
                core=np.flatnonzero(level_ana <= t_min + 1e-9),
                perm=spec.perm,
                rotation=spec.rotation,
            )
            return LocalSpectrum(
                **common,
                stationary=True,
                period=p * spec.period,
                neighbourhood=int(_candidate(w0, t_min).size),
                analysis_size=int(A.shape[0]),
                level=L,
                rotation=spec.rotation,
                eigenvalues=spec.values,
                matrix=A,
                modes=spec.modes,
                note=f"half-rings {t_min:g} (closed) and {t_ana:g} (analysed)"
                + (
                    "; two steps make one period (the neighbourhood turns by half a sector)"
                    if spec.period == 2
                    else ""
                ),
                _context=ctx,
            )
    contraction = _measured_contraction(steps, el)
    return LocalSpectrum(
        **common,
        stationary=False,
        note=f"no stationary neighbourhood found within {max_faces:,} faces ({reason})",
        contraction=contraction,
    )


def _planted(mesh, kind: str, size: int, element) -> tuple[Mesh, tuple[str, int]]:
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh must be a pentanb.Mesh, got {type(mesh).__name__}")
    count = mesh.n_vertices if kind == "vertex" else mesh.n_faces
    if isinstance(element, bool) or not isinstance(element, (int, np.integer)):
        raise ValueError(f"give the {kind} to analyse as element=<index>, got {element!r}")
    if not 0 <= element < count:
        raise ValueError(f"{kind} {element} does not exist (the mesh has {count})")
    have = int(mesh.valences[element]) if kind == "vertex" else int(mesh.face_sizes[element])
    if have != size:
        what = "valence" if kind == "vertex" else "sides"
        raise ValueError(f"{kind} {element} has {what} {have}, not {size}")
    return mesh, (kind, int(element))


def _rotations(steps, level, element, start, walk) -> list[_Walk]:
    """The walks from ``start`` and from the start turned by one sector."""
    hs = _starts(steps[level].mesh, element)
    j = hs.index(start)
    return [walk(level, hs[j]), walk(level, hs[(j + 1) % len(hs)])]


def _smallest_closed(w0, w1, w2, S01, S12):
    """The smallest closed, repeating candidate, and the analysed one a ring above it.

    Returns (t_min, t_analysed, A, domain, image) or None.
    """
    closed: list[tuple[float, NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]] = []
    for t in THRESHOLDS:
        dom, img, nxt = _candidate(w0, t), _candidate(w1, t), _candidate(w2, t)
        if not (dom.size == img.size == nxt.size):
            return None
        ok, A = _closed(S01, img, dom)
        if not ok:
            continue
        ok2, A2 = _closed(S12, nxt, img)
        if not ok2 or not np.allclose(A, A2, rtol=0, atol=1e-12):
            continue  # the walks matched but the weights differ: not stationary yet
        closed.append((t, A, dom, img))
        if t >= closed[0][0] + 1.0:
            break
    if not closed:
        return None
    t_ana, A, dom, img = closed[-1]
    return closed[0][0], t_ana, A, dom, img
