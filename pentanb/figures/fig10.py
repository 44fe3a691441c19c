"""Figure 10: the pentagon preserving scheme on one face, drawn flat.

(A) a pentagon, the polygon of its edge midpoints scaled by 0.75 (this
package's default; the paper asks only for a factor below 1) and the edges
to insert; (B) five pentagons around a smaller pentagon.  Computed by
:func:`pentanb.preserve_pentagons` on a flat two-faced "pillow" (built
here, privately: the :class:`~pentanb.Mesh` constructor refuses its
2-valent vertices); only what became of the front face is drawn.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from ..mesh import Mesh
from ..schemes.pentagonal import preserve_pentagons
from ._flat import pillow
from .claim import FAILS, HOLDS, Claim, bounded, exact, fmt, judged

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagon preserving scheme"
CAPTION = "Pentagon preserving scheme. (A) is the initial mesh and (B) the resulting mesh."
LABELS = ("A", "B")

#: The scale of the midpoints' polygon drawn in Figure 10.
SCALE = 0.75


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 10: ``{"A": flat pentagon pillow, "B": pentagon preservation}``.

    (A) has two faces, the pentagon (face 0) and its back; in (B), face 0 is
    the front face's scaled copy and face ``F + h`` the pentagon of
    half-edge ``h``.  Neither is a mesh the constructor accepts: the
    pentagon's corners stay 2-valent in both.  They are the figure's
    teaching meshes.
    """
    a = pillow(5)
    return {"A": a, "B": preserve_pentagons(a, scale=SCALE)}


