"""The students' notebooks: the teacher's without the solution cells."""

from __future__ import annotations

import os
from collections.abc import Iterable
from functools import partial
from pathlib import Path

from .._checks import shown
from ..io._common import check_force, writable_target, write_atomically

__all__ = ["student_version", "SOLUTION_TAG", "EXERCISE_TAG"]

#: The tag of the cells holding the teacher's solutions (removed for students).
SOLUTION_TAG = "solution"
#: The tag of the exercise cells (questions and the students' check cells).
EXERCISE_TAG = "exercise"


# --------------------------------------------------------------------------------------
# The students' notebooks
# --------------------------------------------------------------------------------------


def _default_notebooks() -> list[Path]:
    folder = Path(__file__).resolve().parents[2] / "notebooks"
    return sorted(folder.glob("*.ipynb"))


def student_version(
    out_dir: str | os.PathLike,
    notebooks: Iterable[str | os.PathLike] | None = None,
    *,
    force: bool = False,
) -> list[Path]:
    """Write the students' notebooks: the teacher's without the solution cells.

    Runs nbconvert's ``TagRemovePreprocessor`` (``remove_cell_tags =
    {"solution"}``) and ``ClearOutputPreprocessor`` over every notebook, as
    the command line does::

        jupyter nbconvert --to notebook --output-dir OUT_DIR \\
            --TagRemovePreprocessor.enabled=True \\
            --TagRemovePreprocessor.remove_cell_tags='{"solution"}' \\
            --ClearOutputPreprocessor.enabled=True notebooks/*.ipynb

    Every notebook is converted before anything is written, and each is
    written as :func:`pentanb.write` writes a mesh: into a temporary file
    beside it, then renamed, with the mode the umask gives a new file (an
    existing copy keeps its mode).

    Parameters
    ----------
    out_dir : str or path
        Folder for the students' notebooks (created if needed); not the
        folder of the teacher's notebooks, however it is reached (a symbolic
        link, a second mount of it: folders are compared by device and
        inode, not by name).
    notebooks : iterable of str or path, optional
        The teacher's notebooks (default: every ``.ipynb`` of the
        repository's ``notebooks/`` folder).
    force : bool
        Replace read-only copies in ``out_dir`` too.

    Returns
    -------
    list of Path
        The notebooks written, one per input, with the same file names.

    Raises
    ------
    ImportError
        If nbconvert is not installed (``pip install -e ".[notebook]"``).
    ValueError
        Before anything is written: there is no notebook, a name does not
        end in ``.ipynb``, two notebooks have one name, a notebook is not a
        notebook (not JSON; the message names the file), ``out_dir`` is
        empty or is the folder of one of them (it would overwrite the
        teacher's copy), a copy in it is a link into that folder, a
        read-only copy without ``force=True``, or something other than a
        file stands where a copy goes.
    OSError
        If a notebook cannot be read or ``out_dir`` cannot be written.
    """
    force = check_force(force, "student_version")
    if not os.fspath(out_dir).strip():
        raise ValueError(
            "student_version: the output folder's name is empty; name a folder "
            "(use '.' for the current one, if it is not the teacher's)"
        )
    paths = _default_notebooks() if notebooks is None else [Path(p) for p in notebooks]
    if not paths:
        raise ValueError(
            "student_version: no notebooks found (run it from a clone of the repository, "
            "or pass notebooks=)"
        )
    out = Path(out_dir)
    names: dict[str, Path] = {}
    for p in paths:
        if p.suffix != ".ipynb":
            raise ValueError(f"student_version: {_path(p)} is not an .ipynb file")
        if p.name in names:
            raise ValueError(
                f"student_version: {_path(names[p.name])} and {_path(p)} would be "
                "written to one file"
            )
        names[p.name] = p
    teachers = {_folder_id(p.parent) for p in paths} - {None}
    if _folder_id(out) in teachers:
        raise ValueError(
            f"student_version: {_path(out)} holds the teacher's notebooks (it is their "
            "folder, by another path); choose another folder"
        )
    targets = []
    for p in paths:
        target, _ = writable_target(out / p.name, force=force, caller="student_version")
        if _folder_id(target.parent) in teachers:
            raise ValueError(
                f"student_version: {_path(out / p.name)} is a link into the folder of the "
                "teacher's notebooks; remove it or choose another folder"
            )
        targets.append(out / p.name)
    try:
        from nbconvert.exporters import NotebookExporter
        from traitlets.config import Config
    except ImportError as exc:
        raise ImportError(
            'student_version needs nbconvert: pip install -e ".[notebook]" '
            "(or pip install nbconvert)"
        ) from exc
    config = Config()
    config.TagRemovePreprocessor.enabled = True
    config.TagRemovePreprocessor.remove_cell_tags = {SOLUTION_TAG}
    config.ClearOutputPreprocessor.enabled = True
    exporter = NotebookExporter(config=config)
    bodies = [_converted(exporter, p) for p in paths]
    out.mkdir(parents=True, exist_ok=True)
    for target, body in zip(targets, bodies):
        data = (body if body.endswith("\n") else body + "\n").encode("utf-8")
        write_atomically(target, partial(_put, data), force=force, caller="student_version")
    return targets


def _path(path: str | os.PathLike) -> str:
    """A path for a message: whole (a real path is at most a few thousand
    characters), or shortened if it is longer (a string that names no file)."""
    text = os.fspath(path)
    return repr(text) if len(text) <= 4096 else shown(text)


def _folder_id(path: Path) -> tuple[int, int] | None:
    """The device and inode of the folder ``path`` (None: it does not exist yet)."""
    try:
        info = os.stat(path)
    except (FileNotFoundError, NotADirectoryError):
        return None
    return (info.st_dev, info.st_ino)


def _converted(exporter, path: Path) -> str:
    """The students' copy of the notebook ``path``, as text; a ValueError naming
    the file if it is not a notebook."""
    try:
        return str(exporter.from_filename(str(path))[0])
    except OSError:
        raise
    except Exception as exc:  # nbformat's NotJSONError, a validation error, a bad key
        raise ValueError(
            f"student_version: {_path(path)} is not a Jupyter notebook "
            f"({type(exc).__name__}: {shown(_first_line(exc))})"
        ) from None


def _first_line(exc: BaseException) -> str:
    text = str(exc)
    return text[: text.find("\n")] if "\n" in text else text


def _put(data: bytes, fh) -> None:
    fh.write(data)
