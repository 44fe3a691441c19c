"""Interactive 3D views with pythreejs: :func:`view`, :func:`explore`, :func:`step_through`.

Every drawing colours a face by its number of sides with
:func:`pentanb.colors.face_color`, the colours of the matplotlib figures, so a
pentagon is bluish green everywhere.

How a mesh becomes WebGL buffers
--------------------------------
A polygon face is drawn as the fan of triangles from its first corner
(:meth:`pentanb.Mesh.fan_triangles`).  So that each face keeps one flat
colour, the buffers are per *corner*, not per vertex: the ``position``
attribute holds ``vertices[corners]`` (one row per corner, face after face),
``color`` repeats each face's colour over its corners and ``index`` holds the
fan triangles as corner numbers.  Flat shading (``MeshPhongMaterial`` with
``flatShading``) needs no normals.  Edges are one ``LineSegments`` whose
``position`` holds the two ends of every edge.

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
index buffer drawn against a shorter position buffer); :meth:`MeshView.update`
avoids it by giving every replaced array a new, higher ``version`` (see
:func:`_set_array`), and the browser tests fail on it.
"""

from __future__ import annotations

import itertools
import math
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field

import ipywidgets as W
import numpy as np
import pythreejs as P3

from ..mesh import Mesh, MeshError
from .colors import EDGE_COLOR, _hex_to_rgb, face_color, face_label, face_rgb

__all__ = ["Drawing", "MeshView", "Explorer", "view", "explore", "step_through", "drawing"]

#: Colour of the points drawn by the step-through (new vertices).
POINT_COLOR = "#000000"


# --------------------------------------------------------------------------
# what is drawn
# --------------------------------------------------------------------------


@dataclass
class Drawing:
    """Everything one picture shows, as flat arrays ready for WebGL.

    Attributes
    ----------
    positions : (H, 3) float
        Corner positions, face after face (CSR with ``offsets``).
    offsets : (m + 1,) int
        Face ``f`` has corners ``offsets[f]:offsets[f + 1]``.
    face_colors : (m, 3) float
        RGB in [0, 1] per face.
    segments : (S, 2, 3) float
        The two ends of every line segment (edges).
    segment_colors : (S, 3) float, optional
        RGB per segment; default :data:`pentanb.colors.EDGE_COLOR`.
    points : (k, 3) float, optional
        Positions of points to mark (new vertices in a step-through).
    point_colors : (k, 3) float, optional
    legend : dict int -> int
        Number of faces per face size, for the legend.
    counts : (V, E, F) or None
        The mesh's counts, when the drawing shows a mesh.
    """

    positions: np.ndarray
    offsets: np.ndarray
    face_colors: np.ndarray
    segments: np.ndarray
    segment_colors: np.ndarray | None = None
    points: np.ndarray | None = None
    point_colors: np.ndarray | None = None
    legend: dict = field(default_factory=dict)
    counts: tuple | None = None

    @property
    def n_faces(self) -> int:
        return len(self.offsets) - 1


def drawing(mesh: Mesh) -> Drawing:
    """The :class:`Drawing` of a mesh: its faces coloured by size and its edges."""
    sizes = np.asarray(mesh.face_sizes)
    v = np.asarray(mesh.vertices, dtype=np.float64)
    return Drawing(
        positions=v[mesh.corners],
        offsets=np.asarray(mesh.offsets, dtype=np.int64),
        face_colors=face_rgb(sizes),
        segments=v[mesh.edges],
        legend=_histogram(sizes),
        counts=(mesh.n_vertices, mesh.n_edges, mesh.n_faces),
    )


def _histogram(sizes) -> dict[int, int]:
    values, counts = np.unique(np.asarray(sizes, dtype=np.int64), return_counts=True)
    return {int(a): int(b) for a, b in zip(values, counts)}


def _as_drawing(obj) -> Drawing:
    if isinstance(obj, Drawing):
        return obj
    if isinstance(obj, Mesh):
        return drawing(obj)
    raise TypeError(f"expected a pentanb.Mesh or a Drawing, got {type(obj).__name__}")


