"""The element and its neighbourhood: the test mesh it is planted in, one step
with its matrices, the element followed through it, and the canonical order
around it.

The element is planted in a small closed mesh (:func:`pyramid`: its apex is a
``size``-valent vertex and its base a ``size``-gon), which is subdivided level
after level.  The element is followed through every step by the rules
themselves (:func:`element_fate`): a vertex survives a remeshing when its row
of the remeshing matrix is a unit row, a face when a new face of the same size
has the same centroid; a dual swaps the two.  Around the element, the vertices
are put in a canonical order by a breadth-first walk that follows the faces
counter-clockwise from a chosen starting half-edge (:func:`_walk`); two levels
*match* when these walks see the same connectivity.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ... import _checks
from ...memory import default_max_bytes, mesh_bytes, readable
from ...mesh import Mesh
from ...notation import seeds
from ...subdivision import get_scheme
from ..subdivision_matrix import dual_matrix, remesh_matrix

__all__ = [
    "KINDS",
    "element_fate",
    "pyramid",
]

KINDS = ("vertex", "face")

#: Most duals after each remeshing (the paper's smoothing takes 2).
MAX_DUALS = 64


# ---------------------------------------------------------------------------
# the test mesh and one step with its matrices
# ---------------------------------------------------------------------------


def pyramid(size: int) -> Mesh:
    """The pyramid ``Y<size>`` (:func:`pentanb.notation.pyramid`), renumbered and
    perturbed: the mesh in which the elements are planted.

    The apex is lifted off-centre and the base ring is slightly irregular, so
    that no accidental symmetry of the positions hides a mode.

    Parameters
    ----------
    size : int >= 3
        The valence of the apex and the number of sides of the base.

    Returns
    -------
    Mesh
        ``size + 1`` vertices: the apex (vertex 0), then the base ring;
        ``size + 1`` faces: the triangles ``(0, 1 + i, 1 + (i + 1) % size)``,
        then the base (face ``size``).

    Raises
    ------
    ValueError
        ``size`` is not an integer >= 3.
    """
    k = _check_size(size)
    seed = seeds.pyramid(k)  # ring 0 .. k - 1, apex k; faces: the base, then (i, i + 1, k)
    label = (np.arange(k + 1) + 1) % (k + 1)  # seed vertex -> here: the apex first
    tris = label[seed.corners[k:].reshape(k, 3)][:, [2, 0, 1]]  # each from the apex
    base = label[seed.corners[:k]]
    t = 2 * np.pi * np.arange(k) / k
    r = 1.0 + 0.05 * np.cos(3 * t + 0.3)
    ring = np.stack([r * np.cos(t), r * np.sin(t), 0.1 * np.sin(2 * t + 0.7)], axis=1)
    apex = np.array([[0.07, -0.04, 1.1]])
    return Mesh(np.concatenate([apex, ring]), [*tris.tolist(), base.tolist()])


def _check_size(size) -> int:
    return _checks.count(size, "size", 3)


def _refuse_pyramid(size: int, max_faces: int | None = None) -> None:
    """Refuse, before building it, a pyramid of more than ``max_faces`` faces or
    more than the memory available (a ValueError naming ``size``)."""
    if max_faces is not None and size + 1 > max_faces:
        raise ValueError(
            f"size={size:,}: the pyramid it is planted in has {size + 1:,} faces, over "
            f"max_faces={max_faces:,}"
        )
    need, limit = mesh_bytes(size + 1, 2 * size, size + 1), default_max_bytes()
    if need > limit:
        raise ValueError(
            f"size={size:,}: the pyramid it is planted in needs {readable(need)}, over the "
            f"memory available ({readable(limit)})"
        )


def _check_kind(kind) -> str:
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    return str(kind)


@dataclass
class _Step:
    """One level of the hierarchy: ``S`` maps this level's positions to the next."""

    mesh: Mesh
    S: Any = None  # (V_next, V) sparse
    element: tuple[str, int] | None = None  # on this mesh


def _track(element, mesh: Mesh, remeshed: Mesh, R) -> tuple[str, int] | None:
    """Where an element of ``mesh`` is in ``remeshed`` (None if it does not survive)."""
    kind, i = element
    R = R.tocsr()
    if kind == "vertex":
        col = R[:, [i]].tocsc()
        rows = col.indices[np.isclose(col.data, 1.0, rtol=0, atol=1e-14)]
        for r in rows:
            if R.indptr[r + 1] - R.indptr[r] == 1:
                return ("vertex", int(r))
        return None
    # a face survives as a new face of the same size with the same centroid
    n = int(mesh.face_sizes[i])
    verts = mesh.corners[mesh.offsets[i] : mesh.offsets[i + 1]]
    C = (dual_matrix(remeshed) @ R).tocsc()
    sub = C[:, verts].tocsr()
    cand = np.flatnonzero(remeshed.face_sizes == n)
    nnz_all = np.diff(C.tocsr().indptr)
    for g in cand:
        row = sub[g].toarray().ravel()
        if nnz_all[g] == n and np.allclose(row, 1.0 / n, rtol=0, atol=1e-13):
            return ("face", int(g))
    return None


