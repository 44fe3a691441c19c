"""Drawing meshes with matplotlib (mplot3d): the paper's figures as static images.

Every face is one polygon of a :class:`~mpl_toolkits.mplot3d.art3d.Poly3DCollection`
(no triangulation), coloured by its number of sides with
:func:`pentanb.viz.colors.face_rgb` and shaded with a Lambert term from its
normal, so that a pentagon is the same green here as in the pythreejs views.
Polygons are built with whole-array indexing (``vertices[corners]``), so a
mesh of ten thousand faces draws in well under a second.  The boundary of an
open mesh is drawn heavier: a band along it in
:data:`pentanb.viz.colors.BOUNDARY_COLOR`, :data:`BOUNDARY_BAND` of the
mesh's size wide, on the hole's side of every boundary edge, in the face's
plane (:func:`boundary_band`).  The bands are polygons of the same collection
as the faces, so mplot3d sorts them by depth with the faces (a boundary
behind the surface stays hidden; a line collection would be drawn wholly
in front of the faces or wholly behind them), and the legend names the
boundary.  A closed mesh is drawn as before.

Nothing here uses :mod:`matplotlib.pyplot`: figures are plain
:class:`matplotlib.figure.Figure` objects (no global state, nothing to close),
which Jupyter displays and :func:`save_figure` writes byte for byte the same
on every run.

Examples
--------
>>> import pentanb
>>> from pentanb.viz.mpl import plot_mesh
>>> fig = plot_mesh(pentanb.smooth(pentanb.pentagonalize(pentanb.shapes.cube())))
>>> fig.axes[0].get_title()
''
"""

from __future__ import annotations

import contextlib
from collections.abc import Mapping, Sequence
from typing import Any

import matplotlib
import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from numpy.typing import ArrayLike

from .. import _checks
from ..mesh import Mesh
from .colors import BOUNDARY_COLOR, EDGE_COLOR, face_color, face_label, face_rgb

__all__ = [
    "draw_mesh",
    "plot_mesh",
    "plot_meshes",
    "add_face_legend",
    "panel_figure",
    "label_panel",
    "draw_flat",
    "draw_segments",
    "face_polygons",
    "shaded_colors",
    "view_direction",
    "fit_view",
    "boundary_band",
    "save_figure",
    "style",
    "DPI",
    "ELEV",
    "AZIM",
]

#: Resolution of every saved figure (dots per inch).
DPI = 120
#: Default camera: elevation and azimuth in degrees (mplot3d conventions).
ELEV, AZIM = 22.0, -58.0
#: Lambert shading: share of the colour that does not depend on the light.
AMBIENT = 0.42
#: Share of the key light in the Lambert term (the rest is a headlight).
KEY = 0.62
#: Width of the band drawn along a boundary, as a share of the mesh's size
#: (the largest side of its bounding box).
BOUNDARY_BAND = 0.012

#: rcParams every figure is built and saved with, on top of matplotlib's
#: defaults, so that a user's matplotlibrc does not change the images.
_RC = {
    "font.family": "DejaVu Sans",
    "font.size": 9.0,
    "axes.titlesize": 9.0,
    "legend.fontsize": 8.5,
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "savefig.facecolor": "white",
    "figure.facecolor": "white",
    "path.simplify": False,
}


@contextlib.contextmanager
def style():
    """Context in which figures are built and saved: matplotlib's defaults plus
    the package's fonts and dpi, whatever the user's rcParams are."""
    with matplotlib.rc_context():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(_RC)
        yield


# ---------------------------------------------------------------------- geometry
def face_polygons(mesh: Mesh, faces: ArrayLike | None = None):
    """The corner positions of every face, for a polygon collection.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Which faces (default: all).

    Returns
    -------
    (m, n, 3) float array when all the faces have ``n`` sides, else a list of
    ``(n_f, 3)`` arrays.  Built with one fancy index, not a loop over faces.
    """
    sizes = mesh.face_sizes
    offsets = mesh.offsets
    if faces is None:
        corners = mesh.corners
        sel_sizes = sizes
    else:
        chosen = np.asarray(faces, dtype=np.int64)
        sel_sizes = sizes[chosen]
        # corner indices of the chosen faces, still in CSR order
        start = np.repeat(offsets[chosen], sel_sizes)
        local = np.arange(sel_sizes.sum()) - np.repeat(np.cumsum(sel_sizes) - sel_sizes, sel_sizes)
        corners = mesh.corners[start + local]
    pts = mesh.vertices[corners]
    if sel_sizes.size and np.all(sel_sizes == sel_sizes[0]):
        return pts.reshape(sel_sizes.size, int(sel_sizes[0]), 3)
    return np.split(pts, np.cumsum(sel_sizes)[:-1])


