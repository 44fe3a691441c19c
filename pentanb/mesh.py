"""The polygon mesh: faces in CSR form, half-edges derived with numpy.

A face is a cyclic sequence of vertex indices.  All faces are stored in one
flat array of *corners* (``corners``) cut by ``offsets``: face ``f`` is
``corners[offsets[f]:offsets[f + 1]]``.  Triangles, pentagons and mixed faces
share this one structure.

A *half-edge* is a corner: half-edge ``h`` runs from ``corners[h]`` to the
next corner of its face.  Everything else (``next``, ``prev``, ``twin``, edge
ids, the rotation around a vertex) is derived from ``corners`` and
``offsets`` with whole-array numpy expressions and cached; the mesh is
immutable, so nothing needs invalidating.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Mesh", "MeshError"]

IntArray = NDArray[np.int64]
FloatArray = NDArray[np.float64]


class MeshError(ValueError):
    """A mesh is not a closed, consistently oriented 2-manifold polygon mesh,
    a file does not hold one, or an operation would be too large.

    The message names the offending face, edge, vertex, file line or size.
    """


def _readonly(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


class Mesh:
    """A closed, oriented 2-manifold polygon mesh (immutable).

    Parameters
    ----------
    vertices : (n, 3) float array_like
        Vertex positions.
    faces : (m,) sequence of int sequences, or (m, k) int array_like
        Vertex indices of each face, counter-clockwise seen from outside.
        Faces may have any number (>= 3) of sides.

    Raises
    ------
    MeshError
        When the input is not a closed, consistently oriented 2-manifold
        polygon mesh: an index out of range, a face with repeated or fewer
        than 3 vertices, a directed edge used twice, a boundary edge, a
        vertex whose faces form more than one fan, an unused vertex or a
        non-finite coordinate.  Also refused, because the dual (the paper's
        smoothing) cannot be built from them: a vertex with fewer than 3
        edges, and two faces that share more than one edge.  The message
        names the culprit.

    Notes
    -----
    Operators (:func:`pentanb.dual`, :func:`pentanb.pentagonalize`, ...)
    build their outputs valid by construction through :meth:`from_csr` with
    ``validate=False`` and often hand over the twin array they already know.

    Examples
    --------
    >>> import pentanb
    >>> m = pentanb.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                  [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
    >>> m.n_vertices, m.n_edges, m.n_faces, m.genus
    (4, 6, 4, 0)
    """

    __slots__ = ("_vertices", "_corners", "_offsets", "__dict__")

    def __init__(self, vertices: ArrayLike, faces: ArrayLike | Sequence[Sequence[int]]):
        v = _as_vertices(vertices)
        corners, offsets = _as_csr(faces)
        self._init(v, corners, offsets)
        self._validate()

    # ------------------------------------------------------------------ construction
    def _init(self, vertices, corners, offsets, twin=None):
        self._vertices = _readonly(vertices)
        self._corners = _readonly(corners)
        self._offsets = _readonly(offsets)
        if twin is not None:
            self.__dict__["twin"] = _readonly(twin)

    @classmethod
    def from_csr(
        cls,
        vertices: ArrayLike,
        corners: ArrayLike,
        offsets: ArrayLike,
        *,
        twin: ArrayLike | None = None,
        validate: bool = True,
    ) -> Mesh:
        """Build a mesh from CSR face arrays.

        Parameters
        ----------
        vertices : (n, 3) float
        corners : (H,) int
            Vertex index of every corner, face after face.
        offsets : (m + 1,) int
            Face ``f`` is ``corners[offsets[f]:offsets[f + 1]]``; ``offsets[0] == 0``.
        twin : (H,) int, optional
            The opposite half-edge of each half-edge, when the caller knows it.
        validate : bool
            Check the mesh (as the constructor does), on copies of the
            arrays.  Operators pass False: their outputs are valid by
            construction.  Without validation the arrays are used as they are
            (read-only views, no copy): changing them afterwards changes the
            mesh.
        """
        self = object.__new__(cls)
        if validate:
            v = _as_vertices(vertices)
            c = np.array(corners, dtype=np.int64).ravel()  # copies: the caller's
            o = np.array(offsets, dtype=np.int64).ravel()  # arrays stay theirs
            if o.size == 0 or o[0] != 0 or o[-1] != c.size or np.any(np.diff(o) < 0):
                raise MeshError("offsets must start at 0, rise, and end at len(corners)")
            self._init(v, c, o)
            self._validate()
        else:
            # read-only views: no copy, and the caller's own arrays keep their flags
            self._init(
                np.asarray(vertices, dtype=np.float64).view(),
                np.asarray(corners, dtype=np.int64).view(),
                np.asarray(offsets, dtype=np.int64).view(),
                None if twin is None else np.asarray(twin, dtype=np.int64).view(),
            )
        return self

    def with_vertices(self, vertices: ArrayLike) -> Mesh:
        """The same connectivity with other vertex positions (``(n, 3)`` float)."""
        v = _as_vertices(vertices)
        if v.shape != self._vertices.shape:
            raise MeshError(f"expected {self._vertices.shape} vertices, got {v.shape}")
        return self._connectivity()._placed(v)

    def _connectivity(self) -> Mesh:
        """A vertex-less shell sharing this mesh's faces and cached connectivity."""
        shell = object.__new__(Mesh)
        shell._vertices = None
        shell._corners = self._corners
        shell._offsets = self._offsets
        for key in _CONNECTIVITY_CACHE[:-1]:  # not _dual_source: no chains
            if key in self.__dict__:
                shell.__dict__[key] = self.__dict__[key]
        return shell

    def _placed(self, vertices: np.ndarray) -> Mesh:
        """This mesh's connectivity (and its caches) with the given positions."""
        out = object.__new__(Mesh)
        out._init(vertices, self._corners, self._offsets)
        for key in _CONNECTIVITY_CACHE:
            if key in self.__dict__:
                out.__dict__[key] = self.__dict__[key]
        return out

    # ------------------------------------------------------------------ raw arrays
    @property
    def vertices(self) -> FloatArray:
        """(n, 3) float: vertex positions (read-only)."""
        return self._vertices

    @property
    def corners(self) -> IntArray:
        """(H,) int: the vertex of every corner, face after face (read-only)."""
        return self._corners

    @property
    def offsets(self) -> IntArray:
        """(m + 1,) int: face ``f`` is ``corners[offsets[f]:offsets[f+1]]``."""
        return self._offsets

    @cached_property
    def faces(self) -> list[IntArray]:
        """(m,) list of int arrays: the vertex indices of every face."""
        return np.split(self._corners, self._offsets[1:-1])

    # ------------------------------------------------------------------ counts
    @property
    def n_vertices(self) -> int:
        """Number of vertices V."""
        return int(self._vertices.shape[0])

    @property
    def n_faces(self) -> int:
        """Number of faces F."""
        return int(self._offsets.size - 1)

    @property
    def n_halfedges(self) -> int:
        """Number of half-edges (= corners) H = 2E."""
        return int(self._corners.size)

    @property
    def n_edges(self) -> int:
        """Number of edges E (= H / 2 on a closed mesh)."""
        return int(self._corners.size // 2)

    @cached_property
    def face_sizes(self) -> IntArray:
        """(m,) int: number of sides of every face."""
        return _readonly(np.diff(self._offsets))

    @cached_property
    def valences(self) -> IntArray:
        """(n,) int: number of edges at every vertex."""
        return _readonly(np.bincount(self._corners, minlength=self.n_vertices))

    @property
    def euler_characteristic(self) -> int:
        """V - E + F."""
        return self.n_vertices - self.n_edges + self.n_faces

    @cached_property
    def n_components(self) -> int:
        """Number of connected components."""
        return int(np.unique(self.component_labels).size)

    @property
    def genus(self) -> int:
        """Total genus: ``(2 * components - (V - E + F)) / 2``.

        For a connected mesh this is the usual g of ``V - E + F = 2 - 2g``.
        """
        return (2 * self.n_components - self.euler_characteristic) // 2

    def face_size_histogram(self) -> dict[int, int]:
        """``{n: number of n-gons}``, sorted by n."""
        sizes, counts = np.unique(self.face_sizes, return_counts=True)
        return {int(s): int(c) for s, c in zip(sizes, counts)}

    def valence_histogram(self) -> dict[int, int]:
        """``{k: number of k-valent vertices}``, sorted by k."""
        vals, counts = np.unique(self.valences, return_counts=True)
        return {int(s): int(c) for s, c in zip(vals, counts)}

    def counts(self) -> dict:
        """V, E, F, the face-size and valence histograms, chi and genus."""
        return {
            "V": self.n_vertices,
            "E": self.n_edges,
            "F": self.n_faces,
            "faces": self.face_size_histogram(),
            "valences": self.valence_histogram(),
            "chi": self.euler_characteristic,
            "genus": self.genus,
        }

    def __repr__(self) -> str:
        hist = ", ".join(f"{n}:{c}" for n, c in self.face_size_histogram().items())
        return f"Mesh(V={self.n_vertices}, E={self.n_edges}, F={self.n_faces}, faces={{{hist}}})"

    # ------------------------------------------------------------------ half-edges
    @cached_property
    def halfedge_face(self) -> IntArray:
        """(H,) int: the face of every half-edge."""
        return _readonly(np.repeat(np.arange(self.n_faces, dtype=np.int64), self.face_sizes))

    @cached_property
    def next(self) -> IntArray:
        """(H,) int: the next half-edge around the same face."""
        nxt = np.arange(1, self.n_halfedges + 1, dtype=np.int64)
        nxt[self._offsets[1:] - 1] = self._offsets[:-1]
        return _readonly(nxt)

    @cached_property
    def prev(self) -> IntArray:
        """(H,) int: the previous half-edge around the same face."""
        prv = np.arange(-1, self.n_halfedges - 1, dtype=np.int64)
        prv[self._offsets[:-1]] = self._offsets[1:] - 1
        return _readonly(prv)

    @property
    def tail(self) -> IntArray:
        """(H,) int: the vertex a half-edge leaves (= ``corners``)."""
        return self._corners

    @cached_property
    def head(self) -> IntArray:
        """(H,) int: the vertex a half-edge reaches."""
        return _readonly(self._corners[self.next])

    @cached_property
    def twin(self) -> IntArray:
        """(H,) int: the opposite half-edge (same edge, other face)."""
        maker = self.__dict__.pop("_twin_maker", None)
        if maker is not None:  # an operator that knows the twins, computed on demand
            return _readonly(maker())
        twin, _ = _match_twins(self._corners, self.head, self.n_vertices)
        return _readonly(twin)

    @cached_property
    def halfedge_edge(self) -> IntArray:
        """(H,) int: the edge id of every half-edge.

        Edge ``e`` is numbered by the order of its half-edge with
        ``tail < head``; see :attr:`edges`.
        """
        primary = self._corners < self.head
        ids = np.cumsum(primary) - 1
        return _readonly(np.where(primary, ids, ids[self.twin]))

    @cached_property
    def edge_halfedge(self) -> IntArray:
        """(E,) int: for every edge, its half-edge with ``tail < head``."""
        return _readonly(np.flatnonzero(self._corners < self.head))

    @cached_property
    def edges(self) -> IntArray:
        """(E, 2) int: the edges as (smaller, larger) vertex pairs."""
        h = self.edge_halfedge
        return _readonly(np.stack([self._corners[h], self.head[h]], axis=1))

    @cached_property
    def rotation(self) -> IntArray:
        """(H,) int: the next outgoing half-edge counter-clockwise around its tail.

        ``rotation[h] = twin[prev[h]]``.
        """
        return _readonly(self.twin[self.prev])

    @cached_property
    def _rings(self) -> tuple[IntArray, IntArray]:
        maker = self.__dict__.pop("_rings_maker", None)
        if maker is not None:  # an operator that knows the rings, computed on demand
            ring, off = maker()
        else:
            ring, off = _vertex_rings(self.rotation, self._corners, self.valences)
        return _readonly(ring), _readonly(off)

    def _set_rings(self, ring: np.ndarray, ring_offsets: np.ndarray) -> None:
        """Cache vertex rings an operator wrote directly (see :attr:`vertex_ring`)."""
        self.__dict__["_rings"] = (_readonly(ring), _readonly(ring_offsets))

    @property
    def vertex_ring(self) -> tuple[IntArray, IntArray]:
        """The outgoing half-edges of every vertex, counter-clockwise, in CSR form.

        Returns
        -------
        ring : (H,) int
            Half-edges, vertex after vertex, each vertex's in rotation order.
        ring_offsets : (n + 1,) int
            Vertex ``v``'s half-edges are ``ring[ring_offsets[v]:ring_offsets[v+1]]``.
        """
        return self._rings

    # ------------------------------------------------------------------ geometry
    @cached_property
    def face_centroids(self) -> FloatArray:
        """(m, 3) float: the plain mean of each face's vertices."""
        return _readonly(self.face_means(self._vertices))

    def face_means(self, values: ArrayLike) -> np.ndarray:
        """Average per-vertex values over every face.

        Parameters
        ----------
        values : (n,) or (n, d) float

        Returns
        -------
        (m,) or (m, d) float
        """
        values = np.asarray(values, dtype=np.float64)
        cols = values.reshape(values.shape[0], -1).T
        m = self.n_faces
        k = int(self._offsets[1]) if m else 0
        uniform = (
            k
            and self._corners.size == k * m
            and self._offsets[-2] == k * (m - 1)
            and not np.any(np.diff(self._offsets) - k)
        )
        out = np.empty((m, cols.shape[0]))
        for i, col in enumerate(cols):  # one coordinate at a time: 1-D takes are fastest
            g = np.ascontiguousarray(col).take(self._corners)
            out[:, i] = (
                g.reshape(m, k).sum(axis=1) if uniform else np.add.reduceat(g, self._offsets[:-1])
            )
        out /= k if uniform else self.face_sizes[:, None]
        return out.reshape((m,) + values.shape[1:])

    @cached_property
    def face_normals(self) -> FloatArray:
        """(m, 3) float: unit normals (Newell's method; zero for degenerate faces)."""
        p = self._vertices[self._corners]
        q = self._vertices[self.head]
        cross = np.cross(p, q)
        n = np.add.reduceat(cross, self._offsets[:-1], axis=0)
        length = np.linalg.norm(n, axis=1, keepdims=True)
        return _readonly(np.divide(n, length, out=np.zeros_like(n), where=length > 0))

    @property
    def volume(self) -> float:
        """Signed enclosed volume (positive for outward-oriented faces).

        Each face is fanned from its centroid; the tetrahedra to the origin
        are summed.
        """
        c = self.face_centroids[self.halfedge_face]
        p = self._vertices[self._corners]
        q = self._vertices[self.head]
        return float(np.einsum("ij,ij->", c, np.cross(p, q)) / 6.0)

    @property
    def bounds(self) -> FloatArray:
        """(2, 3) float: the lower and upper corners of the bounding box."""
        return np.stack([self._vertices.min(axis=0), self._vertices.max(axis=0)])

    def fan_triangles(self) -> tuple[IntArray, IntArray]:
        """Fan triangulation of every face from its first corner (for drawing).

        Returns
        -------
        triangles : (H - 2m, 3) int
            Vertex indices, counter-clockwise like their faces.
        triangle_face : (H - 2m,) int
            The face each triangle comes from.
        """
        sizes = self.face_sizes
        tri_face = np.repeat(np.arange(self.n_faces, dtype=np.int64), sizes - 2)
        start = self._offsets[:-1][tri_face]
        # k-th triangle of a face: corners 0, k+1, k+2
        first = np.cumsum(sizes - 2) - (sizes - 2)
        k = np.arange(tri_face.size, dtype=np.int64) - first[tri_face]
        tris = np.stack(
            [self._corners[start], self._corners[start + k + 1], self._corners[start + k + 2]],
            axis=1,
        )
        return tris, tri_face

    def component_labels_of_faces(self) -> IntArray:
        """(m,) int: the component label of every face."""
        return self.component_labels[self._corners[self._offsets[:-1]]]

    @cached_property
    def component_labels(self) -> IntArray:
        """(n,) int: a component label (its smallest vertex index) per vertex.

        Shiloach-Vishkin style: hook the larger root of every edge whose ends
        disagree onto the smaller one, then jump pointers until every vertex
        points at its root; a few rounds on any mesh.
        """
        u, w = self.edges[:, 0], self.edges[:, 1]
        lab = np.arange(self.n_vertices, dtype=np.int64)
        while True:
            lu, lw = lab[u], lab[w]
            differ = lu != lw
            if not differ.any():
                return _readonly(lab)
            lu, lw = lu[differ], lw[differ]
            np.minimum.at(lab, np.maximum(lu, lw), np.minimum(lu, lw))
            while True:
                jumped = lab[lab]
                if np.array_equal(jumped, lab):
                    break
                lab = jumped

    # ------------------------------------------------------------------ checks
    def _validate(self) -> None:
        n = self.n_vertices
        c = self._corners
        sizes = self.face_sizes
        small = np.flatnonzero(sizes < 3)
        if small.size:
            f = int(small[0])
            raise MeshError(
                f"face {f} has {sizes[f]} vertices {self.faces[f].tolist()}; "
                "a face needs at least 3 distinct vertices"
            )
        bad = np.flatnonzero((c < 0) | (c >= n))
        if bad.size:
            f = int(np.searchsorted(self._offsets, bad[0], side="right") - 1)
            raise MeshError(
                f"face {f} uses vertex index {int(c[bad[0]])}, out of range for {n} vertices"
            )
        # repeated vertex inside a face
        fid = self.halfedge_face
        key = fid * n + c
        order = np.argsort(key, kind="stable")
        dup = np.flatnonzero(key[order][1:] == key[order][:-1])
        if dup.size:
            h = int(order[dup[0]])
            f = int(fid[h])
            distinct = np.unique(self.faces[f]).size
            raise MeshError(
                f"face {f} {self.faces[f].tolist()} repeats vertex {int(c[h])} "
                f"({distinct} distinct vertices); a face needs at least 3 "
                "distinct vertices and may use each vertex once"
            )
        if n == 0:
            raise MeshError("the mesh has no vertices")
        head = self.head
        twin, problem = _match_twins(c, head, n, check=True)
        if problem is not None:
            kind, h = problem
            u, w = int(c[h]), int(head[h])
            if kind == "duplicate":
                faces = np.flatnonzero((c == u) & (head == w))
                raise MeshError(
                    f"directed edge ({u}, {w}) is used by faces "
                    f"{fid[faces].tolist()}: inconsistent orientation or "
                    "a non-manifold edge"
                )
            raise MeshError(
                f"edge ({u}, {w}) of face {int(fid[h])} has only one side "
                "(a boundary): the mesh must be closed"
            )
        self.__dict__["twin"] = _readonly(twin)
        unused = np.flatnonzero(self.valences == 0)
        if unused.size:
            raise MeshError(
                f"vertex {int(unused[0])} is not used by any face ({unused.size} unused vertices)"
            )
        few = np.flatnonzero(self.valences < 3)
        if few.size:
            v = int(few[0])
            raise MeshError(
                f"vertex {v} has only {int(self.valences[v])} edges; every vertex "
                "needs at least 3 (Section 4 rules out 1- and 2-valent vertices, "
                "and the dual of such a vertex would be a face of fewer than "
                "3 sides)"
            )
        eh = self.edge_halfedge
        f1, f2 = fid[eh], fid[twin[eh]]
        # (a face on both sides of an edge would repeat a vertex: refused above)
        m = np.int64(self.n_faces)
        pair = np.minimum(f1, f2) * m + np.maximum(f1, f2)
        order = np.argsort(pair, kind="stable")
        dup = np.flatnonzero(pair[order][1:] == pair[order][:-1])
        if dup.size:
            a, b = order[dup[0]], order[dup[0] + 1]
            e1, e2 = (tuple(int(x) for x in self.edges[i]) for i in (a, b))
            raise MeshError(
                f"faces {int(min(f1[a], f2[a]))} and {int(max(f1[a], f2[a]))} "
                f"share more than one edge ({e1} and {e2}); the dual would "
                "have a double edge"
            )
        ring, _ = self._rings
        if not np.array_equal(np.sort(ring), np.arange(c.size)):
            # a vertex whose rotation orbit is shorter than its valence
            bad_v = _multi_fan_vertex(self.rotation, c, self.valences)
            raise MeshError(f"vertex {bad_v} is non-manifold: its faces form more than one fan")


_CONNECTIVITY_CACHE = (
    "faces",
    "face_sizes",
    "valences",
    "n_components",
    "halfedge_face",
    "next",
    "prev",
    "head",
    "twin",
    "halfedge_edge",
    "edge_halfedge",
    "edges",
    "rotation",
    "_rings",
    "component_labels",
    "_twin_maker",
    "_rings_maker",
    "_dual_source",
)


# ---------------------------------------------------------------------- helpers
def _as_vertices(vertices: ArrayLike) -> FloatArray:
    try:
        v = np.array(vertices, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise MeshError(f"vertices must be an (n, 3) array of numbers: {exc}") from None
    if v.ndim != 2 or v.shape[1] != 3:
        raise MeshError(f"vertices must be an (n, 3) array, got shape {v.shape}")
    bad = np.flatnonzero(~np.isfinite(v).all(axis=1))
    if bad.size:
        raise MeshError(f"vertex {int(bad[0])} has a non-finite coordinate {v[bad[0]].tolist()}")
    return v


def _as_csr(faces) -> tuple[IntArray, IntArray]:
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        if faces.dtype.kind not in "iu":
            whole = (
                np.equal(np.mod(faces, 1), 0).all(axis=1)
                if faces.dtype.kind == "f"
                else np.zeros(len(faces), dtype=bool)
            )
            if not whole.all():
                f = int(np.flatnonzero(~whole)[0])
                raise MeshError(
                    f"face {f} has non-integer vertex indices "
                    f"{faces[f].tolist()}: face indices must be integers"
                )
        arr = faces.astype(np.int64)
        m, k = arr.shape
        if m == 0:
            raise MeshError("the mesh has no faces")
        return arr.ravel().copy(), np.arange(0, (m + 1) * k, k, dtype=np.int64)[: m + 1]
    if isinstance(faces, np.ndarray) and faces.ndim != 1:
        raise MeshError(
            f"faces must be a list of index sequences or an (m, k) array, got shape {faces.shape}"
        )
    if not isinstance(faces, np.ndarray) and len(faces) and len({len(f) for f in faces}) == 1:
        # a list of faces of one size: one array conversion instead of one per face
        try:
            arr = np.array(faces)
        except (TypeError, ValueError):
            arr = None
        if arr is not None and arr.ndim == 2 and arr.dtype.kind in "iuf":
            return _as_csr(arr)
    sizes = []
    flat = []
    for f, face in enumerate(faces):
        try:
            a = np.asarray(face)
        except Exception:  # pragma: no cover - ragged nested input
            raise MeshError(f"face {f} is not a sequence of vertex indices") from None
        if a.ndim != 1:
            raise MeshError(f"face {f} is not a flat sequence of vertex indices")
        if a.size and a.dtype.kind not in "iu":
            if a.dtype.kind != "f" or not np.all(np.equal(np.mod(a, 1), 0)):
                raise MeshError(f"face {f} has non-integer vertex indices {a.tolist()}")
        sizes.append(a.size)
        flat.append(a.astype(np.int64))
    if not sizes:
        raise MeshError("the mesh has no faces")
    offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    return np.concatenate(flat), offsets


def _match_twins(tail, head, n, check=False):
    """Pair every half-edge (u, w) with its opposite (w, u) by sorting once.

    The key of a half-edge is its undirected edge with the direction as the
    lowest bit, so after one (radix-friendly, stable) argsort the two halves
    of every edge sit side by side.  When that pattern breaks, a slower
    search names the first duplicate directed edge or boundary edge
    (``problem = (kind, halfedge)``; only with ``check``).
    """
    n = np.int64(n)
    lo = np.minimum(tail, head)
    key = (lo * n + (tail + head - lo)) * 2 + (tail > head)
    order = np.argsort(key, kind="stable")
    skey = key[order]
    if skey.size % 2 == 0:
        a, b = skey[0::2], skey[1::2]
        if not np.any(a & 1) and np.array_equal(a + 1, b):
            twin = np.empty_like(order)
            twin[order[0::2]] = order[1::2]
            twin[order[1::2]] = order[0::2]
            return twin, None
    if not check:
        raise MeshError("the faces do not pair up into a closed, oriented manifold")
    dup = np.flatnonzero(skey[1:] == skey[:-1])
    if dup.size:
        return None, ("duplicate", int(order[dup[0]]))
    want = (lo * n + (tail + head - lo)) * 2 + (tail < head)
    pos = np.minimum(np.searchsorted(skey, want), skey.size - 1)
    missing = np.flatnonzero(skey[pos] != want)
    return None, ("boundary", int(missing[0]))


def _vertex_rings(rotation, tail, valences):
    """Outgoing half-edges of every vertex in rotation order, as CSR.

    One vectorized step per position around the vertex (a loop over the
    largest valence, not over vertices).  On a non-manifold vertex the orbit
    closes early; the ring then repeats half-edges, which ``_validate``
    detects.
    """
    n = valences.size
    ring_off = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(valences, out=ring_off[1:])
    start = np.empty(n, dtype=np.int64)
    # any outgoing half-edge per vertex: the last one written wins
    start[tail] = np.arange(tail.size, dtype=np.int64)
    ring = np.empty(tail.size, dtype=np.int64)
    top = int(valences.max(initial=0))
    # vertices by valence (a radix sort on small ints): at step k the vertices
    # still walking are a suffix of this order
    small = valences.astype(np.uint16 if top < 65536 else np.int64)
    order = np.argsort(small, kind="stable")
    first = np.searchsorted(small[order], np.arange(top), side="right")
    cur = start[order]
    base = ring_off[:-1][order]
    for k in range(top):
        lo = int(first[k])
        c = cur[lo:]
        if k:
            c = rotation[c]
            cur[lo:] = c
        ring[base[lo:] + k] = c
    return ring, ring_off


def _multi_fan_vertex(rotation, tail, valences) -> int:
    """The first vertex whose rotation orbit is shorter than its valence."""
    n = valences.size
    start = np.empty(n, dtype=np.int64)
    start[tail] = np.arange(tail.size, dtype=np.int64)
    cur = start.copy()
    closed_at = np.zeros(n, dtype=np.int64)
    for k in range(1, int(valences.max(initial=0)) + 1):
        cur = rotation[cur]
        newly = (cur == start) & (closed_at == 0)
        closed_at[newly] = k
    bad = np.flatnonzero((closed_at < valences) & (valences > 0))
    return int(bad[0]) if bad.size else -1
