"""Hostile arguments (issue 24, items 3 and 5): every bound checked before work starts.

Each case is one the issue reported: a count that ran for minutes, a size
that was built before its check, a wrong type that failed late or with a
bare error.  No test here reads a clock: a refusal "before work starts" is
shown by counting the work (the operators are wrapped by counters that
fail the test, fast, past a small budget, as the old code would have run
on for minutes), and "linear" by counting the interpreter's line events.
Nothing here runs long on the current code; the few cases that need a
memory limit run in a subprocess of their own (marked slow).
"""

from __future__ import annotations

import dataclasses
import gc
import os
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import pentanb
import pentanb.analysis.convergence as convergence
import pentanb.analysis.spectral as spectral
import pentanb.analysis.spectral.characteristic as characteristic
import pentanb.analysis.spectral.local as local
import pentanb.analysis.spectral.neighbourhood as neighbourhood
import pentanb.notation.build as build
import pentanb.schemes.smoothing as smoothing
import pentanb.subdivision
from pentanb import MeshError, shapes
from pentanb._checks import MAX_STEPS, count, excerpt, number, shown
from pentanb.notation import NotationError, conway, reduce_notation
from pentanb.notation.grammar import MAX_DIGITS, MAX_LENGTH, parse
from pentanb.notation.operators import OPERATORS


class Overrun(Exception):
    """Work went on past the budget of a test (the refusal did not come first)."""


def counter(func, budget: int):
    """``func`` wrapped: calls are counted in ``wrapped.calls``; past ``budget``, Overrun."""

    def wrapped(*args, **kwargs):
        wrapped.calls += 1
        if wrapped.calls > budget:
            raise Overrun(f"{func.__name__} called more than {budget} times")
        return func(*args, **kwargs)

    wrapped.calls = 0
    return wrapped


@pytest.fixture
def cube():
    return shapes.cube()


# ====================================================================== the helper
@pytest.mark.parametrize(
    "value, error, message",
    [
        (True, TypeError, r"^n must be an integer in \[0, 10\], got bool True$"),
        (1.0, TypeError, r"^n must be an integer in \[0, 10\], got float 1\.0$"),
        ("3", TypeError, r"^n must be an integer in \[0, 10\], got str '3'$"),
        (None, TypeError, r"^n must be an integer in \[0, 10\], got NoneType None$"),
        (np.array([1, 2]), TypeError, r"^n must be an integer in \[0, 10\], got ndarray"),
        (-1, ValueError, r"^n must be an integer in \[0, 10\], got -1$"),
        (11, ValueError, r"^n must be an integer in \[0, 10\], got 11$"),
        (10**5000, ValueError, r"got an integer of about 5,001 digits$"),
    ],
    ids=["bool", "float", "str", "None", "array", "negative", "over", "5000 digits"],
)
def test_count_refuses_with_the_name_and_the_range(value, error, message):
    with pytest.raises(error, match=message):
        count(value, "n", 0, 10)


def test_count_takes_python_and_numpy_integers():
    assert count(np.int64(3), "n") == 3 and type(count(np.int64(3), "n")) is int
    assert count(np.uint8(3), "n", 3) == 3
    assert count(np.array(4), "n") == 4  # a 0-d integer array
    assert count(2**70, "n") == 2**70


def test_number_refuses_with_the_name_and_the_range():
    with pytest.raises(TypeError, match=r"^x must be a number in \(0, 1\), got str '0\.5'$"):
        number("0.5", "x", 0, 1, open_low=True, open_high=True)
    with pytest.raises(ValueError, match=r"^x must be a finite number > 0, got nan$"):
        number(float("nan"), "x", 0, open_low=True)
    with pytest.raises(ValueError, match=r"^x must be a finite number > 0, got inf$"):
        number(float("inf"), "x", 0, open_low=True)
    assert number(2, "x", 0) == 2.0


def test_messages_never_echo_megabytes():
    assert len(shown("x" * 10**6)) < 100
    assert len(shown(-(10**5000))) < 60
    text = excerpt("t" * 100_000 + "T", 99_990, 100_001)
    assert len(text) < 120 and "99,990" in text


