"""Figure 11: a semi-regular tiling from pentagon preservation of a cube.

(A) pentagon preservation (scale 0.75, this package's default) of the plain
cube with two duals: 6 quadrilaterals and 24 pentagons whose corners make
4.3.3.4.3; (B) its dual.  The claims: the counts, the number of
non-pentagons staying constant, the regions counted by corner valences.  An
observation: their geometry against the classical tile, level by level (the
paper says neither "classical" nor 4.3.3.4.3 of Figure 11).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import (
    HOLDS,
    OBSERVATION,
    Claim,
    configuration_claim,
    counts_claim,
    exact,
    region_claim,
    take,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagon preservation on a cube"
CAPTION = (
    "A semi-regular tiling created by pentagon preserving scheme that is applied to "
    "a cube. (A) is one iteration with two dual, (B) is the dual of (A)."
)
LABELS = ("A", "B")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 11: the cube after pentagon preservation with two duals (A)
    and its dual (B)."""
    a = subdivide(shapes.cube(), "preserve_pentagons", 1, 2)
    return {"A": a, "B": dual(a)}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 11: pentagon preservation (scale 0.75) of a cube with two duals (A), and
    its dual (B).

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
            (p["A"], "cube: one iteration, two duals", {}),
            (p["B"], "dual of (A)", {}),
        ],
        suptitle="Figure 11. A semi-regular tiling from pentagon preservation of a cube",
        panel_size=3.6,
    )


SPLIT = (
    "Each face in the original mesh would now have been split into as many pentagons as "
    "the number of edges (or vertices) in the original face plus one central face with "
    "the same number of sides as the original face."
)


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 11, measured on :func:`panels`, the cube they come
    from and (A) refined once and twice more (``meshes["source"]``,
    ``meshes["level 2"]`` and ``meshes["level 3"]`` replace them)."""
    p = panels() if meshes is None else meshes
    a = p["A"]
    src = take(meshes, "source", shapes.cube)
    a2 = take(meshes, "level 2", lambda: subdivide(a, "preserve_pentagons", 1, 2))
    a3 = take(meshes, "level 3", lambda: subdivide(a2, "preserve_pentagons", 1, 2))

    def non5(m: Mesh) -> int:
        return int((m.face_sizes != 5).sum())

    return [
        counts_claim(
            "fig11.A.counts",
            "Section 5.2, Figure 11",
            SPLIT,
            "(A)",
            src,
            a,
            "preserve_pentagons",
            cause="pentagon preservation's combinatorics",
        ),
        exact(
            "fig11.A.faces",
            "Section 5.2, Figure 11",
            SPLIT,
            "(A) faces by size, against the cube's 6 quads kept and 2E = 24 pentagons",
            {4: src.n_faces, 5: 2 * src.n_edges},
            a.face_size_histogram(),
            reading="every n-gon becomes n pentagons (one per half-edge: 2E in all) and a "
            "central n-gon",
            cause="pentagon preservation's combinatorics",
        ),
        exact(
            "fig11.non_pentagons",
            "Section 1",
            "creates only pentagons and the number of non-pentagonal faces remains constant "
            "after the first refinement",
            "non-pentagons at levels 1, 2, 3",
            (src.n_faces,) * 3,
            (non5(a), non5(a2), non5(a3)),
            reading="every new face is a pentagon; the central copies of the input's faces "
            "keep their sizes, so the non-pentagons stay as many as the input's faces",
            cause="pentagon preservation's combinatorics",
        ),
        configuration_claim(
            "fig11.A.regions",
            "Figure 11",
            "A semi-regular tiling created by pentagon preserving scheme that is applied to a "
            "cube.",
            a,
            {"3.3.4.3.4": 2 * src.n_edges, "3.3.3.3": src.n_faces},
            "4.3.3.4.3",
            reading="a tiling whose faces repeat a few kinds, counted by the valences of their "
            "corners: every pentagon 4.3.3.4.3, every kept quad 3.3.3.3",
            cause="pentagon preservation's combinatorics",
        ),
        region_claim(
            "fig11.A.geometry",
            "Figure 11 (the paper says neither 'classical' nor 4.3.3.4.3 here)",
            "A semi-regular tiling created by pentagon preserving scheme that is applied to a "
            "cube.",
            [("level 1 (A)", a), ("level 2", a2), ("level 3", a3)],
            "4.3.3.4.3",
            HOLDS,
            kind=OBSERVATION,
            cause="the regions on curved or non-uniform inputs",
        ),
    ]