def _front(src: Mesh) -> np.ndarray:
    """Faces of the output that fill face 0 of ``src``: its inner copy, then one per half-edge."""
    return np.concatenate([[0], src.n_faces + np.arange(src.face_sizes[0])])


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 10: pentagon preservation of one polygon (a pentagon), drawn flat.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
    """
    from ..viz import mpl as vz
    from ..viz.colors import EDGE_COLOR
    from ._draw import NEW, OLD, flat_figure, flat_legend, flat_points

    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    front = _front(src)
    n = src.n_vertices
    pts = out.vertices
    mids = pts[n : n + src.n_edges]
    inner = pts[out.faces[0]]
    with vz.style():
        fig, (a, b) = flat_figure("Figure 10. Pentagon preserving scheme on one face")
        vz.draw_flat(a, src, np.array([0]))
        c = mids.mean(axis=0)
        vz.draw_segments(
            a,
            np.stack([np.repeat(c[None], n, 0), mids], 1)[:, :, :2],
            colors="#777777",
            linewidths=0.8,
            linestyles=(0, (1, 2)),
        )
        ring = np.concatenate([inner, inner[:1]])
        a.plot(ring[:, 0], ring[:, 1], color=EDGE_COLOR, lw=1.1, ls=(0, (3, 2.5)), zorder=3)
        # the edges from the scaled face to the midpoints
        q = out.corners.reshape(-1)[out.offsets[front[1]] : out.offsets[front[-1] + 1]]
        pent = q.reshape(-1, 5)  # (m_h, w, m_next, q_next, q_h)
        vz.draw_segments(
            a,
            np.stack([pts[pent[:, 0]], pts[pent[:, 4]]], 1)[:, :, :2],
            colors=EDGE_COLOR,
            linewidths=1.1,
            linestyles=(0, (3, 2.5)),
        )
        flat_points(a, pts[:n], **OLD)
        flat_points(a, mids, **NEW)
        flat_points(a, inner, **NEW)
        vz.label_panel(
            a, f"(A) the midpoints' polygon scaled\nby {SCALE}; dashed: the edges to insert"
        )
        vz.draw_flat(b, out, front)
        flat_points(b, pts[:n], **OLD)
        flat_points(b, mids, **NEW)
        flat_points(b, inner, **NEW)
        vz.label_panel(b, f"(B) {n} pentagons around a smaller pentagon")
        flat_legend(fig, [5])
    return fig


def _by_position(points: np.ndarray, out: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """The vertex of ``out`` nearest to every point, and the distance to it."""
    d = np.linalg.norm(points[:, None, :] - out.vertices[None, :, :], axis=2)
    j = d.argmin(axis=1)
    return j, d[np.arange(len(points)), j]


def _face_at(points: np.ndarray, out: Mesh, normal: np.ndarray) -> int | None:
    """The face of ``out`` whose corners are at ``points`` (to rounding, any order) and
    whose normal turns the way ``normal`` does; None if there is none.  (The pillow's
    front and back faces have their central copies at the same points: the normal tells
    them apart.)"""
    for f in np.flatnonzero(out.face_sizes == len(points)):
        q = out.vertices[out.faces[f]]
        d = np.linalg.norm(q[:, None, :] - points[None, :, :], axis=2)
        if d.min(axis=0).max() <= 1e-9 and d.min(axis=1).max() <= 1e-9:
            if float(out.face_normals[f] @ normal) > 0:
                return int(f)
    return None


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 10, measured on :func:`panels`.

    The points of the construction are computed from (A)'s positions alone
    (the midpoints of its edges, their polygon scaled by :data:`SCALE`) and
    looked for among (B)'s vertices and faces by position: nothing is read
    from the operator's numbering of its output.
    """
    p = panels() if meshes is None else meshes
    src, out = p["A"], p["B"]
    n = int(src.face_sizes[0])
    v = src.vertices
    edges = {frozenset(map(int, e)) for e in out.edges}

    # step 1: every edge of (A) cut at its midpoint, both halves edges of (B)
    ends = src.edges
    old, old_d = _by_position(v, out)
    mid, mid_d = _by_position((v[ends[:, 0]] + v[ends[:, 1]]) / 2, out)
    halves = sum(
        {int(old[a]), int(m)} in edges and {int(old[b]), int(m)} in edges
        for (a, b), m in zip(ends, mid)
    )
    step1 = float(max(mid_d.max(), old_d.max()))

    # step 2: the front face's midpoints, in order, scaled about their centroid
    ring = src.corners[src.offsets[0] : src.offsets[1]]
    mids = (v[ring] + v[np.roll(ring, -1)]) / 2
    c = mids.mean(axis=0)
    target = c + SCALE * (mids - c)
    face = _face_at(target, out, src.face_normals[0])
    _, near = _by_position(target, out)
    scaled = float(near.max()) if face is not None else float("inf")
    where = "a face of (B), turned as (A)" if face is not None else "no face of (B) there"
    # step 3: every corner of that face joined to the midpoint it was scaled from
    mids_at, _ = _by_position(mids, out)
    joined, by_size = 0, {}
    if face is not None:
        ring_out = out.faces[face]
        d = np.linalg.norm(target[:, None, :] - out.vertices[ring_out][None, :, :], axis=2)
        corners = ring_out[d.argmin(axis=1)]  # the central face's corner at every target
        joined = sum({int(q), int(m)} in edges for q, m in zip(corners, mids_at))
        # the faces that fill the front face: the central one and those sharing its edges
        hs = np.arange(out.offsets[face], out.offsets[face + 1])
        around = out.halfedge_face[out.twin[hs]]
        sizes = out.face_sizes[np.concatenate([[face], around])]
        by_size = {int(k): int(x) for k, x in zip(*np.unique(sizes, return_counts=True))}
    return [
        judged(
            "fig10.midpoints",
            "Section 5.2, step 1",
            "Subdivide all edges in the mesh into 2 equal parts. Let the set of newly created "
            "points be Vs.",
            f"largest distance of the midpoint of an edge of (A) (from (A)'s positions) or of "
            f"a vertex of (A) from the nearest vertex of (B) = {fmt(step1)}; edges of (A) whose "
            f"two halves are edges of (B) (vertices found by position): {halves} of "
            f"{src.n_edges}",
            "holds if the distance is <= 1e-09 (rounding) and every edge is cut in two there",
            HOLDS if step1 <= 1e-9 and halves == src.n_edges else FAILS,
            reading="every edge of the input gets a new vertex at its midpoint and becomes two "
            "edges of the output; the old vertices stay where they are",
            cause="pentagon preservation's positions",
        ),
        exact(
            "fig10.pentagons",
            "Section 5.2, Figure 10",
            "Each face in the original mesh would now have been split into as many pentagons "
            "as the number of edges (or vertices) in the original face plus one central face "
            "with the same number of sides as the original face.",
            f"the central face of (B) in the {n}-gon of (A) and the faces on its edges, by size",
            {n: 1, 5: n} if n != 5 else {5: n + 1},
            by_size,
            reading=f"the {n}-gon of (A) becomes a central {n}-gon with {n} pentagons around it",
            cause="pentagon preservation's combinatorics",
        ),
        bounded(
            "fig10.scaled",
            "Section 5.2, Figure 10",
            "Scale the points in Pi around their centroid by a specified amount. The scale "
            "factor should be less than 1.",
            f"largest distance of the midpoints of the edges of (A)'s {n}-gon (from (A)'s "
            f"positions) scaled by {SCALE} (this package's default) about their centroid from "
            f"the nearest vertices of (B) ({where})",
            scaled,
            reading="the central face's corners are the input face's edge midpoints, scaled "
            "about their centroid by the factor (below 1)",
            cause="pentagon preservation's positions",
        ),
        exact(
            "fig10.joined",
            "Section 5.2, Figure 10",
            "For each vertex vi,j in fi, insert an edge between vi,j and the point in Vs "
            "corresponding to vi,j.",
            "corners of the central face joined by an edge of (B) to the midpoint they were "
            "scaled from (both found by position)",
            n,
            joined,
            reading="every corner of the central face is joined to the midpoint it comes from",
            cause="pentagon preservation's combinatorics",
        ),
    ]
