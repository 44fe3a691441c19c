"""Build ``open_disk.obj``, a small open model: a domed disk with two holes.

A surface with boundary for the open-mesh features (a mesh with boundary
loops, the schemes and the dual on them).  Topologically a pair of pants:
genus 0, three boundary loops (the rim and two holes), Euler characteristic
``2 - 0 - 3 = -1``.  Made for this package (no third-party data):

1. points in the unit disk: 30 on the rim, 11 on each of two holes of radius
   0.23 at ``(-0.42, 0.06)`` and ``(0.44, -0.05)``, and a jittered
   hexagonal lattice of spacing 0.16 inside (fixed seed), none closer than
   0.07 to the rim or a hole;
2. their Delaunay triangulation (``scipy.spatial.Delaunay``), without the
   triangles inside the holes, every triangle counter-clockwise seen from
   above;
3. the most square pairs of neighbouring triangles become quadrilaterals
   and a few quadrilaterals take in a neighbouring triangle to become
   pentagons, never leaving an interior vertex with fewer than 3 edges;
4. the disk is laid on a sphere of radius 1.4 (a dome, its normals up).

The result: 147 vertices, 300 edges, 152 faces (72 triangles, 68
quadrilaterals, 12 pentagons), valences 3 to 6 (every boundary vertex has
two faces or more: no corner), three boundary loops of 30, 11 and 11 edges.
``pentanb.shapes.open_disk()`` reads the OBJ (numpy only); ``python -m
pentanb.data.make_open_disk`` rebuilds it (needs scipy), and the test suite
checks that the shipped file is what this script writes.

Licence: the script and the OBJ are part of pentanb (MIT licence).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

__all__ = ["HOLES", "RIM", "build", "obj_text", "main"]

#: Points on the rim (the unit circle).
RIM = 30
#: The holes: centre (x, y), radius, number of points.
HOLES: tuple[tuple[tuple[float, float], float, int], ...] = (
    ((-0.42, 0.06), 0.23, 11),
    ((0.44, -0.05), 0.23, 11),
)
#: Radius of the sphere the disk is laid on.
DOME = 1.4


def _circle(centre: tuple[float, float], radius: float, k: int, phase: float) -> np.ndarray:
    t = phase + 2 * np.pi * np.arange(k) / k
    return np.stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)], axis=1)


def _inside_points(rng: np.random.Generator) -> np.ndarray:
    """A jittered hexagonal lattice in the disk, away from the rim and the holes."""
    step = 0.16
    rows = np.arange(-1.0, 1.0 + step, step * np.sqrt(3) / 2)
    pts = []
    for i, y in enumerate(rows):
        for x in np.arange(-1.0, 1.0 + step, step) + (step / 2 if i % 2 else 0.0):
            pts.append((x, y))
    p = np.array(pts) + rng.uniform(-0.025, 0.025, (len(pts), 2))
    keep = np.linalg.norm(p, axis=1) < 1.0 - 0.07
    for centre, radius, _ in HOLES:
        keep &= np.linalg.norm(p - centre, axis=1) > radius + 0.07
    return p[keep]


def _quality(p: np.ndarray, face: list[int]) -> float:
    """How far a polygon is from regular: the largest |angle - the regular one|,
    infinite when it is not convex."""
    q = p[face]
    a = np.roll(q, 1, axis=0) - q
    b = np.roll(q, -1, axis=0) - q
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    if (cross > 0).any():  # a reflex corner (counter-clockwise polygons turn left)
        return np.inf
    cos = np.einsum("ij,ij->i", a, b) / np.linalg.norm(a, axis=1) / np.linalg.norm(b, axis=1)
    angles = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    return float(np.abs(angles - 180.0 * (len(face) - 2) / len(face)).max())


def _merge(
    p: np.ndarray, faces: list[list[int]], sizes: tuple[int, int], most: int, limit: float
) -> list[list[int]]:
    """Join up to ``most`` pairs of neighbouring faces of the given sizes across an
    interior edge, the most regular results first (no corner more than ``limit``
    degrees from the regular polygon's), each face at most once, never leaving
    an interior vertex with fewer than 3 edges."""
    owner: dict[tuple[int, int], int] = {}
    for fi, face in enumerate(faces):
        for a, b in zip(face, face[1:] + face[:1]):
            owner[a, b] = fi
    edges: dict[int, set[int]] = {}
    for a, b in owner:
        edges.setdefault(a, set()).add(b)
        edges.setdefault(b, set()).add(a)
    boundary = {a for a, b in owner if (b, a) not in owner}
    candidates: list[tuple[float, int, int, int, int, list[int]]] = []
    for (a, b), f in owner.items():
        g = owner.get((b, a))
        if g is None or f > g or sorted((len(faces[f]), len(faces[g]))) != sorted(sizes):
            continue
        fa, gb = faces[f].index(a), faces[g].index(b)
        walk_f = faces[f][fa + 1 :] + faces[f][: fa + 1]  # b ... a
        walk_g = faces[g][gb + 1 :] + faces[g][: gb + 1]  # a ... b
        joined = walk_f + walk_g[1:-1]
        if len(set(joined)) == len(joined):
            candidates.append((_quality(p, joined), a, b, f, g, joined))
    candidates.sort(key=lambda c: c[:5])
    used: set[int] = set()
    alive = [True] * len(faces)
    done = 0
    for quality, a, b, f, g, joined in candidates:
        if done == most or quality > limit:
            break
        if f in used or g in used:
            continue
        if any(len(edges[x]) - 1 < (2 if x in boundary else 3) for x in (a, b)):
            continue
        faces[f] = joined
        alive[g] = False
        used |= {f, g}
        edges[a].discard(b)
        edges[b].discard(a)
        done += 1
    return [face for face, keep in zip(faces, alive) if keep]


def build() -> tuple[np.ndarray, list[list[int]]]:
    """The model's vertices ((V, 3) float) and faces (lists of vertex indices,
    counter-clockwise seen from above)."""
    from scipy.spatial import Delaunay

    rng = np.random.default_rng(7)
    parts = [_circle((0.0, 0.0), 1.0, RIM, 0.0)]
    parts += [_circle(c, r, k, 0.3 * i) for i, (c, r, k) in enumerate(HOLES)]
    parts.append(_inside_points(rng))
    p = np.concatenate(parts)
    tris = Delaunay(p).simplices.copy()
    centre = p[tris].mean(axis=1)
    keep = np.ones(len(tris), dtype=bool)
    for c, r, _ in HOLES:
        keep &= np.linalg.norm(centre - c, axis=1) > r
    tris = tris[keep]
    a, b, c = (p[tris[:, i]] for i in range(3))
    cross = (b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]
    tris[cross < 0] = tris[cross < 0][:, ::-1]
    tris = np.array([np.roll(t, -int(np.argmin(t))) for t in tris])
    tris = tris[np.lexsort(tris.T[::-1])]  # an order independent of qhull
    faces = [t.tolist() for t in tris]
    faces = _merge(p, faces, (3, 3), 80, 40.0)
    faces = _merge(p, faces, (3, 4), 12, 40.0)
    r2 = (p**2).sum(axis=1)
    z = np.sqrt(DOME**2 - r2) - np.sqrt(DOME**2 - 1.0)
    return np.column_stack([p, z]), faces


def obj_text(vertices: np.ndarray, faces: list[list[int]]) -> str:
    """The OBJ file's text (coordinates to 6 decimals)."""
    lines = [
        "# pentanb: a domed disk with two holes (genus 0, three boundary loops)",
        "# built by pentanb/data/make_open_disk.py; part of pentanb, MIT licence",
    ]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices.tolist()]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Write the OBJ next to this script (or to the path given)."""
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else Path(__file__).with_name("open_disk.obj")
    out.write_text(obj_text(*build()))
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
