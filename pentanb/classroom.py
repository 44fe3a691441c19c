"""Exercises that check themselves, for a class: :func:`check` and the students' notebooks.

Every notebook of ``notebooks/`` ends with a few exercises of four kinds:

* **predict**: work out counts (or a number) with pencil and paper, from the
  paper's formulas, before running anything;
* **explain**: move a slider or read a table, then answer a multiple-choice
  question (a letter) or give a number or a name; the "why" is for
  discussion in class and has no check;
* **find**: find a mesh on which a claim, read strictly or outside the
  input it is about, does not hold (or on which its hypothesis matters);
* **extend**: write a small scheme of your own from the package's operators.

Each exercise ends with a cell that calls ``check``::

    from pentanb.classroom import check

    answer = (92, 150, 60)  # (V, E, F)
    check("02.1", answer)

which prints one line, ``02.1: right``, ``02.1: not quite: <a hint>`` (the
hint never gives the answer away) or ``02.1: not answered yet`` while the
answer is still the placeholder ``...``, and returns a :class:`Result`.  An
answer of the wrong kind (a string where counts are expected, a function
that raises) gets a hint too, never a traceback.  The expected answers are
computed by the package where that is the point of the exercise (counts by
:func:`pentanb.predict_counts`, ranges by :mod:`pentanb.topology`, spectra
by :mod:`pentanb.analysis`), so a check agrees with the code the notebooks
run.

The teacher's notebooks (the repository's) hold a solution under every
exercise, in a cell tagged ``solution``; :func:`student_version` (the
command ``python -m pentanb classroom OUT_DIR``) writes the students' copies
without those cells, with nbconvert's ``TagRemovePreprocessor``.

Checking needs only numpy (and scipy for the spectra of notebook 09): a
student can answer in a plain Python prompt as well as in a notebook.
"""

from __future__ import annotations

import functools
import io
import math
import numbers
import os
import tempfile
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from . import shapes, topology
from ._checks import shown
from .mesh import Mesh, MeshError
from .schemes import SCHEMES, dual, pentagonalize
from .subdivision import predict_counts, subdivide

__all__ = [
    "check",
    "Result",
    "Exercise",
    "EXERCISES",
    "KINDS",
    "exercises",
    "student_version",
    "SOLUTION_TAG",
    "EXERCISE_TAG",
]

#: The tag of the cells holding the teacher's solutions (removed for students).
SOLUTION_TAG = "solution"
#: The tag of the exercise cells (questions and the students' check cells).
EXERCISE_TAG = "exercise"

#: The kinds of exercise, with what each asks.
KINDS = {
    "predict": "predict counts (or a number) before running anything",
    "explain": "move a slider or read a table, then answer a checkable question",
    "find": "find a mesh on which a claim read strictly, or its hypothesis dropped, fails",
    "extend": "write a small scheme of your own from the package's operators",
}

#: Largest mesh (faces) a check builds or measures: a student's mesh beyond it
#: is refused with a hint, so that a check answers in a moment.
MAX_FACES = 20_000

RIGHT = "right"
NOT_QUITE = "not quite"
NOT_ANSWERED = "not answered yet"


@dataclass(frozen=True)
class Result:
    """What :func:`check` said about one answer.

    Attributes
    ----------
    exercise : str
        The exercise, e.g. ``"02.1"``.
    status : str
        ``"right"``, ``"not quite"`` or ``"not answered yet"``.
    hint : str
        For ``"not quite"``: what to look at again (never the answer).
    """

    exercise: str
    status: str
    hint: str = ""

    @property
    def ok(self) -> bool:
        """True when the answer is right."""
        return self.status == RIGHT

    @property
    def message(self) -> str:
        """The line :func:`check` prints: ``"02.1: right"``, ``"02.1: not quite: ..."``."""
        if self.status == NOT_QUITE:
            return f"{self.exercise}: {NOT_QUITE}: {self.hint}"
        if self.status == NOT_ANSWERED:
            return f"{self.exercise}: {NOT_ANSWERED} (replace ... with your answer)"
        return f"{self.exercise}: {self.status}"

    def __str__(self) -> str:
        return self.message

    def _ipython_display_(self) -> None:
        """Show nothing in a notebook: :func:`check` has printed the line already."""


