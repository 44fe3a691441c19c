"""Local subdivision matrices, their spectra and characteristic maps (Section 7's open question).

The paper closes (Section 7): "we have visually confirmed that the
algorithms converge with G1 continuity. However, there is still a need for
theoretical proofs for convergence."  Subdivision theory answers such
questions locally, around an *extraordinary element* -- a vertex of some
valence or a face of some size that survives every level:

1. Find the smallest neighbourhood N of the element that the scheme maps
   onto itself: the vertices of N at level l + p depend only on the
   vertices of N at level l, and N looks the same (same connectivity, same
   weights) at every level.  Its local subdivision matrix A is then one
   fixed matrix (:func:`local_spectrum`).
2. Sort A's eigenvalues by modulus, ``1 = lambda0 > |lambda1| >= |lambda2|
   >= ...``.  A tangent plane needs ``|lambda1| = |lambda2| > |lambda3|``
   (Reif 1995; Peters and Reif, *Subdivision Surfaces*, 2008, Ch. 5; Zorin
   2000): the *necessary condition*.
3. The *characteristic map* is the limit of subdividing the planar control
   net whose coordinates are the two subdominant eigenvectors; if it is
   regular (no fold) and injective (one sheet), the scheme is C1 at the
   element -- Reif's sufficient condition, stated for a real double
   subdominant eigenvalue (:func:`characteristic_map`).

How the neighbourhood is found.  The element is planted in a small closed
mesh (a pyramid over a ``size``-gon: its apex is a ``size``-valent vertex
and its base a ``size``-gon), which is subdivided level after level.  The
element is followed through every step by the rules themselves: a vertex
survives a remeshing when its row of the remeshing matrix is a unit row (it
stays where it is, as in all the paper's remeshings), a face when a new face
of the same size has the same centroid; a dual swaps the two.  Around the
element, the vertices are put in a canonical order by a breadth-first walk
that follows the faces counter-clockwise from a chosen starting half-edge;
two levels *match* when these walks see the same connectivity.  Candidate
neighbourhoods grow by half rings (edge neighbours, then whole faces); the
smallest one whose image depends only on itself, at a level where the next
two levels match and give the same matrix, is the stationary neighbourhood.

Rotation.  The starting half-edge at level l + p can be any of the
element's ``size`` half-edges; the choice turns the identification of the
two levels by whole sectors, which multiplies the eigenvalues of Fourier
mode w by ``exp(2 pi i a w / size)`` and leaves their moduli alone.  The
choice reported ("rotation taken out") is the one that makes the
subdominant eigenvalue's argument smallest.  A scheme that turns its
neighbourhood by half a sector per step (sqrt(3)) is analysed over the two
steps that bring it back (``period`` 2) when the single step cannot be
identified without a turn; a *chiral* scheme (pentagonalization, whose
pentagons have no mirror symmetry) turns its neighbourhood by an angle
that no relabelling removes: its subdominant eigenvalues are a complex
pair, reported with their argument.

What is proven and what is not.  The eigenvalues are those of an exactly
assembled matrix (floating point, checked against the operators), so the
necessary condition and its failures are established up to round-off.  The
characteristic map is drawn from its control net a few iterations down; the
verdict on it (all faces turn the same way, the boundary winds once) is
numerical evidence, not a proof of regularity of the limit map.  Reif's
criterion also assumes a C1 surface away from the element (true for
spline-based schemes such as vertex insertion + 2 duals, which is bicubic
on regular regions) and a real double subdominant eigenvalue; where either
is missing the statement is left *undecided*.
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .. import schemes as _schemes
from ..mesh import Mesh
from ..notation import seeds
from ..schemes.registry import SCHEMES, Scheme
from ..subdivision import get_scheme
from .subdivision_matrix import _name, dual_matrix, remesh_matrix

__all__ = [
    "KINDS",
    "LocalSpectrum",
    "CharacteristicMap",
    "ContinuityRow",
    "local_spectrum",
    "characteristic_map",
    "ring_contraction",
    "extrapolate_ratio",
    "element_fate",
    "pyramid",
    "continuity_table",
    "table_markdown",
    "TABLE_CASES",
]

KINDS = ("vertex", "face")

#: Largest mesh (faces) the search for a stationary neighbourhood builds.
MAX_FACES = 60_000
#: Relative tolerance of "equal moduli" and of "same matrix".
TOL = 1e-8


# ---------------------------------------------------------------------------
# the test mesh and one step with its matrices
# ---------------------------------------------------------------------------


def pyramid(size: int) -> Mesh:
    """The pyramid ``Y<size>`` (:func:`pentanb.notation.pyramid`), renumbered and
    perturbed: the mesh in which the elements are planted.

    The apex is lifted off-centre and the base ring is slightly irregular, so
    that no accidental symmetry of the positions hides a mode.

    Parameters
    ----------
    size : int >= 3
        The valence of the apex and the number of sides of the base.

    Returns
    -------
    Mesh
        ``size + 1`` vertices: the apex (vertex 0), then the base ring;
        ``size + 1`` faces: the triangles ``(0, 1 + i, 1 + (i + 1) % size)``,
        then the base (face ``size``).

    Raises
    ------
    ValueError
        ``size`` is not an integer >= 3.
    """
    k = _check_size(size)
    seed = seeds.pyramid(k)  # ring 0 .. k - 1, apex k; faces: the base, then (i, i + 1, k)
    label = (np.arange(k + 1) + 1) % (k + 1)  # seed vertex -> here: the apex first
    tris = label[seed.corners[k:].reshape(k, 3)][:, [2, 0, 1]]  # each from the apex
    base = label[seed.corners[:k]]
    t = 2 * np.pi * np.arange(k) / k
    r = 1.0 + 0.05 * np.cos(3 * t + 0.3)
    ring = np.stack([r * np.cos(t), r * np.sin(t), 0.1 * np.sin(2 * t + 0.7)], axis=1)
    apex = np.array([[0.07, -0.04, 1.1]])
    return Mesh(np.concatenate([apex, ring]), [*tris.tolist(), base.tolist()])


def _check_size(size) -> int:
    if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or size < 3:
        raise ValueError(f"size must be an integer >= 3, got {size!r}")
    return int(size)


def _check_kind(kind) -> str:
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    return str(kind)


@dataclass
class _Step:
    """One level of the hierarchy: ``S`` maps this level's positions to the next."""

    mesh: Mesh
    S: Any = None  # (V_next, V) sparse
    element: tuple[str, int] | None = None  # on this mesh


