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
   >= ...``.  *Reif's standard setting* is ``|lambda1| = |lambda2| >
   |lambda3|`` (Reif 1995; Peters and Reif, *Subdivision Surfaces*, 2008,
   Ch. 5; Zorin 2000): the setting of the sufficient condition below, not
   a necessary condition for a tangent plane.  What is necessary, for
   generic control points, is a pair of leading eigenvectors whose planar
   map can be regular and injective -- in the standard setting, a double
   subdominant eigenvalue (real, or a complex pair).  A simple ``lambda1``
   gives no pair, and where its eigenvector has Fourier mode 0 no map built
   on it is injective and the limit normal turns around the element; three
   or more eigenvalues of the subdominant modulus leave rings that are not
   flat, so no tangent plane either
   (:attr:`LocalSpectrum.map_obstruction`).
3. The *characteristic map* is the limit of subdividing the planar control
   net whose coordinates are the two subdominant eigenvectors; it exists
   only when exactly two eigenvalues lead.  If it is regular (no fold) and
   injective (one sheet), the scheme is C1 at the element -- Reif's
   sufficient condition, stated for a real double subdominant eigenvalue
   (:func:`characteristic_map`).

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
mode w by ``exp(2 pi i a w / size)`` and leaves their moduli alone.  A
scheme that turns its neighbourhood by half a sector per step (pentagon
preservation at its faces, whose corners are scaled edge midpoints;
sqrt(3) and honeycomb) cannot be identified with itself over one step
without that half turn; it is analysed over the two steps that bring it
back (``period`` 2).  The half turn is read from the neighbourhood (a new
corner leans equally on two old ones), so the period does not depend on
which eigenvalue leads.  The turn taken out is the one that leaves the
fewest non-real eigenvalues over the whole spectrum, then the smallest
subdominant argument.  A *chiral* scheme (pentagonalization, whose
pentagons have no mirror symmetry) turns its neighbourhood by an angle
that no relabelling removes: its subdominant eigenvalues are a complex
pair, reported with their argument.

What is established and what is not.  The eigenvalues reported are
computed in floating point from the assembled matrix; the weights are
rational, and :func:`exact_ordering` establishes the ordering of the
leading ones in exact arithmetic (the characteristic polynomial, split by
Fourier modes; Schur-Cohn counts of roots in discs of rational radius;
Sturm counts of real roots; exact gcds).  The characteristic map is drawn
from its control net a few iterations down; the verdict on it (all faces
turn the same way, the boundary winds once) is numerical evidence, not a
proof of regularity or injectivity of the limit map.  Reif's criterion
also assumes a C1 surface away from the element (true for spline-based
schemes such as vertex insertion + 2 duals, which is bicubic on regular
regions) and a real double subdominant eigenvalue; where either is missing
the statement is left *undecided*.

Pentagon preservation's scale.  One remeshing step is affine in the
scale, so the local matrix is too (:func:`scale_family`);
:func:`scale_study` maps the standard setting along the scale for 2, 4 and
6 duals, each change established exactly, and recommends a scale.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .. import _checks
from .. import schemes as _schemes
from ..memory import default_max_bytes, mesh_bytes, readable
from ..mesh import Mesh, MeshError
from ..notation import seeds
from ..schemes.registry import SCHEMES, Scheme
from ..subdivision import get_scheme, predict_counts
from . import _exact
from .subdivision_matrix import _name, dual_matrix, remesh_matrix

