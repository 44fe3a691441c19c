"""Tests of :mod:`pentanb.analysis.measures`: exact answers on small meshes worked
out by hand, and the vectorized configurations against a slow Python walk."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import pentanb
from pentanb import analysis, shapes
from pentanb.analysis import (
    canonical_configuration,
    configuration_counts,
    edge_waviness,
    face_configurations,
    normal_angles,
    radius_spread,
    ray_distances,
    vertex_configurations,
)
from pentanb.analysis.measures import (
    BOX_EDGES,
    angle_spread,
    corner_angles,
    crease_angles,
    edge_length_spread,
    edge_lengths,
    edge_profile,
    face_planarity,
    lateral_amplitude,
    region_geometry,
    uniformity,
)


# ---------------------------------------------------------------------- small meshes
def square_pyramid() -> pentanb.Mesh:
    """Apex 4 over the square 0-3: one quad, four triangles."""
    v = [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0], [0, 0, 1.5]]
    return shapes.outward(v, [[0, 1, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])


def triangular_prism() -> pentanb.Mesh:
    """A regular triangle extruded along z: two triangles, three squares."""
    t = 2 * np.pi * np.arange(3) / 3
    ring = np.stack([np.cos(t), np.sin(t)], axis=1)
    v = np.concatenate([np.column_stack([ring, -np.ones(3)]), np.column_stack([ring, np.ones(3)])])
    faces = [[0, 1, 2], [3, 4, 5]] + [[i, (i + 1) % 3, 3 + (i + 1) % 3, 3 + i] for i in range(3)]
    return shapes.outward(v, faces)


def cuboctahedron() -> pentanb.Mesh:
    """The 12 points (+-1, +-1, 0) and permutations: 8 triangles, 6 squares."""
    v = np.array(
        [np.insert(p, a, 0.0) for a in range(3) for p in itertools.product((-1.0, 1.0), repeat=2)]
    )
    faces = []
    for axis, sign in itertools.product(range(3), (-1, 1)):
        ids = np.flatnonzero(v[:, axis] == sign)
        other = [k for k in range(3) if k != axis]
        angle = np.arctan2(v[ids, other[1]], v[ids, other[0]])
        faces.append(ids[np.argsort(angle)].tolist())
    for s in itertools.product((-1, 1), repeat=3):
        corners = [(s[0], s[1], 0), (s[0], 0, s[2]), (0, s[1], s[2])]
        faces.append([int(np.flatnonzero((v == c).all(axis=1))[0]) for c in corners])
    return shapes.outward(v, faces)


# ---------------------------------------------------------------------- configurations
def test_configurations_of_a_cube():
    cube = shapes.cube()
    assert vertex_configurations(cube) == ["4.4.4"] * 8
    assert face_configurations(cube) == ["3.3.3.3"] * 6


def test_configurations_of_a_cuboctahedron():
    m = cuboctahedron()
    assert (m.n_vertices, m.n_edges, m.n_faces) == (12, 24, 14)
    assert vertex_configurations(m) == ["3.4.3.4"] * 12  # triangle, square, triangle, square
    assert configuration_counts(face_configurations(m)) == {"4.4.4": 8, "4.4.4.4": 6}


def test_configurations_of_a_square_pyramid():
    m = square_pyramid()
    assert vertex_configurations(m) == ["3.3.4"] * 4 + ["3.3.3.3"]
    # the square's corners are 3-valent; a triangle has the apex (4) and two corners
    assert face_configurations(m) == ["3.3.3.3"] + ["3.3.4"] * 4


def test_configurations_of_a_triangular_prism():
    m = triangular_prism()
    assert vertex_configurations(m) == ["3.4.4"] * 6
    assert face_configurations(m) == ["3.3.3"] * 2 + ["3.3.3.3"] * 3


def test_configurations_of_the_pentagonalized_cube():
    # every pentagon: one cube corner, three edge points (all 3-valent) and a
    # face centre (4-valent); vertices: 32 of valence 3 and 6 of valence 4
    m = pentanb.pentagonalize(shapes.cube())
    assert configuration_counts(face_configurations(m)) == {"3.3.3.3.4": 24}
    assert configuration_counts(vertex_configurations(m)) == {"5.5.5": 32, "5.5.5.5": 6}


def test_canonical_configuration():
    assert canonical_configuration("4.3.3.4.3") == "3.3.4.3.4"
    assert canonical_configuration("3.4.3.4.3") == "3.3.4.3.4"
    assert canonical_configuration("6.3.3.3.3") == "3.3.3.3.6"
    assert canonical_configuration([4, 6, 8]) == "4.6.8"
    assert canonical_configuration([4, 8, 6]) == "4.6.8"  # a reflection
    assert canonical_configuration("4.3.4.3") == "3.4.3.4"


def test_configuration_counts_most_frequent_first_ties_by_name():
    assert configuration_counts(["5.5.5", "3.3.3", "5.5.5"]) == {"5.5.5": 2, "3.3.3": 1}
    assert list(configuration_counts(["4.4.4", "3.3.3"])) == ["3.3.3", "4.4.4"]
    assert configuration_counts([]) == {}


def _canon(seq):
    seq = list(seq)
    n = len(seq)
    cands = [seq[i:] + seq[:i] for i in range(n)]
    cands += [list(reversed(c)) for c in cands]
    return ".".join(map(str, min(cands)))


def _slow_vertex_configs(mesh):
    """Walk every vertex's faces in Python (reference for the vectorized version)."""
    twin, face = mesh.twin, mesh.halfedge_face
    prev = mesh.prev
    out = {}
    for h in range(mesh.n_halfedges):
        v = int(mesh.corners[h])
        if v in out:
            continue
        sizes, g = [], h
        while True:
            sizes.append(int(mesh.face_sizes[face[g]]))
            g = int(twin[prev[g]])
            if g == h:
                break
        out[v] = _canon(sizes)
    return [out[v] for v in range(mesh.n_vertices)]