def _track(element, mesh: Mesh, remeshed: Mesh, R) -> tuple[str, int] | None:
    """Where an element of ``mesh`` is in ``remeshed`` (None if it does not survive)."""
    kind, i = element
    R = R.tocsr()
    if kind == "vertex":
        col = R[:, [i]].tocsc()
        rows = col.indices[np.isclose(col.data, 1.0, rtol=0, atol=1e-14)]
        for r in rows:
            if R.indptr[r + 1] - R.indptr[r] == 1:
                return ("vertex", int(r))
        return None
    # a face survives as a new face of the same size with the same centroid
    n = int(mesh.face_sizes[i])
    verts = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
    C = (dual_matrix(remeshed) @ R).tocsc()
    sub = C[:, verts].tocsr()
    cand = np.flatnonzero(remeshed.face_sizes == n)
    nnz_all = np.diff(C.tocsr().indptr)
    for g in cand:
        row = sub[g].toarray().ravel()
        if nnz_all[g] == n and np.allclose(row, 1.0 / n, rtol=0, atol=1e-13):
            return ("face", int(g))
    return None


def element_fate(scheme, kind: str, size: int, **options) -> str:
    """What one remeshing makes of a ``size``-valent vertex or a ``size``-gon.

    Returns
    -------
    str
        ``"vertex k"`` / ``"face n"`` for the element that keeps its place
        (a kept vertex, a face copy about the same centroid), or, when it
        does not survive, what takes its place (e.g. ``"becomes a vertex of
        valence 5"`` for a face whose centroid becomes a vertex).
    """
    kind = _check_kind(kind)
    size = _check_size(size)
    s = get_scheme(scheme)
    mesh = pyramid(size)
    element = ("vertex", 0) if kind == "vertex" else ("face", size)
    R, out = remesh_matrix(mesh, s, **options)
    found = _track(element, mesh, out, R)
    if found is not None:
        k, j = found
        n = int(out.valences[j]) if k == "vertex" else int(out.face_sizes[j])
        return f"{k} {n}"
    R = R.tocsr()
    if kind == "face":
        verts = mesh.corners[mesh.offsets[size] : mesh.offsets[size + 1]]
        target = np.zeros(mesh.n_vertices)
        target[verts] = 1.0 / size
        for r in range(out.n_vertices):
            if np.allclose(R[r].toarray().ravel(), target, atol=1e-13):
                return f"becomes a vertex of valence {int(out.valences[r])}"
        return "does not survive"
    # a vertex whose place is taken by a face: every corner of the face
    # leans most on the vertex
    dense = R.toarray()
    best = dense.max(axis=1)
    leans = dense[:, 0] >= best - 1e-13
    for g in range(out.n_faces):
        corners = out.corners[out.offsets[g] : out.offsets[g + 1]]
        if leans[corners].all() and dense[corners, 0].min() > 0:
            return f"becomes a face of {int(out.face_sizes[g])} sides"
    return "does not survive"


