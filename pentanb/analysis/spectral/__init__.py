"""Local subdivision matrices, their spectra and characteristic maps (Section 7's open question).

The paper closes (Section 7): "we have visually confirmed that the
algorithms converge with G1 continuity. However, there is still a need for
theoretical proofs for convergence."  Subdivision theory answers such
questions locally, around an *extraordinary element* -- a vertex of some
valence or a face of some size that survives every level:

1. Find the smallest neighbourhood N of the element that the scheme maps
   onto itself: the vertices of N at level l + p depend only on the
   vertices of N at level l, and N looks the same (same connectivity, same
   weights) at every level.  Its local subdivision matrix A is then one
   fixed matrix (:func:`local_spectrum`).
2. Sort A's eigenvalues by modulus, ``1 = lambda0 > |lambda1| >= |lambda2|
   >= ...``.  *Reif's standard setting* is ``|lambda1| = |lambda2| >
   |lambda3|`` (Reif 1995; Peters and Reif, *Subdivision Surfaces*, 2008,
   Ch. 5; Zorin 2000): the setting of the sufficient condition below, not
   a necessary condition for a tangent plane.  What is necessary, for
   generic control points, is a pair of leading eigenvectors whose planar
   map can be regular and injective -- in the standard setting, a double
   subdominant eigenvalue (real, or a complex pair).  A simple ``lambda1``
   gives no pair, and where its eigenvector has Fourier mode 0 no map built
   on it is injective and the limit normal turns around the element; three
   or more eigenvalues of the subdominant modulus leave rings that are not
   flat, so no tangent plane either
   (:attr:`LocalSpectrum.map_obstruction`).
3. The *characteristic map* is the limit of subdividing the planar control
   net whose coordinates are the two subdominant eigenvectors; it exists
   only when exactly two eigenvalues lead.  If it is regular (no fold) and
   injective (one sheet), the scheme is C1 at the element -- Reif's
   sufficient condition, stated for a real double subdominant eigenvalue
   (:func:`characteristic_map`).

How the neighbourhood is found.  The element is planted in a small closed
mesh (a pyramid over a ``size``-gon: its apex is a ``size``-valent vertex
and its base a ``size``-gon), which is subdivided level after level.  The
element is followed through every step by the rules themselves: a vertex
survives a remeshing when its row of the remeshing matrix is a unit row (it
stays where it is, as in all the paper's remeshings), a face when a new face
of the same size has the same centroid; a dual swaps the two.  Around the
element, the vertices are put in a canonical order by a breadth-first walk
that follows the faces counter-clockwise from a chosen starting half-edge;
two levels *match* when these walks see the same connectivity.  Candidate
neighbourhoods grow by half rings (edge neighbours, then whole faces); the
smallest one whose image depends only on itself, at a level where the next
two levels match and give the same matrix, is the stationary neighbourhood.

Rotation.  The starting half-edge at level l + p can be any of the
element's ``size`` half-edges; the choice turns the identification of the
two levels by whole sectors, which multiplies the eigenvalues of Fourier
mode w by ``exp(2 pi i a w / size)`` and leaves their moduli alone.  A
scheme that turns its neighbourhood by half a sector per step (pentagon
preservation at its faces, whose corners are scaled edge midpoints;
sqrt(3) and honeycomb) cannot be identified with itself over one step
without that half turn; it is analysed over the two steps that bring it
back (``period`` 2).  The half turn is read from the neighbourhood (a new
corner leans equally on two old ones), so the period does not depend on
which eigenvalue leads.  The turn taken out is the one that leaves the
fewest non-real eigenvalues over the whole spectrum, then the smallest
subdominant argument.  A *chiral* scheme (pentagonalization, whose
pentagons have no mirror symmetry) turns its neighbourhood by an angle
that no relabelling removes: its subdominant eigenvalues are a complex
pair, reported with their argument.

What is established and what is not.  The eigenvalues reported are
computed in floating point from the assembled matrix; the weights are
rational, and :func:`exact_ordering` establishes the ordering of the
leading ones in exact arithmetic (the characteristic polynomial, split by
Fourier modes; Schur-Cohn counts of roots in discs of rational radius;
Sturm counts of real roots; exact gcds).  The characteristic map is drawn
from its control net a few iterations down; the verdict on it (all faces
turn the same way, the boundary winds once) is numerical evidence, not a
proof of regularity or injectivity of the limit map.  Reif's criterion
also assumes a C1 surface away from the element (true for spline-based
schemes such as vertex insertion + 2 duals, which is bicubic on regular
regions) and a real double subdominant eigenvalue; where either is missing
the statement is left *undecided*.

Pentagon preservation's scale.  One remeshing step is affine in the
scale, so the local matrix is too (:func:`scale_family`);
:func:`scale_study` maps the standard setting along the scale for 2, 4 and
6 duals, each change established exactly, and recommends a scale.

The modules, in the order of the method:

* :mod:`~pentanb.analysis.spectral.neighbourhood`: the test mesh
  (:func:`pyramid`), one step with its matrices, the element followed through
  it (:func:`element_fate`), the canonical order around it;
* :mod:`~pentanb.analysis.spectral.local`: the search for a stationary
  neighbourhood and its local matrix (:func:`local_spectrum`,
  :class:`LocalSpectrum`);
* :mod:`~pentanb.analysis.spectral.eigen`: the eigenvalues by modulus and
  Fourier mode, the rotation and the half turn between levels;
* :mod:`~pentanb.analysis.spectral.contraction`: the measured contraction of
  the rings, independent of the matrices (:func:`ring_contraction`);
* :mod:`~pentanb.analysis.spectral.characteristic`: the characteristic map
  and its verdict (:func:`characteristic_map`);
* :mod:`~pentanb.analysis.spectral.exact`: the ordering of the leading
  eigenvalues in exact arithmetic (:func:`exact_ordering`);
* :mod:`~pentanb.analysis.spectral.scale`: pentagon preservation's scale
  (:func:`scale_family`, :func:`scale_study`);
* :mod:`~pentanb.analysis.spectral.table`: the results table
  (:func:`continuity_table`, :func:`table_markdown`).

Every public name is importable from here
(``from pentanb.analysis.spectral import local_spectrum``).
"""

