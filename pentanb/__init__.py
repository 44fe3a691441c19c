"""pentanb: the paper "Semiregular pentagonal subdivisions" as a Python package.

Akleman, Srinivasan, Melek and Edmundson show that any closed 2-manifold can
be meshed with pentagons only, give a scheme that turns any mesh into
pentagons (:func:`pentagonalize`) and one that keeps a pentagonal mesh
pentagonal (:func:`preserve_pentagons`), and smooth with the dual
(:func:`dual`, :func:`smooth`).  This package rebuilds those schemes, the
ones the paper compares them with, Section 4's topology, and every figure.

``import pentanb`` needs only numpy; matplotlib, ipywidgets and pythreejs
load when a drawing function is first called.
"""

from __future__ import annotations

from . import shapes, topology
from ._jit import use_jit
from .io import read, write
from .mesh import Mesh, MeshError
from .notation import ConvergenceError, canonical, conway, planarize
from .schemes import (
    SCHEMES,
    Scheme,
    Table,
    corner_cutting,
    dual,
    honeycomb,
    loop_remesh,
    pentagonalize,
    preserve_hexagons,
    preserve_pentagons,
    smooth,
    sqrt3_remesh,
    triangulate,
    vertex_insertion,
)
from .subdivision import max_iterations, predict_counts, subdivide

__version__ = "0.1.0"

__all__ = [
    "Mesh",
    "MeshError",
    "dual",
    "smooth",
    "pentagonalize",
    "preserve_pentagons",
    "triangulate",
    "loop_remesh",
    "sqrt3_remesh",
    "vertex_insertion",
    "corner_cutting",
    "preserve_hexagons",
    "honeycomb",
    "subdivide",
    "SCHEMES",
    "Scheme",
    "Table",
    "predict_counts",
    "max_iterations",
    "read",
    "write",
    "shapes",
    "topology",
    "view",
    "explore",
    "step_through",
    "export_html",
    "figures",
    "analysis",
    "conway",
    "canonical",
    "planarize",
    "ConvergenceError",
    "use_jit",
]

# drawing functions: imported on first use, so that `import pentanb` needs numpy only
_LAZY = {
    "view": ("pentanb.viz.three", "view"),
    "explore": ("pentanb.viz.explorer", "explore"),
    "step_through": ("pentanb.viz.steps", "step_through"),
    "export_html": ("pentanb.viz.html", "export_html"),
}


def __getattr__(name):
    if name in _LAZY:
        import importlib

        module, attr = _LAZY[name]
        return getattr(importlib.import_module(module), attr)
    if name in ("figures", "analysis"):
        import importlib

        return importlib.import_module(f"pentanb.{name}")
    raise AttributeError(f"module 'pentanb' has no attribute {name!r}")
