"""What :func:`pentanb.classroom.check` says, and how it reads a student's answer.

:class:`Result` is one check's verdict, :class:`Exercise` one exercise with
its checker, :data:`EXERCISES` the registry the exercises of
:mod:`pentanb.classroom._exercises` fill (by :func:`exercise`); the readers
below turn an answer into counts, a number, a letter, a name, a mesh or a
function's result, or raise :class:`Hint` with what to give instead.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import shapes
from .._checks import shown
from ..mesh import Mesh
from ..subdivision import predict_counts

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
        try:
            if _unanswered(answer):
                return Result(self.id, NOT_ANSWERED)
            hint = self._checker(answer)
        except _NotAnswered:
            return Result(self.id, NOT_ANSWERED)
        except _Hint as h:
            hint = str(h)
        except OverflowError:
            hint = _TOO_LARGE
        except Exception as exc:  # never a traceback for a student's answer
            hint = (
                f"your answer could not be read: using it raised {type(exc).__name__}"
                f"{': ' + _short(exc) if str(exc) else ''}; give a plain value "
                "(numbers, a string, a tuple or list, a mesh or a function, as asked)"
            )
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
# Reading answers
# --------------------------------------------------------------------------------------


class _Hint(Exception):
    """Raised by a checker or a reader with the hint to show."""


class _NotAnswered(Exception):
    """A student's function still returns the placeholder."""


def _short(exc: BaseException) -> str:
    """The first line of an exception's message, at most 160 characters."""
    try:
        text = str(exc)
    except Exception:  # a __str__ that raises
        return type(exc).__name__
    text = text[: text.find("\n")] if "\n" in text[:161] else text
    return text if len(text) <= 160 else text[:157] + "..."


#: The hint for a number too large (or a count too large) to be an answer.
_TOO_LARGE = "that number is far too large to be the answer: look at your working again"

#: Counts larger than this are no mesh's (and would make hints of megabytes).
_MAX_COUNT = 10**15

#: The longest string read as a number (a number needs far fewer characters).
_MAX_NUMBER_TEXT = 100


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
    if isinstance(answer, np.ndarray) and answer.ndim != 1:
        raise _Hint(f"give three whole numbers {what} in brackets, like {example}")
    n = len(answer)
    if n != 3:
        raise _Hint(f"give three numbers {what}, not {n:,}")
    values = []
    for x in tuple(answer)[:3]:
        if isinstance(x, (float, np.floating)) and math.isfinite(x) and float(x).is_integer():
            x = int(x)
        if not _is_int(x):
            raise _Hint(f"each of {what} is a whole number; {shown(x)} is not")
        if abs(int(x)) > _MAX_COUNT:
            raise _Hint(f"{shown(x)} is far too large for a count of this mesh")
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
        return _number_text(answer)
    if isinstance(answer, (numbers.Real, np.integer, np.floating)):
        try:
            value = float(answer)
        except OverflowError:  # an int or a Fraction beyond float64
            raise _Hint(_TOO_LARGE) from None
        if math.isfinite(value):
            return value
        if isinstance(answer, (float, np.floating)) and not math.isfinite(answer):
            raise _Hint("give a finite number")
        raise _Hint(_TOO_LARGE)  # a Decimal, numpy longdouble, ... beyond float64
    raise _Hint(f"give a number, like 3 or 0.5; {shown(answer)} is a {type(answer).__name__}")


def _number_text(answer: str) -> float:
    """A number written as a string: ``'3'``, ``'0.5'``, ``'1e-3'`` or a fraction
    ``'2/3'`` (each part a number), else a hint.  Read with ``float``, never as an
    exact fraction, so ``'1e999999999'`` costs nothing (and is too large)."""
    text = answer.strip()
    example = "give a number, like 3 or 0.5 or '2/3'"
    if len(text) > _MAX_NUMBER_TEXT:
        raise _Hint(f"{example}; this is a string of {len(text):,} characters")
    parts = text.split("/")
    if len(parts) > 2:
        raise _Hint(f"{example}; {shown(answer)} is not one")
    values = []
    for part in parts:
        try:
            values.append(float(part))
        except ValueError:
            raise _Hint(f"{example}; {shown(answer)} is not one") from None
    if not all(math.isfinite(v) for v in values):
        words = {t.strip().lower().lstrip("+-") for t in parts}
        if words & {"inf", "infinity", "nan"}:
            raise _Hint("give a finite number")
        raise _Hint(_TOO_LARGE)
    if len(values) == 1:
        return values[0]
    if values[1] == 0:
        raise _Hint(f"{shown(answer)} divides by zero")
    value = values[0] / values[1]
    if not math.isfinite(value):
        raise _Hint(_TOO_LARGE)
    return value


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
