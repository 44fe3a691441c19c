"""Build ``rabbit.obj``, the irregular low-polygon rabbit of Figure 12.

The paper's Figure 12 starts from "an initial mesh", a low-polygon rabbit
modelled by Esan Mandal, which is not available.  This script builds a
stand-in of the same kind, made for this package (no third-party data):

1. the rabbit is a union of ellipsoids (body, rump, head, snout, two ears,
   tail, four feet);
2. about 170 directions from a point inside it (a Fibonacci spread plus
   points on the small parts, slightly jittered with a fixed seed, none
   closer than 4 degrees to another) are joined into a triangulated sphere
   (their convex hull, ``scipy.spatial.ConvexHull``);
3. every direction is pushed out to where its ray leaves the union (the
   farthest exit), so the mesh is star-shaped around that point, closed,
   genus 0 and free of self-intersections;
4. the flattest pairs of neighbouring triangles become quadrilaterals and
   a few quadrilaterals take in a neighbouring triangle to become
   pentagons, never taking a vertex below valence 3.

The result: 172 vertices, 231 faces (136 triangles, 81 quadrilaterals, 14
pentagons), vertex valences 3 to 7.  ``pentanb.shapes.rabbit()`` reads the
OBJ (numpy only); run ``python -m pentanb.data.make_rabbit`` (needs scipy)
to rebuild it, and the test suite checks that the shipped file is what this
script writes.

Licence: the script and the OBJ are part of pentanb (MIT licence).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

__all__ = ["BLOBS", "CENTRE", "build", "obj_text", "main"]

#: The parts of the rabbit: name, centre, semi-axes, (turn about y, turn about x)
#: in radians, number of extra directions placed on the part.  x points forward
#: (to the snout), z up.
BLOBS: tuple[tuple[str, tuple, tuple, tuple, int], ...] = (
    ("body", (0.0, 0.0, 0.0), (0.95, 0.62, 0.66), (0.15, 0.0), 0),
    ("rump", (-0.45, 0.0, -0.05), (0.62, 0.66, 0.62), (0.0, 0.0), 0),
    ("head", (0.92, 0.0, 0.62), (0.42, 0.36, 0.38), (0.3, 0.0), 24),
    ("snout", (1.25, 0.0, 0.5), (0.18, 0.2, 0.17), (0.0, 0.0), 10),
    ("left ear", (0.66, 0.24, 1.32), (0.13, 0.1, 0.5), (-0.3, -0.35), 30),
    ("right ear", (0.66, -0.24, 1.32), (0.13, 0.1, 0.5), (-0.3, 0.35), 30),
    ("tail", (-1.1, 0.0, 0.25), (0.18, 0.18, 0.18), (0.0, 0.0), 10),
    ("left fore foot", (0.62, 0.26, -0.62), (0.26, 0.11, 0.12), (0.0, 0.0), 8),
    ("right fore foot", (0.62, -0.26, -0.62), (0.26, 0.11, 0.12), (0.0, 0.0), 8),
    ("left hind foot", (-0.35, 0.42, -0.62), (0.42, 0.15, 0.13), (0.0, 0.0), 10),
    ("right hind foot", (-0.35, -0.42, -0.62), (0.42, 0.15, 0.13), (0.0, 0.0), 10),
)
#: The point the rabbit is star-shaped around.
CENTRE = np.array([0.6, 0.0, 0.35])


def _rotation(turn: tuple[float, float]) -> np.ndarray:
    ay, ax = turn
    ry = np.array([[np.cos(ay), 0, np.sin(ay)], [0, 1, 0], [-np.sin(ay), 0, np.cos(ay)]])
    rx = np.array([[1, 0, 0], [0, np.cos(ax), -np.sin(ax)], [0, np.sin(ax), np.cos(ax)]])
    return rx @ ry


def _fibonacci(k: int) -> np.ndarray:
    """k roughly evenly spread unit vectors ((k, 3) float)."""
    i = np.arange(k) + 0.5
    z = 1 - 2 * i / k
    t = np.pi * (1 + 5**0.5) * i
    s = np.sqrt(1 - z * z)
    return np.stack([s * np.cos(t), s * np.sin(t), z], axis=1)


def _exit_distance(d: np.ndarray) -> np.ndarray:
    """Distance from CENTRE along every unit direction (rows of d) to the farthest
    point where the ray leaves one of the ellipsoids."""
    best = np.zeros(len(d))
    for _, c, a, turn, _ in BLOBS:
        r = _rotation(turn)
        axes = np.asarray(a)
        o = ((CENTRE - np.asarray(c)) @ r) / axes
        dd = (d @ r) / axes
        qa = (dd * dd).sum(axis=1)
        qb = 2 * dd @ o
        qc = o @ o - 1
        disc = qb * qb - 4 * qa * qc
        t = (-qb + np.sqrt(np.maximum(disc, 0.0))) / (2 * qa)
        best = np.maximum(best, np.where((disc > 0) & (t > 0), t, 0.0))
    return best


def _normal(v: np.ndarray, face: list[int]) -> np.ndarray:
    p = v[face]
    n = np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)
    return n / np.linalg.norm(n)


def _merge(v: np.ndarray, faces: list[list[int]], sizes: tuple[int, int], most: int, limit: float):
    """Join up to ``most`` pairs of neighbouring faces of the given sizes, flattest
    first (angle between their normals below ``limit`` degrees), each face at most
    once, never taking a vertex below valence 3."""
    owner: dict[tuple[int, int], int] = {}
    for fi, face in enumerate(faces):
        for a, b in zip(face, face[1:] + face[:1]):
            owner[a, b] = fi
    valence = np.bincount(np.concatenate(faces), minlength=len(v))
    pairs: list[tuple[float, int, int, int, int]] = []
    for (a, b), f in owner.items():
        g = owner[b, a]
        if f < g and sorted((len(faces[f]), len(faces[g]))) == sorted(sizes):
            cos = float(np.clip(_normal(v, faces[f]) @ _normal(v, faces[g]), -1.0, 1.0))
            pairs.append((float(np.degrees(np.arccos(cos))), a, b, f, g))
    pairs.sort()
    used: set[int] = set()
    alive = [True] * len(faces)
    done = 0
    for angle, a, b, f, g in pairs:
        if done == most or angle > limit:
            break
        if f in used or g in used or valence[a] < 4 or valence[b] < 4:
            continue
        # f runs a -> b, g runs b -> a: join them across that edge
        fa, gb = faces[f].index(a), faces[g].index(b)
        walk_f = faces[f][fa + 1 :] + faces[f][: fa + 1]  # b ... a
        walk_g = faces[g][gb + 1 :] + faces[g][: gb + 1]  # a ... b
        joined = walk_f + walk_g[1:-1]
        if len(set(joined)) != len(joined):
            continue
        faces[f] = joined
        alive[g] = False
        used |= {f, g}
        valence[a] -= 1
        valence[b] -= 1
        done += 1
    return [face for face, keep in zip(faces, alive) if keep]


def build() -> tuple[np.ndarray, list[list[int]]]:
    """The rabbit's vertices ((V, 3) float) and faces (lists of vertex indices,
    counter-clockwise seen from outside)."""
    from scipy.spatial import ConvexHull

    rng = np.random.default_rng(3)
    dirs = [_fibonacci(90)]
    for _, c, a, turn, k in BLOBS:
        if k:
            p = (_fibonacci(k) * np.asarray(a)) @ _rotation(turn).T + np.asarray(c) - CENTRE
            dirs.append(p / np.linalg.norm(p, axis=1)[:, None])
    d = np.concatenate(dirs)
    d += 0.02 * rng.standard_normal(d.shape)
    d /= np.linalg.norm(d, axis=1)[:, None]
    keep: list[int] = []
    for i in range(len(d)):  # none closer than 0.07 rad (4 degrees) to another
        if not keep or np.arccos(np.clip(d[keep] @ d[i], -1.0, 1.0)).min() > 0.07:
            keep.append(i)
    d = d[keep]
    tris = ConvexHull(d).simplices.copy()
    n = np.cross(d[tris[:, 1]] - d[tris[:, 0]], d[tris[:, 2]] - d[tris[:, 0]])
    flip = np.einsum("ij,ij->i", n, d[tris].mean(axis=1)) < 0
    tris[flip] = tris[flip][:, ::-1]
    tris = tris[np.lexsort(np.sort(tris, axis=1).T[::-1])]  # an order independent of qhull
    tris = np.array([np.roll(t, -int(np.argmin(t))) for t in tris])
    v = CENTRE + _exit_distance(d)[:, None] * d
    faces = [t.tolist() for t in tris]
    faces = _merge(v, faces, (3, 3), 95, 40.0)
    faces = _merge(v, faces, (3, 4), 14, 30.0)
    return v, faces


def obj_text(vertices: np.ndarray, faces: list[list[int]]) -> str:
    """The OBJ file's text (coordinates to 6 decimals)."""
    lines = [
        "# pentanb: an irregular low-polygon rabbit (stand-in for the paper's Figure 12 model)",
        "# built by pentanb/data/make_rabbit.py; part of pentanb, MIT licence",
    ]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices.tolist()]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Write the OBJ next to this script (or to the path given)."""
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else Path(__file__).with_name("rabbit.obj")
    out.write_text(obj_text(*build()))
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
