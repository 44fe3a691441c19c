"""Write the notebooks of this folder from the cell sources below.

Run ``python notebooks/_build_notebooks.py`` after editing; it rewrites every
``.ipynb`` here, without outputs.  ``tests/test_notebooks.py`` executes the
notebooks, checks that they are committed clean, and that they match this
script.

The notebooks are thin: they call :mod:`pentanb` (``pentanb.figures`` for the
paper's figures and their claims, ``pentanb.viz`` for drawing,
``pentanb.topology`` and ``pentanb.analysis.convergence`` for the numbers) and explain.
The only code of their own is widget wiring and a cache of built meshes.
"""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

HERE = Path(__file__).resolve().parent

KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}


def md(text: str):
    return new_markdown_cell(textwrap.dedent(text).strip("\n"))


def code(text: str):
    return new_code_cell(textwrap.dedent(text).strip("\n"))


# ---------------------------------------------------------------------------
# Cells shared by several notebooks
# ---------------------------------------------------------------------------


def setup(*imports: str):
    """The first code cell: the imports every notebook needs, then ``imports``."""
    lines = [
        "%matplotlib inline",
        "import functools",
        "",
        "import ipywidgets as widgets",
        "from IPython.display import clear_output, display",
        "",
        "import pentanb",
        "from pentanb import figures",
        *imports,
    ]
    return new_code_cell("\n".join(lines))


SETUP = setup("from pentanb.viz.mpl import plot_mesh")

#: Building is cached so that a slider coming back to a position is instant;
#: slider ranges are capped so that no position builds more than MAX_FACES.
CACHE = code('''
    MAX_FACES = 100_000   # no slider position builds a bigger mesh


    @functools.lru_cache(maxsize=128)
    def build(shape, scheme, iterations, duals, scale=None):
        """pentanb.subdivide on a named shape, cached on all its arguments."""
        options = {} if scale is None else {"scale": scale}
        return pentanb.subdivide(pentanb.shapes.get(shape), scheme, iterations, duals,
                                 **options)


    def max_iterations(mesh, scheme, duals=2):
        """Most iterations whose meshes all stay under MAX_FACES (predicted, not built)."""
        return pentanb.max_iterations(mesh, scheme, duals, max_faces=MAX_FACES, cap=6)
''')


def claims_cell(name) -> object:
    """Print the claims of figure ``name`` (and fail loudly if one does not hold)."""
    return code(f"""
        for claim in figures.claims({name!r}):
            print(claim)
            assert claim.holds, claim
    """)


# ---------------------------------------------------------------------------
# 01 Topology
# ---------------------------------------------------------------------------

