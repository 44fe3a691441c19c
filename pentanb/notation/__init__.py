"""Conway polyhedron notation: strings such as ``"gC"`` or ``"ddgT"``.

A string is read right to left, as in the literature (Hart, "Conway
notation for polyhedra"; polyHedronisme; Antiprism's ``conway``): the
rightmost letter is a *seed*, every letter to its left an *operator*
applied to what stands to its right.  ``"dgT"`` is the dual of the
pentagonalized (gyro) tetrahedron, Figure 7(C) of the paper; ``"ddgT"``
is Figure 7(D).

Seeds: ``T C O I D`` (the Platonic solids of :mod:`pentanb.shapes`),
``Pn An Yn`` (prism, antiprism, pyramid on an n-gon, n >= 3), or any
:class:`~pentanb.Mesh` passed as ``seed`` (the string then holds operators
only).

Operators (:data:`OPERATORS`, one table: letter, name, function, count
formula, literature):

* the paper's and its comparison schemes, called as they are:
  ``g`` = :func:`~pentanb.pentagonalize` (gyro), ``q`` =
  :func:`~pentanb.preserve_pentagons` (quinto, scale 0.5), ``e`` =
  :func:`~pentanb.corner_cutting` (expand), ``o`` =
  :func:`~pentanb.vertex_insertion` (ortho), ``c`` =
  :func:`~pentanb.preserve_hexagons` (chamfer), ``z`` =
  :func:`~pentanb.honeycomb` (zip), ``u`` = :func:`~pentanb.loop_remesh`
  (subdivide), ``n`` = :func:`~pentanb.sqrt3_remesh` (needle), ``d`` =
  :func:`~pentanb.dual`;
* the others from :mod:`pentanb.notation.operators`: ``a t k j s p w m b r``
  (ambo, truncate, kis, join, snub, propeller, whirl, meta, bevel,
  reflect); ``kN`` raises pyramids on N-sided faces only, ``tN`` cuts
  N-valent vertices only (Hart).

Positions follow the package's conventions (edge midpoints and thirds, face
centroids, old vertices kept), so the dual is the paper's smoothing and
``"ddgT"`` is *not* ``"gT"``.  ``canonical=True`` puts the result in
canonical form (:func:`canonical`), which depends only on
the topology; there the rewrite table :data:`REDUCTIONS` (``dd`` -> nothing,
``ad`` -> ``a``, ``dk`` -> ``z``, ..., polyHedronisme's and Hart's
substitutions) is applied before any work, because it then changes nothing
but the time.

The package, each module importing only those above it (and
:mod:`pentanb.mesh`, :mod:`pentanb.shapes`, :mod:`pentanb.schemes`; never
:mod:`pentanb.analysis`):

* :mod:`~pentanb.notation.operators`: the operator functions and
  :data:`OPERATORS`, every letter with its count formula;
* :mod:`~pentanb.notation.seeds`: :data:`SEEDS`, :func:`prism`,
  :func:`antiprism`, :func:`pyramid`;
* :mod:`~pentanb.notation.grammar`: :func:`parse`, :data:`REDUCTIONS`,
  :func:`reduce_notation`, :class:`NotationError`;
* :mod:`~pentanb.notation.positions`: :func:`canonical`, :func:`planarize`
  (canonical and planar positions, also ``pentanb.canonical`` and
  ``pentanb.planarize``);
* :mod:`~pentanb.notation.build`: :func:`conway`, :func:`resolve` (an
  operator string as a :class:`~pentanb.Scheme`) and :func:`as_scheme`
  (a scheme name or an operator string).
"""

from __future__ import annotations

from .build import MAX_FACES, as_scheme, conway, resolve
from .grammar import (
    REDUCTIONS,
    SEED_REDUCTIONS,
    Notation,
    NotationError,
    Token,
    parse,
    reduce_notation,
)
from .operators import (
    OPERATORS,
    Invariants,
    Operator,
    ambo,
    bevel,
    join,
    kis,
    meta,
    propeller,
    reflect,
    snub,
    truncate,
    whirl,
)
from .positions import ConvergenceError, PlacementReport, canonical, planarize
from .seeds import SEEDS, Seed, antiprism, prism, pyramid

__all__ = [
    "conway",
    "resolve",
    "as_scheme",
    "parse",
    "Notation",
    "Token",
    "reduce_notation",
    "NotationError",
    "Operator",
    "Invariants",
    "Seed",
    "OPERATORS",
    "SEEDS",
    "REDUCTIONS",
    "SEED_REDUCTIONS",
    "MAX_FACES",
    "prism",
    "antiprism",
    "pyramid",
    "ambo",
    "truncate",
    "kis",
    "join",
    "snub",
    "propeller",
    "whirl",
    "meta",
    "bevel",
    "reflect",
    "canonical",
    "planarize",
    "ConvergenceError",
    "PlacementReport",
]
