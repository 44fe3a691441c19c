"""The classroom kit: :mod:`pentanb.classroom`'s checks, the notebooks' exercise
sections, and the students' version of the notebooks.

* Every check says *right* on the teacher's answer, *not quite* (with a hint that
  does not give the answer away) on a wrong one, *not answered yet* on ``...``, and
  a hint, never a traceback, on an answer of the wrong kind.  The teacher's answers
  are written here from the paper's count formulas and by hand, not computed by the
  checks.
* Every numbered notebook ends with an "Exercises" section of two to five exercises:
  a question, an answer cell calling ``check`` and a solution cell tagged
  ``solution``.
* :func:`pentanb.classroom.student_version` (``python -m pentanb classroom OUT_DIR``)
  leaves out every solution cell and keeps every exercise cell.
* Executed: the exercise sections only, all of them concatenated into one notebook
  per version, one kernel each (the whole teacher notebooks are executed by
  ``tests/test_notebooks.py`` or ``tests/test_browser.py``).  In the teacher's
  version every solution's check says right; in the students', every check says
  not answered yet, and the run does not fail.
"""

from __future__ import annotations

import importlib.util
import math
import re
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import pentanb
from pentanb import classroom, shapes
from pentanb.classroom import EXERCISES, check

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = sorted(ROOT.glob("notebooks/[0-9][0-9]_*.ipynb"))
#: The notebooks that must end with exercises (a new notebook joins when its exercises do).
WITH_EXERCISES = [p for p in NOTEBOOKS if p.stem[:2] in {e.id[:2] for e in EXERCISES.values()}]


def _hexagonal_pyramid() -> str:
    """An OBJ file: a pyramid on a hexagon (apex of valence 6, a six-sided face)."""
    lines = [
        f"v {math.cos(k * math.pi / 3):.6f} {math.sin(k * math.pi / 3):.6f} 0" for k in range(6)
    ]
    lines += ["v 0 0 1", "f 6 5 4 3 2 1"]
    lines += [f"f {k + 1} {(k + 1) % 6 + 1} 7" for k in range(6)]
    return "\n".join(lines)


_TETRAHEDRON_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"

