"""Open meshes: surfaces with boundary (the open-meshes issue).

* a :class:`~pentanb.Mesh` with boundary: what it accepts and refuses, its
  boundary loops, Euler characteristic and genus (``V - E + F = 2 - 2g - b``),
  its twins (hole half-edges from ``H`` on) and vertex rings, checked against
  references built here with dictionaries and walks;
* what only makes sense on a closed mesh refuses an open one.

Every reference here is computed independently of the package (plain Python
over the face lists), so that a test can fail.
"""

from __future__ import annotations

import gc
import itertools
import math
import pickle
import weakref

import numpy as np
import pytest
from helpers import face_lists

import pentanb as pb
from pentanb import Mesh, MeshError, shapes
from pentanb.mesh import check_closed


# ====================================================================== open meshes to test on
def grid(nx: int = 3, ny: int = 2, z=None) -> Mesh:
    """A planar nx x ny patch of unit quads in z = 0 (or heights ``z(x, y)``)."""
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    zs = np.zeros_like(xs) if z is None else z(xs, ys)
    v = np.stack([xs.ravel(), ys.ravel(), zs.ravel()], 1)

    def idx(i, j):
        return i * (ny + 1) + j

    faces = [
        [idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]
        for i in range(nx)
        for j in range(ny)
    ]
    return Mesh(v, faces)


def annulus(n: int = 8, rings: int = 2, hole: float = 0.5) -> Mesh:
    """A flat ring of quads: ``rings`` circles of n vertices from radius ``hole`` to 1."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = np.linspace(hole, 1.0, rings + 1)
    v = np.concatenate([np.stack([ri * np.cos(t), ri * np.sin(t), 0 * t], 1) for ri in r])
    faces = [
        [k * n + i, k * n + (i + 1) % n, (k + 1) * n + (i + 1) % n, (k + 1) * n + i]
        for k in range(rings)
        for i in range(n)
    ]
    return Mesh(v, faces)


def without(m: Mesh, drop) -> Mesh:
    """``m`` without the faces ``drop`` (unused vertices removed, order kept)."""
    faces = [f for i, f in enumerate(face_lists(m)) if i not in set(drop)]
    used = sorted({v for f in faces for v in f})
    new = {v: i for i, v in enumerate(used)}
    return Mesh(m.vertices[used], [[new[v] for v in f] for f in faces])


def moebius_band(n: int = 5) -> tuple[np.ndarray, list[list[int]]]:
    """A band of n quads closed with a half twist: non-orientable."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    centre = np.stack([np.cos(t), np.sin(t), 0 * t], 1)
    across = np.stack([np.cos(t / 2) * np.cos(t), np.cos(t / 2) * np.sin(t), np.sin(t / 2)], 1)
    v = np.concatenate([centre - 0.3 * across, centre + 0.3 * across])
    quads = [[i, i + 1, n + i + 1, n + i] for i in range(n - 1)]
    quads.append([n - 1, n, 0, 2 * n - 1])  # the twist
    return v, quads


OPEN = {
    "grid 3x2": lambda: grid(3, 2),
    "one pentagon": lambda: Mesh(
        np.stack([np.cos(np.arange(5) * 1.2566), np.sin(np.arange(5) * 1.2566), np.zeros(5)], 1),
        [[0, 1, 2, 3, 4]],
    ),
    "annulus": lambda: annulus(8, 2),
    "cube without a face": lambda: without(shapes.cube(), [5]),
    "cube without two opposite faces": lambda: without(shapes.cube(), [0, 1]),
    "torus without a face": lambda: without(shapes.torus(6, 4), [0]),
    "torus without three faces": lambda: without(shapes.torus(6, 4), [0, 10, 17]),
    "dodecahedron without a face": lambda: without(shapes.dodecahedron(), [3]),
}

#: (V, E, F, boundary loops, genus) of every open mesh, counted by hand
EXPECTED = {
    "grid 3x2": (12, 17, 6, 1, 0),
    "one pentagon": (5, 5, 1, 1, 0),
    "annulus": (24, 40, 16, 2, 0),
    "cube without a face": (8, 12, 5, 1, 0),
    "cube without two opposite faces": (8, 12, 4, 2, 0),
    "torus without a face": (24, 48, 23, 1, 1),
    "torus without three faces": (24, 48, 21, 3, 1),
    "dodecahedron without a face": (20, 30, 11, 1, 0),
}


# ====================================================================== references
def reference(m: Mesh):
    """Twins (hole half-edges numbered loop by loop), loops and rings, by walking dicts."""
    faces = face_lists(m)
    tail, head, nxt, prv = [], [], [], []
    for f in faces:
        base = len(tail)
        for i, v in enumerate(f):
            tail.append(v)
            head.append(f[(i + 1) % len(f)])
            nxt.append(base + (i + 1) % len(f))
            prv.append(base + (i - 1) % len(f))
    H = len(tail)
    of = {(u, w): h for h, (u, w) in enumerate(zip(tail, head))}
    boundary = [h for h in range(H) if (head[h], tail[h]) not in of]
    leaving = {tail[h]: h for h in boundary}
    loops, seen = [], set()
    for h in boundary:  # in increasing order: every loop starts at its smallest
        if h in seen:
            continue
        loop = [h]
        seen.add(h)
        while (g := leaving[head[loop[-1]]]) != h:
            loop.append(g)
            seen.add(g)
        loops.append(loop)
    flat = [h for loop in loops for h in loop]
    twin = [of.get((head[h], tail[h]), -1) for h in range(H)]
    for j, h in enumerate(flat):
        twin[h] = H + j
    # all half-edges: the hole half-edge H + j runs head -> tail of flat[j]
    tail_all = tail + [head[h] for h in flat]
    twin_all = twin + flat
    prev_all = prv + [0] * len(flat)
    for loop in loops:
        for i, h in enumerate(loop):
            # the hole face runs against the loop: before H + j comes the hole
            # half-edge of the next boundary half-edge
            prev_all[H + flat.index(h)] = H + flat.index(loop[(i + 1) % len(loop)])
    rotation = [twin_all[prev_all[h]] for h in range(len(tail_all))]
    rings = []
    for v in range(m.n_vertices):
        out = [h for h in range(len(tail_all)) if tail_all[h] == v]
        start, ring = max(out), []
        h = start
        while True:
            ring.append(h)
            h = rotation[h]
            if h == start:
                break
        assert sorted(ring) == sorted(out)  # one cycle round v
        rings.append(ring)
    return twin, loops, rings


# ====================================================================== 1. a Mesh with boundary
@pytest.mark.parametrize("name", list(OPEN))
def test_open_mesh_counts_loops_euler_and_genus(name):
    m = OPEN[name]()
    V, E, F, b, g = EXPECTED[name]
    assert (m.n_vertices, m.n_edges, m.n_faces) == (V, E, F)
    assert not m.is_closed
    assert (m.n_boundary_loops, m.genus) == (b, g)
    assert m.euler_characteristic == V - E + F == 2 - 2 * g - b
    assert m.edges.shape == (E, 2) and m.n_boundary_edges == 2 * E - m.n_halfedges
    assert m.counts()["loops"] == b and m.counts()["B"] == m.n_boundary_edges


@pytest.mark.parametrize("name", list(OPEN))
def test_open_mesh_twins_loops_and_rings_match_a_walk(name):
    m = OPEN[name]()
    twin, loops, rings = reference(m)
    assert m.twin.tolist() == twin
    assert [loop.tolist() for loop in m.boundary_loops] == loops
    assert m.boundary_halfedges.tolist() == [h for loop in loops for h in loop]
    ring, off = m.vertex_ring
    assert ring.size == 2 * m.n_edges
    assert [ring[off[v] : off[v + 1]].tolist() for v in range(m.n_vertices)] == rings
    # valence: edges at a vertex, the boundary's too (faces + 1 on the boundary)
    faces_at = np.bincount(m.corners, minlength=m.n_vertices)
    assert np.array_equal(m.valences, faces_at + m.is_boundary_vertex)
    assert np.array_equal(np.diff(off), m.valences)


