"""The explorer: shape, scheme, iterations, duals and scale beside one 3D view.

:func:`explore` (also ``pentanb.explore``) builds an :class:`Explorer`.
Moving a control rebuilds the mesh with :func:`pentanb.subdivide` (or takes
it from a cache) and writes it into the existing view
(:meth:`pentanb.viz.three.MeshView.update`).  Every argument is checked as
:func:`pentanb.subdivide` checks its own: a value a control cannot show is a
``ValueError`` naming the argument and its range (a ``TypeError`` for a
wrong type), never clamped, and a range the caller declares is never changed.

A mesh of your own comes in three ways: ``explore(mesh)``,
``explore("path/to/file.obj")`` (read with :func:`pentanb.io.read`), or the
explorer's upload button (``.obj``, ``.off``, ``.ply``, ``.stl``).  It is
listed in the shape drop-down under its file name.  Open meshes (with
boundary) work as closed ones do.

After any refused request (a mesh too large, a file that cannot be read)
the controls are put back to the values of the mesh shown, so the controls
and the picture always agree.

:meth:`Explorer.export_plan` chooses what a stand-alone page keeps of the
explorer within a size budget (every control, values nearest the current
ones first); :func:`pentanb.viz.html.export_html` builds the page from it.

The controls' ranges, the checks of :func:`explore`'s arguments, the reading
of an upload and :class:`ExportPlan` live in :mod:`pentanb.viz.controls`
(no widgets); their names are importable from here too.
"""

from __future__ import annotations

import html
import os
import time
from collections import OrderedDict
from collections.abc import Callable, Iterator, Sequence

import ipywidgets as W

from .. import shapes
from ..mesh import Mesh, MeshError
from ..schemes.registry import SCHEMES, Scheme
from ..subdivision import predict_counts, subdivide
from .controls import (
    CONTROLS,
    DEFAULT_ITERATIONS,
    MAX_DUALS,
    MAX_ITERATIONS,
    MESH_SUFFIXES,
    SCALE_RANGE,
    SCALE_STEP,
    YOUR_MESH,
    ExportPlan,
    Key,
    has_scale,
    read_upload,
    scheme_argument,
    shape_argument,
)
from .drawing import counts_text, error_html
from .three import MAX_PIXELS, MeshView, close_tree
from .widgets import integer_argument, number_argument

__all__ = [
    "Explorer",
    "ExportPlan",
    "explore",
    "MAX_DUALS",
    "MAX_ITERATIONS",
    "SCALE_RANGE",
    "SCALE_STEP",
    "MESH_SUFFIXES",
    "YOUR_MESH",
    "CONTROLS",
    "read_upload",
]


def _uploaded(entry: object) -> tuple[str, bytes]:
    """(file name, content) of one file of an :class:`ipywidgets.FileUpload` value.

    ipywidgets 8: a dict with ``name`` and ``content`` (a memoryview);
    ipywidgets 7: ``(name, {"metadata": ..., "content": bytes})``.
    """
    if isinstance(entry, tuple) and len(entry) == 2 and isinstance(entry[1], dict):
        name, data = entry
        return str(name), bytes(data["content"])
    if isinstance(entry, dict) and "content" in entry:
        return str(entry.get("name", "upload")), bytes(entry["content"])
    raise TypeError(f"an uploaded file is a dict with a name and a content, not {entry!r:.60}")


def _upload_entries(value: object) -> list:
    if isinstance(value, dict):  # ipywidgets 7: {name: {"metadata", "content"}}
        return list(value.items())
    return list(value)  # type: ignore[call-overload]


def _scale_values() -> list[float]:
    low, high = SCALE_RANGE
    n = round((high - low) / SCALE_STEP)
    return [round(low + k * SCALE_STEP, 2) for k in range(n + 1)]