NB01 = [
    md(r"""
    # Which n-gonal meshes can exist? (Section 4, equation 1)

    Section 4 of the paper counts. A closed mesh of genus $g$ with $v$ vertices,
    $e$ edges and $f$ faces satisfies Euler's formula $v - e + f = 2 - 2g$. If every
    face has $n$ sides then $2e = nf$; if the vertices have average valence $m$ then
    $2e = mv$. Eliminating $e$ and $f$ gives equation (1):

    $$m = \frac{2n}{n-2}\left(1 + \frac{2g-2}{v}\right).$$

    A subdivision scheme keeps adding vertices, so it needs $m \ge 3$ for large $v$
    (otherwise it piles up 1- and 2-valent vertices). The paper concludes:

    > "$\frac{2n}{n-2}$ is a monotone decreasing function that becomes smaller than 3
    > for values of $n$ larger than 6."

    > "for values of $v$ larger than 20, we can create pentagonal mesh. Note that
    > $v = 20$ corresponds to a dodecahedron."

    > "it is not possible to create a hexagonal mesh for $g = 0$."

    So every closed surface can be meshed with pentagons, hexagons need genus at
    least 1, and nothing with more than six sides works. This notebook redraws
    equation (1) and the paper's $(n, m)$ chart, checks these claims with
    `pentanb.topology`, and then lets you move $n$, $g$ and $v$ yourself.
    """),
    code("""
    %matplotlib inline
    import ipywidgets as widgets
    import numpy as np
    from IPython.display import clear_output, display
    from matplotlib.figure import Figure

    import pentanb
    from pentanb import figures, topology
    """),
    md(r"""
    ## Equation (1) and the chart

    Panels (A)-(C): the average valence $m$ against the number of vertices $v$ for
    $n = 3, \dots, 8$ on a sphere, a torus and a genus-2 surface; dots are meshes of
    the package. Below the dashed line $m = 3$ no mesh avoids 1- and 2-valent
    vertices. Panel (D): the limits $(n, 2n/(n-2))$ as $v \to \infty$, the paper's
    chart.
    """),
    code("""
    figures.equation1()
    """),
    md(r"""
    ## The paper's chart, and the claims checked

    As $v \to \infty$, $m \to 2n/(n-2)$, the value for $g = 1$ (tessellations of the
    plane). "(5, 10/3) can only have semi-regular tesselations": in the limit,
    pentagons cannot all meet at vertices of one valence.
    """),
    code("""
    print(f"{'(n, m)':>16}  regular?  type")
    for row in topology.schlafli_chart():
        pair = f"({float(row.n):.2f}, {float(row.m):.2f})"
        print(f"{pair:>16}  {'yes' if row.admits_regular else 'no ':>8}  {row.description}")
    """),
    md(r"""
    For each $n$: the limit valence $2n/(n-2)$, the fewest vertices of an $n$-gon
    sphere and torus with $m \ge 3$, and whether a conversion ("$n$-gonalization")
    or a preservation scheme can exist. Then every claim of Section 4, measured.
    """),
    code("""
    print(" n  2n/(n-2)  min v (g=0)  min v (g=1)  conversion  preservation")
    for n in range(3, 9):
        print(f"{n:2d}  {str(topology.limit_valence(n)):>8}  "
              f"{str(topology.min_vertices(n, 0)):>11}  {str(topology.min_vertices(n, 1)):>11}  "
              f"{str(topology.ngonalization_exists(n)):>10}  "
              f"{str(topology.ngon_preservation_exists(n)):>12}")
    """),
    claims_cell("equation1"),
    md(r"""
    ## Equation (1) against every shape of the package

    For each shape whose faces all have the same number of sides: its measured
    average valence $2e/v$ and the value equation (1) predicts from $n$, $g$ and $v$
    alone.
    """),
    code("""
    print(f"{'shape':>18}  n  g    v  measured m  equation (1)")
    for name in pentanb.shapes.SHAPES:
        mesh = pentanb.shapes.get(name)
        sizes = set(mesh.face_size_histogram())
        if len(sizes) != 1:
            continue
        n = sizes.pop()
        measured = 2 * mesh.n_edges / mesh.n_vertices
        predicted = topology.average_valence(n, mesh.genus, mesh.n_vertices)
        row = f"{n}  {mesh.genus}  {mesh.n_vertices:3d}  {measured:10.4f}  {predicted:12.4f}"
        print(f"{name:>18}  {row}")
        assert abs(measured - predicted) < 1e-9
    """),
    md(r"""
    ## Try it

    Choose the number of sides $n$, the genus $g$ and the number of vertices $v$.
    The plot shows $m(v)$ for your $n$ and $g$, the line $m = 3$ and the limit
    $2n/(n-2)$; the text says whether Euler's formula allows such a mesh. Try
    $n = 6, g = 0$ (never), $n = 6, g = 1$ (always exactly 3), $n = 7, g = 2$
    (only up to 28 vertices).
    """),
    code("""
    n_slider = widgets.IntSlider(value=5, min=3, max=10, description="n (sides)")
    g_slider = widgets.IntSlider(value=0, min=0, max=5, description="g (genus)")
    v_slider = widgets.IntSlider(value=20, min=1, max=200, description="v (vertices)")
    out = widgets.Output()


    def redraw(change=None):
        n, g, v = n_slider.value, g_slider.value, v_slider.value
        vs = np.linspace(max(1.0, 2.5 - 2 * g), 200, 500)
        fig = Figure(figsize=(6, 3.5))
        ax = fig.subplots()
        ax.plot(vs, topology.average_valence(n, g, vs), label=f"equation (1), n={n}, g={g}")
        ax.axhline(3, color="k", lw=0.8, ls="--", label="m = 3")
        ax.axhline(float(topology.limit_valence(n)), color="gray", lw=0.8, ls=":",
                   label="limit 2n/(n-2)")
        if v + 2 * g - 2 > 0:
            ax.plot([v], [topology.average_valence(n, g, v)], "o", color="C3")
        ax.set(xlabel="v", ylabel="m", ylim=(0, 8))
        ax.legend(loc="lower right", fontsize=8)
        counts = topology.ngon_mesh_counts(n, g, v)
        with out:
            clear_output(wait=True)
            display(fig)
            print(f"m = {topology.average_valence(n, g, v):.4f}  "
                  f"(limit {topology.limit_valence(n)})")
            print("(v, e, f) =", counts if counts else "not integers: no such mesh")
            print("possible with m >= 3:", topology.can_tile(n, g, v))
            print("admissible v for this n and g:", topology.vertex_range(n, g))


    for w in (n_slider, g_slider, v_slider):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([n_slider, g_slider, v_slider]), out]))
    redraw()
    """),
]


# ---------------------------------------------------------------------------
# 02 Tetrahedron to dodecahedron
# ---------------------------------------------------------------------------

NB02 = [
    md(r"""
    # From a tetrahedron to a dodecahedron (Figures 6 and 7)

    Pentagonalization (Section 5.1) cuts every edge into three equal parts, puts a
    "point sphere" at the centre of every face and joins it to every third point
    around the face (Figure 6), so that every $n$-gon becomes $n$ pentagons. Then
    the dual is applied an even number of times to smooth the result.

    > "This scheme can convert the simplest triangular mesh (tetrahedron) to the
    > simplest pentagonal mesh (dodecahedron) as shown in Figure 7. This set of images
    > also show the role of dual operation; the resulting shape becomes more and more
    > uniform with each application of dual operation."

    This notebook checks both claims: the pentagonalized tetrahedron has exactly the
    counts of a dodecahedron (12 pentagons, 30 edges, 20 three-valent vertices), and
    the spread of its vertices' distances from the centre shrinks with every pair
    of duals. Then you can slide through the dual passes, and step through the
    scheme one stage at a time.
    """),
    setup(
        "from pentanb.analysis.convergence import radius_spread",
        "from pentanb.viz.mpl import plot_mesh",
    ),
    CACHE,
    md("""
    ## Figure 6: the scheme on one face

    A hexagon: its edges are cut in three, the point sphere sits at its centroid, and
    the dashed edges join them. The hexagon becomes six pentagons.
    """),
    code("""
    figures.figure6()
    """),
    claims_cell(6),
    md("""
    ## Figure 7

    (A) the tetrahedron, (B) one pentagonalization, (C) its dual (icosahedral),
    (D) the dual of (C), (E) and (F) the 5th and 6th duals. As in the paper, each
    panel is scaled to fit.
    """),
    code("""
    figures.figure7()
    """),
    claims_cell(7),
    md("""
    How uniform is it? The spread (standard deviation / mean) of the distances of
    the 20 vertices from their centroid is 0 for a regular dodecahedron. It falls
    by about a factor of three with every pair of duals. (After an odd number of
    duals the 12 vertices sit at the centres of 12 faces that the tetrahedron's
    rotations carry into one another, so they are always equidistant: the spread
    says nothing there.)
    """),
    code("""
    for k in range(0, 11, 2):
        mesh = build("tetrahedron", "pentagonalize", 1, k)
        print(f"{k:2d} duals: {str(mesh):40s} radius spread {radius_spread(mesh):.5f}")
    """),
    md("""
    ## Slide through the dual passes

    Even numbers of duals give dodecahedral shapes (12 pentagons), odd numbers
    icosahedral ones (20 triangles). Watch the shape even out. Drag the 3D view to
    turn it.
    """),
    code("""
    duals = widgets.IntSlider(value=2, min=0, max=12, description="dual passes",
                              continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(build("tetrahedron", "pentagonalize", 1, 2), width=420, height=380)


    def redraw(change=None):
        mesh = build("tetrahedron", "pentagonalize", 1, duals.value)
        with picture:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"pentagonalize + {duals.value} duals", size=3.4))
            print(mesh)
            if duals.value % 2 == 0:
                print(f"radius spread {radius_spread(mesh):.5f}")
        view3d.update(mesh, fit=True)


    duals.observe(redraw, names="value")
    display(widgets.VBox([duals, widgets.HBox([picture, view3d],
                                              layout={"flex_flow": "row wrap"})]))
    redraw()
    """),
    md("""
    ## Step through the scheme

    Move the slider: the tetrahedron, its edges cut in three, a point sphere in
    every face, the new edges inserted one group at a time (in red), the pentagons,
    then the duals. On every face you see Figure 6 happen.
    """),
    code("""
    pentanb.step_through(pentanb.shapes.tetrahedron(), "pentagonalize", duals=2)
    """),
]


