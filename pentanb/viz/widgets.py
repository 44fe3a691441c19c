"""Controls for the notebooks: :func:`panel`, and the checks every widget's arguments pass.

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

:func:`integer_argument` and :func:`number_argument` are the checks of the
widgets' own arguments (:func:`pentanb.explore`, :func:`pentanb.step_through`):
a value a slider cannot show is refused, naming the argument and its range,
never clamped.
"""

from __future__ import annotations

import inspect
import numbers
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import ipywidgets as W
from IPython.display import clear_output

from .. import _checks
from ..mesh import Mesh
from .three import MAX_PIXELS, MeshView, close_tree

__all__ = ["Panel", "panel", "control", "integer_argument", "number_argument"]


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
        return spec
    style = {"description_width": "initial"}
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


class Panel(W.VBox):
    """Controls above an output area and a 3D view; see :func:`panel`.

    Attributes
    ----------
    controls : dict of str -> ipywidgets.ValueWidget
        One widget per control, by name.
    output : ipywidgets.Output
        What the function prints and displays.
    view : MeshView or None
        The 3D view, made when the function first returns a Mesh.
    mesh : Mesh or None
        The mesh last returned.
    """

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
        self.output = W.Output()
        self.view: MeshView | None = None
        self.mesh: Mesh | None = None
        self._pictures = W.HBox([self.output], layout=W.Layout(flex_flow="row wrap"))
        row = W.HBox(list(self.controls.values()), layout=W.Layout(flex_flow="row wrap"))
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

        An exception from the function is shown in the output area and
        raised again (so a test that moves a control sees it).
        """
        if self._busy:  # a limit moved a control's value: one call does it all
            return
        self._busy = True
        try:
            values = self.values
            for name, rule in self._active.items():
                self.controls[name].disabled = not rule(values)
            for name, limit in self._limits.items():
                w = self.controls[name]
                top = limit(self.values)
                w.max = max(w.min, int(top) if isinstance(w, W.IntSlider) else float(top))
            values = self.values
            failure: BaseException | None = None
            with self.output:
                clear_output(wait=True)
                try:
                    result = self._draw(**values)
                except Exception as err:  # shown in the output area, raised below
                    failure = err
                    raise
            if failure is not None:
                raise failure
        finally:
            self._busy = False
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
        arguments are the controls' first values.
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
        draw, controls, refit=refit, limits=limits, active=active, width=width, height=height
    )
