"""Beyond the paper: the boundary curve of an open mesh under the paper's two schemes.

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity. However, there is still a need for theoretical proofs for
convergence."  The paper's meshes are closed.  On an open mesh the new
boundary points of either scheme with two duals depend on the old boundary
points only, so the boundary polygon is refined by a curve subdivision
scheme of its own (:func:`pentanb.analysis.boundary_spectrum`):
pentagonalization's is the ternary scheme of mask
``(1, 4, 8, 10, 8, 4, 1) / 12``, pentagon preservation's the cubic B-spline's
``(1, 4, 6, 4, 1) / 8``.  This report block (``boundary``) holds one
observation: the two rules, the eigenvalues of their local matrices beside
the interior's at 3- and 4-valent vertices, and whether the boundary curve
is C1.  No verdict on the paper, which does not speak of boundaries.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..analysis.boundary import BoundaryRow, boundary_table
from .claim import Claim, observed

TITLE = "The boundary curve of open meshes (beyond the paper)"

#: The paper's two schemes, each with two duals.
SCHEMES = ("pentagonalize", "preserve_pentagons")

CONVERGE = (
    "we have visually confirmed that the algorithms converge with G1 continuity. However, "
    "there is still a need for theoretical proofs for convergence."
)


def _measured(rows: Sequence[BoundaryRow]) -> str:
    parts = []
    for row in rows:
        b = row.boundary
        inner = "; ".join(f"{k}: |lambda1| {v[1]:.4f}" for k, v in row.interior.items())
        if b.mask:
            parts.append(
                f"{b.scheme} + {b.duals} duals: arity {b.arity}, mask {b.mask_text}, "
                f"eigenvalues {b.eigenvalue_text} ({'C1' if b.is_c1 else 'not C1'}; "
                f"interior {inner})"
            )
        else:
            parts.append(f"{b.scheme} + {b.duals} duals: {b.reason}")
    return "; ".join(parts)


def boundary_claims(rows: Sequence[BoundaryRow] | None = None) -> list[Claim]:
    """The observation on the boundary curve of open meshes.

    Parameters
    ----------
    rows : sequence of BoundaryRow, optional
        :func:`pentanb.analysis.boundary_table` of the paper's two schemes
        with two duals (computed here by default, about 3 s); the tests pass
        other rows (no duals: a polygon, not C1).

    Returns
    -------
    list of Claim
        One observation, ``boundary.curve``: seen when the boundary of every
        scheme decouples, is refined by a uniform rule, and is C1
        (:attr:`pentanb.analysis.BoundarySpectrum.is_c1`).
    """
    rows = boundary_table(SCHEMES, 2) if rows is None else rows
    seen = bool(rows) and all(r.boundary.decoupled and r.boundary.is_c1 for r in rows)
    return [
        observed(
            "boundary.curve",
            "Section 7",
            CONVERGE,
            _measured(rows),
            "on an open mesh the boundary of both schemes with two duals is refined by a "
            "curve scheme of its own (its new points lean on the old boundary points only), "
            "and that curve is C1: 1 simple, a single real subdominant eigenvalue above the "
            "rest, a monotone characteristic eigenvector, a contracting difference scheme",
            seen,
            True,
            cause="the boundary rules are B-spline-like curve schemes",
        )
    ]
