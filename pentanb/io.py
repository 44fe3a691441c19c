"""Reading and writing OBJ and OFF files, polygon faces kept as they are.

``read(path)`` and ``write(mesh, path)`` choose the format by the file's
ending.  A round trip is exact: coordinates are written with ``repr``
precision (17 significant digits).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .mesh import Mesh, MeshError

__all__ = ["read", "write", "read_obj", "read_off", "write_obj", "write_off"]


def read(path: str | os.PathLike) -> Mesh:
    """Read a mesh from an ``.obj`` or ``.off`` file.

    Raises
    ------
    MeshError
        A malformed file (a bad number, a face index out of range, counts
        that do not match); the message names the file and line.  A file
        whose mesh is not a closed manifold raises the mesh's own error,
        prefixed with the file name.
    ValueError
        An unknown file ending.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".obj":
        return read_obj(path)
    if suffix == ".off":
        return read_off(path)
    raise ValueError(f"{path}: unknown mesh format {suffix!r}; use .obj or .off")


def write(mesh: Mesh, path: str | os.PathLike) -> None:
    """Write ``mesh`` to an ``.obj`` or ``.off`` file (chosen by the ending).

    The file is written to a temporary name first and renamed, so a failure
    leaves nothing half-written.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".obj":
        text = _obj_text(mesh)
    elif suffix == ".off":
        text = _off_text(mesh)
    else:
        raise ValueError(f"{path}: unknown mesh format {suffix!r}; use .obj or .off")
    tmp = path.with_name(path.name + ".part")
    try:
        tmp.write_text(text)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def write_obj(mesh: Mesh, path) -> None:
    """Write an OBJ file (``v`` and ``f`` lines, 1-based indices)."""
    write(mesh, Path(path).with_suffix(".obj") if Path(path).suffix.lower() != ".obj" else path)


def write_off(mesh: Mesh, path) -> None:
    """Write an OFF file."""
    write(mesh, Path(path).with_suffix(".off") if Path(path).suffix.lower() != ".off" else path)


def _fmt_vertices(v: np.ndarray, prefix: str) -> list[str]:
    return [f"{prefix}{x!r} {y!r} {z!r}" for x, y, z in v.tolist()]


def _face_lines(mesh: Mesh, prefix: str, base: int, with_size: bool) -> list[str]:
    lines = []
    for f in mesh.faces:
        idx = " ".join(str(i + base) for i in f.tolist())
        lines.append(f"{prefix}{len(f)} {idx}" if with_size else f"{prefix}{idx}")
    return lines


def _obj_text(mesh: Mesh) -> str:
    head = [f"# pentanb: {mesh.n_vertices} vertices, {mesh.n_faces} faces"]
    return (
        "\n".join(head + _fmt_vertices(mesh.vertices, "v ") + _face_lines(mesh, "f ", 1, False))
        + "\n"
    )


def _off_text(mesh: Mesh) -> str:
    head = ["OFF", f"{mesh.n_vertices} {mesh.n_faces} {mesh.n_edges}"]
    return (
        "\n".join(head + _fmt_vertices(mesh.vertices, "") + _face_lines(mesh, "", 0, True)) + "\n"
    )


def _mesh_or_error(path, vertices, faces) -> Mesh:
    try:
        return Mesh(vertices, faces)
    except MeshError as exc:
        raise MeshError(f"{path}: {exc}") from None


def read_obj(path) -> Mesh:
    """Read an OBJ file: ``v`` and ``f`` lines; ``f 1/2/3`` and negative
    (relative) indices are understood; all other lines are skipped."""
    vertices: list[list[float]] = []
    faces: list[list[int]] = []
    face_lines: list[int] = []
    with open(path) as fh:
        for lineno, line in enumerate(fh, 1):
            parts = line.split("#", 1)[0].split()
            if not parts:
                continue
            if parts[0] == "v":
                if len(parts) < 4:
                    raise MeshError(
                        f"{path}:{lineno}: a 'v' line needs 3 coordinates: {line.strip()!r}"
                    )
                try:
                    vertices.append([float(x) for x in parts[1:4]])
                except ValueError:
                    raise MeshError(f"{path}:{lineno}: bad number in {line.strip()!r}") from None
            elif parts[0] == "f":
                face = []
                for token in parts[1:]:
                    try:
                        i = int(token.split("/", 1)[0])
                    except ValueError:
                        raise MeshError(f"{path}:{lineno}: bad face index {token!r}") from None
                    if i > 0:
                        i -= 1  # may refer to a vertex defined further down
                    elif i < 0:
                        i += len(vertices)
                        if i < 0:
                            raise MeshError(
                                f"{path}:{lineno}: face index {token} out of range "
                                "(a relative index before the first vertex; "
                                f"{len(vertices)} vertices so far)"
                            )
                    else:
                        raise MeshError(f"{path}:{lineno}: face index 0 (OBJ counts from 1)")
                    face.append(i)
                faces.append(face)
                face_lines.append(lineno)
    if not faces:
        raise MeshError(f"{path}: no faces")
    for face, lineno in zip(faces, face_lines):
        bad = [i for i in face if i >= len(vertices)]
        if bad:
            raise MeshError(
                f"{path}:{lineno}: face index {bad[0] + 1} out of range "
                f"({len(vertices)} vertices in the file)"
            )
    return _mesh_or_error(path, vertices, faces)


def read_off(path) -> Mesh:
    """Read an OFF file (header ``OFF``, counts, vertices, then ``k i1 .. ik`` faces)."""
    with open(path) as fh:
        lines = [(n, l.split("#", 1)[0].split()) for n, l in enumerate(fh, 1)]
    lines = [(n, p) for n, p in lines if p]
    if not lines or not lines[0][1][0].upper().endswith("OFF"):
        raise MeshError(f"{path}:1: not an OFF file (no 'OFF' header)")
    head = lines[0][1][1:]
    rest = lines[1:]
    if not head:
        if not rest:
            raise MeshError(f"{path}: missing the vertex and face counts")
        head_line, head = rest[0]
        rest = rest[1:]
    else:
        head_line = lines[0][0]
    try:
        nv, nf = int(head[0]), int(head[1])
    except (ValueError, IndexError):
        raise MeshError(f"{path}:{head_line}: bad counts line {' '.join(head)!r}") from None
    if len(rest) != nv + nf:
        raise MeshError(
            f"{path}: header says {nv} vertices and {nf} faces "
            f"({nv + nf} lines) but the file has {len(rest)} data lines"
        )
    vertices = []
    for lineno, parts in rest[:nv]:
        try:
            if len(parts) < 3:
                raise ValueError
            vertices.append([float(x) for x in parts[:3]])
        except ValueError:
            raise MeshError(f"{path}:{lineno}: bad vertex line {' '.join(parts)!r}") from None
    faces = []
    for lineno, parts in rest[nv:]:
        try:
            k = int(parts[0])
            idx = [int(x) for x in parts[1 : 1 + k]]
        except (ValueError, IndexError):
            raise MeshError(f"{path}:{lineno}: bad face line {' '.join(parts)!r}") from None
        if len(idx) != k:
            raise MeshError(f"{path}:{lineno}: face says {k} vertices but lists {len(idx)}")
        bad = [i for i in idx if not 0 <= i < nv]
        if bad:
            raise MeshError(f"{path}:{lineno}: face index {bad[0]} out of range ({nv} vertices)")
        faces.append(idx)
    return _mesh_or_error(path, vertices, faces)