# The teacher's answers, from the paper's count formulas and by hand.
TEACHER = {
    # Euler's formula with 2e = 5f on a sphere: f = 2 (v - 2) / 3, e = 5 f / 2
    "01.1": (26, 40, 16),
    # (6 - n) v >= 4 n (1 - g) gives v <= 56 for n = 7, g = 3; f = 2 (v + 4) / 5 = 24
    "01.2": 56,
    "01.3": "dodecahedron",  # 2E / V = 60 / 20 = 3
    # pentagonalization: V + 2E + F, 5E, 2E on the icosahedron (12, 30, 20)
    "02.1": (12 + 2 * 30 + 20, 5 * 30, 2 * 30),
    "02.2": "b",  # 20 triangles, the icosahedron's combinatorics
    # radius spread 0.104 after two duals, 0.126 after four (notebook 08's table)
    "02.3": ("tetrahedron", "preserve_pentagons"),
    "02.4": lambda m: pentanb.dual(pentanb.dual(pentanb.pentagonalize(m))),
    # preservation: (8, 12, 6) -> (44, 72, 30) -> (44 + 216, 432, 30 + 144)
    "03.1": (260, 432, 174),
    "03.2": "c",  # the scale moves points only
    "03.3": lambda m: pentanb.preserve_pentagons(m, scale=0.5),  # quinto: scale 1/2
    # hexagon preservation: V + 2E, 4E, F + E on (144, 216, 72)
    "04.1": (144 + 2 * 216, 4 * 216, 72 + 216),
    "04.2": "b",  # m = 3 (1 + 2 / v) > 3 for g = 2
    "04.3": "hexagonal_genus2",
    # honeycomb: 2E, 3E, V + F on the dodecahedron (20, 30, 12): the truncated icosahedron
    "05.1": (60, 90, 32),
    "05.2": "cube",  # its quads stay quads
    "05.3": lambda m: pentanb.dual(pentanb.sqrt3_remesh(pentanb.dual(m))),
    # vertex insertion: V + E + F, 4E, 2E on the cube
    "06.1": (8 + 12 + 6, 4 * 12, 2 * 12),
    # faces after two steps on the tetrahedron (4, 6, 4): preservation 4 -> 16 -> 88
    "06.2": "preserve_pentagons",
    "06.3": ["sqrt3_remesh", "vertex_insertion", "pentagonalize", "triangulate"],
    "06.4": "octahedron",  # triangles stay: 6 + 8 vertices would be V + F
    # pentagonalization's pentagon with two more edge points: one heptagon per half-edge
    "06.5": pentanb.Table(
        "heptagons",
        edge_points=(0.2, 0.4, 0.6, 0.8),
        face_points=True,
        faces=(("halfedge", ("E0", "E1", "E2", "E3", "n:V", "n:E0", "F")),),
    ),
    # rabbit: 136 triangles, 81 quads, 14 pentagons: 3 * 136 + 4 * 81 + 5 * 14
    "07.1": 802,
    "07.2": 136 + 81,
    "07.3": _hexagonal_pyramid(),
    "08.1": 1 / math.sqrt(6),  # F and E grow six times per step
    "08.2": "octahedron",  # largest crease 70.5, 46.1, 52.0 degrees after 0, 1, 2 pairs
    "08.3": "b",  # vertex insertion's points stay on the cube's faces: 90 degrees
    "09.1": "b",  # lambda1 = 17/120 simple, mode 0: no characteristic map
    # 11/60 - s/12 = (s + 3)/30 at s = 5/7: (5/7 + 3)/30 = 13/105
    "09.2": "13/105",
    "09.3": ("preserve_pentagons 0.5", "face", 3),
    # chamfer: V + 2E, 4E, F + E on the dodecahedron
    "10.1": (80, 120, 42),
    "10.2": "gg",
    "10.3": "c",
    # open patch (20, 31, 11), 18 boundary edges: corners 2E - B = 44; V + 2E + F, 3E + 44, 44
    "11.1": (93, 137, 44),
    "11.2": 3,  # the rim and two holes of the open disk
    "11.3": pentanb.Mesh(
        [[math.cos(k * math.pi / 3), math.sin(k * math.pi / 3), 0] for k in range(6)],
        [[0, 1, 2, 3, 4, 5]],
    ),
}

# Wrong answers of the right kind.
WRONG = {
    "01.1": (26, 39, 15),
    "01.2": 57,
    "01.3": "cube",
    "02.1": (92, 150, 61),
    "02.2": "a",
    "02.3": ("cube", "pentagonalize"),
    "02.4": lambda m: pentanb.dual(pentanb.pentagonalize(m)),
    "03.1": (260, 432, 175),
    "03.2": "a",
    "03.3": lambda m: pentanb.preserve_pentagons(m, scale=0.75),
    "04.1": (576, 864, 289),
    "04.2": "a",
    "04.3": "hexagonal_torus",  # a (6, 3) mesh: every pentagon 6.3.3.3.3
    "05.1": (60, 90, 30),
    "05.2": "dodecahedron",
    "05.3": lambda m: pentanb.dual(pentanb.sqrt3_remesh(m)),
    "06.1": (26, 48, 26),
    "06.2": "loop_remesh",
    "06.3": ["pentagonalize", "vertex_insertion"],
    "06.4": "cube",
    "06.5": pentanb.SCHEMES["pentagonalize"].table,  # pentagons
    "07.1": 801,
    "07.2": 231,
    "07.3": _TETRAHEDRON_OBJ,
    "08.1": 1 / math.sqrt(5),
    "08.2": "cube",
    "08.3": "a",
    "09.1": "a",
    "09.2": Fraction(5, 7),
    "09.3": ("preserve_pentagons 0.75", "face", 3),
    "10.1": (80, 120, 40),
    "10.2": "ddg",
    "10.3": "a",
    "11.1": (93, 155, 62),  # as if the patch were closed: 5E, 2E
    "11.2": 2,
    "11.3": "hexagonal_torus",  # hexagons, but genus 1
}


