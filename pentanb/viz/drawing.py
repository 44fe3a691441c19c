"""What a picture shows, as numpy arrays: the data every 3D view is drawn from.

Needs numpy only (no matplotlib, no widgets), so it can be tested and reused
without a browser.  :mod:`pentanb.viz.three` turns a :class:`Drawing` into
pythreejs widgets; :mod:`pentanb.viz.stages` builds the drawings of the
step-through.

How a mesh becomes WebGL buffers
--------------------------------
A polygon face is drawn as the fan of triangles from its first corner,
:meth:`pentanb.Mesh.fan_triangles`, in one flat colour: the colour of its
number of sides.  The buffers are *indexed*: ``position`` holds the
vertices and ``index`` three rows of it per triangle.  A vertex has one
colour in WebGL, so a vertex shared by faces of S different sizes is held S
times: ``position`` is the vertex array once per face size present (S
copies, S = 1 for a mesh of one face size) with ``color`` that size's colour
on its copy, and a triangle's corners point into the copy of its face's
size.  For the meshes of the explorer's slider (a few face sizes) that is
1.3-2.3x fewer bytes to compute and to send to the browser than three rows
per triangle (``benchmarks/bench_pipeline.py`` measures it).
Flat shading (``MeshPhongMaterial`` with ``flatShading``) needs no normals.
Edges are one indexed ``LineSegments`` over the vertices; marked points are
one ``Points``.  A general :class:`Drawing` (any colour per face) gets three
rows per triangle and an index that counts through them.
"""

from __future__ import annotations

import dataclasses
import html
import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _jit
from ..mesh import Mesh, check_mesh
from ..mesh import build as _mesh
from .colors import EDGE_COLOR, face_color, face_label, face_rgb, hex_to_rgb

__all__ = [
    "POINT_COLOR",
    "Drawing",
    "drawing",
    "as_drawing",
    "size_histogram",
    "Buffers",
    "buffers",
    "mesh_buffers",
    "legend_html",
    "counts_text",
    "error_html",
    "camera_fit",
    "look_at_quaternion",
    "Frame",
    "IDENTITY",
    "view_frame",
    "in_frame",
    "frame_fits",
    "framed",
]

#: Colour of marked points (the new vertices of a step-through).
POINT_COLOR = "#000000"


@dataclass(frozen=True)
class Drawing:
    """Everything one 3D picture shows: polygons, line segments and points.

    The polygons are the faces of a mesh, fanned into triangles by
    :meth:`pentanb.Mesh.fan_triangles`, each face in one flat colour (which
    need not be its face-size colour: the step-through colours pieces by
    stage).  Build one with :func:`drawing`.

    Attributes
    ----------
    vertices : (n, 3) float
        Positions the triangles index.
    triangles : (T, 3) int
        Vertex indices of the triangles.
    triangle_face : (T,) int
        The face each triangle belongs to.
    face_colors : (m, 3) float
        RGB in [0, 1] per face.
    segments : (S, 2, 3) float
        The two ends of every line segment (edges).
    segment_colors : (S, 3) float, optional
        RGB per segment; default :data:`pentanb.viz.colors.EDGE_COLOR`.
    points : (k, 3) float, optional
        Positions of points to mark.
    point_colors : (k, 3) float, optional
        RGB per point; default :data:`POINT_COLOR`.
    legend : dict int -> int
        Number of faces per face size, for the legend.
    counts : (V, E, F) or None
        The mesh's counts, shown under the legend.
    """

    vertices: NDArray[np.float64]
    triangles: NDArray[np.int64]
    triangle_face: NDArray[np.int64]
    face_colors: NDArray[np.float64]
    segments: NDArray[np.float64]
    segment_colors: NDArray[np.float64] | None = None
    points: NDArray[np.float64] | None = None
    point_colors: NDArray[np.float64] | None = None
    legend: dict[int, int] = field(default_factory=dict)
    counts: tuple[int, int, int] | None = None

    @property
    def n_faces(self) -> int:
        """Number of polygons drawn."""
        return len(self.face_colors)

    @property
    def n_triangles(self) -> int:
        """Number of triangles drawn."""
        return len(self.triangles)


def size_histogram(sizes: ArrayLike) -> dict[int, int]:
    """Number of faces per face size: ``{n: count}`` in increasing ``n``.

    Parameters
    ----------
    sizes : (m,) int
        Number of sides of each face (any subset of a mesh's faces).
    """
    values, counts = np.unique(np.asarray(sizes, dtype=np.int64), return_counts=True)
    return {int(a): int(b) for a, b in zip(values, counts)}


