"""The notebooks' building blocks: :func:`panel`, :func:`claims_table`, :func:`scheme_title`.

:func:`panel` is the slider wiring of the notebooks, written once: name the
controls, give a function of their values, and the panel calls it whenever a
control moves, shows what it prints and plots, and draws the mesh it returns
in a 3D view (:class:`pentanb.viz.three.MeshView`) that keeps the reader's
viewpoint.  A notebook's interactive cell is then the function and one call::

    def draw(scheme="pentagonalize", duals=2):
        mesh = pentanb.subdivide(pentanb.shapes.cube(), scheme, 1, duals)
        print(mesh)
        return mesh

    panel(draw, scheme=list(pentanb.SCHEMES), duals=(0, 4))

A call that takes longer than :data:`BUSY_AFTER` seconds shows a "computing"
note beside the controls until the new picture is sent.

:func:`claims_table` shows the paper's claims checked on a figure as a short
table of verdicts, each claim's full text one click away; it raises only if
a verdict differs from the one recorded in the package.  :func:`scheme_title`
names a scheme for a class: the comparison schemes of the package are the
*remeshing steps* of Loop's, sqrt(3), Catmull-Clark's and Doo-Sabin's
subdivisions smoothed by duals, not those subdivisions (which move the
points with their own weights), and their titles say so.

:func:`integer_argument` and :func:`number_argument` are the checks of the
widgets' own arguments (:func:`pentanb.explore`, :func:`pentanb.step_through`):
a value a slider cannot show is refused, naming the argument and its range,
never clamped.
"""

from __future__ import annotations

import html
import inspect
import numbers
import threading
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import ipywidgets as W
from IPython.display import clear_output

from .. import _checks
from ..mesh import Mesh
from .three import MAX_PIXELS, MeshView, close_tree

__all__ = [
    "Panel",
    "panel",
    "control",
    "integer_argument",
    "number_argument",
    "BUSY_AFTER",
    "LABEL_STYLE",
    "DROPDOWN_LAYOUT",
    "ClaimsTable",
    "claims_table",
    "SCHEME_TITLES",
    "scheme_title",
]

#: Seconds a call of a panel's function may take before the panel says it is busy.
BUSY_AFTER = 0.5
#: The controls' style: every label as wide as its text (ipywidgets' default
#: width cuts a label such as "sides / valence" to "sides / val...").
LABEL_STYLE = {"description_width": "initial"}
#: A drop-down's layout: as wide as its longest option, so that none is cut.
DROPDOWN_LAYOUT = {"width": "max-content"}


def integer_argument(value: object, name: str, low: int, high: int | None = None) -> int:
    """``value`` as an int, checked to lie in ``[low, high]`` (``high`` None: no bound).

    The package's one check of counts, :func:`pentanb._checks.count`.

    Raises
    ------
    TypeError
        ``value`` is not an integer (a bool, a float such as 1.5 or 2.0, a
        string such as ``"2"``); the message names ``name``.
    ValueError
        ``value`` is out of range; the message names ``name`` and the range.
    """
    return _checks.count(value, name, low, high)


def number_argument(value: object, name: str, low: float, high: float) -> float:
    """``value`` as a float, checked to lie in ``[low, high]``.

    Raises
    ------
    TypeError
        ``value`` is not a real number (a bool or a string is not); the
        message names ``name``.
    ValueError
        ``value`` is out of range (or not finite); the message names
        ``name`` and the range.
    """
    return _checks.number(value, name, low, high)


def _label(name: str) -> str:
    return name.replace("_", " ")


