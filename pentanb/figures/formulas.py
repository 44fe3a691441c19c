"""Every scheme's counts and the kind of mesh it makes, checked on a mixed mesh.

Not a figure of the paper: the report's ``schemes`` block.  Each scheme of
:data:`pentanb.SCHEMES` (but the simplest triangulation, whose counts
depend on how many faces are triangles already) is applied once to a mesh
with triangles, quads and a pentagon (Figure 3's
:func:`~pentanb.figures.fig03.capped_prism`) and its V, E, F compared with
the counts its construction gives, next to what the paper says it makes
(only triangles, only quadrilaterals, only 4-valent vertices, ...).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from ..mesh import Mesh
from ..schemes import SCHEMES
from .claim import Claim, exact, vef
from .fig03 import capped_prism

__all__ = ["TITLE", "scheme_claims", "PAPER"]

TITLE = (
    "Every scheme's counts and kind of mesh, checked on a mesh with triangles, quads and a pentagon"
)


def _sizes(m: Mesh) -> list[int]:
    return sorted(m.face_size_histogram())


def _valences(m: Mesh) -> list[int]:
    return sorted(m.valence_histogram())


#: Per scheme: (section, the paper's words, what is measured, the measure, the
#: value the words imply).  ``None`` as the value: the input's face sizes are
#: kept, and the scheme's own added (pentagons, triangles or hexagons).
PAPER: dict[str, tuple[str, str, str, Callable[[Mesh], object], object]] = {
    "pentagonalize": (
        "Section 5.1",
        "So we will have only pentagons in the new mesh.",
        "face sizes",
        _sizes,
        [5],
    ),
    "preserve_pentagons": (
        "Section 5.2",
        "Each face in the original mesh would now have been split into as many pentagons as "
        "the number of edges (or vertices) in the original face plus one central face with "
        "the same number of sides as the original face.",
        "face sizes",
        _sizes,
        None,
    ),
    "loop_remesh": (
        "Section 3",
        "a central face in the middle of each original face and triangles in each corner",
        "face sizes",
        _sizes,
        None,
    ),
    "sqrt3_remesh": (
        "Section 3",
        "The remeshing scheme of sqrt(3) subdivision [10] is a triangulization algorithm.",
        "face sizes",
        _sizes,
        [3],
    ),
    "vertex_insertion": (
        "Section 3",
        "the remeshing scheme of Catmull-Clark subdivision [7], which is also called the "
        "vertex insertion, is a quadrilateralization scheme",
        "face sizes",
        _sizes,
        [4],
    ),
    "corner_cutting": (
        "Section 3",
        "the dual of vertex insertion, corner cutting [9, 3], is a 4-valent conversion "
        "scheme. After one application of corner cutting the valence of all the vertices "
        "become 4.",
        "valences",
        _valences,
        [4],
    ),
    "preserve_hexagons": (
        "Section 3",
        "An hexagonal preservation scheme, which is the dual of Loop subdivision",
        "face sizes",
        _sizes,
        None,
    ),
    "honeycomb": (
        "Section 3",
        "the dual of sqrt(3) [...] is a 3-valent conversion scheme that converts any "
        "manifold mesh to a mesh with only 3-valent vertices",
        "valences",
        _valences,
        [3],
    ),
}


#: The causes the schemes' claims share with the figures' (the others: their own key).
CAUSES = {
    "pentagonalize": "pentagonalization's combinatorics",
    "preserve_pentagons": "pentagon preservation's combinatorics",
    "loop_remesh": "Loop's remeshing",
    "preserve_hexagons": "hexagon preservation",
}


def scheme_claims(
    mesh: Mesh | None = None, outputs: Mapping[str, Mesh] | None = None
) -> list[Claim]:
    """Every scheme's counts and kind of mesh, checked on a mesh.

    Parameters
    ----------
    mesh : Mesh, optional
        Default: the capped pentagonal prism of Figure 3 (triangles, quads
        and a pentagon).
    outputs : dict, optional
        ``{scheme name: Mesh}`` to use instead of applying the scheme (a
        wrong output, for the tests).

    Returns
    -------
    list of Claim
        One per scheme of :data:`PAPER`: ``(V, E, F)`` against the counts its
        construction gives (:attr:`pentanb.Scheme.formula`) and the kind of
        mesh the paper says it makes.  A scheme that keeps the input's faces
        (preservations, Loop's) must keep the input's face sizes and add its
        own (pentagons, triangles, hexagons).
    """
    mesh = capped_prism() if mesh is None else mesh
    added = {"preserve_pentagons": 5, "loop_remesh": 3, "preserve_hexagons": 6}
    out = []
    for name, (section, quote, what, measure, expected) in PAPER.items():
        s = SCHEMES[name]
        after = outputs[name] if outputs is not None and name in outputs else s(mesh)
        if expected is None:
            expected = sorted(set(_sizes(mesh)) | {added[name]})
        out.append(
            exact(
                f"schemes.{name}",
                section,
                quote,
                f"{s.label}: (V, E, F), against {s.formula} from {vef(mesh)}; {what}",
                (s.counts(*vef(mesh)), expected),
                (vef(after), measure(after)),
                reading=f"the construction, counted ({s.formula} from (V, E, F)), and the kind "
                f"of mesh it makes ({what}) from a mesh of triangles, quads and a pentagon",
                cause=CAUSES.get(name, ""),
            )
        )
    return out