@pytest.mark.parametrize("name", list(OPEN))
def test_open_mesh_edges_are_sorted_pairs_numbered_by_their_halfedges(name):
    m = OPEN[name]()
    pairs = {tuple(sorted(p)) for p in zip(m.corners.tolist(), m.head.tolist())}
    assert sorted(map(tuple, m.edges.tolist())) == sorted(pairs)
    assert (m.edges[:, 0] < m.edges[:, 1]).all()
    lo = np.minimum(m.corners, m.head)
    hi = np.maximum(m.corners, m.head)
    assert np.array_equal(m.edges[m.halfedge_edge], np.stack([lo, hi], 1))


def test_the_grid_has_honest_valences_and_one_loop_round_it():
    m = grid(3, 2)
    # corners 2 edges, sides 3, inside 4
    assert m.valence_histogram() == {2: 4, 3: 6, 4: 2}
    (loop,) = m.boundary_loops
    ring = m.corners[loop].tolist()
    assert len(ring) == 10 and set(ring) == set(np.flatnonzero(m.is_boundary_vertex).tolist())
    assert np.array_equal(m.head[loop], np.roll(m.corners[loop], -1))


def test_two_components_open_and_closed_add_their_genus():
    disk = grid(2, 2)
    torus = shapes.torus(6, 4)
    v = np.concatenate([disk.vertices, torus.vertices])
    faces = face_lists(disk) + [[x + disk.n_vertices for x in f] for f in face_lists(torus)]
    m = Mesh(v, faces)
    assert (m.n_components, m.n_boundary_loops, m.genus, m.euler_characteristic) == (2, 1, 1, 1)


def test_a_closed_mesh_has_no_boundary_and_its_arrays_are_unchanged():
    m = shapes.cube()
    assert m.is_closed and m.n_boundary_loops == 0 and m.boundary_loops == ()
    assert m.boundary_halfedges.size == 0 and not m.is_boundary_vertex.any()
    assert m.n_edges == m.n_halfedges // 2
    assert (m.twin < m.n_halfedges).all()
    assert "B" not in m.counts()


# ---------------------------------------------------------------------- what is refused
REFUSED = {
    "two fans at a vertex": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]],
        [[0, 1, 2], [0, 3, 4]],
        r"^vertex 0 is non-manifold: its faces form more than one fan \(2 fans meet there",
    ),
    "a fan and a cycle at a vertex": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1], [0, 1, 1]],
        [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2], [3, 4, 5]],
        r"^vertex 3 is non-manifold: its faces form more than one fan \(or a fan and a cycle\)",
    ),
    "Moebius band": (
        *moebius_band(),
        r"^directed edge \(\d+, \d+\) is used by faces \[\d+, \d+\]: the surface is "
        r"non-orientable",
    ),
    "a flipped face in a grid": (
        grid(2, 1).vertices,
        [[0, 2, 3, 1], [5, 4, 2, 3]],
        r"^directed edge \(2, 3\) is used by faces \[0, 1\]: inconsistent orientation .*"
        r"reversing face 1 would orient",
    ),
    "a boundary edge used twice": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0]],
        [[0, 1, 2], [0, 1, 3]],
        r"^directed edge \(0, 1\) is used by faces \[0, 1\]: inconsistent orientation "
        r"\(both run along it from 0 to 1, none from 1 to 0\)",
    ),
    "three faces on an edge": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]],
        [[0, 1, 2], [1, 0, 3], [0, 1, 4]],
        r"^directed edge \(0, 1\) is used by faces \[0, 2\]: edge \(0, 1\) has 3 faces "
        r"\[0, 1, 2\], a non-manifold edge",
    ),
    "an isolated vertex": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5]],
        [[0, 1, 2]],
        r"^vertex 3 is not used by any face \(1 unused vertices\)$",
    ),
    "a face using a vertex twice": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]],
        [[0, 1, 3, 1, 2]],
        r"^face 0 \[0, 1, 3, 1, 2\] repeats vertex 1",
    ),
    "an interior vertex of 2 edges": (
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.4, 0.4, 0]],
        [[0, 1, 4, 2], [1, 3, 2, 4]],
        r"^interior vertex 4 has only 2 edges",
    ),
}


@pytest.mark.parametrize("name", list(REFUSED))
def test_what_is_not_a_manifold_with_boundary_is_refused_naming_the_culprit(name):
    v, faces, message = REFUSED[name]
    with pytest.raises(MeshError, match=message):
        Mesh(v, faces)
    # the fast path refuses it too (validate=False keeps every check the
    # arrays' consistency rests on: all but the last two)
    if name not in ("an isolated vertex", "an interior vertex of 2 edges"):
        c = np.concatenate([np.asarray(f) for f in faces])
        o = np.cumsum([0] + [len(f) for f in faces])
        with pytest.raises(MeshError):
            Mesh.from_csr(v, c, o, validate=False)


@pytest.mark.parametrize("block", [2, 3, 7])
@pytest.mark.parametrize("name", ["annulus", "torus without three faces", "grid 3x2"])
def test_open_pairing_is_the_same_whatever_the_blocks(name, block, monkeypatch):
    # the sorted keys are read on block by block past the first boundary
    # edge, every block ending between two edges: blocks of a few keys
    # split every edge that can be split
    from pentanb.mesh import halfedge

    m = OPEN[name]()
    want = halfedge.pair_sorted(m.corners, m.head, m.n_vertices, boundary=True)
    monkeypatch.setattr(halfedge, "PAIR_BLOCK", block)
    got = halfedge.pair_sorted(m.corners, m.head, m.n_vertices, boundary=True)
    assert want is not None and got is not None
    assert got[0].tolist() == want[0].tolist() and got[1].tolist() == want[1].tolist()
    assert sorted(got[1].tolist()) == sorted(m.boundary_halfedges.tolist())
    # and a third half-edge on an edge is still refused, wherever it falls
    v, faces, _ = REFUSED["three faces on an edge"]
    c = np.concatenate([np.asarray(f) for f in faces])
    head = np.concatenate([np.roll(f, -1) for f in faces])
    assert halfedge.pair_sorted(c, head, len(v), boundary=True) is None


def test_a_moebius_band_with_its_twist_undone_is_an_orientable_band():
    v, quads = moebius_band()
    n = len(quads)
    quads[-1] = [n - 1, 0, n, 2 * n - 1]  # b_{n-1}, b_0, t_0, t_{n-1}: no twist
    m = Mesh(v, quads)
    assert (m.n_boundary_loops, m.genus, m.euler_characteristic) == (2, 0, 0)


# ---------------------------------------------------------------------- closed-only code
def test_closed_only_code_refuses_an_open_mesh_by_name():
    m = grid(2, 2)
    with pytest.raises(MeshError, match=r"^volume needs a closed mesh; this one is open: "):
        _ = m.volume
    with pytest.raises(MeshError, match=r"^canonical needs a closed mesh; .*1 boundary loop"):
        check_closed(m, "canonical")
    assert check_closed(shapes.cube(), "volume") is not None


