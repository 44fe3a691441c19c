"""The optional compiled kernels (:mod:`pentanb._jit`) against the numpy path, bit for bit.

The one module that compares the two paths: the rest of the suite runs the
path users get by default (the kernels, numba being in the test extra, on
meshes of at least ``MIN_CORNERS`` corners).  Here each test switches
explicitly between the numpy path and the kernels, switched on for meshes
of every size, and the two must give the same arrays, byte for byte.
Without numba these tests are skipped, except on CI, where numba is in the
test extra and its absence fails them.  The comparisons are marked ``slow``:
they compile every kernel for every argument type it takes (tens of seconds
in a fresh checkout, before numba's disk cache holds them).
"""

from __future__ import annotations

import dataclasses
import sys
import threading

import numpy as np
import pytest
from browser_support import skip_or_fail
from helpers import holed_grid, prism
from test_open import REFUSED

import pentanb
from pentanb import _jit, shapes
from pentanb.mesh.geometry import face_means as _face_means
from pentanb.viz import drawing


@pytest.fixture
def compiled(monkeypatch):
    """The kernels, used for meshes of any size for the test's duration."""
    if not _jit.available():
        skip_or_fail("numba is not installed (pip install 'pentanb[jit]')")
    monkeypatch.setattr(_jit, "MIN_CORNERS", 0)
    before = _jit.use_jit(True)
    yield _jit.kernels(0)
    _jit.use_jit(before)


def both(fn):
    """``fn()`` by the numpy path, then by the kernels."""
    _jit.use_jit(False)
    a = fn()
    _jit.use_jit(True)
    return a, fn()


def same_bytes(a: np.ndarray, b: np.ndarray) -> bool:
    """Equal dtype, shape and bytes (so -0.0 and 0.0 differ, and every NaN payload)."""
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def fresh(m: pentanb.Mesh) -> pentanb.Mesh:
    """The same mesh without its caches."""
    return pentanb.Mesh.from_csr(m.vertices, m.corners, m.offsets, validate=False)


# -- the face means ------------------------------------------------------------------


@pytest.mark.slow
@pytest.mark.parametrize("d", [1, 3, 5])
def test_face_means_are_the_numpy_sums_bit_for_bit(corpus_mesh, compiled, d):
    rng = np.random.default_rng(d)
    values = rng.standard_normal((corpus_mesh.n_vertices, d)) * 10.0 ** rng.integers(
        -8, 8, (corpus_mesh.n_vertices, 1)
    )
    k = corpus_mesh._uniform_size
    a, b = both(lambda: _face_means(values, corpus_mesh.corners, corpus_mesh.offsets, k, 1.0))
    assert same_bytes(a, b)


@pytest.mark.slow
def test_face_centroids_of_every_scheme_are_the_same_compiled(compiled):
    base = shapes.icosahedron()
    for name in pentanb.SCHEMES:
        m = pentanb.subdivide(base, name, 1, 0)
        a, b = both(lambda m=m: fresh(m).face_centroids)
        assert same_bytes(a, b), name


@pytest.mark.slow
def test_the_kernels_add_in_the_numpy_paths_order(compiled):
    # 1e16 + 1 + 1 is 1e16 left to right but 1e16 + 2 with the ones added first:
    # the expected values are Python's sums in the order each path documents
    big = 1e16
    values = np.array([[big], [1.0], [1.0], [1.0]])
    # one size (uniform path): v[c0] + v[c1] + v[c2], left to right
    uniform = _face_means(values, np.array([0, 1, 2, 3, 1, 2]), np.array([0, 3, 6]), 3, big)
    assert uniform[0, 0] == ((big + 1.0) + 1.0) / 3 and uniform[1, 0] == ((1.0 + 1.0) + 1.0) / 3
    # mixed sizes: (v[c1] + v[c2] + ...) + v[c0], as np.add.reduceat adds them
    corners, offsets = np.array([0, 1, 2, 0, 1, 2, 3]), np.array([0, 3, 7])
    mixed = _face_means(values, corners, offsets, 0, big)
    assert mixed[0, 0] == ((1.0 + 1.0) + big) / 3
    assert mixed[1, 0] == (((1.0 + 1.0) + 1.0) + big) / 4
    # and the two orders do differ here, so the test can tell them apart
    assert ((big + 1.0) + 1.0) / 3 != ((1.0 + 1.0) + big) / 3
    _jit.use_jit(False)
    assert same_bytes(mixed, _face_means(values, corners, offsets, 0, big))