def _slow_face_configs(mesh):
    return [_canon(mesh.valences[f].tolist()) for f in mesh.faces]


@pytest.mark.parametrize("shape", ["cube", "icosahedron", "torus", "hexagonal_genus2", "animal"])
def test_configurations_match_slow_reference(shape):
    mesh = pentanb.preserve_pentagons(shapes.get(shape))
    assert vertex_configurations(mesh) == _slow_vertex_configs(mesh)
    assert face_configurations(mesh) == _slow_face_configs(mesh)


def test_dual_swaps_vertex_and_face_configurations():
    mesh = pentanb.subdivide(shapes.hard_edged_cube(1 / 3), "preserve_pentagons", 1, 2)
    assert sorted(face_configurations(mesh)) == sorted(vertex_configurations(pentanb.dual(mesh)))


# ---------------------------------------------------------------------- geometry
def test_radius_spread_by_hand():
    assert radius_spread(shapes.icosahedron()) == pytest.approx(0.0, abs=1e-12)
    assert radius_spread(shapes.cube()) == pytest.approx(0.0, abs=1e-12)
    # an octahedron stretched to +-2 along x: radii 2, 2, 1, 1, 1, 1 about the
    # centroid 0; mean 4/3, std sqrt(2 - 16/9) = sqrt(2)/3, ratio sqrt(2)/4
    m = shapes.octahedron()
    stretched = m.with_vertices(m.vertices * [2.0, 1.0, 1.0])
    assert radius_spread(stretched) == pytest.approx(np.sqrt(2) / 4, rel=1e-12)


def test_radius_spread_ignores_position_and_scale():
    m = shapes.torus()
    moved = m.with_vertices(3.0 * m.vertices + [5.0, -2.0, 1.0])
    assert radius_spread(moved) == pytest.approx(radius_spread(m), rel=1e-12)


def test_normal_angles_of_a_cube_are_right_angles():
    a = normal_angles(shapes.cube())
    assert a.shape == (12,)
    assert np.allclose(a, 90.0)


