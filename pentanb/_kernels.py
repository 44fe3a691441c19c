"""The numba kernels behind :mod:`pentanb._jit` (imported only when they are used).

Every kernel is a module-level function, so numba caches its machine code
on disk (a kernel calling another defined in a closure would be compiled
again in every process).  Those named ``*_part`` fill the rows ``lo:hi``
of an output they are given (:func:`split` runs one over all its rows);
the functions without the suffix take the numpy path's arguments and are
what :func:`pentanb._jit.kernels` hands out.  Each gives the numpy path's
results bit for bit; ``tests/test_jit.py`` compares them.
"""

from __future__ import annotations

from collections.abc import Callable

import numba
import numpy as np

jit: Callable = numba.njit(cache=True, nogil=True)
#: Helpers the kernels call, inlined into them (a call per face costs as much as the face).
inline: Callable = numba.njit(cache=True, nogil=True, inline="always")


@inline
def ix(i):  # pragma: no cover - compiled
    # an index known to be >= 0, as unsigned: numba then drops its wraparound
    # test (a negative index counts from the end), a compare and branch on
    # every access that also keeps LLVM from vectorizing the loop (a plain
    # copy loop here: 0.31 ms signed, 0.034 ms unsigned, as fast as numpy)
    return numba.uint64(i)


@inline
def quo(h, k):  # pragma: no cover - compiled
    # h // k for h >= 0 and k > 0: the usual face sizes as constants, which LLVM
    # turns into a multiply and shift (a division by a variable k is an idiv,
    # five times slower over a mesh's half-edges)
    if k == 4:
        return ix(h) // numba.uint64(4)
    if k == 5:
        return ix(h) // numba.uint64(5)
    if k == 3:
        return ix(h) // numba.uint64(3)
    if k == 6:
        return ix(h) // numba.uint64(6)
    return ix(h) // ix(k)


@inline
def rem(h, k):  # pragma: no cover - compiled
    # h % k for h >= 0 and k > 0 (see quo)
    return h - numba.int64(quo(h, k)) * k  # (int64: int64 - uint64 would be a float)


def split(n, kernel, *args):
    """Run ``kernel(*args, lo, hi)`` over all of ``range(n)``, on the calling thread."""
    kernel(*args, 0, n)


#: What :func:`pentanb._jit.kernels` hands out.
__all__ = [
    "face_means_uniform",
    "face_means_mixed",
    "fan_index",
    "edge_index",
    "start_at_max",
    "edge_points",
    "gather",
    "halfedge_face",
    "scaled_copies",
    "inverse",
    "corner_points",
    "pair_twins",
    "open_rings",
    "loop_order",
    "vertex_normals",
    "open_dual_faces",
    "bounds",
]


@jit
def face_means_uniform_part(values, corners, k, out, lo, hi):  # pragma: no cover - compiled
    # acc = v[c0]; acc += v[c1]; ...; acc / k: the numpy path's order,
    # every coordinate on its own (three at once for points)
    d = values.shape[1]
    if d == 3:
        for f in range(lo, hi):
            c = ix(corners[ix(f * k)])
            x, y, z = values[c, 0], values[c, 1], values[c, 2]
            for j in range(1, k):
                c = ix(corners[ix(f * k + j)])
                x += values[c, 0]
                y += values[c, 1]
                z += values[c, 2]
            out[ix(f), 0], out[ix(f), 1], out[ix(f), 2] = x / k, y / k, z / k
        return
    for f in range(lo, hi):
        for i in range(d):
            acc = values[ix(corners[ix(f * k)]), ix(i)]
            for j in range(1, k):
                acc += values[ix(corners[ix(f * k + j)]), ix(i)]
            out[ix(f), ix(i)] = acc / k


