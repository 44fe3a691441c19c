"""The polygon mesh: an immutable :class:`Mesh` of CSR faces, half-edges derived with numpy.

* :mod:`~pentanb.mesh.core`: the sealed :class:`Mesh` and its cached properties;
* :mod:`~pentanb.mesh.halfedge`: next, prev, head, twins, rotation and vertex rings;
* :mod:`~pentanb.mesh.validate`: the one validation, with messages naming the culprit;
* :mod:`~pentanb.mesh.coerce`: array coercions shared by the constructor, readers and schemes;
* :mod:`~pentanb.mesh.geometry`: face means and normals, exact and finite at any scale;
* :mod:`~pentanb.mesh.boundary`: the boundary of an open mesh: twins with hole
  half-edges, boundary loops, orientation, and their words for messages;
* :mod:`~pentanb.mesh.build`: how operators, readers and drawing code build meshes
  and read what a mesh has cached (code outside this package uses nothing else).
"""

from __future__ import annotations

from .coerce import FloatArray, IntArray, MeshError
from .core import Mesh, Rings, Several, check_closed, check_mesh
from .halfedge import fan_triangle_corners

__all__ = [
    "Mesh",
    "MeshError",
    "check_mesh",
    "check_closed",
    "fan_triangle_corners",
    "Rings",
    "Several",
    "IntArray",
    "FloatArray",
]
