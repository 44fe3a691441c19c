"""The subdivision matrix: one step of "remesh, then duals" as a sparse linear map.

Section 7 of the paper leaves open whether its schemes converge to smooth
surfaces ("there is still a need for theoretical proofs for convergence").
The standard tool of subdivision theory for that question is the
*subdivision matrix*: every operator of the package places its new
vertices at affine combinations of the old ones (edge points, centroids,
scaled blends), so ``k`` iterations of "remesh, then ``duals`` duals" map
old positions to new ones by one sparse matrix ``S`` with
``S @ mesh.vertices == result.vertices``, the connectivity being fixed by
the input's.

Two ways to build ``S``:

* **from the rules** (every scheme of :data:`pentanb.SCHEMES` and the
  dual): each new vertex's row is written from the operator's documented
  numbering -- old vertices, then edge points, then per-face or
  per-half-edge points.  Fast (whole-array expressions) and exact.
* **by probing** (any other ``Mesh -> Mesh`` callable): the callable is run
  on positions moved one basis direction at a time (three columns per
  call, one per coordinate), then ``S`` is checked on random positions: if
  the callable is not linear in the positions, or its connectivity depends
  on them, a :class:`ValueError` says so.  Costs about ``n / 3`` calls.

Every row of ``S`` sums to 1 (affine invariance: translating the mesh
translates the result).

Open meshes (surfaces with boundary) too: the rules add the rows of the
points an operator puts on the boundary (the midpoints of the boundary
edges for the dual and honeycomb, two points per boundary edge for corner
cutting and hexagon preservation) and of the boundary's corners, kept
(:func:`pentanb.schemes.boundary_corners`; which vertices are corners
depends on the positions, so ``S`` is the matrix of the connectivity the
positions give).  :func:`pentanb.analysis.boundary_spectrum` reads the
boundary curve's own rule from it.

The weights of every registered scheme are rational (edge points at 1/2
or 1/3, centroids 1/n, the scale of pentagon preservation and of the
hexagonal and corner-cutting rules), so ``S`` is also available exactly:
:func:`exact_remesh_matrix` and :func:`exact_dual_matrix` write the same
rules with :class:`fractions.Fraction` weights (an :class:`ExactMatrix`),
for the exact eigenvalue analysis of :mod:`pentanb.analysis.spectral`.  A
float scale is taken as the binary fraction it is (``0.75`` is ``3/4``);
pass a :class:`~fractions.Fraction` for any other rational.

The weights are non-negative for every registered scheme (their rules are
convex combinations); a user's scheme may have negative weights, which
:func:`matrix_checks` reports.

scipy is needed here (and only here and in the other analysis modules):
``import pentanb`` needs numpy only.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from .. import _checks
from .. import schemes as _schemes
from ..mesh import Mesh, MeshError
from ..schemes.refs import parse_ref
from ..schemes.registry import Scheme
from ..subdivision import estimate_bytes, get_scheme, predict_counts, subdivide

__all__ = [
    "subdivision_matrix",
    "remesh_matrix",
    "dual_matrix",
    "probe_matrix",
    "matrix_checks",
    "MatrixChecks",
    "RULE_SCHEMES",
    "ExactMatrix",
    "exact_remesh_matrix",
    "exact_dual_matrix",
]

#: Relative tolerance of ``S @ vertices == result.vertices``.
RTOL = 1e-12


def _sparse():
    import scipy.sparse

    return scipy.sparse


def _csr(rows, cols, vals, shape):
    sp = _sparse()
    m = sp.csr_matrix(
        (np.asarray(vals, dtype=np.float64), (np.asarray(rows), np.asarray(cols))), shape=shape
    )
    m.sum_duplicates()
    m.eliminate_zeros()
    return m


# ---------------------------------------------------------------------------
# row blocks: (rows, cols, vals) for points written from the old vertices
# ---------------------------------------------------------------------------


class ExactMatrix:
    """A sparse matrix of :class:`~fractions.Fraction` weights (CSR, rows summed once).

    What :func:`exact_remesh_matrix` and :func:`exact_dual_matrix` return: the
    same rules as the float matrices, in exact arithmetic.

    Attributes
    ----------
    shape : (int, int)
    indptr, indices : int arrays
        CSR structure, columns sorted within each row.
    data : object array of Fraction
        The non-zero weights.
    """

    def __init__(self, indptr, indices, data, shape: tuple[int, int]):
        self.indptr = np.asarray(indptr, dtype=np.int64)
        self.indices = np.asarray(indices, dtype=np.int64)
        self.data = np.asarray(data, dtype=object)
        self.shape = (int(shape[0]), int(shape[1]))

    @classmethod
    def from_coo(cls, rows, cols, vals, shape) -> ExactMatrix:
        """Entries ``(rows[i], cols[i], vals[i])``, duplicates summed, zeros dropped.

        Parameters
        ----------
        rows, cols : int arrays
        vals : sequence of Fraction
        shape : (int, int)

        Returns
        -------
        ExactMatrix
        """
        rows = np.asarray(rows, dtype=np.int64)
        cols = np.asarray(cols, dtype=np.int64)
        vals = np.asarray(vals, dtype=object)
        order = np.lexsort((cols, rows))
        rows, cols, vals = rows[order], cols[order], vals[order]
        if rows.size:
            new = np.ones(rows.size, dtype=bool)
            new[1:] = (rows[1:] != rows[:-1]) | (cols[1:] != cols[:-1])
            starts = np.flatnonzero(new)
            vals = np.add.reduceat(vals, starts) if vals.size else vals
            rows, cols = rows[starts], cols[starts]
            keep = np.array([v != 0 for v in vals], dtype=bool)
            rows, cols, vals = rows[keep], cols[keep], vals[keep]
        indptr = np.zeros(int(shape[0]) + 1, dtype=np.int64)
        np.add.at(indptr, rows + 1, 1)
        return cls(np.cumsum(indptr), cols, vals, shape)

    @property
    def nnz(self) -> int:
        """Number of stored weights."""
        return int(self.indices.size)

    def row(self, i: int) -> dict[int, Fraction]:
        """Row ``i`` as ``{column: weight}``.

        Parameters
        ----------
        i : int
            A row index.

        Returns
        -------
        dict
        """
        a, b = int(self.indptr[i]), int(self.indptr[i + 1])
        return dict(zip(self.indices[a:b].tolist(), self.data[a:b].tolist()))

    def toarray(self) -> np.ndarray:
        """The weights as a dense float array (each rounded once).

        Returns
        -------
        (m, n) float ndarray
        """
        out = np.zeros(self.shape)
        r = np.repeat(np.arange(self.shape[0]), np.diff(self.indptr))
        out[r, self.indices] = [float(x) for x in self.data]
        return out


def _inverses(sizes: np.ndarray) -> np.ndarray:
    """``1 / sizes`` as an object array of fractions."""
    top = int(sizes.max(initial=1))
    table = np.array([Fraction(0)] + [Fraction(1, n) for n in range(1, top + 1)], dtype=object)
    return table[sizes]


class _Rows:
    """Accumulates blocks of rows ``(cols, vals)`` in output order.

    With ``exact``, the weights are :class:`~fractions.Fraction` objects and
    :meth:`matrix` returns an :class:`ExactMatrix`.
    """

    def __init__(self, n_old: int, exact: bool = False):
        self.n_old = n_old
        self.exact = exact
        self.rows: list[np.ndarray] = []
        self.cols: list[np.ndarray] = []
        self.vals: list[np.ndarray] = []
        self.n = 0

    def weight(self, x):
        """A scalar weight in this accumulator's number type."""
        return Fraction(x) if self.exact else float(x)

    def add(self, row_local, cols, vals, count: int) -> None:
        """``count`` new rows; entry ``i`` sits in local row ``row_local[i]``."""
        self.rows.append(self.n + np.asarray(row_local, dtype=np.int64))
        self.cols.append(np.asarray(cols, dtype=np.int64))
        self.vals.append(np.asarray(vals, dtype=object if self.exact else np.float64))
        self.n += int(count)

    def identity(self) -> None:
        n = self.n_old
        r = np.arange(n, dtype=np.int64)
        self.add(r, r, np.full(n, self.weight(1), dtype=object if self.exact else np.float64), n)

    def edge_points(self, mesh: Mesh, k: int, fractions=None) -> None:
        """Rows ``k e + j`` at ``(j + 1) / (k + 1)`` (or ``fractions[j]``) from the
        edge's smaller vertex."""
        E = mesh.n_edges
        a, b = mesh.edges[:, 0], mesh.edges[:, 1]
        if fractions is not None:
            t = np.array(fractions, dtype=object if self.exact else np.float64)
        elif self.exact:
            t = np.array([Fraction(j, k + 1) for j in range(1, k + 1)], dtype=object)
        else:
            t = np.arange(1, k + 1, dtype=np.float64) / (k + 1)
        rows = np.arange(E * k, dtype=np.int64)
        ta = np.broadcast_to(1 - t, (E, k)).reshape(-1)
        tb = np.broadcast_to(t, (E, k)).reshape(-1)
        self.add(
            np.concatenate([rows, rows]),
            np.concatenate([np.repeat(a, k), np.repeat(b, k)]),
            np.concatenate([ta, tb]),
            E * k,
        )

    def centroids(self, mesh: Mesh, faces: np.ndarray | None = None) -> None:
        """One row per face (or per face of ``faces``, in that order): its centroid."""
        hf = mesh.halfedge_face
        sizes = mesh.face_sizes[hf]
        w = _inverses(sizes) if self.exact else 1.0 / sizes
        if faces is None:
            self.add(hf, mesh.corners, w, mesh.n_faces)
            return
        local = np.full(mesh.n_faces, -1, dtype=np.int64)
        local[faces] = np.arange(faces.size, dtype=np.int64)
        keep = local[hf] >= 0
        self.add(local[hf[keep]], mesh.corners[keep], w[keep], faces.size)

    def per_halfedge(self, mesh: Mesh, w_tail, w_head, w_centroid) -> None:
        """One row per half-edge ``h``: ``w_tail tail + w_head head + w_centroid c_f``."""
        H = mesh.n_halfedges
        h = np.arange(H, dtype=np.int64)
        hf = mesh.halfedge_face
        # the centroid of h's face, spread over the face's corners
        sizes = mesh.face_sizes[hf]
        owner = np.repeat(h, sizes)  # row h gets every corner of its face
        start = mesh.offsets[:-1][hf]
        within = np.arange(owner.size, dtype=np.int64) - np.repeat(np.cumsum(sizes) - sizes, sizes)
        corner_cols = mesh.corners[np.repeat(start, sizes) + within]
        dtype = object if self.exact else np.float64
        share = _inverses(sizes) * w_centroid if self.exact else w_centroid / sizes
        self.add(
            np.concatenate([h, h, owner]),
            np.concatenate([mesh.corners, mesh.head, corner_cols]),
            np.concatenate(
                [
                    np.full(H, w_tail, dtype=dtype),
                    np.full(H, w_head, dtype=dtype),
                    np.repeat(share, sizes),
                ]
            ),
            H,
        )

    def boundary_points(self, mesh: Mesh, weights) -> None:
        """``len(weights)`` rows per boundary edge ``bh[j]`` (rows ``k j + i``):
        ``weights[i] = (w_tail, w_head)`` on its tail and head.  None when closed."""
        bh = mesh.boundary_halfedges
        B, k = bh.size, len(weights)
        if not B:
            return
        tail = np.asarray(mesh.corners[bh], dtype=np.int64)
        head = np.asarray(mesh.head[bh], dtype=np.int64)
        dtype = object if self.exact else np.float64
        wt = np.array([self.weight(w) for w, _ in weights], dtype=dtype)
        wh = np.array([self.weight(w) for _, w in weights], dtype=dtype)
        rows = np.arange(B * k, dtype=np.int64)
        self.add(
            np.concatenate([rows, rows]),
            np.concatenate([np.repeat(tail, k), np.repeat(head, k)]),
            np.concatenate([np.tile(wt, B), np.tile(wh, B)]),
            B * k,
        )

    def kept_corners(self, mesh: Mesh) -> None:
        """One row per corner of the boundary (:func:`pentanb.schemes.boundary_corners`,
        in vertex order): the corner itself.  None when closed."""
        at = _schemes.boundary_corners(mesh)
        if at.size:
            self.add(
                np.arange(at.size),
                at,
                np.full(at.size, self.weight(1), dtype=object if self.exact else np.float64),
                at.size,
            )

    def matrix(self):
        rows = np.concatenate(self.rows)
        cols = np.concatenate(self.cols)
        vals = np.concatenate(self.vals)
        if self.exact:
            return ExactMatrix.from_coo(rows, cols, vals, (self.n, self.n_old))
        return _csr(rows, cols, vals, (self.n, self.n_old))