@dataclass(frozen=True)
class Exercise:
    """One exercise of a notebook.

    Attributes
    ----------
    id : str
        ``"NN.k"``: the notebook's number and the exercise's number in it.
    notebook : str
        The notebook's file name without ``.ipynb``, e.g. ``"02_tetrahedron_to_dodecahedron"``.
    kind : str
        One of :data:`KINDS`.
    title : str
        What it asks, in a few words.
    """

    id: str
    notebook: str
    kind: str
    title: str
    _checker: Callable[[Any], str | None]

    def check(self, answer: Any) -> Result:
        """Check ``answer`` without printing (:func:`check` prints).

        Parameters
        ----------
        answer : object
            The student's answer; ``...`` (Ellipsis) while not answered.

        Returns
        -------
        Result
        """
        if _unanswered(answer):
            return Result(self.id, NOT_ANSWERED)
        try:
            hint = self._checker(answer)
        except _NotAnswered:
            return Result(self.id, NOT_ANSWERED)
        except _Hint as h:
            hint = str(h)
        except Exception as exc:  # never a traceback for a student's answer
            hint = f"this answer could not be checked ({type(exc).__name__}: {_short(exc)})"
        return Result(self.id, RIGHT) if hint is None else Result(self.id, NOT_QUITE, hint)


#: Every exercise, by id, in the order of the notebooks.
EXERCISES: dict[str, Exercise] = {}

_NOTEBOOKS = {
    "01": "01_topology",
    "02": "02_tetrahedron_to_dodecahedron",
    "03": "03_cube_tilings",
    "04": "04_torus_hexagons",
    "05": "05_soccerball",
    "06": "06_schemes_compared",
    "07": "07_complex_model",
    "08": "08_convergence",
    "09": "09_continuity",
    "10": "10_conway",
    "11": "11_open_surfaces",
}


def check(exercise: str, answer: Any) -> Result:
    """Say whether ``answer`` to ``exercise`` is right, and print it.

    Parameters
    ----------
    exercise : str
        The exercise's id, as in its heading: ``"02.1"``.
    answer : object
        The answer, of the kind the exercise asks for: counts ``(V, E, F)``,
        a number, a letter, a scheme or shape name, a mesh, a function.
        ``...`` (Ellipsis), or counts with ``...`` in them, means not
        answered yet.

    Returns
    -------
    Result
        ``result.ok`` is True when the answer is right; the line printed is
        ``result.message``.  (In a notebook the result shows nothing more.)

    Raises
    ------
    ValueError
        If ``exercise`` is not the id of an exercise (the message lists them).
    """
    found = EXERCISES.get(exercise) if isinstance(exercise, str) else None
    if found is None:
        known = ", ".join(EXERCISES)
        raise ValueError(f"check: no exercise {shown(exercise)}; the exercises are {known}")
    result = found.check(answer)
    print(result.message)
    return result


def exercises(notebook: str | None = None) -> list[Exercise]:
    """The exercises, all or those of one notebook.

    Parameters
    ----------
    notebook : str, optional
        A notebook's number (``"02"``) or file name with or without
        ``.ipynb``.

    Returns
    -------
    list of Exercise
        In order.

    Raises
    ------
    ValueError
        If ``notebook`` names no notebook with exercises.
    """
    if notebook is None:
        return list(EXERCISES.values())
    key = str(notebook).removesuffix(".ipynb")[:2]
    found = [e for e in EXERCISES.values() if e.id[:2] == key]
    if not found:
        raise ValueError(f"exercises: no notebook {shown(notebook)} with exercises")
    return found


# --------------------------------------------------------------------------------------
# The students' notebooks
# --------------------------------------------------------------------------------------


def _default_notebooks() -> list[Path]:
    folder = Path(__file__).resolve().parent.parent / "notebooks"
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


# --------------------------------------------------------------------------------------
# Reading answers
# --------------------------------------------------------------------------------------


class _Hint(Exception):
    """Raised by a checker or a reader with the hint to show."""


class _NotAnswered(Exception):
    """A student's function still returns the placeholder."""


def _short(exc: BaseException) -> str:
    text = str(exc).splitlines()[0] if str(exc) else ""
    return text if len(text) <= 160 else text[:157] + "..."


def _unanswered(answer: Any) -> bool:
    if answer is Ellipsis:
        return True
    if isinstance(answer, (tuple, list)) and len(answer) <= 10:
        return any(a is Ellipsis for a in answer)
    return False


def _is_int(x: Any) -> bool:
    return isinstance(x, (numbers.Integral, np.integer)) and not isinstance(x, (bool, np.bool_))


def _counts(answer: Any, what: str = "(V, E, F)") -> tuple[int, ...]:
    """Three whole numbers, or a hint."""
    example = "(4, 6, 4)"  # the tetrahedron's: never an exercise's answer
    if isinstance(answer, (str, bytes)) or not isinstance(answer, (tuple, list, np.ndarray)):
        raise _Hint(f"give three whole numbers {what} in brackets, like {example}")
    if len(answer) != 3:
        raise _Hint(f"give three numbers {what}, not {len(answer)}")
    values = []
    for x in answer:
        if isinstance(x, (float, np.floating)) and float(x).is_integer():
            x = int(x)
        if not _is_int(x):
            raise _Hint(f"each of {what} is a whole number; {shown(x)} is not")
        values.append(int(x))
    return tuple(values)


