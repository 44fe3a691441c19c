"""Measures of meshes and studies beyond the paper.

* :mod:`~pentanb.analysis.convergence`: how fast dual smoothing converges.
"""
