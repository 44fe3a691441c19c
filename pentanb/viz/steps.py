"""A classroom step-through of the paper's schemes (Section 5), driven by a slider.

Each stage is a :class:`pentanb.viz.three.Drawing` built from the input
mesh's arrays in a few whole-array expressions: the pieces of the result
(one pentagon per half-edge, and for pentagon preservation the inner copy of
every face) are drawn from the start, coloured like the face they lie in
until the edges that close them have been inserted; new points are marked;
the inserted edges appear one group at a time (group ``j``: the edges of
every face's ``j``-th corner) in red.  The last stages are the scheme's
result and its duals, built by the package's own operators.
"""

from __future__ import annotations

import ipywidgets as W
import numpy as np

from ..mesh import Mesh
from .colors import _hex_to_rgb, face_rgb
from .three import Drawing, MeshView, _histogram, slider_stack

__all__ = ["stages", "StepThrough", "step_through"]

#: Colour of the edges inserted at the current step.
NEW_EDGE_COLOR = "#c00000"
#: Colours of new points: points on edges, then points inside faces.
EDGE_POINT_COLOR = "#000000"
FACE_POINT_COLOR = "#c00000"


def _input_caption(mesh: Mesh) -> str:
    return (
        f"The input mesh: {mesh.n_vertices} vertices, {mesh.n_edges} edges, {mesh.n_faces} faces."
    )


def _halfedges(mesh: Mesh):
    """Per half-edge: face, position in face, next half-edge, tail and head positions."""
    sizes = np.asarray(mesh.face_sizes, dtype=np.int64)
    off = np.asarray(mesh.offsets, dtype=np.int64)
    corners = np.asarray(mesh.corners, dtype=np.int64)
    hf = np.repeat(np.arange(sizes.size, dtype=np.int64), sizes)
    h = np.arange(corners.size, dtype=np.int64)
    j = h - off[:-1][hf]
    nxt = np.where(j == sizes[hf] - 1, off[:-1][hf], h + 1)
    v = np.asarray(mesh.vertices, dtype=np.float64)
    u, w = v[corners], v[corners[nxt]]
    once = corners < corners[nxt]  # each undirected edge once
    return hf, j, nxt, u, w, once


def _lighten(rgb, amount=0.55):
    return rgb + (1.0 - rgb) * amount


def _pieces(parts):
    """CSR positions of polygons given as (k, n, 3) blocks (n may differ per block)."""
    positions = np.concatenate([p.reshape(-1, 3) for p in parts])
    sizes = np.concatenate([np.full(len(p), p.shape[1], dtype=np.int64) for p in parts])
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    return positions, offsets, sizes


def _draw(
    positions, offsets, colors, segments, seg_colors, points, point_colors, legend
) -> Drawing:
    return Drawing(
        positions=positions,
        offsets=offsets,
        face_colors=colors,
        segments=segments,
        segment_colors=seg_colors,
        points=points,
        point_colors=point_colors,
        legend=legend,
    )


def stages(
    mesh: Mesh, scheme: str = "pentagonalize", *, duals: int = 2, scale: float | None = None
) -> list[tuple[str, object]]:
    """The stages of one application of a scheme, as (caption, Drawing or Mesh).

    ``"pentagonalize"`` (Section 5.1) and ``"preserve_pentagons"``
    (Section 5.2) are shown step by step; any other scheme of
    :data:`pentanb.SCHEMES` as input, result and duals.
    """
    from ..schemes import SCHEMES, dual

    if scheme not in SCHEMES:
        raise ValueError(f"unknown scheme {scheme!r}; known schemes: {', '.join(SCHEMES)}")
    s = SCHEMES[scheme]
    opts = {}
    if "scale" in s.options:
        opts["scale"] = s.options["scale"] if scale is None else float(scale)
    if scheme == "pentagonalize":
        out = _pentagonalize_stages(mesh)
    elif scheme == "preserve_pentagons":
        out = _preservation_stages(mesh, opts["scale"])
    else:
        out = [(_input_caption(mesh), mesh)]
    result = s(mesh, **opts)
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
            (f"Dual pass {k + 1}: {what} (Section 5: apply the dual an even number of times).", m)
        )
    return out


