# mypy: disable-error-code="attr-defined, call-overload"
# (a base class of Mesh: its methods read the mesh's own attributes and properties)
"""What a :class:`~pentanb.Mesh`'s positions give: centroids, normals, volume, bounds.

These depend on the vertex positions (each mesh keeps its own, unlike the
connectivity, which meshes with the same faces share).  Sums that could
overflow or underflow are taken on positions scaled by a power of two.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .boundary import describe_boundary
from .cache import _geometry
from .coerce import FloatArray, MeshError, readonly
from .geometry import face_means, scaled_newell


class Positions:
    """The geometry of :class:`~pentanb.Mesh` (a base class: the mesh holds the arrays)."""

    __slots__ = ()
    _vertices: Any
    _corners: Any
    _offsets: Any
    _own: dict

    @_geometry
    def _extent(self) -> float:
        """The largest absolute coordinate (an upper bound, for operator outputs).

        Operators place new points by affine combinations with non-negative
        weights, which never move a point outside the box of its input, so
        an output inherits its input's extent (see :meth:`_note_extent`).
        Above :data:`SAFE_EXTENT` sums of coordinates could overflow, and
        the geometry is computed on positions scaled by a power of two
        (exact) instead.
        """
        v = self._vertices
        if v.size == 0:
            return 0.0
        return float(max(v.max(), -v.min()))

    def _note_extent(self, bound: float) -> None:
        """Record an upper bound of :attr:`_extent` known without a pass over the positions."""
        self._own.setdefault("_extent", float(bound))

    @_geometry
    def face_centroids(self) -> FloatArray:
        """(m, 3) float: the plain mean of each face's vertices."""
        means = face_means(
            self._vertices, self._corners, self._offsets, self._uniform_size, self._extent
        )
        return readonly(means)

    def face_means(self, values: ArrayLike) -> np.ndarray:
        """Average per-vertex values over every face.

        Parameters
        ----------
        values : (n,) or (n, d) float

        Returns
        -------
        (m,) or (m, d) float
            A new array (the caller's to keep).  Finite for any finite
            ``values``: sums that would overflow are taken on values scaled
            down by a power of two.

        Notes
        -----
        The corners are gathered in blocks of faces, so the memory beyond
        the result stays small whatever the mesh's size.
        """
        values = np.asarray(values, dtype=np.float64)
        flat = values.reshape(values.shape[0], -1)
        extent = float(np.abs(flat).max()) if flat.size else 0.0
        means = face_means(flat, self._corners, self._offsets, self._uniform_size, extent)
        return means.reshape((self.n_faces,) + values.shape[1:])

    @_geometry
    def face_normals(self) -> FloatArray:
        """(m, 3) float: unit normals (Newell's method; zero for degenerate faces).

        Faces whose cross products would overflow or underflow (coordinates
        near 1e-150 or 1e150 and beyond) are computed again from their
        corners relative to the first, scaled per face by a power of two,
        so their normals neither vanish nor become NaN.
        """
        p = self._vertices[self._corners]
        q = self._vertices[self.head]
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            cross = np.cross(p, q)
            n = np.add.reduceat(cross, self._offsets[:-1], axis=0)
            length = np.linalg.norm(n, axis=1, keepdims=True)
        # lengths outside [2**-800, 2**800] may have lost everything to
        # underflow or overflow: those faces again, rescaled
        redo = np.flatnonzero(~((length[:, 0] >= 2.0**-800) & (length[:, 0] <= 2.0**800)))
        if redo.size:
            n[redo] = scaled_newell(self._vertices, self._corners, self._offsets, redo)
            length = np.linalg.norm(n, axis=1, keepdims=True)
        return readonly(np.divide(n, length, out=np.zeros_like(n), where=length > 0))

    @property
    def volume(self) -> float:
        """Signed enclosed volume (positive for outward-oriented faces).

        Each face is fanned from its centroid; the tetrahedra to the origin
        are summed.  Coordinates beyond 2**300 (or below 2**-300) are
        scaled by a power of two first, so the result is ``inf`` (or 0)
        only when the volume itself is beyond float64's range.

        Closed meshes only: an open surface encloses nothing (the sum would
        depend on where the origin is).

        Raises
        ------
        MeshError
            For an open mesh, naming its boundary loops.
        """
        if not self.is_closed:
            raise MeshError(
                "volume needs a closed mesh; this one is open: "
                f"{describe_boundary(self._corners, self.head)}"
            )
        extent = self._extent
        if extent == 0 or 2.0**-300 < extent < 2.0**300:
            c = self.face_centroids[self.halfedge_face]
            p = self._vertices[self._corners]
            q = self._vertices[self.head]
            return float(np.einsum("ij,ij->", c, np.cross(p, q)) / 6.0)
        shift = int(np.frexp(extent)[1])
        small = self._rescaled(-shift)
        with np.errstate(over="ignore", under="ignore"):
            return float(np.ldexp(small.volume, 3 * shift))

    @property
    def bounds(self) -> FloatArray:
        """(2, 3) float: the lower and upper corners of the bounding box (read-only)."""
        return readonly(np.stack([self._vertices.min(axis=0), self._vertices.max(axis=0)]))
