"""The students' notebooks: the teacher's without the solution cells."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable
from pathlib import Path

from .._checks import shown

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
    out_dir: str | os.PathLike, notebooks: Iterable[str | os.PathLike] | None = None
) -> list[Path]:
    """Write the students' notebooks: the teacher's without the solution cells.

    Runs nbconvert's ``TagRemovePreprocessor`` (``remove_cell_tags =
    {"solution"}``) and ``ClearOutputPreprocessor`` over every notebook, as
    the command line does::

        jupyter nbconvert --to notebook --output-dir OUT_DIR \\
            --TagRemovePreprocessor.enabled=True \\
            --TagRemovePreprocessor.remove_cell_tags='{"solution"}' \\
            --ClearOutputPreprocessor.enabled=True notebooks/*.ipynb

    Parameters
    ----------
    out_dir : str or path
        Folder for the students' notebooks (created if needed); not the
        folder of the teacher's notebooks.
    notebooks : iterable of str or path, optional
        The teacher's notebooks (default: every ``.ipynb`` of the
        repository's ``notebooks/`` folder).

    Returns
    -------
    list of Path
        The notebooks written, one per input, with the same file names.

    Raises
    ------
    ImportError
        If nbconvert is not installed (``pip install -e ".[notebook]"``).
    ValueError
        If there is no notebook, or ``out_dir`` is the folder of one of them
        (it would overwrite the teacher's copy).
    OSError
        If a notebook cannot be read or ``out_dir`` cannot be written.
    """
    paths = _default_notebooks() if notebooks is None else [Path(p) for p in notebooks]
    if not paths:
        raise ValueError(
            "student_version: no notebooks found (run it from a clone of the repository, "
            "or pass notebooks=)"
        )
    out = Path(out_dir)
    for p in paths:
        if p.suffix != ".ipynb":
            raise ValueError(f"student_version: {shown(str(p))} is not an .ipynb file")
        if out.resolve() == p.resolve().parent:
            raise ValueError(
                f"student_version: {shown(str(out))} holds the teacher's notebooks; "
                "choose another folder"
            )
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
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for p in paths:
        body = str(exporter.from_filename(str(p))[0])
        target = out / p.name
        fd, tmp = tempfile.mkstemp(dir=out, prefix=f".{p.stem}.", suffix=".tmp")
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(body if body.endswith("\n") else body + "\n")
            os.replace(tmp, target)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise
        written.append(target)
    return written
