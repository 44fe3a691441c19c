"""Section 4 of the paper, "Topological Constraints", as code.

A closed 2-manifold mesh of genus ``g`` with ``v`` vertices, ``e`` edges and
``f`` faces satisfies Euler's formula ``v - e + f = 2 - 2g``.  If every face
has ``n`` sides then ``2e = n f``, and if the vertices have average valence
``m`` then ``2e = m v``.  Eliminating ``e`` and ``f`` gives the paper's
equation (1),

.. math::  m = \\frac{2n}{n - 2} \\left(1 + \\frac{2g - 2}{v}\\right),

and everything in this module follows from it:

* :func:`average_valence` is equation (1); :func:`limit_valence` is its limit
  ``2n / (n - 2)`` as ``v -> inf``, which is also its value for ``g = 1``
  (planar tessellations mapped to a torus).
* :func:`ngon_mesh_counts` solves Euler's formula for ``(v, e, f)``.
* :func:`vertex_range`, :func:`min_vertices` and :func:`can_tile` say for
  which ``v`` an ``n``-gon mesh of genus ``g`` can avoid 1- and 2-valent
  vertices *on average* (``m >= 3``), the paper's existence criterion.
* :func:`ngonalization_exists` and :func:`ngon_preservation_exists` are the
  paper's conclusions: pentagonalization exists, hexagonalization does not
  (``g = 0`` fails), hexagon preservation does (for ``g >= 1``), and nothing
  exists for ``n > 6``.
* :func:`limit_valence_is_integer` is the claim that pentagonal meshes have
  a non-integer average valence (10/3) in the limit, unlike triangle (6) and
  quad (4) meshes.
* :data:`SCHLAFLI_CHART` is the paper's chart of ``(n, m)`` pairs.
* :func:`average_face_size`, :func:`limit_face_size`,
  :func:`mvalent_mesh_counts`, :func:`face_range` and :func:`min_faces` are
  the dual statements ("the same analysis can be repeated just by replacing
  ``v`` with ``f``"): meshes whose vertices all have valence ``m``.

Surfaces with boundary (the paper's Section 4 is about closed ones):

* :func:`euler_characteristic` is ``2 - 2g - b`` for ``b`` boundary loops;
* :func:`average_valence_with_boundary` is equation (1) with boundary terms,
  every vertex's valence counted honestly as its number of edges (a
  boundary vertex has one more edge than faces);
* :func:`ngon_mesh_counts_with_boundary`,
  :func:`vertex_range_with_boundary`, :func:`can_tile_with_boundary`,
  :func:`min_boundary_edges` and :func:`ngonalization_exists_with_boundary`
  say which ``(n, m, g, b)`` admit meshes of ``n``-gons only: every ``n``
  for every ``g`` and ``b >= 1`` with few enough interior vertices, but
  refinement (interior vertices growing faster than the boundary) only for
  ``n <= 6``; hexagons then need ``e_b >= 6 (2 - 2g - b)`` boundary edges,
  so unlike the sphere a disk can be hexagonal.

All criteria are *count-wise*: they are necessary conditions derived from
the numbers ``v, e, f`` alone, exactly as in the paper.  ``m >= 3`` on
average does not by itself guarantee that *every* vertex has valence 3 or
more, and valid counts do not by themselves guarantee that a mesh with those
counts exists.

This module needs only numpy.

The modules: :mod:`~pentanb.topology.closed` (closed surfaces, the paper's
Section 4) and :mod:`~pentanb.topology.boundary` (surfaces with boundary).
Every name is importable from here (``from pentanb.topology import
can_tile``).
"""

from __future__ import annotations

from .boundary import (
    average_valence_with_boundary,
    can_tile_with_boundary,
    euler_characteristic,
    min_boundary_edges,
    ngon_mesh_counts_with_boundary,
    ngonalization_exists_with_boundary,
    vertex_range_with_boundary,
)
from .closed import (
    SCHLAFLI_CHART,
    SchlafliRow,
    average_face_size,
    average_valence,
    can_tile,
    face_range,
    limit_face_size,
    limit_valence,
    limit_valence_is_integer,
    min_faces,
    min_vertices,
    mvalent_mesh_counts,
    ngon_mesh_counts,
    ngon_preservation_exists,
    ngonalization_exists,
    schlafli_chart,
    vertex_range,
)
from .closed import FloatArray as FloatArray
from .closed import Range as Range

__all__ = [
    "average_valence",
    "limit_valence",
    "limit_valence_is_integer",
    "ngon_mesh_counts",
    "vertex_range",
    "min_vertices",
    "can_tile",
    "ngonalization_exists",
    "ngon_preservation_exists",
    "SchlafliRow",
    "SCHLAFLI_CHART",
    "schlafli_chart",
    "average_face_size",
    "limit_face_size",
    "mvalent_mesh_counts",
    "face_range",
    "min_faces",
    "euler_characteristic",
    "average_valence_with_boundary",
    "ngon_mesh_counts_with_boundary",
    "vertex_range_with_boundary",
    "can_tile_with_boundary",
    "min_boundary_edges",
    "ngonalization_exists_with_boundary",
]