def _secrets(exercise: str) -> list[str]:
    """Strings a hint for ``exercise`` must not contain: its expected counts or number."""
    answer = TEACHER[exercise]
    if isinstance(answer, tuple) and all(isinstance(x, int) for x in answer):
        return [str(x) for x in answer]
    if isinstance(answer, int):
        return [str(answer)]
    if isinstance(answer, float):
        return [f"{answer:.2f}", f"{answer:.3f}"]
    if exercise == "09.2":
        return ["13/105", "0.1238"]
    return []


IDS = list(EXERCISES)


def test_every_exercise_has_a_teacher_answer_and_a_wrong_one():
    assert set(TEACHER) == set(EXERCISES) == set(WRONG)
    assert all(e.kind in classroom.KINDS for e in EXERCISES.values())
    for notebook in {e.notebook for e in EXERCISES.values()}:
        kinds = {e.kind for e in EXERCISES.values() if e.notebook == notebook}
        assert len(kinds) >= 2, f"{notebook}: exercises of one kind only ({kinds})"


@pytest.mark.parametrize("exercise", IDS)
def test_the_teachers_answer_is_right(exercise, capsys):
    result = check(exercise, TEACHER[exercise])
    assert result.ok and result.status == "right", result.message
    assert capsys.readouterr().out == f"{exercise}: right\n"


@pytest.mark.parametrize("exercise", IDS)
def test_a_wrong_answer_is_not_quite_and_the_hint_keeps_the_answer(exercise, capsys):
    result = check(exercise, WRONG[exercise])
    assert not result.ok and result.status == "not quite", result.message
    assert result.hint and result.message == f"{exercise}: not quite: {result.hint}"
    for secret in _secrets(exercise):
        assert secret not in result.hint, (secret, result.hint)
    assert capsys.readouterr().out == result.message + "\n"


@pytest.mark.parametrize("exercise", IDS)
def test_the_placeholder_is_not_answered_yet(exercise, capsys):
    result = check(exercise, ...)
    assert not result.ok and result.status == "not answered yet"
    assert capsys.readouterr().out.startswith(f"{exercise}: not answered yet")


@pytest.mark.parametrize("exercise", IDS)
def test_an_answer_of_the_wrong_kind_gets_a_hint_not_a_traceback(exercise):
    for answer in (None, object(), "", "zz", 3.5, -1, [1, 2], (1, 2, 3, 4), True, lambda m: 1 / 0):
        result = classroom.EXERCISES[exercise].check(answer)
        assert result.status == "not quite", (answer, result)
        assert "Traceback" not in result.hint and result.hint


class _BadLength(list):
    def __len__(self):
        raise RuntimeError("no length")


class _BadIteration(tuple):
    def __iter__(self):
        raise RuntimeError("no iteration")


class _BadString(str):
    def strip(self, chars=None):
        raise KeyError("x" * 1_000_000)


#: Answers a student may give that used to escape the check or read as an internal error.
HOSTILE_ANSWERS = [
    _BadLength([1, 2, 3]),
    _BadIteration((1, 2, 3)),
    _BadString("a"),
    10**400,
    -(10**5000),
    (10**5000, 1, 1),
    (1e300, 2.0, 3.0),
    (float("inf"), 1, 1),
    "1e400",
    "-1e400/3",
    "1e999999999",
    "1" * 100_000,
    "3/0",
    Fraction(10**400, 3),
    Fraction(1, 10**400) ** -1,
    np.longdouble("1e4000") if np.finfo(np.longdouble).max > 1e4000 else 10**400,
]


@pytest.mark.parametrize("exercise", IDS)
def test_hostile_answers_get_a_hint_never_an_internal_error(exercise):
    for answer in HOSTILE_ANSWERS:
        result = classroom.EXERCISES[exercise].check(answer)
        assert result.status == "not quite", (exercise, answer, result)
        assert "could not be checked" not in result.hint and "Overflow" not in result.hint
        assert len(result.hint) < 400, (exercise, result.hint[:200])