@pytest.mark.slow
@pytest.mark.parametrize("n", [9, 12, 16, 17, 30, 128, 129])
def test_long_faces_are_summed_pairwise_as_numpy_does(compiled, n):
    # a face of n corners: v[c0] + (v[c1] + ... ), the bracket numpy's
    # pairwise sum from 8 terms on (eight running sums); values of very
    # different sizes, chosen so that a plain left-to-right sum differs in
    # the last bits (the comparison can tell the orders apart)
    m = prism(n)  # two n-gons and n squares
    for seed in range(100):
        rng = np.random.default_rng(seed)
        values = rng.standard_normal((m.n_vertices, 3)) * 10.0 ** rng.integers(
            -8, 8, (m.n_vertices, 1)
        )
        top = values[m.corners[:n]]
        seq = top[1].copy()
        for row in top[2:]:
            seq += row
        seq += top[0]
        if not np.array_equal(seq, np.add.reduceat(top, [0], axis=0)[0]):
            break
    else:
        pytest.fail("no values found on which the two orders differ")
    a, b = both(lambda: _face_means(values, m.corners, m.offsets, 0, 1.0))
    assert same_bytes(a, b)
    assert not np.array_equal(b[0], seq / n)


@pytest.mark.slow
def test_faces_of_more_than_129_corners_keep_the_numpy_sums(compiled, monkeypatch):
    m = prism(130)  # numpy's pairwise sum splits 129 or more terms in two halves

    def refuse(*args):
        raise AssertionError("the mixed kernel ran on a face of more than 129 corners")

    monkeypatch.setattr(compiled, "face_means_mixed", refuse)
    a, b = both(lambda: fresh(m).face_centroids)
    assert same_bytes(a, b)


def test_small_meshes_never_load_the_kernels(monkeypatch):
    monkeypatch.setitem(_jit._state, "on", True)
    monkeypatch.setitem(_jit._state, "kernels", None)

    def refuse():
        raise AssertionError("numba was loaded for a small mesh")

    monkeypatch.setattr(_jit, "_compile", refuse)
    m = pentanb.pentagonalize(shapes.cube())
    assert len(m.corners) < _jit.MIN_CORNERS
    assert np.isfinite(fresh(m).face_centroids).all()
    assert drawing.mesh_buffers(fresh(m)).index.size == 3 * (len(m.corners) - 2 * m.n_faces)
    with pytest.raises(AssertionError, match="small mesh"):
        _jit.kernels(_jit.MIN_CORNERS)


# -- the twins ------------------------------------------------------------------------


@pytest.mark.slow
def test_twins_are_the_numpy_twins(corpus_mesh, compiled):
    from pentanb.mesh.halfedge import pair_twins as _pair_twins

    m = corpus_mesh
    k = m._uniform_size
    for head in ([None] if k else []) + [m.head]:
        a, b = both(lambda head=head: _pair_twins(m.corners, head, m.n_vertices, k))
        assert a is not None and same_bytes(a, b)
    a, b = both(lambda: fresh(m).twin)
    assert same_bytes(a, b)


@pytest.mark.slow
@pytest.mark.parametrize(
    "faces",
    [
        [[0, 1, 2], [0, 1, 3]],  # the directed edge 0 -> 1 twice
        [[0, 1, 2], [1, 0, 3]],  # edges 1-2, 2-0, 0-3, 3-1 without a partner
        [[0, 0, 1, 2], [2, 1, 0, 0]],  # the loop 0 -> 0
        [[0, 1, 2], [2, 1, 0], [0, 1, 2], [2, 1, 0]],  # every edge four times
    ],
)
def test_half_edges_that_do_not_pair_give_none_both_ways(compiled, faces):
    from pentanb.mesh.halfedge import pair_twins as _pair_twins

    f = np.array(faces)
    tail = f.reshape(-1).astype(np.int32)
    a, b = both(lambda: _pair_twins(tail, None, 4, f.shape[1]))
    assert a is None and b is None


