"""Interactive 3D views with pythreejs: :class:`MeshView`, :func:`view`, :func:`slider_stack`.

Every drawing colours a face by its number of sides with
:func:`pentanb.viz.colors.face_color`, the colours of the matplotlib
figures, so a pentagon is bluish green everywhere.  What is drawn comes from
:mod:`pentanb.viz.drawing` (numpy only: a :class:`~pentanb.viz.drawing.Drawing`
and its WebGL :func:`~pentanb.viz.drawing.buffers`); this module only makes
widgets of it.  The explorer (:mod:`pentanb.viz.explorer`), the
step-through (:mod:`pentanb.viz.steps`) and the notebooks' panels
(:mod:`pentanb.viz.widgets`) are built on :class:`MeshView`.

A new mesh (a slider move) is written into the *same* ``BufferAttribute``
widgets: their arrays are replaced, the geometry, the renderer, the camera and
the orbit controls stay, so the reader's viewpoint is kept.

Console messages in JupyterLab 4
--------------------------------
pythreejs 2.4 was built against older Lumino and widget packages.  The
browser console of JupyterLab 4 (and of a page from :func:`pentanb.export_html`)
shows these messages; none comes from pentanb and none affects the drawing:

* warning ``Unsatisfied version 2.2.2 from CORE_FEDERATION of shared
  singleton module @lumino/coreutils (required ^1.11.0)``: JupyterLab shares
  its own Lumino with the pythreejs extension, which still works;
* log ``THREE.WebGLRenderer 97`` (one per WebGL context) and
  ``TV(...): already frozen...`` (pythreejs reusing a context);
* warning ``[.WebGL-...] GL Driver Message (OpenGL, Performance, ...): GPU
  stall due to ReadPixels``: Chromium's software renderer (SwiftShader, in
  headless browsers without a GPU) when pythreejs snapshots a canvas;
* warning ``strict mode: use allowUnionTypes ...`` from the JSON-schema check
  of ``@jupyter-widgets/html-manager`` in exported pages;
* error ``Error setting state: t.on is not a function``: printed by pythreejs
  for every light that casts shadows (``PointLight``, ``DirectionalLight``,
  ``SpotLight``).  pentanb lights its views with an ``AmbientLight`` and a
  ``HemisphereLight`` riding on the camera, so its views never print it;
  user code that adds such lights will.

``GL_INVALID_OPERATION ... Insufficient buffer size`` would be a real error (an
index pointing past the rows of the position or colour buffer, or a position
buffer drawn against a shorter colour buffer); :meth:`MeshView.update` avoids
it by replacing the arrays in an order that never lets that happen
(:func:`_replace`) and giving every replaced array a new, higher ``version``
(see :func:`_set_array`), and the browser tests fail on it.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import ipywidgets as W
import numpy as np
import pythreejs as P3

from .. import _checks
from ..mesh import Mesh
from .colors import BOUNDARY_COLOR
from .drawing import (
    BOUNDARY_WIDTH,
    IDENTITY,
    VIEW_AZIM,
    VIEW_ELEV,
    Buffers,
    Drawing,
    Frame,
    as_drawing,
    buffers,
    camera_fit,
    edge_opacity,
    eye_direction,
    frame_fits,
    framed,
    in_frame,
    legend_html,
    look_at_quaternion,
    mesh_buffers,
    view_frame,
)

__all__ = ["MeshView", "view", "slider_stack", "close_tree", "MAX_PIXELS"]

#: Largest width or height of a view, in pixels (browsers' largest WebGL canvas).
MAX_PIXELS = 16_384


_VERSIONS = itertools.count(1)


# attribute of a widget listing the widgets to close with it (the browser
# links made with it; the camera that the views of a slider_stack share)
OWNED = "_pentanb_owned"


def _own(owner: W.Widget, widget: W.Widget) -> None:
    """List ``widget`` among those :func:`close_tree` closes with ``owner``."""
    if not hasattr(owner, OWNED):
        setattr(owner, OWNED, [])
    getattr(owner, OWNED).append(widget)


def _linked(a: tuple[W.Widget, str], b: tuple[W.Widget, str], *, one_way: bool = False):
    """``jslink(a, b)`` (or ``jsdlink``), closed with either end by :func:`close_tree`."""
    link = (W.jsdlink if one_way else W.jslink)(a, b)
    _own(a[0], link)
    _own(b[0], link)
    return link


def _widgets_in(value: object) -> list[W.Widget]:
    """The widgets a trait value holds (itself, or in a list, tuple or dict)."""
    if isinstance(value, W.Widget):
        return [value]
    if isinstance(value, dict):
        value = list(value.values())
    if isinstance(value, (list, tuple)):
        return [x for x in value if isinstance(x, W.Widget)]
    return []


def close_tree(widget: W.Widget, keep: Sequence[W.Widget] = ()) -> int:
    """Close ``widget`` and every widget it holds, through its synced traits.

    ipywidgets' ``close()`` closes one widget: its children (and a pythreejs
    view's renderer, scene, geometries and buffers) stay registered, with
    the observers that point back at their parent, so nothing of the tree
    can be freed.  This walks the traits that are synced with the browser
    (``children``, ``scene``, ``geometry``, ``attributes``, ...) and closes
    every widget found, each once, the innermost first, with
    ``ipywidgets.Widget.close``.  The browser links that pentanb made with
    a widget are closed with it; a camera that a :class:`MeshView` shares
    with other views stays open, unless the :func:`slider_stack` that made
    it is closed whole.

    Parameters
    ----------
    widget : ipywidgets.Widget
    keep : sequence of ipywidgets.Widget
        Widgets to leave open, and not to walk into (a camera shared with
        other views).

    Returns
    -------
    int
        How many open widgets were closed.
    """
    if not isinstance(widget, W.Widget):
        raise TypeError(f"close_tree() expects an ipywidgets.Widget, got {type(widget).__name__}")
    kept = {id(w) for w in keep}
    shared: set[int] = set()  # cameras shared by the views met: not walked into
    seen: set[int] = set()
    order: list[W.Widget] = []
    stack = [widget]
    while stack:
        w = stack.pop()
        if id(w) in seen or id(w) in kept or id(w) in shared:
            continue
        seen.add(id(w))
        order.append(w)
        if isinstance(w, MeshView) and not getattr(w, "_own_camera", True):
            shared.add(id(w.camera))
        for name in w.keys:
            if name.startswith("_"):  # _model_name, _view_module, ...
                continue
            stack.extend(_widgets_in(getattr(w, name, None)))
    # then what they own: the browser links made with them (a link left open
    # with a closed end breaks ipywidgets' embedding of every later page), and
    # the camera of a slider_stack closed whole
    for w in list(order):
        for x in getattr(w, OWNED, ()):
            if id(x) not in seen and id(x) not in kept:
                seen.add(id(x))
                order.append(x)
    n = 0
    for w in reversed(order):
        n += w.comm is not None
        W.Widget.close(w)  # not a subclass's close(), which may call this one
    return n


def _set_array(attribute, array) -> None:
    """Replace a BufferAttribute's array so that the browser re-uploads it.

    three.js uploads an attribute to the GPU again only when its ``version``
    is above the one it uploaded last.  pythreejs syncs ``version`` from
    Python too (a state request can send an old value back), so an array
    replaced after that may never reach the GPU (``GL_INVALID_OPERATION``:
    a buffer drawn with fewer rows than the draw call reads).  Each new array therefore comes with a
    version far above any the browser has counted to.
    """
    with attribute.hold_sync():
        attribute.array = array
        attribute.version = next(_VERSIONS) << 20


def _replace(
    position,
    new_position,
    color,
    new_color,
    index=None,
    new_index=None,
    normal=None,
    new_normal=None,
) -> None:
    """Replace a geometry's arrays so that nothing drawn outruns the rows it reads.

    Growing, the colours (and normals) go first, then the positions, then
    the index (if the geometry has one); shrinking, the index first, then
    the positions, then the colours: at no moment does the index point past
    the rows of any attribute, nor the position buffer outrun another.
    """
    steps = [(color, new_color)]
    if normal is not None:
        steps.append((normal, new_normal))
    steps.append((position, new_position))
    if index is not None:
        steps.append((index, new_index))
    if len(new_position) < len(position.array):
        steps.reverse()
    for attribute, array in steps:
        _set_array(attribute, array)


class MeshView(W.VBox):
    """A pythreejs view of a polygon mesh with a legend and an edge switch.

    Faces are shaded smoothly (a normal per vertex, so a curved pentagon
    shows no seams along its fan triangles); the edges fade on
    large meshes (:func:`pentanb.viz.drawing.edge_opacity`: fully drawn up
    to 2,000 faces, about a third as opaque at 20,000); the boundary of an
    open mesh is drawn in :data:`pentanb.viz.colors.BOUNDARY_COLOR`, 3
    pixels wide, whether the edges are shown or not; the camera looks from
    ``elev``, ``azim`` (default: the matplotlib figures' view, from the
    front and a little above, +z up).

    Build it with :func:`view`.  Attributes give the widgets inside, for
    tests and for building larger panels:

    Attributes
    ----------
    renderer : pythreejs.Renderer
    camera : pythreejs.PerspectiveCamera
    controls : pythreejs.OrbitControls
    face_geometry, edge_geometry, point_geometry : pythreejs.BufferGeometry
        Their ``attributes`` are updated in place.
    faces, edges, points : pythreejs.Mesh, LineSegments, Points
    edge_material : pythreejs.LineBasicMaterial
        Its ``opacity`` is :func:`pentanb.viz.drawing.edge_opacity` of the
        number of faces shown.
    boundary_geometry : pythreejs.LineSegmentsGeometry
    boundary : pythreejs.LineSegments2
        The boundary's edges, wide (hidden for a closed mesh).
    elev, azim : float
        Where the camera looks from when fitted (degrees, +z up).
    wireframe : ipywidgets.Checkbox
        Shows or hides the edges (linked in the browser, so it works in an
        exported page too).
    legend : ipywidgets.HTML
    frame : Frame
        How the coordinates are drawn (:func:`pentanb.viz.drawing.view_frame`):
        as they are, or, for coordinates float32 would not draw well (near
        ``1e300``, or a small mesh far from the origin), moved and scaled by
        a power of two, the camera fitted to them there.

    Raises
    ------
    TypeError
        ``width`` or ``height`` not an integer, ``fov``, ``point_size``,
        ``elev`` or ``azim`` not a number (the message names it).
    ValueError
        ``width`` or ``height`` outside ``[1, MAX_PIXELS]``, ``fov`` outside
        (0, 180), ``point_size`` not positive, ``elev`` outside [-90, 90],
        ``azim`` outside [-360, 360].
    """

    def __init__(
        self,
        mesh: Mesh | Drawing,
        *,
        width: int = 600,
        height: int = 450,
        edges: bool = True,
        legend: bool = True,
        background: str = "#ffffff",
        fov: float = 40.0,
        toggle: bool = True,
        point_size: float | None = None,
        camera: P3.PerspectiveCamera | None = None,
        target: tuple | None = None,
        frame: Frame | None = None,
        elev: float = VIEW_ELEV,
        azim: float = VIEW_AZIM,
    ):
        width = _checks.count(width, "width", 1, MAX_PIXELS)
        height = _checks.count(height, "height", 1, MAX_PIXELS)
        fov = _checks.number(fov, "fov", 0.0, 180.0, open_low=True, open_high=True)
        self.elev = _checks.number(elev, "elev", -90.0, 90.0)
        self.azim = _checks.number(azim, "azim", -360.0, 360.0)
        if point_size is not None:
            point_size = _checks.number(point_size, "point_size", 0.0, open_low=True)
        self._mesh: Mesh | None = None
        self._drawing: Drawing | None = None
        self.frame: Frame = IDENTITY if frame is None else frame
        b, _ = self._show(mesh, refit=frame is None)
        self._point_size = point_size

        def attr(a):
            # colours are bytes, read by WebGL as normalized values in [0, 1]
            return P3.BufferAttribute(array=a, normalized=a.dtype == np.uint8)

        # pythreejs hands an attribute named "index" to three.js's setIndex()
        self.face_geometry = P3.BufferGeometry(
            attributes={
                "position": attr(b.position),
                "color": attr(b.color),
                "normal": attr(b.normal),
                "index": attr(b.index),
            },
        )
        # a normal per vertex, interpolated (not flatShading, which lights every
        # fan triangle by its own plane: seams across a curved pentagon)
        self.face_material = P3.MeshPhongMaterial(
            vertexColors="VertexColors",
            flatShading=False,
            side="DoubleSide",
            shininess=1,
            specular="#000000",
            polygonOffset=True,
            polygonOffsetFactor=1.0,
            polygonOffsetUnits=1.0,
        )
        self._serial = 0
        self.faces = P3.Mesh(
            self.face_geometry, self.face_material, frustumCulled=False, name="pentanb-faces-0"
        )

        self.edge_geometry = P3.BufferGeometry(
            attributes={
                "position": attr(b.edge_position),
                "color": attr(b.edge_color),
                "index": attr(b.edge_index),
            }
        )
        opacity = edge_opacity(self._n_faces())
        self.edge_material = P3.LineBasicMaterial(
            vertexColors="VertexColors", transparent=opacity < 1.0, opacity=opacity
        )
        self.edges = P3.LineSegments(
            self.edge_geometry,
            self.edge_material,
            frustumCulled=False,
            visible=bool(edges and b.edge_count),
        )

        # WebGL draws lines 1 pixel wide: the boundary is a LineSegments2 (quads
        # facing the camera), BOUNDARY_WIDTH pixels wide
        self.boundary_geometry = P3.LineSegmentsGeometry(positions=b.boundary_position)
        self.boundary_material = P3.LineMaterial(color=BOUNDARY_COLOR, linewidth=BOUNDARY_WIDTH)
        self.boundary = P3.LineSegments2(
            self.boundary_geometry,
            self.boundary_material,
            frustumCulled=False,
            visible=bool(b.boundary_count),
        )

        self.point_geometry = P3.BufferGeometry(
            attributes={"position": attr(b.point_position), "color": attr(b.point_color)}
        )
        self.point_material = P3.PointsMaterial(
            vertexColors="VertexColors", sizeAttenuation=True, size=0.03
        )
        self.points = P3.Points(
            self.point_geometry,
            self.point_material,
            frustumCulled=False,
            visible=bool(b.point_count),
        )

        aspect = width / height
        centre, radius, position = camera_fit(self._points(), fov, aspect, self.direction)
        # a hemisphere light riding on the camera: faces turned to the reader
        # are lit, faces turned away darker (lights with shadows, such as
        # PointLight and DirectionalLight, print "Error setting state" in
        # JupyterLab 4)
        self.headlight = P3.HemisphereLight(color="#ffffff", groundColor="#202020", intensity=0.6)
        self.ambient = P3.AmbientLight(color="#ffffff", intensity=0.45)
        objects = [self.faces, self.edges, self.boundary, self.points, self.ambient]
        if camera is None:
            self.camera = P3.PerspectiveCamera(
                position=tuple(float(c) for c in position),
                up=(0.0, 0.0, 1.0),
                fov=fov,
                aspect=aspect,
                near=radius / 100,
                far=radius * 100,
                quaternion=look_at_quaternion(position, centre),
                children=[self.headlight],
            )
            objects.append(self.camera)
            self._own_camera = True
        else:
            # a camera shared with other views stays outside every scene (an
            # object has one parent); the light follows it through a link
            self.camera = camera
            self._own_camera = False
            self.headlight.position = tuple(camera.position)
            self._light_link = _linked(
                (camera, "position"), (self.headlight, "position"), one_way=True
            )
            objects.append(self.headlight)
            centre = np.asarray(target if target is not None else centre, dtype=np.float64)
        self.scene = P3.Scene(children=objects, background=background)
        self.controls = P3.OrbitControls(
            controlling=self.camera, target=tuple(float(c) for c in centre)
        )
        self.renderer = P3.Renderer(
            scene=self.scene,
            camera=self.camera,
            controls=[self.controls],
            width=width,
            height=height,
            antialias=True,
            background=background,
        )
        self._set_point_size(radius)

        self.wireframe = W.Checkbox(
            value=bool(edges), description="edges", indent=False, layout=W.Layout(width="auto")
        )
        self._edges_present = bool(b.edge_count)
        self._link = _linked((self.wireframe, "value"), (self.edges, "visible"))
        self.legend = W.HTML(self._legend() if legend else "")
        self._show_legend = legend
        bottom = [self.legend] + ([self.wireframe] if toggle else [])
        self.bottom = W.HBox(
            bottom,
            layout=W.Layout(
                align_items="center", justify_content="space-between", width=f"{width}px"
            ),
        )
        super().__init__([self.renderer, self.bottom])
        self.add_class("pentanb-view")

    # -- data ---------------------------------------------------------------
    @property
    def direction(self) -> np.ndarray:
        """(3,) float: the unit vector from the model towards the camera when it is
        fitted (:func:`pentanb.viz.drawing.eye_direction` of ``elev``, ``azim``)."""
        return eye_direction(self.elev, self.azim)

    def _n_faces(self) -> int:
        """Number of faces shown (the edges fade with it)."""
        return self._mesh.n_faces if self._mesh is not None else self.drawing.n_faces

    @property
    def mesh(self) -> Mesh | None:
        """The mesh shown (None when showing a step-through drawing)."""
        return self._mesh

    @property
    def drawing(self) -> Drawing:
        """The :class:`Drawing` shown (of a mesh: made when first asked for)."""
        if self._drawing is None:
            assert self._mesh is not None
            self._drawing = as_drawing(self._mesh)
        return self._drawing

    def _show(self, obj: Mesh | Drawing, refit: bool = False) -> tuple[Buffers, bool]:
        """Remember what is shown; its buffers (a mesh's by the fast path), and
        whether the frame changed (``refit``: always choose it anew; else only
        when the current one does not draw ``obj`` well)."""
        if isinstance(obj, Mesh):
            self._mesh, self._drawing = obj, None
        else:
            self._mesh, self._drawing = None, as_drawing(obj)
        points = self._raw_points()
        changed = False
        if refit or not frame_fits(self.frame, *points):
            new = view_frame(*points)
            changed = not (new[1] == self.frame[1] and np.array_equal(new[0], self.frame[0]))
            self.frame = new
        if self._mesh is not None:
            return mesh_buffers(framed(self._mesh, self.frame)), changed  # type: ignore[arg-type]
        return buffers(framed(self.drawing, self.frame)), changed  # type: ignore[arg-type]

    def _legend(self) -> str:
        m = self._mesh
        if m is not None:  # as drawing(m) would give it
            return legend_html(m.face_size_histogram(), (m.n_vertices, m.n_edges, m.n_faces))
        return legend_html(self.drawing.legend, self.drawing.counts)

    def _raw_points(self) -> list[np.ndarray]:
        """The coordinates shown, as given (a drawing's segments and points too)."""
        if self._mesh is not None:
            return [self._mesh.vertices]
        d = self.drawing
        return [d.vertices, d.segments] + ([] if d.points is None else [d.points])

    def _points(self) -> np.ndarray:
        """The vertices as drawn (in :attr:`frame`): what the camera is fitted to."""
        raw = self._mesh.vertices if self._mesh is not None else self.drawing.vertices
        return in_frame(raw, self.frame)

    def update(self, mesh: Mesh | Drawing, *, fit: bool = False) -> None:
        """Show another mesh (or :class:`Drawing`) in the same geometry.

        The arrays of the existing ``BufferAttribute`` widgets are replaced;
        the geometry objects, renderer, camera and controls are kept, so the
        viewpoint stays where the reader left it (unless ``fit``).
        """
        # (as_drawing refuses anything but a Mesh or a Drawing); a mesh whose
        # coordinates the current frame does not draw well gets its own, and
        # the camera is fitted to it there
        b, moved = self._show(mesh, refit=fit)
        # no frame is drawn half-updated: the browser waits for the last array
        with self.renderer.hold():
            self._write(b)
        self._redraw()
        if self._show_legend:
            self.legend.value = self._legend()
        if fit or moved:
            self.fit_camera()

    def _redraw(self) -> None:
        """Ask the browser for a new frame.

        ``Renderer.hold()`` pauses pythreejs' automatic redraws, but lifting
        the pause draws nothing; a change to an object of the scene does.
        """
        self._serial += 1
        self.faces.name = f"pentanb-faces-{self._serial}"

    def _write(self, b: Buffers) -> None:
        fa = self.face_geometry.attributes
        ea = self.edge_geometry.attributes
        pa = self.point_geometry.attributes
        # the index says which rows are drawn, the position buffer how many
        # points are: never let either outrun the arrays it reads, not even
        # between two messages
        _replace(
            fa["position"],
            b.position,
            fa["color"],
            b.color,
            fa["index"],
            b.index,
            fa["normal"],
            b.normal,
        )
        _replace(
            ea["position"], b.edge_position, ea["color"], b.edge_color, ea["index"], b.edge_index
        )
        # no points before nor after: the hidden placeholder row stays (two
        # messages fewer a move)
        if b.point_count or self.points.visible or len(pa["position"].array) != 1:
            _replace(pa["position"], b.point_position, pa["color"], b.point_color)
        self.points.visible = bool(b.point_count)
        self._edges_present = bool(b.edge_count)
        self.edges.visible = bool(self.wireframe.value and b.edge_count)
        opacity = edge_opacity(self._n_faces())
        with self.edge_material.hold_sync():
            self.edge_material.opacity = opacity
            self.edge_material.transparent = opacity < 1.0
        if b.boundary_count or self.boundary.visible:
            self.boundary_geometry.positions = b.boundary_position
        self.boundary.visible = bool(b.boundary_count)

    def fit_camera(self) -> None:
        """Point the camera at the whole drawing again."""
        centre, radius, position = camera_fit(
            self._points(), self.camera.fov, self.camera.aspect, self.direction
        )
        with self.renderer.hold():
            self.camera.near = radius / 100
            self.camera.far = radius * 100
            self.controls.target = tuple(float(c) for c in centre)
            self.camera.position = tuple(float(c) for c in position)
            self.camera.quaternion = look_at_quaternion(position, centre)
        self._redraw()
        self._set_point_size(radius)

    def _set_point_size(self, radius: float) -> None:
        self.point_material.size = float(self._point_size or radius * 0.09)

    def close(self) -> None:
        """Close the view and every widget inside it, so that its arrays can be freed.

        A camera given to the constructor (shared with other views) is left
        open.
        """
        close_tree(self)
        self._mesh, self._drawing = None, None

    # -- embedding ----------------------------------------------------------
    def copy(self, mesh: Mesh | Drawing | None = None, **kwargs) -> MeshView:
        """A new, independent view of ``mesh`` (default: the one shown), in its own frame
        unless ``frame=`` is given."""
        r = self.renderer
        opts = dict(
            width=r.width,
            height=r.height,
            edges=self.wireframe.value,
            legend=self._show_legend,
            background=r.background,
            fov=self.camera.fov,
            point_size=self._point_size,
            elev=self.elev,
            azim=self.azim,
        )
        opts.update(kwargs)
        shown = self._mesh if self._mesh is not None else self.drawing
        return MeshView(shown if mesh is None else mesh, **opts)


def view(
    mesh: Mesh,
    *,
    width: int = 600,
    height: int = 450,
    edges: bool = True,
    legend: bool = True,
    background: str = "#ffffff",
    elev: float = VIEW_ELEV,
    azim: float = VIEW_AZIM,
) -> MeshView:
    """An interactive 3D view of a mesh (pythreejs, orbit controls).

    Faces are coloured by their number of sides, with the colours of the
    matplotlib figures and a legend, each lit as one polygon; the edges are
    drawn as a wireframe with a check box to hide them, fainter on large
    meshes; an open mesh's boundary is drawn wide and dark; the camera is
    fitted to the mesh, looking from the front and a little above (+z up)
    unless ``elev`` and ``azim`` say otherwise.

    Parameters
    ----------
    mesh : Mesh
    width, height : int
        Size of the picture in pixels.
    edges : bool
        Draw the wireframe at first.
    legend : bool
        Show the colour legend and the counts V, E, F under the picture.
    background : str
        CSS colour behind the mesh.
    elev, azim : float
        Where the camera looks from, in degrees (matplotlib's ``view_init``
        conventions, +z up): default :data:`pentanb.viz.drawing.VIEW_ELEV`,
        :data:`~pentanb.viz.drawing.VIEW_AZIM`, the figures' view.

    Returns
    -------
    MeshView
        An ipywidgets box; the last expression of a notebook cell shows it.
        :meth:`MeshView.update` shows another mesh in the same view.

    Examples
    --------
    >>> import pentanb
    >>> pentanb.view(pentanb.pentagonalize(pentanb.shapes.cube()))  # doctest: +SKIP
    """
    return MeshView(
        mesh,
        width=width,
        height=height,
        edges=edges,
        legend=legend,
        background=background,
        elev=elev,
        azim=azim,
    )


def _coordinates(item: Mesh | Drawing) -> list[np.ndarray]:
    if isinstance(item, Mesh):
        return [item.vertices]
    d = as_drawing(item)
    return [d.vertices, d.segments] + ([] if d.points is None else [d.points])


def slider_stack(
    items: Sequence[Mesh | Drawing],
    captions: Sequence[str],
    like: MeshView,
    *,
    description: str = "step",
    title: str = "",
    value: int = 0,
) -> W.VBox:
    """A slider choosing one of several prebuilt views, linked in the browser.

    Every item gets its own :class:`MeshView` with the size and viewpoint of
    ``like``; the views share one camera, so orbiting one keeps the viewpoint
    for the others.  The slider is linked to an :class:`ipywidgets.Stack` in
    the browser (``jslink``), so the box keeps working in a page exported
    by :func:`pentanb.export_html`, without a kernel.

    Parameters
    ----------
    items : sequence of Mesh or Drawing
    captions : sequence of str
        HTML shown above the view of the same index.
    like : MeshView
        Size, colours, edges and camera to copy.
    description : str
        The slider's label.
    title : str
        HTML above the slider.
    value : int
        The item shown first.
    """
    if len(items) != len(captions) or not items:
        raise ValueError(f"{len(items)} items and {len(captions)} captions; need as many, >= 1")
    cam = like.camera
    # one camera for all the views, outside their scenes: orbiting one view
    # moves the camera of all
    camera = P3.PerspectiveCamera(
        position=tuple(cam.position),
        up=tuple(cam.up),
        quaternion=tuple(cam.quaternion),
        fov=cam.fov,
        aspect=cam.aspect,
        near=cam.near,
        far=cam.far,
    )
    # one frame for all the views, as they share the camera: like's when it
    # draws every item well (always for the package's meshes), else one for
    # all the items, the camera fitted to all of them there
    points = [p for item in items for p in _coordinates(item)]
    frame = like.frame if frame_fits(like.frame, *points) else view_frame(*points)
    target = tuple(like.controls.target)
    if frame is not like.frame:
        drawn = np.concatenate([in_frame(p, frame).reshape(-1, 3) for p in points])
        centre, radius, eye = camera_fit(drawn, cam.fov, cam.aspect, like.direction)
        target = tuple(float(c) for c in centre)
        camera.position = tuple(float(c) for c in eye)
        camera.quaternion = look_at_quaternion(eye, centre)
        camera.near, camera.far = radius / 100, radius * 100
    views = [like.copy(item, camera=camera, target=target, frame=frame) for item in items]
    for v in views:
        v.point_material.size = like.point_material.size
        v.wireframe.value = like.wireframe.value
    stack = W.Stack(views, selected_index=value)
    texts = W.Stack([W.HTML(c) for c in captions], selected_index=value)
    slider = W.IntSlider(
        value=value,
        min=0,
        max=len(views) - 1,
        description=description,
        continuous_update=True,
        layout=W.Layout(width="420px"),
    )
    _linked((slider, "value"), (stack, "selected_index"))
    _linked((slider, "value"), (texts, "selected_index"))
    for v in views[1:]:
        _linked((views[0].wireframe, "value"), (v.wireframe, "value"))
    box = W.VBox([W.HTML(title), slider, texts, stack])
    _own(box, camera)  # closed with the whole box, not with one view
    box.add_class("pentanb-static")
    return box
