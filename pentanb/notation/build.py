"""Building what a Conway string names: :func:`conway`, and :func:`resolve` /
:func:`as_scheme` for the functions that take a scheme name."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from .. import _checks
from ..mesh import Mesh
from ..schemes.registry import SCHEMES, Counts, Scheme, get_scheme
from .grammar import Notation, Token, _reduce, parse
from .operators import OPERATORS
from .positions import canonical as canonical_form
from .seeds import SEEDS

__all__ = ["conway", "resolve", "as_scheme", "MAX_FACES"]

#: Refuse a string whose predicted result has more faces than this.
MAX_FACES = 1_000_000

#: Counts are not followed beyond this (an upper bound then): no operator string
#: builds huge integers (3**100,000 after 100,000 truncations).
_COUNT_CAP = 2**80


def _check_options(n: Notation, options: Mapping) -> None:
    takes = {k for t in n.operators for k in OPERATORS[t.letter].options}
    unknown = sorted(set(options) - takes)
    if unknown:
        offer = (
            "; ".join(
                f"{op.letter} ({op.name}) takes {', '.join(op.options)}"
                for op in OPERATORS.values()
                if op.options
            )
            or "none"
        )
        raise TypeError(f"option(s) {unknown} are taken by no operator of {n.text!r} ({offer})")


def _apply(tokens: Sequence[Token], mesh: Mesh, options: Mapping) -> Mesh:
    for tok in reversed(tokens):
        op = OPERATORS[tok.letter]
        kwargs = {k: options.get(k, default) for k, default in op.options.items()}
        mesh = (
            op.func(mesh, tok.number, **kwargs)
            if tok.number is not None
            else op.func(mesh, **kwargs)
        )
    return mesh


def _capped(counts: Counts) -> Counts:
    """Each count at most ``_COUNT_CAP`` (numbers only: a formula's symbols pass)."""
    return tuple(  # type: ignore[return-value]
        min(x, _COUNT_CAP) if isinstance(x, (int, float)) else x for x in counts
    )


def _steps(tokens: Sequence[Token], counts: Counts) -> list[Counts]:
    """``counts``, then the counts after every operator, right to left (upper
    bounds after ``kN`` and ``tN``; each count at most ``2**80``, so that no
    string builds huge integers)."""
    out = [counts]
    for tok in reversed(tokens):
        counts = _capped(OPERATORS[tok.letter].counts(*counts))
        out.append(counts)
    return out


def _check_size(n: Notation, seed: Mesh | None, max_faces: int) -> None:
    """Refuse (ValueError) before building: the first step, right to left, whose
    predicted mesh has more than ``max_faces`` faces (or ``2 max_faces``
    vertices), quoting only that part of the string."""

    def check(counts: Counts, tok: Token | None) -> None:
        V, E, F = counts
        if F > max_faces or V > 2 * max_faces:
            where = (
                ""
                if tok is None
                else " (its seed)"
                if tok is n.seed
                else f" after {tok} at position {tok.position:,}"
            )
            near = "" if tok is None else _checks.excerpt(n.text, tok.position)
            raise ValueError(
                f"{near or _checks.shown(n.text)} would build a mesh of about {F:,} faces "
                f"({V:,} vertices, {E:,} edges){where}, over max_faces={max_faces:,}"
            )

    if seed is not None:
        counts: Counts = (seed.n_vertices, seed.n_edges, seed.n_faces)
    else:
        assert n.seed is not None
        s = SEEDS[n.seed.letter]
        counts = s.counts(n.seed.number) if s.needs_number else s.counts()
    check(counts, n.seed)
    for tok in reversed(n.operators):  # stops at the first too large: no huge integers
        counts = OPERATORS[tok.letter].counts(*counts)
        check(counts, tok)


def _counts(notation: str | Notation, seed: Mesh | None = None) -> tuple[list[Counts], bool]:
    """``(V, E, F)`` of every step of ``conway(notation, seed)``, without building it.

    For :func:`conway`'s size check (the public count prediction is
    :func:`pentanb.predict_counts`).  ``counts[0]`` is the seed's,
    ``counts[-1]`` the result's; ``exact`` is False when the string holds
    ``kN`` or ``tN``, whose counts are then upper bounds (every face or
    vertex counted as chosen).
    """
    n = parse(notation, seed_given=seed is not None) if isinstance(notation, str) else notation
    if seed is not None:
        start: Counts = (seed.n_vertices, seed.n_edges, seed.n_faces)
    else:
        assert n.seed is not None
        s = SEEDS[n.seed.letter]
        start = s.counts(n.seed.number) if s.needs_number else s.counts()
    return _steps(n.operators, start), not any(t.number is not None for t in n.operators)


def conway(
    notation: str,
    seed: Mesh | None = None,
    *,
    canonical: bool = False,
    reduce: bool | None = None,
    max_faces: int = MAX_FACES,
    **options,
) -> Mesh:
    """Build the polyhedron a Conway string names.

    Parameters
    ----------
    notation : str
        Operators then a seed, read right to left: ``"gC"``, ``"ddgT"``,
        ``"t5dA5"``, ``"k4P6"``; operators only when ``seed`` is given.
    seed : Mesh, optional
        Any mesh to start from instead of a seed letter.
    canonical : bool
        Put the result in canonical form (:func:`pentanb.canonical`;
        genus 0 only).  Otherwise the package's positions (centroids, edge
        midpoints and thirds; the dual is the paper's smoothing).
    reduce : bool, optional
        Apply :data:`REDUCTIONS` first.  Default: only with ``canonical``,
        where it changes nothing but the time (with the package's positions
        ``dd`` is two smoothing steps, Figure 7, not the identity).
    max_faces : int, >= 1
        Refuse, before building anything, a string whose predicted result
        or any step towards it (an upper bound with ``kN``/``tN``) has more
        faces (or twice as many vertices).
    **options
        Options of the operators in the string, given to every operator that
        takes them: ``scale`` for ``q`` (default 0.5), ``e`` and ``c`` (0.5).

    Returns
    -------
    Mesh
        The result, with the package's positions or in canonical form.

    Raises
    ------
    NotationError
        (a ValueError) a malformed string, or one of more than
        :data:`~pentanb.notation.grammar.MAX_LENGTH` characters or with a
        number of more than :data:`~pentanb.notation.grammar.MAX_DIGITS`
        digits; the message names the character and its position, and
        quotes only that part of a long string.
    TypeError
        ``notation`` is not a string, ``seed`` not a Mesh, ``max_faces``
        not an integer, or an option no operator of the string takes.
    ValueError
        A step exceeds ``max_faces`` (found without building anything, and
        without huge integers: the message quotes the operator);
        ``max_faces`` < 1; an option's value is out of range.

    Notes
    -----
    The string is checked (its length and numbers, then its options), then
    reduced when asked (in time linear in its length), then its sizes are
    predicted, and only then is anything built.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.notation import conway
    >>> m = conway("tI")
    >>> m.n_vertices, m.n_edges, m.n_faces, m.face_size_histogram()
    (60, 90, 32, {5: 12, 6: 20})
    """
    if seed is not None and not isinstance(seed, Mesh):
        raise TypeError(f"seed must be a pentanb.Mesh or None, got {type(seed).__name__}")
    max_faces = _checks.count(max_faces, "max_faces", 1)
    n = parse(notation, seed_given=seed is not None)
    _check_options(n, options)
    if reduce is None:
        reduce = bool(canonical)
    if reduce:
        n = _reduce(n)
    _check_size(n, seed, max_faces)
    if seed is None:
        assert n.seed is not None
        s = SEEDS[n.seed.letter]
        seed = s.build(n.seed.number) if s.needs_number else s.build()
    mesh = _apply(n.operators, seed, options)
    if canonical:
        mesh = canonical_form(mesh)
    return mesh


def resolve(text: str) -> Scheme:
    """An operator string as a :class:`~pentanb.schemes.registry.Scheme`.

    For the explorer and :func:`pentanb.subdivide`, which take a scheme
    name: ``resolve("dgd")`` is a scheme whose ``func(mesh, **options)``
    applies the operators right to left, with the package's positions, and
    whose ``counts(V, E, F)`` composes the operators' formulas (an upper
    bound, ``exact_counts=False``, when ``kN`` or ``tN`` occur).

    Parameters
    ----------
    text : str
        Operators only, no seed: ``"dg"``, ``"k4t"``.

    Returns
    -------
    Scheme
        Named ``text``, of family ``"conway"``; its options are those of
        the string's operators, with the notation's defaults.

    Raises
    ------
    NotationError
        A malformed string, or one holding a seed letter.
    """
    n = parse(text, seed_given=True)
    tokens = n.operators
    opts: dict[str, float] = {}
    for t in reversed(tokens):
        for k, v in OPERATORS[t.letter].options.items():
            opts.setdefault(k, v)

    def func(mesh: Mesh, **options) -> Mesh:
        _check_options(n, options)
        return _apply(tokens, mesh, options)

    def counts(V, E, F):
        return _steps(tokens, (V, E, F))[-1]

    func.__name__ = f"conway_{text}"
    names = " of ".join(
        OPERATORS[t.letter].name + (str(t.number) if t.number else "") for t in tokens
    )
    return Scheme(
        name=text,
        func=func,
        label=f"Conway {text} ({names})",
        paper="Conway notation (beyond the paper)",
        conway=text,
        counts=counts,
        options=opts,
        family="conway",
        exact_counts=not any(t.number is not None for t in tokens),
    )


def as_scheme(scheme: str | Scheme | Callable) -> Scheme | Callable:
    """A scheme name, a string of Conway operators, a :class:`~pentanb.Scheme` or a
    callable, as the scheme to apply.

    :func:`pentanb.schemes.registry.get_scheme` with Conway notation added:
    a name of :data:`pentanb.SCHEMES` is looked up there, any other string is
    read as operators (``"dg"``, ``"k4t"``) by :func:`resolve`, so the
    explorer, :func:`pentanb.subdivide` and the step counts accept ``"dg"``
    wherever they take a scheme name.

    Parameters
    ----------
    scheme : str, Scheme or callable

    Returns
    -------
    Scheme or callable
        The registered or resolved :class:`~pentanb.Scheme`, or ``scheme``
        itself when it is a Scheme or a callable.

    Raises
    ------
    ValueError
        For a string that is neither a registered name nor Conway notation;
        the message lists the known names and says why the notation was
        refused.
    """
    if not isinstance(scheme, str) or scheme in SCHEMES:
        return get_scheme(scheme)
    try:
        return resolve(scheme)
    except ValueError as exc:
        why = str(exc).splitlines()[0] if str(exc) else "not Conway notation"
        raise ValueError(
            f"unknown scheme {_checks.shown(scheme)}; known schemes: {', '.join(SCHEMES)}, "
            f"or Conway operators such as 'dg' ({why})"
        ) from None