class Explorer(W.HBox):
    """Controls (shape, scheme, iterations, duals, scale, edges, upload) beside one view.

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
    upload : ipywidgets.FileUpload
        A mesh file of the reader's own (:data:`MESH_SUFFIXES`): read with
        :func:`pentanb.io.read`, listed in :attr:`shape` under its file name
        and shown.  A file that cannot be read leaves everything as it was
        and says why in :attr:`status`.
    progress : ipywidgets.IntProgress
        Steps done of a long computation (``subdivide``'s ``progress``):
        shown from the start when the request's predicted cost
        (:meth:`predicted_seconds`) is over :attr:`progress_seconds`, else
        once it has run :attr:`PROGRESS_AFTER` seconds (a quick move sends
        the browser no progress messages).
    status : ipywidgets.HTML
        Empty, or why the last request was refused.
    counts : ipywidgets.HTML
        The counts line of the mesh shown.
    view : MeshView
    max_faces : int
        Largest mesh (faces, at every step) the view builds.
    cache_limit : int
        Largest number of corners kept in the cache (all entries together).
    seconds_per_face : float
        Predicted seconds of work per face built (every step counted), for
        :meth:`predicted_seconds`; the tests set their own.
    progress_seconds : float
        A request predicted to take longer shows the progress bar from its start.
    """

    #: Seconds of work per face built, every step counted: ``subdivide``
    #: and the drawing of the result, through the explorer's own path,
    #: measured at 240-920 ns per face (median 470 ns) with and without the
    #: compiled kernels, on meshes of 170,000 to 2,100,000 faces built, on
    #: a busy 2-core machine (``benchmarks/bench_explorer.py``).  So a
    #: request over half a second, some 800,000 faces built, shows the bar
    #: from its start.
    SECONDS_PER_FACE = 6e-7
    #: Predicted seconds over which a request shows the bar from its start.
    PROGRESS_SECONDS = 0.5
    #: Seconds after which a request predicted to be quicker shows it anyway.
    PROGRESS_AFTER = 0.2
    #: The clock :attr:`PROGRESS_AFTER` is measured on, in seconds (the
    #: tests put a fake clock here, so that no test depends on the machine's load).
    clock = staticmethod(time.perf_counter)

    def __init__(
        self,
        shape: Mesh | str | os.PathLike = "dodecahedron",
        scheme: str | Scheme = "pentagonalize",
        *,
        iterations: int | None = None,
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
        self._yours: list[str] = []
        first, mesh = shape_argument(shape)
        if mesh is not None:
            self._meshes[first] = mesh
            self._yours.append(first)
        s = scheme_argument(scheme)
        top = integer_argument(max_iterations, "max_iterations", 0, MAX_ITERATIONS)
        if iterations is None:
            iterations = min(DEFAULT_ITERATIONS, top)
        else:
            iterations = integer_argument(iterations, "iterations", 0)
            if iterations > top:
                raise ValueError(
                    f"iterations={iterations} is more than max_iterations={top}: raise "
                    "max_iterations (the iterations slider's top) or lower iterations"
                )
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
        self.seconds_per_face = self.SECONDS_PER_FACE
        self.progress_seconds = self.PROGRESS_SECONDS
        self._quiet = 0  # > 0 while the explorer sets its own controls

        style = {"description_width": "80px"}
        wide = W.Layout(width="300px")
        self.shape = W.Dropdown(
            options=self._yours + names, value=first, description="shape", style=style, layout=wide
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
            step=SCALE_STEP,
            readout_format=".2f",
            description="scale",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        self.upload = W.FileUpload(
            accept=",".join(MESH_SUFFIXES),
            multiple=False,
            description="your mesh",
            layout=W.Layout(width="300px"),
        )
        self.progress = W.IntProgress(
            value=0,
            min=0,
            max=1,
            description="",
            layout=W.Layout(width="300px", visibility="hidden"),
        )
        self.status = W.HTML("", layout=W.Layout(width="300px"))
        self._sync_scale()

        # the first request: refused at once (with the sizes) rather than
        # showing a picture the controls do not describe
        shown = self.mesh_at()
        self.view = MeshView(shown, width=width, height=height, toggle=False)
        self._shown = self._settings()
        self.wireframe = self.view.wireframe
        self.counts = W.HTML(counts_text(shown))
        panel = W.VBox(
            [
                W.HTML("<b>Semiregular pentagonal subdivision</b>"),
                self.shape,
                self.scheme,
                self.iterations,
                self.duals,
                self.scale,
                self.wireframe,
                self.upload,
                self.progress,
                self.status,
            ],
            layout=W.Layout(width="320px"),
        )
        super().__init__([panel, W.VBox([self.view, self.counts])])
        self.add_class("pentanb-explorer")
        for w in (self.shape, self.scheme, self.iterations, self.duals, self.scale):
            w.observe(self._on_change, names="value")
        self.upload.observe(self._on_upload, names="value")

    # -- state --------------------------------------------------------------
    def _base(self, name: str) -> Mesh:
        if name not in self._meshes:
            self._meshes[name] = shapes.get(name)
        return self._meshes[name]

    def _options(self) -> dict[str, float]:
        s = scheme_argument(self.scheme.value)
        return {"scale": float(self.scale.value)} if "scale" in s.options else {}

    def key(self, iterations: int | None = None) -> Key:
        """Cache key of the current settings (at ``iterations``).

        Parameters
        ----------
        iterations : int, optional
            Default: the iterations slider's value.

        Returns
        -------
        tuple (shape, scheme, duals, options, iterations)
        """
        it = self.iterations.value if iterations is None else iterations
        opts = tuple(sorted(self._options().items()))
        return (self.shape.value, self.scheme.value, self.duals.value, opts, it)

    @property
    def shown_key(self) -> Key:
        """The key (:meth:`key`) of the mesh shown: after any refusal the
        controls are put back to it."""
        return self._key_of(self._shown)

    def _settings(self) -> dict[str, object]:
        return {
            "shape": self.shape.value,
            "scheme": self.scheme.value,
            "iterations": self.iterations.value,
            "duals": self.duals.value,
            "scale": self.scale.value,
        }

    @staticmethod
    def _key_of(settings: dict) -> Key:
        opts = (("scale", float(settings["scale"])),) if has_scale(settings["scheme"]) else ()
        return (
            settings["shape"],
            settings["scheme"],
            settings["duals"],
            opts,
            settings["iterations"],
        )

    def _restore(self, settings: dict) -> None:
        """Put every control back to ``settings`` without computing anything."""
        self._quiet += 1
        try:
            for name, value in settings.items():
                widget = getattr(self, name)
                if widget.value != value:
                    widget.value = value
            self._sync_scale()
        finally:
            self._quiet -= 1

    def _sync_scale(self) -> None:
        self.scale.disabled = not has_scale(self.scheme.value)

    def _on_change(self, change) -> None:
        if self._quiet:
            return
        if change["owner"] is self.scheme:
            self._sync_scale()
        self.refresh(fit=change["owner"] is self.shape)

    # -- your own mesh -----------------------------------------------------
    def add_mesh(self, mesh: Mesh, name: str = YOUR_MESH) -> bool:
        """List ``mesh`` in the shape drop-down as ``name`` and show it.

        A name already listed for a mesh of the reader's own is replaced
        (its cached results with it); the package's shape names cannot be
        taken.  When the current iterations would make it too large, the
        refusal is written in :attr:`status`, the mesh stays listed and the
        controls go back to the mesh shown.

        Parameters
        ----------
        mesh : Mesh
        name : str
            Its name in the drop-down (a file name).

        Returns
        -------
        bool
            Whether it is shown.

        Raises
        ------
        TypeError
            ``mesh`` is not a Mesh or ``name`` not a string.
        ValueError
            ``name`` is empty or the name of one of the package's shapes.
        """
        if not isinstance(mesh, Mesh):
            raise TypeError(f"add_mesh() takes a pentanb.Mesh, not {type(mesh).__name__}")
        if not isinstance(name, str) or not name:
            raise (TypeError if not isinstance(name, str) else ValueError)(
                f"name must be a non-empty string, got {name!r:.60}"
            )
        if name in shapes.SHAPES:
            raise ValueError(f"{name!r} is the name of one of the package's shapes; choose another")
        self._forget(name)
        before = self._meshes.get(name)
        self._meshes[name] = mesh
        if name not in self._yours:
            self._yours.append(name)
        self._quiet += 1
        try:
            value = self.shape.value
            self.shape.options = self._yours + list(shapes.SHAPES)
            self.shape.value = value
        finally:
            self._quiet -= 1
        if self.shape.value == name:  # replaced while shown
            if self.refresh(fit=True):
                return True
            self._forget(name)  # refused: the name keeps the mesh shown
            self._meshes[name] = before  # type: ignore[assignment]
            return False
        self.shape.value = name  # observed: refresh(fit=True)
        return self.shape.value == name

    def _forget(self, name: str) -> None:
        """Drop the cached results of the shape ``name``."""
        for key in [k for k in self._cache if k[0] == name]:
            self._cache_corners -= len(self._cache.pop(key).corners)

    def _on_upload(self, change) -> None:
        entries = _upload_entries(change["new"])
        if not entries:
            return
        self.load_upload(entries[-1])
        self._quiet += 1
        try:
            self.upload.value = ()  # frees the bytes; a new upload of the same file works
        except Exception:  # (ipywidgets 7 takes a dict)
            pass
        finally:
            self._quiet -= 1

    def load_upload(self, entry: object) -> bool:
        """Read one file of :attr:`upload`'s value and show it (:meth:`add_mesh`).

        Parameters
        ----------
        entry : dict
            One file of an ``ipywidgets.FileUpload`` value: ipywidgets 8's
            dict with ``name`` and ``content`` (bytes or a memoryview), or
            ipywidgets 7's ``(name, {"content": ...})`` pair.

        Returns
        -------
        bool
            Whether the mesh is shown.  A file that cannot be read, or whose
            mesh is not valid, is not: the reader's message is written in
            :attr:`status`, and the picture and the controls stay as they were.
        """
        try:
            name, content = _uploaded(entry)
            mesh = read_upload(name, content)
        except (ValueError, TypeError, OSError) as err:  # MeshError is a ValueError
            self.status.value = error_html(
                f"could not read the file: {err}",
                "(the picture still shows the previous mesh)",
            )
            return False
        return self.add_mesh(mesh, name)

    # -- work ---------------------------------------------------------------
    def _levels(self, key: Key) -> Iterator[tuple[int, list[tuple[int, int, int]]]]:
        """(level, (V, E, F) of every step of that level) for levels 1 to the key's,
        from the counts, stopping at a level that keeps the counts (every
        later one is the same)."""
        shape, scheme, duals, _, iterations = key
        base = self._base(shape)
        # (a move asks twice, for its predicted cost and its size check: the
        # counts of the last key asked for are kept, with the mesh they are of)
        memo = getattr(self, "_levels_memo", None)
        if memo is not None and memo[0] is base and memo[1] == (scheme, duals, iterations):
            yield from memo[2]
            return
        found: list[tuple[int, list[tuple[int, int, int]]]] = []
        before = (base.n_vertices, base.n_edges, base.n_faces)
        for level in range(1, iterations + 1):
            if base.is_closed:
                steps = predict_counts(before, scheme, 1, duals)
            else:  # the boundary's counts too: predicted from the mesh
                steps = predict_counts(base, scheme, level, duals)[-(1 + duals) :]
            found.append((level, steps))
            yield level, steps
            if steps[-1] == before:
                break
            before = steps[-1]
        # (kept only when read to the end: a check that stops at the first
        # level too large never works out the levels after it)
        self._levels_memo = (base, (scheme, duals, iterations), found)

    def _largest_steps(self, base: Mesh, iterations: int):
        """(level, (V, E, F)) of the largest step of every level up to ``iterations``."""
        for level, steps in self._levels(self.key(iterations)):
            yield level, max(steps, key=lambda c: c[2])

    def _builds_at_least(self, faces: int) -> bool:
        """Whether some step of the current request makes ``faces`` faces or more."""
        base = self._base(self.shape.value)
        return any(F >= faces for _, (_, _, F) in self._largest_steps(base, self.iterations.value))

    def _refuse_too_large(self, base: Mesh, iterations: int) -> None:
        """MeshError when the current settings at ``iterations`` pass ``max_faces``
        (``base``: the current shape's mesh)."""
        self._refuse_key(self.key(iterations))

    def _refuse_key(self, key: Key) -> None:
        """MeshError when the mesh or any step up to the key's level passes ``max_faces``.

        Level by level from the counts, stopping at the first step too
        large: milliseconds for any number of iterations.
        """
        shape, scheme, duals, _, iterations = key
        base = self._base(shape)
        if base.n_faces > self.max_faces:
            raise MeshError(
                f"{shape} has {base.n_faces:,} faces; this view draws at most "
                f"{self.max_faces:,} (explore(..., max_faces=...) raises the limit)"
            )
        for level, steps in self._levels(key):
            V, E, F = max(steps, key=lambda c: c[2])
            if F > self.max_faces:
                raise MeshError(
                    f"{scheme} x{iterations} with {duals} duals would make a mesh of {F:,} "
                    f"faces ({V:,} vertices, {E:,} edges) at iteration {level}; this view "
                    f"draws at most {self.max_faces:,} faces. Lower the iterations, or call "
                    "pentanb.subdivide() yourself."
                )

    def predicted_seconds(self, iterations: int | None = None) -> float:
        """Predicted seconds of work for the current settings at ``iterations``.

        :attr:`seconds_per_face` times the faces of every step still to be
        built (from the deepest cached level below), predicted from the
        counts; 0 for a cached result.

        Parameters
        ----------
        iterations : int, optional
            Default: the iterations slider's value.

        Returns
        -------
        float
        """
        key = self.key(iterations)
        if key in self._cache:
            return 0.0
        start = self._deepest_cached(key)[0]
        faces, level = 0, 0
        steps: list[tuple[int, int, int]] = []
        for level, steps in self._levels(key):
            if level > start:
                faces += sum(F for _, _, F in steps)
        # a level that keeps the counts: every later one costs as much
        faces += (key[4] - max(level, start)) * sum(F for _, _, F in steps)
        return faces * self.seconds_per_face

    def _deepest_cached(self, key: Key) -> tuple[int, Mesh]:
        """(level, mesh) of the deepest cached level below ``key``'s (0: the base)."""
        for j in range(key[4] - 1, 0, -1):
            below = key[:4] + (j,)
            if below in self._cache:
                return j, self._cache[below]
        return 0, self._base(key[0])

    def mesh_at(self, iterations: int | None = None, progress: Callable | None = None) -> Mesh:
        """The mesh of the current settings at ``iterations`` (default: the slider's).

        Parameters
        ----------
        iterations : int in [0, iterations.max], optional
        progress : callable, optional
            ``progress(done, total, message)``, as for :func:`pentanb.subdivide`.

        Returns
        -------
        Mesh

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
        return self._mesh_for(self.key(it), progress)

    def _mesh_for(self, key: Key, progress: Callable | None = None) -> Mesh:
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        self._refuse_key(key)
        _, scheme, duals, opts, it = key
        start, mesh = self._deepest_cached(key)
        total = (it - start) * (1 + duals)
        done = 0
        for j in range(start + 1, it + 1):

            def step(d, t, message, _offset=done):
                if progress:
                    progress(_offset + d, total, message)

            mesh = subdivide(
                mesh, scheme, 1, duals, progress=step, max_bytes=self.max_bytes, **dict(opts)
            )
            done += 1 + duals
            self._store(key[:4] + (j,), mesh)
        if it == 0:
            self._store(key, mesh)
        return mesh

    def _store(self, key: Key, mesh: Mesh) -> None:
        self._cache[key] = mesh
        self._cache_corners += len(mesh.corners)
        while self._cache_corners > self.cache_limit and len(self._cache) > 1:
            _, old = self._cache.popitem(last=False)
            self._cache_corners -= len(old.corners)

    def refresh(self, fit: bool = False) -> bool:
        """Compute (or fetch) the mesh of the current settings and show it.

        A request refused (:class:`pentanb.MeshError`: too many faces, or
        over the memory limit) is written in :attr:`status`; the picture
        keeps the previous mesh and every control is put back to its values.

        Parameters
        ----------
        fit : bool
            Point the camera at the new mesh.

        Returns
        -------
        bool
            Whether the request was shown (False: refused).
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

        settings = self._settings()
        try:
            if self.predicted_seconds() > self.progress_seconds:
                self._refuse_key(self.key())  # (refused before the bar shows)
                show()
            mesh = self.mesh_at(progress=report)
        except (MeshError, MemoryError) as err:
            self.progress.layout.visibility = "hidden"
            self._restore(self._shown)
            self.status.value = error_html(
                str(err), "(the picture and the controls still show the previous mesh)"
            )
            return False
        self.progress.layout.visibility = "hidden"
        self.view.update(mesh, fit=fit)
        self._shown = settings
        self.status.value = ""
        self.counts.value = counts_text(mesh)
        return True

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
        if hasattr(self, "view"):
            close_tree(self)
        else:  # __init__ refused its first request: close what it had made
            for name in ("shape", "scheme", "iterations", "duals", "scale", "upload"):
                if hasattr(self, name):
                    close_tree(getattr(self, name))
            for name in ("progress", "status"):
                if hasattr(self, name):
                    close_tree(getattr(self, name))

    # -- export -------------------------------------------------------------
    #: Bytes of a page's widget state per view (its two dozen widget
    #: models) and per corner of its mesh (the base64 buffers of faces,
    #: edges and colours): measured at 11,300 + 27 to 54 per corner (fewer
    #: for pentagons, more for triangles) on views of 12 to 20,000 corners,
    #: rounded up.
    VIEW_BYTES = 12_000
    #: See :attr:`VIEW_BYTES`.
    CORNER_BYTES = 60
    #: Bytes of a combination the page names in a line of text instead of
    #: drawing it, and of each selector (a Stack and its browser link).
    TEXT_BYTES = 600
    #: A control stops taking values after this many in a row did not fit.
    EXPORT_MISSES = 2

    def _candidates(self) -> dict[str, list]:
        """Every value of every control, nearest the current one first."""
        cur = self._settings()

        def nearest(values: Sequence, value) -> list:
            rest = sorted((v for v in values if v != value), key=lambda v: abs(v - value))
            return [value] + rest

        def listed_from(values: Sequence, value) -> list:
            return [value] + [v for v in values if v != value]

        schemes = [v for _, v in self.scheme.options]
        return {
            "shape": listed_from(list(self.shape.options), cur["shape"]),
            "scheme": listed_from(schemes, cur["scheme"]),
            "scale": nearest(_scale_values(), round(float(cur["scale"]), 10)),  # type: ignore[arg-type]
            "duals": nearest(range(MAX_DUALS + 1), cur["duals"]),
            "iterations": nearest(range(self.iterations.max + 1), cur["iterations"]),
        }

    def _page_entry(self, key: Key, max_faces: int) -> tuple[int, str]:
        """(bytes predicted, reason it is left out or "") of one combination in a page."""
        try:
            self._refuse_key(key)
            base = self._base(key[0])
            E, F = base.n_edges, base.n_faces
            for _, steps in self._levels(key):
                _, E, F = steps[-1]
        except MeshError as err:
            return self.TEXT_BYTES, str(err)
        if F > max_faces:
            return self.TEXT_BYTES, (
                f"{F:,} faces, more than the {max_faces:,} a page keeps per view "
                "(export_html(..., max_faces=...))"
            )
        return self.VIEW_BYTES + self.CORNER_BYTES * 2 * E, ""

    def export_plan(self, max_bytes: int = 15_000_000, max_faces: int = 5_000) -> ExportPlan:
        """What a stand-alone page keeps of this explorer within ``max_bytes``.

        Every control is kept.  Each starts with its current value; then,
        in turn (iterations, duals, scheme, shape, scale), each control is
        offered its next value, nearest the current one first (the shapes
        and schemes in drop-down order), taken when the predicted size of
        every combination of the values kept stays within ``max_bytes``,
        else left out; a control stops after :attr:`EXPORT_MISSES` values
        in a row were left out (so a lower level can still come in after a
        higher one did not fit).  A
        combination whose mesh has more than ``max_faces`` faces (or that
        the explorer refuses) is kept as a line of text saying so.  The
        meshes are built (or taken from the cache).

        Parameters
        ----------
        max_bytes : int >= 1
            Bytes of widget state the page may hold (its scripts not
            counted); the prediction uses :attr:`VIEW_BYTES`,
            :attr:`CORNER_BYTES` and :attr:`TEXT_BYTES`.
        max_faces : int >= 1
            Largest mesh (faces) drawn for one combination.

        Returns
        -------
        ExportPlan

        Raises
        ------
        TypeError, ValueError
            ``max_bytes`` or ``max_faces`` not an integer >= 1.
        """
        budget = integer_argument(max_bytes, "max_bytes", 1)
        cap = integer_argument(max_faces, "max_faces", 1)
        candidates = self._candidates()
        entries: dict[Key, tuple[int, str]] = {}
        schemes = [v for _, v in self.scheme.options]
        labels = {v: label for label, v in self.scheme.options}

        def plan_of(kept: dict[str, list]) -> ExportPlan:
            order = {
                "shape": list(self.shape.options),
                "scheme": schemes,
            }
            values = {
                c: ([v for v in order[c] if v in kept[c]] if c in order else sorted(kept[c]))
                for c in CONTROLS
            }
            return ExportPlan(values=values, current=self._settings(), labels=labels)

        def cost(kept: dict[str, list]) -> int:
            total = 0
            plan = plan_of(kept)
            for key in plan.keys():
                if key not in entries:
                    entries[key] = self._page_entry(key, cap)
                total += entries[key][0]
            # one selector per node of the tree of controls
            nodes = 1
            for _ in plan.values["shape"]:
                nodes += 1
                for scheme in plan.values["scheme"]:
                    scales = len(plan.values["scale"]) if has_scale(scheme) else 1
                    nodes += (1 if has_scale(scheme) else 0) + scales * (
                        1 + len(plan.values["duals"])
                    )
            return total + nodes * self.TEXT_BYTES

        kept = {c: [candidates[c][0]] for c in CONTROLS}
        total = cost(kept)
        growing = ["iterations", "duals", "scheme", "shape", "scale"]
        if not _any_scale(schemes):
            growing.remove("scale")
        position = dict.fromkeys(CONTROLS, 1)
        misses = dict.fromkeys(CONTROLS, 0)
        while growing:
            for c in list(growing):
                if position[c] >= len(candidates[c]) or misses[c] >= self.EXPORT_MISSES:
                    growing.remove(c)
                    continue
                trial = dict(kept)
                trial[c] = kept[c] + [candidates[c][position[c]]]
                position[c] += 1
                t = cost(trial)
                if t <= budget:
                    kept, total = trial, t
                    misses[c] = 0
                else:  # left out; a further value may still fit (a lower level)
                    misses[c] += 1
        plan = plan_of(kept)
        plan.estimate = total
        plan.dropped = {c: [v for v in candidates[c] if v not in kept[c]] for c in CONTROLS}
        for c in ("iterations", "duals", "scale"):
            plan.dropped[c].sort()
        plan.dropped["shape"] = [v for v in self.shape.options if v in plan.dropped["shape"]]
        plan.dropped["scheme"] = [v for v in schemes if v in plan.dropped["scheme"]]
        for key in plan.keys():
            _, reason = entries[key]
            if reason:
                plan.left_out[key] = reason
                continue
            try:
                plan.meshes[key] = self._mesh_for(key)
            except (MeshError, MemoryError) as err:
                plan.left_out[key] = str(err)
        return plan


def _any_scale(schemes: Sequence[str]) -> bool:
    return any(has_scale(s) for s in schemes)


def explore(
    shape: Mesh | str | os.PathLike = "dodecahedron",
    scheme: str | Scheme = "pentagonalize",
    *,
    iterations: int | None = None,
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
    it).  A request predicted to take more than half a second drives a
    progress bar from its start.  A request over ``max_faces`` (at any
    step) or over ``subdivide``'s memory limit is refused with a message
    giving the size the mesh would have, and the controls go back to the
    mesh shown.  The upload button reads a mesh file of the reader's own.

    Parameters
    ----------
    shape : Mesh, str or path
        A mesh (listed as "your mesh"), a name from
        :data:`pentanb.shapes.SHAPES`, or the path of an ``.obj``, ``.off``,
        ``.ply`` or ``.stl`` file, read with :func:`pentanb.io.read` and
        listed under its file name.  A string is a shape name when it is
        one, else a path when it ends in one of those endings or holds a
        folder separator.  Open meshes (with boundary) are welcome.
    scheme : str or Scheme
        A scheme of :data:`pentanb.SCHEMES`, or Conway operators such as ``"dg"``
        (:func:`pentanb.notation.resolve`).
    iterations : int in [0, max_iterations], optional
        First value of the iterations slider (default: 1, or 0 when
        ``max_iterations`` is 0).
    duals : int in [0, :data:`MAX_DUALS`]
        First value of the duals slider.
    scale : float in :data:`SCALE_RANGE`, optional
        First value of the scale slider (default: the scheme's scale, or
        0.75); used by the schemes that take one.
    max_iterations : int in [0, :data:`MAX_ITERATIONS`]
        Largest value of the iterations slider, kept as given.
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
        A shape that is neither a Mesh, a name nor a path, a scheme that is
        not a registered one, or a number of the wrong type
        (``iterations=1.5``, ``iterations="2"``).
    ValueError
        An unknown shape or scheme name, a value a control cannot show
        (``iterations=-1``, ``duals=5``, ``scale=2``), or ``iterations``
        more than ``max_iterations``; the message names the arguments.
    MeshError
        A file that cannot be read (the reader's message), or a first
        request over ``max_faces`` or the memory limit.
    OSError
        A path that cannot be opened (``FileNotFoundError``).
    """
    return Explorer(
        shape,
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
