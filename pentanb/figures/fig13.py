"""Figure 13: soccerball subdivision of pentagonal meshes.

Honeycomb (dual of sqrt(3), Conway's zip) of the dodecahedron (A) and of the
pentagonalized cube (B); hexagon preservation (dual of Loop, Conway's
chamfer) of the same (C, D); two duals after each.  (A) is the soccer ball.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from .. import shapes
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import Claim, add_counts, exact, vef

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Soccerball subdivision"
CAPTION = "An example of soccerball subdivision."
LABELS = ("A", "B", "C", "D")


def _sources() -> dict[str, Mesh]:
    """The two pentagonal meshes: the dodecahedron and the pentagonalized cube (two duals)."""
    return {
        "dodecahedron": shapes.dodecahedron(),
        "pentagonal cube": subdivide(shapes.cube(), "pentagonalize", 1, 2),
    }


#: Panel -> (source, scheme).
_PANELS = {
    "A": ("dodecahedron", "honeycomb"),
    "B": ("pentagonal cube", "honeycomb"),
    "C": ("dodecahedron", "preserve_hexagons"),
    "D": ("pentagonal cube", "preserve_hexagons"),
}


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 13: honeycomb of the dodecahedron (A) and of the
    pentagonalized cube (B), hexagon preservation of the same (C, D); two duals each."""
    src = _sources()
    return {k: subdivide(src[s], scheme, 1, 2) for k, (s, scheme) in _PANELS.items()}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 13: soccerball subdivisions of pentagonal meshes.

    Honeycomb (dual of sqrt(3)) of the dodecahedron (A) and of the
    pentagonalized cube (B); hexagon preservation (dual of Loop) of the same
    (C, D).  Two duals after each.

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
            (p["A"], "honeycomb of a dodecahedron", {}),
            (p["B"], "honeycomb of a pentagonal cube", {}),
            (p["C"], "dual of Loop, dodecahedron", {}),
            (p["D"], "dual of Loop, pentagonal cube", {}),
        ],
        ncols=4,
        suptitle="Figure 13. Soccerball subdivision of pentagonal meshes",
    )


SOCCER = (
    "If one applies a honeycomb subdivision, dual of sqrt(3) [5, 8, 19, 6] or dual of Loop "
    "[18, 12], to the pentagonal meshes, the resulting meshes do not include any triangle or "
    "quadrilateral."
)


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 13, measured on :func:`panels` and their sources."""
    p = panels() if meshes is None else meshes
    src = _sources()
    a = p["A"]
    out = [
        exact(
            "fig13.A.soccer_ball",
            "Section 6, Figure 13",
            "the portions of the resulting mesh resemble geodesic domes [16] (also called "
            "buckyballs, fullerenes or soccerballs)",
            "(A) faces by size, valences, (V, E, F), against the truncated icosahedron's",
            ({5: 12, 6: 20}, {3: 60}, (60, 90, 32)),
            (a.face_size_histogram(), a.valence_histogram(), vef(a)),
            reading="honeycomb subdivision of the dodecahedron is the soccer ball as a mesh: 12 "
            "pentagons, 20 hexagons, 60 three-valent vertices",
            cause="soccerball subdivision of pentagonal meshes",
        )
    ]
    for label in ("B", "C", "D"):
        panel, m = f"({label})", p[label]
        s_name, scheme = _PANELS[label]
        s = src[s_name]
        new = (
            {2 * k: c for k, c in s.valence_histogram().items()}
            if scheme == "honeycomb"
            else {6: s.n_edges}
        )
        how = (
            "a 2k-gon for every k-valent vertex"
            if scheme == "honeycomb"
            else "a hexagon for every edge"
        )
        out.append(
            exact(
                f"fig13.{label}.faces",
                "Section 6, Figure 13",
                SOCCER,
                f"{panel} faces by size, against the {s_name}'s pentagons kept and {how}",
                add_counts({5: s.n_faces}, new),
                m.face_size_histogram(),
                reading="the pentagons stay and every new face has six sides or more: no "
                "triangle, no quadrilateral",
                cause="soccerball subdivision of pentagonal meshes",
            )
        )
    hb = p["B"]
    out.append(
        exact(
            "fig13.B.valence",
            "Section 6",
            "In the case of dual of sqrt(3) each vertex becomes valence three",
            "(B) valences",
            {3: hb.n_vertices},
            hb.valence_histogram(),
            reading="every vertex of a honeycomb subdivision is 3-valent",
            cause="soccerball subdivision of pentagonal meshes",
        )
    )
    return out