# ====================================================================== smooth and subdivide
def test_smooth_refuses_a_step_count_over_the_cap_before_the_first_dual(monkeypatch, cube):
    dual = counter(smoothing.dual, 10)
    monkeypatch.setattr(smoothing, "dual", dual)
    with pytest.raises(ValueError, match=r"^duals must be an integer in \[0, 100,000\]"):
        pentanb.smooth(cube, 10**7)
    assert dual.calls == 0
    assert pentanb.smooth(cube, 4).n_faces == 6 and dual.calls == 4


def test_subdivide_checks_progress_before_the_first_step(cube):
    scheme = counter(pentanb.pentagonalize, 10)
    with pytest.raises(TypeError, match=r"^progress must be a callable .*, got str 'yes'$"):
        pentanb.subdivide(cube, scheme, 2, progress="yes")
    assert scheme.calls == 0


@pytest.mark.parametrize("bad", [1.5, "2", None, True])
def test_subdivide_wrong_types_are_type_errors_as_in_the_explorer(cube, bad):
    with pytest.raises(TypeError, match=r"^iterations must be an integer"):
        pentanb.subdivide(cube, "pentagonalize", bad)
    with pytest.raises(TypeError, match=r"^iterations must be an integer"):
        pentanb.explore(cube, iterations=bad if bad is not None else "None")  # None: default


@pytest.mark.parametrize("bad", [5, None, 2.5])
def test_a_scheme_of_a_wrong_type_is_a_type_error(cube, bad):
    with pytest.raises(TypeError, match=r"^scheme must be a scheme's name"):
        pentanb.subdivide(cube, bad)


def test_a_callable_that_hands_its_input_back_once_then_grows_is_guarded(cube):
    """The old guard looked at the first iteration only: growth 1, so let every later
    one through (and ran out of memory).  Each iteration is guarded now."""

    def scheme(m):
        scheme.calls += 1
        if scheme.calls > 3:
            raise Overrun("the guard let a growing callable run on")
        return m if scheme.calls == 1 else pentanb.pentagonalize(m)

    scheme.calls = 0
    with pytest.raises(MeshError, match="if it grows as its last iteration did"):
        pentanb.subdivide(cube, scheme, 20, 2, max_bytes=2_000_000)
    assert scheme.calls == 2  # the growth seen in the second predicts the refusal


def test_a_callable_s_duals_are_checked_before_they_run(monkeypatch, cube):
    dual = counter(pentanb.subdivision.dual, 0)
    monkeypatch.setattr(pentanb.subdivision, "dual", dual)
    big = shapes.torus(64, 32)
    with pytest.raises(MeshError, match=r"^the duals of .* iteration 1 of 1 "):
        pentanb.subdivide(cube, lambda m: big, 1, 2, max_bytes=200_000)
    assert dual.calls == 0


def test_subdivide_names_a_long_conway_scheme_by_an_excerpt(cube):
    with pytest.raises(MeshError) as info:
        pentanb.subdivide(cube, "t" * 1000, 1)
    assert len(str(info.value)) < 500


# ====================================================================== the explorer
def test_the_explorer_caps_its_iterations_before_building(monkeypatch):
    import pentanb.viz.explorer as ex

    sub = counter(ex.subdivide, 50)
    predict = counter(ex.predict_counts, 1000)
    monkeypatch.setattr(ex, "subdivide", sub)
    monkeypatch.setattr(ex, "predict_counts", predict)
    with pytest.raises(ValueError, match=r"^max_iterations must be an integer in \[0, 1,000\]"):
        pentanb.explore(
            "icosahedron", "triangulate", duals=0, iterations=10**6, max_iterations=10**6
        )
    assert sub.calls == predict.calls == 0


