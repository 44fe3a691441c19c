"""One colour per number of sides, shared by every drawing in the package.

The matplotlib figures (:mod:`pentanb.viz.mpl`) and the pythreejs views
(:mod:`pentanb.viz.three`) both colour a face by its number of sides with
:func:`face_color`, so a pentagon has the same colour everywhere.  Needs
numpy only.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "FACE_COLORS",
    "LARGE_FACE_COLOR",
    "EDGE_COLOR",
    "BOUNDARY_COLOR",
    "face_color",
    "face_label",
    "face_rgb",
    "hex_to_rgb",
]

#: Colour of an n-gon, for n = 3 .. 8 (hex strings, colour-blind friendly
#: Okabe-Ito palette).  Larger faces share :data:`LARGE_FACE_COLOR`.
FACE_COLORS: dict[int, str] = {
    3: "#56B4E9",  # triangles: sky blue
    4: "#E69F00",  # quadrilaterals: orange
    5: "#009E73",  # pentagons: bluish green
    6: "#F0E442",  # hexagons: yellow
    7: "#CC79A7",  # heptagons: reddish purple
    8: "#D55E00",  # octagons: vermillion
}
#: Colour of faces with more than 8 sides.
LARGE_FACE_COLOR = "#999999"

#: Colour of the wireframe.
EDGE_COLOR = "#222222"

#: Colour of the boundary of an open mesh, drawn heavier than the wireframe
#: (wider lines, in every picture of an open mesh).
BOUNDARY_COLOR = "#000000"


def face_color(n: int) -> str:
    """Hex colour of a face with ``n`` sides."""
    return FACE_COLORS.get(int(n), LARGE_FACE_COLOR)


def face_label(n: int) -> str:
    """Legend label of a face with ``n`` sides ("pentagons", "9-gons", ...)."""
    names = {
        3: "triangles",
        4: "quads",
        5: "pentagons",
        6: "hexagons",
        7: "heptagons",
        8: "octagons",
    }
    return names.get(int(n), f"{int(n)}-gons")


def face_rgb(sizes) -> np.ndarray:
    """RGB colours in [0, 1] for an array of face sizes.

    Parameters
    ----------
    sizes : (m,) int
        Number of sides of each face.

    Returns
    -------
    (m, 3) float
    """
    sizes = np.asarray(sizes, dtype=np.int64)
    table = np.tile(hex_to_rgb(LARGE_FACE_COLOR), (max(int(sizes.max(initial=8)), 8) + 1, 1))
    for n, c in FACE_COLORS.items():
        table[n] = hex_to_rgb(c)
    return table[sizes]


def hex_to_rgb(color: str) -> np.ndarray:
    """(3,) float in [0, 1]: the RGB of a ``"#rrggbb"`` colour."""
    color = color.lstrip("#")
    return np.array([int(color[i : i + 2], 16) / 255.0 for i in (0, 2, 4)])
