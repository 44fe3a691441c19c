"""The explorer: shape, scheme, iterations, duals and scale beside one 3D view.

:func:`explore` (also ``pentanb.explore``) builds an :class:`Explorer`.
Moving a control rebuilds the mesh with :func:`pentanb.subdivide` (or takes
it from a cache) and writes it into the existing view
(:meth:`pentanb.viz.three.MeshView.update`).  Every argument is checked as
:func:`pentanb.subdivide` checks its own: a value a control cannot show is a
``ValueError`` naming the argument and its range (a ``TypeError`` for a
wrong type), never clamped.
"""

from __future__ import annotations

import html
import time
from collections import OrderedDict
from collections.abc import Callable

import ipywidgets as W

from .. import shapes
from ..mesh import Mesh, MeshError
from ..schemes.registry import SCHEMES, Scheme
from ..subdivision import get_scheme, predict_counts, subdivide
from .drawing import counts_text, error_html
from .three import MAX_PIXELS, MeshView, close_tree, slider_stack
from .widgets import integer_argument, number_argument

__all__ = ["Explorer", "explore", "MAX_DUALS", "MAX_ITERATIONS", "SCALE_RANGE"]

#: Largest value of the duals slider.
MAX_DUALS = 4
#: Largest ``max_iterations`` (the iterations slider's top).  The explorer
#: builds one level at a time, so this bounds its steps, as
#: :data:`pentanb.subdivision.MAX_STEPS` bounds :func:`pentanb.subdivide`'s:
#: every scheme passes ``max_faces`` within a few levels, but one that keeps
#: the counts (triangulate on triangles) never does.
MAX_ITERATIONS = 1000
#: Range of the scale slider (the scheme's ``scale`` option).
SCALE_RANGE = (0.05, 0.95)

_MESH_OPTION = "(your mesh)"

Key = tuple[str, str, int, tuple, int]


def _scheme_argument(scheme: object) -> Scheme:
    s = get_scheme(scheme)  # type: ignore[arg-type]
    if not isinstance(s, Scheme):
        raise TypeError(
            f"scheme must be the name of a scheme of pentanb.SCHEMES ({', '.join(SCHEMES)}) "
            f"or Conway notation such as 'dg', not {type(scheme).__name__}"
        )
    return s


