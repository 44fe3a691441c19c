"""How operators, readers and drawing code build meshes and read what a mesh has cached.

Code outside :mod:`pentanb.mesh` never touches a :class:`~pentanb.mesh.Mesh`'s
private members; it goes through these functions.  The one way to make a
mesh without validation is :func:`trusted`, for outputs that are valid by
construction (every operator's).  The readers, which hand over arrays they
have just made, use :func:`adopted` (validated, not copied).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any, cast

import numpy as np

from .coerce import IntArray, as_vertices
from .core import Mesh, Rings, Several
from .geometry import face_means
from .validate import validate

__all__ = [
    "trusted",
    "adopted",
    "faces_only",
    "uniform_size",
    "size_counts",
    "forward",
    "ring_faces",
    "extent",
    "face_centroids_into",
    "note_extent",
    "dual_source_offsets",
    "dual_again",
    "rescaled",
    "loop_offsets",
    "note_boundary",
    "note_open_dual",
    "open_dual_record",
    "Room",
    "note_room",
    "room",
]


def trusted(
    vertices: np.ndarray,
    corners: np.ndarray,
    offsets: np.ndarray,
    *,
    twin: IntArray | Callable[[], IntArray | Several] | None = None,
    rings: Rings | Callable[[], Rings | Several] | None = None,
    size_counts: tuple[tuple[int, int], ...] | None = None,
    dual_of: Mesh | None = None,
    closed: bool = False,
) -> Mesh:
    """The internal constructor: a mesh from arrays the package itself made.

    No validation and no copy: the arrays become the mesh's, read-only.

    Parameters
    ----------
    vertices : (n, 3) float
    corners : (H,) int
    offsets : (m + 1,) int
        The faces in CSR form, of the index dtype the counts call for
        (:func:`pentanb.mesh.coerce.index_dtype`).
    twin : (H,) int, or a zero-argument callable returning it, optional
        The output's twins when the caller knows them; a callable runs when
        the twins are first asked for.  For an open output the callable
        returns a :class:`~pentanb.mesh.core.Several` of ``twin`` and
        ``_boundary`` (the boundary half-edges loop after loop and the
        loops' offsets, as :attr:`Mesh.boundary_halfedges` records them).
    rings : ((H,) int, (n + 1,) int), or a callable returning them, optional
        The vertex rings (:attr:`Mesh.vertex_ring`), likewise; the callable
        may return a :class:`~pentanb.mesh.core.Several` holding them and
        other connectivity written in the same pass (``_ring_faces``, the
        dual's corners).
    size_counts : ((size, faces), ...), optional
        The face-size histogram by ascending size, when the caller knows it.
    dual_of : Mesh, optional
        The mesh this one is the dual of: the dual of this mesh then reuses
        that mesh's connectivity (:func:`dual_again`).  Closed meshes only.
    closed : bool
        True when the faces are known to close up (an output of a closed
        input): :attr:`Mesh.is_closed` and :attr:`Mesh.n_edges` then need
        no pass over the twins.  Never True for an open mesh.

    Returns
    -------
    Mesh
    """
    return Mesh._new(
        vertices,
        corners,
        offsets,
        twin=cast("IntArray | Callable[[], IntArray] | None", twin),  # (a Several is cached whole)
        rings=rings,
        size_counts=size_counts,
        dual_of=dual_of,
        closed=closed,
    )


def adopted(vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray) -> Mesh:
    """A validated mesh from arrays a reader has just made (not copied).

    Parameters
    ----------
    vertices : (n, 3) float
    corners : (H,) int
    offsets : (m + 1,) int

    Returns
    -------
    Mesh

    Raises
    ------
    MeshError
        What the constructor refuses, naming the culprit.
    """
    v = as_vertices(vertices, copy=False)
    mesh = Mesh._new(v, corners, offsets)
    validate(mesh)
    return mesh


def faces_only(mesh: Mesh) -> Any:
    """``mesh``'s faces without its positions (the connectivity properties of a Mesh).

    For the producers an operator hands over with its output: they derive
    what they need from the faces (shared with ``mesh``, so nothing is
    derived twice) without keeping the positions alive.
    """
    return mesh._faces_only()


def faces_keeping(mesh: Mesh, names: tuple[str, ...]) -> Any:
    """``mesh``'s faces with only the named connectivity it has derived (twins,
    boundary, ...), for a producer that may run an iteration later: holding
    :func:`faces_only` instead would keep all of ``mesh``'s cached
    connectivity alive until then."""
    return mesh._faces_keeping(names)


def uniform_size(mesh: Any) -> int:
    """k when every face of ``mesh`` (a Mesh or its :func:`faces_only`) has k sides, else 0."""
    return int(mesh._uniform_size)


def size_counts(mesh: Mesh) -> tuple[tuple[int, int], ...]:
    """``((n, number of n-gons), ...)`` by n, counted once per connectivity."""
    return mesh._size_counts


def forward(mesh: Any) -> np.ndarray:
    """(H,) bool: ``tail < head``, the half-edge that numbers its edge."""
    return mesh._forward


def ring_faces(mesh: Mesh) -> IntArray:
    """(H,) int: the face of every entry of :attr:`Mesh.vertex_ring`, in its order.

    The dual's corners; taken from the cache once when an operator wrote
    them with its output's rings.
    """
    return mesh._ring_faces()


def face_centroids_into(mesh: Mesh, out: np.ndarray) -> np.ndarray:
    """Write :attr:`Mesh.face_centroids` into ``out`` ((m, 3) float64, C-contiguous).

    Copied when ``mesh`` has them; else computed there (the same numbers)
    and not kept by ``mesh``: for an operator whose output's vertices
    start with them (the dual of an open mesh), so that they are not made
    and then copied.
    """
    made = mesh._own.get("face_centroids")
    if made is not None:
        out[...] = made
        return out
    return face_means(
        mesh._vertices, mesh._corners, mesh._offsets, mesh._uniform_size, mesh._extent, out
    )


def written_ring_faces(mesh: Mesh) -> IntArray | None:
    """The face of every entry of an open ``mesh``'s vertex rings (a hole
    half-edge's: any), when the operator that made it wrote them with its
    rings; taken (the array becomes the caller's), else None.  Ask for
    :attr:`Mesh.vertex_ring` first."""
    return mesh._shared.values.pop("_ring_faces", None)


def extent(mesh: Mesh) -> float:
    """The largest absolute coordinate of ``mesh`` (an upper bound for operator outputs)."""
    return float(mesh._extent)


def note_extent(mesh: Mesh, bound: float) -> None:
    """Record an upper bound of :func:`extent` known without a pass over the positions."""
    mesh._note_extent(bound)


def dual_source_offsets(mesh: Mesh) -> IntArray | None:
    """The offsets of the mesh ``mesh`` is the dual of (its face sizes are
    ``mesh``'s valences), or None when ``mesh`` was not built as a dual."""
    source = mesh._dual_source
    return None if source is None else source.offsets


def dual_again(mesh: Mesh) -> Mesh | None:
    """The dual of ``mesh`` when it was built as the dual of a mesh M, else None.

    Its faces are M's faces in M's order, with all M has derived; its
    vertices are ``mesh``'s face centroids.
    """
    return mesh._dual_again()


def rescaled(mesh: Mesh, shift: int) -> Mesh:
    """The same faces (shared) with every position times ``2**shift`` (exact).

    Raises
    ------
    MeshError
        When a scaled position is not finite.
    """
    return mesh._rescaled(shift)


def loop_offsets(mesh: Any) -> IntArray:
    """(L + 1,) int: loop ``i`` of ``mesh`` (a Mesh or its :func:`faces_only`) is
    ``mesh.boundary_halfedges[offsets[i]:offsets[i + 1]]`` (``[0]`` when closed)."""
    return mesh._boundary[1]


def note_boundary(mesh: Mesh, producer: Callable[[], tuple[IntArray, IntArray]]) -> None:
    """Hand over a producer of ``mesh``'s boundary record (:attr:`Mesh.boundary_halfedges`
    and its loop offsets), run instead of pairing the twins when the boundary is
    first asked for.  For an operator's open output whose loops it knows."""
    shared = mesh._shared
    if "_boundary" not in shared.values:
        shared.producers.setdefault("_boundary", producer)


def note_open_dual(mesh: Mesh, record: Any) -> None:
    """Record how the open mesh ``mesh`` was built as a dual (:func:`open_dual_record`)."""
    mesh._shared.values["_open_dual"] = record


def open_dual_record(mesh: Mesh) -> Any:
    """What :func:`note_open_dual` recorded with ``mesh``'s faces, or None."""
    return mesh._shared.values.get("_open_dual")


class Room:
    """Spare entries after an open mesh's face arrays, for its dual of a dual.

    The dual of the open dual of a mesh M has M's faces, as they are, then a
    few faces along the boundary (a quad along every boundary half-edge and
    one at every corner).  An operator that makes an open M may allocate
    M's corners and offsets as the first entries of longer buffers; the
    dual of M's dual then writes its boundary faces after M's and shares
    the buffers, as the dual of a closed dual shares its source's faces,
    instead of copying every corner.  M's own arrays are views of the
    first entries and never change.

    The room goes to one taker only (the first to ask, under a lock): a
    second dual of a dual of M (made from positions of its own, say) copies.

    Parameters
    ----------
    corners, offsets : (H + r,) and (m + 1 + s,) int, writable
        The buffers M's corners and offsets are the first H and m + 1
        entries of.
    """

    __slots__ = ("_corners", "_offsets", "_lock", "_taken")

    def __init__(self, corners: np.ndarray, offsets: np.ndarray) -> None:
        self._corners, self._offsets = corners, offsets
        self._lock = threading.Lock()
        self._taken = False

    def take(
        self, n_corners: int, n_offsets: int, dtype: np.dtype
    ) -> tuple[np.ndarray, np.ndarray] | None:
        """The first ``n_corners`` and ``n_offsets`` entries of the buffers
        (writable views, M's faces first), or None when they are shorter, of
        another dtype, or were taken already."""
        c, o = self._corners, self._offsets
        if c.size < n_corners or o.size < n_offsets or c.dtype != dtype or o.dtype != dtype:
            return None
        with self._lock:
            if self._taken:
                return None
            self._taken = True
        return c[:n_corners], o[:n_offsets]


def _starts(view: np.ndarray, buffer: np.ndarray) -> bool:
    """Whether ``view`` is the first entries of ``buffer`` (contiguous, same dtype)."""
    return (
        view.dtype == buffer.dtype
        and view.ndim == buffer.ndim == 1
        and view.flags.c_contiguous
        and buffer.flags.c_contiguous
        and buffer.flags.writeable
        and view.size <= buffer.size
        and view.ctypes.data == buffer.ctypes.data
    )


def note_room(mesh: Mesh, corners: np.ndarray, offsets: np.ndarray) -> None:
    """Record that ``mesh``'s corners and offsets are the first entries of the
    buffers ``corners`` and ``offsets`` (:class:`Room`); nothing is recorded
    when they are not (an operator's arrays converted to another dtype)."""
    if _starts(mesh._corners, corners) and _starts(mesh._offsets, offsets):
        mesh._shared.values.setdefault("_room", Room(corners, offsets))


def room(mesh: Any) -> Room | None:
    """The :class:`Room` after the faces of ``mesh`` (a Mesh or its
    :func:`faces_only`), or None."""
    return mesh._shared.values.get("_room")
