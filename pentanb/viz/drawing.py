"""What a picture shows, as numpy arrays: the data every 3D view is drawn from.

Needs numpy only (no matplotlib, no widgets), so it can be tested and reused
without a browser.  :mod:`pentanb.viz.three` turns a :class:`Drawing` into
pythreejs widgets; :mod:`pentanb.viz.stages` builds the drawings of the
step-through.

How a mesh becomes WebGL buffers
--------------------------------
A polygon face is drawn as the fan of triangles from its first corner,
:meth:`pentanb.Mesh.fan_triangles`, in one flat colour: the colour of its
number of sides.  It is shaded smoothly: every vertex carries a normal, the
sum of its faces' vector areas normalised (:func:`vertex_normals`), and
WebGL interpolates it across the triangles, so a curved pentagon shows no
seam along its fan diagonals (flat shading, which lights every triangle by
its own plane, would).  The buffers are *indexed*: ``position`` holds the
vertices (cast to float32) once per face size present, each copy in that
size's colour with the vertices' normals, and ``index`` three rows per
triangle pointing into the copy of its face's size: for a mesh of one face
size, ``V`` rows against three per triangle (``3 (H - 2F)``).  Edges are one
indexed ``LineSegments`` over the vertices (drawn fainter on large meshes:
:func:`edge_opacity`); the edges of an open mesh's boundary are a second
line set, drawn wide and dark (:data:`pentanb.viz.colors.BOUNDARY_COLOR`,
:data:`BOUNDARY_WIDTH` pixels); marked points are one ``Points``.  A general
:class:`Drawing` (any colour per face) gets three rows per triangle and an
index that counts through them.

The camera
----------
A view looks at a model from the direction of the matplotlib figures'
default camera (elevation :data:`VIEW_ELEV`, azimuth :data:`VIEW_AZIM`,
with +z up: :func:`eye_direction`), so the package's models, which stand
on the xy plane and face +x (the rabbit's snout), are seen from the front
and a little above, as in the figures.  The camera and the frame a view's
coordinates are drawn in live in :mod:`pentanb.viz.camera`; their names are
importable from here too.
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
from .camera import (
    IDENTITY,
    VIEW_AZIM,
    VIEW_ELEV,
    Frame,
    camera_fit,
    eye_direction,
    frame_fits,
    in_frame,
    look_at_quaternion,
    view_frame,
)
from .colors import EDGE_COLOR, face_color, face_label, face_rgb, hex_to_rgb

__all__ = [
    "POINT_COLOR",
    "BOUNDARY_WIDTH",
    "EDGE_FADE_FACES",
    "EDGE_MIN_OPACITY",
    "VIEW_ELEV",
    "VIEW_AZIM",
    "edge_opacity",
    "eye_direction",
    "polygon_normals",
    "face_areas",
    "vertex_normals",
    "boundary_segments",
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

#: Width of a drawn boundary, in pixels (the edges are 1 pixel wide).
BOUNDARY_WIDTH = 3.0

#: Up to this many faces the edges are drawn fully opaque; beyond it they fade
#: (:func:`edge_opacity`), so that a large mesh is not drawn black.
EDGE_FADE_FACES = 2_000
#: The faintest the edges get (on the largest meshes).
EDGE_MIN_OPACITY = 0.12
#: Faces whose vector areas :func:`face_areas` works out together on the
#: numpy path (a block's arrays stay in cache).
AREA_BLOCK = 8192


def edge_opacity(n_faces: int) -> float:
    """How opaque a view draws the edges of a mesh of ``n_faces`` faces.

    1 up to :data:`EDGE_FADE_FACES` faces; then ``sqrt(EDGE_FADE_FACES /
    n_faces)`` (the edges per pixel grow as the faces, their spacing on the
    screen shrinks as its square root), never below :data:`EDGE_MIN_OPACITY`:
    about 0.32 at 20,000 faces, 0.14 at 100,000.

    Parameters
    ----------
    n_faces : int
        Number of faces drawn (>= 0).

    Returns
    -------
    float
        In [:data:`EDGE_MIN_OPACITY`, 1].
    """
    n = int(n_faces)
    if n <= EDGE_FADE_FACES:
        return 1.0
    return max(math.sqrt(EDGE_FADE_FACES / n), EDGE_MIN_OPACITY)


def polygon_normals(
    vertices: ArrayLike, triangles: ArrayLike, triangle_face: ArrayLike, n_faces: int
) -> NDArray[np.float64]:
    """The unit normal of every polygon, from its fan triangles.

    The direction of the polygon's vector area: the sum of its triangles'
    cross products ``(b - a) x (c - a)``, which for a polygon that is not
    flat is the same from any fan (Newell's normal), and for a flat one its
    plane's normal.  A polygon of no area gets ``(0, 0, 1)``.

    Parameters
    ----------
    vertices : (n, 3) float
    triangles : (T, 3) int
        Vertex indices of the triangles.
    triangle_face : (T,) int
        The polygon of every triangle, in ``[0, n_faces)``.
    n_faces : int

    Returns
    -------
    (n_faces, 3) float
    """
    v = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles).reshape(-1, 3)
    owner = np.asarray(triangle_face).reshape(-1)
    # by coordinate (contiguous columns), the cross products written out: np.cross
    # and row gathers of (T, 3) arrays cost several times more on large meshes
    cols = [np.ascontiguousarray(v[:, k]) for k in range(3)]
    a = [c.take(t[:, 0]) for c in cols]
    u = [c.take(t[:, 1]) - a[k] for k, c in enumerate(cols)]
    w = [c.take(t[:, 2]) - a[k] for k, c in enumerate(cols)]
    cross = (
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    )
    area = np.empty((n_faces, 3))
    starts = np.flatnonzero(np.diff(owner, prepend=-1)) if owner.size else owner
    if owner.size and starts.size == n_faces and bool((owner[starts] == np.arange(n_faces)).all()):
        # the fans' usual order: every face's triangles together, faces in order
        for k in range(3):
            area[:, k] = np.add.reduceat(cross[k], starts)
    else:
        for k in range(3):
            area[:, k] = np.bincount(owner, weights=cross[k], minlength=n_faces)
    length = np.sqrt((area * area).sum(axis=1))
    flat = ~(length > 0)
    out = area / np.where(flat, 1.0, length)[:, None]
    out[flat] = (0.0, 0.0, 1.0)
    return out


def face_areas(mesh: Mesh) -> NDArray[np.float64]:
    """The vector area of every face (twice it), by Newell's formula over its edges.

    ``sum_i p_i x p_(i+1)`` over the face's corners in order, summed one by
    one (faces of one size at a time): the same vector as the sum of any
    fan's triangle cross products (see :func:`polygon_normals`), with no
    triangles built.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (F, 3) float
    """
    check_mesh(mesh, "face_areas()")
    return np.ascontiguousarray(_face_areas_by_axis(mesh).T)


def _face_areas_by_axis(mesh: Mesh) -> NDArray[np.float64]:
    """(3, F) float: :func:`face_areas` axis by axis (each row contiguous)."""
    v = np.asarray(mesh.vertices, dtype=np.float64)
    cols = [np.ascontiguousarray(v[:, k]) for k in range(3)]
    corners, offsets, sizes = mesh.corners, mesh.offsets, mesh.face_sizes
    area = np.empty((3, mesh.n_faces))
    counts = _mesh.size_counts(mesh)
    for n, _ in counts:
        faces = None if len(counts) == 1 else np.flatnonzero(sizes == n)
        # (n, faces): the i-th corners of all faces side by side, contiguous
        # (a gather by a strided index is slow), as numpy's own index type (a
        # take by int32 indices converts them first, every time)
        at = np.empty((n, len(sizes) if faces is None else len(faces)), np.intp)
        if faces is None:
            at[:] = corners.reshape(-1, n).T
        else:
            first = offsets[faces].astype(np.intp)
            for i in range(n):
                at[i] = corners.take(first + i)
        # block by block of faces: every array of a block stays in cache
        # (a third faster than whole-array passes at 60,000 pentagons)
        k = at.shape[1]
        t, u = np.empty(min(k, AREA_BLOCK)), np.empty(min(k, AREA_BLOCK))
        for lo in range(0, k, AREA_BLOCK):
            hi = min(lo + AREA_BLOCK, k)
            block = at[:, lo:hi]
            tb, ub = t[: hi - lo], u[: hi - lo]
            ax, ay, az = (np.zeros(hi - lo) for _ in range(3))
            # the coordinates of two corners at a time (no (n, faces) arrays of them)
            xi, yi, zi = start = [c.take(block[0]) for c in cols]
            for i in range(n):  # in order, corner by corner (no pairwise sums)
                xj, yj, zj = start if i + 1 == n else [c.take(block[i + 1]) for c in cols]
                terms = ((ax, yi, zj, zi, yj), (ay, zi, xj, xi, zj), (az, xi, yj, yi, xj))
                for a, pi, qj, qi, pj in terms:
                    # a += p_i q_j - q_i p_j, without temporaries
                    np.multiply(pi, qj, out=tb)
                    np.multiply(qi, pj, out=ub)
                    tb -= ub
                    a += tb
                xi, yi, zi = xj, yj, zj
            rows = slice(lo, hi) if faces is None else faces[lo:hi]
            for c, a in enumerate((ax, ay, az)):
                area[c, rows] = a
    return area


def vertex_normals(mesh: Mesh) -> NDArray[np.float32]:
    """The unit normal at every vertex: the sum of its faces' vector areas, normalised.

    What the 3D view shades with: interpolated across every face, these
    normals show a curved polygon as smooth, with no seam along the fan
    triangles it is drawn with (flat shading lights each triangle on its
    own).  Each vertex sums :func:`face_areas` of its faces in face order; a
    vertex whose sum is zero gets ``(0, 0, 1)``.  The optional compiled
    kernels (:mod:`pentanb._jit`) give the same numbers bit for bit.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (n, 3) float32
    """
    check_mesh(mesh, "vertex_normals()")
    return _vertex_normals(mesh, 1)


def _vertex_normals(mesh: Mesh, copies: int, spare: int = 0) -> NDArray[np.float32]:
    """((spare + copies) * n, 3) float32: :func:`vertex_normals` in each of the
    last ``copies`` blocks of n rows; the first ``spare`` blocks are the
    caller's to fill (left with any content).

    The buffers of a slider move are fresh memory, which costs a page fault
    per 4 KiB on first touch: the compiled kernel keeps its float64 sums in
    the bytes of the rows it returns when they are at least 2n, and the
    numpy path writes its quotients straight into them.
    """
    n = mesh.n_vertices
    rows = np.empty(((spare + copies) * n, 3), np.float32)
    jit = _jit.kernels(len(mesh.corners))
    if jit is not None:
        jit.vertex_normals(mesh.vertices, mesh.corners, mesh.offsets, rows, copies)
    else:
        _numpy_vertex_normals(mesh, rows[spare * n :], copies)
    return rows


def _numpy_vertex_normals(mesh: Mesh, out: NDArray[np.float32], copies: int) -> None:
    """Write the vertex normals into every block of n rows of ``out`` ((copies * n, 3))."""
    # every face's area once per corner, the three axes in one repeat
    weights = np.repeat(_face_areas_by_axis(mesh), mesh.face_sizes, axis=1)
    # the corners as numpy's index type once: bincount converts int32 corners
    # on every call, which took longer than its sums
    owner = mesh.corners.astype(np.intp, copy=False)
    n = mesh.n_vertices
    total = np.empty((n, 3))
    for k in range(3):
        total[:, k] = np.bincount(owner, weights=weights[k], minlength=n)
    del weights
    length = np.sqrt(
        total[:, 0] * total[:, 0] + total[:, 1] * total[:, 1] + total[:, 2] * total[:, 2]
    )
    flat = ~(length > 0)
    length[flat] = 1.0
    first = out[:n]
    # the float64 quotients rounded to float32 as they are written (as astype would)
    np.divide(total, length[:, None], out=first, casting="same_kind")
    first[flat] = (0.0, 0.0, 1.0)
    for k in range(1, copies):
        out[k * n : (k + 1) * n] = first


def boundary_segments(mesh: Mesh) -> NDArray[np.float64]:
    """The edges of a mesh's boundary, loop after loop, as segments.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (B, 2, 3) float
        Segment ``j`` runs from the tail to the head of
        ``mesh.boundary_halfedges[j]`` (B = 0 for a closed mesh).
    """
    check_mesh(mesh, "boundary_segments()")
    bh = mesh.boundary_halfedges
    v = np.asarray(mesh.vertices, dtype=np.float64)
    return np.stack([v[mesh.corners[bh]], v[mesh.head[bh]]], axis=1).reshape(-1, 2, 3)


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
    boundary : (B, 2, 3) float, optional
        The boundary's edges, drawn heavier (none: nothing drawn heavier).
    normals : (n, 3) float, optional
        The unit normal at every vertex, shaded smoothly across the faces
        (:func:`vertex_normals`); default: every face lit flat with its
        polygon's normal (:func:`polygon_normals`).
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
    boundary: NDArray[np.float64] | None = None
    normals: NDArray[np.floating] | None = None

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
    boundary: ArrayLike | None = None,
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
    boundary : (B, 2, 3) float, optional
        Segments drawn heavier; default: the mesh's boundary
        (:func:`boundary_segments`; none for a closed mesh).

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
        boundary=(
            boundary_segments(mesh)
            if boundary is None
            else np.asarray(boundary, dtype=np.float64).reshape(-1, 2, 3)
        ),
        normals=vertex_normals(mesh),
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


def _fill(out: NDArray[np.uint8], rgb: NDArray[np.uint8]) -> None:
    """Set every row of ``out`` ((k, 3)) to ``rgb``: the first row, then copies
    of the rows done, doubling (no temporary; 20x np.tile's speed)."""
    k = len(out)
    if k:
        out[0] = rgb
    done = 1
    while done < k:
        step = min(done, k - done)
        out[done : done + step] = out[:step]
        done += step


def _same_rows(rgb: NDArray[np.uint8], n: int) -> NDArray[np.uint8]:
    """``n`` rows of the bytes ``rgb`` (a writeable array)."""
    out = np.empty((n, 3), np.uint8)
    _fill(out, rgb)
    return out


def _rows(colors: ArrayLike | None, default: str, n: int, repeat: int) -> NDArray[np.uint8]:
    if colors is None:
        return _same_rows(_bytes(hex_to_rgb(default)), n * repeat)
    return np.repeat(_bytes(colors).reshape(-1, 3), repeat, axis=0)


@dataclass(frozen=True)
class Buffers:
    """The arrays WebGL draws a :class:`Drawing` from (indexed: see the module notes).

    Positions and normals are float32; colours are bytes (uint8, 0 .. 255),
    drawn as normalized attributes, a quarter of the bytes of float colours;
    indices are uint32 (one dtype always: WebGL keeps a buffer's index type).

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
    normal : (P, 3) float32
        The normal of every row: its vertex's smooth normal
        (:func:`vertex_normals`), or for a drawing without normals the unit
        normal of its face's polygon (:func:`polygon_normals`).
    boundary_position : (max(B, 1), 2, 3) float32
        The two ends of every boundary segment (one degenerate placeholder
        when there is none).
    boundary_count : int
        B.
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
    normal: NDArray[np.float32] = field(default_factory=lambda: np.zeros((1, 3), np.float32))
    boundary_position: NDArray[np.float32] = field(
        default_factory=lambda: np.zeros((1, 2, 3), np.float32)
    )
    boundary_count: int = 0

    def triangles(self) -> NDArray[np.float32]:
        """(T, 3, 3) float32: the corners of every triangle drawn."""
        return self.position[self.index].reshape(-1, 3, 3)

    def triangle_colors(self) -> NDArray[np.uint8]:
        """(T, 3, 3) uint8: the colour of every triangle's corners."""
        return self.color[self.index].reshape(-1, 3, 3)

    def triangle_normals(self) -> NDArray[np.float32]:
        """(T, 3, 3) float32: the normal at every triangle's corners."""
        return self.normal[self.index].reshape(-1, 3, 3)

    def segments(self) -> NDArray[np.float32]:
        """(S, 2, 3) float32: the ends of every segment drawn (no placeholder)."""
        return self.edge_position[self.edge_index].reshape(-1, 2, 3)[: self.edge_count]

    def boundary(self) -> NDArray[np.float32]:
        """(B, 2, 3) float32: the ends of every boundary segment drawn (no placeholder)."""
        return self.boundary_position[: self.boundary_count]


def _counting(n: int, width: int) -> NDArray[np.uint32]:
    """The index of unindexed rows: 0 .. n - 1 (a degenerate primitive on row 0 if n is 0)."""
    return np.arange(n, dtype=np.uint32) if n else np.zeros(width, np.uint32)


def _addressable(rows: int) -> None:
    """ValueError when a uint32 index cannot address ``rows`` rows."""
    if rows > 2**32:
        raise ValueError(f"{rows:,} rows are more than a WebGL index can address")


def _boundary_rows(segments: ArrayLike | None, centre: NDArray[np.float32]):
    """The boundary's (max(B, 1), 2, 3) float32 rows and B (a placeholder on ``centre``)."""
    seg = (
        np.zeros((0, 2, 3), np.float32)
        if segments is None
        else np.asarray(segments, dtype=np.float32).reshape(-1, 2, 3)
    )
    if len(seg):
        return np.ascontiguousarray(seg), len(seg)
    return np.repeat(centre.reshape(1, 1, 3), 2, axis=1).astype(np.float32), 0


def buffers(d: Drawing) -> Buffers:
    """The WebGL arrays of a drawing (see :class:`Buffers`): three rows per triangle.

    Parameters
    ----------
    d : Drawing

    Returns
    -------
    Buffers
        Every triangle's corners, colour and polygon normal on rows of its
        own; the segments, points and boundary as given.
    """
    position = np.asarray(d.vertices, dtype=np.float32)[d.triangles].reshape(-1, 3)
    color = _rows(np.asarray(d.face_colors)[d.triangle_face], "#000000", 0, 3)
    if d.normals is None:  # flat: the polygon's normal on each of its triangles' corners
        normals = polygon_normals(d.vertices, d.triangles, d.triangle_face, d.n_faces)
        normal = np.repeat(normals.astype(np.float32)[np.asarray(d.triangle_face)], 3, axis=0)
    else:  # smooth: every corner its vertex's normal
        normal = np.asarray(d.normals, dtype=np.float32)[np.asarray(d.triangles)].reshape(-1, 3)
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
    boundary, n_boundary = _boundary_rows(d.boundary, centre)
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
        normal=normal if len(position) else np.array([[0.0, 0.0, 1.0]], np.float32),
        boundary_position=boundary,
        boundary_count=n_boundary,
    )


def mesh_buffers(mesh: Mesh) -> Buffers:
    """The explorer's buffers of a mesh: what ``buffers(drawing(mesh))`` draws, indexed.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    Buffers
        The same triangles with the same colours and normals, in the same
        order (``triangles()``, ``triangle_colors()`` and
        ``triangle_normals()`` of both are equal bit for bit), the same
        segments in the same order and the same boundary; but ``position``
        is the vertices cast to float32 once per face size present (each
        copy coloured by its size, with the vertices' normals), not three
        rows per triangle.  When that would be more rows than three per
        triangle (a mesh with very many face sizes), the rows are per
        triangle corner as in :func:`buffers`.  The fan triangles and edges
        come from the mesh's connectivity caches, which the dual of a dual
        shares with the mesh it came from; with the optional compiled
        kernels (:mod:`pentanb._jit`), on a large mesh, they are written from
        the faces straight into uint32.
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
        normal = _vertex_normals(mesh, 1).take(tri.reshape(-1), axis=0)
        index = _counting(len(position), 3)
    else:
        # the normals first: with one copy, they share a block with the
        # vertices (the kernel's sums are kept in its bytes meanwhile)
        if copies == 1:
            rows = _vertex_normals(mesh, 1, spare=1)
            position, normal = rows[:n], rows[n:]
        else:
            normal = _vertex_normals(mesh, copies)
            position = np.empty((copies * n, 3), np.float32)
        # the vertices cast to float32 straight into every copy (the first
        # copy is also the edges' array): the view's arrays, writeable
        position.reshape(copies, n, 3)[:] = mesh.vertices  # (broadcast: every copy)
        v = position[:n]
        color = np.empty((copies * n, 3), np.uint8)
        for k, p in enumerate(present):
            _fill(color[k * n : (k + 1) * n], table[p])
        _addressable(len(position))
        slot = np.zeros(high - low + 1, np.int64)
        slot[present] = np.arange(copies) * n
        if jit is not None:  # (a k-gon's rows are shifted by slot[k - low])
            index = jit.fan_index(mesh.corners, mesh.offsets, slot if copies > 1 else slot[:0], low)
        else:
            tri, tri_face = mesh.fan_triangles()
            index = tri.astype(np.uint32)  # (a copy: the mesh's cache stays as it is)
            if copies > 1:  # (addressable: no sum wraps around)
                index += slot.astype(np.uint32)[sizes[tri_face] - low][:, None]
            index = index.reshape(-1)
    if jit is not None:
        edge_index = jit.edge_index(mesh.corners, mesh.offsets)
    else:
        edge_index = mesh.edges.astype(np.uint32).reshape(-1)
    boundary, n_boundary = _boundary_rows(
        boundary_segments(mesh) if not mesh.is_closed else None, v[:1]
    )
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
        normal=normal,
        boundary_position=boundary,
        boundary_count=n_boundary,
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
        boundary=None if obj.boundary is None else in_frame(obj.boundary, frame),
    )
