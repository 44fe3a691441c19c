"""Measuring what the paper "visually confirmed": convergence under the dual.

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity".  Two studies turn that into numbers, with the measures of
:mod:`pentanb.analysis.measures`:

* :func:`dual_convergence`: one remeshing, then an even number of duals;
  after the remeshing and after every pair of duals, how round the mesh is
  (:func:`~pentanb.analysis.measures.radius_spread`), how uniform (the
  spreads of its edge lengths and face angles) and how sharp its sharpest
  crease is (the largest of :func:`~pentanb.analysis.measures.normal_angles`).
  Section 5.1 says of Figure 7 that the shape "becomes more and more uniform
  with each application of dual operation".
* :func:`subdivision_convergence`: the same after every iteration (one
  remeshing and two duals), with the largest crease angle measured
  separately at the extraordinary vertices and elsewhere.  On a G1
  (tangent-continuous) limit surface the largest crease angle must fall
  towards 0 as the mesh refines; a falling angle is necessary for G1, not a
  proof of it.

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

from .. import _checks, shapes
from ..mesh import Mesh, check_mesh
from ..schemes import SCHEMES
from ..schemes.registry import Scheme
from ..schemes.smoothing import dual
from ..subdivision import get_scheme, predict_counts, subdivide
from .measures import angle_spread, crease_angles, edge_length_spread, normal_angles, radius_spread
from .measures import edge_waviness as edge_waviness  # the old import path
from .measures import ray_distances as ray_distances  # the old import path

__all__ = [
    "Convergence",
    "dual_convergence",
    "subdivision_convergence",
    "study",
    "STUDY_MESHES",
    "STUDY_SCHEMES",
    "ROUND_MESHES",
    "extraordinary",
    "predicted_crease_rate",
]


@dataclass(frozen=True)
class Convergence:
    """Measurements after successive steps.

    Attributes
    ----------
    scheme : str
    steps : (k,) int
        0, 1, 2, ...: pairs of duals done after the remeshing
        (:func:`dual_convergence`; 0 is the remeshing alone) or 1, 2, ...:
        iterations (:func:`subdivision_convergence`).
    faces : (k,) int
        Number of faces after each step.
    radius_spread : (k,) float
        :func:`~pentanb.analysis.measures.radius_spread` after each step.
    edge_spread : (k,) float
        :func:`~pentanb.analysis.measures.edge_length_spread`.
    angle_spread : (k,) float
        :func:`~pentanb.analysis.measures.angle_spread` (corners grouped by face size).
    max_normal_angle : (k,) float
        Largest angle between neighbouring face normals, in degrees.
    mean_normal_angle : (k,) float
        Mean of those angles, in degrees.
    crease_at : (k,) float
        Largest crease angle at the extraordinary vertices (:func:`extraordinary`;
        NaN where there are none).
    crease_elsewhere : (k,) float
        Largest crease angle everywhere else (NaN where every edge is at one).
    """

    scheme: str
    steps: NDArray[np.int64]
    faces: NDArray[np.int64]
    radius_spread: NDArray[np.float64]
    edge_spread: NDArray[np.float64]
    angle_spread: NDArray[np.float64]
    max_normal_angle: NDArray[np.float64]
    mean_normal_angle: NDArray[np.float64]
    crease_at: NDArray[np.float64]
    crease_elsewhere: NDArray[np.float64]


def extraordinary(mesh: Mesh, source: Mesh) -> NDArray[np.bool_]:
    """The extraordinary vertices of a mesh made from ``source`` by the paper's schemes.

    The vertices of ``source`` whose valence is not 4 (both of the paper's
    schemes keep the input's vertices, numbered first, and so does a pair
    of duals) and the corners of the faces that are not pentagons (pentagon
    preservation keeps a copy of every input face, with its size).

    Parameters
    ----------
    mesh : Mesh
        ``source`` after remeshings by :func:`pentanb.pentagonalize` or
        :func:`pentanb.preserve_pentagons` and pairs of duals.
    source : Mesh

    Returns
    -------
    (V,) bool
    """
    marked = np.zeros(mesh.n_vertices, dtype=bool)
    marked[: source.n_vertices] = source.valences != 4
    odd = mesh.face_sizes[mesh.halfedge_face] != 5
    marked[mesh.corners[odd]] = True
    return marked


def _row(mesh: Mesh, source: Mesh | None, spreads: bool = True) -> dict[str, float]:
    """Every measure of :class:`Convergence` for one mesh (the spreads NaN if not asked)."""
    a = normal_angles(mesh)
    if source is None:
        crease = {"at": np.nan, "elsewhere": float(a.max())}
    else:
        crease = crease_angles(mesh, extraordinary(mesh, source), a)
    nan = float("nan")
    return {
        "faces": mesh.n_faces,
        "radius_spread": radius_spread(mesh) if spreads else nan,
        "edge_spread": edge_length_spread(mesh) if spreads else nan,
        "angle_spread": angle_spread(mesh) if spreads else nan,
        "max_normal_angle": float(a.max()),
        "mean_normal_angle": float(a.mean()),
        "crease_at": crease["at"],
        "crease_elsewhere": crease["elsewhere"],
    }


def _collect(rows: list[dict[str, float]], scheme_name: str, steps) -> Convergence:
    return Convergence(
        scheme=scheme_name,
        steps=np.asarray(steps, dtype=np.int64),
        faces=np.array([r["faces"] for r in rows], dtype=np.int64),
        **{k: np.array([r[k] for r in rows], dtype=np.float64) for k in rows[0] if k != "faces"},
    )


def _name(scheme) -> str:
    s = get_scheme(scheme)
    return getattr(s, "name", getattr(s, "__name__", str(scheme)))


#: Most measurements one study takes (pairs of duals, or iterations): each is
#: a mesh built and measured, and a thousand already show any trend.
MAX_MEASURED = 1000


def dual_convergence(mesh: Mesh, scheme="pentagonalize", duals: int = 12, **options) -> Convergence:
    """Remesh once, then apply ``duals`` duals, measuring after the remeshing and after
    every second dual.

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    duals : int, even, in [2, 2 :data:`MAX_MEASURED`]
        Number of dual operations after the remeshing; they are measured in
        pairs (the dual of a dual is a mesh of the remeshing's kind again),
        so the number must be even.
    **options
        Options of the scheme (e.g. ``scale``).

    Returns
    -------
    Convergence
        ``steps`` = 0 .. duals / 2: the pairs of duals done (0: the remeshing
        alone).

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh, or ``duals`` not an integer.
    ValueError
        ``duals`` is odd, < 2 or more than ``2 * MAX_MEASURED`` (refused
        before any work).
    """
    check_mesh(mesh, "dual_convergence")
    duals = _checks.count(duals, "duals", 2, 2 * MAX_MEASURED)
    if duals % 2:
        raise ValueError(f"duals must be an even integer >= 2 (pairs of duals), got {duals}")
    pairs = duals // 2
    m = subdivide(mesh, scheme, 1, 0, **options)
    rows = [_row(m, None)]
    for _ in range(pairs):
        m = dual(dual(m))
        rows.append(_row(m, None))
    return _collect(rows, _name(scheme), np.arange(pairs + 1))


def subdivision_convergence(
    mesh: Mesh,
    scheme="pentagonalize",
    iterations: int = 4,
    duals: int = 2,
    *,
    spreads: bool = True,
    **options,
) -> Convergence:
    """Subdivide ``iterations`` times (remesh + ``duals`` duals), measuring after each
    iteration.

    The crease angle is measured at the extraordinary vertices
    (:func:`extraordinary`; meaningful for the paper's two schemes) and elsewhere.
    Each mesh is measured as soon as it is made and then let go.

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    iterations : int, in [1, :data:`MAX_MEASURED`]
        Repetitions of the scheme, each followed by ``duals`` duals.
    duals : int, >= 0
        Dual operations after every remeshing.
    spreads : bool
        Measure the radius, edge and angle spreads too (on meshes of a
        million faces they take most of the time); NaN when False.
    **options
        Options of the scheme (e.g. ``scale``).

    Returns
    -------
    Convergence
        ``steps`` = 1 .. iterations.

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh, or a count not an integer.
    ValueError
        ``iterations`` < 1 or over :data:`MAX_MEASURED`, ``duals`` < 0.
    MeshError
        Before anything is built, when an iteration would not fit in memory
        (as :func:`pentanb.subdivide` refuses it, for a registered scheme).
    """
    check_mesh(mesh, "subdivision_convergence")
    iterations = _checks.count(iterations, "iterations", 1, MAX_MEASURED)
    duals = _checks.count(duals, "duals")
    s = get_scheme(scheme)
    if isinstance(s, Scheme):  # every level at once: refused before the first is built
        predict_counts(mesh, s, iterations, duals)
    else:
        _checks.steps(iterations * (1 + duals), f"{iterations:,} iterations with {duals:,} duals")
    name = _name(scheme)
    source = mesh if name in ("pentagonalize", "preserve_pentagons") and duals % 2 == 0 else None
    rows = []
    m = mesh
    for _ in range(iterations):
        m = subdivide(m, scheme, 1, duals, **options)
        rows.append(_row(m, source, spreads))
    return _collect(rows, name, np.arange(1, iterations + 1))


#: Meshes of the convergence study (name -> builder).
STUDY_MESHES = {
    "cube": shapes.cube,
    "tetrahedron": shapes.tetrahedron,
    "torus": lambda: shapes.torus(8, 6),
    "rabbit": shapes.rabbit,
}
#: Meshes of the study around a centre, for which the radius spread measures roundness.
ROUND_MESHES = ("cube", "tetrahedron")
#: Schemes of the convergence study: the paper's two.
STUDY_SCHEMES = ("pentagonalize", "preserve_pentagons")


def study(duals: int = 12, iterations: int = 4, max_faces: int | None = None) -> dict:
    """Both schemes on :data:`STUDY_MESHES`.

    Parameters
    ----------
    duals : int, even, >= 2
        Duals after one remeshing, for :func:`dual_convergence`.
    iterations : int, >= 1
        Iterations (remesh + two duals), for :func:`subdivision_convergence`.
    max_faces : int, optional
        Stop every mesh's iterations before the first whose mesh would have
        more faces (the notebooks' 100,000; at least one iteration is kept).

    Returns
    -------
    dict
        ``"meshes"``: the mesh names; ``"duals"`` and ``"iterations"``: dicts
        ``{(mesh name, scheme): Convergence}`` from :func:`dual_convergence`
        and :func:`subdivision_convergence`.  The rabbit (the one mesh of more
        than 50 faces) is refined one iteration more than the others, five by
        default: under pentagon preservation its creases fall slowly and need
        the levels (its last mesh has 1.2 million faces).  The iterations
        carry the crease angles, not the spreads (``spreads=False``: NaN).
        The torus is 8 x 6 quads.

    Notes
    -----
    The results of the last four ``(duals, iterations)`` asked for are kept
    (however the arguments are passed): the convergence figure and its claims
    share one study.  Treat the returned dict as read-only.
    """
    return _study(int(duals), int(iterations), None if max_faces is None else int(max_faces))


def _within(mesh: Mesh, scheme: str, iterations: int, max_faces: int | None) -> int:
    """The iterations, at most ``iterations`` and at least 1, whose meshes keep to
    ``max_faces`` faces (counted by the scheme's formula, nothing built)."""
    if max_faces is None:
        return iterations
    counts = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    for k in range(iterations):
        counts = SCHEMES[scheme].counts(*counts)
        if counts[2] > max_faces:
            return max(k, 1)
    return iterations


@functools.lru_cache(maxsize=4)
def _study(duals: int, iterations: int, max_faces: int | None = None) -> dict:
    res_duals, res_iterations = {}, {}
    for name, build in STUDY_MESHES.items():
        mesh = build()
        for scheme in STUDY_SCHEMES:
            res_duals[name, scheme] = dual_convergence(mesh, scheme, duals)
            it = iterations + 1 if mesh.n_faces > 50 else iterations
            it = _within(mesh, scheme, it, max_faces)
            res_iterations[name, scheme] = subdivision_convergence(mesh, scheme, it, spreads=False)
    return {"meshes": tuple(STUDY_MESHES), "duals": res_duals, "iterations": res_iterations}


#: |lambda1| and |lambda3| per step at a triangle under pentagon preservation (scale
#: 0.75) + 2 duals, as the spectra table gives them: what
#: :func:`predicted_crease_rate` falls back on without scipy.
TRIANGLE_075 = (0.125, 0.12083333333333333)


@functools.lru_cache(maxsize=8)
def predicted_crease_rate(
    scheme: str = "preserve_pentagons", kind: str = "face", size: int = 3, scale: float = 0.75
) -> tuple[float, float, str]:
    """The factor by which the crease angle near an extraordinary element falls per level,
    as the element's spectrum predicts: ``|lambda3| / |lambda1|``.

    Near the element, the positions after k steps are ``a0 + lambda1^k a1 v1 +
    lambda2^k a2 v2 + lambda3^k a3 v3 + ...``: the subdominant pair spans the
    tangent plane and the next eigenvalue bends the mesh away from it, so the
    angles between neighbouring faces there shrink like ``(|lambda3| /
    |lambda1|)^k`` once k is large (:func:`pentanb.analysis.local_spectrum`,
    one step = remesh + 2 duals).

    Parameters
    ----------
    scheme : str
    kind : {"vertex", "face"}
    size : int
    scale : float
        Pentagon preservation's scale (ignored by other schemes).

    Returns
    -------
    (float, float, str)
        ``|lambda1|``, ``|lambda3|`` per step, and where they come from
        (``"local_spectrum"``, or, without scipy and for a triangle under
        pentagon preservation at 0.75, the table's values,
        :data:`TRIANGLE_075`).
    """
    from .spectral import local_spectrum

    try:
        if scheme == "preserve_pentagons":
            sp = local_spectrum(scheme, kind, size, 2, scale=scale)
        else:
            sp = local_spectrum(scheme, kind, size, 2)
    except ImportError:
        if (scheme, kind, size, scale) == ("preserve_pentagons", "face", 3, 0.75):
            return (*TRIANGLE_075, "the spectra table (scipy is not installed)")
        raise
    m = sp.moduli
    return float(m[1]), float(m[3]), "local_spectrum"
