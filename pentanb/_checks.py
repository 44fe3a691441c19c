"""The one check of every count, number and callback an argument gives.

Every public function checks its arguments here before any work starts:

* :func:`count` -- iterations, duals, sizes, ``max_faces``,
  ``max_iterations``, widths and heights: an integer (a Python or numpy
  integer, not a bool, not a float even when whole, not a string), else a
  ``TypeError``; in its range, else a ``ValueError``.  Both messages name
  the argument and its range.
* :func:`number` -- a real number (not a bool, not a string) in a range.
* :func:`callback` -- a callable, or one of a few accepted constants.
* :func:`steps` -- at most :data:`MAX_STEPS` operations in one call.
* :func:`shown`, :func:`excerpt` and :func:`bounded` -- values, strings and
  whole messages quoted in a message without echoing megabytes of them (a
  5,000-digit integer or a 100,000-character string is described, not
  printed).

Imports nothing from pentanb (numpy only), so every module may use it.
"""

from __future__ import annotations

import math
import numbers
import operator
from typing import Any

import numpy as np

__all__ = ["MAX_STEPS", "count", "number", "callback", "steps", "shown", "excerpt", "bounded"]

#: Most steps (remeshings and duals together) one call may take: more would
#: run for hours without the counts changing (duals, or triangulate after
#: its first pass, keep them).  :func:`pentanb.subdivide`, :func:`pentanb.smooth`,
#: the explorer and the analysis functions all stop here.
MAX_STEPS = 100_000

#: An integer of more digits is described in messages, not printed.
_MAX_SHOWN_DIGITS = 30
#: Characters of a value's repr a message quotes at most.
_MAX_SHOWN = 80


def _digits(n: int) -> int:
    """Decimal digits of ``abs(n)`` (within one), without converting it to a string."""
    return max(1, int(abs(n).bit_length() * math.log10(2)) + 1)


def shown(value: object) -> str:
    """``value`` for an error message: its repr, shortened.

    An integer of more than 30 digits is described by its number of digits
    (Python refuses to print one of more than 4,300); a long string or repr
    is cut, with its length given.
    """
    if isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_)):
        n = int(value)
        if abs(n) >= 10**_MAX_SHOWN_DIGITS:
            sign = "-" if n < 0 else ""
            return f"{sign}an integer of about {_digits(n):,} digits"
        return repr(n) if isinstance(value, int) else repr(value)
    if isinstance(value, str) and len(value) > _MAX_SHOWN:
        return f"{value[:40]!r}... ({len(value):,} characters)"
    try:
        text = repr(value)
    except Exception:  # a repr that fails: the type will do
        return f"a {type(value).__name__}"
    if len(text) > _MAX_SHOWN:
        text = text[: _MAX_SHOWN - 3] + "..."
    return text


def _span(low: float | None, high: float | None) -> str:
    if low is not None and high is not None:
        return f"in [{low:,}, {high:,}]" if isinstance(low, int) else f"in [{low:g}, {high:g}]"
    if low is not None:
        return f">= {low:,}" if isinstance(low, int) else f">= {low:g}"
    if high is not None:
        return f"<= {high:,}" if isinstance(high, int) else f"<= {high:g}"
    return ""


def count(value: object, name: str, low: int = 0, high: int | None = None) -> int:
    """``value`` as a Python int in ``[low, high]`` (``high`` None: no upper bound).

    Parameters
    ----------
    value : object
        A Python or numpy integer (anything with ``__index__``, but not a
        bool).  A float is refused even when whole (``2.0``): a count
        written as a float is usually a computation gone wrong.
    name : str
        The argument's name, for the messages.
    low, high : int
        The range, both ends included.

    Returns
    -------
    int

    Raises
    ------
    TypeError
        ``value`` is not an integer (a bool, a float, a string, None); the
        message names ``name``, its range and what was given.
    ValueError
        ``value`` is out of range; the message names ``name`` and the range.
    """
    span = _span(low, high)
    if isinstance(value, (bool, np.bool_)) or not hasattr(type(value), "__index__"):
        raise TypeError(
            f"{name} must be an integer {span}, got {type(value).__name__} {shown(value)}"
        )
    try:
        n = operator.index(value)  # type: ignore[arg-type]
    except TypeError:  # an array of more than one element, ...
        raise TypeError(
            f"{name} must be an integer {span}, got {type(value).__name__} {shown(value)}"
        ) from None
    if n < low or (high is not None and n > high):
        raise ValueError(f"{name} must be an integer {span}, got {shown(n)}")
    return int(n)


