"""Measures of a mesh shared by the figures, the convergence study and the notebooks.

Combinatorics (Section 5.1's semi-regular regions):

* :func:`vertex_configurations`: the sizes of the faces around every vertex,
  e.g. ``"3.3.4.3.4"``;
* :func:`face_configurations`: the valences of every face's corners (the
  vertex configurations of the dual);
* :func:`canonical_configuration`, :func:`configuration_counts`.

Geometry (what the paper judges by eye):

* :func:`radius_spread`: how round a mesh is (0 on a sphere);
* :func:`edge_lengths`, :func:`edge_length_spread`, :func:`corner_angles`,
  :func:`angle_spread`, :func:`uniformity`: how uniform a mesh is (Section
  5.1: "the resulting shape becomes more and more uniform with each
  application of dual operation");
* :func:`face_planarity`, :func:`region_geometry`: how far a set of faces is
  from a flat tiling (Section 5.1's "classical (or geometrical)
  semi-regular regions");
* :func:`normal_angles`, :func:`crease_angles`: the crease angle at every
  edge, and its largest value at the input's extraordinary vertices and
  elsewhere (Section 7's G1 convergence);
* :func:`ray_distances`, :func:`edge_waviness`, :func:`edge_profile`,
  :func:`lateral_amplitude`: Section 1's "lateral artifact", a wave along a
  straight edge.

numpy only.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mesh import Mesh
from ..notation.positions import best_fit_planes, face_planarity

__all__ = [
    "vertex_configurations",
    "face_configurations",
    "canonical_configuration",
    "configuration_counts",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
    "edge_lengths",
    "edge_length_spread",
    "corner_angles",
    "angle_spread",
    "uniformity",
    "face_planarity",
    "planarity",
    "best_fit_planes",
    "region_geometry",
    "crease_angles",
    "BOX_EDGES",
    "edge_profile",
    "lateral_amplitude",
]


# ====================================================================== configurations
def _canonical_rows(seqs: np.ndarray) -> np.ndarray:
    """Lexicographically smallest rotation or reflection of every row.

    Parameters
    ----------
    seqs : (k, n) int

    Returns
    -------
    (k, n) int
    """
    k, n = seqs.shape
    if k == 0:
        return seqs
    idx = (np.arange(n)[:, None] + np.arange(n)[None, :]) % n  # rotations
    cands = np.concatenate([seqs[:, idx], seqs[:, ::-1][:, idx]], axis=1)  # (k, 2n, n)
    order = np.lexsort(cands.transpose(2, 0, 1)[::-1].reshape(n, -1))
    # position of the smallest candidate of every row: rank candidates, take min rank
    rank = np.empty(k * 2 * n, dtype=np.int64)
    rank[order] = np.arange(k * 2 * n)
    best = rank.reshape(k, 2 * n).argmin(axis=1)
    return cands[np.arange(k), best]


def _configurations(
    values: np.ndarray, sizes: np.ndarray, order: np.ndarray, offsets: np.ndarray
) -> list[str]:
    """Canonical cyclic sequences ``values[order[offsets[i]:offsets[i+1]]]`` as strings.

    Parameters
    ----------
    values : (H,) int
        A value per half-edge.
    sizes : (k,) int
        Length of every sequence (``offsets[i+1] - offsets[i]``).
    order : (H,) int
        Half-edges in the order the sequences visit them.
    offsets : (k + 1,) int
    """
    out = np.empty(sizes.size, dtype=object)
    for k in np.unique(sizes):
        rows = np.flatnonzero(sizes == k)
        cols = offsets[rows][:, None] + np.arange(k)[None, :]
        canon = _canonical_rows(values[order[cols]])
        out[rows] = [".".join(map(str, r)) for r in canon.tolist()]
    return out.tolist()


def vertex_configurations(mesh: Mesh) -> list[str]:
    """The vertex configuration of every vertex: face sizes around it, e.g. ``"3.3.4.3.4"``.

    The cyclic sequence of the sizes of the faces met going round the
    vertex, written from its lexicographically smallest rotation or
    reflection (so ``4.3.3.4.3`` and ``3.4.3.4.3`` are both ``3.3.4.3.4``).
    Section 5.1 names the semi-regular regions of Figures 8, 9 and 11 this
    way.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (V,) list of str
        Vertex ``i``'s configuration at position ``i``.
    """
    ring, ring_off = mesh.vertex_ring
    face_size_of_he = mesh.face_sizes[mesh.halfedge_face]
    return _configurations(face_size_of_he, mesh.valences, ring, ring_off)


def face_configurations(mesh: Mesh) -> list[str]:
    """The valences of every face's corners, in order and canonical form.

    A face configuration of a mesh is the vertex configuration of the same
    element of its dual: the pentagons of Figure 8.A have corners of valence
    4.3.3.4.3, the vertices of Figure 8.B are surrounded by a 4.3.3.4.3 ring of
    faces.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (F,) list of str
        Face ``i``'s configuration at position ``i``.
    """
    order = np.arange(mesh.n_halfedges, dtype=np.int64)
    return _configurations(mesh.valences[mesh.corners], mesh.face_sizes, order, mesh.offsets)


def canonical_configuration(config: str | Sequence[int]) -> str:
    """Canonical form of a configuration given in any rotation or reflection.

    Parameters
    ----------
    config : str or sequence of int
        E.g. the paper's ``"4.3.3.4.3"`` or ``[4, 3, 3, 4, 3]``.

    Returns
    -------
    str
        E.g. ``"3.3.4.3.4"``, as :func:`vertex_configurations` writes it.
    """
    seq = [int(x) for x in config.split(".")] if isinstance(config, str) else list(config)
    return ".".join(map(str, _canonical_rows(np.array([seq]))[0].tolist()))


def configuration_counts(configs: Iterable[str]) -> dict[str, int]:
    """``{configuration: count}``, most frequent first (ties by name).

    Parameters
    ----------
    configs : iterable of str
        E.g. the output of :func:`vertex_configurations`.

    Returns
    -------
    dict
        ``{configuration (str): count (int)}``, most frequent first.
    """
    names, counts = np.unique(
        np.asarray(list(configs), dtype=object).astype(str), return_counts=True
    )
    pairs = sorted(zip(names.tolist(), counts.tolist()), key=lambda p: (-p[1], p[0]))
    return {k: int(v) for k, v in pairs}


# ====================================================================== geometry
def radius_spread(mesh: Mesh) -> float:
    """How far a mesh is from round: std / mean of the vertices' distances to their centroid.

    0 when every vertex lies on one sphere around the centroid (a Platonic
    solid); Figure 7's duals make the tetrahedron's dodecahedron rounder.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    float
    """
    r = np.linalg.norm(mesh.vertices - mesh.vertices.mean(axis=0), axis=1)
    return float(r.std() / r.mean())


def normal_angles(mesh: Mesh) -> NDArray[np.float64]:
    """The crease angle of every edge: the angle between the normals of its two faces.

    Uses one half-edge per edge (``edge_halfedge``), its face
    (``halfedge_face``) and its twin's face.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (E,) float
        Degrees; 0 where the two faces are coplanar, 90 on a cube's edges.
    """
    h = mesh.edge_halfedge
    f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
    n = mesh.face_normals
    cos = np.einsum("ij,ij->i", n[f], n[g])
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def ray_distances(mesh: Mesh, origins: ArrayLike, direction: ArrayLike) -> NDArray[np.float64]:
    """Distance from every origin to the farthest crossing of the mesh along ``direction``.

    Every face is fanned from its centroid (one triangle per half-edge) and
    all rays are intersected with all triangles at once (Moller-Trumbore).

    Parameters
    ----------
    mesh : Mesh
    origins : (k, 3) float
        Points inside the mesh.
    direction : (3,) float
        Unit direction of the rays.

    Returns
    -------
    (k,) float
        NaN where a ray misses.
    """
    d = np.asarray(direction, dtype=np.float64)
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    a = mesh.face_centroids[mesh.halfedge_face]
    e1 = mesh.vertices[mesh.corners] - a
    e2 = mesh.vertices[mesh.head] - a
    pvec = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, pvec)
    good = np.abs(det) > 1e-14
    a, e1, e2, pvec, det = a[good], e1[good], e2[good], pvec[good], det[good]
    tvec = o[:, None, :] - a[None]  # (k, T, 3)
    u = np.einsum("ktj,tj->kt", tvec, pvec) / det
    q = np.cross(tvec, e1[None])
    v = (q @ d) / det
    t = np.einsum("tj,ktj->kt", e2, q) / det
    eps = 1e-9
    hit = (u >= -eps) & (v >= -eps) & (u + v <= 1 + eps) & (t > 0)
    return np.where(hit.any(axis=1), np.where(hit, t, -np.inf).max(axis=1), np.nan)


def edge_waviness(
    mesh: Mesh,
    start: ArrayLike = (-0.5, 0.0, 0.0),
    end: ArrayLike = (0.5, 0.0, 0.0),
    direction: ArrayLike = (0.0, 1.0, 1.0),
    samples: int = 41,
) -> float:
    """How much a surface wobbles along a straight edge (Section 1's "lateral artifact").

    Rays leave ``samples`` evenly spaced points of the segment ``start`` ->
    ``end`` in ``direction``; the result is the range of the distances at
    which they leave the mesh (:func:`ray_distances`).  The defaults probe
    the middle half of the edge ``y = z = 1`` of a cube ``[-1, 1]^3``: the
    rays start on the cube's x axis (parallel to the edge) and point along
    the edge's bisecting direction.  A surface without a wave pattern along
    the edge keeps that distance constant (0).

    Parameters
    ----------
    mesh : Mesh
    start, end : (3,) float
        The segment the rays start from, inside the mesh and parallel to the edge.
    direction : (3,) float
        Direction of the rays (need not be unit length).
    samples : int
        Number of rays.

    Returns
    -------
    float
        ``max - min`` of the distances (in the mesh's units).
    """
    s, e = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    d = np.asarray(direction, dtype=float)
    t = np.linspace(0.0, 1.0, samples)[:, None]
    dist = ray_distances(mesh, s + t * (e - s), d / np.linalg.norm(d))
    return float(np.nanmax(dist) - np.nanmin(dist))


# ====================================================================== uniformity
def edge_lengths(mesh: Mesh) -> NDArray[np.float64]:
    """The length of every edge.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (E,) float
        Edge ``e`` from its half-edge ``edge_halfedge[e]``.
    """
    h = mesh.edge_halfedge
    return np.linalg.norm(mesh.vertices[mesh.head[h]] - mesh.vertices[mesh.corners[h]], axis=1)


def _face_edges(mesh: Mesh, faces: ArrayLike | None) -> NDArray[np.int64]:
    """The edges of ``faces`` (every edge once), or of the whole mesh."""
    if faces is None:
        return np.arange(mesh.n_edges, dtype=np.int64)
    hs = _face_halfedges(mesh, faces)
    return np.unique(mesh.halfedge_edge[hs])


def _face_halfedges(mesh: Mesh, faces: ArrayLike | None) -> NDArray[np.int64]:
    """The half-edges of ``faces`` (all of them when None)."""
    if faces is None:
        return np.arange(mesh.n_halfedges, dtype=np.int64)
    f = np.asarray(faces, dtype=np.int64).reshape(-1)
    if f.size and (f.min() < 0 or f.max() >= mesh.n_faces):
        raise ValueError(f"face index out of range 0..{mesh.n_faces - 1}")
    return np.flatnonzero(np.isin(mesh.halfedge_face, f))


def _spread(x: np.ndarray) -> float:
    """std / mean (0 for an empty or constant array)."""
    if x.size == 0:
        return 0.0
    return float(x.std() / x.mean())


def edge_length_spread(mesh: Mesh, faces: ArrayLike | None = None) -> float:
    """How unequal the edges are: std / mean of the edge lengths.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Only the edges of these faces (each edge once).

    Returns
    -------
    float
        0 when every edge has the same length (a Platonic solid).  Does not
        change with the mesh's position or scale.
    """
    return _spread(edge_lengths(mesh)[_face_edges(mesh, faces)])


def corner_angles(mesh: Mesh) -> NDArray[np.float64]:
    """The angle of every face at every corner.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (H,) float
        Degrees; the angle at the corner ``corners[h]`` of face
        ``halfedge_face[h]`` between its edges to the next and the previous
        corner.  A planar n-gon's angles add up to ``(n - 2) 180``.
    """
    v = mesh.vertices
    p = v[mesh.corners]
    a = v[mesh.head] - p
    b = v[mesh.corners[mesh.prev]] - p
    cos = np.einsum("ij,ij->i", a, b) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def angle_spread(mesh: Mesh, faces: ArrayLike | None = None, by: str = "size") -> float:
    """How unequal the corner angles are within their kind, over the mean angle.

    Corners are grouped by the size of their face (``by="size"``: a regular
    solid's faces are regular polygons) or by the valence of their vertex
    (``by="valence"``: in a classical tiling such as Section 5.1's
    4.3.3.4.3, the angle at a corner depends on its valence).  The result is
    the root mean square of every angle's deviation from its group's mean,
    divided by the mean of all the angles.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Only the corners of these faces.
    by : {"size", "valence"}

    Returns
    -------
    float
        0 when the angles within every group are equal.
    """
    if by not in ("size", "valence"):
        raise ValueError(f"by must be 'size' or 'valence', got {by!r}")
    hs = _face_halfedges(mesh, faces)
    if hs.size == 0:
        return 0.0
    ang = corner_angles(mesh)[hs]
    key = (
        mesh.face_sizes[mesh.halfedge_face[hs]] if by == "size" else mesh.valences[mesh.corners[hs]]
    )
    _, inv = np.unique(key, return_inverse=True)
    means = np.bincount(inv, weights=ang) / np.bincount(inv)
    dev = ang - means[inv]
    return float(np.sqrt(np.mean(dev**2)) / ang.mean())


def uniformity(mesh: Mesh) -> dict[str, float]:
    """The three spreads of Figure 7's "more and more uniform".

    Parameters
    ----------
    mesh : Mesh
        A closed manifold polygon mesh.

    Returns
    -------
    dict
        ``"edge"``: :func:`edge_length_spread`; ``"angle"``:
        :func:`angle_spread` (corners grouped by face size); ``"radius"``:
        :func:`radius_spread`.  Each is 0 on a Platonic solid.
    """
    return {
        "edge": edge_length_spread(mesh),
        "angle": angle_spread(mesh),
        "radius": radius_spread(mesh),
    }


# ====================================================================== flatness
def planarity(mesh: Mesh) -> float:
    """The largest distance of a corner from its face's best-fit plane,
    over the mesh's mean edge length (0 when every face is planar).

    The measure of issue 10: the paper's meshes after two duals (Figures 1B,
    9A, 12B) are 6-15 % of an edge length off; canonical positions
    (:func:`pentanb.canonical`) and :func:`pentanb.planarize` bring it to
    rounding level.

    Parameters
    ----------
    mesh : Mesh
        A closed manifold polygon mesh.

    Returns
    -------
    float, >= 0
        0 when every face is planar.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.analysis import planarity
    >>> planarity(pentanb.shapes.cube())
    0.0
    """
    return float(face_planarity(mesh).max(initial=0.0))


def region_geometry(mesh: Mesh, faces: ArrayLike) -> dict[str, object]:
    """The geometry of a set of faces, e.g. Section 5.1's 4.3.3.4.3 regions.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int
        The faces of the region.

    Returns
    -------
    dict
        ``"faces"``: k; ``"edge_spread"``: :func:`edge_length_spread` of
        their edges; ``"angle_spread"``: :func:`angle_spread` of their
        corners grouped by the corners' valence; ``"planarity"``: the
        largest distance of a corner from its face's least-squares plane,
        over the mean length of the region's edges; ``"angles"``: ``{valence:
        mean corner angle in degrees}``.  (A flat classical tiling of
        congruent faces has angle spread and planarity 0; its edge spread
        is that of its tile, see :data:`pentanb.figures.claim.CLASSICAL`.)
    """
    f = np.asarray(faces, dtype=np.int64).reshape(-1)
    if f.size == 0:
        raise ValueError("region_geometry needs at least one face")
    hs = _face_halfedges(mesh, f)
    edges = np.unique(mesh.halfedge_edge[hs])
    mean_len = float(edge_lengths(mesh)[edges].mean())
    mesh_len = float(
        np.linalg.norm(mesh.vertices[mesh.head] - mesh.vertices[mesh.corners], axis=1).mean()
    )
    flat = face_planarity(mesh)[f] * mesh_len / mean_len
    ang = corner_angles(mesh)[hs]
    val = mesh.valences[mesh.corners[hs]]
    return {
        "faces": int(f.size),
        "edge_spread": edge_length_spread(mesh, f),
        "angle_spread": angle_spread(mesh, f, by="valence"),
        "planarity": float(flat.max()),
        "angles": {int(k): float(ang[val == k].mean()) for k in np.unique(val)},
    }


# ====================================================================== creases
def crease_angles(mesh: Mesh, marked: ArrayLike) -> dict[str, float]:
    """The largest crease angle at some vertices, and elsewhere.

    Parameters
    ----------
    mesh : Mesh
    marked : (V,) bool or (k,) int
        The vertices to look at (Section 7's G1 question is decided at the
        extraordinary vertices): an edge is "at" them when one of its ends
        is marked, so its crease angle is one between two faces around a
        marked vertex.

    Returns
    -------
    dict
        ``"at"``: the largest :func:`normal_angles` of the edges at the
        marked vertices, ``"elsewhere"``: of all the other edges (NaN where
        there is no such edge); degrees.
    """
    m = np.asarray(marked)
    if m.dtype == bool:
        if m.shape != (mesh.n_vertices,):
            raise ValueError(f"marked must have one entry per vertex ({mesh.n_vertices})")
    else:
        idx = m.astype(np.int64).reshape(-1)
        if idx.size and (idx.min() < 0 or idx.max() >= mesh.n_vertices):
            raise ValueError(f"marked vertex out of range 0..{mesh.n_vertices - 1}")
        m = np.zeros(mesh.n_vertices, dtype=bool)
        m[idx] = True
    ends = mesh.edges
    at = m[ends[:, 0]] | m[ends[:, 1]]
    a = normal_angles(mesh)
    return {
        "at": float(a[at].max()) if at.any() else float("nan"),
        "elsewhere": float(a[~at].max()) if (~at).any() else float("nan"),
    }


# ====================================================================== lateral artifact
#: The 12 edges of the box ``[-1, 1]^3``: ``(axis, s1, s2)``, the edge runs along
#: ``axis`` where the two other coordinates (in increasing order) are ``s1`` and ``s2``.
BOX_EDGES: tuple[tuple[int, int, int], ...] = tuple(
    (axis, s1, s2) for axis in range(3) for s1 in (1, -1) for s2 in (1, -1)
)


def _near_segments(mesh: Mesh, half: float) -> list[tuple[np.ndarray, ...]]:
    """For every edge of :data:`BOX_EDGES`, the segments of the surface
    :func:`ray_distances` sees (every face fanned from its centroid: the faces'
    sides and the spokes centroid -> corner) of the faces that reach near it.

    Returns
    -------
    list of 6-tuples of (s,) float
        One per box edge: ``(xa, ua, wa, xb, ub, wb)``, the two ends of every
        segment in coordinates turned to (along the edge, towards its first
        face, towards its second face).
    """
    v = mesh.vertices
    tail, head, hf = mesh.corners, mesh.head, mesh.halfedge_face
    offsets = mesh.offsets
    starts = offsets[:-1]
    # per half-edge: its tail, its head, its face's centroid; one column each
    cols = [np.ascontiguousarray(v[tail, k]) for k in range(3)]
    cols += [np.ascontiguousarray(v[head, k]) for k in range(3)]
    cols += [np.ascontiguousarray(mesh.face_centroids[hf, k]) for k in range(3)]
    lim = 0.6 * half
    # which faces reach past +-lim along x, y, z
    reach = {}
    for k in range(3):
        reach[k, 1] = np.maximum.reduceat(cols[k], starts) > lim
        reach[k, -1] = np.minimum.reduceat(cols[k], starts) < -lim
    out = []
    for axis, s1, s2 in BOX_EDGES:
        i, j = (k for k in range(3) if k != axis)
        faces = np.flatnonzero(reach[i, s1] & reach[j, s2])
        sizes = offsets[faces + 1] - offsets[faces]
        # the half-edges of those faces: offsets[f] .. offsets[f + 1] - 1, in a row
        first = np.repeat(offsets[faces] - np.cumsum(sizes) + sizes, sizes)
        hs = first + np.arange(int(sizes.sum()))
        ends = []
        for k, sign in ((axis, 1), (i, s1), (j, s2)):  # sides tail -> head, spokes centroid -> tail
            ends.append(sign * np.concatenate([cols[k][hs], cols[6 + k][hs]]))
        for k, sign in ((axis, 1), (i, s1), (j, s2)):
            ends.append(sign * np.concatenate([cols[3 + k][hs], cols[k][hs]]))
        out.append(tuple(ends))
    return out


def _profile(near: tuple[np.ndarray, ...], angle: float) -> tuple[np.ndarray, np.ndarray]:
    """(x, r) where the segments ``near`` (from :func:`_near_segments`) cross the
    half-plane at ``angle`` degrees from the edge's first face."""
    xa, ua, wa, xb, ub, wb = near
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    da, db = c * wa - s * ua, c * wb - s * ub  # signed distances from the plane
    cross = np.flatnonzero((da > 0) != (db > 0))
    da, db = da[cross], db[cross]
    t = da / (da - db)
    x = xa[cross] + t * (xb[cross] - xa[cross])
    ra = c * ua[cross] + s * wa[cross]
    r = ra + t * (c * ub[cross] + s * wb[cross] - ra)
    keep = r > 0
    order = np.argsort(x[keep], kind="stable")
    return x[keep][order], r[keep][order]


def edge_profile(
    mesh: Mesh,
    edge: tuple[int, int, int] = (0, 1, 1),
    angle: float = 45.0,
    half: float = 1.0,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The distance of a smoothed box's surface from an edge's axis, along the edge.

    The half-plane that holds the axis of the box ``[-half, half]^3``
    parallel to ``edge`` and makes the angle ``angle`` with the first of the
    edge's faces (45 degrees: the plane through the edge itself) cuts the
    surface in a curve; this is that curve, as the points where it crosses
    the surface's edges, ``(x, r)``: position along the edge and distance
    from the axis.  The surface is the one :func:`ray_distances` sees (every
    face fanned from its centroid), so ``r`` at ``x`` is the distance a ray
    from the axis would measure.  Along a straight edge without a wave
    (Section 1's "lateral artifact"), ``r`` is constant away from the
    corners.

    Parameters
    ----------
    mesh : Mesh
        A smoothed box, centred at the origin, with its edges along the axes.
    edge : (axis, s1, s2)
        One of :data:`BOX_EDGES`.
    angle : float
        Degrees, from 35 to 55 (the plane must cut the surface within
        0.6 ``half`` of the edge on both sides).
    half : float
        Half the box's size.

    Returns
    -------
    x, r : (k,) float
        Sorted by ``x``; the curve is straight between its points.  At the
        ends (``|x|`` near ``half``) the plane also cuts the box's end faces;
        :func:`lateral_amplitude` measures away from them.
    """
    if not 35.0 <= angle <= 55.0:
        raise ValueError(f"angle must be from 35 to 55 degrees, got {angle}")
    if tuple(edge) not in BOX_EDGES:
        raise ValueError(f"edge must be one of BOX_EDGES, got {edge!r}")
    return _profile(_near_segments(mesh, half)[BOX_EDGES.index(tuple(edge))], angle)


def lateral_amplitude(
    mesh: Mesh,
    window: float,
    angles: Sequence[float] = (40.0, 45.0, 50.0),
    half: float = 1.0,
) -> NDArray[np.float64]:
    """The wave along every straight edge of a smoothed box (Section 1's "lateral artifact").

    For each of the box's 12 edges and each angle, the peak-to-peak
    variation of :func:`edge_profile` over ``|x| <= window`` (away from the
    box's corners, whose rounding is not a wave); the largest over the
    angles.  The default angles cut the rounded edge through its middle
    (45 degrees) and on either side of it, where a wave that sways sideways
    shows too.  A box whose edges stay straight gives 0; a wave pattern along
    the edge gives its peak-to-peak height, in the mesh's units.

    Parameters
    ----------
    mesh : Mesh
        A smoothed box ``[-half, half]^3`` (centred, edges along the axes).
    window : float
        Half the length of the stretch measured, in the mesh's units
        (``0 < window < half``).
    angles : sequence of float
        Degrees (see :func:`edge_profile`).
    half : float

    Returns
    -------
    (12,) float
        One value per edge of :data:`BOX_EDGES`.
    """
    if not 0.0 < window < half:
        raise ValueError(f"window must be in (0, {half}), got {window}")
    for angle in angles:
        if not 35.0 <= angle <= 55.0:
            raise ValueError(f"angles must be from 35 to 55 degrees, got {angle}")
    out = np.zeros(len(BOX_EDGES))
    for k, (edge, near) in enumerate(zip(BOX_EDGES, _near_segments(mesh, half))):
        for angle in angles:
            x, r = _profile(near, angle)
            r = r[np.abs(x) <= window]
            if r.size < 2:
                raise ValueError(
                    f"the surface does not cross edge {edge}'s {angle}-degree plane "
                    f"within |x| <= {window}: not a box [-{half}, {half}]^3?"
                )
            out[k] = max(out[k], float(np.ptp(r)))
    return out
