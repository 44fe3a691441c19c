"""The notebooks' building blocks in :mod:`pentanb.viz.widgets`: the panel's busy note
and its one drawing per move, the labels' width, the claims table, and the schemes'
titles for a class.

No test here reads a clock: the panel's busy delay runs on a timer the tests replace
(:attr:`pentanb.viz.widgets.Panel.start_timer`), firing it when they choose.
"""

from __future__ import annotations

import dataclasses
import html
import threading
from typing import ClassVar

import pytest

pytest.importorskip("ipywidgets")
pytest.importorskip("pythreejs")

import pentanb
from pentanb import shapes
from pentanb.figures.claim import CHECK, CLAIM, FAILS, HOLDS, OBSERVATION, WITHIN, Claim
from pentanb.notation import OPERATORS
from pentanb.viz import three, widgets


class FakeTimer:
    """What ``Panel.start_timer`` returns: remembers its delay and callback, fires on demand."""

    made: ClassVar[list[FakeTimer]] = []

    def __init__(self, seconds, callback, fire_at_start=False):
        self.seconds, self.callback, self.cancelled = seconds, callback, False
        FakeTimer.made.append(self)
        if fire_at_start:  # the call outlasts the delay: the callback comes while it runs
            callback()

    def cancel(self):
        self.cancelled = True

    def fire(self):
        if not self.cancelled:
            self.callback()


@pytest.fixture
def timers(monkeypatch):
    """The panel's timers, replaced: ``timers.slow = True`` fires each as it starts."""

    class Timers:
        slow = False

    t = Timers()
    FakeTimer.made = []
    monkeypatch.setattr(
        widgets.Panel,
        "start_timer",
        staticmethod(lambda s, cb: FakeTimer(s, cb, fire_at_start=t.slow)),
    )
    t.made = FakeTimer.made
    return t


def _visibility_changes(p):
    seen = []
    p.busy.layout.observe(lambda c: seen.append(c["new"]), names="visibility")
    return seen


# -- the busy note ------------------------------------------------------------------


def test_a_slow_call_shows_computing_while_it_runs_and_hides_it_after(timers):
    during = []
    holder = {}

    def draw(n=1):
        if "p" in holder:
            during.append(holder["p"].busy.layout.visibility)
        return pentanb.subdivide(shapes.tetrahedron(), "pentagonalize", 1, n)

    p = holder["p"] = widgets.panel(draw, n=(0, 4))
    assert p.busy.layout.visibility == "hidden"
    assert "computing" in p.busy.value
    seen = _visibility_changes(p)
    timers.slow = True
    p.controls["n"].value = 2
    assert during == ["visible"]  # shown before the function ran on
    assert seen == ["visible", "hidden"] and p.busy.layout.visibility == "hidden"
    assert timers.made[-1].seconds == widgets.BUSY_AFTER == 0.5
    assert timers.made[-1].cancelled


def test_a_quick_call_sends_no_busy_note(timers):
    p = widgets.panel(lambda n=1: None, n=(0, 4))
    seen = _visibility_changes(p)
    for n in (2, 3, 4):
        p.controls["n"].value = n
    assert seen == []  # no message to the browser at all
    assert len(timers.made) == 4 and all(t.cancelled for t in timers.made)


def test_a_timer_that_fires_after_the_call_shows_nothing(timers):
    p = widgets.panel(lambda n=1: None, n=(0, 4))
    seen = _visibility_changes(p)
    p.controls["n"].value = 2
    timers.made[-1].callback()  # a real timer's callback can still run once cancelled
    assert seen == [] and p.busy.layout.visibility == "hidden"


def test_the_busy_note_goes_when_the_function_fails(timers):
    def draw(n=1):
        if n > 1:
            raise RuntimeError("no such mesh")

    p = widgets.panel(draw, n=(1, 3))
    timers.slow = True
    with pytest.raises(RuntimeError, match="no such mesh"):
        p.controls["n"].value = 2
    assert p.busy.layout.visibility == "hidden"


def test_busy_after_is_the_delay_and_is_checked(timers):
    widgets.panel(lambda n=1: None, n=(0, 4), busy_after=2.5)
    assert timers.made[-1].seconds == 2.5
    with pytest.raises(ValueError, match="busy_after must be a number"):
        widgets.panel(lambda n=1: None, n=(0, 4), busy_after=-1)
    with pytest.raises(TypeError, match="busy_after"):
        widgets.panel(lambda n=1: None, n=(0, 4), busy_after="soon")


def test_the_real_timer_is_a_daemon_thread_that_can_be_cancelled():
    fired = []
    t = widgets.Panel.start_timer(3600.0, lambda: fired.append(1))
    assert isinstance(t, threading.Timer) and t.daemon and t.is_alive()
    t.cancel()
    t.join()
    assert fired == []


