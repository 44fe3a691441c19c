"""How a :class:`~pentanb.schemes.table.Table` names a point: a :class:`Ref`.

``[moves:]ELEMENT[|fallback]``: the moves from a half-edge ``h``, left to
right (``n`` next, ``p`` previous, ``t`` twin), then the element of the
half-edge reached: ``V`` its tail vertex, ``E0``, ``E1``, ... its edge
points counted from its tail, ``F`` its face's point, ``C`` its corner point.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Ref", "parse_ref"]

_TOKEN = re.compile(r"^(?:([npt]*):)?(V|F|C|E(\d+))$")


@dataclass(frozen=True)
class Ref:
    """A point named from a half-edge: ``path`` moves, then an element.

    Attributes
    ----------
    path : str
        Moves applied left to right: ``n`` next, ``p`` previous, ``t`` twin.
    elem : str
        ``"V"`` (tail vertex), ``"E"`` (an edge point), ``"F"`` (face point),
        ``"C"`` (corner point).
    j : int
        Which edge point, counted from the half-edge's tail (``elem == "E"``).
    fallback : Ref or None
        Used where ``path`` runs into a boundary's hole (open meshes).
    """

    path: str
    elem: str
    j: int = 0
    fallback: Ref | None = None

    def __str__(self) -> str:
        name = f"E{self.j}" if self.elem == "E" else self.elem
        text = f"{self.path}:{name}" if self.path else name
        return text + (f"|{self.fallback}" if self.fallback is not None else "")


def parse_ref(token: object, where: str) -> Ref:
    """A :class:`Ref` from its text (``"n:E0"``, ``"t:F|n:V"``); ValueError naming ``where``."""
    if not isinstance(token, str):
        raise TypeError(f"{where}: a point is named by a string such as 'n:E0', got {token!r}")
    first, _, rest = token.partition("|")
    found = _TOKEN.match(first.strip())
    if found is None:
        raise ValueError(
            f"{where}: {first!r} is not a point; write [moves:]ELEMENT, moves from "
            "n, p, t and ELEMENT one of V, E0, E1, ..., F, C (e.g. 'n:E0')"
        )
    path, elem, j = found.group(1) or "", found.group(2)[0], found.group(3)
    fallback = parse_ref(rest, where) if rest else None
    return Ref(path, elem, int(j) if j else 0, fallback)
