"""Small whole-array helpers shared by the remeshing operators.

Every operator indexes new vertices in blocks: first the old vertices (when
kept), then points on edges, then points per face or per half-edge.  These
helpers compute those blocks from the input's half-edge arrays.

Open meshes (surfaces with boundary) take a numpy path: an operator writes
its output's faces (boundary edges split as interior edges are, faces
remeshed face by face).  The output's twins and vertex rings are written
from the input's when first asked for where the operator knows them
(pentagonalization, pentagon preservation and the dual: every boundary
half-edge of the output lies along one of the input's, so its boundary
loops are the input's, refined, put in order by :func:`open_twins_from`),
and derived from its faces otherwise (:func:`remeshed` does this).  The
operators that make a face of every vertex (the dual, corner cutting,
honeycomb) close a boundary vertex's face along the boundary with
:func:`open_vertex_faces`: through one point on each of its two boundary
edges, and through the vertex itself where it is a *corner*
(:func:`boundary_corners`): a boundary vertex of one face (two edges) where
the boundary turns by more than :data:`CORNER_ANGLE`.  A vertex of one face
on a straight boundary is no corner (pentagonalization leaves one on every
boundary edge, at two thirds of it: keeping those would pin the boundary to
its first polygon); a vertex of one face where the boundary turns sharply
is (as Catmull-Clark's and Doo-Sabin's boundary rules keep such corners:
cutting them lets the faces next to them fold).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, TypeVar

import numpy as np

from .. import _checks, _jit
from ..mesh import Mesh, MeshError, Rings, Several, check_mesh
from ..mesh import build as _mesh
from ..mesh.boundary import canonical_loops, hole_twins
from ..mesh.coerce import index_dtype as _index_dtype
from ..mesh.geometry import SAFE_EXTENT

_Op = TypeVar("_Op", bound=Callable[..., Mesh])

#: Edges (or faces) per block when positions are computed block by block:
#: small enough that the temporaries stay in cache and out of the peak.
BLOCK = 1 << 13


def index_dtype(n_vertices: int, n_corners: int) -> np.dtype:
    """The dtype of an output's index arrays (int32 when its counts allow)."""
    return _index_dtype(n_vertices, n_corners)


def edge_points(
    mesh: Mesh, k: int, out: np.ndarray | None = None, t: np.ndarray | None = None
) -> np.ndarray:
    """Points splitting every edge into ``k + 1`` equal parts.

    Parameters
    ----------
    mesh : Mesh
    k : int
    out : (E * k, 3) float, optional
        Where to write them (a block of an operator's output positions).
    t : (k,) float, optional
        The fractions, from the smaller vertex (``(j + 1) / (k + 1)`` by default).

    Returns
    -------
    (E * k, 3) float
        Point ``j`` (0-based) of edge ``e`` is row ``k * e + j``, at
        ``(j + 1) / (k + 1)`` of the way from the edge's smaller vertex to its
        larger one: ``a * (1 - t) + b * t``.
    """
    edges, v = mesh.edges, mesh.vertices
    E = edges.shape[0]
    res = np.empty((E * k, 3)) if out is None else out
    if t is None:
        t = np.arange(1, k + 1, dtype=np.float64) / (k + 1)
    jit = _jit.kernels(2 * E)
    if jit is not None and v.flags.c_contiguous:  # the same products and sums, compiled
        jit.edge_points(v, edges, t, res)
        return res
    rows = res.reshape(E, k, 3)
    # the products and sums on contiguous blocks (numpy runs those as one
    # flat loop; on the rows of point j, three values of every k * 3, it
    # loops three at a time), then one copy into the rows, each row one
    # 24-byte item: 18.6 -> 8.5 ms for the 983,040 points of 327,680
    # triangles.  The last point is computed in place on the ends (not
    # needed after it), the others in two halves of a block: three blocks
    # at most, as many as ``r = pa * s; r += pb * t`` took
    half = (BLOCK + 1) // 2
    rows_x = min(E, half) if k > 1 else 0
    x, y = np.empty((rows_x, 3)), np.empty((rows_x, 3))
    for a in range(0, E, BLOCK):
        ends = edges[a : a + BLOCK]
        pa, pb = v.take(ends[:, 0], axis=0), v.take(ends[:, 1], axis=0)
        dest = rows[a : a + BLOCK]
        for j in range(k - 1):
            for b in range(0, len(pa), half):
                xa, ya = x[: len(pa) - b], y[: len(pa) - b]
                np.multiply(pa[b : b + half], 1.0 - t[j], out=xa)
                np.multiply(pb[b : b + half], t[j], out=ya)
                xa += ya
                dest[b : b + half, j].view("V24")[:, 0] = xa.view("V24")[:, 0]
        pa *= 1.0 - t[k - 1]
        pb *= t[k - 1]
        pa += pb
        dest[:, k - 1].view("V24")[:, 0] = pa.view("V24")[:, 0]
        del pa, pb  # (a block's temporaries: gone before the next allocations)
    return res


