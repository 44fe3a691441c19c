"""Beyond the paper: the two schemes on an open surface with holes.

The paper's meshes are closed.  ``pentanb`` takes open meshes too: every
boundary loop is a hole, the remeshings cut boundary edges as they cut any
edge, and the dual closes a boundary vertex's face through the midpoints of
its boundary edges (see ``docs/schemes.md``).  This figure runs both of the
paper's schemes on :func:`pentanb.shapes.open_disk` (a domed disk with two
holes: triangles, quadrilaterals and pentagons), before and after
smoothing (two duals after every step), and measures the boundary: the
*turning angle* at a boundary vertex is the angle between the directions of
the boundary edges that meet there (0 on a straight boundary; the turning
angles of a smooth curve sampled finer and finer shrink with the edges).

Panels: (A) the input; (B) pentagonalized, (C) with two duals, (D) twice,
two duals each; (E)-(G) the same with pentagon preservation; and a chart
of the boundary's largest and mean turning angle per level, with and
without the duals, on a log scale.  Its statements are observations beyond the paper
(no verdict on it): with the duals the largest turning angle falls level by
level (about halving); without them it stays the input's (the remeshings
put their new boundary points on the straight boundary edges); with
pentagonalization every face away from the boundary is a pentagon (with
the duals, the faces along the boundary are quadrilaterals); pentagon
preservation without duals keeps the input's non-pentagons, and with the
duals the non-pentagons grow level by level (the quadrilaterals along the
boundary become central faces that the next step keeps).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .. import shapes
from ..mesh import Mesh, check_mesh
from ..subdivision import subdivide
from .claim import Claim, falls, fmt, observed, take

if TYPE_CHECKING:
    from matplotlib.figure import Figure

TITLE = "Open surfaces: the schemes on a disk with holes (beyond the paper)"
CAPTION = (
    "Beyond the paper, whose meshes are closed: a domed disk with two holes, (A) the input, "
    "(B) pentagonalized, (C) with two duals, (D) twice with two duals each; (E)-(G) the same "
    "with pentagon preservation; the boundary drawn heavier. The chart: the boundary's largest "
    "and mean turning angle (between consecutive boundary edges) per level, with and without the "
    "duals."
)
#: The mesh panels' letters; the chart of turning angles comes last, unlettered.
LABELS = tuple("ABCDEFG")

#: The paper's two schemes, as drawn in the two rows.
SCHEMES = ("pentagonalize", "preserve_pentagons")
#: Duals after every step: none (the remeshing alone) and two (smoothed).
DUALS = (0, 2)
#: Levels measured (0, the input, to LEVELS).
LEVELS = 3

#: The panels drawn: label -> (scheme, level, duals); (A) is the input.
PANELS = {
    "B": ("pentagonalize", 1, 0),
    "C": ("pentagonalize", 1, 2),
    "D": ("pentagonalize", 2, 2),
    "E": ("preserve_pentagons", 1, 0),
    "F": ("preserve_pentagons", 1, 2),
    "G": ("preserve_pentagons", 2, 2),
}

#: The camera of the mesh panels: elevation and azimuth, degrees.
VIEW_ELEV, VIEW_AZIM = 30.0, -58.0

_NAMES = {"pentagonalize": "pentagonalization", "preserve_pentagons": "pentagon preservation"}

#: The observations, key -> seen when written.
RECORDED = {
    "open_surfaces.turning.smoothed": True,
    "open_surfaces.turning.unsmoothed": True,
    "open_surfaces.pentagonalize.faces": True,
    "open_surfaces.preserve.non_pentagons": True,
}

SMOOTH = "We then apply dual operation even number of times to create a smooth mesh."
KEEP = (
    "Our remeshing operations do not change positions of existing vertices and newly created "
    "vertices do not change the shape of the initial mesh."
)
ANY = "converts any arbitrary mesh structure to a pentagonal mesh"
CONSTANT = (
    "creates only pentagons and the number of non-pentagonal faces remains constant after the "
    "first refinement"
)
OPEN = "; here on an open surface with holes, where the paper's meshes are closed"


def turning_angles(mesh: Mesh) -> NDArray[np.float64]:
    """The turning angle at every boundary vertex, in degrees.

    At the head of boundary edge ``j`` the angle between the direction of
    that edge and of the next edge of its loop: 0 where the boundary runs
    straight on, 180 where it turns back.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (B,) float
        One angle per boundary edge, in the order of
        :attr:`pentanb.Mesh.boundary_halfedges` (empty for a closed mesh).
    """
    check_mesh(mesh, "turning_angles()")
    out = []
    v = mesh.vertices
    for loop in mesh.boundary_loops:
        d = v[mesh.head[loop]] - v[mesh.corners[loop]]
        d = d / np.linalg.norm(d, axis=1)[:, None]
        cos = (d * np.roll(d, -1, axis=0)).sum(axis=1)
        out.append(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return np.concatenate(out) if out else np.zeros(0)


def turning(mesh: Mesh) -> tuple[float, float]:
    """The largest and the mean turning angle of a mesh's boundary, in degrees.

    Parameters
    ----------
    mesh : Mesh
        An open mesh.

    Returns
    -------
    (float, float)
        ``(largest, mean)`` of :func:`turning_angles`; ``(nan, nan)`` for a
        closed mesh.
    """
    t = turning_angles(mesh)
    if not t.size:
        return float("nan"), float("nan")
    return float(t.max()), float(t.mean())


def study(source: Mesh | None = None, levels: int = LEVELS) -> dict[tuple[str, int], list[Mesh]]:
    """Both schemes on an open mesh, level by level, with and without the duals.

    Parameters
    ----------
    source : Mesh, optional
        Default :func:`pentanb.shapes.open_disk`.
    levels : int
        Steps of each scheme (default :data:`LEVELS`; 3 builds at most
        28,188 faces from the disk).

    Returns
    -------
    dict
        ``{(scheme, duals): [level 0 (the source), level 1, ...]}`` for the
        schemes of :data:`SCHEMES` and the duals of :data:`DUALS`; level
        ``k + 1`` is one step of the scheme on level ``k``, then ``duals``
        duals.
    """
    src = shapes.open_disk() if source is None else source
    out = {}
    for scheme in SCHEMES:
        for d in DUALS:
            steps = [src]
            for _ in range(levels):
                steps.append(subdivide(steps[-1], scheme, 1, d))
            out[(scheme, d)] = steps
    return out


def panels() -> dict[str, Mesh]:
    """The meshes drawn: (A) the open disk, (B)-(D) pentagonalized, (E)-(G) with
    pentagon preservation (see :data:`PANELS`); the last panel is a chart."""
    a = shapes.open_disk()
    out = {"A": a}
    for label, (scheme, level, d) in PANELS.items():
        out[label] = subdivide(a, scheme, level, d)
    return out


def _caption(label: str) -> str:
    if label == "A":
        return "open disk, two holes"
    scheme, level, d = PANELS[label]
    done = "pentagonalized" if scheme == "pentagonalize" else "preserved"
    if level > 1:
        return f"{done} {level}x, {d} duals each"
    return done + (f", {d} duals" if d else "")


def _series(data: Mapping[tuple[str, int], Sequence[Mesh]]) -> dict[tuple[str, int], np.ndarray]:
    """``{(scheme, duals): (levels + 1, 2) array of (largest, mean)}``."""
    return {k: np.array([turning(m) for m in ms]) for k, ms in data.items()}


def draw(
    meshes: Mapping[str, Mesh] | None = None,
    data: Mapping[tuple[str, int], Sequence[Mesh]] | None = None,
) -> Figure:
    """The open disk under both schemes, and the boundary's turning angles per level.

    Parameters
    ----------
    meshes : dict, optional
        :func:`panels` (built here otherwise).
    data : dict, optional
        :func:`study` (built here otherwise) for the chart.

    Returns
    -------
    matplotlib.figure.Figure
        Panels (A)-(G) meshes, then the chart.
    """
    from ..viz import mpl as vz

    meshes = panels() if meshes is None else meshes
    data = study() if data is None else data
    series = _series(data)
    with vz.style():
        fig, axes = vz.panel_figure(
            len(LABELS) + 1, 4, panel_size=2.8, suptitle=TITLE, legend_space=0.55, aspect=0.7
        )
        for ax, label in zip(axes, LABELS):
            m = meshes[label]
            vz.draw_mesh(ax, m, elev=VIEW_ELEV, azim=VIEW_AZIM)
            vz.label_panel(
                ax,
                f"({label}) {_caption(label)}\nV {m.n_vertices:,}  E {m.n_edges:,}  "
                f"F {m.n_faces:,}",
            )
        cell = axes[-1].get_position()
        fig.delaxes(axes[-1])
        chart = fig.add_axes(
            (
                cell.x0 + 0.2 * cell.width,
                cell.y0 + 0.06 * cell.height,
                0.76 * cell.width,
                0.8 * cell.height,
            )
        )
        colours = {"pentagonalize": "#0072B2", "preserve_pentagons": "#D55E00"}
        for (scheme, d), s in series.items():
            levels = np.arange(len(s))
            first = scheme == SCHEMES[0]  # drawn larger and hollow: the two coincide
            word = "pentagonalized" if first else "preserved"
            chart.plot(
                levels,
                s[:, 0],
                "-" if d else "--",
                marker="o" if d else "s",
                ms=6 if first else 3,
                mfc="none" if first else colours[scheme],
                color=colours[scheme],
                label=f"{word}, {d} duals",
            )
            chart.plot(levels, s[:, 1], ":", marker=".", ms=3, color=colours[scheme])
        chart.set_yscale("log")
        chart.set_xticks(range(LEVELS + 1))
        chart.set_xlabel("level (dotted: mean)", fontsize=7.5)
        chart.set_ylabel("turning angle (degrees)", fontsize=7.5)
        chart.tick_params(labelsize=7)
        chart.legend(fontsize=6, frameon=False, loc="lower left")
        chart.set_title("boundary: largest turning angle", fontsize=8)
        vz.add_face_legend(fig, [meshes[k] for k in LABELS])
    return fig


def _turning_smoothed(series, recorded: bool) -> Claim:
    parts, seen = [], True
    for scheme in SCHEMES:
        s = series[(scheme, 2)]
        largest = [round(float(x), 3) for x in s[:, 0]]
        rises = falls(s[:, 0])
        seen = seen and not rises
        ratio = [round(float(b / a), 3) for a, b in zip(s[:-1, 0], s[1:, 0])]
        parts.append(
            f"{_NAMES[scheme]} + 2 duals, levels 0-{len(s) - 1}: largest {fmt(largest)} "
            f"(ratio per level {fmt(ratio)}), mean {fmt([round(float(x), 3) for x in s[:, 1]])}"
            + (f" (rises at level {', '.join(map(str, rises))})" if rises else "")
        )
    return observed(
        "open_surfaces.turning.smoothed",
        "Section 3" + OPEN,
        SMOOTH,
        "turning angle between consecutive boundary edges (degrees): " + "; ".join(parts),
        "with two duals after every step, the boundary's largest turning angle falls at every "
        "level, for both schemes",
        seen,
        recorded,
        cause="the duals smooth the boundary curve",
    )


def _turning_unsmoothed(series, recorded: bool) -> Claim:
    parts, seen = [], True
    for scheme in SCHEMES:
        s = series[(scheme, 0)]
        largest = s[:, 0]
        off = float(np.max(np.abs(largest - largest[0]))) if len(largest) else float("nan")
        seen = seen and off <= 1e-9 * max(abs(float(largest[0])), 1.0)
        parts.append(
            f"{_NAMES[scheme]} without duals, levels 0-{len(s) - 1}: largest "
            f"{fmt([round(float(x), 6) for x in largest])} (largest change {off:.2g}), mean "
            f"{fmt([round(float(x), 3) for x in s[:, 1]])}"
        )
    return observed(
        "open_surfaces.turning.unsmoothed",
        "Section 3" + OPEN,
        KEEP,
        "turning angle between consecutive boundary edges (degrees): " + "; ".join(parts),
        "without duals, the boundary's largest turning angle is the input's at every level "
        "(to rounding): the new boundary points lie on the straight boundary edges and the "
        "old corners keep their angles",
        seen,
        recorded,
        cause="the remeshings keep the boundary polygon",
    )


def _rows(mesh: Mesh) -> tuple[dict[int, int], dict[int, int]]:
    """Faces by size away from the boundary (no boundary vertex) and at it."""
    at = np.zeros(mesh.n_faces, dtype=bool)
    bnd = mesh.is_boundary_vertex
    np.logical_or.at(at, mesh.halfedge_face, bnd[mesh.corners])
    sizes = mesh.face_sizes

    def hist(sel: np.ndarray) -> dict[int, int]:
        v, c = np.unique(sizes[sel], return_counts=True)
        return {int(a): int(b) for a, b in zip(v, c)}

    return hist(~at), hist(at)


def _pentagonalize_faces(data, recorded: bool) -> Claim:
    parts, seen = [], True
    for d in DUALS:
        steps = data[("pentagonalize", d)][1:]
        rows = [_rows(m) for m in steps]
        inner_ok = all(set(inner) == {5} for inner, _ in rows)
        edge_ok = all(set(at) == ({5} if d == 0 else {4}) for _, at in rows)
        seen = seen and inner_ok and edge_ok
        parts.append(
            f"{d} duals, levels 1-{len(steps)}: away from the boundary "
            + ", ".join(fmt(inner) for inner, _ in rows)
            + "; at the boundary "
            + ", ".join(fmt(at) for _, at in rows)
        )
    return observed(
        "open_surfaces.pentagonalize.faces",
        "Section 1" + OPEN,
        ANY,
        "pentagonalization of the open disk, faces by size: " + "; ".join(parts),
        "every face away from the boundary is a pentagon at every level; at the boundary, "
        "pentagons without duals and quadrilaterals with two duals (the dual closes a "
        "boundary vertex's face through the midpoints of its two boundary edges)",
        seen,
        recorded,
        cause="the dual of a boundary vertex",
    )


def _preserve_non_pentagons(data, recorded: bool) -> Claim:
    def non5(m: Mesh) -> int:
        return int((m.face_sizes != 5).sum())

    plain = [non5(m) for m in data[("preserve_pentagons", 0)]]
    dualled = [non5(m) for m in data[("preserve_pentagons", 2)]]
    steady = all(x == plain[0] for x in plain)
    grows = len(dualled) > 1 and all(b > a for a, b in itertools.pairwise(dualled))
    return observed(
        "open_surfaces.preserve.non_pentagons",
        "Section 1" + OPEN,
        CONSTANT,
        f"pentagon preservation of the open disk, non-pentagons at levels 0-{len(plain) - 1}: "
        f"without duals {fmt(plain)}; with two duals {fmt(dualled)}",
        "without duals the non-pentagons stay the input's at every level; with two duals they "
        "grow at every level: the quadrilaterals that the duals leave along the "
        "boundary are kept by the next step as central faces",
        steady and grows,
        recorded,
        cause="pentagon preservation keeps the boundary's quadrilaterals",
    )


def claims(
    meshes: Mapping[str, Mesh] | None = None,
    data: Mapping[tuple[str, int], Sequence[Mesh]] | None = None,
) -> list[Claim]:
    """Observations on the two schemes on an open surface with holes.

    Parameters
    ----------
    meshes : dict, optional
        ``"source"``: the open mesh to study (default
        :func:`pentanb.shapes.open_disk`); the panels are not needed.
    data : dict, optional
        :func:`study` of the source (built here otherwise); the tests pass
        wrong ones.

    Returns
    -------
    list of Claim
        Of kind :data:`~pentanb.figures.claim.OBSERVATION`, one per entry of
        :data:`RECORDED`.
    """
    if data is None:
        data = study(take(meshes, "source", shapes.open_disk))
    series = _series(data)
    return [
        _turning_smoothed(series, RECORDED["open_surfaces.turning.smoothed"]),
        _turning_unsmoothed(series, RECORDED["open_surfaces.turning.unsmoothed"]),
        _pentagonalize_faces(data, RECORDED["open_surfaces.pentagonalize.faces"]),
        _preserve_non_pentagons(data, RECORDED["open_surfaces.preserve.non_pentagons"]),
    ]
