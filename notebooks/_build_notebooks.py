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
    import matplotlib.pyplot as plt
    from IPython.display import clear_output, display

    import pentanb
    from _interim import draw_mesh, grid, plot_mesh
""")

#: Building a mesh is cached so that a slider revisiting a position is instant,
#: and every slider range is capped so that no position builds more than
#: MAX_FACES faces.
CACHE = code("""
    MAX_FACES = 100_000   # no slider position builds a bigger mesh


    @functools.lru_cache(maxsize=128)
    def build(shape, scheme, iterations, duals, scale=None):
        \"\"\"pentanb.subdivide on a named shape, cached on all its arguments.\"\"\"
        options = {} if scale is None else {"scale": scale}
        return pentanb.subdivide(pentanb.shapes.get(shape), scheme, iterations, duals,
                                 **options)


    def max_iterations(mesh, scheme, duals=2, limit=MAX_FACES, cap=6):
        \"\"\"Largest iteration count whose meshes all stay under `limit` faces.\"\"\"
        counts = (mesh.n_vertices, mesh.n_edges, mesh.n_faces)
        best = 0
        for k in range(1, cap + 1):
            steps = pentanb.predict_counts(counts, scheme, k, duals)
            if max(F for _, _, F in steps) > limit:
                break
            best = k
        return best
""")


# ---------------------------------------------------------------------------
# 01 Topology
# ---------------------------------------------------------------------------

NB01 = [
    md("""
    # Which n-gonal meshes can exist? (Section 4, equation 1)

    Section 4 of the paper counts. A closed mesh of genus $g$ with $v$ vertices,
    $e$ edges and $f$ faces satisfies Euler's formula $v - e + f = 2 - 2g$. If every
    face has $n$ sides then $2e = nf$; if the vertices have average valence $m$ then
    $2e = mv$. Eliminating $e$ and $f$ gives equation (1):

    $$m = \\frac{2n}{n-2}\\left(1 + \\frac{2g-2}{v}\\right).$$

    A subdivision scheme keeps adding vertices, so it needs $m \\ge 3$ for large $v$
    (otherwise it piles up 1- and 2-valent vertices). The paper concludes:

    > "$\\frac{2n}{n-2}$ is a monotone decreasing function that becomes smaller than 3
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
    SETUP,
    code("""
    from pentanb import topology
    """),
    md("""
    ## Equation (1)

    Average valence $m$ against the number of vertices $v$ for triangles, quads,
    pentagons and hexagons on a sphere ($g = 0$). Points below the line $m = 3$
    cannot be meshes without 1- or 2-valent vertices.
    """),
    code("""
    import numpy as np

    v = np.linspace(2, 80, 400)
    fig, ax = plt.subplots(figsize=(6, 4))
    for n in (3, 4, 5, 6):
        ax.plot(v, topology.average_valence(n, 0, v), label=f"n = {n}")
    ax.axhline(3, color="k", lw=0.8, ls="--")
    ax.set(xlabel="v", ylabel="m", ylim=(0, 7), title="Equation (1), g = 0")
    ax.legend()
    plt.show()
    """),
    md("""
    ## The paper's chart

    As $v \\to \\infty$, $m \\to 2n/(n-2)$: the value for $g = 1$, the tessellations of
    the plane. "(5, 10/3) can only have semi-regular tesselations": pentagons cannot
    all meet at vertices of one valence in the limit.
    """),
    code("""
    print(f"{'(n, m)':>16}  regular?  type")
    for row in topology.schlafli_chart():
        pair = f"({float(row.n):.2f}, {float(row.m):.2f})"
        print(f"{pair:>16}  {'yes' if row.admits_regular else 'no ':>8}  {row.description}")
    """),
    md("""
    ## The claims, checked

    For each $n$: the limit valence $2n/(n-2)$, the fewest vertices of an $n$-gon
    sphere and torus with $m \\ge 3$, and whether a conversion ("$n$-gonalization")
    or a preservation scheme can exist.
    """),
    code("""
    print(" n  2n/(n-2)  min v (g=0)  min v (g=1)  conversion  preservation")
    for n in range(3, 9):
        print(f"{n:2d}  {str(topology.limit_valence(n)):>8}  "
              f"{str(topology.min_vertices(n, 0)):>11}  {str(topology.min_vertices(n, 1)):>11}  "
              f"{str(topology.ngonalization_exists(n)):>10}  "
              f"{str(topology.ngon_preservation_exists(n)):>12}")

    assert topology.min_vertices(5, 0) == 20   # the dodecahedron
    assert topology.min_vertices(4, 0) == 8    # the cube
    assert topology.min_vertices(3, 0) == 4    # the tetrahedron
    assert topology.min_vertices(6, 0) is None # no hexagonal sphere
    assert topology.ngonalization_exists(5) and not topology.ngonalization_exists(6)
    assert topology.ngon_preservation_exists(6) and not topology.ngon_preservation_exists(7)
    print("Section 4's claims hold.")
    """),
    md("""
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
    md("""
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


NOTEBOOKS = {
    "01_topology": NB01,
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