def view_direction(elev: float = ELEV, azim: float = AZIM) -> np.ndarray:
    """(3,) float: unit vector from the scene towards an mplot3d camera."""
    e, a = np.radians(elev), np.radians(azim)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def _lights(elev: float, azim: float) -> tuple[np.ndarray, np.ndarray]:
    """A key light over the viewer's left shoulder and a headlight (along the view),
    both fixed relative to the camera."""
    eye = view_direction(elev, azim)
    a = np.radians(azim)
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    up = np.cross(eye, right)
    key = eye + 0.6 * up - 0.7 * right
    return key / np.linalg.norm(key), eye


def shaded_colors(
    mesh: Mesh,
    elev: float = ELEV,
    azim: float = AZIM,
    *,
    shade: bool = True,
    ambient: float = AMBIENT,
    faces: np.ndarray | None = None,
) -> np.ndarray:
    """RGB colour of every face: its face-size colour times a Lambert term.

    Parameters
    ----------
    mesh : Mesh
    elev, azim : float
        Camera, in degrees; the light moves with it.
    shade : bool
        False gives the flat face-size colours.
    ambient : float in [0, 1]
        Brightness of a face turned away from the light.
    faces : (k,) int, optional
        Which faces (default: all).

    Returns
    -------
    (m, 3) float in [0, 1]
    """
    sizes = mesh.face_sizes if faces is None else mesh.face_sizes[faces]
    rgb = face_rgb(sizes)
    if not shade:
        return rgb
    normals = mesh.face_normals if faces is None else mesh.face_normals[faces]
    key, head = _lights(elev, azim)
    lambert = KEY * np.clip(normals @ key, 0.0, 1.0) + (1.0 - KEY) * np.clip(
        normals @ head, 0.0, 1.0
    )
    return rgb * np.minimum(ambient + (1.0 - ambient) * lambert, 1.0)[:, None]


def fit_view(ax, points: np.ndarray, zoom: float = 1.0, fill: float = 0.94) -> None:
    """Equal aspect, axis off, and the camera zoomed so ``points`` fill the panel.

    mplot3d draws into the largest square inside the axes; the zoom is
    chosen from the projected extent of ``points`` ((k, 3) float) so that
    they fill ``fill`` of the axes' own rectangle (wide panels included),
    then multiplied by ``zoom``.
    """
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.maximum(hi - lo, 1e-9 * max(float((hi - lo).max()), 1.0))
    mid = (lo + hi) / 2
    ax.set_xlim(mid[0] - span[0] / 2, mid[0] + span[0] / 2)
    ax.set_ylim(mid[1] - span[1] / 2, mid[1] + span[1] / 2)
    ax.set_zlim(mid[2] - span[2] / 2, mid[2] + span[2] / 2)
    ax.set_axis_off()
    aspect = tuple(span / span.max())
    pos = ax.get_position(original=True)
    fw, fh = ax.figure.get_size_inches()
    pw, ph = pos.width * fw, pos.height * fh  # the panel, inches
    side = min(pw, ph)  # mplot3d's square, inches
    view = ax.viewLim
    unit = side / max(view.width, view.height)  # inches per projected unit
    z = 1.0
    for _ in range(3):  # perspective: refine twice
        ax.set_box_aspect(aspect, zoom=z)
        xs, ys, _ = proj3d.proj_transform(*points.T, ax.get_proj())
        hx = max(xs.max() - view.x0 - view.width / 2, view.x0 + view.width / 2 - xs.min()) * unit
        hy = max(ys.max() - view.y0 - view.height / 2, view.y0 + view.height / 2 - ys.min()) * unit
        z *= fill * min(pw / 2 / max(hx, 1e-12), ph / 2 / max(hy, 1e-12))
    ax.set_box_aspect(aspect, zoom=z * zoom)


def _edge_width(n_faces: int) -> float:
    return float(np.clip(0.9 * np.sqrt(150.0 / max(n_faces, 1)), 0.12, 0.9))


