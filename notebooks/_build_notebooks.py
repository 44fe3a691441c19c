"""Write the notebooks of this folder from the cell sources below.

Run ``python notebooks/_build_notebooks.py`` after editing; the ``.ipynb``
files are written without outputs (``tests/test_notebooks.py`` executes them
and checks that they stay clean).  Each notebook is thin: it calls
:mod:`pentanb` and explains; every computation lives in the library.
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

SETUP = code("""
    %matplotlib inline
    import functools

    import ipywidgets as widgets
    from IPython.display import clear_output, display

    import pentanb
    from pentanb.viz.mpl import plot_mesh
    from _interim import row
""")

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


    def max_iterations(mesh, scheme, duals=2, limit=MAX_FACES, cap=6):
        """Most iterations whose meshes all stay under `limit` faces (predicted, not built)."""
        counts = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
        best = 0
        for k in range(1, cap + 1):
            if max(F for _, _, F in pentanb.predict_counts(counts, scheme, k, duals)) > limit:
                break
            best = k
        return best
''')


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
    equation (1), prints the paper's $(n, m)$ chart, checks these claims with
    `pentanb.topology`, compares equation (1) with real meshes, and then lets you
    move $n$, $g$ and $v$ yourself.
    """),
    code("""
    %matplotlib inline
    import ipywidgets as widgets
    import matplotlib.pyplot as plt
    import numpy as np
    from IPython.display import clear_output, display

    import pentanb
    from pentanb import topology
    """),
    md(r"""
    ## Equation (1)

    Average valence $m$ against the number of vertices $v$ for triangles, quads,
    pentagons and hexagons on a sphere ($g = 0$). Points below the line $m = 3$
    cannot be meshes without 1- or 2-valent vertices.
    """),
    code("""
    v = np.linspace(2, 80, 400)
    fig, ax = plt.subplots(figsize=(6, 4))
    for n in (3, 4, 5, 6):
        ax.plot(v, topology.average_valence(n, 0, v), label=f"n = {n}")
    ax.axhline(3, color="k", lw=0.8, ls="--")
    ax.set(xlabel="v", ylabel="m", ylim=(0, 7), title="Equation (1), g = 0")
    ax.legend()
    plt.show()
    """),
    md(r"""
    ## The paper's chart

    As $v \to \infty$, $m \to 2n/(n-2)$: the value for $g = 1$, the tessellations of
    the plane. "(5, 10/3) can only have semi-regular tesselations": pentagons cannot
    all meet at vertices of one valence in the limit.
    """),
    code("""
    print(f"{'(n, m)':>16}  regular?  type")
    for row in topology.schlafli_chart():
        pair = f"({float(row.n):.2f}, {float(row.m):.2f})"
        print(f"{pair:>16}  {'yes' if row.admits_regular else 'no ':>8}  {row.description}")
    """),
    md(r"""
    ## The claims, checked

    For each $n$: the limit valence $2n/(n-2)$, the fewest vertices of an $n$-gon
    sphere and torus with $m \ge 3$, and whether a conversion ("$n$-gonalization")
    or a preservation scheme can exist.
    """),
    code("""
    print(" n  2n/(n-2)  min v (g=0)  min v (g=1)  conversion  preservation")
    for n in range(3, 9):
        print(f"{n:2d}  {str(topology.limit_valence(n)):>8}  "
              f"{str(topology.min_vertices(n, 0)):>11}  {str(topology.min_vertices(n, 1)):>11}  "
              f"{str(topology.ngonalization_exists(n)):>10}  "
              f"{str(topology.ngon_preservation_exists(n)):>12}")

    assert topology.min_vertices(5, 0) == 20    # the dodecahedron
    assert topology.min_vertices(4, 0) == 8     # the cube
    assert topology.min_vertices(3, 0) == 4     # the tetrahedron
    assert topology.min_vertices(6, 0) is None  # no hexagonal sphere
    assert topology.ngonalization_exists(5) and not topology.ngonalization_exists(6)
    assert topology.ngon_preservation_exists(6) and not topology.ngon_preservation_exists(7)
    print("Section 4's claims hold.")
    """),
    md(r"""
    ## Equation (1) against real meshes

    Every shape in `pentanb.shapes` whose faces all have the same number of sides:
    its measured average valence $2e/v$ and the value equation (1) predicts from
    $n$, $g$ and $v$ alone.
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
        print(f"{name:>18}  {n}  {mesh.genus}  {mesh.n_vertices:3d}  {measured:10.4f}  {predicted:12.4f}")
        assert abs(measured - predicted) < 1e-9
    """),
    md(r"""
    ## Try it

    Choose the number of sides $n$, the genus $g$ and the number of vertices $v$.
    The plot shows $m(v)$ for your $n$ and $g$, the line $m = 3$ and the limit
    $2n/(n-2)$; the text says whether Euler's formula allows such a mesh.
    """),
    code("""
    n_slider = widgets.IntSlider(value=5, min=3, max=10, description="n (sides)")
    g_slider = widgets.IntSlider(value=0, min=0, max=5, description="g (genus)")
    v_slider = widgets.IntSlider(value=20, min=1, max=200, description="v (vertices)")
    out = widgets.Output()


    def redraw(change=None):
        n, g, v = n_slider.value, g_slider.value, v_slider.value
        with out:
            clear_output(wait=True)
            vs = np.linspace(max(1.0, 2.5 - 2 * g), 200, 500)
            fig, ax = plt.subplots(figsize=(6, 3.5))
            ax.plot(vs, topology.average_valence(n, g, vs), label=f"equation (1), n={n}, g={g}")
            ax.axhline(3, color="k", lw=0.8, ls="--", label="m = 3")
            ax.axhline(float(topology.limit_valence(n)), color="gray", lw=0.8, ls=":",
                       label="limit 2n/(n-2)")
            if v + 2 * g - 2 > 0:
                ax.plot([v], [topology.average_valence(n, g, v)], "o", color="C3")
            ax.set(xlabel="v", ylabel="m", ylim=(0, 8))
            ax.legend(loc="lower right", fontsize=8)
            plt.show()
            m = topology.average_valence(n, g, v)
            print(f"m = {m:.4f}  (limit {topology.limit_valence(n)})")
            counts = topology.ngon_mesh_counts(n, g, v)
            print("(v, e, f) =", counts if counts else "not integers: no such mesh")
            print("possible with m >= 3:", topology.can_tile(n, g, v))
            print("admissible v for this n, g:", topology.vertex_range(n, g))


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
    point at the centre of every face and joins it to every third point around the
    face (Figure 6), so that every $n$-gon becomes $n$ pentagons. Then the dual is
    applied an even number of times to smooth the result.

    > "This scheme can convert the simplest triangular mesh (tetrahedron) to the
    > simplest pentagonal mesh (dodecahedron) as shown in Figure 7. This set of images
    > also show the role of dual operation; the resulting shape becomes more and more
    > uniform with each application of dual operation."

    This notebook checks both claims: the pentagonalized tetrahedron has exactly the
    counts of a dodecahedron (12 pentagons, 30 edges, 20 three-valent vertices), and
    the dual passes make it more uniform.
    """),
    SETUP,
    CACHE,
    md("""
    ## Figure 7

    (A) the tetrahedron, (B) one pentagonalization, (C) its dual (an icosahedral
    shape), (D) the dual of (C), (E) and (F) the 5th and 6th duals.
    """),
    code("""
    tet = pentanb.shapes.tetrahedron()
    B = pentanb.pentagonalize(tet)
    stages = [tet, B] + [pentanb.smooth(B, k) for k in (1, 2, 5, 6)]
    row(stages, ["(A)", "(B)", "(C)", "(D)", "(E)", "(F)"], ncols=3)
    """),
    md("## The counts"),
    code("""
    for k in range(7):
        print(f"{k} duals: {pentanb.smooth(B, k)}")

    dodeca = pentanb.shapes.dodecahedron()
    assert B.face_size_histogram() == dodeca.face_size_histogram() == {5: 12}
    assert B.valence_histogram() == dodeca.valence_histogram() == {3: 20}
    assert (B.n_vertices, B.n_edges, B.n_faces) == (20, 30, 12)
    print("The pentagonalized tetrahedron has the counts of a dodecahedron.")
    """),
    md("""
    ## Slide through the dual passes

    Even numbers of duals give dodecahedral shapes (12 pentagons), odd numbers
    icosahedral ones (20 triangles). Watch the shape even out.
    """),
    code("""
    duals = widgets.IntSlider(value=2, min=0, max=12, description="dual passes",
                              continuous_update=False)
    out = widgets.Output()


    def redraw(change=None):
        mesh = build("tetrahedron", "pentagonalize", 1, duals.value)
        with out:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"pentagonalize + {duals.value} duals"))
            print(mesh)


    duals.observe(redraw, names="value")
    display(widgets.VBox([duals, out]))
    redraw()
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
    As shown in Figure 1.C, the new subdivision does not create any lateral artifact."

    Both of the paper's schemes are applied to it:

    * **pentagonalization** (Section 5.1) turns every $n$-gon into $n$ pentagons. On the
      cube's quad regions it makes the Cairo-like tiling the paper calls
      "4.3.3.4.3" (Figure 8);
    * **pentagon preservation** (Section 5.2) keeps a shrunken copy of every face and
      rings it with pentagons, so "the number of non-pentagonal faces remains constant
      after the first refinement" (Figures 10 and 11), and a pentagonal mesh stays
      pentagonal (Figure 1D).

    The counts below check these claims; the sliders at the end let you choose the
    scheme, the number of iterations, the dual passes and the preservation scale.
    """),
    SETUP,
    CACHE,
    md("""
    ## Figure 1

    (A) the cube, (B) one pentagonalization, (C) two, (D) pentagon preservation
    applied to (B). Each scheme is followed by two duals.
    """),
    code("""
    cube = pentanb.shapes.cube()
    B = build("cube", "pentagonalize", 1, 2)
    C = build("cube", "pentagonalize", 2, 2)
    D = pentanb.subdivide(B, "preserve_pentagons", 1, 2)
    row([cube, B, C, D], ["(A)", "(B)", "(C)", "(D)"], ncols=4)
    """),
    code("""
    for label, mesh in zip("ABCD", [cube, B, C, D]):
        print(f"({label}) {mesh}")
    assert B.face_size_histogram() == {5: 24} and C.face_size_histogram() == {5: 120}
    assert set(D.face_size_histogram()) == {5}
    print("Pentagonalization gives only pentagons; preservation keeps them.")
    """),
    md("""
    ## Figure 8: the 4.3.3.4.3 tiling and its dual
    """),
    code("""
    A8 = build("cube", "pentagonalize", 1, 2)
    row([A8, pentanb.dual(A8)], ["(A)", "(B)"])
    """),
    md("""
    ## Figures 10 and 11: pentagon preservation on the cube

    Every quad keeps a shrunken copy of itself and gets a ring of four pentagons.
    """),
    code("""
    row([cube, pentanb.preserve_pentagons(cube)], ["(A)", "(B)"])
    """),
    code("""
    A11 = build("cube", "preserve_pentagons", 1, 2)
    row([A11, pentanb.dual(A11)], ["(A)", "(B)"])
    """),
    md("""
    "The number of non-pentagonal faces remains constant after the first
    refinement": the cube's six quads survive every round of preservation while
    the pentagons multiply.
    """),
    code("""
    for k in range(1, 5):
        mesh = build("cube", "preserve_pentagons", k, 2)
        hist = mesh.face_size_histogram()
        others = sum(c for n, c in hist.items() if n != 5)
        print(f"{k} rounds: {hist.get(5, 0):6d} pentagons, {others} other faces")
        assert others == 6
    """),
    md("""
    ## Try it

    Pick a scheme, the number of iterations, the number of dual passes after each
    and (for pentagon preservation) the scale of the inner face. The iteration
    slider stops before a mesh would pass 100,000 faces.
    """),
    code("""
    pentagonal = [(s.label, s.name) for s in pentanb.SCHEMES.values() if s.family == "pentagonal"]
    scheme = widgets.Dropdown(options=pentagonal, value="pentagonalize", description="scheme")
    iterations = widgets.IntSlider(value=1, min=0, max=3, description="iterations",
                                   continuous_update=False)
    duals = widgets.IntSlider(value=2, min=0, max=4, description="dual passes",
                              continuous_update=False)
    scale = widgets.FloatSlider(value=0.75, min=0.1, max=0.9, step=0.05, description="scale",
                                continuous_update=False)
    out = widgets.Output()


    def redraw(change=None):
        scale.disabled = "scale" not in pentanb.SCHEMES[scheme.value].options
        iterations.max = max_iterations(cube, scheme.value, duals.value)
        mesh = build("cube", scheme.value, iterations.value, duals.value,
                     None if scale.disabled else round(scale.value, 2))
        with out:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"{scheme.label} x{iterations.value}, "
                                          f"{duals.value} duals"))
            print(mesh)


    for w in (scheme, iterations, duals, scale):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([scheme, iterations]), widgets.HBox([duals, scale]), out]))
    redraw()
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
    centre of an old hexagon) and four 3-valent ones.
    """),
    SETUP,
    CACHE,
    code("""
    from pentanb import topology


    @functools.lru_cache(maxsize=64)
    def hexagonal(genus, rings, sides):
        \"\"\"A mesh of hexagons with the given genus and torus size.\"\"\"
        if genus == 1:
            return pentanb.shapes.hexagonal_torus(rings, sides)
        return pentanb.shapes.hexagonal_surface(genus, rings, sides)


    @functools.lru_cache(maxsize=128)
    def build_hex(genus, rings, sides, scheme, rounds, duals):
        return pentanb.subdivide(hexagonal(genus, rings, sides), scheme, rounds, duals)
    """),
    md("""
    ## Figure 4: hexagonal meshes of genus 1 and 2
    """),
    code("""
    torus6 = hexagonal(1, 12, 6)
    genus2 = hexagonal(2, 8, 6)
    row([torus6, genus2], ["(A) genus 1", "(B) genus 2"], size=3.2)
    """),
    code("""
    for name, mesh in (("genus 1", torus6), ("genus 2", genus2)):
        m = 2 * mesh.n_edges / mesh.n_vertices
        print(f"{name}: {mesh}, genus {mesh.genus}, average valence {m:.4f}, "
              f"equation (1): {topology.average_valence(6, mesh.genus, mesh.n_vertices):.4f}")
    assert torus6.face_size_histogram() == {6: torus6.n_faces}
    assert torus6.valence_histogram() == {3: torus6.n_vertices}   # the regular (6, 3) tiling
    assert topology.min_vertices(6, 0) is None                     # but never on a sphere
    """),
    md("""
    ## Figure 5: two rounds of hexagon preservation

    Hexagon preservation (the dual of Loop's remeshing) keeps every hexagon a
    hexagon and adds one hexagon per edge.
    """),
    code("""
    A5 = build_hex(1, 12, 6, "preserve_hexagons", 2, 2)
    B5 = build_hex(2, 8, 6, "preserve_hexagons", 2, 2)
    row([A5, B5], ["(A)", "(B)"], size=3.2)
    """),
    code("""
    for mesh in (A5, B5):
        print(mesh)
        assert set(mesh.face_size_histogram()) == {6}
    print("Still only hexagons after two rounds.")
    """),
    md("""
    ## Figure 9: the 6.3.3.3.3 tiling

    One pentagonalization with two duals on the hexagonal torus, and its dual.
    """),
    code("""
    A9 = build_hex(1, 12, 6, "pentagonalize", 1, 2)
    row([A9, pentanb.dual(A9)], ["(A)", "(B)"], size=3.2)
    print(A9, "valences:", A9.valence_histogram())
    # one 6-valent vertex per old hexagon (its centre), every other vertex 3-valent
    assert A9.valence_histogram() == {3: A9.n_vertices - torus6.n_faces, 6: torus6.n_faces}
    """),
    md("""
    ## Try it

    Change the size of the torus (rings around the axis, hexagons around the tube),
    the genus, the scheme and the number of rounds. The rounds slider stops before a
    mesh would pass 100,000 faces.
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
    out = widgets.Output()


    def redraw(change=None):
        base = hexagonal(genus.value, rings.value, sides.value)
        rounds.max = max_iterations(base, scheme.value, 2)
        mesh = build_hex(genus.value, rings.value, sides.value, scheme.value, rounds.value, 2)
        with out:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"genus {genus.value}: {scheme.label} x{rounds.value}"))
            print(mesh)
            print("valences:", mesh.valence_histogram())


    for w in (genus, rings, sides, scheme, rounds):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([genus, rings, sides]), widgets.HBox([scheme, rounds]),
                          out]))
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
    """),
    SETUP,
    CACHE,
    md("""
    ## Figure 13
    """),
    code("""
    dodeca = pentanb.shapes.dodecahedron()
    ball = pentanb.honeycomb(dodeca)
    fine = pentanb.subdivide(build("tetrahedron", "pentagonalize", 2, 2), "honeycomb", 1, 2)
    row([dodeca, ball, fine], ["dodecahedron", "(A) honeycomb", "(B) finer"])
    """),
    code("""
    print(ball)
    assert ball.face_size_histogram() == {5: 12, 6: 20}
    assert ball.valence_histogram() == {3: 60}
    print("honeycomb(dodecahedron) is the truncated icosahedron (a soccer ball).")
    """),
    md("""
    ## The claim on every pentagonal base

    Honeycomb and hexagon preservation on several pentagonal meshes: the smallest
    face left, and (for honeycomb) the valences.
    """),
    code("""
    BASES = {
        "dodecahedron": ("dodecahedron", "pentagonalize", 0),
        "pentagonalized tetrahedron": ("tetrahedron", "pentagonalize", 1),
        "pentagonalized cube": ("cube", "pentagonalize", 1),
        "pentagonalized octahedron": ("octahedron", "pentagonalize", 1),
        "pentagonalized torus": ("torus", "pentagonalize", 1),
    }


    def base_mesh(label):
        shape, scheme, k = BASES[label]
        return build(shape, scheme, k, 2)


    print(f"{'base':>28}  {'scheme':>18}  smallest face  valences")
    for label in BASES:
        for s in ("honeycomb", "preserve_hexagons"):
            mesh = pentanb.subdivide(base_mesh(label), s, 1, 0)
            smallest = min(mesh.face_size_histogram())
            print(f"{label:>28}  {s:>18}  {smallest:13d}  {mesh.valence_histogram()}")
            assert smallest >= 5
            if s == "honeycomb":
                assert set(mesh.valence_histogram()) == {3}
    """),
    md("""
    ## Try it

    Choose the pentagonal base, the scheme, the number of rounds and the dual passes.
    """),
    code("""
    base = widgets.Dropdown(options=list(BASES), value="dodecahedron", description="base")
    schemes = ["honeycomb", "preserve_hexagons", "preserve_pentagons", "pentagonalize"]
    scheme = widgets.Dropdown(options=[(pentanb.SCHEMES[s].label, s) for s in schemes],
                              value="honeycomb", description="scheme")
    rounds = widgets.IntSlider(value=1, min=0, max=3, description="rounds",
                               continuous_update=False)
    duals = widgets.IntSlider(value=0, min=0, max=4, description="dual passes",
                              continuous_update=False)
    out = widgets.Output()


    @functools.lru_cache(maxsize=128)
    def ball_of(label, scheme, rounds, duals):
        return pentanb.subdivide(base_mesh(label), scheme, rounds, duals)


    def redraw(change=None):
        rounds.max = max_iterations(base_mesh(base.value), scheme.value, duals.value)
        mesh = ball_of(base.value, scheme.value, rounds.value, duals.value)
        with out:
            clear_output(wait=True)
            display(plot_mesh(mesh, title=f"{scheme.label} x{rounds.value}"))
            print(mesh, "valences:", mesh.valence_histogram())


    for w in (base, scheme, rounds, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([base, scheme]), widgets.HBox([rounds, duals]), out]))
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
    one kind of face ($\sqrt{3}$ and vertex insertion for triangles and quads), and
    **preservation** schemes, which keep a mesh of one kind of face that way (Loop).
    It sets one remeshing aside:

    > "The remeshing algorithm shown in Figure 2 is also not considered, since after
    > the first iteration it does not change the mesh (i.e., it becomes null
    > algorithm)."

    and shows that Loop's remeshing works on any mesh:

    > "we first subdivide every edge at its midpoint and connect these midpoints to
    > create a central face in the middle of each original face and triangles in each
    > corner." (Figure 3)

    `pentanb.SCHEMES` lists every remeshing of the package, the paper's two and the
    ones it compares with. This notebook redraws Figures 2 and 3, tabulates all the
    schemes (with the counts each predicts before building and the counts it builds),
    classifies them, and draws them all on a mesh of your choice.
    """),
    SETUP,
    CACHE,
    md("## Figure 2: the simplest triangulation"),
    code("""
    cube = pentanb.shapes.cube()
    T = pentanb.triangulate(cube)
    row([cube, T], ["(A)", "(B)"])
    """),
    code("""
    TT = pentanb.triangulate(T)
    print("once: ", T)
    print("twice:", TT)
    assert (TT.n_vertices, TT.n_edges, TT.n_faces) == (T.n_vertices, T.n_edges, T.n_faces)
    print("A second triangulation changes nothing: a null algorithm.")
    """),
    md("## Figure 3: Loop's remeshing on a mesh of quads"),
    code("""
    L = pentanb.loop_remesh(cube)
    row([cube, L], ["(A)", "(B)"])
    """),
    code("""
    print(L, L.face_size_histogram())
    assert L.face_size_histogram() == {3: 24, 4: 6}   # corner triangles + central quads
    """),
    md("""
    ## All the schemes

    For each scheme: where the paper uses it, the Conway operator with the same
    topology, the counts after one application predicted by the registry, and the
    counts actually built. Change the mesh to compare.
    """),
    code("""
    def scheme_table(mesh):
        counts = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
        print(f"input: {mesh}")
        print(f"{'scheme':>20}  {'paper':>34}  {'conway':>18}  {'predicted V, E, F':>20}  "
              f"{'built V, E, F':>20}  faces")
        for s in pentanb.SCHEMES.values():
            out = s(mesh)
            built = (out.n_vertices, out.n_edges, out.n_faces)
            predicted = pentanb.predict_counts(counts, s.name, 1, 0)[0]
            print(f"{s.name:>20}  {s.paper:>34}  {str(s.conway):>18}  {str(predicted):>20}  "
                  f"{str(built):>20}  {out.face_size_histogram()}")
            if s.name != "triangulate":   # the registry gives an upper bound for it
                assert predicted == built


    scheme_table(cube)
    """),
    md("""
    ## Conversion or preservation?

    Each scheme applied twice to Figure 3's output (24 triangles and 6 quads). A
    conversion scheme leaves one kind of face; a preservation scheme keeps the odd
    faces out while the rest multiply.
    """),
    code("""
    mixed = L
    for s in pentanb.SCHEMES.values():
        hist = pentanb.subdivide(mixed, s.name, 2, 0).face_size_histogram()
        kind = "conversion" if len(hist) == 1 else "preservation or neither"
        print(f"{s.label:>38}: {kind:>24}  {hist}")
    """),
    md("""
    ## Side by side

    Every scheme on the chosen mesh, with the chosen number of iterations and
    dual passes.
    """),
    code("""
    shape = widgets.Dropdown(options=list(pentanb.shapes.SHAPES), value="cube", description="mesh")
    iterations = widgets.IntSlider(value=1, min=1, max=2, description="iterations",
                                   continuous_update=False)
    duals = widgets.IntSlider(value=0, min=0, max=2, step=2, description="dual passes",
                              continuous_update=False)
    out = widgets.Output()


    def redraw(change=None):
        names = list(pentanb.SCHEMES)
        meshes = [build(shape.value, name, iterations.value, duals.value) for name in names]
        with out:
            clear_output(wait=True)
            display(row(meshes, [pentanb.SCHEMES[n].label for n in names], ncols=3))
            for name, mesh in zip(names, meshes):
                print(f"{name:>20}: {mesh}")


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
    edges. Figure 12 applies pentagonalization twice. Afterwards you can load any
    closed OBJ or OFF file of your own and subdivide it.
    """),
    SETUP,
    CACHE,
    md("## Figure 12"),
    code("""
    animal = pentanb.shapes.animal()
    twice = build("animal", "pentagonalize", 2, 2)
    row([animal, twice], ["(A) initial mesh", "(B) pentagonalized twice"], size=3.2)
    """),
    code("""
    counts = (animal.n_vertices, animal.n_edges, animal.n_faces)
    predicted = pentanb.predict_counts(counts, "pentagonalize", 2, 2)[-1]
    print(f"(A) {animal}, genus {animal.genus}")
    print(f"(B) {twice}, genus {twice.genus}")
    assert (twice.n_vertices, twice.n_edges, twice.n_faces) == predicted
    assert twice.face_size_histogram() == {5: twice.n_faces}
    assert twice.genus == animal.genus
    print("Only pentagons, the predicted counts, the same genus.")
    """),
    md("""
    ## Your own mesh

    `pentanb.read` reads `.obj` and `.off` files (any polygon faces; the mesh must be
    closed and manifold) and `pentanb.write` writes them. To show the round trip,
    the rabbit is written to a temporary folder and read back. Put the path of your
    own file in the text box (or in `path` below) and press *Load*.
    """),
    code("""
    import tempfile
    from pathlib import Path

    folder = Path(tempfile.mkdtemp())
    for suffix in (".obj", ".off"):
        pentanb.write(animal, folder / f"rabbit{suffix}")
        back = pentanb.read(folder / f"rabbit{suffix}")
        assert (back.vertices == animal.vertices).all()
        print(f"{suffix}: wrote and read back {back}")

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
    out = widgets.Output()
    loaded = {}


    @functools.lru_cache(maxsize=64)
    def subdivided(file, scheme, iterations, duals):
        return pentanb.subdivide(loaded[file], scheme, iterations, duals)


    def redraw(change=None):
        file = path_box.value
        with out:
            clear_output(wait=True)
            if file not in loaded:
                print("press Load to read", file)
                return
            mesh = loaded[file]
            iterations.max = max_iterations(mesh, scheme.value, duals.value)
            result = subdivided(file, scheme.value, iterations.value, duals.value)
            display(plot_mesh(result, title=f"{scheme.label} x{iterations.value}"))
            print(f"input:  {mesh}, genus {mesh.genus}")
            print(f"result: {result}")


    def read_file(button=None):
        file = path_box.value
        try:
            loaded[file] = pentanb.read(file)
        except (OSError, ValueError) as err:   # pentanb.MeshError is a ValueError
            with out:
                clear_output()
                print("could not read the file:", err)
            return
        redraw()


    load.on_click(read_file)
    for w in (scheme, iterations, duals):
        w.observe(redraw, names="value")
    display(widgets.VBox([widgets.HBox([path_box, load]),
                          widgets.HBox([scheme, iterations, duals]), out]))
    read_file()
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
}


def build(outdir: Path = HERE) -> list[Path]:
    """Write every notebook into ``outdir``; return their paths."""
    outdir = Path(outdir)
    paths = []
    for name, cells in NOTEBOOKS.items():
        nb = new_notebook(cells=[c.copy() for c in cells],
                          metadata={"kernelspec": KERNELSPEC,
                                    "language_info": {"name": "python"}})
        for i, cell in enumerate(nb.cells):
            cell["id"] = f"{name[:2]}-{i:02d}"
        nbformat.validate(nb)
        path = outdir / f"{name}.ipynb"
        nbformat.write(nb, path)
        paths.append(path)
    return paths


if __name__ == "__main__":
    for p in build(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(p)
