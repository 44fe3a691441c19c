"""Flat classical tilings for the tests: inputs on which Section 5.1's geometry holds.

:func:`laves_pillow` builds a patch of an Archimedean tiling (regular
polygons of unit side: the snub square tiling 3.3.4.3.4 or the snub
hexagonal tiling 3.3.3.3.6), closes it into a flat two-sided "pillow" and
returns its dual: away from the rim, the dual's faces are exactly the
classical (Laves) tiles, flat, with the angle 360/k at every k-valent
corner.  Fed to a region-geometry claim, they show that the claim can
hold.
"""

from __future__ import annotations

import itertools
from collections import Counter

import numpy as np

from pentanb import Mesh, dual

__all__ = ["archimedean_patch", "laves_pillow"]


def _regular(center, k: int, turn: float) -> np.ndarray:
    """A regular k-gon of unit side, counter-clockwise ((k, 2) float)."""
    r = 0.5 / np.sin(np.pi / k)
    a = turn + 2 * np.pi * np.arange(k) / k
    return np.asarray(center, dtype=float) + r * np.stack([np.cos(a), np.sin(a)], axis=1)


def archimedean_patch(config: str, radius: float) -> tuple[np.ndarray, list[list[int]]]:
    """Vertices ((n, 2) float) and faces of a patch of the snub tiling ``config``.

    ``"3.3.4.3.4"``: unit squares on two square lattices of period
    sqrt(2 + sqrt(3)), turned by +-15 degrees; ``"3.3.3.3.6"``: unit
    hexagons on a triangular lattice of period sqrt(7), turned by
    atan(sqrt(3) / 5).  The triangles are every three mutually adjacent
    vertices.  Only faces within ``radius`` of the origin are kept.
    """
    polys = []
    if config == "3.3.4.3.4":
        p = np.sqrt(2 + np.sqrt(3))
        for i, j in itertools.product(range(-8, 9), repeat=2):
            polys.append(_regular((i * p, j * p), 4, np.radians(15) + np.pi / 4))
            polys.append(_regular(((i + 0.5) * p, (j + 0.5) * p), 4, np.radians(-15) + np.pi / 4))
    elif config == "3.3.3.3.6":
        s = np.sqrt(7)
        turn = np.arctan(np.sqrt(3) / 5)
        for i, j in itertools.product(range(-9, 10), repeat=2):
            c = i * np.array([s, 0.0]) + j * np.array([s / 2, s * np.sqrt(3) / 2])
            polys.append(_regular(c, 6, turn))
    else:
        raise ValueError(f"no construction for {config!r}")
    polys = [q for q in polys if np.linalg.norm(q, axis=1).max() < radius + 2]
    pts = np.concatenate(polys)
    _, first, inv = np.unique(np.round(pts, 6), axis=0, return_index=True, return_inverse=True)
    inv = inv.reshape(-1)
    verts = pts[first]  # exact positions, not the rounded keys
    faces, o = [], 0
    for q in polys:
        faces.append(inv[o : o + len(q)].tolist())
        o += len(q)
    d = np.linalg.norm(verts[:, None] - verts[None], axis=2)
    adj = np.isclose(d, 1.0, atol=1e-6)
    for a in range(len(verts)):
        for b, c in itertools.combinations(np.flatnonzero(adj[a]), 2):
            if a < b and a < c and adj[b, c]:
                e1, e2 = verts[b] - verts[a], verts[c] - verts[a]
                faces.append([a, b, c] if e1[0] * e2[1] - e1[1] * e2[0] > 0 else [a, c, b])
    keep = [f for f in faces if np.linalg.norm(verts[f], axis=1).max() < radius]
    return verts, keep


def laves_pillow(config: str, radius: float = 5.0) -> Mesh:
    """The dual of a flat two-sided pillow of :func:`archimedean_patch`.

    The patch is pruned until every vertex lies on two faces or more, its
    rim is shared by the front and a copy of the patch facing the other
    way 0.1 below it, and the dual is taken (vertices at face centroids).
    """
    verts, faces = archimedean_patch(config, radius)
    while True:  # no vertex on one face only (it would become 2-valent)
        count = Counter(v for f in faces for v in f)
        kept = [f for f in faces if min(count[v] for v in f) > 1]
        if len(kept) == len(faces):
            break
        faces = kept
    edges = Counter(frozenset(e) for f in faces for e in zip(f, f[1:] + f[:1]))
    rim = {v for e, n in edges.items() if n == 1 for v in e}
    used = sorted({v for f in faces for v in f})
    front = {v: i for i, v in enumerate(used)}
    back = {v: len(used) + i for i, v in enumerate(v for v in used if v not in rim)}
    pos = np.zeros((len(used) + len(back), 3))
    pos[: len(used), :2] = verts[used]
    for v, i in back.items():
        pos[i] = [*verts[v], -0.1]
    top = [[front[v] for v in f] for f in faces]
    bottom = [[front[v] if v in rim else back[v] for v in f][::-1] for f in faces]
    return dual(Mesh(pos, top + bottom))
