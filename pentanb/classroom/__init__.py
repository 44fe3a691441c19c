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

The package holds one module per concept: ``_answers`` (what :func:`check`
says, and how it reads an answer), ``_exercises`` (every notebook's
exercises and their expected answers) and ``_students`` (writing the
students' notebooks).
"""

from __future__ import annotations

from . import _exercises  # noqa: F401  (registers every exercise in EXERCISES)
from ._answers import EXERCISES, KINDS, Exercise, Result, check, exercises
from ._answers import MAX_FACES as MAX_FACES
from ._students import EXERCISE_TAG, SOLUTION_TAG, student_version

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
