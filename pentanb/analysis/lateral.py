"""Section 1's "lateral artifact", measured: the wave along the straight edges of a box.

"Although, the edge is straight, the first iteration can create a wave
pattern that does not exist in the original data and the final smooth
surface include a smooth wave pattern [...] As shown in Figure 1.C, the new
subdivision does not create any lateral artifact."

:func:`study` subdivides boxes whose faces are even grids of 3, 6 and 10
cells per edge (:func:`pentanb.shapes.box`), and Figure 1's hard-edged cube,
with every scheme of :data:`pentanb.SCHEMES` (but the simplest
triangulation, which the paper sets aside because it stops changing the mesh
after one iteration) followed by two duals, iterations 1 to 4, and measures
after every iteration the absolute peak-to-peak height of the wave along each of the
box's 12 edges (:func:`~pentanb.analysis.measures.lateral_amplitude`), away
from the corners (one grid cell from each end).  :func:`wavelength` finds
the wave's period.  numpy only.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _checks, shapes
from ..mesh import Mesh
from ..schemes import SCHEMES
from ..subdivision import predict_counts, subdivide
from .measures import edge_profile, lateral_amplitude

__all__ = [
    "BOXES",
    "LATERAL_SCHEMES",
    "ITERATIONS",
    "Lateral",
    "study",
    "wavelength",
]

#: The boxes of the study: name -> (builder, half-length of the stretch of every
#: edge that is measured, width of the grid cells along the edges).  The stretch
#: leaves out one grid cell at each end of an edge (on Figure 1's cube, the thin
#: corner cell and as much again).  Figure 1's cube: 0.2-wide strips along its
#: edges and a 1.6 x 1.6 quad in the middle of every face.
BOXES: dict[str, tuple[Callable[[], Mesh], float, float]] = {
    "3 cells": (lambda: shapes.box(3), 1 - 2 / 3, 2 / 3),
    "6 cells": (lambda: shapes.box(6), 1 - 2 / 6, 2 / 6),
    "10 cells": (lambda: shapes.box(10), 1 - 2 / 10, 2 / 10),
    "Figure 1's cube": (shapes.hard_edged_cube, 0.6, 0.2),
}
#: Every scheme but the simplest triangulation (Section 3: after one iteration
#: it does not change the mesh, so its iterations would be duals only).
LATERAL_SCHEMES: tuple[str, ...] = tuple(s for s in SCHEMES if s != "triangulate")
#: Iterations of the study (remeshing + two duals each).
ITERATIONS = 4


@dataclass(frozen=True)
class Lateral:
    """The study's results.

    Attributes
    ----------
    amplitude : dict
        ``{(box, scheme): (iterations, 12) float}``: peak-to-peak height of the
        wave along each of the 12 edges (:data:`~pentanb.analysis.measures.BOX_EDGES`),
        iteration by iteration, in the box's units (the boxes span [-1, 1]^3).
    profile : dict
        ``{(box, scheme): (x, r)}`` after the last iteration: the distance from the
        axis of the edge ``y = z = 1`` along it, in the plane through the edge
        (45 degrees), over the stretch measured.
    seconds : dict
        ``{(box, scheme): seconds}`` to build and measure all iterations.
    """

    amplitude: dict[tuple[str, str], NDArray[np.float64]]
    profile: dict[tuple[str, str], tuple[NDArray[np.float64], NDArray[np.float64]]]
    seconds: dict[tuple[str, str], float]

    def worst(self, box: str, scheme: str) -> NDArray[np.float64]:
        """The largest of the 12 edges after every iteration.

        Parameters
        ----------
        box : str
            A name of :data:`BOXES`.
        scheme : str
            A name of :data:`LATERAL_SCHEMES`.

        Returns
        -------
        (iterations,) float
        """
        return self.amplitude[box, scheme].max(axis=1)


@functools.lru_cache(maxsize=2)
def study(
    iterations: int = ITERATIONS,
    boxes: tuple[str, ...] = tuple(BOXES),
    schemes: tuple[str, ...] = LATERAL_SCHEMES,
) -> Lateral:
    """Every scheme with two duals on every box, iterations 1 .. ``iterations``, measured.

    Parameters
    ----------
    iterations : int, >= 1
        Repetitions of every scheme (each followed by two duals).
    boxes : tuple of str
        Names of :data:`BOXES`.
    schemes : tuple of str
        Names of :data:`pentanb.SCHEMES`.

    Returns
    -------
    Lateral

    Notes
    -----
    The results of the last two calls are kept (``functools.lru_cache``):
    the lateral figure and its claims share one study.  The largest mesh
    (pentagon preservation of the 10-cell box after 4 iterations) has 1.6 million
    edges; the whole default study takes about 10 s of one core.
    """
    iterations = _checks.count(iterations, "iterations", 1)
    for b in boxes:
        if b not in BOXES:
            raise ValueError(f"unknown box {b!r}; known: {', '.join(BOXES)}")
    for s in schemes:
        if s not in SCHEMES:
            raise ValueError(f"unknown scheme {s!r}; known: {', '.join(SCHEMES)}")
    starts = {b: BOXES[b][0]() for b in boxes}
    for b in boxes:  # every request refused before the first is built (MeshError)
        for s in schemes:
            predict_counts(starts[b], s, iterations, 2)
    amp, prof, secs = {}, {}, {}
    for b in boxes:
        _, window, _ = BOXES[b]
        start = starts[b]
        for s in schemes:
            t = time.perf_counter()
            mesh, rows = start, []
            for _ in range(iterations):
                mesh = subdivide(mesh, s, 1, 2)
                rows.append(lateral_amplitude(mesh, window))
            amp[b, s] = np.array(rows)
            x, r = edge_profile(mesh, (0, 1, 1), 45.0)
            keep = np.abs(x) <= window
            prof[b, s] = (x[keep], r[keep])
            secs[b, s] = time.perf_counter() - t
    return Lateral(amp, prof, secs)


def wavelength(x: ArrayLike, r: ArrayLike, samples: int = 512) -> float:
    """The period of the strongest wave in a profile ``r(x)`` (in the units of ``x``).

    The profile is resampled evenly, its mean removed, and the strongest
    frequency of its discrete Fourier transform (above the constant) taken.

    Parameters
    ----------
    x, r : (k,) float
        Sorted by ``x`` (as :func:`~pentanb.analysis.measures.edge_profile` gives them).
    samples : int, in [3, 10,000,000]
        Points of the even resampling.

    Returns
    -------
    float
        NaN for a flat profile.
    """
    samples = _checks.count(samples, "samples", 3, 10_000_000)
    x = np.asarray(x, dtype=float)
    r = np.asarray(r, dtype=float)
    if x.size < 3 or np.ptp(r) < 1e-12:
        return float("nan")
    grid = np.linspace(x[0], x[-1], samples)
    y = np.interp(grid, x, r)
    y = y - y.mean()
    power = np.abs(np.fft.rfft(y)) ** 2
    k = int(np.argmax(power[1:])) + 1
    return float((grid[-1] - grid[0]) * samples / (samples - 1) / k)