# ---------------------------------------------------------------------------
# 03 Cube tilings
# ---------------------------------------------------------------------------

NB03 = [
    md(r"""
    # Pentagonal tilings of a cube (Figures 1, 8, 10 and 11)

    The cube is the paper's hard case: "if a non-quadrilateral or non-triangular
    subdivision is applied to such a cube, it is hard to represent boundary edges ...
    As shown in Figure 1.C, the new subdivision does not create any lateral
    artifact." As in the paper, the cube has hard edges: each face is a 3 x 3 grid
    whose outer rows are thin (`pentanb.shapes.hard_edged_cube()`).

    Both of the paper's schemes are applied to it:

    * **pentagonalization** (Section 5.1) turns every $n$-gon into $n$ pentagons; on
      the cube's grid of quads it makes the "4.3.3.4.3" semi-regular tiling of
      Figure 8 (pentagons whose corners have valences 4, 3, 3, 4, 3);
    * **pentagon preservation** (Section 5.2) keeps a shrunken copy of every face
      and rings it with pentagons (Figure 10), so "the number of non-pentagonal
      faces remains constant after the first refinement" (Figure 11), and a
      pentagonal mesh stays pentagonal (Figure 1D).

    Below, each figure is followed by the paper's claims about it, measured. The
    sliders at the end let you choose the cube, the scheme, the number of
    iterations, the dual passes and the preservation scale.
    """),
    SETUP,
    CACHE,
    md("""
    ## Figure 1

    (A) the hard-edged cube, (B) one pentagonalization, (C) two, (D) pentagon
    preservation applied to (B); two duals after each.

    "No lateral artifact" is measured (`pentanb.analysis.convergence.edge_waviness`): rays
    shot from the middle half of one of the cube's straight edges, perpendicular
    to it, hit the smoothed surface; a wave pattern would make their lengths
    oscillate. The claims compare that range with honeycomb (the dual of
    $\\sqrt{3}$, one of the schemes the paper cites for the artifact), and check
    that the mesh keeps all 24 rotations of the cube.
    """),
    code("""
    figures.figure1()
    """),
    claims_cell(1),
    md("""
    The same measurement for every scheme of the package on the hard-edged cube,
    after one and two iterations with two duals each (the edges are 2 units long;
    0 means a straight edge stayed straight):
    """),
    code("""
    from pentanb.analysis.convergence import edge_waviness

    print(f"{'scheme':>36}  {'1 iteration':>12}  {'2 iterations':>12}")
    for s in pentanb.SCHEMES.values():
        wobble = [edge_waviness(build("hard_cube", s.name, k, 2)) for k in (1, 2)]
        print(f"{s.label:>36}  {wobble[0]:12.4f}  {wobble[1]:12.4f}")
    """),
    md("""
    ## Figure 8: the 4.3.3.4.3 tiling and its dual

    Faces are tallied by the valences of their corners (`figures.face_configurations`),
    written from the smallest rotation, so the paper's 4.3.3.4.3 reads 3.3.4.3.4.
    Only the 24 pentagons at the cube's eight 3-valent corners differ.
    """),
    code("""
    figures.figure8()
    """),
    claims_cell(8),
    md("""
    ## Figure 10: pentagon preservation on one face

    The midpoints of a pentagon's edges are scaled about their centroid (here by
    0.75) to make a smaller pentagon, and each of its corners is joined to its
    midpoint: one pentagon becomes six.
    """),
    code("""
    figures.figure10()
    """),
    claims_cell(10),
    md("""
    The same steps on every face of a cube, one at a time: midpoints, the scaled
    inner faces, the edges to the midpoints (in red), the result and its duals.
    """),
    code("""
    pentanb.step_through(pentanb.shapes.cube(), "preserve_pentagons", duals=2)
    """),
    md("""
    ## Figure 11: pentagon preservation on the cube
    """),
    code("""
    figures.figure11()
    """),
    claims_cell(11),
    md("""
    The non-pentagons (the shrunken copies of the cube's quads) stay as many as
    there were faces at the start, round after round, while the pentagons multiply.
    """),
    code("""
    hard_cube = pentanb.shapes.hard_edged_cube()
    mesh = hard_cube
    for k in range(1, 4):
        mesh = pentanb.subdivide(mesh, "preserve_pentagons", 1, 2)
        hist = mesh.face_size_histogram()
        others = sum(c for n, c in hist.items() if n != 5)
        print(f"{k} rounds: {hist.get(5, 0):6d} pentagons, {others} other faces")
        assert others == hard_cube.n_faces
    """),
    md("""
    ## Try it

    Pick the cube, a scheme, the number of iterations, the number of dual passes
    after each and (for pentagon preservation) the scale of the inner face. The
    iteration slider stops before a mesh would pass 100,000 faces. The text lists
    the most common face configurations (watch 3.3.4.3.4, the paper's 4.3.3.4.3,
    take over on the hard-edged cube) and the edge waviness. Drag the 3D view to
    turn it.
    """),
    code("""
    base = widgets.Dropdown(options=[("hard-edged cube", "hard_cube"), ("plain cube", "cube")],
                            value="hard_cube", description="cube")
    pentagonal = [(s.label, s.name) for s in pentanb.SCHEMES.values() if s.family == "pentagonal"]
    scheme = widgets.Dropdown(options=pentagonal, value="pentagonalize", description="scheme")
    iterations = widgets.IntSlider(value=1, min=0, max=3, description="iterations",
                                   continuous_update=False)
    duals = widgets.IntSlider(value=2, min=0, max=4, description="dual passes",
                              continuous_update=False)
    scale = widgets.FloatSlider(value=0.75, min=0.1, max=0.9, step=0.05, description="scale",
                                continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(hard_cube, width=420, height=380)


    def redraw(change=None):
        scale.disabled = "scale" not in pentanb.SCHEMES[scheme.value].options
        iterations.max = max_iterations(pentanb.shapes.get(base.value), scheme.value,
                                        duals.value)
        mesh = build(base.value, scheme.value, iterations.value, duals.value,
                     None if scale.disabled else round(scale.value, 2))
        configs = figures.configuration_counts(figures.face_configurations(mesh))
        with picture:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"{scheme.label} x{iterations.value}, "
                                          f"{duals.value} duals", size=3.4))
            print(mesh)
            print("faces by corner valences:", dict(list(configs.items())[:4]))
            if mesh.n_faces <= 20_000:   # the ray test grows with the mesh
                print(f"edge waviness: {edge_waviness(mesh):.4f}")
        view3d.update(mesh, fit=change is not None and change["owner"] is base)


    for w in (base, scheme, iterations, duals, scale):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([base, scheme, iterations]), widgets.HBox([duals, scale]),
                          widgets.HBox([picture, view3d], layout={"flex_flow": "row wrap"})]))
    redraw()
    """),
    md("""
    `pentanb.explore` puts the same controls, for every shape and every scheme of
    the package, beside one 3D view:
    """),
    code("""
    pentanb.explore("cube", "pentagonalize", max_faces=MAX_FACES)
    """),
]


