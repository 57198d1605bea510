#!/usr/bin/env python3
"""Writes the hand-made bad-input meshes of tests/reliability/bad_inputs/.

The files are committed; this script documents how each was made and can
regenerate them (deterministically): python3 make_bad_inputs.py
"""
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
CUBE_T = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_T = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(HERE, name), mode) as f:
        f.write(data)


def off(vertices, faces, header="OFF"):
    lines = [header, f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(str(c) for c in v) for v in vertices]
    lines += [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def obj(vertices, faces):
    lines = ["v " + " ".join(str(c) for c in v) for v in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def ply_ascii(vertices, faces):
    head = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property float x",
            "property float y", "property float z", f"element face {len(faces)}",
            "property list uchar int vertex_indices", "end_header"]
    body = [" ".join(str(c) for c in v) for v in vertices]
    body += [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    return "\n".join(head + body) + "\n"


def ply_binary(vertices, faces):
    head = ("ply\nformat binary_little_endian 1.0\n"
            f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(struct.pack("<3f", *v) for v in vertices)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in faces)
    return head.encode() + body


def stl_binary(vertices, faces, declared=None):
    out = b"binary stl written by make_bad_inputs.py".ljust(80, b" ")
    out += struct.pack("<I", len(faces) if declared is None else declared)
    for f in faces:
        out += struct.pack("<3f", 0, 0, 0)
        for i in f:
            out += struct.pack("<3f", *vertices[i])
        out += struct.pack("<H", 0)
    return out


def main():
    rng = random.Random(20031)
    # Empty files.
    for ext in ("ply", "off", "obj", "stl"):
        write(f"empty.{ext}", b"")
    # Garbage: random bytes, and text that starts like the format then goes wrong.
    for ext in ("ply", "off", "obj", "stl"):
        write(f"garbage.{ext}", bytes(rng.randrange(256) for _ in range(700)))
    write("garbage_header.ply", "ply\nformat ascii 1.0\nelement vertex banana\nend_header\n1 2 3\n")
    write("garbage_counts.off", "OFF\n-5 99999999999 0\n0 0 0\n")
    write("garbage_text.obj", "v 0 0 zero\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    # Truncated files: valid headers, data cut short.
    write("truncated.ply", ply_ascii(CUBE_V, CUBE_T)[:260])
    write("truncated_binary.ply", ply_binary(CUBE_V, CUBE_T)[:330])
    write("truncated.off", off(CUBE_V, CUBE_T)[:70])
    write("truncated.obj", obj(CUBE_V, CUBE_T)[:90] + "f 1 2")
    write("truncated_binary.stl", stl_binary(CUBE_V, CUBE_T)[:84 + 50 * 5 + 20])
    write("overdeclared_binary.stl", stl_binary(CUBE_V, CUBE_T, declared=100000000))
    # Non-finite coordinates.
    write("nan.off", off([TETRA_V[0], (1, "nan", 0)] + TETRA_V[2:], TETRA_T))
    write("inf.obj", obj([TETRA_V[0], TETRA_V[1], (0, "inf", 0), TETRA_V[3]], TETRA_T))
    write("nan.ply", ply_binary([TETRA_V[0], (float("nan"), 0, 0)] + TETRA_V[2:], TETRA_T))
    # Point clouds.
    write("pointcloud.ply", ply_ascii(CUBE_V, []))
    write("pointcloud.obj", obj(CUBE_V, []))
    # Out-of-range face indices.
    write("out_of_range.off", off(TETRA_V, TETRA_T[:3] + [(0, 3, 7)]))
    write("out_of_range.obj", obj(TETRA_V, TETRA_T[:3] + [(0, 3, 41)]))
    write("negative_index.ply", ply_ascii(TETRA_V, TETRA_T[:3] + [(0, -1, 2)]))
    write("out_of_range_binary.ply", ply_binary(TETRA_V, TETRA_T[:3] + [(0, 3, 1000000)]))
    # Zero-area face: the cube's bottom split at the midpoint E of edge 0-1, the
    # collinear triangle (0, E, 1) closing the mesh (closed, manifold, oriented).
    v = CUBE_V + [(0.5, 0, 0)]
    t = [f for f in CUBE_T if f not in ((0, 3, 2), (0, 2, 1))]
    t += [(0, 3, 8), (8, 3, 2), (8, 2, 1), (0, 8, 1)]
    write("zero_area_face.off", off(v, t))
    # A face that repeats a vertex.
    write("repeated_vertex_face.off", off(TETRA_V, TETRA_T + [(0, 1, 1)]))
    # Duplicate faces: same orientation, and the same triangle flipped.
    write("duplicate_face.off", off(TETRA_V, TETRA_T + [TETRA_T[0]]))
    write("duplicate_face_flipped.obj", obj(TETRA_V, TETRA_T + [TETRA_T[0][::-1]]))
    # Duplicate vertices: corner 6 of the cube listed twice, half its fan uses the copy
    # (the mesh opens along two edges there).
    v = CUBE_V + [CUBE_V[6]]
    t, used = [], 0
    for f in CUBE_T:
        if 6 in f and used < 2:
            f = tuple(8 if i == 6 else i for i in f)
            used += 1
        t.append(f)
    write("duplicate_vertex.off", off(v, t))
    # Unreferenced vertices (one far away): must not change the result.
    write("unreferenced_vertices.off", off(CUBE_V + [(0.5, 0.5, 0.5), (40, 40, 40)], CUBE_T))
    # Non-manifold edge: three triangles on edge 0-1.
    write("nonmanifold_edge.off",
          off([(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -1, 0), (0.5, 0, 1)],
              [(0, 1, 2), (1, 0, 3), (0, 1, 4)]))
    # Non-manifold vertex: two tetrahedra sharing only vertex 0.
    v2 = TETRA_V + [(-1, 0, 0), (0, -1, 0), (0, 0, -1)]
    t2 = TETRA_T + [(0, 4, 5), (0, 5, 6), (0, 6, 4), (4, 6, 5)]
    write("nonmanifold_vertex.off", off(v2, t2))
    # Inconsistent orientation: one face of the tetrahedron flipped.
    write("inconsistent_orientation.off", off(TETRA_V, TETRA_T[:3] + [TETRA_T[3][::-1]]))
    # Open mesh: a box without its top (boundary of 4 edges).
    write("open_box.off", off(CUBE_V, [f for f in CUBE_T if not all(CUBE_V[i][2] == 1 for i in f)]))
    # Several components: a cube and a tetrahedron far apart.
    write("two_components.obj", obj(CUBE_V + [(x + 3, y, z) for x, y, z in TETRA_V],
                                    CUBE_T + [tuple(i + 8 for i in f) for f in TETRA_T]))
    # Polygons: the cube as 6 quads (OFF, OBJ, PLY); a pentagonal prism in OBJ.
    write("quads.off", off(CUBE_V, CUBE_QUADS))
    write("quads.obj", obj(CUBE_V, CUBE_QUADS))
    write("quads.ply", ply_ascii(CUBE_V, CUBE_QUADS))
    import math
    ring = [(math.cos(2 * math.pi * k / 5), math.sin(2 * math.pi * k / 5)) for k in range(5)]
    pv = [(x, y, 0) for x, y in ring] + [(x, y, 1) for x, y in ring]
    pf = [tuple(range(4, -1, -1)), tuple(range(5, 10))]
    pf += [(k, (k + 1) % 5, (k + 1) % 5 + 5, k + 5) for k in range(5)]
    write("pentagonal_prism.obj", obj(pv, pf))
    # PLY polygons with an index out of range after the third vertex: vcglib's
    # importer read freed memory here (fuzz_read_mesh); now our reader refuses it.
    write("polygon_out_of_range.ply", ply_ascii(CUBE_V, CUBE_QUADS[:5] + [(3, 0, 4, 99)]))
    write("polygon_short.ply", ply_ascii(TETRA_V, TETRA_T[:3] + [(0, 1)]))
    # Valid PLY variants our reader must handle: big endian with double
    # coordinates, extra vertex properties and an extra element; triangle strips.
    head = ("ply\nformat binary_big_endian 1.0\ncomment written by make_bad_inputs.py\n"
            f"element vertex {len(CUBE_V)}\nproperty double x\nproperty double y\n"
            "property double z\nproperty uchar red\nproperty list uchar float extra\n"
            f"element face {len(CUBE_QUADS)}\nproperty list uint8 uint32 vertex_indices\n"
            "property int flags\nelement material 1\nproperty float shininess\nend_header\n")
    body = b"".join(struct.pack(">3dBBf", *v, 7, 1, 0.5) for v in CUBE_V)
    body += b"".join(struct.pack(">B4Ii", 4, *q, -1) for q in CUBE_QUADS)
    body += struct.pack(">f", 2.0)
    write("cube_big_endian.ply", head.encode() + body)
    # The tetrahedron as triangle strips (every other triangle flipped, -1 restarts a strip).
    strips = [[2, 1, 0, 3, -1, 0, 3, 2], [1, 2, 3]]
    head = ["ply", "format ascii 1.0", f"element vertex {len(TETRA_V)}", "property float x",
            "property float y", "property float z", f"element tristrips {len(strips)}",
            "property list int int vertex_indices", "end_header"]
    body = [" ".join(str(c) for c in v) for v in TETRA_V]
    body += [f"{len(s)} " + " ".join(str(i) for i in s) for s in strips]
    write("tetra_tristrips.ply", "\n".join(head + body) + "\n")
    # A single triangle.
    write("one_triangle.off", off([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]))
    # A valid binary STL triangle soup (vertices merged on load).
    write("tetra_binary.stl", stl_binary(TETRA_V, TETRA_T))


if __name__ == "__main__":
    main()
