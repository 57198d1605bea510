"""The faces at non-manifold spots of a triangle mesh, found by brute force (independent of
the core), for the Python tests and the Blender test (no pytest needed)."""


def spot_faces(vertices, faces):
    """The faces at non-manifold spots, as sorted tuples of vertex indices: the faces at a
    vertex on an edge of three or more faces, or whose faces are not one fan joined by
    two-face edges (brute force, independent of the core)."""
    edge_faces = {}
    for f in faces:
        for k in range(3):
            e = tuple(sorted((int(f[k]), int(f[(k + 1) % 3]))))
            edge_faces[e] = edge_faces.get(e, 0) + 1
    around = {}
    for i, f in enumerate(faces):
        for v in f:
            around.setdefault(int(v), []).append(i)
    out = set()
    for v, fs in around.items():
        spot = False
        group = {i: i for i in fs}

        def root(i):
            while group[i] != i:
                i = group[i]
            return i
        for i in fs:
            for w in faces[i]:
                w = int(w)
                if w == v:
                    continue
                n = edge_faces[tuple(sorted((v, w)))]
                spot |= n > 2
                if n == 2:
                    for j in fs:
                        if j != i and w in faces[j]:
                            group[root(i)] = root(j)
        spot |= len({root(i) for i in fs}) > 1
        if spot:
            out |= {tuple(sorted(map(int, faces[i]))) for i in fs}
    return out
