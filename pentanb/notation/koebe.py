"""The canonical form's numerics (:func:`pentanb.notation.positions.canonical`).

The form is built from a circle pattern, following Bobenko and Springborn
("Variational principles for circle patterns and Koebe's theorem", Trans.
AMS 356, 2004): the vertices' horizon circles and the faces' circles on the
unit sphere cross at right angles, and after a stereographic projection
their radii minimise a *convex* function (:func:`_koebe`: one Newton solve
per step, a handful of steps).  The pattern is laid out, lifted back to the
sphere (:func:`_initial_sphere`, :func:`_poles`) and centred by the Moebius
boost that puts the tangency points' mean at the origin (:func:`_centre`).
A few damped Gauss-Newton steps of least norm polish the result
(:func:`_solve_canonical` over :func:`_canonical_system`;
:func:`_least_norm_lm`, the least-norm step, serves planarize too).

scipy.sparse is imported when a function is called.
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh
from .planarity import tangency_points

# ---------------------------------------------------------------------- Koebe start
_GAUSS_NODES, _GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(20)


def _psi(x: np.ndarray) -> np.ndarray:
    """``2 Ti2(e^x) = 2 Im Li2(i e^x)``, whose derivative is ``2 arctan(e^x)``.

    ``Ti2(y)``, the inverse tangent integral of ``arctan(t) / t`` over
    ``[0, y]``, by 20-point Gauss-Legendre on ``[0, min(y, 1/y)]`` (the
    integrand is analytic there, its poles at +-i: about 1e-16) and
    ``Ti2(y) = Ti2(1/y) + (pi/2) log y``.
    """
    y = np.exp(x)
    z = np.minimum(y, 1.0 / y)
    t = 0.5 * z[:, None] * (_GAUSS_NODES + 1.0)
    f = np.arctan(t) / np.where(t > 0, t, 1.0)
    integral = 0.5 * z * (f @ _GAUSS_WEIGHTS)
    return 2.0 * np.where(y <= 1.0, integral, integral + 0.5 * np.pi * x)


def _koebe(mesh: Mesh, max_iterations: int = 100):
    """The canonical form from a circle pattern (Bobenko and Springborn).

    Bobenko and Springborn, "Variational principles for circle patterns
    and Koebe's theorem", Trans. AMS 356 (2004): on the canonical
    polyhedron each vertex sees the unit sphere within a circle, each face
    plane cuts it in a circle, and the circles of a vertex and of a face
    through it cross at right angles, at the tangency points of the two
    edges they share.  Projected stereographically from the tangency point
    of one edge ``e0`` (its two vertex and two face circles become the four
    sides of a rectangle), the other circles form a planar pattern whose
    log-radii ``rho`` minimise the convex function

        S(rho) = sum_j Phi_j rho_j + sum_kites (Psi(rho_f - rho_v) - pi rho_f)

    (``Psi' = 2 arctan exp``; a kite per corner (v, f); ``Phi_j = 2 pi``,
    or ``pi`` for the circles centred on the rectangle's sides): the angles
    ``2 arctan(r_f / r_v)`` of the kites then close up around every circle.
    Newton's method with a line search finds the minimum; the kites are
    laid out, their corners (the tangency points) lifted back to the sphere
    and centred, and every vertex is the pole of the plane through its
    tangency points.

    Returns
    -------
    x : (V, 3) float or None
        Vertices (None when the Newton iteration fails).
    """
    from scipy import sparse
    from scipy.sparse.linalg import spsolve

    V, F = mesh.n_vertices, mesh.n_faces
    tail, hf, twin = mesh.corners, mesh.halfedge_face, mesh.twin
    deg = mesh.valences
    # the edge sent to infinity: one between two vertices of high valence
    score = deg[mesh.edges[:, 0]] + deg[mesh.edges[:, 1]]
    h0 = int(mesh.edge_halfedge[int(np.argmax(score))])
    v_out = np.zeros(V, dtype=bool)
    v_out[[tail[h0], tail[twin[h0]]]] = True
    f_out = np.zeros(F, dtype=bool)
    f_out[[hf[h0], hf[twin[h0]]]] = True
    kite = ~v_out[tail] & ~f_out[hf]  # kite h: the corner (tail h, face h)
    vid = np.full(V, -1, dtype=np.int64)
    vid[~v_out] = np.arange(int((~v_out).sum()))
    nvc = int((~v_out).sum())
    fid = np.full(F, -1, dtype=np.int64)
    fid[~f_out] = nvc + np.arange(int((~f_out).sum()))
    n = nvc + int((~f_out).sum())
    phi = np.full(n, 2.0 * np.pi)
    on_side_v = np.zeros(V, dtype=bool)
    on_side_v[tail[f_out[hf]]] = True
    on_side_v[v_out] = False
    on_side_f = np.zeros(F, dtype=bool)
    on_side_f[hf[v_out[tail]]] = True
    on_side_f[f_out] = False
    phi[vid[on_side_v]] = np.pi
    phi[fid[on_side_f]] = np.pi
    kh = np.flatnonzero(kite)
    a, b = vid[tail[kh]], fid[hf[kh]]

    def gradient(rho):
        x = rho[b] - rho[a]
        g = phi - np.bincount(a, 2.0 * np.arctan(np.exp(x)), n)
        g -= np.bincount(b, 2.0 * np.arctan(np.exp(-x)), n)
        return g, x

    def objective(rho):
        return float(phi @ rho + np.sum(_psi(rho[b] - rho[a]) - np.pi * rho[b]))

    rho = np.zeros(n)
    ab = np.concatenate([a, b, a, b])
    ba = np.concatenate([a, b, b, a])
    s0 = objective(rho)
    for _ in range(max_iterations):
        g, x = gradient(rho)
        if not np.all(np.isfinite(g)):
            return None
        gmax = np.abs(g).max()
        if gmax < 1e-11:
            break
        w = 1.0 / np.cosh(x)
        L = sparse.csc_matrix((np.concatenate([w, w, -w, -w]), (ab, ba)), shape=(n, n))
        step = np.zeros(n)
        # rho_0 fixed: the scale is free
        step[1:] = -spsolve(L[1:, 1:], g[1:], permc_spec="MMD_AT_PLUS_A")
        if gmax < 1e-4:  # Newton's own region: full steps, no line search
            rho = rho + step
            continue
        t = 1.0
        slack = 1e-12 * (1.0 + abs(s0))
        while True:
            s1 = objective(rho + t * step)
            if s1 <= s0 + 1e-4 * t * float(g @ step) + slack:
                break
            t *= 0.5
            if t < 1e-10:
                return None
        rho, s0 = rho + t * step, s1
    else:
        return None
    r = np.exp(rho)
    # each circle's kites in cyclic order (vertex: rotation; face: face order),
    # a side circle's list starting just after its one missing kite
    ring, ring_off = mesh.vertex_ring
    lists = np.concatenate([ring, np.arange(mesh.n_halfedges)])
    owner = np.concatenate([np.repeat(vid, deg), np.repeat(fid, mesh.face_sizes)])
    seg_off = np.concatenate([ring_off, ring_off[-1] + mesh.offsets[1:]])
    seg = np.concatenate([np.repeat(np.arange(V), deg), V + hf])
    missing = ~kite[lists] & (owner >= 0)
    start = np.zeros(V + F, dtype=np.int64)
    start[seg[missing]] = np.flatnonzero(missing) - seg_off[seg[missing]] + 1
    size = np.diff(seg_off)
    local = np.arange(lists.size) - seg_off[seg]
    lists = lists[seg_off[seg] + (start[seg] + local) % size[seg]]
    keep = kite[lists] & (owner >= 0)
    entry_kite = lists[keep]
    entry_circle = owner[keep]
    entry_other = np.where(entry_circle < nvc, fid[hf[entry_kite]], vid[tail[entry_kite]])
    circ_off = np.concatenate([[0], np.cumsum(np.bincount(entry_circle, minlength=n))])
    alpha = np.arctan(r[entry_other] / r[entry_circle])
    csum = np.cumsum(alpha)
    first = circ_off[entry_circle]
    before = np.where(first > 0, csum[first - 1], 0.0)
    offset = 2.0 * (csum - before) - alpha - alpha[first]
    dist = np.hypot(r[entry_other], r[entry_circle])
    # the entry of the same kite in the other circle's list
    pos_v = np.full(mesh.n_halfedges, -1, dtype=np.int64)
    pos_f = np.full(mesh.n_halfedges, -1, dtype=np.int64)
    is_v = entry_circle < nvc
    pos_v[entry_kite[is_v]] = np.flatnonzero(is_v)
    pos_f[entry_kite[~is_v]] = np.flatnonzero(~is_v)
    mate = np.where(is_v, pos_f[entry_kite], pos_v[entry_kite])
    # lay the pattern out, breadth first (one vectorized step per level)
    centre = np.full((n, 2), np.nan)
    theta = np.full(n, np.nan)
    centre[0] = 0.0
    theta[0] = 0.0
    frontier = np.array([0])
    while frontier.size:
        e = _entries(circ_off, frontier)
        j, k = entry_circle[e], entry_other[e]
        angle = theta[j] + offset[e]
        new = np.isnan(theta[k])
        e, j, k, angle = e[new], j[new], k[new], angle[new]
        k, once = np.unique(k, return_index=True)
        e, j, angle = e[once], j[once], angle[once]
        centre[k] = centre[j] + dist[e][:, None] * np.stack([np.cos(angle), np.sin(angle)], 1)
        theta[k] = angle + np.pi - offset[mate[e]]
        frontier = k
    if np.isnan(theta).any():
        return None
    # tangency points: from each kite seen from its vertex circle, the corner
    # clockwise of the axis is t(h), the one counter-clockwise t(prev h)
    ev = np.flatnonzero(is_v)
    hk = entry_kite[ev]
    ang = theta[entry_circle[ev]] + offset[ev]
    rv = r[entry_circle[ev]][:, None]
    cv = centre[entry_circle[ev]]
    cw = cv + rv * np.stack([np.cos(ang - alpha[ev]), np.sin(ang - alpha[ev])], 1)
    ccw = cv + rv * np.stack([np.cos(ang + alpha[ev]), np.sin(ang + alpha[ev])], 1)
    E = mesh.n_edges
    edge = mesh.halfedge_edge
    plane = np.zeros((E, 2))
    count = np.zeros(E)
    for pts, hh in ((cw, hk), (ccw, mesh.prev[hk])):
        np.add.at(plane, edge[hh], pts)
        np.add.at(count, edge[hh], 1.0)
    e0 = int(edge[h0])
    if np.any(count[np.arange(E) != e0] == 0):
        return None
    plane /= np.where(count > 0, count, 1.0)[:, None]
    for flip in (1.0, -1.0):
        X, Y = plane[:, 0], flip * plane[:, 1]
        q = 1.0 + X * X + Y * Y
        lifted = np.stack([2.0 * X / q, 2.0 * Y / q, (q - 2.0) / q], 1)
        lifted[e0] = (0.0, 0.0, 1.0)
        x = _poles_through(mesh, _centred_points(lifted))
        if x is None:
            return None
        if mesh.with_vertices(x).volume > 0:
            return x
    return None


def _entries(off: np.ndarray, circles: np.ndarray) -> np.ndarray:
    """All list entries of the given circles (CSR offsets ``off``)."""
    sizes = off[circles + 1] - off[circles]
    base = np.repeat(off[circles] - np.concatenate([[0], np.cumsum(sizes)[:-1]]), sizes)
    return base + np.arange(int(sizes.sum()))


def _centred_points(t: np.ndarray) -> np.ndarray:
    """Points of the unit sphere moved by the Moebius boost that centres them."""
    for _ in range(100):
        c = t.mean(axis=0)
        if np.linalg.norm(c) < 1e-15:
            break
        M = t.T @ t / t.shape[0]
        step = np.linalg.lstsq(np.eye(3) - M, c, rcond=None)[0]
        size = np.linalg.norm(step)
        if size > 2.0:  # points bunched together: a damped boost first
            step *= 2.0 / size
        t = _apply_projective(_boost_matrix(step), t)
        t /= np.linalg.norm(t, axis=1, keepdims=True)
    return t


def _poles_through(mesh: Mesh, t: np.ndarray):
    """Every vertex as the pole of the plane through its edges' tangency
    points ``t`` (least squares of ``x . t = 1``)."""
    te = t[mesh.halfedge_edge]
    A = np.zeros((mesh.n_vertices, 3, 3))
    rhs = np.zeros((mesh.n_vertices, 3))
    np.add.at(A, mesh.corners, te[:, :, None] * te[:, None, :])
    np.add.at(rhs, mesh.corners, te)
    try:
        x = np.linalg.solve(A, rhs[:, :, None])[:, :, 0]
    except np.linalg.LinAlgError:
        return None
    return x if np.all(np.isfinite(x)) else None


def _initial_sphere(mesh: Mesh) -> np.ndarray:
    """Vertices pushed radially onto a sphere about their mean, scaled so that
    the edges are at mean distance 1 from the origin."""
    x = mesh.vertices - mesh.vertices.mean(axis=0)
    r = np.linalg.norm(x, axis=1, keepdims=True)
    x = x / np.where(r > 0, r, 1.0)
    d = _edge_distances(x, mesh.edges)
    return x / d.mean()


def _edge_distances(x: np.ndarray, edges: np.ndarray) -> np.ndarray:
    u, w = x[edges[:, 0]], x[edges[:, 1]]
    return np.linalg.norm(np.cross(u, w), axis=1) / np.linalg.norm(u - w, axis=1)


def _poles(mesh: Mesh, x: np.ndarray) -> np.ndarray:
    """The pole ``y`` of every face's plane ``{z : y . z = 1}`` (Newell normal
    through the corners' mean)."""
    p = x[mesh.corners]
    starts = mesh.offsets[:-1]
    n = np.add.reduceat(np.cross(p, x[mesh.head]), starts, axis=0)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    c = np.add.reduceat(p, starts, axis=0) / mesh.face_sizes[:, None]
    d = np.einsum("ij,ij->i", n, c)
    d = np.where(d > 1e-3, d, 1e-3)  # a plane through the origin has no pole
    return n / d[:, None]


def _canonical_system(mesh: Mesh, x: np.ndarray, y: np.ndarray):
    """Residuals and Jacobian (sparse) of the canonical equations.

    Rows: one per corner (``x_v . y_f - 1``), one per edge (distance of its
    line from the origin, minus 1), and three for the mean tangency point
    (scaled by ``sqrt(E)``), which pin the Moebius boosts that would
    otherwise be free.
    """
    from scipy import sparse

    nv = x.shape[0]
    H = mesh.n_halfedges
    v, f = mesh.corners, mesh.halfedge_face
    xv, yf = x[v], y[f]
    r_corner = np.einsum("ij,ij->i", xv, yf) - 1.0
    a, b = mesh.edges[:, 0], mesh.edges[:, 1]
    E = a.size
    u, w = x[a], x[b]
    c = np.cross(u, w)
    lv = u - w
    cn = np.linalg.norm(c, axis=1)
    ln = np.linalg.norm(lv, axis=1)
    d = cn / ln
    r_edge = d - 1.0
    ch = c / cn[:, None]
    lh = lv / ln[:, None]
    du = (np.cross(w, ch) - d[:, None] * lh) / ln[:, None]
    dw = (np.cross(ch, u) + d[:, None] * lh) / ln[:, None]
    # tangency point t = u - alpha l, l = w - u, alpha = u.l / l.l
    lw = -lv
    ll = np.einsum("ij,ij->i", lw, lw)
    alpha = np.einsum("ij,ij->i", u, lw) / ll
    t = u - alpha[:, None] * lw
    eye = np.eye(3)
    dt_du = (1.0 + alpha)[:, None, None] * eye - np.einsum(
        "ei,ej->eij", lw, lw - u + 2.0 * alpha[:, None] * lw
    ) / ll[:, None, None]
    dt_dw = (
        -alpha[:, None, None] * eye
        - np.einsum("ei,ej->eij", lw, u - 2.0 * alpha[:, None] * lw) / ll[:, None, None]
    )
    root = np.sqrt(E)
    r_centre = t.sum(axis=0) / root
    k3 = np.arange(3)
    centre_rows = H + E + np.repeat(k3, 3)  # (i, j) pairs, row-major
    centre_cols = np.tile(k3, 3)
    rows = np.concatenate(
        [
            np.repeat(np.arange(H), 3),
            np.repeat(np.arange(H), 3),
            np.repeat(H + np.arange(E), 3),
            np.repeat(H + np.arange(E), 3),
            np.tile(centre_rows, E),
            np.tile(centre_rows, E),
        ]
    )
    cols = np.concatenate(
        [
            (3 * v[:, None] + k3).ravel(),
            (3 * nv + 3 * f[:, None] + k3).ravel(),
            (3 * a[:, None] + k3).ravel(),
            (3 * b[:, None] + k3).ravel(),
            (3 * a[:, None] + centre_cols).ravel(),
            (3 * b[:, None] + centre_cols).ravel(),
        ]
    )
    vals = np.concatenate(
        [
            yf.ravel(),
            xv.ravel(),
            du.ravel(),
            dw.ravel(),
            dt_du.reshape(E, 9).ravel() / root,
            dt_dw.reshape(E, 9).ravel() / root,
        ]
    )
    n_unknowns = 3 * (nv + y.shape[0])
    J = sparse.csr_matrix((vals, (rows, cols)), shape=(H + E + 3, n_unknowns))
    return np.concatenate([r_corner, r_edge, r_centre]), J


def _least_norm_lm(
    residual_and_jacobian,
    z,
    max_iterations,
    stop,
    weights=None,
):
    """Levenberg-Marquardt with steps of least (weighted) norm.

    ``residual_and_jacobian(z) -> (r, J)``; the step solves
    ``(J W J^T + lam I) mu = r``, ``dz = -W J^T mu`` and is kept when it
    lowers ``|r|``.  Stops when ``max |r| <= stop``.

    Returns
    -------
    z, iterations, message
    """
    from scipy import sparse
    from scipy.sparse.linalg import spsolve

    r, J = residual_and_jacobian(z)
    cost = float(r @ r)
    lam = 1e-6
    W = None if weights is None else sparse.diags(weights)
    its = 0
    while its < max_iterations:
        if np.abs(r).max() <= stop:
            return z, its, "converged"
        JW = J if W is None else J @ W
        A = (JW @ J.T).tocsc()
        eye = sparse.identity(A.shape[0], format="csc")
        accepted = False
        while its < max_iterations:
            its += 1
            mu = spsolve(A + lam * eye, r)
            dz = -(JW.T @ mu)
            z_new = z + dz
            r_new, J_new = residual_and_jacobian(z_new)
            cost_new = float(r_new @ r_new)
            if np.isfinite(cost_new) and cost_new < cost:
                z, r, J, cost = z_new, r_new, J_new, cost_new
                lam = max(lam / 10.0, 1e-15)
                accepted = True
                break
            lam *= 10.0
            if lam > 1e8:
                break
        if not accepted:
            return z, its, "no step lowers the residual (stalled)"
    if np.abs(r).max() <= stop:
        return z, its, "converged"
    return z, its, f"stopped after {max_iterations} iterations"


def _solve_canonical(mesh, x, y, max_iterations, tolerance, centring=True):
    """Newton (least-norm Levenberg-Marquardt) on the canonical equations;
    without ``centring`` the three dense centring rows are left out (a
    polish that is centred afterwards)."""
    nv = x.shape[0]

    def system(z):
        r, J = _canonical_system(mesh, z[: 3 * nv].reshape(-1, 3), z[3 * nv :].reshape(-1, 3))
        return (r, J) if centring else (r[:-3], J[:-3])

    z0 = np.concatenate([x.ravel(), y.ravel()])
    z, its, message = _least_norm_lm(system, z0, max_iterations, stop=min(tolerance, 1e-8) * 1e-3)
    return z[: 3 * nv].reshape(-1, 3), z[3 * nv :].reshape(-1, 3), its, message


def _boost_matrix(b: np.ndarray) -> np.ndarray:
    """The Lorentz boost of rapidity vector ``b`` on homogeneous ``(p, 1)``."""
    theta = float(np.linalg.norm(b))
    L = np.eye(4)
    if theta == 0.0:
        return L
    n = b / theta
    ch, sh = np.cosh(theta), np.sinh(theta)
    L[:3, :3] += (ch - 1.0) * np.outer(n, n)
    L[:3, 3] = -sh * n
    L[3, :3] = -sh * n
    L[3, 3] = ch
    return L


def _apply_projective(L: np.ndarray, p: np.ndarray) -> np.ndarray:
    h = np.concatenate([p, np.ones((p.shape[0], 1))], axis=1) @ L.T
    return h[:, :3] / h[:, 3:]


def _centre(mesh: Mesh, x: np.ndarray) -> np.ndarray:
    """Apply the Moebius boost that puts the mean of the tangency points at
    the origin (Newton on the three rapidity components; the boost maps
    the unit sphere to itself, tangent lines to tangent lines and planes to
    planes, so the equations solved before stay solved)."""
    t, _ = tangency_points(mesh.with_vertices(x))
    t /= np.linalg.norm(t, axis=1, keepdims=True)
    total = np.eye(4)
    for _ in range(50):
        c = t.mean(axis=0)
        if np.linalg.norm(c) < 1e-15:
            break
        M = t.T @ t / t.shape[0]
        step = np.linalg.solve(np.eye(3) - M, c)
        L = _boost_matrix(step)
        t = _apply_projective(L, t)
        t /= np.linalg.norm(t, axis=1, keepdims=True)
        total = L @ total
    return _apply_projective(total, x)
