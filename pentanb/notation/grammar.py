"""Reading Conway strings: :func:`parse` checks and splits one, :func:`reduce_notation`
rewrites it by :data:`REDUCTIONS` (same topology, fewer operators).

A string is read right to left: the rightmost letter is the seed
(:data:`~pentanb.notation.seeds.SEEDS`), every letter to its left an
operator (:data:`~pentanb.notation.operators.OPERATORS`); ``kN`` and ``tN``
take a number, and so do the seeds ``Pn An Yn``.

Bounds: a string of at most :data:`MAX_LENGTH` characters, numbers of at
most :data:`MAX_DIGITS` digits (checked before any is converted); a
message quotes only the offending part of a long string.  Parsing and
reducing take time linear in the string's length.
"""

from __future__ import annotations

from dataclasses import dataclass

from .._checks import excerpt, shown
from .operators import OPERATORS
from .seeds import SEEDS

__all__ = [
    "NotationError",
    "Token",
    "Notation",
    "parse",
    "REDUCTIONS",
    "SEED_REDUCTIONS",
    "reduce_notation",
    "MAX_LENGTH",
    "MAX_DIGITS",
]

#: Longest Conway string read (characters): every letter is an operation,
#: and :func:`pentanb.conway` applies at most this many.
MAX_LENGTH = 100_000
#: Most digits of a number in a string (``k12``, ``P100``): up to 999,999,999.
MAX_DIGITS = 9

#: Characters of the string shown on each side of the offending one in a message.
_CONTEXT = 30


class NotationError(ValueError):
    """A malformed Conway string.

    Attributes
    ----------
    notation : str
    position : int
        0-based index of the offending character (``len(notation)`` when
        something is missing at the end).
    """

    def __init__(self, message: str, notation: str, position: int):
        pointer = ""
        if notation:
            # a window of the string around the position (a long string is not echoed)
            lo = max(0, position - _CONTEXT)
            hi = min(len(notation), position + _CONTEXT + 1)
            lead = "..." if lo > 0 else ""
            tail = "..." if hi < len(notation) else ""
            pointer = f"\n  {lead}{notation[lo:hi]}{tail}\n  {' ' * (len(lead) + position - lo)}^"
        super().__init__(message + pointer)
        self.notation = notation
        self.position = position


# ---------------------------------------------------------------------- parsing
@dataclass(frozen=True)
class Token:
    """One letter of a string, with its number (``k4``) and 0-based position."""

    letter: str
    number: int | None
    position: int

    def __str__(self) -> str:
        return self.letter + ("" if self.number is None else str(self.number))


@dataclass(frozen=True)
class Notation:
    """A parsed string: the operators left to right, and the seed (or None)."""

    text: str
    operators: tuple[Token, ...]
    seed: Token | None

    def __str__(self) -> str:
        return "".join(str(t) for t in self.operators) + (str(self.seed) if self.seed else "")


_DIGITS = "0123456789"


def _known() -> str:
    return f"operators {' '.join(OPERATORS)} (kN, tN take a number); seeds T C O I D Pn An Yn"


def parse(notation: str, *, seed_given: bool = False) -> Notation:
    """Check and split a Conway string.

    Parameters
    ----------
    notation : str
    seed_given : bool
        A mesh is passed as the seed: the string must hold operators only.

    Returns
    -------
    Notation

    Raises
    ------
    TypeError
        ``notation`` is not a string.
    NotationError
        (a ValueError) naming the character and its 0-based position: an
        empty string, an unknown letter, a number where none may stand or a
        missing one (``P``), a number out of range (``P2``, ``k2``) or of
        more than :data:`MAX_DIGITS` digits, no seed, a seed that is not the
        rightmost letter, a seed both in the string and passed as a mesh, a
        string of more than :data:`MAX_LENGTH` characters.
    """
    if not isinstance(notation, str):
        raise TypeError(f"a Conway notation must be a string, got {type(notation).__name__}")
    s = notation
    if not s:
        raise NotationError(
            "empty notation: write operators then a seed, e.g. 'gC' (" + _known() + ")", s, 0
        )
    if len(s) > MAX_LENGTH:
        raise NotationError(
            f"a Conway string of {len(s):,} characters ({s[:20]!r}...); at most {MAX_LENGTH:,} "
            "are read (each letter is an operation)",
            s,
            MAX_LENGTH,
        )
    tokens: list[Token] = []
    i = 0
    while i < len(s):
        ch = s[i]
        if ch in _DIGITS:
            raise NotationError(f"number {ch!r} at position {i} does not follow a letter", s, i)
        op, seed = OPERATORS.get(ch), SEEDS.get(ch)
        if op is None and seed is None:
            raise NotationError(
                f"unknown letter {ch!r} at position {i} in {excerpt(s, i)}; " + _known(), s, i
            )
        j = i + 1
        while j < len(s) and s[j] in _DIGITS:
            j += 1
        digits = s[i + 1 : j]
        number = None
        if j - (i + 1) > MAX_DIGITS:
            raise NotationError(
                f"the number after {ch!r} at position {i} has {j - i - 1:,} digits, "
                f"{excerpt(s, i + 1, j)}; at most {MAX_DIGITS} are read",
                s,
                i + 1,
            )
        if digits:
            takes = op.number if op is not None else (seed is not None and seed.needs_number)
            if not takes:
                name = op.name if op is not None else seed.name  # type: ignore[union-attr]
                raise NotationError(
                    f"{ch!r} ({name}) at position {i} takes no number, "
                    f"but {digits!r} follows it at position {i + 1}",
                    s,
                    i + 1,
                )
            number = int(digits)
            if number < 3:
                what = op.number if op is not None else "number of sides"
                name = op.name if op is not None else seed.name  # type: ignore[union-attr]
                raise NotationError(
                    f"{ch}{digits} at position {i}: {name} needs a {what} of at least 3",
                    s,
                    i + 1,
                )
        elif seed is not None and seed.needs_number:
            raise NotationError(
                f"seed {ch!r} ({seed.name}) at position {i} needs a number of sides "
                f"(at least 3), e.g. {ch}5",
                s,
                j,
            )
        tokens.append(Token(ch, number, i))
        i = j
    seeds = [t for t in tokens if t.letter in SEEDS]
    if seed_given:
        if seeds:
            t = seeds[0]
            raise NotationError(
                f"seed given twice: {str(t)!r} at position {t.position} and the seed "
                "argument (with a mesh as seed the string holds operators only)",
                s,
                t.position,
            )
        return Notation(s, tuple(tokens), None)
    if not seeds:
        raise NotationError(
            f"no seed in {shown(s)}: end the string with T, C, O, I, D, Pn, An or Yn, "
            "or pass a Mesh as seed",
            s,
            len(s),
        )
    first = seeds[0]
    if first is not tokens[-1]:
        raise NotationError(
            f"seed {str(first)!r} at position {first.position} is not at the right end: "
            "operators stand left of the one seed, e.g. 'dkC'",
            s,
            first.position,
        )
    return Notation(s, tuple(tokens[:-1]), tokens[-1])