# -- one call and one drawing per move -----------------------------------------------


def test_one_call_and_one_drawing_per_move_even_when_a_limit_moves_a_slider(timers, monkeypatch):
    updates = []
    original = three.MeshView.update

    def counted(self, mesh, *args, **kwargs):
        updates.append(mesh.n_faces)
        return original(self, mesh, *args, **kwargs)

    monkeypatch.setattr(three.MeshView, "update", counted)
    seen = []

    def draw(shape="cube", iterations=2):
        seen.append((shape, iterations))
        return pentanb.subdivide(shapes.get(shape), "pentagonalize", iterations, 0)

    p = widgets.panel(
        draw,
        shape=["cube", "tetrahedron"],
        iterations=(0, 3),
        limits={"iterations": lambda v: 3 if v["shape"] == "cube" else 1},
    )
    assert p.calls == 1 and seen == [("cube", 2)] and updates == []  # made, not updated
    p.controls["shape"].value = "tetrahedron"  # the limit pulls iterations from 2 to 1
    assert p.controls["iterations"].value == 1
    assert seen == [("cube", 2), ("tetrahedron", 1)] and p.calls == 2
    # the tetrahedron pentagonalized once: 12 pentagons, drawn once
    assert updates == [12]
    p.controls["iterations"].value = 0
    assert p.calls == 3 and updates == [12, 4]


# -- the labels ---------------------------------------------------------------------


@pytest.mark.parametrize(
    "name, spec",
    [
        ("iterations", (0, 3)),
        ("sides_or_valence", (3, 8)),
        ("scale", (0.1, 0.9)),
        ("scheme", ["pentagonalize", "preserve_pentagons"]),
    ],
)
def test_every_label_is_as_wide_as_its_text(name, spec):
    # ipywidgets' default label width (80 pixels) shows "sides / val..."; "initial"
    # is the label's own width
    w = widgets.control(name, spec)
    assert w.style.description_width == "initial"
    assert w.description == name.replace("_", " ")


def test_a_drop_down_is_as_wide_as_its_longest_option():
    titles = {widgets.scheme_title(s): s for s in pentanb.SCHEMES}
    w = widgets.control("scheme", titles)
    assert w.layout.width == "max-content"  # the select's own width: its longest option


def test_a_given_widget_keeps_its_own_label_width_or_gets_room():
    import ipywidgets as W

    plain = widgets.control("edges", W.Checkbox(value=True, description="edges"))
    assert plain.style.description_width == "initial"
    fixed = W.Checkbox(value=True, description="edges", style={"description_width": "3em"})
    assert widgets.control("edges", fixed).style.description_width == "3em"


# -- the claims table -----------------------------------------------------------------


def _claim(key, verdict=HOLDS, recorded=None, kind=CLAIM, reading="", quote="the words"):
    return Claim(
        key,
        "Section 9",
        quote,
        f"{key} measured",
        f"{key} criterion",
        verdict,
        verdict if recorded is None else recorded,
        kind,
        reading,
    )


def test_claims_table_counts_the_verdicts_and_hides_the_full_text_behind_a_click():
    claims = [
        _claim("a", reading="pentagons only"),
        _claim("b", WITHIN, reading="close to the tile"),
        _claim("c", FAILS, reading="no wave <here>"),  # a finding: shown, no error
        _claim("d", kind=CHECK, quote="Euler's formula"),
        _claim("e", FAILS, kind=OBSERVATION),
    ]
    t = widgets.claims_table(claims)
    assert t.counts == {
        "holds": 1,
        "holds within tolerance": 1,
        "does not hold as stated": 1,
        "consistency check": 1,
        "observation": 1,
    }
    assert t.summary() == (
        "3 claims of the paper: 1 holds, 1 within tolerance, 1 not as stated; "
        "1 consistency check; 1 observation beyond the paper"
    )
    page = t._repr_html_()
    assert page.count("<tr>") == 1 + 5 and page.count("<details>") == 5
    # the short text: a claim's reading, a check's words, an observation's property
    for short in ("pentagons only", "close to the tile", "Euler&#x27;s formula", "e criterion"):
        assert f"<summary>{short}</summary>" in page
    assert "no wave &lt;here&gt;" in page and "<here>" not in page  # escaped
    # behind the click: every line of the statement
    for line in claims[2].lines():
        assert html.escape(line) in page
    assert "observation: not seen" in page and "check: holds" in page
    text = str(t).splitlines()
    assert text[0] == t.summary() and len(text) == 6
    assert text[3] == "  [does not hold as stated] Section 9: no wave <here>"