# ---------------------------------------------------------------------------
# 04 Torus and hexagons
# ---------------------------------------------------------------------------

NB04 = [
    md(r"""
    # Hexagons need a hole (Figures 4, 5 and 9)

    Equation (1) with $n = 6$ gives $m = 3\,(1 + (2g - 2)/v)$: below 3 on a sphere,
    exactly 3 on a torus, above 3 for genus 2 and more. So

    > "for $g > 0$, it is always possible to create hexagonal meshes; two examples
    > are shown in Figure 4."

    > "it is possible to develop an hexagonal preservation scheme since hexagonal
    > meshes exist for $g > 0$. Figure 5 shows two examples of an hexagon preserving
    > scheme applied to $g > 0$ hexagonal meshes."

    Pentagonalization applied to such a (6, 3) mesh makes the "6.3.3.3.3
    semi-regular tiling" of Figure 9: every pentagon has one 6-valent corner (the
    centre of an old hexagon) and four 3-valent ones. Each figure is followed by the
    claims measured; then the sliders change the torus and the number of rounds.
    """),
    SETUP,
    CACHE,
    code('''
    @functools.lru_cache(maxsize=64)
    def hexagonal(genus, rings, sides):
        """A mesh of hexagons of the given genus, made of rings x sides tori."""
        if genus == 1:
            return pentanb.shapes.hexagonal_torus(rings, sides)
        return pentanb.shapes.hexagonal_surface(genus, rings, sides)


    @functools.lru_cache(maxsize=128)
    def build_hex(genus, rings, sides, scheme, rounds, duals):
        return pentanb.subdivide(hexagonal(genus, rings, sides), scheme, rounds, duals)
    '''),
    md("""
    ## Figure 4: hexagonal meshes of genus 1 and 2

    The torus is the regular (6, 3) tiling: every vertex 3-valent. On the genus-2
    surface $m > 3$, so some vertices must have valence 4.
    """),
    code("""
    figures.figure4()
    """),
    claims_cell(4),
    md("""
    ## Figure 5: two rounds of hexagon preservation

    Hexagon preservation (the dual of Loop's remeshing) keeps every hexagon a
    hexagon and adds one hexagon per edge; two duals follow each round.
    """),
    code("""
    figures.figure5()
    """),
    claims_cell(5),
    md("""
    ## Figure 9: the 6.3.3.3.3 tiling

    One pentagonalization with two duals on the hexagonal torus (A), and its dual (B).
    """),
    code("""
    figures.figure9()
    """),
    claims_cell(9),
    md("""
    ## Try it

    Change the genus, the size of the tori (rings around the axis, hexagons around
    the tube), the scheme and the number of rounds (two duals after each). The
    rounds slider stops before a mesh would pass 100,000 faces; the text gives the
    measured average valence next to equation (1).
    """),
    code("""
    genus = widgets.Dropdown(options=[1, 2, 3], value=1, description="genus")
    rings = widgets.IntSlider(value=12, min=4, max=24, step=2, description="rings",
                              continuous_update=False)
    sides = widgets.IntSlider(value=6, min=3, max=16, description="sides",
                              continuous_update=False)
    schemes = ["preserve_hexagons", "pentagonalize", "preserve_pentagons", "honeycomb"]
    scheme = widgets.Dropdown(options=[(pentanb.SCHEMES[s].label, s) for s in schemes],
                              value="preserve_hexagons", description="scheme")
    rounds = widgets.IntSlider(value=1, min=0, max=3, description="rounds",
                               continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(hexagonal(1, 12, 6), width=420, height=380)


    def redraw(change=None):
        base = hexagonal(genus.value, rings.value, sides.value)
        rounds.max = max_iterations(base, scheme.value, 2)
        mesh = build_hex(genus.value, rings.value, sides.value, scheme.value, rounds.value, 2)
        with picture:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"genus {genus.value}: {scheme.label} x{rounds.value}",
                              size=3.4, elev=38, azim=-60))
            print(mesh)
            print("valences:", mesh.valence_histogram())
            if len(mesh.face_size_histogram()) == 1:
                n = int(mesh.face_sizes[0])
                print(f"average valence {2 * mesh.n_edges / mesh.n_vertices:.4f}, equation (1): "
                      f"{pentanb.topology.average_valence(n, mesh.genus, mesh.n_vertices):.4f}")
        view3d.update(mesh, fit=change is not None and change["owner"] in (genus, rings, sides))


    for w in (genus, rings, sides, scheme, rounds):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([genus, rings, sides]), widgets.HBox([scheme, rounds]),
                          widgets.HBox([picture, view3d], layout={"flex_flow": "row wrap"})]))
    redraw()
    """),
]