def control(name: str, spec: Any, value: Any = inspect.Parameter.empty) -> W.ValueWidget:
    """The widget of one control of a :func:`panel`.

    Parameters
    ----------
    name : str
        Its label (underscores shown as spaces).
    spec
        ``(low, high)`` or ``(low, high, step)`` of ints: an integer slider;
        the same with a float: a float slider; a list (of values, or of
        ``(label, value)`` pairs) or a dict ``{label: value}``: a drop-down;
        an ipywidgets value widget: itself.
    value : optional
        The first value (default: ``low``, or the first option).

    Raises
    ------
    TypeError
        A spec of none of these kinds.
    ValueError
        A first value the control cannot show (the message gives the range
        or the options).
    """
    given = value is not inspect.Parameter.empty
    if isinstance(spec, W.ValueWidget):
        if given:
            spec.value = value
        style = getattr(spec, "style", None)
        if style is not None and getattr(style, "description_width", None) == "":
            style.description_width = LABEL_STYLE["description_width"]  # (not cut either)
        return spec
    style = dict(LABEL_STYLE)
    if isinstance(spec, Mapping) or isinstance(spec, list):
        options = list(spec.items()) if isinstance(spec, Mapping) else list(spec)
        if not options:
            raise ValueError(f"control {name!r} has no options")
        values = [o[1] if isinstance(o, tuple) and len(o) == 2 else o for o in options]
        if given and value not in values:
            raise ValueError(f"{name} must be one of {values}, got {value!r}")
        return W.Dropdown(
            options=options,
            value=value if given else values[0],
            description=_label(name),
            style=style,
            layout=W.Layout(**DROPDOWN_LAYOUT),
        )
    if (
        isinstance(spec, tuple)
        and len(spec) in (2, 3)
        and all(isinstance(x, numbers.Real) and not isinstance(x, bool) for x in spec)
    ):
        low, high = spec[0], spec[1]
        step = spec[2] if len(spec) == 3 else 1
        if not low <= high or step <= 0:
            raise ValueError(f"control {name!r}: need low <= high and step > 0, got {spec}")
        integral = all(isinstance(x, numbers.Integral) for x in (low, high, step))
        if integral:
            first = low if not given else integer_argument(value, name, low, high)
            return W.IntSlider(
                value=first,
                min=low,
                max=high,
                step=step,
                description=_label(name),
                continuous_update=False,
                style=style,
            )
        first_f = float(low) if not given else number_argument(value, name, low, high)
        return W.FloatSlider(
            value=first_f,
            min=low,
            max=high,
            step=step,
            description=_label(name),
            continuous_update=False,
            style=style,
        )
    raise TypeError(
        f"control {name!r}: expected (low, high[, step]), a list or dict of options, "
        f"or an ipywidgets value widget, got {spec!r}"
    )


def _start_timer(seconds: float, callback: Callable[[], None]) -> threading.Timer:
    """``callback()`` in ``seconds``, on a daemon thread; ``.cancel()`` stops it."""
    timer = threading.Timer(seconds, callback)
    timer.daemon = True
    timer.start()
    return timer