@pytest.mark.slow
def test_twins_of_indices_out_of_range_are_refused_not_written(compiled):
    from pentanb.mesh.halfedge import pair_twins as _pair_twins

    tail = np.array([0, 1, 2, 2, 1, 7], dtype=np.int32)  # vertex 7 of 4
    twin, alone, b = compiled.pair_twins(tail, tail[:0], 3, 4)
    assert twin.size == alone.size == 0 and b == -1
    assert _pair_twins(tail, None, 4, 3) is None


@pytest.mark.slow
def test_bad_meshes_get_the_same_message_compiled(compiled):
    # the constructor's messages come from the exact checker either way
    bad = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]  # one face turned the wrong way
    v = shapes.tetrahedron().vertices
    messages = []
    for on in (False, True):
        _jit.use_jit(on)
        with pytest.raises(pentanb.MeshError) as err:
            pentanb.Mesh(v, bad)
        messages.append(str(err.value))
    assert messages[0] == messages[1] and "edge" in messages[0]


# -- open meshes: pairing, boundary loops, vertex rings --------------------------------


def open_meshes() -> dict[str, tuple[np.ndarray, list[list[int]]]]:
    v, q = holed_grid(9, 8, [(2, 2), (5, 4), (1, 6)])
    mixed = [list(f) for f in q[:20]] + [
        f for r in q[20:] for f in ([r[0], r[1], r[2]], [r[0], r[2], r[3]])
    ]
    cube = shapes.cube()
    return {
        "holed grid": (v, q.tolist()),
        "holed grid, quads and triangles": (v, mixed),
        "cube without a face": (cube.vertices, [f.tolist() for f in cube.faces[:5]]),
        "two triangles on an edge": (np.eye(4)[:, :3], [[0, 1, 2], [1, 0, 3]]),
    }


@pytest.mark.slow
@pytest.mark.parametrize("name", list(open_meshes()))
def test_open_twins_loops_and_rings_are_the_numpy_ones(compiled, name):
    from pentanb.mesh.boundary import open_twins, pair_halfedges

    v, faces = open_meshes()[name]
    m = pentanb.Mesh(v, faces)
    k, c, n = m._uniform_size, m.corners, m.n_vertices
    assert not m.is_closed
    a, b = both(lambda: pair_halfedges(c, None if k else m.head, n, k))
    assert same_bytes(a[0], b[0]) and same_bytes(a[1], b[1])
    assert a[1].size and np.array_equal(a[1], np.flatnonzero(a[0] < 0))
    a, b = both(lambda: open_twins(c, None if k else m.head, n, k))
    for x, y in zip([a[0], *a[1]], [b[0], *b[1]]):
        assert same_bytes(x, y)
    # what the constructor keeps, and a mesh's own derivation of it
    for make in (lambda: pentanb.Mesh(v, faces), lambda: fresh(m)):
        a, b = both(lambda make=make: make())
        for attr in ("twin", "boundary_halfedges", "vertex_ring"):
            x, y = getattr(a, attr), getattr(b, attr)
            for p, q in zip(*((x, y) if isinstance(x, tuple) else ((x,), (y,)))):
                assert same_bytes(p, q), attr
        assert same_bytes(a._boundary[1], b._boundary[1])


@pytest.mark.slow
@pytest.mark.parametrize(
    "faces",
    [
        [[0, 1, 2], [0, 1, 3]],  # a boundary edge used twice: vertex 0 leaves two boundaries
        [[0, 1, 2], [0, 1, 3], [1, 0, 4]],  # three faces on an edge
        [[0, 1, 2], [0, 3, 4]],  # two fans at vertex 0
        [[0, 1, 2], [2, 1, 0], [0, 1, 2], [2, 1, 0]],  # every edge four times
    ],
)
def test_open_pairing_fails_on_the_same_meshes_both_ways(compiled, faces):
    from pentanb.mesh.boundary import open_twins

    tail = np.array(faces).reshape(-1).astype(np.int32)
    a, b = both(lambda: open_twins(tail, None, 5, 3))
    assert a is None and b is None