def _pentagonalize_stages(mesh: Mesh):
    hf, j, nxt, u, w, once = _halfedges(mesh)
    sizes = np.asarray(mesh.face_sizes)
    t1 = u + (w - u) / 3
    t2 = u + 2 * (w - u) / 3
    centre = np.add.reduceat(u, np.asarray(mesh.offsets[:-1]), axis=0) / sizes[:, None]
    c = centre[hf]
    # the pentagon of half-edge h = (u, w): t1, t2, w, t1 of next, centre
    positions, offsets, _ = _pieces([np.stack([t1, t2, w, t1[nxt], c], axis=1)])
    parent = face_rgb(sizes)[hf]
    old_edges = np.stack([u[once], w[once]], axis=1)
    black = np.zeros((len(old_edges), 3))
    edge_pts = np.concatenate([t1[once], t2[once]])
    face_pts = centre
    ep_col = np.tile(_hex_to_rgb(EDGE_POINT_COLOR), (len(edge_pts), 1))
    fp_col = np.tile(_hex_to_rgb(FACE_POINT_COLOR), (len(face_pts), 1))
    legend0 = _histogram(sizes)
    out = [
        (
            _input_caption(mesh),
            _draw(positions, offsets, parent, old_edges, black, None, None, legend0),
        ),
        (
            f"Step 1: every edge is cut into three equal parts: {2 * mesh.n_edges} new "
            "points (black).",
            _draw(positions, offsets, parent, old_edges, black, edge_pts, ep_col, legend0),
        ),
        (
            "Step 2a: a point sphere at the centroid of every face (red).",
            _draw(
                positions,
                offsets,
                parent,
                old_edges,
                black,
                np.concatenate([edge_pts, face_pts]),
                np.concatenate([ep_col, fp_col]),
                legend0,
            ),
        ),
    ]
    spoke = np.stack([c, t1], axis=1)  # inserted edge of half-edge h
    jn = j[nxt]
    n_groups = int(sizes.max())
    for g in range(n_groups):
        done = np.maximum(j, jn) <= g  # both edges closing pentagon h are in
        colors = np.where(done[:, None], face_rgb(np.full(len(j), 5)), _lighten(parent))
        inserted = j <= g
        segs = np.concatenate([old_edges, spoke[inserted]])
        seg_col = np.concatenate(
            [black, np.where((j[inserted] == g)[:, None], _hex_to_rgb(NEW_EDGE_COLOR), 0.0)]
        )
        legend = _histogram(sizes[np.unique(hf[~done])])  # faces not yet split
        if done.any():
            legend[5] = legend.get(5, 0) + int(done.sum())
        out.append(
            (
                f"Step 2b, group {g + 1} of {n_groups}: an edge from each point "
                f"sphere to the first trisection point after corner {g + 1} of its "
                "face (every third corner of the subdivided face); a pentagon is "
                "closed when both its edges are in.",
                _draw(
                    positions,
                    offsets,
                    colors,
                    segs,
                    seg_col,
                    np.concatenate([edge_pts, face_pts]),
                    np.concatenate([ep_col, fp_col]),
                    legend,
                ),
            )
        )
    return out