class Panel(W.VBox):
    """Controls above an output area and a 3D view; see :func:`panel`.

    Attributes
    ----------
    controls : dict of str -> ipywidgets.ValueWidget
        One widget per control, by name.
    output : ipywidgets.Output
        What the function prints and displays.
    busy : ipywidgets.HTML
        "computing...", beside the controls, visible while a call has taken
        more than :attr:`busy_after` seconds and is not done (its picture
        not yet sent); hidden otherwise.
    busy_after : float
        That delay, in seconds (:data:`BUSY_AFTER` unless given).
    view : MeshView or None
        The 3D view, made when the function first returns a Mesh.
    mesh : Mesh or None
        The mesh last returned.
    calls : int
        How many times the function has been called (one per move of a
        control, however many controls a move changes through ``limits``).
    """

    #: Starts the busy delay: ``start_timer(seconds, callback)`` calls
    #: ``callback()`` after ``seconds`` unless the object it returns is
    #: ``.cancel()``-ed first.  A daemon :class:`threading.Timer` (the kernel
    #: sends the note while the function runs); the tests put a fake here,
    #: so that none depends on the clock or on the machine's load.
    start_timer = staticmethod(_start_timer)

    def __init__(
        self,
        draw: Callable[..., Mesh | None],
        controls: Mapping[str, Any],
        *,
        refit: bool | Iterable[str] = (),
        limits: Mapping[str, Callable[[dict], float]] | None = None,
        active: Mapping[str, Callable[[dict], bool]] | None = None,
        width: int = 420,
        height: int = 380,
        busy_after: float = BUSY_AFTER,
    ):
        if not callable(draw):
            raise TypeError(f"panel() needs a function to call, got {type(draw).__name__}")
        params = inspect.signature(draw).parameters
        takes_any = any(p.kind is inspect.Parameter.VAR_KEYWORD for p in params.values())
        unknown = [n for n in controls if n not in params and not takes_any]
        if unknown:
            raise TypeError(f"{draw.__name__}() takes no argument {', '.join(unknown)}")
        missing = [
            n
            for n, p in params.items()
            if n not in controls
            and p.default is inspect.Parameter.empty
            and p.kind not in (inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD)
        ]
        if missing:
            raise TypeError(
                f"no control for the argument {', '.join(missing)} of {draw.__name__}()"
            )
        self.busy_after = _checks.number(busy_after, "busy_after", 0.0, 3600.0)
        self._draw = draw
        self.controls: dict[str, W.ValueWidget] = {
            name: control(
                name, spec, params[name].default if name in params else inspect.Parameter.empty
            )
            for name, spec in controls.items()
        }
        for name in [*(limits or {}), *(active or {})]:
            if name not in self.controls:
                raise ValueError(f"no control named {name!r} (controls: {list(self.controls)})")
        self._limits = dict(limits or {})
        self._active = dict(active or {})
        self._refit = refit if isinstance(refit, bool) else set(refit)
        self._size = (
            _checks.count(width, "width", 1, MAX_PIXELS),
            _checks.count(height, "height", 1, MAX_PIXELS),
        )
        self._busy = False
        self.calls = 0
        self.output = W.Output()
        self.busy = W.HTML(
            '<span style="color:#555"><i class="fa fa-spinner fa-spin"></i> computing...</span>',
            layout=W.Layout(visibility="hidden", align_self="center"),
        )
        self.view: MeshView | None = None
        self.mesh: Mesh | None = None
        self._pictures = W.HBox([self.output], layout=W.Layout(flex_flow="row wrap"))
        row = W.HBox([*self.controls.values(), self.busy], layout=W.Layout(flex_flow="row wrap"))
        super().__init__([row, self._pictures])
        self.add_class("pentanb-panel")
        for w in self.controls.values():
            w.observe(self._on_change, names="value")
        self.refresh(refit=True)

    @property
    def values(self) -> dict[str, Any]:
        """The controls' current values, by name (None for a disabled control)."""
        return {
            name: None if getattr(w, "disabled", False) else w.value
            for name, w in self.controls.items()
        }

    def close(self) -> None:
        """Close the panel and every widget inside it (``close_tree``)."""
        self.mesh = None
        close_tree(self)

    def _on_change(self, change) -> None:
        owner = next(n for n, w in self.controls.items() if w is change["owner"])
        refit = self._refit if isinstance(self._refit, bool) else owner in self._refit
        self.refresh(refit=refit)

    def refresh(self, refit: bool = False) -> None:
        """Apply the limits, call the function again and show what it gives.

        One call of the function, and one drawing of the mesh it returns,
        per refresh.  If that takes more than :attr:`busy_after` seconds,
        :attr:`busy` is shown from then until it is done.  An exception from
        the function is shown in the output area and raised again (so a test
        that moves a control sees it).

        Parameters
        ----------
        refit : bool
            Point the 3D view's camera at the whole new mesh (else the
            reader's viewpoint is kept).
        """
        if self._busy:  # a limit moved a control's value: one call does it all
            return
        self._busy = True
        lock = threading.Lock()
        state = {"done": False, "shown": False}

        def show() -> None:  # on the timer's thread
            with lock:
                if not state["done"]:
                    state["shown"] = True
                    self.busy.layout.visibility = "visible"

        timer = self.start_timer(self.busy_after, show)
        try:
            self._refresh(refit)
        finally:
            with lock:
                state["done"] = True
            timer.cancel()
            join = getattr(timer, "join", None)
            if join is not None:  # no thread outlives the call (a cancelled timer ends at once)
                join()
            if state["shown"]:
                self.busy.layout.visibility = "hidden"
            self._busy = False

    def _refresh(self, refit: bool) -> None:
        values = self.values
        for name, rule in self._active.items():
            self.controls[name].disabled = not rule(values)
        for name, limit in self._limits.items():
            w = self.controls[name]
            top = limit(self.values)
            w.max = max(w.min, int(top) if isinstance(w, W.IntSlider) else float(top))
        values = self.values
        failure: BaseException | None = None
        self.calls += 1
        with self.output:
            clear_output(wait=True)
            try:
                result = self._draw(**values)
            except Exception as err:  # shown in the output area, raised below
                failure = err
                raise
        if failure is not None:
            raise failure
        if isinstance(result, Mesh):
            self.mesh = result
            if self.view is None:
                self.view = MeshView(result, width=self._size[0], height=self._size[1])
                self._pictures.children = (self.output, self.view)
            else:
                self.view.update(result, fit=refit)


