"""Meshes to and from trimesh and meshio (each imported only when called).

``pip install pentanb[convert]`` installs both.  trimesh holds triangles
only, so :func:`to_trimesh` fans every polygon into triangles; meshio holds
polygons in blocks of one type, so :func:`to_meshio` cuts the faces into
runs of one size, in order, and :func:`from_meshio` joins the blocks in
order again: a pentanb -> meshio -> pentanb round trip gives the same mesh.
"""

from __future__ import annotations

import importlib
import warnings
from typing import Any

import numpy as np

from ..mesh import Mesh, MeshError
from ._common import IgnoredDataWarning, check_mesh

__all__ = ["from_trimesh", "to_trimesh", "from_meshio", "to_meshio"]

#: meshio's names of the surface cell types pentanb reads, by number of corners.
MESHIO_POLYGONS = {"triangle": 3, "quad": 4, "polygon": None}
#: meshio cell types that are points and lines: skipped by :func:`from_meshio`, with a warning.
MESHIO_SKIPPED = ("vertex", "line", "line3")


def _need(module: str, caller: str) -> Any:
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ImportError(
            f"{caller} needs the {module} package: pip install {module} "
            "(or pip install pentanb[convert])"
        ) from None


def from_trimesh(tmesh: Any) -> Mesh:
    """A :class:`~pentanb.Mesh` from a ``trimesh.Trimesh``.

    The vertices and triangles are taken as they are (no merging): a
    trimesh loaded with ``process=False`` from a file with duplicated
    corners is refused, as is any triangle soup that is not an oriented
    2-manifold (closed, or open with boundary loops);
    ``trimesh.Trimesh(..., process=True)`` (trimesh's default) merges
    coincident vertices first.

    Parameters
    ----------
    tmesh : trimesh.Trimesh

    Returns
    -------
    Mesh
        The trimesh's vertices, ``(n, 3)`` float, and triangles, in order.

    Raises
    ------
    TypeError
        ``tmesh`` is not a trimesh.Trimesh (or anything with ``vertices`` and
        ``faces``).
    MeshError
        The triangles are not an oriented 2-manifold, closed or with boundary
        (the mesh's message).
    """
    if not (hasattr(tmesh, "vertices") and hasattr(tmesh, "faces")) or isinstance(tmesh, Mesh):
        raise TypeError(f"from_trimesh expects a trimesh.Trimesh, got {type(tmesh).__name__}")
    try:
        return Mesh(np.asarray(tmesh.vertices), np.asarray(tmesh.faces))
    except MeshError as exc:
        raise MeshError(f"the trimesh is not an oriented 2-manifold: {exc}") from None


def to_trimesh(mesh: Mesh) -> Any:
    """A ``trimesh.Trimesh`` of ``mesh`` (``process=False``: nothing merged or reordered).

    Every polygon is fanned from its first corner (:meth:`Mesh.fan_triangles`);
    ``face_attributes["polygon"]`` holds the polygon each triangle comes from.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    trimesh.Trimesh
        Its ``vertices`` are ``(n, 3)`` float, its ``faces`` ``(t, 3)`` int.
    """
    check_mesh(mesh, "to_trimesh")
    trimesh = _need("trimesh", "to_trimesh")
    triangles, polygon = mesh.fan_triangles()
    return trimesh.Trimesh(
        vertices=np.array(mesh.vertices),
        faces=np.array(triangles),
        face_attributes={"polygon": np.array(polygon)},
        process=False,
    )


