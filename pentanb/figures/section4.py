"""Section 4: equation (1), ``m = 2n/(n-2) (1 + (2g-2)/v)``, and the (n, m) chart.

The figure ``equation1`` plots the average valence m of an n-gonal mesh
against its number of vertices v for genus 0, 1, 2 (panels A-C, with dots
for meshes of this package) and the chart of the limits ``(n, 2n/(n-2))``
(panel D).  Its panels are charts, not meshes: :func:`panels` is empty.

Equation (1) is Euler's formula rewritten, so measuring it on meshes is
bookkeeping: those statements are consistency checks (with the genus each
mesh was built with, never the genus computed from V - E + F, so that a mesh
of the wrong genus fails them), not evidence.  The claims are the ones with
content: the simplest meshes, and "necessarily rational" read as the limit
10/3 not being an integer; the stricter reading "never an integer" is an
observation.  ``claims({name: mesh})`` replaces a sample by name
(:data:`SAMPLES`, :func:`samples`).

(The module is called ``section4`` so that ``pentanb.figures.equation1``
stays the drawing function.)
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import shapes, topology
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import subdivide
from .claim import CHECK, FAILS, HOLDS, Claim, exact, fmt, judged, observed

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

TITLE = "Section 4: equation (1) and the (n, m) chart"
CAPTION = (
    "m = 2n/(n-2) (1 + (2g-2)/v), the average valence of an n-gonal mesh of genus g with "
    "v vertices; n-gonal meshes need m >= 3."
)
LABELS = ("A", "B", "C", "D")


def panels() -> dict[str, Mesh]:
    """No mesh panels: every panel of this figure is a chart (``{}``)."""
    return {}


def _samples() -> list[tuple[int, int, int, str, float]]:
    """(n, g, v, name, label offset) of meshes of the package drawn on equation (1)."""
    rows = []
    for name, mesh, dy in (
        ("tetrahedron", shapes.tetrahedron(), -2.2),
        ("cube", shapes.cube(), -1.6),
        ("dodecahedron", shapes.dodecahedron(), -1.0),
        ("gyro(cube)", subdivide(shapes.cube(), "pentagonalize", 1, 2), 0.9),
        ("hexagonal torus", shapes.hexagonal_torus(), 0.8),
        ("hexagonal genus 2", shapes.hexagonal_surface(2), 0.9),
    ):
        n = int(mesh.face_sizes[0])
        rows.append((n, mesh.genus, mesh.n_vertices, name, dy))
    return rows


def draw(meshes: Mapping[str, Mesh] | None = None) -> Figure:
    """Section 4: equation (1), ``m = 2n/(n-2) (1 + (2g-2)/v)``, and the (n, m) chart.

    Panels (A)-(C) plot the average valence m against v for n = 3..8 and
    g = 0, 1, 2 with the line m = 3 (an n-gonal mesh needs m >= 3); dots
    mark meshes of the package.  Panel (D) is the chart of the limits
    ``(n, 2n/(n-2))``.

    Parameters
    ----------
    meshes : dict, optional
        Ignored (the figure has no mesh panels); accepted like every figure's.

    Returns
    -------
    matplotlib.figure.Figure
        Equation (1) and the paper's ``(n, m)`` chart.
    """
    from matplotlib.figure import Figure

    from ..viz import mpl as vz
    from ..viz.colors import EDGE_COLOR, face_color

    v = np.arange(1, 201, dtype=float)
    samples = _samples()
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


def _chart_panel(ax: Axes) -> None:
    from ..viz.colors import EDGE_COLOR, face_color

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


EQ1 = "m = 2n/(n-2) (1 + (2g-2)/v) (1)"


def _gyro(mesh: Mesh, k: int = 1) -> Mesh:
    return subdivide(mesh, "pentagonalize", k, 2)


#: The meshes the claims measure, by name: (builder, genus it is built with, role).
#: Roles: "simplest" (Section 4's simplest n-gonal meshes), "n-gonal" (equation
#: (1) with the built genus), "3-valent g0" (honeycombs of genus-0 shapes),
#: "pentagonal g0" (some growing), "g1" (genus 1, the plane's tilings folded on a
#: torus: pentagons, and triangles as the hexagonal torus's dual; "torus" has quads).
SAMPLES: dict[str, tuple] = {
    "tetrahedron": (shapes.tetrahedron, 0, "simplest"),
    "cube": (shapes.cube, 0, "simplest"),
    "dodecahedron": (shapes.dodecahedron, 0, "simplest"),
    "gyro(hard cube)": (lambda: _gyro(shapes.hard_edged_cube()), 0, "n-gonal"),
    "gyro(rabbit) x2": (lambda: _gyro(shapes.rabbit(), 2), 0, "n-gonal"),
    "torus": (shapes.torus, 1, "n-gonal"),
    "hexagonal genus 2": (lambda: shapes.hexagonal_surface(2), 2, "n-gonal"),
    "genus 3": (lambda: shapes.genus_surface(3), 3, "n-gonal"),
    "honeycomb(tetrahedron)": (lambda: _zip(shapes.tetrahedron()), 0, "3-valent g0"),
    "honeycomb(cube)": (lambda: _zip(shapes.cube()), 0, "3-valent g0"),
    "honeycomb(rabbit)": (lambda: _zip(shapes.rabbit()), 0, "3-valent g0"),
    "gyro(tetrahedron)": (lambda: _gyro(shapes.tetrahedron()), 0, "pentagonal g0"),
    "gyro(cube)": (lambda: _gyro(shapes.cube()), 0, "pentagonal g0"),
    "gyro(cube) x2": (lambda: _gyro(shapes.cube(), 2), 0, "pentagonal g0"),
    "gyro(cube) x3": (lambda: _gyro(shapes.cube(), 3), 0, "pentagonal g0"),
    "gyro(hexagonal torus)": (lambda: _gyro(shapes.hexagonal_torus()), 1, "g1"),
    "dual(hexagonal torus)": (lambda: dual(shapes.hexagonal_torus()), 1, "g1"),
    "hexagon disk": (lambda: hexagon_disk(2), 0, "with boundary"),
    "pentagonalized open disk": (
        lambda: subdivide(shapes.open_disk(), "pentagonalize", 1, 0),
        0,
        "with boundary",
    ),
}


def hexagon_disk(rings: int = 2) -> Mesh:
    """A flat disk of regular hexagons: one, then ``rings`` rings round it (an open mesh).

    The cells of the plane's honeycomb within ``rings`` steps of a central
    one (1, 7, 19, ... hexagons of side 1), sharing their corners; genus 0
    with one boundary loop.

    Parameters
    ----------
    rings : int
        Rings of hexagons round the central one, ``>= 0``.

    Returns
    -------
    Mesh
    """
    centres = [
        (3**0.5 * (q + r / 2), 1.5 * r)
        for q in range(-rings, rings + 1)
        for r in range(-rings, rings + 1)
        if abs(q + r) <= rings
    ]
    index: dict[tuple[float, float], int] = {}
    points: list[tuple[float, float, float]] = []
    faces = []
    for cx, cy in centres:
        face = []
        for k in range(6):  # corners counter-clockwise: the face looks up (+z)
            a = np.radians(30 + 60 * k)
            x, y = cx + np.cos(a), cy + np.sin(a)
            key = (round(x, 6), round(y, 6))
            if key not in index:
                index[key] = len(points)
                points.append((x, y, 0.0))
            face.append(index[key])
        faces.append(face)
    return Mesh(np.array(points), faces)


def _zip(mesh: Mesh) -> Mesh:
    return subdivide(mesh, "honeycomb", 1, 2)


def samples(meshes: Mapping[str, Mesh] | None = None) -> dict[str, Mesh]:
    """Every mesh of :data:`SAMPLES`, built (``meshes`` replaces some by name)."""
    return {
        name: (meshes[name] if meshes is not None and name in meshes else build())
        for name, (build, _, _) in SAMPLES.items()
    }


def _n(mesh: Mesh) -> int | None:
    """The face size of an n-gonal mesh (None for mixed faces)."""
    sizes = np.unique(mesh.face_sizes)
    return int(sizes[0]) if sizes.size == 1 else None


def _eq1(mesh: Mesh, g: int) -> Fraction | None:
    n = _n(mesh)
    if n is None:
        return None
    return Fraction(2 * n, n - 2) * (1 + Fraction(2 * g - 2, mesh.n_vertices))


def _m(mesh: Mesh) -> Fraction:
    return Fraction(2 * mesh.n_edges, mesh.n_vertices)


def claims(meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """What Section 4 says, measured on the meshes of :data:`SAMPLES`.

    Parameters
    ----------
    meshes : dict, optional
        ``{sample name: Mesh}`` replacing samples (a wrong input for the tests).
    """
    m = samples(meshes)
    genus = {name: g for name, (_, g, _) in SAMPLES.items()}

    def role(r: str) -> list[str]:
        return [name for name, (_, _, rr) in SAMPLES.items() if rr == r]

    def vals(k: str) -> str:
        return fmt(m[k].valence_histogram())

    euler = "equation (1) is Euler's formula with 2E = nF and 2E = mV"
    out = []
    simplest = role("simplest")
    out.append(
        exact(
            "eq1.simplest",
            "Section 4",
            "Note that v = 20 corresponds to a dodecahedron (simplest pentagonal mesh with 12 "
            "pentagons). [...] In the case of n = 4, we find that v must be larger than 8 and "
            "the simplest case v = 8 corresponds to an hexahedron [...] In the case of n = 3, v "
            "must be larger than 4 and the simplest case v = 4 corresponds to a tetrahedron",
            "(n, v, average valence m = 2E/V) of the " + ", ".join(simplest),
            [(3, 4, Fraction(3)), (4, 8, Fraction(3)), (5, 20, Fraction(3))],
            [(_n(m[k]), m[k].n_vertices, _m(m[k])) for k in simplest],
            reading="the smallest closed n-gonal meshes of genus 0 with no vertex below "
            "valence 3 (m = 3 in equation (1)) are the tetrahedron, the cube and the "
            "dodecahedron, with v = 4, 8 and 20",
        )
    )
    ngonal = role("n-gonal")
    out.append(
        exact(
            "eq1.meshes",
            "Section 4",
            EQ1,
            "average valence 2E/V of the "
            + ", ".join(f"{k} (built with g = {genus[k]})" for k in ngonal)
            + ", against equation (1) with that g",
            {k: _eq1(m[k], genus[k]) for k in ngonal},
            {k: _m(m[k]) for k in ngonal},
            kind=CHECK,
            cause=euler,
        )
    )
    honey = role("3-valent g0")
    out.append(
        exact(
            "eq1.no_hexagons_g0",
            "Section 4",
            "For g = 0 and n = 6 the equation 1 becomes [...] m = 3 (1 - 2/v) In this equation m "
            "is always smaller than 3 regardless of the value of v. This shows that it is not "
            "possible to create a hexagonal mesh for g = 0.",
            "sum over faces of (6 - sides) and smallest and largest valence of the "
            + ", ".join(honey)
            + " (built with g = 0); equation (1) for 3-valent meshes of genus 0 gives 12: "
            "never 0, never all hexagons",
            {k: (12, 3, 3) for k in honey},
            {
                k: (
                    int((6 - m[k].face_sizes).sum()),
                    int(m[k].valences.min()),
                    int(m[k].valences.max()),
                )
                for k in honey
            },
            kind=CHECK,
            cause=euler,
        )
    )
    pent = role("pentagonal g0") + ["dodecahedron"]
    rows = {k: (_n(m[k]), m[k].n_vertices, int(m[k].valences.min())) for k in pent}
    ok = all(n == 5 and v >= 20 and lo >= 3 for n, v, lo in rows.values())
    out.append(
        judged(
            "eq1.pentagons_g0",
            "Section 4",
            "For g = 0 and n = 5 the equation 1 becomes m = 10/3 (1 - 2/v). Here, for values "
            "of v larger than 20, we can create pentagonal mesh.",
            "(n, v, smallest valence) of the pentagonal genus-0 meshes: " + fmt(rows),
            "holds if every one is pentagonal with v >= 20 and no vertex below valence 3",
            HOLDS if ok else FAILS,
            kind=CHECK,
            cause=euler,
        )
    )
    grow = ["gyro(cube)", "gyro(cube) x2", "gyro(cube) x3"]
    gaps = [abs(_m(m[k]) - Fraction(10, 3)) for k in grow]
    torus_m = _m(m["gyro(hexagonal torus)"])
    falls = all(b < a for a, b in itertools.pairwise(gaps))
    out.append(
        judged(
            "eq1.limit",
            "Section 4",
            "Another insteresting case occurs when v goes to infinity. [...] This is the same as "
            "the value of the m for g = 1",
            "|2E/V - 10/3| of " + ", ".join(grow) + f": {fmt([float(x) for x in gaps])}; 2E/V "
            f"of the gyro(hexagonal torus) (g = 1): {fmt(torus_m)}",
            "holds if the distance to 10/3 falls as v grows and the genus-1 mesh has exactly 10/3",
            HOLDS if falls and torus_m == Fraction(10, 3) else FAILS,
            kind=CHECK,
            cause=euler,
        )
    )
    # "necessarily rational": the limit 10/3 (the plane's tilings, g = 1) is no integer, so
    # no pentagonal tiling has every vertex of one valence; triangles and quads reach 6, 4
    plane = {
        "pentagons": "gyro(hexagonal torus)",
        "quads": "torus",
        "triangles": "dual(hexagonal torus)",
    }
    limit = {kind: (_n(m[k]), _m(m[k]), len(m[k].valence_histogram())) for kind, k in plane.items()}
    five, four, three = limit["pentagons"], limit["quads"], limit["triangles"]
    rational = five[0] == 5 and five[1] == Fraction(10, 3) and five[2] > 1
    integers = four == (4, Fraction(4), 1) and three == (3, Fraction(6), 1)
    out.append(
        judged(
            "eq1.non_integer",
            "Section 2 (main results); Section 4",
            "The average valence of vertices (vertex degree) in a pentagonal meshes is "
            "necessarily rational, while triangular and quadrilateral meshes can have integer "
            "vertex degree.",
            "2E/V of growing pentagonal meshes: "
            + fmt({k: _m(m[k]) for k in grow})
            + "; of genus-1 meshes (the plane's tilings folded on a torus): "
            + "; ".join(
                f"{kind}, {plane[kind]}: {fmt(_m(m[plane[kind]]))}, valences {vals(plane[kind])}"
                for kind in plane
            ),
            "holds if the genus-1 pentagonal mesh's 2E/V is 10/3, not an integer, and its "
            "vertices have more than one valence, while the genus-1 quad and triangle meshes "
            "have 4 and 6 with one valence each",
            HOLDS if rational and integers else FAILS,
            reading="as v grows, the average valence of a pentagonal mesh tends to 2n/(n-2) = "
            "10/3 (equation (1); the value of the plane's tilings, g = 1), which is not an "
            "integer: no tiling of pentagons has all its vertices of one valence, while the "
            "limits of triangles (6) and quadrilaterals (4) are integers, reached by regular "
            "tilings",
        )
    )
    # Section 4 on surfaces with boundary (the paper's meshes are closed): V - E + F = 2 - 2g - b
    # and nF = 2E - e_b extend equation (1); a boundary lets hexagons mesh a genus-0 surface
    bounded: dict[str, dict[str, Any]] = {}
    for k in role("with boundary"):
        mk = m[k]
        e_b = mk.n_boundary_edges
        n = _n(mk)
        formula = (
            topology.average_valence_with_boundary(
                n, genus[k], mk.n_boundary_loops, mk.n_vertices, e_b
            )
            if n is not None and mk.n_boundary_loops > 0
            else None
        )
        bounded[k] = {
            "n": n,
            "g, b": (genus[k], mk.n_boundary_loops),
            "V - E + F": mk.euler_characteristic,
            "e_b": e_b,
            "2E/V": float(_m(mk)),
            "equation (1) with boundary": formula,
            "can tile": n is not None
            and topology.can_tile_with_boundary(
                n, genus[k], mk.n_boundary_loops, mk.n_vertices, e_b
            ),
        }
    disk = bounded.get("hexagon disk", {})
    seen = (
        disk.get("n") == 6
        and disk.get("g, b") == (0, 1)
        and disk.get("V - E + F") == 1
        and all(
            r["equation (1) with boundary"] is not None
            and abs(r["equation (1) with boundary"] - r["2E/V"]) < 1e-12
            and r["can tile"]
            and r["V - E + F"] == 2 - 2 * r["g, b"][0] - r["g, b"][1]
            for r in bounded.values()
        )
    )
    out.append(
        observed(
            "eq1.with_boundary",
            "Section 4, extended to surfaces with boundary",
            "For g = 0 and n = 6 the equation 1 becomes [...] m = 3 (1 - 2/v) [...] This shows "
            "that it is not possible to create a hexagonal mesh for g = 0.",
            "built open meshes: " + fmt(bounded),
            "on surfaces with boundary, equation (1) extended by b loops and e_b boundary edges "
            "gives each built mesh's average valence, and a disk (g = 0, b = 1) has a mesh of "
            "hexagons only",
            seen,
            cause="surfaces with boundary",
        )
    )
    pent_all = role("pentagonal g0") + ["dodecahedron", "gyro(hard cube)", "gyro(rabbit) x2"]
    integer = [k for k in pent_all if _m(m[k]).denominator == 1]
    out.append(
        observed(
            "eq1.integer_at_20",
            "Section 2 (main results), read strictly as 'never an integer'",
            "The average valence of vertices (vertex degree) in a pentagonal meshes is "
            "necessarily rational",
            "2E/V of the pentagonal meshes: "
            + fmt({k: _m(m[k]) for k in pent_all})
            + (f"; an integer for {', '.join(integer)}" if integer else "; none an integer")
            + " (equation (1): 10/3 (1 - 2/v) is the integer 3 exactly when v = 20)",
            "some pentagonal mesh has an integer average valence",
            bool(integer),
            cause="the pentagonal meshes of 20 vertices",
        )
    )
    return out