def test_normal_angles_of_a_triangular_prism():
    # side squares meet at 120 degrees between normals (the triangle's exterior
    # angle); squares and triangles at 90
    a = np.sort(normal_angles(triangular_prism()))
    assert np.allclose(a, [90.0] * 6 + [120.0] * 3)


def test_normal_angles_of_an_icosahedron():
    # dihedral angle of the icosahedron: 138.19 deg, so normals differ by 41.81 deg
    a = normal_angles(shapes.icosahedron())
    assert np.allclose(a, 180.0 - np.degrees(np.arccos(-np.sqrt(5) / 3)))


def test_normal_angles_match_a_loop_over_edges():
    mesh = pentanb.preserve_pentagons(shapes.torus(6, 4))
    n = mesh.face_normals
    slow = {}
    for h in range(mesh.n_halfedges):
        e = int(mesh.halfedge_edge[h])
        f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
        slow[e] = np.degrees(np.arccos(np.clip(n[f] @ n[g], -1, 1)))
    fast = normal_angles(mesh)
    # (arccos amplifies rounding next to 0 degrees)
    assert np.allclose(fast, [slow[e] for e in range(mesh.n_edges)], atol=1e-5)


def test_ray_distances_by_hand():
    cube = shapes.cube()
    d = np.array([1.0, 0.3, 0.2])
    d /= np.linalg.norm(d)
    assert ray_distances(cube, np.zeros((1, 3)), d) == pytest.approx([1.0 / d[0]])
    got = ray_distances(cube, [[0.1, 0.2, 0.0], [0.0, 0.0, 0.5]], [0.0, 0.0, 1.0])
    assert got == pytest.approx([1.0, 0.5])
    # the octahedron |x| + |y| + |z| = 1 along the diagonal: 1/sqrt(3)
    diag = np.ones(3) / np.sqrt(3)
    assert ray_distances(shapes.octahedron(), [[0.0, 0.0, 0.0]], diag) == pytest.approx(
        [1 / np.sqrt(3)]
    )


def test_ray_that_misses_is_nan():
    got = ray_distances(shapes.cube(), [[0.0, 0.0, 5.0], [0.0, 0.0, 0.0]], [0.0, 0.0, 1.0])
    assert np.isnan(got[0]) and got[1] == pytest.approx(1.0)


def test_edge_waviness_by_hand():
    cube = shapes.cube()
    # the default probe: rays towards the straight edge y = z = 1: no wave
    assert edge_waviness(cube) == pytest.approx(0.0, abs=1e-12)
    # rays up (+z) from a segment rising from z = -0.25 to 0.25: distances 1.25 .. 0.75
    w = edge_waviness(cube, (-0.5, 0.0, -0.25), (0.5, 0.0, 0.25), (0.0, 0.0, 1.0))
    assert w == pytest.approx(0.5, rel=1e-12)


def test_edge_waviness_sees_a_bent_edge():
    cube = shapes.hard_edged_cube(1 / 3)
    assert edge_waviness(cube) == pytest.approx(0.0, abs=1e-9)
    v = cube.vertices.copy()
    ridge = (v[:, 1] == 1) & (v[:, 2] == 1)
    v[ridge, 1:] += 0.05 * np.cos(np.pi * v[ridge, 0])[:, None]  # bend the edge
    assert edge_waviness(cube.with_vertices(v)) > 0.02


#: The measures ``pentanb.analysis`` re-exports (the later ones are imported from
#: :mod:`pentanb.analysis.measures`).
REEXPORTED = (
    "vertex_configurations",
    "face_configurations",
    "canonical_configuration",
    "configuration_counts",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
)


def test_analysis_reexports_the_measures_and_old_paths_work():
    from pentanb.analysis import convergence as cv
    from pentanb.analysis import measures

    for name in REEXPORTED:
        assert getattr(analysis, name) is getattr(measures, name), name
    for name in measures.__all__:
        assert callable(getattr(measures, name)) or name == "BOX_EDGES", name
    # the notebooks' import path
    assert cv.radius_spread is radius_spread and cv.edge_waviness is edge_waviness
    assert cv.normal_angles is normal_angles and cv.ray_distances is ray_distances