# ---------------------------------------------------------------------- copies, pickles, files
def test_an_open_mesh_pickles_and_shares_its_faces_with_new_positions():
    m = annulus()
    _ = m.twin, m.vertex_ring
    again = pickle.loads(pickle.dumps(m))
    assert np.array_equal(again.twin, m.twin)
    assert np.array_equal(again.vertex_ring[0], m.vertex_ring[0])
    moved = m.with_vertices(m.vertices * 2)
    assert moved.n_boundary_loops == 2 and np.array_equal(moved.twin, m.twin)
    raw = Mesh.from_csr(m.vertices, m.corners, m.offsets, validate=False)
    assert [x.tolist() for x in raw.boundary_loops] == [x.tolist() for x in m.boundary_loops]


def test_an_open_mesh_refuses_handed_twins_outside_the_face_halfedges():
    m = grid(1, 1)
    with pytest.raises(MeshError, match=r"twin of half-edge 0 is 4, outside the 4 half-edges"):
        Mesh.from_csr(m.vertices, m.corners, m.offsets, twin=m.twin)


@pytest.mark.parametrize("suffix", [".obj", ".off", ".ply"])
def test_an_open_file_is_read_and_written_back(tmp_path, suffix):
    m = grid(3, 2)
    path = tmp_path / f"patch{suffix}"
    pb.write(m, path)
    again = pb.read(path)
    assert face_lists(again) == face_lists(m)
    assert [x.tolist() for x in again.boundary_loops] == [x.tolist() for x in m.boundary_loops]


def test_an_open_obj_written_by_hand_is_read():
    text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n"
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "open.obj"
        path.write_text(text)
        m = pb.read(path)
    assert (m.n_vertices, m.n_edges, m.n_faces, m.n_boundary_loops) == (5, 6, 2, 1)
    assert m.corners[m.boundary_loops[0]].tolist() == [0, 1, 4, 2, 3]


def test_loop_order_names_the_vertex_two_boundary_fans_share():
    from pentanb.mesh.boundary import loop_order

    tail = np.array([0, 1, 2, 0, 3, 4])  # two triangles meeting at vertex 0
    head = np.array([1, 2, 0, 3, 4, 0])
    loops, offsets, bad = loop_order(tail, head, np.arange(6), 5)
    assert bad == 0 and loops.size == 0
    loops, offsets, bad = loop_order(tail[:3], head[:3], np.arange(3), 5)
    assert bad == -1 and loops.tolist() == [0, 1, 2] and offsets.tolist() == [0, 3]


# ================================================================= 2. the schemes on open meshes
SCHEME_NAMES = list(pb.SCHEMES)
SMALL_OPEN = ["grid 3x2", "one pentagon", "annulus", "torus without three faces"]
#: the flat ones, to check that no face is folded
FLAT = {"grid 3x2": lambda: grid(3, 2), "one pentagon": OPEN["one pentagon"]}


def open_counts(m: Mesh) -> tuple[int, int, int, int, int]:
    """(V, E, F, B, C): vertices, edges, faces, boundary edges, corners."""
    C = len(pb.schemes.boundary_corners(m))
    return m.n_vertices, m.n_edges, m.n_faces, m.n_boundary_edges, C


def check_open_valid(out: Mesh) -> None:
    """An operator's open output is a valid mesh whose arrays are the references'."""
    rebuilt = Mesh(out.vertices, face_lists(out))  # validates (raises when invalid)
    twin, loops, rings = reference(out)
    assert out.twin.tolist() == twin
    assert [x.tolist() for x in out.boundary_loops] == loops
    ring, off = out.vertex_ring
    assert [ring[off[v] : off[v + 1]].tolist() for v in range(out.n_vertices)] == rings
    for name in ("halfedge_edge", "edges", "valences", "is_boundary_vertex"):
        assert np.array_equal(getattr(out, name), getattr(rebuilt, name)), name


@pytest.mark.parametrize("scheme", SCHEME_NAMES + ["dual"])
@pytest.mark.parametrize("name", SMALL_OPEN)
def test_every_scheme_and_the_dual_give_valid_open_meshes_with_the_predicted_counts(name, scheme):
    m = OPEN[name]()
    counts = open_counts(m)
    if scheme == "dual":
        steps = [pb.dual(m)]
        steps.append(pb.dual(steps[0]))
        predicted = [pb.schemes.registry.dual_counts(*counts)]
        predicted.append(pb.schemes.registry.dual_counts(*predicted[0]))
    else:
        out = pb.SCHEMES[scheme](m)
        steps = [out, pb.dual(out), pb.dual(pb.dual(out))]
        predicted = pb.schemes.registry.open_counts_after(counts, scheme, 1, 2)
    for out, expect in zip(steps, predicted):
        check_open_valid(out)
        got = open_counts(out)
        if scheme == "triangulate" and out is steps[0]:  # exact without triangles only
            assert all(g <= e for g, e in zip(got[:3], expect)) and got[3] == expect[3]
        elif scheme != "triangulate":
            assert got == expect
        assert out.n_boundary_loops == m.n_boundary_loops
        assert (out.genus, out.n_components) == (m.genus, m.n_components)


def _loop_points(m: Mesh) -> list[np.ndarray]:
    return [m.vertices[m.corners[loop]] for loop in m.boundary_loops]


def _turned(points: np.ndarray, start: np.ndarray) -> np.ndarray:
    """The cyclic point sequence turned to begin at its point nearest ``start``."""
    at = int(np.argmin(np.linalg.norm(points - start, axis=1)))
    return np.roll(points, -at, axis=0)


#: schemes that keep the old vertices: every boundary edge of the input becomes
#: this many, at these fractions of its length
SPLIT = {
    "pentagonalize": 3,
    "preserve_pentagons": 2,
    "loop_remesh": 2,
    "vertex_insertion": 2,
    "preserve_hexagons": 3,
    "triangulate": 1,
    "sqrt3_remesh": 1,
}


@pytest.mark.parametrize("scheme", list(SPLIT))
@pytest.mark.parametrize("name", ["annulus", "torus without three faces", "one pentagon"])
def test_the_boundary_of_a_remeshing_is_the_inputs_refined(name, scheme):
    m = OPEN[name]()
    out = pb.SCHEMES[scheme](m)
    k = SPLIT[scheme]
    t = np.arange(k)[:, None, None] / k
    for before, after in zip(_loop_points(m), _loop_points(out)):
        refined = (1 - t) * before + t * np.roll(before, -1, axis=0)  # (k, b, 3)
        refined = refined.transpose(1, 0, 2).reshape(-1, 3)
        assert np.allclose(_turned(after, before[0]), refined, rtol=0, atol=1e-12)


@pytest.mark.parametrize("op", [pb.dual, pb.honeycomb])
def test_the_dual_and_honeycomb_close_the_boundary_through_its_midpoints(op):
    m = OPEN["torus without three faces"]()  # (no corner: every boundary vertex has 2 faces)
    assert len(pb.schemes.boundary_corners(m)) == 0
    out = op(m)
    for before, after in zip(_loop_points(m), _loop_points(out)):
        mids = 0.5 * before + 0.5 * np.roll(before, -1, axis=0)
        assert np.array_equal(_turned(after, mids[0]), mids)


def test_corner_cutting_cuts_the_boundary_as_chaikin_does():
    m = OPEN["annulus"]()
    for scale, near in ((0.5, 0.25), (0.8, 0.1)):
        out = pb.corner_cutting(m, scale=scale)
        for before, after in zip(_loop_points(m), _loop_points(out)):
            nxt = np.roll(before, -1, axis=0)
            cut = np.stack([(1 - near) * before + near * nxt, near * before + (1 - near) * nxt], 1)
            assert np.allclose(_turned(after, cut[0, 0]), cut.reshape(-1, 3), atol=1e-12)


