"""The exercises of notebooks 01-11, each with its checker and expected answer.

Every checker takes the student's answer and returns None when it is right,
else a hint that never gives the answer away; the expected answers are
computed by the package (:func:`pentanb.predict_counts`,
:mod:`pentanb.topology`, :mod:`pentanb.analysis`) where that is the point
of the exercise.  Importing the module registers them in
:data:`pentanb.classroom.EXERCISES`.
"""

from __future__ import annotations

import functools
import io
import math
from collections.abc import Iterable
from fractions import Fraction
from typing import Any

import numpy as np

from .. import shapes, topology
from ..mesh import Mesh, MeshError
from ..schemes import SCHEMES, dual, pentagonalize
from ..subdivision import predict_counts, subdivide
from ._answers import (
    MAX_FACES,
    _call,
    _compare_counts,
    _counts,
    _exercise,
    _fmt_hist,
    _letter,
    _mesh,
    _name,
    _number,
    _predicted,
    _same_mesh,
    _short,
    _topology,
    _vef,
    _whole,
)

# --------------------------------------------------------------------------------------
# 01 topology
# --------------------------------------------------------------------------------------


@_exercise("01.1", "predict", "(v, e, f) of a sphere of pentagons with 26 vertices")
def _ex_01_1(answer: Any) -> str | None:
    given = _counts(answer, "(v, e, f)")
    expected = topology.ngon_mesh_counts(5, 0, 26)
    assert expected is not None
    if given[0] != 26:
        return "v is given: the mesh has 26 vertices"
    _, e, f = given
    if 2 * e != 5 * f:
        return "every face has 5 sides and every edge is shared by two faces: 2e = 5f"
    return _compare_counts(given, expected, 2)


@_exercise("01.2", "explain", "largest v of a heptagonal mesh of genus 3")
def _ex_01_2(answer: Any) -> str | None:
    v = _whole(answer)
    r = topology.vertex_range(7, 3)
    assert r is not None
    if v == r[1]:
        return None
    if topology.ngon_mesh_counts(7, 3, v) is None:
        return f"at v = {v}, e and f are not whole numbers: no such mesh"
    if v > r[1]:
        return f"at v = {v} the average valence m is below 3: watch the dot against m = 3"
    return f"at v = {v} the mesh is possible, but there are larger ones: keep moving v"


@_exercise("01.3", "find", "a pentagonal mesh with a whole-number average valence")
def _ex_01_3(answer: Any) -> str | None:
    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {5}:
        return f"every face must be a pentagon; this mesh has faces {_fmt_hist(sizes)}"
    if (2 * mesh.n_edges) % mesh.n_vertices == 0:
        return None
    m = 2 * mesh.n_edges / mesh.n_vertices
    return (
        f"its average valence 2E/V is {m:.4f}; equation (1) for a sphere of pentagons: "
        "which v makes m a whole number?"
    )


# --------------------------------------------------------------------------------------
# 02 tetrahedron to dodecahedron
# --------------------------------------------------------------------------------------


