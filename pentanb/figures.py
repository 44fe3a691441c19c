"""Every figure of the paper, one function each, with the claims it makes.

``figure1()`` ... ``figure13()`` redraw the paper's Figures 1-13,
:func:`equation1` draws Section 4 (equation (1) and the ``(n, m)`` chart) and
:func:`convergence_figure` measures what the paper only "visually
confirmed" (G1 convergence under duals).  Each returns a
:class:`matplotlib.figure.Figure` whose panels are labelled ``(A)``,
``(B)``, ... as in the paper.

:data:`FIGURES` maps a file stem (``"fig07"``) to a :class:`FigureSpec`:
its drawing function, the paper's caption, and ``claims()``, which builds the
same meshes and returns what the paper says of them next to what we measure
(:class:`Claim`).  ``python -m pentanb figures`` draws them all into
``figures/`` and prints the claims (:func:`report`).

Meshes are built once per process (cached builders below; meshes are
immutable), so drawing a figure and checking its claims share the work.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from . import shapes, topology
from .mesh import Mesh
from .schemes import SCHEMES, dual
from .schemes.classic import honeycomb, loop_remesh, preserve_hexagons, triangulate
from .schemes.pentagonal import pentagonalize, preserve_pentagons
from .shapes import hard_edged_cube
from .subdivision import subdivide
from .viz import mpl as vz
from .viz.colors import EDGE_COLOR, face_color, face_label

__all__ = [
    "Claim",
    "FigureSpec",
    "FIGURES",
    "claims",
    "render",
    "render_all",
    "report",
    "check_all",
    "scheme_claims",
    "vertex_configurations",
    "face_configurations",
    "configuration_counts",
    "canonical_configuration",
    "hard_edged_cube",
    "pillow",
    "equation1",
    "convergence_figure",
] + [f"figure{i}" for i in range(1, 14)]


# ====================================================================== claims
@dataclass(frozen=True)
class Claim:
    """One statement of the paper, checked on our meshes.

    Attributes
    ----------
    text : str
        What the paper says (or what follows from it), naming the panel.
    expected : object
        The value the statement predicts.
    measured : object
        The value measured on the mesh.
    holds : bool
        Whether the measurement agrees.
    """

    text: str
    expected: object
    measured: object
    holds: bool

    def __str__(self) -> str:
        mark = "ok  " if self.holds else "FAIL"
        return (
            f"[{mark}] {self.text}: expected {_fmt(self.expected)}, measured {_fmt(self.measured)}"
        )


def _fmt(x) -> str:
    if isinstance(x, float):
        return f"{x:.4g}"
    if isinstance(x, Fraction):
        return str(x) if x.denominator == 1 else f"{x} = {float(x):.4g}"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{k}: {_fmt(v)}" for k, v in x.items()) + "}"
    if isinstance(x, tuple):
        return "(" + ", ".join(_fmt(v) for v in x) + ")"
    if isinstance(x, list):
        return "[" + ", ".join(_fmt(v) for v in x) + "]"
    return str(x)


def _eq(text: str, expected, measured) -> Claim:
    """A claim that holds when ``measured == expected``."""
    return Claim(text, expected, measured, bool(expected == measured))


def _check(text: str, expected, measured, holds) -> Claim:
    return Claim(text, expected, measured, bool(holds))


def _vef(mesh: Mesh) -> tuple[int, int, int]:
    return mesh.n_vertices, mesh.n_edges, mesh.n_faces


def _counts_claims(
    panel: str, before: Mesh, after: Mesh, scheme: str, iterations: int = 1
) -> list[Claim]:
    """V, E, F of ``after`` against the scheme's count formula applied to ``before``."""
    s = SCHEMES[scheme]
    vef = _vef(before)
    for _ in range(iterations):
        vef = s.counts(*vef)
    times = "" if iterations == 1 else f" x{iterations}"
    return [
        _eq(
            f"{panel} (V, E, F) = {s.label.lower()}{times} formula "
            f"{formula(scheme)} from (V, E, F) = {_vef(before)}",
            vef,
            _vef(after),
        )
    ]


def formula(scheme: str) -> str:
    """A scheme's count formula as text, e.g. ``"(V+2E+F, 5E, 2E)"`` (see
    :attr:`pentanb.Scheme.formula`)."""
    return SCHEMES[scheme].formula


# ====================================================================== configurations
def _canonical_rows(seqs: np.ndarray) -> np.ndarray:
    """Lexicographically smallest rotation or reflection of every row ((k, n) int)."""
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
    """Canonical cyclic sequences ``values[order[offsets[i]:offsets[i+1]]]`` as strings."""
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

    Returns
    -------
    (n,) list of str
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

    Returns
    -------
    (m,) list of str
    """
    order = np.arange(mesh.n_halfedges, dtype=np.int64)
    return _configurations(mesh.valences[mesh.corners], mesh.face_sizes, order, mesh.offsets)


def canonical_configuration(config: str | Sequence[int]) -> str:
    """Canonical form of a configuration given in any rotation, e.g. the paper's "4.3.3.4.3"."""
    seq = [int(x) for x in config.split(".")] if isinstance(config, str) else list(config)
    return ".".join(map(str, _canonical_rows(np.array([seq]))[0].tolist()))


def configuration_counts(configs: Iterable[str]) -> dict[str, int]:
    """``{configuration: count}``, most frequent first (ties by name)."""
    names, counts = np.unique(
        np.asarray(list(configs), dtype=object).astype(str), return_counts=True
    )
    pairs = sorted(zip(names.tolist(), counts.tolist()), key=lambda p: (-p[1], p[0]))
    return {k: int(v) for k, v in pairs}


# ====================================================================== meshes
def pillow(n: int, radius: float = 1.0) -> Mesh:
    """A flat closed mesh of two faces: a regular n-gon (face 0, facing +z) and its back.

    The operators work on closed meshes; drawing only the sub-faces of face
    0 shows what a scheme does to one polygon (Figures 6 and 10).
    """
    t = 2 * np.pi * (np.arange(n) / n) + np.pi / 2
    v = np.stack([radius * np.cos(t), radius * np.sin(t), np.zeros(n)], axis=1)
    poly = np.arange(n)
    # two faces sharing all their edges: a valid 2-manifold (a "dihedron"), but
    # its 2-valent vertices are refused by the Mesh constructor (whose dual
    # they would break); pentagonalize and preserve_pentagons handle it
    return Mesh.from_csr(v, np.concatenate([poly, poly[::-1]]), [0, n, 2 * n], validate=False)


