"""The stages of one step of the paper's schemes (Section 5), as drawings.

Needs numpy only; :func:`pentanb.viz.steps.step_through` puts the stages
behind a slider.

Each stage is a :class:`~pentanb.viz.drawing.Drawing` of the scheme's
*result*, before any dual: its faces are the pieces the input is cut into,
drawn from the first stage on, coloured like the input face they lie in
until the edges that close them have been inserted.  The operators document
their output's numbering (:func:`pentanb.pentagonalize`: face ``h`` is the
pentagon of half-edge ``h``, new vertices after the old ones;
:func:`pentanb.preserve_pentagons`: the inner copies first, then one pentagon
per half-edge), so every stage is a few whole-array expressions on the input
and the result: the input's edges in black, the new points, and the
inserted edges one group at a time (group ``j``: the edges of every face's
``j``-th corner) in red.  The last stages are the result and its duals.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from .. import _checks
from ..mesh import Mesh
from ..schemes.registry import Scheme
from ..schemes.smoothing import dual
from ..subdivision import get_scheme
from .colors import face_rgb, hex_to_rgb
from .drawing import Drawing, drawing, size_histogram

__all__ = [
    "NEW_EDGE_COLOR",
    "EDGE_POINT_COLOR",
    "FACE_POINT_COLOR",
    "MAX_DUALS",
    "stages",
    "check_stage_arguments",
]

#: Colour of the edges inserted at the current step.
NEW_EDGE_COLOR = "#c00000"
#: Colours of new points: points on edges, then points inside faces.
EDGE_POINT_COLOR = "#000000"
FACE_POINT_COLOR = "#c00000"
#: Most duals a step-through shows (each is one more stage).
MAX_DUALS = 12

Stage = tuple[str, Drawing | Mesh]


def check_stage_arguments(
    mesh: object, scheme: object, duals: object, options: dict
) -> tuple[Scheme, int, dict]:
    """The checked arguments of :func:`stages`: (scheme, duals, options).

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh, ``scheme`` not a name or Scheme of
        :data:`pentanb.SCHEMES`, or ``duals`` not an integer.
    ValueError
        An unknown scheme (the message lists the known ones), ``duals``
        outside 0 .. :data:`MAX_DUALS`, or an option the scheme does not take.
    """
    if not isinstance(mesh, Mesh):
        raise TypeError(
            f"mesh must be a pentanb.Mesh, got {type(mesh).__name__}"
            + (
                " (for a shape by name, use pentanb.shapes.get(name))"
                if isinstance(mesh, str)
                else ""
            )
        )
    s = get_scheme(scheme)  # type: ignore[arg-type]
    if not isinstance(s, Scheme):
        raise TypeError("scheme must be the name of a scheme of pentanb.SCHEMES, not a function")
    duals = _checks.count(duals, "duals", 0, MAX_DUALS)
    given = {k: v for k, v in options.items() if v is not None}
    unknown = sorted(set(given) - set(s.options))
    if unknown:
        takes = ", ".join(s.options) or "no options"
        raise ValueError(f"scheme {s.name!r} takes {takes}; got {', '.join(unknown)}")
    opts = {**s.options, **given}
    return s, int(duals), opts


def stages(
    mesh: Mesh,
    scheme: str | Scheme = "pentagonalize",
    *,
    duals: int = 2,
    scale: float | None = None,
) -> list[Stage]:
    """The stages of one application of a scheme, as (caption, Drawing or Mesh).

    ``"pentagonalize"`` (Section 5.1) and ``"preserve_pentagons"``
    (Section 5.2) are shown step by step; any other scheme of
    :data:`pentanb.SCHEMES` as input, result and duals.

    Parameters
    ----------
    mesh : Mesh
    scheme : str or Scheme
        A scheme of :data:`pentanb.SCHEMES`.
    duals : int in [0, :data:`MAX_DUALS`]
        Duals shown after the result.
    scale : float, optional
        The ``scale`` option, for schemes that take one (default: the
        scheme's); refused for schemes without it.

    Returns
    -------
    list of (str, Drawing or Mesh)

    Raises
    ------
    TypeError, ValueError
        See :func:`check_stage_arguments`.
    """
    s, duals, opts = check_stage_arguments(mesh, scheme, duals, {"scale": scale})
    result = s(mesh, **opts)
    if s.name == "pentagonalize":
        out = _pentagonalize_stages(mesh, result)
    elif s.name == "preserve_pentagons":
        out = _preservation_stages(mesh, result, opts["scale"])
    else:
        out = [(_input_caption(mesh), mesh)]
    out.append(
        (
            f"{s.label}: the remeshed mesh, {result.n_vertices} vertices, "
            f"{result.n_edges} edges, {result.n_faces} faces ({s.paper}).",
            result,
        )
    )
    m = result
    for k in range(duals):
        m = dual(m)
        what = "the dual" if k == 0 else "the dual of the dual" if k == 1 else f"dual {k + 1}"
        out.append(
            (f"Dual {k + 1}: {what} (Section 5: apply the dual an even number of times).", m)
        )
    return out


def _input_caption(mesh: Mesh) -> str:
    return (
        f"The input mesh: {mesh.n_vertices} vertices, {mesh.n_edges} edges, {mesh.n_faces} faces."
    )


def _lighten(rgb: NDArray, amount: float = 0.55) -> NDArray:
    return rgb + (1.0 - rgb) * amount


def _tile(color: str, n: int) -> NDArray:
    return np.tile(hex_to_rgb(color), (n, 1))


class _Halfedges:
    """Per half-edge of the input: its face, its place in the face, the next one."""

    def __init__(self, mesh: Mesh):
        self.face = mesh.halfedge_face
        self.index = np.arange(mesh.n_halfedges) - mesh.offsets[:-1][self.face]
        self.next = mesh.next
        self.sizes = mesh.face_sizes
        self.groups = int(self.sizes.max())


def _grouped(
    mesh: Mesh,
    result: Mesh,
    before: Sequence[Stage],
    colors: Callable[[NDArray[np.bool_]], NDArray],
    segments: Callable[[NDArray[np.bool_], NDArray[np.bool_]], tuple[NDArray, NDArray]],
    legend: Callable[[NDArray[np.bool_]], dict[int, int]],
    points: tuple[NDArray, NDArray],
    caption: Callable[[int, int], str],
) -> list[Stage]:
    """``before``, then one stage per group of inserted edges."""
    he = _Halfedges(mesh)
    out = list(before)
    for g in range(he.groups):
        done = np.maximum(he.index, he.index[he.next]) <= g  # both closing edges are in
        segs, seg_colors = segments(he.index <= g, he.index[he.index <= g] == g)
        out.append(
            (
                caption(g, he.groups),
                drawing(
                    result,
                    face_colors=colors(done),
                    segments=segs,
                    segment_colors=seg_colors,
                    points=points[0],
                    point_colors=points[1],
                    legend=legend(done),
                    show_counts=False,
                ),
            )
        )
    return out


def _pentagonalize_stages(mesh: Mesh, result: Mesh) -> list[Stage]:
    """Figure 6 on every face: trisection points, point spheres, spokes by group."""
    he = _Halfedges(mesh)
    V, E = mesh.n_vertices, mesh.n_edges
    pent = result.corners.reshape(-1, 5)  # pentagon h: t1, t2, w, t1 of next, centre
    rv = result.vertices
    parent = face_rgb(he.sizes)[he.face]
    old_edges = mesh.vertices[mesh.edges]
    black = np.zeros((len(old_edges), 3))
    edge_pts = rv[V : V + 2 * E]
    all_pts = rv[V:]
    all_col = np.concatenate(
        [_tile(EDGE_POINT_COLOR, len(edge_pts)), _tile(FACE_POINT_COLOR, mesh.n_faces)]
    )
    spoke = rv[pent[:, [4, 0]]]  # the inserted edge of half-edge h: centre to t1
    legend0 = size_histogram(he.sizes)

    def still(points=None, colors=None) -> Drawing:
        return drawing(
            result,
            face_colors=parent,
            segments=old_edges,
            segment_colors=black,
            points=points,
            point_colors=colors,
            legend=legend0,
            show_counts=False,
        )

    def colors(done):
        return np.where(done[:, None], face_rgb(np.full(len(done), 5)), _lighten(parent))

    def segments(inserted, newest):
        return (
            np.concatenate([old_edges, spoke[inserted]]),
            np.concatenate([black, np.where(newest[:, None], hex_to_rgb(NEW_EDGE_COLOR), 0.0)]),
        )

    def legend(done):
        counts = size_histogram(he.sizes[np.unique(he.face[~done])])  # faces not yet split
        if done.any():
            counts[5] = counts.get(5, 0) + int(done.sum())
        return counts

    before = [
        (_input_caption(mesh), still()),
        (
            f"Step 1: every edge is cut into three equal parts: {2 * E} new points (black).",
            still(edge_pts, _tile(EDGE_POINT_COLOR, len(edge_pts))),
        ),
        ("Step 2a: a point sphere at the centroid of every face (red).", still(all_pts, all_col)),
    ]
    return _grouped(
        mesh,
        result,
        before,
        colors,
        segments,
        legend,
        (all_pts, all_col),
        lambda g, n: (
            f"Step 2b, group {g + 1} of {n}: an edge from each point sphere to the first "
            f"trisection point after corner {g + 1} of its face (every third corner of the "
            "subdivided face); a pentagon is closed when both its edges are in."
        ),
    )


def _preservation_stages(mesh: Mesh, result: Mesh, scale: float) -> list[Stage]:
    """Figure 10 on every face: midpoints, the scaled inner copies, spokes by group."""
    he = _Halfedges(mesh)
    V, E, H = mesh.n_vertices, mesh.n_edges, mesh.n_halfedges
    rv = result.vertices
    pent = result.corners[H:].reshape(-1, 5)  # pentagon h: m_h, w, m_next, q_next, q_h
    parent_face = face_rgb(he.sizes)
    parent = np.concatenate([parent_face, parent_face[he.face]])
    ring = np.concatenate([parent_face, _lighten(parent_face[he.face])])
    old_edges = mesh.vertices[mesh.edges]
    black = np.zeros((len(old_edges), 3))
    q = rv[V + E :]  # the inner copies' corners, one per half-edge
    copy_edges = np.stack([q, q[he.next]], axis=1)
    red = _tile(NEW_EDGE_COLOR, H)
    mids = rv[V : V + E]
    all_pts = rv[V:]
    all_col = np.concatenate([_tile(EDGE_POINT_COLOR, E), _tile(FACE_POINT_COLOR, H)])
    spoke = rv[pent[:, [4, 0]]]  # the inserted edge of half-edge h: q_h to m_h
    legend0 = size_histogram(he.sizes)

    def colors(done):
        pentagon = face_rgb(np.full(H, 5))
        return np.concatenate(
            [parent_face, np.where(done[:, None], pentagon, _lighten(parent_face[he.face]))]
        )

    def segments(inserted, newest):
        return (
            np.concatenate([old_edges, copy_edges, spoke[inserted]]),
            np.concatenate(
                [
                    black,
                    np.zeros((H, 3)),
                    np.where(newest[:, None], hex_to_rgb(NEW_EDGE_COLOR), 0.0),
                ]
            ),
        )

    def legend(done):
        counts = dict(legend0)
        if done.any():
            counts[5] = counts.get(5, 0) + int(done.sum())
        return counts

    def stage(face_colors, segs, seg_colors, points=None, colors=None) -> Drawing:
        return drawing(
            result,
            face_colors=face_colors,
            segments=segs,
            segment_colors=seg_colors,
            points=points,
            point_colors=colors,
            legend=legend0,
            show_counts=False,
        )

    before = [
        (_input_caption(mesh), stage(parent, old_edges, black)),
        (
            f"Step 1: every edge is cut at its midpoint: {E} new points (black).",
            stage(parent, old_edges, black, mids, _tile(EDGE_POINT_COLOR, E)),
        ),
        (
            f"Step 2: in every face the midpoints are scaled by {scale:g} about their "
            "centroid: a smaller copy of the face, with as many sides.",
            stage(
                ring,
                np.concatenate([old_edges, copy_edges]),
                np.concatenate([black, red]),
                all_pts,
                all_col,
            ),
        ),
    ]
    return _grouped(
        mesh,
        result,
        before,
        colors,
        segments,
        legend,
        (all_pts, all_col),
        lambda g, n: (
            f"Step 3, group {g + 1} of {n}: an edge from corner {g + 1} of every copy to "
            "its midpoint; a pentagon is closed when both its edges are in."
        ),
    )