@_exercise("02.1", "predict", "(V, E, F) of the pentagonalized icosahedron")
def _ex_02_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((12, 30, 20), "pentagonalize", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint and given[2] != expected[2]:
        hint += "; every n-gon becomes n pentagons"
    return hint


@functools.lru_cache(maxsize=1)
def _odd_duals_letter() -> str:
    hist = subdivide(shapes.tetrahedron(), "pentagonalize", 1, 1).face_size_histogram()
    return {5: "a", 3: "b", 4: "c"}[min(hist)]


@_exercise("02.2", "explain", "the faces after an odd number of duals")
def _ex_02_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _odd_duals_letter():
        return None
    return "set the slider to 1, 3 or 5 duals and read the faces printed under the picture"


_PLATONIC = ("tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron")


@_exercise("02.3", "find", "a solid on which two more duals make it less round")
def _ex_02_3(answer: Any) -> str | None:
    from ..analysis import radius_spread

    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        return "give a pair of names: (shape, scheme), like ('cube', 'pentagonalize')"
    shape = _name(answer[0], _PLATONIC, "Platonic solid")
    scheme = _name(answer[1], ("pentagonalize", "preserve_pentagons"), "scheme of the paper")
    base = shapes.get(shape)
    two, four = (radius_spread(subdivide(base, scheme, 1, d)) for d in (2, 4))
    if four > two:
        return None
    return (
        f"there the radius spread falls from {two:.4f} (2 duals) to {four:.4f} (4 duals): "
        "the shape gets rounder; try another solid or the other scheme"
    )


@_exercise("02.4", "extend", "Figure 7(D) as a function: pentagonalize, then two duals")
def _ex_02_4(answer: Any) -> str | None:
    for name in ("tetrahedron", "cube", "torus"):
        base = shapes.get(name)
        mine = _call(answer, base, "fig7d")
        expected = subdivide(base, "pentagonalize", 1, 2)
        if _vef(mine) != _vef(expected):
            return (
                f"on the {name} your function gives {mine}: not the right counts "
                "(pentagonalize once, then count your duals)"
            )
        if not _same_mesh(mine, expected):
            return (
                f"on the {name} the counts are right but the points are elsewhere: "
                "use pentanb.pentagonalize and pentanb.dual as they are"
            )
    return None


# --------------------------------------------------------------------------------------
# 03 cube tilings
# --------------------------------------------------------------------------------------


@_exercise("03.1", "predict", "(V, E, F) after two iterations of pentagon preservation")
def _ex_03_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((8, 12, 6), "preserve_pentagons", 2, 2)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; one step gives V + 3E, 6E, F + 2E, and two duals give back the same counts"
    return hint


@functools.lru_cache(maxsize=1)
def _scale_letter() -> str:
    cube = shapes.cube()
    low, high = (_vef(subdivide(cube, "preserve_pentagons", 1, 2, scale=s)) for s in (0.2, 0.8))
    if low == high:
        return "c"
    return "a" if high[2] > low[2] else "b"


@_exercise("03.2", "explain", "what the scale slider does to V, E and F")
def _ex_03_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _scale_letter():
        return None
    return "pick pentagon preservation, read V, E and F at scale 0.1 and at 0.9, and compare"


@_exercise("03.3", "extend", "Conway's quinto from preserve_pentagons")
def _ex_03_3(answer: Any) -> str | None:
    from ..notation import conway

    for name in ("cube", "tetrahedron", "dodecahedron"):
        base = shapes.get(name)
        mine = _call(answer, base, "quinto")
        expected = conway("q", seed=base)
        if _topology(mine) != _topology(expected):
            return (
                f"on the {name} your function gives {mine}: not quinto's faces "
                "(one step of pentagon preservation, no duals)"
            )
        if not _same_mesh(mine, expected):
            return f"on the {name} the faces are right but the points are not: which scale?"
    return None


# --------------------------------------------------------------------------------------
# 04 torus hexagons
# --------------------------------------------------------------------------------------


@_exercise("04.1", "predict", "(V, E, F) of hexagon preservation on the hexagonal torus")
def _ex_04_1(answer: Any) -> str | None:
    given = _counts(answer)
    torus = shapes.hexagonal_torus()
    expected = _predicted(_vef(torus), "preserve_hexagons", 1, 0)
    hint = _compare_counts(given, expected, 0)
    if hint and given[2] != expected[2]:
        hint += "; every hexagon stays, and every edge adds one"
    return hint


@functools.lru_cache(maxsize=1)
def _genus2_letter() -> str:
    valences = shapes.hexagonal_surface(2).valence_histogram()
    if min(valences) < 3:
        return "c"
    return "b" if max(valences) > 3 else "a"


@_exercise("04.2", "explain", "the valences of a hexagonal mesh of genus 2")
def _ex_04_2(answer: Any) -> str | None:
    if _letter(answer, "abc") == _genus2_letter():
        return None
    return "set the genus to 2 and read the line 'valences:'; equation (1) with n = 6, g = 2"


@_exercise("04.3", "find", "a mesh of hexagons whose pentagonalization is not all 6.3.3.3.3")
def _ex_04_3(answer: Any) -> str | None:
    from ..analysis import configuration_counts, face_configurations

    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {6}:
        return f"every face must be a hexagon; this mesh has faces {_fmt_hist(sizes)}"
    configs = configuration_counts(face_configurations(pentagonalize(mesh)))
    if set(configs) != {"3.3.3.3.6"}:
        return None
    return (
        "on this mesh every pentagon is 6.3.3.3.3 (its vertices are all 3-valent); "
        "equation (1) says which surfaces force some vertices above 3"
    )


# --------------------------------------------------------------------------------------
# 05 soccer balls
# --------------------------------------------------------------------------------------


@_exercise("05.1", "predict", "(V, E, F) of honeycomb on the dodecahedron")
def _ex_05_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((20, 30, 12), "honeycomb", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; the honeycomb's faces come from the old faces and the old vertices"
    return hint


@_exercise("05.2", "find", "a mesh whose honeycomb has a triangle or a quadrilateral")
def _ex_05_2(answer: Any) -> str | None:
    from ..schemes import honeycomb

    mesh = _mesh(answer)
    sizes = honeycomb(mesh).face_size_histogram()
    if min(sizes) < 5:
        return None
    return (
        f"its honeycomb has faces {_fmt_hist(sizes)}, none below 5 sides; "
        "which faces of the input become which faces of the honeycomb?"
    )


@_exercise("05.3", "extend", "honeycomb as the dual of sqrt(3)")
def _ex_05_3(answer: Any) -> str | None:
    from ..schemes import honeycomb, sqrt3_remesh

    for name in ("cube", "tetrahedron", "dodecahedron", "torus"):
        base = shapes.get(name)
        mine = _call(answer, base, "my_honeycomb")
        expected = honeycomb(base)
        if _topology(mine) == _topology(expected):
            continue
        plain = dual(sqrt3_remesh(base))
        extra = (
            " (that is the dual of sqrt(3)'s result; the dual of a scheme works on the dual mesh)"
            if _topology(mine) == _topology(plain)
            else ""
        )
        return (
            f"on the {name}, honeycomb makes faces {_fmt_hist(expected.face_size_histogram())}"
            f", your function {_fmt_hist(mine.face_size_histogram())}{extra}"
        )
    return None


# --------------------------------------------------------------------------------------
# 06 schemes compared
# --------------------------------------------------------------------------------------


@_exercise("06.1", "predict", "(V, E, F) of vertex insertion on the cube")
def _ex_06_1(answer: Any) -> str | None:
    given = _counts(answer)
    expected = _predicted((8, 12, 6), "vertex_insertion", 1, 0)
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; a new point on every edge and in every face, and quads around them"
    return hint


@functools.lru_cache(maxsize=1)
def _most_faces() -> frozenset[str]:
    tet = _vef(shapes.tetrahedron())
    faces = {s: predict_counts(tet, s, 2, 0)[-1][2] for s in SCHEMES}
    most = max(faces.values())
    return frozenset(s for s, f in faces.items() if f == most)


@_exercise("06.2", "explain", "the scheme with the most faces on the tetrahedron")
def _ex_06_2(answer: Any) -> str | None:
    if isinstance(answer, str) and answer.strip() in {s.label for s in SCHEMES.values()}:
        answer = next(s.name for s in SCHEMES.values() if s.label == answer.strip())
    name = _name(answer, SCHEMES, "scheme")
    if name in _most_faces():
        return None
    return "choose the tetrahedron, 2 iterations, 0 duals, and read the faces under each picture"


@functools.lru_cache(maxsize=1)
def _conversion() -> frozenset[str]:
    from ..schemes import loop_remesh

    mixed = loop_remesh(shapes.cube())
    return frozenset(
        s for s in SCHEMES if len(subdivide(mixed, s, 2, 0).face_size_histogram()) == 1
    )


@_exercise("06.3", "explain", "which schemes are conversion schemes")
def _ex_06_3(answer: Any) -> str | None:
    if isinstance(answer, str) or not isinstance(answer, Iterable):
        return "give the schemes' names as a list of strings, like ['loop_remesh', 'honeycomb']"
    names = {_name(a, SCHEMES, "scheme") for a in answer}
    expected = _conversion()
    if names == expected:
        return None
    extra, missing = len(names - expected), len(expected - names)
    parts = []
    if extra:
        parts.append(f"{extra} of yours {'is' if extra == 1 else 'are'} not a conversion scheme")
    if missing:
        parts.append(f"{missing} {'is' if missing == 1 else 'are'} missing")
    return "; ".join(parts) + " (a conversion scheme leaves one kind of face)"


@_exercise("06.4", "find", "a mesh on which triangulate's count formula does not hold")
def _ex_06_4(answer: Any) -> str | None:
    from ..schemes import triangulate

    mesh = _mesh(answer)
    V, E, F = _vef(mesh)
    if _vef(triangulate(mesh)) != (V + F, 3 * E, 2 * E):
        return None
    return "on this mesh triangulate gives exactly V + F, 3E, 2E; what does it do to a triangle?"


def _heptagon_hint(table: Any) -> str | None:
    """None when ``table`` makes only heptagons on a cube and a tetrahedron, else a hint."""
    from ..schemes.table import Table

    if not isinstance(table, Table):
        return "give a pentanb.Table, like pentanb.Table('mine', edge_points=..., faces=...)"
    for name in ("cube", "tetrahedron"):
        mesh = shapes.get(name)
        faces = table.counts(*_vef(mesh))[2]
        if faces > MAX_FACES:
            return f"on the {name} your table makes {faces:,} faces: a smaller table will do"
        sizes = table(mesh).face_size_histogram()
        if set(sizes) != {7}:
            return (
                f"on the {name} its faces are {_fmt_hist(sizes)}: every kind of face needs "
                "7 corners on every mesh (a 'face' kind copies the input's face sizes)"
            )
    return None


@_exercise("06.5", "extend", "a table whose every face is a heptagon")
def _ex_06_5(answer: Any) -> str | None:
    return _heptagon_hint(answer)


# --------------------------------------------------------------------------------------
# 07 complex model
# --------------------------------------------------------------------------------------


@_exercise("07.1", "predict", "the number of pentagons of the pentagonalized rabbit")
def _ex_07_1(answer: Any) -> str | None:
    given = _whole(answer)
    rabbit = shapes.rabbit()
    expected = predict_counts(rabbit, "pentagonalize", 1, 0)[0][2]
    if given == expected:
        return None
    return "every n-gon becomes n pentagons: add up the sides of the rabbit's faces"


@functools.lru_cache(maxsize=1)
def _rabbit_others() -> int:
    mesh = subdivide(shapes.rabbit(), "preserve_pentagons", 1, 2)
    return sum(c for n, c in mesh.face_size_histogram().items() if n != 5)


@_exercise("07.2", "explain", "the rabbit's non-pentagons under pentagon preservation")
def _ex_07_2(answer: Any) -> str | None:
    if _whole(answer) == _rabbit_others():
        return None
    return (
        "choose pentagon preservation and read the faces of the result (faces={...}) "
        "at 1, 2 and 3 iterations: count the faces that are not pentagons"
    )


@_exercise("07.3", "find", "an OBJ file whose pentagonalization has a vertex of valence 6")
def _ex_07_3(answer: Any) -> str | None:
    from ..io import read

    if not isinstance(answer, str):
        return "give the text of an OBJ file, as a string (lines 'v x y z' and 'f i j k ...')"
    try:
        mesh = read(io.BytesIO(answer.encode("utf-8")), format="obj")
    except (MeshError, ValueError) as exc:
        return f"pentanb.read refuses it: {_short(exc)}"
    if not mesh.is_closed:
        return "the mesh has boundary edges: close it (every edge in two faces)"
    if mesh.n_faces > MAX_FACES:
        return f"use a smaller mesh: this one has {mesh.n_faces:,} faces"
    top = max(pentagonalize(mesh).valence_histogram())
    if top >= 6:
        return None
    return (
        f"its pentagonalization has valences up to {top}; which of the input's vertices "
        "and faces keep or give their valence?"
    )


# --------------------------------------------------------------------------------------
# 08 convergence
# --------------------------------------------------------------------------------------


@functools.lru_cache(maxsize=1)
def _preservation_rate() -> float:
    steps = predict_counts(shapes.cube(), "preserve_pentagons", 8, 0)
    k = steps[-1][2] / steps[-2][2]  # faces multiply by k per iteration, for large meshes
    return 1 / math.sqrt(k)


@_exercise("08.1", "predict", "the crease factor per iteration of pentagon preservation")
def _ex_08_1(answer: Any) -> str | None:
    value = _number(answer)
    expected = _preservation_rate()
    if abs(value - expected) <= 0.01:
        return None
    if abs(value - expected**2) <= 0.01:
        return "the faces multiply by k, but the edges get only sqrt(k) times shorter"
    if abs(value - 1 / math.sqrt(5)) <= 0.01:
        return "that is pentagonalization's factor: F + 2E grows faster than 2E"
    return "how many times more faces per iteration (k)? then the angle shrinks like 1/sqrt(k)"


@_exercise("08.2", "find", "a mesh on which a second pair of duals sharpens the largest crease")
def _ex_08_2(answer: Any) -> str | None:
    from ..analysis import convergence

    mesh = _mesh(answer)
    if not mesh.is_closed:
        return "use a closed mesh"
    if 5 * mesh.n_edges > MAX_FACES // 2:  # pentagonalize makes 2E faces, twice
        return "use a smaller mesh"
    angles = convergence.dual_convergence(mesh, "pentagonalize", duals=4).max_normal_angle
    if angles[2] > angles[1]:
        return None
    return (
        f"there the largest crease falls from {angles[1]:.1f} (one pair) to {angles[2]:.1f} "
        "degrees (two pairs): try another shape of pentanb.shapes"
    )


@functools.lru_cache(maxsize=1)
def _vertex_insertion_letter() -> str:
    from ..analysis import convergence

    angles = convergence.subdivision_convergence(
        shapes.cube(), "vertex_insertion", 3, 0
    ).max_normal_angle
    if np.allclose(angles, angles[0], atol=1e-6):
        return "b"
    return "a" if angles[-1] < angles[0] else "c"


@_exercise("08.3", "explain", "vertex insertion without duals: the largest crease")
def _ex_08_3(answer: Any) -> str | None:
    if _letter(answer, "abc") == _vertex_insertion_letter():
        return None
    return "choose the cube, vertex insertion, 0 duals, and read the left plot's 'largest' line"


# --------------------------------------------------------------------------------------
# 09 continuity
# --------------------------------------------------------------------------------------


def _table_cases() -> dict[str, tuple[str, dict]]:
    from ..analysis.spectral import TABLE_CASES

    return {label: (scheme, options) for label, scheme, options in TABLE_CASES}


@functools.lru_cache(maxsize=32)
def _spectrum(label: str, kind: str, size: int):
    from ..analysis import local_spectrum

    scheme, options = _table_cases()[label]
    return local_spectrum(scheme, kind, size, **options)


@functools.lru_cache(maxsize=1)
def _triangle_letter() -> str:
    return "b" if _spectrum("preserve_pentagons 0.5", "face", 3).map_obstruction else "a"


@_exercise("09.1", "explain", "pentagon preservation at scale 0.5 around a triangle")
def _ex_09_1(answer: Any) -> str | None:
    if _letter(answer, "ab") == _triangle_letter():
        return None
    return "pick 'preserve_pentagons 0.5', element 'face', 3 sides, and read the right panel"


@functools.lru_cache(maxsize=1)
def _triangle_meeting() -> tuple[Fraction, Fraction]:
    """The scale at which the triangle's leading eigenvalues meet (2 duals), and their
    common modulus per step, established in exact arithmetic by the analysis."""
    from ..analysis.spectral import scale_family, scale_threshold

    threshold = scale_threshold(scale_family("face", 3, 2))
    s = threshold.value
    assert s is not None
    period = threshold.exact_at[s].value  # over one period of two steps
    assert period is not None
    per_step = Fraction(math.isqrt(period.numerator), math.isqrt(period.denominator))
    assert per_step**2 == period
    return Fraction(s), per_step


@_exercise("09.2", "predict", "the common value of the triangle's leading eigenvalues")
def _ex_09_2(answer: Any) -> str | None:
    value = _number(answer)
    scale, expected = _triangle_meeting()
    if abs(value - float(expected)) <= 1e-6:
        return None
    if abs(value - float(scale)) <= 1e-6:
        return "that is the scale: now put it into either eigenvalue"
    if abs(value - float(expected) ** 2) <= 1e-6:
        return "that is over a period of two steps; per step is its square root"
    return "set 11/60 - s/12 equal to (s + 3)/30, solve for s, and put s into either one"


@_exercise("09.3", "find", "an element where Reif's standard setting fails")
def _ex_09_3(answer: Any) -> str | None:
    cases = _table_cases()
    if not isinstance(answer, (tuple, list)) or len(answer) != 3:
        return "give three things: (scheme label, 'vertex' or 'face', valence or sides)"
    label = _name(answer[0], cases, "scheme label of the table")
    kind = _name(answer[1], ("vertex", "face"), "kind of element")
    size = _whole(answer[2])
    if not 3 <= size <= 8:
        return "the valence or number of sides is from 3 to 8"
    sp = _spectrum(label, kind, size)
    if not sp.stationary:
        return f"that element does not survive the scheme: {sp.note}"
    if not sp.standard:
        return None
    return "there the standard setting holds (|lambda1| = |lambda2| > |lambda3|); try another"


# --------------------------------------------------------------------------------------
# 10 Conway notation
# --------------------------------------------------------------------------------------


@_exercise("10.1", "predict", "(V, E, F) of cD")
def _ex_10_1(answer: Any) -> str | None:
    from ..notation import conway

    given = _counts(answer)
    expected = _vef(conway("cD"))
    hint = _compare_counts(given, expected, 2)
    if hint:
        hint += "; chamfer's counts are V + 2E, 4E, F + E"
    return hint


_SEEDS = ("cube", "tetrahedron", "torus", "octahedron")


@_exercise("10.2", "extend", "an operator string other than g that makes only pentagons")
def _ex_10_2(answer: Any) -> str | None:
    from ..notation import conway, reduce_notation

    if not isinstance(answer, str) or not answer.strip():
        return "give an operator string, in quotes, without a seed (like 'dk')"
    text = answer.strip()
    try:
        reduced = reduce_notation(text)
    except (ValueError, TypeError) as exc:
        return f"not a string of operators: {_short(exc)}"
    if reduced == "g":
        return f"{text!r} has the same topology as g itself: find another"
    for name in _SEEDS:
        try:
            mesh = conway(text, seed=shapes.get(name), max_faces=MAX_FACES)
        except (ValueError, TypeError, RuntimeError) as exc:
            return f"on the {name}: {_short(exc)}"
        sizes = mesh.face_size_histogram()
        if set(sizes) != {5}:
            return f"on the {name} it makes faces {_fmt_hist(sizes)}"
    return None


@functools.lru_cache(maxsize=1)
def _canonical_letter() -> str:
    from ..analysis import planarity
    from ..notation import canonical, conway

    mesh = conway("ddgC")
    before, after = planarity(mesh), planarity(canonical(mesh))
    if after < 1e-9:
        return "c"
    return "b" if after < before / 3 else "a"


@_exercise("10.3", "explain", "what canonical positions do to the planarity of ddgC")
def _ex_10_3(answer: Any) -> str | None:
    if _letter(answer, "abc") == _canonical_letter():
        return None
    return "type ddgC, read the planarity, then tick 'canonical positions' and read it again"


# --------------------------------------------------------------------------------------
# 11 open surfaces
# --------------------------------------------------------------------------------------


def _patch() -> Mesh:
    """Notebook 11's patch: a 4 x 3 grid of squares, its middle square left out."""
    vertices = [[x, y, 0.1 * (x - 2) ** 2] for y in range(4) for x in range(5)]
    faces = [
        [y * 5 + x, y * 5 + x + 1, y * 5 + x + 6, y * 5 + x + 5]
        for y in range(3)
        for x in range(4)
        if (x, y) != (1, 1)
    ]
    return Mesh(vertices, faces)


@_exercise("11.1", "predict", "(V, E, F) of the pentagonalized patch with a hole")
def _ex_11_1(answer: Any) -> str | None:
    given = _counts(answer)
    patch = _patch()
    expected = tuple(predict_counts(patch, "pentagonalize", 1, 0)[0])
    hint = _compare_counts(given, expected, patch.euler_characteristic)
    if hint and given[2] != expected[2]:
        hint += "; one pentagon per corner, and the corners add up to 2E - B here"
    return hint


@functools.lru_cache(maxsize=1)
def _disk_loops() -> int:
    disk = shapes.open_disk()
    loops = {
        subdivide(disk, s, k, d).n_boundary_loops
        for s in ("pentagonalize", "preserve_pentagons")
        for k, d in ((1, 0), (2, 2))
    }
    assert len(loops) == 1
    return loops.pop()


@_exercise("11.2", "explain", "the boundary loops after the schemes and the duals")
def _ex_11_2(answer: Any) -> str | None:
    if _whole(answer) == _disk_loops():
        return None
    return "in Explore, read the line 'boundary:' at a few positions of the sliders"


@_exercise("11.3", "find", "a hexagonal mesh of genus 0")
def _ex_11_3(answer: Any) -> str | None:
    mesh = _mesh(answer)
    sizes = mesh.face_size_histogram()
    if set(sizes) != {6}:
        return f"every face must be a hexagon; this mesh has faces {_fmt_hist(sizes)}"
    if mesh.genus != 0:
        return f"this mesh has genus {mesh.genus}; find one of genus 0"
    if mesh.is_closed:
        return "Section 4 rules out a closed hexagonal mesh of genus 0: what else can a mesh be?"
    return None