@functools.cache
def _m(key: str) -> Mesh:
    """Every mesh the figures use, built once."""
    p = lambda m, k=1: subdivide(m, "pentagonalize", k, 2)  # noqa: E731
    builders: dict[str, Callable[[], Mesh]] = {
        "hard_cube": shapes.hard_edged_cube,
        "fig1B": lambda: p(_m("hard_cube")),
        "fig1C": lambda: p(_m("fig1B")),
        "fig1D": lambda: subdivide(_m("fig1B"), "preserve_pentagons", 1, 2),
        "hard_cube_honeycomb1": lambda: subdivide(_m("hard_cube"), "honeycomb", 1, 2),
        "hard_cube_honeycomb2": lambda: subdivide(_m("hard_cube"), "honeycomb", 2, 2),
        "cube": shapes.cube,
        "fig2B": lambda: triangulate(_m("cube")),
        "fig2C": lambda: triangulate(_m("fig2B")),
        "mixed": _capped_prism,
        "fig3B": lambda: loop_remesh(_m("mixed")),
        "fig3C": lambda: loop_remesh(_m("fig3B")),
        "hex_torus": shapes.hexagonal_torus,
        "hex_genus2": lambda: shapes.hexagonal_surface(2),
        "fig5A": lambda: subdivide(_m("hex_torus"), "preserve_hexagons", 2, 2),
        "fig5B": lambda: subdivide(_m("hex_genus2"), "preserve_hexagons", 2, 2),
        "tet": shapes.tetrahedron,
        "fig7B": lambda: pentagonalize(_m("tet")),
        "fig7C": lambda: dual(_m("fig7B")),
        "fig7D": lambda: dual(_m("fig7C")),
        "fig7E": lambda: dual(dual(dual(_m("fig7D")))),
        "fig7F": lambda: dual(_m("fig7E")),
        "fig8A": lambda: p(_m("hard_cube")),
        "fig8B": lambda: dual(_m("fig8A")),
        "fig9A": lambda: p(_m("hex_torus")),
        "fig9B": lambda: dual(_m("fig9A")),
        "grid_cube": lambda: shapes.hard_edged_cube(1 / 3),
        "fig11A": lambda: subdivide(_m("grid_cube"), "preserve_pentagons", 1, 2),
        "fig11B": lambda: dual(_m("fig11A")),
        "fig11A2": lambda: subdivide(_m("fig11A"), "preserve_pentagons", 1, 2),
        "animal": shapes.animal,
        "fig12B": lambda: p(_m("animal"), 2),
        "dodeca": shapes.dodecahedron,
        "pent_cube": lambda: p(_m("cube")),
        "fig13A": lambda: subdivide(_m("dodeca"), "honeycomb", 1, 2),
        "fig13B": lambda: subdivide(_m("pent_cube"), "honeycomb", 1, 2),
        "fig13C": lambda: subdivide(_m("dodeca"), "preserve_hexagons", 1, 2),
        "fig13D": lambda: subdivide(_m("pent_cube"), "preserve_hexagons", 1, 2),
    }
    return builders[key]()


def _capped_prism() -> Mesh:
    """A house-like pentagonal prism with a pyramid at its back: a pentagon, five
    quads and five triangles (the mixed mesh of Figure 3 and :func:`scheme_claims`)."""
    t = 2 * np.pi * np.arange(5) / 5 + np.pi / 2
    ring = np.stack([np.cos(t), np.sin(t)], axis=1)  # in the x-z plane
    front = np.column_stack([ring[:, 0], np.full(5, -1.0), ring[:, 1]])
    back = np.column_stack([ring[:, 0], np.full(5, 0.5), ring[:, 1]])
    v = np.concatenate([front, back, [[0.0, 1.7, 0.0]]])
    faces = [[0, 1, 2, 3, 4]]
    faces += [[i, 5 + i, 5 + (i + 1) % 5, (i + 1) % 5] for i in range(5)]
    faces += [[5 + (i + 1) % 5, 5 + i, 10] for i in range(5)]
    return _oriented(v, faces)


def _oriented(v, faces) -> Mesh:
    """A mesh whose faces are all turned outwards (a convex solid around its centroid)."""
    c = v.mean(axis=0)
    out = []
    for f in faces:
        p = v[f]
        normal = np.cross(p[1] - p[0], p[2] - p[0])
        out.append(f if normal @ (p.mean(axis=0) - c) > 0 else f[::-1])
    return Mesh(v, out)


# ====================================================================== drawing helpers
def _panel_text(letter: str, text: str, mesh: Mesh | None = None) -> str:
    label = f"({letter}) {text}"
    if mesh is not None:
        label += f"\nV {mesh.n_vertices:,}  E {mesh.n_edges:,}  F {mesh.n_faces:,}"
    return label


def _mesh_figure(
    panels: Sequence[tuple[Mesh, str, dict]],
    *,
    ncols: int | None = None,
    suptitle: str,
    panel_size: float = 3.0,
    counts: bool = True,
    aspect: float = 1.0,
) -> Figure:
    """A figure of 3-D mesh panels, labelled (A), (B), ..., with a face-size legend."""
    with vz.style():
        fig, axes = vz.panel_figure(
            len(panels),
            ncols,
            panel_size=panel_size,
            suptitle=suptitle,
            legend_space=0.55,
            aspect=aspect,
        )
        for i, (ax, (mesh, text, kw)) in enumerate(zip(axes, panels)):
            vz.draw_mesh(ax, mesh, **kw)
            vz.label_panel(ax, _panel_text("ABCDEFGH"[i], text, mesh if counts else None))
        vz.add_face_legend(fig, [m for m, _, _ in panels])
    return fig


# ====================================================================== Figure 1
def figure1() -> Figure:
    """Figure 1: a hard-edged cube (A), one (B) and two (C) pentagonalizations,
    pentagon preservation applied to (B) (D); each smoothed by two duals."""
    return _mesh_figure(
        [
            (_m("hard_cube"), "hard-edged cube", {}),
            (_m("fig1B"), "one pentagonalization", {}),
            (_m("fig1C"), "two pentagonalizations", {}),
            (_m("fig1D"), "pentagon preservation of (B)", {}),
        ],
        ncols=4,
        suptitle="Figure 1. Pentagonal subdivision examples (each step followed by two duals)",
    )


