"""The limit surface at the control vertices: positions, normals, curvature measures.

Beyond the paper (Section 7 leaves convergence open).  Around an element
(a vertex of valence k, or a k-gon) that a scheme keeps, one step of
"remesh, then duals" maps a neighbourhood onto itself by the local
subdivision matrix ``A`` of :func:`pentanb.analysis.local_spectrum`.  Its
eigenvalues are ``1 = lambda0 > |lambda1| = |lambda2| > |lambda3| >= ...``
where Reif's standard setting holds, and, writing ``l_i`` for the *left*
eigenvectors (``l_i A = lambda_i l_i``) and ``P`` for the positions of the
neighbourhood (Warren and Weimer 2001, Ch. 8; Peters and Reif 2008, Ch. 5):

* the limit position of the element is ``l0 . P``, with ``l0`` normalised
  to ``sum(l0) = 1`` (the rows of ``A`` sum to 1);
* the limit tangent plane is spanned by ``l1 . P`` and ``l2 . P`` (for a
  complex pair, the real and imaginary parts of ``l1``): the limit normal
  is their cross product.

:func:`limit_points` and :func:`limit_normals` do that at every vertex (or
face) of a closed mesh, :func:`limit_stencil` gives the weights at one,
and :func:`limit_convergence` checks them against levels of actual
subdivision (:func:`pentanb.subdivide`): the distance from the limit falls
at the rate the spectrum predicts, and a wrong eigenvector leaves a
distance that does not fall.

:func:`curvature_measures` reads the spectrum for what it says about the
limit surface's second order (Peters and Reif 2008, Ch. 7; Peters and
Umlauf 2000): with ``lambda = |lambda1|`` and ``mu = |lambda3|`` (the
largest modulus after the subdominant pair), per step,

* the rings around the element lie at distances ``~ lambda^m`` and leave
  the tangent plane by ``~ mu^m``, so the curvature on ring m is
  ``~ (mu / lambda^2)^m``: for generic control points it is bounded only
  where ``mu <= lambda^2`` (and tends to 0, a flat point, where
  ``mu < lambda^2``) and diverges where ``mu > lambda^2``;
* the normal turns by ``~ (mu / lambda)^m`` on ring m, so it is Hölder
  continuous with exponent ``alpha = log(lambda / mu) / log(1 / lambda)``
  (``|n(x) - n(0)| ~ |x|^alpha``): a per-distance measure, beside the
  per-step gap ``(lambda - mu) / lambda``.

These are generic statements about the leading eigenvalues (special
control points, whose component on the ``mu`` eigenvectors vanishes, do
better); they assume the standard setting and, like Reif's criterion, a
well-behaved surface on the rings, which is not established for the
paper's schemes (see ``docs/continuity.md``).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..mesh import Mesh, MeshError

__all__ = [
    "LimitStencil",
    "limit_stencil",
    "limit_points",
    "limit_normals",
    "LimitConvergence",
    "limit_convergence",
    "CurvatureMeasure",
    "curvature_measures",
    "curvature_table",
    "curvature_markdown",
]

#: Relative tolerance for eigenvalue moduli taken as equal.
TOL = 1e-7


# ---------------------------------------------------------------------------
# the stencils
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class LimitStencil:
    """The limit position and tangent weights of one element of a mesh.

    Attributes
    ----------
    scheme : str
    kind : {"vertex", "face"}
        What the element is in the mesh handed in.
    element : int
        Its index in that mesh.
    size : int
        Valence of the vertex, or sides of the face.
    level : int
        Steps of the scheme (from the mesh handed in) after which the
        neighbourhood is stationary; the weights apply to that level.
    tracked : tuple of (str, int)
        What the element is at ``level`` (``("vertex", i)`` or ``("face", f)``).
    vertices : (m,) int
        The neighbourhood's vertices at ``level``, in the order of ``matrix``.
    positions : (m, 3) float
        Their positions at ``level``.
    matrix : (m, m) float
        The local subdivision matrix of one step.
    weights : (m,) float
        ``l0``: the left eigenvector of the eigenvalue 1, summing to 1.
    tangent_weights : (2, m) float or None
        A real basis of the left eigenspace of the subdominant pair
        (orthonormal rows); None where there is no such pair
        (``note`` says why).
    lambda1, lambda_next : float
        Per-step moduli of the subdominant eigenvalues and of the largest
        one after them.
    centre : (m,) float
        The element's own point as a combination of the neighbourhood (the
        vertex, or the mean of the face's corners): what
        :func:`limit_convergence` follows.
    note : str
    """

    scheme: str
    kind: str
    element: int
    size: int
    level: int
    tracked: tuple[str, int]
    vertices: NDArray[np.int64] = field(repr=False)
    positions: NDArray[np.float64] = field(repr=False)
    matrix: NDArray[np.float64] = field(repr=False)
    weights: NDArray[np.float64] = field(repr=False)
    tangent_weights: NDArray[np.float64] | None = field(repr=False)
    lambda1: float
    lambda_next: float
    centre: NDArray[np.float64] = field(repr=False)
    orientation: NDArray[np.float64] = field(repr=False)
    options: dict = field(default_factory=dict)
    note: str = ""

    @property
    def point(self) -> NDArray[np.float64]:
        """(3,) float: the limit position ``l0 . P``."""
        return np.asarray(self.weights @ self.positions, dtype=np.float64)

    @property
    def tangents(self) -> NDArray[np.float64] | None:
        """(2, 3) float: two vectors spanning the limit tangent plane, or None."""
        if self.tangent_weights is None:
            return None
        return np.asarray(self.tangent_weights @ self.positions, dtype=np.float64)

    @property
    def normal(self) -> NDArray[np.float64]:
        """(3,) float: the unit limit normal, turned to the mesh's side; NaN
        where there is no tangent plane (``note``)."""
        t = self.tangents
        if t is None:
            return np.full(3, np.nan)
        n = np.cross(t[0], t[1])
        norm = float(np.linalg.norm(n))
        if not norm > 0:
            return np.full(3, np.nan)
        n = n / norm
        return -n if float(n @ self.orientation) < 0 else n


def _scheme_name(scheme) -> str:
    name = getattr(scheme, "name", scheme)
    return name if isinstance(name, str) else getattr(scheme, "__name__", repr(scheme))


def _closed_mesh(mesh) -> Mesh:
    if not isinstance(mesh, Mesh):
        raise TypeError(f"mesh must be a pentanb.Mesh, got {type(mesh).__name__}")
    if not mesh.is_closed:
        raise MeshError(
            "limit positions here need a closed mesh; this one has "
            f"{mesh.n_boundary_loops} boundary loop(s) (the boundary follows its own curve "
            "rule: pentanb.analysis.boundary_spectrum)"
        )
    return mesh


def _left_spaces(A: NDArray[np.float64]) -> tuple[NDArray, NDArray | None, float, float, str]:
    """``l0`` (sum 1), an orthonormal real basis of the subdominant left
    eigenspace (or None), its per-step modulus and the next modulus."""
    w, VL = np.linalg.eig(A.T)
    mod = np.abs(w)
    order = np.argsort(-mod, kind="stable")
    unit = int(order[np.argmin(np.abs(w[order[:3]] - 1.0))])
    l0 = VL[:, unit].real
    l0 = l0 / l0.sum()
    rest = [int(i) for i in order if i != unit]
    if not rest:
        return l0, None, 0.0, 0.0, "neighbourhood too small"
    lam1 = float(mod[rest[0]])
    group = [i for i in rest if abs(mod[i] - lam1) <= TOL * max(lam1, 1e-300)]
    after = [i for i in rest if i not in group]
    lam_next = float(mod[after[0]]) if after else 0.0
    if len(group) != 2:
        what = "simple" if len(group) == 1 else f"{len(group)}-fold"
        return l0, None, lam1, lam_next, f"the subdominant eigenvalue is {what}: no tangent pair"
    parts = np.concatenate([VL[:, group].real.T, VL[:, group].imag.T])
    _, sv, vt = np.linalg.svd(parts, full_matrices=False)
    if sv.size < 2 or sv[1] <= 1e-9 * sv[0]:
        return l0, None, lam1, lam_next, "the subdominant left eigenspace is defective"
    return l0, vt[:2], lam1, lam_next, ""


def _faces_at(mesh: Mesh, v: int) -> NDArray[np.int64]:
    idx = np.flatnonzero(mesh.corners == v)
    return np.searchsorted(mesh.offsets, idx, side="right") - 1


def _element_normal(mesh: Mesh, tracked: tuple[str, int]) -> NDArray[np.float64]:
    kind, i = tracked
    faces = _faces_at(mesh, i) if kind == "vertex" else np.array([i])
    n = mesh.face_normals[faces].sum(axis=0)
    return np.asarray(n / max(float(np.linalg.norm(n)), 1e-300), dtype=np.float64)


def _element_point(mesh: Mesh, tracked: tuple[str, int]) -> NDArray[np.float64]:
    kind, i = tracked
    if kind == "vertex":
        return np.asarray(mesh.vertices[i], dtype=np.float64)
    c = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
    return np.asarray(mesh.vertices[c].mean(axis=0), dtype=np.float64)


def limit_stencil(
    mesh: Mesh,
    scheme="pentagonalize",
    kind: str = "vertex",
    element: int = 0,
    duals: int = 2,
    **options,
) -> LimitStencil:
    """The limit position and tangent weights of one vertex or face of a closed mesh.

    The element is followed through the scheme by
    :func:`pentanb.analysis.local_spectrum` (planted in ``mesh``) until
    its neighbourhood is stationary; the weights are the left eigenvectors
    of that neighbourhood's local subdivision matrix.  Pentagonalization
    turns every face into a vertex of the same valence: a face is then
    followed as the vertex ``V + 2E + f`` of one step of the scheme (the
    face points come after the ``V`` old vertices and the ``2E`` edge
    points, and two duals give every vertex back with its index).

    Parameters
    ----------
    mesh : Mesh
        A closed mesh.
    scheme : str or Scheme
        As for :func:`pentanb.subdivide`; the paper's two schemes with 2
        duals are what the tests check.
    kind : {"vertex", "face"}
    element : int
        The vertex or face index.
    duals : int
    **options
        The scheme's options (``scale=...``).

    Returns
    -------
    LimitStencil

    Raises
    ------
    TypeError
        A mesh that is not a :class:`~pentanb.Mesh`.
    MeshError
        An open mesh.
    ValueError
        An element that does not exist, or whose neighbourhood never
        becomes stationary (the note of the local spectrum says why).
    """
    from .. import subdivide
    from . import local_spectrum

    mesh = _closed_mesh(mesh)
    if kind not in ("vertex", "face"):
        raise ValueError(f"kind must be 'vertex' or 'face', got {kind!r}")
    count = mesh.n_vertices if kind == "vertex" else mesh.n_faces
    if isinstance(element, bool) or not isinstance(element, (int, np.integer)):
        raise TypeError(f"element must be an integer, got {element!r}")
    element = int(element)
    if not 0 <= element < count:
        raise ValueError(f"{kind} {element} does not exist (the mesh has {count})")
    size = int(mesh.valences[element] if kind == "vertex" else mesh.face_sizes[element])
    spec = local_spectrum(scheme, kind, size, duals, mesh=mesh, element=element, **options)
    offset = 0
    if not spec.stationary and "becomes a vertex" in spec.note:
        # pentagonalization: the face is the vertex V + 2E + f after one step
        one = subdivide(mesh, scheme, 1, duals, **options)
        v = mesh.n_vertices + 2 * mesh.n_edges + element
        if v >= one.n_vertices or int(one.valences[v]) != size:
            raise ValueError(f"face {element}: {spec.note}, not found after one step")
        spec = local_spectrum(scheme, "vertex", size, duals, mesh=one, element=v, **options)
        offset = 1
    if not spec.stationary or spec._context is None:
        raise ValueError(f"{kind} {element}: {spec.note or 'no stationary neighbourhood'}")
    ctx = spec._context  # the hierarchy local_spectrum built from `mesh`
    level_mesh: Mesh = ctx.steps[ctx.level].mesh
    tracked = ctx.steps[ctx.level].element
    dom = np.asarray(ctx.domain, dtype=np.int64)
    A = np.asarray(spec.matrix, dtype=np.float64)
    l0, tw, lam1, lam_next, note = _left_spaces(A)
    centre = np.zeros(dom.size)
    if tracked[0] == "vertex":
        centre[np.flatnonzero(dom == tracked[1])] = 1.0
    else:
        c = level_mesh.corners[level_mesh.offsets[tracked[1]] : level_mesh.offsets[tracked[1] + 1]]
        centre[np.isin(dom, c)] = 1.0 / c.size
    if abs(centre.sum() - 1.0) > 1e-12:  # pragma: no cover - the element is in its neighbourhood
        raise ValueError(f"{kind} {element}: the element is not in its neighbourhood")
    return LimitStencil(
        scheme=_scheme_name(spec.scheme),
        kind=kind,
        element=element,
        size=size,
        level=int(ctx.level) + offset,
        tracked=(str(tracked[0]), int(tracked[1])),
        vertices=dom,
        positions=np.asarray(level_mesh.vertices[dom], dtype=np.float64),
        matrix=A,
        weights=l0,
        tangent_weights=tw,
        lambda1=lam1,
        lambda_next=lam_next,
        centre=centre,
        orientation=_element_normal(level_mesh, tracked),
        options=dict(options),
        note=note,
    )


def _elements(mesh: Mesh, kind: str, elements) -> list[int]:
    count = mesh.n_vertices if kind == "vertex" else mesh.n_faces
    if elements is None:
        return list(range(count))
    return [int(e) for e in np.atleast_1d(np.asarray(elements, dtype=np.int64))]


def _stencils(mesh, scheme, duals, kind, elements, options) -> list[LimitStencil]:
    mesh = _closed_mesh(mesh)
    return [
        limit_stencil(mesh, scheme, kind, e, duals, **options)
        for e in _elements(mesh, kind, elements)
    ]


def limit_points(
    mesh: Mesh,
    scheme="pentagonalize",
    duals: int = 2,
    *,
    kind: str = "vertex",
    elements: Iterable[int] | None = None,
    **options,
) -> NDArray[np.float64]:
    """Limit positions of the vertices (or face centres) of a closed mesh.

    Parameters
    ----------
    mesh : Mesh
        A closed mesh.
    scheme : str or Scheme
    duals : int
    kind : {"vertex", "face"}
    elements : sequence of int, optional
        The vertices (or faces) wanted; default all.  Each one is followed
        through the scheme on its own (:func:`limit_stencil`, about 0.05-0.5 s
        per element on a small mesh), so ask for the ones you need.
    **options
        The scheme's options.

    Returns
    -------
    (n, 3) float
        One limit position per element asked for, in order.
    """
    st = _stencils(mesh, scheme, duals, kind, elements, options)
    return np.array([s.point for s in st], dtype=np.float64).reshape(len(st), 3)


def limit_normals(
    mesh: Mesh,
    scheme="pentagonalize",
    duals: int = 2,
    *,
    kind: str = "vertex",
    elements: Iterable[int] | None = None,
    **options,
) -> NDArray[np.float64]:
    """Unit limit normals at the vertices (or face centres) of a closed mesh.

    The normal is the cross product of the two limit tangents (the
    subdominant left eigenvectors applied to the neighbourhood), turned to
    the side of the mesh's own face normals there.

    Parameters
    ----------
    As for :func:`limit_points`.

    Returns
    -------
    (n, 3) float
        NaN rows where the element has no subdominant pair (pentagon
        preservation at scale 0.5 around a triangle: a simple
        ``lambda1``, no tangent plane for generic control points).
    """
    st = _stencils(mesh, scheme, duals, kind, elements, options)
    return np.array([s.normal for s in st], dtype=np.float64).reshape(len(st), 3)


# ---------------------------------------------------------------------------
# the check against actual subdivision
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class LimitConvergence:
    """The limit of a stencil against levels of actual subdivision.

    Attributes
    ----------
    stencil : LimitStencil
    levels : (n,) int
        Levels measured, from the mesh handed in (``stencil.level`` on).
    distances : (n,) float
        ``|x_level - limit|``: the element's point (vertex, or mean of the
        face's corners) after actual subdivision, from the stencil's limit.
    predicted : (n,) float
        The same distances from the local matrix's powers,
        ``|centre A^j P - l0 P|``.
    rate : float
        The spectrum's prediction for the fall of ``distances`` per step:
        the largest modulus, after 1, of an eigenvalue whose right
        eigenvector reaches the element's point.
    measured_rate : float
        ``(d_last / d_first) ** (1 / steps)`` over the last three levels.
    normal_angles : (n,) float
        Angle (radians) between the mesh's normal at the element (the
        normalised sum of its faces' normals) and the limit normal; NaN
        without a tangent plane.
    normal_rate : float
        The spectrum's bound for their fall per step, ``lambda_next / lambda1``.
    """

    stencil: LimitStencil
    levels: NDArray[np.int64]
    distances: NDArray[np.float64]
    predicted: NDArray[np.float64]
    rate: float
    measured_rate: float
    normal_angles: NDArray[np.float64]
    normal_rate: float

    @property
    def scale(self) -> float:
        """Size of the neighbourhood (largest distance of its points from the limit)."""
        p = self.stencil.positions
        return float(np.linalg.norm(p - self.stencil.point, axis=1).max())

    @property
    def agrees(self) -> bool:
        """The actual subdivision follows the local matrix (distances to 1e-9 of the
        neighbourhood's size) and the distance falls at the predicted rate (to 10 %)."""
        tol = 1e-9 * self.scale
        same = bool(np.all(np.abs(self.distances - self.predicted) <= tol + 1e-9 * self.predicted))
        small = self.distances[-1] <= tol
        return same and (small or abs(self.measured_rate - self.rate) <= 0.1 * self.rate)

    @property
    def normals_agree(self) -> bool:
        """The mesh's normal at the element turns towards the limit normal at least as
        fast as the spectrum's bound allows (every step, to 10 %), or is already on it
        (1e-7 radians)."""
        a = self.normal_angles
        if not np.isfinite(a).all():
            return False
        steps = itertools.pairwise(a)
        return all(b <= 1e-7 or b <= 1.1 * self.normal_rate * x for x, b in steps)


def _reach_rate(A: NDArray[np.float64], centre: NDArray[np.float64]) -> float:
    """Largest modulus after 1 among eigenvalues whose eigenvector reaches the
    element's point (``centre . r != 0``)."""
    w, V = np.linalg.eig(A)
    reach = np.abs(centre @ V) / np.maximum(np.linalg.norm(V, axis=0), 1e-300)
    ok = (np.abs(w - 1.0) > 1e-9) & (reach > 1e-8)
    return float(np.abs(w[ok]).max()) if ok.any() else 0.0


def limit_convergence(
    stencil: LimitStencil,
    mesh: Mesh,
    levels: int = 4,
    duals: int = 2,
) -> LimitConvergence:
    """Check a limit stencil against ``levels`` more levels of actual subdivision.

    The mesh is subdivided with :func:`pentanb.subdivide` to
    ``stencil.level + levels`` steps; the element keeps its index (both of
    the paper's schemes put the old vertices first and the central faces
    first, and two duals give every vertex and face back with its index),
    which is checked against the stencil's own neighbourhood at
    ``stencil.level``.

    Parameters
    ----------
    stencil : LimitStencil
        From :func:`limit_stencil` on ``mesh`` (or a deliberately wrong one).
    mesh : Mesh
        The mesh the stencil was made from.
    levels : int, >= 2
        Levels beyond ``stencil.level``.
    duals : int

    Returns
    -------
    LimitConvergence

    Raises
    ------
    ValueError
        ``levels`` below 2, or a mesh whose level ``stencil.level`` does not
        put the neighbourhood where the stencil says.
    """
    from .. import subdivide

    if isinstance(levels, bool) or not isinstance(levels, (int, np.integer)) or levels < 2:
        raise ValueError(f"levels must be an integer >= 2, got {levels!r}")
    limit = stencil.point
    tn = stencil.normal
    kind, idx = stencil.tracked
    m = subdivide(mesh, stencil.scheme, stencil.level, duals, **stencil.options)
    if not np.allclose(m.vertices[stencil.vertices], stencil.positions, rtol=0, atol=1e-12):
        raise ValueError(
            "the mesh's subdivision does not put the neighbourhood where the stencil says"
        )
    dist, angles, lv = [], [], []
    for j in range(levels + 1):
        if j:
            m = subdivide(m, stencil.scheme, 1, duals, **stencil.options)
        dist.append(float(np.linalg.norm(_element_point(m, (kind, idx)) - limit)))
        n = _element_normal(m, (kind, idx))
        ok = bool(np.isfinite(tn).all())
        angles.append(float(np.arccos(np.clip(n @ tn, -1.0, 1.0))) if ok else math.nan)
        lv.append(stencil.level + j)
    A, P = stencil.matrix, stencil.positions
    pred, x = [], P.copy()
    for j in range(levels + 1):
        if j:
            x = A @ x
        pred.append(float(np.linalg.norm(stencil.centre @ x - limit)))
    d = np.array(dist)
    tail = d[-3:]
    measured = float((tail[-1] / tail[0]) ** 0.5) if tail[0] > 0 else 0.0
    return LimitConvergence(
        stencil=stencil,
        levels=np.array(lv, dtype=np.int64),
        distances=d,
        predicted=np.array(pred),
        rate=_reach_rate(A, stencil.centre),
        measured_rate=measured,
        normal_angles=np.array(angles),
        normal_rate=stencil.lambda_next / stencil.lambda1 if stencil.lambda1 else math.nan,
    )


# ---------------------------------------------------------------------------
# curvature and the normal's Hölder exponent
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class CurvatureMeasure:
    """What the leading eigenvalues say about the limit's second order at one element.

    Attributes
    ----------
    label : str
        Scheme and options, as in the continuity table.
    kind : {"vertex", "face"}
    size : int
    lambda1 : float
        ``|lambda1| = |lambda2|``, per step.
    lambda3 : float
        The largest modulus after the subdominant pair, per step (``mu``).
    ratio : float
        ``lambda3 / lambda1 ** 2``: curvature bounded for generic control
        points only where it is at most 1.
    holder : float
        ``log(lambda1 / lambda3) / log(1 / lambda1)``: the normal's Hölder
        exponent (per unit distance).
    gap : float
        ``(lambda1 - lambda3) / lambda1``: the per-step relative gap.
    curvature : str
        "tends to 0" (ratio < 1), "bounded" (ratio = 1), "diverges"
        (ratio > 1; generic control points), or "no tangent plane".
    """

    label: str
    kind: str
    size: int
    lambda1: float
    lambda3: float
    ratio: float
    holder: float
    gap: float
    curvature: str


def curvature_measures(spectrum, label: str | None = None) -> CurvatureMeasure:
    """Curvature measures of one local spectrum (:func:`pentanb.analysis.local_spectrum`).

    Parameters
    ----------
    spectrum : LocalSpectrum
        Stationary, with the eigenvalue 1 simple.
    label : str, optional
        A name for the row (default: the scheme and its options).

    Returns
    -------
    CurvatureMeasure
        ``curvature == "no tangent plane"`` (and NaN measures but
        ``lambda1``) where the subdominant eigenvalue is not a pair.

    Raises
    ------
    ValueError
        A spectrum that is not stationary.
    """
    if not spectrum.stationary or spectrum.eigenvalues.size < 4:
        raise ValueError(f"no spectrum to read: {spectrum.note or 'too small'}")
    if label is None:
        opts = " ".join(f"{v:g}" for v in spectrum.options.values())
        label = f"{spectrum.scheme} {opts}".strip()
    m = spectrum.moduli
    lam1 = float(m[1])
    group = int(np.sum(np.abs(m[1:] - lam1) <= TOL * lam1))
    if group != 2:
        nan = math.nan
        return CurvatureMeasure(
            label, spectrum.kind, spectrum.size, lam1, nan, nan, nan, nan, "no tangent plane"
        )
    lam3 = float(m[3])
    ratio = lam3 / lam1**2
    holder = math.log(lam1 / lam3) / math.log(1.0 / lam1) if lam3 > 0 else math.inf
    if abs(ratio - 1.0) <= 1e-9:
        what = "bounded"
    else:
        what = "tends to 0" if ratio < 1 else "diverges"
    return CurvatureMeasure(
        label, spectrum.kind, spectrum.size, lam1, lam3, ratio, holder, (lam1 - lam3) / lam1, what
    )


def curvature_table(rows: Sequence[Any] | None = None) -> list[CurvatureMeasure]:
    """Curvature measures for every row of the continuity table that has a spectrum.

    Parameters
    ----------
    rows : sequence of ContinuityRow, optional
        Default: :func:`pentanb.analysis.continuity_table` (``map_iterations=0``).

    Returns
    -------
    list of CurvatureMeasure
    """
    if rows is None:
        from . import continuity_table

        rows = continuity_table(map_iterations=0)
    out = []
    for r in rows:
        sp = r.spectrum
        if sp is None or not sp.stationary or sp.eigenvalues.size < 4:
            continue
        out.append(curvature_measures(sp, r.label))
    return out


def curvature_markdown(measures: Sequence[CurvatureMeasure]) -> str:
    """The measures as a Markdown table.

    Parameters
    ----------
    measures : sequence of CurvatureMeasure

    Returns
    -------
    str
    """
    lines = [
        "| scheme + 2 duals | element | λ1 | λ3 | λ3 / λ1² | curvature (generic) "
        "| Hölder exponent of the normal | gap (λ1 - λ3) / λ1 |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for c in measures:
        if c.curvature == "no tangent plane":
            lines.append(
                f"| {c.label} | {c.kind} {c.size} | {c.lambda1:.4f} (simple) | | | "
                "no tangent plane | | |"
            )
            continue
        lines.append(
            f"| {c.label} | {c.kind} {c.size} | {c.lambda1:.4f} | {c.lambda3:.4f} | "
            f"{c.ratio:.3f} | {c.curvature} | {c.holder:.3f} | {c.gap:.3f} |"
        )
    return "\n".join(lines)
