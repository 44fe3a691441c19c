"""Measured contraction, independent of the matrices: how fast the ring around
the element shrinks level after level (:func:`ring_contraction`), extrapolated
to its limit (:func:`extrapolate_ratio`).  It checks the subdominant modulus of
:func:`~pentanb.analysis.spectral.local_spectrum` from the meshes themselves.
"""

from __future__ import annotations

import itertools

import numpy as np
from numpy.typing import NDArray

from ... import _checks
from ...memory import default_max_bytes, mesh_bytes, readable
from ...mesh import Mesh, MeshError
from ...schemes.registry import Scheme
from ...subdivision import get_scheme, predict_counts
from ..subdivision_matrix import _name
from .neighbourhood import (
    MAX_DUALS,
    _check_kind,
    _check_size,
    _refuse_pyramid,
    _starts,
    _Topo,
    _walk,
    pyramid,
)

__all__ = [
    "ring_contraction",
    "extrapolate_ratio",
]

# ---------------------------------------------------------------------------
# measured contraction (independent of the matrices)
# ---------------------------------------------------------------------------


def _ring_points(mesh: Mesh, element) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
    """The points around the element and its centre.

    A vertex: its neighbours, about the vertex.  A face: its corners *and*
    their neighbours, about the mean of the corners.  The corners alone
    would miss Fourier mode 0 (which moves every corner alike, so their
    offsets from their own mean do not see it); the ring one edge further
    out sees every mode.
    """
    kind, i = element
    v = np.asarray(mesh.vertices)
    ring, off = mesh.vertex_ring
    if kind == "vertex":
        return mesh.head[ring[off[i] : off[i + 1]]], v[i]
    corners = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
    around = np.concatenate([mesh.head[ring[off[c] : off[c + 1]]] for c in corners])
    return np.unique(np.concatenate([corners, around])), v[corners].mean(axis=0)


def _ring_radius(mesh: Mesh, element) -> float:
    """Root mean square distance from the element's centre to the points around it
    (:func:`_ring_points`)."""
    pts, centre = _ring_points(mesh, element)
    v = np.asarray(mesh.vertices)
    return float(np.sqrt(((v[pts] - centre) ** 2).sum(axis=1).mean()))


def _mode_radii(mesh: Mesh, element) -> tuple[float, float] | None:
    """Root mean square offsets of the points around the element, split into
    Fourier mode 0 and the other modes, or None when the neighbourhood is not
    k-fold symmetric.

    The walks from the element's ``k`` half-edges order the points sector by
    sector (connectivity only, no weights): averaging a point's offset over
    its ``k`` turned copies keeps mode 0, the remainder is every other mode.
    Each part contracts at the rate of its own leading eigenvalue, so a
    simple ``lambda1`` of mode 0 close to the next eigenvalue of another mode
    (pentagon preservation at triangles) is not hidden behind it.
    """
    topo = _Topo(mesh)
    walks = [_walk(topo, element, h, 1) for h in _starts(mesh, element)]
    if len({w.signature for w in walks}) != 1:
        return None
    n = min(int(np.sum(walks[0].level <= 1.0)), *(w.verts.size for w in walks))
    idx = np.stack([w.verts[:n] for w in walks])  # (k, n): a point and its turned copies
    if np.any(walks[0].level[:n] > 1.0):
        return None
    v = np.asarray(mesh.vertices)
    _, centre = _ring_points(mesh, element)
    x = v[idx] - centre  # (k, n, 3)
    mean = x.mean(axis=0, keepdims=True)
    rest = x - mean
    return (
        float(np.sqrt((mean**2).sum(axis=-1).mean())),
        float(np.sqrt((rest**2).sum(axis=-1).mean())),
    )


def _ring_ratios(meshes, elements) -> list[float]:
    radii = [
        _ring_radius(m, e)
        for m, e in zip(meshes, elements)
        if e is not None and e[0] == elements[0][0]
    ]
    return [b / a for a, b in itertools.pairwise(radii)]


def extrapolate_ratio(ratios) -> float:
    """Aitken's delta-squared limit of a sequence of ratios (last three terms).

    Falls back to the last ratio when the differences vanish or change sign
    erratically.
    """
    r = [float(x) for x in ratios]
    if not r:
        raise ValueError("no ratios to extrapolate")
    if len(r) < 3:
        return r[-1]
    a, b, c = r[-3:]
    den = (c - b) - (b - a)
    if abs(den) < 1e-15 or (c - b) * (b - a) <= 0:
        return c
    return c - (c - b) ** 2 / den