# ---------------------------------------------------------------------------
# 05 Soccer ball
# ---------------------------------------------------------------------------

NB05 = [
    md(r"""
    # Soccer balls from pentagons (Figure 13)

    No sphere can be tiled by hexagons alone, but pentagonal meshes can be turned
    into meshes with no triangles or quads at all:

    > "If one applies a honeycomb subdivision, dual of $\sqrt{3}$ or dual of Loop, to
    > the pentagonal meshes, the resulting meshes do not include any triangle or
    > quadrilateral. In the case of dual of $\sqrt{3}$ each vertex becomes valence three
    > and each face becomes rounder ... the portions of the resulting mesh resemble
    > geodesic domes (also called buckyballs, fullerenes or soccerballs)."

    Honeycomb (the dual of $\sqrt{3}$) applied to the dodecahedron is the truncated
    icosahedron: 12 pentagons, 20 hexagons, 60 three-valent vertices, a soccer ball.
    The figure is followed by the claims measured, then the claim is checked on
    several pentagonal meshes, and the sliders let you build your own.
    """),
    SETUP,
    CACHE,
    md("""
    ## Figure 13

    Honeycomb of a dodecahedron (A) and of a pentagonalized cube (B); hexagon
    preservation (the dual of Loop) of the same (C, D). Two duals after each.
    """),
    code("""
    figures.figure13()
    """),
    claims_cell(13),
    md("""
    ## The claim on every pentagonal base

    Honeycomb and hexagon preservation on several pentagonal meshes: the smallest
    face left (never a triangle or quad), and the valences (all 3 after honeycomb).
    """),
    code('''
    BASES = {   # label: (shape, pentagonalizations)
        "dodecahedron": ("dodecahedron", 0),
        "pentagonalized tetrahedron": ("tetrahedron", 1),
        "pentagonalized cube": ("cube", 1),
        "pentagonalized octahedron": ("octahedron", 1),
        "pentagonalized torus": ("torus", 1),
    }


    def base_mesh(label):
        """A pentagonal mesh: a shape pentagonalized (with two duals) 0 or more times."""
        shape, k = BASES[label]
        return build(shape, "pentagonalize", k, 2)


    print(f"{'base':>28}  {'scheme':>18}  smallest face  valences")
    for label in BASES:
        for s in ("honeycomb", "preserve_hexagons"):
            mesh = pentanb.subdivide(base_mesh(label), s, 1, 0)
            smallest = min(mesh.face_size_histogram())
            print(f"{label:>28}  {s:>18}  {smallest:13d}  {mesh.valence_histogram()}")
            assert smallest >= 5
            if s == "honeycomb":
                assert set(mesh.valence_histogram()) == {3}
    '''),
    md("""
    ## Try it

    Choose the pentagonal base, the scheme, the number of rounds and the dual passes
    after each. Drag the 3D view to turn the ball.
    """),
    code("""
    base = widgets.Dropdown(options=list(BASES), value="dodecahedron", description="base")
    schemes = ["honeycomb", "preserve_hexagons", "preserve_pentagons", "pentagonalize"]
    scheme = widgets.Dropdown(options=[(pentanb.SCHEMES[s].label, s) for s in schemes],
                              value="honeycomb", description="scheme")
    rounds = widgets.IntSlider(value=1, min=0, max=3, description="rounds",
                               continuous_update=False)
    duals = widgets.IntSlider(value=2, min=0, max=4, description="dual passes",
                              continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(base_mesh("dodecahedron"), width=420, height=380)


    @functools.lru_cache(maxsize=128)
    def ball(label, scheme, rounds, duals):
        return pentanb.subdivide(base_mesh(label), scheme, rounds, duals)


    def redraw(change=None):
        rounds.max = max_iterations(base_mesh(base.value), scheme.value, duals.value)
        mesh = ball(base.value, scheme.value, rounds.value, duals.value)
        with picture:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"{scheme.label} x{rounds.value}", size=3.4))
            print(mesh)
            print("valences:", mesh.valence_histogram())
        view3d.update(mesh, fit=change is not None and change["owner"] is base)


    for w in (base, scheme, rounds, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([base, scheme]), widgets.HBox([rounds, duals]),
                          widgets.HBox([picture, view3d], layout={"flex_flow": "row wrap"})]))
    redraw()
    """),
]


