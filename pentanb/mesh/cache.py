"""What a :class:`~pentanb.Mesh` derives, cached: the shared connectivity record.

A mesh is immutable, so what it derives never goes stale: a property computed
on first use is kept (:class:`_Derived`).  What depends on the faces alone is
kept in a :class:`_Connectivity` record shared by every mesh with these faces
(the same faces with new positions, the dual of a dual); an operator may hand
over a producer for a property, run once when first asked for, which may
return several values written in one pass (:class:`Several`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Generic, TypeVar, overload

from .coerce import IntArray, frozen

Mesh = Any  # (a pentanb.Mesh: core imports this module)
_T = TypeVar("_T")


class Several(dict):
    """Connectivity values one producer wrote together, by property name.

    A producer handed over for one property (say ``vertex_ring``) may
    return this instead of the value alone: every value in it is cached at
    once (so that one pass can write two arrays that are read together).
    """


class _Connectivity:
    """The faces of a mesh and everything derived from them alone.

    Shared by every mesh with these faces (:meth:`Mesh.with_vertices`, the
    dual of a dual), so each array is derived once for all of them.

    Attributes
    ----------
    corners, offsets : read-only int arrays
        The faces in CSR form.
    values : dict
        Derived arrays (read-only) and numbers, by property name.
    producers : dict
        Zero-argument callables an operator handed over to write a derived
        array on first use (see :meth:`Mesh._new`); each runs at most once
        and is then dropped.
    """

    __slots__ = ("corners", "offsets", "values", "producers")

    def __init__(self, corners: IntArray, offsets: IntArray) -> None:
        self.corners = corners
        self.offsets = offsets
        self.values: dict[str, Any] = {}
        self.producers: dict[str, Callable[[], Any]] = {}


class _Derived(Generic[_T]):
    """A read-only property of a mesh computed on first use and cached.

    With ``connectivity=True`` the value depends on the faces alone and is
    kept in the mesh's shared :class:`_Connectivity`; an operator may have
    handed over a producer for it, which then replaces the computation.
    Otherwise (positions are involved) it is kept by the mesh itself.
    """

    def __init__(self, func: Callable[[Mesh], _T], connectivity: bool) -> None:
        self.func = func
        self.name = func.__name__
        self.connectivity = connectivity
        self.__doc__ = func.__doc__

    @overload
    def __get__(self, mesh: None, owner: type | None = None) -> _Derived[_T]: ...

    @overload
    def __get__(self, mesh: Mesh, owner: type | None = None) -> _T: ...

    def __get__(self, mesh: Mesh | None, owner: type | None = None) -> _T | _Derived[_T]:
        if mesh is None:
            return self
        shared = mesh._shared
        store = shared.values if self.connectivity else mesh._own
        try:
            return store[self.name]
        except KeyError:
            pass
        producer = shared.producers.pop(self.name, None) if self.connectivity else None
        if producer is None:
            value = self.func(mesh)
        else:
            value = producer()
            if isinstance(value, Several):  # several values written in one pass
                for name, made in value.items():
                    if name != self.name:
                        shared.producers.pop(name, None)
                        store.setdefault(name, frozen(made))
                value = value[self.name]
            value = frozen(value)
        store[self.name] = value
        return value


def _connectivity(func: Callable[[Mesh], _T]) -> _Derived[_T]:
    """Decorator: a cached property that depends on the faces alone."""
    return _Derived(func, connectivity=True)


def _geometry(func: Callable[[Mesh], _T]) -> _Derived[_T]:
    """Decorator: a cached property that depends on the vertex positions."""
    return _Derived(func, connectivity=False)
