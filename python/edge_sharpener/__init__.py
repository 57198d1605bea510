"""Edge-Sharpener: restores the sharp edges and corners that marching cubes,
voxel remeshers and uniform resamplings cut into chamfers (Attene et al. 2003).

    import edge_sharpener as es
    vertices, faces, report = es.sharpen(vertices, faces)  # the default method, auto

numpy arrays in, numpy arrays out: sharpen(), detect(), mesh_distance().
OPTIONS describes every keyword (from the C++ option table); see
help(edge_sharpener.sharpen).
"""
from ._edge_sharpener import (
    FACE_LABELS,
    OPTIONS,
    InputError,
    detect,
    mesh_distance,
    sharpen,
)

__all__ = ["sharpen", "detect", "mesh_distance", "InputError", "OPTIONS", "FACE_LABELS",
           "ordinary_options"]


def ordinary_options():
    """The options users set first (CLI help, MeshLab dialog, Blender panel):
    the rows of OPTIONS whose group is the ordinary one."""
    return tuple(option for option in OPTIONS if option["ordinary"])