class Explorer(W.HBox):
    """Controls (shape, scheme, iterations, duals, scale, edges) beside one view.

    Build it with :func:`explore`.  Every result is cached, so a slider that
    goes back shows its mesh at once, and more iterations are built from the
    deepest cached result.

    Attributes
    ----------
    shape, scheme : ipywidgets.Dropdown
    iterations, duals : ipywidgets.IntSlider
    scale : ipywidgets.FloatSlider
        The scheme's ``scale`` option (disabled for schemes without one).
    wireframe : ipywidgets.Checkbox
    progress : ipywidgets.IntProgress
        Steps done of a long computation (``subdivide``'s ``progress``):
        shown from the start when the request builds at least
        :attr:`PROGRESS_FACES` faces, else once it has run
        :attr:`PROGRESS_AFTER` seconds (a quick move sends the browser no
        progress messages).
    status : ipywidgets.HTML
        Empty, or why the last request was refused.
    counts : ipywidgets.HTML
        The counts line of the mesh shown.
    view : MeshView
    max_faces : int
        Largest mesh (faces, at every step) the view builds.
    cache_limit : int
        Largest number of corners kept in the cache (all entries together).
    """

    def __init__(
        self,
        mesh: Mesh | str = "dodecahedron",
        scheme: str | Scheme = "pentagonalize",
        *,
        iterations: int = 1,
        duals: int = 2,
        scale: float | None = None,
        max_iterations: int = 5,
        max_faces: int = 100_000,
        max_bytes: int | None = None,
        width: int = 560,
        height: int = 460,
    ):
        names = list(shapes.SHAPES)
        self._meshes: dict[str, Mesh] = {}
        if isinstance(mesh, Mesh):
            self._meshes[_MESH_OPTION] = mesh
            options, first = [_MESH_OPTION] + names, _MESH_OPTION
        elif isinstance(mesh, str):
            shapes.get(mesh)  # an unknown name raises here, listing the known ones
            options, first = names, mesh
        else:
            raise TypeError(
                f"mesh must be a pentanb.Mesh or a shape name ({', '.join(names)}), "
                f"got {type(mesh).__name__}"
            )
        s = _scheme_argument(scheme)
        top = integer_argument(max_iterations, "max_iterations", 0, MAX_ITERATIONS)
        iterations = integer_argument(iterations, "iterations", 0, top)
        duals = integer_argument(duals, "duals", 0, MAX_DUALS)
        low, high = SCALE_RANGE
        first_scale = (
            s.options.get("scale", 0.75)
            if scale is None
            else number_argument(scale, "scale", low, high)
        )
        self.max_faces = integer_argument(max_faces, "max_faces", 1)
        self.max_bytes = None if max_bytes is None else integer_argument(max_bytes, "max_bytes", 1)
        width = integer_argument(width, "width", 1, MAX_PIXELS)
        height = integer_argument(height, "height", 1, MAX_PIXELS)
        self._cache: OrderedDict[Key, Mesh] = OrderedDict()
        self._cache_corners = 0
        self.cache_limit = 12_000_000

        style = {"description_width": "80px"}
        wide = W.Layout(width="300px")
        self.shape = W.Dropdown(
            options=options, value=first, description="shape", style=style, layout=wide
        )
        choices = [(x.label, x.name) for x in SCHEMES.values()]
        if s.name not in SCHEMES:  # Conway notation, e.g. explore("cube", "dg")
            choices.append((s.label, s.name))
        self.scheme = W.Dropdown(
            options=choices,
            value=s.name,
            description="scheme",
            style=style,
            layout=wide,
        )
        self.iterations = W.IntSlider(
            value=iterations,
            min=0,
            max=top,
            description="iterations",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        self.duals = W.IntSlider(
            value=duals,
            min=0,
            max=MAX_DUALS,
            description="duals",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        self.scale = W.FloatSlider(
            value=first_scale,
            min=low,
            max=high,
            step=0.05,
            readout_format=".2f",
            description="scale",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        self.progress = W.IntProgress(
            value=0,
            min=0,
            max=1,
            description="",
            layout=W.Layout(width="300px", visibility="hidden"),
        )
        self.status = W.HTML("", layout=W.Layout(width="300px"))

        self.view = MeshView(self._base(first), width=width, height=height, toggle=False)
        self.wireframe = self.view.wireframe
        self.counts = W.HTML("")
        panel = W.VBox(
            [
                W.HTML("<b>Semiregular pentagonal subdivision</b>"),
                self.shape,
                self.scheme,
                self.iterations,
                self.duals,
                self.scale,
                self.wireframe,
                self.progress,
                self.status,
            ],
            layout=W.Layout(width="320px"),
        )
        super().__init__([panel, W.VBox([self.view, self.counts])])
        self.add_class("pentanb-explorer")
        self._sync_scale()
        for w in (self.shape, self.scheme, self.iterations, self.duals, self.scale):
            w.observe(self._on_change, names="value")
        self.refresh()
        self.view.fit_camera()

    # -- state --------------------------------------------------------------
    def _base(self, name: str) -> Mesh:
        if name not in self._meshes:
            self._meshes[name] = shapes.get(name)
        return self._meshes[name]

    def _options(self) -> dict[str, float]:
        s = _scheme_argument(self.scheme.value)
        return {"scale": float(self.scale.value)} if "scale" in s.options else {}

    def key(self, iterations: int | None = None) -> Key:
        """Cache key of the current settings (at ``iterations``)."""
        it = self.iterations.value if iterations is None else iterations
        opts = tuple(sorted(self._options().items()))
        return (self.shape.value, self.scheme.value, self.duals.value, opts, it)

    def _sync_scale(self) -> None:
        self.scale.disabled = "scale" not in _scheme_argument(self.scheme.value).options

    def _on_change(self, change) -> None:
        if change["owner"] is self.scheme:
            self._sync_scale()
        self.refresh(fit=change["owner"] is self.shape)

    #: A request building at least this many faces (at its largest step)
    #: shows the progress bar from its start: a tenth of a second or more
    #: of work with the compiled kernels, half a second on the numpy path.
    #: (A slider move at 20,480 faces builds about 100,000 and takes 10-20
    #: ms: a bar would only flash, and its messages cost a millisecond.)
    PROGRESS_FACES = 1_000_000
    #: Seconds after which a smaller request shows it.
    PROGRESS_AFTER = 0.2
    #: The clock :attr:`PROGRESS_AFTER` is measured on, in seconds (the
    #: tests put a fake clock here, so that no test depends on the machine's load).
    clock = staticmethod(time.perf_counter)

    # -- work ---------------------------------------------------------------
    def _largest_steps(self, base: Mesh, iterations: int):
        """(level, (V, E, F)) of the largest step of every level up to ``iterations``,
        stopping at a level that keeps the counts (every later one is the same)."""
        scheme, duals = self.scheme.value, self.duals.value
        counts = (base.n_vertices, base.n_edges, base.n_faces)
        for level in range(1, iterations + 1):
            steps = predict_counts(counts, scheme, 1, duals)
            yield level, max(steps, key=lambda c: c[2])
            if steps[-1] == counts:
                return
            counts = steps[-1]

    def _builds_at_least(self, faces: int) -> bool:
        """Whether some step of the current request makes ``faces`` faces or more."""
        base = self._base(self.shape.value)
        return any(F >= faces for _, (_, _, F) in self._largest_steps(base, self.iterations.value))

    def _refuse_too_large(self, base: Mesh, iterations: int) -> None:
        """MeshError when any step up to ``iterations`` passes ``max_faces``.

        Level by level from the counts, stopping at the first step too
        large: milliseconds for any number of iterations.
        """
        scheme, duals = self.scheme.value, self.duals.value
        for level, (V, E, F) in self._largest_steps(base, iterations):
            if F > self.max_faces:
                raise MeshError(
                    f"{scheme} x{iterations} with {duals} duals would make a mesh of {F:,} "
                    f"faces ({V:,} vertices, {E:,} edges) at iteration {level}; this view "
                    f"draws at most {self.max_faces:,} faces. Lower the iterations, or call "
                    "pentanb.subdivide() yourself."
                )

    def mesh_at(self, iterations: int | None = None, progress: Callable | None = None) -> Mesh:
        """The mesh of the current settings at ``iterations`` (default: the slider's).

        Parameters
        ----------
        iterations : int in [0, iterations.max], optional
        progress : callable, optional
            ``progress(done, total, message)``, as for :func:`pentanb.subdivide`.

        Raises
        ------
        TypeError, ValueError
            ``iterations`` is not an integer the slider can show.
        MeshError
            A step would pass ``max_faces`` faces, or ``max_bytes``.
        """
        it = (
            self.iterations.value
            if iterations is None
            else integer_argument(iterations, "iterations", 0, self.iterations.max)
        )
        key = self.key(it)
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        base = self._base(self.shape.value)
        self._refuse_too_large(base, it)
        scheme, duals, opts = self.scheme.value, self.duals.value, self._options()
        # start from the deepest cached level below
        start, mesh = 0, base
        for j in range(it - 1, 0, -1):
            if self.key(j) in self._cache:
                start, mesh = j, self._cache[self.key(j)]
                break
        total = (it - start) * (1 + duals)
        done = 0
        for j in range(start + 1, it + 1):

            def step(d, t, message, _offset=done):
                if progress:
                    progress(_offset + d, total, message)

            mesh = subdivide(
                mesh, scheme, 1, duals, progress=step, max_bytes=self.max_bytes, **opts
            )
            done += 1 + duals
            self._store(self.key(j), mesh)
        if it == 0:
            self._store(key, mesh)
        return mesh

    def _store(self, key: Key, mesh: Mesh) -> None:
        self._cache[key] = mesh
        self._cache_corners += len(mesh.corners)
        while self._cache_corners > self.cache_limit and len(self._cache) > 1:
            _, old = self._cache.popitem(last=False)
            self._cache_corners -= len(old.corners)

    def refresh(self, fit: bool = False) -> None:
        """Compute (or fetch) the mesh of the current settings and show it.

        A request refused for its size (:class:`pentanb.MeshError`) is
        written in :attr:`status`; the picture keeps the previous mesh.
        """
        start, shown = self.clock(), False

        def show() -> None:
            nonlocal shown
            shown = True
            self.progress.value = 0
            self.progress.layout.visibility = "visible"
            self.status.value = "<i>computing...</i>"

        def report(done, total, message):
            if not shown:
                if self.clock() - start < self.PROGRESS_AFTER:
                    return
                show()
            self.progress.max = max(total, 1)
            self.progress.value = done
            self.status.value = f"<i>computing: {html.escape(message)}</i>"

        if self.key() not in self._cache and self._builds_at_least(self.PROGRESS_FACES):
            show()
        try:
            mesh = self.mesh_at(progress=report)
        except MeshError as err:
            self.status.value = error_html(str(err), "(the picture still shows the previous mesh)")
            self.progress.layout.visibility = "hidden"
            return
        self.progress.layout.visibility = "hidden"
        self.view.update(mesh, fit=fit)
        self.status.value = ""
        self.counts.value = counts_text(mesh)

    @property
    def mesh(self) -> Mesh | None:
        """The mesh shown."""
        return self.view.mesh

    def close(self) -> None:
        """Close the explorer and every widget inside it; empty its cache.

        ipywidgets' own ``close()`` would leave the sliders open, and their
        observers would keep the explorer and every cached mesh alive
        (see :func:`pentanb.viz.three.close_tree`).
        """
        # (ipywidgets calls close() from __del__ too, also when __init__ failed)
        getattr(self, "_cache", {}).clear()
        self._cache_corners = 0
        getattr(self, "_meshes", {}).clear()
        close_tree(self)

    # -- export -------------------------------------------------------------
    def static_copy(self, iterations: int | None = None) -> W.Widget:
        """A kernel-free copy: one view per iteration count, chosen by a slider.

        The slider is linked to a :class:`ipywidgets.Stack` in the browser
        (``jslink``), so the copy keeps working in a stand-alone HTML page.

        Parameters
        ----------
        iterations : int in [0, iterations.max], optional
            Iterations 0 to ``iterations`` (default: the iterations slider's
            value), stopping before one over the size limits.

        Returns
        -------
        ipywidgets.Widget
            The views and their slider.

        Raises
        ------
        TypeError, ValueError
            ``iterations`` is not an integer the iterations slider can show.
        """
        top = (
            self.iterations.value
            if iterations is None
            else integer_argument(iterations, "iterations", 0, self.iterations.max)
        )
        meshes = []
        for k in range(top + 1):
            try:
                meshes.append(self.mesh_at(k))
            except MeshError:
                break
        label = _scheme_argument(self.scheme.value).label
        opts = self._options()
        title = (
            f"<b>{html.escape(str(self.shape.value))}</b>: {html.escape(label)}"
            + (f" (scale {opts['scale']:.2f})" if opts else "")
            + f", {self.duals.value} duals per iteration"
        )
        return slider_stack(
            meshes,
            [counts_text(m) for m in meshes],
            self.view,
            description="iterations",
            title=title,
            value=min(self.iterations.value, len(meshes) - 1),
        )


def explore(
    mesh: Mesh | str = "dodecahedron",
    scheme: str | Scheme = "pentagonalize",
    *,
    iterations: int = 1,
    duals: int = 2,
    scale: float | None = None,
    max_iterations: int = 5,
    max_faces: int = 100_000,
    max_bytes: int | None = None,
    width: int = 560,
    height: int = 460,
) -> Explorer:
    """A panel of controls beside one 3D view, with a live line of counts.

    Moving a control rebuilds the mesh with :func:`pentanb.subdivide` (or
    fetches it from a cache) and writes it into the existing geometry's
    buffers; the camera stays where the reader left it (a new shape refits
    it).  Long work drives a progress bar; a request over ``max_faces`` (at
    any step) or over ``subdivide``'s memory limit is refused with a message
    giving the size the mesh would have.

    Parameters
    ----------
    mesh : Mesh or str
        A mesh, or a name from :data:`pentanb.shapes.SHAPES`.
    scheme : str or Scheme
        A scheme of :data:`pentanb.SCHEMES`, or Conway operators such as ``"dg"``
        (:func:`pentanb.notation.resolve`).
    iterations : int in [0, max_iterations]
        First value of the iterations slider.
    duals : int in [0, :data:`MAX_DUALS`]
        First value of the duals slider.
    scale : float in :data:`SCALE_RANGE`, optional
        First value of the scale slider (default: the scheme's scale, or
        0.75); used by the schemes that take one.
    max_iterations : int in [0, :data:`MAX_ITERATIONS`]
        Largest value of the iterations slider.
    max_faces : int >= 1
        Largest mesh (faces, at every step) that the view builds; the
        default, 100,000, is the limit of the notebooks' sliders too.
    max_bytes : int, optional
        Passed to :func:`pentanb.subdivide`.
    width, height : int in [1, :data:`pentanb.viz.three.MAX_PIXELS`]
        Size of the picture, in pixels.

    Returns
    -------
    Explorer

    Raises
    ------
    TypeError
        A mesh that is neither a Mesh nor a name, a scheme that is not a
        registered one, or a number of the wrong type (``iterations=1.5``,
        ``iterations="2"``).
    ValueError
        An unknown shape or scheme name, or a value a control cannot show
        (``iterations=-1``, ``duals=5``, ``scale=2``); the message names the
        argument and its range.
    """
    return Explorer(
        mesh,
        scheme,
        iterations=iterations,
        duals=duals,
        scale=scale,
        max_iterations=max_iterations,
        max_faces=max_faces,
        max_bytes=max_bytes,
        width=width,
        height=height,
    )
