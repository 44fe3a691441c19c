"""Every public function and method has a numpydoc docstring with its sections.

The public API is every name in ``pentanb.__all__`` and in the ``__all__`` of
the public modules (:data:`MODULES`, and the modules of ``pentanb.viz.__all__``
if it has one); for a class, its public methods (the ones defined in
``pentanb``, properties left out: they are attributes).
Each function or method must have a docstring with

* a ``Parameters`` section when it takes parameters (``self`` and ``cls``
  aside);
* a ``Returns`` (or ``Yields``) section unless its return annotation is
  ``None`` (a function without a return annotation needs one: it may
  return something).

A section is a title line followed by a line of dashes, as numpydoc writes
it.  The functions of modules whose owners have not documented them yet are
listed in :data:`PENDING` and expected to fail (strictly: one that passes
must leave the list).
"""

from __future__ import annotations

import importlib
import inspect
import itertools
import re
from collections.abc import Callable, Iterator

import pytest

import pentanb

#: Public modules walked besides ``pentanb`` itself (each by its ``__all__``).
MODULES = (
    "pentanb.io",
    "pentanb.shapes",
    "pentanb.topology",
    "pentanb.analysis",
    "pentanb.notation",
    "pentanb.figures",
    "pentanb.classroom",
)

#: Public names whose modules others own, not documented yet: expected to fail.
#: Empty it as they are documented (a name here that passes fails the run).
PENDING: set[str] = set()

_HEADER = re.compile(r"^-{3,}$")


def sections(doc: str) -> set[str]:
    """The numpydoc section titles of a docstring.

    Parameters
    ----------
    doc : str
        A docstring, cleaned (:func:`inspect.cleandoc`) or not.

    Returns
    -------
    set of str
        Every line followed by a line of (at least three) dashes.
    """
    lines = [line.strip() for line in inspect.cleandoc(doc).splitlines()]
    return {a for a, b in itertools.pairwise(lines) if a and _HEADER.match(b)}


def _returns_none(annotation: object) -> bool:
    """The return annotation says the function returns nothing."""
    return annotation is None or annotation is type(None) or annotation == "None"


def problems(func: Callable, method: bool = False) -> list[str]:
    """What the docstring of ``func`` misses.

    Parameters
    ----------
    func : callable
        A function, a bound method, or a function from a class body.
    method : bool
        ``func`` is a function from a class body: its first parameter is
        ``self`` and needs no documentation.

    Returns
    -------
    list of str
        Empty when the docstring is complete.
    """
    doc = inspect.getdoc(func)
    if not doc:
        return ["no docstring"]
    found = sections(doc)
    out = []
    sig = inspect.signature(func)
    params = list(sig.parameters)[1:] if method else list(sig.parameters)
    if params and "Parameters" not in found:
        out.append("no Parameters section")
    if not _returns_none(sig.return_annotation) and not found & {"Returns", "Yields"}:
        out.append("no Returns (or Yields) section")
    return out


def _methods(cls: type) -> Iterator[tuple[str, Callable, bool]]:
    """The public methods of a class defined in pentanb (properties left out).

    Yields (name, callable, whether its first parameter is ``self``): class
    methods come bound to the class, static methods as they are.
    """
    seen: set[str] = set()
    for klass in cls.__mro__:
        if not klass.__module__.startswith("pentanb"):
            continue
        for name, member in vars(klass).items():
            if name.startswith("_") or name in seen:
                continue
            seen.add(name)
            if isinstance(member, (staticmethod, classmethod)):
                yield name, getattr(cls, name), False
            elif inspect.isfunction(member):
                yield name, member, True


def _public(module: str, names: list[str]) -> Iterator[tuple[str, object]]:
    mod = importlib.import_module(module)
    for name in names:
        if module == "pentanb" and name in pentanb._LAZY:
            yield f"{module}.{name}", None  # a drawing function: resolved in the test
            continue
        yield f"{module}.{name}", getattr(mod, name)