__all__ = [
    "KINDS",
    "ExactSpectrum",
    "exact_local_matrix",
    "exact_ordering",
    "ScaleFamily",
    "ScaleThreshold",
    "scale_family",
    "scale_threshold",
    "scale_map",
    "ScaleStudy",
    "scale_study",
    "SCALE_SCHEME",
    "SCALE_GRID",
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
#: Most duals after each remeshing (the paper's smoothing takes 2).
MAX_DUALS = 64
#: Largest mesh (faces) the characteristic map's levels may reach (the
#: figure's maps reach 40,000).
MAP_MAX_FACES = 1_000_000
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
    return _checks.count(size, "size", 3)


def _refuse_pyramid(size: int, max_faces: int | None = None) -> None:
    """Refuse, before building it, a pyramid of more than ``max_faces`` faces or
    more than the memory available (a ValueError naming ``size``)."""
    if max_faces is not None and size + 1 > max_faces:
        raise ValueError(
            f"size={size:,}: the pyramid it is planted in has {size + 1:,} faces, over "
            f"max_faces={max_faces:,}"
        )
    need, limit = mesh_bytes(size + 1, 2 * size, size + 1), default_max_bytes()
    if need > limit:
        raise ValueError(
            f"size={size:,}: the pyramid it is planted in needs {readable(need)}, over the "
            f"memory available ({readable(limit)})"
        )


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


def _measured_contraction(steps, element) -> float | None:
    ratios = _ring_ratios([st.mesh for st in steps], [st.element for st in steps])
    return extrapolate_ratio(ratios) if ratios else None


# ---------------------------------------------------------------------------
# measured contraction (independent of the matrices)
# ---------------------------------------------------------------------------


def _ring_points(mesh: Mesh, element) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
    """The points around the element and its centre.

    A vertex: its neighbours, about the vertex.  A face: its corners *and*
    their neighbours, about the mean of the corners.  The corners alone
    would miss Fourier mode 0 (which moves every corner alike, so their
    offsets from their own mean do not see it); the ring one edge further
    out sees every mode.
    """
    kind, i = element
    v = np.asarray(mesh.vertices)
    ring, off = mesh.vertex_ring
    if kind == "vertex":
        return mesh.head[ring[off[i] : off[i + 1]]], v[i]
    corners = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
    around = np.concatenate([mesh.head[ring[off[c] : off[c + 1]]] for c in corners])
    return np.unique(np.concatenate([corners, around])), v[corners].mean(axis=0)


def _ring_radius(mesh: Mesh, element) -> float:
    """Root mean square distance from the element's centre to the points around it
    (:func:`_ring_points`)."""
    pts, centre = _ring_points(mesh, element)
    v = np.asarray(mesh.vertices)
    return float(np.sqrt(((v[pts] - centre) ** 2).sum(axis=1).mean()))


def _mode_radii(mesh: Mesh, element) -> tuple[float, float] | None:
    """Root mean square offsets of the points around the element, split into
    Fourier mode 0 and the other modes, or None when the neighbourhood is not
    k-fold symmetric.

    The walks from the element's ``k`` half-edges order the points sector by
    sector (connectivity only, no weights): averaging a point's offset over
    its ``k`` turned copies keeps mode 0, the remainder is every other mode.
    Each part contracts at the rate of its own leading eigenvalue, so a
    simple ``lambda1`` of mode 0 close to the next eigenvalue of another mode
    (pentagon preservation at triangles) is not hidden behind it.
    """
    topo = _Topo(mesh)
    walks = [_walk(topo, element, h, 1) for h in _starts(mesh, element)]
    if len({w.signature for w in walks}) != 1:
        return None
    n = min(int(np.sum(walks[0].level <= 1.0)), *(w.verts.size for w in walks))
    idx = np.stack([w.verts[:n] for w in walks])  # (k, n): a point and its turned copies
    if np.any(walks[0].level[:n] > 1.0):
        return None
    v = np.asarray(mesh.vertices)
    _, centre = _ring_points(mesh, element)
    x = v[idx] - centre  # (k, n, 3)
    mean = x.mean(axis=0, keepdims=True)
    rest = x - mean
    return (
        float(np.sqrt((mean**2).sum(axis=-1).mean())),
        float(np.sqrt((rest**2).sum(axis=-1).mean())),
    )


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


def _refuse_levels(start, s, iterations: int, duals: int) -> None:
    """Refuse, before anything is built, ``iterations`` levels of ``s`` from
    ``start`` counts that are all kept: one too large for memory (as
    :func:`pentanb.subdivide` refuses it), all together over the memory
    available (MeshError), or too many steps (ValueError)."""
    if not isinstance(s, Scheme):  # a callable: subdivide guards every level
        _checks.steps(iterations * (1 + duals), f"{iterations:,} iterations with {duals:,} duals")
        return
    after = predict_counts(start, s, iterations, duals)
    kept = sum(mesh_bytes(*c) for c in after[duals :: 1 + duals])
    limit = default_max_bytes()
    if kept > limit:
        raise MeshError(
            f"{iterations:,} iterations of {_name(s)} keep meshes of {readable(kept)} in all, "
            f"over the memory available ({readable(limit)}); lower iterations"
        )


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
    them): the offsets of the points around a surviving vertex (its
    neighbours) or face (its corners and their neighbours: the corners
    alone would miss Fourier mode 0, which moves them alike) from its
    centre, after each iteration, split into mode 0 (the mean of a point's
    offset over its ``k`` turned copies, found by connectivity alone) and
    the other modes; the root mean square of each part, and the ratio of
    consecutive iterations.  Each part tends to the modulus of its own
    leading eigenvalue, so the slower part's ratio tends to ``|lambda1|``
    whatever its mode (a complex ``lambda1`` turns the ring and leaves the
    root mean square alone), without waiting for one mode to outgrow a
    close one of another mode (pentagon preservation at triangles, where
    ``|lambda2 / lambda1| = 0.82`` at scale 0.5).  Without k-fold
    symmetry the two parts are not split.

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
        The ratios of the part (mode 0, or the other modes) that contracts
        slowest.
    limit : float
        Aitken's extrapolation of those ratios (:func:`extrapolate_ratio`).

    Raises
    ------
    TypeError
        A size or count that is not an integer.
    ValueError
        When the element does not keep its index and valence (or size); a
        count out of range.
    MeshError
        Before anything is built, when the meshes (every level is kept)
        would not fit in memory.
    """
    kind = _check_kind(kind)
    iterations = _checks.count(iterations, "iterations", 1)
    duals = _checks.count(duals, "duals", 0, MAX_DUALS)
    s = get_scheme(scheme)
    if mesh is None:
        size = _check_size(size)
        _refuse_pyramid(size)
        start = (size + 1, 2 * size, size + 1)
    else:
        start = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    _refuse_levels(start, s, iterations, duals)
    if mesh is None:
        mesh = pyramid(size)
        element = 0 if kind == "vertex" else size
    if element is None:
        raise ValueError("give the element to follow when you give a mesh")
    from ..subdivision import subdivide

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
    split = [_mode_radii(m, el) for m in meshes]
    if any(x is None for x in split):
        ratios = np.array(_ring_ratios(meshes, [el] * len(meshes)))
        return ratios, extrapolate_ratio(ratios)
    radii = np.array(split, dtype=np.float64)  # (levels, 2): mode 0, the other modes
    best: tuple[float, NDArray[np.float64]] | None = None
    for part in radii.T:
        if part[-1] <= 1e-12 * radii[-1].max():
            continue  # no such mode in the data (a symmetric start)
        r = part[1:] / part[:-1]
        lim = extrapolate_ratio(r)
        if best is None or lim > best[0]:
            best = (lim, r)
    assert best is not None
    return best[1], best[0]


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
    from .subdivision_matrix import exact_remesh_matrix

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


# ---------------------------------------------------------------------------
# the results table
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
        None where the element has no characteristic map (``map_note`` says
        why) or no spectrum.
    fate : str
        What the element becomes when it does not survive.
    map_note : str
        Why there is no characteristic map (:attr:`LocalSpectrum.map_obstruction`).
    exact : ExactSpectrum or None
        The leading eigenvalues established in exact arithmetic
        (:func:`exact_ordering`), when the table was asked for them.
    """

    label: str
    kind: str
    size: int
    spectrum: LocalSpectrum | None
    char_map: CharacteristicMap | None
    fate: str = ""
    map_note: str = ""
    exact: ExactSpectrum | None = None

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
    def standard(self) -> str:
        """``"holds"`` / ``"fails: <what>"`` for Reif's standard setting
        (:attr:`LocalSpectrum.standard`), ``"exact"`` added where
        :func:`exact_ordering` established it; ``"n/a"`` without a spectrum."""
        if self.spectrum is None or not self.spectrum.stationary:
            return "n/a"
        r = self.spectrum.standard_reason
        text = "holds" if not r else f"fails: {r}"
        if self.exact is not None and self.exact.decided:
            text += " (exact)" if self.exact.standard == (not r) else " (exact disagrees)"
        return text

    @property
    def necessary(self) -> str:
        """The old name of :attr:`standard`; kept for old code."""
        return self.standard

    @property
    def verdict(self) -> str:
        """The characteristic map's verdict, or ``"none: <why>"`` where there is none."""
        if self.char_map is not None:
            return self.char_map.verdict
        if self.map_note:
            return f"none: {self.map_note}"
        return "n/a"

    @property
    def c1(self) -> str:
        """``yes`` / ``no`` / ``undecided`` with the reason.

        ``no`` is said for generic control points: where no characteristic
        map exists (a simple ``lambda1`` of Fourier mode 0, or three or more
        eigenvalues of the subdominant modulus: no tangent plane, see
        :attr:`LocalSpectrum.map_obstruction`), or where the map is not
        injective.
        """
        sp = self.spectrum
        if sp is None:
            return "n/a"
        if not sp.stationary:
            return "undecided (no stationary neighbourhood)"
        n = sp.subdominant_count
        if n == 1:
            mode = int(sp.modes[1]) if sp.modes.size > 1 else -1
            if mode == 0:
                return (
                    "no tangent plane for generic control points "
                    "(lambda1 simple, of Fourier mode 0)"
                )
            return "undecided (lambda1 simple)"
        if n >= 3:
            return (
                f"no tangent plane for generic control points ({n} eigenvalues of the "
                "subdominant modulus)"
            )
        cm = self.char_map
        if cm is None:
            return "undecided"
        if not cm.injective:
            return "no (characteristic map not injective)"
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
    exact: bool | Callable[[str], bool] = False,
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
    exact : bool or callable
        Establish the leading eigenvalues of every row in exact arithmetic
        (:func:`exact_ordering`, in :attr:`ContinuityRow.exact`); a callable
        ``exact(label) -> bool`` chooses the cases.

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
        want_exact = exact(label) if callable(exact) else bool(exact)
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
                cm, why = None, ""
                if sp.stationary:
                    why = sp.map_obstruction
                    if not why:
                        cm = characteristic_map(sp, iterations=map_iterations)
                ex = exact_ordering(sp) if want_exact and sp.stationary else None
                row = ContinuityRow(label, kind, n, sp, cm, map_note=why, exact=ex)
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
        "standard setting | characteristic map | C1 |\n"
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
            f"{r.lam(3)} | {r.lam(4)} | {r.standard} | {r.verdict} | {r.c1} |"
        )
    return head + "\n".join(lines) + "\n"