# ---------------------------------------------------------------------- reductions
#: Rewrites that keep the oriented topology: (pattern, replacement), read
#: like the notation (``("a", "d") -> ("a",)`` is ``ad -> a``).  From Hart's
#: and polyHedronisme's substitutions (dd -> "", ad -> a, ...) and the
#: operators' definitions (z = dk, n = kd, t = dkd, s = dg, j = da, o = de,
#: b = dm, c = dud, p = dpd).  Every rule shortens the string.
REDUCTIONS: tuple[tuple[str, str], ...] = (
    ("dd", ""),
    ("rr", ""),
    ("ad", "a"),
    ("jd", "j"),
    ("ed", "e"),
    ("od", "o"),
    ("bd", "b"),
    ("md", "m"),
    ("da", "j"),
    ("dj", "a"),
    ("de", "o"),
    ("do", "e"),
    ("db", "m"),
    ("dm", "b"),
    ("dk", "z"),
    ("dz", "k"),
    ("kd", "n"),
    ("nd", "k"),
    ("td", "z"),
    ("zd", "t"),
    ("dt", "n"),
    ("dn", "t"),
    ("dg", "s"),
    ("ds", "g"),
    ("dpd", "p"),
    ("dud", "c"),
    ("dcd", "u"),
)

#: Seed rewrites (Hart): a dual seed is another seed; P4 = C, A3 = O, Y3 = T.
SEED_REDUCTIONS: dict[str, str] = {
    "dT": "T",
    "dC": "O",
    "dO": "C",
    "dI": "D",
    "dD": "I",
    "P4": "C",
    "A3": "O",
    "Y3": "T",
}


#: The rewrites by their pattern's length, pattern -> replacement (no two-letter
#: pattern is the end of a three-letter one, so the order between them is moot).
_RULES: tuple[dict[str, str], ...] = tuple(
    {p: r for p, r in REDUCTIONS if len(p) == k} for k in (2, 3)
)


def _reduce(n: Notation) -> Notation:
    """``n`` with :data:`REDUCTIONS` applied until none applies, then the seed's.

    Linear in the number of operators: the operators are pushed left to
    right onto a stack kept free of patterns, and after every push the
    rules whose pattern ends at the top are tried there (a rewrite can only
    make a pattern that ends at the new top, since the rest of the stack
    has none).  Every rewrite shortens the stack, so there are fewer
    rewrites than operators.  Then the seed: ``P4`` is ``C``, and a ``d``
    left of a seed turns it into its dual seed (``dC`` is ``O``).
    """
    stack: list[Token] = []
    letters: list[str] = []  # the stack's letters ("#" for a letter with a number)
    for tok in n.operators:
        stack.append(tok)
        letters.append(tok.letter if tok.number is None else "#")
        while len(letters) >= 2:
            for k, rules in zip((2, 3), _RULES):
                repl = rules.get("".join(letters[-k:])) if len(letters) >= k else None
                if repl is not None:
                    pos = stack[-k].position
                    del stack[-k:], letters[-k:]
                    stack.extend(Token(c, None, pos) for c in repl)
                    letters.extend(repl)
                    break
            else:
                break
    seed = n.seed
    while seed is not None:
        key = str(seed)
        if key in SEED_REDUCTIONS:
            seed = Token(SEED_REDUCTIONS[key], None, seed.position)
        elif stack and stack[-1].letter == "d" and "d" + key in SEED_REDUCTIONS:
            seed = Token(SEED_REDUCTIONS["d" + key], None, seed.position)
            stack.pop()  # (the rest of the stack stays free of patterns)
            letters.pop()
        else:
            break
    return Notation(n.text, tuple(stack), seed)


def reduce_notation(notation: str) -> str:
    """The string after the rewrites of :data:`REDUCTIONS` (same topology).

    Parameters
    ----------
    notation : str
        Operators then a seed, or operators only.

    Returns
    -------
    str
        The reduced string (``""`` when every operator cancels out of a
        seedless string).

    Raises
    ------
    NotationError
        A malformed string (as :func:`parse`).

    Examples
    --------
    >>> reduce_notation("ddgT")
    'gT'
    >>> reduce_notation("dkdC")
    'tC'
    """
    seedless = not any(c in SEEDS for c in notation) if isinstance(notation, str) else False
    return str(_reduce(parse(notation, seed_given=seedless)))
