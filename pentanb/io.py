"""Reading and writing OBJ and OFF files, polygon faces kept as they are.

``read(path)`` and ``write(mesh, path)`` choose the format by the file's
ending (``.obj`` or ``.off``, any case) or by ``format=``; ``write`` writes
exactly the path it is given, or refuses before writing anything.  A round
trip is exact: coordinates are written with ``repr`` precision (17
significant digits).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .mesh import Mesh, MeshError

__all__ = ["read", "write", "read_obj", "read_off", "write_obj", "write_off", "FORMATS"]

#: The file formats, by the suffix that names them.
FORMATS = {".obj": "obj", ".off": "off"}


def _format(path: Path, format: str | None) -> str:
    """The format to use for ``path``: ``format`` if given, else the suffix's.

    Raises
    ------
    ValueError
        An unknown ``format``; no ``format`` and a suffix that names none (the
        message names the suffix and the known ones); or a ``format`` that
        contradicts a known suffix.
    """
    known = ", ".join(FORMATS)
    suffix = path.suffix.lower()
    from_suffix = FORMATS.get(suffix)
    if format is None:
        if from_suffix is None:
            shown = repr(suffix) if suffix else "no suffix"
            raise ValueError(
                f"{path}: unknown mesh format ({shown}); use a file ending in {known} "
                "(any case) or pass format='obj' or format='off'"
            )
        return from_suffix
    if not isinstance(format, str) or format.lower().lstrip(".") not in FORMATS.values():
        raise ValueError(f"unknown mesh format {format!r}; known formats: obj, off")
    chosen = format.lower().lstrip(".")
    if from_suffix is not None and from_suffix != chosen:
        raise ValueError(f"{path}: the name ends in {suffix!r} but format={format!r} was asked for")
    return chosen


def read(path: str | os.PathLike, format: str | None = None) -> Mesh:
    """Read a mesh from an OBJ or OFF file.

    Parameters
    ----------
    path : str or path-like
    format : {"obj", "off"}, optional
        The file's format; default: from the suffix of ``path`` (``.obj`` or
        ``.off``, any case).

    Raises
    ------
    MeshError
        A malformed file (a bad number, a face index out of range, counts
        that do not match); the message names the file and line.  A file
        whose mesh is not a closed manifold raises the mesh's own error,
        prefixed with the file name.
    ValueError
        An unknown suffix (without ``format``) or format.
    """
    path = Path(path)
    return read_obj(path) if _format(path, format) == "obj" else read_off(path)


def write(mesh: Mesh, path: str | os.PathLike, format: str | None = None) -> None:
    """Write ``mesh`` to exactly ``path``, as OBJ or OFF.

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
        The file to write; its name is used as given.
    format : {"obj", "off"}, optional
        The format; default: from the suffix of ``path`` (``.obj`` or
        ``.off``, any case).  Needed for any other name (``model.v2``).

    Raises
    ------
    ValueError
        Before anything is written: a suffix that names no format and no
        ``format`` (the message names the suffix and the known ones), an
        unknown ``format``, or a ``format`` that contradicts the suffix.
    TypeError
        ``mesh`` is not a :class:`~pentanb.Mesh`.

    Notes
    -----
    The file is written to a temporary name first and renamed, so a failure
    leaves nothing half-written.
    """
    path = Path(path)
    text = _text(mesh, _format(path, format))
    tmp = path.with_name(path.name + ".part")
    try:
        tmp.write_text(text)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def write_obj(mesh: Mesh, path: str | os.PathLike) -> None:
    """Write an OBJ file (``v`` and ``f`` lines, 1-based indices) to exactly ``path``.

    A name ending in ``.off`` is refused (ValueError).
    """
    write(mesh, path, format="obj")


def write_off(mesh: Mesh, path: str | os.PathLike) -> None:
    """Write an OFF file to exactly ``path``.

    A name ending in ``.obj`` is refused (ValueError).
    """
    write(mesh, path, format="off")


def _text(mesh: Mesh, format: str) -> str:
    if not isinstance(mesh, Mesh):
        raise TypeError(f"write expects a pentanb.Mesh, got {type(mesh).__name__}")
    return _obj_text(mesh) if format == "obj" else _off_text(mesh)


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


def read_obj(path: str | os.PathLike) -> Mesh:
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


def read_off(path: str | os.PathLike) -> Mesh:
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