@pytest.mark.slow
@pytest.mark.parametrize(
    "tail, head",
    [
        ([5, 2, 0, 7, 1, 3, 8], [1, 5, 7, 2, 0, 8, 3]),  # loops 0 4 2 3 1 and 5 6
        ([4, 0, 4, 2, 0], [1, 4, 3, 0, 2]),  # vertices 4 and 0 left twice: 0 named
        ([0, 1, 2], [1, 2, 6]),  # nothing leaves vertex 6
    ],
)
def test_loop_order_is_the_numpy_loop_order(compiled, tail, head):
    from pentanb.mesh.boundary import loop_order

    t, w = np.array(tail, dtype=np.int32), np.array(head, dtype=np.int32)
    want = loop_order(t, w, np.arange(t.size), 9)
    got = compiled.loop_order(t, w, 9)
    assert same_bytes(got[0], want[0]) and same_bytes(got[1], want[1]) and got[2] == want[2]
    assert (want[2] >= 0) == (len(tail) != 7)


def _non_manifold(closed: bool):
    """Faces with their twins paired whose vertex 0 has faces in two fans or cycles
    (two tetrahedra sharing vertex 0; the second without a face when not closed)."""
    tet = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]
    faces = tet + [[0 if x == 0 else x + 3 for x in f] for f in tet[: 4 if closed else 3]]
    return np.array(faces).reshape(-1).astype(np.int32), 7


@pytest.mark.slow
@pytest.mark.parametrize("closed", [True, False])
def test_rings_of_a_vertex_of_two_fans_are_the_numpy_ones(compiled, closed):
    # the rings repeat half-edges: both paths write the same ones, and say so
    from pentanb.mesh.boundary import open_twins
    from pentanb.mesh.halfedge import (
        heads_at,
        open_vertex_rings,
        rotation_of,
        vertex_rings,
        walk_rings,
    )

    c, n = _non_manifold(closed)
    o = np.arange(0, c.size + 1, 3)
    twin, boundary = open_twins(c, None, n, 3)
    bh, off = boundary
    assert bh.size == (0 if closed else 3)
    val = np.bincount(c, minlength=n) + np.bincount(c[bh], minlength=n)
    head = heads_at(c, np.arange(c.size), 3)
    rotation = rotation_of(twin, o, 3)
    if closed:
        want = vertex_rings(rotation, c, val)
        got = walk_rings(twin, c, 3, None, val)
    else:
        want = open_vertex_rings(rotation, c, head, bh, off, val)
        got = walk_rings(twin, c, 3, None, val, boundary, head[bh])
    assert got is not None
    assert same_bytes(got[0], want[0]) and same_bytes(got[1], want[1])
    assert got[2] is False and np.unique(want[0]).size < want[0].size
    # and with the previous half-edges handed over (faces of several sizes)
    prv = np.arange(-1, c.size - 1, dtype=c.dtype)
    prv[o[:-1]] = o[1:] - 1
    again = walk_rings(twin, c, 0, prv, val, boundary, head[bh])
    assert again is not None and same_bytes(again[0], got[0])


@pytest.mark.slow
@pytest.mark.parametrize("name", list(REFUSED))
def test_open_meshes_refused_get_the_same_message_compiled(compiled, name):
    v, faces, message = REFUSED[name]
    messages = []
    for on in (False, True):
        _jit.use_jit(on)
        with pytest.raises(pentanb.MeshError, match=message) as err:
            pentanb.Mesh(v, faces)
        messages.append(str(err.value))
    assert messages[0] == messages[1]


# -- the WebGL index arrays ----------------------------------------------------------


@pytest.mark.slow
@pytest.mark.parametrize("text", ["C", "tI", "k4P6", "open"])
def test_vertex_normals_in_any_block_layout_are_the_numpy_ones(compiled, text):
    # the kernel keeps its float64 sums in the rows it returns when there are
    # at least 2n (one block spare, or two copies): every layout, odd n and
    # odd copies too (the sums then start a row earlier, float64-aligned)
    m = shapes.open_disk() if text == "open" else pentanb.conway(text)
    n = m.n_vertices
    _jit.use_jit(False)
    want = drawing.vertex_normals(m)
    _jit.use_jit(True)
    assert same_bytes(drawing.vertex_normals(m), want)
    for copies in (1, 2, 3):
        for spare in (0, 1):
            rows = drawing._vertex_normals(m, copies, spare)
            assert rows.shape == ((spare + copies) * n, 3)
            for k in range(copies):
                block = rows[(spare + k) * n : (spare + k + 1) * n]
                assert same_bytes(np.ascontiguousarray(block), want), (copies, spare, k)