# ---------------------------------------------------------------------------
# 06 Schemes compared
# ---------------------------------------------------------------------------

NB06 = [
    md(r"""
    # Every scheme, side by side (Figures 2 and 3)

    Section 3 sorts remeshings into **conversion** schemes, which turn any mesh into
    one kind of face ($\sqrt{3}$ and vertex insertion make triangles and quads), and
    **preservation** schemes, which keep a mesh of one kind of face that way (Loop).
    It sets one remeshing aside:

    > "The remeshing algorithm shown in Figure 2 is also not considered, since after
    > the first iteration it does not change the mesh (i.e., it becomes null
    > algorithm)."

    and shows that Loop's remeshing works on any mesh:

    > "we first subdivide every edge at its midpoint and connect these midpoints to
    > create a central face in the middle of each original face and triangles in each
    > corner." (Figure 3)

    `pentanb.SCHEMES` lists every remeshing of the package: the paper's two and the
    ones it compares with. This notebook redraws Figures 2 and 3 with their claims,
    tabulates all the schemes (the counts each predicts before building and the
    counts it builds), sorts them into conversion and preservation, and draws them
    all on a mesh of your choice.
    """),
    setup("from pentanb.viz.mpl import plot_meshes"),
    CACHE,
    md("""
    ## Figure 2: the simplest triangulation

    Every non-triangle becomes a fan of triangles around its centroid. Applied again,
    nothing changes: a null algorithm.
    """),
    code("""
    figures.figure2()
    """),
    claims_cell(2),
    md("""
    ## Figure 3: Loop's remeshing on a mesh that is not all triangles

    A pentagonal prism with a pyramid on top (a pentagon, five quads, five
    triangles): every face keeps a central copy of itself, and triangles fill the
    corners. The non-triangles stay as many as they were.
    """),
    code("""
    figures.figure3()
    """),
    claims_cell(3),
    md("""
    ## All the schemes

    For each scheme: where the paper uses it, the Conway operator with the same
    topology, the counts after one application predicted by the registry (without
    building anything), and the counts built. Then the Conway names and count
    formulas, checked on Figure 3's mixed mesh (`figures.scheme_claims`).
    """),
    code("""
    def scheme_table(mesh):
        counts = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
        print(f"input: {mesh}")
        print(f"{'scheme':>20}  {'paper':>34}  {'Conway':>18}  {'predicted V, E, F':>18}  "
              f"{'built V, E, F':>18}  faces")
        for s in pentanb.SCHEMES.values():
            out = s(mesh)
            built = (out.n_vertices, out.n_edges, out.n_faces)
            predicted = pentanb.predict_counts(counts, s.name, 1, 0)[0]
            print(f"{s.name:>20}  {s.paper:>34}  {str(s.conway):>18}  {str(predicted):>18}  "
                  f"{str(built):>18}  {out.face_size_histogram()}")


    scheme_table(pentanb.shapes.cube())
    """),
    code("""
    for claim in figures.scheme_claims():
        print(claim)
        assert claim.holds, claim
    """),
    md("""
    ## Conversion or preservation?

    Each scheme applied twice to a mesh of triangles, quads and a pentagon (Figure
    3's). A conversion scheme leaves one kind of face whatever it starts from. A
    preservation scheme leaves the faces of other kinds as they were (their number
    stays constant) while its own kind multiplies.
    """),
    code("""
    mixed = pentanb.loop_remesh(pentanb.shapes.cube())   # 24 triangles and 6 quads
    print("input:", mixed.face_size_histogram())
    for s in pentanb.SCHEMES.values():
        once = pentanb.subdivide(mixed, s.name, 1, 0).face_size_histogram()
        twice = pentanb.subdivide(mixed, s.name, 2, 0).face_size_histogram()
        kind = "conversion" if len(twice) == 1 else "mixed faces remain"
        print(f"{s.label:>38}: {kind:>18}  once {once}  twice {twice}")
    """),
    md("""
    ## Side by side

    Every scheme on the chosen mesh, with the chosen number of iterations and
    dual passes after each. Iterations are capped so that no mesh passes 100,000
    faces.
    """),
    code("""
    shape = widgets.Dropdown(options=list(pentanb.shapes.SHAPES), value="cube", description="mesh")
    iterations = widgets.IntSlider(value=1, min=1, max=3, description="iterations",
                                   continuous_update=False)
    duals = widgets.IntSlider(value=0, min=0, max=2, step=2, description="dual passes",
                              continuous_update=False)
    out = widgets.Output()


    def redraw(change=None):
        base = pentanb.shapes.get(shape.value)
        names = list(pentanb.SCHEMES)
        iterations.max = max(1, min(max_iterations(base, s, duals.value) for s in names))
        meshes = [build(shape.value, s, iterations.value, duals.value) for s in names]
        fig = plot_meshes(meshes, [f"{pentanb.SCHEMES[s].label}\\n{mesh.n_faces:,} faces"
                                   for s, mesh in zip(names, meshes)], ncols=3)
        with out:
            clear_output(wait=True)
            display(fig)
            for s, mesh in zip(names, meshes):
                print(f"{s:>20}: {mesh}")


    for w in (shape, iterations, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([shape, iterations, duals]), out]))
    redraw()
    """),
]


