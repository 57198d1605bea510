"""Shared by the study figures (corner_figure.py, verdict_figure.py): a 3D panel framed as a
cube around a centre, seen from one view, without axes."""


def frame(ax, centre, half, zoom, elev, azim, title, fontsize):
    """Frames matplotlib 3D axes `ax` as the cube of half-side `half` around `centre`."""
    for axis, c in zip("xyz", centre):
        getattr(ax, f"set_{axis}lim")(c - half, c + half)
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    ax.set_title(title, fontsize=fontsize)