def halfedge_edge_point(mesh: Mesh, k: int, j: int) -> np.ndarray:
    """Index (within :func:`edge_points` ``(mesh, k)``) of the ``j``-th point
    along every half-edge, counted from the half-edge's tail.

    Returns
    -------
    (H,) int
    """
    e = mesh.halfedge_edge
    forward = mesh.corners < mesh.head
    return k * e + np.where(forward, j, k - 1 - j)


def fixed_size(corners_2d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """CSR arrays of faces that all have the same size.

    Parameters
    ----------
    corners_2d : (m, k) int
    """
    m, k = corners_2d.shape
    return corners_2d.reshape(-1), np.arange(0, m * k + 1, k, dtype=corners_2d.dtype)


def concat_faces(*parts: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Concatenate several CSR face blocks into one (int64 offsets: :func:`output` narrows them)."""
    corners = np.concatenate([c for c, _ in parts])
    offs = [parts[0][1].astype(np.int64)]
    shift = int(parts[0][1][-1])
    for _, o in parts[1:]:
        offs.append(o[1:].astype(np.int64) + shift)
        shift += int(o[-1])
    return corners, np.concatenate(offs)


def inverse(ring: np.ndarray) -> np.ndarray:
    """``pos`` with ``pos[ring[i]] = i``: where every half-edge sits in the vertex rings."""
    jit = _jit.kernels(ring.size)
    if jit is not None:  # the same scatter, in parts over the threads
        return jit.inverse(ring)
    pos = np.empty_like(ring)
    pos[ring] = np.arange(ring.size, dtype=ring.dtype)
    return pos


#: Places per block where :func:`opened_ring_items` copies the ring's items
#: around the boundary's insertions (the blocks' masks stay in cache).
OUT_BLOCK = 1 << 15


#: Rings of up to this many half-edges each are turned by :func:`turned`
#: (its work grows as the square of the size: beyond, numpy's argmax and
#: take_along_axis cost less).
TURNED_BY_SELECTS = 6


def turned(cols: list[np.ndarray], out: np.ndarray) -> None:
    """Write the rows ``(cols[0][i], ..., cols[k - 1][i])`` into ``out``, each
    turned to start at its largest entry (the first of equal ones, as argmax).

    Column ``s`` of a row whose largest is in column ``r`` is ``cols[(r + s) % k]``:
    written with branch-free selects on whole columns (``col += (a - col) * m``),
    the last column as what the row sums to less the others (integer
    arithmetic wraps around: both exact), about five times faster on 12
    million entries than an argmax along rows of 3 and a take_along_axis,
    or than ``np.where`` (which mispredicts on a mask of no pattern).

    Parameters
    ----------
    cols : list of k (m,) int arrays
        Contiguous, of one dtype.
    out : (m, k) int
        Where to write the turned rows (a view is fine).
    """
    k = len(cols)
    top = cols[0].copy()
    rest = cols[0].copy()  # the row's sum less its columns written so far
    for c in cols[1:]:
        np.maximum(top, c, out=top)
        rest += c
    at_top = [c == top for c in cols[:-1]]  # (the last column: where no other is)
    out[:, 0] = top
    rest -= top
    del top
    col, step = np.empty_like(cols[0]), np.empty_like(cols[0])
    for s in range(1, k - 1):
        col[...] = cols[(k - 1 + s) % k]  # the largest in the last column...
        for r in range(k - 2, -1, -1):  # ...or in the first column r holding it
            np.subtract(cols[(r + s) % k], col, out=step)
            step *= at_top[r]
            col += step
        out[:, s] = col
        rest -= col
    if k > 1:
        out[:, k - 1] = rest


def start_at_max(
    ring: np.ndarray, offsets: np.ndarray | None, k: int = 0, out: np.ndarray | None = None
) -> np.ndarray:
    """Every vertex's ring turned to start at its largest half-edge, order kept.

    The rings :attr:`pentanb.Mesh.vertex_ring` derives for a mesh start
    there; operators that write their output's rings directly turn them
    the same way, so that the output is the same mesh, bit for bit, as one
    whose rings were derived (the dual's faces start where its rings do).

    Parameters
    ----------
    ring : (H,) int
        Half-edges, vertex after vertex, each vertex's in rotation order
        (any start).
    offsets : (n + 1,) int, or None with ``k``
    k : int
        Every vertex has k half-edges (0: read the sizes from ``offsets``).
    out : (H,) int, optional
        Where to write them (not overlapping ``ring``).

    Returns
    -------
    (H,) int
        ``out``, or a new array.
    """
    jit = _jit.kernels(ring.size)
    if jit is not None:  # the same permutation, compiled
        csr = ring[:0] if offsets is None else offsets  # empty: k half-edges each
        return jit.start_at_max(ring, csr, max(k, 1), out)
    if out is not None:
        out[...] = start_at_max(ring, offsets, k)
        return out
    if k:
        rows = ring.reshape(-1, k)
        if k <= TURNED_BY_SELECTS:
            res = np.empty_like(rows)
            turned([np.ascontiguousarray(rows[:, s]) for s in range(k)], res)
            return res.reshape(-1)
        first = rows.argmax(axis=1)
        cols = (first[:, None] + np.arange(k)) % k
        return np.take_along_axis(rows, cols, axis=1).reshape(-1)
    assert offsets is not None
    sizes = np.diff(offsets)
    if not ring.size:
        return ring.copy()
    runs = np.flatnonzero(sizes[1:] != sizes[:-1]) + 1  # where the size changes
    if 64 * (runs.size + 1) <= sizes.size:  # long runs of one size (an operator's blocks)
        out = np.empty_like(ring)
        for a, b in zip([0, *runs.tolist()], [*runs.tolist(), sizes.size]):
            lo, hi = int(offsets[a]), int(offsets[b])
            if hi > lo:
                out[lo:hi] = start_at_max(ring[lo:hi], None, int(sizes[a]))
        return out
    start = offsets[:-1].astype(np.int64)
    top = np.maximum.reduceat(ring, start) if ring.size else ring[:0]
    h = np.arange(ring.size, dtype=np.int64)
    owner_start = np.repeat(start, sizes)
    owner_size = np.repeat(sizes, sizes)
    at = np.flatnonzero(ring == np.repeat(top, sizes))  # one per vertex: ids are distinct
    shift = np.repeat(at - start, sizes)
    out = np.empty_like(ring)
    out[owner_start + (h - owner_start - shift) % owner_size] = ring
    return out


def output(
    vertices: np.ndarray,
    corners: np.ndarray,
    offsets: np.ndarray,
    *,
    twin: np.ndarray | Callable[[], np.ndarray | Several] | None = None,
    rings: Rings | Callable[[], Rings | Several] | None = None,
    size_counts: tuple[tuple[int, int], ...] | None = None,
    dual_of: Mesh | None = None,
    closed: bool = False,
) -> Mesh:
    """Wrap an operator's output, valid by construction (no re-validation, no copy).

    Parameters
    ----------
    vertices : (n, 3) float
    corners : (H,) int
    offsets : (m + 1,) int
        New arrays the operator made (they become the mesh's, read-only);
        converted to the output's index dtype (int32 when the counts allow)
        if the operator made them wider.
    twin : (H,) int, or a zero-argument callable returning it, optional
        The output's twins when the operator knows them (a callable runs
        only if the twins are asked for); an open output's callable returns
        them with its boundary (:func:`open_twins_from`).
    rings : ((H,) int, (n + 1,) int), or a callable returning them, optional
        The output's vertex rings (:attr:`pentanb.Mesh.vertex_ring`), likewise;
        the callable may return a :class:`pentanb.mesh.Several` holding them
        (``vertex_ring``) and other connectivity written in the same pass
        (``_ring_faces``, the dual's corners).
    size_counts : ((size, faces), ...), optional
        The output's face-size histogram, by ascending size, when the
        operator knows it (what :func:`pentanb.mesh.build.size_counts` would count).
    dual_of : Mesh, optional
        The mesh the output is the dual of (:func:`pentanb.dual` only).
    closed : bool
        True when the output is closed (the operator's input was): recorded
        with it (see :func:`pentanb.mesh.build.trusted`).
    """
    dtype = index_dtype(vertices.shape[0], corners.size)
    corners = corners.astype(dtype, copy=False)
    offsets = offsets.astype(dtype, copy=False)
    if twin is None and not closed:  # an open output: straight to the open pairing
        twin = functools.partial(_open_twin, corners, offsets, vertices.shape[0])
    return _mesh.trusted(
        vertices,
        corners,
        offsets,
        twin=twin,
        rings=rings,
        size_counts=size_counts,
        dual_of=dual_of,
        closed=closed,
    )


def _open_twin(corners: np.ndarray, offsets: np.ndarray, n: int) -> np.ndarray:
    """The twins of an operator's open output (:func:`pentanb.mesh.boundary.open_twins`),
    without first trying the closed pairing, which fails on every open mesh."""
    from ..mesh.boundary import open_twins
    from ..mesh.halfedge import next_of

    got = open_twins(corners, corners[next_of(offsets, corners.size, corners.dtype)], n)
    if got is None:  # pragma: no cover - an operator's output is a manifold by construction
        raise MeshError("an operator's output does not pair up into an oriented manifold")
    return got[0]


def open_twins_from(twin: np.ndarray, chain: np.ndarray, chain_offsets: np.ndarray) -> Several:
    """An open output's twins and boundary, from twins written but for the boundary's.

    Parameters
    ----------
    twin : (H,) int
        The output's twins, any value at its boundary half-edges (written over).
    chain : (B,) int
        The output's boundary half-edges, loop after loop, each loop chained
        head to tail from any start (an operator knows them from its input's loops).
    chain_offsets : (L + 1,) int
        Loop ``i`` is ``chain[chain_offsets[i]:chain_offsets[i + 1]]``.

    Returns
    -------
    Several
        ``twin`` (the boundary half-edge ``bh[j]`` paired with the hole
        half-edge ``H + j``) and ``_boundary`` (``bh`` and its loop offsets,
        as pairing would record them: :func:`pentanb.mesh.boundary.canonical_loops`).
    """
    bh, off = canonical_loops(chain, chain_offsets)
    return Several(twin=hole_twins(twin, bh), _boundary=(bh, off))


def face_of(offsets: np.ndarray, h: np.ndarray) -> np.ndarray:
    """(k,) int64: the face of each of a few half-edges ``h``, from the faces' offsets alone.

    A search per half-edge, run on ``h`` sorted (a search walks the offsets
    from near where the last one ended: several times faster than in loop
    order on a mesh of millions of faces) and on ``h`` cast to the offsets'
    dtype (else numpy widens all the offsets on every call).
    """
    h = np.asarray(h, dtype=np.int64)
    o = np.asarray(offsets)
    if h.size < 2:
        return np.searchsorted(o, h, side="right").astype(np.int64) - 1
    order = np.argsort(h, kind="stable")
    f = np.empty(h.size, dtype=np.int64)
    f[order] = np.searchsorted(o, h[order].astype(o.dtype, copy=False), side="right")
    f -= 1
    return f


def boundary_next(offsets: np.ndarray, h: np.ndarray, k: int = 0) -> np.ndarray:
    """(k,) int64: ``next[h]`` of a few half-edges ``h``, from the faces' offsets alone
    (``k``: every face has k sides, when the caller knows it; 0: read the offsets)."""
    h = np.asarray(h, dtype=np.int64)
    if k:
        nxt = h + 1
        nxt[nxt % k == 0] -= k
        return nxt
    o = np.asarray(offsets)
    f = face_of(o, h)
    last = o[f + 1].astype(np.int64) - 1
    return np.where(h == last, o[f].astype(np.int64), h + 1)


def scale_safe(op: _Op) -> _Op:
    """Decorator: run a remeshing operator safely on huge coordinates.

    An operator places its new points by affine combinations of old ones
    with non-negative weights (edge points, centroids, corner points), so
    its output's coordinates are bounded by its input's.  Up to
    ``2**1000`` (about 1e301) nothing can overflow.  Beyond, the operator
    runs on the positions scaled down by a power of two (exact), and its
    output is scaled back; a result that would not be finite is a
    :class:`MeshError`.
    """

    @functools.wraps(op)
    def run(mesh: Mesh, *args: Any, **kwargs: Any) -> Mesh:
        check_mesh(mesh, op.__name__)
        extent = _mesh.extent(mesh)
        if extent < SAFE_EXTENT:
            out = op(mesh, *args, **kwargs)
            _mesh.note_extent(out, extent)
            return out
        shift = int(np.frexp(extent)[1]) - 1000
        return _mesh.rescaled(op(_mesh.rescaled(mesh, -shift), *args, **kwargs), shift)

    return run  # type: ignore[return-value]


def check_scale(scale: float, name: str = "scale") -> float:
    """A scale factor must be a finite number strictly between 0 and 1."""
    try:
        s = float(scale)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number in (0, 1), got {scale!r}") from None
    if not (0.0 < s < 1.0):
        raise ValueError(f"{name} must be in (0, 1), got {scale!r}")
    return s


def check_count(value: object, name: str, high: int | None = None) -> int:
    """``value`` as an int in ``[0, high]`` (:func:`pentanb._checks.count`): a TypeError
    naming it when it is not an integer, a ValueError when out of range."""
    return _checks.count(value, name, 0, high)


def check_vertex_faces(mesh: Mesh, op: str, valence: np.ndarray | None = None) -> None:
    """Refuse a mesh with a vertex of fewer than 3 edges (its vertex face would not be a polygon).

    The dual (and corner cutting) make a k-gon of every k-valent vertex.
    The constructor refuses such vertices; a mesh built with
    ``Mesh.from_csr(..., validate=False)`` is not checked and may have one
    (e.g. the flat "pillow", two n-gons glued along their boundary).

    ``valence`` (the number of edges at every vertex), when the caller
    knows it, spares deriving the vertex rings.

    Raises
    ------
    MeshError
        Naming the first such vertex and its number of edges.
    """
    if valence is None:
        _, ring_offsets = mesh.vertex_ring
        valence = np.diff(ring_offsets)
    few = np.flatnonzero(valence < 3)
    if few.size and not mesh.is_closed:
        # a boundary vertex's face closes along the boundary: 2 edges are
        # enough (its ring starts at its hole half-edge, numbered from H)
        ring, ring_offsets = mesh.vertex_ring
        few = few[ring[ring_offsets[few]] < mesh.n_halfedges]
    if few.size:
        v, k = int(few[0]), int(valence[few[0]])
        more = f" (and {few.size - 1} more such vertices)" if few.size > 1 else ""
        raise MeshError(
            f"{op}: vertex {v} has only {k} edge{'s' if k != 1 else ''}{more}; its face "
            f"in the result would have {k} sides, and a face needs at least 3 (a mesh "
            "built with Mesh.from_csr(..., validate=False) is not checked for this)"
        )


#: Turning angle (degrees) of the boundary above which a boundary vertex of
#: one face is a corner, kept by the dual (see :func:`boundary_corners`).
CORNER_ANGLE = 30.0


def boundary_corners(mesh: Mesh, nxt: np.ndarray | None = None) -> np.ndarray:
    """(C,) int: the corners of an open mesh's boundary, in increasing order.

    A corner is a boundary vertex of one face (two edges) where the
    boundary turns by more than :data:`CORNER_ANGLE` degrees (the angle
    between the boundary edge that enters it and the one that leaves
    it).  The dual, corner cutting and honeycomb keep every corner where
    it is, and it stays a corner of their outputs (one face, the same
    turn); the other boundary vertices are cut off.  Empty for a closed
    mesh.

    Parameters
    ----------
    mesh : Mesh
    nxt : (B,) int, optional
        ``next`` of every boundary half-edge, when the caller has it
        (:func:`boundary_next`).

    Returns
    -------
    (C,) int
    """
    if not mesh.boundary_halfedges.size:
        return np.zeros(0, dtype=np.int64)
    head, corner = _corner_heads(mesh, nxt)
    return np.sort(head[corner]).astype(np.int64)


def _corner_heads(mesh: Mesh, nxt: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """The head of every boundary half-edge ``bh[j]`` and whether it is a corner ((B,) bool)."""
    bh = mesh.boundary_halfedges
    v = mesh.vertices
    if nxt is None:
        nxt = boundary_next(mesh.offsets, bh, _mesh.uniform_size(mesh))
    head = mesh.corners[nxt]
    after = loop_successor(mesh)  # the edge leaving head[bh[j]] is bh[after[j]]
    before = np.empty_like(after)
    before[after] = np.arange(after.size)  # so bh[j]'s tail is head[bh[before[j]]]
    p = v.take(head, axis=0)  # (one gather from the many vertices, each a cache miss)
    a = p - p.take(before, axis=0)
    b = a.take(after, axis=0)

    def norm(x: np.ndarray) -> np.ndarray:  # np.linalg.norm(x, axis=1), in that order, faster
        return np.sqrt(x[:, 0] * x[:, 0] + x[:, 1] * x[:, 1] + x[:, 2] * x[:, 2])

    with np.errstate(invalid="ignore", divide="ignore"):
        cos = np.einsum("ij,ij->i", a, b) / (norm(a) * norm(b))
    sharp = cos < np.cos(np.radians(CORNER_ANGLE))  # (NaN, a zero-length edge: no corner)
    one_face = nxt == bh[after]  # the edge leaving head[bh[j]] is on the same face
    return head, sharp & one_face


def corner_ids(
    mesh: Mesh, first: int, nxt: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The output vertices that keep the corners of an open mesh's boundary.

    Parameters
    ----------
    mesh : Mesh
        An open mesh (B boundary edges, C corners).
    first : int
        The output vertex of the first corner; the corners are numbered on
        from it in vertex order.
    nxt : (B,) int, optional
        ``next`` of every boundary half-edge (:func:`boundary_next`).

    Returns
    -------
    keep : (B,) int64
        For every boundary half-edge ``bh[j]``, the output vertex keeping
        its head, -1 where that is not a corner (a boundary vertex is the
        head of one boundary half-edge: no array the size of the mesh).
    at : (C,) int64
        The corners in increasing order (:func:`boundary_corners`).
    """
    bh = mesh.boundary_halfedges
    if not bh.size:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    head, corner = _corner_heads(mesh, nxt)
    js = np.flatnonzero(corner)
    js = js[np.argsort(head[js])]
    keep = np.full(bh.size, -1, dtype=np.int64)
    keep[js] = np.arange(first, first + js.size)
    return keep, head[js].astype(np.int64)


def loop_successor(mesh: Mesh) -> np.ndarray:
    """(B,) int: for every boundary half-edge (index j into
    :attr:`~pentanb.Mesh.boundary_halfedges`), the index of the next one round its loop."""
    bh = mesh.boundary_halfedges
    off = _mesh.loop_offsets(mesh)
    j = np.arange(bh.size, dtype=np.int64)
    if not bh.size:
        return j
    loop_of = np.repeat(np.arange(off.size - 1), np.diff(off))
    after = j + 1
    last = after == off[1:][loop_of]
    after[last] = off[:-1][loop_of[last]]
    return after


def open_vertex_faces(
    mesh: Mesh,
    items: tuple[np.ndarray, ...],
    entering: np.ndarray,
    leaving: np.ndarray,
    keep: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """A face round every vertex of an open mesh, from its vertex ring (CSR, int64).

    Round an interior vertex, its ring's face half-edges h in order, each
    giving ``items[0][h], items[1][h], ...``: what the closed operator
    writes.  Round a boundary vertex v, whose ring is its hole half-edge
    ``H + j`` then its face half-edges from the boundary edge it leaves
    by: ``entering[j]`` (a point for the boundary edge ``bh[j]`` that
    enters v), ``keep[j]`` when it is not -1 (v itself, kept: a corner),
    ``leaving[j']`` (a point for the boundary edge ``bh[j']`` that leaves
    v), then the items of the face half-edges.  Counter-clockwise, as the
    faces round interior vertices.

    Parameters
    ----------
    mesh : Mesh
        An open mesh.
    items : tuple of one or two (H,) int
        What every face half-edge of a ring contributes, in order.
    entering, leaving : (B,) int
        What every boundary edge contributes to the face of its head, of its tail.
    keep : (B,) int, optional
        The output vertex that keeps the head of ``bh[j]``, -1 where none
        does (:func:`corner_ids`).

    Returns
    -------
    corners : int64 array
    offsets : (n + 1,) int64
    """
    ring, _ = mesh.vertex_ring
    # what every ring entry gives, in ring order (a hole half-edge's: any,
    # written over): gathers in ring order, no scatter
    values = np.empty((ring.size, len(items)), dtype=np.result_type(*items))
    for s, item in enumerate(items):
        values[:, s] = item.take(ring, mode="clip")
    return opened_ring_items(mesh, values.reshape(-1), len(items), entering, leaving, keep)


def open_dual_faces(
    mesh: Mesh, keep: np.ndarray, n_out: int, nxt: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The faces of the dual of an open mesh: :func:`open_vertex_faces` with the
    face of every ring half-edge, ``F + j`` for the boundary edge ``bh[j]``.

    One compiled pass over the vertex rings on a large mesh (the same
    arrays as the numpy path's, which runs otherwise).

    Parameters
    ----------
    mesh : Mesh
        An open mesh (F faces, B boundary edges).
    keep : (B,) int
        :func:`corner_ids` of ``mesh`` (numbered from ``F + B``).
    n_out : int
        The dual's number of vertices.
    nxt : (B,) int, optional
        ``next`` of every boundary half-edge (:func:`boundary_next`).

    Returns
    -------
    corners : int array
        Of the dual's index dtype (:func:`index_dtype`).
    offsets : (n + 1,) int
    """
    F, bh = mesh.n_faces, mesh.boundary_halfedges
    mids = np.arange(F, F + bh.size, dtype=np.int64)
    ring, ring_off = mesh.vertex_ring
    k = _mesh.uniform_size(mesh)
    if nxt is None:
        nxt = boundary_next(mesh.offsets, bh, k)
    written = _mesh.written_ring_faces(mesh)  # the face of every ring entry, or None
    jit = _jit.kernels(ring.size)
    if jit is None:
        # the face of every ring entry, as the closed dual's corners (a hole
        # half-edge's: any, written over)
        if written is not None:
            return opened_ring_items(mesh, written, 1, mids, mids, keep, n_out, nxt)
        if k:
            return opened_ring_items(mesh, ring, 1, mids, mids, keep, n_out, nxt, k)
        face = mesh.halfedge_face.take(ring, mode="clip")
        return opened_ring_items(mesh, face, 1, mids, mids, keep, n_out, nxt)
    heads = mesh.corners[nxt]  # the boundary vertices: hole half-edge H + j starts at heads[j]
    leave = mids[loop_successor(mesh)]
    total = ring.size + bh.size + int(np.count_nonzero(keep >= 0))
    if written is not None:
        face, k = written, -1  # (the kernel reads face[i] for ring entry i)
    else:
        face = ring[:0] if k else mesh.halfedge_face
    bj = np.argsort(heads)
    return jit.open_dual_faces(
        ring,
        ring_off,
        k,
        face,
        heads[bj],
        bj,
        mids,
        keep,
        leave,
        total,
        index_dtype(n_out, total),
    )


def ring_places(mesh: Mesh, keep: np.ndarray | None, n_out: int) -> np.ndarray:
    """Where every vertex ring entry of an open mesh goes in its dual's faces.

    A face half-edge gives one corner, a hole half-edge ``H + j`` two (three
    where its tail, the head of ``bh[j]``, is kept: ``keep[j]`` not -1,
    :func:`corner_ids`); ``n_out``, the dual's number of vertices, gives
    the index dtype (:func:`index_dtype`).

    Returns
    -------
    at : (H + B,) int
        The position in the dual's corners of what every entry of
        :attr:`~pentanb.Mesh.vertex_ring` contributes first.
    """
    ring, _ = mesh.vertex_ring
    H, N = mesh.n_halfedges, ring.size
    hp = np.flatnonzero(ring >= H)  # the hole half-edges' places: few
    j = ring[hp].astype(np.int64) - H
    extra = np.ones(j.size, dtype=np.int64) if keep is None else 1 + (keep[j] >= 0)
    # at[i] = i + what the hole half-edges before i give beyond one
    shift = np.zeros(hp.size + 1, dtype=np.int64)
    np.cumsum(extra, out=shift[1:])
    bounds = np.empty(hp.size + 2, dtype=np.int64)
    bounds[0], bounds[1:-1], bounds[-1] = 0, hp + 1, N
    dt = index_dtype(n_out, N + int(shift[-1]))
    at = np.repeat(shift.astype(dt), np.diff(bounds))
    at += np.arange(N, dtype=dt)
    return at


def running_sum(at: np.ndarray, add: np.ndarray, size: int, dtype: Any) -> np.ndarray:
    """(size,) the running sum of an array that is ``add`` at the places ``at``
    (increasing) and zero elsewhere: ``np.cumsum`` of it, made with one
    ``np.repeat`` of the few partial sums (several times faster than a
    cumulative sum over ``size`` places when the places are few)."""
    sums = np.zeros(at.size + 1, dtype=dtype)
    np.cumsum(add, out=sums[1:])
    lengths = np.empty(at.size + 1, dtype=np.int64)
    lengths[0] = at[0] if at.size else size
    np.subtract(at[1:], at[:-1], out=lengths[1:-1])
    if at.size:
        lengths[-1] = size - at[-1]
    return np.repeat(sums, lengths)


def opened_ring_items(
    mesh: Mesh,
    values: np.ndarray,
    per: int,
    entering: np.ndarray,
    leaving: np.ndarray,
    keep: np.ndarray | None = None,
    n_out: int | None = None,
    nxt: np.ndarray | None = None,
    k: int = 1,
) -> tuple[np.ndarray, np.ndarray]:
    """The faces of :func:`open_vertex_faces` from the items of every vertex ring entry.

    The closed operator's faces are ``values``, ``per`` items (1 or 2) for
    every entry of :attr:`~pentanb.Mesh.vertex_ring`, in ring order.  A
    boundary vertex's ring starts with its hole half-edge, which gives 2
    items (3 at a corner) instead: its ``per`` items are written over and
    the rest inserted after them.  Those are few (one per boundary edge),
    so ``values`` is copied in order around the insertions (a mask),
    without an index per ring entry.

    Parameters
    ----------
    mesh : Mesh
        An open mesh.
    values : (per * (H + B),) int
        What every ring entry gives (a hole half-edge's: any).
    per : int
        1 or 2.
    entering, leaving, keep
        As for :func:`open_vertex_faces`.
    n_out : int, optional
        The output's number of vertices: the corners are of its index
        dtype (:func:`index_dtype`), else int64.
    nxt : (B,) int, optional
        ``next`` of every boundary half-edge (:func:`boundary_next`).
    k : int
        The items are ``values // k``, divided in place in the corners (the
        faces of the ring entries of a mesh of k-gons from the ring itself,
        without an array of them the ring's size).

    Returns
    -------
    corners : int array
    offsets : (n + 1,) int
        Of the corners' dtype.
    """
    ring, ring_off = mesh.vertex_ring
    bh = mesh.boundary_halfedges
    if nxt is None:
        nxt = boundary_next(mesh.offsets, bh, _mesh.uniform_size(mesh))
    v = mesh.corners[nxt]  # the tail of the hole half-edge H + j: first in its ring
    if keep is None:
        keep = np.full(bh.size, -1, dtype=np.int64)
    count = 2 + (keep >= 0)  # what every hole half-edge gives, the others ``per``
    total = per * ring.size + int(np.sum(count - per))
    dt = np.dtype(np.int64) if n_out is None else index_dtype(n_out, total)
    # the face of vertex u starts past what the hole half-edges of the
    # vertices before u give beyond ``per`` (every boundary vertex has one)
    order = np.argsort(v)
    offsets = running_sum(v[order] + 1, (count - per)[order], ring_off.size, dt)
    offsets += ring_off if per == 1 else per * ring_off.astype(dt)
    base = offsets[v].astype(np.int64)  # where the face of v starts: what H + j gives
    out = np.empty(total, dtype=dt)
    if total > values.size:
        # the inserted places (base + per + q, q < count - per), in order; the
        # other places take ``values`` in order, block by block of the output
        inserted = np.sort(
            np.concatenate([base[count - per > q] + per + q for q in range(3 - per)])
        )
        cut = np.searchsorted(inserted, np.arange(0, total + OUT_BLOCK, OUT_BLOCK))
        for i, a in enumerate(range(0, total, OUT_BLOCK)):
            z, lo, hi = min(a + OUT_BLOCK, total), int(cut[i]), int(cut[i + 1])
            at = a - lo  # the values before place a: a less the insertions before it
            if lo == hi:
                out[a:z] = values[at : at + z - a]
            else:
                taken = np.ones(z - a, dtype=bool)
                taken[inserted[lo:hi] - a] = False
                out[a:z][taken] = values[at : at + z - a - (hi - lo)]
            if k > 1:  # (while the block is in cache)
                out[a:z] //= k
    else:
        out[...] = values
        if k > 1:
            out //= k
    out[base] = entering
    out[base[keep >= 0] + 1] = keep[keep >= 0]
    out[base + count - 1] = leaving[loop_successor(mesh)]
    return out, offsets
