"""TEMPORARY stand-ins for pentanb.viz.mpl / pentanb.figures until they land.

Deleted as soon as the library's own drawing functions exist.
"""

import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import pentanb
from pentanb.colors import face_rgb


def draw_mesh(ax, mesh, title=None):
    polys = [mesh.vertices[f] for f in mesh.faces]
    coll = Poly3DCollection(polys, facecolors=face_rgb(mesh.face_sizes),
                            edgecolors="#222222", linewidths=0.3)
    ax.add_collection3d(coll)
    lo, hi = mesh.vertices.min(0), mesh.vertices.max(0)
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()
    if title:
        ax.set_title(title, fontsize=9)
    return ax


def plot_mesh(mesh, title=None):
    fig = plt.figure(figsize=(4, 4))
    draw_mesh(fig.add_subplot(projection="3d"), mesh, title)
    return fig


def grid(meshes, titles):
    fig = plt.figure(figsize=(3 * len(meshes), 3))
    for i, (m, t) in enumerate(zip(meshes, titles)):
        draw_mesh(fig.add_subplot(1, len(meshes), i + 1, projection="3d"), m, t)
    return fig