def test_the_explorer_stops_predicting_at_a_fixed_point(monkeypatch):
    """Triangulating triangles keeps the counts: the size checks stop at the first
    level instead of predicting every level (10**6 of them, minutes, before)."""
    import pentanb.viz.explorer as ex

    predict = counter(ex.predict_counts, 40)
    monkeypatch.setattr(ex, "predict_counts", predict)
    e = pentanb.explore("icosahedron", "triangulate", duals=0, iterations=0, max_iterations=1000)
    e._refuse_too_large(e._base("icosahedron"), 1000)
    assert e._builds_at_least(10**9) is False
    assert predict.calls <= 4
    e.close()


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (
            {"max_iterations": 10**6},
            ValueError,
            r"^max_iterations must be an integer in \[0, 1,000\]",
        ),
        ({"max_iterations": 1.5}, TypeError, r"^max_iterations must be an integer in \[0, 1,000\]"),
        (
            {"max_iterations": None},
            TypeError,
            r"^max_iterations must be an integer in \[0, 1,000\]",
        ),
        ({"width": -100}, ValueError, r"^width must be an integer in \[1, 16,384\], got -100$"),
        ({"height": 0}, ValueError, r"^height must be an integer in \[1, 16,384\], got 0$"),
    ],
)
def test_the_explorer_names_a_bad_argument(kwargs, error, message):
    with pytest.raises(error, match=message):
        pentanb.explore("cube", **kwargs)


@pytest.mark.parametrize("bad, error", [("10", TypeError), (None, TypeError), (-1, ValueError)])
def test_the_slider_bound_names_max_faces(cube, bad, error):
    with pytest.raises(error, match=r"^max_faces must be an integer >= 0, got "):
        pentanb.max_iterations(cube, "pentagonalize", max_faces=bad)


# ====================================================================== Conway strings
@pytest.mark.parametrize(
    "call",
    [
        lambda: conway("dC", max_faces="10"),
        lambda: conway("dC", max_faces=None),
        lambda: conway("dC", max_faces=1.5),
    ],
)
def test_conway_names_max_faces(call):
    with pytest.raises(TypeError, match=r"^max_faces must be an integer >= 1, got "):
        call()


@pytest.mark.parametrize("function", ["canonical", "planarize"])
@pytest.mark.parametrize(
    "bad, error", [(1.5, TypeError), (None, TypeError), ("10", TypeError), (10**6, ValueError)]
)
def test_positions_name_max_iterations(function, bad, error, cube):
    with pytest.raises(error, match=r"^max_iterations must be an integer in \[0, 10,000\], got "):
        getattr(pentanb, function)(cube, max_iterations=bad)


def test_a_number_of_thousands_of_digits_is_refused_before_it_is_converted():
    with pytest.raises(NotationError, match=rf"has 5,000 digits.*at most {MAX_DIGITS}") as info:
        conway("k" + "9" * 5000 + "C")
    assert len(str(info.value)) < 400  # (was Python's "Exceeds the limit (4300 digits)")
    assert info.value.position == 1


def test_a_long_string_is_quoted_only_where_it_fails(monkeypatch):
    """The counts stop at the first step too large (no 47,000-digit integers), and the
    message quotes the operator there, not the 100,000 characters."""
    t = OPERATORS["t"]
    counts = counter(t.counts, 100)
    monkeypatch.setitem(OPERATORS, "t", dataclasses.replace(t, counts=counts))
    text = "t" * (MAX_LENGTH - 1) + "T"
    with pytest.raises(ValueError, match=r"over max_faces=1,000,000$") as info:
        conway(text)
    assert len(str(info.value)) < 400 and "at position 99,98" in str(info.value)
    assert counts.calls < 20


def test_a_string_over_the_length_limit_is_refused_before_it_is_reduced(monkeypatch):
    reduce = counter(build._reduce, 0)
    monkeypatch.setattr(build, "_reduce", reduce)
    with pytest.raises(NotationError, match=r"of 100,001 characters .* at most 100,000") as info:
        conway("d" * MAX_LENGTH + "C", reduce=True)
    assert len(str(info.value)) < 400 and reduce.calls == 0
    with pytest.raises(NotationError) as info:
        parse("x" * 50_000 + "C")
    assert len(str(info.value)) < 500 and info.value.position == 0


