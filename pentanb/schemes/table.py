"""A local remeshing scheme as data: the :class:`Table`, checked slot by slot.

A scheme of the paper is a local rewriting rule: it puts new points on the
input's vertices, edges, faces and corners, then joins them into faces, the
same faces around every half-edge, face, vertex or edge.  A :class:`Table`
says exactly that and nothing more; one engine (:mod:`pentanb.schemes.engine`)
evaluates every table, closed or open, and derives the output's twins from
the table itself (so no scheme writes index arithmetic of its own).  The
model is Antiprism's ``wythoff`` patterns and the lsp/lopsp operations of
Brinkmann, Goetschalckx and Coolsaet: every Conway operator is such a table.

**Points**, numbered in this order in the output:

* the input's vertices (``vertices=True``), where they are;
* ``edge_points=(t0, t1, ...)``: points at those fractions of every edge,
  from its smaller vertex (edge ``e`` gives rows ``k e + j``); symmetric
  (``t_j + t_{k-1-j} = 1``), so that the same points are ``E0, E1, ...``
  seen from either of the edge's half-edges;
* ``face_points=True``: every face's centroid;
* ``corner_points``: one point per half-edge, either ``(ELEMENT, s)``, the
  face's polygon of that element scaled by ``s`` about its own centroid
  (Section 5.2, step 2(b): "Scale the points in P_i around their centroid"),
  or a mapping ``{REF: weight}`` whose weights sum to 1 (an affine rule).

**Faces**, a tuple of ``(kind, refs)``: ``"halfedge"`` (one face per
half-edge, ``refs`` its corners), ``"face"`` (one face per face: the refs
of every half-edge of the face in turn), ``"vertex"`` (one face per vertex:
the refs of its outgoing half-edges, counter-clockwise) and ``"edge"`` (one
face per edge, from its half-edge with the smaller tail).

**References** name a point from a half-edge ``h``: a path of moves
applied left to right (``n`` next, ``p`` previous, ``t`` twin), a colon,
then the element of the half-edge reached: ``V`` its tail vertex, ``E0``,
``E1``, ... its edge points counted from its tail, ``F`` its face's point,
``C`` its corner point.  ``"V"`` is h's tail, ``"n:V"`` its head,
``"nt:F"`` the face across the next edge.  ``"t:F|n:V"`` falls back to
``n:V`` where the twin is a boundary's hole (open meshes).

Every table is checked when it is made, on small probe meshes, before any
mesh of the user's is touched: an unknown element, a face of fewer than 3
corners, weights that do not sum to 1, faces that do not pair up into an
oriented surface (two faces along one edge the same way: an orientation
flip) are refused with a :class:`ValueError` naming the slot.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from .engine import apply
from .probe import compile_table
from .refs import parse_ref

__all__ = ["Table", "KINDS"]

#: The kinds of faces a table makes, and what each is made around.
KINDS = ("halfedge", "face", "vertex", "edge")


@dataclass(frozen=True, eq=False)
class Table:
    """A local remeshing scheme as data (see the module docstring for the slots).

    Parameters
    ----------
    name : str
        What messages, menus and :func:`pentanb.subdivide` call it.
    faces : sequence of (kind, refs)
        The faces it makes: ``kind`` in :data:`KINDS`, ``refs`` a sequence
        of point names (:class:`Ref` text).
    vertices : bool
        Whether the input's vertices are kept (first in the output).
    edge_points : sequence of float
        Fractions along every edge, from its smaller vertex, in (0, 1),
        increasing and symmetric.
    face_points : bool
        Whether every face's centroid is a point.
    corner_points : (str, float or str) or mapping, optional
        ``(element, scale)``: the face's polygon of that element (``"V"`` or
        ``"E0"``, ...) scaled about its centroid by ``scale`` (a number or
        the name of an option); or ``{ref: weight}``, weights summing to 1.
    options : mapping of str to float
        The keyword options of the scheme and their defaults (e.g.
        ``{"scale": 0.75}``), each a number in (0, 1).
    label : str
        A human-readable name (for menus); ``name`` by default.

    Raises
    ------
    ValueError, TypeError
        A malformed table, naming the slot.

    Examples
    --------
    Loop's remeshing (the paper's Figure 3): midpoints, a central face in
    every face and a triangle in every corner.

    >>> from pentanb.schemes.table import Table
    >>> loop = Table("loop", edge_points=(0.5,),
    ...              faces=(("face", ("E0",)), ("halfedge", ("E0", "n:V", "n:E0"))))
    >>> loop.counts(8, 12, 6)
    (20, 48, 30)
    """

    name: str
    faces: Any
    vertices: bool = True
    edge_points: tuple[float, ...] = ()
    face_points: bool = False
    corner_points: Any = None
    options: Mapping[str, float] = field(default_factory=dict)
    label: str = ""
    compiled: Any = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        if not isinstance(self.name, str) or not self.name:
            raise TypeError(f"a table's name must be a non-empty string, got {self.name!r}")
        set_(self, "edge_points", tuple(float(t) for t in self.edge_points))
        set_(self, "options", dict(self.options))
        set_(self, "label", self.label or self.name)
        if isinstance(self.faces, (str, bytes)) or not self.faces:
            raise ValueError(f"table {self.name!r}: faces must be a non-empty sequence")
        faces = []
        for i, decl in enumerate(self.faces):
            where = f"table {self.name!r}, faces[{i}]"
            if not (isinstance(decl, (tuple, list)) and len(decl) == 2):
                raise ValueError(f"{where}: expected (kind, refs), got {decl!r}")
            kind, refs = decl
            if kind not in KINDS:
                raise ValueError(f"{where}: kind {kind!r} is not one of {', '.join(KINDS)}")
            if isinstance(refs, str):
                refs = (refs,)
            refs = tuple(refs)
            fixed = kind in ("halfedge", "edge")
            if not refs or (fixed and len(refs) < 3):
                raise ValueError(f"{where}: a {kind} face needs at least 3 corners, got {refs!r}")
            faces.append((kind, refs))
        set_(self, "faces", tuple(faces))
        self._check_points()
        set_(self, "compiled", compile_table(self))

    def _check_points(self) -> None:
        where = f"table {self.name!r}"
        for key, value in self.options.items():
            if not isinstance(key, str) or not isinstance(value, (int, float)):
                raise TypeError(f"{where}: options map names to numbers, got {key!r}: {value!r}")
        t = self.edge_points
        if any(not 0.0 < x < 1.0 for x in t) or list(t) != sorted(set(t)):
            raise ValueError(f"{where}: edge_points must increase inside (0, 1), got {t}")
        if any(abs(a + b - 1.0) > 1e-12 for a, b in zip(t, reversed(t))):
            raise ValueError(
                f"{where}: edge_points must be symmetric (t_j + t_(k-1-j) = 1), got {t}: "
                "an edge's points are the same from either end"
            )
        cp = self.corner_points
        if cp is None:
            return
        if isinstance(cp, Mapping):
            total = sum(float(w) for w in cp.values())
            if abs(total - 1.0) > 1e-9 or any(float(w) < 0 for w in cp.values()):
                raise ValueError(
                    f"{where}, corner_points: the weights must be >= 0 and sum to 1, "
                    f"they sum to {total:g}"
                )
            for ref in cp:
                got = parse_ref(ref, f"{where}, corner_points")
                if got.elem == "C" or "t" in got.path or got.fallback is not None:
                    raise ValueError(
                        f"{where}, corner_points: {ref!r}: a corner point is an affine rule "
                        "over its own face's V, E and F (paths of n and p only)"
                    )
                if got.elem == "E" and got.j >= len(self.edge_points):
                    raise ValueError(f"{where}, corner_points: {ref!r} names a missing edge point")
            return
        if not (isinstance(cp, (tuple, list)) and len(cp) == 2):
            raise ValueError(f"{where}: corner_points is (element, scale) or {{ref: weight}}")
        elem, scale = cp
        got = parse_ref(elem, f"{where}, corner_points")
        if got.path or got.fallback is not None or got.elem not in ("V", "E"):
            raise ValueError(f"{where}, corner_points: scale the polygon of V or of an E point")
        if got.elem == "E" and got.j >= len(self.edge_points):
            raise ValueError(f"{where}, corner_points: {elem!r} names a missing edge point")
        if isinstance(scale, str) and scale not in self.options:
            raise ValueError(f"{where}, corner_points: {scale!r} is not one of its options")

    # ------------------------------------------------------------------ counts
    def counts(self, V: Any, E: Any, F: Any) -> tuple[Any, Any, Any]:
        """(V', E', F') of the output on a closed mesh of V vertices, E edges, F faces.

        Parameters
        ----------
        V, E, F : int
            The input's vertices, edges and faces (or symbols: the count is
            linear, and the registry prints it as a formula).

        Returns
        -------
        (V', E', F')
        """
        v, e, f, _ = self.open_counts(V, E, F, 0 * V)
        return v, e, f

    def open_counts(self, V: Any, E: Any, F: Any, B: Any) -> tuple[Any, Any, Any, Any]:
        """(V', E', F', B') on a mesh with B boundary edges (the table's own count).

        Parameters
        ----------
        V, E, F, B : int
            The input's vertices, edges, faces and boundary edges (B = 0:
            closed; faces round vertices are for closed meshes).  Evaluated
            as integer combinations, so symbols work too.

        Returns
        -------
        (V', E', F', B')
        """
        H = (0, 2, 0, -1)  # half-edges: 2E - B, as coefficients of (V, E, F, B)
        unit = {"V": (1, 0, 0, 0), "E": (0, 1, 0, 0), "F": (0, 0, 1, 0), "H": H}
        per = {"halfedge": "H", "face": "F", "vertex": "V", "edge": "E"}
        made = {"halfedge": "H", "face": "H", "vertex": "H", "edge": "E"}

        def plus(a: tuple[int, ...], b: tuple[int, ...], k: int = 1) -> tuple[int, ...]:
            return tuple(x + k * y for x, y in zip(a, b))

        zero: tuple[int, ...] = (0, 0, 0, 0)
        points: tuple[int, ...] = plus(
            plus(zero, unit["V"], int(self.vertices)), unit["E"], len(self.edge_points)
        )
        points = plus(points, unit["F"], int(self.face_points))
        points = plus(points, H, int(self.corner_points is not None))
        faces, corners = zero, zero
        for kind, refs in self.faces:
            faces = plus(faces, unit[per[kind]])
            corners = plus(corners, unit[made[kind]], len(refs))
        rim = self.compiled.boundary_per_edge
        boundary = (0, 0, 0, rim)
        edges = tuple(c // 2 for c in plus(corners, boundary))
        args = (V, E, F, B)

        def value(c: tuple[int, ...]) -> Any:
            return sum((k * x for k, x in zip(c, args) if k), 0 * V)

        return value(points), value(edges), value(faces), value(boundary)

    def __call__(self, mesh: Any, **options: float) -> Any:
        """Apply the table to ``mesh`` (:func:`pentanb.schemes.engine.apply`)."""
        return apply(self, mesh, **options)

    def __repr__(self) -> str:
        return f"Table({self.name!r}, {len(self.faces)} kinds of faces)"
