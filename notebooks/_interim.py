"""TEMPORARY: a row of meshes, until pentanb.figures lands (then deleted)."""

from pentanb.viz.mpl import add_face_legend, draw_mesh, panel_figure, style


def row(meshes, titles, ncols=None, size=2.6):
    with style():
        fig, axes = panel_figure(len(meshes), ncols or len(meshes), panel_size=size,
                                 legend_space=0.45)
        for ax, m, t in zip(axes, meshes, titles):
            draw_mesh(ax, m, title=t)
        add_face_legend(fig, meshes)
    return fig