def number(
    value: object,
    name: str,
    low: float | None = None,
    high: float | None = None,
    *,
    open_low: bool = False,
    open_high: bool = False,
    finite: bool = True,
) -> float:
    """``value`` as a float in its range.

    Parameters
    ----------
    value : object
        A real number (Python or numpy; an integer too), not a bool nor a string.
    name : str
        The argument's name, for the messages.
    low, high : float, optional
        The range; ``open_low`` / ``open_high`` leave an end out.
    finite : bool
        Refuse infinities (NaN is always refused).

    Returns
    -------
    float

    Raises
    ------
    TypeError
        Not a real number; the message names ``name``.
    ValueError
        NaN, infinite (when ``finite``), or out of range; the message names
        ``name`` and the range.
    """
    left = "(" if open_low else "["
    right = ")" if open_high else "]"
    if low is not None and high is not None:
        span = f" in {left}{low:g}, {high:g}{right}"
    elif low is not None:
        span = f" {'>' if open_low else '>='} {low:g}"
    elif high is not None:
        span = f" {'<' if open_high else '<='} {high:g}"
    else:
        span = ""
    bounded = low is not None and high is not None
    what = f"{name} must be a {'finite ' if finite and not bounded else ''}number{span}"
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{what}, got {type(value).__name__} {shown(value)}")
    try:
        x = float(value)
    except OverflowError:  # an int beyond float
        x = math.inf if operator.index(value) > 0 else -math.inf  # type: ignore[arg-type]
    if math.isnan(x) or (finite and math.isinf(x)):
        raise ValueError(f"{what}, got {shown(value)}")
    if low is not None and (x < low or (open_low and x == low)):
        raise ValueError(f"{what}, got {shown(value)}")
    if high is not None and (x > high or (open_high and x == high)):
        raise ValueError(f"{what}, got {shown(value)}")
    return x


def callback(value: object, name: str, allowed: tuple = (None,), what: str = "") -> Any:
    """``value`` when it is callable or one of ``allowed`` (compared with ``is``).

    For functions called during the work (``progress=``): checked before
    it starts, so that a wrong value does not fail after the first step.

    Raises
    ------
    TypeError
        Neither; the message names ``name`` and says what it takes (``what``).
    """
    if callable(value) or any(value is a for a in allowed):
        return value
    takes = what or "a callable" + "".join(f" or {a!r}" for a in allowed)
    raise TypeError(f"{name} must be {takes}, got {type(value).__name__} {shown(value)}")


def steps(n: int, what: str, limit: int = MAX_STEPS) -> None:
    """Refuse (ValueError) more than ``limit`` steps in one call; ``what`` says which."""
    if n > limit:
        raise ValueError(
            f"{what} is {shown(n)} steps; at most {limit:,} are taken in one call "
            "(it would run for hours)"
        )


def excerpt(text: str, start: int, stop: int | None = None, width: int = 24) -> str:
    """The part ``text[start:stop]`` of a long string, with a little context, for a message.

    The whole string when it is short (at most ``2 * width + 20``
    characters), else ``'...abc[part]def...' (at position i of n characters)``
    with at most ``width`` characters of the part and of each side.
    """
    stop = start + 1 if stop is None else stop
    if len(text) <= 2 * width + 20:
        return repr(text)
    part = text[start:stop]
    if len(part) > width:
        part = part[: width // 2] + "..." + part[-(width // 2) :]
    before = text[max(0, start - width) : start]
    after = text[stop : stop + width]
    lead = "..." if start > width else ""
    tail = "..." if stop + width < len(text) else ""
    return repr(f"{lead}{before}[{part}]{after}{tail}") + (
        f" (at position {start:,} of {len(text):,} characters)"
    )


#: The longest error message :func:`bounded` lets through whole.
MAX_MESSAGE = 2_000


def bounded(message: str, limit: int = MAX_MESSAGE) -> str:
    """An error message of at most about ``limit`` characters.

    A longer one (a face of a million indices listed whole) keeps its start
    and its end, each about ``limit // 2`` characters, and says how long
    it was: ``"... [1,234,567 characters in all] ..."``.

    Parameters
    ----------
    message : str
        The message.
    limit : int
        The most characters kept whole.

    Returns
    -------
    str
        ``message`` itself when it is short enough, else its excerpt.
    """
    if len(message) <= limit:
        return message
    half = limit // 2
    return f"{message[:half]} ... [{len(message):,} characters in all] ... {message[-half:]}"