def fan_corner_triangles(offsets) -> np.ndarray:
    """Fan triangulation of CSR polygons, as corner numbers.

    Parameters
    ----------
    offsets : (m + 1,) int
        Polygon ``f`` has corners ``offsets[f]:offsets[f + 1]`` (at least 3).

    Returns
    -------
    (T, 3) int64
        Triangle ``k`` of polygon ``f`` is corners ``(o, o + k + 1, o + k + 2)``
        with ``o = offsets[f]``: the same triangles, in the same order, as
        :meth:`pentanb.Mesh.fan_triangles` with corners in place of vertices.
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    sizes = np.diff(offsets)
    per = sizes - 2
    tri_face = np.repeat(np.arange(sizes.size, dtype=np.int64), per)
    start = offsets[:-1][tri_face]
    k = np.arange(tri_face.size, dtype=np.int64) - (np.cumsum(per) - per)[tri_face]
    return np.stack([start, start + k + 1, start + k + 2], axis=1)


def buffers(d: Drawing) -> dict[str, np.ndarray]:
    """The WebGL arrays of a drawing (float32 positions and colours, uint32 index).

    Returns
    -------
    dict with
        ``position`` (H, 3), ``color`` (H, 3), ``index`` (3T,),
        ``edge_position`` (2S, 3), ``edge_color`` (2S, 3),
        ``point_position`` (k, 3), ``point_color`` (k, 3).
        Empty edge or point sets become one hidden point (``edge_count``
        and ``point_count`` say how many there really are).
    """
    sizes = np.diff(d.offsets)
    color = np.repeat(np.asarray(d.face_colors, dtype=np.float32), sizes, axis=0)
    seg = np.asarray(d.segments, dtype=np.float32).reshape(-1, 3)
    if d.segment_colors is None:
        seg_color = np.tile(_hex_to_rgb(EDGE_COLOR).astype(np.float32), (len(seg), 1))
    else:
        seg_color = np.repeat(np.asarray(d.segment_colors, dtype=np.float32), 2, axis=0)
    pts = (
        np.zeros((0, 3), np.float32)
        if d.points is None
        else np.asarray(d.points, dtype=np.float32).reshape(-1, 3)
    )
    if d.point_colors is None:
        pt_color = np.tile(_hex_to_rgb(POINT_COLOR).astype(np.float32), (len(pts), 1))
    else:
        pt_color = np.asarray(d.point_colors, dtype=np.float32).reshape(-1, 3)
    out = {
        "position": np.ascontiguousarray(d.positions, dtype=np.float32),
        "color": np.ascontiguousarray(color),
        "index": fan_corner_triangles(d.offsets).astype(np.uint32).reshape(-1),
        "edge_count": len(seg) // 2,
        "point_count": len(pts),
    }
    centre = out["position"][:1] if len(out["position"]) else np.zeros((1, 3), np.float32)
    # WebGL buffers are never empty: an empty set becomes one hidden point
    out["edge_position"] = seg if len(seg) else np.repeat(centre, 2, axis=0)
    out["edge_color"] = seg_color if len(seg) else np.zeros((2, 3), np.float32)
    out["point_position"] = pts if len(pts) else centre.copy()
    out["point_color"] = pt_color if len(pts) else np.zeros((1, 3), np.float32)
    return out


def legend_html(legend: dict, counts=None) -> str:
    """HTML of the colour legend: a swatch, a label and a count per face size."""
    items = []
    for n in sorted(legend):
        items.append(
            '<span style="white-space:nowrap;margin-right:12px">'
            f'<span style="display:inline-block;width:12px;height:12px;'
            f"background:{face_color(n)};border:1px solid {EDGE_COLOR};"
            'vertical-align:middle;margin-right:4px"></span>'
            f"{legend[n]:,} {face_label(n)}</span>"
        )
    text = "".join(items)
    if counts is not None:
        V, E, F = counts
        text += (
            f'<span style="white-space:nowrap;color:#555">V = {V:,}, E = {E:,}, F = {F:,}</span>'
        )
    return f'<div class="pentanb-legend" style="line-height:1.6">{text}</div>'


def counts_text(mesh: Mesh) -> str:
    """One line of counts: V, E, F, Euler characteristic and faces per size."""
    sizes = ", ".join(
        f"{c:,} {face_label(n)}" for n, c in sorted(_histogram(mesh.face_sizes).items())
    )
    return (
        f"V = {mesh.n_vertices:,} &nbsp; E = {mesh.n_edges:,} &nbsp; "
        f"F = {mesh.n_faces:,} &nbsp; ({sizes})"
    )


# --------------------------------------------------------------------------
# the view
# --------------------------------------------------------------------------


def _fit(positions: np.ndarray, fov: float, aspect: float):
    """Centre, radius and a camera position showing every point."""
    p = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
    if len(p) == 0:
        return np.zeros(3), 1.0, np.array([0.0, 0.0, 4.0])
    lo, hi = p.min(axis=0), p.max(axis=0)
    centre = (lo + hi) / 2
    radius = float(np.sqrt(((p - centre) ** 2).sum(axis=1).max())) or 1.0
    half = math.radians(fov) / 2
    if aspect < 1:  # narrow view: the horizontal field of view limits
        half = math.atan(math.tan(half) * aspect)
    distance = radius / math.sin(half) * 1.15
    direction = np.array([0.9, 0.6, 1.1])
    direction /= np.linalg.norm(direction)
    return centre, radius, centre + distance * direction


def look_at_quaternion(eye, target, up=(0.0, 0.0, 1.0)) -> tuple:
    """Quaternion (x, y, z, w) turning a camera at ``eye`` towards ``target``.

    The camera looks down its -z axis, as in three.js ``Object3D.lookAt``;
    setting it from Python keeps a moved camera aimed without a browser-side
    ``lookAt`` call (and so in exported pages too).
    """
    eye, target, up = (np.asarray(a, dtype=np.float64) for a in (eye, target, up))
    z = eye - target
    z /= np.linalg.norm(z) or 1.0
    x = np.cross(up, z)
    if np.linalg.norm(x) < 1e-12:  # looking along up: any perpendicular will do
        x = np.cross((1.0, 0.0, 0.0) if abs(z[0]) < 0.9 else (0.0, 1.0, 0.0), z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.stack([x, y, z], axis=1)  # columns: the camera's axes in the world
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = 2.0 * math.sqrt(tr + 1.0)
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = (s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = ((m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s)
    return tuple(float(c) for c in q)


_VERSIONS = itertools.count(1)


def _set_array(attribute, array) -> None:
    """Replace a BufferAttribute's array so that the browser re-uploads it.

    three.js uploads an attribute to the GPU again only when its ``version``
    is above the one it uploaded last.  pythreejs syncs ``version`` from
    Python too (a state request can send an old value back), so an array
    replaced after that may never reach the GPU ("glDrawElements:
    Insufficient buffer size").  Each new array therefore comes with a
    version far above any the browser has counted to.
    """
    with attribute.hold_sync():
        attribute.array = array
        attribute.version = next(_VERSIONS) << 20


class MeshView(W.VBox):
    """A pythreejs view of a polygon mesh with a legend and an edge switch.

    Build it with :func:`view`.  Attributes give the widgets inside, for
    tests and for building larger panels:

    Attributes
    ----------
    renderer : pythreejs.Renderer
    camera : pythreejs.PerspectiveCamera
    controls : pythreejs.OrbitControls
    face_geometry, edge_geometry, point_geometry : pythreejs.BufferGeometry
        Their ``attributes`` (and the faces' ``index``) are updated in place.
    faces, edges, points : pythreejs.Mesh, LineSegments, Points
    wireframe : ipywidgets.Checkbox
        Shows or hides the edges (linked in the browser, so it works in an
        exported page too).
    legend : ipywidgets.HTML
    """

    def __init__(
        self,
        mesh,
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
    ):
        d = _as_drawing(mesh)
        b = buffers(d)
        self._drawing = d
        self._mesh = mesh if isinstance(mesh, Mesh) else None
        self._point_size = point_size

        def attr(a):
            return P3.BufferAttribute(array=a, normalized=False)

        self.face_geometry = P3.BufferGeometry(
            attributes={"position": attr(b["position"]), "color": attr(b["color"])},
            index=attr(b["index"]),
        )
        self.face_material = P3.MeshPhongMaterial(
            vertexColors="VertexColors",
            flatShading=True,
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
            attributes={"position": attr(b["edge_position"]), "color": attr(b["edge_color"])}
        )
        self.edges = P3.LineSegments(
            self.edge_geometry,
            P3.LineBasicMaterial(vertexColors="VertexColors"),
            frustumCulled=False,
            visible=bool(edges and b["edge_count"]),
        )

        self.point_geometry = P3.BufferGeometry(
            attributes={"position": attr(b["point_position"]), "color": attr(b["point_color"])}
        )
        self.point_material = P3.PointsMaterial(
            vertexColors="VertexColors", sizeAttenuation=True, size=0.03
        )
        self.points = P3.Points(
            self.point_geometry,
            self.point_material,
            frustumCulled=False,
            visible=bool(b["point_count"]),
        )

        aspect = width / height
        centre, radius, position = _fit(d.positions, fov, aspect)
        # a hemisphere light riding on the camera: faces turned to the reader
        # are lit, faces turned away darker (lights with shadows, such as
        # PointLight and DirectionalLight, print "Error setting state" in
        # JupyterLab 4)
        self.headlight = P3.HemisphereLight(color="#ffffff", groundColor="#202020", intensity=0.6)
        self.ambient = P3.AmbientLight(color="#ffffff", intensity=0.45)
        objects = [self.faces, self.edges, self.points, self.ambient]
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
        else:
            # a camera shared with other views stays outside every scene (an
            # object has one parent); the light follows it through a link
            self.camera = camera
            self.headlight.position = tuple(camera.position)
            self._light_link = W.jsdlink((camera, "position"), (self.headlight, "position"))
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
        self._edges_present = bool(b["edge_count"])
        self._link = W.jslink((self.wireframe, "value"), (self.edges, "visible"))
        self.legend = W.HTML(legend_html(d.legend, d.counts) if legend else "")
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
    def mesh(self) -> Mesh | None:
        """The mesh shown (None when showing a step-through drawing)."""
        return self._mesh

    @property
    def drawing(self) -> Drawing:
        return self._drawing

    def update(self, mesh, *, fit: bool = False) -> None:
        """Show another mesh (or :class:`Drawing`) in the same geometry.

        The arrays of the existing ``BufferAttribute`` widgets are replaced;
        the geometry objects, renderer, camera and controls are kept, so the
        viewpoint stays where the reader left it (unless ``fit``).
        """
        d = _as_drawing(mesh)
        b = buffers(d)
        # no frame is drawn half-updated: the browser waits for the last array
        with self.renderer.hold():
            self._write(d, b)
        self._redraw()
        if self._show_legend:
            self.legend.value = legend_html(d.legend, d.counts)
        self._drawing = d
        self._mesh = mesh if isinstance(mesh, Mesh) else None
        if fit:
            self.fit_camera()

    def _redraw(self) -> None:
        """Ask the browser for a new frame.

        ``Renderer.hold()`` pauses pythreejs' automatic redraws, but lifting
        the pause draws nothing; a change to an object of the scene does.
        """
        self._serial += 1
        self.faces.name = f"pentanb-faces-{self._serial}"

    def _write(self, d: Drawing, b: dict) -> None:
        fa = self.face_geometry.attributes
        ea = self.edge_geometry.attributes
        pa = self.point_geometry.attributes
        index = self.face_geometry.index
        old = len(fa["position"].array)
        # keep every index inside the position buffer at all times:
        # growing, positions first; shrinking, index first
        if len(b["position"]) >= old:
            _set_array(fa["position"], b["position"])
            _set_array(fa["color"], b["color"])
            _set_array(index, b["index"])
        else:
            _set_array(index, b["index"])
            _set_array(fa["position"], b["position"])
            _set_array(fa["color"], b["color"])
        _set_array(ea["position"], b["edge_position"])
        _set_array(ea["color"], b["edge_color"])
        _set_array(pa["position"], b["point_position"])
        _set_array(pa["color"], b["point_color"])
        self.points.visible = bool(b["point_count"])
        self._edges_present = bool(b["edge_count"])
        self.edges.visible = bool(self.wireframe.value and b["edge_count"])

    def fit_camera(self) -> None:
        """Point the camera at the whole drawing again."""
        centre, radius, position = _fit(
            self._drawing.positions, self.camera.fov, self.camera.aspect
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

    # -- embedding ----------------------------------------------------------
    def copy(self, mesh=None, **kwargs) -> MeshView:
        """A new, independent view of ``mesh`` (default: the one shown)."""
        r = self.renderer
        opts = dict(
            width=r.width,
            height=r.height,
            edges=self.wireframe.value,
            legend=self._show_legend,
            background=r.background,
            fov=self.camera.fov,
            point_size=self._point_size,
        )
        opts.update(kwargs)
        return MeshView(self._drawing if mesh is None else mesh, **opts)


def view(
    mesh: Mesh,
    *,
    width: int = 600,
    height: int = 450,
    edges: bool = True,
    legend: bool = True,
    background: str = "#ffffff",
) -> MeshView:
    """An interactive 3D view of a mesh (pythreejs, orbit controls).

    Faces are flat shaded and coloured by their number of sides, with the
    colours of the matplotlib figures and a legend; the edges are drawn as a
    wireframe with a check box to hide them; the camera is fitted to the mesh.

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
        mesh, width=width, height=height, edges=edges, legend=legend, background=background
    )


# --------------------------------------------------------------------------
# the explorer
# --------------------------------------------------------------------------

_MESH_OPTION = "(your mesh)"


class Explorer(W.HBox):
    """Controls (shape, scheme, iterations, duals, scale, edges) beside one view.

    Build it with :func:`explore`.  Every result is cached, so a slider that
    goes back shows its mesh at once, and a deeper level is built from the
    deepest cached one.

    Attributes
    ----------
    shape, scheme : ipywidgets.Dropdown
    iterations, duals : ipywidgets.IntSlider
    scale : ipywidgets.FloatSlider
        The scheme's ``scale`` option (disabled for schemes without one).
    wireframe : ipywidgets.Checkbox
    progress : ipywidgets.IntProgress
        Steps done of a long computation (``subdivide``'s ``progress``).
    status : ipywidgets.HTML
        The counts line of the mesh shown, or why a request was refused.
    view : MeshView
    """

    def __init__(
        self,
        mesh="dodecahedron",
        scheme: str = "pentagonalize",
        *,
        iterations: int = 1,
        duals: int = 2,
        scale: float | None = None,
        max_iterations: int = 5,
        max_faces: int = 250_000,
        max_bytes: int | None = None,
        width: int = 560,
        height: int = 460,
    ):
        from .. import shapes
        from ..schemes import SCHEMES

        self._schemes = SCHEMES
        self._meshes: dict = {}
        names = list(shapes.SHAPES)
        if isinstance(mesh, Mesh):
            self._meshes[_MESH_OPTION] = mesh
            options, first = [_MESH_OPTION] + names, _MESH_OPTION
        elif isinstance(mesh, str):
            shapes.get(mesh)  # unknown names raise here, listing the known ones
            options, first = names, mesh
        else:
            raise TypeError(f"explore() takes a pentanb.Mesh or a shape name ({', '.join(names)})")
        if scheme not in SCHEMES:
            raise ValueError(f"unknown scheme {scheme!r}; known schemes: {', '.join(SCHEMES)}")
        self.max_faces = int(max_faces)
        self.max_bytes = max_bytes
        self._cache: OrderedDict = OrderedDict()
        self._cache_corners = 0
        #: Largest number of corners kept in the cache (all entries together).
        self.cache_limit = 12_000_000

        style = {"description_width": "80px"}
        wide = W.Layout(width="300px")
        self.shape = W.Dropdown(
            options=options, value=first, description="shape", style=style, layout=wide
        )
        self.scheme = W.Dropdown(
            options=[(s.label, s.name) for s in SCHEMES.values()],
            value=scheme,
            description="scheme",
            style=style,
            layout=wide,
        )
        self.iterations = W.IntSlider(
            value=iterations,
            min=0,
            max=max_iterations,
            description="iterations",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        self.duals = W.IntSlider(
            value=duals,
            min=0,
            max=4,
            description="dual passes",
            continuous_update=False,
            style=style,
            layout=wide,
        )
        default_scale = SCHEMES[scheme].options.get("scale", 0.75)
        self.scale = W.FloatSlider(
            value=default_scale if scale is None else scale,
            min=0.05,
            max=0.95,
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

        first_mesh = self._base(first)
        self.view = MeshView(first_mesh, width=width, height=height, toggle=False)
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
        right = W.VBox([self.view, self.counts])
        super().__init__([panel, right])
        self.add_class("pentanb-explorer")
        self._sync_scale()
        self._busy = False
        for w in (self.shape, self.scheme, self.iterations, self.duals, self.scale):
            w.observe(self._on_change, names="value")
        self.refresh()
        self.view.fit_camera()

    # -- state --------------------------------------------------------------
    def _base(self, name: str) -> Mesh:
        if name not in self._meshes:
            from .. import shapes

            self._meshes[name] = shapes.get(name)
        return self._meshes[name]

    def _options(self) -> dict:
        s = self._schemes[self.scheme.value]
        return {"scale": float(self.scale.value)} if "scale" in s.options else {}

    def key(self, iterations: int | None = None) -> tuple:
        """Cache key of the current settings (at ``iterations``)."""
        it = self.iterations.value if iterations is None else iterations
        opts = tuple(sorted(self._options().items()))
        return (self.shape.value, self.scheme.value, self.duals.value, opts, it)

    def _sync_scale(self) -> None:
        self.scale.disabled = "scale" not in self._schemes[self.scheme.value].options

    def _on_change(self, change) -> None:
        if change["owner"] is self.scheme:
            self._sync_scale()
        self.refresh(fit=change["owner"] is self.shape)

    # -- work ---------------------------------------------------------------
    def mesh_at(self, iterations: int | None = None, progress: Callable | None = None) -> Mesh:
        """The mesh for the current settings (cached); raises MeshError when too large."""
        from ..subdivision import predict_counts, subdivide

        it = self.iterations.value if iterations is None else int(iterations)
        key = self.key(it)
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        base = self._base(self.shape.value)
        scheme, duals, opts = self.scheme.value, self.duals.value, self._options()
        counts = predict_counts((base.n_vertices, base.n_edges, base.n_faces), scheme, it, duals)
        if counts and counts[-1][2] > self.max_faces:
            V, E, F = counts[-1]
            raise MeshError(
                f"{scheme} x{it} with {duals} duals would make a mesh of {F:,} faces "
                f"({V:,} vertices, {E:,} edges); this view draws at most "
                f"{self.max_faces:,} faces. Lower the iterations, or call "
                "pentanb.subdivide() yourself."
            )
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

    def _store(self, key, mesh: Mesh) -> None:
        self._cache[key] = mesh
        self._cache_corners += len(mesh.corners)
        while self._cache_corners > self.cache_limit and len(self._cache) > 1:
            _, old = self._cache.popitem(last=False)
            self._cache_corners -= len(old.corners)

    def refresh(self, fit: bool = False) -> None:
        """Compute (or fetch) the mesh of the current settings and show it."""

        def report(done, total, message):
            self.progress.max = max(total, 1)
            self.progress.value = done
            self.status.value = f"<i>computing: {message}</i>"

        key = self.key()
        if key not in self._cache:
            self.progress.value = 0
            self.progress.layout.visibility = "visible"
            self.status.value = "<i>computing...</i>"
        try:
            mesh = self.mesh_at(progress=report)
        except (MeshError, ValueError) as err:
            self.status.value = (
                f'<span style="color:#b00020">{_escape(str(err))}</span>'
                "<br>(the picture still shows the previous mesh)"
            )
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

    # -- export -------------------------------------------------------------
    def static_copy(self, levels: int | None = None) -> W.Widget:
        """A kernel-free copy: one view per iteration count, chosen by a slider.

        The slider is linked to a :class:`ipywidgets.Stack` in the browser
        (``jslink``), so the copy keeps working in a stand-alone HTML page.
        Levels run from 0 to ``levels`` (default: the current iterations),
        stopping before one that would exceed the size limits.
        """
        top = self.iterations.value if levels is None else int(levels)
        meshes = []
        for k in range(top + 1):
            try:
                meshes.append(self.mesh_at(k))
            except (MeshError, ValueError):
                break
        label = self._schemes[self.scheme.value].label
        opts = self._options()
        title = (
            f"<b>{_escape(str(self.shape.value))}</b>: {label}"
            + (f" (scale {opts['scale']:.2f})" if opts else "")
            + f", {self.duals.value} dual passes per iteration"
        )
        return slider_stack(
            meshes,
            [counts_text(m) for m in meshes],
            self.view,
            description="iterations",
            title=title,
            value=min(self.iterations.value, len(meshes) - 1),
        )


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def slider_stack(
    items, captions, like: MeshView, *, description: str = "step", title: str = "", value: int = 0
) -> W.VBox:
    """A slider choosing one of several prebuilt views, linked in the browser.

    Every item (a Mesh or a Drawing) gets its own :class:`MeshView` with the
    size and viewpoint of ``like``; the views share one camera, so orbiting
    one keeps the viewpoint for the others.
    """
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
    views = [like.copy(item, camera=camera, target=tuple(like.controls.target)) for item in items]
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
    W.jslink((slider, "value"), (stack, "selected_index"))
    W.jslink((slider, "value"), (texts, "selected_index"))
    for v in views[1:]:
        W.jslink((views[0].wireframe, "value"), (v.wireframe, "value"))
    box = W.VBox([W.HTML(title), slider, texts, stack])
    box.add_class("pentanb-static")
    return box


def explore(
    mesh="dodecahedron",
    scheme: str = "pentagonalize",
    *,
    iterations: int = 1,
    duals: int = 2,
    scale: float | None = None,
    max_iterations: int = 5,
    max_faces: int = 250_000,
    max_bytes: int | None = None,
    width: int = 560,
    height: int = 460,
) -> Explorer:
    """A panel of controls beside one 3D view, with a live line of counts.

    Moving a control rebuilds the mesh with :func:`pentanb.subdivide` (or
    fetches it from a cache) and writes it into the existing geometry's
    buffers; the camera stays where the reader left it (a new shape refits
    it).  Long work drives a progress bar; a request over ``max_faces`` or
    over ``subdivide``'s memory limit is refused with a message giving the
    size the mesh would have.

    Parameters
    ----------
    mesh : Mesh or str
        A mesh, or a name from :data:`pentanb.shapes.SHAPES`.
    scheme : str
        A name from :data:`pentanb.SCHEMES`.
    iterations, duals : int
        Initial slider values (:func:`pentanb.subdivide`).
    scale : float, optional
        Initial scale for schemes that take one (default: the scheme's).
    max_iterations : int
        Largest value of the iterations slider.
    max_faces : int
        Largest mesh (in faces) that the view draws.
    max_bytes : int, optional
        Passed to :func:`pentanb.subdivide`.
    width, height : int
        Size of the picture.

    Returns
    -------
    Explorer
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


def step_through(mesh, scheme: str = "pentagonalize", **kwargs):
    """A classroom step-through of a scheme; see :func:`pentanb.viz.steps.step_through`."""
    from .steps import step_through as _step_through

    return _step_through(mesh, scheme, **kwargs)
