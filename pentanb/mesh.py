"""The polygon mesh: faces in CSR form, half-edges derived with numpy.

A face is a cyclic sequence of vertex indices.  All faces are stored in one
flat array of *corners* (``corners``) cut by ``offsets``: face ``f`` is
``corners[offsets[f]:offsets[f + 1]]``.  Triangles, pentagons and mixed faces
share this one structure.

A *half-edge* is a corner: half-edge ``h`` runs from ``corners[h]`` to the
next corner of its face.  Everything else (``next``, ``prev``, ``twin``, edge
ids, the rotation around a vertex) is derived from ``corners`` and
``offsets`` with whole-array numpy expressions, on first use, and cached.

Index arrays (``corners``, ``offsets`` and every derived array of indices)
are int32 when the mesh's counts allow it (fewer than 2**31 corners and
vertices), int64 otherwise: half the memory and memory traffic for every
mesh that fits in a computer's memory.  Arithmetic on them that may exceed
2**31 (keys such as ``u * n + w``) must first convert to int64.

A :class:`Mesh` is sealed: no attribute can be set, replaced or deleted, and
every array it hands out is read-only, so nothing it has cached can go
stale.  What depends on the faces alone is kept in one connectivity record
shared by the meshes with the same faces (:meth:`Mesh.with_vertices`, the
dual of a dual), so it is derived once for all of them.

Operators build their outputs, valid by construction, through one internal
constructor, ``Mesh._new(vertices, corners, offsets, *, twin=None,
rings=None, dual_of=None)``: the arrays they know about their output (the
twins, the vertex rings) are handed over as arrays or as zero-argument
producers run on first use, and the dual names the mesh it is the dual of.
This module is the only code that touches a mesh's caches.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, Generic, TypeVar, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _jit

__all__ = ["Mesh", "MeshError", "fan_triangle_corners"]

IntArray = NDArray[np.signedinteger[Any]]
FloatArray = NDArray[np.float64]
Rings = tuple[IntArray, IntArray]
_T = TypeVar("_T")


class MeshError(ValueError):
    """A mesh is not a closed, consistently oriented 2-manifold polygon mesh,
    a file does not hold one, or an operation would be too large.

    The message names the offending face, edge, vertex, file line or size.
    """


def _readonly(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


def _frozen(value: Any) -> Any:
    """``value`` with every array in it made read-only (arrays, tuples of arrays)."""
    if isinstance(value, np.ndarray):
        return _readonly(value)
    if isinstance(value, tuple):
        return tuple(_frozen(x) for x in value)
    return value


class _Several(dict):
    """Connectivity values one producer wrote together, by property name.

    A producer handed over for one property (say ``vertex_ring``) may
    return this instead of the value alone: every value in it is cached at
    once (so that one pass can write two arrays that are read together).
    """


class _Connectivity:
    """The faces of a mesh and everything derived from them alone.

    Shared by every mesh with these faces (:meth:`Mesh.with_vertices`, the
    dual of a dual), so each array is derived once for all of them.

    Attributes
    ----------
    corners, offsets : read-only int arrays
        The faces in CSR form.
    values : dict
        Derived arrays (read-only) and numbers, by property name.
    producers : dict
        Zero-argument callables an operator handed over to write a derived
        array on first use (see :meth:`Mesh._new`); each runs at most once
        and is then dropped.
    """

    __slots__ = ("corners", "offsets", "values", "producers")

    def __init__(self, corners: IntArray, offsets: IntArray) -> None:
        self.corners = corners
        self.offsets = offsets
        self.values: dict[str, Any] = {}
        self.producers: dict[str, Callable[[], Any]] = {}


class _Derived(Generic[_T]):
    """A read-only property of a mesh computed on first use and cached.

    With ``connectivity=True`` the value depends on the faces alone and is
    kept in the mesh's shared :class:`_Connectivity`; an operator may have
    handed over a producer for it, which then replaces the computation.
    Otherwise (positions are involved) it is kept by the mesh itself.
    """

    def __init__(self, func: Callable[[Mesh], _T], connectivity: bool) -> None:
        self.func = func
        self.name = func.__name__
        self.connectivity = connectivity
        self.__doc__ = func.__doc__

    @overload
    def __get__(self, mesh: None, owner: type | None = None) -> _Derived[_T]: ...

    @overload
    def __get__(self, mesh: Mesh, owner: type | None = None) -> _T: ...

    def __get__(self, mesh: Mesh | None, owner: type | None = None) -> _T | _Derived[_T]:
        if mesh is None:
            return self
        shared = mesh._shared
        store = shared.values if self.connectivity else mesh._own
        try:
            return store[self.name]
        except KeyError:
            pass
        producer = shared.producers.pop(self.name, None) if self.connectivity else None
        if producer is None:
            value = self.func(mesh)
        else:
            value = producer()
            if isinstance(value, _Several):  # several values written in one pass
                for name, made in value.items():
                    if name != self.name:
                        shared.producers.pop(name, None)
                        store.setdefault(name, _frozen(made))
                value = value[self.name]
            value = _frozen(value)
        store[self.name] = value
        return value


def _connectivity(func: Callable[[Mesh], _T]) -> _Derived[_T]:
    """Decorator: a cached property that depends on the faces alone."""
    return _Derived(func, connectivity=True)


def _geometry(func: Callable[[Mesh], _T]) -> _Derived[_T]:
    """Decorator: a cached property that depends on the vertex positions."""
    return _Derived(func, connectivity=False)


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
        v = _as_vertices(vertices)
        corners, offsets = _compact(*_as_csr(faces), v.shape[0])
        self._init(v, corners, offsets)
        del corners, offsets  # (any wider copy made on the way is gone before validating)
        self._validate()

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
        rings: Rings | Callable[[], Rings | _Several] | None = None,
        size_counts: tuple[tuple[int, int], ...] | None = None,
        dual_of: Mesh | None = None,
        shared: _Connectivity | None = None,
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
        """
        if hasattr(self, "_vertices"):
            raise AttributeError("a Mesh is initialised once: meshes are immutable")
        if shared is None:
            shared = _Connectivity(_readonly(corners), _readonly(offsets))
            if twin is not None:
                if callable(twin):
                    shared.producers["twin"] = twin
                else:
                    shared.values["twin"] = _readonly(twin)
            if rings is not None:
                if callable(rings):
                    shared.producers["vertex_ring"] = rings
                else:
                    shared.values["vertex_ring"] = _frozen(tuple(rings))
            if size_counts is not None:
                shared.values["_size_counts"] = tuple(size_counts)
        elif corners is not shared.corners or offsets is not shared.offsets:
            raise ValueError("shared connectivity needs the very corners and offsets it holds")
        elif twin is not None or rings is not None or size_counts is not None:
            raise ValueError("twin, rings and size counts come with the shared connectivity")
        init = object.__setattr__
        init(self, "_vertices", _readonly(vertices))
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
        rings: Rings | Callable[[], Rings | _Several] | None = None,
        size_counts: tuple[tuple[int, int], ...] | None = None,
        dual_of: Mesh | None = None,
        shared: _Connectivity | None = None,
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
            The opposite half-edge of each half-edge, when the caller knows
            it (used only without validation, which derives the twins itself).
        validate : bool
            Check the mesh, as the constructor does.  With False the arrays
            are trusted as they are: nothing but the shape of ``vertices``
            and the ranges of the indices is checked (an index outside the
            arrays would make the compiled kernels read outside them), and
            a mesh that is not a closed oriented manifold gives wrong
            results or errors later (the operators refuse what they cannot
            handle, e.g. :func:`pentanb.dual` a vertex with fewer than 3
            edges).  For speed only, on arrays known to be good.

        Notes
        -----
        The arrays are always copied (a copy costs little next to deriving
        the half-edges): the mesh never aliases, nor freezes, the caller's
        arrays, so changing them afterwards cannot change the mesh.
        """
        if validate:
            v = _as_vertices(vertices)
            c = _csr_part(corners, "corners")  # copies: the caller's
            o = _csr_part(offsets, "offsets")  # arrays stay theirs
            _check_offsets(c, o)
            self = cls._new(v, *_compact(c, o, v.shape[0]))
            self._validate()
            return self
        v = np.array(vertices, dtype=np.float64)
        if v.ndim != 2 or v.shape[1] != 3:
            raise MeshError(f"vertices must be an (n, 3) array, got shape {v.shape}")
        c, o = _compact(_csr_part(corners, "corners"), _csr_part(offsets, "offsets"), v.shape[0])
        t = None if twin is None else _csr_part(twin, "twin")
        _check_ranges(c, o, t, v.shape[0])
        return cls._new(v, c, o, twin=None if t is None else t.astype(c.dtype))

    def with_vertices(self, vertices: ArrayLike) -> Mesh:
        """The same connectivity with other vertex positions (``(n, 3)`` float).

        The faces and everything derived from them alone are shared with
        this mesh (nothing is derived twice); ``vertices`` is copied.
        """
        v = _as_vertices(vertices)
        if v.shape != self._vertices.shape:
            raise MeshError(f"expected {self._vertices.shape} vertices, got {v.shape}")
        return type(self)._new(v, self._corners, self._offsets, shared=self._shared)

    # ------------------------------------------------------------------ pickling
    def __reduce__(self) -> tuple[Callable[..., Mesh], tuple[Any, ...]]:
        """Pickle (and copy) as the arrays plus the twins and rings already known.

        A producer an operator handed over is run now (no callable is
        pickled); other derived arrays are derived again after loading.
        """
        shared = self._shared
        known = {
            name: getattr(self, name)
            for name in ("twin", "vertex_ring")
            if name in shared.values or name in shared.producers
        }
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
        """Number of edges E (= H / 2 on a closed mesh)."""
        return int(self._corners.size // 2)

    @_connectivity
    def face_sizes(self) -> IntArray:
        """(m,) int: number of sides of every face."""
        return _readonly(np.diff(self._offsets))

    @_connectivity
    def _uniform_size(self) -> int:
        """k when every face has k sides, else 0."""
        return _uniform_size(self._offsets, self._corners.size)

    @_connectivity
    def valences(self) -> IntArray:
        """(n,) int: number of edges at every vertex."""
        counts = np.bincount(self._corners, minlength=self.n_vertices)
        return _readonly(counts.astype(self._corners.dtype, copy=False))

    @property
    def euler_characteristic(self) -> int:
        """V - E + F."""
        return self.n_vertices - self.n_edges + self.n_faces

    @_connectivity
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
    @_connectivity
    def halfedge_face(self) -> IntArray:
        """(H,) int: the face of every half-edge."""
        return _readonly(_halfedge_face(self._offsets, self._corners.size, self._uniform_size))

    @_connectivity
    def halfedge_slot(self) -> IntArray:
        """(H,) int: the position of every half-edge in its face (0 at the face's first corner).

        Half-edge ``h`` is ``offsets[halfedge_face[h]] + halfedge_slot[h]``.
        """
        h = np.arange(self.n_halfedges, dtype=self._corners.dtype)
        return _readonly(h - self._offsets[:-1][self.halfedge_face])

    @_connectivity
    def next(self) -> IntArray:
        """(H,) int: the next half-edge around the same face."""
        return _readonly(_next_of(self._offsets, self._corners.size, self._corners.dtype))

    @_connectivity
    def prev(self) -> IntArray:
        """(H,) int: the previous half-edge around the same face."""
        return _readonly(_prev_of(self._offsets, self._corners.size, self._corners.dtype))

    @property
    def tail(self) -> IntArray:
        """(H,) int: the vertex a half-edge leaves (= ``corners``)."""
        return self._corners

    @_connectivity
    def head(self) -> IntArray:
        """(H,) int: the vertex a half-edge reaches (``corners[next]``)."""
        k = self._uniform_size
        if k:
            return _readonly(_head(self._corners, self._offsets, k))
        return _readonly(self._corners[self.next])

    @_connectivity
    def twin(self) -> IntArray:
        """(H,) int: the opposite half-edge (same edge, other face)."""
        k = self._uniform_size
        twin = _pair_twins(self._corners, None if k else self.head, self.n_vertices, k)
        if twin is None:
            raise MeshError("the faces do not pair up into a closed, oriented manifold")
        return _readonly(twin)

    @_connectivity
    def _forward(self) -> NDArray[np.bool_]:
        """(H,) bool: ``tail < head``, the half-edge that numbers its edge."""
        return _readonly(self._corners < self.head)

    @_connectivity
    def halfedge_edge(self) -> IntArray:
        """(H,) int: the edge id of every half-edge.

        Edge ``e`` is numbered by the order of its half-edge with
        ``tail < head``; see :attr:`edges`.
        """
        primary = self._forward
        ids = np.cumsum(primary, dtype=self._corners.dtype)
        ids -= 1
        back = np.flatnonzero(~primary)
        ids[back] = ids[self.twin[back]]
        return _readonly(ids)

    @_connectivity
    def edge_halfedge(self) -> IntArray:
        """(E,) int: for every edge, its half-edge with ``tail < head`` (each edge once)."""
        return _readonly(np.flatnonzero(self._forward).astype(self._corners.dtype, copy=False))

    @_connectivity
    def edges(self) -> IntArray:
        """(E, 2) int: the edges as (smaller, larger) vertex pairs."""
        h = self.edge_halfedge
        return _readonly(np.stack([self._corners[h], self.head[h]], axis=1))

    @_connectivity
    def rotation(self) -> IntArray:
        """(H,) int: the next outgoing half-edge counter-clockwise around its tail.

        ``rotation[h] = twin[prev[h]]``.
        """
        return _readonly(_rotation(self.twin, self._offsets, self._uniform_size, self))

    @_connectivity
    def vertex_ring(self) -> Rings:
        """The outgoing half-edges of every vertex, counter-clockwise, in CSR form.

        Returns
        -------
        ring : (H,) int
            Half-edges, vertex after vertex, each vertex's in rotation order.
        ring_offsets : (n + 1,) int
            Vertex ``v``'s half-edges are ``ring[ring_offsets[v]:ring_offsets[v+1]]``.
        """
        ring, off = _vertex_rings(self.rotation, self._corners, self.valences)
        return _readonly(ring), _readonly(off)

    def _ring_faces(self) -> IntArray:
        """(H,) int: the face of every entry of :attr:`vertex_ring`, in its order.

        ``halfedge_face[vertex_ring[0]]``: the faces round every vertex in
        rotation order, which are the dual's faces (its corners).  An
        operator that knows its output's rings may write these with them
        (:class:`_Several`); they are then taken from the cache, once: the
        array becomes the dual's, and is not kept here as well.
        """
        made = self._shared.values.pop("_ring_faces", None)
        if made is not None:
            return made
        ring, _ = self.vertex_ring
        k = self._uniform_size
        if k:
            return _readonly(ring // k)
        jit = _jit.kernels(ring.size)
        return _readonly(jit.gather(self.halfedge_face, ring) if jit else self.halfedge_face[ring])

    def _faces_only(self) -> Any:
        """This mesh's faces without its positions (a :class:`_Faces`).

        For the producers an operator hands over with its output: they
        derive what they need from the faces (shared with this mesh, so
        nothing is derived twice) without keeping the positions alive.
        """
        return _Faces(self._shared, self.n_vertices)

    # ------------------------------------------------------------------ geometry
    @_geometry
    def _extent(self) -> float:
        """The largest absolute coordinate (an upper bound, for operator outputs).

        Operators place new points by affine combinations with non-negative
        weights, which never move a point outside the box of its input, so
        an output inherits its input's extent (see :meth:`_note_extent`).
        Above :data:`_SAFE_EXTENT` sums of coordinates could overflow, and
        the geometry is computed on positions scaled by a power of two
        (exact) instead.
        """
        v = self._vertices
        if v.size == 0:
            return 0.0
        return float(max(v.max(), -v.min()))

    def _note_extent(self, bound: float) -> None:
        """Record an upper bound of :attr:`_extent` known without a pass over the positions."""
        self._own.setdefault("_extent", float(bound))

    @_geometry
    def face_centroids(self) -> FloatArray:
        """(m, 3) float: the plain mean of each face's vertices."""
        means = _face_means(
            self._vertices, self._corners, self._offsets, self._uniform_size, self._extent
        )
        return _readonly(means)

    def face_means(self, values: ArrayLike) -> np.ndarray:
        """Average per-vertex values over every face.

        Parameters
        ----------
        values : (n,) or (n, d) float

        Returns
        -------
        (m,) or (m, d) float
            A new array (the caller's to keep).  Finite for any finite
            ``values``: sums that would overflow are taken on values scaled
            down by a power of two.

        Notes
        -----
        The corners are gathered in blocks of faces, so the memory beyond
        the result stays small whatever the mesh's size.
        """
        values = np.asarray(values, dtype=np.float64)
        flat = values.reshape(values.shape[0], -1)
        extent = float(np.abs(flat).max()) if flat.size else 0.0
        means = _face_means(flat, self._corners, self._offsets, self._uniform_size, extent)
        return means.reshape((self.n_faces,) + values.shape[1:])

    @_geometry
    def face_normals(self) -> FloatArray:
        """(m, 3) float: unit normals (Newell's method; zero for degenerate faces).

        Faces whose cross products would overflow or underflow (coordinates
        near 1e-150 or 1e150 and beyond) are computed again from their
        corners relative to the first, scaled per face by a power of two,
        so their normals neither vanish nor become NaN.
        """
        p = self._vertices[self._corners]
        q = self._vertices[self.head]
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            cross = np.cross(p, q)
            n = np.add.reduceat(cross, self._offsets[:-1], axis=0)
            length = np.linalg.norm(n, axis=1, keepdims=True)
        # lengths outside [2**-800, 2**800] may have lost everything to
        # underflow or overflow: those faces again, rescaled
        redo = np.flatnonzero(~((length[:, 0] >= 2.0**-800) & (length[:, 0] <= 2.0**800)))
        if redo.size:
            n[redo] = _scaled_newell(self._vertices, self._corners, self._offsets, redo)
            length = np.linalg.norm(n, axis=1, keepdims=True)
        return _readonly(np.divide(n, length, out=np.zeros_like(n), where=length > 0))

    @property
    def volume(self) -> float:
        """Signed enclosed volume (positive for outward-oriented faces).

        Each face is fanned from its centroid; the tetrahedra to the origin
        are summed.  Coordinates beyond 2**300 (or below 2**-300) are
        scaled by a power of two first, so the result is ``inf`` (or 0)
        only when the volume itself is beyond float64's range.
        """
        extent = self._extent
        if extent == 0 or 2.0**-300 < extent < 2.0**300:
            c = self.face_centroids[self.halfedge_face]
            p = self._vertices[self._corners]
            q = self._vertices[self.head]
            return float(np.einsum("ij,ij->", c, np.cross(p, q)) / 6.0)
        shift = int(np.frexp(extent)[1])
        small = self._rescaled(-shift)
        with np.errstate(over="ignore", under="ignore"):
            return float(np.ldexp(small.volume, 3 * shift))

    @property
    def bounds(self) -> FloatArray:
        """(2, 3) float: the lower and upper corners of the bounding box (read-only)."""
        return _readonly(np.stack([self._vertices.min(axis=0), self._vertices.max(axis=0)]))

    def fan_triangles(self) -> tuple[IntArray, IntArray]:
        """Fan triangulation of every face from its first corner (for drawing).

        Returns
        -------
        triangles : (H - 2m, 3) int
            Vertex indices, counter-clockwise like their faces: triangle
            ``k`` of face ``f`` is its corners ``0, k + 1, k + 2``.
        triangle_face : (H - 2m,) int
            The face each triangle comes from.

        See Also
        --------
        fan_triangle_corners : the same triangles as corner indices.
        """
        return self._fan

    @_connectivity
    def _fan(self) -> tuple[IntArray, IntArray]:
        tri_corners, tri_face = fan_triangle_corners(self._offsets)
        return _readonly(self._corners[tri_corners]), tri_face

    def component_labels_of_faces(self) -> IntArray:
        """(m,) int: the component label of every face (read-only)."""
        return _readonly(self.component_labels[self._corners[self._offsets[:-1]]])

    @_connectivity
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
        """Check that the mesh is a closed, oriented 2-manifold; raise MeshError if not.

        Every check runs first as a whole-array pass that only says whether
        the mesh is valid (:meth:`_valid`); only a mesh that fails one is
        checked again, in order, by :meth:`_validate_exactly`, which finds
        the first culprit and names it.  The twins and vertex rings the
        checks derive stay cached.
        """
        if not self._valid():
            self._validate_exactly()

    def _valid(self) -> bool:
        """Every check of :meth:`_validate_exactly`, without messages.

        Faces of at least 3 corners; indices in range; no vertex twice in a
        face; every directed edge once and with its opposite (one sort of
        packed 64-bit keys, :func:`_pair_twins`); at least 3 edges at every
        vertex (so none unused); no two faces sharing two edges (no face
        twice among a face's neighbours); one fan around every vertex (the
        vertex rings use every half-edge once).
        """
        n, c, o = self.n_vertices, self._corners, self._offsets
        if n == 0 or o.size < 2 or c.size == 0:
            return False
        k = self._uniform_size
        if (k < 3) if k else int(self.face_sizes.min()) < 3:
            return False
        if int(c.min()) < 0 or int(c.max()) >= n:
            return False
        if self._repeats_in_a_face(c, n):
            return False
        # the arrays below are not kept (only the twins and rings are): the
        # peak stays a few bytes per corner above the faces themselves
        twin = _pair_twins(c, None if k else self.head, n, k)
        if twin is None:
            return False
        if int(self.valences.min()) < 3:
            return False
        neighbour = twin // k if k else self.halfedge_face[twin]
        if self._repeats_in_a_face(neighbour, self.n_faces):
            return False
        del neighbour
        self._shared.values["twin"] = _readonly(twin)
        # (no rotation array: a column copy of the twins walks the rings a
        # little faster, but raises the peak of reading a 1,000,000-triangle
        # file from 2.9x to 3.3x the arrays read)
        if k:  # rotation[h] = twin[prev[h]], prev computed as needed (no array kept)
            ring, ring_off = _vertex_rings(_RotateUniform(twin, k), c, self.valences)
        else:
            ring, ring_off = _vertex_rings(_rotation(twin, o, k, self), c, self.valences)
        seen = np.zeros(c.size, dtype=bool)
        for a in range(0, ring.size, _BLOCK):
            seen[ring[a : a + _BLOCK]] = True
        if not seen.all():
            return False
        self._shared.values["vertex_ring"] = (_readonly(ring), _readonly(ring_off))
        return True

    def _repeats_in_a_face(self, values: np.ndarray, bound: int) -> bool:
        """Whether some face holds a value twice (``values``: one per corner, in ``[0, bound)``).

        Compares every corner with the corners 1, 2, ..., k // 2 places
        further round its face (every pair once), in whole-array passes;
        faces of more than 16 sides are checked by one sort instead.
        """
        k = self._uniform_size
        if k:
            if k <= 16:
                a = values.reshape(-1, k)
                for s in range(1, k // 2 + 1):
                    if (a[:, s:] == a[:, :-s]).any() or (a[:, :s] == a[:, k - s :]).any():
                        return True
                return False
        else:
            sizes = self.face_sizes
            top = int(sizes.max())
            if top <= 16:
                slot = self.halfedge_slot
                size = sizes[self.halfedge_face]
                h = np.arange(values.size, dtype=slot.dtype)
                for s in range(1, top // 2 + 1):
                    # s places further round the face (faces of more than s sides)
                    longer = size > s
                    p = h + s
                    p -= np.where(slot + s >= size, size, 0).astype(p.dtype, copy=False)
                    p = np.where(longer, p, h)
                    if ((values[p] == values) & longer).any():
                        return True
                return False
        key = self.halfedge_face.astype(np.int64) * np.int64(bound) + values
        key.sort()
        return bool((key[1:] == key[:-1]).any())

    def _validate_exactly(self) -> None:
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
        key = fid.astype(np.int64) * n + c
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
            from ._boundary import describe_boundary

            raise MeshError(
                f"edge ({u}, {w}) of face {int(fid[h])} has only one side "
                f"(a boundary): the mesh must be closed; it has {describe_boundary(c, head)}"
            )
        self._shared.values["twin"] = _readonly(twin)
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
        ring, _ = self.vertex_ring
        if not np.array_equal(np.sort(ring), np.arange(c.size)):
            # a vertex whose rotation orbit is shorter than its valence
            bad_v = _multi_fan_vertex(self.rotation, c, self.valences)
            raise MeshError(f"vertex {bad_v} is non-manifold: its faces form more than one fan")

    # ------------------------------------------------------------------ other libraries
    @classmethod
    def from_trimesh(cls, tmesh: Any) -> Mesh:
        """A mesh from a ``trimesh.Trimesh`` (see :func:`pentanb.io.from_trimesh`)."""
        from .io.convert import from_trimesh

        return from_trimesh(tmesh)

    def to_trimesh(self) -> Any:
        """This mesh as a ``trimesh.Trimesh``, polygons fanned into triangles
        (see :func:`pentanb.io.to_trimesh`)."""
        from .io.convert import to_trimesh

        return to_trimesh(self)


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
    "halfedge_face",
    "halfedge_slot",
    "next",
    "prev",
    "head",
    "twin",
    "_forward",
    "halfedge_edge",
    "edge_halfedge",
    "edges",
    "rotation",
    "vertex_ring",
):
    setattr(_Faces, _name, Mesh.__dict__[_name])
del _name


# ---------------------------------------------------------------------- helpers
_NOT_ARRAYS = (str, bytes, dict, set, frozenset)


def _as_vertices(vertices: ArrayLike, copy: bool = True) -> FloatArray:
    """``vertices`` as an (n, 3) float64 array of finite numbers (a copy unless ``copy=False``).

    Raises
    ------
    TypeError
        Not an array or a sequence (None, a string, a number, a dict), or
        complex numbers.
    MeshError
        Not (n, 3), entries that are not numbers, or a non-finite coordinate.
    """
    if not _array_like(vertices):
        raise TypeError(
            f"vertices must be an (n, 3) array of numbers, got {type(vertices).__name__}"
        )
    if np.iscomplexobj(vertices):
        raise TypeError("vertices must be real numbers, got complex numbers")
    try:
        v = np.array(vertices, dtype=np.float64, copy=True if copy else None)
    except (TypeError, ValueError) as exc:
        raise MeshError(f"vertices must be an (n, 3) array of numbers: {exc}") from None
    if v.ndim != 2 or v.shape[1] != 3:
        raise MeshError(f"vertices must be an (n, 3) array, got shape {v.shape}")
    bad = np.flatnonzero(~np.isfinite(v).all(axis=1))
    if bad.size:
        raise MeshError(f"vertex {int(bad[0])} has a non-finite coordinate {v[bad[0]].tolist()}")
    return v


def _array_like(x: Any) -> bool:
    """Whether ``x`` could be an array: an array of rank >= 1, a sequence or an iterable
    (not a string, bytes, dict or set)."""
    if isinstance(x, np.ndarray):
        return x.ndim > 0
    if x is None or isinstance(x, (*_NOT_ARRAYS, np.generic)):
        return False
    return hasattr(x, "__iter__") or hasattr(x, "__array__")


_INDEX_LIMIT = 1 << 63


def _as_indices(values: Any, what: str) -> IntArray | str:
    """``values`` as a flat int64 array (a new one), or what is wrong with them.

    Whole numbers of any integer or float type are taken; anything else,
    and integers int64 cannot hold (an index of 2**63 or more is out of
    range for any mesh), is described in the returned message, which
    starts with ``what`` (e.g. ``"face 3"`` or ``"corners"``).
    """
    a = np.asarray(values)
    if a.dtype.kind == "O":  # Python ints too large for int64, or non-numbers
        flat = a.ravel().tolist()
        for x in flat:
            if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
                if isinstance(x, (float, np.floating)) and float(x).is_integer():
                    continue
                return f"{what} has non-integer vertex indices {flat[:8]}"
        huge = [x for x in flat if not -_INDEX_LIMIT <= int(x) < _INDEX_LIMIT]
        if huge:
            return f"{what} uses vertex index {int(huge[0])}, out of range (larger than any mesh)"
        a = np.array([int(x) for x in flat], dtype=np.int64).reshape(a.shape)
    if a.dtype.kind == "u":
        if a.size and a.max() >= _INDEX_LIMIT:
            return f"{what} uses vertex index {int(a.max())}, out of range (larger than any mesh)"
    elif a.dtype.kind == "f":
        with np.errstate(invalid="ignore"):
            whole = np.isfinite(a) & (np.mod(a, 1) == 0)
        if not whole.all():
            return f"{what} has non-integer vertex indices {a.ravel()[:8].tolist()}"
        big = np.flatnonzero(np.abs(a.ravel()) >= float(_INDEX_LIMIT))
        if big.size:
            value = int(a.ravel()[big[0]])
            return f"{what} uses vertex index {value}, out of range (larger than any mesh)"
    elif a.dtype.kind != "i":
        return f"{what} has non-integer vertex indices {a.ravel()[:8].tolist()}"
    return np.array(a, dtype=np.int64).ravel()


def _as_csr(faces: Any) -> tuple[IntArray, IntArray]:
    """``faces`` (a sequence of index sequences, or an (m, k) array) as CSR ``(corners, offsets)``.

    Raises
    ------
    TypeError
        ``faces`` is not a sequence or an array (None, a string, a number).
    MeshError
        No faces, a face that is not a flat sequence, non-integer indices,
        or an index no mesh could have (2**63 or more).  Faces of fewer
        than 3 vertices (empty ones too) pass here and are refused, by
        number, when the mesh is validated.
    """
    if not _array_like(faces):
        raise TypeError(
            "faces must be a sequence of vertex-index sequences or an (m, k) int "
            f"array, got {type(faces).__name__}"
        )
    if not isinstance(faces, np.ndarray) and not hasattr(faces, "__len__"):
        faces = list(faces)  # an iterator or generator of faces
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        m, k = faces.shape
        if m == 0:
            raise MeshError("the mesh has no faces")
        indices = _as_indices(faces, "face")
        if isinstance(indices, str):
            rows = faces.reshape(m, -1)
            for f in range(m):  # name the first face at fault
                problem = _as_indices(rows[f], f"face {f}")
                if isinstance(problem, str):
                    integers = ": face indices must be integers" if "non-integer" in problem else ""
                    raise MeshError(problem + integers)
            raise MeshError(indices)  # pragma: no cover - a row is always at fault
        return indices, np.arange(m + 1, dtype=np.int64) * k
    if isinstance(faces, np.ndarray) and faces.ndim != 1:
        raise MeshError(
            f"faces must be a list of index sequences or an (m, k) array, got shape {faces.shape}"
        )
    if not isinstance(faces, np.ndarray) and len(faces) and len({_len(f) for f in faces}) == 1:
        # a list of faces of one size: one array conversion instead of one per face
        try:
            same = np.array(faces)
        except (TypeError, ValueError):
            pass
        else:
            if same.ndim == 2 and same.dtype.kind in "iuf":
                return _as_csr(same)
    sizes = []
    flat = []
    for f, face in enumerate(faces):
        try:
            a = np.asarray(face)
        except Exception:  # pragma: no cover - ragged nested input
            raise MeshError(f"face {f} is not a sequence of vertex indices") from None
        if a.ndim != 1:
            raise MeshError(f"face {f} is not a flat sequence of vertex indices")
        got = _as_indices(a, f"face {f}") if a.size else np.zeros(0, dtype=np.int64)
        if isinstance(got, str):
            raise MeshError(got)
        sizes.append(got.size)
        flat.append(got)
    if not sizes:
        raise MeshError("the mesh has no faces")
    offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    return np.concatenate(flat), offsets


#: Largest index an int32 index array holds.
_INT32_MAX = 2**31 - 1

#: Above this absolute coordinate, geometry is computed on positions scaled
#: down by a power of two (sums of up to 2**23 coordinates cannot overflow).
_SAFE_EXTENT = 2.0**1000


def _index_dtype(*counts: int) -> np.dtype:
    """int32 when every index of arrays of these sizes fits in it, else int64."""
    return np.dtype(np.int32) if max(counts, default=0) <= _INT32_MAX else np.dtype(np.int64)


def _check_offsets(corners: np.ndarray, offsets: np.ndarray) -> None:
    """MeshError unless ``offsets`` starts at 0, never falls and ends at ``len(corners)``."""
    if (
        offsets.size == 0
        or offsets[0] != 0
        or offsets[-1] != corners.size
        or (np.diff(offsets) < 0).any()
    ):
        raise MeshError("offsets must start at 0, rise, and end at len(corners)")


def _check_ranges(
    corners: np.ndarray, offsets: np.ndarray, twin: np.ndarray | None, n: int
) -> None:
    """MeshError unless every index of unchecked CSR arrays points inside the arrays.

    What :meth:`Mesh.from_csr` checks without validation: a few whole-array
    passes, so that no operator (numpy's or a compiled kernel, which does
    not check) reads outside an array.
    """
    _check_offsets(corners, offsets)
    if corners.size and (int(corners.min()) < 0 or int(corners.max()) >= n):
        bad = int(np.flatnonzero((corners < 0) | (corners >= n))[0])
        raise MeshError(f"corner {bad} is vertex {int(corners[bad])}, outside the {n:,} vertices")
    if twin is not None:
        if twin.size != corners.size:
            raise MeshError(
                f"twin must have one entry per corner ({corners.size:,}), got {twin.size:,}"
            )
        if twin.size and (int(twin.min()) < 0 or int(twin.max()) >= twin.size):
            bad = int(np.flatnonzero((twin < 0) | (twin >= twin.size))[0])
            raise MeshError(
                f"twin of half-edge {bad} is {int(twin[bad])}, outside the {twin.size:,} half-edges"
            )


def _compact(corners: np.ndarray, offsets: np.ndarray, n: int) -> tuple[IntArray, IntArray]:
    """``corners`` and ``offsets`` as int32 when they fit (see :func:`_index_dtype`).

    Values out of int32's range stay int64, so that validation still sees
    (and names) them instead of a wrapped-around index.  Always plain numpy
    arrays (a subclass such as trimesh's ``TrackedArray`` is not kept: its
    Python-level operators would slow every pass down).
    """
    corners, offsets = np.asarray(corners), np.asarray(offsets)
    dtype = _index_dtype(n, corners.size)
    if dtype == corners.dtype:
        return corners, offsets
    if corners.size and not (
        -_INT32_MAX <= int(corners.min()) and int(corners.max()) <= _INT32_MAX
    ):
        return corners, offsets
    if offsets.size and not (
        -_INT32_MAX <= int(offsets.min()) and int(offsets.max()) <= _INT32_MAX
    ):
        return corners, offsets
    return corners.astype(dtype), offsets.astype(dtype)


def _uniform_size(offsets: np.ndarray, n_corners: int) -> int:
    """k when the faces of these offsets all have k corners, else 0."""
    m = offsets.size - 1
    if m < 1:
        return 0
    k = int(offsets[1] - offsets[0])
    if k < 1 or k * m != n_corners or np.any(np.diff(offsets) != k):
        return 0
    return k


def _halfedge_face(offsets: np.ndarray, n_corners: int, k: int) -> IntArray:
    jit = _jit.kernels(n_corners)
    if jit is not None:  # the same array, each face's run written in one loop
        return jit.halfedge_face(offsets, n_corners)
    faces = np.arange(offsets.size - 1, dtype=offsets.dtype)
    return np.repeat(faces, k if k else np.diff(offsets))


def _shifted(a: np.ndarray, k: int, step: int) -> np.ndarray:
    """``a`` (one value per corner of k-gons) moved ``step`` places round every face.

    ``out[h] = a[next[h]]`` for ``step = 1``, ``a[prev[h]]`` for ``step = -1``:
    a copy column by column, without gathering.
    """
    rows = a.reshape(-1, k)
    out = np.empty_like(rows)
    if step == 1:
        out[:, :-1] = rows[:, 1:]
        out[:, -1] = rows[:, 0]
    else:
        out[:, 1:] = rows[:, :-1]
        out[:, 0] = rows[:, -1]
    return out.reshape(-1)


def _head(corners: np.ndarray, offsets: np.ndarray, k: int) -> IntArray:
    """(H,) the vertex every half-edge reaches, for faces that are all k-gons."""
    return _shifted(corners, k, 1)


def _rotation(twin: np.ndarray, offsets: np.ndarray, k: int, mesh: Any = None) -> IntArray:
    """(H,) ``twin[prev]``: the next outgoing half-edge counter-clockwise round its tail."""
    if k:
        return _shifted(twin, k, -1)
    prv = mesh.prev if mesh is not None else _prev_of(offsets, twin.size, twin.dtype)
    return twin[prv]


class _RotateUniform:
    """``rotation[h]`` of a mesh of k-gons from its twins, without a rotation array.

    ``rotate[cur]`` is ``twin[prev[cur]]``, ``prev[h]`` being ``h - 1``, or
    ``h + k - 1`` at the first corner of a face.
    """

    def __init__(self, twin: np.ndarray, k: int) -> None:
        self.twin, self.k = twin, k

    def __getitem__(self, cur: np.ndarray) -> np.ndarray:
        # the first corners: cur // k * k == cur (numpy divides by a constant
        # with a multiplication, 4x faster here than its remainder)
        first = cur // self.k
        first *= self.k
        first = first == cur
        prv = cur - 1
        prv[first] += self.k
        return self.twin[prv]


def _next_of(offsets: np.ndarray, n_corners: int, dtype: Any) -> IntArray:
    """(H,) the next half-edge round each face, from the offsets alone."""
    nxt = np.arange(1, n_corners + 1, dtype=dtype)
    nxt[offsets[1:] - 1] = offsets[:-1]
    return nxt


def _prev_of(offsets: np.ndarray, n_corners: int, dtype: Any) -> IntArray:
    """(H,) the previous half-edge round each face, from the offsets alone."""
    prv = np.arange(-1, n_corners - 1, dtype=dtype)
    prv[offsets[:-1]] = offsets[1:] - 1
    return prv


def _pair_twins(tail: np.ndarray, head: np.ndarray | None, n: int, k: int = 0) -> IntArray | None:
    """The twin of every half-edge of a closed oriented manifold, or None.

    Every half-edge ``h = (u, w)`` gets the key ``(min, max, u > w)`` of its
    undirected edge and direction, packed with ``h`` itself into one 64-bit
    integer: one sort of plain integers (numpy's vectorized sort, several
    times faster than an argsort) then puts the two halves of every edge
    side by side, the forward one first.  None when that pattern breaks (a
    directed edge used twice, a boundary edge): the caller then looks for
    the culprit (:func:`_match_twins`).  Beyond the twins, only the packed
    keys (8 bytes a half-edge) are allocated: keys are built, checked and
    unpacked in blocks.  ``head`` may be None when every face is a k-gon:
    it is then read block by block from ``tail``.

    When key and index need more than 63 bits (meshes of millions of
    vertices), the half-edges are first split by the high bits of their
    smaller vertex (a radix pass; both halves of an edge fall in the same
    part) and each part is sorted on its own.
    """
    H = tail.size
    if H % 2:
        return None
    jit = _jit.kernels(H)
    if jit is not None and n > 0:  # each half-edge's partner among its head's (compiled)
        got = jit.pair_twins(tail, tail[:0] if head is None else head, max(k, 1), n)
        return got if got.size == H else None
    twin = np.empty(H, dtype=tail.dtype)
    index_bits = max(int(H - 1).bit_length(), 1)
    vertex_bits = max(int(n - 1).bit_length(), 1)
    # a key (lo * n + hi) * 2 + flip with lo < 2**low_bits is below 2**(63 - index_bits)
    low_bits = 62 - index_bits - int(n).bit_length()
    if low_bits >= vertex_bits:
        return twin if _pair_part(tail, head, n, index_bits, None, None, twin, k) else None
    if head is None:
        head = _head(tail, np.empty(0), k)
    parts = vertex_bits - max(low_bits, 0)
    if low_bits < 1 or parts > 16:  # pragma: no cover - beyond 2**40 half-edges
        return _match_twins_argsort(tail, head, n, twin)
    part = (np.minimum(tail, head) >> low_bits).astype(np.uint16)
    order = np.argsort(part, kind="stable").astype(tail.dtype)  # radix sort: O(H)
    bounds = np.concatenate([[0], np.cumsum(np.bincount(part, minlength=1 << parts))])
    del part
    mask = (1 << low_bits) - 1
    for a, b in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
        if a == b:
            continue
        ids = order[a:b]
        if not _pair_part(tail[ids], head[ids], n, index_bits, ids, mask, twin):
            return None
    return twin


#: Elements per block of the block-wise passes: the temporaries of a pass
#: stay a few hundred kilobytes (in cache, and out of the peak memory).
_BLOCK = 1 << 13


def _pair_part(tail, head, n, index_bits, ids, mask, twin, k=0) -> bool:
    """Pair the half-edges of one part (see :func:`_pair_twins`); False if they do not pair.

    ``ids`` maps the part's half-edges to the mesh's (None: the whole mesh);
    ``mask`` keeps the low bits of the smaller vertex (None: all of it);
    ``head`` None: faces of ``k`` corners, heads read from ``tail``.
    """
    size = tail.size
    if size % 2:
        return False
    key = np.empty(size, dtype=np.int64)
    step = _BLOCK - _BLOCK % k if head is None else _BLOCK
    for a in range(0, size, step):
        t = tail[a : a + step]
        h = _head(t, np.empty(0), k) if head is None else head[a : a + step]
        lo = np.minimum(t, h)
        part = key[a : a + step]
        np.multiply(lo & mask if mask is not None else lo, np.int64(n), out=part)
        part += np.maximum(t, h)
        part <<= 1
        part |= t > h
        part <<= index_bits
        part |= np.arange(a, a + part.size, dtype=np.int64)
        del t, h, lo, part
    key.sort()
    # the two halves of every edge must sit side by side: keys 2K and 2K + 1,
    # which differ in their lowest bit only; then the low bits say which
    # half-edges they are
    low = np.int64((1 << index_bits) - 1)
    for a in range(0, size, _BLOCK):
        part = key[a : a + _BLOCK]
        pair = np.bitwise_xor(part[0::2], part[1::2])
        pair >>= index_bits
        if not (pair == 1).all():
            return False
        part &= low
        first, second = part[0::2], part[1::2]
        if ids is not None:
            first, second = ids[first], ids[second]
        twin[first] = second
        twin[second] = first
    return True


def _match_twins_argsort(tail, head, n, twin):  # pragma: no cover - huge meshes only
    lo = np.minimum(tail, head)
    key = (lo.astype(np.int64) * np.int64(n) + np.maximum(tail, head)) * 2 + (tail > head)
    order = np.argsort(key)
    skey = key[order]
    a, b = skey[0::2], skey[1::2]
    if (a & 1).any() or not np.array_equal(a + 1, b):
        return None
    twin[order[0::2]] = order[1::2]
    twin[order[1::2]] = order[0::2]
    return twin


def _face_means(
    values: np.ndarray, corners: np.ndarray, offsets: np.ndarray, k: int, extent: float
) -> FloatArray:
    """(m, d) the mean of ``values`` (n, d) over every face, in blocks of faces.

    The sums run in the order of the faces' corners, as numpy's
    ``reshape(m, k).sum(axis=1)`` (faces of k < 8 corners) or
    ``np.add.reduceat`` (mixed sizes) would add them, so the results are
    those of those whole-array expressions, bit for bit; only the memory
    they need is bounded (a block at a time).  Values beyond
    :data:`_SAFE_EXTENT` are scaled down by a power of two first (exact),
    so no sum overflows.
    """
    values = values.reshape(values.shape[0], -1)
    if extent >= _SAFE_EXTENT:
        shift = int(np.frexp(extent)[1]) - 1000
        out = _face_means(np.ldexp(values, -shift), corners, offsets, k, 0.0)
        out = np.ldexp(out, shift)
        if not np.isfinite(out).all():
            raise MeshError(
                f"coordinates up to {extent:.3g} are too large: a mean of them "
                "is not a finite float64"
            )
        return out
    m, d = offsets.size - 1, values.shape[1]
    if m == 0:
        return np.empty((m, d))
    if not values.flags.c_contiguous:
        values = np.ascontiguousarray(values)
    jit = _jit.kernels(corners.size)
    if jit is not None:  # the same sums in the same order, compiled
        if k and k < 8:
            return jit.face_means_uniform(values, corners, k)
        if not k:
            sizes = np.diff(offsets)
            if 3 <= int(sizes.min()) and int(sizes.max()) <= 129:
                return jit.face_means_mixed(values, corners, offsets)
    out = np.empty((m, d))
    if k and k < 8:
        block = _BLOCK
        corner_rows = corners.reshape(m, k)
        for a in range(0, m, block):
            rows = corner_rows[a : a + block]
            acc = out[a : a + block]
            np.take(values, rows[:, 0], axis=0, out=acc)
            for j in range(1, k):
                acc += values.take(rows[:, j], axis=0)
        out /= k
        return out
    if k:  # k >= 8: numpy's pairwise sums, one coordinate at a time
        block = max(1, (_BLOCK * 4) // k)
        for i in range(d):
            col = np.ascontiguousarray(values[:, i])
            for a in range(0, m, block):
                g = col.take(corners[a * k : (a + block) * k])
                out[a : a + block, i] = g.reshape(-1, k).sum(axis=1)
                del g
            del col
        out /= k
        return out
    # mixed sizes: np.add.reduceat adds a face's corners as a0 + (a1 + a2 + ...),
    # the sum in brackets from left to right while it has fewer than 8 terms
    # (pairwise beyond); the same order here, slot by slot over blocks of faces
    sizes = np.diff(offsets)
    a = 0
    while a < m:
        # blocks of at most _BLOCK faces and about 4 * _BLOCK corners
        b = int(np.searchsorted(offsets, offsets[a] + 4 * _BLOCK, side="right")) - 1
        b = min(max(b, a + 1), a + _BLOCK, m)
        size, start, acc = sizes[a:b], offsets[a:b], out[a:b]
        a = b
        np.take(values, corners[start + 1], axis=0, out=acc)
        top = int(size.max())
        for j in range(2, min(top, 8)):
            longer = np.flatnonzero(size > j)
            if longer.size == size.size:
                acc += values.take(corners[start + j], axis=0)
            else:
                acc[longer] += values.take(corners[start[longer] + j], axis=0)
        acc += values.take(corners[start], axis=0)
        long = np.flatnonzero(size > 8)  # 8 or more terms in the brackets: numpy's own sums
        if long.size:
            o = np.stack([start[long], start[long] + size[long]], axis=1).reshape(-1)
            h = np.repeat(o[0::2] - np.cumsum(np.r_[0, size[long][:-1]]), size[long])
            h += np.arange(h.size, dtype=h.dtype)
            g = values.take(corners[h], axis=0)
            acc[long] = np.add.reduceat(g, np.cumsum(np.r_[0, size[long][:-1]]), axis=0)
            del g, h, o
    out /= sizes[:, None]
    return out


def _scaled_newell(
    vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray, faces: np.ndarray
) -> FloatArray:
    """(len(faces), 3) Newell normals of some faces, safe from overflow and underflow.

    Each face's corners are scaled by a power of two to at most 1, taken
    relative to its first corner, and scaled again so that the largest of
    those differences is about 1: the cross products then neither
    overflow nor underflow, and the direction is the face's.
    """
    start, stop = offsets[faces].astype(np.int64), offsets[faces + 1].astype(np.int64)
    sizes = stop - start
    local = np.repeat(np.arange(faces.size), sizes)
    first = np.repeat(start, sizes)
    h = first + np.arange(local.size) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    p = vertices[corners[h]]

    def exponent(a: np.ndarray) -> np.ndarray:
        top = np.maximum.reduceat(np.abs(a).max(axis=1), np.cumsum(sizes) - sizes)
        return np.frexp(top)[1]

    p = np.ldexp(p, -exponent(p)[local][:, None])
    p -= p[np.cumsum(sizes) - sizes][local]
    p = np.ldexp(p, -exponent(p)[local][:, None])
    nxt = np.arange(local.size) + 1
    last = np.cumsum(sizes) - 1
    nxt[last] = last - sizes + 1
    return np.add.reduceat(np.cross(p, p[nxt]), np.cumsum(sizes) - sizes, axis=0)


def _csr_part(values: Any, name: str) -> IntArray:
    """A CSR array given to :meth:`Mesh.from_csr` as a new flat int64 array."""
    if values is None or isinstance(values, _NOT_ARRAYS):
        raise TypeError(f"{name} must be an array of integers, got {type(values).__name__}")
    got = _as_indices(values, name)
    if isinstance(got, str):
        raise MeshError(got.replace("vertex indices", "values").replace("vertex index", "value"))
    return got


def _len(face: Any) -> int:
    try:
        return len(face)
    except TypeError:
        return -1


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
    dtype = tail.dtype
    ring_off = np.zeros(n + 1, dtype=dtype)
    np.cumsum(valences, out=ring_off[1:])
    start = np.empty(n, dtype=dtype)
    # any outgoing half-edge per vertex: the last one written wins (in blocks:
    # numpy widens a scatter's index array, the whole of it at once otherwise)
    for a in range(0, tail.size, _BLOCK):
        start[tail[a : a + _BLOCK]] = np.arange(a, min(a + _BLOCK, tail.size), dtype=dtype)
    ring = np.empty(tail.size, dtype=dtype)
    if n == 0:
        return ring, ring_off
    # every vertex has at least `low` edges: the first `low` steps run over
    # all vertices in index order (writes in increasing order of address)
    low, top = int(valences.min()), int(valences.max())
    base = ring_off[:-1]
    cur = start
    for k in range(low):
        if k:
            cur = rotation[cur]
        ring[base + k] = cur
    if top == low:
        return ring, ring_off
    # the rest, for the vertices of more edges, by valence (a radix sort on
    # small ints): at step k the vertices still walking are a suffix
    more = np.flatnonzero(valences > low).astype(dtype)
    small = valences[more].astype(np.uint16 if top < 65536 else np.int64)
    order = np.argsort(small, kind="stable").astype(dtype)
    more = more[order]
    first = np.searchsorted(small[order], np.arange(top), side="right")
    cur = cur[more]
    base = base[more]
    for k in range(low, top):
        lo = int(first[k])
        c = rotation[cur[lo:]] if k else cur[lo:]
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


def _rebuild(
    vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray, known: dict[str, Any]
) -> Mesh:
    """Unpickle (or copy) a mesh: see :meth:`Mesh.__reduce__`."""
    return Mesh._new(
        vertices, corners, offsets, twin=known.get("twin"), rings=known.get("vertex_ring")
    )


def fan_triangle_corners(offsets: ArrayLike) -> tuple[IntArray, IntArray]:
    """Fan triangulation of CSR polygons, as corner indices (for drawing).

    Parameters
    ----------
    offsets : (m + 1,) int
        Polygon ``f`` has corners ``offsets[f]`` to ``offsets[f + 1] - 1``.

    Returns
    -------
    triangles : (T, 3) int
        Triangle ``k`` of polygon ``f`` is corners ``(o, o + k + 1, o + k + 2)``
        with ``o = offsets[f]``, counter-clockwise like the polygon;
        ``T = offsets[-1] - 2m``.
    triangle_face : (T,) int
        The polygon each triangle comes from.

    See Also
    --------
    Mesh.fan_triangles : the same triangles as vertex indices.
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    sizes = np.diff(offsets)
    k = int(sizes[0]) if sizes.size else 0
    if k >= 3 and int(sizes.min()) == k == int(sizes.max()):
        # one size: every face's triangles are one pattern shifted by its offset
        pattern = np.stack([np.zeros(k - 2, np.int64), np.arange(1, k - 1), np.arange(2, k)], 1)
        tris = (offsets[:-1, None, None] + pattern).reshape(-1, 3)
        tri_face = np.repeat(np.arange(sizes.size, dtype=np.int64), k - 2)
        return _readonly(tris), _readonly(tri_face)
    per = np.maximum(sizes - 2, 0)
    tri_face = np.repeat(np.arange(per.size, dtype=np.int64), per)
    start = offsets[:-1][tri_face]
    k = np.arange(tri_face.size, dtype=np.int64) - (np.cumsum(per) - per)[tri_face]
    tris = np.stack([start, start + k + 1, start + k + 2], axis=1)
    return _readonly(tris), _readonly(tri_face)


def check_mesh(mesh: object, op: str) -> Mesh:
    """``mesh`` itself, or a TypeError naming ``op`` when it is not a Mesh.

    Every operator, writer and position solver starts with it.
    """
    if not isinstance(mesh, Mesh):
        raise TypeError(f"{op} expects a pentanb.Mesh, got {type(mesh).__name__}")
    return mesh