# ---------------------------------------------------------------------------
# canonical order around an element
# ---------------------------------------------------------------------------


@dataclass
class _Walk:
    verts: NDArray[np.int64]  # mesh vertex ids, in discovery order
    level: NDArray[np.float64]  # half-ring level of each (0, 0.5, 1, 1.5, ...)
    signature: tuple


def _starts(mesh: Mesh, element) -> list[int]:
    """The element's half-edges in rotation order (its possible starts)."""
    kind, i = element
    if kind == "vertex":
        ring, off = mesh.vertex_ring
        return [int(h) for h in ring[off[i] : off[i + 1]]]
    return list(range(int(mesh.offsets[i]), int(mesh.offsets[i + 1])))


class _Topo:
    """Python lists of a mesh's half-edge arrays (fast scalar access for walks)."""

    def __init__(self, mesh: Mesh):
        ring, off = mesh.vertex_ring
        self.ring = ring.tolist()
        self.off = off.tolist()
        self.nxt = mesh.next.tolist()
        self.tail = mesh.corners.tolist()
        self.size = mesh.face_sizes[mesh.halfedge_face].tolist()

    def rotated(self, u: int, g: int) -> list[int]:
        hs = self.ring[self.off[u] : self.off[u + 1]]
        j = hs.index(g)
        return hs[j:] + hs[:j]