def test_hostile_answers_get_the_hint_that_fits():
    assert "far too large" in check("01.2", 10**400).hint
    assert "far too large" in check("01.2", "1e400").hint
    assert "far too large" in check("08.1", Fraction(10**400, 3)).hint
    assert "far too large" in check("02.1", (10**5000, 1, 1)).hint
    assert "divides by zero" in check("08.1", "3/0").hint
    assert "100,000 characters" in check("08.1", "1" * 100_000).hint
    assert "using it raised RuntimeError: no length" in check("02.1", _BadLength([1, 2, 3])).hint
    assert check("09.2", "13/105").ok and check("08.1", " 0.41 ").ok


def test_partial_counts_and_a_function_returning_the_placeholder_are_not_answered_yet():
    assert check("02.1", (92, ..., ...)).status == "not answered yet"
    assert check("02.4", lambda mesh: ...).status == "not answered yet"


def test_hints_say_what_to_look_at():
    assert "E and F are off" in check("02.1", (92, 151, 61)).hint
    assert "V - E + F is 1" in check("02.1", (92, 151, 60)).hint
    assert "raised ZeroDivisionError" in check("02.4", lambda m: 1 / 0).hint
    assert "returns nothing" in check("02.4", lambda m: None).hint
    assert "one of the letters 'a', 'b', 'c'" in check("02.2", "d").hint
    assert "not a shape of pentanb.shapes" in check("01.3", "sphere").hint
    assert "pentanb.read refuses it" in check("07.3", "v 0 0 0\nf 1 2 3\n").hint
    assert "same topology as g" in check("10.2", "ddg").hint
    big = shapes.torus(200, 120)  # 24,000 faces: over what a check measures
    assert "smaller mesh" in check("01.3", big).hint


def test_other_right_answers_are_right_too():
    """An exercise with several right answers accepts each (the check measures)."""
    assert check("01.3", pentanb.pentagonalize(shapes.tetrahedron())).ok
    assert check("06.4", shapes.tetrahedron()).ok
    assert check("08.2", "rabbit").ok
    assert check("10.2", "gd").ok
    assert check("09.2", Fraction(13, 105)).ok and check("09.2", 13 / 105).ok
    assert check("08.1", 0.41).ok and not check("08.1", 0.43).ok
    assert check("02.2", " (B) ").ok


def test_an_unknown_exercise_is_refused_with_the_known_ones():
    with pytest.raises(ValueError, match=r"no exercise '99\.9'.*01\.1"):
        check("99.9", 1)
    with pytest.raises(ValueError, match="no exercise 2"):
        check(2, 1)  # type: ignore[arg-type]


def test_exercises_by_notebook():
    assert [e.id for e in classroom.exercises("02")] == ["02.1", "02.2", "02.3", "02.4"]
    assert classroom.exercises("03_cube_tilings.ipynb") == classroom.exercises("03")
    assert len(classroom.exercises()) == len(EXERCISES)
    with pytest.raises(ValueError, match="no notebook '42'"):
        classroom.exercises("42")


def test_the_result_shows_nothing_more_in_a_notebook():
    result = check("01.2", 56)
    assert str(result) == "01.2: right" and result._ipython_display_() is None


# -- the notebooks ---------------------------------------------------------------------

_CHECK = re.compile(r'check\("(\d\d\.\d)"')


def _tags(cell) -> set[str]:
    return set(cell.get("metadata", {}).get("tags", []))


def _read(path: Path) -> dict:
    import json

    return json.loads(path.read_text(encoding="utf-8"))


def _source(cell) -> str:
    src = cell["source"]
    return src if isinstance(src, str) else "".join(src)


def _section(nb: dict) -> list[dict]:
    mine = {classroom.EXERCISE_TAG, classroom.SOLUTION_TAG}
    return [c for c in nb["cells"] if mine & _tags(c)]


def test_every_numbered_notebook_has_exercises():
    assert [p.stem[:2] for p in WITH_EXERCISES] == [p.stem[:2] for p in NOTEBOOKS]
    assert len(NOTEBOOKS) >= 11


