"""A reader of binary little-endian PLY triangle meshes (what the CLI writes),
for the Python tests and the Blender test (no pytest needed)."""
import pathlib

import numpy as np

_PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "<i2", "ushort": "<u2", "int": "<i4",
              "uint": "<u4", "float": "<f4", "double": "<f8", "int8": "i1", "uint8": "u1",
              "int16": "<i2", "uint16": "<u2", "int32": "<i4", "uint32": "<u4",
              "float32": "<f4", "float64": "<f8"}


def read_ply(path):
    """A triangle mesh from a binary little-endian PLY (vcglib's output):
    {'vertices': float32 (n, 3), 'faces': int64 (m, 3), and every other
    property by element: 'vertex_red', 'face_flags', ...}."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    elements = []
    for line in data[:end].decode("ascii").splitlines():
        words = line.split()
        if words[0] == "format":
            assert words[1] == "binary_little_endian", words
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and words[1] == "list":
            # Triangles only: every list holds 3 items.
            elements[-1][2].append((words[4] + "_count", _PLY_TYPES[words[2]]))
            elements[-1][2].append((words[4], _PLY_TYPES[words[3]], (3,)))
        elif words[0] == "property":
            elements[-1][2].append((words[2], _PLY_TYPES[words[1]]))
    out, offset = {}, end
    for name, count, fields in elements:
        records = np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=offset)
        offset += records.nbytes
        for field in records.dtype.names:
            out[name + "_" + field] = records[field].copy()
    assert offset == len(data), "trailing bytes: not a triangle mesh"
    mesh = {k: v for k, v in out.items()}
    mesh["vertices"] = np.stack([out["vertex_x"], out["vertex_y"], out["vertex_z"]], axis=1)
    if "face_vertex_indices" in out:
        assert (out["face_vertex_indices_count"] == 3).all()
        mesh["faces"] = out["face_vertex_indices"].astype(np.int64)
    return mesh