def claims1() -> list[Claim]:
    a, b, c, d = (_m(k) for k in ("hard_cube", "fig1B", "fig1C", "fig1D"))
    out = [
        _eq(
            "(A) hard-edged cube: 54 quads, genus 0",
            ({4: 54}, 0),
            (a.face_size_histogram(), a.genus),
        )
    ]
    out += _counts_claims("(B)", a, b, "pentagonalize")
    out.append(
        _eq(
            "(B) one pentagonalization: only pentagons", {5: 2 * a.n_edges}, b.face_size_histogram()
        )
    )
    out += _counts_claims("(C)", a, c, "pentagonalize", 2)
    out.append(
        _eq("(C) two pentagonalizations: only pentagons", [5], sorted(c.face_size_histogram()))
    )
    out += _counts_claims("(D)", b, d, "preserve_pentagons")
    out.append(
        _eq(
            "(D) pentagon preservation of a pentagonal mesh: only pentagons",
            [5],
            sorted(d.face_size_histogram()),
        )
    )
    # "the new subdivision does not create any lateral artifact": along a
    # straight edge the surface keeps its distance from the edge's axis;
    # compared with honeycomb (dual of sqrt(3)), a (6, 3) scheme of [5]
    from .analysis.convergence import edge_waviness

    for panel, mesh, k in (("(B)", b, 1), ("(C)", c, 2)):
        w = edge_waviness(mesh)
        wh = edge_waviness(_m(f"hard_cube_honeycomb{k}"))
        out.append(
            _check(
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
        _check(
            "(C) the smoothed mesh keeps the cube's 24 rotations (largest vertex mismatch / size)",
            "< 1e-9",
            sym,
            sym < 1e-9,
        )
    )
    return out


def _cube_rotations() -> np.ndarray:
    """The 24 rotation matrices of the cube."""
    import itertools

    mats = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product([1, -1], repeat=3):
            r = np.zeros((3, 3))
            r[np.arange(3), perm] = signs
            if np.linalg.det(r) > 0:
                mats.append(r)
    return np.array(mats)


def _symmetry_error(mesh: Mesh) -> float:
    """Largest distance from a rotated vertex to the nearest vertex, over the cube's rotations."""
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


# ====================================================================== Figure 2
def figure2() -> Figure:
    """Figure 2: the simplest triangulation (A -> B) and a second application (C)."""
    return _mesh_figure(
        [
            (_m("cube"), "initial mesh", {}),
            (_m("fig2B"), "non-triangles split", {}),
            (_m("fig2C"), "applied again: no change", {}),
        ],
        suptitle="Figure 2. The simplest triangulation cannot be used iteratively",
    )


def claims2() -> list[Claim]:
    b, c = _m("fig2B"), _m("fig2C")
    same = (
        np.array_equal(b.vertices, c.vertices)
        and np.array_equal(b.corners, c.corners)
        and np.array_equal(b.offsets, c.offsets)
    )
    return [
        _eq(
            "(B) every non-triangle of the cube fanned into triangles: (V, E, F), faces",
            ((8 + 6, 12 + 24, 24), {3: 24}),
            (_vef(b), b.face_size_histogram()),
        ),
        _eq(
            "(C) a second application changes nothing (null algorithm): identical mesh",
            True,
            bool(same),
        ),
        _eq("(C) the number of vertices stops growing", b.n_vertices, c.n_vertices),
    ]


# ====================================================================== Figure 3
def figure3() -> Figure:
    """Figure 3: Loop's remeshing applied to a mesh with a pentagon, quads and triangles."""
    kw = {"elev": 24.0, "azim": -30.0}
    return _mesh_figure(
        [
            (_m("mixed"), "initial mesh", kw),
            (_m("fig3B"), "Loop's remeshing", kw),
        ],
        suptitle="Figure 3. A triangle preserving remeshing: Loop's",
    )


def claims3() -> list[Claim]:
    a, b, c = _m("mixed"), _m("fig3B"), _m("fig3C")
    non_tri = {k: v for k, v in a.face_size_histogram().items() if k != 3}
    keep = lambda m: {k: v for k, v in m.face_size_histogram().items() if k != 3}  # noqa
    out = [_eq("(A) a mesh with non-triangles", {3: 5, 4: 5, 5: 1}, a.face_size_histogram())]
    out += _counts_claims("(B)", a, b, "loop_remesh")
    out += [
        _eq(
            "(B) a central face of the same size in every face: non-triangles kept",
            non_tri,
            keep(b),
        ),
        _eq(
            "(B) a triangle at every corner (2E of them) plus the old triangles' centres",
            2 * a.n_edges + a.face_size_histogram()[3],
            b.face_size_histogram()[3],
        ),
        _eq("applied again, the number of non-triangles stays constant", non_tri, keep(c)),
    ]
    return out


# ====================================================================== Figures 4, 5
_TORUS_VIEW = {"elev": 38.0, "azim": -60.0}
_GENUS2_VIEW = {"elev": 40.0, "azim": -75.0}


def figure4() -> Figure:
    """Figure 4: hexagonal meshes of genus 1 (A) and 2 (B)."""
    return _mesh_figure(
        [
            (_m("hex_torus"), "genus 1", _TORUS_VIEW),
            (_m("hex_genus2"), "genus 2", _GENUS2_VIEW),
        ],
        suptitle="Figure 4. Hexagonal meshes for g > 0",
        panel_size=4.0,
        aspect=0.6,
    )


def _valence_claims(panel: str, mesh: Mesh, n: int) -> list[Claim]:
    g, v = mesh.genus, mesh.n_vertices
    eq1 = Fraction(2 * n, n - 2) * (1 + Fraction(2 * g - 2, v))
    return [
        _eq(
            f"{panel} average valence 2E/V = equation (1) m = 2n/(n-2) (1 + (2g-2)/v) "
            f"with n={n}, g={g}, v={v}",
            eq1,
            Fraction(2 * mesh.n_edges, v),
        )
    ]


def claims4() -> list[Claim]:
    a, b = _m("hex_torus"), _m("hex_genus2")
    out = []
    for panel, m, g in (("(A)", a, 1), ("(B)", b, 2)):
        out.append(
            _eq(
                f"{panel} only hexagons, genus {g}",
                ([6], g),
                (sorted(m.face_size_histogram()), m.genus),
            )
        )
        out += _valence_claims(panel, m, 6)
    out.append(_eq("(A) genus 1: every vertex 3-valent", {3: a.n_vertices}, a.valence_histogram()))
    out.append(
        _check(
            "(B) genus 2: m > 3, so some vertices have valence > 3",
            "> 3",
            Fraction(2 * b.n_edges, b.n_vertices),
            Fraction(2 * b.n_edges, b.n_vertices) > 3,
        )
    )
    return out


def figure5() -> Figure:
    """Figure 5: two rounds of hexagon preservation (two duals each) on Figure 4's meshes."""
    return _mesh_figure(
        [
            (_m("fig5A"), "genus 1, two iterations", _TORUS_VIEW),
            (_m("fig5B"), "genus 2, two iterations", _GENUS2_VIEW),
        ],
        suptitle="Figure 5. Two iterations of hexagon preservation (dual of Loop)",
        panel_size=4.0,
        aspect=0.6,
    )


def claims5() -> list[Claim]:
    out = []
    for panel, src, m in (
        ("(A)", _m("hex_torus"), _m("fig5A")),
        ("(B)", _m("hex_genus2"), _m("fig5B")),
    ):
        out += _counts_claims(panel, src, m, "preserve_hexagons", 2)
        out.append(
            _eq(
                f"{panel} hexagonal meshes stay hexagonal, genus kept",
                ([6], src.genus),
                (sorted(m.face_size_histogram()), m.genus),
            )
        )
        extra = lambda x: int((x.valences != 3).sum())  # noqa: E731
        out.append(
            _eq(f"{panel} the number of non-3-valent vertices stays constant", extra(src), extra(m))
        )
    return out


# ====================================================================== Figures 6, 10
def _flat_points(ax, pts, **kw):
    ax.scatter(pts[:, 0], pts[:, 1], zorder=5, **kw)


def _flat_figure(suptitle: str) -> tuple[Figure, list]:
    fig, axes = vz.panel_figure(
        2, panel_size=3.2, projection=None, suptitle=suptitle, legend_space=0.75
    )
    for ax in axes:
        ax.set_xlim(-1.18, 1.18)
        ax.set_ylim(-1.18, 1.18)
        ax.set_aspect("equal")
        ax.set_axis_off()
    return fig, axes


_OLD = {"s": 30, "color": EDGE_COLOR}
_NEW = {"s": 34, "facecolor": "white", "edgecolor": EDGE_COLOR, "linewidths": 1.2}
_CENTRE = {"s": 60, "color": "#D55E00", "marker": "o", "edgecolor": EDGE_COLOR}


def _fig6_data():
    src = pillow(6)
    out = pentagonalize(src)
    n = src.face_sizes[0]
    front = np.arange(n)  # pentagon of half-edge h of face 0 is face h
    return src, out, front


def figure6() -> Figure:
    """Figure 6: pentagonalization of one polygon (a hexagon), drawn flat.

    Computed by :func:`pentagonalize` on :func:`pillow` ``(6)``; only the
    pentagons of the front face are drawn.
    """
    src, out, front = _fig6_data()
    n = src.n_vertices
    with vz.style():
        fig, (a, b) = _flat_figure("Figure 6. Pentagonalization scheme on one face")
        vz.draw_flat(a, src, [0])
        faces = out.corners.reshape(-1, 5)[front]  # (t1, t2, w, t1', c)
        pts = out.vertices
        centre = pts[faces[0, 4]]
        seg = np.stack([np.repeat(centre[None], len(front), 0), pts[faces[:, 0]]], 1)
        vz.draw_segments(
            a, seg[:, :, :2], colors=EDGE_COLOR, linewidths=1.1, linestyles=(0, (3, 2.5)), zorder=3
        )
        _flat_points(a, pts[:n], **_OLD)
        _flat_points(a, pts[np.unique(faces[:, :2])], **_NEW)
        _flat_points(a, centre[None], **_CENTRE)
        a.annotate(
            "point sphere",
            centre[:2],
            xytext=(0.28, -0.3),
            fontsize=8,
            arrowprops={"arrowstyle": "-", "lw": 0.7},
        )
        vz.label_panel(a, "(A) edges cut in three, a point sphere;\ndashed: the edges to insert")
        vz.draw_flat(b, out, front)
        _flat_points(b, pts[:n], **_OLD)
        _flat_points(b, pts[np.unique(faces[:, :2])], **_NEW)
        _flat_points(b, centre[None], **_CENTRE)
        vz.label_panel(b, f"(B) the hexagon becomes {len(front)} pentagons")
        _flat_legend(fig, [6, 5])
    return fig


def _flat_legend(fig, sizes):
    from matplotlib.lines import Line2D

    handles = [
        Patch(facecolor=face_color(n), edgecolor=EDGE_COLOR, label=f"{face_label(n)} ({n})")
        for n in sizes
    ]
    handles += [
        Line2D([], [], ls="none", marker="o", markersize=5, color=EDGE_COLOR, label="old vertex"),
        Line2D(
            [],
            [],
            ls="none",
            marker="o",
            markersize=5.5,
            mfc="white",
            color=EDGE_COLOR,
            label="new vertex",
        ),
    ]
    fig.legend(
        handles=handles, loc="lower center", ncol=4, frameon=False, bbox_to_anchor=(0.5, 0.0)
    )


def claims6() -> list[Claim]:
    src, out, front = _fig6_data()
    n = int(src.face_sizes[0])
    faces = out.corners.reshape(-1, 5)[front]
    p = out.vertices
    old = src.vertices
    # t1 at 1/3 and t2 at 2/3 of every half-edge (u, w) of the front face
    u, w = old[np.arange(n)], old[(np.arange(n) + 1) % n]
    err = max(
        float(np.abs(p[faces[:, 0]] - (2 * u + w) / 3).max()),
        float(np.abs(p[faces[:, 1]] - (u + 2 * w) / 3).max()),
    )
    return [
        _eq(
            f"a {n}-gon is split into as many pentagons as it has edges",
            {5: n},
            {int(k): int(v) for k, v in zip(*np.unique(out.face_sizes[front], return_counts=True))},
        ),
        _check(
            "every edge is cut into 3 equal parts (largest position error)", "0", err, err < 1e-12
        ),
        _eq(
            "every pentagon has one old vertex, three edge points and the point sphere",
            (1, 3, 1),
            (
                int(np.isin(faces, np.arange(n)).sum(axis=1).max()),
                int((faces[:, :4] >= n).sum(axis=1).min()),
                int(np.unique(faces[:, 4]).size),
            ),
        ),
        _check(
            "the point sphere sits at the face's centroid (distance)",
            "0",
            float(np.linalg.norm(p[faces[0, 4]] - old.mean(axis=0))),
            np.allclose(p[faces[0, 4]], old.mean(axis=0)),
        ),
    ]


_FIG10_SCALE = 0.75


def _fig10_data():
    src = pillow(5)
    out = preserve_pentagons(src, scale=_FIG10_SCALE)
    n = int(src.face_sizes[0])
    # face 0: the front face's inner copy; then one pentagon per half-edge (F + h)
    front = np.concatenate([[0], src.n_faces + np.arange(n)])
    return src, out, front


def figure10() -> Figure:
    """Figure 10: pentagon preservation of one polygon (a pentagon), drawn flat.

    Computed by :func:`preserve_pentagons` (scale 0.75) on :func:`pillow`
    ``(5)``; only the faces of the front face are drawn.
    """
    src, out, front = _fig10_data()
    n = src.n_vertices
    pts = out.vertices
    mids = pts[n : n + src.n_edges]
    inner = pts[out.faces[0]]
    with vz.style():
        fig, (a, b) = _flat_figure("Figure 10. Pentagon preserving scheme on one face")
        vz.draw_flat(a, src, [0])
        c = mids.mean(axis=0)
        vz.draw_segments(
            a,
            np.stack([np.repeat(c[None], n, 0), mids], 1)[:, :, :2],
            colors="#777777",
            linewidths=0.8,
            linestyles=(0, (1, 2)),
        )
        ring = np.concatenate([inner, inner[:1]])
        a.plot(ring[:, 0], ring[:, 1], color=EDGE_COLOR, lw=1.1, ls=(0, (3, 2.5)), zorder=3)
        # the edges from the scaled face to the midpoints
        q = out.corners.reshape(-1)[out.offsets[front[1]] : out.offsets[front[-1] + 1]]
        pent = q.reshape(-1, 5)  # (m_h, w, m_next, q_next, q_h)
        vz.draw_segments(
            a,
            np.stack([pts[pent[:, 0]], pts[pent[:, 4]]], 1)[:, :, :2],
            colors=EDGE_COLOR,
            linewidths=1.1,
            linestyles=(0, (3, 2.5)),
        )
        _flat_points(a, pts[:n], **_OLD)
        _flat_points(a, mids, **_NEW)
        _flat_points(a, inner, **_NEW)
        vz.label_panel(
            a, f"(A) the midpoints' polygon scaled\nby {_FIG10_SCALE}; dashed: the edges to insert"
        )
        vz.draw_flat(b, out, front)
        _flat_points(b, pts[:n], **_OLD)
        _flat_points(b, mids, **_NEW)
        _flat_points(b, inner, **_NEW)
        vz.label_panel(b, f"(B) {n} pentagons around a smaller pentagon")
        _flat_legend(fig, [5])
    return fig


def claims10() -> list[Claim]:
    src, out, front = _fig10_data()
    n = int(src.face_sizes[0])
    p = out.vertices
    mids = p[n : n + src.n_edges]
    c = mids.mean(axis=0)
    err = float(np.abs(p[out.faces[0]] - (c + _FIG10_SCALE * (mids - c))).max())
    sizes = out.face_sizes[front]
    return [
        _eq(
            f"a {n}-gon becomes {n} pentagons plus a central {n}-gon: only pentagons",
            {5: n + 1},
            {int(k): int(v) for k, v in zip(*np.unique(sizes, return_counts=True))},
        ),
        _check(
            f"the central face is the edge midpoints scaled by {_FIG10_SCALE} "
            "about their centroid (largest error)",
            "0",
            err,
            err < 1e-12,
        ),
        _eq(
            "every vertex of the central face is joined to its midpoint (3-valent)",
            {3: n},
            {3: int((out.valences[out.faces[0]] == 3).sum())},
        ),
    ]


# ====================================================================== Figure 7
def figure7() -> Figure:
    """Figure 7: tetrahedron (A), pentagonalized (B), its dual (C), the dual of that
    (D), the 5th (E) and 6th (F) duals.  Each panel is scaled to fit."""
    kw = {"elev": 22.0, "azim": 25.0}
    return _mesh_figure(
        [
            (_m("tet"), "tetrahedron", kw),
            (_m("fig7B"), "pentagonalized", kw),
            (_m("fig7C"), "dual of (B)", kw),
            (_m("fig7D"), "dual of (C)", kw),
            (_m("fig7E"), "5th dual", kw),
            (_m("fig7F"), "6th dual", kw),
        ],
        ncols=3,
        suptitle="Figure 7. Conversion of a tetrahedron to a dodecahedron",
    )


def _radius_spread(mesh: Mesh) -> float:
    r = np.linalg.norm(mesh.vertices - mesh.vertices.mean(axis=0), axis=1)
    return float(r.std() / r.mean())


def claims7() -> list[Claim]:
    b, c, d, e, f = (_m(f"fig7{k}") for k in "BCDEF")
    dodeca = ({5: 12}, {3: 20}, (20, 30, 12))
    icosa = ({3: 20}, {5: 12}, (12, 30, 20))
    top = lambda m: (m.face_size_histogram(), m.valence_histogram(), _vef(m))  # noqa
    spreads = [_radius_spread(m) for m in (b, d, f)]
    return [
        _eq(
            "(B) the tetrahedron pentagonalized is a dodecahedron: 12 pentagons, "
            "20 3-valent vertices",
            dodeca,
            top(b),
        ),
        _eq("(C) its dual is icosahedral", icosa, top(c)),
        _eq("(D) the dual of (C) is dodecahedral", dodeca, top(d)),
        _eq("(E) the 5th dual is icosahedral", icosa, top(e)),
        _eq("(F) the 6th dual is dodecahedral", dodeca, top(f)),
        _check(
            "the shape becomes more uniform with every dual: spread of vertex "
            "radii (std/mean) of (B), (D), (F) decreases",
            "decreasing",
            tuple(round(s, 4) for s in spreads),
            spreads[0] > spreads[1] > spreads[2],
        ),
    ]


# ====================================================================== Figures 8, 9, 11
def figure8() -> Figure:
    """Figure 8: pentagonalization of the hard-edged cube with two duals (A) and its dual (B)."""
    return _mesh_figure(
        [
            (_m("fig8A"), "one iteration, two duals", {}),
            (_m("fig8B"), "dual of (A)", {}),
        ],
        suptitle="Figure 8. 4.3.3.4.3 semi-regular tiling from pentagonalizing a cube",
        panel_size=3.6,
    )


def _config_claims(
    a: Mesh, b: Mesh, paper: str, expected: dict[str, int], kind: str
) -> list[Claim]:
    canon = canonical_configuration(paper)
    fa = configuration_counts(face_configurations(a))
    vb = configuration_counts(vertex_configurations(b))
    pent = {5: a.n_faces}
    return [
        _eq("(A) only pentagons", pent, a.face_size_histogram()),
        _eq(
            f"(A) {paper} {kind} regions: pentagons by the valences of their corners "
            f"({paper} = {canon} up to rotation)",
            expected,
            fa,
        ),
        _eq(
            f"(B) the dual has {paper} semi-regular regions: vertices by the sizes of "
            "the faces around them",
            expected,
            vb,
        ),
    ]


def claims8() -> list[Claim]:
    a, b, src = _m("fig8A"), _m("fig8B"), _m("hard_cube")
    # every pentagon belongs to a half-edge (u, w) of the cube and has w as a
    # corner: 4.3.3.4.3 when w is a 4-valent grid vertex, 4.3.3.3.3 at the 8 corners
    corners3 = int(src.valences[src.valences == 3].sum())
    expected = {"3.3.4.3.4": a.n_faces - corners3, "3.3.3.3.4": corners3}
    return _config_claims(a, b, "4.3.3.4.3", expected, "semi-regular")


def figure9() -> Figure:
    """Figure 9: pentagonalization of the hexagonal torus with two duals (A) and its dual (B)."""
    return _mesh_figure(
        [
            (_m("fig9A"), "one iteration, two duals", _TORUS_VIEW),
            (_m("fig9B"), "dual of (A)", _TORUS_VIEW),
        ],
        suptitle="Figure 9. 6.3.3.3.3 semi-regular tiling from pentagonalizing the hexagonal torus",
        panel_size=4.0,
        aspect=0.6,
    )


def claims9() -> list[Claim]:
    a, b = _m("fig9A"), _m("fig9B")
    return _config_claims(a, b, "6.3.3.3.3", {"3.3.3.3.6": a.n_faces}, "semi-regular")


def figure11() -> Figure:
    """Figure 11: pentagon preservation (scale 0.75) of a cube whose faces are 3x3 grids,
    with two duals (A), and its dual (B)."""
    return _mesh_figure(
        [
            (_m("fig11A"), "3x3-grid cube: one iteration, two duals", {}),
            (_m("fig11B"), "dual of (A)", {}),
        ],
        suptitle="Figure 11. A semi-regular tiling from pentagon preservation of a cube",
        panel_size=3.6,
    )


def claims11() -> list[Claim]:
    src, a, b, a2 = _m("grid_cube"), _m("fig11A"), _m("fig11B"), _m("fig11A2")
    non5 = lambda m: int((m.face_sizes != 5).sum())  # noqa: E731
    corners3 = int(src.valences[src.valences == 3].sum())
    out = _counts_claims("(A)", src, a, "preserve_pentagons")
    fa = configuration_counts(face_configurations(a))
    vb = configuration_counts(vertex_configurations(b))
    out += [
        _eq(
            "(A) every n-gon gives n pentagons and a central n-gon",
            {4: src.n_faces, 5: 2 * src.n_edges},
            a.face_size_histogram(),
        ),
        _eq(
            "the number of non-pentagons stays constant after the first refinement",
            non5(a),
            non5(a2),
        ),
        _eq(
            "(A) semi-regular regions: pentagons with corner valences 3.3.4.4.4 (grid) "
            "or 3.3.4.3.4 (at the cube's corners), centre quads 3.3.3.3",
            {
                "3.3.4.4.4": 2 * src.n_edges - corners3,
                "3.3.3.3": src.n_faces,
                "3.3.4.3.4": corners3,
            },
            fa,
        ),
        _eq("(B) the dual: vertex configurations are (A)'s face configurations", fa, vb),
    ]
    return out


# ====================================================================== Figure 12
def figure12() -> Figure:
    """Figure 12: a low-poly animal (A), pentagonalized twice with two duals after each
    (B), and (B) shaded without wireframe (C)."""
    kw = {"elev": 18.0, "azim": -55.0}
    return _mesh_figure(
        [
            (_m("animal"), "initial mesh", kw),
            (_m("fig12B"), "pentagonalized twice", kw),
            (_m("fig12B"), "shaded, no wireframe", dict(kw, wireframe=False)),
        ],
        suptitle="Figure 12. Pentagonalization of a low-poly rabbit",
        panel_size=3.4,
    )


def claims12() -> list[Claim]:
    a, b = _m("animal"), _m("fig12B")
    out = [
        _eq(
            "(A) the initial mesh: quads only, genus 0",
            ({4: a.n_faces}, 0),
            (a.face_size_histogram(), a.genus),
        )
    ]
    out += _counts_claims("(B)", a, b, "pentagonalize", 2)
    out.append(
        _eq("(B) only pentagons, genus kept", ([5], 0), (sorted(b.face_size_histogram()), b.genus))
    )
    return out


# ====================================================================== Figure 13
def figure13() -> Figure:
    """Figure 13: soccerball subdivisions of pentagonal meshes.

    Honeycomb (dual of sqrt(3)) of the dodecahedron (A) and of the
    pentagonalized cube (B); hexagon preservation (dual of Loop) of the same
    (C, D).  Two duals after each.
    """
    return _mesh_figure(
        [
            (_m("fig13A"), "honeycomb of a dodecahedron", {}),
            (_m("fig13B"), "honeycomb of a pentagonal cube", {}),
            (_m("fig13C"), "dual of Loop, dodecahedron", {}),
            (_m("fig13D"), "dual of Loop, pentagonal cube", {}),
        ],
        ncols=4,
        suptitle="Figure 13. Soccerball subdivision of pentagonal meshes",
    )


def claims13() -> list[Claim]:
    out = [
        _eq(
            "(A) the honeycomb of a dodecahedron is a soccer ball (truncated "
            "icosahedron): 12 pentagons, 20 hexagons, 60 3-valent vertices",
            ({5: 12, 6: 20}, {3: 60}, (60, 90, 32)),
            (
                _m("fig13A").face_size_histogram(),
                _m("fig13A").valence_histogram(),
                _vef(_m("fig13A")),
            ),
        )
    ]
    for panel, key, src, scheme in (
        ("(B)", "fig13B", "pent_cube", "honeycomb"),
        ("(C)", "fig13C", "dodeca", "preserve_hexagons"),
        ("(D)", "fig13D", "pent_cube", "preserve_hexagons"),
    ):
        m = _m(key)
        out.append(
            _check(
                f"{panel} no triangle or quad (smallest face)",
                ">= 5",
                int(m.face_sizes.min()),
                m.face_sizes.min() >= 5,
            )
        )
        s = _m(src)
        new = (
            {2 * k: c for k, c in s.valence_histogram().items()}
            if scheme == "honeycomb"
            else {6: s.n_edges}
        )
        out.append(
            _eq(
                f"{panel} the pentagons kept, "
                + (
                    "a 2k-gon for every k-valent vertex"
                    if scheme == "honeycomb"
                    else "a hexagon for every edge"
                ),
                _add({5: s.n_faces}, new),
                m.face_size_histogram(),
            )
        )
    hb = _m("fig13B")
    out.append(
        _eq(
            "(B) honeycomb: every vertex becomes 3-valent",
            {3: hb.n_vertices},
            hb.valence_histogram(),
        )
    )
    return out


# ====================================================================== Section 4
def equation1() -> Figure:
    """Section 4: equation (1), ``m = 2n/(n-2) (1 + (2g-2)/v)``, and the (n, m) chart.

    Panels (A)-(C) plot the average valence m against v for n = 3..8 and
    g = 0, 1, 2 with the line m = 3 (an n-gonal mesh needs m >= 3); dots
    mark meshes of the package.  Panel (D) is the chart of the limits
    ``(n, 2n/(n-2))``.
    """
    v = np.arange(1, 201, dtype=float)
    samples = _equation1_samples()
    with vz.style():
        fig = Figure(figsize=(7.6, 7.4), dpi=vz.DPI)
        axes = list(fig.subplots(2, 2).ravel())
        fig.subplots_adjust(left=0.08, right=0.98, bottom=0.1, top=0.93, hspace=0.45, wspace=0.22)
        fig.suptitle(
            "Section 4. Equation (1): average valence m of an n-gonal mesh with "
            "v vertices and genus g",
            fontsize=10.5,
        )
        for g, ax in zip((0, 1, 2), axes):
            for n in range(3, 9):
                m = topology.average_valence(n, g, v)
                ax.plot(
                    v, np.where(m >= 3, m, np.nan), color=face_color(n), lw=1.7, label=f"n = {n}"
                )
                ax.plot(v, m, color=face_color(n), lw=1.2, alpha=0.35)
            ax.axhline(3, color=EDGE_COLOR, lw=1.0, ls="--", label="m = 3")
            for n, gg, vv, name, dy in samples:
                if gg == g:
                    mm = topology.average_valence(n, g, vv)
                    ax.plot(vv, mm, "o", ms=5, mfc=face_color(n), mec=EDGE_COLOR, mew=0.8, zorder=5)
                    ax.annotate(
                        name,
                        (vv, mm),
                        xytext=(vv + 12 if vv < 120 else vv - 75, mm + dy),
                        fontsize=7.5,
                        arrowprops={"arrowstyle": "-", "lw": 0.6, "color": "#555555"},
                        va="center",
                    )
            ax.set_xlim(0, 200)
            ax.set_ylim(0, 8.2)
            ax.set_xlabel("v (vertices)")
            ax.set_ylabel("m (average valence)")
            ax.grid(alpha=0.25)
            vz.label_panel(ax, f"({'ABC'[g]}) genus g = {g}")
            ax.title.set_y(-0.2)
        axes[1].legend(
            ncol=4,
            fontsize=7.5,
            loc="upper center",
            frameon=True,
            title="faint where m < 3",
            title_fontsize=7.5,
            columnspacing=1.0,
            handlelength=1.6,
        )
        _chart_panel(axes[3])
        vz.label_panel(axes[3], "(D) the (n, m) chart: limits v -> inf (= g = 1)")
        axes[3].title.set_y(-0.2)
    return fig


def _chart_panel(ax) -> None:
    n = np.linspace(3, 8, 200)
    ax.plot(n, 2 * n / (n - 2), color="#555555", lw=1.2, label="m = 2n / (n - 2)")
    ax.axhline(3, color=EDGE_COLOR, lw=1.0, ls="--")
    ax.axvspan(6, 8.2, color="#999999", alpha=0.18, lw=0)
    ax.text(7.1, 4.8, "n > 6:\nm < 3,\nno n-gonal\nschemes", ha="center", fontsize=7.5)
    for row in topology.SCHLAFLI_CHART:
        nn, mm = float(row.n), float(row.m)
        color = face_color(int(row.n)) if row.n.denominator == 1 else "#777777"
        ax.plot(nn, mm, "o", ms=7, mfc=color, mec=EDGE_COLOR, mew=0.8, zorder=4)
        ax.annotate(
            f"({_frac(row.n)}, {_frac(row.m)})",
            (nn, mm),
            xytext=(7, 3),
            textcoords="offset points",
            fontsize=8,
        )
    ax.set_xlim(2.8, 8.2)
    ax.set_ylim(0, 8.2)
    ax.set_xlabel("n (sides of a face)")
    ax.set_ylabel("m (valence)")
    ax.grid(alpha=0.25)
    ax.legend(fontsize=7.5, loc="upper right")


def _frac(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


@functools.cache
def _equation1_samples() -> tuple[tuple[int, int, int, str, float], ...]:
    """(n, g, v, name, label offset) of meshes of the package drawn on equation (1)."""
    rows = []
    for name, key, dy in (
        ("tetrahedron", "tet", -2.2),
        ("cube", "cube", -1.6),
        ("dodecahedron", "dodeca", -1.0),
        ("gyro(cube)", "pent_cube", 0.9),
        ("hexagonal torus", "hex_torus", 0.8),
        ("hexagonal genus 2", "hex_genus2", 0.9),
    ):
        m = _m(key)
        n = int(m.face_sizes[0])
        rows.append((n, m.genus, m.n_vertices, name, dy))
    return tuple(rows)


def claims_equation1() -> list[Claim]:
    av = topology.average_valence
    out = []
    for name, n, g, v in (("tetrahedron", 3, 0, 4), ("cube", 4, 0, 8), ("dodecahedron", 5, 0, 20)):
        out.append(
            _eq(
                f"n = {n}, g = 0: the simplest mesh ({name}) has v = {v} and m = 3 by equation (1)",
                (v, 3.0),
                (topology.min_vertices(n, 0), av(n, g, v)),
            )
        )
    big = np.arange(3, 100000)
    out.append(
        _eq(
            "n = 6, g = 0: m = 3 (1 - 2/v) < 3 for every v: no hexagonalization "
            "(values of v < 100000 with m >= 3)",
            0,
            int(np.sum(av(6, 0, big) >= 3)),
        )
    )
    out.append(
        _eq(
            "n = 5, g = 0: m = 10/3 (1 - 2/v) >= 3 exactly when v >= 20",
            20,
            int(big[np.argmax(av(5, 0, big) >= 3)]),
        )
    )
    lim = {n: topology.limit_valence(n) for n in range(3, 9)}
    out.append(
        _eq(
            "limit of m as v -> inf: 2n/(n-2) for n = 3..8",
            {n: Fraction(2 * n, n - 2) for n in range(3, 9)},
            lim,
        )
    )
    out.append(
        _eq(
            "2n/(n-2) < 3 exactly for n > 6 (no n-gonal schemes)",
            [7, 8],
            [n for n, x in lim.items() if x < 3],
        )
    )
    out.append(
        _eq(
            "the limit valence of pentagonal meshes is not an integer (10/3); "
            "of triangles, quads, hexagons it is",
            {3: True, 4: True, 5: False, 6: True},
            {n: lim[n].denominator == 1 for n in (3, 4, 5, 6)},
        )
    )
    chart = [(r.n, r.m) for r in topology.SCHLAFLI_CHART]
    out.append(
        _eq(
            "the (n, m) chart",
            [
                (Fraction(6), Fraction(3)),
                (Fraction(5), Fraction(10, 3)),
                (Fraction(4), Fraction(4)),
                (Fraction(10, 3), Fraction(5)),
                (Fraction(3), Fraction(6)),
            ],
            chart,
        )
    )
    # equation (1) on real meshes: measured 2E/V against the formula
    for name, key in (
        ("pentagonalized hard cube", "fig8A"),
        ("rabbit x2", "fig12B"),
        ("hexagonal genus 2", "hex_genus2"),
        ("gyro(hex. torus)", "fig9A"),
    ):
        m = _m(key)
        n = int(m.face_sizes[0])
        eq = Fraction(2 * n, n - 2) * (1 + Fraction(2 * m.genus - 2, m.n_vertices))
        out.append(
            _eq(
                f"equation (1) = measured 2E/V on the {name} (n={n}, "
                f"g={m.genus}, v={m.n_vertices})",
                eq,
                Fraction(2 * m.n_edges, m.n_vertices),
            )
        )
    return out


# ====================================================================== convergence
def convergence_figure(pairs: int = 6, levels: int = 4) -> Figure:
    """Beyond the paper: G1 convergence measured instead of "visually confirmed".

    (A) spread of vertex radii and (B) largest angle between neighbouring
    face normals after each pair of duals following one remeshing
    (:func:`pentanb.analysis.convergence.dual_convergence`); (C) the largest angle
    after every subdivision level (remesh + two duals,
    :func:`pentanb.analysis.convergence.subdivision_convergence`): it falls towards
    0, as a G1 limit surface requires.
    """
    from .analysis import convergence as cv

    data = cv.study(pairs=pairs, levels=levels)
    styles = {"pentagonalize": "-", "preserve_pentagons": "--"}
    with vz.style():
        fig = Figure(figsize=(10.5, 4.0), dpi=vz.DPI)
        axes = list(fig.subplots(1, 3))
        fig.subplots_adjust(left=0.065, right=0.99, bottom=0.3, top=0.9, wspace=0.3)
        fig.suptitle("Convergence under duals (beyond the paper)", fontsize=10.5)
        colors = ["#0072B2", "#D55E00", "#009E73", "#CC79A7"]
        for (mesh_name, scheme), res in data["pairs"].items():
            c = colors[list(data["meshes"]).index(mesh_name)]
            if mesh_name in cv.ROUND_MESHES:
                axes[0].plot(
                    res.steps, res.radius_spread, styles[scheme], color=c, marker="o", ms=3
                )
            axes[1].plot(res.steps, res.max_normal_angle, styles[scheme], color=c, marker="o", ms=3)
        for (mesh_name, scheme), res in data["levels"].items():
            c = colors[list(data["meshes"]).index(mesh_name)]
            axes[2].semilogy(
                res.steps, res.max_normal_angle, styles[scheme], color=c, marker="o", ms=3
            )
        axes[0].set_xlabel("pairs of duals after one remeshing")
        axes[0].set_ylabel("std / mean of vertex radii")
        axes[1].set_xlabel("pairs of duals after one remeshing")
        axes[1].set_ylabel("largest neighbour normal angle (deg)")
        axes[2].set_xlabel("subdivision level (remesh + 2 duals)")
        axes[2].set_ylabel("largest neighbour normal angle (deg)")
        from matplotlib.ticker import FixedLocator, MaxNLocator, NullLocator

        axes[2].yaxis.set_major_locator(FixedLocator([5, 10, 20, 50, 100]))
        axes[2].yaxis.set_minor_locator(NullLocator())
        axes[2].set_yticklabels(["5", "10", "20", "50", "100"])
        axes[2].set_ylim(5, 100)
        for ax, text in zip(
            axes,
            [
                "(A) roundness (cube, tetrahedron)",
                "(B) crease angle per dual pair",
                "(C) crease angle per level: -> 0",
            ],
        ):
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
            ax.grid(alpha=0.25)
            vz.label_panel(ax, text)
            ax.title.set_y(-0.3)
        from matplotlib.lines import Line2D

        handles = [
            Line2D([], [], color=colors[i], label=name) for i, name in enumerate(data["meshes"])
        ]
        handles += [
            Line2D([], [], color="#444444", ls=ls, label=SCHEMES[s].label)
            for s, ls in styles.items()
        ]
        fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False)
    return fig


def claims_convergence() -> list[Claim]:
    from .analysis import convergence as cv

    data = cv.study()
    out = []
    for (mesh_name, scheme), res in data["levels"].items():
        a = res.max_normal_angle
        out.append(
            _check(
                f"{SCHEMES[scheme].label} of the {mesh_name}: the largest "
                "angle between neighbouring normals falls at every level "
                "(G1 limit)",
                "decreasing",
                tuple(round(float(x), 2) for x in a),
                bool(np.all(np.diff(a) < 0)),
            )
        )
    return out


# ====================================================================== schemes
def scheme_claims(mesh: Mesh | None = None) -> list[Claim]:
    """Every scheme's Conway name and count formula, checked on a mesh.

    Default mesh: the capped pentagonal prism (triangles, quads and a pentagon).
    """
    mesh = _m("mixed") if mesh is None else mesh
    out = []
    for name, s in SCHEMES.items():
        if name == "triangulate":
            continue  # its count formula is an upper bound
        after = s(mesh)
        conway = f" = Conway's {s.conway}" if s.conway else ""
        out.append(
            _eq(
                f"{s.label}{conway}: (V, E, F) -> {formula(name)}",
                s.counts(*_vef(mesh)),
                _vef(after),
            )
        )
    # the Conway operators' face structure
    gyro = pentagonalize(mesh)
    quinto = preserve_pentagons(mesh, 0.5)
    chamfer = preserve_hexagons(mesh)
    zp = honeycomb(mesh)
    hist = mesh.face_size_histogram()
    out += [
        _eq(
            "gyro: every n-gon becomes n pentagons",
            {5: 2 * mesh.n_edges},
            gyro.face_size_histogram(),
        ),
        _eq(
            "quinto (pentagon preservation, scale 0.5): n-gons kept, 2E pentagons added",
            _add(hist, {5: 2 * mesh.n_edges}),
            quinto.face_size_histogram(),
        ),
        _eq(
            "chamfer (dual of Loop): faces kept, a hexagon per edge",
            _add(hist, {6: mesh.n_edges}),
            chamfer.face_size_histogram(),
        ),
        _eq(
            "zip (dual of sqrt(3)): faces kept, a 2k-gon per k-valent vertex",
            _add(hist, {2 * k: c for k, c in mesh.valence_histogram().items()}),
            zp.face_size_histogram(),
        ),
    ]
    return out


def _add(a: dict, b: dict) -> dict:
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + v
    return dict(sorted(out.items()))


# ====================================================================== registry
@dataclass(frozen=True)
class FigureSpec:
    """One image of ``figures/``: how to draw it and what the paper claims of it.

    Attributes
    ----------
    name : str
        File stem, e.g. ``"fig07"``.
    title : str
        Short title.
    caption : str
        The paper's caption (or a description for images beyond the paper).
    draw : callable
        ``draw() -> Figure``.
    claims : callable
        ``claims() -> list[Claim]``.
    panels : tuple of str
        The panel letters, e.g. ``("A", "B")``.
    """

    name: str
    title: str
    caption: str
    draw: Callable[[], Figure]
    claims: Callable[[], list[Claim]]
    panels: tuple[str, ...] = field(default=("A", "B"))

    @property
    def filename(self) -> str:
        return f"{self.name}.png"


def _spec(num, title, caption, panels):
    g = globals()
    return FigureSpec(
        f"fig{num:02d}", title, caption, g[f"figure{num}"], g[f"claims{num}"], tuple(panels)
    )


FIGURES: dict[str, FigureSpec] = {
    s.name: s
    for s in [
        _spec(
            1,
            "Pentagonal subdivision examples",
            "(A) is the initial mesh, (B) is one application of pentagonalization scheme, "
            "(C) is two iterations of pentagonalization scheme, (D) is obtained by applying "
            "pentagonal preserving scheme to the pentagonal mesh in (B).",
            "ABCD",
        ),
        _spec(
            2,
            "Simplest triangulation",
            "An example of simplest triangulization that cannot be used iteratively. (A) is "
            "the initial mesh and (B) is obtained by subdividing each non-triangular face "
            "into triangles.",
            "ABC",
        ),
        _spec(
            3,
            "Loop's remeshing",
            "A triangle preserving remeshing: The remeshing scheme of Loop subdivision. (A) "
            "is the initial mesh and (B) the resulting mesh.",
            "AB",
        ),
        _spec(4, "Hexagonal meshes", "Examples of hexagonal meshes for g>0.", "AB"),
        _spec(
            5,
            "Hexagon preservation",
            "Two iterations of an hexagon preserving scheme applied to the hexagonal meshes "
            "shown in Figure 4.",
            "AB",
        ),
        _spec(
            6,
            "Pentagonalization scheme",
            "Pentagonalization scheme. (A) is the initial mesh and (B) the resulting mesh.",
            "AB",
        ),
        _spec(
            7,
            "Tetrahedron to dodecahedron",
            "Conversion of a tetrahedron to a dodecahedron by the pentagonalization scheme. "
            "(A) is the original tetrahedron. (B) is the dodecahedral shape after the "
            "application of pentagonalization scheme. (C) is the icosahedral dual of (B). "
            "(D) is the dodecahedral shape that is the dual of (C). (E) is the 5th iteration "
            "of the dual and (F) is 6th iteration of the dual.",
            "ABCDEF",
        ),
        _spec(
            8,
            "4.3.3.4.3 semi-regular tiling",
            "4.3.3.4.3 semi-regular tiling created by pentagon conversion scheme that is "
            "applied to a cube. (A) is one iteration with two dual, (B) is the dual of (A).",
            "AB",
        ),
        _spec(
            9,
            "6.3.3.3.3 semi-regular tiling",
            "6.3.3.3.3 semi-regular tiling created by pentagon conversion scheme that is "
            "applied to the toroidal shape shown in Figure 4.A. (A) is one iteration with two "
            "dual, (B) is the dual of (A).",
            "AB",
        ),
        _spec(
            10,
            "Pentagon preserving scheme",
            "Pentagon preserving scheme. (A) is the initial mesh and (B) the resulting mesh.",
            "AB",
        ),
        _spec(
            11,
            "Pentagon preservation on a cube",
            "A semi-regular tiling created by pentagon preserving scheme that is applied to "
            "a cube. (A) is one iteration with two dual, (B) is the dual of (A).",
            "AB",
        ),
        _spec(
            12,
            "Pentagonalized animal",
            "(A) An initial mesh (B) pentagonalization scheme applied twice to the initial "
            "mesh, (C) shaded model without wireframe.",
            "ABC",
        ),
        _spec(13, "Soccerball subdivision", "An example of soccerball subdivision.", "ABCD"),
    ]
}
FIGURES["equation1"] = FigureSpec(
    "equation1",
    "Section 4: equation (1) and the (n, m) chart",
    "m = 2n/(n-2) (1 + (2g-2)/v), the average valence of an n-gonal mesh of genus g with "
    "v vertices; n-gonal meshes need m >= 3.",
    equation1,
    claims_equation1,
    ("A", "B", "C", "D"),
)
FIGURES["convergence"] = FigureSpec(
    "convergence",
    "Convergence under duals (beyond the paper)",
    "The paper 'visually confirmed that the algorithms converge with G1 continuity'; "
    "here the largest angle between neighbouring face normals is measured.",
    convergence_figure,
    claims_convergence,
    ("A", "B", "C"),
)


def _get(name) -> FigureSpec:
    if isinstance(name, int):
        name = f"fig{name:02d}"
    try:
        return FIGURES[name]
    except KeyError:
        raise ValueError(f"unknown figure {name!r}; known: {', '.join(FIGURES)}") from None


def claims(name: int | str) -> list[Claim]:
    """The claims of one figure: ``claims(7)``, ``claims("fig07")``, ``claims("equation1")``."""
    return _get(name).claims()


def render(name: int | str, out_dir: str | Path = "figures") -> Path:
    """Draw one figure and write it to ``out_dir/<name>.png``; returns the path."""
    spec = _get(name)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / spec.filename
    fig = spec.draw()
    vz.save_figure(fig, path)
    return path


def render_all(
    out_dir: str | Path = "figures",
    names: Iterable[str] | None = None,
    progress: Callable[[int, int, str], None] | None = None,
) -> dict[str, float]:
    """Draw every figure (or ``names``) into ``out_dir``; returns seconds per figure."""
    names = list(FIGURES) if names is None else [_get(n).name for n in names]
    times = {}
    for i, name in enumerate(names):
        t = time.perf_counter()
        path = render(name, out_dir)
        times[name] = time.perf_counter() - t
        if progress:
            progress(i + 1, len(names), f"{path} ({times[name]:.1f} s)")
    return times


def check_all(names: Iterable[str] | None = None) -> dict[str, list[Claim]]:
    """``{figure name: claims}`` for every figure (or ``names``), plus ``"schemes"``."""
    names = list(FIGURES) if names is None else [_get(n).name for n in names]
    out = {n: FIGURES[n].claims() for n in names}
    out["schemes"] = scheme_claims()
    return out


def report(results: dict[str, list[Claim]]) -> str:
    """The claims as text: one block per figure, one line per claim, then a total."""
    lines = []
    for name, cl in results.items():
        if name == "schemes":
            lines.append(
                "schemes  Conway names and count formulas, checked on a mesh with "
                "triangles, quads and a pentagon"
            )
        else:
            lines.append(f"{name}  {FIGURES[name].title}")
        lines += [f"  {c}" for c in cl]
    total = sum(len(c) for c in results.values())
    failed = [(n, c) for n, cl in results.items() for c in cl if not c.holds]
    lines.append(
        f"{total - len(failed)} of {total} claims hold"
        + ("" if not failed else "; FAILED: " + "; ".join(f"{n}: {c.text}" for n, c in failed))
    )
    return "\n".join(lines)
