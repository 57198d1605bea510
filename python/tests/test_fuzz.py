"""Seeded random-array fuzz: a few thousand calls with random arrays (shapes,
dtypes, indices, NaN/inf, orientation, noise) and random options. Each call
returns a valid mesh or raises InputError/TypeError; nothing crashes; the
caller's arrays are never modified."""
import numpy as np
import pytest

import edge_sharpener as es
from conftest import split_options

CASES = 4200
SEED = 20260522

# Small closed meshes to perturb (valid inputs that reach the core's stages).
_OCTA_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
_OCTA_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])


def _grid_box(n):
    """A closed box of 6 n x n grids of quads (two triangles each), outward."""
    vertices, index, faces = [], {}, []
    def vertex(p):
        key = tuple(np.round(p, 9))
        if key not in index:
            index[key] = len(vertices)
            vertices.append(p)
        return index[key]
    for axis in range(3):
        for side in (0, 1):
            u, w = (axis + 1) % 3, (axis + 2) % 3
            for i in range(n):
                for j in range(n):
                    corners = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = np.zeros(3)
                        p[axis], p[u], p[w] = side, (i + di) / n, (j + dj) / n
                        corners.append(vertex(p))
                    a, b, c, d = corners if side else corners[::-1]
                    faces += [[a, b, c], [a, c, d]]
    return np.array(vertices), np.array(faces)


_BOX_V, _BOX_F = _grid_box(3)


def random_case(rng):
    kind = rng.integers(0, 4)
    if kind == 0:  # random soup: mostly refused
        nv, nf = rng.integers(0, 12), rng.integers(0, 12)
        vertices = rng.normal(size=(nv, 3))
        faces = rng.integers(-2, nv + 2, size=(nf, 3)) if nv else rng.integers(-2, 3, size=(nf, 3))
    else:  # a closed mesh, perturbed
        base_v, base_f = (_OCTA_V, _OCTA_F) if kind == 1 else (_BOX_V, _BOX_F)
        vertices = base_v + rng.normal(scale=rng.choice([0, 1e-6, 0.05, 0.5]), size=base_v.shape)
        faces = base_f.copy()
        if rng.random() < 0.2:  # flip a face
            faces[rng.integers(len(faces))] = faces[rng.integers(len(faces))][::-1]
        if rng.random() < 0.2:  # drop faces (open the mesh)
            faces = faces[rng.random(len(faces)) > 0.2]
        if rng.random() < 0.1:  # an index out of range
            faces[rng.integers(len(faces)), rng.integers(3)] = rng.choice([-1, len(vertices)])
        if rng.random() < 0.1:  # collapse a vertex onto another (degenerate faces)
            vertices[rng.integers(len(vertices))] = vertices[rng.integers(len(vertices))]
    if rng.random() < 0.08 and vertices.size:
        vertices[rng.integers(len(vertices)), rng.integers(3)] = rng.choice([np.nan, np.inf, -np.inf])
    with np.errstate(invalid="ignore"):  # NaN to int32: a bad dtype anyway
        vertices = vertices.astype(rng.choice([np.float32, np.float64, np.float16, np.int32], p=[0.45, 0.45, 0.05, 0.05]))
    faces = faces.astype(rng.choice([np.int64, np.int32, np.uint32, np.int16, np.float64], p=[0.4, 0.3, 0.15, 0.1, 0.05]))
    if rng.random() < 0.05:
        vertices = vertices.reshape(-1)
    if rng.random() < 0.05 and faces.size:
        faces = faces[:, :2]
    return vertices, faces


def random_options(rng):
    options = {}
    for spec in es.OPTIONS:
        if rng.random() > 0.06:
            continue
        if spec["type"] == "choice":
            options[spec["key"]] = rng.choice(list(spec["choices"]) + ["nonsense"])
        elif spec["type"] == "flag":
            options[spec["key"]] = bool(rng.integers(2))
        elif spec["type"] == "integer":
            options[spec["key"]] = int(rng.integers(int(spec["min"]) - 1, min(int(spec["max"]), 6) + 2))
        else:  # mostly in range, sometimes just outside
            low, high = spec["min"], min(spec["max"], 10)
            options[spec["key"]] = float(rng.uniform(low - 0.1 * (high - low), high))
    return options


def check_result(vertices, faces, out_vertices, out_faces):
    assert out_vertices.ndim == 2 and out_vertices.shape[1] == 3
    assert out_faces.ndim == 2 and out_faces.shape[1] == 3 and out_faces.dtype == np.int64
    assert out_vertices.dtype == (np.float32 if vertices.dtype == np.float32 else np.float64)
    if out_faces.size:
        assert out_faces.min() >= 0 and out_faces.max() < len(out_vertices)
    assert np.isfinite(out_vertices).all()


@pytest.mark.parametrize("chunk", range(6))
def test_random_arrays(chunk):
    rng = np.random.default_rng([SEED, chunk])
    outcomes = {"sharpened": 0, "detected": 0, "measured": 0, "refused": 0}
    for _ in range(CASES // 6):
        vertices, faces = random_case(rng)
        options = split_options(random_options(rng)) if rng.random() < 0.5 else {}
        copies = (vertices.copy(), faces.copy())
        function = rng.choice(["sharpen", "detect", "mesh_distance"], p=[0.75, 0.15, 0.1])
        try:
            if function == "sharpen":
                out_vertices, out_faces, report = es.sharpen(vertices, faces, **options)
                check_result(vertices, faces, out_vertices, out_faces)
                assert report["output"]["faces"] == len(out_faces)
                outcomes["sharpened"] += 1
            elif function == "mesh_distance":
                d = es.mesh_distance(vertices, faces, _BOX_V, _BOX_F, samples=200)
                assert d["symmetric"]["max"] >= d["symmetric"]["rms"] >= 0
                outcomes["measured"] += 1
            else:
                labels = es.detect(vertices, faces, **options)
                assert labels.shape == (len(faces),) and labels.max(initial=0) < 4
                outcomes["detected"] += 1
        except (es.InputError, TypeError) as error:  # refused, with a message
            assert str(error)
            outcomes["refused"] += 1
        assert vertices.dtype == copies[0].dtype and faces.dtype == copies[1].dtype
        assert np.array_equal(vertices, copies[0], equal_nan=vertices.dtype.kind == "f")
        assert np.array_equal(faces, copies[1])
    # The fuzz reaches the core, not only the checks.
    print(outcomes)
    assert outcomes["sharpened"] > 50 and outcomes["refused"] > 50, outcomes