#: what folds faces near the boundary of a flat patch within three iterations:
#: triangulate and sqrt(3) give a corner a second face, so the dual cuts it off
#: (then the faces next to the cut fold, as when Catmull-Clark cuts a corner);
#: honeycomb with one dual makes long thin triangles along the boundary
FOLDS = {("triangulate", 1), ("triangulate", 2), ("sqrt3_remesh", 1), ("sqrt3_remesh", 2)}
FOLDS |= {("honeycomb", 1)}


@pytest.mark.parametrize(
    "scheme, duals",
    [
        pytest.param(
            s, d, marks=[pytest.mark.xfail(strict=True, reason="folds")] if (s, d) in FOLDS else []
        )
        for s in SCHEME_NAMES
        for d in (0, 1, 2)
    ],
)
@pytest.mark.parametrize("name", list(FLAT))
def test_no_face_of_a_flat_patch_folds_iteration_after_iteration(name, scheme, duals):
    m = FLAT[name]()
    for _ in range(3):
        m = pb.subdivide(m, scheme, iterations=1, duals=duals)
        assert np.allclose(m.face_normals, [0, 0, 1], atol=1e-9), scheme


def test_pentagonalize_gives_pentagons_and_two_duals_line_the_boundary_with_quads():
    m = OPEN["annulus"]()
    out = pb.pentagonalize(m)
    assert out.face_size_histogram() == {5: m.n_halfedges}
    smooth = pb.smooth(out, duals=2)
    # the faces of the boundary's midpoints are quads: one per boundary edge
    assert smooth.face_size_histogram() == {4: out.n_boundary_edges, 5: out.n_faces}


def test_corners_are_the_sharp_one_face_vertices_and_stay_where_they_are():
    m = grid(3, 2)
    square = {(0.0, 0.0), (3.0, 0.0), (0.0, 2.0), (3.0, 2.0)}
    assert {tuple(m.vertices[v, :2]) for v in pb.schemes.boundary_corners(m)} == square
    # pentagonalization's point at two thirds of a boundary edge has one face but
    # lies on a straight boundary: no corner
    p = pb.pentagonalize(m)
    assert (p.valences[p.is_boundary_vertex] == 2).sum() == m.n_boundary_edges + 4
    assert {tuple(p.vertices[v, :2]) for v in pb.schemes.boundary_corners(p)} == square
    for scheme in ("pentagonalize", "preserve_pentagons", "corner_cutting", "honeycomb"):
        out = pb.subdivide(m, scheme, iterations=2, duals=2)
        corners = pb.schemes.boundary_corners(out)
        assert {tuple(out.vertices[v, :2]) for v in corners} == square, scheme
        # the boundary stays on the square's sides
        rim = out.vertices[out.is_boundary_vertex]
        on_side = np.isclose(rim[:, 0], 0) | np.isclose(rim[:, 0], 3)
        on_side |= np.isclose(rim[:, 1], 0) | np.isclose(rim[:, 1], 2)
        assert on_side.all(), scheme


def test_a_vertex_of_one_face_turning_less_than_the_corner_angle_is_cut_off():
    n = 16  # a regular 16-gon: the boundary turns by 22.5 degrees at every vertex
    t = 2 * np.pi * np.arange(n) / n
    m = Mesh(np.stack([np.cos(t), np.sin(t), 0 * t], 1), [list(range(n))])
    assert len(pb.schemes.boundary_corners(m)) == 0
    assert pb.dual(m).n_vertices == 1 + n  # the centroid and the midpoints
    t = 2 * np.pi * np.arange(5) / 5  # a pentagon turns by 72 degrees: five corners
    m = Mesh(np.stack([np.cos(t), np.sin(t), 0 * t], 1), [list(range(5))])
    assert pb.schemes.boundary_corners(m).tolist() == [0, 1, 2, 3, 4]
    assert pb.dual(m).n_vertices == 1 + 5 + 5