from __future__ import annotations

from .characteristic import MAP_MAX_FACES as MAP_MAX_FACES
from .characteristic import CharacteristicMap, characteristic_map
from .contraction import extrapolate_ratio, ring_contraction
from .eigen import REAL_TOL as REAL_TOL
from .eigen import TOL as TOL
from .exact import ExactSpectrum, exact_local_matrix, exact_ordering
from .local import MAX_FACES as MAX_FACES
from .local import THRESHOLDS as THRESHOLDS
from .local import LocalSpectrum, local_spectrum
from .neighbourhood import KINDS, element_fate, pyramid
from .neighbourhood import MAX_DUALS as MAX_DUALS
from .scale import REFERENCE_SCALE as REFERENCE_SCALE
from .scale import (
    SCALE_GRID,
    SCALE_SCHEME,
    ScaleFamily,
    ScaleStudy,
    ScaleThreshold,
    scale_family,
    scale_map,
    scale_study,
    scale_threshold,
)
from .table import TABLE_CASES, ContinuityRow, continuity_table, table_markdown

__all__ = [
    "KINDS",
    "ExactSpectrum",
    "exact_local_matrix",
    "exact_ordering",
    "ScaleFamily",
    "ScaleThreshold",
    "scale_family",
    "scale_threshold",
    "scale_map",
    "ScaleStudy",
    "scale_study",
    "SCALE_SCHEME",
    "SCALE_GRID",
    "LocalSpectrum",
    "CharacteristicMap",
    "ContinuityRow",
    "local_spectrum",
    "characteristic_map",
    "ring_contraction",
    "extrapolate_ratio",
    "element_fate",
    "pyramid",
    "continuity_table",
    "table_markdown",
    "TABLE_CASES",
]
