"""A table checked on small probe meshes, and the formulas of its output's twins.

:func:`compile_table` runs once per :class:`~pentanb.schemes.table.Table`,
before any mesh of the user's is touched.  It evaluates the table's faces on
a handful of small meshes (face sizes 3 to 6, valences 3 to 5, genus 0 and
1, two open ones), pairs the output's half-edges there by their ends, and
refuses a table whose faces do not make an oriented surface, naming the
slot.  For every slot it then finds the slot and the path of moves that
reach the slot's opposite (the shortest path that works on every probe):
those formulas are what the engine evaluates on real meshes, as whole-array
gathers.  Checked on the open probes too; a table whose formulas do not
hold there has its open outputs paired instead.
"""

from __future__ import annotations

import functools
from dataclasses import replace
from typing import Any

import numpy as np

from ..mesh import Mesh
from .engine import (
    PATHS,
    Compiled,
    _bases,
    _Walk,
    faces_of,
    positions,
    rings_of,
    slot_index,
    twins_of,
)
from .refs import Ref, parse_ref

__all__ = ["compile_table", "probes"]


def _grid(nx: int, ny: int, wrap: bool) -> Mesh:
    """A grid of quads: a torus (``wrap``) or an open sheet, in a plane or round a tube."""
    u, v = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    if wrap:
        a, b = 2 * np.pi * u / nx, 2 * np.pi * v / ny
        pts = np.stack([(2 + np.cos(b)) * np.cos(a), (2 + np.cos(b)) * np.sin(a), np.sin(b)], -1)
        cols, rows = nx, ny
    else:
        pts = np.stack([u, v, 0 * u], -1).astype(float)
        cols, rows = nx - 1, ny - 1
    idx = np.arange(nx * ny).reshape(nx, ny)
    quads = [
        [idx[i, j], idx[(i + 1) % nx, j], idx[(i + 1) % nx, (j + 1) % ny], idx[i, (j + 1) % ny]]
        for i in range(cols)
        for j in range(rows)
    ]
    return Mesh(pts.reshape(-1, 3), quads)


def _prism(k: int, closed: bool = True) -> Mesh:
    """A k-gonal prism (two k-gons, k quads); open: the quads alone, a tube."""
    a = 2 * np.pi * np.arange(k) / k
    pts = np.concatenate([np.stack([np.cos(a), np.sin(a), 0 * a], 1)] * 2)
    pts[k:, 2] = 1.0
    faces = [[i, (i + 1) % k, k + (i + 1) % k, k + i] for i in range(k)]
    if closed:
        faces += [list(range(k))[::-1], list(range(k, 2 * k))]
    return Mesh(pts, faces)