def test_claims_table_raises_only_on_a_changed_verdict():
    changed = _claim("fig99.changed", HOLDS, recorded=FAILS)
    with pytest.raises(RuntimeError, match=r"fig99\.changed") as err:
        widgets.claims_table([_claim("fine"), changed, _claim("finding", FAILS)])
    assert "fine" not in str(err.value).replace("fig99", "")
    t = widgets.claims_table([_claim("fine"), changed], check=False)
    assert "1 verdict CHANGED" in t.summary()
    assert "holds (changed)" in t._repr_html_() and "(CHANGED)" in str(t)


def test_claims_table_on_the_package_figures_matches_their_claims():
    claims = pentanb.figures.claims(6)
    t = widgets.claims_table(claims)
    assert len(t.claims) == len(claims) and t.counts == {"holds": len(claims)}


@pytest.mark.parametrize("bad", ["fig07", 7, [object()]])
def test_claims_table_refuses_what_is_not_claims(bad):
    with pytest.raises(TypeError, match="claims"):
        widgets.claims_table(bad)


def test_statements_that_start_alike_are_told_apart():
    same = "the construction, counted: "
    # the paper's words differ: they tell the statements apart
    t = widgets.claims_table(
        [
            _claim("loop", reading=same + "triangles", quote="Loop's words"),
            _claim("sqrt3", reading=same + "triangles", quote="sqrt(3)'s words"),
            _claim("c", reading="only pentagons"),
        ]
    )
    assert [line.split(": ", 1)[1] for line in str(t).splitlines()[1:]] == [
        "Loop's words",
        "sqrt(3)'s words",
        "only pentagons",
    ]
    # the same words: the measurements, from the first word where they differ
    a, b = _claim("edge", reading=same), _claim("angle", reading=same)
    a = dataclasses.replace(a, measured="after 2 duals: 0 spread of edge lengths 0.02")
    b = dataclasses.replace(b, measured="after 2 duals: 0.41 spread of face angles 0.14")
    shown = [line.split(": ", 1)[1] for line in str(widgets.claims_table([a, b])).splitlines()[1:]]
    dots = "\N{HORIZONTAL ELLIPSIS}"
    assert shown == [
        dots + "0 spread of edge lengths 0.02",  # (the 0 is its own: not cut in a word)
        dots + "0.41 spread of face angles 0.14",
    ]


def test_long_texts_are_cut_at_a_word_with_an_ellipsis():
    words = "pentagon " * 30
    t = widgets.claims_table([_claim("long", reading=words)])
    short = str(t).splitlines()[1].split(": ", 1)[1]
    assert short.endswith("\N{HORIZONTAL ELLIPSIS}") and len(short) <= 110
    assert set(short[:-1].split()) == {"pentagon"}


# -- the schemes' titles --------------------------------------------------------------


def test_every_scheme_has_a_title_and_the_comparison_ones_say_remeshing_step():
    assert set(widgets.SCHEME_TITLES) == set(pentanb.SCHEMES)
    for name, s in pentanb.SCHEMES.items():
        title = widgets.scheme_title(name)
        if s.family == "comparison" and name != "triangulate":
            assert "remeshing step" in title, title
    assert widgets.scheme_title("loop_remesh") == "Loop's remeshing step"
    assert widgets.scheme_title("vertex_insertion", 2).startswith("Catmull-Clark's remeshing")
    assert widgets.scheme_title("corner_cutting", 2).startswith("Doo-Sabin's remeshing")


def test_scheme_title_counts_the_duals():
    assert widgets.scheme_title("pentagonalize", 0) == "Pentagonalization"
    assert widgets.scheme_title("pentagonalize", 1) == "Pentagonalization + 1 dual"
    assert widgets.scheme_title(pentanb.SCHEMES["sqrt3_remesh"], 4) == (
        "\N{SQUARE ROOT}3's remeshing step + 4 duals"
    )
    assert widgets.scheme_title("dg") == pentanb.notation.resolve("dg").label
    with pytest.raises(ValueError, match="unknown scheme"):
        widgets.scheme_title("loop")
    with pytest.raises(ValueError, match="duals must be an integer"):
        widgets.scheme_title("pentagonalize", -2)


def test_each_scheme_names_the_conway_operator_that_calls_it():
    """What notebook 06 prints from the registry agrees with notebook 10's letters."""
    by_func = {op.func: op for op in OPERATORS.values()}
    for name, s in pentanb.SCHEMES.items():
        op = by_func.get(s.func)
        if op is None:  # (triangulate and pentagonalize's letter wraps it)
            continue
        assert s.conway is not None and s.conway.split()[0] == op.name, (name, op.letter)
    assert pentanb.SCHEMES["sqrt3_remesh"].conway == "needle" == OPERATORS["n"].name


def test_a_move_with_the_real_timer_leaves_no_thread_behind():
    before = set(threading.enumerate())
    p = widgets.panel(lambda n=1: None, n=(0, 4))  # the real timer: busy_after 0.5 s
    p.controls["n"].value = 3
    assert p.calls >= 2
    assert set(threading.enumerate()) <= before
