"""The seeds of Conway notation: ``T C O I D`` and ``Pn An Yn`` (:data:`SEEDS`).

``T C O I D`` are the Platonic solids of :mod:`pentanb.shapes`; ``Pn``,
``An`` and ``Yn`` the prism, antiprism and pyramid on a regular n-gon
(n >= 3), built here.  :func:`pyramid` is also the mesh in which
:mod:`pentanb.analysis.spectral` plants its extraordinary elements.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .. import _checks, shapes
from ..mesh import Mesh
from ..schemes.registry import Counts

__all__ = ["Seed", "SEEDS", "prism", "antiprism", "pyramid"]


@dataclass(frozen=True)
class Seed:
    """A seed letter: ``build(n)`` gives the mesh, ``counts(n)`` its (V, E, F)."""

    letter: str
    name: str
    build: Callable[..., Mesh]
    counts: Callable[..., Counts]
    needs_number: bool = False


def _regular_polygon(n: int, z: float = 0.0, turn: float = 0.0) -> np.ndarray:
    t = 2.0 * np.pi * (np.arange(n) + turn) / n
    return np.stack([np.cos(t), np.sin(t), np.full(n, z)], axis=1)


def _check_n(n, what: str) -> int:
    """The number of sides of ``what`` (:func:`pentanb._checks.count`, >= 3)."""
    return _checks.count(n, f"n (the sides of {what})", 3)


def prism(n: int) -> Mesh:
    """The prism ``Pn`` on a regular n-gon of circumradius 1, with square sides.

    Parameters
    ----------
    n : int >= 3
        The number of sides of the base (the n of ``Pn``).

    Returns
    -------
    Mesh
        2n vertices (bottom ring, then top ring), 3n edges, n + 2 faces
        (bottom, top, then the n quads).  ``P4`` is a cube.
    """
    n = _check_n(n, "a prism")
    side = 2.0 * np.sin(np.pi / n)
    v = np.concatenate([_regular_polygon(n, -side / 2), _regular_polygon(n, side / 2)])
    i = np.arange(n)
    j = (i + 1) % n
    quads = np.stack([i, j, n + j, n + i], axis=1)
    faces = [i[::-1], n + i] + list(quads)
    return Mesh(v, faces)


def antiprism(n: int) -> Mesh:
    """The antiprism ``An`` on a regular n-gon of circumradius 1, with
    equilateral triangles (the uniform antiprism).

    Parameters
    ----------
    n : int >= 3
        The number of sides of the base (the n of ``An``).

    Returns
    -------
    Mesh
        2n vertices, 4n edges, 2n + 2 faces (bottom, top, then 2n
        triangles).  ``A3`` is an octahedron.
    """
    n = _check_n(n, "an antiprism")
    h = np.sqrt(2.0 * np.cos(np.pi / n) - 2.0 * np.cos(2.0 * np.pi / n))
    v = np.concatenate([_regular_polygon(n, -h / 2), _regular_polygon(n, h / 2, turn=0.5)])
    i = np.arange(n)
    j = (i + 1) % n
    down = np.stack([i, j, n + i], axis=1)
    up = np.stack([n + i, j, n + j], axis=1)
    faces = [i[::-1], n + i] + list(down) + list(up)
    return Mesh(v, faces)


def pyramid(n: int) -> Mesh:
    """The pyramid ``Yn`` on a regular n-gon of circumradius 1.

    Equilateral triangles where they exist (n <= 5: the tetrahedron and
    Johnson's J1, J2), height 1 otherwise; centred on its vertices' mean.

    Parameters
    ----------
    n : int >= 3
        The number of sides of the base (the n of ``Yn``).

    Returns
    -------
    Mesh
        n + 1 vertices (the base ring 0 .. n - 1, then the apex n), 2n
        edges, n + 1 faces (the base ``(n - 1, ..., 0)``, then the n
        triangles ``(i, i + 1, n)``).  ``Y3`` is a tetrahedron.
    """
    n = _check_n(n, "a pyramid")
    side2 = (2.0 * np.sin(np.pi / n)) ** 2
    h = np.sqrt(side2 - 1.0) if n < 6 else 1.0
    v = np.concatenate([_regular_polygon(n), [[0.0, 0.0, h]]])
    v -= v.mean(axis=0)
    i = np.arange(n)
    tris = np.stack([i, (i + 1) % n, np.full(n, n)], axis=1)
    return Mesh(v, [i[::-1]] + list(tris))


_SEEDS = [
    Seed("T", "tetrahedron", shapes.tetrahedron, lambda: (4, 6, 4)),
    Seed("C", "cube", shapes.cube, lambda: (8, 12, 6)),
    Seed("O", "octahedron", shapes.octahedron, lambda: (6, 12, 8)),
    Seed("I", "icosahedron", shapes.icosahedron, lambda: (12, 30, 20)),
    Seed("D", "dodecahedron", shapes.dodecahedron, lambda: (20, 30, 12)),
    Seed("P", "prism", prism, lambda n: (2 * n, 3 * n, n + 2), True),
    Seed("A", "antiprism", antiprism, lambda n: (2 * n, 4 * n, 2 * n + 2), True),
    Seed("Y", "pyramid", pyramid, lambda n: (n + 1, 2 * n, n + 1), True),
]

#: Every seed letter.
SEEDS: dict[str, Seed] = {s.letter: s for s in _SEEDS}
