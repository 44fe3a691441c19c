# mypy: disable-error-code="attr-defined, call-overload"
# (a base class of Mesh: its methods read the mesh's own attributes and properties)
"""A :class:`~pentanb.Mesh`'s pieces: its connected components, and its faces as fans.

Derived from the faces alone (shared by the meshes with these faces).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .cache import _connectivity
from .coerce import IntArray, readonly
from .halfedge import fan_triangle_corners


class Pieces:
    """Components and fan triangles of :class:`~pentanb.Mesh` (a base class)."""

    __slots__ = ()
    _corners: Any
    _offsets: Any

    def fan_triangles(self) -> tuple[IntArray, IntArray]:
        """Fan triangulation of every face from its first corner (for drawing).

        Returns
        -------
        triangles : (H - 2m, 3) int
            Vertex indices, counter-clockwise like their faces: triangle
            ``k`` of face ``f`` is its corners ``0, k + 1, k + 2``.
        triangle_face : (H - 2m,) int
            The face each triangle comes from.

        See Also
        --------
        fan_triangle_corners : the same triangles as corner indices.
        """
        return self._fan

    @_connectivity
    def _fan(self) -> tuple[IntArray, IntArray]:
        tri_corners, tri_face = fan_triangle_corners(self._offsets)
        return readonly(self._corners[tri_corners]), tri_face

    def component_labels_of_faces(self) -> IntArray:
        """The connected component of every face.

        Returns
        -------
        (m,) int
            The label (see :attr:`component_labels`) of every face, read-only.
        """
        return readonly(self.component_labels[self._corners[self._offsets[:-1]]])

    @_connectivity
    def component_labels(self) -> IntArray:
        """(n,) int: a component label (its smallest vertex index) per vertex.

        Shiloach-Vishkin style: hook the larger root of every edge whose ends
        disagree onto the smaller one, then jump pointers until every vertex
        points at its root; a few rounds on any mesh.
        """
        u, w = self.edges[:, 0], self.edges[:, 1]
        lab = np.arange(self.n_vertices, dtype=np.int64)
        while True:
            lu, lw = lab[u], lab[w]
            differ = lu != lw
            if not differ.any():
                return readonly(lab)
            lu, lw = lu[differ], lw[differ]
            np.minimum.at(lab, np.maximum(lu, lw), np.minimum(lu, lw))
            while True:
                jumped = lab[lab]
                if np.array_equal(jumped, lab):
                    break
                lab = jumped
