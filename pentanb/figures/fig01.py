"""Figure 1: pentagonal subdivision examples on a hard-edged cube.

(A) the hard-edged cube (:func:`pentanb.shapes.hard_edged_cube`), (B) one
and (C) two pentagonalizations, (D) pentagon preservation applied to (B);
every step followed by two duals.  The claims: the count formulas, only
pentagons, Section 1's "no lateral artifact" (compared with honeycomb) and
the cube's symmetry kept.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from .. import shapes
from ..analysis.measures import edge_waviness
from ..mesh import Mesh
from ..subdivision import subdivide
from .claim import Claim, check, counts_claims, eq

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Pentagonal subdivision examples"
CAPTION = (
    "(A) is the initial mesh, (B) is one application of pentagonalization scheme, "
    "(C) is two iterations of pentagonalization scheme, (D) is obtained by applying "
    "pentagonal preserving scheme to the pentagonal mesh in (B)."
)
LABELS = ("A", "B", "C", "D")


def panels() -> dict[str, Mesh]:
    """The meshes of Figure 1, by panel: ``{"A": hard-edged cube, "B", "C", "D"}``."""
    a = shapes.hard_edged_cube()
    b = subdivide(a, "pentagonalize", 1, 2)
    c = subdivide(b, "pentagonalize", 1, 2)
    d = subdivide(b, "preserve_pentagons", 1, 2)
    return {"A": a, "B": b, "C": c, "D": d}


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Figure 1: a hard-edged cube (A), one (B) and two (C) pentagonalizations,
    pentagon preservation applied to (B) (D); each smoothed by two duals.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels`, if already built.
    """
    from ._draw import mesh_figure

    p = panels() if meshes is None else meshes
    return mesh_figure(
        [
            (p["A"], "hard-edged cube", {}),
            (p["B"], "one pentagonalization", {}),
            (p["C"], "two pentagonalizations", {}),
            (p["D"], "pentagon preservation of (B)", {}),
        ],
        ncols=4,
        suptitle="Figure 1. Pentagonal subdivision examples (each step followed by two duals)",
    )


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What the paper says of Figure 1, measured on :func:`panels`."""
    p = panels() if meshes is None else meshes
    a, b, c, d = (p[k] for k in LABELS)
    out = [
        eq(
            "(A) hard-edged cube: 54 quads, genus 0",
            ({4: 54}, 0),
            (a.face_size_histogram(), a.genus),
        )
    ]
    out += counts_claims("(B)", a, b, "pentagonalize")
    out.append(
        eq("(B) one pentagonalization: only pentagons", {5: 2 * a.n_edges}, b.face_size_histogram())
    )
    out += counts_claims("(C)", a, c, "pentagonalize", 2)
    out.append(
        eq("(C) two pentagonalizations: only pentagons", [5], sorted(c.face_size_histogram()))
    )
    out += counts_claims("(D)", b, d, "preserve_pentagons")
    out.append(
        eq(
            "(D) pentagon preservation of a pentagonal mesh: only pentagons",
            [5],
            sorted(d.face_size_histogram()),
        )
    )
    # "the new subdivision does not create any lateral artifact": along a
    # straight edge the surface keeps its distance from the edge's axis;
    # compared with honeycomb (dual of sqrt(3)), a (6, 3) scheme of [5]
    for panel, mesh, k in (("(B)", b, 1), ("(C)", c, 2)):
        w = edge_waviness(mesh)
        wh = edge_waviness(subdivide(a, "honeycomb", k, 2))
        out.append(
            check(
                f"{panel} no lateral artifact: the surface's distance from a "
                "straight edge's axis varies along the edge by less than half as "
                f"much as with honeycomb x{k} (dual of sqrt(3)) and the same duals "
                "(ours, honeycomb's; cube size 2)",
                "ours < honeycomb / 2",
                (round(w, 4), round(wh, 4)),
                w < wh / 2,
            )
        )
    sym = _symmetry_error(c)
    out.append(
        check(
            "(C) the smoothed mesh keeps the cube's 24 rotations (largest vertex mismatch / size)",
            "< 1e-9",
            sym,
            sym < 1e-9,
        )
    )
    return out


def _cube_rotations() -> np.ndarray:
    """The 24 rotation matrices of the cube ((24, 3, 3) float)."""
    mats = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product([1, -1], repeat=3):
            r = np.zeros((3, 3))
            r[np.arange(3), perm] = signs
            if np.linalg.det(r) > 0:
                mats.append(r)
    return np.array(mats)


def _symmetry_error(mesh: Mesh) -> float:
    """Largest distance from a rotated vertex to the nearest vertex, over the cube's
    rotations, divided by the mesh's size."""
    v = mesh.vertices
    size = float(np.ptp(v, axis=0).max())
    key = np.round(v / size, 6)
    order = np.lexsort(key.T[::-1])
    sv = v[order]
    worst = 0.0
    for r in _cube_rotations():
        w = v @ r.T
        ow = np.lexsort(np.round(w / size, 6).T[::-1])
        worst = max(worst, float(np.abs(w[ow] - sv).max()) / size)
    return worst