def _preservation_stages(mesh: Mesh, scale: float):
    hf, j, nxt, u, w, once = _halfedges(mesh)
    sizes = np.asarray(mesh.face_sizes)
    off = np.asarray(mesh.offsets)
    mid = (u + w) / 2
    centre = np.add.reduceat(mid, off[:-1], axis=0) / sizes[:, None]
    q = centre[hf] + scale * (mid - centre[hf])
    # inner copies (corners q, CSR like the input) then one pentagon per half-edge
    pent = np.stack([mid, w, mid[nxt], q[nxt], q], axis=1)
    positions = np.concatenate([q, pent.reshape(-1, 3)])
    offsets = np.concatenate([off, off[-1] + 5 * np.arange(1, len(j) + 1)])
    parent_face = face_rgb(sizes)
    parent = np.concatenate([parent_face, parent_face[hf]])
    old_edges = np.stack([u[once], w[once]], axis=1)
    black = np.zeros((len(old_edges), 3))
    copy_edges = np.stack([q, q[nxt]], axis=1)
    mids = mid[once]
    mp_col = np.tile(_hex_to_rgb(EDGE_POINT_COLOR), (len(mids), 1))
    q_col = np.tile(_hex_to_rgb(FACE_POINT_COLOR), (len(q), 1))
    legend0 = _histogram(sizes)
    ring = np.concatenate([parent_face, _lighten(parent_face[hf])])
    out = [
        (
            _input_caption(mesh),
            _draw(positions, offsets, parent, old_edges, black, None, None, legend0),
        ),
        (
            f"Step 1: every edge is cut at its midpoint: {mesh.n_edges} new points (black).",
            _draw(positions, offsets, parent, old_edges, black, mids, mp_col, legend0),
        ),
        (
            f"Step 2: in every face the midpoints are scaled by {scale:g} about their "
            "centroid: a smaller copy of the face, with as many sides.",
            _draw(
                positions,
                offsets,
                ring,
                np.concatenate([old_edges, copy_edges]),
                np.concatenate([black, np.tile(_hex_to_rgb(NEW_EDGE_COLOR), (len(copy_edges), 1))]),
                np.concatenate([mids, q]),
                np.concatenate([mp_col, q_col]),
                legend0,
            ),
        ),
    ]
    spoke = np.stack([q, mid], axis=1)
    jn = j[nxt]
    n_groups = int(sizes.max())
    for g in range(n_groups):
        done = np.maximum(j, jn) <= g
        colors = np.concatenate(
            [
                parent_face,
                np.where(done[:, None], face_rgb(np.full(len(j), 5)), _lighten(parent_face[hf])),
            ]
        )
        inserted = j <= g
        segs = np.concatenate([old_edges, copy_edges, spoke[inserted]])
        seg_col = np.concatenate(
            [
                black,
                np.zeros((len(copy_edges), 3)),
                np.where((j[inserted] == g)[:, None], _hex_to_rgb(NEW_EDGE_COLOR), 0.0),
            ]
        )
        legend = _histogram(sizes)
        if done.any():
            legend[5] = legend.get(5, 0) + int(done.sum())
        out.append(
            (
                f"Step 3, group {g + 1} of {n_groups}: an edge from corner {g + 1} "
                "of every copy to its midpoint; a pentagon is closed when both its "
                "edges are in.",
                _draw(
                    positions,
                    offsets,
                    colors,
                    segs,
                    seg_col,
                    np.concatenate([mids, q]),
                    np.concatenate([mp_col, q_col]),
                    legend,
                ),
            )
        )
    return out


class StepThrough(W.VBox):
    """A step slider, a caption and one :class:`MeshView` (updated in place).

    Attributes
    ----------
    step : ipywidgets.IntSlider
    caption : ipywidgets.HTML
    view : MeshView
    stages : list of (caption, Drawing or Mesh)
    """

    def __init__(
        self,
        mesh: Mesh,
        scheme: str = "pentagonalize",
        *,
        duals: int = 2,
        scale: float | None = None,
        width: int = 600,
        height: int = 450,
    ):
        self.scheme = scheme
        self.stages = stages(mesh, scheme, duals=duals, scale=scale)
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
        return f"<b>{k}/{len(self.stages) - 1}</b> &nbsp; {self.stages[k][0]}"

    def _on_step(self, change) -> None:
        k = change["new"]
        self.caption.value = self._caption(k)
        self.view.update(self.stages[k][1])

    def static_copy(self) -> W.Widget:
        """A kernel-free copy (one view per stage, slider linked in the browser)."""
        from ..schemes import SCHEMES

        return slider_stack(
            [d for _, d in self.stages],
            [self._caption(k) for k in range(len(self.stages))],
            self.view,
            description="step",
            title=f"<b>{SCHEMES[self.scheme].label}</b>, step by step",
            value=self.step.value,
        )


def step_through(
    mesh: Mesh,
    scheme: str = "pentagonalize",
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
    scheme : str
        A name from :data:`pentanb.SCHEMES`.
    duals : int
        Dual passes shown after the result.
    scale : float, optional
        The scale of ``preserve_pentagons`` (and other schemes with one).
    width, height : int

    Returns
    -------
    StepThrough
    """
    return StepThrough(mesh, scheme, duals=duals, scale=scale, width=width, height=height)
