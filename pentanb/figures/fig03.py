"""Figure 3: a triangle preserving remeshing, Loop's.

(A) a mixed mesh (:func:`capped_prism`: a pentagon, five quads and five
triangles), (B) Loop's remeshing of it (:func:`pentanb.loop_remesh`): a
central face of the same size in every face and a triangle at every corner.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from .. import shapes
from ..mesh import Mesh
from ..schemes.classic import loop_remesh
from .claim import Claim, add_counts, bounded, counts_claim, exact

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Loop's remeshing"
CAPTION = (
    "A triangle preserving remeshing: The remeshing scheme of Loop subdivision. (A) "
    "is the initial mesh and (B) the resulting mesh."
)
LABELS = ("A", "B")


def capped_prism() -> Mesh:
    """A house-like pentagonal prism with a pyramid at its back.

    A pentagon, five quads and five triangles: the mixed mesh of Figure 3
    and of :func:`pentanb.figures.scheme_claims`.

    Returns
    -------
    Mesh
        11 vertices, 11 faces, genus 0.
    """
    t = 2 * np.pi * np.arange(5) / 5 + np.pi / 2
    ring = np.stack([np.cos(t), np.sin(t)], axis=1)  # in the x-z plane
    front = np.column_stack([ring[:, 0], np.full(5, -1.0), ring[:, 1]])
    back = np.column_stack([ring[:, 0], np.full(5, 0.5), ring[:, 1]])
    v = np.concatenate([front, back, [[0.0, 1.7, 0.0]]])
    faces = [[0, 1, 2, 3, 4]]
    faces += [[i, 5 + i, 5 + (i + 1) % 5, (i + 1) % 5] for i in range(5)]
    faces += [[5 + (i + 1) % 5, 5 + i, 10] for i in range(5)]
    return shapes.outward(v, faces)


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 3: ``{"A": capped prism, "B": its Loop remeshing}``."""
    a = capped_prism()
    return {"A": a, "B": loop_remesh(a)}


_VIEW = {"elev": 24.0, "azim": -30.0}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 3: Loop's remeshing applied to a mesh with a pentagon, quads and triangles.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.

    Returns
    -------
    matplotlib.figure.Figure
        The figure, its panels labelled ``(A)``, ``(B)``, ... as in the paper.
    """
    from ._draw import mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "initial mesh", _VIEW),
            (p["B"], "Loop's remeshing", _VIEW),
        ],
        suptitle="Figure 3. A triangle preserving remeshing: Loop's",
    )


LOOP = (
    "Here, we first subdivide every edge at its midpoint and connect these midpoints to "
    "create a central face in the middle of each original face and triangles in each corner."
)


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 3, measured on :func:`panels` (and (B) remeshed again)."""
    p = panels() if meshes is None else meshes
    a, b = p["A"], p["B"]
    c = loop_remesh(b)

    def non_tri(m: Mesh) -> dict[int, int]:
        return {k: v for k, v in m.face_size_histogram().items() if k != 3}

    e = a.edges
    mids = (a.vertices[e[:, 0]] + a.vertices[e[:, 1]]) / 2
    new = b.vertices[a.n_vertices :]
    err = float(np.abs(new - mids).max()) if new.shape == mids.shape else float("inf")
    return [
        counts_claim(
            "fig03.B.counts",
            "Section 3, Figure 3",
            LOOP,
            "(B)",
            a,
            b,
            "loop_remesh",
            cause="Loop's remeshing",
        ),
        exact(
            "fig03.B.faces",
            "Section 3, Figure 3",
            LOOP,
            "(B) faces by size, against a central face of every face of (A) and a triangle "
            "at each of its 2E corners",
            add_counts(a.face_size_histogram(), {3: 2 * a.n_edges}),
            b.face_size_histogram(),
            reading="every face keeps a central copy of its size, and every corner of every face "
            "becomes a triangle",
            cause="Loop's remeshing",
        ),
        bounded(
            "fig03.B.midpoints",
            "Section 3, Figure 3",
            "we first subdivide every edge at its midpoint",
            "largest distance of a new vertex of (B) from the midpoint of its edge of (A)",
            err,
            reading="every new vertex sits at the midpoint of an edge",
            cause="Loop's remeshing",
        ),
        exact(
            "fig03.non_triangles",
            "Section 3",
            "if the original mesh has some non-triangles, the resulting mesh does not become "
            "a triangular mesh",
            "non-triangles by size in (B) and in (B) remeshed again, against those of (A)",
            (non_tri(a), non_tri(a)),
            (non_tri(b), non_tri(c)),
            reading="the non-triangles of the input stay, as central copies, at every level",
            cause="Loop's remeshing",
        ),
    ]