@functools.lru_cache(maxsize=1)
def probes() -> tuple[tuple[Mesh, ...], tuple[Mesh, ...]]:
    """The closed and the open probe meshes."""
    tet = Mesh(np.eye(4, 3), [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
    apex = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]], dtype=float)
    pyramid = Mesh(
        apex,
        [[3, 2, 1, 0], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
    )
    fan = Mesh(
        apex,
        [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
    )
    closed = (tet, _prism(3), _prism(5), pyramid, _prism(6), _grid(4, 3, True))
    return closed, (_grid(3, 3, False), fan, _prism(5, closed=False))


def _pairs(corners: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, int]:
    """The opposite of every output half-edge of a probe (-1: none), and a doubled one or -1."""
    nxt = np.arange(corners.size) + 1
    nxt[offsets[1:] - 1] = offsets[:-1]
    seen: dict[tuple[int, int], int] = {}
    for h, (a, b) in enumerate(zip(corners.tolist(), corners[nxt].tolist())):
        if (a, b) in seen:
            return np.zeros(0, dtype=np.int64), h
        seen[a, b] = h
    twin = np.array([seen.get((b, a), -1) for (a, b) in seen], dtype=np.int64)
    return twin, -1


def _where(decls: tuple, d: int, s: int) -> str:
    kind, refs = decls[d]
    corner = f"{refs[s]} -> {refs[(s + 1) % len(refs)]}"
    return f"faces[{d}] ({kind}: {', '.join(map(str, refs))}), slot {s} ({corner})"


def _decode(walk: Any, decls: tuple, starts: list, y: np.ndarray):
    """(kind index, slot, base half-edge) of every output half-edge ``y``."""
    d = np.searchsorted(np.asarray(starts), y, side="right") - 1
    base, slot = np.empty_like(y), np.empty_like(y)
    for i, (kind, refs) in enumerate(decls):
        mine = d == i
        g, slot[mine] = np.divmod(y[mine] - starts[i], len(refs))
        if kind == "vertex":
            g = walk.m.vertex_ring[0][g]
        elif kind == "edge":
            g = walk.m.edge_halfedge[g]
        base[mine] = g
    return d, slot, base


def _sources(walk: Any, kind: str) -> np.ndarray:
    base = _bases(walk, kind)
    return np.arange(walk.H) if base is None else np.asarray(base)


def compile_table(table: Any) -> Any:
    """Check ``table`` and derive its twins' formulas (a :class:`~pentanb.schemes.engine.Compiled`).

    Raises
    ------
    ValueError
        Naming the slot: an element the table has no points for, a face with
        a repeated corner, faces that run along an edge the same way (an
        orientation flip) or leave an edge with one face on a closed mesh
        (twins that do not pair), an edge face that differs seen from its
        two half-edges.
    """
    name = f"table {table.name!r}"
    k = len(table.edge_points)
    decls = []
    for d, (kind, texts) in enumerate(table.faces):
        refs = tuple(parse_ref(t, f"{name}, faces[{d}]") for t in texts)
        for ref in refs:
            _check_element(ref, table, k, f"{name}, faces[{d}]")
        decls.append((kind, refs))
    decls_t = tuple(decls)
    open_rule = _open_rule(decls_t, table)
    paired = any(r.fallback is not None for _, refs in decls_t for r in refs)
    closed, open_ = probes()
    draft = Compiled(decls_t, (), (), (), open_rule, paired, 0)
    runs = []
    for mesh in closed:
        walk = _Walk(mesh, table, np.int64)
        corners, offsets, starts = faces_of(walk, draft, np.int64)
        _check_faces(corners, offsets, starts, decls_t, name)
        twin, doubled = _pairs(corners, offsets)
        if doubled >= 0 or (twin < 0).any():
            y = doubled if doubled >= 0 else int(np.flatnonzero(twin < 0)[0])
            d, s, _ = _decode(walk, decls_t, starts, np.array([y]))
            why = (
                "two faces run along one edge the same way (an orientation flip)"
                if doubled >= 0
                else "its edge has one face on a closed mesh (the twins do not pair)"
            )
            raise ValueError(f"{name}, {_where(decls_t, int(d[0]), int(s[0]))}: {why}")
        runs.append((walk, starts, twin, corners, offsets))
    _check_orientation(table, draft, closed[1], name)  # (a prism: convex)
    turns = tuple(_turn(runs[0][0], decls_t, d, name) for d in range(len(decls_t)))
    twins = tuple(
        tuple(_formula(runs, decls_t, turns, d, s, name) for s in range(len(refs)))
        for d, (_, refs) in enumerate(decls_t)
    )
    found = Compiled(decls_t, twins, turns, (), open_rule, paired, 0)
    rings = _ring_rules(runs, found, table, name)
    rim = 0
    if open_rule is None:
        for mesh in open_:
            walk = _Walk(mesh, table, np.int64)
            corners, offsets, starts = faces_of(walk, found, np.int64)
            twin, doubled = _pairs(corners, offsets)
            if doubled >= 0:
                d, s, _ = _decode(walk, decls_t, starts, np.array([doubled]))
                where = _where(decls_t, int(d[0]), int(s[0]))
                raise ValueError(f"{name}, {where}: an orientation flip on an open mesh")
            rim = int(np.count_nonzero(twin < 0)) // mesh.n_boundary_edges
            if not paired and not np.array_equal(twins_of(walk, found, starts, twin.size), twin):
                paired = True  # (the formulas do not hold at the boundary: pair there)
    return Compiled(decls_t, twins, turns, rings, open_rule, paired, rim)


def _check_element(ref: Ref, table: Any, k: int, where: str) -> None:
    while ref is not None:
        if ref.elem == "E" and ref.j >= k:
            raise ValueError(f"{where}: {ref} names edge point {ref.j}, the table has {k}")
        if ref.elem == "F" and not table.face_points:
            raise ValueError(f"{where}: {ref} names a face point; set face_points=True")
        if ref.elem == "C" and table.corner_points is None:
            raise ValueError(f"{where}: {ref} names a corner point; give corner_points")
        ref = ref.fallback  # type: ignore[assignment]


def _open_rule(decls: tuple, table: Any) -> str | None:
    """None when the table runs on open meshes, else the reason it does not."""
    if any(kind == "vertex" for kind, _ in decls):
        return "its faces round vertices need a boundary rule (the dual's page has one)"

    def safe(ref: Ref | None) -> bool:
        if ref is None:
            return False
        if "t" not in ref.path or (ref.path.rindex("t") == len(ref.path) - 1 and ref.elem in "VE"):
            return True
        return safe(ref.fallback)

    for _kind, refs in decls:
        for ref in refs:
            if not safe(ref):
                return f"{ref} crosses the boundary and has no fallback ('{ref}|...')"
    return None


def _check_orientation(table: Any, compiled: Any, mesh: Mesh, name: str) -> None:
    """The faces must turn as the input's do (counter-clockwise seen from outside):
    on a convex probe, the output encloses a volume of the input's sign."""
    walk = _Walk(mesh, table, np.int64)
    corners, offsets, _ = faces_of(walk, compiled, np.int64)
    v = positions(walk, table, compiled, dict(table.options))
    out = Mesh.from_csr(v, corners, offsets, validate=False)
    if out.volume * mesh.volume <= 0:
        raise ValueError(
            f"{name}: its faces turn clockwise seen from outside (an orientation flip): "
            "list every face's corners counter-clockwise, as the input's"
        )


def _check_faces(corners, offsets, starts, decls, name: str) -> None:
    """No output face may repeat a corner (a face that does not close into a polygon)."""
    for f in range(offsets.size - 1):
        face = corners[offsets[f] : offsets[f + 1]]
        if np.unique(face).size != face.size:
            d = int(np.searchsorted(np.asarray(starts), offsets[f], side="right") - 1)
            kind, refs = decls[d]
            raise ValueError(
                f"{name}, faces[{d}] ({kind}: {', '.join(map(str, refs))}): a face repeats "
                "a corner (two references name the same point)"
            )


def _turn(walk: Any, decls: tuple, d: int, name: str) -> int:
    """How far an edge face's corners turn seen from its other half-edge (0 otherwise)."""
    kind, refs = decls[d]
    if kind != "edge":
        return 0
    eh = np.asarray(walk.m.edge_halfedge)
    here = np.stack([walk.point(r)[eh] for r in refs], 1)
    there = np.stack([walk.point(r)[walk.m.twin[eh]] for r in refs], 1)
    rho = len(refs) // 2
    if len(refs) % 2 == 0 and np.array_equal(there, np.roll(here, -rho, axis=1)):
        return rho
    raise ValueError(
        f"{name}, faces[{d}] (edge: {', '.join(map(str, refs))}): seen from the edge's other "
        "half-edge the references must make the same face, turned by half (slot s from one "
        "half-edge is slot s + r/2 from the other)"
    )


def _formula(runs: list, decls: tuple, turns: tuple, d: int, s: int, name: str):
    """``(path, d', s')``: the opposite of slot s of kind d, the same on every probe."""
    wanted = []
    for walk, starts, twin, _, _ in runs:
        src = _sources(walk, decls[d][0])
        y = twin[starts[d] + len(decls[d][1]) * np.arange(src.size) + s]
        wanted.append((walk, src, _decode(walk, decls, starts, y)))
    d2s = {int(x) for _, _, (dd, _, _) in wanted for x in np.unique(dd)}
    if len(d2s) == 1:
        d2 = d2s.pop()
        r2 = len(decls[d2][1])
        for path in PATHS:
            slot = None
            for walk, src, (_, s2, base2) in wanted:
                x = src if not path else walk.at(path)[0][src]
                m = walk.m
                if decls[d2][0] == "edge":
                    if not np.array_equal(m.halfedge_edge[x], m.halfedge_edge[base2]):
                        break
                    down = ~(m.corners[x] < m.head[x])
                    got = np.unique((s2 - turns[d2] * down) % r2)
                elif np.array_equal(x, base2):
                    got = np.unique(s2)
                else:
                    break
                if got.size != 1 or (slot is not None and int(got[0]) != slot):
                    break
                slot = int(got[0])
            else:
                return path, d2, slot
    raise ValueError(
        f"{name}, {_where(decls, d, s)}: its opposite is not one slot at a fixed path "
        "(no local rule pairs it; is the table a local operator?)"
    )


def _inverse(path: str) -> str:
    """The path back: moves reversed, next and prev swapped."""
    return "".join({"n": "p", "p": "n", "t": "t"}[c] for c in reversed(path))


def _ring_rules(runs: list, compiled: Any, table: Any, name: str) -> tuple:
    """The rules of every block's rings (see :class:`~pentanb.schemes.engine.Compiled`).

    The output half-edges leaving a point are those whose first corner
    names it: slot s of kind d at base b leaves the element of ``path(b)``,
    so from the point's own half-edge h it is slot s at ``path^-1(h)``.
    Their order round the point is read off one probe and checked on all.
    """
    k = len(table.edge_points)
    blocks: dict[str, list] = {"V": [], "F": [], "C": []}
    edge: list[list] = [[] for _ in range(k)]
    for d, (kind, refs) in enumerate(compiled.faces):
        for s, ref in enumerate(refs):
            if kind == "edge" and s >= compiled.turns[d]:
                continue  # (an edge's face from both its half-edges: half its slots each)
            back = _inverse(ref.path)
            if ref.elem == "E":
                edge[ref.j].append((back, d, s))
                edge[k - 1 - ref.j].append(("t" + back, d, s))
                if 2 * ref.j == k - 1:
                    edge[ref.j].pop()  # (the middle point: once from each half-edge)
                    edge[ref.j].append(("t" + back, d, s))
            else:
                blocks[ref.elem].append((back, d, s))
    want: dict[str, list | None] = {
        "V": [blocks["V"]] if table.vertices else None,
        "E": edge if k else None,
        "F": [blocks["F"]] if table.face_points else None,
        "C": [blocks["C"]] if table.corner_points is not None else None,
    }
    rules = tuple(
        None if g is None else tuple(_ordered(runs, compiled, b, x, name) for x in g)
        for b, g in ((b, want[b]) for b in "VEFC")
    )
    done = replace(compiled, rings=rules)
    for walk, starts, _, corners, offsets in runs:  # every ring, on every probe
        got = rings_of(walk, done, starts, np.int64)
        ring, off = _derived_rings(corners, offsets)
        if not (np.array_equal(got[0], ring) and np.array_equal(got[1], off)):
            return ()  # (not in turn on every probe: the output's rings are walked)
    return rules


def _derived_rings(corners: np.ndarray, offsets: np.ndarray) -> tuple:
    """The vertex rings of a probe's output, as the Mesh derives them."""
    out = Mesh.from_csr(np.zeros((int(corners.max()) + 1, 3)), corners, offsets, validate=False)
    return out.vertex_ring


def _ordered(runs: list, compiled: Any, block: str, group: list, name: str) -> tuple:
    """The rules of ``group`` in their order round the point, from the first probe."""
    if not group:
        what = {"V": "the old vertices", "E": "the edge points", "F": "the face points"}
        point = what.get(block, "the corner points")
        raise ValueError(
            f"{name}: {point} of the table are in no face; every point must be a corner of "
            "some face (drop it, or use it in faces)"
        )
    walk, starts, _, corners, offsets = runs[0]
    m = walk.m
    vals = np.stack([slot_index(walk, compiled, starts, r) for r in group], 1)  # (H, c)
    h0 = int(m.edge_halfedge[0]) if block == "E" else 0
    if block == "V":
        ring, off = m.vertex_ring
        v = int(m.corners[h0])
        units = ring[off[v] : off[v + 1]]
    elif block == "F":
        units = np.arange(m.offsets[0], m.offsets[1])
    else:
        units = np.array([h0])
    seq = vals[units]  # (units, c): the rules' half-edges, units in order
    ring, off = _derived_rings(corners, offsets)
    c = len(group)
    for q in range(c):
        start = int(seq[0, q])
        tail = int(corners[start])
        actual = ring[off[tail] : off[tail + 1]].tolist()
        if len(actual) != seq.size:
            raise ValueError(f"{name}: the ring of a {block} point is not made of its rules")
        first = actual.index(start)
        turned = actual[first:] + actual[:first]
        if sorted(turned[:c]) == sorted(seq[0].tolist()):
            order = [int(np.flatnonzero(seq[0] == x)[0]) for x in turned[:c]]
            return tuple(group[i] for i in order)
    raise ValueError(f"{name}: the edges round a {block} point are not in turn")