def boundary_band(
    mesh: Mesh, faces: ArrayLike | None = None, width: float | None = None
) -> np.ndarray:
    """The band :func:`draw_mesh` draws along a mesh's boundary: one quad per edge.

    Each boundary edge ``a -> b`` (its face on the left) gets the quad
    ``a, b, b + w u, a + w u``, ``u`` the unit vector in its face's plane
    at right angles to the edge, pointing away from the face (into the
    hole), so the band borders the surface without covering it.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Only the boundary edges of these faces (default: all).
    width : float, optional
        ``w``; default :data:`BOUNDARY_BAND` times the largest side of the
        mesh's bounding box.

    Returns
    -------
    (B, 4, 3) float
        Empty (B = 0) for a closed mesh.
    """
    bh = mesh.boundary_halfedges
    if faces is not None:
        bh = bh[np.isin(mesh.halfedge_face[bh], np.asarray(faces))]
    if width is None:
        v = mesh.vertices
        width = BOUNDARY_BAND * float((v.max(axis=0) - v.min(axis=0)).max()) if len(v) else 0.0
    a = mesh.vertices[mesh.corners[bh]]
    b = mesh.vertices[mesh.head[bh]]
    out = np.cross(b - a, mesh.face_normals[mesh.halfedge_face[bh]])
    length = np.linalg.norm(out, axis=1)
    out = out / np.where(length > 0, length, 1.0)[:, None] * float(width)
    return np.stack([a, b, b + out, a + out], axis=1)


# ---------------------------------------------------------------------- drawing
def draw_mesh(
    ax,
    mesh: Mesh,
    *,
    wireframe: bool = True,
    shade: bool = True,
    title: str | None = None,
    elev: float = ELEV,
    azim: float = AZIM,
    zoom: float = 1.0,
    edge_width: float | None = None,
    faces: np.ndarray | None = None,
    proj: str = "persp",
) -> Poly3DCollection:
    """Draw a mesh into a 3-D axes: one shaded polygon per face, coloured by sides.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
    mesh : Mesh
    wireframe : bool
        Draw the edges (in :data:`pentanb.viz.colors.EDGE_COLOR`).  The
        boundary of an open mesh is drawn in any case, as a dark band
        (:func:`boundary_band`).
    shade : bool
        Lambert shading from the face normals (:func:`shaded_colors`).
    title : str, optional
        Panel label, drawn under the panel (e.g. ``"(B) pentagonalized"``).
    elev, azim : float
        Camera angles in degrees.
    zoom : float
        Multiplies the zoom that makes the mesh fill its panel (:func:`fit_view`).
    edge_width : float, optional
        Line width of the edges; default shrinks with the number of faces.
    faces : (k,) int, optional
        Draw only these faces.
    proj : {"persp", "ortho"}

    Returns
    -------
    Poly3DCollection
    """
    polys = face_polygons(mesh, faces)
    colors = shaded_colors(mesh, elev, azim, shade=shade, faces=faces)
    n = len(polys)
    lw = _edge_width(n) if edge_width is None else edge_width
    rim = None if mesh.is_closed else boundary_band(mesh, faces)
    if rim is None or not len(rim):
        coll = Poly3DCollection(
            polys,
            facecolors=colors,
            edgecolors=EDGE_COLOR if wireframe else colors,
            linewidths=lw if wireframe else 0.15,
        )
    else:
        # the band's quads in the same collection, sorted by depth with the
        # faces (mplot3d sorts colours with the polygons, one line width for all)
        dark = np.tile(to_rgba(BOUNDARY_COLOR), (len(rim), 1))
        face_rgba = np.concatenate([colors, np.ones((n, 1))], axis=1)
        edge_rgba = np.tile(to_rgba(EDGE_COLOR), (n, 1)) if wireframe else face_rgba
        coll = Poly3DCollection(
            list(polys) + list(rim),
            facecolors=np.concatenate([face_rgba, dark]),
            edgecolors=np.concatenate([edge_rgba, dark]),
            linewidths=lw if wireframe else 0.15,
        )
    coll.set_clip_on(False)  # mplot3d's square may be narrower than a wide panel
    _add_without_autoscale(ax, coll)
    ax.view_init(elev=elev, azim=azim)
    ax.set_proj_type(proj)
    fit_view(ax, mesh.vertices if faces is None else _poly_points(polys), zoom=zoom)
    if title is not None:
        label_panel(ax, title)
    return coll


def _add_without_autoscale(ax, coll) -> None:
    """Add a polygon collection to a 3-D axes without mplot3d's autoscaling.

    :func:`fit_view` sets the limits.  mplot3d's own autoscale (``autolim=True``;
    seen with matplotlib 3.11) reads ``Poly3DCollection._faces``, which for
    faces of several sizes is padded with uninitialised memory: now and then
    a garbage float overflows or is NaN and ``set_xlim`` raises "Axis limits
    cannot be NaN or Inf" (seen in a notebook's slider sweep).
    """
    try:
        ax.add_collection3d(coll, autolim=False)
    except TypeError:  # an older matplotlib without autolim
        ax.add_collection3d(coll)