@pytest.mark.slow
@pytest.mark.parametrize("n", [1, 2, 7, 1000])
def test_bounds_are_numpys_min_and_max(compiled, n):
    # the view's frame check: every column's least and greatest value, a
    # NaN anywhere in a column making both NaN, an infinity a bound
    rng = np.random.default_rng(n)
    cases = []
    for scale in (1e-300, 1.0, 1e300):
        p = rng.standard_normal((n, 3)) * scale
        cases.append(p)
        for bad in (np.nan, np.inf, -np.inf):
            q = p.copy()
            q[rng.integers(n), rng.integers(3)] = bad
            cases.append(q)
    for p in cases:
        lo, hi = np.empty(3), np.empty(3)
        compiled.bounds(p, lo, hi)
        want_lo = np.array([min(p[:, k].tolist()) for k in range(3)])
        want_hi = np.array([max(p[:, k].tolist()) for k in range(3)])
        has_nan = np.isnan(p).any(axis=0)
        want_lo[has_nan] = want_hi[has_nan] = np.nan
        np.testing.assert_array_equal(lo, want_lo)
        np.testing.assert_array_equal(hi, want_hi)
        for frame in (drawing.IDENTITY, (np.array([1e10, 0.0, 0.0]), 5)):
            fits = drawing.frame_fits(frame, p)
            _jit.use_jit(False)
            assert drawing.frame_fits(frame, p) == fits
            _jit.use_jit(True)


@pytest.mark.slow
def test_edge_index_is_the_meshs_edges(corpus_mesh, compiled):
    got = compiled.edge_index(corpus_mesh.corners, corpus_mesh.offsets)
    assert got.dtype == np.uint32
    assert np.array_equal(got.reshape(-1, 2), corpus_mesh.edges)


def same_buffers(a: drawing.Buffers, b: drawing.Buffers) -> None:
    for f in dataclasses.fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            assert same_bytes(x, y), f.name
            assert y.flags.writeable and y.flags.c_contiguous, f.name
        else:
            assert x == y, f.name


@pytest.mark.slow
@pytest.mark.parametrize("text", ["C", "dgC", "k4P6", "ddgT", "tI", "bbP5", "pD"])
def test_mesh_buffers_are_the_same_compiled(text, compiled):
    m = pentanb.conway(text)
    a, b = both(lambda: drawing.mesh_buffers(fresh(m)))
    same_buffers(a, b)


@pytest.mark.slow
def test_mesh_buffers_of_every_scheme_with_duals_are_the_same_compiled(compiled):
    base = shapes.octahedron()
    for name in pentanb.SCHEMES:
        m = pentanb.subdivide(base, name, 2, 2)
        a, b = both(lambda m=m: drawing.mesh_buffers(fresh(m)))
        same_buffers(a, b)


@pytest.mark.slow
def test_buffers_comparison_fails_on_a_moved_vertex_or_another_fan(compiled):
    m = shapes.cube()
    a = drawing.mesh_buffers(m)
    moved = m.with_vertices(m.vertices + np.eye(8, 3) * 1e-3)
    with pytest.raises(AssertionError, match="position"):
        same_buffers(a, drawing.mesh_buffers(moved))
    # the same squares fanned from their second corner: other triangles
    turned = np.roll(m.corners.reshape(-1, 4), -1, axis=1).reshape(-1)
    other = pentanb.Mesh.from_csr(m.vertices, turned, m.offsets)
    with pytest.raises(AssertionError, match="index"):
        same_buffers(a, drawing.mesh_buffers(other))


@pytest.mark.slow
@pytest.mark.parametrize("name", list(pentanb.SCHEMES))
def test_subdivision_is_the_same_compiled(compiled, name):
    # positions (edge points, centroids), faces and rings (start_at_max) of
    # every scheme, two iterations with their duals
    a, b = both(lambda: pentanb.subdivide(shapes.cube(), name, 2, 2))
    for attr in ("vertices", "corners", "offsets"):
        assert same_bytes(getattr(a, attr), getattr(b, attr)), attr
    for x, y in zip(a.vertex_ring, b.vertex_ring):
        assert same_bytes(x, y)
    assert same_bytes(a.twin, b.twin)