def _walk(topo: _Topo, element, start: int, depth: int) -> _Walk:
    """Breadth-first walk over faces from ``element`` and half-edge ``start``.

    Every vertex at face distance < ``depth`` is processed: its outgoing
    half-edges, counter-clockwise from the one it was entered by, and the
    faces they bound, corner after corner.  The signature records, for every
    processed vertex, the discovery number of each neighbour and the size of
    each face: two walks with equal signatures see the same connectivity.
    """
    kind, i = element
    order: dict[int, int] = {}
    entry: list[int] = []
    dist: list[int] = []
    edge_near: list[bool] = []
    verts: list[int] = []

    def discover(w: int, h: int, d: int) -> None:
        order[w] = len(verts)
        verts.append(w)
        entry.append(h)
        dist.append(d)
        edge_near.append(False)

    if kind == "vertex":
        discover(i, start, 0)
    else:
        h = start
        while True:
            discover(topo.tail[h], h, 0)
            h = topo.nxt[h]
            if h == start:
                break
    record = []
    q = deque(range(len(verts)))
    while q:
        a = q.popleft()
        if dist[a] >= depth:
            continue
        u = verts[a]
        rec = []
        for h in topo.rotated(u, entry[a]):
            g = topo.nxt[h]
            w = topo.tail[g]
            if w not in order:
                discover(w, g, dist[a] + 1)
                q.append(len(verts) - 1)
            b = order[w]
            if dist[b] == dist[a] + 1:
                edge_near[b] = True
            rec.append((b, topo.size[h]))
            g = topo.nxt[g]
            while g != h:
                w = topo.tail[g]
                if w not in order:
                    discover(w, g, dist[a] + 1)
                    q.append(len(verts) - 1)
                g = topo.nxt[g]
        record.append(tuple(rec))
    level = np.array(
        [d - 0.5 if (d > 0 and near) else float(d) for d, near in zip(dist, edge_near)]
    )
    return _Walk(np.array(verts, dtype=np.int64), level, tuple(record))


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
    def necessary(self) -> bool:
        """``1 = lambda0 > |lambda1| = |lambda2| > |lambda3|`` (Reif's necessary condition)."""
        return self.necessary_reason == ""

    @property
    def necessary_reason(self) -> str:
        """Empty when the necessary condition holds, else what fails."""
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
    ValueError
        A bad kind, size, count, scheme or option.
    """
    kind = _check_kind(kind)
    size = _check_size(size)
    s = get_scheme(scheme)
    if isinstance(s, Scheme):
        unknown = set(options) - set(s.options)
        if unknown:
            raise ValueError(f"scheme {s.name!r} takes {', '.join(s.options) or 'no options'}")
    if isinstance(duals, bool) or not isinstance(duals, (int, np.integer)) or duals < 0:
        raise ValueError(f"duals must be a non-negative integer, got {duals!r}")
    duals = int(duals)
    name = _name(s)
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
            spec = _spectrum(A, img, [_candidate(wk, t_ana) for wk in rot], size)
            ctx = _Context(
                steps, L, p * spec.period, dom, img, spec.vectors, s, dict(options), duals
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


@dataclass
class _Spec:
    values: NDArray[np.complex128]
    vectors: NDArray[np.complex128]
    modes: NDArray[np.int64]
    rotation: int
    period: int


def _spectrum(A, img, rotated_orders, k: int) -> _Spec:
    """Eigenvalues of the local matrix by Fourier modes, rotation taken out.

    ``A`` maps the domain (ordered like ``img``) to the image ``img``;
    ``rotated_orders[1]`` is the image ordered from the start turned by one
    sector (the rotation that block-diagonalizes ``A``).  Turning the
    identification by ``a`` sectors multiplies the eigenvalues of mode w by
    ``exp(2 pi i a w / k)``; the turn chosen makes the subdominant
    eigenvalue's argument smallest.  When that still
    leaves a complex pair that two steps make real (a turn by half a
    sector), the period is 2 and the eigenvalues are squared.
    """
    pos = {int(v): i for i, v in enumerate(img)}
    perm = None
    if len(rotated_orders) > 1:
        order1 = rotated_orders[1]
        if order1.size == img.size and set(order1.tolist()) == set(pos):
            perm = np.array([pos[int(v)] for v in order1], dtype=np.int64)
    blocks = _fourier(A, perm, k) if perm is not None else None
    if blocks is None:  # no rotational symmetry to use: dense, modes unknown
        w, V = np.linalg.eig(A)
        modes = np.full(w.size, -1, dtype=np.int64)
    else:
        w, V, modes = blocks
    # the subdominant: largest modulus after the eigenvalue 1
    order = np.argsort(-np.abs(w), kind="stable")
    unit = order[np.argmin(np.abs(w[order[:3]] - 1.0))] if w.size else 0
    rest = [i for i in order if i != unit]

    # the eigenvalues of the subdominant modulus
    top = [i for i in rest if abs(abs(w[i]) - abs(w[rest[0]])) <= TOL * abs(w[rest[0]])]
    turnable = modes >= 0

    def best_turn(vals):
        if not top or not turnable.all():
            return 0, vals
        cands = []
        for a in range(k):
            turned = vals * np.exp(2j * np.pi * a * modes / k)
            worst = max(abs(float(np.angle(turned[i]))) for i in top)
            cands.append((round(worst, 9), a, turned))
        _, a, turned = min(cands, key=lambda c: (c[0], c[1]))
        return a, turned

    a, vals = best_turn(w)
    period = 1
    if any(_is_complex(vals[i]) for i in top):
        # complex after one step but all real after two (a turn by half a
        # sector): the period is two steps
        a2, vals2 = best_turn(w**2)
        if not any(_is_complex(vals2[i]) for i in top):
            a, vals, period = a2, vals2, 2
    key = np.lexsort(
        (np.angle(vals), np.round(np.abs(np.angle(vals)), 9), -np.round(np.abs(vals), 12))
    )
    return _Spec(vals[key], V[:, key], modes[key], a, period)


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


def _measured_contraction(steps, element) -> float | None:
    ratios = _ring_ratios([st.mesh for st in steps], [st.element for st in steps])
    return extrapolate_ratio(ratios) if ratios else None


# ---------------------------------------------------------------------------
# measured contraction (independent of the matrices)
# ---------------------------------------------------------------------------


def _ring_radius(mesh: Mesh, element) -> float:
    kind, i = element
    v = np.asarray(mesh.vertices)
    if kind == "vertex":
        ring, off = mesh.vertex_ring
        nbrs = mesh.head[ring[off[i] : off[i + 1]]]
        centre = v[i]
    else:
        nbrs = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
        centre = v[nbrs].mean(axis=0)
    return float(np.sqrt(((v[nbrs] - centre) ** 2).sum(axis=1).mean()))


def _ring_ratios(meshes, elements) -> list[float]:
    radii = [
        _ring_radius(m, e)
        for m, e in zip(meshes, elements)
        if e is not None and e[0] == elements[0][0]
    ]
    return [b / a for a, b in itertools.pairwise(radii)]


def extrapolate_ratio(ratios) -> float:
    """Aitken's delta-squared limit of a sequence of ratios (last three terms).

    Falls back to the last ratio when the differences vanish or change sign
    erratically.
    """
    r = [float(x) for x in ratios]
    if not r:
        raise ValueError("no ratios to extrapolate")
    if len(r) < 3:
        return r[-1]
    a, b, c = r[-3:]
    den = (c - b) - (b - a)
    if abs(den) < 1e-15 or (c - b) * (b - a) <= 0:
        return c
    return c - (c - b) ** 2 / den


def ring_contraction(
    scheme="pentagonalize",
    kind: str = "vertex",
    size: int = 3,
    iterations: int = 6,
    duals: int = 2,
    *,
    mesh: Mesh | None = None,
    element: int | None = None,
    **options,
) -> tuple[NDArray[np.float64], float]:
    """The measured contraction of an element's 1-ring, iteration after iteration.

    Computed with :func:`pentanb.subdivide` alone (no matrices, so it checks
    them): the root mean square distance from a surviving vertex to its
    neighbours (or from a surviving face's centroid to its corners) after
    each iteration, and the ratio of consecutive iterations.  For a scheme with a
    stationary neighbourhood the ratio tends to ``|lambda1|`` (the root
    mean square is unchanged by a rotation of the ring, so a complex
    ``lambda1`` gives a steady ratio too).

    The element keeps its index: every remeshing of the package numbers the
    kept vertices and the face copies first, in the input's order, and two
    duals give back the numbering (checked: the valence or size must stay).

    Parameters
    ----------
    scheme, kind, size, duals, **options
        As for :func:`local_spectrum`.
    iterations : int, >= 1
        Repetitions of the scheme, each followed by ``duals`` duals.
    mesh : Mesh, optional
        Start here instead of :func:`pyramid` ``(size)``; ``element`` then
        names the vertex (or face) to follow.

    Returns
    -------
    ratios : (iterations,) float
    limit : float
        Aitken's extrapolation of the ratios (:func:`extrapolate_ratio`).

    Raises
    ------
    ValueError
        When the element does not keep its index and valence (or size).
    """
    kind = _check_kind(kind)
    if mesh is None:
        size = _check_size(size)
        mesh = pyramid(size)
        element = 0 if kind == "vertex" else size
    if element is None:
        raise ValueError("give the element to follow when you give a mesh")
    from ..subdivision import subdivide

    s = get_scheme(scheme)
    el = (kind, int(element))

    def measure(m: Mesh) -> int:
        return int(m.valences[el[1]]) if kind == "vertex" else int(m.face_sizes[el[1]])

    n0 = measure(mesh)
    meshes = [mesh]
    for _ in range(iterations):
        mesh = subdivide(mesh, s, 1, duals, **options)
        count = mesh.n_vertices if kind == "vertex" else mesh.n_faces
        if el[1] >= count or measure(mesh) != n0:
            raise ValueError(
                f"the {kind} {el[1]} does not keep its place under {_name(s)} + {duals} duals"
            )
        meshes.append(mesh)
    ratios = np.array(_ring_ratios(meshes, [el] * len(meshes)))
    return ratios, extrapolate_ratio(ratios)


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
        When the spectrum has no stationary neighbourhood (nothing to draw).
    """
    if not isinstance(spectrum, LocalSpectrum):
        spectrum = local_spectrum(spectrum, kind, size, duals, **options)
    if not spectrum.stationary or spectrum._context is None:
        raise ValueError(f"no characteristic map: {spectrum.note or 'no stationary neighbourhood'}")
    if (
        isinstance(iterations, bool)
        or not isinstance(iterations, (int, np.integer))
        or iterations < 0
    ):
        raise ValueError(f"iterations must be a non-negative integer, got {iterations!r}")
    ctx: _Context = spectrum._context
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


# ---------------------------------------------------------------------------
# the results table (issue 9, item 4)
# ---------------------------------------------------------------------------

#: (label, scheme, options) analysed by :func:`continuity_table`: the paper's
#: schemes first, then every other scheme of the registry.
TABLE_CASES: tuple[tuple[str, str, dict], ...] = (
    ("pentagonalize", "pentagonalize", {}),
    ("preserve_pentagons 0.75", "preserve_pentagons", {"scale": 0.75}),
    ("preserve_pentagons 0.5", "preserve_pentagons", {"scale": 0.5}),
    *((name, name, {}) for name in SCHEMES if name not in ("pentagonalize", "preserve_pentagons")),
)


@dataclass(frozen=True)
class ContinuityRow:
    """One row of the results table: a scheme (+ 2 duals) at one element type.

    Attributes
    ----------
    label : str
        Scheme and options, e.g. ``"preserve_pentagons 0.5"``.
    kind, size : the element
    spectrum : LocalSpectrum or None
    char_map : CharacteristicMap or None
    fate : str
        What the element becomes when it does not survive.
    """

    label: str
    kind: str
    size: int
    spectrum: LocalSpectrum | None
    char_map: CharacteristicMap | None
    fate: str = ""

    @property
    def element(self) -> str:
        return f"{self.kind} {self.size}"

    def lam(self, i: int) -> str:
        """Eigenvalue ``i`` as the table shows it: its modulus per step, and
        its argument in degrees when it is complex (``"0.3840∠20.2°"``).

        Parameters
        ----------
        i : int, >= 0
            Index into the spectrum's eigenvalues (sorted by modulus, decreasing).

        Returns
        -------
        str
            Empty when there is no stationary spectrum or no eigenvalue ``i``.
        """
        if self.spectrum is None or not self.spectrum.stationary:
            return ""
        sp = self.spectrum
        if i >= sp.eigenvalues.size:
            return ""
        z = sp.eigenvalues[i]
        mod = abs(z) ** (1.0 / sp.period)
        if abs(z.imag) > 1e-9 * max(abs(z), 1e-300):
            return f"{mod:.4f}∠{math.degrees(np.angle(z)):.1f}°"
        return f"{mod:.4f}" if z.real >= 0 else f"-{mod:.4f}"

    @property
    def necessary(self) -> str:
        if self.spectrum is None or not self.spectrum.stationary:
            return "n/a"
        r = self.spectrum.necessary_reason
        return "holds" if not r else f"fails: {r}"

    @property
    def verdict(self) -> str:
        if self.char_map is None:
            return "n/a"
        return self.char_map.verdict

    @property
    def c1(self) -> str:
        """``yes`` / ``no`` / ``undecided`` with the reason."""
        sp = self.spectrum
        if sp is None:
            return "n/a"
        if not sp.stationary:
            return "undecided (no stationary neighbourhood)"
        if not sp.necessary:
            return "no (necessary condition fails)"
        cm = self.char_map
        if cm is None or not cm.injective:
            return "no (characteristic map not injective)" if cm is not None else "undecided"
        if sp.subdominant_complex:
            return "undecided (complex subdominant pair; Reif's criterion is for real ones)"
        if not _spline_background(self.label):
            return "undecided (no C1 spline away from the element; map injective numerically)"
        return "yes (Reif's criterion; map injective numerically)"


def _spline_background(label: str) -> bool:
    """Is the surface away from extraordinary elements a known C1 spline?

    Only vertex insertion + 2 duals: bilinear subdivision plus quad
    averaging (Warren and Weimer 2001, Section 7.2), the bicubic B-spline
    on regular quads.
    """
    return label == "vertex_insertion"


def continuity_table(
    cases=TABLE_CASES,
    sizes=range(3, 9),
    duals: int = 2,
    *,
    map_iterations: int = 2,
    progress: Callable[[str], None] | None = None,
) -> list[ContinuityRow]:
    """The results table: every scheme + ``duals`` duals at every element type.

    Parameters
    ----------
    cases : sequence of (label, scheme, options)
        Default :data:`TABLE_CASES`.
    sizes : iterable of int
        Valences and face sizes (default 3 to 8).
    duals : int
    map_iterations : int
        Iterations of the characteristic map's control net
        (:func:`characteristic_map`'s ``iterations``).
    progress : callable, optional
        Called with a line of text after every row.

    Returns
    -------
    list of ContinuityRow
        For each case, a row per vertex valence, then per face size, for the
        elements that survive the scheme; an element that does not survive
        gets one row saying what it becomes (``spectrum`` None).
    """
    rows: list[ContinuityRow] = []
    sizes = list(sizes)
    for label, scheme, options in cases:
        for kind in KINDS:
            fates = {n: element_fate(scheme, kind, n, **options) for n in sizes}
            lost = {n: f for n, f in fates.items() if not f.startswith(kind)}
            if lost:
                rows.append(ContinuityRow(label, kind, min(lost), None, None, _fate_rule(lost)))
            kept = [n for n in sizes if n not in lost]
            for n in kept:
                sp = local_spectrum(scheme, kind, n, duals, **options)
                if not sp.refines:
                    rows.append(ContinuityRow(label, kind, n, None, None, sp.note))
                    break
                cm = None
                if sp.stationary and sp.eigenvalues.size > 3:
                    cm = characteristic_map(sp, iterations=map_iterations)
                row = ContinuityRow(label, kind, n, sp, cm)
                rows.append(row)
                if progress:
                    progress(f"{label} {kind} {n}: {row.lam(1)} {row.c1}")
    return rows


def _fate_rule(lost: dict[int, str]) -> str:
    """``"3: becomes a vertex of valence 3; 4: ..."`` condensed."""
    return "; ".join(f"{n}: {text}" for n, text in sorted(lost.items()))


def table_markdown(rows: list[ContinuityRow]) -> str:
    """The table as markdown (for the README).

    Parameters
    ----------
    rows : list of ContinuityRow
        From :func:`continuity_table`.

    Returns
    -------
    str
        A header and one table line per row, ending with a newline.
    """
    head = (
        "| scheme + 2 duals | element | period | N | λ1 | λ2 | λ3 | λ4 | "
        "necessary condition | characteristic map | C1 |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n"
    )
    lines = []
    for r in rows:
        sp = r.spectrum
        if sp is None:
            what = "vertices" if r.kind == "vertex" else "faces"
            lines.append(f"| {r.label} | {what} | | | | | | | | | {r.fate} |")
            continue
        period = str(sp.period) if sp.stationary else ""
        size = f"{sp.neighbourhood}/{sp.analysis_size}" if sp.stationary else ""
        lines.append(
            f"| {r.label} | {r.element} | {period} | {size} | {r.lam(1)} | {r.lam(2)} | "
            f"{r.lam(3)} | {r.lam(4)} | {r.necessary} | {r.verdict} | {r.c1} |"
        )
    return head + "\n".join(lines) + "\n"