def drawing(
    mesh: Mesh,
    *,
    face_colors: ArrayLike | None = None,
    segments: ArrayLike | None = None,
    segment_colors: ArrayLike | None = None,
    points: ArrayLike | None = None,
    point_colors: ArrayLike | None = None,
    legend: dict[int, int] | None = None,
    show_counts: bool = True,
) -> Drawing:
    """The :class:`Drawing` of a mesh: its faces and edges, or what you give instead.

    Parameters
    ----------
    mesh : Mesh
    face_colors : (m, 3) float, optional
        Default: each face's face-size colour (:func:`pentanb.viz.colors.face_rgb`).
    segments : (S, 2, 3) float, optional
        Default: the mesh's edges.
    segment_colors : (S, 3) float, optional
    points, point_colors : (k, 3) float, optional
        Points to mark (default none).
    legend : dict int -> int, optional
        Default: the mesh's face-size histogram.
    show_counts : bool
        Put the mesh's V, E, F under the legend.

    Returns
    -------
    Drawing
    """
    check_mesh(mesh, "drawing()")
    v = np.asarray(mesh.vertices, dtype=np.float64)
    triangles, triangle_face = mesh.fan_triangles()
    return Drawing(
        vertices=v,
        triangles=triangles,
        triangle_face=triangle_face,
        face_colors=(
            face_rgb(mesh.face_sizes)
            if face_colors is None
            else np.asarray(face_colors, dtype=np.float64)
        ),
        segments=v[mesh.edges] if segments is None else np.asarray(segments, dtype=np.float64),
        segment_colors=None if segment_colors is None else np.asarray(segment_colors, np.float64),
        points=None if points is None else np.asarray(points, dtype=np.float64),
        point_colors=None if point_colors is None else np.asarray(point_colors, np.float64),
        legend=mesh.face_size_histogram() if legend is None else dict(legend),
        counts=(mesh.n_vertices, mesh.n_edges, mesh.n_faces) if show_counts else None,
    )


def as_drawing(obj: Mesh | Drawing) -> Drawing:
    """A Drawing as it is; a Mesh as :func:`drawing` draws it."""
    if isinstance(obj, Drawing):
        return obj
    if isinstance(obj, Mesh):
        return drawing(obj)
    raise TypeError(f"expected a pentanb.Mesh or a Drawing, got {type(obj).__name__}")


def _bytes(rgb: ArrayLike) -> NDArray[np.uint8]:
    """RGB in [0, 1] as bytes 0 .. 255 (exact for the hex colours of the palette)."""
    return np.rint(np.clip(np.asarray(rgb, dtype=np.float64), 0.0, 1.0) * 255).astype(np.uint8)


def _same_rows(rgb: NDArray[np.uint8], n: int) -> NDArray[np.uint8]:
    """``n`` rows of the bytes ``rgb`` (a writeable array; bytes repeated, 20x np.tile's speed)."""
    return np.frombuffer(bytearray(rgb.tobytes() * n), dtype=np.uint8).reshape(n, 3)


def _rows(colors: ArrayLike | None, default: str, n: int, repeat: int) -> NDArray[np.uint8]:
    if colors is None:
        return _same_rows(_bytes(hex_to_rgb(default)), n * repeat)
    return np.repeat(_bytes(colors).reshape(-1, 3), repeat, axis=0)


