"""Test helpers: the mesh corpus and independent checks.

Everything here is written in plain Python (dicts, loops) on purpose: it
must not share code with the half-edge machinery it checks.  The helpers
have their own tests in ``tests/test_helpers.py``.
"""

from __future__ import annotations

import functools
import inspect
from collections import Counter
from collections.abc import Callable

import numpy as np

import pentanb
from pentanb import Mesh, shapes

# ---------------------------------------------------------------------- the corpus


def cube_split() -> Mesh:
    """The cube [-1, 1]^3 with one face split into a triangle and a pentagon.

    Face x = 1 is ``[4, 6, 7, 5]`` (vertex ``4x + 2y + z``, counter-clockwise
    from +x).  Points a = midpoint of 4-6 and b = midpoint of 6-7 are added
    and joined: triangle ``(a, 6, b)`` and pentagon ``(b, 7, 5, 4, a)``; the
    faces across 4-6 and 6-7 become pentagons.  V = 10, E = 15, F = 7:
    one triangle, three quads, three pentagons, every vertex 3-valent.
    """
    c = shapes.cube()
    v = np.concatenate(
        [c.vertices, [(c.vertices[4] + c.vertices[6]) / 2, (c.vertices[6] + c.vertices[7]) / 2]]
    )
    a, b = 8, 9
    faces = []
    for f in c.faces:
        f = f.tolist()
        if sorted(f) == [4, 5, 6, 7]:
            faces += [[a, 6, b], [b, 7, 5, 4, a]]
            continue
        out = []
        for i, x in enumerate(f):
            out.append(x)
            y = f[(i + 1) % len(f)]
            if {x, y} == {4, 6}:
                out.append(a)
            if {x, y} == {6, 7}:
                out.append(b)
        faces.append(out)
    return Mesh(v, faces)


def holed_grid(
    nx: int, ny: int, holes: list[tuple[int, ...]], size: int = 2
) -> tuple[np.ndarray, np.ndarray]:
    """An nx x ny grid of unit quads in the plane z = 0 without a block of quads at
    every hole ``(x0, y0)`` (``size`` x ``size``) or ``(x0, y0, s)`` (s x s);
    the vertices no face uses left out.  Returns ``(vertices, quads)``."""
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    v = np.stack([xs.ravel(), ys.ravel(), 0 * xs.ravel()], 1)
    keep = np.ones((nx, ny), dtype=bool)
    for x0, y0, s in ((*hole, size)[:3] for hole in holes):
        keep[x0 : x0 + s, y0 : y0 + s] = False
    i, j = np.nonzero(keep)
    a = i * (ny + 1) + j
    quads = np.stack([a, a + ny + 1, a + ny + 2, a + 1], 1)
    used, f = np.unique(quads, return_inverse=True)
    return v[used], f.reshape(-1, 4)


