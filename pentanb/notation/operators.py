"""Conway's operators: the functions, and the table of every letter (:data:`OPERATORS`).

The paper's pentagonalization is Conway's *gyro* and its comparison schemes
are *expand* (corner cutting), *ortho* (vertex insertion), *chamfer* (hexagon
preservation), *zip* (honeycomb), *subdivide* (Loop's remeshing) and
*needle* (the sqrt(3) remeshing): those letters call those functions, with
the count formulas of :data:`pentanb.SCHEMES` (written there once).  This
module adds the rest of Conway's and Hart's set (Hart, "Conway notation for
polyhedra", and the extended set of Antiprism's ``conway``), written like
the other remeshings: whole-array numpy over the input's half-edges,
outputs valid by construction.

Positions follow the package's conventions: old vertices stay where they
are, new points sit at fixed fractions of edges (midpoints, thirds) or at
face centroids (the plain mean of a face's vertices).  They are a starting
point, not the literature's geometry: Hart and Antiprism put the results in
canonical form (:func:`pentanb.canonical`), which depends only on the
topology.

=============  ==========  ====================================
function       letter      new positions
=============  ==========  ====================================
``ambo``       a           edge midpoints
``truncate``   t, tN       ``ratio`` (1/3) along each edge
``kis``        k, kN       face centroids (flat pyramids)
``join``       j           face centroids
``snub``       s           ``dual(pentagonalize(mesh))``
``propeller``  p           edge thirds (as pentagonalize)
``whirl``      w           edge thirds; 1/3 from centroid
``meta``       m           midpoints and centroids
``bevel``      b           ``truncate(ambo(mesh))``
``reflect``    r           mirror image (x -> -x)
=============  ==========  ====================================

Every letter's count formula, ``(V', E', F')`` from the input's
``(V, E, F)``, is ``OPERATORS[letter].counts`` (as text:
``OPERATORS[letter].formula``).  For ``tN`` and ``kN`` only the N-valent
vertices or N-sided faces are cut or raised; the counts then depend on how
many there are (:meth:`Operator.counts_on`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from .. import _checks
from ..mesh import Mesh, check_closed, check_mesh
from ..schemes import pentagonal
from ..schemes._build import (
    concat_faces,
    edge_points,
    fixed_size,
    halfedge_edge_point,
    output,
)
from ..schemes.registry import SCHEMES, Counts, count_formula
from ..schemes.smoothing import dual
from ..schemes.table import Table

__all__ = [
    "ambo",
    "truncate",
    "kis",
    "join",
    "snub",
    "propeller",
    "whirl",
    "meta",
    "bevel",
    "reflect",
    "Invariants",
    "Operator",
    "OPERATORS",
]


def _check_sides(n, what: str) -> int | None:
    """``None`` or an integer >= 3 (a face size or a valence)."""
    if n is None:
        return None
    return _checks.count(n, what, 3)


#: ambo: the midpoints; every face's copy through them, a face round every vertex.
AMBO = Table(
    "ambo", vertices=False, edge_points=(0.5,), faces=(("face", ("E0",)), ("vertex", ("E0",)))
)
#: kis: a flat pyramid (u, w, c_f) on every half-edge.
KIS = Table("kis", face_points=True, faces=(("halfedge", ("V", "n:V", "F")),))
#: join: a quad (u, c_g, w, c_f) across every edge.
JOIN = Table("join", face_points=True, faces=(("edge", ("V", "t:F", "n:V", "F")),))
#: propeller: the face's inner n-gon through t1, a quad (t1, t2, w, t1') per half-edge.
PROPELLER = Table(
    "propeller",
    edge_points=(1 / 3, 2 / 3),
    faces=(("face", ("E0",)), ("halfedge", ("E0", "E1", "n:V", "n:E0"))),
)


def ambo(mesh: Mesh) -> Mesh:
    """Conway's ambo ``a`` (rectification): a vertex at every edge midpoint.

    Every n-gon gives the n-gon of its edge midpoints and every k-valent
    vertex the k-gon of the midpoints around it; every new vertex is
    4-valent.  ``aC`` is the cuboctahedron, ``aT`` the octahedron.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces.

    Returns
    -------
    Mesh
        E vertices (edge ``e``'s midpoint is vertex ``e``), 2E edges,
        F + V faces: the face copies in the input's order, then one face per
        vertex (its outgoing edges counter-clockwise).
    """
    check_closed(mesh, "ambo")
    return AMBO(mesh)


def truncate(mesh: Mesh, n: int | None = None, ratio: float = 1.0 / 3.0) -> Mesh:
    """Conway's truncate ``t`` (``tN``: only the N-valent vertices).

    Every cut vertex is replaced by the polygon of the points at ``ratio``
    of the way along its edges; each face keeps its uncut corners and gets
    two points for every cut one.  ``tI`` is the truncated icosahedron
    (with ``ratio = 1/3`` the regular one: 12 regular pentagons, 20 regular
    hexagons), ``t = dkd``.

    Parameters
    ----------
    mesh : Mesh
    n : int >= 3, optional
        Cut only the vertices of valence ``n`` (all when None).
    ratio : float in (0, 1/2)
        Where a cut crosses an edge, from the cut vertex.

    Returns
    -------
    Mesh
        With every vertex cut: 2E vertices, 3E edges, F + V faces.  With
        ``n``: V + (n - 1) V_n vertices, E + n V_n edges, F + V_n faces
        (``V_n`` the number of n-valent vertices).  Vertices: the uncut old
        vertices in order, then one point per half-edge leaving a cut
        vertex; faces: the old faces in order, then one per cut vertex.
    """
    check_closed(mesh, "truncate")
    n = _check_sides(n, "truncate's valence n")
    r = _check_ratio(ratio)
    cut = np.ones(mesh.n_vertices, dtype=bool) if n is None else mesh.valences == n
    if not cut.any():
        return mesh
    tail, head = mesh.corners, mesh.head
    kept = np.flatnonzero(~cut)
    new_id = np.empty(mesh.n_vertices, dtype=np.int64)
    new_id[kept] = np.arange(kept.size, dtype=np.int64)
    from_cut = cut[tail]  # half-edges leaving a cut vertex get a point
    point = np.full(mesh.n_halfedges, -1, dtype=np.int64)
    point[from_cut] = kept.size + np.arange(int(from_cut.sum()), dtype=np.int64)
    # old face: each uncut corner stays; a cut corner (tail of h) becomes the
    # point on the incoming edge, then the point on h
    first = np.where(from_cut, point[mesh.twin[mesh.prev]], new_id[tail])
    pairs = np.stack([first, point], axis=1)
    keep = np.stack([np.ones_like(from_cut), from_cut], axis=1)
    face_corners = pairs[keep]
    sizes = np.add.reduceat(1 + from_cut.astype(np.int64), mesh.offsets[:-1])
    face_off = np.concatenate([[0], np.cumsum(sizes)])
    # one face per cut vertex, its points counter-clockwise
    ring, _ = mesh.vertex_ring
    ring_cut = np.repeat(cut, mesh.valences)
    vert_corners = point[ring[ring_cut]]
    vert_off = np.concatenate([[0], np.cumsum(mesh.valences[cut])])
    corners, offsets = concat_faces((face_corners, face_off), (vert_corners, vert_off))
    v = mesh.vertices
    h = np.flatnonzero(from_cut)
    points = v[tail[h]] + r * (v[head[h]] - v[tail[h]])
    return output(np.concatenate([v[kept], points]), corners, offsets)


def _check_ratio(ratio: float) -> float:
    try:
        r = float(ratio)
    except (TypeError, ValueError):
        raise ValueError(f"ratio must be a number in (0, 1/2), got {ratio!r}") from None
    if not (0.0 < r < 0.5):
        raise ValueError(f"ratio must be in (0, 1/2), got {ratio!r}")
    return r


def kis(mesh: Mesh, n: int | None = None) -> Mesh:
    """Conway's kis ``k`` (``kN``: only the N-sided faces): a pyramid on every face.

    A vertex at each chosen face's centroid, joined to the face's corners.
    With the package's convention the apex stays *in* the face (the
    pyramids are flat); :func:`pentanb.canonical` raises them.  ``kD`` is
    the pentakis dodecahedron, ``k = dtd``.

    Parameters
    ----------
    mesh : Mesh
    n : int >= 3, optional
        Raise pyramids only on the ``n``-sided faces (all when None).

    Returns
    -------
    Mesh
        With every face: V + F vertices, 3E edges, 2E triangles.  With
        ``n``: V + F_n vertices, E + n F_n edges, F + (n - 1) F_n faces.
        Vertices: the old ones, then one centroid per chosen face; faces:
        the other faces in order, then one triangle ``(u, w, c_f)`` per
        half-edge of each chosen face.
    """
    check_closed(mesh, "kis")
    n = _check_sides(n, "kis's face size n")
    if n is None:
        return KIS(mesh)
    chosen = np.ones(mesh.n_faces, dtype=bool) if n is None else mesh.face_sizes == n
    if not chosen.any():
        return mesh
    faces = np.flatnonzero(chosen)
    apex = np.full(mesh.n_faces, -1, dtype=np.int64)
    apex[faces] = mesh.n_vertices + np.arange(faces.size, dtype=np.int64)
    hf = mesh.halfedge_face
    fan = chosen[hf]
    h = np.flatnonzero(fan)
    tris = np.stack([mesh.corners[h], mesh.head[h], apex[hf[h]]], axis=1)
    other = np.flatnonzero(~chosen)
    kept = mesh.corners[~fan]
    kept_off = np.concatenate([[0], np.cumsum(mesh.face_sizes[other])])
    corners, offsets = concat_faces((kept, kept_off), fixed_size(tris))
    vertices = np.concatenate([mesh.vertices, mesh.face_centroids[faces]])
    return output(vertices, corners, offsets)


def join(mesh: Mesh) -> Mesh:
    """Conway's join ``j``: a quad across every edge, joining its ends and its faces' centres.

    ``jX`` is ``kX`` without the old edges (``j = da``); ``jC`` is the
    rhombic dodecahedron, ``jT`` the cube.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        V + F vertices (old, then face centroids), 2E edges, E quads: edge
        ``e`` with ends ``u < w`` gives ``(u, c_g, w, c_f)`` where f lies to
        the left of ``u -> w``.
    """
    check_closed(mesh, "join")
    return JOIN(mesh)


def snub(mesh: Mesh) -> Mesh:
    """Conway's snub ``s = dg``: the dual of pentagonalization (gyro).

    Every face becomes a smaller twisted copy, every vertex a face, every
    edge two triangles; every vertex is 5-valent.  ``sC`` is the snub cube,
    ``sT`` the icosahedron.  Conway defines it as the dual of gyro, and so
    it is built here, with the package's dual (vertices at the centroids of
    the gyro pentagons).

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        2E vertices, 5E edges, V + 2E + F faces.
    """
    check_closed(mesh, "snub")
    return dual(pentagonal.pentagonalize(mesh))


def _thirds(mesh: Mesh):
    """Vertex ids (after the V old ones) of the trisection points of every
    half-edge: ``t1`` near its tail, ``t2`` near its head (as in
    :func:`~pentanb.schemes.pentagonal.pentagonalize`)."""
    n = mesh.n_vertices
    return n + halfedge_edge_point(mesh, 2, 0), n + halfedge_edge_point(mesh, 2, 1)


def propeller(mesh: Mesh) -> Mesh:
    """Hart's propeller ``p``: each n-gon becomes a twisted n-gon and n quads.

    "Makes each n-gon face into a 'propeller' of an n-gon surrounded by n
    quadrilaterals" (Hart).  Every edge is cut in three (as in
    pentagonalization); the face's inner n-gon joins the points just after
    its corners, and half-edge ``h = (u, w)`` gives the quad
    ``(t1(h), t2(h), w, t1(next h))``.  The new vertices are 4-valent.
    ``pT`` is the propello-tetrahedron (4 triangles, 12 quads).

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        V + 2E vertices (old, then two per edge as in pentagonalize), 5E
        edges, F + 2E faces: the inner faces in the input's order, then one
        quad per half-edge.  With the package's positions every new face
        lies in its old face's plane.
    """
    check_closed(mesh, "propeller")
    return PROPELLER(mesh)


def whirl(mesh: Mesh) -> Mesh:
    """Whirl ``w``: pentagonalization with every face centre truncated.

    Antiprism: "Gyro followed by truncation of vertices centered on
    original faces.  This create 2 new hexagons for every original edge."
    Every n-gon becomes a small twisted n-gon and n hexagons; half-edge
    ``h = (u, w)`` gives ``(t1(h), t2(h), w, t1(next h), q(next h), q(h))``
    where ``q(h)`` lies on the gyro spoke from the centroid ``c_f`` to
    ``t1(h)``, a third of the way from ``c_f`` (as :func:`truncate` cuts).
    ``wD`` is the Goldberg polyhedron GP(2, 1).

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        V + 4E vertices (old; two per edge; one per half-edge), 7E edges,
        F + 2E faces: the inner faces in the input's order, then one
        hexagon per half-edge.
    """
    check_closed(mesh, "whirl")
    t1, t2 = _thirds(mesh)
    thirds = edge_points(mesh, 2)
    q = mesh.n_vertices + thirds.shape[0] + np.arange(mesh.n_halfedges, dtype=np.int64)
    nxt = mesh.next
    hexagons = np.stack([t1, t2, mesh.head, t1[nxt], q[nxt], q], axis=1)
    corners, offsets = concat_faces((q, mesh.offsets), fixed_size(hexagons))
    c = mesh.face_centroids[mesh.halfedge_face]
    inner = c + (thirds[t1 - mesh.n_vertices] - c) / 3.0
    return output(np.concatenate([mesh.vertices, thirds, inner]), corners, offsets)


def meta(mesh: Mesh) -> Mesh:
    """Conway's meta ``m = kj``: every n-gon cut into 2n triangles.

    The vertex-insertion (ortho) quads ``(m_h, w, m_next, c_f)`` split along
    ``w - c_f``; ``mC`` is the disdyakis dodecahedron.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        V + E + F vertices (old, edge midpoints, face centroids: the layout
        of :func:`~pentanb.schemes.classic.vertex_insertion`), 6E edges, 4E
        triangles: ``(u, m_h, c_f)`` and ``(m_h, w, c_f)`` for every
        half-edge ``h = (u, w)`` of face f.
    """
    check_closed(mesh, "meta")
    n, E = mesh.n_vertices, mesh.n_edges
    mid = n + mesh.halfedge_edge
    c = n + E + mesh.halfedge_face
    tris = np.stack(
        [
            np.stack([mesh.corners, mid, c], axis=1),
            np.stack([mid, mesh.head, c], axis=1),
        ],
        axis=1,
    ).reshape(-1, 3)
    corners, offsets = fixed_size(tris)
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 1), mesh.face_centroids])
    return output(vertices, corners, offsets)


def bevel(mesh: Mesh) -> Mesh:
    """Conway's bevel ``b = ta`` (omnitruncation): ``truncate(ambo(mesh))``.

    Every n-gon becomes a 2n-gon, every edge a quad, every k-valent vertex a
    2k-gon.  ``bC`` is the truncated cuboctahedron.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        4E vertices, 6E edges, V + E + F faces (faces: F 2n-gons, then V
        2k-gons, then E quads, the order :func:`truncate` gives the faces
        of :func:`ambo`).
    """
    check_closed(mesh, "bevel")
    return truncate(ambo(mesh))


def reflect(mesh: Mesh) -> Mesh:
    """Hart's reflect ``r``: the mirror image (x -> -x, every face reversed).

    The orientation stays outward.  ``rsC`` is the other snub cube.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces (H = 2E half-edges).

    Returns
    -------
    Mesh
        The same counts; face ``f`` keeps its first corner and lists the
        others backwards.
    """
    check_mesh(mesh, "reflect")
    hf = mesh.halfedge_face
    start = mesh.offsets[:-1][hf]
    size = mesh.face_sizes[hf]
    i = np.arange(mesh.n_halfedges, dtype=np.int64) - start
    corners = mesh.corners[start + (size - i) % size]
    v = mesh.vertices * np.array([-1.0, 1.0, 1.0])
    return output(v, corners, mesh.offsets)


# ---------------------------------------------------------------------- the table
@dataclass(frozen=True)
class Invariants:
    """How an operator turns seed elements into new ones, per seed element.

    The local-symmetry-preserving operations of Brinkmann, Goetschalckx and
    Schein ("Comparing the constructions of Goldberg, Fuller, Caspar, Klug
    and Coxeter, and a general approach to local symmetry-preserving
    operations", Proc. R. Soc. A 473, 2017), in the notation of B.
    Stewart's notes on Conway operators (antitile, ``docs/conway.rst``):
    with ``v_i`` the i-valent vertices, ``f_i`` the i-sided faces and E the
    edges of the seed, the result has

    * ``V_i = a v_{i/k} + E b[i] + c f_{i/l}`` vertices of valence i,
    * ``F_i = (1-a) v_{i/k} + E b'[i] + (1-c) f_{i/l}`` faces of i sides,
    * ``g E`` edges, ``g = 1 + sum(b) + sum(b')``.

    Attributes
    ----------
    a : int
        1 when a seed vertex stays a vertex, 0 when it becomes a face.
    c : int
        1 when a seed face becomes a vertex, 0 when it stays a face.
    k, l : int
        The valence (or size) of what a seed vertex (face) becomes, over its own.
    b : dict
        New vertices per seed edge, by valence.
    b_faces : dict
        New faces per seed edge, by number of sides.
    """

    a: int
    c: int
    k: int
    l: int
    b: Mapping[int, int] = field(default_factory=dict)
    b_faces: Mapping[int, int] = field(default_factory=dict)

    @property
    def g(self) -> int:
        """Edge multiplier (Brinkmann's inflation rate)."""
        return 1 + sum(self.b.values()) + sum(self.b_faces.values())


@dataclass(frozen=True)
class Operator:
    """One letter of Conway notation.

    Attributes
    ----------
    letter : str
    name : str
    func : callable
        ``func(mesh, **options) -> Mesh`` (and ``func(mesh, n)`` for the
        numeric forms ``kN``, ``tN``).
    counts : callable
        ``counts(V, E, F) -> (V', E', F')``: exact for the plain letter, an
        upper bound for the numeric forms (:meth:`counts_on` is exact for
        both).  The letters that are registered schemes share the
        scheme's function (``SCHEMES[name].counts``).
    invariants : Invariants
        The counts by valence and face size (the tests check every letter's
        valence and face-size histograms against them).
    reference : str
        Where the literature defines it.
    positions : str
        Where the package puts new vertices, against the literature.
    options : dict
        Keyword options and their defaults *in the notation* (``q`` is
        quinto: ``scale=0.5``, not preserve_pentagons' default 0.75).
    number : str or None
        What a number after the letter selects (``"face size"`` for ``kN``,
        ``"valence"`` for ``tN``), or None when it takes none.
    identity : str
        The literature's expression in other operators, if any (``"dg"``).
    """

    letter: str
    name: str
    func: Callable[..., Mesh]
    counts: Callable[..., tuple]
    invariants: Invariants
    reference: str
    positions: str
    options: Mapping[str, float] = field(default_factory=dict)
    number: str | None = None
    identity: str = ""

    @property
    def formula(self) -> str:
        """The count formula as text, e.g. ``"(V+2E+F, 5E, 2E)"``."""
        return count_formula(self.counts)

    def counts_on(self, mesh: Mesh, n: int | None = None) -> Counts:
        """The counts of ``func(mesh, n)`` without building it, exact also for ``kN`` / ``tN``.

        Parameters
        ----------
        mesh : Mesh
            The input: V vertices, E edges, F faces.
        n : int >= 3, optional
            The number of ``kN`` (a face size) or ``tN`` (a valence); None
            for the plain letter.

        Returns
        -------
        (V', E', F') : tuple of int
            :attr:`counts` for the plain letter; with ``n``, what raising
            pyramids on the ``n``-sided faces (``kN``) or cutting the
            ``n``-valent vertices (``tN``) gives.
        """
        V, E, F = mesh.n_vertices, mesh.n_edges, mesh.n_faces
        if n is None:
            return tuple(int(x) for x in self.counts(V, E, F))  # type: ignore[return-value]
        if self.number == "face size":
            m = int(np.count_nonzero(mesh.face_sizes == n))
            return V + m, E + n * m, F + (n - 1) * m
        m = int(np.count_nonzero(mesh.valences == n))
        return V + (n - 1) * m, E + n * m, F + m


def _quinto(mesh: Mesh, scale: float = 0.5) -> Mesh:
    return pentagonal.preserve_pentagons(mesh, scale=scale)


_quinto.__doc__ = "preserve_pentagons with quinto's scale 0.5 as default."

_HART = "Hart, 'Conway notation for polyhedra' (georgehart.com)"
_ANTIPRISM = "Antiprism conway (extended operators)"

_OPERATORS = [
    Operator(
        "d",
        "dual",
        dual,
        lambda V, E, F: (F, E, V),
        Invariants(0, 1, 1, 1),
        f"Conway; {_HART}",
        "vertices at face centroids (the paper's smoothing), so dd is not the "
        "identity; Hart reciprocates in canonical form, where dd = identity",
        identity="",
    ),
    Operator(
        "a",
        "ambo",
        ambo,
        lambda V, E, F: (E, 2 * E, V + F),
        Invariants(0, 0, 1, 1, {4: 1}),
        f"Conway; {_HART}",
        "edge midpoints (Hart: 'truncating to the edge midpoints')",
        identity="dj",
    ),
    Operator(
        "t",
        "truncate",
        truncate,
        lambda V, E, F: (2 * E, 3 * E, V + F),
        Invariants(0, 0, 1, 2, {3: 2}),
        f"Conway; tN: {_HART}",
        "cuts at 1/3 of each edge (the regular tT, tO, tI); Hart: dkd, canonical",
        number="valence",
        identity="dkd",
    ),
    Operator(
        "k",
        "kis",
        kis,
        lambda V, E, F: (V + F, 3 * E, 2 * E),
        Invariants(1, 1, 2, 1, {}, {3: 2}),
        f"Conway; kN: {_HART}",
        "apex at the face centroid (flat pyramids); Hart raises it (canonical)",
        number="face size",
        identity="dtd",
    ),
    Operator(
        "j",
        "join",
        join,
        lambda V, E, F: (V + F, 2 * E, E),
        Invariants(1, 1, 1, 1, {}, {4: 1}),
        f"Conway; {_HART}",
        "old vertices and face centroids; the quads are folded until canonical",
        identity="da",
    ),
    Operator(
        "e",
        "expand",
        SCHEMES["corner_cutting"].func,
        SCHEMES["corner_cutting"].counts,
        Invariants(0, 0, 1, 1, {4: 2}, {4: 1}),
        f"Conway (Stott's expansion); {_HART}",
        "corner_cutting: corner (v, f) halfway from v to the centroid of f; aa with "
        "midpoint ambo would put it at (u + 2v + w) / 4",
        options={"scale": 0.5},
        identity="aa",
    ),
    Operator(
        "o",
        "ortho",
        SCHEMES["vertex_insertion"].func,
        SCHEMES["vertex_insertion"].counts,
        Invariants(1, 1, 1, 1, {4: 1}, {4: 2}),
        f"Conway; {_HART}",
        "vertex_insertion: edge midpoints and face centroids (Hart: 'new vertices in "
        "the middle of each face ... connected to the edge midpoints'); jj with "
        "centroid join would put the edge vertex at the mean of u, w, c_f, c_g",
        identity="jj",
    ),
    Operator(
        "s",
        "snub",
        snub,
        lambda V, E, F: (2 * E, 5 * E, V + 2 * E + F),
        Invariants(0, 0, 1, 1, {5: 2}, {3: 2}),
        f"Conway; {_HART}",
        "dual(pentagonalize(mesh)): centroids of the gyro pentagons",
        identity="dg",
    ),
    Operator(
        "g",
        "gyro",
        SCHEMES["pentagonalize"].func,
        SCHEMES["pentagonalize"].counts,
        Invariants(1, 1, 1, 1, {3: 2}, {5: 2}),
        f"Conway; {_HART}; the paper's pentagonalization (Section 5.1)",
        "pentagonalize: edge thirds and face centroids, exactly Hart's 'like k but "
        "with the new edges connecting the face centers to the 1/3 points'",
        identity="ds",
    ),
    Operator(
        "p",
        "propeller",
        propeller,
        lambda V, E, F: (V + 2 * E, 5 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {4: 2}, {4: 2}),
        "Hart, 'Sculpture based on propellorized polyhedra', MOSAIC 2000",
        "edge thirds (as pentagonalize); flat until canonical",
        identity="dpd",
    ),
    Operator(
        "m",
        "meta",
        meta,
        lambda V, E, F: (V + E + F, 6 * E, 4 * E),
        Invariants(1, 1, 2, 2, {4: 1}, {3: 4}),
        f"Conway; {_HART}",
        "edge midpoints and face centroids (flat until canonical)",
        identity="kj",
    ),
    Operator(
        "b",
        "bevel",
        bevel,
        lambda V, E, F: (4 * E, 6 * E, V + E + F),
        Invariants(0, 0, 2, 2, {3: 4}, {4: 1}),
        f"Conway; {_HART}",
        "truncate(ambo(mesh)): thirds of the ambo edges",
        identity="ta",
    ),
    Operator(
        "c",
        "chamfer",
        SCHEMES["preserve_hexagons"].func,
        SCHEMES["preserve_hexagons"].counts,
        Invariants(1, 0, 1, 1, {3: 2}, {6: 1}),
        f"{_ANTIPRISM}; Goldberg-Coxeter GP(m, n) -> GP(2m, 2n)",
        "preserve_hexagons: old vertices kept, face copies halfway to the centroid "
        "in the face's plane, so the new hexagons are folded along the old edge "
        "(planar only in canonical form)",
        options={"scale": 0.5},
        identity="dud",
    ),
    Operator(
        "w",
        "whirl",
        whirl,
        lambda V, E, F: (V + 4 * E, 7 * E, F + 2 * E),
        Invariants(1, 0, 1, 1, {3: 4}, {6: 2}),
        f"{_ANTIPRISM} ('gyro followed by truncation of vertices centered on original faces')",
        "edge thirds; inner points 1/3 from the centroid along the gyro spokes",
    ),
    Operator(
        "q",
        "quinto",
        _quinto,
        SCHEMES["preserve_pentagons"].counts,
        Invariants(1, 0, 1, 1, {3: 2, 4: 1}, {5: 2}),
        f"{_ANTIPRISM}; the paper's pentagon preservation (Section 5.2)",
        "preserve_pentagons with scale 0.5 (the inner face halfway between the "
        "centroid of the edge midpoints and the midpoints); its own default is 0.75",
        options={"scale": 0.5},
    ),
    Operator(
        "z",
        "zip",
        SCHEMES["honeycomb"].func,
        SCHEMES["honeycomb"].counts,
        Invariants(0, 0, 2, 1, {3: 2}),
        f"{_ANTIPRISM} (zip = dk, bitruncation); the paper's honeycomb (Figure 13)",
        "honeycomb: centroid of (u, w, c_f), exactly dual(kis(mesh)) with the package's centroids",
        identity="dk",
    ),
    Operator(
        "u",
        "subdivide",
        SCHEMES["loop_remesh"].func,
        SCHEMES["loop_remesh"].counts,
        Invariants(1, 0, 1, 1, {6: 1}, {3: 2}),
        f"{_ANTIPRISM} ('ambo while retaining original vertices'); Loop's remeshing (Figure 3)",
        "loop_remesh: old vertices and edge midpoints (not pushed to a sphere)",
        identity="dcd",
    ),
    Operator(
        "n",
        "needle",
        SCHEMES["sqrt3_remesh"].func,
        SCHEMES["sqrt3_remesh"].counts,
        Invariants(1, 1, 1, 2, {}, {3: 2}),
        f"{_ANTIPRISM} (needle = kd = dt); the sqrt(3) remeshing (Section 3)",
        "sqrt3_remesh: old vertices and face centroids, two triangles across every edge",
        identity="kd",
    ),
    Operator(
        "r",
        "reflect",
        reflect,
        lambda V, E, F: (V, E, F),
        Invariants(1, 0, 1, 1),
        f"Hart; {_HART}",
        "x -> -x, faces reversed",
    ),
]

#: Every operator letter, in the order of the table above.
OPERATORS: dict[str, Operator] = {op.letter: op for op in _OPERATORS}
