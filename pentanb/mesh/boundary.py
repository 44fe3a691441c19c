"""The boundary of an open mesh, for error messages: how many loops, how long.

A pentanb mesh must be closed; when faces leave edges with one side only,
:meth:`pentanb.Mesh` names the first such edge and, through
:func:`describe_boundary`, says how many boundary loops (holes, open rims)
there are, so a user can tell one missing face from an open scan.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["boundary_edges", "boundary_loops", "describe_boundary"]


def boundary_edges(tail: ArrayLike, head: ArrayLike) -> np.ndarray:
    """(b,) int: the half-edges ``tail[h] -> head[h]`` without an opposite ``head -> tail``."""
    tail = np.asarray(tail, dtype=np.int64)
    head = np.asarray(head, dtype=np.int64)
    if tail.size == 0:
        return np.zeros(0, dtype=np.int64)
    n = np.int64(max(int(tail.max()), int(head.max())) + 1)
    key = np.sort(tail * n + head)
    want = head * n + tail
    pos = np.minimum(np.searchsorted(key, want), key.size - 1)
    return np.flatnonzero(key[pos] != want)


def boundary_loops(tail: ArrayLike, head: ArrayLike) -> list[int]:
    """The number of edges of every boundary loop, largest first.

    A loop is a connected chain of boundary edges (see
    :func:`boundary_edges`); on a manifold with boundary each is a cycle
    around a hole or along an open rim.

    Parameters
    ----------
    tail, head : (H,) int
        The half-edges of a mesh (``Mesh.tail``, ``Mesh.head``; or the
        corners and their successors in each face).

    Returns
    -------
    list of int
        Empty for a closed mesh.
    """
    tail = np.asarray(tail, dtype=np.int64)
    head = np.asarray(head, dtype=np.int64)
    b = boundary_edges(tail, head)
    if not b.size:
        return []
    u, w = tail[b], head[b]
    ids, inverse = np.unique(np.concatenate([u, w]), return_inverse=True)
    u, w = inverse[: b.size], inverse[b.size :]
    label = np.arange(ids.size, dtype=np.int64)
    while True:  # hook the larger label onto the smaller, then jump pointers
        lu, lw = label[u], label[w]
        differ = lu != lw
        if not differ.any():
            break
        np.minimum.at(label, np.maximum(lu[differ], lw[differ]), np.minimum(lu[differ], lw[differ]))
        while True:
            jumped = label[label]
            if np.array_equal(jumped, label):
                break
            label = jumped
    sizes = np.bincount(label[u], minlength=ids.size)
    return sorted((int(x) for x in sizes[sizes > 0]), reverse=True)


def describe_boundary(tail: ArrayLike, head: ArrayLike) -> str:
    """``"1 boundary loop (4 edges)"`` or ``"3 boundary loops (12, 4 and 3 edges)"``."""
    loops = boundary_loops(tail, head)
    if not loops:
        return "no boundary"
    if len(loops) == 1:
        return f"1 boundary loop ({loops[0]} edges)"
    shown = [str(x) for x in loops[:5]]
    edges = ", ".join(shown[:-1]) + " and " + shown[-1] if len(loops) <= 5 else ", ".join(shown)
    more = "" if len(loops) <= 5 else f", ... {sum(loops):,} in all"
    return f"{len(loops)} boundary loops ({edges}{more} edges)"