def element_fate(scheme, kind: str, size: int, **options) -> str:
    """What one remeshing makes of a ``size``-valent vertex or a ``size``-gon.

    Returns
    -------
    str
        ``"vertex k"`` / ``"face n"`` for the element that keeps its place
        (a kept vertex, a face copy about the same centroid), or, when it
        does not survive, what takes its place (e.g. ``"becomes a vertex of
        valence 5"`` for a face whose centroid becomes a vertex).
    """
    kind = _check_kind(kind)
    size = _check_size(size)
    s = get_scheme(scheme)
    mesh = pyramid(size)
    element = ("vertex", 0) if kind == "vertex" else ("face", size)
    R, out = remesh_matrix(mesh, s, **options)
    found = _track(element, mesh, out, R)
    if found is not None:
        k, j = found
        n = int(out.valences[j]) if k == "vertex" else int(out.face_sizes[j])
        return f"{k} {n}"
    R = R.tocsr()
    if kind == "face":
        verts = mesh.corners[mesh.offsets[size] : mesh.offsets[size + 1]]
        target = np.zeros(mesh.n_vertices)
        target[verts] = 1.0 / size
        for r in range(out.n_vertices):
            if np.allclose(R[r].toarray().ravel(), target, atol=1e-13):
                return f"becomes a vertex of valence {int(out.valences[r])}"
        return "does not survive"
    # a vertex whose place is taken by a face: every corner of the face
    # leans most on the vertex
    dense = R.toarray()
    best = dense.max(axis=1)
    leans = dense[:, 0] >= best - 1e-13
    for g in range(out.n_faces):
        corners = out.corners[out.offsets[g] : out.offsets[g + 1]]
        if leans[corners].all() and dense[corners, 0].min() > 0:
            return f"becomes a face of {int(out.face_sizes[g])} sides"
    return "does not survive"


# ---------------------------------------------------------------------------
# canonical order around an element
# ---------------------------------------------------------------------------


@dataclass
class _Walk:
    verts: NDArray[np.int64]  # mesh vertex ids, in discovery order
    level: NDArray[np.float64]  # half-ring level of each (0, 0.5, 1, 1.5, ...)
    signature: tuple


def _starts(mesh: Mesh, element) -> list[int]:
    """The element's half-edges in rotation order (its possible starts)."""
    kind, i = element
    if kind == "vertex":
        ring, off = mesh.vertex_ring
        return [int(h) for h in ring[off[i] : off[i + 1]]]
    return list(range(int(mesh.offsets[i]), int(mesh.offsets[i + 1])))


class _Topo:
    """Python lists of a mesh's half-edge arrays (fast scalar access for walks)."""

    def __init__(self, mesh: Mesh):
        ring, off = mesh.vertex_ring
        self.ring = ring.tolist()
        self.off = off.tolist()
        self.nxt = mesh.next.tolist()
        self.tail = mesh.corners.tolist()
        self.size = mesh.face_sizes[mesh.halfedge_face].tolist()

    def rotated(self, u: int, g: int) -> list[int]:
        hs = self.ring[self.off[u] : self.off[u + 1]]
        j = hs.index(g)
        return hs[j:] + hs[:j]


def _walk(topo: _Topo, element, start: int, depth: int) -> _Walk:
    """Breadth-first walk over faces from ``element`` and half-edge ``start``.

    Every vertex at face distance < ``depth`` is processed: its outgoing
    half-edges, counter-clockwise from the one it was entered by, and the
    faces they bound, corner after corner.  The signature records, for every
    processed vertex, the discovery number of each neighbour and the size of
    each face: two walks with equal signatures see the same connectivity.
    """
    kind, i = element
    order: dict[int, int] = {}
    entry: list[int] = []
    dist: list[int] = []
    edge_near: list[bool] = []
    verts: list[int] = []

    def discover(w: int, h: int, d: int) -> None:
        order[w] = len(verts)
        verts.append(w)
        entry.append(h)
        dist.append(d)
        edge_near.append(False)

    if kind == "vertex":
        discover(i, start, 0)
    else:
        h = start
        while True:
            discover(topo.tail[h], h, 0)
            h = topo.nxt[h]
            if h == start:
                break
    record = []
    q = deque(range(len(verts)))
    while q:
        a = q.popleft()
        if dist[a] >= depth:
            continue
        u = verts[a]
        rec = []
        for h in topo.rotated(u, entry[a]):
            g = topo.nxt[h]
            w = topo.tail[g]
            if w not in order:
                discover(w, g, dist[a] + 1)
                q.append(len(verts) - 1)
            b = order[w]
            if dist[b] == dist[a] + 1:
                edge_near[b] = True
            rec.append((b, topo.size[h]))
            g = topo.nxt[g]
            while g != h:
                w = topo.tail[g]
                if w not in order:
                    discover(w, g, dist[a] + 1)
                    q.append(len(verts) - 1)
                g = topo.nxt[g]
        record.append(tuple(rec))
    level = np.array(
        [d - 0.5 if (d > 0 and near) else float(d) for d, near in zip(dist, edge_near)]
    )
    return _Walk(np.array(verts, dtype=np.int64), level, tuple(record))