@pytest.mark.slow
@pytest.mark.parametrize("n", [5, 12, 129, 130])
def test_preserved_copies_of_long_faces_are_the_same_compiled(compiled, n):
    # the copies' centres are the faces' means in np.add.reduceat's order
    # (kernel up to 129 corners, numpy beyond); coordinates of many sizes
    m = prism(n)
    rng = np.random.default_rng(n)
    moved = m.with_vertices(m.vertices * 10.0 ** rng.integers(-6, 6, (m.n_vertices, 1)))
    a, b = both(lambda: pentanb.preserve_pentagons(fresh(moved), 0.6).vertices)
    assert same_bytes(a, b)


@pytest.mark.slow
@pytest.mark.parametrize(
    "op",
    [
        pentanb.pentagonalize,
        pentanb.preserve_pentagons,
        pentanb.corner_cutting,
        pentanb.preserve_hexagons,
        pentanb.honeycomb,
    ],
)
def test_the_points_and_rings_schemes_write_are_the_numpy_ones(corpus_mesh, compiled, op):
    # the positions, the faces (pentagon preservation writes them compiled)
    # and the rings these schemes write for their outputs, and the dual's
    # faces (pentagon preservation writes the face of every ring entry too)
    def run():
        out = op(fresh(corpus_mesh))
        ring = out.vertex_ring
        d = pentanb.dual(out)
        return (out.vertices, out.corners, out.offsets, *ring, d.corners, d.offsets)

    a, b = both(run)
    for x, y in zip(a, b):
        assert same_bytes(x, y)


def holed(reverse: bool = False) -> pentanb.Mesh:
    """An 8 x 7 grid without three quads (two holes, one at the rim), every
    third quad split in two triangles; its faces reversed if asked."""
    xs, ys = np.meshgrid(np.arange(9.0), np.arange(8.0), indexing="ij")
    v = np.stack([xs.ravel(), ys.ravel(), 0.1 * np.sin(xs.ravel() + ys.ravel())], 1)
    faces = []
    for i in range(8):
        for j in range(7):
            if (i, j) in ((2, 2), (2, 3), (7, 0)):
                continue
            a = i * 8 + j
            q = [a, a + 8, a + 9, a + 1]
            faces += [q[:3], [q[0], q[2], q[3]]] if len(faces) % 3 == 0 else [q]
    if reverse:
        faces = [f[::-1] for f in faces]
    used = sorted({x for f in faces for x in f})
    new = {x: i for i, x in enumerate(used)}
    return pentanb.Mesh(v[used], [[new[x] for x in f] for f in faces])


@pytest.mark.slow
@pytest.mark.parametrize("op", [pentanb.pentagonalize, pentanb.preserve_pentagons])
@pytest.mark.parametrize("first", ["vertex_ring", "twin", "boundary_halfedges"])
@pytest.mark.parametrize(
    "name", ["open disk", "holed grid", "holed grid reversed", "torus without two faces"]
)
def test_the_open_rings_the_paper_schemes_write_are_the_numpy_ones(compiled, op, first, name):
    # the rings of an open output (compiled in one pass, its boundary's rows
    # among them), its twins and boundary, whichever is asked for first,
    # and its dual's faces, built from them
    m = {
        "open disk": shapes.open_disk,
        "holed grid": holed,
        "holed grid reversed": lambda: holed(reverse=True),
        "torus without two faces": lambda: pentanb.Mesh(
            shapes.torus().vertices, [f.tolist() for f in shapes.torus().faces[2:]]
        ),
    }[name]()
    assert not m.is_closed

    def run():
        out = op(fresh(m))
        getattr(out, first)
        ring, off = out.vertex_ring
        d = pentanb.dual(out)
        loops = np.concatenate(out.boundary_loops)
        return (ring, off, out.twin, out.boundary_halfedges, loops, d.corners, d.offsets)

    a, b = both(run)
    for x, y in zip(a, b):
        assert same_bytes(x, y)


