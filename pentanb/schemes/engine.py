"""The one engine that evaluates every :class:`~pentanb.schemes.table.Table`.

Given a mesh, a table's points are laid out in blocks (old vertices, edge
points, face points, corner points), and every face slot is one whole-array
gather: the reference's path of moves (``next``, ``prev``, ``twin``) applied
to every base half-edge, then the element's index.  The output's twins are
written the same way, from formulas the engine derives once per table
(:func:`compile_table`): for every slot, the slot and the path that reach
its opposite, found on small probe meshes and checked on all of them.  The
vertex rings are then the output's own (:attr:`pentanb.Mesh.vertex_ring`:
every ring starts at its largest half-edge), one rule for every scheme.

On an open mesh (each boundary loop a *hole face*, its half-edges numbered
from H) the same formulas run: where a path crosses the boundary the output
half-edge lies on the output's boundary, and its loops are chained once
(:func:`pentanb.mesh.boundary.loop_order`).  Faces round vertices need a
boundary rule of their own (the dual's page has it) and are for closed
meshes here.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import _jit
from ..mesh import Mesh, MeshError, Several
from ..mesh import build as _mesh
from ..mesh.boundary import hole_twins, loop_order
from ..mesh.geometry import SAFE_EXTENT
from ._build import (
    BLOCK,
    boundary_next,
    check_mesh,
    check_scale,
    edge_points,
    index_dtype,
    output,
    start_at_max,
)
from ._build import inverse as ring_inverse
from .refs import Ref, parse_ref

__all__ = ["apply", "Compiled"]

#: The paths the twin formulas are searched among (shortest first).
PATHS = tuple(
    "".join(p)
    for n in range(4)
    for p in itertools.product("npt", repeat=n)
    if not any(a + b in ("np", "pn", "tt") for a, b in itertools.pairwise(p))
)


@dataclass(frozen=True)
class Compiled:
    """A table ready for the engine: its references parsed and its twins' formulas.

    ``faces[d]`` is ``(kind, refs)``; ``twins[d][s]`` is ``(path, d', s',
    turn)``: the opposite of slot s of face kind d at base half-edge h is
    slot s' of kind d' at ``path(h)`` (for a face round an edge, seen from
    its other half-edge the slot turns by ``turn``); ``turns[d]`` that turn
    of every edge kind.  ``rings[b]`` for every block of points (V, E, F, C;
    None for a block the table has not) the groups of rules of the ring of
    one of its points: for an old vertex, those of each of its outgoing
    half-edges in turn; for an edge, one group per edge point; for a face,
    those of each of its half-edges; for a corner, one.  ``open_rule``: None
    when the table runs on open meshes, else why not; ``paired``: an open
    output's twins are found by
    pairing (a fallback reference changes the faces at the boundary).
    """

    faces: tuple[tuple[str, tuple[Ref, ...]], ...]
    twins: tuple[tuple[tuple[str, int, int], ...], ...]
    turns: tuple[int, ...]
    rings: tuple[Any, ...]
    open_rule: str | None
    paired: bool
    boundary_per_edge: int


# ---------------------------------------------------------------------- walking
class _Walk:
    """A mesh's half-edges walked by paths, and the output's point of every element.

    ``at(path)`` is ``path(h)`` for every half-edge h, with a mask of where
    the path moved on from a hole (None where it never did); ``point(ref)``
    the output vertex every half-edge's reference names, of dtype ``dt``.
    """

    def __init__(self, mesh: Any, table: Any, dt: Any) -> None:
        self.m, self.H, self.dt, self.table = mesh, mesh.n_halfedges, np.dtype(dt), table
        self.bh = mesh.boundary_halfedges
        k = len(table.edge_points)
        n = mesh.n_vertices if table.vertices else 0
        self.k, self.e0 = k, n
        self.f0 = n + k * mesh.n_edges
        self.c0 = self.f0 + (mesh.n_faces if table.face_points else 0)
        self.n_out = self.c0 + (self.H if table.corner_points is not None else 0)
        self._at: dict[str, tuple[np.ndarray, np.ndarray | None]] = {}
        self._full: dict[tuple[str, int], np.ndarray] = {}

    def forget(self) -> None:
        """Drop the arrays of the paths and elements walked so far."""
        self._at.clear()
        self._full.clear()

    def ring_position(self) -> np.ndarray:
        """(H,) where every half-edge stands in the vertex rings (closed meshes)."""
        if "ring" not in self._at:
            self._at["ring"] = (ring_inverse(self.m.vertex_ring[0]), None)
        return self._at["ring"][0]

    def at(self, path: str) -> tuple[np.ndarray, np.ndarray | None]:
        """``path(h)`` for every half-edge h (hole half-edges ``>= H``), and the bad mask."""
        if path in self._at:
            return self._at[path]
        m = self.m
        move = getattr(m, {"n": "next", "p": "prev", "t": "twin"}[path[-1]])  # (that one only)
        if len(path) == 1:
            got: tuple[np.ndarray, np.ndarray | None] = (move, None)
        else:
            x, bad = self.at(path[:-1])
            hole = x >= self.H if self.bh.size else None
            if hole is not None and hole.any():  # moved on from a hole: marked
                bad = hole if bad is None else bad | hole
                x = np.where(hole, 0, x)
            got = (move[x], bad)
        self._at[path] = got
        return got

    def full(self, elem: str, j: int) -> np.ndarray:
        """(H + B,) the output vertex of an element at every half-edge, hole ones after
        (a hole half-edge has a tail and edge points, no face nor corner: -1)."""
        key = (elem, j)
        if key in self._full:
            return self._full[key]
        m, H, dt, bh = self.m, self.H, self.dt, self.bh
        if elem == "V":
            got, rim = m.corners.astype(dt, copy=False), m.head[bh]
        elif elem == "E":
            k = self.k
            forward = m.corners < m.head
            got = m.halfedge_edge.astype(dt)
            got *= k
            got += self.e0 + k - 1 - j
            if 2 * j != k - 1:
                got += forward * (2 * j - k + 1)
            rim = got[bh] + np.where(forward[bh], k - 1 - 2 * j, 2 * j + 1 - k)
        elif elem == "F":
            got, rim = m.halfedge_face + self.f0, np.full(bh.size, -1)
        else:
            got, rim = np.arange(self.c0, self.c0 + H, dtype=dt), np.full(bh.size, -1)
        if bh.size:
            got = np.concatenate([got, rim.astype(got.dtype)])
        self._full[key] = got
        return got

    def point(self, ref: Ref) -> np.ndarray:
        """(H,) int: the output vertex ``ref`` names from every half-edge."""
        if ref.path == "n" and ref.elem == "V" and not self.bh.size:
            return self.m.head
        full = self.full(ref.elem, ref.j)
        if not ref.path:
            return full[: self.H]
        k = _mesh.uniform_size(self.m)
        if ref.path in ("n", "p") and k and not self.bh.size:  # k-gons: the face's next row
            rows, got = full.reshape(-1, k), np.empty_like(full)
            turn = got.reshape(-1, k)
            if ref.path == "n":
                turn[:, :-1], turn[:, -1] = rows[:, 1:], rows[:, 0]
            else:
                turn[:, 1:], turn[:, 0] = rows[:, :-1], rows[:, -1]
            return got
        x, bad = self.at(ref.path)
        got = full[x]
        lost = got < 0 if ref.elem in "FC" and self.bh.size else None
        bad = lost if bad is None else (bad if lost is None else bad | lost)
        if bad is not None and bad.any():
            if ref.fallback is None:  # (refused before: the table's open rule)
                raise MeshError(f"{ref} crosses the boundary and has no fallback")
            got = np.where(bad, self.point(ref.fallback), got)
        return got


# ---------------------------------------------------------------------- faces
def _bases(walk: _Walk, kind: str) -> np.ndarray | None:
    """The base half-edge of every face (or slot group) of a kind, None for every h."""
    if kind == "vertex":
        return walk.m.vertex_ring[0]
    if kind == "edge":
        return walk.m.edge_halfedge
    return None


#: Room an open output keeps after its corners and its offsets, per boundary
#: half-edge of the output, for the faces its dual of a dual adds there (a quad
#: along the half-edge, and one more where it ends at a corner): the dual of
#: that dual then shares the output's face arrays, as a closed one does.
ROOM_CORNERS, ROOM_OFFSETS = 8, 2


def faces_of(walk: _Walk, compiled: Compiled, dt: Any, room: int = 0):
    """The output's corners and offsets, and where every kind's block starts.

    ``room``: the output's boundary half-edges, for whose faces the buffers
    keep room (:data:`ROOM_CORNERS`); returned as the buffers, the arrays
    being their first entries.
    """
    m = walk.m
    kinds = [(kind, refs, _bases(walk, kind)) for kind, refs in compiled.faces]
    counts = [m.n_halfedges if base is None else base.size for _, _, base in kinds]
    total = sum(len(refs) * c for (_, refs, _), c in zip(kinds, counts))
    n_faces = sum(
        m.n_faces if k == "face" else m.n_vertices if k == "vertex" else c
        for (k, _, _), c in zip(kinds, counts)
    )
    corners = np.empty(total + ROOM_CORNERS * room, dtype=dt)
    offsets = np.empty(n_faces + 1 + ROOM_OFFSETS * room, dtype=dt)
    offsets[0] = 0
    starts, at, f = [], 0, 1
    for (kind, refs, base), count in zip(kinds, counts):
        r = len(refs)
        block = corners[at : at + r * count].reshape(count, r)
        for s, ref in enumerate(refs):
            col = walk.point(ref)
            block[:, s] = col if base is None else col[base]
            del col
        if kind == "face":
            ends = m.offsets[1:]
        elif kind == "vertex":
            ends = m.vertex_ring[1][1:]
        else:
            ends = np.arange(1, count + 1, dtype=dt)
        mine = offsets[f : f + ends.size]
        np.multiply(ends, r, out=mine, casting="unsafe")
        mine += at
        starts.append(at)
        at += r * count
        f += ends.size
    return corners, offsets, starts


def slot_index(walk: _Walk, compiled: Compiled, starts: list, rule: tuple, base=None, out=None):
    """Output half-edge ``(d2, s2)`` at ``path(b)`` for every base b (-1 across a hole).

    ``rule`` is ``(path, d2, s2)``; ``base`` the base half-edges (None:
    every half-edge); ``out`` where to write them (else a new int64 array).
    """
    m, H = walk.m, walk.H
    path, d2, s2 = rule
    x, bad = walk.at(path) if path else (np.arange(H, dtype=walk.dt), None)
    if base is not None:
        x, bad = x[base], None if bad is None else bad[base]
    kind2, r2 = compiled.faces[d2][0], len(compiled.faces[d2][1])
    hole = x >= H if walk.bh.size else None
    col = np.empty(x.size, dtype=np.int64) if out is None else out
    if kind2 == "edge":  # the face of x's edge, its slot turned when x runs down
        if hole is not None:  # a hole half-edge: its boundary half-edge's edge, down
            x = np.where(hole, walk.bh[np.where(hole, x - H, 0)], x)
        down = ~(m.corners[x] < m.head[x])  # (the edge's half-edge: tail < head...)
        if walk.bh.size:  # (...or, on the boundary, its one face half-edge)
            down &= m.twin[x] < H
            down |= hole
        np.multiply(m.halfedge_edge[x], r2, out=col)
        col += (s2 + compiled.turns[d2] * down) % r2
        hole = None  # (an edge's face is there from either side)
    else:
        xs = x if hole is None else np.where(hole, 0, x)
        if kind2 == "vertex":
            xs = walk.ring_position()[xs]
        np.multiply(xs, r2, out=col)
    col += starts[d2] + (0 if kind2 == "edge" else s2)
    if hole is not None:
        bad = hole if bad is None else bad | hole
    if bad is not None:
        col[bad] = -1
    return col


def twins_of(walk: _Walk, compiled: Compiled, starts: list, total: int) -> np.ndarray:
    """The output's twins from the table's formulas (-1 on the output's boundary)."""
    H = walk.H
    out = np.empty(total, dtype=walk.dt if total < 2**31 - 1 else np.int64)
    for d, (kind, refs) in enumerate(compiled.faces):
        base = _bases(walk, kind)
        r = len(refs)
        count = H if base is None else base.size
        block = out[starts[d] : starts[d] + r * count].reshape(count, r)
        for s, rule in enumerate(compiled.twins[d]):
            block[:, s] = slot_index(walk, compiled, starts, rule, base, None)
    return out


def rings_of(walk: _Walk, compiled: Compiled, starts: list, dt: Any) -> tuple:
    """The output's vertex rings (closed) from the table's ring formulas, each turned
    to start at its largest half-edge: the rings the output would derive."""
    m, H, E = walk.m, walk.H, walk.m.n_edges
    total = sum(len(refs) * (E if kind == "edge" else H) for kind, refs in compiled.faces)
    ring = np.empty(total, dtype=dt)
    pieces, at = [np.zeros(1, dtype=dt)], 0
    for block, groups in zip("VEFC", compiled.rings):
        if groups is None:
            continue
        units = E if block == "E" else H
        base = m.edge_halfedge if block == "E" else None
        width = [len(g) for g in groups]
        c = sum(width)
        cols = np.empty((units, c), dtype=dt)
        col = np.empty(units, dtype=dt)
        for i, rule in enumerate(r for g in groups for r in g):
            cols[:, i] = slot_index(walk, compiled, starts, rule, base, col)
        del col
        mine = ring[at : at + units * c]
        if block == "V":  # its half-edges' rules, round the vertex
            inner, off = m.vertex_ring
            cols = cols.reshape(-1)[inner] if c == 1 else cols[inner]
            ends = c * off[1:].astype(dt)
        elif block == "F":  # its face's half-edges' rules, round the face
            ends = c * m.offsets[1:].astype(dt)
        elif len(set(width)) == 1:  # (every point of one block: as many edges each)
            ends, off = np.arange(width[0], units * c + 1, width[0], dtype=dt), None
            start_at_max(cols.reshape(-1), None, width[0], out=mine)
        else:
            ends = np.cumsum(np.tile(np.array(width, dtype=dt), units), dtype=dt)
        if block in "VF" or len(set(width)) > 1:
            edges = np.concatenate([np.zeros(1, dtype=dt), ends])
            start_at_max(cols.reshape(-1), edges, 0, out=mine)
        pieces.append(ends + at)
        at += units * c
    return ring, np.concatenate(pieces)


def _closed_connectivity(walk: _Walk, compiled: Compiled, starts: list, total: int, dt: Any):
    """The producers of a closed output's twins and rings (each run when first asked for)."""

    def twin() -> np.ndarray:
        return twins_of(walk, compiled, starts, total)

    def rings() -> tuple:
        return rings_of(walk, compiled, starts, dt)

    return twin, (rings if compiled.rings else None)


def _open_twins(walk: _Walk, compiled: Compiled, starts, corners, offsets, n_out):
    def make() -> Several:
        twin = twins_of(walk, compiled, starts, corners.size)
        bh = np.flatnonzero(twin < 0)
        tail = corners[bh]
        head = corners[boundary_next(offsets, bh)]
        order, loop_off, _ = loop_order(tail, head, np.arange(bh.size), n_out)
        loops = bh[order]
        return Several(twin=hole_twins(twin, loops), _boundary=(loops, loop_off))

    return make


# ---------------------------------------------------------------------- positions
def positions(walk: _Walk, table: Any, compiled: Compiled, options: dict) -> np.ndarray:
    """(n_out, 3) float: the old vertices, edge points, face points and corner points."""
    m = walk.m
    out = np.empty((walk.n_out, 3))
    if table.vertices:
        out[: m.n_vertices] = m.vertices
    if table.edge_points:
        t = np.array(table.edge_points)
        edge_points(m, len(t), out=out[walk.e0 : walk.f0], t=t)
    if table.face_points:
        out[walk.f0 : walk.c0] = m.face_centroids
    cp = table.corner_points
    if cp is None:
        return out
    copies = out[walk.c0 :]
    if isinstance(cp, dict):  # an affine rule over the input's tail, head, centroid ...
        terms = [(float(w), parse_ref(r, table.name)) for r, w in cp.items() if w]
        equal = len({w for w, _ in terms}) == 1
        for i, (w, ref) in enumerate(terms):
            p = _place(m, walk, ref, None if i else copies)
            if not equal:
                p *= w
            if i:
                copies += p
            del p
        if equal:  # (equal weights: the plain mean)
            copies /= len(terms)
        return out
    elem, scale = cp
    s = options[scale] if isinstance(scale, str) else float(scale)
    ref = parse_ref(elem, table.name)
    if ref.elem == "V" and not ref.path:  # the face itself, scaled about its centroid
        v, centres = m.vertices, m.face_centroids
        jit = _jit.kernels(m.n_halfedges)
        if jit is not None and v.flags.c_contiguous:  # the same sums, one pass
            got = jit.corner_points(v, m.corners, centres, m.halfedge_face, s)
            if walk.c0 == 0:
                return got
            copies[...] = got
        else:
            c = centres[m.halfedge_face]
            np.take(v, m.corners, axis=0, out=copies)
            copies -= c
            copies *= s
            copies += c
        return out
    idx = walk.point(ref)  # (the polygon of the face's edge points, in the output)
    offsets, sizes = m.offsets, m.face_sizes
    jit = _jit.kernels(m.n_halfedges) if int(sizes.max()) <= 129 else None
    if jit is not None:  # the same sums and products, compiled
        jit.scaled_copies(out, idx.astype(offsets.dtype, copy=False), offsets, s, copies)
        return out
    for a in range(0, m.n_faces, BLOCK):  # the face's polygon scaled about its centroid
        o = offsets[a : a + BLOCK + 1]
        lo, hi = int(o[0]), int(o[-1])
        p = out.take(idx[lo:hi], axis=0)
        centre = np.add.reduceat(p, o[:-1] - lo, axis=0) / sizes[a : a + BLOCK, None]
        centre = np.repeat(centre, sizes[a : a + BLOCK], axis=0)
        p -= centre
        p *= s
        np.add(centre, p, out=copies[lo:hi])
    return out


def _place(m: Any, walk: _Walk, ref: Ref, out: np.ndarray | None = None) -> np.ndarray:
    """(H, 3) the input's position ``ref`` names from every half-edge (into ``out``)."""
    x = walk.at(ref.path)[0] if ref.path else None
    if ref.elem == "F":
        face = m.halfedge_face if x is None else m.halfedge_face[x]
        return np.take(m.face_centroids, face, axis=0, out=out)
    tail = m.corners if x is None else m.corners[x]
    if ref.elem == "V":
        return np.take(m.vertices, tail, axis=0, out=out)
    t = walk.table.edge_points[ref.j]
    got = np.take(m.vertices, tail, axis=0, out=out)
    got *= 1.0 - t
    got += m.vertices[m.head if x is None else m.head[x]] * t
    return got


# ---------------------------------------------------------------------- apply
def apply(table: Any, mesh: Mesh, **options: float) -> Mesh:
    """Evaluate ``table`` on ``mesh``: the output mesh, its twins written when asked for.

    Parameters
    ----------
    table : Table
    mesh : Mesh
        Closed, or open where the table allows it (no faces round vertices,
        no path across the boundary without a fallback).
    **options : float
        The table's options (``scale=...``), each in (0, 1).

    Returns
    -------
    Mesh

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh, or an option the table does not have.
    ValueError
        An option outside (0, 1).
    MeshError
        An open mesh the table cannot remesh (the message says why).
    """
    check_mesh(mesh, table.name)
    unknown = sorted(set(options) - set(table.options))
    if unknown:
        raise TypeError(f"{table.name}() got an unexpected keyword argument {unknown[0]!r}")
    values = {k: check_scale(options.get(k, v), k) for k, v in table.options.items()}
    compiled: Compiled = table.compiled
    if not mesh.is_closed and compiled.open_rule is not None:
        raise MeshError(f"{table.name} needs a closed mesh: {compiled.open_rule}")
    # new points are affine combinations with weights >= 0: inside the input's box;
    # beyond SAFE_EXTENT the work runs on positions scaled by a power of two (exact)
    extent = _mesh.extent(mesh)
    if extent < SAFE_EXTENT:
        out = _evaluate(table, compiled, mesh, values)
        _mesh.note_extent(out, extent)
        return out
    shift = int(np.frexp(extent)[1]) - 1000
    small = _evaluate(table, compiled, _mesh.rescaled(mesh, -shift), values)
    return _mesh.rescaled(small, shift)


def _evaluate(table: Any, compiled: Compiled, mesh: Mesh, values: dict) -> Mesh:
    """:func:`apply` on a mesh of safe extent, its options checked."""
    closed = mesh.is_closed
    total = sum(
        len(refs) * (mesh.n_edges if kind == "edge" else mesh.n_halfedges)
        for kind, refs in compiled.faces
    )
    points = _Walk(mesh, table, np.int64).n_out
    dt = index_dtype(points, total)
    walk = _Walk(mesh, table, dt)
    room = 0 if closed or compiled.paired else compiled.boundary_per_edge * mesh.n_boundary_edges
    buffer, offsets_buffer, starts = faces_of(walk, compiled, dt, room)
    walk.forget()  # (the paths' arrays: out of the peak of what follows)
    corners = buffer[:total]
    offsets = offsets_buffer[: offsets_buffer.size - ROOM_OFFSETS * room]
    vertices = positions(walk, table, compiled, values)
    del walk
    source = _Walk(_mesh.faces_only(mesh), table, dt)  # (the positions not kept alive)
    if closed:
        twin, rings = _closed_connectivity(source, compiled, starts, total, dt)
        return output(vertices, corners, offsets, twin=twin, rings=rings, closed=True)
    if compiled.paired:
        return output(vertices, corners, offsets)
    twin = _open_twins(source, compiled, starts, corners, offsets, source.n_out)
    out = output(vertices, corners, offsets, twin=twin)
    _mesh.note_room(out, buffer, offsets_buffer)
    return out