def from_meshio(mmesh: Any) -> Mesh:
    """A :class:`~pentanb.Mesh` from a ``meshio.Mesh`` (e.g. ``meshio.read(path)``).

    The ``triangle``, ``quad`` and ``polygon`` cell blocks are the faces, in
    the order of the blocks; ``vertex`` and ``line`` blocks are skipped with
    a warning.  Volume cells (tetrahedra, hexahedra, ...) and higher-order
    faces are refused: a pentanb mesh is a polygon surface.

    Parameters
    ----------
    mmesh : meshio.Mesh

    Returns
    -------
    Mesh
        The points, ``(n, 3)`` float, and the faces of the polygon blocks, in order.

    Raises
    ------
    TypeError
        ``mmesh`` is not a meshio.Mesh (anything with ``points`` and ``cells``).
    MeshError
        Points that are not 3-D, cells that are not polygons, no faces, or
        faces that are not an oriented 2-manifold, closed or with boundary
        (the mesh's message).
    """
    if not (hasattr(mmesh, "points") and hasattr(mmesh, "cells")):
        raise TypeError(f"from_meshio expects a meshio.Mesh, got {type(mmesh).__name__}")
    try:
        points = np.asarray(mmesh.points, dtype=np.float64)
    except OverflowError:
        raise MeshError("the meshio mesh has a point coordinate too large for float64") from None
    except (TypeError, ValueError) as exc:
        raise TypeError(f"the meshio mesh's points must be numbers: {exc}") from None
    if points.ndim != 2 or points.shape[1] != 3:
        raise MeshError(f"the meshio mesh's points must be (n, 3), got shape {points.shape}")
    blocks: list[np.ndarray] = []
    skipped: list[str] = []
    refused: list[str] = []
    for block in mmesh.cells:
        kind, data = block.type, np.asarray(block.data)
        if kind in MESHIO_POLYGONS:
            k = MESHIO_POLYGONS[kind]
            if data.ndim != 2 or (k is not None and data.shape[1] != k):
                raise MeshError(f"a meshio {kind!r} block of shape {data.shape}")
            blocks.append(_cell_indices(data, kind, len(blocks)))
        elif kind in MESHIO_SKIPPED:
            skipped.append(kind)
        else:
            refused.append(kind)
    if refused:
        raise MeshError(
            f"the meshio mesh has {', '.join(sorted(set(refused)))} cells; a pentanb mesh is a "
            "polygon surface (triangle, quad and polygon cells only; extract the boundary "
            "surface of a volume mesh first)"
        )
    if skipped:
        warnings.warn(
            f"from_meshio: {', '.join(sorted(set(skipped)))} cells skipped (not faces)",
            IgnoredDataWarning,
            stacklevel=2,
        )
    if not blocks:
        raise MeshError("the meshio mesh has no triangle, quad or polygon cells")
    sizes = np.concatenate([np.full(b.shape[0], b.shape[1], dtype=np.int64) for b in blocks])
    corners = np.concatenate([b.reshape(-1) for b in blocks]).astype(np.int64)
    offsets = np.zeros(sizes.size + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    try:
        return Mesh.from_csr(points, corners, offsets)
    except MeshError as exc:
        raise MeshError(f"the meshio mesh is not an oriented 2-manifold: {exc}") from None


def _cell_indices(data: np.ndarray, kind: str, block: int) -> np.ndarray:
    """A meshio cell block's indices as int64: integers as they are, floats
    only if every one is a whole number (never truncated)."""
    if data.dtype.kind in "iu":
        if data.dtype == np.uint64 and data.size and data.max() >= 1 << 62:
            raise MeshError(
                f"meshio cell block {block} ({kind!r}): index {data.max()} out of range"
            )
        return data.astype(np.int64)
    if data.dtype.kind != "f":
        raise TypeError(
            f"meshio cell block {block} ({kind!r}) holds {data.dtype} values; cell indices "
            "must be integers"
        )
    with np.errstate(invalid="ignore"):
        ok = (data == np.floor(data)) & (np.abs(data) < 1 << 62)
    if not ok.all():
        at = np.argwhere(~ok)[0]
        value = float(data[tuple(at)])
        why = (
            "out of range"
            if value == np.floor(value)
            else "not a whole number (float cell indices are taken only when every one is)"
        )
        raise MeshError(
            f"meshio cell block {block} ({kind!r}), cell {int(at[0])}: index {value!r} is {why}"
        )
    return data.astype(np.int64)


def to_meshio(mesh: Mesh) -> Any:
    """A ``meshio.Mesh`` of ``mesh``: faces in runs of one size, in order.

    Triangles become ``triangle`` blocks, quads ``quad`` blocks, other
    polygons ``polygon`` blocks (one block per run of faces of one size, so
    the faces keep their order).

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    meshio.Mesh
        Its ``points`` are ``(n, 3)`` float.
    """
    check_mesh(mesh, "to_meshio")
    meshio = _need("meshio", "to_meshio")
    sizes = mesh.face_sizes
    change = np.flatnonzero(np.diff(sizes)) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [sizes.size]])
    cells = []
    for a, b in zip(starts.tolist(), ends.tolist()):
        k = int(sizes[a])
        data = mesh.corners[mesh.offsets[a] : mesh.offsets[b]].reshape(b - a, k)
        cells.append(({3: "triangle", 4: "quad"}.get(k, "polygon"), np.array(data)))
    return meshio.Mesh(np.array(mesh.vertices), cells)