def _compare_counts(given: tuple[int, ...], expected: tuple[int, ...], chi: int) -> str | None:
    """None when equal, else a hint naming which of V, E, F are off (not their values)."""
    if given == expected:
        return None
    wrong = [n for n, a, b in zip("VEF", given, expected) if a != b]
    right = [n for n, a, b in zip("VEF", given, expected) if a == b]
    parts = [f"{' and '.join(wrong)} {'is' if len(wrong) == 1 else 'are'} off"]
    if right:
        parts.append(f"{' and '.join(right)} {'is' if len(right) == 1 else 'are'} right")
    v, e, f = given
    if v - e + f != chi:
        parts.append(
            f"check Euler's formula: your V - E + F is {v - e + f}, this surface has {chi}"
        )
    return "; ".join(parts)


def _number(answer: Any) -> float:
    if isinstance(answer, (bool, np.bool_)):
        raise _Hint("give a number, not True or False")
    if isinstance(answer, str):
        try:
            return float(Fraction(answer.strip()))
        except (ValueError, ZeroDivisionError):
            hint = f"give a number, like 3 or 0.5 or '2/3'; {shown(answer)} is not one"
            raise _Hint(hint) from None
    if isinstance(answer, (numbers.Real, np.integer, np.floating)):
        value = float(answer)
        if math.isfinite(value):
            return value
        raise _Hint("give a finite number")
    raise _Hint(f"give a number, like 3 or 0.5; {shown(answer)} is a {type(answer).__name__}")


def _whole(answer: Any) -> int:
    value = _number(answer)
    if not value.is_integer():
        raise _Hint(f"the answer is a whole number; {shown(answer)} is not")
    return int(value)


def _letter(answer: Any, options: str) -> str:
    choices = ", ".join(f"'{c}'" for c in options)
    if not isinstance(answer, str):
        raise _Hint(f"answer with one letter in quotes: {choices}")
    text = answer.strip().strip("()").strip().lower()
    if text not in options or len(text) != 1:
        raise _Hint(f"answer with one of the letters {choices}")
    return text


def _name(answer: Any, known: Iterable[str], what: str) -> str:
    names = list(known)
    if not isinstance(answer, str):
        raise _Hint(f"give the {what}'s name as a string, in quotes (one of {', '.join(names)})")
    if answer.strip() not in names:
        raise _Hint(f"{shown(answer)} is not a {what} here; one of {', '.join(names)}")
    return answer.strip()


def _mesh(answer: Any) -> Mesh:
    """A Mesh, or the name of a shape of :mod:`pentanb.shapes`."""
    if isinstance(answer, str):
        try:
            answer = shapes.get(answer.strip())
        except (ValueError, TypeError):
            raise _Hint(
                f"{shown(answer)} is not a shape of pentanb.shapes; give a Mesh or one of "
                + ", ".join(shapes.SHAPES)
            ) from None
    if not isinstance(answer, Mesh):
        raise _Hint(
            "give a mesh (a pentanb.Mesh, e.g. pentanb.shapes.cube()) or a shape's name; "
            f"this is a {type(answer).__name__}"
        )
    if answer.n_faces > MAX_FACES:
        raise _Hint(f"use a smaller mesh: this one has {answer.n_faces:,} faces")
    return answer


def _call(func: Any, mesh: Mesh, name: str) -> Mesh:
    """``func(mesh)``, checked: a Mesh, or a hint (the placeholder: not answered)."""
    if not callable(func):
        raise _Hint(f"give a function of one mesh (def {name}(mesh): ...), not a value")
    try:
        out = func(mesh)
    except Exception as exc:
        raise _Hint(f"your function raised {type(exc).__name__}: {_short(exc)}") from None
    if out is Ellipsis:
        raise _NotAnswered
    if out is None:
        raise _Hint("your function returns nothing: end it with return and the new mesh")
    if not isinstance(out, Mesh):
        raise _Hint(f"your function should return a mesh; it returned a {type(out).__name__}")
    return out


def _same_mesh(a: Mesh, b: Mesh) -> bool:
    return (
        a.n_vertices == b.n_vertices
        and np.array_equal(a.corners, b.corners)
        and np.array_equal(a.offsets, b.offsets)
        and np.allclose(a.vertices, b.vertices, atol=1e-9)
    )


def _vef(m: Mesh) -> tuple[int, int, int]:
    return (m.n_vertices, m.n_edges, m.n_faces)


def _topology(m: Mesh) -> tuple:
    return (_vef(m), m.face_size_histogram(), m.valence_histogram())


def _fmt_hist(h: dict) -> str:
    return "{" + ", ".join(f"{k}: {v}" for k, v in sorted(h.items())) + "}"


def _exercise(id: str, kind: str, title: str):
    """Register a checker: ``checker(answer)`` returns None when right, else a hint."""

    def register(checker: Callable[[Any], str | None]) -> Callable[[Any], str | None]:
        assert kind in KINDS and id[:2] in _NOTEBOOKS and id not in EXERCISES
        EXERCISES[id] = Exercise(id, _NOTEBOOKS[id[:2]], kind, title, checker)
        return checker

    return register


