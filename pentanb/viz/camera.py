"""The camera of a 3D view, and the frame its coordinates are drawn in.

A view looks at a model from the direction of the matplotlib figures'
default camera (elevation :data:`VIEW_ELEV`, azimuth :data:`VIEW_AZIM`,
with +z up: :func:`eye_direction`), so the package's models, which stand
on the xy plane and face +x (the rabbit's snout), are seen from the front
and a little above, as in the figures; :func:`camera_fit` places a camera
that shows every point, :func:`look_at_quaternion` turns it towards them.

A :data:`Frame` is how a view draws its coordinates (an offset and an exact
power-of-two scale, :func:`view_frame`, :func:`in_frame`,
:func:`frame_fits`), so that WebGL's float32 keeps a model's detail.

Needs numpy only.  Every name here is importable from
:mod:`pentanb.viz.drawing` too.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _jit

__all__ = [
    "VIEW_ELEV",
    "VIEW_AZIM",
    "eye_direction",
    "camera_fit",
    "look_at_quaternion",
    "Frame",
    "IDENTITY",
    "view_frame",
    "in_frame",
    "frame_fits",
]

#: The camera of a 3D view: elevation and azimuth in degrees, +z up, as the
#: matplotlib figures' default (:data:`pentanb.viz.mpl.ELEV`, ``AZIM``).
VIEW_ELEV, VIEW_AZIM = 22.0, -58.0


def eye_direction(elev: float = VIEW_ELEV, azim: float = VIEW_AZIM) -> NDArray[np.float64]:
    """The unit vector from a model towards the camera, +z up.

    Parameters
    ----------
    elev, azim : float
        Elevation above the xy plane and azimuth from +x towards +y, in
        degrees (the conventions of matplotlib's ``view_init``).

    Returns
    -------
    (3,) float
        ``(cos e cos a, cos e sin a, sin e)``.
    """
    e, a = math.radians(float(elev)), math.radians(float(azim))
    return np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])


#: How a 3D view draws its coordinates: ``(offset, exponent)``, a point ``p``
#: drawn at ``(p - offset) * 2**-exponent`` (exact scaling by a power of two).
Frame = tuple[NDArray[np.float64], int]

#: The coordinates as they are.
IDENTITY: Frame = (np.zeros(3), 0)

#: Drawn coordinates stay within ``2**±32``: WebGL's float32 holds ``2**±126``,
#: and the camera's matrices multiply distances.
_FRAME_LIMIT = 2.0**32
#: A drawing smaller than this fraction of its distance from the origin is
#: moved to the origin (float32 keeps 24 bits: it would be drawn as a blob).
_FRAME_DETAIL = 2.0**-12


def _bounds(
    points: ArrayLike, signed_zeros: bool = True
) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
    """(least, greatest) of every coordinate, or None for no points.

    ``signed_zeros=False``: where a column holds both -0.0 and 0.0, either
    may be returned (the optional compiled kernel, one pass over a large
    array); a NaN or an infinity gives a NaN or an infinity all the same.
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(p) == 0:
        return None
    jit = None if signed_zeros else _jit.kernels(len(p))
    if jit is not None:
        lo, hi = np.empty(3), np.empty(3)
        jit.bounds(np.ascontiguousarray(p), lo, hi)
        return lo, hi
    # column by column: numpy reduces a strided column with SIMD, while
    # p.min(axis=0) walks the rows three values at a time (30-40x slower on
    # 100,000 vertices, the largest cost of a slider move); a NaN or an
    # infinity gives a NaN or an infinity in the bounds all the same
    cols = [p[:, k] for k in range(3)]
    return np.array([c.min() for c in cols]), np.array([c.max() for c in cols])


def view_frame(*points: ArrayLike) -> Frame:
    """The frame in which a 3D view draws these points (all arrays together).

    :data:`IDENTITY` when float32 holds the coordinates well: within
    ``2**32`` of the origin, the drawing no smaller than ``2**-32`` and
    than ``2**-12`` of its distance from the origin (every mesh of the
    package's shapes and schemes).  Otherwise the centre of the bounding
    box and the power of two that brings its half-size into [0.5, 1): so
    any finite coordinates are framed, near ``1e300`` as near ``1e-300``,
    or a small drawing far from the origin.

    Parameters
    ----------
    *points : (k, 3) float
        Finite coordinates.

    Returns
    -------
    Frame
        ``(offset, exponent)``: a point ``p`` is drawn at
        ``(p - offset) * 2**-exponent`` (:func:`in_frame`).

    Raises
    ------
    ValueError
        A coordinate that is not finite.
    """
    return _frame_of([b for b in (_bounds(p) for p in points) if b is not None])


def _frame_of(found: list[tuple[NDArray[np.float64], NDArray[np.float64]]]) -> Frame:
    """:func:`view_frame` from the bounds of every array (those of empty ones left out)."""
    if not found:
        return IDENTITY
    lo = np.min([b[0] for b in found], axis=0)
    hi = np.max([b[1] for b in found], axis=0)
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ValueError("a view needs finite coordinates")
    far = float(max(np.abs(lo).max(), np.abs(hi).max()))  # from the origin
    centre = lo * 0.5 + hi * 0.5  # (no sum that could overflow)
    half = float((hi * 0.5 - lo * 0.5).max())
    if half == 0.0:  # one point
        return IDENTITY if far <= _FRAME_LIMIT else (centre, 0)
    if far <= _FRAME_LIMIT and half >= 1.0 / _FRAME_LIMIT and half >= far * _FRAME_DETAIL:
        return IDENTITY
    return centre, int(np.frexp(half)[1])


def in_frame(points: ArrayLike, frame: Frame) -> NDArray[np.float64]:
    """``points`` as drawn in ``frame``: ``(p - offset) * 2**-exponent`` (exact scaling).

    Parameters
    ----------
    points : (..., 3) float
    frame : Frame

    Returns
    -------
    (..., 3) float
        ``points`` itself in :data:`IDENTITY`.
    """
    p = np.asarray(points, dtype=np.float64)
    offset, exponent = frame
    if exponent == 0 and not offset.any():
        return p
    return np.ldexp(p - offset, -exponent)


def frame_fits(frame: Frame, *points: ArrayLike) -> bool:
    """Whether ``frame`` draws these points well (their frame within it is the identity).

    Parameters
    ----------
    frame : Frame
    *points : (k, 3) float

    Returns
    -------
    bool
    """
    drawn = [in_frame(p, frame) for p in points]
    # (every coordinate finite exactly when the bounds are: min and max keep
    # a NaN, and an infinity is a bound; no pass of its own.  The sign of a
    # zero bound changes no answer here: the identity frame is one of
    # magnitudes)
    found = [b for b in (_bounds(d, signed_zeros=False) for d in drawn) if b is not None]
    if not all(np.isfinite(lo).all() and np.isfinite(hi).all() for lo, hi in found):
        return False
    frame_found = _frame_of(found)
    return frame_found[1] == 0 and not frame_found[0].any()


def camera_fit(
    points: ArrayLike, fov: float, aspect: float, direction: ArrayLike | None = None
) -> tuple[NDArray[np.float64], float, NDArray[np.float64]]:
    """A camera that shows every point.

    Parameters
    ----------
    points : (k, 3) float
    fov : float
        Vertical field of view, degrees.
    aspect : float
        Width / height of the picture.
    direction : (3,) float, optional
        From the model towards the camera (any length but 0); default
        :func:`eye_direction` of :data:`VIEW_ELEV`, :data:`VIEW_AZIM`: from
        the front (+x), a little to the right (-y) and above (+z).

    Returns
    -------
    centre : (3,) float
        Middle of the bounding box (the orbit target).
    radius : float
        Radius of the bounding sphere about ``centre``.
    eye : (3,) float
        Camera position: ``centre`` plus ``direction``, far enough for the
        sphere to fit in both fields of view, with a 15 % margin.

    Raises
    ------
    ValueError
        A ``direction`` that is not three finite numbers, not all 0.
    """
    toward = eye_direction() if direction is None else np.asarray(direction, dtype=np.float64)
    size = float(np.linalg.norm(toward)) if toward.shape == (3,) else 0.0
    if not (math.isfinite(size) and size > 0):
        raise ValueError(
            f"a camera direction is three finite numbers, not all 0, got {direction!r}"
        )
    toward = toward / size
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(p) == 0:
        return np.zeros(3), 1.0, 4.0 * toward
    lo, hi = p.min(axis=0), p.max(axis=0)
    centre = (lo + hi) / 2
    radius = float(np.sqrt(((p - centre) ** 2).sum(axis=1).max())) or 1.0
    half = math.radians(fov) / 2
    if aspect < 1:  # narrow view: the horizontal field of view limits
        half = math.atan(math.tan(half) * aspect)
    distance = radius / math.sin(half) * 1.15
    return centre, radius, centre + distance * toward


def look_at_quaternion(
    eye: ArrayLike, target: ArrayLike, up: ArrayLike = (0.0, 0.0, 1.0)
) -> tuple[float, float, float, float]:
    """Quaternion (x, y, z, w) turning a camera at ``eye`` towards ``target``.

    The camera looks down its -z axis, as in three.js ``Object3D.lookAt``;
    setting it from Python keeps a moved camera aimed without a browser-side
    ``lookAt`` call (and so in exported pages too).
    """
    e, t, u = (np.asarray(a, dtype=np.float64) for a in (eye, target, up))
    z = e - t
    z /= np.linalg.norm(z) or 1.0
    x = np.cross(u, z)
    if np.linalg.norm(x) < 1e-12:  # looking along up: any perpendicular will do
        x = np.cross((1.0, 0.0, 0.0) if abs(z[0]) < 0.9 else (0.0, 1.0, 0.0), z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.stack([x, y, z], axis=1)  # columns: the camera's axes in the world
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = 2.0 * math.sqrt(tr + 1.0)
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = (s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = ((m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s)
    return (float(q[0]), float(q[1]), float(q[2]), float(q[3]))
