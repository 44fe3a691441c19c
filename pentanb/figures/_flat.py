"""The flat "pillow" that Figures 6 and 10 draw one polygon of (private).

A regular n-gon and its back, sharing all their edges: a closed 2-manifold
(a "dihedron"), but its 2-valent vertices are refused by the
:class:`~pentanb.Mesh` constructor (the dual of a 2-valent vertex would be
a 2-sided face).  :func:`pentanb.pentagonalize` and
:func:`pentanb.preserve_pentagons` handle it, so the figures apply them to
it and draw only what became of the front face.  It is built here, for
those two figures, and not offered as a public shape.
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh

__all__ = ["pillow"]


def pillow(n: int, radius: float = 1.0) -> Mesh:
    """A flat closed mesh of two faces: a regular n-gon (face 0, facing +z) and its back.

    Parameters
    ----------
    n : int, >= 3
        Sides of the polygon.
    radius : float
        Distance of its corners from the origin; corner 0 on the +y axis.

    Returns
    -------
    Mesh
        ``n`` vertices in the plane z = 0, 2 faces, built without validation.
    """
    t = 2 * np.pi * (np.arange(n) / n) + np.pi / 2
    v = np.stack([radius * np.cos(t), radius * np.sin(t), np.zeros(n)], axis=1)
    poly = np.arange(n)
    return Mesh.from_csr(v, np.concatenate([poly, poly[::-1]]), [0, n, 2 * n], validate=False)