def panel(
    draw: Callable[..., Mesh | None],
    /,
    *,
    refit: bool | Iterable[str] = (),
    limits: Mapping[str, Callable[[dict], float]] | None = None,
    active: Mapping[str, Callable[[dict], bool]] | None = None,
    width: int = 420,
    height: int = 380,
    busy_after: float = BUSY_AFTER,
    **controls: Any,
) -> Panel:
    """Sliders and drop-downs that call ``draw`` with their values whenever one moves.

    Parameters
    ----------
    draw : callable
        Called with one keyword argument per control.  What it prints or
        displays (a matplotlib figure, say) appears under the controls; a
        :class:`~pentanb.Mesh` it returns is drawn in a 3D view beside, the
        same view every time (the reader's viewpoint is kept).  Its default
        arguments are the controls' first values.  Draw a mesh once: return
        it for the 3D view, or plot it yourself and return None (a mesh of
        50,000 faces takes matplotlib over a second, the 3D view a tenth).
    refit : bool or names of controls
        Point the camera at the whole mesh again after these controls move
        (True: after every move).
    limits : dict name -> callable, optional
        Before every call, the slider ``name`` gets ``max = limit(values)``
        (``values``: every control's value, by name); e.g. the iterations a
        mesh can take without passing a size.
    active : dict name -> callable, optional
        The control ``name`` is enabled only while ``rule(values)`` is true;
        while disabled, ``draw`` gets None for it.
    width, height : int
        Size of the 3D view.
    busy_after : float
        Seconds after which a call still running shows "computing..."
        beside the controls (until its picture is sent).
    **controls
        One per argument of ``draw``: ``(low, high)`` or ``(low, high, step)``
        for a slider (integer or float, from the numbers given), a list or a
        dict ``{label: value}`` for a drop-down, or any ipywidgets value
        widget.  The label is the name, underscores shown as spaces.

    Returns
    -------
    Panel
        An ipywidgets box; the last expression of a cell shows it.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.viz.widgets import panel
    >>> def draw(duals=2):
    ...     return pentanb.subdivide(pentanb.shapes.tetrahedron(), "pentagonalize", 1, duals)
    >>> p = panel(draw, duals=(0, 12))
    >>> p.mesh.n_faces
    12
    """
    return Panel(
        draw,
        controls,
        refit=refit,
        limits=limits,
        active=active,
        width=width,
        height=height,
        busy_after=busy_after,
    )


# -- the claims of a figure, for a class --------------------------------------------------

#: Colours of the verdicts in :func:`claims_table` (text, background).
_BADGES = {
    "holds": ("#14532d", "#dcfce7"),
    "holds within tolerance": ("#14532d", "#ecfccb"),
    "does not hold as stated": ("#7c2d12", "#ffedd5"),
    "consistency check": ("#374151", "#f3f4f6"),
    "observation": ("#1e3a8a", "#dbeafe"),
    "changed": ("#ffffff", "#b91c1c"),
}

#: Longest text :func:`claims_table` shows of a statement before the click (characters).
_SHORT_QUOTE = 110
#: Statements whose texts share this many first characters are told apart.
_ALIKE = 25


def _common_words(texts: list[str]) -> str:
    """The longest start, ending at a space, that all ``texts`` share."""
    first = texts[0]
    n = 0
    while n < len(first) and all(len(t) > n and t[n] == first[n] for t in texts):
        n += 1
    return first if n == len(first) else first[: first.rfind(" ", 0, n) + 1]


def _short(text: str, limit: int = _SHORT_QUOTE) -> str:
    text = " ".join(text.split())
    if len(text) <= limit:
        return text
    cut = text[: limit - 1].rsplit(" ", 1)[0]
    return cut.rstrip(" ,;:.") + "\N{HORIZONTAL ELLIPSIS}"


