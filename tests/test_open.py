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

import pickle

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