# ---------------------------------------------------------------------------
# 07 Complex model
# ---------------------------------------------------------------------------

NB07 = [
    md(r"""
    # A complex model, and your own meshes (Figure 12)

    > "Figure 12 shows an example of pentagonalization scheme. As it can be seen in
    > this example, such complicated models can effectively be smoothed by our
    > approach. More importantly, even meshes having hard edges can be effectively
    > smoothed without creating any lateral artifacts."

    The paper's rabbit (modelled by Esan Mandal) is not available, so
    `pentanb.shapes.animal()` stands in: a blocky rabbit of unit cubes, all hard
    edges. Figure 12 applies pentagonalization twice (two duals after each); the
    claims check the counts and that only pentagons remain. Afterwards you can load
    any closed OBJ or OFF file of your own and subdivide it.
    """),
    SETUP,
    CACHE,
    md("## Figure 12"),
    code("""
    figures.figure12()
    """),
    claims_cell(12),
    md("""
    ## Your own mesh

    `pentanb.read` reads `.obj` and `.off` files (faces with any number of sides;
    the mesh must be closed and manifold) and `pentanb.write` writes them. To show
    the round trip, the rabbit is written to a temporary folder and read back.
    """),
    code("""
    import tempfile
    from pathlib import Path

    animal = pentanb.shapes.animal()
    folder = Path(tempfile.mkdtemp())
    for suffix in (".obj", ".off"):
        pentanb.write(animal, folder / f"rabbit{suffix}")
        back = pentanb.read(folder / f"rabbit{suffix}")
        assert (back.vertices == animal.vertices).all()
        assert (back.corners == animal.corners).all()
        print(f"{suffix}: wrote and read back {back}")
    """),
    md("""
    Put the path of your own file in `path` (or in the text box) and press *Load*.
    A file that cannot be read says why. Choose a scheme, the iterations (capped so
    that no mesh passes 100,000 faces) and the dual passes.
    """),
    code("""
    path = folder / "rabbit.obj"   # replace with the path of your own .obj or .off file
    """),
    code("""
    path_box = widgets.Text(value=str(path), description="file", layout={"width": "60%"})
    load = widgets.Button(description="Load")
    scheme = widgets.Dropdown(options=[(s.label, s.name) for s in pentanb.SCHEMES.values()],
                              value="pentagonalize", description="scheme")
    iterations = widgets.IntSlider(value=1, min=0, max=3, description="iterations",
                                   continuous_update=False)
    duals = widgets.IntSlider(value=2, min=0, max=4, description="dual passes",
                              continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(animal, width=420, height=380)
    loaded = {}


    @functools.lru_cache(maxsize=64)
    def subdivided(file, scheme, iterations, duals):
        return pentanb.subdivide(loaded[file], scheme, iterations, duals)


    def redraw(change=None, fit=False):
        file = path_box.value
        with picture:
            clear_output(wait=True)
            if file not in loaded:
                print("press Load to read", file)
                return
            mesh = loaded[file]
            iterations.max = max_iterations(mesh, scheme.value, duals.value)
            result = subdivided(file, scheme.value, iterations.value, duals.value)
            display(plot_mesh(result, title=f"{scheme.label} x{iterations.value}", size=3.4,
                              elev=12, azim=-62))
            print(f"input:  {mesh}, genus {mesh.genus}")
            print(f"result: {result}")
        view3d.update(result, fit=fit)


    def read_file(button=None):
        file = path_box.value
        try:
            loaded[file] = pentanb.read(file)
        except (OSError, ValueError) as err:   # pentanb.MeshError is a ValueError
            with picture:
                clear_output()
                print("could not read the file:", err)
            return
        subdivided.cache_clear()   # the file may have changed on disk
        redraw(fit=True)


    load.on_click(read_file)
    for w in (scheme, iterations, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([path_box, load]),
                          widgets.HBox([scheme, iterations, duals]),
                          widgets.HBox([picture, view3d], layout={"flex_flow": "row wrap"})]))
    read_file()
    """),
    md("""
    A file that is not a closed manifold is refused with a message naming the
    culprit, for instance a single triangle (it has boundary edges):
    """),
    code("""
    bad = folder / "triangle.obj"
    bad.write_text("v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n")
    try:
        pentanb.read(bad)
    except pentanb.MeshError as err:
        print("refused:", err)
    """),
]


# ---------------------------------------------------------------------------
# 08 Convergence
# ---------------------------------------------------------------------------