@pytest.mark.parametrize("sides", [3, 4, 5, 6, "mixed"])
def test_the_open_dual_faces_are_the_numpy_ones_for_every_face_size(compiled, sides):
    # the compiled pass divides by the face size, a constant for each of the
    # usual ones, and reads the face of every half-edge otherwise
    m = {
        3: lambda: pentanb.Mesh(*tri(holed())),
        4: lambda: pentanb.Mesh(*holed_grid(9, 8, [(2, 2), (5, 4)])),
        5: lambda: pentanb.pentagonalize(holed_grid_mesh()),
        6: hexagons,
        "mixed": holed,
    }[sides]()
    assert not m.is_closed
    assert m.offsets.size and (sides == "mixed") == (len(set(np.diff(m.offsets).tolist())) > 1)

    def run():
        d = pentanb.dual(fresh(m))
        return d.vertices, d.corners, d.offsets

    a, b = both(run)
    for x, y in zip(a, b):
        assert same_bytes(x, y)


def holed_grid_mesh() -> pentanb.Mesh:
    return pentanb.Mesh(*holed_grid(9, 8, [(2, 2), (5, 4)]))


def hexagons() -> pentanb.Mesh:
    """A patch of 6 x 5 regular hexagons (open: one boundary loop)."""
    corners = [
        (np.cos(np.pi / 3 * i + np.pi / 6), np.sin(np.pi / 3 * i + np.pi / 6)) for i in range(6)
    ]
    index: dict[tuple[float, float], int] = {}
    faces = []
    for i in range(6):
        for j in range(5):
            cx, cy = np.sqrt(3) * (i + 0.5 * (j % 2)), 1.5 * j
            key = [(round(cx + x, 6), round(cy + y, 6)) for x, y in corners]
            faces.append([index.setdefault(q, len(index)) for q in key])
    v = np.array([[x, y, 0.0] for x, y in index], dtype=float)
    return pentanb.Mesh(v, faces)


def tri(m: pentanb.Mesh) -> tuple[np.ndarray, list[list[int]]]:
    """``m``'s vertices and its faces cut into fans of triangles."""
    return m.vertices, [[f[0], f[i], f[i + 1]] for f in m.faces for i in range(1, len(f) - 1)]


def rings(made):
    """The rings and offsets a producer made (with the faces of its entries or not)."""
    return made["vertex_ring"] if isinstance(made, dict) else made


@pytest.mark.slow
def test_start_at_max_is_the_numpy_permutation(compiled):
    from pentanb.schemes._build import start_at_max

    rng = np.random.default_rng(5)
    sizes = rng.integers(1, 9, 500)
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    ring = rng.permutation(offsets[-1])
    for dt in (np.int32, np.int64):
        a, b = both(lambda dt=dt: start_at_max(ring.astype(dt), offsets.astype(dt)))
        assert same_bytes(a, b)
        # every ring starts at its largest entry and keeps its cyclic order
        _jit.use_jit(True)
        for v in (0, 7, 499):
            got = b[offsets[v] : offsets[v + 1]]
            r = ring[offsets[v] : offsets[v + 1]]
            assert got[0] == r.max()
            assert np.array_equal(got, np.roll(r, -int(r.argmax())))
    rows = rng.permutation(600)
    a, b = both(lambda: start_at_max(rows, None, 4))
    assert same_bytes(a, b)


@pytest.mark.slow
@pytest.mark.parametrize("k", [1, 2, 3])
def test_edge_points_are_the_numpy_points(compiled, k):
    from pentanb.schemes._build import edge_points

    rng = np.random.default_rng(k)
    m = shapes.torus()
    moved = m.with_vertices(m.vertices * rng.uniform(0.1, 1e6, (m.n_vertices, 1)))
    a, b = both(lambda: edge_points(fresh(moved), k))
    assert same_bytes(a, b)
    t = (np.arange(k) + 1.0) / (k + 1)
    e = moved.edges
    expect = (
        moved.vertices[e[:, 0], None] * (1 - t[:, None])
        + moved.vertices[e[:, 1], None] * (t[:, None])
    )
    assert np.array_equal(b, expect.reshape(-1, 3))


# -- the switch ----------------------------------------------------------------------


def test_use_jit_takes_a_bool():
    with pytest.raises(TypeError, match="use_jit\\(\\) expects True or False, got int"):
        _jit.use_jit(1)  # type: ignore[arg-type]