def prism(n: int) -> Mesh:
    """A prism over a regular n-gon: two n-gons and n quads; V = 2n, E = 3n, F = n + 2."""
    t = 2 * np.pi * np.arange(n) / n
    ring = np.stack([np.cos(t), np.sin(t), np.zeros(n)], axis=1)
    v = np.concatenate([ring + [0, 0, -1], ring + [0, 0, 1]])
    faces = [list(range(n))[::-1], list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return Mesh(v, faces)


def pyramid(n: int) -> Mesh:
    """A pyramid over a regular n-gon: one n-gon, n triangles, an n-valent apex."""
    t = 2 * np.pi * np.arange(n) / n
    v = np.concatenate([np.stack([np.cos(t), np.sin(t), np.zeros(n)], axis=1), [[0.0, 0.0, 1.0]]])
    faces = [list(range(n))[::-1]] + [[i, (i + 1) % n, n] for i in range(n)]
    return Mesh(v, faces)


def merged_icosahedron() -> Mesh:
    """An icosahedron with a few faces merged: triangles, a quad, a pentagon, a hexagon."""
    ico = shapes.icosahedron()
    return merge_faces(ico, [3, 4, 5, 6, 7, 8, 9])


def faces_sharing_two_edges() -> tuple[np.ndarray, list[list[int]]]:
    """A 3 x 3 quad torus with two neighbouring quads merged into a hexagon.

    Quad 0, ``[2, 5, 3, 0]``, then meets the hexagon (face 7) along
    ``(2, 5)`` and along ``(0, 3)``: faces sharing two edges, which the
    constructor refuses.  Returns the vertices and the face lists.
    """
    faces = [
        [2, 5, 3, 0],
        [3, 6, 7, 4],
        [4, 7, 8, 5],
        [5, 8, 6, 3],
        [6, 0, 1, 7],
        [7, 1, 2, 8],
        [8, 2, 0, 6],
        [1, 0, 3, 4, 5, 2],
    ]
    return shapes.torus(3, 3).vertices, faces


def two_cubes() -> Mesh:
    """Two disjoint cubes (two components, genus 0 each)."""
    c = shapes.cube()
    v = np.concatenate([c.vertices, c.vertices + [5.0, 0.0, 0.0]])
    return Mesh(v, [f.tolist() for f in c.faces] + [(f + 8).tolist() for f in c.faces])


#: Every corpus mesh by name: all of shapes.SHAPES plus mixed-face meshes.
EXTRA: dict[str, Callable[[], Mesh]] = {
    "cube_split": cube_split,
    "hexagonal_prism": lambda: prism(6),
    "pentagonal_pyramid": lambda: pyramid(5),
    "small_torus": lambda: shapes.torus(3, 5),
    "merged_icosahedron": merged_icosahedron,
}
BUILDERS: dict[str, Callable[[], Mesh]] = {**shapes.SHAPES, **EXTRA}
CORPUS_NAMES = list(BUILDERS)
#: Small corpus meshes for the slower (pure-Python) checks.
SMALL_NAMES = [
    "tetrahedron",
    "cube",
    "octahedron",
    "dodecahedron",
    "icosahedron",
    "cube_split",
    "hexagonal_prism",
    "pentagonal_pyramid",
    "small_torus",
    "merged_icosahedron",
]


@functools.cache
def corpus(name: str) -> Mesh:
    """Build (once: meshes are immutable) the corpus mesh called ``name``."""
    return BUILDERS[name]()


# ---------------------------------------------------------------------- operators
#: Every operator under test: the registry's schemes and the dual.
OPERATORS: dict[str, Callable[[Mesh], Mesh]] = {
    **{name: s.func for name, s in pentanb.SCHEMES.items()},
    "dual": pentanb.dual,
}


def expected_counts(name: str, m: Mesh) -> tuple[int, int, int]:
    """(V, E, F) after operator ``name``, from the paper and the docstrings."""
    V, E, F = m.n_vertices, m.n_edges, m.n_faces
    sizes = face_sizes(m)
    if name == "pentagonalize":
        return V + 2 * E + F, 5 * E, 2 * E
    if name == "preserve_pentagons":
        return V + 3 * E, 6 * E, F + 2 * E
    if name == "loop_remesh":
        return V + E, 4 * E, F + 2 * E
    if name == "sqrt3_remesh":
        return V + F, 3 * E, 2 * E
    if name == "vertex_insertion":
        return V + E + F, 4 * E, 2 * E
    if name == "corner_cutting":
        return 2 * E, 4 * E, V + E + F
    if name == "preserve_hexagons":
        return V + 2 * E, 4 * E, F + E
    if name == "honeycomb":
        return 2 * E, 3 * E, F + V
    if name == "dual":
        return F, E, V
    if name == "triangulate":
        # F' non-triangles with s' sides in all: a centre each, s' new edges,
        # each non-triangle replaced by its s sides' triangles
        big = [s for s in sizes if s > 3]
        return V + len(big), E + sum(big), F - len(big) + sum(big)
    raise KeyError(name)


def expected_face_histogram(name: str, m: Mesh) -> dict[int, int]:
    """Face-size histogram after operator ``name`` (from the schemes' descriptions)."""
    sizes = face_sizes(m)
    vals = valences(m)
    E = m.n_edges
    hist: Counter = Counter()
    if name == "pentagonalize":
        hist[5] += 2 * E  # every n-gon -> n pentagons
    elif name == "preserve_pentagons":
        hist.update(sizes)  # inner n-gon per n-gon
        hist[5] += 2 * E  # + n pentagons
    elif name == "loop_remesh":
        hist.update(sizes)  # central n-gon
        hist[3] += 2 * E  # + a triangle per corner
    elif name in ("sqrt3_remesh",):
        hist[3] += 2 * E
    elif name == "vertex_insertion":
        hist[4] += 2 * E
    elif name == "corner_cutting":
        hist.update(sizes)  # face copies
        hist[4] += E  # a quad per edge
        hist.update(vals)  # a k-gon per k-valent vertex
    elif name == "preserve_hexagons":
        hist.update(sizes)  # face copies
        hist[6] += E  # a hexagon per edge
    elif name == "honeycomb":
        hist.update(sizes)  # an n-gon per n-gon
        hist.update(2 * k for k in vals)  # a 2k-gon per k-valent vertex
    elif name == "dual":
        hist.update(vals)  # a k-gon per k-valent vertex
    elif name == "triangulate":
        hist[3] += sum(1 for s in sizes if s == 3) + sum(s for s in sizes if s > 3)
    else:
        raise KeyError(name)
    return {k: c for k, c in sorted(hist.items()) if c}


# ---------------------------------------------------------------------- plain-Python views
def face_lists(m: Mesh) -> list[list[int]]:
    """The faces as lists of ints, read from ``corners``/``offsets``."""
    c, o = m.corners.tolist(), m.offsets.tolist()
    return [c[o[i] : o[i + 1]] for i in range(len(o) - 1)]


def face_sizes(m: Mesh) -> list[int]:
    return [len(f) for f in face_lists(m)]


def valences(m: Mesh) -> list[int]:
    """Valence of every vertex = number of corners it appears in (closed mesh)."""
    count = Counter(v for f in face_lists(m) for v in f)
    return [count[v] for v in range(len(m.vertices))]


def histogram(values) -> dict[int, int]:
    return dict(sorted(Counter(int(x) for x in values).items()))


def darts(faces: list[list[int]]) -> tuple[list[int], list[int], list[int], list[int]]:
    """Half-edges numbered corner by corner: (tail, head, next, twin), by dicts."""
    tail, head, nxt = [], [], []
    for f in faces:
        base = len(tail)
        k = len(f)
        for i in range(k):
            tail.append(f[i])
            head.append(f[(i + 1) % k])
            nxt.append(base + (i + 1) % k)
    where = {(u, w): h for h, (u, w) in enumerate(zip(tail, head))}
    assert len(where) == len(tail), "a directed edge is used twice"
    twin = [where[(w, u)] for u, w in zip(tail, head)]
    return tail, head, nxt, twin


# ---------------------------------------------------------------------- checks
def check_valid(out: Mesh) -> None:
    """Assert that an operator's output is a valid mesh whose derived arrays are right.

    The constructor re-validates the faces; the arrays an operator may hand
    over with its output (``twin``, the vertex rings, ...) are compared with
    the rebuilt mesh's, and ``twin`` with a dictionary of directed edges
    built here.
    """
    assert isinstance(out, Mesh)
    assert out.vertices.shape == (out.n_vertices, 3)
    assert np.isfinite(out.vertices).all()
    assert out.offsets[0] == 0 and out.offsets[-1] == out.corners.size
    check_sealed(out)
    rebuilt = Mesh(out.vertices, face_lists(out))  # raises MeshError when invalid
    _, _, _, twin = darts(face_lists(out))
    assert out.twin.tolist() == twin
    for name in (
        "twin",
        "next",
        "prev",
        "head",
        "rotation",
        "halfedge_face",
        "halfedge_edge",
        "edge_halfedge",
        "edges",
        "valences",
        "face_sizes",
        "component_labels",
    ):
        assert np.array_equal(getattr(out, name), getattr(rebuilt, name)), name
    assert np.allclose(out.face_centroids, rebuilt.face_centroids, rtol=0, atol=1e-12)
    ring, off = out.vertex_ring
    ring2, off2 = rebuilt.vertex_ring
    assert np.array_equal(off, off2)
    for v in range(out.n_vertices):
        assert same_faces_up_to_rotation(
            [ring[off[v] : off[v + 1]].tolist()], [ring2[off[v] : off[v + 1]].tolist()]
        ), v


def handed_out_arrays(m: Mesh) -> dict[str, np.ndarray]:
    """Every array a mesh hands out, by where it came from.

    Found by introspection, so that a property or method added later is
    covered too: every public attribute, and the result of every public
    method that needs no argument, searched through tuples, lists and dicts.
    """
    found: dict[str, np.ndarray] = {}

    def collect(label, value):
        if isinstance(value, np.ndarray):
            found[label] = value
        elif isinstance(value, (tuple, list)):
            for i, x in enumerate(value):
                collect(f"{label}[{i}]", x)
        elif isinstance(value, dict):
            for k, x in value.items():
                collect(f"{label}[{k!r}]", x)

    for name in dir(m):
        if name.startswith("_"):
            continue
        value = getattr(m, name)
        if inspect.ismethod(value):
            params = inspect.signature(value).parameters.values()
            if any(
                p.default is p.empty and p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
                for p in params
            ):
                continue  # needs an argument (from_csr, with_vertices, face_means)
            try:
                value = value()
            except ImportError:
                continue  # a conversion whose optional package is absent (to_trimesh)
            name += "()"
        collect(name, value)
    return found


def check_sealed(m: Mesh) -> None:
    """Assert that nothing about ``m`` can be changed from outside.

    Setting or deleting any attribute (its own, or a new one) raises
    AttributeError saying that meshes are immutable, and leaves the mesh
    as it was; every array it hands out is read-only.
    """
    before = {k: a.copy() for k, a in handed_out_arrays(m).items()}
    names = [n for n in dir(m) if not (n.startswith("__") and n.endswith("__"))] + ["foo"]
    for name in names:
        for attempt, args in ((setattr, (m, name, None)), (delattr, (m, name))):
            try:
                attempt(*args)
            except AttributeError as exc:
                assert "immutable" in str(exc), (name, str(exc))
            else:
                raise AssertionError(f"attribute {name!r} of a Mesh could be set or deleted")
    after = handed_out_arrays(m)
    assert sorted(after) == sorted(before)
    writable = [k for k, a in after.items() if a.flags.writeable]
    assert not writable, f"writable arrays handed out: {writable}"
    for k, a in after.items():
        assert np.array_equal(a, before[k]), k


def same_mesh(a: Mesh, b: Mesh) -> None:
    """Assert that two meshes are equal: positions bitwise, faces, twins and vertex rings."""
    assert a.vertices.tobytes() == b.vertices.tobytes() and a.vertices.shape == b.vertices.shape
    assert np.array_equal(a.corners, b.corners) and np.array_equal(a.offsets, b.offsets)
    assert np.array_equal(a.twin, b.twin)
    for x, y in zip(a.vertex_ring, b.vertex_ring):
        assert np.array_equal(x, y)


def same_faces_up_to_rotation(a: list[list[int]], b: list[list[int]]) -> bool:
    """Same faces in the same order, each possibly starting at another corner."""
    if len(a) != len(b):
        return False
    for fa, fb in zip(a, b):
        if len(fa) != len(fb) or fa[0] not in fb:
            return False
        k = fb.index(fa[0])
        if fb[k:] + fb[:k] != fa:
            return False
    return True


def n_components(faces: list[list[int]]) -> int:
    """Connected components by union-find over the faces' vertices."""
    parent: dict[int, int] = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for f in faces:
        for x in f[1:]:
            parent[find(x)] = find(f[0])
    return len({find(x) for f in faces for x in f})


def is_isomorphic(a: Mesh, b: Mesh, *, reflect: bool = False) -> bool:
    """Whether two connected meshes are the same oriented map (combinatorially).

    An isomorphism of oriented maps sends half-edges to half-edges and
    commutes with ``next`` and ``twin``; on a connected mesh it is fixed
    by the image of one half-edge, so every candidate image of half-edge 0
    is tried and the map propagated.  With ``reflect=True`` the faces of
    ``b`` are reversed first (an orientation-reversing isomorphism).
    """
    fa, fb = face_lists(a), face_lists(b)
    if reflect:
        fb = [f[::-1] for f in fb]
    assert n_components(fa) == 1 and n_components(fb) == 1, "connected meshes only"
    if (len(fa), sum(map(len, fa)), a.n_vertices) != (len(fb), sum(map(len, fb)), b.n_vertices):
        return False
    ta, _, na, wa = darts(fa)
    tb, _, nb, wb = darts(fb)
    size_a = [len(f) for f in fa for _ in f]
    size_b = [len(f) for f in fb for _ in f]
    val_a, val_b = Counter(ta), Counter(tb)
    sig = lambda size, val, t, h: (size[h], val[t[h]])  # noqa: E731
    want = sig(size_a, val_a, ta, 0)
    H = len(ta)
    for start in range(H):
        if sig(size_b, val_b, tb, start) != want:
            continue
        phi = [-1] * H
        used = [False] * H
        phi[0], used[start] = start, True
        stack = [0]
        ok = True
        while stack and ok:
            h = stack.pop()
            for ga, gb in ((na, nb), (wa, wb)):
                x, y = ga[h], gb[phi[h]]
                if phi[x] == -1:
                    if used[y]:
                        ok = False
                        break
                    phi[x], used[y] = y, True
                    stack.append(x)
                elif phi[x] != y:
                    ok = False
                    break
        if ok:
            return True
    return False


def kis(m: Mesh) -> Mesh:
    """Conway's kis: a centroid fan in every face (triangles included)."""
    faces = face_lists(m)
    n = m.n_vertices
    tris = [[f[i], f[(i + 1) % len(f)], n + k] for k, f in enumerate(faces) for i in range(len(f))]
    cent = np.array([m.vertices[f].mean(axis=0) for f in faces])
    return Mesh(np.concatenate([m.vertices, cent]), tris)


def reflect(m: Mesh) -> Mesh:
    """The mirror image through the plane x = 0, faces reversed to stay outward."""
    v = m.vertices * [-1.0, 1.0, 1.0]
    return Mesh(v, [f[::-1] for f in face_lists(m)])


def polyhedral(faces: list[list[int]], n_vertices: int) -> bool:
    """Every vertex at least 3-valent and no two faces sharing two edges.

    Those are what the dual needs to be a mesh again (no 2-gons, no double
    edges); the shapes of the corpus all satisfy them.
    """
    val = Counter(v for f in faces for v in f)
    if len(val) != n_vertices or min(val.values()) < 3:
        return False
    if any(len(set(f)) != len(f) for f in faces):
        return False
    edge_faces: dict[tuple[int, int], list[int]] = {}
    for k, f in enumerate(faces):
        for i in range(len(f)):
            u, w = f[i], f[(i + 1) % len(f)]
            edge_faces.setdefault((min(u, w), max(u, w)), []).append(k)
    pairs = Counter(tuple(sorted(fs)) for fs in edge_faces.values())
    return all(len(fs) == 2 for fs in edge_faces.values()) and max(pairs.values()) == 1


def merge_faces(m: Mesh, picks) -> Mesh:
    """Merge pairs of adjacent faces across edges, keeping the mesh polyhedral.

    For every ``p`` in ``picks`` the edge ``p mod E`` (in sorted order of the
    current mesh's edges) is removed, joining its two faces, unless the
    result would have a repeated vertex in a face, a vertex of valence < 3
    or two faces sharing two edges; such picks are skipped.
    """
    faces = face_lists(m)
    for p in picks:
        where = {}
        for k, f in enumerate(faces):
            for i in range(len(f)):
                where[(f[i], f[(i + 1) % len(f)])] = k
        edges = sorted((u, w) for (u, w) in where if u < w)
        u, w = edges[p % len(edges)]
        f, g = where[(u, w)], where[(w, u)]
        F, G = faces[f], faces[g]
        i, j = F.index(w), G.index(u)
        Fr, Gr = F[i:] + F[:i], G[j:] + G[:j]  # w ... u  and  u ... w
        merged = Fr + Gr[1:-1]
        trial = [x for k, x in enumerate(faces) if k not in (f, g)] + [merged]
        if polyhedral(trial, m.n_vertices):
            faces = trial
    return Mesh(m.vertices, faces)


def vertex_configurations(m: Mesh) -> list[tuple[int, ...]]:
    """For every vertex, the sizes of its faces in counter-clockwise order.

    Computed from dictionaries of directed edges: around vertex v, the face
    after the one holding half-edge ``(v, w)`` holds ``(v, u)`` where ``u``
    precedes ``v`` in that face.
    """
    faces = face_lists(m)
    out_edge = {}
    for k, f in enumerate(faces):
        for i in range(len(f)):
            out_edge[(f[i], f[(i + 1) % len(f)])] = (k, f[i - 1])
    first = {}
    for v, w in out_edge:
        first.setdefault(v, w)
    configs = []
    for v in range(m.n_vertices):
        w = first[v]
        seq = []
        while True:
            k, u = out_edge[(v, w)]
            seq.append(len(faces[k]))
            # next outgoing half-edge round v: the twin of (u, v), i.e. (v, u)
            w = u
            if w == first[v]:
                break
        configs.append(tuple(seq))
    return configs


def cyclic_equal(seq, pattern) -> bool:
    """``seq`` is a rotation of ``pattern`` or of its reverse."""
    seq, pattern = tuple(seq), tuple(pattern)
    if len(seq) != len(pattern):
        return False
    rots = lambda p: {p[i:] + p[:i] for i in range(len(p))}  # noqa: E731
    return seq in rots(pattern) | rots(pattern[::-1])
