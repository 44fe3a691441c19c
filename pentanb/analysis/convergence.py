"""Measuring what the paper "visually confirmed": convergence under the dual.

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity".  Two studies turn that into numbers, with the measures of
:mod:`pentanb.analysis.measures`:

* :func:`dual_convergence`: one remeshing, then pairs of duals; after each
  pair, how round the mesh is (:func:`~pentanb.analysis.measures.radius_spread`)
  and how sharp its sharpest crease is (the largest of
  :func:`~pentanb.analysis.measures.normal_angles`).
* :func:`subdivision_convergence`: the same after every subdivision level
  (one remeshing and two duals).  On a G1 (tangent-continuous) limit
  surface the largest crease angle must fall towards 0 as the mesh refines;
  a falling angle is necessary for G1, not a proof of it.

:func:`study` runs both on :data:`STUDY_MESHES` for the paper's two schemes
(the convergence figure).  numpy only.

``radius_spread``, ``normal_angles``, ``ray_distances`` and ``edge_waviness``
are defined in :mod:`pentanb.analysis.measures`; they are still importable
from here.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import get_scheme, subdivide
from .measures import edge_waviness as edge_waviness  # the old import path
from .measures import normal_angles, radius_spread
from .measures import ray_distances as ray_distances  # the old import path

__all__ = [
    "Convergence",
    "dual_convergence",
    "subdivision_convergence",
    "study",
    "STUDY_MESHES",
    "STUDY_SCHEMES",
    "ROUND_MESHES",
]


@dataclass(frozen=True)
class Convergence:
    """Measurements after successive steps.

    Attributes
    ----------
    scheme : str
    steps : (k,) int
        1, 2, ...: pairs of duals (:func:`dual_convergence`) or subdivision
        levels (:func:`subdivision_convergence`).
    faces : (k,) int
        Number of faces after each step.
    radius_spread : (k,) float
        :func:`~pentanb.analysis.measures.radius_spread` after each step.
    max_normal_angle : (k,) float
        Largest angle between neighbouring face normals, in degrees.
    mean_normal_angle : (k,) float
        Mean of those angles, in degrees.
    """

    scheme: str
    steps: NDArray[np.int64]
    faces: NDArray[np.int64]
    radius_spread: NDArray[np.float64]
    max_normal_angle: NDArray[np.float64]
    mean_normal_angle: NDArray[np.float64]


def _measure(meshes, scheme_name):
    angles = [normal_angles(m) for m in meshes]
    return Convergence(
        scheme=scheme_name,
        steps=np.arange(1, len(meshes) + 1, dtype=np.int64),
        faces=np.array([m.n_faces for m in meshes], dtype=np.int64),
        radius_spread=np.array([radius_spread(m) for m in meshes]),
        max_normal_angle=np.array([a.max() for a in angles]),
        mean_normal_angle=np.array([a.mean() for a in angles]),
    )


def _name(scheme) -> str:
    s = get_scheme(scheme)
    return getattr(s, "name", getattr(s, "__name__", str(scheme)))


def dual_convergence(mesh: Mesh, scheme="pentagonalize", pairs: int = 6, **options) -> Convergence:
    """Remesh once, then apply ``pairs`` pairs of duals, measuring after each pair.

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    pairs : int, >= 1
    **options
        Options of the scheme (e.g. ``scale``).

    Returns
    -------
    Convergence
        ``steps`` = 1 .. pairs.
    """
    if pairs < 1:
        raise ValueError(f"pairs must be >= 1, got {pairs}")
    m = subdivide(mesh, scheme, 1, 0, **options)
    out = []
    for _ in range(pairs):
        m = dual(dual(m))
        out.append(m)
    return _measure(out, _name(scheme))


def subdivision_convergence(
    mesh: Mesh, scheme="pentagonalize", levels: int = 4, duals: int = 2, **options
) -> Convergence:
    """Subdivide ``levels`` times (remesh + ``duals`` duals), measuring after each level.

    Returns
    -------
    Convergence
        ``steps`` = 1 .. levels.
    """
    if levels < 1:
        raise ValueError(f"levels must be >= 1, got {levels}")
    out = []
    m = mesh
    for _ in range(levels):
        m = subdivide(m, scheme, 1, duals, **options)
        out.append(m)
    return _measure(out, _name(scheme))


#: Meshes of the convergence study (name -> builder).
STUDY_MESHES = {
    "cube": shapes.cube,
    "tetrahedron": shapes.tetrahedron,
    "torus": lambda: shapes.torus(8, 6),
    "rabbit": shapes.animal,
}
#: Meshes of the study around a centre, for which the radius spread measures roundness.
ROUND_MESHES = ("cube", "tetrahedron")
#: Schemes of the convergence study: the paper's two.
STUDY_SCHEMES = ("pentagonalize", "preserve_pentagons")


@functools.lru_cache(maxsize=4)
def study(pairs: int = 6, levels: int = 4) -> dict:
    """Both schemes on :data:`STUDY_MESHES`.

    Returns
    -------
    dict
        ``"meshes"``: the mesh names; ``"pairs"`` and ``"levels"``: dicts
        ``{(mesh name, scheme): Convergence}`` from :func:`dual_convergence`
        and :func:`subdivision_convergence`.  (Meshes of more than 50 faces,
        here the rabbit, are refined at most three levels, to keep the study
        to a few seconds.)

    Notes
    -----
    The results of the last four ``(pairs, levels)`` asked for are kept
    (``functools.lru_cache(maxsize=4)``): the convergence figure and its
    claims share one study.  Treat the returned dict as read-only.
    """
    res_pairs, res_levels = {}, {}
    for name, build in STUDY_MESHES.items():
        mesh = build()
        for scheme in STUDY_SCHEMES:
            res_pairs[name, scheme] = dual_convergence(mesh, scheme, pairs)
            lv = min(levels, 3) if mesh.n_faces > 50 else levels
            res_levels[name, scheme] = subdivision_convergence(mesh, scheme, lv)
    return {"meshes": tuple(STUDY_MESHES), "pairs": res_pairs, "levels": res_levels}
