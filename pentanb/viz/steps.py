"""A classroom step-through of the paper's schemes (Section 5), driven by a slider.

:func:`step_through` (also ``pentanb.step_through``) shows the stages of
:func:`pentanb.viz.stages.stages` one at a time in one
:class:`~pentanb.viz.three.MeshView`, updated in place.
"""

from __future__ import annotations

import html

import ipywidgets as W

from ..mesh import Mesh
from ..schemes.registry import Scheme
from .drawing import Drawing
from .stages import check_stage_arguments, stages
from .three import MAX_PIXELS, MeshView, close_tree, slider_stack
from .widgets import integer_argument

__all__ = ["StepThrough", "step_through"]


class StepThrough(W.VBox):
    """A step slider, a caption and one :class:`MeshView` (updated in place).

    Build it with :func:`step_through`.

    Attributes
    ----------
    step : ipywidgets.IntSlider
    caption : ipywidgets.HTML
    view : MeshView
    stages : list of (caption, Drawing or Mesh)
    scheme : Scheme
    """

    def __init__(
        self,
        mesh: Mesh,
        scheme: str | Scheme = "pentagonalize",
        *,
        duals: int = 2,
        scale: float | None = None,
        width: int = 600,
        height: int = 450,
    ):
        self.scheme, _, _ = check_stage_arguments(mesh, scheme, duals, {"scale": scale})
        width = integer_argument(width, "width", 1, MAX_PIXELS)
        height = integer_argument(height, "height", 1, MAX_PIXELS)
        self.stages: list[tuple[str, Drawing | Mesh]] = stages(
            mesh, self.scheme, duals=duals, scale=scale
        )
        self.step = W.IntSlider(
            value=0,
            min=0,
            max=len(self.stages) - 1,
            description="step",
            continuous_update=True,
            layout=W.Layout(width="420px"),
        )
        self.caption = W.HTML(self._caption(0))
        self.view = MeshView(self.stages[0][1], width=width, height=height)
        self.step.observe(self._on_step, names="value")
        super().__init__([self.step, self.caption, self.view])
        self.add_class("pentanb-steps")

    def _caption(self, k: int) -> str:
        return f"<b>{k}/{len(self.stages) - 1}</b> &nbsp; {html.escape(self.stages[k][0])}"

    def _on_step(self, change) -> None:
        k = change["new"]
        self.caption.value = self._caption(k)
        self.view.update(self.stages[k][1])

    def close(self) -> None:
        """Close the step-through and every widget inside it (``close_tree``)."""
        close_tree(self)

    def static_copy(self) -> W.Widget:
        """A kernel-free copy (one view per stage, slider linked in the browser)."""
        return slider_stack(
            [d for _, d in self.stages],
            [self._caption(k) for k in range(len(self.stages))],
            self.view,
            description="step",
            title=f"<b>{html.escape(self.scheme.label)}</b>, step by step",
            value=self.step.value,
        )


def step_through(
    mesh: Mesh,
    scheme: str | Scheme = "pentagonalize",
    *,
    duals: int = 2,
    scale: float | None = None,
    width: int = 600,
    height: int = 450,
) -> StepThrough:
    """Step through one application of a scheme with a slider, for the classroom.

    For pentagonalization (Section 5.1): the input; edges cut in three; a
    point sphere in every face; the edges from it inserted one group at a
    time; the result; its duals.  For pentagon preservation (Section 5.2):
    the input; midpoints; the scaled inner faces; the edges to the midpoints
    one group at a time; the result; its duals.  Other schemes: input,
    result, duals.

    Parameters
    ----------
    mesh : Mesh
    scheme : str or Scheme
        A scheme of :data:`pentanb.SCHEMES`.
    duals : int in [0, :data:`pentanb.viz.stages.MAX_DUALS`]
        Duals shown after the result.
    scale : float, optional
        The ``scale`` of ``preserve_pentagons`` (and of the other schemes
        with one); refused for a scheme that takes no scale.
    width, height : int
        Size of the picture.

    Returns
    -------
    StepThrough

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh (a shape name is not: use
        ``pentanb.shapes.get(name)``), or ``duals`` not an integer.
    ValueError
        An unknown scheme, ``duals`` out of range, or an option the scheme
        does not take; the message names the argument.
    """
    return StepThrough(mesh, scheme, duals=duals, scale=scale, width=width, height=height)
