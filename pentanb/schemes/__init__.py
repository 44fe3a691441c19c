"""The remeshing operators, the dual that smooths them, and their registry.

* :mod:`~pentanb.schemes.pentagonal`: the paper's two schemes (Section 5),
  pentagonalization and pentagon preservation;
* :mod:`~pentanb.schemes.classic`: the schemes the paper compares them with
  (Sections 3 and 6);
* :mod:`~pentanb.schemes.smoothing`: the dual and ``smooth`` (the paper's
  smoothing);
* :mod:`~pentanb.schemes.registry`: :data:`SCHEMES`, one table naming them all;
* :mod:`~pentanb.schemes.table`, :mod:`~pentanb.schemes.engine`: a scheme as
  data (:class:`Table`) and the one engine that evaluates every table
  (:mod:`~pentanb.schemes.probe` checks a table and derives its twins' and
  rings' formulas; :mod:`~pentanb.schemes.refs` names its points).

Every operator is a pure function ``Mesh -> Mesh``, on closed and open
meshes alike (:func:`boundary_corners` names the boundary vertices the dual
keeps; :mod:`~pentanb.schemes.smoothing` gives the rule).
"""

from __future__ import annotations

from ._build import CORNER_ANGLE, boundary_corners
from .classic import (
    corner_cutting,
    honeycomb,
    loop_remesh,
    preserve_hexagons,
    sqrt3_remesh,
    triangulate,
    vertex_insertion,
)
from .pentagonal import pentagonalize, preserve_pentagons
from .registry import SCHEMES, Scheme, from_table, get_scheme
from .smoothing import dual, smooth
from .table import Table

__all__ = [
    "pentagonalize",
    "preserve_pentagons",
    "triangulate",
    "loop_remesh",
    "sqrt3_remesh",
    "vertex_insertion",
    "corner_cutting",
    "preserve_hexagons",
    "honeycomb",
    "dual",
    "smooth",
    "SCHEMES",
    "Scheme",
    "get_scheme",
    "from_table",
    "Table",
    "boundary_corners",
    "CORNER_ANGLE",
]