# ---------------------------------------------------------------------- uniformity
def test_edge_lengths_and_spread_by_hand():
    cube = shapes.cube()
    assert np.allclose(edge_lengths(cube), 2.0)
    assert edge_length_spread(cube) == pytest.approx(0.0, abs=1e-15)
    # the prism: 6 triangle edges of sqrt(3) (unit circle), 3 vertical edges of 2
    m = triangular_prism()
    lengths = np.sort(edge_lengths(m))
    assert np.allclose(lengths, [3**0.5] * 6 + [2.0] * 3)
    x = np.array([3**0.5] * 6 + [2.0] * 3)
    assert edge_length_spread(m) == pytest.approx(x.std() / x.mean(), rel=1e-12)
    # only the edges of face 0 (a triangle): all equal
    assert edge_length_spread(m, [0]) == pytest.approx(0.0, abs=1e-12)


def test_corner_angles_by_hand():
    m = square_pyramid()
    a = corner_angles(m)
    assert a.shape == (m.n_halfedges,)
    square = a[m.halfedge_face == 0]
    assert np.allclose(square, 90.0)
    # every planar face's angles add up to (n - 2) 180
    sums = np.bincount(m.halfedge_face, weights=a)
    assert np.allclose(sums, (m.face_sizes - 2) * 180.0)


def test_angle_spread_groups_by_face_size_or_valence():
    # the prism: triangles 60 degrees, squares 90: each group equal
    m = triangular_prism()
    assert angle_spread(m) == pytest.approx(0.0, abs=1e-12)
    # grouped by valence (all 3-valent) they differ: 6 corners of 60, 12 of 90
    ang = np.array([60.0] * 6 + [90.0] * 12)
    assert angle_spread(m, by="valence") == pytest.approx(ang.std() / ang.mean(), rel=1e-9)
    with pytest.raises(ValueError, match="by must be"):
        angle_spread(m, by="colour")


def test_uniformity_is_zero_on_platonic_solids_and_scale_free():
    for name in ("tetrahedron", "cube", "dodecahedron", "icosahedron"):
        u = uniformity(shapes.get(name))
        assert max(u.values()) < 1e-12, (name, u)
    m = pentanb.pentagonalize(shapes.cube())
    big = m.with_vertices(3 * m.vertices + 1)
    assert uniformity(big) == pytest.approx(uniformity(m))


