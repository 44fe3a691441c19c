"""Measures of meshes and studies beyond the paper.

* :mod:`~pentanb.analysis.measures`: measures that the figures, the
  convergence study and the notebooks share (vertex and face
  configurations, radius spread, crease angles, edge waviness); re-exported
  here, so ``from pentanb.analysis import vertex_configurations`` works.
* :mod:`~pentanb.analysis.convergence`: how fast dual smoothing converges
  (Section 7's "visually confirmed" G1 continuity, measured).

Everything here needs only numpy.  (Analyses that need scipy import it
inside the functions that use it, so that ``import pentanb.analysis``
stays numpy-only.)
"""

from __future__ import annotations

from .measures import (
    canonical_configuration,
    configuration_counts,
    edge_waviness,
    face_configurations,
    normal_angles,
    radius_spread,
    ray_distances,
    vertex_configurations,
)

__all__ = [
    "vertex_configurations",
    "face_configurations",
    "canonical_configuration",
    "configuration_counts",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
]
