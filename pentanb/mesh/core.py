"""The sealed :class:`Mesh`: CSR faces, positions, and what is derived from them, cached.

A face is a cyclic sequence of vertex indices.  All faces are stored in one
flat array of *corners* (``corners``) cut by ``offsets``: face ``f`` is
``corners[offsets[f]:offsets[f + 1]]``.  Triangles, pentagons and mixed faces
share this one structure.  Half-edges and the rest are derived on first use
(:mod:`pentanb.mesh.halfedge`) and cached.

A :class:`Mesh` is sealed: no attribute can be set, replaced or deleted, and
every array it hands out is read-only, so nothing it has cached can go
stale.  What depends on the faces alone is kept in one connectivity record
shared by the meshes with the same faces (:meth:`Mesh.with_vertices`, the
dual of a dual), so it is derived once for all of them.

Operators build their outputs, valid by construction, through one internal
constructor, :func:`pentanb.mesh.build.trusted`; :mod:`pentanb.mesh.build`
is the only way code outside this package reaches a mesh's caches.

A mesh may be open (a surface with boundary).  Each boundary loop is an
implicit *hole face* (geometry-central's representation): the twin of a
boundary half-edge is a hole half-edge numbered from ``H`` on (see
:attr:`Mesh.twin`), so that every half-edge has a twin and every vertex's
edges one cycle round it (:attr:`Mesh.vertex_ring`).  A closed mesh is the
case of no loops, and its arrays are those of a mesh without this
extension, bit for bit.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _jit
from .boundary import CLOSED as _CLOSED
from .boundary import describe_boundary, open_twins
from .cache import Several, _Connectivity, _connectivity
from .coerce import (
    FloatArray,
    IntArray,
    MeshError,
    as_csr,
    as_csr_part,
    as_vertices,
    check_offsets,
    check_ranges,
    compact,
    frozen,
    readonly,
)
from .halfedge import (
    halfedge_face,
    head_of,
    heads_at,
    next_of,
    open_vertex_rings,
    prev_of,
    rotation_of,
    uniform_size,
    vertex_rings,
    walk_rings,
)
from .pieces import Pieces
from .positions import Positions
from .validate import validate as validate_mesh
from .validate import validate_rings

__all__ = ["Mesh", "Rings", "Several", "check_mesh", "check_closed"]

Rings = tuple[IntArray, IntArray]


class Mesh(Positions, Pieces):
    """An oriented 2-manifold polygon mesh, closed or with boundary (immutable).

    Parameters
    ----------
    vertices : (n, 3) float array_like
        Vertex positions.
    faces : (m,) sequence of int sequences, or (m, k) int array_like
        Vertex indices of each face, counter-clockwise seen from outside
        (from the side of the normal).  Faces may have any number (>= 3)
        of sides.

    Raises
    ------
    MeshError
        When the input is not a consistently oriented 2-manifold polygon
        mesh: an index out of range, a face with repeated or fewer than 3
        vertices, an edge with more than two faces (a non-manifold edge),
        two faces running along an edge in the same direction
        (inconsistent orientation; "non-orientable" when no choice of
        orientations mends it, as on a Moebius band), a vertex whose faces
        form more than one fan (or a fan and a cycle), an unused vertex or
        a non-finite coordinate.  Also refused, because the dual (the
        paper's smoothing) cannot be built from them: an interior vertex
        with fewer than 3 edges, and two faces that share more than one
        edge.  The message names the culprit.

    Notes
    -----
    Every edge has one or two faces: an edge with one is a boundary edge,
    and the boundary edges form :attr:`boundary_loops` (holes, open rims).
    Every vertex's faces form one cycle round it (an interior vertex) or
    one fan (a boundary vertex, which then has one more edge than faces).
    A closed mesh is the case without boundary (:attr:`is_closed`); its
    every array is what it was before open meshes were accepted.

    A mesh is sealed: setting, replacing or deleting any attribute raises
    AttributeError, and every array it hands out is read-only.  The
    constructor and :meth:`from_csr` copy their inputs, so changing the
    caller's arrays afterwards cannot change the mesh.  New positions:
    :meth:`with_vertices`; new faces: an operator (:func:`pentanb.dual`,
    :func:`pentanb.pentagonalize`, ...), which builds its output valid by
    construction, without re-validation.

    Meshes pickle and copy (:mod:`pickle`, :func:`copy.deepcopy`): the
    positions, the faces and the twins and vertex rings an operator handed
    over are kept; everything else is derived again on first use.

    Examples
    --------
    >>> import pentanb
    >>> m = pentanb.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                  [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
    >>> m.n_vertices, m.n_edges, m.n_faces, m.genus
    (4, 6, 4, 0)
    >>> disk = pentanb.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    >>> disk.is_closed, disk.n_edges, disk.n_boundary_loops, disk.euler_characteristic
    (False, 4, 1, 1)
    >>> m.vertices[0, 0] = 5.0
    Traceback (most recent call last):
    ...
    ValueError: assignment destination is read-only
    """

    __slots__ = (
        "_vertices",
        "_corners",
        "_offsets",
        "_shared",
        "_own",
        "_dual_source",
        "__weakref__",
    )

    _vertices: FloatArray
    _corners: IntArray
    _offsets: IntArray
    _shared: _Connectivity
    _own: dict[str, Any]
    _dual_source: _Connectivity | None

    def __init__(self, vertices: ArrayLike, faces: ArrayLike | Sequence[Sequence[int]]):
        v = as_vertices(vertices)
        corners, offsets = compact(*as_csr(faces), v.shape[0])
        self._init(v, corners, offsets)
        del corners, offsets  # (any wider copy made on the way is gone before validating)
        validate_mesh(self)

    # ------------------------------------------------------------------ sealing
    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(
            f"cannot set {name!r}: a Mesh is immutable (use mesh.with_vertices(...) "
            "for new positions; operators build new meshes)"
        )

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"cannot delete {name!r}: a Mesh is immutable")

    # ------------------------------------------------------------------ construction
    def _init(
        self,
        vertices: np.ndarray,
        corners: np.ndarray,
        offsets: np.ndarray,
        *,
        twin: IntArray | Callable[[], IntArray] | None = None,
        rings: Rings | Callable[[], Rings | Several] | None = None,
        size_counts: tuple[tuple[int, int], ...] | None = None,
        dual_of: Mesh | None = None,
        shared: _Connectivity | None = None,
        closed: bool = False,
    ) -> None:
        """Initialise a new mesh: every mesh with vertices is set up here, once.

        The arrays are taken as they are (no copy) and made read-only: the
        caller hands over arrays nobody else holds (or read-only arrays of
        another mesh).  Nothing is checked; :meth:`__init__` and
        :meth:`from_csr` validate afterwards.

        Parameters
        ----------
        vertices : (n, 3) float
        corners : (H,) int
        offsets : (m + 1,) int
        twin : (H,) int, or a zero-argument callable returning it, optional
            The output's twins, when the caller knows them; a callable runs
            when the twins are first asked for.
        rings : ((H,) int, (n + 1,) int), or a callable returning them, optional
            The vertex rings (see :attr:`vertex_ring`), likewise.
        size_counts : ((size, faces), ...), optional
            The face-size histogram by ascending size, when the caller
            knows it (an operator, from its input's).
        dual_of : Mesh, optional
            The mesh this one is the dual of: the dual of this mesh then
            reuses that mesh's connectivity (see :meth:`_dual_again`).
        shared : _Connectivity, optional
            The connectivity record of another mesh with these very faces
            (``corners`` and ``offsets`` must be its arrays): what it has
            derived is shared.
        closed : bool
            True when the caller knows the faces close up (an operator's
            output from a closed input): recorded, so that no pass over the
            twins is needed to tell (:attr:`is_closed`, :attr:`n_edges`).
            False: found out when first needed.
        """
        if hasattr(self, "_vertices"):
            raise AttributeError("a Mesh is initialised once: meshes are immutable")
        if shared is None:
            shared = _Connectivity(readonly(corners), readonly(offsets))
            if twin is not None:
                if callable(twin):
                    shared.producers["twin"] = twin
                else:
                    shared.values["twin"] = readonly(twin)
            if rings is not None:
                if callable(rings):
                    shared.producers["vertex_ring"] = rings
                else:
                    shared.values["vertex_ring"] = frozen(tuple(rings))
            if size_counts is not None:
                shared.values["_size_counts"] = tuple(size_counts)
            if closed:
                shared.values["_boundary"] = _CLOSED
        elif corners is not shared.corners or offsets is not shared.offsets:
            raise ValueError("shared connectivity needs the very corners and offsets it holds")
        elif twin is not None or rings is not None or size_counts is not None or closed:
            raise ValueError("twin, rings and size counts come with the shared connectivity")
        init = object.__setattr__
        init(self, "_vertices", readonly(vertices))
        init(self, "_corners", shared.corners)
        init(self, "_offsets", shared.offsets)
        init(self, "_shared", shared)
        init(self, "_own", {})
        init(self, "_dual_source", None if dual_of is None else dual_of._shared)

    @classmethod
    def _new(
        cls,
        vertices: np.ndarray,
        corners: np.ndarray,
        offsets: np.ndarray,
        *,
        twin: IntArray | Callable[[], IntArray] | None = None,
        rings: Rings | Callable[[], Rings | Several] | None = None,
        size_counts: tuple[tuple[int, int], ...] | None = None,
        dual_of: Mesh | None = None,
        shared: _Connectivity | None = None,
        closed: bool = False,
    ) -> Mesh:
        """The internal constructor: a mesh from arrays the package itself made.

        No validation and no copy (the arrays become the mesh's, read-only);
        operators use it for outputs that are valid by construction.  The
        arguments are those of :meth:`_init`.
        """
        self = object.__new__(cls)
        self._init(
            vertices,
            corners,
            offsets,
            twin=twin,
            rings=rings,
            size_counts=size_counts,
            dual_of=dual_of,
            shared=shared,
            closed=closed,
        )
        return self

    def _dual_again(self) -> Mesh | None:
        """The dual of this mesh when it was built as the dual of a mesh M, else None.

        Its faces are M's faces, in M's order (the dual of a dual gives back
        the connectivity), so M's connectivity record is shared, with all M
        has derived; its vertices are this mesh's face centroids.
        """
        source = self._dual_source
        if source is None:
            return None
        out = Mesh._new(
            self.face_centroids, source.corners, source.offsets, shared=source, dual_of=self
        )
        out._note_extent(self._extent)
        return out

    def _rescaled(self, shift: int) -> Mesh:
        """The same faces (shared) with every position times ``2**shift`` (exact).

        Raises
        ------
        MeshError
            When a scaled position is not finite.
        """
        with np.errstate(over="ignore"):
            v = np.ldexp(self._vertices, shift)
        if not np.isfinite(v).all():
            raise MeshError(
                "the result's coordinates would be too large for float64 "
                f"(beyond {np.finfo(np.float64).max:.3g})"
            )
        return Mesh._new(v, self._corners, self._offsets, shared=self._shared)

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
            The opposite half-edge of each half-edge of a closed mesh, when
            the caller knows it: checked (an involution pairing every
            half-edge with its reverse) instead of derived by sorting.  An
            open mesh's twins (which name hole half-edges, ``>= H``) are
            always derived: a twin outside ``[0, H)`` is refused.
        validate : bool
            True: every check of the constructor.  False: only what the
            arrays' consistency rests on (indices in range, finite
            coordinates, faces of at least 3 distinct vertices, every
            directed edge once and with its opposite, one fan round every
            vertex), so that no operator, numpy's or a compiled kernel, can
            read outside an array; what the operators refuse one by one
            with their own message (a vertex of fewer than 3 edges, two
            faces sharing two edges, an unused vertex) is let through, for
            meshes such as a flat polygon closed by its reverse.

        Returns
        -------
        Mesh

        Raises
        ------
        MeshError
            Naming the first culprit.
        TypeError
            An argument that is not an array of numbers.

        Notes
        -----
        The arrays are always copied (a copy costs little next to deriving
        the half-edges): the mesh never aliases, nor freezes, the caller's
        arrays, so changing them afterwards cannot change the mesh.
        """
        v = as_vertices(vertices)
        c = as_csr_part(corners, "corners")  # copies: the caller's
        o = as_csr_part(offsets, "offsets")  # arrays stay theirs
        check_offsets(c, o)
        c, o = compact(c, o, v.shape[0])
        t = None
        if twin is not None:
            t = as_csr_part(twin, "twin")
            check_ranges(c, o, t, v.shape[0])
            t = t.astype(c.dtype)
        self = cls._new(v, c, o)
        validate_mesh(self, twin=t, strict=bool(validate))
        return self

    def with_vertices(self, vertices: ArrayLike) -> Mesh:
        """The same connectivity with other vertex positions.

        The faces and everything derived from them alone are shared with
        this mesh (nothing is derived twice); ``vertices`` is copied.

        Parameters
        ----------
        vertices : (n, 3) float array_like
            New positions, one per vertex of this mesh.

        Returns
        -------
        Mesh

        Raises
        ------
        MeshError
            A shape other than this mesh's ``(n, 3)``, or a non-finite coordinate.
        """
        v = as_vertices(vertices)
        if v.shape != self._vertices.shape:
            raise MeshError(f"expected {self._vertices.shape} vertices, got {v.shape}")
        return type(self)._new(v, self._corners, self._offsets, shared=self._shared)

    # ------------------------------------------------------------------ pickling
    def __reduce__(self) -> tuple[Callable[..., Mesh], tuple[Any, ...]]:
        """Pickle (and copy) as the arrays plus the twins and rings already known.

        Loading checks them (:func:`_rebuild`); everything else is derived
        again on first use.
        """
        shared = self._shared
        known = {
            name: getattr(self, name)
            for name in ("twin", "vertex_ring")
            if name in shared.values or name in shared.producers
        }
        if known and not self.is_closed:  # an open mesh's twins and rings are derived again
            known = {}
        return (_rebuild, (self._vertices, self._corners, self._offsets, known))

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

    @_connectivity
    def faces(self) -> tuple[IntArray, ...]:
        """(m,) tuple of int arrays: the vertex indices of every face (read-only views)."""
        return tuple(np.split(self._corners, self._offsets[1:-1]))

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
        """Number of edges E: ``(H + B) / 2``, B boundary edges (``H / 2`` when closed)."""
        return int((self._corners.size + self._boundary[0].size) // 2)

    # ------------------------------------------------------------------ boundary
    @_connectivity
    def _boundary(self) -> tuple[IntArray, IntArray]:
        """The boundary half-edges loop after loop (B,) and the loops' offsets (L + 1,).

        Recorded when the twins are paired (or by an operator whose output
        is closed); otherwise read from the twins: the boundary half-edge
        ``h`` with ``twin[h] = H + j`` is the j-th, and a loop ends where
        the next half-edge does not start at the previous one's head.
        """
        values = self._shared.values
        twin = self.twin  # pairing the twins records the boundary
        got = values.get("_boundary")
        if got is not None:
            return got
        H = twin.size
        if H == 0 or int(twin.max()) < H:
            return _CLOSED
        at = np.flatnonzero(twin >= H)
        bh = np.empty(at.size, dtype=np.int64)
        bh[twin[at].astype(np.int64) - H] = at
        head = self.head
        starts = np.flatnonzero(self._corners[bh[1:]] != head[bh[:-1]]) + 1
        offsets = np.concatenate([[0], starts, [bh.size]]).astype(np.int64)
        return readonly(bh), readonly(offsets)

    @property
    def is_closed(self) -> bool:
        """True when every edge has two faces (no boundary)."""
        return self._boundary[0].size == 0

    @property
    def n_boundary_edges(self) -> int:
        """Number of boundary edges B (edges with one face); 0 when closed."""
        return int(self._boundary[0].size)

    @property
    def n_boundary_loops(self) -> int:
        """Number of boundary loops b (holes and open rims); 0 when closed."""
        return int(self._boundary[1].size - 1)

    @property
    def boundary_halfedges(self) -> IntArray:
        """(B,) int: the half-edges without an opposite, loop after loop (read-only).

        In every loop the head of a half-edge is the tail of the next (the
        last's head the first's tail); the face of each is on its left, the
        hole on its right.  A loop starts at its smallest half-edge, and
        loops come in the order of those.  The twin of
        ``boundary_halfedges[j]`` is the hole half-edge ``H + j``.
        """
        return self._boundary[0]

    @property
    def boundary_loops(self) -> tuple[IntArray, ...]:
        """The boundary half-edges of every loop, in order: a tuple of (B_i,) int arrays.

        Empty for a closed mesh.  Loop ``i``'s vertices, in order, are
        ``mesh.corners[mesh.boundary_loops[i]]``.
        """
        bh, off = self._boundary
        return tuple(bh[a:b] for a, b in zip(off[:-1].tolist(), off[1:].tolist()))

    @_connectivity
    def is_boundary_vertex(self) -> NDArray[np.bool_]:
        """(n,) bool: the vertices on the boundary (all False when closed)."""
        out = np.zeros(self.n_vertices, dtype=bool)
        out[self._corners[self._boundary[0]]] = True
        return readonly(out)

    @_connectivity
    def face_sizes(self) -> IntArray:
        """(m,) int: number of sides of every face."""
        return readonly(np.diff(self._offsets))

    @_connectivity
    def _uniform_size(self) -> int:
        """k when every face has k sides, else 0."""
        return uniform_size(self._offsets, self._corners.size)

    @_connectivity
    def valences(self) -> IntArray:
        """(n,) int: number of edges at every vertex.

        On the boundary a vertex has one more edge than it has faces (a
        vertex of one face, a corner, has 2 edges).
        """
        counts = np.bincount(self._corners, minlength=self.n_vertices)
        bh = self._boundary[0]
        if bh.size:  # (a few boundary vertices: no second count over every vertex)
            np.add.at(counts, self._corners[bh], 1)
        return readonly(counts.astype(self._corners.dtype, copy=False))

    @_connectivity
    def _face_counts(self) -> IntArray:
        """(n,) int: number of faces at every vertex (= valences when closed)."""
        if self.is_closed:
            return self.valences
        counts = np.bincount(self._corners, minlength=self.n_vertices)
        return readonly(counts.astype(self._corners.dtype, copy=False))

    @property
    def euler_characteristic(self) -> int:
        """V - E + F (``2 - 2g - b`` for a connected mesh of genus g with b boundary loops)."""
        return self.n_vertices - self.n_edges + self.n_faces

    @_connectivity
    def n_components(self) -> int:
        """Number of connected components."""
        return int(np.unique(self.component_labels).size)

    @property
    def genus(self) -> int:
        """Total genus: ``(2 * components - loops - (V - E + F)) / 2``.

        For a connected mesh this is the g of ``V - E + F = 2 - 2g - b``,
        b its boundary loops (``2 - 2g`` when closed); for several
        components, the sum of theirs.
        """
        return (2 * self.n_components - self.n_boundary_loops - self.euler_characteristic) // 2

    def face_size_histogram(self) -> dict[int, int]:
        """The number of faces of every size.

        Returns
        -------
        dict of int to int
            ``{n: number of n-gons}``, sorted by n.
        """
        return dict(self._size_counts)

    @_connectivity
    def _size_counts(self) -> tuple[tuple[int, int], ...]:
        """``((n, number of n-gons), ...)`` by n: the face-size histogram, counted once."""
        k, F = self._uniform_size, self.n_faces
        if k or not F:
            return ((k, F),) if F else ()
        sizes = self.face_sizes
        low = int(sizes.min())
        counts = np.bincount(sizes - low)
        return tuple((low + int(s), int(counts[s])) for s in np.flatnonzero(counts))

    def valence_histogram(self) -> dict[int, int]:
        """The number of vertices of every valence.

        Returns
        -------
        dict of int to int
            ``{k: number of k-valent vertices}``, sorted by k.
        """
        vals, counts = np.unique(self.valences, return_counts=True)
        return {int(s): int(c) for s, c in zip(vals, counts)}

    def counts(self) -> dict:
        """V, E, F, the face-size and valence histograms, chi and genus.

        Returns
        -------
        dict
            ``"V"``, ``"E"``, ``"F"`` (ints), ``"faces"`` and ``"valences"``
            (the histograms), ``"chi"`` and ``"genus"`` (ints).  An open
            mesh adds ``"B"``, its boundary edges, and ``"loops"``, its
            boundary loops (``chi = 2 - 2 genus - loops`` when connected).
        """
        out = {
            "V": self.n_vertices,
            "E": self.n_edges,
            "F": self.n_faces,
            "faces": self.face_size_histogram(),
            "valences": self.valence_histogram(),
            "chi": self.euler_characteristic,
            "genus": self.genus,
        }
        if not self.is_closed:
            out["B"] = self.n_boundary_edges
            out["loops"] = self.n_boundary_loops
        return out

    def __repr__(self) -> str:
        hist = ", ".join(f"{n}:{c}" for n, c in self.face_size_histogram().items())
        rim = "" if self.is_closed else f", boundary loops={self.n_boundary_loops}"
        return (
            f"Mesh(V={self.n_vertices}, E={self.n_edges}, F={self.n_faces}, faces={{{hist}}}{rim})"
        )

    # ------------------------------------------------------------------ half-edges
    @_connectivity
    def halfedge_face(self) -> IntArray:
        """(H,) int: the face of every half-edge."""
        return readonly(halfedge_face(self._offsets, self._corners.size, self._uniform_size))

    @_connectivity
    def halfedge_slot(self) -> IntArray:
        """(H,) int: the position of every half-edge in its face (0 at the face's first corner).

        Half-edge ``h`` is ``offsets[halfedge_face[h]] + halfedge_slot[h]``.
        """
        h = np.arange(self.n_halfedges, dtype=self._corners.dtype)
        return readonly(h - self._offsets[:-1][self.halfedge_face])

    @_connectivity
    def next(self) -> IntArray:
        """(H,) int: the next half-edge around the same face."""
        return readonly(next_of(self._offsets, self._corners.size, self._corners.dtype))

    @_connectivity
    def prev(self) -> IntArray:
        """(H,) int: the previous half-edge around the same face."""
        return readonly(prev_of(self._offsets, self._corners.size, self._corners.dtype))

    @property
    def tail(self) -> IntArray:
        """(H,) int: the vertex a half-edge leaves (= ``corners``)."""
        return self._corners

    @_connectivity
    def head(self) -> IntArray:
        """(H,) int: the vertex a half-edge reaches (``corners[next]``)."""
        k = self._uniform_size
        if k:
            return readonly(head_of(self._corners, self._offsets, k))
        return readonly(self._corners[self.next])

    @_connectivity
    def twin(self) -> IntArray:
        """(H,) int: the opposite half-edge (same edge, other face).

        On an open mesh the twin of a boundary half-edge is a *hole*
        half-edge, numbered ``H + j`` (``j`` its place in
        :attr:`boundary_halfedges`): ``twin[h] >= H`` exactly on the
        boundary.  Each boundary loop is an implicit hole face whose
        half-edges run opposite to the boundary's (geometry-central's
        representation), so every half-edge has a twin; the hole
        half-edges have no corner and no entry in the arrays of length H.
        """
        k = self._uniform_size
        got = open_twins(self._corners, None if k else self.head, self.n_vertices, k)
        if got is None:  # (only faces nothing validated: validation names the culprit)
            raise MeshError("the faces do not pair up into an oriented manifold")
        if got[1][0].size:
            self._shared.values["_boundary"] = got[1]
        else:
            self._shared.values.setdefault("_boundary", _CLOSED)
        return readonly(got[0])

    @_connectivity
    def _forward(self) -> NDArray[np.bool_]:
        """(H,) bool: ``tail < head``, the half-edge that numbers its edge."""
        return readonly(self._corners < self.head)

    @_connectivity
    def _primary(self) -> NDArray[np.bool_]:
        """(H,) bool: the half-edge that numbers its edge.

        ``tail < head`` (:attr:`_forward`), and on the boundary the edge's
        one half-edge whichever its direction.
        """
        bh = self._boundary[0]
        if not bh.size:
            return self._forward
        primary = self._forward.copy()
        primary[bh] = True
        return readonly(primary)

    @_connectivity
    def halfedge_edge(self) -> IntArray:
        """(H,) int: the edge id of every half-edge.

        Edge ``e`` is numbered by the order of its half-edge with
        ``tail < head`` (on the boundary: of its one half-edge); see
        :attr:`edges`.
        """
        primary = self._primary
        ids = np.cumsum(primary, dtype=self._corners.dtype)
        ids -= 1
        back = np.flatnonzero(~primary)
        ids[back] = ids[self.twin[back]]
        return readonly(ids)

    @_connectivity
    def edge_halfedge(self) -> IntArray:
        """(E,) int: for every edge, its half-edge with ``tail < head`` (each edge once).

        A boundary edge's is its one half-edge, whichever its direction.
        """
        return readonly(np.flatnonzero(self._primary).astype(self._corners.dtype, copy=False))

    @_connectivity
    def edges(self) -> IntArray:
        """(E, 2) int: the edges as (smaller, larger) vertex pairs."""
        h = self.edge_halfedge
        if self.is_closed:
            return readonly(np.stack([self._corners[h], self.head[h]], axis=1))
        a, b = self._corners[h], self.head[h]
        return readonly(np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1))

    @_connectivity
    def rotation(self) -> IntArray:
        """(H,) int: the next outgoing half-edge counter-clockwise around its tail.

        ``rotation[h] = twin[prev[h]]``: on an open mesh a hole half-edge
        (``>= H``) where ``prev[h]`` is on the boundary, the end of the fan.
        """
        return readonly(rotation_of(self.twin, self._offsets, self._uniform_size, self))

    @_connectivity
    def vertex_ring(self) -> Rings:
        """The outgoing half-edges of every vertex, counter-clockwise, in CSR form.

        Returns
        -------
        ring : (H + B,) int
            Half-edges, vertex after vertex, each vertex's in rotation order,
            starting at its largest.  A boundary vertex's ring starts with
            its hole half-edge (``>= H``, running along the boundary to the
            vertex before it), then its face half-edges from the boundary
            edge it leaves by, counter-clockwise; on a closed mesh B = 0.
        ring_offsets : (n + 1,) int
            Vertex ``v``'s half-edges are ``ring[ring_offsets[v]:ring_offsets[v+1]]``:
            as many as its edges (:attr:`valences`).
        """
        bh, off = self._boundary
        k, c = self._uniform_size, self._corners
        if bh.size:
            hole_tail = heads_at(c, bh, k, None if k else self.head)
            got = walk_rings(
                self.twin, c, k, None if k else self.prev, self.valences, (bh, off), hole_tail
            )
        else:
            got = walk_rings(self.twin, c, k, None if k else self.prev, self.valences)
        if got is not None:  # (compiled: the same arrays, without a rotation array)
            return readonly(got[0]), readonly(got[1])
        if not bh.size:
            ring, off = vertex_rings(self.rotation, self._corners, self.valences)
            return readonly(ring), readonly(off)
        ring, ring_off = open_vertex_rings(
            self.rotation, self._corners, self.head, bh, off, self.valences
        )
        return readonly(ring), readonly(ring_off)

    def _ring_faces(self) -> IntArray:
        """(H,) int: the face of every entry of :attr:`vertex_ring`, in its order.

        ``halfedge_face[vertex_ring[0]]``: the faces round every vertex in
        rotation order, which are the dual's faces (its corners).  An
        operator that knows its output's rings may write these with them
        (:class:`Several`); they are then taken from the cache, once: the
        array becomes the dual's, and is not kept here as well.
        """
        made = self._shared.values.pop("_ring_faces", None)
        if made is not None:
            return made
        if not self.is_closed:
            raise MeshError("an open mesh's vertex rings hold hole half-edges, which have no face")
        ring, _ = self.vertex_ring
        k = self._uniform_size
        if k:
            return readonly(ring // k)
        jit = _jit.kernels(ring.size)
        return readonly(jit.gather(self.halfedge_face, ring) if jit else self.halfedge_face[ring])

    def _faces_only(self) -> Any:
        """This mesh's faces without its positions (a :class:`_Faces`).

        For the producers an operator hands over with its output: they
        derive what they need from the faces (shared with this mesh, so
        nothing is derived twice) without keeping the positions alive.
        """
        return _Faces(self._shared, self.n_vertices)

    def _faces_keeping(self, names: tuple[str, ...]) -> Any:
        """This mesh's faces with only the named connectivity derived so far
        carried over (a :class:`_Faces` of its own record): what else it is
        asked for it derives again, and it keeps nothing else of this mesh's alive."""
        shared = _Connectivity(self._corners, self._offsets)
        for name in names:
            if name in self._shared.values:
                shared.values[name] = self._shared.values[name]
        return _Faces(shared, self.n_vertices)


class _Faces:
    """The faces of a mesh without positions: :class:`Mesh`'s connectivity properties.

    Reads and fills the same shared connectivity record as the meshes with
    these faces.  Not a mesh (it has no positions and is never handed to
    users): operators' producers hold one instead of the mesh, so that a
    lazy twin or ring does not keep the input's positions alive.
    """

    __slots__ = ("_shared", "_corners", "_offsets", "_n")

    def __init__(self, shared: _Connectivity, n: int) -> None:
        self._shared = shared
        self._corners = shared.corners
        self._offsets = shared.offsets
        self._n = n

    @property
    def n_vertices(self) -> int:
        return self._n


for _name in (
    "corners",
    "offsets",
    "tail",
    "n_faces",
    "n_halfedges",
    "n_edges",
    "face_sizes",
    "_uniform_size",
    "valences",
    "_face_counts",
    "_boundary",
    "is_closed",
    "n_boundary_edges",
    "n_boundary_loops",
    "boundary_halfedges",
    "boundary_loops",
    "is_boundary_vertex",
    "halfedge_face",
    "halfedge_slot",
    "next",
    "prev",
    "head",
    "twin",
    "_forward",
    "_primary",
    "halfedge_edge",
    "edge_halfedge",
    "edges",
    "rotation",
    "vertex_ring",
):
    setattr(_Faces, _name, Mesh.__dict__[_name])
del _name


def _rebuild(
    vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray, known: dict[str, Any]
) -> Mesh:
    """Unpickle (or copy) a mesh: see :meth:`Mesh.__reduce__`.

    A pickle is outside data: the arrays are checked as by
    ``Mesh.from_csr(..., validate=False)`` (the twins it holds are checked,
    not trusted), so a tampered pickle is a MeshError, never a mesh that
    sends an operator outside its arrays.
    """
    mesh = Mesh.from_csr(vertices, corners, offsets, twin=known.get("twin"), validate=False)
    rings = known.get("vertex_ring")
    if rings is not None:
        if not (isinstance(rings, tuple) and len(rings) == 2):
            raise MeshError("the pickled vertex rings are not a pair of arrays")
        validate_rings(mesh, rings)
    return mesh


def check_mesh(mesh: object, op: str) -> Mesh:
    """``mesh`` itself, or a TypeError naming ``op`` when it is not a Mesh.

    Every operator, writer and position solver starts with it.
    """
    if not isinstance(mesh, Mesh):
        raise TypeError(f"{op} expects a pentanb.Mesh, got {type(mesh).__name__}")
    return mesh


def check_closed(mesh: object, op: str) -> Mesh:
    """``mesh`` itself when it is a closed Mesh; else an error naming ``op``.

    For what only makes sense on a closed surface (an enclosed volume, a
    polyhedron's canonical form, measures of a closed surface).

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh.
    MeshError
        ``mesh`` is open: the message names ``op`` and the boundary loops,
        e.g. ``"volume needs a closed mesh; this one is open: 1 boundary
        loop (12 edges)"``.
    """
    check_mesh(mesh, op)
    assert isinstance(mesh, Mesh)
    if not mesh.is_closed:
        raise MeshError(
            f"{op} needs a closed mesh; this one is open: "
            f"{describe_boundary(mesh.corners, mesh.head)}"
        )
    return mesh