class ClaimsTable:
    """The paper's claims checked on a figure, as a short table; see :func:`claims_table`.

    Shown as HTML in a notebook (one row per statement: its verdict, where
    the paper says it and what is checked, in a few words, the full
    statement one click away) and as one line per statement elsewhere.

    Attributes
    ----------
    claims : tuple of pentanb.figures.Claim
        The statements, in the order given.
    """

    def __init__(self, claims: Iterable[Any]):
        self.claims = tuple(claims)
        self._whats = self._what_texts()

    def _what_texts(self) -> list[str]:
        """What each statement checks, in a few words: a claim's reading (else the
        paper's words), a check's words, the property an observation states.
        Statements that would start alike are told apart by the paper's words
        when those differ, else by their measurements from where those differ."""
        texts = []
        for c in self.claims:
            if c.kind == "observation":
                text = c.criterion or c.quote
            elif c.kind == "consistency check":
                text = c.quote
            else:
                text = getattr(c, "reading", "") or c.quote
            texts.append(" ".join(str(text).split()))
        out = [_short(t) for t in texts]
        groups: dict[str, list[int]] = {}
        for i, t in enumerate(texts):
            groups.setdefault(t[:_ALIKE], []).append(i)
        for members in groups.values():
            if len(members) < 2:
                continue
            quotes = [" ".join(str(self.claims[i].quote).split()) for i in members]
            if len(set(quotes)) == len(quotes):
                for i, q in zip(members, quotes):
                    out[i] = _short(q)
                continue
            measured = [" ".join(str(self.claims[i].measured).split()) for i in members]
            common = len(_common_words(measured))
            for i, m in zip(members, measured):
                out[i] = _short(("\N{HORIZONTAL ELLIPSIS}" if common else "") + m[common:])
        return out

    def _verdict(self, c: Any) -> str:
        if c.kind == "observation":
            return "observation"
        if c.kind == "consistency check":
            return "consistency check"
        return str(c.verdict)

    @property
    def counts(self) -> dict[str, int]:
        """How many statements got each verdict (observations and checks apart), in order.

        Returns
        -------
        dict of str -> int
            ``"holds"``, ``"holds within tolerance"``, ``"does not hold as
            stated"``, ``"consistency check"``, ``"observation"``: the ones
            present.
        """
        out: dict[str, int] = {}
        for key in _BADGES:
            n = sum(self._verdict(c) == key for c in self.claims)
            if n:
                out[key] = n
        return out

    def summary(self) -> str:
        """One line: how many statements, by verdict.

        Returns
        -------
        str
            E.g. ``"3 claims of the paper: 2 hold, 1 does not hold as stated;
            1 observation beyond the paper"``.
        """
        c = self.counts
        parts = []
        n_claims = sum(c.get(k, 0) for k in list(_BADGES)[:3])
        if n_claims:
            said = [
                f"{c[k]} {word}"
                for k, word in (
                    ("holds", "hold" if c.get("holds", 0) != 1 else "holds"),
                    ("holds within tolerance", "within tolerance"),
                    ("does not hold as stated", "not as stated"),
                )
                if k in c
            ]
            noun = "claim" if n_claims == 1 else "claims"
            parts.append(f"{n_claims} {noun} of the paper: " + ", ".join(said))
        if "consistency check" in c:
            k = c["consistency check"]
            parts.append(f"{k} consistency check{'s' if k > 1 else ''}")
        if "observation" in c:
            k = c["observation"]
            parts.append(f"{k} observation{'s' if k > 1 else ''} beyond the paper")
        changed = sum(bool(x.regressed) for x in self.claims)
        if changed:
            parts.append(f"{changed} verdict{'s' if changed > 1 else ''} CHANGED")
        return "; ".join(parts) if parts else "no statements"

    def _badge(self, c: Any) -> str:
        key = "changed" if c.regressed else self._verdict(c)
        fg, bg = _BADGES[key]
        text = self._verdict(c) if not c.regressed else f"{c.verdict} (changed)"
        if c.kind == "observation" and not c.regressed:
            text = "observation: " + ("seen" if c.verdict == "holds" else "not seen")
        elif c.kind == "consistency check" and not c.regressed:
            text = f"check: {c.verdict}"
        return (
            f'<span style="color:{fg};background:{bg};padding:1px 6px;border-radius:8px;'
            f'white-space:nowrap">{html.escape(text)}</span>'
        )

    def _repr_html_(self) -> str:
        rows = []
        for c, what in zip(self.claims, self._whats):
            full = html.escape("\n".join(c.lines()))
            rows.append(
                "<tr>"
                f'<td style="text-align:left;vertical-align:top">{self._badge(c)}</td>'
                f'<td style="text-align:left;vertical-align:top;min-width:10em;max-width:16em">'
                f"{html.escape(str(c.section))}</td>"
                '<td style="text-align:left;vertical-align:top"><details><summary>'
                f"{html.escape(what)}</summary>"
                '<pre style="white-space:pre-wrap;font-size:85%;margin:4px 0">'
                f"{full}</pre></details></td></tr>"
            )
        titles = ("verdict", "where in the paper", "what is checked")
        head = "".join(f'<th style="text-align:left">{h}</th>' for h in titles)
        return (
            '<div class="pentanb-claims">'
            f"<p style='margin:2px 0'><b>{html.escape(self.summary())}</b> "
            "(click a row for the full statement and the measurement)</p>"
            f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table></div>"
        )

    def __str__(self) -> str:
        lines = [self.summary()]
        for c, what in zip(self.claims, self._whats):
            verdict = self._verdict(c) + (" (CHANGED)" if c.regressed else "")
            lines.append(f"  [{verdict}] {c.section}: {what}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        return str(self)


def claims_table(claims: Iterable[Any], *, check: bool = True) -> ClaimsTable:
    """The paper's claims on a figure, as a short table of verdicts for a class.

    Parameters
    ----------
    claims : iterable of pentanb.figures.Claim
        E.g. ``pentanb.figures.claims(7)``.
    check : bool
        Raise if a verdict differs from the one recorded in the package
        (``claim.regressed``): the package measures something else than
        when the statement was written.  A claim of the paper that does
        not hold as stated is a finding, shown as one, never an error.

    Returns
    -------
    ClaimsTable
        Shown by a notebook as a table: per statement its verdict, where
        the paper says it and what is checked (a claim's reading, a check's
        words, the property an observation states, shortened; where two
        would start alike, the paper's words or the measurement); a click on a row
        shows the full statement (the paper's words, the reading, the
        measurement, the criterion).

    Raises
    ------
    TypeError
        Something that is not a claim (it has no ``verdict``, ``kind``,
        ``regressed`` and ``lines``).
    RuntimeError
        With ``check``, a verdict other than the recorded one; the message
        names every such statement.

    Examples
    --------
    >>> from pentanb import figures
    >>> from pentanb.viz.widgets import claims_table
    >>> print(claims_table(figures.claims(6)).summary())
    4 claims of the paper: 4 hold
    """
    if isinstance(claims, (str, bytes)) or not isinstance(claims, Iterable):
        raise TypeError(f"claims must be an iterable of claims, got {type(claims).__name__}")
    items = list(claims)
    for c in items:
        if not all(hasattr(c, a) for a in ("verdict", "kind", "regressed", "lines", "quote")):
            raise TypeError(
                f"claims_table takes pentanb.figures.Claim objects, got {type(c).__name__}"
            )
    table = ClaimsTable(items)
    if check:
        changed = [c for c in items if c.regressed]
        if changed:
            raise RuntimeError(
                "verdicts differ from the ones recorded in the package:\n"
                + "\n".join(str(c) for c in changed)
            )
    return table


# -- scheme names for a class --------------------------------------------------------------

#: What each scheme of :data:`pentanb.SCHEMES` is, in words a student will not
#: mistake: the comparison schemes are the remeshing steps of Loop's, sqrt(3),
#: Catmull-Clark's and Doo-Sabin's subdivisions (Section 3 compares those
#: steps); smoothed by duals, as the paper smooths its own schemes, they are
#: not those subdivisions, whose vertex rules use other weights.
SCHEME_TITLES = {
    "pentagonalize": "Pentagonalization",
    "preserve_pentagons": "Pentagon preservation",
    "triangulate": "Simplest triangulation",
    "loop_remesh": "Loop's remeshing step",
    "sqrt3_remesh": "\N{SQUARE ROOT}3's remeshing step",
    "vertex_insertion": "Catmull-Clark's remeshing step (vertex insertion)",
    "corner_cutting": "Doo-Sabin's remeshing step (corner cutting)",
    "preserve_hexagons": "Hexagon preservation (dual of Loop's remeshing step)",
    "honeycomb": "Honeycomb (dual of \N{SQUARE ROOT}3's remeshing step)",
}


def scheme_title(scheme: Any, duals: int | None = None) -> str:
    """A scheme's name for a class: what it is, and the duals that smooth it.

    Parameters
    ----------
    scheme : str or Scheme
        A name of :data:`pentanb.SCHEMES`, a Scheme, or a Conway string
        scheme (its label is used).
    duals : int, optional
        Duals after each remeshing: ``" + 2 duals"`` is added (``" + 1 dual"``;
        nothing for None or 0).

    Returns
    -------
    str
        E.g. ``"Loop's remeshing step + 2 duals"``.

    Raises
    ------
    TypeError, ValueError
        As :func:`pentanb.subdivision.get_scheme` for a scheme it does not
        know; ``duals`` not an integer >= 0.
    """
    from ..subdivision import get_scheme

    s = get_scheme(scheme)
    name = str(getattr(s, "name", ""))
    title = SCHEME_TITLES.get(name) or str(getattr(s, "label", "") or name)
    if duals is None:
        return title
    k = _checks.count(duals, "duals", 0)
    return title if k == 0 else f"{title} + {k} dual{'s' if k != 1 else ''}"