@dataclass(frozen=True)
class Buffers:
    """The arrays WebGL draws a :class:`Drawing` from (indexed: see the module notes).

    Positions are float32; colours are bytes (uint8, 0 .. 255), drawn as
    normalized attributes, a quarter of the bytes of float colours; indices
    are uint32 (one dtype always: WebGL keeps a buffer's index type).

    Attributes
    ----------
    position : (P, 3) float32
        The rows the triangles are drawn from.
    color : (P, 3) uint8
        The colour of every row: a triangle takes the colour of its face.
    index : (3T,) uint32
        Triangle ``t`` is rows ``index[3t : 3t + 3]`` of ``position``.
    edge_position : (Q, 3) float32
    edge_color : (Q, 3) uint8
    edge_index : (2S,) uint32
        Segment ``s`` joins rows ``edge_index[2s]`` and ``edge_index[2s + 1]``.
    point_position : (k, 3) float32
    point_color : (k, 3) uint8
    edge_count, point_count : int
        S and k.  WebGL buffers are never empty: no triangle, segment or
        point becomes one hidden point (and a degenerate triangle or
        segment on it), and these counts say how many there really are.
    """

    position: NDArray[np.float32]
    color: NDArray[np.uint8]
    index: NDArray[np.uint32]
    edge_position: NDArray[np.float32]
    edge_color: NDArray[np.uint8]
    edge_index: NDArray[np.uint32]
    point_position: NDArray[np.float32]
    point_color: NDArray[np.uint8]
    edge_count: int
    point_count: int

    def triangles(self) -> NDArray[np.float32]:
        """(T, 3, 3) float32: the corners of every triangle drawn."""
        return self.position[self.index].reshape(-1, 3, 3)

    def triangle_colors(self) -> NDArray[np.uint8]:
        """(T, 3, 3) uint8: the colour of every triangle's corners."""
        return self.color[self.index].reshape(-1, 3, 3)

    def segments(self) -> NDArray[np.float32]:
        """(S, 2, 3) float32: the ends of every segment drawn (no placeholder)."""
        return self.edge_position[self.edge_index].reshape(-1, 2, 3)[: self.edge_count]


def _counting(n: int, width: int) -> NDArray[np.uint32]:
    """The index of unindexed rows: 0 .. n - 1 (a degenerate primitive on row 0 if n is 0)."""
    return np.arange(n, dtype=np.uint32) if n else np.zeros(width, np.uint32)


def _addressable(rows: int) -> None:
    """ValueError when a uint32 index cannot address ``rows`` rows."""
    if rows > 2**32:
        raise ValueError(f"{rows:,} rows are more than a WebGL index can address")


