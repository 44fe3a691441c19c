"""Pictures of open meshes and the cleaner 3D view.

The boundary of an open mesh drawn heavier (3D buffers and widgets, the
matplotlib band), the edges fading on large meshes, the camera looking from
the front with +z up, and a normal per polygon so that a curved pentagon
shows no seams along its fan triangles.  Expected values are worked out here
from the face lists, not by the code under test.
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest

pytest.importorskip("ipywidgets")
pytest.importorskip("pythreejs")
matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from helpers import face_lists  # noqa: E402

import pentanb  # noqa: E402
from pentanb import shapes  # noqa: E402
from pentanb.viz import drawing  # noqa: E402
from pentanb.viz import mpl as vz  # noqa: E402
from pentanb.viz.colors import BOUNDARY_COLOR, hex_to_rgb  # noqa: E402


def boundary_edges_by_hand(mesh):
    """The edges of one face only, as sorted vertex pairs, from the face lists."""
    count = Counter()
    for face in face_lists(mesh):
        for a, b in zip(face, face[1:] + face[:1]):
            count[tuple(sorted((a, b)))] += 1
    return {e for e, c in count.items() if c == 1}


def as_pairs(segments, mesh):
    """Segments (k, 2, 3) as sorted vertex pairs (matched by position)."""
    v = mesh.vertices.astype(np.float32)
    index = {tuple(p): i for i, p in enumerate(v.tolist())}
    return {
        tuple(sorted((index[tuple(s[0].tolist())], index[tuple(s[1].tolist())])))
        for s in np.asarray(segments, dtype=np.float32)
    }


def rotate(q, d):
    """The vector ``d`` turned by the quaternion ``q = (x, y, z, w)``."""
    x, y, z, w = q
    u = np.array([x, y, z])
    d = np.asarray(d, dtype=np.float64)
    return d + 2 * np.cross(u, np.cross(u, d) + w * d)


# ---------------------------------------------------------------------- boundary, 3D
def test_buffers_hold_the_boundary_edges():
    disk = shapes.open_disk()
    b = drawing.mesh_buffers(disk)
    assert b.boundary_count == 30 + 11 + 11
    assert b.boundary().shape == (52, 2, 3) and b.boundary().dtype == np.float32
    assert as_pairs(b.boundary(), disk) == boundary_edges_by_hand(disk)
    # the general path (a Drawing of the mesh) draws the same boundary
    general = drawing.buffers(drawing.drawing(disk))
    assert np.array_equal(general.boundary(), b.boundary())


def test_a_closed_mesh_has_no_boundary_to_draw():
    b = drawing.mesh_buffers(shapes.cube())
    assert b.boundary_count == 0 and b.boundary().shape == (0, 2, 3)
    assert b.boundary_position.shape == (1, 2, 3)  # a hidden placeholder: never empty
    assert drawing.drawing(shapes.cube()).boundary.shape == (0, 2, 3)


def test_view_draws_the_boundary_wide_and_dark_whatever_the_edges():
    disk = shapes.open_disk()
    v = pentanb.view(disk)
    assert v.boundary.visible
    assert v.boundary_material.linewidth == drawing.BOUNDARY_WIDTH >= 3
    assert v.boundary_material.color == BOUNDARY_COLOR
    assert as_pairs(np.asarray(v.boundary_geometry.positions), disk) == boundary_edges_by_hand(disk)
    v.wireframe.value = False  # the edges hidden (linked in the browser): the boundary stays
    assert v.boundary.visible
    v.update(shapes.cube())  # a closed mesh: no boundary
    assert not v.boundary.visible
    finer = pentanb.subdivide(disk, "pentagonalize", 1, 2)
    v.update(finer)
    assert v.boundary.visible and not v.edges.visible  # (the edges' switch is off)
    assert as_pairs(np.asarray(v.boundary_geometry.positions), finer) == (
        boundary_edges_by_hand(finer)
    )


def test_a_closed_view_hides_its_boundary():
    v = pentanb.view(shapes.torus())
    assert not v.boundary.visible


# ---------------------------------------------------------------------- boundary, matplotlib
def test_matplotlib_draws_a_dark_band_outside_every_boundary_edge():
    disk = shapes.open_disk()
    fig = vz.plot_mesh(disk)
    coll = fig.axes[0].collections[0]
    colours = coll.get_facecolor()
    assert len(colours) == disk.n_faces + 52
    # (sorted by depth with the faces: 52 of them in the boundary's colour)
    dark = np.all(np.isclose(colours[:, :3], hex_to_rgb(BOUNDARY_COLOR)), axis=1)
    assert dark.sum() == 52
    band = vz.boundary_band(disk)
    assert band.shape == (52, 4, 3)
    # every quad stands on a boundary edge and reaches away from its face
    assert as_pairs(band[:, :2], disk) == boundary_edges_by_hand(disk)
    faces = face_lists(disk)
    centroid = {}
    for face in faces:
        for a, b in zip(face, face[1:] + face[:1]):
            centroid[(a, b)] = disk.vertices[face].mean(axis=0)
    index = {tuple(p): i for i, p in enumerate(disk.vertices.tolist())}
    for quad in band:
        a, b = index[tuple(quad[0].tolist())], index[tuple(quad[1].tolist())]
        mid = (quad[0] + quad[1]) / 2
        out = (quad[2] + quad[3]) / 2 - mid
        assert np.dot(out, centroid[(a, b)] - mid) < 0
        size = (disk.vertices.max(0) - disk.vertices.min(0)).max()
        assert np.linalg.norm(out) == pytest.approx(vz.BOUNDARY_BAND * size)
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert texts[-1] == "boundary"


def test_matplotlib_draws_a_closed_mesh_without_band_or_legend_entry():
    cube = shapes.cube()
    fig = vz.plot_mesh(cube)
    assert len(fig.axes[0].collections[0].get_facecolor()) == cube.n_faces
    assert "boundary" not in [t.get_text() for t in fig.legends[0].get_texts()]


# ---------------------------------------------------------------------- edges on large meshes
def test_edge_opacity_fades_with_the_faces():
    assert drawing.edge_opacity(0) == drawing.edge_opacity(2_000) == 1.0
    assert drawing.edge_opacity(20_000) == pytest.approx(math.sqrt(0.1))
    assert drawing.edge_opacity(100_000) == pytest.approx(math.sqrt(0.02))
    assert drawing.edge_opacity(10**9) == drawing.EDGE_MIN_OPACITY
    sizes = [10, 2_000, 2_001, 5_000, 20_000, 100_000, 10**6]
    values = [drawing.edge_opacity(n) for n in sizes]
    assert values == sorted(values, reverse=True)


def test_a_large_mesh_gets_faint_edges_and_a_small_one_opaque_edges():
    big = pentanb.subdivide(shapes.cube(), "pentagonalize", 4, 0)  # 3,000 pentagons
    assert big.n_faces == 3_000
    v = pentanb.view(big)
    assert v.edge_material.transparent
    assert v.edge_material.opacity == pytest.approx(math.sqrt(2_000 / 3_000))
    v.update(shapes.cube())
    assert v.edge_material.opacity == 1.0 and not v.edge_material.transparent


# ---------------------------------------------------------------------- the camera
def test_eye_direction_is_the_figures_view():
    assert (drawing.VIEW_ELEV, drawing.VIEW_AZIM) == (vz.ELEV, vz.AZIM)
    np.testing.assert_allclose(drawing.eye_direction(), vz.view_direction(), atol=1e-15)
    e, a = math.radians(22.0), math.radians(-58.0)
    expected = [math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)]
    np.testing.assert_allclose(drawing.eye_direction(), expected, atol=1e-15)


def test_the_rabbit_is_seen_from_the_front_and_upright():
    rabbit = shapes.rabbit()
    v = pentanb.view(rabbit)
    eye = np.array(v.camera.position)
    target = np.array(v.controls.target)
    toward = (eye - target) / np.linalg.norm(eye - target)
    # from +x (the snout's side: the rabbit's head is its largest x), -y and above
    np.testing.assert_allclose(toward, [0.4913, -0.7863, 0.3746], atol=1e-4)
    snout = rabbit.vertices[np.argmax(rabbit.vertices[:, 0])]
    assert np.dot(snout - target, toward) > 0
    q = v.camera.quaternion
    # the camera looks down its -z axis at the target, its +y (up on the screen)
    # leans to +z and its +x (right on the screen) is level
    np.testing.assert_allclose(rotate(q, [0, 0, -1]), -toward, atol=1e-9)
    up, right = rotate(q, [0, 1, 0]), rotate(q, [1, 0, 0])
    assert up[2] > 0.9
    assert abs(right[2]) < 1e-9
    assert tuple(v.camera.up) == (0.0, 0.0, 1.0)


def test_elev_and_azim_choose_the_view():
    v = pentanb.view(shapes.cube(), elev=0.0, azim=90.0)  # from +y, level
    eye = np.array(v.camera.position) - np.array(v.controls.target)
    np.testing.assert_allclose(eye / np.linalg.norm(eye), [0.0, 1.0, 0.0], atol=1e-12)
    v.fit_camera()  # a refit keeps the direction
    eye = np.array(v.camera.position) - np.array(v.controls.target)
    np.testing.assert_allclose(eye / np.linalg.norm(eye), [0.0, 1.0, 0.0], atol=1e-12)
    copy = v.copy()
    assert (copy.elev, copy.azim) == (0.0, 90.0)


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"elev": 91.0}, ValueError, "elev"),
        ({"azim": float("nan")}, ValueError, "azim"),
        ({"elev": "up"}, TypeError, "elev"),
    ],
)
def test_a_view_refuses_a_bad_angle(kwargs, error, message):
    with pytest.raises(error, match=message):
        pentanb.view(shapes.cube(), **kwargs)


def test_camera_fit_refuses_a_zero_direction():
    with pytest.raises(ValueError, match="camera direction"):
        drawing.camera_fit(shapes.cube().vertices, 40.0, 1.0, (0.0, 0.0, 0.0))


# ---------------------------------------------------------------------- no seams
def test_a_curved_pentagon_is_lit_without_seams():
    mesh = pentanb.smooth(pentanb.pentagonalize(shapes.cube()))
    b = drawing.mesh_buffers(mesh)
    tri = b.triangles().astype(np.float64)
    planes = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    planes /= np.linalg.norm(planes, axis=1)[:, None]
    per_face = np.repeat(np.arange(mesh.n_faces), mesh.face_sizes - 2)
    # the pentagons are curved: their fan triangles lie in planes up to degrees apart
    # (flat shading would light them differently: a seam along every diagonal)
    spread = max(
        np.degrees(np.arccos(np.clip(planes[per_face == f] @ planes[per_face == f].T, -1, 1))).max()
        for f in range(mesh.n_faces)
    )
    assert spread > 1.0
    # but a triangle corner carries its vertex's normal, whichever triangle it is
    # in: the two triangles on either side of a diagonal agree at both its ends
    # (the normalised sum of the vertex's faces' Newell vectors, worked out here)
    total = np.zeros((mesh.n_vertices, 3))
    for face in face_lists(mesh):
        p = mesh.vertices[face]
        q = np.roll(p, -1, axis=0)
        area = np.array(
            [
                ((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])).sum(),
                ((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])).sum(),
                ((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])).sum(),
            ]
        )
        total[face] += area
    expected = total / np.linalg.norm(total, axis=1)[:, None]
    fan = np.concatenate(
        [[[f[0], f[k + 1], f[k + 2]] for k in range(len(f) - 2)] for f in face_lists(mesh)]
    )
    np.testing.assert_allclose(b.triangle_normals(), expected[fan], atol=1e-6)


def test_the_view_lights_polygons_not_triangles():
    v = pentanb.view(pentanb.smooth(pentanb.pentagonalize(shapes.cube())))
    assert not v.face_material.flatShading  # which would light every fan triangle apart
    assert "normal" in v.face_geometry.attributes


def test_polygon_normals_of_a_flat_polygon_and_of_no_area():
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], dtype=float)
    tris = np.array([[0, 1, 2], [0, 2, 3], [0, 0, 0]])
    n = drawing.polygon_normals(square, tris, [0, 0, 1], 2)
    np.testing.assert_array_equal(n, [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    flipped = drawing.polygon_normals(square, tris[:, ::-1], [0, 0, 1], 2)
    np.testing.assert_array_equal(flipped[0], [0.0, 0.0, -1.0])