def api() -> dict[str, tuple[Callable | None, bool]]:
    """Every public function and method, by its first public name.

    Returns
    -------
    dict
        ``{"pentanb.subdivide": (function, False), "pentanb.Mesh.with_vertices":
        (function, True), ...}``: the callable and whether it is a function
        from a class body (its ``self`` needs no documentation).  The lazily
        imported drawing functions of ``pentanb`` (ipywidgets, pythreejs)
        map to None and are imported by the test.  A function reachable
        under several names appears once, under the first.
    """
    names = [("pentanb", [n for n in pentanb.__all__ if n not in ("figures", "analysis")])]
    names += [(m, list(importlib.import_module(m).__all__)) for m in MODULES]
    # the drawing modules, if pentanb.viz ever lists some (today it imports none)
    for sub in getattr(importlib.import_module("pentanb.viz"), "__all__", ()):
        module = f"pentanb.viz.{sub}"
        names.append((module, list(importlib.import_module(module).__all__)))
    out: dict[str, tuple[Callable | None, bool]] = {}
    seen: set[int] = set()
    for module, public in names:
        for path, obj in _public(module, public):
            if obj is None:
                out[path] = (None, False)
            elif inspect.ismodule(obj) or id(obj) in seen:
                continue
            elif inspect.isclass(obj):
                seen.add(id(obj))
                for name, method, in_body in _methods(obj):
                    key = getattr(method, "__func__", method)
                    if id(key) not in seen:
                        seen.add(id(key))
                        out[f"{path}.{name}"] = (method, in_body)
            elif callable(obj):
                seen.add(id(obj))
                out[path] = (obj, False)
    return out


API = api()


def _param(path: str):
    if path in PENDING:
        return pytest.param(path, marks=pytest.mark.xfail(strict=True, reason="pending its owner"))
    return path


@pytest.mark.parametrize("path", [_param(p) for p in API])
def test_public_function_has_numpydoc_sections(path):
    func, method = API[path]
    if func is None:
        pytest.importorskip("ipywidgets")
        pytest.importorskip("pythreejs")
        func = getattr(pentanb, path.rsplit(".", 1)[1])
    assert problems(func, method) == [], path


def test_pending_names_are_public():
    """No stale entry: every pending name is still part of the public API."""
    assert PENDING <= set(API), sorted(PENDING - set(API))


def test_the_walk_finds_the_api():
    assert {"pentanb.subdivide", "pentanb.Mesh.from_csr", "pentanb.io.read_obj"} <= set(API)
    assert "pentanb.figures.figure1" in API and "pentanb.analysis.ring_contraction" in API
    assert "pentanb.explore" in API  # lazy: resolved by the test
    assert not any(p.rsplit(".", 1)[1].startswith("_") for p in API)


# ---------------------------------------------------------------------- the check itself
def test_a_function_without_sections_is_flagged():
    def bad(mesh, iterations=1):
        """Subdivide ``mesh``, said in prose only."""
        return mesh

    assert problems(bad) == ["no Parameters section", "no Returns (or Yields) section"]

    def undocumented(x) -> None:
        pass

    assert problems(undocumented) == ["no docstring"]


def test_sections_are_read_from_their_dashes():
    def good(mesh, iterations=1) -> int:
        """Count.

        Parameters
        ----------
        mesh : Mesh
        iterations : int

        Returns
        -------
        int
        """
        return iterations

    def only_mentioned(mesh) -> int:
        """Parameters: mesh.  Returns: a number (no dashes: not sections)."""
        return 1

    def generator(n: int) -> Iterator[int]:
        """Count up.

        Parameters
        ----------
        n : int

        Yields
        ------
        int
        """
        yield from range(n)

    def no_arguments() -> None:
        """Nothing in, nothing out: no section needed."""

    assert problems(good) == [] and problems(generator) == [] and problems(no_arguments) == []
    assert problems(only_mentioned) == [
        "no Parameters section",
        "no Returns (or Yields) section",
    ]


def test_methods_count_their_parameters_without_self():
    class Thing:
        def size(self) -> int:
            """The size.

            Returns
            -------
            int
            """
            return 1

        def grow(self, by) -> None:
            """Grow, undocumented argument."""

        @classmethod
        def make(cls) -> Thing:
            """Make one.

            Returns
            -------
            Thing
            """
            return cls()

    assert problems(Thing().size) == [] and problems(Thing.make) == []
    assert problems(Thing.size, method=True) == []  # as the walk sees it: self aside
    assert problems(Thing().grow) == ["no Parameters section"]
    assert problems(Thing.grow, method=True) == ["no Parameters section"]
    assert [name for name, _, _ in _methods(pentanb.Mesh)]  # the walk sees methods