@pytest.mark.parametrize("path", WITH_EXERCISES, ids=[p.stem for p in WITH_EXERCISES])
def test_a_notebook_ends_with_its_exercises(path):
    nb = _read(path)
    section = _section(nb)
    number = path.stem[:2]
    assert section and nb["cells"][-len(section) :] == section, "the exercises come last"
    assert _source(section[0]).startswith("## Exercises\n")
    first_code = next(c for c in section if c["cell_type"] == "code")
    assert "from pentanb.classroom import check" in _source(first_code)  # self-contained
    asked = [
        _CHECK.findall(_source(c))
        for c in section
        if c["cell_type"] == "code" and _tags(c) == {classroom.EXERCISE_TAG}
    ]
    solved = [_CHECK.findall(_source(c)) for c in section if classroom.SOLUTION_TAG in _tags(c)]
    ids = [e.id for e in classroom.exercises(number)]
    assert 2 <= len(ids) <= 5
    assert [a for a in asked if a] == [[i] for i in ids], "one answer cell per exercise"
    assert solved == [[i] for i in ids], "one solution cell per exercise"
    headings = [_source(c).splitlines()[0] for c in section if c["cell_type"] == "markdown"][1:]
    assert [h.split()[1] for h in headings] == ids
    for cell in section:
        if classroom.SOLUTION_TAG in _tags(cell):
            assert cell["cell_type"] == "code" and "remove-cell" in _tags(cell)
        if cell["cell_type"] == "code" and classroom.SOLUTION_TAG not in _tags(cell):
            assert "check(" not in _source(cell) or "..." in _source(cell)


# -- the students' version, and the sections executed ------------------------------------

needs_nbconvert = pytest.mark.skipif(
    any(importlib.util.find_spec(m) is None for m in ("nbconvert", "nbformat", "nbclient")),
    reason="nbconvert, nbformat or nbclient is not installed",
)


def _import_nbformat() -> None:
    """Import nbformat without the seconds jsonschema spends, at import, building
    rfc3987_syntax's grammar for the string format "iri" (no notebook schema uses it:
    jsonschema then leaves that one format unchecked)."""
    if "jsonschema" not in sys.modules and "rfc3987_syntax" not in sys.modules:
        sys.modules["rfc3987_syntax"] = None  # type: ignore[assignment]
        try:
            import nbformat  # noqa: F401
        finally:
            del sys.modules["rfc3987_syntax"]


@pytest.fixture(scope="module")
def students(tmp_path_factory) -> list[Path]:
    """The students' notebooks, written once by the command line."""
    from pentanb.cli import main

    _import_nbformat()

    out = tmp_path_factory.mktemp("students")
    assert main(["classroom", str(out)]) == 0
    return sorted(out.glob("*.ipynb"))


@needs_nbconvert
def test_the_students_version_has_no_solution_and_every_exercise(students):
    assert [p.name for p in students] == [p.name for p in sorted(ROOT.glob("notebooks/*.ipynb"))]
    for path in students:
        teacher, student = _read(ROOT / "notebooks" / path.name), _read(path)
        assert not [c for c in student["cells"] if classroom.SOLUTION_TAG in _tags(c)]
        kept = [c for c in teacher["cells"] if classroom.SOLUTION_TAG not in _tags(c)]
        assert [_source(c) for c in student["cells"]] == [_source(c) for c in kept]
        assert all(not c.get("outputs") for c in student["cells"] if c["cell_type"] == "code")
    found = {i for p in students for c in _read(p)["cells"] for i in _CHECK.findall(_source(c))}
    assert found == set(EXERCISES)


@needs_nbconvert
def test_the_students_version_never_overwrites_the_teachers(capsys):
    from pentanb.cli import main

    assert main(["classroom", str(ROOT / "notebooks")]) == 2
    assert "holds the teacher's notebooks" in capsys.readouterr().err
    with pytest.raises(ValueError, match="no notebooks found"):
        classroom.student_version(ROOT, notebooks=[])


