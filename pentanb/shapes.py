"""Test shapes: the Platonic solids, boxes, tori, higher genus and two low-poly rabbits.

Every function returns a closed, outward-oriented :class:`~pentanb.Mesh`,
but :func:`open_disk`, a surface with boundary (not in :data:`SHAPES`).
:data:`SHAPES` lists them by name (with their default sizes) for sliders,
the command line and the tests; :func:`get` builds one by name.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable

import numpy as np
from numpy.typing import ArrayLike

from . import _checks
from .memory import default_max_bytes, mesh_bytes
from .mesh import Mesh, MeshError, check_closed
from .schemes.smoothing import dual

__all__ = [
    "tetrahedron",
    "cube",
    "octahedron",
    "dodecahedron",
    "icosahedron",
    "torus",
    "hexagonal_torus",
    "genus_surface",
    "double_torus",
    "hexagonal_surface",
    "voxels",
    "hard_edged_cube",
    "box",
    "rabbit",
    "animal",
    "open_disk",
    "outward",
    "SHAPES",
    "get",
]

PHI = (1.0 + 5.0**0.5) / 2.0


def outward(vertices: ArrayLike, faces: Iterable[ArrayLike]) -> Mesh:
    """A convex solid with every face turned outwards.

    A face whose corners turn clockwise seen from outside (its normal, from
    its first three corners, pointing towards the vertices' centroid) is
    reversed; the others are kept as given.

    Parameters
    ----------
    vertices : (n, 3) float
        Corners of a convex solid.
    faces : (m,) sequence of int sequences
        Its faces in either orientation; any mix of sizes.

    Returns
    -------
    Mesh

    Raises
    ------
    MeshError
        If the faces do not make a closed manifold once turned outwards.
    """
    v = np.asarray(vertices, dtype=np.float64)
    c = v.mean(axis=0)
    out = []
    for face in faces:
        f = np.asarray(face, dtype=np.int64)
        p = v[f]
        normal = np.cross(p[1] - p[0], p[2] - p[0])
        out.append(f if normal @ (p.mean(axis=0) - c) > 0 else f[::-1])
    return check_closed(Mesh(v, out), "outward")


def tetrahedron() -> Mesh:
    """Regular tetrahedron inscribed in the cube [-1, 1]^3 (4 triangles).

    Returns
    -------
    Mesh
        4 vertices, 6 edges, 4 triangles.
    """
    v = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
    return outward(v, [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]])


def cube() -> Mesh:
    """The cube [-1, 1]^3 (6 quads); vertex ``4x + 2y + z`` has coordinates (x, y, z) in {-1, 1}.

    Returns
    -------
    Mesh
        8 vertices, 12 edges, 6 quads.
    """
    v = np.array(list(itertools.product([-1.0, 1.0], repeat=3)))
    faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    return outward(v, faces)


def octahedron() -> Mesh:
    """Regular octahedron with vertices at +-1 on the axes (8 triangles).

    Returns
    -------
    Mesh
        6 vertices, 12 edges, 8 triangles.
    """
    v = np.concatenate([np.eye(3), -np.eye(3)])
    faces = [
        [a + 3 * sa, b + 3 * sb, c + 3 * sc]
        for sa, sb, sc in itertools.product([0, 1], repeat=3)
        for a, b, c in [(0, 1, 2)]
    ]
    return outward(v, faces)


def icosahedron() -> Mesh:
    """Regular icosahedron, vertices (0, +-1, +-phi) and cyclic shifts (20 triangles).

    Returns
    -------
    Mesh
        12 vertices, 30 edges, 20 triangles.
    """
    base = [(0.0, s1, s2 * PHI) for s1 in (-1, 1) for s2 in (-1, 1)]
    v = np.array([np.roll(p, k) for k in range(3) for p in base])
    d = np.linalg.norm(v[:, None] - v[None], axis=2)
    near = np.isclose(d, 2.0)
    faces = [
        t
        for t in itertools.combinations(range(12), 3)
        if near[t[0], t[1]] and near[t[1], t[2]] and near[t[0], t[2]]
    ]
    return outward(v, faces)


def dodecahedron() -> Mesh:
    """Regular dodecahedron (12 pentagons): the dual of :func:`icosahedron`.

    Returns
    -------
    Mesh
        20 vertices, 30 edges, 12 pentagons.
    """
    return dual(icosahedron())


def torus(rings: int = 12, sides: int = 8, radius: float = 1.0, tube: float = 0.4) -> Mesh:
    """A torus as a ``rings x sides`` grid of quads (genus 1).

    Parameters
    ----------
    rings : int, >= 3
        Quads around the central axis (z).
    sides : int, >= 3
        Quads around the tube.
    radius, tube : float
        Distance of the tube's centre from the axis, and the tube's radius.

    Returns
    -------
    Mesh
        ``rings * sides`` vertices and quads, ``2 rings sides`` edges; genus 1.

    Notes
    -----
    Vertex ``(i, j)`` (index ``i * sides + j``) sits at angles
    ``2 pi (i - 1/2) / rings`` around the axis and ``2 pi (j - 1/2) / sides``
    around the tube, so face 0 is centred on the outer equator at +x.
    """
    rings, sides = _grid_size(rings, sides)
    _radii(radius, tube)
    _check_size(f"torus({rings}, {sides})", rings * sides, 2 * rings * sides, rings * sides)
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    v = _torus_points((i - 0.5) / rings, (j - 0.5) / sides, radius, tube)
    idx = lambda a, b: (a % rings) * sides + (b % sides)  # noqa: E731
    quads = np.stack([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)], axis=-1).reshape(
        -1, 4
    )
    return Mesh(v.reshape(-1, 3), quads)


def hexagonal_torus(
    rings: int = 12, sides: int = 6, radius: float = 1.0, tube: float = 0.4
) -> Mesh:
    """A torus of hexagons only, every vertex 3-valent: a (6, 3) mesh (Figure 4A).

    The dual of a torus grid whose quads are cut by parallel diagonals (every
    vertex of that triangulation is 6-valent); the hexagons' corners are put
    back on the torus at the triangles' parametric centres.

    Parameters
    ----------
    rings : int, >= 3
        Hexagons around the central axis (z).
    sides : int, >= 3
        Hexagons around the tube.
    radius, tube : float
        Distance of the tube's centre from the axis, and the tube's radius.

    Returns
    -------
    Mesh
        ``rings * sides`` hexagons, ``2 rings sides`` vertices; face ``i *
        sides + j`` surrounds grid point (i, j), face 0 on the outer equator.
    """
    rings, sides = _grid_size(rings, sides)
    _radii(radius, tube)
    n = rings * sides  # (the triangulated grid it is the dual of is about as large)
    _check_size(f"hexagonal_torus({rings}, {sides})", 2 * n, 3 * n, n)
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    idx = lambda a, b: (a % rings) * sides + (b % sides)  # noqa: E731
    a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
    tris = np.concatenate(
        [np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)]
    )
    grid = _torus_points(i / rings, j / sides, radius, tube).reshape(-1, 3)
    hexes = dual(Mesh(grid, tris))
    # triangle centres in grid units: (i + 2/3, j + 1/3) and (i + 1/3, j + 2/3)
    ci = np.concatenate([(i + 2 / 3).ravel(), (i + 1 / 3).ravel()])
    cj = np.concatenate([(j + 1 / 3).ravel(), (j + 2 / 3).ravel()])
    return hexes.with_vertices(_torus_points(ci / rings, cj / sides, radius, tube))


def _torus_points(u, v, radius, tube):
    t, p = 2 * np.pi * np.asarray(u), 2 * np.pi * np.asarray(v)
    r = radius + tube * np.cos(p)
    return np.stack([r * np.cos(t), r * np.sin(t), tube * np.sin(p)], axis=-1)


def _radii(radius, tube) -> None:
    for name, value in (("radius", radius), ("tube", tube)):
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
            raise TypeError(f"{name} must be a number, got {type(value).__name__}")
    if not (0 < tube < radius):
        raise ValueError(f"need 0 < tube < radius, got tube={tube}, radius={radius}")


def _check_size(what: str, V: int, E: int, F: int, extra: int = 0) -> None:
    """Refuse (MeshError) a shape whose mesh would need more than the memory available.

    The bytes are :func:`pentanb.memory.mesh_bytes` of its counts
    (plus ``extra``), the limit :func:`pentanb.memory.default_max_bytes`,
    as for :func:`pentanb.subdivide`.
    """

    limit = default_max_bytes()
    need = mesh_bytes(V, E, F) + extra
    if need > limit:
        raise MeshError(
            f"{what} would build a mesh of {F:,} faces ({V:,} vertices, {E:,} edges) needing "
            f"about {need:,} bytes, over the limit of {limit:,} bytes (the memory available)"
        )


def _grid_size(rings, sides):
    return _checks.count(rings, "rings", 3), _checks.count(sides, "sides", 3)


def genus_surface(genus: int = 2, base: Mesh | None = None, rings: int = 8, sides: int = 6) -> Mesh:
    """A chain of ``genus`` tori joined where they touch (Figure 4B style).

    Each torus loses its face furthest along +x and, in the middle of the
    chain, the one furthest along -x; neighbours are mirror images glued
    along those faces.  The glued faces' corners are flattened onto the
    mirror planes first.  Every other face of ``base`` is kept, so a chain
    of hexagonal tori is all hexagons (its 6 (g - 1) seam vertices are
    4-valent, as equation (1) demands for g >= 2).

    Parameters
    ----------
    genus : int, >= 1
    base : Mesh, optional
        A torus (any mesh whose +x-most and -x-most faces share no vertex).
        Default: ``torus(rings, sides)``.
    rings, sides : int
        Size of the default base (ignored when ``base`` is given).

    Returns
    -------
    Mesh
        One connected surface of genus ``genus``.
    """
    genus = _checks.count(genus, "genus", 1)
    if base is not None and not isinstance(base, Mesh):
        raise TypeError(f"base must be a pentanb.Mesh (a torus) or None, got {type(base).__name__}")
    if base is None:
        base = torus(rings, sides)
    elif base.genus != 1 or base.n_components != 1:
        raise ValueError(
            f"base must be a connected torus (genus 1): a chain of {genus} copies of a mesh of "
            f"genus {base.genus} with {base.n_components} component(s) does not have genus {genus}"
        )
    genus = int(genus)
    # each copy glued on drops two faces and shares the corners of one; the chain is
    # built face by face in Python, about 500 bytes a face on top of the arrays
    k = int(base.face_sizes[np.argmax(base.face_centroids[:, 0])])
    V, E, F = base.n_vertices, base.n_edges, base.n_faces
    _check_size(
        f"genus_surface({genus})",
        genus * V - (genus - 1) * k,
        genus * E - (genus - 1) * k,
        genus * F - 2 * (genus - 1),
        extra=500 * genus * F,
    )
    if genus == 1:
        return base
    faces = base.faces
    x = base.face_centroids[:, 0]
    right, left = int(np.argmax(x)), int(np.argmin(x))
    v = base.vertices.copy()
    fr, fl = faces[right], faces[left]
    if np.intersect1d(fr, fl).size:
        raise MeshError(
            f"faces {right} and {left} of the base share a vertex; cannot chain copies along them"
        )
    a = float(np.abs(np.concatenate([v[fr, 0], v[fl, 0]])).mean())
    v[fr, 0] = a
    v[fl, 0] = -a
    n = base.n_vertices
    verts, all_faces = [], []
    rep = np.arange(genus * n, dtype=np.int64)
    for k in range(genus):
        if k % 2:
            pos = v.copy()
            pos[:, 0] = 2 * a - pos[:, 0]
            pos[:, 0] += 4 * a * (k // 2)
            fk = [f[::-1] for f in faces]
        else:
            pos = v.copy()
            pos[:, 0] += 4 * a * (k // 2)
            fk = list(faces)
        # glue to the previous copy: odd copies meet it at the right face,
        # even ones at the left face
        drop = set()
        if k > 0:
            glue = right if k % 2 else left
            drop.add(glue)
            rep[k * n + faces[glue]] = rep[(k - 1) * n + faces[glue]]
        if k < genus - 1:
            drop.add(left if k % 2 else right)
        verts.append(pos)
        all_faces += [k * n + f for idx, f in enumerate(fk) if idx not in drop]
    used, inverse = np.unique(rep, return_inverse=True)
    stacked = np.concatenate(verts)[used]
    return Mesh(stacked, [inverse[f] for f in all_faces])


def double_torus(rings: int = 8, sides: int = 6) -> Mesh:
    """Genus 2: two quad tori glued along a face (see :func:`genus_surface`).

    Parameters
    ----------
    rings, sides : int, >= 3
        Size of each quad torus (:func:`torus`).

    Returns
    -------
    Mesh
        Quads only, genus 2.
    """
    return genus_surface(2, torus(rings, sides), rings, sides)


def hexagonal_surface(genus: int = 2, rings: int = 8, sides: int = 6) -> Mesh:
    """A mesh of hexagons only with any genus >= 1 (Figure 4B style).

    ``genus`` hexagonal tori glued in a chain; see :func:`genus_surface`.

    Parameters
    ----------
    genus : int, >= 1
    rings, sides : int, >= 3
        Size of each hexagonal torus (:func:`hexagonal_torus`).

    Returns
    -------
    Mesh
        Hexagons only, genus ``genus``.
    """
    return genus_surface(genus, hexagonal_torus(rings, sides), rings, sides)


def voxels(occupied) -> Mesh:
    """The boundary of a set of unit cubes, as quads.

    Parameters
    ----------
    occupied : (X, Y, Z) bool array_like
        Which cells are solid.  Cells may touch only face to face (two
        cells sharing just an edge or a corner make a non-manifold surface,
        which is refused with :class:`MeshError`).

    Returns
    -------
    Mesh
        One quad per exposed cell face; the vertices are the cells' corners,
        at integer coordinates (the cell ``(i, j, k)`` spans ``[i, i + 1] x
        [j, j + 1] x [k, k + 1]``).
    """
    occ = np.asarray(occupied, dtype=bool)
    if occ.ndim != 3 or not occ.any():
        raise MeshError("voxels need a 3-D array with at least one solid cell")
    pad = np.pad(occ, 1)
    shape = np.array(pad.shape) + 1
    parts = []
    # square of the face at +axis, counter-clockwise seen from outside
    unit = {
        0: [(0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)],
        1: [(0, 0, 0), (0, 0, 1), (1, 0, 1), (1, 0, 0)],
        2: [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
    }
    for axis in range(3):
        for sign in (1, -1):
            nb = np.roll(pad, -sign, axis=axis)
            cells = np.argwhere(pad & ~nb)
            sq = np.array(unit[axis])
            if sign == 1:
                sq = sq + np.eye(3, dtype=int)[axis]
            else:
                sq = sq[::-1]
            corners = cells[:, None, :] + sq[None]
            parts.append(np.ravel_multi_index(corners.reshape(-1, 3).T, shape).reshape(-1, 4))
    quads = np.concatenate(parts)
    used, inverse = np.unique(quads, return_inverse=True)
    pts = np.stack(np.unravel_index(used, shape), axis=1).astype(float) - 1.0
    return Mesh(pts, inverse.reshape(-1, 4))


def hard_edged_cube(inset: float = 0.8) -> Mesh:
    """A cube with hard edges: each face a 3x3 grid whose outer rows are thin.

    The planes ``+-inset`` cut every face into a big central quad, four
    strips along the edges and four small corner squares (54 quads).  This
    package's reading of the cube of Figures 1 and 8 (the paper does not
    describe its cube): the thin strips keep the edges hard under the
    duals, and the 4-valent grid vertices make the (4, 4) regions that
    become 4.3.3.4.3 after pentagonalization.  ``inset=1/3`` gives
    :func:`box` ``(3)``.

    Parameters
    ----------
    inset : float in (0, 1)
        Where the edge loops sit; closer to 1 keeps the edges harder.

    Returns
    -------
    Mesh
        54 quads spanning [-1, 1]^3.
    """
    if isinstance(inset, bool) or not isinstance(inset, (int, float, np.integer, np.floating)):
        raise TypeError(f"inset must be a number in (0, 1), got {type(inset).__name__}")
    if not 0 < inset < 1:
        raise ValueError(
            f"inset must be in (0, 1), got {inset!r}: 0 and 1 give faces of no area with "
            "doubled vertices, values outside fold faces inward"
        )
    m = voxels(np.ones((3, 3, 3), dtype=bool))
    coord = np.array([-1.0, -inset, inset, 1.0])
    return m.with_vertices(coord[np.rint(m.vertices).astype(int)])


def box(cells: int = 3) -> Mesh:
    """The cube ``[-1, 1]^3`` with every face an even ``cells x cells`` grid of quads.

    The boxes of the lateral-artifact study (Section 1): their 12
    edges are straight and every grid line meets them at the same spacing
    ``2 / cells``.  ``box(1)`` is :func:`cube` (numbered differently).

    Parameters
    ----------
    cells : int, >= 1

    Returns
    -------
    Mesh
        ``6 cells^2`` quads, ``6 cells^2 + 2`` vertices, genus 0.
    """
    n = _checks.count(cells, "cells", 1)
    m = voxels(np.ones((n, n, n), dtype=bool))
    return m.with_vertices(m.vertices * (2.0 / n) - 1.0)


def rabbit() -> Mesh:
    """An irregular low-polygon rabbit: the initial mesh of Figure 12.

    172 vertices and 231 faces (136 triangles, 81 quadrilaterals, 14
    pentagons), vertex valences 3 to 7, closed, genus 0, about 2.7 units
    long.  The paper's model (by Esan Mandal) is not available; this one is
    built by :mod:`pentanb.data.make_rabbit` (a star-shaped union of
    ellipsoids, triangulated and partly merged into larger faces) and
    shipped as ``pentanb/data/rabbit.obj`` (read here with numpy only).

    Returns
    -------
    Mesh
        172 vertices, 231 faces.
    """
    from importlib import resources

    from .io import read_obj

    with resources.as_file(resources.files("pentanb.data") / "rabbit.obj") as path:
        return read_obj(path)


def open_disk() -> Mesh:
    """A small open model: a domed disk with two holes (a surface with boundary).

    147 vertices, 300 edges and 152 faces (72 triangles, 68 quadrilaterals,
    12 pentagons), genus 0 with three boundary loops (the rim, 30 edges, and
    two holes of 11), so ``V - E + F = 2 - 2g - b = -1``; it lies on a
    sphere of radius 1.4 over the unit disk, its normals up.  Built by
    :mod:`pentanb.data.make_open_disk` and shipped as
    ``pentanb/data/open_disk.obj`` (read here with numpy only).

    Returns
    -------
    Mesh
        An open mesh: ``open_disk().boundary_loops`` has three loops.
    """
    from importlib import resources

    from .io import read_obj

    with resources.as_file(resources.files("pentanb.data") / "open_disk.obj") as path:
        return read_obj(path)


def animal() -> Mesh:
    """A voxel rabbit: 178 unit-cube quads (valences 3 to 5) scaled into [-1, 1]^3.

    Genus 0 with hard features: a body, four legs, a head with a snout, two
    long ears and a tail.  Figure 12 used it before :func:`rabbit`; it stays
    as a quads-only shape with hard edges.

    Returns
    -------
    Mesh
        178 quads in [-1, 1]^3.
    """
    occ = np.zeros((11, 5, 10), dtype=bool)
    occ[2:7, 1:4, 2:5] = True  # body
    for x in (2, 6):
        for y in (1, 3):
            occ[x, y, 0:2] = True  # legs
    occ[7:9, 1:4, 4:7] = True  # head
    occ[9, 2, 5] = True  # snout
    occ[7, 1, 7:10] = True  # ears
    occ[7, 3, 7:10] = True
    occ[1, 2, 4] = True  # tail
    m = voxels(occ)
    v = m.vertices - m.vertices.mean(axis=0)
    return m.with_vertices(v / np.abs(v).max())


#: Every named shape with its default size, for menus and tests.
SHAPES: dict[str, Callable[[], Mesh]] = {
    "tetrahedron": tetrahedron,
    "cube": cube,
    "hard_cube": hard_edged_cube,
    "box": box,
    "octahedron": octahedron,
    "dodecahedron": dodecahedron,
    "icosahedron": icosahedron,
    "torus": torus,
    "hexagonal_torus": hexagonal_torus,
    "double_torus": double_torus,
    "hexagonal_genus2": lambda: hexagonal_surface(2),
    "genus3": lambda: genus_surface(3),
    "rabbit": rabbit,
    "animal": animal,
}


def get(name: str) -> Mesh:
    """Build the shape called ``name`` (see :data:`SHAPES`).

    Parameters
    ----------
    name : str
        A key of :data:`SHAPES`, e.g. ``"cube"``.

    Returns
    -------
    Mesh
        A new mesh at every call.

    Raises
    ------
    ValueError
        For an unknown name; the message lists the known ones.
    """
    if not isinstance(name, str) or name not in SHAPES:
        raise ValueError(f"unknown shape {name!r}; known shapes: {', '.join(SHAPES)}")
    return SHAPES[name]()
