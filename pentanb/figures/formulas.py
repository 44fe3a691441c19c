"""Every scheme's Conway name and count formula, checked on a mixed mesh.

Not a figure of the paper: the report's ``schemes`` block.  Each scheme of
:data:`pentanb.SCHEMES` is applied once to a mesh with triangles, quads and
a pentagon (Figure 3's :func:`~pentanb.figures.fig03.capped_prism`) and its
V, E, F compared with the scheme's formula; the four Conway operators'
face structure is checked too.
"""

from __future__ import annotations

from ..mesh import Mesh
from ..schemes import SCHEMES
from ..schemes.classic import honeycomb, preserve_hexagons
from ..schemes.pentagonal import pentagonalize, preserve_pentagons
from .claim import Claim, add_counts, eq, vef
from .fig03 import capped_prism

__all__ = ["TITLE", "scheme_claims"]

TITLE = "Conway names and count formulas, checked on a mesh with triangles, quads and a pentagon"


def scheme_claims(mesh: Mesh | None = None) -> list[Claim]:
    """Every scheme's Conway name and count formula, checked on a mesh.

    Parameters
    ----------
    mesh : Mesh, optional
        Default: the capped pentagonal prism of Figure 3 (triangles, quads
        and a pentagon).

    Returns
    -------
    list of Claim
        One per scheme of :data:`pentanb.SCHEMES` (but ``triangulate``, whose
        formula is an upper bound), then the face structure of gyro, quinto,
        chamfer and zip.
    """
    mesh = capped_prism() if mesh is None else mesh
    out = []
    for name, s in SCHEMES.items():
        if name == "triangulate":
            continue  # its count formula is an upper bound
        after = s(mesh)
        conway = f" = Conway's {s.conway}" if s.conway else ""
        out.append(
            eq(
                f"{s.label}{conway}: (V, E, F) -> {s.formula}",
                s.counts(*vef(mesh)),
                vef(after),
            )
        )
    # the Conway operators' face structure
    gyro = pentagonalize(mesh)
    quinto = preserve_pentagons(mesh, 0.5)
    chamfer = preserve_hexagons(mesh)
    zp = honeycomb(mesh)
    hist = mesh.face_size_histogram()
    out += [
        eq(
            "gyro: every n-gon becomes n pentagons",
            {5: 2 * mesh.n_edges},
            gyro.face_size_histogram(),
        ),
        eq(
            "quinto (pentagon preservation, scale 0.5): n-gons kept, 2E pentagons added",
            add_counts(hist, {5: 2 * mesh.n_edges}),
            quinto.face_size_histogram(),
        ),
        eq(
            "chamfer (dual of Loop): faces kept, a hexagon per edge",
            add_counts(hist, {6: mesh.n_edges}),
            chamfer.face_size_histogram(),
        ),
        eq(
            "zip (dual of sqrt(3)): faces kept, a 2k-gon per k-valent vertex",
            add_counts(hist, {2 * k: c for k, c in mesh.valence_histogram().items()}),
            zp.face_size_histogram(),
        ),
    ]
    return out
