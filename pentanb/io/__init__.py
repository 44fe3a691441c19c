"""Meshes from files and other libraries, and back.

``read(path)`` and ``write(mesh, path)`` choose the format by the file's
ending (any case) or by ``format=``:

========  =====================================  ==========================
format    read                                   write
========  =====================================  ==========================
``obj``   ``v`` and ``f`` lines, polygons kept    exact (``repr`` precision)
``off``   OFF, COFF, NOFF; polygons kept          exact (``repr`` precision)
``ply``   ASCII and binary (both byte orders);   binary little-endian
          polygons kept                          (``ascii=True``,
                                                 ``byteorder="big"``); exact
``stl``   ASCII and binary; coincident corners   binary (float32; polygons
          welded into shared vertices            fanned into triangles) or
                                                 ``ascii=True`` (exact)
========  =====================================  ==========================

``write`` writes exactly the path it is given (through a symbolic link, to
the file it points to), or refuses before writing anything (a read-only
file, unless ``force=True``); a failure leaves no half-written file.  Every reader reads its
file as bytes in blocks, checks counts as it goes (a damaged file fails at
its first inconsistency) and names the file and line of what it refuses.
``read`` takes a path (a regular file or a pipe: a FIFO, ``/dev/stdin``) or
a binary file object; see :func:`read`.

Other libraries (imported only when these are called; ``pip install
pentanb[convert]``): :func:`from_trimesh`, :func:`to_trimesh`,
:func:`from_meshio`, :func:`to_meshio`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import IO, Any

from ..mesh import Mesh
from . import obj, off, ply, stl
from ._common import (
    FORMATS,
    IgnoredDataWarning,
    as_path,
    check_force,
    check_mesh,
    format_of,
    name_of,
    write_as,
)
from .convert import from_meshio, from_trimesh, to_meshio, to_trimesh
from .obj import read_obj, write_obj
from .off import read_off, write_off
from .ply import read_ply, write_ply
from .stl import read_stl, write_stl

__all__ = [
    "read",
    "write",
    "read_obj",
    "read_off",
    "read_ply",
    "read_stl",
    "write_obj",
    "write_off",
    "write_ply",
    "write_stl",
    "from_trimesh",
    "to_trimesh",
    "from_meshio",
    "to_meshio",
    "FORMATS",
    "IgnoredDataWarning",
]

_READERS = {"obj": read_obj, "off": read_off, "ply": read_ply, "stl": read_stl}
_WRITERS = {"obj": obj._write, "off": off._write, "ply": ply._write, "stl": stl._write}
#: The keyword options of every format's reader and writer.
READ_OPTIONS: dict[str, tuple[str, ...]] = {
    "obj": (),
    "off": (),
    "ply": (),
    "stl": ("tolerance",),
}
WRITE_OPTIONS: dict[str, tuple[str, ...]] = {
    "obj": (),
    "off": (),
    "ply": ("ascii", "byteorder"),
    "stl": ("ascii",),
}


def _check_options(caller: str, format: str, options: dict[str, Any], known: tuple[str, ...]):
    unknown = sorted(set(options) - set(known))
    if unknown:
        takes = ", ".join(known) if known else "no options"
        raise TypeError(f"{caller}: format {format!r} takes {takes}; got {', '.join(unknown)}")


def read(path: str | os.PathLike | IO[bytes], format: str | None = None, **options: Any) -> Mesh:
    """Read a mesh from an OBJ, OFF, PLY or STL file.

    Parameters
    ----------
    path : str, path-like or binary file object
        A path to a regular file or to a pipe (a FIFO, ``/dev/stdin`` under
        ``cat mesh.ply | python ...``), or a binary file object
        (``io.BytesIO``, ``open(p, "rb")``, ``sys.stdin.buffer``), read from
        its position and left open.  Every format reads from a stream that
        cannot seek; memory then grows with the bytes that arrive, never
        with the counts a header claims (binary PLY and STL from a pipe are
        held in memory whole, as binary PLY from a file is).  A FIFO is
        opened without blocking: with no writer it reads as empty.  A path
        to a device (a terminal, ``/dev/zero``) is refused.
    format : {"obj", "off", "ply", "stl"}, optional
        The file's format; default: from the suffix of ``path`` (any case),
        or of a file object's ``name``.  Needed for a name without a known
        suffix (``/dev/stdin``, ``io.BytesIO``).
    **options
        Options of the format's reader: ``tolerance`` for STL (see
        :func:`read_stl`).

    Returns
    -------
    Mesh

    Raises
    ------
    MeshError
        A malformed file (a bad number, a face index out of range, counts
        that do not match); the message names the file and line.  A file
        whose faces are not an oriented 2-manifold (closed, or open with
        boundary loops) raises the mesh's own error,
        prefixed with the file name.
    ValueError
        An unknown suffix (without ``format``) or format; a path to a
        device or socket.
    TypeError
        ``path`` is neither a path nor a binary file object (a text file
        object is refused), or an option the format does not take.
    """
    name = name_of(path)
    if name is None:
        if format is None:
            names = ", ".join(FORMATS.values())
            raise ValueError(
                f"read: a {type(path).__name__} has no file name to tell its format by; "
                f"pass format= one of {names}"
            )
        name = Path()
    fmt = format_of(name, format)
    _check_options("read", fmt, options, READ_OPTIONS[fmt])
    return _READERS[fmt](path, **options)


def write(
    mesh: Mesh,
    path: str | os.PathLike,
    format: str | None = None,
    *,
    force: bool = False,
    **options: Any,
) -> None:
    """Write ``mesh`` to exactly ``path``, as OBJ, OFF, PLY or STL.

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
        The file to write; its name is used as given.
    format : {"obj", "off", "ply", "stl"}, optional
        The format; default: from the suffix of ``path`` (any case).  Needed
        for any other name (``model.v2``).
    force : bool
        Replace a read-only file too (one whose mode lets no one write it,
        such as ``0444``, or that this process may not write); it keeps its
        mode.  Default: such a file is refused.
    **options
        Options of the format's writer: ``ascii`` and ``byteorder`` for PLY
        (:func:`write_ply`), ``ascii`` for STL (:func:`write_stl`).

    Raises
    ------
    ValueError
        Before anything is written: a suffix that names no format and no
        ``format`` (the message names the suffix and the known ones), an
        unknown ``format``, a ``format`` that contradicts the suffix, a
        bad option value, or a read-only ``path`` without ``force=True``.
        For binary STL (float32 coordinates) also a ``MeshError``: a vertex
        float32 cannot hold, or triangles whose corners meet at one float32
        point (see :func:`write_stl`).
    TypeError
        ``mesh`` is not a :class:`~pentanb.Mesh`, ``path`` not a path, or an
        option the format does not take.

    Notes
    -----
    The file is written to a new temporary file beside it first and renamed,
    so a failure leaves nothing half-written (and an existing file as it
    was, with its permissions); a path that exists and is not a regular
    file (a device, a FIFO, a directory) is refused with a ValueError.  A
    symbolic link is kept and the file it points to is replaced (its
    temporary file made beside that file); a dangling link's target is
    created.
    """
    check_mesh(mesh, "write")
    fmt = format_of(as_path(path, "write"), format)
    check_force(force, "write")
    _check_options("write", fmt, options, WRITE_OPTIONS[fmt])
    if fmt == "ply":
        ply.check_write_options(**options)
    elif fmt == "stl":
        stl.check_write_options(**options)
        options["prepared"] = stl.prepare(mesh, options.get("ascii", False))
    write_as(mesh, path, fmt, "write", _WRITERS[fmt], force=force, **options)