def _predicted(counts: tuple[int, int, int], scheme: str, iterations: int, duals: int, **kw):
    return tuple(predict_counts(counts, scheme, iterations, duals, **kw)[-1])


# --------------------------------------------------------------------------------------
# 01 topology
# --------------------------------------------------------------------------------------


@_exercise("01.1", "predict", "(v, e, f) of a sphere of pentagons with 26 vertices")
def _ex_01_1(answer: Any) -> str | None:
    given = _counts(answer, "(v, e, f)")
    expected = topology.ngon_mesh_counts(5, 0, 26)
    assert expected is not None
    if given[0] != 26:
        return "v is given: the mesh has 26 vertices"
    _, e, f = given
    if 2 * e != 5 * f:
        return "every face has 5 sides and every edge is shared by two faces: 2e = 5f"
    return _compare_counts(given, expected, 2)


@_exercise("01.2", "explain", "largest v of a heptagonal mesh of genus 3")
def _ex_01_2(answer: Any) -> str | None:
    v = _whole(answer)
    r = topology.vertex_range(7, 3)
    assert r is not None
    if v == r[1]:
        return None
    if topology.ngon_mesh_counts(7, 3, v) is None:
        return f"at v = {v}, e and f are not whole numbers: no such mesh"
    if v > r[1]:
        return f"at v = {v} the average valence m is below 3: watch the dot against m = 3"
    return f"at v = {v} the mesh is possible, but there are larger ones: keep moving v"


@_exercise("01.3", "find", "a pentagonal mesh with a whole-number average valence")
def _ex_01_3(answer: Any) -> str | None:
    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {5}:
        return f"every face must be a pentagon; this mesh has faces {_fmt_hist(sizes)}"
    if (2 * mesh.n_edges) % mesh.n_vertices == 0:
        return None
    m = 2 * mesh.n_edges / mesh.n_vertices
    return (
        f"its average valence 2E/V is {m:.4f}; equation (1) for a sphere of pentagons: "
        "which v makes m a whole number?"
    )


# --------------------------------------------------------------------------------------
# 02 tetrahedron to dodecahedron
# --------------------------------------------------------------------------------------