def _lines(call, budget: float = float("inf")) -> int:
    """Line events the interpreter runs in pentanb's own code for ``call()``: a count
    of work, not a time (Overrun past ``budget``, so that super-linear work fails fast).

    Only pentanb's lines count, and the collector is held off during the call: a
    collection there would run other tests' finalizers (a widget's ``__del__``) and
    their lines would count as this call's work.
    """
    events = 0
    package = os.path.dirname(pentanb.__file__)

    def trace(frame, event, arg):
        nonlocal events
        if not frame.f_code.co_filename.startswith(package):
            return None
        if event == "line":
            events += 1
            if events > budget:
                raise Overrun(f"more than {budget:,.0f} line events")
        return trace

    gc.collect()
    was_enabled = gc.isenabled()
    gc.disable()
    sys.settrace(trace)
    try:
        call()
    finally:
        sys.settrace(None)
        if was_enabled:
            gc.enable()
    return events


@pytest.mark.parametrize(
    "make",
    [
        lambda n: "g" * n + "dd" * (n // 2) + "T",  # the case (117 s at n = 8,000)
        lambda n: "d" + "kd" * n + "C",
        lambda n: "dpd" * n + "adad" * n,
    ],
)
def test_reductions_take_time_linear_in_the_length(make):
    small = _lines(lambda: reduce_notation(make(200)))
    # 4x the length: ~4x the work (16x when quadratic)
    _lines(lambda: reduce_notation(make(800)), budget=4.6 * small)


def test_long_reductions_give_their_answer():
    """(117 s and more than 25 s before.)"""
    text = "g" * 8000 + "dd" * 4000 + "T"
    _lines(lambda: reduce_notation(text), budget=100 * len(text))
    assert reduce_notation(text) == "g" * 8000 + "T"
    text = "dd" * 20_000 + "C"
    _lines(lambda: conway(text, reduce=True), budget=100 * len(text))
    assert reduce_notation(text) == "C"
    assert conway(text, reduce=True).n_faces == 6


# ====================================================================== analysis
def test_dual_convergence_refuses_millions_of_duals_at_once(monkeypatch, cube):
    dual = counter(convergence.dual, 0)
    sub = counter(convergence.subdivide, 0)
    monkeypatch.setattr(convergence, "dual", dual)
    monkeypatch.setattr(convergence, "subdivide", sub)
    with pytest.raises(ValueError, match=r"^duals must be an integer in \[2, 2,000\]"):
        convergence.dual_convergence(cube, duals=2 * 10**6)
    with pytest.raises(TypeError, match=r"^duals must be an integer"):
        convergence.dual_convergence(cube, duals=4.0)
    with pytest.raises(TypeError, match=r"^dual_convergence expects a pentanb\.Mesh"):
        convergence.dual_convergence(None)
    assert dual.calls == sub.calls == 0


def test_subdivision_convergence_refuses_before_the_first_level(monkeypatch, cube):
    sub = counter(convergence.subdivide, 0)
    monkeypatch.setattr(convergence, "subdivide", sub)
    with pytest.raises(MeshError, match="iteration"):
        convergence.subdivision_convergence(cube, iterations=40)
    with pytest.raises(TypeError, match=r"^iterations must be an integer"):
        convergence.subdivision_convergence(cube, iterations=2.0)
    assert sub.calls == 0


def test_local_spectrum_checks_the_size_before_building_the_pyramid(monkeypatch):
    pyramid = counter(spectral.pyramid, 0)
    monkeypatch.setattr(local, "pyramid", pyramid)
    monkeypatch.setattr(neighbourhood, "pyramid", pyramid)  # (element_fate's)
    with pytest.raises(ValueError, match=r"^size=100,000,000: the pyramid .* over max_faces"):
        spectral.local_spectrum("pentagonalize", "vertex", 10**8)
    with pytest.raises(ValueError, match=r"^size=70,000: the pyramid .* over max_faces=60,000"):
        spectral.local_spectrum("pentagonalize", "vertex", 70_000)  # (IndexError before)
    with pytest.raises(ValueError, match=r"^max_faces must be an integer >= 1, got 0$"):
        spectral.local_spectrum("pentagonalize", "vertex", 3, max_faces=0)  # (IndexError)
    with pytest.raises(TypeError, match=r"^max_faces must be an integer"):
        spectral.local_spectrum("pentagonalize", "vertex", 3, max_faces="10")
    with pytest.raises(TypeError, match=r"^size must be an integer >= 3"):
        spectral.local_spectrum("pentagonalize", "vertex", 3.0)
    assert pyramid.calls == 0


def test_ring_contraction_refuses_ten_thousand_iterations_at_once(monkeypatch):
    sub = counter(pentanb.subdivision.subdivide, 0)
    monkeypatch.setattr(pentanb.subdivision, "subdivide", sub)
    with pytest.raises(MeshError, match="iteration"):
        spectral.ring_contraction("pentagonalize", "vertex", 3, iterations=10**4)
    assert sub.calls == 0


def test_characteristic_map_refuses_levels_too_large_before_building_them(monkeypatch):
    sp = spectral.local_spectrum("pentagonalize", "vertex", 3)
    step = counter(characteristic._build_step, 0)
    monkeypatch.setattr(characteristic, "_build_step", step)
    with pytest.raises(ValueError, match=r"^iterations must be an integer in \[0, 100,000\]"):
        spectral.characteristic_map(sp, iterations=10**6)
    with pytest.raises(MeshError, match=r"over MAP_MAX_FACES=1,000,000"):
        spectral.characteristic_map(sp, iterations=1000)
    with pytest.raises(TypeError, match=r"^iterations must be an integer"):
        spectral.characteristic_map(sp, iterations=2.0)
    assert step.calls == 0


def test_measures_name_a_mesh_that_is_not_one():
    with pytest.raises(TypeError, match=r"^planarity expects a pentanb\.Mesh, got NoneType$"):
        pentanb.analysis.planarity(None)
    with pytest.raises(TypeError, match=r"^radius_spread expects a pentanb\.Mesh"):
        pentanb.analysis.radius_spread("cube")


def test_the_lateral_study_refuses_before_building(monkeypatch):
    import pentanb.analysis.lateral as lateral

    sub = counter(lateral.subdivide, 0)
    monkeypatch.setattr(lateral, "subdivide", sub)
    study = lateral.study.__wrapped__  # (no cache)
    with pytest.raises(MeshError):
        study(40)
    with pytest.raises(TypeError, match=r"^iterations must be an integer"):
        study(2.0)
    assert sub.calls == 0
    with pytest.raises(ValueError, match=r"^samples must be an integer in \[3, 10,000,000\]"):
        lateral.wavelength([0, 1, 2], [0, 1, 0], samples=10**12)


# ====================================================================== views
def test_a_view_refuses_bad_sizes_with_their_name(cube):
    with pytest.raises(ValueError, match=r"^width must be an integer in \[1, 16,384\], got -100$"):
        pentanb.view(cube, width=-100)
    with pytest.raises(ValueError, match=r"^height must be an integer in \[1, 16,384\], got 0$"):
        pentanb.view(cube, height=0)  # (ZeroDivisionError before)
    with pytest.raises(TypeError, match=r"^width must be an integer .* got float 600\.0$"):
        pentanb.view(cube, width=600.0)


def _drawn(v):
    return np.asarray(v.face_geometry.attributes["position"].array, dtype=np.float64)


@pytest.mark.parametrize("scale, shift", [(1e300, 0.0), (1.7e307, 0.0), (1e-300, 0.0), (1.0, 1e12)])
def test_a_view_frames_any_finite_coordinates(cube, scale, shift):
    m = cube.with_vertices(cube.vertices * scale + shift)
    v = pentanb.view(m)
    drawn = _drawn(v)
    camera = np.array(v.camera.position)
    assert np.isfinite(drawn).all() and np.isfinite(camera).all()
    assert 0.25 < np.abs(drawn).max() < 4  # the cube, scaled for the camera
    assert 0 < v.camera.near < v.camera.far < np.inf
    # the drawing is the cube's shape, exactly scaled
    offset, exponent = v.frame
    np.testing.assert_allclose(drawn[:8], np.ldexp(m.vertices - offset, -exponent), rtol=1e-6)
    v.close()


def test_a_view_of_ordinary_coordinates_draws_them_as_they_are(cube):
    v = pentanb.view(cube)
    assert v.frame[1] == 0 and not v.frame[0].any()
    assert np.array_equal(_drawn(v)[:8], cube.vertices.astype(np.float32))
    # a mesh the frame cannot draw gets its own, and the camera follows
    v.update(cube.with_vertices(cube.vertices * 1e300))
    assert v.frame[1] > 900 and np.isfinite(np.array(v.camera.position)).all()
    v.update(cube, fit=True)
    assert v.frame[1] == 0
    v.close()


# ====================================================================== the command line
def test_the_demo_exits_quietly_on_a_closed_pipe():
    """``python -m pentanb demo | head -c 10``: the reader is gone before anything is
    written (its end of the pipe closed at once), so the write always fails."""
    p = subprocess.Popen(
        [sys.executable, "-m", "pentanb", "demo"], stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    p.stdout.close()
    err = p.stderr.read()
    p.stderr.close()
    assert p.wait() == 141
    assert err == b"", err.decode(errors="replace")


# ====================================================================== in a process of their own
#: Address space of each case's process (bytes).
MEMORY = 2 << 30

PRELUDE = """
import resource, numpy as np, pentanb as pb
resource.setrlimit(resource.RLIMIT_AS, ({memory}, {memory}))
"""

#: name -> (code, the error it must end in).  Each would have run out of memory before.
ISOLATED = {
    "a 10**8-gon for local_spectrum": (
        "from pentanb.analysis.spectral import local_spectrum\n"
        "local_spectrum('pentagonalize', 'vertex', 10**8, max_faces=10**9)",
        "ValueError: size=100,000,000",
    ),
    "a callable that grows after handing its input back": (
        "calls = []\n"
        "def s(m):\n"
        "    calls.append(1)\n"
        "    return m if len(calls) == 1 else pb.subdivide(m, 'pentagonalize', 1, 0)\n"
        "pb.subdivide(pb.shapes.cube(), s, 30)",
        "MeshError: s iteration",  # (pentanb.mesh.coerce.MeshError)
    ),
}


@pytest.mark.slow
@pytest.mark.parametrize("name", list(ISOLATED))
def test_memory_hungry_requests_are_refused_under_a_memory_limit(name):
    body, expected = ISOLATED[name]
    code = PRELUDE.format(memory=MEMORY) + textwrap.dedent(body)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=900)
    assert out.returncode == 1, out.stderr[-2000:]
    last = out.stderr.strip().splitlines()[-1]
    assert re.sub(r"^[\w.]*\.(?=\w+Error)", "", last).startswith(expected), last
    assert "MemoryError" not in out.stderr


def test_the_default_limit_counts_the_address_space_limit(tmp_path, monkeypatch):
    """Under ``ulimit -v`` (a 4 GiB limit, as the issue's battery ran) the guard's
    default is the room left there, not the machine's free memory."""
    import resource

    import pentanb.memory as memory

    status = tmp_path / "status"
    status.write_text("Name:\tpython\nVmSize:\t  100000 kB\nVmRSS:\t 5000 kB\n")
    monkeypatch.setattr(resource, "getrlimit", lambda which: (4 << 30, resource.RLIM_INFINITY))
    limit = memory.default_max_bytes(tmp_path / "no meminfo", tmp_path / "no cgroup", status)
    assert limit == (4 << 30) - 100000 * 1024
    monkeypatch.setattr(resource, "getrlimit", lambda which: (resource.RLIM_INFINITY,) * 2)
    assert memory._address_space_room(status) is None


def test_the_step_cap_is_one_constant():
    assert pentanb.subdivision.MAX_STEPS == MAX_STEPS == 100_000
    assert re.search(r"MAX_STEPS", smoothing.smooth.__doc__)


def test_bounded_keeps_a_short_message_and_cuts_a_long_one():
    from pentanb._checks import bounded

    assert bounded("face 3 repeats vertex 2") == "face 3 repeats vertex 2"
    long = "face 0 [" + ", ".join(["0, 1, 2"] * 300_000) + "] repeats vertex 0"
    cut = bounded(long)
    assert len(cut) < 2_100
    assert cut.startswith("face 0 [0, 1, 2") and cut.endswith("repeats vertex 0")
    assert f"[{len(long):,} characters in all]" in cut
    assert bounded("x" * 50, limit=10) == "xxxxx ... [50 characters in all] ... xxxxx"