def test_without_numba_the_kernels_are_refused_by_name(monkeypatch):
    monkeypatch.setitem(sys.modules, "numba", None)  # import numba raises ImportError
    monkeypatch.setitem(_jit._state, "on", None)
    assert not _jit.available()
    with pytest.raises(ImportError, match=r"pip install 'pentanb\[jit\]'"):
        _jit.use_jit(True)
    monkeypatch.setenv("PENTANB_JIT", "")
    assert not _jit.enabled()  # default: off without numba, numpy path
    assert _jit.kernels(10**9) is None
    monkeypatch.setitem(_jit._state, "on", None)
    monkeypatch.setenv("PENTANB_JIT", "1")
    with pytest.raises(ImportError, match="numba, which is not installed"):
        _jit.enabled()


def test_a_numba_that_fails_to_load_falls_back_to_numpy_with_a_warning(monkeypatch):
    def broken():
        raise ImportError("numba built for another numpy")

    monkeypatch.setitem(_jit._state, "on", True)
    monkeypatch.setitem(_jit._state, "kernels", None)
    monkeypatch.setattr(_jit, "_compile", broken)
    with pytest.warns(RuntimeWarning, match="could not be loaded .numba built for another"):
        assert _jit.kernels(10**9) is None
    assert not _jit.enabled()
    m = pentanb.pentagonalize(shapes.cube())
    monkeypatch.setattr(_jit, "MIN_CORNERS", 0)
    assert np.array_equal(fresh(m).face_centroids, m.face_centroids)


def test_the_environment_switch_is_read_strictly(monkeypatch):
    monkeypatch.setitem(_jit._state, "on", None)
    monkeypatch.setenv("PENTANB_JIT", "maybe")
    with pytest.raises(ValueError, match="PENTANB_JIT must be 0 or 1, got 'maybe'"):
        _jit.enabled()
    _jit.use_jit(False)  # an explicit choice overrides the bad variable
    assert not _jit.enabled()
    monkeypatch.setitem(_jit._state, "on", None)
    monkeypatch.setenv("PENTANB_JIT", "0")
    assert not _jit.enabled() and _jit.kernels(10**9) is None


@pytest.mark.slow
def test_kernels_run_on_the_calling_thread_over_every_item(compiled):
    from pentanb import _kernels

    calls = []

    def kernel(out, lo, hi):
        calls.append((lo, hi, threading.current_thread()))
        out[lo:hi] += 1

    for n in (0, 1, 1000):
        calls.clear()
        out = np.zeros(n, int)
        _kernels.split(n, kernel, out)
        assert calls == [(0, n, threading.current_thread())] and (out == 1).all()
    before = threading.active_count()
    pentanb.subdivide(shapes.torus(), "preserve_pentagons", 1, 1)
    assert threading.active_count() == before  # pentanb starts no thread


# -- open meshes -----------------------------------------------------------------------


def two_holed_grid(nx: int = 7, ny: int = 6) -> pentanb.Mesh:
    """A grid of quads with two holes, lifted a little out of its plane: corners
    (sharp vertices of one face) on its rim, boundary vertices of three faces
    round the holes."""
    v, f = holed_grid(nx, ny, [(1, 1), (4, 3, 1)])
    v[:, 2] = 0.1 * np.sin(v[:, 0] + v[:, 1])
    return pentanb.Mesh(v, f)


@pytest.mark.slow
@pytest.mark.parametrize("name", list(pentanb.SCHEMES))
@pytest.mark.parametrize("shape", ["holed grid", "open disk"])
def test_open_meshes_give_the_numpy_results_compiled(compiled, name, shape):
    # positions, faces, twins, boundary loops and rings of every scheme and
    # its two duals on an open mesh, each derived from its input's
    def run():
        m = fresh(two_holed_grid() if shape == "holed grid" else shapes.open_disk())
        out = pentanb.subdivide(m, name, 1, 0)
        d1 = pentanb.dual(out)
        d2 = pentanb.dual(d1)
        got = []
        for x in (out, d1, d2):
            got += [x.vertices, x.corners, x.offsets, *x.vertex_ring, x.twin]
            got += [x.boundary_halfedges, np.asarray(x.boundary_loops[0])]
        return got

    a, b = both(run)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert same_bytes(np.asarray(x), np.asarray(y))