def face_means_uniform(values, corners, k, out=None):
    if out is None:
        out = np.empty((corners.size // k, values.shape[1]))
    split(len(out), face_means_uniform_part, values, corners, k, out)
    return out


@jit
def bracket(values, corners, a, b, i):  # pragma: no cover - compiled
    # values[corners[a:b], i] summed as numpy's pairwise sum adds them
    # (at most 128 terms): left to right below 8; else eight running
    # sums, joined pairwise, then the remainder left to right
    n = b - a
    i = ix(i)
    if n < 8:
        acc = values[ix(corners[ix(a)]), i]
        for h in range(a + 1, b):
            acc += values[ix(corners[ix(h)]), i]
        return acc
    r0, r1 = values[ix(corners[ix(a)]), i], values[ix(corners[ix(a + 1)]), i]
    r2, r3 = values[ix(corners[ix(a + 2)]), i], values[ix(corners[ix(a + 3)]), i]
    r4, r5 = values[ix(corners[ix(a + 4)]), i], values[ix(corners[ix(a + 5)]), i]
    r6, r7 = values[ix(corners[ix(a + 6)]), i], values[ix(corners[ix(a + 7)]), i]
    h = a + 8
    while h < b - n % 8:
        r0 += values[ix(corners[ix(h)]), i]
        r1 += values[ix(corners[ix(h + 1)]), i]
        r2 += values[ix(corners[ix(h + 2)]), i]
        r3 += values[ix(corners[ix(h + 3)]), i]
        r4 += values[ix(corners[ix(h + 4)]), i]
        r5 += values[ix(corners[ix(h + 5)]), i]
        r6 += values[ix(corners[ix(h + 6)]), i]
        r7 += values[ix(corners[ix(h + 7)]), i]
        h += 8
    acc = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    while h < b:
        acc += values[ix(corners[ix(h)]), i]
        h += 1
    return acc


@inline
def short_mean(values, corners, a, b):  # pragma: no cover - compiled
    # the mean point of corners[a:b] (at most 8): (v[c1] + ... + v[c_last]) + v[c0],
    # over the size, np.add.reduceat's order, three coordinates at once
    c = ix(corners[ix(a + 1)])
    x, y, z = values[c, 0], values[c, 1], values[c, 2]
    for h in range(a + 2, b):
        c = ix(corners[ix(h)])
        x += values[c, 0]
        y += values[c, 1]
        z += values[c, 2]
    c = ix(corners[ix(a)])
    x += values[c, 0]
    y += values[c, 1]
    z += values[c, 2]
    n = b - a
    return x / n, y / n, z / n


@inline
def long_mean(values, corners, a, b, i):  # pragma: no cover - compiled
    # coordinate i of the mean of corners[a:b] (at most 129): v[c0] + the
    # pairwise bracket of the rest, over the size (np.add.reduceat's order)
    acc = bracket(values, corners, a + 1, b, i)
    acc += values[ix(corners[ix(a)]), ix(i)]
    return acc / (b - a)


@jit
def face_means_mixed_part(values, corners, offsets, out, lo, hi):  # pragma: no cover - compiled
    # faces of at most 129 corners, as np.add.reduceat adds them (the numpy path's order)
    d = values.shape[1]
    for f in range(lo, hi):
        a, b = offsets[ix(f)], offsets[ix(f + 1)]
        if d == 3 and b - a <= 8:
            out[ix(f), 0], out[ix(f), 1], out[ix(f), 2] = short_mean(values, corners, a, b)
            continue
        for i in range(d):
            out[ix(f), ix(i)] = long_mean(values, corners, a, b, i)


def face_means_mixed(values, corners, offsets, out=None):
    if out is None:
        out = np.empty((offsets.size - 1, values.shape[1]))
    split(len(out), face_means_mixed_part, values, corners, offsets, out)
    return out


@jit
def fan_index_part(corners, offsets, slot, low, out, lo, hi):  # pragma: no cover - compiled
    # face f's triangles (c0, c_{j+1}, c_{j+2}), each vertex plus the shift
    # slot[size - low] of its size (none when slot is empty), from row
    # offsets[f] - 2 f (faces of at least 3 corners)
    shifted = slot.size > 0
    for f in range(lo, hi):
        a, b = offsets[ix(f)], offsets[ix(f + 1)]
        s = slot[ix(b - a - low)] if shifted else 0
        first = corners[ix(a)] + s
        t = 3 * (a - 2 * f)
        for c in range(a + 1, b - 1):
            out[ix(t)] = first
            out[ix(t + 1)] = corners[ix(c)] + s
            out[ix(t + 2)] = corners[ix(c + 1)] + s
            t += 3


def fan_index(corners, offsets, slot, low):
    # every face has at least 3 corners (the caller checks): T = H - 2F triangles
    m = offsets.size - 1
    out = np.empty(3 * (corners.size - 2 * m), np.uint32)
    split(m, fan_index_part, corners, offsets, slot, low, out)
    return out


@jit
def edge_index_fill(corners, offsets, out):  # pragma: no cover - compiled
    # every edge once, as (tail, head) of its half-edge with tail < head,
    # in half-edge order (Mesh.edges); -1 if there are more than out holds
    # (a branch on tail < head: here faster than writing every half-edge
    # and keeping those, 0.32 against 0.39 ms at 368,640 half-edges)
    m, e, room = offsets.size - 1, 0, out.size
    for f in range(m):
        a, b = offsets[ix(f)], offsets[ix(f + 1)]
        prev = corners[ix(a)]
        for c in range(a + 1, b + 1):
            cur = corners[ix(c)] if c < b else corners[ix(a)]
            if prev < cur:
                if e + 2 > room:
                    return -1
                out[ix(e)] = prev
                out[ix(e + 1)] = cur
                e += 2
            prev = cur
    return e


def edge_index(corners, offsets):
    # a closed mesh has H / 2 edges, which one pass fills; a mesh built
    # unchecked may have more (a second pass into room for H) or fewer
    out = np.empty(2 * (corners.size // 2), np.uint32)
    e = edge_index_fill(corners, offsets, out)
    if e < 0:  # more than H / 2 (at most one per half-edge)
        out = np.empty(2 * corners.size, np.uint32)
        e = edge_index_fill(corners, offsets, out)
    return out if e == out.size else out[:e].copy()


@jit
def start_at_max_part(ring, offsets, k, out, lo, hi):  # pragma: no cover - compiled
    # every ring (CSR, or k each when offsets is empty) turned to start at
    # its largest entry, order kept
    for v in range(lo, hi):
        if offsets.size == 0:
            a, b = v * k, v * k + k
        else:
            a, b = offsets[ix(v)], offsets[ix(v + 1)]
        top = a
        for i in range(a + 1, b):
            if ring[ix(i)] > ring[ix(top)]:
                top = i
        j = a
        for i in range(top, b):
            out[ix(j)] = ring[ix(i)]
            j += 1
        for i in range(a, top):
            out[ix(j)] = ring[ix(i)]
            j += 1


def start_at_max(ring, offsets, k, out=None):
    if out is None:
        out = np.empty_like(ring)
    n = ring.size // k if offsets.size == 0 else offsets.size - 1
    split(n, start_at_max_part, ring, offsets, k, out)
    return out


@jit
def edge_points_part(vertices, edges, t, out, lo, hi):  # pragma: no cover - compiled
    # point j of edge e: a * (1 - t[j]) + b * t[j], as the numpy path rounds it
    k = t.size
    for e in range(lo, hi):
        a, b = ix(edges[ix(e), 0]), ix(edges[ix(e), 1])
        for j in range(k):
            s, w = 1.0 - t[ix(j)], t[ix(j)]
            for i in range(3):
                out[ix(e * k + j), ix(i)] = vertices[a, ix(i)] * s + vertices[b, ix(i)] * w


def edge_points(vertices, edges, t, out):
    split(edges.shape[0], edge_points_part, vertices, edges, t, out)


@jit
def gather_part(table, index, out, lo, hi):  # pragma: no cover - compiled
    for i in range(lo, hi):
        out[ix(i)] = table[ix(index[ix(i)])]


def gather(table, index):
    # table[index] for 1-d arrays (indices in range: the caller's arrays)
    out = np.empty(index.size, table.dtype)
    split(index.size, gather_part, table, index, out)
    return out


@jit
def halfedge_face_part(offsets, out, lo, hi):  # pragma: no cover - compiled
    for f in range(lo, hi):
        for h in range(offsets[ix(f)], offsets[ix(f + 1)]):
            out[ix(h)] = f


def halfedge_face(offsets, n_corners):
    # the face of every half-edge: np.repeat(arange(F), sizes)
    out = np.empty(n_corners, offsets.dtype)
    split(offsets.size - 1, halfedge_face_part, offsets, out)
    return out


@jit
def scaled_copies_part(values, points, offsets, s, out, lo, hi):  # pragma: no cover - compiled
    # every face's points scaled by s about their mean c: c + (p - c) * s,
    # c in np.add.reduceat's order (faces of at most 129 corners)
    for f in range(lo, hi):
        a, b = offsets[ix(f)], offsets[ix(f + 1)]
        if b - a <= 8:
            x, y, z = short_mean(values, points, a, b)
            for h in range(a, b):
                p, q = ix(points[ix(h)]), ix(h)
                out[q, 0] = x + (values[p, 0] - x) * s
                out[q, 1] = y + (values[p, 1] - y) * s
                out[q, 2] = z + (values[p, 2] - z) * s
            continue
        for i in range(3):
            c = long_mean(values, points, a, b, i)
            for h in range(a, b):
                out[ix(h), ix(i)] = c + (values[ix(points[ix(h)]), ix(i)] - c) * s


def scaled_copies(values, points, offsets, s, out):
    # faces of 3 to 129 corners (the caller checks)
    split(offsets.size - 1, scaled_copies_part, values, points, offsets, s, out)


@jit
def inverse_part(ring, out, lo, hi):  # pragma: no cover - compiled
    # pos[ring[i]] = i (ring a permutation: the parts write disjoint rows)
    for i in range(lo, hi):
        out[ix(ring[ix(i)])] = i


def inverse(ring):
    # where every half-edge sits in the vertex rings (what _build.inverse hands out)
    out = np.empty_like(ring)
    split(ring.size, inverse_part, ring, out)
    return out


@jit
def corner_points_part(vertices, corners, centres, face_of, s, out, lo, hi):  # pragma: no cover
    # c + s * (v - c) for every half-edge: its tail v, its face's centre c
    for h in range(lo, hi):
        v, f = ix(corners[ix(h)]), ix(face_of[ix(h)])
        for i in range(3):
            c = centres[f, ix(i)]
            out[ix(h), ix(i)] = c + s * (vertices[v, ix(i)] - c)


def corner_points(vertices, corners, centres, face_of, s):
    # classic._corner_points
    out = np.empty((corners.size, 3))
    split(corners.size, corner_points_part, vertices, corners, centres, face_of, s, out)
    return out


@jit
def pair_twins(tail, head, k, n):  # pragma: no cover - compiled
    # twin of every half-edge u -> w: the one half-edge w -> u, found among
    # w's outgoing half-edges (a counting sort by tail), or -1 when there is
    # none (a boundary half-edge); those half-edges in increasing order (int64);
    # their number, or -1 (and empty arrays) when some half-edge has more
    # than one partner, is a loop or leaves a vertex out of range.  On a
    # closed mesh (no -1) these are the numpy path's twins exactly when its
    # sorted keys pair; on an open one, with the boundary then chained into
    # loops (which refuses a vertex two boundary half-edges leave: a directed
    # edge used twice without its opposite), they fail exactly where
    # boundary.pair_open does
    H = tail.size
    fail = np.empty(0, tail.dtype), np.empty(0, np.int64), -1
    if head.size == 0:  # faces of k corners: heads from the tails
        head = np.empty_like(tail)
        for h in range(H):
            head[ix(h)] = tail[ix(h + 1)] if rem(h + 1, k) else tail[ix(h + 1 - k)]
    start = np.zeros(n + 1, np.int64)
    for h in range(H):
        u = tail[ix(h)]
        if u < 0 or u >= n:  # out of range: no pairing (and no stray write)
            return fail
        start[ix(u + 1)] += 1
    # (from here on every tail, so every head, is a vertex in range)
    for v in range(n):
        start[ix(v + 1)] += start[ix(v)]
    fill = start[:-1].copy()
    out_of = np.empty(H, tail.dtype)  # half-edges by tail
    for h in range(H):
        u = ix(tail[ix(h)])
        out_of[ix(fill[u])] = h
        fill[u] += 1
    twin = np.empty(H, tail.dtype)
    alone = np.empty(H, np.int64)  # (pages only touched as far as written)
    b = 0
    for h in range(H):
        u, w = tail[ix(h)], head[ix(h)]
        if u == w:
            return fail
        found = 0
        twin[ix(h)] = -1
        for i in range(start[ix(w)], start[ix(w + 1)]):
            g = out_of[ix(i)]
            if head[ix(g)] == u:
                twin[ix(h)] = g
                found += 1
        if found > 1:
            return fail
        if found == 0:
            alone[ix(b)] = h
            b += 1
    return twin, alone[:b].copy(), b


@jit
def vertex_normals(vertices, corners, offsets, rows, copies):  # pragma: no cover - compiled
    # every face's vector area by Newell's formula (its corners in order,
    # summed one by one in float64), added to each of its vertices in face
    # order, then normalised and written as float32 into each of the last
    # `copies` blocks of n rows of rows ((R, 3) float32: the buffer the view
    # sends, so no copy is made of them): the numpy path's
    # (pentanb.viz.drawing.vertex_normals) numbers; a zero sum gives (0, 0, 1).
    # The float64 sums live in the bytes of rows' last 2n rows when R >= 2n
    # (no scratch of their size: fresh memory costs a page fault per 4 KiB,
    # 4 us each here), so the last block is written from the highest vertex
    # down: its row u (bytes 12 (n + u) of the sums) covers the sum of vertex
    # (n + u) // 2 >= u, already read; the other blocks are copies of it
    n = vertices.shape[0]
    size = rows.shape[0]
    s = size - 2 * n
    s -= s & 1  # (an even row: float64 aligned)
    if s >= 0:
        total = rows.reshape(-1)[3 * s : 3 * (s + 2 * n)].view(np.float64).reshape((n, 3))
    else:
        total = np.empty((n, 3))
    total[:] = 0.0
    m = offsets.size - 1
    for f in range(m):
        a, b = offsets[ix(f)], offsets[ix(f + 1)]
        ax = 0.0
        ay = 0.0
        az = 0.0
        i = corners[ix(a)]
        x0, y0, z0 = vertices[ix(i), 0], vertices[ix(i), 1], vertices[ix(i), 2]
        xi, yi, zi = x0, y0, z0
        for c in range(a, b):  # each corner's vertex read once
            if c + 1 < b:
                j = corners[ix(c + 1)]
                xj, yj, zj = vertices[ix(j), 0], vertices[ix(j), 1], vertices[ix(j), 2]
            else:
                xj, yj, zj = x0, y0, z0
            ax += yi * zj - zi * yj
            ay += zi * xj - xi * zj
            az += xi * yj - yi * xj
            xi, yi, zi = xj, yj, zj
        for c in range(a, b):
            u = ix(corners[ix(c)])
            total[u, 0] += ax
            total[u, 1] += ay
            total[u, 2] += az
    last = size - n
    for u in range(n - 1, -1, -1):
        x, y, z = total[ix(u), 0], total[ix(u), 1], total[ix(u), 2]
        length = np.sqrt(x * x + y * y + z * z)
        if length > 0.0:
            p, q, r = np.float32(x / length), np.float32(y / length), np.float32(z / length)
        else:
            p, q, r = np.float32(0.0), np.float32(0.0), np.float32(1.0)
        row = ix(last + u)
        rows[row, 0] = p
        rows[row, 1] = q
        rows[row, 2] = r
    for k in range(1, copies):
        first = last - k * n
        for u in range(n):
            for j in range(3):
                rows[ix(first + u), j] = rows[ix(last + u), j]


@jit
def bounds(points, lo, hi):  # pragma: no cover - compiled
    # the least and the greatest value of every column of points ((n, 3)
    # float64, n >= 1) into lo and hi ((3,) float64), as numpy's min and max
    # find them (a NaN in a column makes both NaN; of -0.0 and 0.0 either
    # may be kept), in one pass over the rows: numpy reduces a strided
    # column at a time, six passes over the array
    n = points.shape[0]
    lx, ly, lz = points[0, 0], points[0, 1], points[0, 2]
    hx, hy, hz = lx, ly, lz
    nx, ny, nz = False, False, False
    for i in range(n):
        x, y, z = points[ix(i), 0], points[ix(i), 1], points[ix(i), 2]
        lx, hx, nx = min(lx, x), max(hx, x), nx | (x != x)
        ly, hy, ny = min(ly, y), max(hy, y), ny | (y != y)
        lz, hz, nz = min(lz, z), max(hz, z), nz | (z != z)
    lo[0], hi[0] = (np.nan, np.nan) if nx else (lx, hx)
    lo[1], hi[1] = (np.nan, np.nan) if ny else (ly, hy)
    lo[2], hi[2] = (np.nan, np.nan) if nz else (lz, hz)


# Open meshes: the dual's faces


@inline
def faces_of_run(ring, a, b, k, face, out, d):  # pragma: no cover - compiled
    # out[i + d] = the face of half-edge ring[i] for i in a:b: ring[i] // k when
    # every face is a k-gon (a loop per usual k, which LLVM vectorizes: a
    # constant divisor inside the loop, not a test of k per entry), face[i]
    # when k < 0 (the faces of the ring entries), else face[ring[i]]
    if k == 4:
        for i in range(a, b):
            out[ix(i + d)] = ring[ix(i)] // 4
    elif k == 5:
        for i in range(a, b):
            out[ix(i + d)] = ring[ix(i)] // 5
    elif k == 3:
        for i in range(a, b):
            out[ix(i + d)] = ring[ix(i)] // 3
    elif k > 0:
        for i in range(a, b):
            out[ix(i + d)] = quo(ring[ix(i)], k)
    elif k < 0:  # face[i]: the face of ring entry i, written with the rings
        for i in range(a, b):
            out[ix(i + d)] = face[ix(i)]
    else:
        for i in range(a, b):
            out[ix(i + d)] = face[ix(ring[ix(i)])]


@jit
def open_dual_faces_fill(
    ring, ring_off, k, face, bv, bj, enter, keep, leave, out, offsets
):  # pragma: no cover - compiled
    # the face of every vertex v of an open mesh: round its ring, the face
    # of every face half-edge r (r // k when every face is a k-gon, else
    # face[r]); a boundary vertex bv[t] (ascending) starts its ring with its
    # hole half-edge H + bj[t], which gives enter[j], keep[j] when it is not
    # -1, then leave[j] (the numpy path's open_vertex_faces with one item).
    # The interior vertices between two boundary vertices are one run of the
    # rings, written shifted by what the boundary inserted before them: a
    # flat loop LLVM vectorizes, where a loop per vertex does not
    n = ring_off.size - 1
    p, v0 = 0, 0
    offsets[0] = 0
    for t in range(bv.size + 1):
        v1 = bv[ix(t)] if t < bv.size else n
        a, b = ring_off[ix(v0)], ring_off[ix(v1)]
        d = p - a
        faces_of_run(ring, a, b, k, face, out, d)
        for v in range(v0 + 1, v1 + 1):
            offsets[ix(v)] = ring_off[ix(v)] + d
        p += b - a
        if t == bv.size:
            break
        j = bj[ix(t)]
        out[ix(p)] = enter[ix(j)]
        p += 1
        if keep[ix(j)] >= 0:
            out[ix(p)] = keep[ix(j)]
            p += 1
        out[ix(p)] = leave[ix(j)]
        p += 1
        a, b = ring_off[ix(v1)] + 1, ring_off[ix(v1 + 1)]  # (after the hole half-edge)
        faces_of_run(ring, a, b, k, face, out, p - a)
        p += b - a
        offsets[ix(v1 + 1)] = p
        v0 = v1 + 1


def open_dual_faces(ring, ring_off, k, face, bv, bj, enter, keep, leave, total, dtype):
    out = np.empty(total, dtype)
    offsets = np.empty(ring_off.size, dtype)
    open_dual_faces_fill(ring, ring_off, k, face, bv, bj, enter, keep, leave, out, offsets)
    return out, offsets


# -- the open outputs' rings of the paper's two schemes (pentagonal._*_open_rings) ----
# One pass each over the input's rings, edges and faces, as the closed
# kernels write theirs, the boundary's few rows written where they fall;
# ``hole`` holds the output's hole half-edge along every piece of the
# input's boundary half-edge j (pentagonalization: 3 a boundary half-edge,
# pentagon preservation: 2), and the offsets are written with the rings.


@jit
def open_rings(twin, tail, k, prv, after, hole_tail, ring, ring_off):  # pragma: no cover
    # ring[ring_off[v]:ring_off[v + 1]] = the outgoing half-edges of v in
    # rotation order (halfedge.open_vertex_rings; halfedge.vertex_rings when
    # there are no hole half-edges), from v's largest: its hole half-edge
    # H + j (tail hole_tail[j]) on the boundary, else its largest face
    # half-edge.  rotation[h] = twin[prev[h]] (prev: h - 1, or h + k - 1 at
    # a face's first corner; prv[h] when k is 0), rotation[H + j] = after[j]
    # (the boundary half-edge after bh[j] in its loop).  True when the rings
    # use every half-edge once (they hold H + B entries: none twice)
    H, B, n = tail.size, after.size, ring_off.size - 1
    start = np.empty(n, np.int64)
    for h in range(H):
        start[ix(tail[ix(h)])] = h
    for j in range(B):
        start[ix(hole_tail[ix(j)])] = H + j
    seen = np.zeros(H + B, np.bool_)
    ok = True
    for v in range(n):
        a, b = ring_off[ix(v)], ring_off[ix(v + 1)]
        if a == b:
            continue
        cur = start[ix(v)]
        for i in range(a, b):
            ring[ix(i)] = cur
            ok &= not seen[ix(cur)]
            seen[ix(cur)] = True
            if cur >= H:
                cur = after[ix(cur - H)]
            elif k:
                cur = twin[ix(cur - 1 if rem(cur, k) else cur + k - 1)]
            else:
                cur = twin[ix(prv[ix(cur)])]
    return ok


@jit
def loop_order(tail, head, n):  # pragma: no cover - compiled
    # boundary.loop_order of the half-edges tail[j] -> head[j] (positions j,
    # vertices in [0, n)), bit for bit: the positions loop after loop, every
    # loop from its smallest, loops in the order of those (a walk from every
    # position not yet met, in increasing order); the loops' offsets; -1, or
    # the smallest vertex two of them leave (or the first head none leaves),
    # the arrays then empty
    B = tail.size
    out = np.full(n, -1, np.int64)  # the position leaving every vertex
    bad = -1
    for j in range(B):
        u = tail[ix(j)]
        if out[ix(u)] >= 0 and (bad < 0 or u < bad):
            bad = u
        out[ix(u)] = j
    if bad < 0:
        for j in range(B):
            if out[ix(head[ix(j)])] < 0:
                bad = head[ix(j)]
                break
    if bad >= 0:
        return np.empty(0, np.int64), np.zeros(1, np.int64), bad
    order = np.empty(B, np.int64)
    offsets = np.empty(B + 1, np.int64)
    met = np.zeros(B, np.bool_)
    p, loops = 0, 0
    for j in range(B):
        if met[ix(j)]:
            continue
        offsets[ix(loops)] = p
        loops += 1
        i = j
        while not met[ix(i)]:
            met[ix(i)] = True
            order[ix(p)] = i
            p += 1
            i = out[ix(head[ix(i)])]
    offsets[ix(loops)] = B
    return order, offsets[: loops + 1].copy(), -1
