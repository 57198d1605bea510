"""Edge-Sharpener: restores the sharp edges and corners that marching cubes,
voxel remeshers and uniform resamplings cut into chamfers (Attene et al. 2003).

    import edge_sharpener as es
    vertices, faces, report = es.sharpen(vertices, faces)  # the default method, auto
    print(report["summary"])  # what was restored and left, as the CLI prints it
    es.sharpen(vertices, faces, method="extended", tuning={"max_label_hops": 4})

numpy arrays in, numpy arrays out: sharpen(), detect(), mesh_distance().
The ordinary options are keyword arguments; each method's tuning goes in the
`tuning` dict. OPTIONS describes every option (from the C++ option table); see
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
           "ordinary_options", "tuning_options"]


def ordinary_options():
    """The options users set first (CLI help, MeshLab dialog, Blender panel),
    keyword arguments of sharpen() and detect(): the rows of OPTIONS whose group
    is the ordinary one."""
    return tuple(option for option in OPTIONS if option["ordinary"])


def tuning_options():
    """Each method's tuning, the keys of sharpen()'s and detect()'s `tuning`
    dict (CLI --help-all, MeshLab's advanced parameters, Blender's Advanced
    panel): the other rows of OPTIONS, with their group's title in "group"."""
    return tuple(option for option in OPTIONS if not option["ordinary"])