def test_face_planarity_by_hand():
    cube = shapes.cube()
    assert np.allclose(face_planarity(cube), 0.0)
    v = cube.vertices.copy()
    v[7, 2] += 0.4  # (1, 1, 1) lifted: only the top face bends (the sides hold z)
    flat = face_planarity(cube.with_vertices(v), "face")
    assert (flat > 1e-3).sum() == 1 and flat[flat > 1e-3][0] < 0.4 / 2
    # a twisted square, corners alternately 0.1 above and below z = 0: its
    # least-squares plane is z = 0, every corner 0.1 from it; its sides ~2 long
    sq = np.array([[1, 1, 0.1], [-1, 1, -0.1], [-1, -1, 0.1], [1, -1, -0.1]], dtype=float)
    pyramid = shapes.outward(
        np.vstack([sq, [[0, 0, -2.0]]]), [[0, 1, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    )
    got = face_planarity(pyramid, "face")[0]
    assert got == pytest.approx(0.1 / np.mean(np.linalg.norm(sq - np.roll(sq, -1, 0), axis=1)))
    with pytest.raises(ValueError, match="relative_to"):
        face_planarity(cube, "edge")


def test_region_geometry_of_a_cuboctahedron():
    m = cuboctahedron()
    squares = np.flatnonzero(m.face_sizes == 4)
    g = region_geometry(m, squares)
    assert g["faces"] == 6
    assert g["angle_spread"] == pytest.approx(0.0, abs=1e-12)
    assert g["planarity"] == pytest.approx(0.0, abs=1e-12)
    assert g["edge_spread"] == pytest.approx(0.0, abs=1e-12)
    assert g["angles"] == pytest.approx({4: 90.0})
    with pytest.raises(ValueError, match="at least one face"):
        region_geometry(m, [])


# ---------------------------------------------------------------------- creases
def test_crease_angles_at_marked_vertices_and_elsewhere():
    m = triangular_prism()  # 90 between triangle and squares, 120 between squares
    c = crease_angles(m, [0])  # vertex 0: one triangle edge pair (90) and a vertical edge (120)
    assert c["at"] == pytest.approx(120.0) and c["elsewhere"] == pytest.approx(120.0)
    top = crease_angles(m, np.isin(np.arange(6), [3, 4, 5]))  # the top triangle's corners
    assert top["at"] == pytest.approx(120.0)
    # the edges away from the top: the bottom triangle's sides only (90)
    assert top["elsewhere"] == pytest.approx(90.0)
    everything = crease_angles(m, np.ones(6, dtype=bool))
    assert np.isnan(everything["elsewhere"])
    with pytest.raises(ValueError, match="one entry per vertex"):
        crease_angles(m, np.ones(3, dtype=bool))
    with pytest.raises(ValueError, match="out of range"):
        crease_angles(m, [6])


# ---------------------------------------------------------------------- lateral artifact
def test_edge_profile_of_a_plain_box_is_the_corner_distance():
    box = shapes.box(4)
    for edge in BOX_EDGES:
        x, r = edge_profile(box, edge, 45.0)
        assert np.all(np.diff(x) >= 0)
        inside = np.abs(x) < 1 - 1e-9  # (at x = +-1 the plane also cuts the end faces)
        assert np.allclose(r[inside], 2**0.5)  # the edge itself, sqrt(2) from the axis
        assert x.min() == pytest.approx(-1.0) and x.max() == pytest.approx(1.0)
    # at 40 degrees the plane meets the face y = 1 at 1 / cos(40) from the axis
    x, r = edge_profile(box, (0, 1, 1), 40.0)
    assert np.allclose(r[np.abs(x) < 1 - 1e-9], 1 / np.cos(np.radians(40)))


def test_lateral_amplitude_by_hand():
    box = shapes.box(6)
    assert lateral_amplitude(box, 2 / 3).max() < 1e-12
    # a box twice as big, measured with half = 2: still no wave
    big = box.with_vertices(2 * box.vertices)
    assert lateral_amplitude(big, 4 / 3, half=2.0).max() < 1e-12
    # push the middle grid vertex of one edge inwards along the bisector by d:
    # the profile at 45 degrees dips by d
    v = box.vertices.copy()
    k = int(np.flatnonzero(np.isclose(v, [0, -1, 1]).all(axis=1))[0])  # edge (0, -1, 1)
    d = 0.01
    v[k] += d * np.array([0, 1, -1]) / 2**0.5
    amp = lateral_amplitude(box.with_vertices(v), 2 / 3, angles=(45.0,))
    edge = BOX_EDGES.index((0, -1, 1))
    assert amp[edge] == pytest.approx(d, rel=1e-9)
    assert np.delete(amp, edge).max() < 1e-12


def test_lateral_measures_refuse_bad_arguments():
    box = shapes.box(3)
    with pytest.raises(ValueError, match="window"):
        lateral_amplitude(box, 1.5)
    with pytest.raises(ValueError, match="from 35 to 55"):
        lateral_amplitude(box, 0.3, angles=(20.0,))
    with pytest.raises(ValueError, match="from 35 to 55"):
        edge_profile(box, (0, 1, 1), 80.0)
    with pytest.raises(ValueError, match="BOX_EDGES"):
        edge_profile(box, (0, 2, 1))
    with pytest.raises(ValueError, match="does not cross"):
        lateral_amplitude(shapes.tetrahedron(), 0.3)
