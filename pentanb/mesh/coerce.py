"""Array coercions shared by the Mesh constructor, the readers and the operators.

Everything that turns what a user hands over (lists, arrays of any dtype,
CSR arrays) into the arrays a :class:`~pentanb.mesh.Mesh` holds lives here,
with :class:`MeshError`, the error that names what is wrong.  Index arrays are
int32 when the counts allow it (fewer than 2**31 corners and vertices), int64
otherwise: half the memory and memory traffic for every mesh that fits in a
computer's memory.  Arithmetic on them that may exceed 2**31 (keys such as
``u * n + w``) must first convert to int64.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "MeshError",
    "IntArray",
    "FloatArray",
    "readonly",
    "frozen",
    "as_vertices",
    "as_csr",
    "as_csr_part",
    "compact",
    "index_dtype",
    "check_offsets",
    "check_ranges",
    "INT32_MAX",
]

IntArray = NDArray[np.signedinteger[Any]]
FloatArray = NDArray[np.float64]


class MeshError(ValueError):
    """A mesh is not a closed, consistently oriented 2-manifold polygon mesh,
    a file does not hold one, or an operation would be too large.

    The message names the offending face, edge, vertex, file line or size.
    """


def readonly(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


def frozen(value: Any) -> Any:
    """``value`` with every array in it made read-only (arrays, tuples of arrays)."""
    if isinstance(value, np.ndarray):
        return readonly(value)
    if isinstance(value, tuple):
        return tuple(frozen(x) for x in value)
    return value


_NOT_ARRAYS = (str, bytes, dict, set, frozenset)


def as_vertices(vertices: ArrayLike, copy: bool = True) -> FloatArray:
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


def as_csr(faces: Any) -> tuple[IntArray, IntArray]:
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
                return as_csr(same)
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
INT32_MAX = 2**31 - 1


def index_dtype(*counts: int) -> np.dtype:
    """int32 when every index of arrays of these sizes fits in it, else int64."""
    return np.dtype(np.int32) if max(counts, default=0) <= INT32_MAX else np.dtype(np.int64)


def check_offsets(corners: np.ndarray, offsets: np.ndarray) -> None:
    """MeshError unless ``offsets`` starts at 0, never falls and ends at ``len(corners)``."""
    if (
        offsets.size == 0
        or offsets[0] != 0
        or offsets[-1] != corners.size
        or (np.diff(offsets) < 0).any()
    ):
        raise MeshError("offsets must start at 0, rise, and end at len(corners)")


def check_ranges(corners: np.ndarray, offsets: np.ndarray, twin: np.ndarray | None, n: int) -> None:
    """MeshError unless every index of unchecked CSR arrays points inside the arrays.

    What :meth:`Mesh.from_csr` checks without validation: a few whole-array
    passes, so that no operator (numpy's or a compiled kernel, which does
    not check) reads outside an array.
    """
    check_offsets(corners, offsets)
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


def compact(corners: np.ndarray, offsets: np.ndarray, n: int) -> tuple[IntArray, IntArray]:
    """``corners`` and ``offsets`` as int32 when they fit (see :func:`index_dtype`).

    Values out of int32's range stay int64, so that validation still sees
    (and names) them instead of a wrapped-around index.  Always plain numpy
    arrays (a subclass such as trimesh's ``TrackedArray`` is not kept: its
    Python-level operators would slow every pass down).
    """
    corners, offsets = np.asarray(corners), np.asarray(offsets)
    dtype = index_dtype(n, corners.size)
    if dtype == corners.dtype:
        return corners, offsets
    if corners.size and not (-INT32_MAX <= int(corners.min()) and int(corners.max()) <= INT32_MAX):
        return corners, offsets
    if offsets.size and not (-INT32_MAX <= int(offsets.min()) and int(offsets.max()) <= INT32_MAX):
        return corners, offsets
    return corners.astype(dtype), offsets.astype(dtype)


def as_csr_part(values: Any, name: str) -> IntArray:
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