def _refuse_levels(start, s, iterations: int, duals: int) -> None:
    """Refuse, before anything is built, ``iterations`` levels of ``s`` from
    ``start`` counts that are all kept: one too large for memory (as
    :func:`pentanb.subdivide` refuses it), all together over the memory
    available (MeshError), or too many steps (ValueError)."""
    if not isinstance(s, Scheme):  # a callable: subdivide guards every level
        _checks.steps(iterations * (1 + duals), f"{iterations:,} iterations with {duals:,} duals")
        return
    after = predict_counts(start, s, iterations, duals)
    kept = sum(mesh_bytes(*c) for c in after[duals :: 1 + duals])
    limit = default_max_bytes()
    if kept > limit:
        raise MeshError(
            f"{iterations:,} iterations of {_name(s)} keep meshes of {readable(kept)} in all, "
            f"over the memory available ({readable(limit)}); lower iterations"
        )


def ring_contraction(
    scheme="pentagonalize",
    kind: str = "vertex",
    size: int = 3,
    iterations: int = 6,
    duals: int = 2,
    *,
    mesh: Mesh | None = None,
    element: int | None = None,
    **options,
) -> tuple[NDArray[np.float64], float]:
    """The measured contraction of an element's 1-ring, iteration after iteration.

    Computed with :func:`pentanb.subdivide` alone (no matrices, so it checks
    them): the offsets of the points around a surviving vertex (its
    neighbours) or face (its corners and their neighbours: the corners
    alone would miss Fourier mode 0, which moves them alike) from its
    centre, after each iteration, split into mode 0 (the mean of a point's
    offset over its ``k`` turned copies, found by connectivity alone) and
    the other modes; the root mean square of each part, and the ratio of
    consecutive iterations.  Each part tends to the modulus of its own
    leading eigenvalue, so the slower part's ratio tends to ``|lambda1|``
    whatever its mode (a complex ``lambda1`` turns the ring and leaves the
    root mean square alone), without waiting for one mode to outgrow a
    close one of another mode (pentagon preservation at triangles, where
    ``|lambda2 / lambda1| = 0.82`` at scale 0.5).  Without k-fold
    symmetry the two parts are not split.

    The element keeps its index: every remeshing of the package numbers the
    kept vertices and the face copies first, in the input's order, and two
    duals give back the numbering (checked: the valence or size must stay).

    Parameters
    ----------
    scheme, kind, size, duals, **options
        As for :func:`local_spectrum`.
    iterations : int, >= 1
        Repetitions of the scheme, each followed by ``duals`` duals.
    mesh : Mesh, optional
        Start here instead of :func:`pyramid` ``(size)``; ``element`` then
        names the vertex (or face) to follow.

    Returns
    -------
    ratios : (iterations,) float
        The ratios of the part (mode 0, or the other modes) that contracts
        slowest.
    limit : float
        Aitken's extrapolation of those ratios (:func:`extrapolate_ratio`).

    Raises
    ------
    TypeError
        A size or count that is not an integer.
    ValueError
        When the element does not keep its index and valence (or size); a
        count out of range.
    MeshError
        Before anything is built, when the meshes (every level is kept)
        would not fit in memory.
    """
    kind = _check_kind(kind)
    iterations = _checks.count(iterations, "iterations", 1)
    duals = _checks.count(duals, "duals", 0, MAX_DUALS)
    s = get_scheme(scheme)
    if mesh is None:
        size = _check_size(size)
        _refuse_pyramid(size)
        start = (size + 1, 2 * size, size + 1)
    else:
        start = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
    _refuse_levels(start, s, iterations, duals)
    if mesh is None:
        mesh = pyramid(size)
        element = 0 if kind == "vertex" else size
    if element is None:
        raise ValueError("give the element to follow when you give a mesh")
    from ...subdivision import subdivide

    el = (kind, int(element))

    def measure(m: Mesh) -> int:
        return int(m.valences[el[1]]) if kind == "vertex" else int(m.face_sizes[el[1]])

    n0 = measure(mesh)
    meshes = [mesh]
    for _ in range(iterations):
        mesh = subdivide(mesh, s, 1, duals, **options)
        count = mesh.n_vertices if kind == "vertex" else mesh.n_faces
        if el[1] >= count or measure(mesh) != n0:
            raise ValueError(
                f"the {kind} {el[1]} does not keep its place under {_name(s)} + {duals} duals"
            )
        meshes.append(mesh)
    split = [_mode_radii(m, el) for m in meshes]
    if any(x is None for x in split):
        ratios = np.array(_ring_ratios(meshes, [el] * len(meshes)))
        return ratios, extrapolate_ratio(ratios)
    radii = np.array(split, dtype=np.float64)  # (levels, 2): mode 0, the other modes
    best: tuple[float, NDArray[np.float64]] | None = None
    for part in radii.T:
        if part[-1] <= 1e-12 * radii[-1].max():
            continue  # no such mode in the data (a symmetric start)
        r = part[1:] / part[:-1]
        lim = extrapolate_ratio(r)
        if best is None or lim > best[0]:
            best = (lim, r)
    assert best is not None
    return best[1], best[0]


def _measured_contraction(steps, element) -> float | None:
    ratios = _ring_ratios([st.mesh for st in steps], [st.element for st in steps])
    return extrapolate_ratio(ratios) if ratios else None
