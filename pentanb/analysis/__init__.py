"""Measures of meshes and studies beyond the paper.

* :mod:`~pentanb.analysis.measures`: measures that the figures, the
  convergence study and the notebooks share (vertex and face
  configurations, radius spread, crease angles, edge waviness, spreads,
  planarity); re-exported
  here, so ``from pentanb.analysis import vertex_configurations`` works.
* :mod:`~pentanb.analysis.convergence`: how fast dual smoothing converges
  (Section 7's "visually confirmed" G1 continuity, measured).
* :mod:`~pentanb.analysis.subdivision_matrix`: one step of "remesh, then k
  duals" as a sparse linear map of positions, ``S @ V``.
* :mod:`~pentanb.analysis.boundary`: the boundary curve of an open mesh:
  its own subdivision rule (mask), the spectrum of its local matrix, C1 or
  not.
* :mod:`~pentanb.analysis.limit`: the limit surface at the control vertices
  (positions and normals from the left eigenvectors of the local matrices,
  checked against actual subdivision) and curvature measures per element.
* :mod:`~pentanb.analysis.spectral`: Section 7's open question answered with
  subdivision theory: local subdivision matrices around extraordinary
  vertices and faces, their spectra, characteristic maps, the results table.

Everything here needs only numpy.  (Analyses that need scipy import it
inside the functions that use it, so that ``import pentanb.analysis``
stays numpy-only.)
"""

from __future__ import annotations

from . import measures
from .boundary import (
    BoundaryRow,
    BoundarySpectrum,
    boundary_markdown,
    boundary_spectrum,
    boundary_table,
    boundary_test_mesh,
)
from .limit import (
    CurvatureMeasure,
    LimitConvergence,
    LimitStencil,
    curvature_markdown,
    curvature_measures,
    curvature_table,
    limit_convergence,
    limit_normals,
    limit_points,
    limit_stencil,
)
from .measures import *  # noqa: F403  (the names of measures.__all__)
from .spectral import (
    CharacteristicMap,
    ContinuityRow,
    LocalSpectrum,
    characteristic_map,
    continuity_table,
    local_spectrum,
    ring_contraction,
    table_markdown,
)
from .subdivision_matrix import subdivision_matrix

__all__ = [
    "subdivision_matrix",
    "local_spectrum",
    "LocalSpectrum",
    "characteristic_map",
    "CharacteristicMap",
    "continuity_table",
    "ContinuityRow",
    "table_markdown",
    "ring_contraction",
    "boundary_spectrum",
    "BoundarySpectrum",
    "boundary_table",
    "BoundaryRow",
    "boundary_markdown",
    "boundary_test_mesh",
    "limit_points",
    "limit_normals",
    "limit_stencil",
    "LimitStencil",
    "limit_convergence",
    "LimitConvergence",
    "curvature_measures",
    "CurvatureMeasure",
    "curvature_table",
    "curvature_markdown",
    *(name for name in measures.__all__ if name != "BOX_EDGES"),
]