@_exercise("02.1", "predict", "(V, E, F) of the pentagonalized icosahedron")
def _ex_02_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((12, 30, 20), "pentagonalize", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint and given[2] != expected[2]:
        hint += "; every n-gon becomes n pentagons"
    return hint


@functools.lru_cache(maxsize=1)
def _odd_duals_letter() -> str:
    hist = subdivide(shapes.tetrahedron(), "pentagonalize", 1, 1).face_size_histogram()
    return {5: "a", 3: "b", 4: "c"}[min(hist)]


@_exercise("02.2", "explain", "the faces after an odd number of duals")
def _ex_02_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _odd_duals_letter():
        return None
    return "set the slider to 1, 3 or 5 duals and read the faces printed under the picture"


_PLATONIC = ("tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron")


@_exercise("02.3", "find", "a solid on which two more duals make it less round")
def _ex_02_3(answer: Any) -> str | None:
    from .analysis import radius_spread

    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        return "give a pair of names: (shape, scheme), like ('cube', 'pentagonalize')"
    shape = _name(answer[0], _PLATONIC, "Platonic solid")
    scheme = _name(answer[1], ("pentagonalize", "preserve_pentagons"), "scheme of the paper")
    base = shapes.get(shape)
    two, four = (radius_spread(subdivide(base, scheme, 1, d)) for d in (2, 4))
    if four > two:
        return None
    return (
        f"there the radius spread falls from {two:.4f} (2 duals) to {four:.4f} (4 duals): "
        "the shape gets rounder; try another solid or the other scheme"
    )


@_exercise("02.4", "extend", "Figure 7(D) as a function: pentagonalize, then two duals")
def _ex_02_4(answer: Any) -> str | None:
    for name in ("tetrahedron", "cube", "torus"):
        base = shapes.get(name)
        mine = _call(answer, base, "fig7d")
        expected = subdivide(base, "pentagonalize", 1, 2)
        if _vef(mine) != _vef(expected):
            return (
                f"on the {name} your function gives {mine}: not the right counts "
                "(pentagonalize once, then count your duals)"
            )
        if not _same_mesh(mine, expected):
            return (
                f"on the {name} the counts are right but the points are elsewhere: "
                "use pentanb.pentagonalize and pentanb.dual as they are"
            )
    return None


# --------------------------------------------------------------------------------------
# 03 cube tilings
# --------------------------------------------------------------------------------------


@_exercise("03.1", "predict", "(V, E, F) after two iterations of pentagon preservation")
def _ex_03_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((8, 12, 6), "preserve_pentagons", 2, 2)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; one step gives V + 3E, 6E, F + 2E, and two duals give back the same counts"
    return hint


@functools.lru_cache(maxsize=1)
def _scale_letter() -> str:
    cube = shapes.cube()
    low, high = (_vef(subdivide(cube, "preserve_pentagons", 1, 2, scale=s)) for s in (0.2, 0.8))
    if low == high:
        return "c"
    return "a" if high[2] > low[2] else "b"


@_exercise("03.2", "explain", "what the scale slider does to V, E and F")
def _ex_03_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _scale_letter():
        return None
    return "pick pentagon preservation, read V, E and F at scale 0.1 and at 0.9, and compare"


@_exercise("03.3", "extend", "Conway's quinto from preserve_pentagons")
def _ex_03_3(answer: Any) -> str | None:
    from .notation import conway

    for name in ("cube", "tetrahedron", "dodecahedron"):
        base = shapes.get(name)
        mine = _call(answer, base, "quinto")
        expected = conway("q", seed=base)
        if _topology(mine) != _topology(expected):
            return (
                f"on the {name} your function gives {mine}: not quinto's faces "
                "(one step of pentagon preservation, no duals)"
            )
        if not _same_mesh(mine, expected):
            return f"on the {name} the faces are right but the points are not: which scale?"
    return None


# --------------------------------------------------------------------------------------
# 04 torus hexagons
# --------------------------------------------------------------------------------------


@_exercise("04.1", "predict", "(V, E, F) of hexagon preservation on the hexagonal torus")
def _ex_04_1(answer: Any) -> str | None:
    given = _counts(answer)
    torus = shapes.hexagonal_torus()
    expected = _predicted(_vef(torus), "preserve_hexagons", 1, 0)
    hint = _compare_counts(given, expected, 0)
    if hint and given[2] != expected[2]:
        hint += "; every hexagon stays, and every edge adds one"
    return hint


@functools.lru_cache(maxsize=1)
def _genus2_letter() -> str:
    valences = shapes.hexagonal_surface(2).valence_histogram()
    if min(valences) < 3:
        return "c"
    return "b" if max(valences) > 3 else "a"


@_exercise("04.2", "explain", "the valences of a hexagonal mesh of genus 2")
def _ex_04_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _genus2_letter():
        return None
    return "set the genus to 2 and read the line 'valences:'; equation (1) with n = 6, g = 2"


@_exercise("04.3", "find", "a mesh of hexagons whose pentagonalization is not all 6.3.3.3.3")
def _ex_04_3(answer: Any) -> str | None:
    from .analysis import configuration_counts, face_configurations

    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {6}:
        return f"every face must be a hexagon; this mesh has faces {_fmt_hist(sizes)}"
    configs = configuration_counts(face_configurations(pentagonalize(mesh)))
    if set(configs) != {"3.3.3.3.6"}:
        return None
    return (
        "on this mesh every pentagon is 6.3.3.3.3 (its vertices are all 3-valent); "
        "equation (1) says which surfaces force some vertices above 3"
    )


# --------------------------------------------------------------------------------------
# 05 soccer balls
# --------------------------------------------------------------------------------------


@_exercise("05.1", "predict", "(V, E, F) of honeycomb on the dodecahedron")
def _ex_05_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((20, 30, 12), "honeycomb", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; the honeycomb's faces come from the old faces and the old vertices"
    return hint


@_exercise("05.2", "find", "a mesh whose honeycomb has a triangle or a quadrilateral")
def _ex_05_2(answer: Any) -> str | None:
    from .schemes import honeycomb

    mesh = _mesh(answer)
    sizes = honeycomb(mesh).face_size_histogram()
    if min(sizes) < 5:
        return None
    return (
        f"its honeycomb has faces {_fmt_hist(sizes)}, none below 5 sides; "
        "which faces of the input become which faces of the honeycomb?"
    )


@_exercise("05.3", "extend", "honeycomb as the dual of sqrt(3)")
def _ex_05_3(answer: Any) -> str | None:
    from .schemes import honeycomb, sqrt3_remesh

    for name in ("cube", "tetrahedron", "dodecahedron", "torus"):
        base = shapes.get(name)
        mine = _call(answer, base, "my_honeycomb")
        expected = honeycomb(base)
        if _topology(mine) == _topology(expected):
            continue
        plain = dual(sqrt3_remesh(base))
        extra = (
            " (that is the dual of sqrt(3)'s result; the dual of a scheme works on the dual mesh)"
            if _topology(mine) == _topology(plain)
            else ""
        )
        return (
            f"on the {name}, honeycomb makes faces {_fmt_hist(expected.face_size_histogram())}"
            f", your function {_fmt_hist(mine.face_size_histogram())}{extra}"
        )
    return None


# --------------------------------------------------------------------------------------
# 06 schemes compared
# --------------------------------------------------------------------------------------


@_exercise("06.1", "predict", "(V, E, F) of vertex insertion on the cube")
def _ex_06_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((8, 12, 6), "vertex_insertion", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; a new point on every edge and in every face, and quads around them"
    return hint


@functools.lru_cache(maxsize=1)
def _most_faces() -> frozenset[str]:
    tet = _vef(shapes.tetrahedron())
    faces = {s: predict_counts(tet, s, 2, 0)[-1][2] for s in SCHEMES}
    most = max(faces.values())
    return frozenset(s for s, f in faces.items() if f == most)


@_exercise("06.2", "explain", "the scheme with the most faces on the tetrahedron")
def _ex_06_2(answer: Any) -> str | None:
    if isinstance(answer, str) and answer.strip() in {s.label for s in SCHEMES.values()}:
        answer = next(s.name for s in SCHEMES.values() if s.label == answer.strip())
    name = _name(answer, SCHEMES, "scheme")
    if name in _most_faces():
        return None
    return "choose the tetrahedron, 2 iterations, 0 duals, and read the faces under each picture"


@functools.lru_cache(maxsize=1)
def _conversion() -> frozenset[str]:
    from .schemes import loop_remesh

    mixed = loop_remesh(shapes.cube())
    return frozenset(
        s for s in SCHEMES if len(subdivide(mixed, s, 2, 0).face_size_histogram()) == 1
    )


@_exercise("06.3", "explain", "which schemes are conversion schemes")
def _ex_06_3(answer: Any) -> str | None:
    if isinstance(answer, str) or not isinstance(answer, Iterable):
        return "give the schemes' names as a list of strings, like ['loop_remesh', 'honeycomb']"
    names = {_name(a, SCHEMES, "scheme") for a in answer}
    expected = _conversion()
    if names == expected:
        return None
    extra, missing = len(names - expected), len(expected - names)
    parts = []
    if extra:
        parts.append(f"{extra} of yours {'is' if extra == 1 else 'are'} not a conversion scheme")
    if missing:
        parts.append(f"{missing} {'is' if missing == 1 else 'are'} missing")
    return "; ".join(parts) + " (a conversion scheme leaves one kind of face)"


@_exercise("06.4", "find", "a mesh on which triangulate's count formula does not hold")
def _ex_06_4(answer: Any) -> str | None:
    from .schemes import triangulate

    mesh = _mesh(answer)
    V, E, F = _vef(mesh)
    if _vef(triangulate(mesh)) != (V + F, 3 * E, 2 * E):
        return None
    return "on this mesh triangulate gives exactly V + F, 3E, 2E; what does it do to a triangle?"


# --------------------------------------------------------------------------------------
# 07 complex model
# --------------------------------------------------------------------------------------


@_exercise("07.1", "predict", "the number of pentagons of the pentagonalized rabbit")
def _ex_07_1(answer: Any) -> str | None:
    given = _whole(answer)
    rabbit = shapes.rabbit()
    expected = predict_counts(rabbit, "pentagonalize", 1, 0)[0][2]
    if given == expected:
        return None
    return "every n-gon becomes n pentagons: add up the sides of the rabbit's faces"


@functools.lru_cache(maxsize=1)
def _rabbit_others() -> int:
    mesh = subdivide(shapes.rabbit(), "preserve_pentagons", 1, 2)
    return sum(c for n, c in mesh.face_size_histogram().items() if n != 5)


@_exercise("07.2", "explain", "the rabbit's non-pentagons under pentagon preservation")
def _ex_07_2(answer: Any) -> str | None:
    if _whole(answer) == _rabbit_others():
        return None
    return (
        "choose pentagon preservation and read the faces of the result (faces={...}) "
        "at 1, 2 and 3 iterations: count the faces that are not pentagons"
    )


@_exercise("07.3", "find", "an OBJ file whose pentagonalization has a vertex of valence 6")
def _ex_07_3(answer: Any) -> str | None:
    from .io import read

    if not isinstance(answer, str):
        return "give the text of an OBJ file, as a string (lines 'v x y z' and 'f i j k ...')"
    try:
        mesh = read(io.BytesIO(answer.encode("utf-8")), format="obj")
    except (MeshError, ValueError) as exc:
        return f"pentanb.read refuses it: {_short(exc)}"
    if not mesh.is_closed:
        return "the mesh has boundary edges: close it (every edge in two faces)"
    if mesh.n_faces > MAX_FACES:
        return f"use a smaller mesh: this one has {mesh.n_faces:,} faces"
    top = max(pentagonalize(mesh).valence_histogram())
    if top >= 6:
        return None
    return (
        f"its pentagonalization has valences up to {top}; which of the input's vertices "
        "and faces keep or give their valence?"
    )


# --------------------------------------------------------------------------------------
# 08 convergence
# --------------------------------------------------------------------------------------


@functools.lru_cache(maxsize=1)
def _preservation_rate() -> float:
    steps = predict_counts(shapes.cube(), "preserve_pentagons", 8, 0)
    k = steps[-1][2] / steps[-2][2]  # faces multiply by k per iteration, for large meshes
    return 1 / math.sqrt(k)


@_exercise("08.1", "predict", "the crease factor per iteration of pentagon preservation")
def _ex_08_1(answer: Any) -> str | None:
    value = _number(answer)
    expected = _preservation_rate()
    if abs(value - expected) <= 0.01:
        return None
    if abs(value - expected**2) <= 0.01:
        return "the faces multiply by k, but the edges get only sqrt(k) times shorter"
    if abs(value - 1 / math.sqrt(5)) <= 0.01:
        return "that is pentagonalization's factor: F + 2E grows faster than 2E"
    return "how many times more faces per iteration (k)? then the angle shrinks like 1/sqrt(k)"


@_exercise("08.2", "find", "a mesh on which a second pair of duals sharpens the largest crease")
def _ex_08_2(answer: Any) -> str | None:
    from .analysis import convergence

    mesh = _mesh(answer)
    if not mesh.is_closed:
        return "use a closed mesh"
    if 5 * mesh.n_edges > MAX_FACES // 2:  # pentagonalize makes 2E faces, twice
        return "use a smaller mesh"
    angles = convergence.dual_convergence(mesh, "pentagonalize", duals=4).max_normal_angle
    if angles[2] > angles[1]:
        return None
    return (
        f"there the largest crease falls from {angles[1]:.1f} (one pair) to {angles[2]:.1f} "
        "degrees (two pairs): try another shape of pentanb.shapes"
    )


@functools.lru_cache(maxsize=1)
def _vertex_insertion_letter() -> str:
    from .analysis import convergence

    angles = convergence.subdivision_convergence(
        shapes.cube(), "vertex_insertion", 3, 0
    ).max_normal_angle
    if np.allclose(angles, angles[0], atol=1e-6):
        return "b"
    return "a" if angles[-1] < angles[0] else "c"


@_exercise("08.3", "explain", "vertex insertion without duals: the largest crease")
def _ex_08_3(answer: Any) -> str | None:
    if _letter(answer, "abc") == _vertex_insertion_letter():
        return None
    return "choose the cube, vertex insertion, 0 duals, and read the left plot's 'largest' line"


# --------------------------------------------------------------------------------------
# 09 continuity
# --------------------------------------------------------------------------------------


def _table_cases() -> dict[str, tuple[str, dict]]:
    from .analysis.spectral import TABLE_CASES

    return {label: (scheme, options) for label, scheme, options in TABLE_CASES}


@functools.lru_cache(maxsize=32)
def _spectrum(label: str, kind: str, size: int):
    from .analysis import local_spectrum

    scheme, options = _table_cases()[label]
    return local_spectrum(scheme, kind, size, **options)


@functools.lru_cache(maxsize=1)
def _triangle_letter() -> str:
    return "b" if _spectrum("preserve_pentagons 0.5", "face", 3).map_obstruction else "a"


@_exercise("09.1", "explain", "pentagon preservation at scale 0.5 around a triangle")
def _ex_09_1(answer: Any) -> str | None:
    if _letter(answer, "ab") == _triangle_letter():
        return None
    return "pick 'preserve_pentagons 0.5', element 'face', 3 sides, and read the right panel"


@functools.lru_cache(maxsize=1)
def _triangle_meeting() -> tuple[Fraction, Fraction]:
    """The scale at which the triangle's leading eigenvalues meet (2 duals), and their
    common modulus per step, established in exact arithmetic by the analysis."""
    from .analysis.spectral import scale_family, scale_threshold

    threshold = scale_threshold(scale_family("face", 3, 2))
    s = threshold.value
    assert s is not None
    period = threshold.exact_at[s].value  # over one period of two steps
    assert period is not None
    per_step = Fraction(math.isqrt(period.numerator), math.isqrt(period.denominator))
    assert per_step**2 == period
    return Fraction(s), per_step


@_exercise("09.2", "predict", "the common value of the triangle's leading eigenvalues")
def _ex_09_2(answer: Any) -> str | None:
    value = _number(answer)
    scale, expected = _triangle_meeting()
    if abs(value - float(expected)) <= 1e-6:
        return None
    if abs(value - float(scale)) <= 1e-6:
        return "that is the scale: now put it into either eigenvalue"
    if abs(value - float(expected) ** 2) <= 1e-6:
        return "that is over a period of two steps; per step is its square root"
    return "set 11/60 - s/12 equal to (s + 3)/30, solve for s, and put s into either one"


@_exercise("09.3", "find", "an element where Reif's standard setting fails")
def _ex_09_3(answer: Any) -> str | None:
    cases = _table_cases()
    if not isinstance(answer, (tuple, list)) or len(answer) != 3:
        return "give three things: (scheme label, 'vertex' or 'face', valence or sides)"
    label = _name(answer[0], cases, "scheme label of the table")
    kind = _name(answer[1], ("vertex", "face"), "kind of element")
    size = _whole(answer[2])
    if not 3 <= size <= 8:
        return "the valence or number of sides is from 3 to 8"
    sp = _spectrum(label, kind, size)
    if not sp.stationary:
        return f"that element does not survive the scheme: {sp.note}"
    if not sp.standard:
        return None
    return "there the standard setting holds (|lambda1| = |lambda2| > |lambda3|); try another"


# --------------------------------------------------------------------------------------
# 10 Conway notation
# --------------------------------------------------------------------------------------


@_exercise("10.1", "predict", "(V, E, F) of cD")
def _ex_10_1(answer: Any) -> str | None:
    from .notation import conway

    given = _counts(answer)
    expected = _vef(conway("cD"))
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; chamfer's counts are V + 2E, 4E, F + E"
    return hint


_SEEDS = ("cube", "tetrahedron", "torus", "octahedron")


@_exercise("10.2", "extend", "an operator string other than g that makes only pentagons")
def _ex_10_2(answer: Any) -> str | None:
    from .notation import conway, reduce_notation

    if not isinstance(answer, str) or not answer.strip():
        return "give an operator string, in quotes, without a seed (like 'dk')"
    text = answer.strip()
    try:
        reduced = reduce_notation(text)
    except (ValueError, TypeError) as exc:
        return f"not a string of operators: {_short(exc)}"
    if reduced == "g":
        return f"{text!r} has the same topology as g itself: find another"
    for name in _SEEDS:
        try:
            mesh = conway(text, seed=shapes.get(name), max_faces=MAX_FACES)
        except (ValueError, TypeError, RuntimeError) as exc:
            return f"on the {name}: {_short(exc)}"
        sizes = mesh.face_size_histogram()
        if set(sizes) != {5}:
            return f"on the {name} it makes faces {_fmt_hist(sizes)}"
    return None


@functools.lru_cache(maxsize=1)
def _canonical_letter() -> str:
    from .analysis import planarity
    from .notation import canonical, conway

    mesh = conway("ddgC")
    before, after = planarity(mesh), planarity(canonical(mesh))
    if after < 1e-9:
        return "c"
    return "b" if after < before / 3 else "a"


@_exercise("10.3", "explain", "what canonical positions do to the planarity of ddgC")
def _ex_10_3(answer: Any) -> str | None:
    if _letter(answer, "abc") == _canonical_letter():
        return None
    return "type ddgC, read the planarity, then tick 'canonical positions' and read it again"


# --------------------------------------------------------------------------------------
# 11 open surfaces
# --------------------------------------------------------------------------------------


def _patch() -> Mesh:
    """Notebook 11's patch: a 4 x 3 grid of squares, its middle square left out."""
    vertices = [[x, y, 0.1 * (x - 2) ** 2] for y in range(4) for x in range(5)]
    faces = [
        [y * 5 + x, y * 5 + x + 1, y * 5 + x + 6, y * 5 + x + 5]
        for y in range(3)
        for x in range(4)
        if (x, y) != (1, 1)
    ]
    return Mesh(vertices, faces)


@_exercise("11.1", "predict", "(V, E, F) of the pentagonalized patch with a hole")
def _ex_11_1(answer: Any) -> str | None:
    given = _counts(answer)
    patch = _patch()
    expected = tuple(predict_counts(patch, "pentagonalize", 1, 0)[0])
    hint = _compare_counts(given, expected, patch.euler_characteristic)
    if hint and given[2] != expected[2]:
        hint += "; one pentagon per corner, and the corners add up to 2E - B here"
    return hint


@functools.lru_cache(maxsize=1)
def _disk_loops() -> int:
    disk = shapes.open_disk()
    loops = {
        subdivide(disk, s, k, d).n_boundary_loops
        for s in ("pentagonalize", "preserve_pentagons")
        for k, d in ((1, 0), (2, 2))
    }
    assert len(loops) == 1
    return loops.pop()


@_exercise("11.2", "explain", "the boundary loops after the schemes and the duals")
def _ex_11_2(answer: Any) -> str | None:
    if _whole(answer) == _disk_loops():
        return None
    return "in Explore, read the line 'boundary:' at a few positions of the sliders"


@_exercise("11.3", "find", "a hexagonal mesh of genus 0")
def _ex_11_3(answer: Any) -> str | None:
    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {6}:
        return f"every face must be a hexagon; this mesh has faces {_fmt_hist(sizes)}"
    if mesh.genus != 0:
        return f"this mesh has genus {mesh.genus}; find one of genus 0"
    if mesh.is_closed:
        return "Section 4 rules out a closed hexagonal mesh of genus 0: what else can a mesh be?"
    return None