def test_without_nbconvert_the_command_says_what_to_install(monkeypatch, tmp_path, capsys):
    from pentanb.cli import main

    monkeypatch.setitem(sys.modules, "nbconvert", None)  # import nbconvert fails
    monkeypatch.setitem(sys.modules, "nbconvert.exporters", None)
    with pytest.raises(ImportError, match=r'pip install -e "\.\[notebook\]"'):
        classroom.student_version(tmp_path)
    assert main(["classroom", str(tmp_path)]) == 2
    assert "needs nbconvert" in capsys.readouterr().err
    assert not list(tmp_path.iterdir())


KERNEL_NAME = "pentanb-classroom-python"


@pytest.fixture(scope="module")
def kernel_dir(tmp_path_factory) -> str:
    """A kernel spec directory whose only kernel runs ``sys.executable``."""
    from ipykernel.kernelspec import write_kernel_spec

    kernels = tmp_path_factory.mktemp("kernels")
    write_kernel_spec(kernels / KERNEL_NAME)
    return str(kernels)


def _run_sections(paths: list[Path], kernel_dir: str, cwd: Path) -> list[tuple[set, str]]:
    """The exercise sections of ``paths``, concatenated and executed in one kernel:
    (tags, standard output) of every code cell."""
    import os

    _import_nbformat()
    import nbclient
    import nbformat
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import KernelManager

    mine = {classroom.EXERCISE_TAG, classroom.SOLUTION_TAG}
    cells = [c for p in paths for c in nbformat.read(p, as_version=4).cells if mine & _tags(c)]
    nb = nbformat.v4.new_notebook(cells=cells)
    ksm = KernelSpecManager(kernel_dirs=[kernel_dir], ensure_native_kernel=False)
    km = KernelManager(kernel_name=KERNEL_NAME, kernel_spec_manager=ksm)
    env = dict(
        os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])
    )
    client = nbclient.NotebookClient(nb, km=km, timeout=600, allow_errors=False)
    client.execute(cwd=str(cwd), env=env)
    return [
        (
            _tags(c),
            "".join(o.get("text", "") for o in c.outputs if o.get("name") == "stdout"),
        )
        for c in nb.cells
        if c.cell_type == "code"
    ]


_LINE = re.compile(r"^(\d\d\.\d): (right|not quite|not answered yet)", re.M)


@pytest.mark.slow
@needs_nbconvert
def test_executed_the_teachers_solutions_are_right(kernel_dir, tmp_path):
    said = _run_sections(WITH_EXERCISES, kernel_dir, tmp_path)
    solutions = [_LINE.findall(out) for tags, out in said if classroom.SOLUTION_TAG in tags]
    asked = [_LINE.findall(out) for tags, out in said if classroom.SOLUTION_TAG not in tags]
    assert solutions == [[(i, "right")] for i in EXERCISES]
    assert [a for a in asked if a] == [[(i, "not answered yet")] for i in EXERCISES]


@pytest.mark.slow
@needs_nbconvert
def test_executed_the_students_checks_are_not_answered_yet(students, kernel_dir, tmp_path):
    said = _run_sections(students, kernel_dir, tmp_path)
    assert not [t for t, _ in said if classroom.SOLUTION_TAG in t]
    lines = [_LINE.findall(out) for _, out in said]
    assert [x for x in lines if x] == [[(i, "not answered yet")] for i in EXERCISES]


def test_the_public_functions_have_numpydoc_sections():
    """As tests/test_api_docs.py asks of the public modules."""
    import inspect

    from test_api_docs import _methods, problems

    found = {}
    for name in classroom.__all__:
        obj = getattr(classroom, name)
        if inspect.isclass(obj):
            for method, func, bound in _methods(obj):
                found[f"{name}.{method}"] = problems(func, bound)
        elif callable(obj):
            found[name] = problems(obj)
    assert {"check", "exercises", "student_version", "Exercise.check"} <= set(found)
    assert not any(found.values()), {k: v for k, v in found.items() if v}