# ---------------------------------------------------------------------------
# the rules of the registered schemes (numbering: see each operator's docstring)
# ---------------------------------------------------------------------------


def dual_matrix(mesh: Mesh):
    """The dual as a matrix: row ``f`` is the centroid of face ``f``.

    Parameters
    ----------
    mesh : Mesh
        V vertices, F faces; open meshes too (B boundary edges, C corners).

    Returns
    -------
    scipy.sparse.csr_matrix, shape (F, V), or (F + B + C, V) when open
        ``dual_matrix(m) @ m.vertices == pentanb.dual(m).vertices``; on an
        open mesh the centroids are followed by the midpoints of the
        boundary edges (in the order of ``m.boundary_halfedges``) and the
        corners, kept (:func:`pentanb.schemes.boundary_corners`).
    """
    return _dual(mesh)


def _dual(mesh: Mesh, out: Mesh | None = None, *, exact: bool = False):
    rows = _Rows(mesh.n_vertices, exact)
    rows.centroids(mesh)
    if not mesh.is_closed:  # the midpoints of the boundary edges, then the corners, kept
        half = Fraction(1, 2)
        rows.boundary_points(mesh, [(half, half)])
        rows.kept_corners(mesh)
    return rows.matrix()


def table_rows(table, mesh: Mesh, out: Mesh | None = None, *, exact: bool = False, **options):
    """The matrix of a :class:`~pentanb.Table`, read off its points' weights.

    Its blocks in output order: the old vertices (identity), its edge points
    at the table's fractions, the face centroids, and its corner points (a
    face's polygon of V or of an edge point scaled about its centroid, or an
    affine rule over V, ``n:V``, E points and F).  None for a rule beyond
    these (a corner point over other half-edges): such a table is probed.
    """
    r = _Rows(mesh.n_vertices, exact)

    def frac(x: float):  # (1/3 given as a float is the fraction 1/3)
        return Fraction(x).limit_denominator(10**6) if exact else float(x)

    if table.vertices:
        r.identity()
    if table.edge_points:
        r.edge_points(mesh, len(table.edge_points), [frac(t) for t in table.edge_points])
    if table.face_points:
        r.centroids(mesh)
    cp = table.corner_points
    if cp is None:
        return r.matrix()
    w = {"tail": 0 * frac(0), "head": 0 * frac(0), "centre": 0 * frac(0)}
    if isinstance(cp, dict):
        terms = [(parse_ref(k, table.name), frac(v)) for k, v in cp.items()]
    else:
        elem, scale = cp
        sc = r.weight(
            options.get(scale, table.options.get(scale)) if isinstance(scale, str) else scale
        )
        terms = [(parse_ref(elem, table.name), sc), (parse_ref("F", table.name), 1 - sc)]
    for ref, x in terms:
        if ref.path not in ("", "n") or (ref.path == "n" and ref.elem != "V"):
            return None
        if ref.elem == "F":
            w["centre"] += x
        elif ref.elem == "V":
            w["head" if ref.path else "tail"] += x
        else:  # E_j of h: (1 - t) tail + t head
            t = frac(table.edge_points[ref.j])
            w["tail"] += x * (1 - t)
            w["head"] += x * t
    r.per_halfedge(mesh, w["tail"], w["head"], w["centre"])
    return r.matrix()


