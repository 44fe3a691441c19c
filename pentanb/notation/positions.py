"""Canonical and planar positions.

* :func:`canonical` moves a genus-0 mesh to its *canonical form* (Hart,
  "Calculating canonical polyhedra", Mathematica in Education and Research
  6(3), 1997; polyHedronisme's "C", Antiprism's ``canonical``): every edge
  tangent to the unit sphere, the tangency points centred at the origin,
  every face planar.  By the Koebe-Andreev-Thurston midsphere theorem a
  3-connected planar mesh has exactly one such form up to rotation, so it
  depends only on the topology.
* :func:`planarize` makes every face planar, for any genus, moving the
  vertices as little as it can (the paper's meshes are 6-15 % of an edge
  off planar after two duals).

Method
------
Hart moves vertices towards tangency, recentres and flattens faces in turn,
a fixed-point iteration that converges linearly, slowly, and not always
(it stalls on ``pP5`` and ``bY5``; polyHedronisme's reciprocation
iteration stalls on ``cY5`` and ``zY5``).  Here:

* canonical: the canonical form is built from a circle pattern, following
  Bobenko and Springborn ("Variational principles for circle patterns and
  Koebe's theorem", Trans. AMS 356, 2004): the vertices' horizon circles
  and the faces' circles on the unit sphere cross at right angles, and
  after a stereographic projection their radii minimise a *convex*
  function (one Newton solve per step, a handful of steps).  The pattern
  is laid out, lifted back to the sphere and centred by the Moebius boost
  that puts the tangency points' mean at the origin (a projective map of
  space that keeps the unit ball, so tangency and planarity are kept);
  each vertex is the pole of the plane through its tangency points.  A
  few damped Gauss-Newton steps of least norm polish the result; their
  unknowns are the vertices ``x_v`` and the poles ``y_f`` of the face
  planes (the plane of f is ``{z : y_f . z = 1}``, ``y_f`` the vertex of the
  canonical dual), their equations ``x_v . y_f = 1`` at every corner,
  ``|x_u x w| / |x_u - x_w| = 1`` on every edge and the mean tangency point
  at the origin.
* planarize: unknowns are the vertices and a plane ``(n_f, d_f)`` for every
  non-triangular face; equations ``n_f . x_v = d_f`` and ``|n_f| = 1``.
  Steps of least norm (vertex moves weighted against plane moves) project
  the mesh onto the planar meshes nearby; if that collapses edges, a first
  phase that also keeps the edge lengths comes before the projection.

The planarity measure (:func:`best_fit_planes`, :func:`face_planarity`)
lives in :mod:`pentanb.notation.planarity`, below :mod:`pentanb.analysis`
(which may import it; nothing in :mod:`pentanb.notation` imports
:mod:`pentanb.analysis`); its names are importable from here too.  The
canonical form's circle pattern, lift and polish are in
:mod:`pentanb.notation.koebe`.  scipy.sparse is imported when a function is
called (``import pentanb`` needs numpy only).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Literal, overload

import numpy as np

from .. import _checks
from ..mesh import Mesh, MeshError, check_closed, check_mesh
from .koebe import (
    _centre,
    _initial_sphere,
    _koebe,
    _least_norm_lm,
    _poles,
    _solve_canonical,
)
from .planarity import (
    _canonical_measures,
    _mean_edge_length,
    best_fit_planes,
    face_planarity,
    tangency_points,
)

__all__ = [
    "canonical",
    "planarize",
    "PlacementReport",
    "ConvergenceError",
    "tangency_points",
    "best_fit_planes",
    "face_planarity",
]

#: Default tolerance: edges tangent, tangency points centred and faces planar
#: (relative to each face's mean edge length) within this.
TOLERANCE = 1e-8
#: Most steps ``max_iterations`` may ask for: a solver that has not
#: converged in 10,000 Newton steps will not (and each step is a sparse
#: solve on the whole mesh).
MAX_ITERATIONS = 10_000


@dataclass(frozen=True)
class PlacementReport:
    """What :func:`canonical` or :func:`planarize` reached.

    Attributes
    ----------
    converged : bool
        Every requested condition holds within ``tolerance`` (and, for the
        canonical form, the result is convex).
    iterations : int
        Gauss-Newton steps taken (accepted or not).
    planarity : float
        Largest corner distance from its face's best-fit plane, over that
        face's mean edge length.
    tangency : float
        Largest ``| distance(edge line, origin) - 1 |`` (nan for planarize).
    centring : float
        Norm of the mean of the tangency points (nan for planarize).
    convex : bool
        No vertex lies outside a face's plane (canonical; True for planarize).
    max_move : float
        Largest vertex displacement, over the input's mean edge length
        (planarize; nan for canonical, whose scale and place are new).
    seconds : float
        Wall time.
    tolerance : float
    message : str
        Why it stopped.
    """

    converged: bool
    iterations: int
    planarity: float
    tangency: float
    centring: float
    convex: bool
    max_move: float
    seconds: float
    tolerance: float
    message: str


class ConvergenceError(RuntimeError):
    """:func:`canonical` or :func:`planarize` did not reach its tolerance.

    Attributes
    ----------
    report : PlacementReport
    mesh : Mesh
        The best positions found.
    """

    def __init__(self, message: str, report: PlacementReport, mesh: Mesh):
        super().__init__(message)
        self.report = report
        self.mesh = mesh


# ---------------------------------------------------------------------- canonical
@overload
def canonical(
    mesh: Mesh,
    *,
    tolerance: float = ...,
    max_iterations: int = ...,
    method: str = ...,
    report: Literal[False] = ...,
) -> Mesh: ...
@overload
def canonical(
    mesh: Mesh,
    *,
    tolerance: float = ...,
    max_iterations: int = ...,
    method: str = ...,
    report: Literal[True],
) -> tuple[Mesh, PlacementReport]: ...
def canonical(
    mesh: Mesh,
    *,
    tolerance: float = TOLERANCE,
    max_iterations: int = 100,
    method: str = "koebe",
    report: bool = False,
):
    """The canonical form of a genus-0 mesh: edges tangent to the unit
    sphere, tangency points centred at the origin, every face planar.

    Parameters
    ----------
    mesh : Mesh
        Connected, genus 0 (a polyhedron's topology: 3-connected, which
        every Conway operator applied to a Platonic seed gives).  Only the
        connectivity matters; the positions are a starting guess.
    tolerance : float
        Largest accepted ``|distance(edge, origin) - 1|``, norm of the mean
        tangency point, and corner distance from its face's best-fit plane
        relative to that face's mean edge length.
    max_iterations : int in [0, :data:`MAX_ITERATIONS`]
        Newton steps (of either method) before giving up.
    method : {"koebe", "newton"}
        ``"koebe"``: from the circle pattern (see the module's notes), then
        at most five Newton steps to polish; falls back to ``"newton"`` if
        the circle pattern cannot be built.  ``"newton"``: damped Newton
        steps from the vertices pushed radially onto a sphere (fast, but it
        can stall or end on a non-convex solution, e.g. on ``pY5``).
    report : bool
        Return ``(mesh, PlacementReport)`` instead of the mesh, and do not
        raise when the tolerance is not reached (the report says so).

    Returns
    -------
    Mesh
        Same connectivity, new positions (``mesh.with_vertices``).

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh; ``tolerance`` or ``max_iterations`` of a
        wrong type (the message names it).
    ValueError
        ``tolerance`` not positive, ``max_iterations`` out of its range, an
        unknown method.
    MeshError
        The mesh is not connected or not of genus 0.
    ConvergenceError
        (unless ``report``) the tolerance was not reached or the result is
        not convex; the error carries the report and the best positions.
    """
    check_closed(mesh, "canonical")
    tolerance = _check_tolerance(tolerance)
    max_iterations = _checks.count(max_iterations, "max_iterations", 0, MAX_ITERATIONS)
    if mesh.n_components != 1 or mesh.genus != 0:
        raise MeshError(
            f"the canonical form needs a connected genus-0 mesh; this one has "
            f"{mesh.n_components} component(s) and genus {mesh.genus} "
            "(planarize works for any genus)"
        )
    if method not in ("koebe", "newton"):
        raise ValueError(f"method must be 'koebe' or 'newton', got {method!r}")
    start = time.perf_counter()
    its, message = 0, "converged"
    x = _koebe(mesh, max_iterations) if method == "koebe" else None
    measures = None
    if x is not None:
        out = mesh.with_vertices(x)
        measures = _canonical_measures(out)
        if max(measures[:3]) > 1e-2 * tolerance:
            # polish: Newton steps from a start that is nearly there
            x, _, its, message = _solve_canonical(
                mesh, x, _poles(mesh, x), 5, tolerance, centring=False
            )
            x = _centre(mesh, x)
            measures = None
    else:  # fall back: Newton from the vertices pushed onto a sphere
        x = _initial_sphere(mesh)
        x, _, its, message = _solve_canonical(mesh, x, _poles(mesh, x), max_iterations, tolerance)
        x = _centre(mesh, x)
    if measures is None:
        out = mesh.with_vertices(x)
        measures = _canonical_measures(out)
    tangency, centring, planar, convex = measures
    ok = max(tangency, centring, planar) <= tolerance and convex
    if not ok and message == "converged":
        message = "not convex" if not convex else "tolerance not reached after centring"
    rep = PlacementReport(
        converged=ok,
        iterations=its,
        planarity=planar,
        tangency=tangency,
        centring=centring,
        convex=convex,
        max_move=float("nan"),
        seconds=time.perf_counter() - start,
        tolerance=tolerance,
        message=message,
    )
    if report:
        return out, rep
    if not ok:
        raise ConvergenceError(
            f"canonical form not reached ({message}): tangency {tangency:.2e}, "
            f"centring {centring:.2e}, planarity {planar:.2e}, convex {convex} "
            f"(tolerance {tolerance:.0e}, {its} iterations)",
            rep,
            out,
        )
    return out


def _check_tolerance(tolerance) -> float:
    return _checks.number(tolerance, "tolerance", 0.0, open_low=True)


# ---------------------------------------------------------------------- planarize
@overload
def planarize(
    mesh: Mesh,
    *,
    tolerance: float = ...,
    max_iterations: int = ...,
    report: Literal[False] = ...,
) -> Mesh: ...
@overload
def planarize(
    mesh: Mesh,
    *,
    tolerance: float = ...,
    max_iterations: int = ...,
    report: Literal[True],
) -> tuple[Mesh, PlacementReport]: ...
def planarize(
    mesh: Mesh,
    *,
    tolerance: float = TOLERANCE,
    max_iterations: int = 100,
    report: bool = False,
):
    """Make every face planar, moving the vertices as little as it can.

    Any genus.  Triangles are planar already and impose nothing; every other
    face gets a plane, and damped Gauss-Newton steps of least norm (a vertex
    move weighs ten times a plane move) bring every corner onto its face's
    plane: nearly the nearest planar mesh.  From a strongly folded start the
    nearest planar mesh can shrink edges to nothing (``conway("atjT")``: the
    centroid join of the tetrahedron is folded inwards and its triangles
    collapse); then a first phase that also keeps the edge lengths (least
    squares) is run before the projection, and a collapse that remains is
    reported (``message="faces collapsed"``, not converged).

    Parameters
    ----------
    mesh : Mesh
    tolerance : float
        Largest accepted corner distance from its face's best-fit plane,
        relative to that face's mean edge length.
    max_iterations : int in [0, :data:`MAX_ITERATIONS`]
        Gauss-Newton steps (of each phase) before giving up.
    report : bool
        Return ``(mesh, PlacementReport)`` (whose ``max_move`` is the largest
        vertex displacement over the mean edge length) and do not raise.

    Returns
    -------
    Mesh
        Same connectivity, new positions.

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh; ``tolerance`` or ``max_iterations`` of a
        wrong type (the message names it).
    ValueError
        ``tolerance`` not positive, ``max_iterations`` out of its range.
    ConvergenceError
        (unless ``report``) the tolerance was not reached.
    """
    check_mesh(mesh, "planarize")
    tolerance = _check_tolerance(tolerance)
    max_iterations = _checks.count(max_iterations, "max_iterations", 0, MAX_ITERATIONS)
    start = time.perf_counter()
    scale = _mean_edge_length(mesh)
    origin = mesh.vertices.mean(axis=0)
    x0 = (mesh.vertices - origin) / scale
    big = np.flatnonzero(mesh.face_sizes > 3)
    its, message = 0, "converged"
    x = x0
    if big.size:
        x, its, message = _solve_planar(mesh, x0, big, max_iterations, tolerance)
        for weight in EDGE_WEIGHTS:  # the nearest planar mesh collapsed faces
            if not _collapsed(x, mesh, x0):
                break
            x, more, message = _solve_planar(mesh, x0, big, max_iterations, tolerance, weight)
            its += more
        if _collapsed(x, mesh, x0):
            message = "faces collapsed"
    out = mesh.with_vertices(x * scale + origin)
    planar = float(face_planarity(out, relative_to="face").max(initial=0.0))
    move = float(np.linalg.norm(x - x0, axis=1).max(initial=0.0))
    ok = planar <= tolerance and message != "faces collapsed"
    if not ok and message == "converged":
        message = "tolerance not reached"
    rep = PlacementReport(
        converged=ok,
        iterations=its,
        planarity=planar,
        tangency=float("nan"),
        centring=float("nan"),
        convex=True,
        max_move=move,
        seconds=time.perf_counter() - start,
        tolerance=tolerance,
        message=message,
    )
    if report:
        return out, rep
    if not ok:
        raise ConvergenceError(
            f"planar positions not reached ({message}): planarity {planar:.2e} "
            f"(tolerance {tolerance:.0e}, {its} iterations)",
            rep,
            out,
        )
    return out


#: Weight of a plane unknown against a vertex coordinate in the least-norm step.
PLANE_WEIGHT = 10.0
#: Weights of the edge-length terms tried, in turn, when the nearest planar
#: mesh collapses faces.
EDGE_WEIGHTS = (1.0, 3.0, 10.0)


def _solve_planar(
    mesh: Mesh, x0: np.ndarray, big: np.ndarray, max_iterations, tolerance, edge_weight=0.0
):
    """Least-norm projection onto the planar meshes; with ``edge_weight``, a
    first phase keeps the edge lengths too (least squares), so that faces
    are not collapsed on the way (then the projection from there)."""
    from scipy import sparse

    nv = x0.shape[0]
    nb = big.size
    slot = np.full(mesh.n_faces, -1, dtype=np.int64)
    slot[big] = np.arange(nb, dtype=np.int64)
    hf = mesh.halfedge_face
    h = np.flatnonzero(slot[hf] >= 0)
    v, f = mesh.corners[h], slot[hf[h]]
    nh = h.size
    sub = Mesh.from_csr(x0, mesh.corners, mesh.offsets, validate=False)
    _, normals = best_fit_planes(sub)
    n0 = normals[big]
    c0 = np.add.reduceat(x0[mesh.corners], mesh.offsets[:-1], axis=0) / mesh.face_sizes[:, None]
    d0 = np.einsum("ij,ij->i", n0, c0[big])
    k3 = np.arange(3)
    base_n = 3 * nv
    base_d = 3 * nv + 3 * nb
    ea, eb = mesh.edges[:, 0], mesh.edges[:, 1]
    length0 = np.linalg.norm(x0[ea] - x0[eb], axis=1)

    def system(z, weight=0.0):
        x = z[:base_n].reshape(-1, 3)
        n = z[base_n:base_d].reshape(-1, 3)
        d = z[base_d:]
        xv, nf = x[v], n[f]
        r1 = np.einsum("ij,ij->i", nf, xv) - d[f]
        r2 = 0.5 * (np.einsum("ij,ij->i", n, n) - 1.0)
        rows = [np.repeat(np.arange(nh), 3), np.repeat(np.arange(nh), 3), np.arange(nh)]
        rows.append(np.repeat(nh + np.arange(nb), 3))
        cols = [
            (3 * v[:, None] + k3).ravel(),
            (base_n + 3 * f[:, None] + k3).ravel(),
            base_d + f,
            (base_n + 3 * np.arange(nb)[:, None] + k3).ravel(),
        ]
        vals = [nf.ravel(), xv.ravel(), -np.ones(nh), n.ravel()]
        res = [r1, r2]
        n_rows = nh + nb
        if weight:
            ev = x[ea] - x[eb]
            length = np.linalg.norm(ev, axis=1)
            unit = ev / length[:, None]
            res.append(weight * (length - length0))
            er = np.repeat(n_rows + np.arange(ea.size), 3)
            rows += [er, er]
            cols += [(3 * ea[:, None] + k3).ravel(), (3 * eb[:, None] + k3).ravel()]
            vals += [weight * unit.ravel(), -weight * unit.ravel()]
            n_rows += ea.size
        J = sparse.csr_matrix(
            (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
            shape=(n_rows, base_d + nb),
        )
        return np.concatenate(res), J

    z = np.concatenate([x0.ravel(), n0.ravel(), d0])
    weights = np.concatenate([np.ones(base_n), np.full(4 * nb, PLANE_WEIGHT)])
    its0 = 0
    if edge_weight:
        z, its0, _ = _least_norm_lm(
            lambda z: system(z, edge_weight), z, 30, stop=0.0, weights=weights
        )
    z, its, message = _least_norm_lm(
        system, z, max_iterations, stop=min(tolerance, 1e-8) * 1e-3, weights=weights
    )
    return z[:base_n].reshape(-1, 3), its0 + its, message


def _collapsed(x: np.ndarray, mesh: Mesh, x0: np.ndarray) -> bool:
    """An edge shrunk to almost nothing that was not so before."""
    ea, eb = mesh.edges[:, 0], mesh.edges[:, 1]
    before = np.linalg.norm(x0[ea] - x0[eb], axis=1)
    after = np.linalg.norm(x[ea] - x[eb], axis=1)
    return bool(np.any((after < 1e-3 * after.mean()) & (before >= 1e-2 * before.mean())))