def _poly_points(polys) -> np.ndarray:
    if isinstance(polys, np.ndarray):
        return polys.reshape(-1, polys.shape[-1])
    return np.concatenate(polys)


def label_panel(ax, text: str) -> None:
    """Put a panel's label, e.g. ``"(A) initial mesh"``, under the panel (as the paper does).

    It is the axes' title (``ax.get_title()``), placed at the bottom.
    """
    ax.set_title(text, y=-0.02, va="top", pad=0)


def draw_flat(
    ax,
    mesh: Mesh,
    faces: ArrayLike | None = None,
    *,
    wireframe: bool = True,
    alpha: float = 1.0,
    edge_width: float = 1.2,
    zorder: float = 1.0,
) -> PolyCollection:
    """Draw faces of a planar mesh (z ignored) into a 2-D axes, coloured by sides.

    Used for the single-polygon diagrams (Figures 6 and 10).
    """
    polys = face_polygons(mesh, faces)
    sizes = mesh.face_sizes if faces is None else mesh.face_sizes[np.asarray(faces)]
    flat = [np.asarray(p)[:, :2] for p in polys]
    coll = PolyCollection(
        flat,
        facecolors=face_rgb(sizes),
        alpha=alpha,
        edgecolors=EDGE_COLOR if wireframe else "none",
        linewidths=edge_width,
        zorder=zorder,
    )
    ax.add_collection(coll)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return coll


def draw_segments(ax, segments: ArrayLike, **kwargs) -> LineCollection:
    """Draw 2-D segments ((k, 2, 2) float) into a 2-D axes."""
    coll = LineCollection(list(np.asarray(segments)[..., :2]), **kwargs)
    ax.add_collection(coll)
    return coll


#: Largest size (width of a panel, spaces) a figure takes, in inches.
MAX_INCHES = 100.0