# ====================================================================== 3. measured properties
def tilted_patch() -> tuple[Mesh, np.ndarray, np.ndarray]:
    """A jittered 4 x 3 grid of quads with one square split into two triangles, laid
    in the plane through ``origin`` with unit normal ``normal``."""
    m = grid(4, 3)
    rng = np.random.default_rng(5)
    uv = m.vertices[:, :2] + rng.uniform(-0.2, 0.2, (m.n_vertices, 2))
    normal = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    e1 = np.cross(normal, [0.0, 0.0, 1.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(normal, e1)
    origin = np.array([0.3, -1.2, 2.5])
    faces = face_lists(m)
    a, b, c, d = faces.pop(5)
    faces += [[a, b, c], [a, c, d]]
    return Mesh(origin + uv[:, :1] * e1 + uv[:, 1:] * e2, faces), origin, normal


@pytest.mark.parametrize("scheme", SCHEME_NAMES)
def test_a_flat_patch_stays_in_its_plane(scheme):
    m, origin, normal = tilted_patch()
    assert np.abs((m.vertices - origin) @ normal).max() < 1e-14
    out = pb.subdivide(m, scheme, iterations=2, duals=2)
    assert np.abs((out.vertices - origin) @ normal).max() < 1e-12
    assert not out.is_closed and out.n_boundary_loops == 1


def test_a_flat_patch_stays_in_its_plane_fails_on_a_bent_patch():
    m, origin, normal = tilted_patch()
    bent = m.with_vertices(m.vertices + 1e-6 * normal * (np.arange(m.n_vertices) == 7)[:, None])
    out = pb.subdivide(bent, "pentagonalize", iterations=1, duals=2)
    assert np.abs((out.vertices - origin) @ normal).max() > 1e-8


# ---------------------------------------------------------------------- the boundary's curve scheme
def refine(p: np.ndarray, k: int) -> np.ndarray:
    """A closed polygon with its edges cut in k equal parts (k - 1 new points each)."""
    nxt = np.roll(p, -1, axis=0)
    return np.stack([(1 - j / k) * p + (j / k) * nxt for j in range(k)], 1).reshape(-1, 3)


def average(p: np.ndarray) -> np.ndarray:
    """The polygon of the midpoints of a closed polygon's edges (the open dual's rule)."""
    return 0.5 * p + 0.5 * np.roll(p, -1, axis=0)


def curve_step(p: np.ndarray, k: int) -> np.ndarray:
    """One iteration with two duals, on the boundary alone: cut, then average twice."""
    return average(average(refine(p, k)))


def turning_angles(p: np.ndarray) -> np.ndarray:
    """(b,) signed turning angle (degrees, + to the left seen from +z) at every vertex
    of a closed plane polygon."""
    a = np.roll(p, -1, axis=0) - p
    b = np.roll(a, 1, axis=0)
    cross = b[:, 0] * a[:, 1] - b[:, 1] * a[:, 0]
    return np.degrees(np.arctan2(cross, np.einsum("ij,ij->i", a, b)))


def heptagon_disk() -> Mesh:
    """A lopsided convex heptagon cut into seven triangles round an inner point:
    every boundary vertex has two faces (no corner); it turns by up to 102.5 degrees."""
    t = np.radians([5, 15, 100, 220, 230, 290, 330])
    v = np.concatenate([[[0.1, -0.05, 0.0]], np.stack([np.cos(t), np.sin(t), 0 * t], 1)])
    return Mesh(v, [[0, 1 + i, 1 + (i + 1) % 7] for i in range(7)])


CUT = {"pentagonalize": 3, "preserve_pentagons": 2}


@pytest.mark.parametrize("scheme", list(CUT))
def test_the_boundary_follows_its_curve_scheme_on_the_mesh(scheme):
    m = heptagon_disk()
    (p,) = _loop_points(m)
    for _ in range(3):
        m = pb.subdivide(m, scheme, iterations=1, duals=2)
        p = curve_step(p, CUT[scheme])
        (q,) = _loop_points(m)
        assert np.allclose(_turned(q, p[0]), p, rtol=0, atol=1e-12)
        assert (m.vertices[:, 2] == 0).all()


def test_preserve_pentagons_with_two_duals_is_cubic_bspline_subdivision_on_the_boundary():
    (p,) = _loop_points(heptagon_disk())
    q = curve_step(p, 2)
    nxt, prv = np.roll(p, -1, axis=0), np.roll(p, 1, axis=0)
    edge = (p + nxt) / 2
    vertex = (prv + 6 * p + nxt) / 8
    bspline = np.stack([edge, np.roll(vertex, -1, axis=0)], 1).reshape(-1, 3)
    assert np.allclose(_turned(q, bspline[0]), bspline, atol=1e-15)
    # and not Chaikin's (quadratic B-spline) rules
    chaikin = np.stack([0.75 * p + 0.25 * nxt, 0.25 * p + 0.75 * nxt], 1).reshape(-1, 3)
    assert not np.allclose(_turned(q, chaikin[0]), chaikin, atol=1e-3)


def test_pentagonalize_with_two_duals_is_a_ternary_scheme_of_mask_1_4_8_10_8_4_1_on_the_boundary():
    (p,) = _loop_points(heptagon_disk())
    q = curve_step(p, 3)
    up = np.zeros((3 * len(p), 3))
    up[::3] = p
    mask = np.array([1, 4, 8, 10, 8, 4, 1]) / 12
    conv = sum(w * np.roll(up, k, axis=0) for k, w in enumerate(mask))
    assert np.allclose(_turned(conv, q[0]), q, atol=1e-15)
    # every new point an affine combination: the mask's three phases sum to 1
    assert [mask[r::3].sum() for r in range(3)] == pytest.approx([1, 1, 1])


#: the largest turning angle (degrees) of the heptagon disk's boundary, iteration
#: by iteration (two duals each), measured on the boundary's curve scheme
TURNS = {
    "pentagonalize": [102.5, 62.76, 33.53, 17.07, 8.571, 4.290, 2.146, 1.073, 0.537],
    "preserve_pentagons": [102.5, 74.50, 40.64, 20.78, 10.81, 5.418, 2.716, 1.358, 0.679],
}


@pytest.mark.parametrize("scheme", list(CUT))
def test_a_disk_boundary_stays_convex_and_turns_less_each_iteration_under_1_degree_after_8(
    scheme,
):
    (p,) = _loop_points(heptagon_disk())
    largest = []
    for _ in range(9):
        a = turning_angles(p)
        assert (a > 0).all() and a.sum() == pytest.approx(360.0)  # convex, once round
        largest.append(float(a.max()))
        p = curve_step(p, CUT[scheme])
    assert largest == pytest.approx(TURNS[scheme], rel=2e-3)
    assert all(b < a for a, b in itertools.pairwise(largest))
    assert largest[7] > 1.0 > largest[8]  # under 1 degree after 8 iterations
    # halving: each iteration divides the largest turn by about 2
    assert largest[8] / largest[7] == pytest.approx(0.5, abs=0.01)


def test_the_turning_angle_measure_fails_on_a_polygon_with_a_kink():
    (p,) = _loop_points(heptagon_disk())
    for _ in range(6):
        p = curve_step(p, 2)
    assert turning_angles(p).max() < 3
    p[10] += 0.05 * (p[10] - p.mean(axis=0))  # one vertex pushed out
    assert turning_angles(p).max() > 10


# ---------------------------------------------------------------------- far from the boundary
def ring_distance(m: Mesh) -> np.ndarray:
    """(n,) int: every vertex's distance (in edges) from the boundary."""
    d = np.full(m.n_vertices, -1)
    front = np.flatnonzero(m.is_boundary_vertex)
    d[front] = 0
    e = m.edges
    k = 0
    while front.size:
        k += 1
        near = np.isin(e, front)
        nb = np.unique(np.concatenate([e[near[:, 0], 1], e[near[:, 1], 0]]))
        front = nb[d[nb] < 0]
        d[front] = k
    return d


def far_faces_match(open_out: Mesh, closed_out: Mesh, rings: int) -> int:
    """How many faces of ``open_out`` at least ``rings`` edges from its boundary are
    faces of ``closed_out``, positions to 1e-12 (AssertionError if one is not)."""
    from scipy.spatial import cKDTree

    d = ring_distance(open_out)
    tree = cKDTree(closed_out.face_centroids)
    count = 0
    for f, verts in enumerate(open_out.faces):
        if d[verts].min() < rings:
            continue
        dist, g = tree.query(open_out.face_centroids[f])
        a, b = open_out.vertices[verts], closed_out.vertices[closed_out.faces[g]]
        assert dist < 1e-9 and len(a) == len(b), f
        s = int(np.argmin(np.linalg.norm(b - a[0], axis=1)))
        assert np.abs(np.roll(b, -s, axis=0) - a).max() < 1e-12, f
        count += 1
    return count


#: rings (of the output) beyond which its faces are the closed mesh's, for one iteration
RINGS = {
    "pentagonalize": 2,
    "preserve_pentagons": 2,
    "triangulate": 2,
    "loop_remesh": 2,
    "sqrt3_remesh": 3,
    "vertex_insertion": 2,
    "corner_cutting": 3,
    "preserve_hexagons": 3,
    "honeycomb": 4,
}


@pytest.mark.parametrize("scheme", SCHEME_NAMES)
def test_faces_far_from_a_cut_are_those_of_the_closed_torus(scheme):
    torus = shapes.torus(12, 8)
    band = without(torus, range(16))  # two rings of faces cut out: a band, two loops
    closed_out = pb.subdivide(torus, scheme, iterations=1, duals=2)
    open_out = pb.subdivide(band, scheme, iterations=1, duals=2)
    assert far_faces_match(open_out, closed_out, RINGS[scheme]) > 100
    with pytest.raises(AssertionError):  # nearer the cut they differ
        far_faces_match(open_out, closed_out, RINGS[scheme] - 1)


@pytest.mark.parametrize("scheme, rings", [("pentagonalize", 8), ("preserve_pentagons", 7)])
def test_faces_far_from_a_cut_are_those_of_the_closed_torus_after_two_iterations(scheme, rings):
    torus = shapes.torus(12, 8)
    band = without(torus, range(16))
    closed_out = pb.subdivide(torus, scheme, iterations=2, duals=2)
    open_out = pb.subdivide(band, scheme, iterations=2, duals=2)
    assert far_faces_match(open_out, closed_out, rings) > 500


# ---------------------------------------------------------------------- counts with boundary terms
@pytest.mark.parametrize("scheme", SCHEME_NAMES)
def test_counts_after_two_iterations_are_the_formulas_with_boundary_terms(scheme):
    m = shapes.open_disk()
    predicted = pb.schemes.registry.open_counts_after(open_counts(m), scheme, 2, 2)
    out = m
    got = []
    for _ in range(2):
        out = pb.SCHEMES[scheme](out)
        got.append(open_counts(out))
        for _ in range(2):
            out = pb.dual(out)
            got.append(open_counts(out))
    if scheme != "triangulate":
        assert got == predicted
        return
    # triangulate is exact on meshes without triangles or of triangles only (the open
    # disk is neither): at most the formula, the boundary kept; then the duals' counts
    before = open_counts(m)
    for i, counts in enumerate(got):
        if i % 3 == 0:
            bound = pb.SCHEMES[scheme].open_counts(*before)
            assert all(g <= b for g, b in zip(counts[:3], bound)) and counts[3] == before[3]
        else:
            assert counts == pb.schemes.registry.dual_counts(*before)
        before = counts


def test_the_open_formulas_are_the_closed_ones_with_boundary_terms():
    for s in pb.SCHEMES.values():
        V, E, F = 20, 30, 12
        assert s.open_counts(V, E, F, 0, 0)[:3] == s.counts(V, E, F), s.name
    assert pb.SCHEMES["pentagonalize"].open_formula == "(V+2E+F, 5E-B, 2E-B, 3B, C)"
    assert pb.SCHEMES["preserve_pentagons"].open_formula == "(V+3E-B, 6E-2B, 2E+F-B, 2B, C)"
    assert pb.schemes.registry.dual_counts(20, 30, 12, 5, 2) == (19, 37, 20, 7, 2)


# ---------------------------------------------------------------------- the open model
def test_the_open_disk_model():
    m = shapes.open_disk()
    assert (m.n_vertices, m.n_edges, m.n_faces) == (147, 300, 152)
    assert m.face_size_histogram() == {3: 72, 4: 68, 5: 12}
    assert [len(x) for x in m.boundary_loops] == [30, 11, 11]
    assert (m.genus, m.euler_characteristic, m.n_components) == (0, -1, 1)
    r = np.linalg.norm(m.vertices[:, :2], axis=1)
    assert np.allclose(r[m.corners[m.boundary_loops[0]]], 1.0, atol=1e-6)  # the rim
    assert (m.face_normals[:, 2] > 0).all()


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
def test_the_papers_schemes_fold_no_face_of_the_open_disk(scheme):
    out = pb.subdivide(shapes.open_disk(), scheme, iterations=2, duals=2)
    up = out.vertices[out.corners] - [0, 0, -np.sqrt(1.4**2 - 1)]  # from the sphere's centre
    outward = np.add.reduceat(up, out.offsets[:-1], axis=0)
    assert (np.einsum("ij,ij->i", out.face_normals, outward) > 0).all()
    assert out.n_boundary_loops == 3 and out.genus == 0


def test_the_shipped_open_disk_is_what_its_script_writes(tmp_path):
    pytest.importorskip("scipy")
    from importlib import resources

    from pentanb.data import make_open_disk

    out = tmp_path / "open_disk.obj"
    assert make_open_disk.main([str(out)]) == 0
    shipped = resources.files("pentanb.data").joinpath("open_disk.obj").read_text()
    assert out.read_text() == shipped


# ====================================================================== 4. Section 4 with boundary
def ngon_meshes_with_boundary() -> dict[str, tuple[int, Mesh]]:
    """Open meshes whose faces all have n sides, by name: (n, mesh)."""
    out: dict[str, tuple[int, Mesh]] = {}
    for n in range(3, 10):
        t = 2 * np.pi * np.arange(n) / n
        out[f"one {n}-gon"] = (n, Mesh(np.stack([np.cos(t), np.sin(t), 0 * t], 1), [range(n)]))
    out["grid of quads"] = (4, grid(3, 2))
    out["torus band of quads"] = (4, without(shapes.torus(12, 8), range(16)))
    out["pentagonalized open disk"] = (5, pb.pentagonalize(shapes.open_disk()))
    out["pentagonalized torus with holes"] = (
        5,
        pb.pentagonalize(OPEN["torus without three faces"]()),
    )
    out["triangulated grid"] = (3, pb.triangulate(grid(3, 2)))
    return out


@pytest.mark.parametrize("name", list(ngon_meshes_with_boundary()))
def test_real_open_ngon_meshes_satisfy_equation_1_with_boundary(name):
    from pentanb import topology as tp

    n, m = ngon_meshes_with_boundary()[name]
    assert set(m.face_size_histogram()) == {n}
    g, b, v, e_b = m.genus, m.n_boundary_loops, m.n_vertices, m.n_boundary_edges
    assert tp.euler_characteristic(g, b) == m.euler_characteristic
    assert tp.ngon_mesh_counts_with_boundary(n, g, b, v, e_b) == (v, m.n_edges, m.n_faces)
    # the valence of equation (1) with boundary is the mesh's, boundary edges counted
    assert tp.average_valence_with_boundary(n, g, b, v, e_b) == pytest.approx(m.valences.mean())
    # and a valid mesh meets the count-wise criterion
    assert tp.can_tile_with_boundary(n, g, b, v, e_b)
    r = tp.vertex_range_with_boundary(n, g, b, e_b)
    assert r is not None and r[0] <= v <= r[1]
    # one boundary edge more or less: no such mesh
    assert tp.ngon_mesh_counts_with_boundary(n, g, b, v, e_b + n - 2 + 1) is None or n == 3


def test_equation_1_with_boundary_is_equation_1_without():
    from pentanb import topology as tp

    for n, g, v in [(3, 0, 4), (5, 0, 20), (6, 1, 30), (5, 2, 31)]:
        assert tp.average_valence_with_boundary(n, g, 0, v, 0) == tp.average_valence(n, g, v)
        assert tp.ngon_mesh_counts_with_boundary(n, g, 0, v, 0) == tp.ngon_mesh_counts(n, g, v)
    with pytest.raises(ValueError, match=r"both 0 \(closed\) or both positive"):
        tp.average_valence_with_boundary(5, 0, 1, 10, 0)
    with pytest.raises(ValueError, match=r"at least 3 edges, got e_b=5"):
        tp.ngon_mesh_counts_with_boundary(5, 0, 2, 10, 5)


def test_which_ngons_tile_surfaces_with_boundary():
    from pentanb import topology as tp

    # closed: pentagons at most (no hexagonal sphere); with boundary: hexagons too
    assert [tp.ngonalization_exists(n) for n in (5, 6, 7)] == [True, False, False]
    assert [tp.ngonalization_exists_with_boundary(n) for n in (5, 6, 7)] == [True, True, False]
    # a hexagonal disk needs six boundary edges (one hexagon), then any number of vertices
    assert tp.min_boundary_edges(6, 0, 1) == 6
    assert tp.vertex_range_with_boundary(6, 0, 1, 5) is None
    assert tp.vertex_range_with_boundary(6, 0, 1, 6) == (6, math.inf)
    # heptagons: the interior is bounded by the boundary, v <= 3 e_b - 14 on a disk
    assert tp.vertex_range_with_boundary(7, 0, 1, 7) == (7, 7)
    assert tp.vertex_range_with_boundary(7, 0, 1, 20)[1] == 3 * 20 - 14
    # every n fits some surface with boundary, of any genus and number of loops
    for n in range(3, 12):
        for g in range(3):
            for b in range(1, 4):
                assert tp.can_tile_with_boundary(n, g, b), (n, g, b)
    assert tp.euler_characteristic(0, 3) == -1


# ====================================================================== large open meshes
def test_a_large_open_mesh_takes_the_default_path_and_stays_valid():
    m = grid(70, 60)  # 16,800 corners: the compiled kernels' size, when numba is there
    assert m.n_halfedges >= pb._jit.MIN_CORNERS
    for scheme in ("pentagonalize", "preserve_pentagons"):
        out = pb.subdivide(m, scheme, iterations=1, duals=2)
        rebuilt = Mesh(out.vertices, face_lists(out))
        assert np.array_equal(out.twin, rebuilt.twin)
        counts = pb.schemes.registry.open_counts_after(open_counts(m), scheme, 1, 2)[-1]
        assert open_counts(out) == counts
        assert (out.vertices[:, 2] == 0).all()


@pytest.mark.slow
@pytest.mark.parametrize("scheme", SCHEME_NAMES + ["dual"])
def test_open_meshes_are_the_same_by_the_numpy_path_and_the_kernels(scheme, monkeypatch):
    from pentanb import _jit

    if not _jit.available():
        pytest.skip("numba is not installed")
    monkeypatch.setattr(_jit, "MIN_CORNERS", 0)
    before = _jit.use_jit(False)
    try:
        outs = []
        for on in (False, True):
            _jit.use_jit(on)
            m = shapes.open_disk()
            out = pb.dual(m) if scheme == "dual" else pb.subdivide(m, scheme, 1, 2)
            outs.append((out.vertices, out.corners, out.offsets, out.twin, out.vertex_ring[0]))
        for a, b in zip(*outs):
            assert a.dtype == b.dtype and a.tobytes() == b.tobytes()
    finally:
        _jit.use_jit(before)


@pytest.mark.parametrize(
    "name", ["pentagonalize", "preserve_pentagons", "loop_remesh", "corner_cutting"]
)
def test_predict_counts_of_an_open_mesh_are_the_built_ones(name):
    disk = shapes.open_disk()
    predicted = pb.predict_counts(disk, name, iterations=2, duals=2)[-1]
    built = pb.subdivide(disk, name, iterations=2, duals=2)
    assert predicted == (built.n_vertices, built.n_edges, built.n_faces)
    counts = (disk.n_vertices, disk.n_edges, disk.n_faces)
    closed_formula = pb.predict_counts(counts, name, iterations=2, duals=2)[-1]
    assert closed_formula != predicted  # the boundary terms matter here


def _vertex_configurations(m):
    from pentanb.analysis.measures import vertex_configurations

    return vertex_configurations(m)


@pytest.mark.parametrize("call", [pb.canonical, pb.notation.ambo, _vertex_configurations])
def test_closed_only_code_refuses_an_open_mesh(call):
    with pytest.raises(MeshError, match="needs a closed mesh; this one is open"):
        call(shapes.open_disk())


# ============================================================ connectivity written, not paired
def holed_grid(nx: int = 9, ny: int = 7) -> Mesh:
    """A grid with two square holes, one touching the rim at a corner of a hole."""
    m = grid(nx, ny)
    return without(m, [2 * ny + 2, 2 * ny + 3, 3 * ny + 2, 3 * ny + 3, 6 * ny + 4])


WRITTEN = {
    "holed grid": holed_grid,
    "annulus": lambda: annulus(9, 3),
    "open disk": shapes.open_disk,
    "grid 3x2": lambda: grid(3, 2),
    "torus without three faces": OPEN["torus without three faces"],
}


def test_canonical_loops_is_what_loop_order_gives_for_chains_from_any_start():
    from pentanb.mesh.boundary import canonical_loops, loop_order

    rng = np.random.default_rng(5)
    for _ in range(20):
        sizes = rng.integers(1, 9, size=rng.integers(1, 6))
        ids = rng.permutation(int(sizes.sum()) * 3)[: sizes.sum()]  # distinct half-edges
        n = int(ids.max()) + 1 + int(sizes.sum())
        # loop i: vertices base_i .. base_i + size_i - 1 in a cycle
        tail = np.zeros(n, dtype=np.int64)
        head = np.zeros(n, dtype=np.int64)
        chain, offsets, v = [], [0], 0
        for s in sizes.tolist():
            loop = ids[offsets[-1] : offsets[-1] + s]
            for i, h in enumerate(loop):
                tail[h], head[h] = v + i, v + (i + 1) % s
            turn = int(rng.integers(0, s))
            chain.extend(np.roll(loop, turn).tolist())
            offsets.append(offsets[-1] + s)
            v += s
        want, want_off, bad = loop_order(tail, head, np.sort(ids), v + 1)
        assert bad == -1
        got, got_off = canonical_loops(np.array(chain), np.array(offsets))
        assert got.tolist() == want.tolist() and got_off.tolist() == want_off.tolist()


@pytest.mark.parametrize("op", ["pentagonalize", "preserve_pentagons", "dual", "dual of dual"])
@pytest.mark.parametrize("name", list(WRITTEN))
def test_open_outputs_connectivity_is_written_as_pairing_finds_it(name, op, monkeypatch):
    from pentanb.mesh import boundary, core

    m = WRITTEN[name]()
    m.vertex_ring  # noqa: B018 - the input's connectivity, paired before pairing is refused
    if op == "dual of dual":
        m = pb.dual(m)
        m.vertex_ring  # noqa: B018
        op = "dual"
    out = pb.dual(m) if op == "dual" else pb.SCHEMES[op](m)
    made = Mesh(out.vertices, face_lists(out))  # validated, paired from its faces

    def refused(*args):
        raise AssertionError("an operator's open output was paired by sorting")

    monkeypatch.setattr(core, "open_twins", refused)
    monkeypatch.setattr(boundary, "pair_open", refused)
    assert out.boundary_halfedges.tolist() == made.boundary_halfedges.tolist()
    assert _loops(out) == _loops(made)
    assert out.twin.tolist() == made.twin.tolist()
    assert out.twin.dtype == made.twin.dtype
    ring, off = out.vertex_ring  # written with the twins
    want, want_off = made.vertex_ring
    assert ring.tolist() == want.tolist() and off.tolist() == want_off.tolist()
    assert ring.dtype == want.dtype and off.dtype == want_off.dtype
    assert not out.is_closed and out.n_edges == made.n_edges


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
def test_an_open_output_keeps_none_of_its_inputs_connectivity_once_it_has_its_rings(scheme):
    # (its twins, asked for later, are still written from the input's)
    m = WRITTEN["holed grid"]()
    rotation = weakref.ref(m.rotation)  # derived and cached on m
    out = pb.SCHEMES[scheme](m)
    out.vertex_ring  # noqa: B018 - written from m's rings
    del m
    gc.collect()
    assert rotation() is None
    assert out.twin.tolist() == Mesh(out.vertices, face_lists(out)).twin.tolist()


def _loops(m: Mesh) -> list[list[int]]:
    return [x.tolist() for x in m.boundary_loops]


def _cyclic(faces: list[list[int]]) -> list[list[int]]:
    """Every face turned to start at its smallest vertex (faces equal up to where they start)."""
    return [f[f.index(min(f)) :] + f[: f.index(min(f))] for f in faces]


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons", None])
@pytest.mark.parametrize("name", list(WRITTEN))
def test_the_dual_of_an_open_dual_is_the_one_built_from_its_faces(name, scheme):
    # the same mesh as the dual of a mesh not known as a dual, but for
    # where the faces of the first mesh start: they are kept as they are
    m = WRITTEN[name]()
    if scheme is not None:
        m = pb.SCHEMES[scheme](m)
    d1 = pb.dual(m)
    fresh = Mesh(d1.vertices, face_lists(d1))  # the same mesh, not known as a dual
    two, want2 = pb.dual(d1), pb.dual(fresh)
    assert face_lists(two)[: m.n_faces] == face_lists(m)
    assert np.array_equal(two.vertices, want2.vertices)
    # a third dual sums the corners of those faces from another start: the
    # same centroids but for rounding
    three, want3 = pb.smooth(d1, 3), pb.smooth(fresh, 3)
    assert np.allclose(three.vertices, want3.vertices, rtol=0, atol=1e-12)
    for got, want in ((two, want2), (three, want3)):
        assert _cyclic(face_lists(got)) == _cyclic(face_lists(want))
        made = Mesh(got.vertices, face_lists(got))  # validated, paired from its faces
        assert got.twin.tolist() == made.twin.tolist()
        assert _loops(got) == _loops(made)
        ring, want_ring = got.vertex_ring, made.vertex_ring
        assert ring[0].tolist() == want_ring[0].tolist()
        assert ring[1].tolist() == want_ring[1].tolist()


@pytest.mark.parametrize("blocks", [[(3, 200), (5, 100), (4, 70)], [(4, 1), (3, 2)] * 40])
def test_start_at_max_turns_every_row_to_its_largest_in_blocks_of_one_size_or_not(blocks):
    from pentanb import _jit
    from pentanb.schemes._build import start_at_max

    rng = np.random.default_rng(3)
    sizes = np.concatenate([np.full(count, k) for k, count in blocks])
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int32)
    ring = rng.permutation(int(offsets[-1])).astype(np.int32)
    want = []
    for a, b in itertools.pairwise(offsets.tolist()):
        row = ring[a:b].tolist()
        top = row.index(max(row))
        want.extend(row[top:] + row[:top])
    before = _jit.use_jit(False)
    try:
        got = start_at_max(ring, offsets)
    finally:
        _jit.use_jit(before)
    assert got.tolist() == want and got.dtype == ring.dtype


@pytest.mark.parametrize("dt", [np.int32, np.int64])
@pytest.mark.parametrize("k", [1, 2, 3, 4, 6, 7])
def test_start_at_max_turns_rows_of_one_size_with_ties_and_extreme_values(k, dt):
    # rows of up to 6 are turned by selects and sums that wrap around: the
    # first of equal largest entries must lead, whatever the values
    from pentanb import _jit
    from pentanb.schemes._build import start_at_max

    rng = np.random.default_rng(k)
    low, high = np.iinfo(dt).min, np.iinfo(dt).max
    rows = np.concatenate(
        [
            rng.integers(-1, 3, (200, k)),  # many ties
            rng.choice([low, high, -1, 0], (200, k)),
            rng.integers(low, high, (200, k), endpoint=True),
        ]
    ).astype(dt)
    want = []
    for row in rows.tolist():
        top = row.index(max(row))
        want.extend(row[top:] + row[:top])
    before = _jit.use_jit(False)
    try:
        got = start_at_max(rows.reshape(-1), None, k)
    finally:
        _jit.use_jit(before)
    assert got.tolist() == want and got.dtype == dt


@pytest.fixture(params=[False, True], ids=["numpy", "compiled"])
def path(request, monkeypatch):
    """The numpy path, then the compiled kernels (for meshes of any size)."""
    from pentanb import _jit

    if request.param and not _jit.available():
        pytest.skip("numba is not installed")
    monkeypatch.setattr(_jit, "MIN_CORNERS", 0)
    before = _jit.use_jit(request.param)
    yield request.param
    _jit.use_jit(before)


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
@pytest.mark.parametrize("name", ["holed grid", "open disk"])
def test_the_dual_of_an_open_schemes_dual_shares_its_faces_and_changes_none(name, scheme, path):
    # as the dual of a closed dual does: the scheme's output keeps room after
    # its faces for the boundary's faces its dual of a dual adds
    m = pb.SCHEMES[scheme](WRITTEN[name]())
    corners, offsets = m.corners.copy(), m.offsets.copy()
    two = pb.dual(pb.dual(m))
    assert np.shares_memory(two.corners, m.corners)
    assert np.shares_memory(two.offsets, m.offsets)
    assert np.array_equal(m.corners, corners) and np.array_equal(m.offsets, offsets)
    fresh = Mesh(m.vertices, face_lists(m))  # not an operator's output: no room, copied
    want = pb.dual(pb.dual(fresh))
    assert not np.shares_memory(want.corners, fresh.corners)
    assert face_lists(two) == face_lists(want)
    assert np.array_equal(two.vertices, want.vertices)
    assert two.corners.dtype == want.corners.dtype and not two.corners.flags.writeable


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
def test_a_second_dual_of_a_dual_copies_and_leaves_the_first_as_it_was(scheme):
    m = pb.SCHEMES[scheme](WRITTEN["holed grid"]())
    first = pb.dual(pb.dual(m))
    kept = first.corners.copy(), first.offsets.copy()
    # other positions (a corner of the boundary straightened, others made):
    # the same faces, so the same room, which the first has taken
    rng = np.random.default_rng(3)
    moved = m.with_vertices(m.vertices + rng.normal(0, 0.2, m.vertices.shape))
    second = pb.dual(pb.dual(moved))
    assert not np.shares_memory(second.corners, m.corners)
    assert np.array_equal(first.corners, kept[0]) and np.array_equal(first.offsets, kept[1])
    want = pb.dual(pb.dual(Mesh(moved.vertices, face_lists(moved))))
    assert face_lists(second) == face_lists(want)
    assert np.array_equal(second.vertices, want.vertices)


@pytest.mark.parametrize("places", [[], [0], [9], [0, 1, 2], [3, 7, 8], list(range(10))])
def test_a_running_sum_of_a_few_places_is_the_cumulative_sum(places):
    # the offsets of open outputs' faces and rings: np.cumsum, by np.repeat
    from pentanb.schemes._build import running_sum

    at = np.array(places, dtype=np.int64)
    add = np.arange(2, 2 + at.size, dtype=np.int64)
    dense = np.zeros(10, dtype=np.int64)
    dense[at] = add
    got = running_sum(at, add, 10, np.dtype(np.int32))
    assert got.dtype == np.int32 and got.tolist() == np.cumsum(dense).tolist()


@pytest.mark.parametrize("block", [1, 2, 7, 64])
@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons", None])
@pytest.mark.parametrize("name", ["holed grid", "open disk", "annulus"])
def test_the_open_duals_faces_are_the_same_whatever_the_blocks(name, scheme, block, monkeypatch):
    # the numpy path copies the ring's items around the boundary's insertions
    # block by block: blocks with and without insertions, of one place or more
    from pentanb.schemes import _build

    m = WRITTEN[name]()
    if scheme is not None:
        m = pb.SCHEMES[scheme](m)
    assert m.n_halfedges < pb._jit.MIN_CORNERS  # (the numpy path)
    want = pb.dual(m)  # (these meshes fit in one block)
    monkeypatch.setattr(_build, "OUT_BLOCK", block)
    got = pb.dual(Mesh(m.vertices, face_lists(m)))
    assert face_lists(got) == face_lists(want)
    assert np.array_equal(got.vertices, want.vertices)


def test_room_goes_to_one_taker_of_its_dtype_and_size():
    from pentanb.mesh.build import Room

    room = Room(np.zeros(10, dtype=np.int32), np.zeros(4, dtype=np.int32))
    assert room.take(11, 4, np.dtype(np.int32)) is None  # too short
    assert room.take(10, 5, np.dtype(np.int32)) is None
    assert room.take(10, 4, np.dtype(np.int64)) is None  # another dtype
    got = room.take(8, 3, np.dtype(np.int32))
    assert got is not None and got[0].size == 8 and got[1].size == 3
    assert room.take(8, 3, np.dtype(np.int32)) is None  # taken


@pytest.mark.parametrize("scheme", ["pentagonalize", "preserve_pentagons"])
@pytest.mark.parametrize("first", ["vertex_ring", "twin", "boundary_halfedges", "n_edges"])
@pytest.mark.parametrize("name", list(WRITTEN))
def test_open_outputs_connectivity_is_the_same_whichever_is_asked_for_first(name, scheme, first):
    # the rings, twins and boundary are written apart: each must be what
    # pairing the output's faces finds, whatever was asked for before it
    out = pb.SCHEMES[scheme](WRITTEN[name]())
    getattr(out, first)
    made = Mesh(out.vertices, face_lists(out))
    ring, off = out.vertex_ring
    want, want_off = made.vertex_ring
    assert ring.tolist() == want.tolist() and off.tolist() == want_off.tolist()
    assert ring.dtype == want.dtype and off.dtype == want_off.dtype
    assert out.twin.tolist() == made.twin.tolist() and out.twin.dtype == made.twin.dtype
    assert out.boundary_halfedges.tolist() == made.boundary_halfedges.tolist()
    assert _loops(out) == _loops(made)


def _arrays(m: Mesh) -> tuple[np.ndarray, list[list[int]]]:
    return m.vertices, face_lists(m)