def _triangulate(mesh: Mesh, out: Mesh, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    r.identity()
    big = np.flatnonzero(mesh.face_sizes > 3)
    if big.size:
        r.centroids(mesh, big)
    return r.matrix()


def _loop_remesh(mesh: Mesh, out: Mesh, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    r.identity()
    r.edge_points(mesh, 1)
    return r.matrix()


def _sqrt3_remesh(mesh: Mesh, out: Mesh, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    r.identity()
    r.centroids(mesh)
    return r.matrix()


def _vertex_insertion(mesh: Mesh, out: Mesh, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    r.identity()
    r.edge_points(mesh, 1)
    r.centroids(mesh)
    return r.matrix()


def _corner_cutting(mesh: Mesh, out: Mesh, scale: float = 0.5, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    s = r.weight(scale)
    r.per_halfedge(mesh, s, r.weight(0), 1 - s)
    if not mesh.is_closed:  # two points per boundary edge at scale about its midpoint; corners
        r.boundary_points(mesh, [((1 + s) / 2, (1 - s) / 2), ((1 - s) / 2, (1 + s) / 2)])
        r.kept_corners(mesh)
    return r.matrix()


def _preserve_hexagons(mesh: Mesh, out: Mesh, scale: float = 0.5, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    s = r.weight(scale)
    r.identity()
    r.per_halfedge(mesh, s, r.weight(0), 1 - s)
    if not mesh.is_closed:  # the trisection points of every boundary edge
        third = Fraction(1, 3)
        r.boundary_points(mesh, [(2 * third, third), (third, 2 * third)])
    return r.matrix()


def _honeycomb(mesh: Mesh, out: Mesh, *, exact: bool = False):
    r = _Rows(mesh.n_vertices, exact)
    third = Fraction(1, 3) if exact else 1.0 / 3.0
    r.per_halfedge(mesh, third, third, third)
    if not mesh.is_closed:  # the midpoints of the boundary edges, then the corners, kept
        half = Fraction(1, 2)
        r.boundary_points(mesh, [(half, half)])
        r.kept_corners(mesh)
    return r.matrix()


_RULES: dict[Callable, Callable] = {
    _schemes.triangulate: _triangulate,
    _schemes.corner_cutting: _corner_cutting,
    _schemes.preserve_hexagons: _preserve_hexagons,
    _schemes.honeycomb: _honeycomb,
    _schemes.dual: _dual,
}

#: Names of the registered schemes whose matrix is written from their rules or
#: their tables' weights (every other callable is probed).
RULE_SCHEMES = tuple(
    s.name for s in _schemes.SCHEMES.values() if s.func in _RULES or s.table is not None
)


def _rule_of(scheme) -> Callable | None:
    func = scheme.func if isinstance(scheme, Scheme) else scheme
    if func in _RULES:
        return _RULES[func]
    table = scheme.table if isinstance(scheme, Scheme) else None
    if table is None:
        table = getattr(func, "__self__", None)  # (a page's function: its table's call)
    if isinstance(table, _schemes.Table):
        rows = table

        def rule(mesh: Mesh, out: Mesh, *, exact: bool = False, **options):
            return table_rows(rows, mesh, out, exact=exact, **options)

        return rule
    return None


# ---------------------------------------------------------------------------
# probing: any Mesh -> Mesh callable whose positions are linear
# ---------------------------------------------------------------------------


def probe_matrix(
    mesh: Mesh,
    func: Callable[[Mesh], Mesh],
    out: Mesh | None = None,
    *,
    max_vertices: int = 3000,
    seed: int = 0,
):
    """The matrix of ``func`` found by probing with basis positions.

    ``func`` is run on ``mesh`` with one vertex moved along x, another
    along y and a third along z at a time, so each call gives three columns
    of ``S``; ``ceil(n / 3)`` calls in all.  ``S`` is then checked on
    random positions.

    Parameters
    ----------
    mesh : Mesh
        n vertices.
    func : callable
        ``func(mesh) -> Mesh``.  Must place new vertices by the same linear
        rule in every coordinate, and keep its connectivity whatever the
        positions.
    out : Mesh, optional
        ``func(mesh)``, when the caller already has it.
    max_vertices : int
        Refuse (ValueError) meshes with more vertices (probing costs about
        ``n / 3`` calls of ``func``).
    seed : int
        Seed of the random check.

    Returns
    -------
    scipy.sparse.csr_matrix, shape (out.n_vertices, n)

    Raises
    ------
    ValueError
        When the mesh is too large to probe, when ``func``'s connectivity
        changes with the positions, or when its positions are not linear
        (the message gives the largest error).
    """
    n = mesh.n_vertices
    if n > max_vertices:
        raise ValueError(
            f"probing needs about {n // 3 + 2} calls of the scheme on this mesh of {n} vertices "
            f"(limit max_vertices={max_vertices}); probe a smaller mesh"
        )
    base = np.asarray(mesh.vertices)
    if out is None:
        out = _call(func, mesh)
    y0 = np.asarray(out.vertices)
    extent = float(np.ptp(base, axis=0).max()) or 1.0
    cols: list[np.ndarray] = []
    rows: list[np.ndarray] = []
    vals: list[np.ndarray] = []
    for start in range(0, n, 3):
        x = base.copy()
        idx = list(range(start, min(start + 3, n)))
        for c, i in enumerate(idx):
            x[i, c] += extent
        y = _call(func, mesh.with_vertices(x))
        _same_connectivity(out, y, name=_name(func))
        d = (np.asarray(y.vertices) - y0) / extent
        for c, i in enumerate(idx):
            nz = np.flatnonzero(np.abs(d[:, c]) > 1e-13)
            rows.append(nz)
            cols.append(np.full(nz.size, i, dtype=np.int64))
            vals.append(d[nz, c])
    S = _csr(np.concatenate(rows), np.concatenate(cols), np.concatenate(vals), (out.n_vertices, n))
    _check_linear(S, mesh, func, out, seed)
    return S


def _check_linear(S, mesh: Mesh, func, out: Mesh, seed: int) -> None:
    rng = np.random.default_rng(seed)
    scale = float(np.ptp(np.asarray(mesh.vertices), axis=0).max()) or 1.0
    err = _relative_error(S @ np.asarray(mesh.vertices), out.vertices)
    x = np.asarray(mesh.vertices) + 0.1 * scale * rng.standard_normal(mesh.vertices.shape)
    y = _call(func, mesh.with_vertices(x))
    _same_connectivity(out, y, name=_name(func))
    err = max(err, _relative_error(S @ x, y.vertices))
    if err > 1e-9:
        raise ValueError(
            f"the positions of {_name(func)} are not linear in the input positions "
            f"(probed matrix misses by {err:.2e} relative on random positions): "
            "no subdivision matrix describes it"
        )


def _call(func, mesh: Mesh) -> Mesh:
    out = func(mesh)
    if not isinstance(out, Mesh):
        raise TypeError(f"scheme {_name(func)} returned {type(out).__name__}, not a pentanb.Mesh")
    return out


def _same_connectivity(a: Mesh, b: Mesh, name: str) -> None:
    if not (np.array_equal(a.offsets, b.offsets) and np.array_equal(a.corners, b.corners)):
        raise ValueError(
            f"the connectivity of {name}'s output changes when the positions change: "
            "no single subdivision matrix describes it"
        )


def _name(func) -> str:
    return str(getattr(func, "name", getattr(func, "__name__", repr(func))))


def _relative_error(a, b) -> float:
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    scale = max(float(np.abs(b).max(initial=0.0)), 1e-300)
    return float(np.abs(a - b).max(initial=0.0) / scale)


# ---------------------------------------------------------------------------
# public entry points
# ---------------------------------------------------------------------------


def remesh_matrix(mesh: Mesh, scheme, *, probe: bool | None = None, **options):
    """One remeshing (no duals) and its matrix.

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    probe : bool, optional
        Force probing (True) or the rules (False; an error for a scheme
        without rules).  Default: the rules where the scheme has them.
    **options
        The scheme's options (``scale=...``).

    Returns
    -------
    S : scipy.sparse.csr_matrix, shape (out.n_vertices, mesh.n_vertices)
    out : Mesh
        ``scheme(mesh, **options)``.
    """
    s = get_scheme(scheme)
    out = _call(lambda m: s(m, **options), mesh)
    rule = _rule_of(s)
    if probe is False and rule is None:
        raise ValueError(f"scheme {_name(s)} has no rules here; it can only be probed")
    if rule is not None and not probe:
        S = rule(mesh, out, **options)
        if S is None:  # (a table whose corner points are beyond the rows: probed)
            return probe_matrix(mesh, lambda m: s(m, **options), out), out
        err = _relative_error(S @ np.asarray(mesh.vertices), out.vertices)
        if S.shape[0] != out.n_vertices or err > RTOL:
            raise RuntimeError(  # pragma: no cover - a broken numbering contract
                f"the rules of {_name(s)} no longer match its output (error {err:.2e}, "
                f"{S.shape[0]} rows for {out.n_vertices} vertices): its vertex numbering changed"
            )
        return S, out
    return probe_matrix(mesh, lambda m: s(m, **options), out), out


def exact_remesh_matrix(mesh: Mesh, scheme, out: Mesh | None = None, **options) -> ExactMatrix:
    """One remeshing's matrix with exact (rational) weights.

    The rules of :func:`remesh_matrix`, with :class:`~fractions.Fraction`
    weights: a scale is taken exactly (a float as the binary fraction it is,
    ``0.75`` as ``3/4``; a :class:`~fractions.Fraction` as itself).

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        A scheme with rules (:data:`RULE_SCHEMES`, or the dual); a probed
        callable has no exact matrix.
    out : Mesh, optional
        ``scheme(mesh, **options)`` when the caller has it (the rules read
        only the input's connectivity; ``out`` is accepted for symmetry).
    **options
        The scheme's options (``scale=Fraction(5, 7)``).

    Returns
    -------
    ExactMatrix, shape (out.n_vertices, mesh.n_vertices)
        Equal, rounded to floats, to :func:`remesh_matrix`'s matrix to
        rounding (checked by the tests).

    Raises
    ------
    ValueError
        For a scheme without rules.
    """
    s = get_scheme(scheme)
    rule = _rule_of(s)
    if rule is None:
        raise ValueError(f"scheme {_name(s)} has no rules here: no exact matrix")
    if out is None:
        out = mesh
    got = rule(mesh, out, exact=True, **options)
    if got is None:
        raise ValueError(f"scheme {_name(s)}'s corner points have no exact rule here")
    return got


def exact_dual_matrix(mesh: Mesh) -> ExactMatrix:
    """The dual's matrix with exact weights (``1/n`` for a face of ``n`` sides).

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    ExactMatrix, shape (F, V)
    """
    return _dual(mesh, exact=True)


def subdivision_matrix(
    mesh: Mesh,
    scheme: str | Scheme | Callable = "pentagonalize",
    iterations: int = 1,
    duals: int = 2,
    *,
    probe: bool | None = None,
    max_bytes: int | None = None,
    **options,
) -> tuple[Any, Mesh]:
    """The subdivision matrix of :func:`pentanb.subdivide` (Section 7's open question).

    Parameters
    ----------
    mesh : Mesh
        n vertices; closed or open (the rows of the boundary's points are
        written from the operators' boundary rules; probing an open mesh
        may fail where moving a vertex makes or unmakes a corner).
    scheme, iterations, duals, **options
        As for :func:`pentanb.subdivide`.
    probe : bool, optional
        Probe the remeshing with basis positions even where rules exist
        (True), or never (False).  Default: rules for the schemes of
        :data:`RULE_SCHEMES`, probing for any other callable.
    max_bytes : int, optional
        As for :func:`pentanb.subdivide`.

    Returns
    -------
    S : scipy.sparse.csr_matrix, shape (result.n_vertices, n)
        ``S @ mesh.vertices`` equals ``result.vertices`` to 1e-12 relative
        (checked).  Rows sum to 1.
    result : Mesh
        Exactly what ``pentanb.subdivide(mesh, scheme, iterations, duals,
        **options)`` returns (the same operators in the same order).

    Raises
    ------
    ValueError
        Unknown scheme or option, bad counts (as :func:`pentanb.subdivide`),
        a scheme whose positions are not linear (probing).
    MeshError
        When the result would not fit in ``max_bytes``.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.analysis.subdivision_matrix import subdivision_matrix
    >>> S, out = subdivision_matrix(pentanb.shapes.cube(), "pentagonalize")
    >>> S.shape
    (38, 8)
    """
    s = get_scheme(scheme)
    # subdivide's own checks: counts, options, memory (nothing is built here)
    subdivide(mesh, s, 0, duals, max_bytes=max_bytes, **options)
    iterations = _count(iterations, "iterations")
    duals = _count(duals, "duals")
    if isinstance(s, Scheme):
        steps = predict_counts((mesh.n_vertices, mesh.n_edges, mesh.n_faces), s, iterations, duals)
        if steps:
            V, E, F = max(steps, key=estimate_bytes)
            # the matrix holds about 8 weights of 12 bytes for every vertex of every step
            need = estimate_bytes((V, E, F)) + 96 * V
            limit = max_bytes if max_bytes is not None else _default_limit()
            if need > limit:
                raise MeshError(
                    f"the subdivision matrix of {s.name} x{iterations} with {duals} duals "
                    f"would need about {need:,} bytes (limit {limit:,})"
                )
    sp = _sparse()
    S = sp.identity(mesh.n_vertices, format="csr")
    x0 = np.asarray(mesh.vertices)
    current = mesh
    for _ in range(iterations):
        R, current = remesh_matrix(current, s, probe=probe, **options)
        S = R @ S
        for _ in range(duals):
            D = dual_matrix(current)
            current = _schemes.dual(current)
            S = D @ S
    S = S.tocsr()
    S.sum_duplicates()
    err = _relative_error(S @ x0, current.vertices)
    if err > RTOL:
        raise RuntimeError(  # pragma: no cover - guarded by remesh_matrix
            f"subdivision matrix misses the result by {err:.2e} relative"
        )
    return S, current


def _count(value, name: str) -> int:
    return _checks.count(value, name)


def _default_limit() -> int:
    from ..subdivision import default_max_bytes

    return default_max_bytes()


@dataclass(frozen=True)
class MatrixChecks:
    """What :func:`matrix_checks` found.

    Attributes
    ----------
    shape : (int, int)
    nnz : int
    row_sum_error : float
        Largest ``|sum of a row - 1|`` (0 up to round-off: affine invariance).
    min_weight : float
        Smallest weight (>= 0 for convex rules).
    reproduces : float
        Relative error of ``S @ vertices`` against the result's vertices.
    """

    shape: tuple[int, int]
    nnz: int
    row_sum_error: float
    min_weight: float
    reproduces: float

    @property
    def affine(self) -> bool:
        """Every row sums to 1 (to 1e-12)."""
        return self.row_sum_error <= 1e-12

    @property
    def convex(self) -> bool:
        """Every weight is non-negative."""
        return self.min_weight >= 0.0


def matrix_checks(S, mesh: Mesh, result: Mesh) -> MatrixChecks:
    """Row sums, signs and reproduction of a subdivision matrix.

    Parameters
    ----------
    S : sparse matrix, shape (result.n_vertices, mesh.n_vertices)
    mesh, result : Mesh
    """
    S = S.tocsr()
    sums = np.asarray(S.sum(axis=1)).ravel()
    return MatrixChecks(
        shape=(int(S.shape[0]), int(S.shape[1])),
        nnz=int(S.nnz),
        row_sum_error=float(np.abs(sums - 1.0).max(initial=0.0)),
        min_weight=float(S.data.min()) if S.nnz else 0.0,
        reproduces=_relative_error(S @ np.asarray(mesh.vertices), result.vertices),
    )