def panel_figure(
    n_panels: int,
    ncols: int | None = None,
    *,
    panel_size: float = 3.0,
    projection: str | None = "3d",
    suptitle: str | None = None,
    legend_space: float = 0.0,
    label_space: float = 0.42,
    aspect: float = 1.0,
) -> tuple[Figure, list]:
    """A figure with a grid of panels (3-D axes by default), room for labels under each.

    Parameters
    ----------
    n_panels : int
    ncols : int, optional
        Panels per row (default: all in one row up to 3).
    panel_size : float
        Width of a panel in inches.
    projection : "3d" or None
    suptitle : str, optional
    legend_space : float
        Inches at the bottom for a legend.
    label_space : float
        Inches under every panel for its label (:func:`label_panel`).
    aspect : float
        Panel height / width.

    Returns
    -------
    fig : Figure
    axes : list of axes, row by row

    Raises
    ------
    TypeError, ValueError
        A count that is not an integer in range (``n_panels`` in [1, 1,000],
        ``ncols`` in [1, 1,000]) or a size that is not a number in (0,
        :data:`MAX_INCHES`] (the spaces may be 0); the message names it.
    """
    n_panels = _checks.count(n_panels, "n_panels", 1, 1000)
    if ncols is not None:
        ncols = _checks.count(ncols, "ncols", 1, 1000)
    panel_size = _checks.number(panel_size, "panel_size", 0.0, MAX_INCHES, open_low=True)
    aspect = _checks.number(aspect, "aspect", 0.0, MAX_INCHES, open_low=True)
    legend_space = _checks.number(legend_space, "legend_space", 0.0, MAX_INCHES)
    label_space = _checks.number(label_space, "label_space", 0.0, MAX_INCHES)
    ncols = min(n_panels, 3) if ncols is None else ncols
    nrows = -(-n_panels // ncols)
    top = 0.42 if suptitle else 0.08
    ph = panel_size * aspect
    width = ncols * panel_size
    height = top + nrows * (ph + label_space) + legend_space
    fig = Figure(figsize=(width, height), dpi=DPI)
    axes = []
    for i in range(n_panels):
        r, c = divmod(i, ncols)
        bottom = legend_space + (nrows - 1 - r) * (ph + label_space) + label_space
        axes.append(
            fig.add_axes(
                (c * panel_size / width, bottom / height, panel_size / width, ph / height),
                projection=projection,
            )
        )
    if suptitle:
        fig.suptitle(suptitle, y=1 - 0.1 / height, va="top", fontsize=10.5)
    return fig, axes


def _sizes_of(sizes) -> list[int]:
    if isinstance(sizes, Mesh):
        return sorted(sizes.face_size_histogram())
    if isinstance(sizes, Mapping):
        return sorted(int(k) for k in sizes)
    out: set[int] = set()
    for s in sizes:
        if isinstance(s, Mesh):
            out.update(s.face_size_histogram())
        else:
            out.update(int(x) for x in np.atleast_1d(s))
    return sorted(out)


def add_face_legend(
    fig_or_ax,
    sizes,
    *,
    loc: str | None = None,
    ncol: int | None = None,
    title: str | None = "faces by number of sides",
    boundary: bool | None = None,
):
    """A legend of the face-size colours (and of the boundary, for open meshes).

    Parameters
    ----------
    fig_or_ax : Figure or Axes
        A figure gets one legend centred at its bottom.
    sizes : Mesh, sequence of meshes, ``{n: count}`` or iterable of ints
        Which face sizes to list.
    loc : str, optional
        Legend location (default "lower center" for a figure, "best" for axes).
    ncol : int, optional
        Columns (default: one row).
    boundary : bool, optional
        Add a "boundary" entry (a heavy line); default: when ``sizes``
        holds a mesh that is open.

    Returns
    -------
    matplotlib.legend.Legend
    """
    if not isinstance(sizes, (Mesh, Mapping)):
        sizes = list(sizes)  # (read twice)
    present = _sizes_of(sizes)
    if boundary is None:
        meshes = [sizes] if isinstance(sizes, Mesh) else []
        if not isinstance(sizes, (Mesh, Mapping)):
            meshes = [m for m in sizes if isinstance(m, Mesh)]
        boundary = any(not m.is_closed for m in meshes)
    handles: list[Patch | Line2D] = [
        Patch(
            facecolor=face_color(n),
            edgecolor=EDGE_COLOR,
            linewidth=0.6,
            label=f"{face_label(n)} ({n})",
        )
        for n in present
    ]
    if boundary:
        handles.append(Line2D([], [], color=BOUNDARY_COLOR, linewidth=3.0, label="boundary"))
    options: dict[str, Any] = {
        "ncol": len(handles) if ncol is None else ncol,
        "frameon": False,
        "title": title,
        "title_fontsize": 8.5,
    }
    if isinstance(fig_or_ax, Figure):
        options.update(loc=loc or "lower center", bbox_to_anchor=(0.5, 0.0))
    else:
        options.update(loc=loc or "best")
    return fig_or_ax.legend(handles=handles, **options)


def plot_mesh(
    mesh: Mesh,
    *,
    wireframe: bool = True,
    shade: bool = True,
    title: str | None = None,
    legend: bool = True,
    size: float = 4.0,
    **kwargs,
) -> Figure:
    """One mesh in a figure of its own, with a face-size legend.

    ``size`` is the panel's width in inches, in (0, :data:`MAX_INCHES`].
    Keyword arguments go to :func:`draw_mesh`.
    """
    size = _checks.number(size, "size", 0.0, MAX_INCHES, open_low=True)
    with style():
        fig, (ax,) = panel_figure(
            1,
            panel_size=size,
            legend_space=0.5 if legend else 0,
            label_space=0.42 if title else 0.05,
        )
        draw_mesh(ax, mesh, wireframe=wireframe, shade=shade, title=title, **kwargs)
        if legend:
            add_face_legend(fig, mesh)
    return fig


def plot_meshes(
    meshes: Sequence[Mesh],
    titles: Sequence[str] | None = None,
    *,
    ncols: int | None = None,
    panel_size: float = 2.6,
    suptitle: str | None = None,
    **kwargs,
) -> Figure:
    """Several meshes side by side, one panel each, with one face-size legend.

    Parameters
    ----------
    meshes : sequence of Mesh
    titles : sequence of str, optional
        One title per panel.
    ncols : int, optional
        Panels per row (default: all in one row up to 3, as :func:`panel_figure`).
    **kwargs
        Go to :func:`draw_mesh` for every panel.
    """
    meshes = list(meshes)
    labels: list[str | None] = [None] * len(meshes) if titles is None else list(titles)
    if len(labels) != len(meshes):
        raise ValueError(f"{len(meshes)} meshes but {len(labels)} titles")
    with style():
        fig, axes = panel_figure(
            len(meshes), ncols, panel_size=panel_size, suptitle=suptitle, legend_space=0.5
        )
        for ax, mesh, title in zip(axes, meshes, labels):
            draw_mesh(ax, mesh, title=title, **kwargs)
        add_face_legend(fig, meshes)
    return fig


def save_figure(fig: Figure, path, dpi: int = DPI) -> None:
    """Write a figure as a PNG that is byte-identical on every run.

    No software version or timestamp is written into the file; the image is
    rendered in :func:`style` at a fixed dpi.
    """
    with style():
        fig.savefig(path, dpi=dpi, format="png", metadata={"Software": None})
