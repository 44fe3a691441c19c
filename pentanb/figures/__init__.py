"""Every figure of the paper, one module each, with the claims it makes.

``figure1()`` ... ``figure13()`` redraw the paper's Figures 1-13,
:func:`equation1` draws Section 4 (equation (1) and the ``(n, m)`` chart),
:func:`lateral_figure` measures Section 1's "lateral artifact" along the
straight edges of boxes, :func:`convergence_figure` what the paper only
"visually confirmed" (convergence under duals), and :func:`spectra_figure`
and :func:`characteristic_maps_figure` answer Section 7's open question
with subdivision theory (eigenvalues of the local subdivision matrices and
characteristic maps, :mod:`pentanb.analysis.spectral`).  Each returns a
:class:`matplotlib.figure.Figure` whose panels are labelled ``(A)``,
``(B)``, ... as in the paper.

:func:`panels` gives the meshes a figure draws (``panels(11)["A"]``), so
they can be taken into one's own code; :func:`claims` what the paper says
of them next to what we measure, with a verdict (:class:`Claim`: holds,
holds within a stated tolerance, or does not hold as stated).  :data:`FIGURES` lists
every image with its caption (:class:`FigureSpec`); ``python -m pentanb
figures`` draws them all into ``figures/`` (:func:`render_all`) and prints
the claims (:func:`check_all`, :func:`report`).

Layout: :mod:`~pentanb.figures.claim` (the claim framework),
:mod:`~pentanb.figures.registry` (the table and the functions above), one
module per figure (:mod:`~pentanb.figures.fig01` ... ``fig13``,
:mod:`~pentanb.figures.section4` for equation (1),
:mod:`~pentanb.figures.lateral`, :mod:`~pentanb.figures.convergence`,
:mod:`~pentanb.figures.spectra`, :mod:`~pentanb.figures.characteristic_maps`)
holding its ``panels()``, ``draw()``
and ``claims()``, and :mod:`~pentanb.figures.formulas` (the schemes' count
formulas).  A figure's meshes are built once per :func:`render` or
:func:`claims` call and passed to the drawing or the claims; no mesh is
cached between calls.  The one thing kept is the continuity table that
``spectra`` and ``characteristic_maps`` share (``_continuity.table()``,
computed once per process: a figures run computes it once).

Building meshes and checking claims need only numpy (the continuity
table's analysis imports scipy where it needs it); matplotlib is imported
when a figure is drawn.
"""

from __future__ import annotations

# the measures moved to pentanb.analysis; these names stay here for old code
from ..analysis.measures import canonical_configuration as canonical_configuration
from ..analysis.measures import configuration_counts as configuration_counts
from ..analysis.measures import face_configurations as face_configurations
from ..analysis.measures import vertex_configurations as vertex_configurations
from .characteristic_maps import draw as characteristic_maps_figure
from .claim import FAILS, HOLDS, VERDICTS, WITHIN, Claim
from .convergence import draw as convergence_figure
from .fig01 import draw as figure1
from .fig02 import draw as figure2
from .fig03 import draw as figure3
from .fig04 import draw as figure4
from .fig05 import draw as figure5
from .fig06 import draw as figure6
from .fig07 import draw as figure7
from .fig08 import draw as figure8
from .fig09 import draw as figure9
from .fig10 import draw as figure10
from .fig11 import draw as figure11
from .fig12 import draw as figure12
from .fig13 import draw as figure13
from .formulas import scheme_claims
from .lateral import draw as lateral_figure
from .registry import (
    FIGURES,
    FigureSpec,
    check_all,
    claims,
    get,
    panels,
    render,
    render_all,
    report,
)
from .section4 import draw as equation1
from .spectra import draw as spectra_figure

__all__ = [
    "Claim",
    "HOLDS",
    "WITHIN",
    "FAILS",
    "VERDICTS",
    "FigureSpec",
    "FIGURES",
    "get",
    "panels",
    "claims",
    "render",
    "render_all",
    "report",
    "check_all",
    "scheme_claims",
    "figure1",
    "figure2",
    "figure3",
    "figure4",
    "figure5",
    "figure6",
    "figure7",
    "figure8",
    "figure9",
    "figure10",
    "figure11",
    "figure12",
    "figure13",
    "equation1",
    "lateral_figure",
    "convergence_figure",
    "spectra_figure",
    "characteristic_maps_figure",
]