NB08 = [
    md(r"""
    # How fast does dual smoothing converge? (beyond the paper)

    The paper smooths by applying the dual an even number of times, and leaves its
    convergence open:

    > "we have visually confirmed that the algorithms converge with $G^1$
    > continuity. However, there is still a need for theoretical proofs for
    > convergence."

    This notebook measures it (`pentanb.analysis.convergence`). Two numbers describe a mesh:

    * the **crease angle**: the angle between the normals of two faces sharing an
      edge. On a $G^1$ (tangent-continuous) limit surface the largest crease angle
      must fall towards 0 as the mesh is refined;
    * the **radius spread**: the standard deviation over the mean of the vertices'
      distances from their centroid, 0 on a sphere.

    Two experiments: remesh once and then apply more and more pairs of duals (does
    smoothing alone converge, and to what?), and subdivide level after level
    (remesh + two duals each time).
    """),
    setup(
        "from pentanb.analysis import convergence",
        "",
        "from matplotlib.figure import Figure",
        "from matplotlib.ticker import NullFormatter, ScalarFormatter",
    ),
    CACHE,
    md("""
    ## The study

    Both of the paper's schemes on a cube, a tetrahedron, a torus and the rabbit.
    (A) and (B): after one remeshing, pairs of duals round the mesh off, but the
    crease angle levels out: duals alone do not make the surface smooth. (C): level
    after level, the largest crease angle falls towards 0.
    """),
    code("""
    figures.convergence_figure()
    """),
    claims_cell("convergence"),
    md("""
    ## Rates

    The factor by which the largest and the mean crease angle shrink from one level
    to the next. When a level multiplies the number of faces by $k$ (about 5 for
    pentagonalization, 6 for pentagon preservation), the edges get about
    $\\sqrt{k}$ times shorter, and on a smooth surface the angle between
    neighbouring faces shrinks like the edges: a mean factor near $1/\\sqrt{k}$
    (last column). The largest angle, found at the extraordinary vertices, shrinks
    more slowly but keeps shrinking.
    """),
    code("""
    import numpy as np

    study = convergence.study()
    print(f"{'mesh':>12}  {'scheme':>18}  {'largest angle (deg)':>24}  {'its factors':>16}  "
          f"{'mean factors':>16}  {'1/sqrt(k)':>16}")
    for (name, scheme), res in study["levels"].items():
        largest, mean = res.max_normal_angle, res.mean_normal_angle
        edge = np.sqrt(res.faces[:-1] / res.faces[1:])
        row = lambda xs, f="{:.2f}": " ".join(f.format(x) for x in xs)  # noqa: E731
        print(f"{name:>12}  {scheme:>18}  {row(largest, '{:5.1f}'):>24}  "
              f"{row(largest[1:] / largest[:-1]):>16}  {row(mean[1:] / mean[:-1]):>16}  "
              f"{row(edge):>16}")
    """),
    md("""
    ## Try it

    Choose a shape, any scheme of the package (to compare the paper's schemes with
    Catmull-Clark's vertex insertion or Doo-Sabin's corner cutting), the number of
    levels and the dual passes after each. The plot shows the largest and mean
    crease angles per level (log scale) and the radius spread; the 3D view shows the
    last level. Levels are capped so that no mesh passes 100,000 faces.
    """),
    code("""
    shape = widgets.Dropdown(options=list(pentanb.shapes.SHAPES), value="cube", description="shape")
    scheme = widgets.Dropdown(options=[(s.label, s.name) for s in pentanb.SCHEMES.values()],
                              value="pentagonalize", description="scheme")
    levels = widgets.IntSlider(value=3, min=1, max=4, description="levels",
                               continuous_update=False)
    duals = widgets.IntSlider(value=2, min=0, max=6, step=2, description="dual passes",
                              continuous_update=False)
    picture = widgets.Output()
    view3d = pentanb.view(build("cube", "pentagonalize", 3, 2), width=420, height=380)


    @functools.lru_cache(maxsize=64)
    def measure(shape, scheme, levels, duals):
        return convergence.subdivision_convergence(pentanb.shapes.get(shape), scheme, levels,
                                                   duals)


    def redraw(change=None):
        base = pentanb.shapes.get(shape.value)
        levels.max = max(1, max_iterations(base, scheme.value, duals.value))
        res = measure(shape.value, scheme.value, levels.value, duals.value)
        fig = Figure(figsize=(7.5, 3.2))
        left, right = fig.subplots(1, 2)
        left.semilogy(res.steps, res.max_normal_angle, "o-", label="largest")
        left.semilogy(res.steps, res.mean_normal_angle, "s--", label="mean")
        left.set(xlabel="level", ylabel="crease angle (deg, log scale)", title="crease angles",
                 xticks=res.steps)
        left.yaxis.set_major_formatter(ScalarFormatter())
        left.yaxis.set_minor_formatter(NullFormatter())
        left.legend()
        right.plot(res.steps, res.radius_spread, "o-", color="C2")
        right.set(xlabel="level", ylabel="std / mean", title="radius spread", xticks=res.steps)
        fig.tight_layout()
        with picture:
            clear_output(wait=True)
            display(fig)
            print("faces per level:", res.faces.tolist())
        view3d.update(build(shape.value, scheme.value, levels.value, duals.value),
                      fit=change is not None and change["owner"] is shape)


    for w in (shape, scheme, levels, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([shape, scheme]), widgets.HBox([levels, duals]),
                          widgets.HBox([picture, view3d], layout={"flex_flow": "row wrap"})]))
    redraw()
    """),
]


NOTEBOOKS = {
    "01_topology": NB01,
    "02_tetrahedron_to_dodecahedron": NB02,
    "03_cube_tilings": NB03,
    "04_torus_hexagons": NB04,
    "05_soccerball": NB05,
    "06_schemes_compared": NB06,
    "07_complex_model": NB07,
    "08_convergence": NB08,
}


def notebook(name: str):
    """The notebook ``name`` (a key of :data:`NOTEBOOKS`), without outputs."""
    nb = new_notebook(
        cells=[c.copy() for c in NOTEBOOKS[name]],
        metadata={"kernelspec": KERNELSPEC, "language_info": {"name": "python"}},
    )
    for i, cell in enumerate(nb.cells):
        cell["id"] = f"{name[:2]}-{i:02d}"
    nbformat.validate(nb)
    return nb


def build(outdir: Path = HERE) -> list[Path]:
    """Write every notebook into ``outdir``; return their paths."""
    outdir = Path(outdir)
    paths = []
    for name in NOTEBOOKS:
        path = outdir / f"{name}.ipynb"
        nbformat.write(notebook(name), path)
        paths.append(path)
    return paths


if __name__ == "__main__":
    for p in build(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(p)