def buffers(d: Drawing) -> Buffers:
    """The WebGL arrays of a drawing (see :class:`Buffers`): three rows per triangle."""
    position = np.asarray(d.vertices, dtype=np.float32)[d.triangles].reshape(-1, 3)
    color = _rows(np.asarray(d.face_colors)[d.triangle_face], "#000000", 0, 3)
    seg = np.asarray(d.segments, dtype=np.float32).reshape(-1, 3)
    seg_color = _rows(d.segment_colors, EDGE_COLOR, len(seg) // 2, 2)
    pts = (
        np.zeros((0, 3), np.float32)
        if d.points is None
        else np.asarray(d.points, dtype=np.float32).reshape(-1, 3)
    )
    pt_color = _rows(d.point_colors, POINT_COLOR, len(pts), 1)
    vertices = np.asarray(d.vertices, dtype=np.float32).reshape(-1, 3)
    centre = vertices[:1] if len(vertices) else np.zeros((1, 3), np.float32)
    hidden = np.zeros((1, 3), np.uint8)
    return Buffers(
        position=np.ascontiguousarray(position) if len(position) else centre.copy(),
        color=np.ascontiguousarray(color) if len(position) else hidden.copy(),
        index=_counting(len(position), 3),
        edge_position=seg if len(seg) else centre.copy(),
        edge_color=seg_color if len(seg) else hidden.copy(),
        edge_index=_counting(len(seg), 2),
        point_position=pts if len(pts) else centre.copy(),
        point_color=pt_color if len(pts) else hidden.copy(),
        edge_count=len(seg) // 2,
        point_count=len(pts),
    )


def mesh_buffers(mesh: Mesh) -> Buffers:
    """The explorer's buffers of a mesh: what ``buffers(drawing(mesh))`` draws, indexed.

    The same triangles with the same colours, in the same order
    (``triangles()`` and ``triangle_colors()`` of both are equal bit for
    bit), and the same segments in the same order; but ``position`` is the
    vertices cast to float32 once per face size present, not three rows per
    triangle.  When that would be more rows than three per triangle (a mesh
    with very many face sizes), the rows are per triangle corner as in
    :func:`buffers`.  The fan triangles and edges come from the mesh's
    connectivity caches, which the dual of a dual shares with the mesh it
    came from; with the optional compiled kernels (:mod:`pentanb._jit`), on
    a large mesh, they are written from the faces straight into uint32.
    """
    check_mesh(mesh, "mesh_buffers()")
    counts = _mesh.size_counts(mesh)  # (size, faces) by size, counted once per connectivity
    if not counts or counts[0][0] < 3:
        return buffers(drawing(mesh))
    sizes = mesh.face_sizes
    n = mesh.n_vertices
    low, high = counts[0][0], counts[-1][0]
    table = _bytes(face_rgb(np.arange(low, high + 1)))
    present = np.array([size - low for size, _ in counts])  # ascending
    copies = len(present)
    triangles = len(mesh.corners) - 2 * mesh.n_faces
    jit = _jit.kernels(len(mesh.corners))
    if copies * n > 3 * triangles:  # more copies than triangle corners: rows per corner
        v = mesh.vertices.astype(np.float32)  # a copy: the view's array, writeable
        tri, tri_face = mesh.fan_triangles()
        position = v.take(tri.reshape(-1), axis=0)
        color = np.repeat(table[sizes[tri_face] - low], 3, axis=0)
        index = _counting(len(position), 3)
    else:
        # the vertices cast to float32 straight into every copy (the first
        # copy is also the edges' array): the view's arrays, writeable
        position = np.empty((copies, n, 3), np.float32)
        position[:] = mesh.vertices  # (broadcast: every copy)
        position = position.reshape(-1, 3)
        v = position[:n]
        if copies == 1:  # one size, one copy of the vertices
            color = _same_rows(table[present[0]], n)
        else:
            rows = b"".join(table[p].tobytes() * n for p in present)
            color = np.frombuffer(bytearray(rows), dtype=np.uint8).reshape(-1, 3)
        _addressable(len(position))
        slot = np.zeros(high - low + 1, np.int64)
        slot[present] = np.arange(copies) * n
        if jit is not None:  # (a k-gon's rows are shifted by slot[k - low])
            index = jit.fan_index(mesh.corners, mesh.offsets, slot if copies > 1 else slot[:0], low)
        else:
            tri, tri_face = mesh.fan_triangles()
            if copies > 1:
                tri = tri + slot[sizes[tri_face] - low][:, None]
            index = tri.astype(np.uint32).reshape(-1)
    if jit is not None:
        edge_index = jit.edge_index(mesh.corners, mesh.offsets)
    else:
        edge_index = mesh.edges.astype(np.uint32).reshape(-1)
    return Buffers(
        position=position,
        color=color,
        index=index,
        edge_position=v,
        edge_color=_rows(None, EDGE_COLOR, n, 1),
        edge_index=edge_index,
        point_position=v[:1].copy(),
        point_color=np.zeros((1, 3), np.uint8),
        edge_count=len(edge_index) // 2,
        point_count=0,
    )


def legend_html(legend: dict[int, int], counts: tuple[int, int, int] | None = None) -> str:
    """HTML of the colour legend: a swatch, a count and a label per face size.

    Parameters
    ----------
    legend : dict int -> int
        Faces per face size.
    counts : (V, E, F), optional
        Written after the swatches.
    """
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
    """One line of HTML: V, E, F and the number of faces per size."""
    sizes = ", ".join(f"{c:,} {face_label(n)}" for n, c in mesh.face_size_histogram().items())
    return (
        f"V = {mesh.n_vertices:,} &nbsp; E = {mesh.n_edges:,} &nbsp; "
        f"F = {mesh.n_faces:,} &nbsp; ({sizes})"
    )


def error_html(message: str, note: str = "") -> str:
    """A refusal or error message as HTML (escaped, in red), with an optional note."""
    text = f'<span style="color:#b00020">{html.escape(message)}</span>'
    return text + (f"<br>{html.escape(note)}" if note else "")


#: How a 3D view draws its coordinates: ``(offset, exponent)``, a point ``p``
#: drawn at ``(p - offset) * 2**-exponent`` (exact scaling by a power of two).
Frame = tuple[NDArray[np.float64], int]

#: The coordinates as they are.
IDENTITY: Frame = (np.zeros(3), 0)

#: Drawn coordinates stay within ``2**±32``: WebGL's float32 holds ``2**±126``,
#: and the camera's matrices multiply distances.
_FRAME_LIMIT = 2.0**32
#: A drawing smaller than this fraction of its distance from the origin is
#: moved to the origin (float32 keeps 24 bits: it would be drawn as a blob).
_FRAME_DETAIL = 2.0**-12


def _bounds(points: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(p) == 0:
        return None
    return p.min(axis=0), p.max(axis=0)


def view_frame(*points: ArrayLike) -> Frame:
    """The frame in which a 3D view draws these points (all arrays together).

    :data:`IDENTITY` when float32 holds the coordinates well: within
    ``2**32`` of the origin, the drawing no smaller than ``2**-32`` and
    than ``2**-12`` of its distance from the origin (every mesh of the
    package's shapes and schemes).  Otherwise the centre of the bounding
    box and the power of two that brings its half-size into [0.5, 1): so
    any finite coordinates are framed, near ``1e300`` as near ``1e-300``,
    or a small drawing far from the origin.

    Parameters
    ----------
    *points : (k, 3) float
        Finite coordinates.

    Returns
    -------
    Frame
        ``(offset, exponent)``: a point ``p`` is drawn at
        ``(p - offset) * 2**-exponent`` (:func:`in_frame`).

    Raises
    ------
    ValueError
        A coordinate that is not finite.
    """
    found = [b for b in (_bounds(p) for p in points) if b is not None]
    if not found:
        return IDENTITY
    lo = np.min([b[0] for b in found], axis=0)
    hi = np.max([b[1] for b in found], axis=0)
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ValueError("a view needs finite coordinates")
    far = float(max(np.abs(lo).max(), np.abs(hi).max()))  # from the origin
    centre = lo * 0.5 + hi * 0.5  # (no sum that could overflow)
    half = float((hi * 0.5 - lo * 0.5).max())
    if half == 0.0:  # one point
        return IDENTITY if far <= _FRAME_LIMIT else (centre, 0)
    if far <= _FRAME_LIMIT and half >= 1.0 / _FRAME_LIMIT and half >= far * _FRAME_DETAIL:
        return IDENTITY
    return centre, int(np.frexp(half)[1])


def in_frame(points: ArrayLike, frame: Frame) -> NDArray[np.float64]:
    """``points`` as drawn in ``frame``: ``(p - offset) * 2**-exponent`` (exact scaling).

    Parameters
    ----------
    points : (..., 3) float
    frame : Frame

    Returns
    -------
    (..., 3) float
        ``points`` itself in :data:`IDENTITY`.
    """
    p = np.asarray(points, dtype=np.float64)
    offset, exponent = frame
    if exponent == 0 and not offset.any():
        return p
    return np.ldexp(p - offset, -exponent)


def frame_fits(frame: Frame, *points: ArrayLike) -> bool:
    """Whether ``frame`` draws these points well (their frame within it is the identity).

    Parameters
    ----------
    frame : Frame
    *points : (k, 3) float

    Returns
    -------
    bool
    """
    drawn = [in_frame(p, frame) for p in points]
    if not all(np.isfinite(d).all() for d in drawn):
        return False
    found = view_frame(*drawn)
    return found[1] == 0 and not found[0].any()


def framed(obj: Mesh | Drawing, frame: Frame) -> Mesh | Drawing:
    """``obj`` with its coordinates in ``frame``.

    Parameters
    ----------
    obj : Mesh or Drawing
    frame : Frame

    Returns
    -------
    Mesh or Drawing
        ``obj`` itself in :data:`IDENTITY`; else a copy with new positions
        (a mesh's connectivity shared).
    """
    if frame[1] == 0 and not frame[0].any():
        return obj
    if isinstance(obj, Mesh):
        return obj.with_vertices(in_frame(obj.vertices, frame))
    return dataclasses.replace(
        obj,
        vertices=in_frame(obj.vertices, frame),
        segments=in_frame(obj.segments, frame),
        points=None if obj.points is None else in_frame(obj.points, frame),
    )


def camera_fit(
    points: ArrayLike, fov: float, aspect: float
) -> tuple[NDArray[np.float64], float, NDArray[np.float64]]:
    """A camera that shows every point.

    Parameters
    ----------
    points : (k, 3) float
    fov : float
        Vertical field of view, degrees.
    aspect : float
        Width / height of the picture.

    Returns
    -------
    centre : (3,) float
        Middle of the bounding box (the orbit target).
    radius : float
        Radius of the bounding sphere about ``centre``.
    eye : (3,) float
        Camera position: from the side (0.9, 0.6, 1.1), far enough for the
        sphere to fit in both fields of view, with a 15 % margin.
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
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


def look_at_quaternion(
    eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 0.0, 1.0)
) -> tuple[float, float, float, float]:
    """Quaternion (x, y, z, w) turning a camera at ``eye`` towards ``target``.

    The camera looks down its -z axis, as in three.js ``Object3D.lookAt``;
    setting it from Python keeps a moved camera aimed without a browser-side
    ``lookAt`` call (and so in exported pages too).
    """
    e, t, u = (np.asarray(a, dtype=np.float64) for a in (eye, target, up))
    z = e - t
    z /= np.linalg.norm(z) or 1.0
    x = np.cross(u, z)
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
    return (float(q[0]), float(q[1]), float(q[2]), float(q[3]))
