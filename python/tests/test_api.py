"""The package's API on numpy arrays: round trips, dtypes, options from the
table, progress, threads, and every kind of bad input refused with the core's
message, never a crash, the caller's arrays never modified."""
import sys
import threading
import time

import numpy as np
import pytest

import edge_sharpener as es
from conftest import SAMPLES, sample
from ply import read_ply
from spots import spot_faces

# An octahedron, consistently oriented (outward normals).
OCTAHEDRON_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                        dtype=np.float64)
OCTAHEDRON_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                         [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]], dtype=np.int32)


@pytest.fixture(scope="module")
def cube():
    mesh = sample("cube_mc2")
    return mesh["vertices"], mesh["faces"]


def frozen_copies(*arrays):
    return [a.copy() for a in arrays]


def assert_unchanged(arrays, copies):
    for a, c in zip(arrays, copies):
        assert a.dtype == c.dtype and a.shape == c.shape
        assert np.array_equal(a, c, equal_nan=a.dtype.kind == "f")


def test_round_trip_float32_and_float64(cube):
    v32, f = cube
    copies = frozen_copies(v32, f)
    out32 = es.sharpen(v32, f, method="extended")
    out64 = es.sharpen(v32.astype(np.float64), f.astype(np.int32), method="extended")
    assert_unchanged((v32, f), copies)
    assert out32[0].dtype == np.float32 and out64[0].dtype == np.float64
    for vertices, faces, report in (out32, out64):
        assert vertices.shape == (report["output"]["vertices"], 3)
        assert faces.shape == (report["output"]["faces"], 3) and faces.dtype == np.int64
        assert faces.min() >= 0 and faces.max() < len(vertices)
        assert report["placement"]["moved"] > 100
    # Double precision makes the same decisions; the planes' intersections differ
    # by rounding (the cube is 1 wide, its edges 0.02 long).
    assert out32[0].shape == out64[0].shape and np.array_equal(out32[1], out64[1])
    assert np.abs(out32[0] - out64[0]).max() < 1e-3
    # The paper's method moves only the inserted vertices: the original ones keep
    # their index and position (in either precision).
    for vertices in (v32, v32.astype(np.float64)):
        out = es.sharpen(vertices, f, method="paper")[0]
        assert len(out) > len(vertices) and np.array_equal(out[: len(vertices)], vertices)
    # The result is a valid input again (a second pass finds what is left).
    es.sharpen(*out32[:2], method="extended")


def test_sharpening_reduces_the_distance_to_the_exact_cube(cube):
    exact = sample("cube_reference")
    vertices, faces, _ = es.sharpen(*cube, method="extended")
    before = es.mesh_distance(*cube, exact["vertices"], exact["faces"], samples=50000)
    after = es.mesh_distance(vertices, faces, exact["vertices"], exact["faces"], samples=50000)
    assert after["symmetric"]["rms"] < before["symmetric"]["rms"] / 5
    assert after["symmetric"]["max"] < before["symmetric"]["max"] / 2


def test_lists_and_non_contiguous_arrays(cube):
    v, f = cube
    strided_v = np.asfortranarray(v)
    reversed_f = f[::-1][::-1]  # a view, not a copy
    a = es.sharpen(strided_v, reversed_f)
    b = es.sharpen(v.tolist(), f.tolist())  # lists: float64 / int64
    assert np.array_equal(a[1], b[1])
    assert es.detect(OCTAHEDRON_V.tolist(), OCTAHEDRON_F.tolist()).shape == (8,)


def test_options_come_from_the_table():
    keys = [o["key"] for o in es.OPTIONS]
    assert keys[:6] == ["method", "multiplier", "edge_length_check", "colorize", "colors",
                        "degenerate_angle_deg"]
    assert [o["key"] for o in es.ordinary_options()] == keys[:6]
    _, _, report = es.sharpen(OCTAHEDRON_V, OCTAHEDRON_F)
    for option in es.OPTIONS:  # defaults: the report's options record the table's defaults
        assert report["options"][option["key"]] == option["default"], option["key"]
        assert option["key"] in es.sharpen.__doc__ and option["key"] in es.detect.__doc__
    # The ordinary options are keywords, the others each method's tuning.
    assert [o["key"] for o in es.tuning_options()] == keys[6:]
    assert all(o["group"].startswith("Tuning: ") for o in es.tuning_options())
    # Every option can be given; the values come back in the report.
    _, _, report = es.sharpen(OCTAHEDRON_V, OCTAHEDRON_F, method="extended", multiplier=1.5,
                              degenerate_angle_deg=2,
                              tuning={"support_rings": 3, "open_region_contacts": False})
    assert report["options"]["multiplier"] == 1.5 and report["options"]["support_rings"] == 3
    assert report["options"]["degenerate_angle_deg"] == 2 and report["options"]["method"] == "extended"
    assert report["options"]["open_region_contacts"] is False
    # The docstrings say where each kind goes.
    for function in (es.sharpen, es.detect):
        doc = function.__doc__
        assert "tuning=None, **options" in doc and "tuning={'max_label_hops': 4" in doc
        assert doc.index("(keyword arguments):") < doc.index("tuning={") < doc.index("Tuning: ")


def test_tuning_dict_reaches_the_core(cube):
    # The default restores the cube's features; with every feature shorter than
    # the minimum size, each is left as it was, and so is the mesh.
    default_vertices, _, default = es.sharpen(*cube)
    assert default["evidence"]["verdicts"]["restored"] == default["evidence"]["features"] > 0
    vertices, faces, report = es.sharpen(*cube, tuning={"min_feature_vertices": 1000})
    assert report["options"]["min_feature_vertices"] == 1000
    verdicts = report["evidence"]["verdicts"]
    assert verdicts["restored"] == 0 and verdicts["too_short"] > 0
    assert sum(verdicts.values()) == report["evidence"]["features"]
    assert len(faces) == len(cube[1]) and np.array_equal(vertices, cube[0])
    assert report["summary"].startswith(f"features: 0 restored, {report['evidence']['features']} left")
    assert f"{verdicts['too_short']} too short" in report["summary"]
    # Any mapping works; an empty one or None is the defaults.
    import types
    mapping = types.MappingProxyType({"min_feature_vertices": 1000})
    assert np.array_equal(es.sharpen(*cube, tuning=mapping)[1], faces)
    for empty in ({}, None):
        assert np.array_equal(es.sharpen(*cube, tuning=empty)[0], default_vertices)
    # detect() takes the same dict (the extended method's detection tuning).
    assert not np.array_equal(es.detect(*cube, method="extended"),
                              es.detect(*cube, method="extended", tuning={"min_region_depth": 100}))


def test_colorize_returns_colors(cube):
    vertices, faces, report = es.sharpen(*cube, colorize=True)
    assert report["colors"]["faces"].shape == (len(faces), 4)
    assert report["colors"]["vertices"].shape == (len(vertices), 4)
    assert "colors" not in es.sharpen(*cube)[2]


def test_detect_labels(cube):
    labels = es.detect(*cube, method="extended")
    counts = np.bincount(labels, minlength=4)
    assert counts[1] > counts[2] > 0  # mostly smooth regions, some chamfer faces
    assert es.FACE_LABELS[labels[0]] in es.FACE_LABELS


def test_progress_callback(cube):
    stages = []
    es.sharpen(*cube, progress=lambda percent, stage: stages.append((percent, stage)))
    assert [p for p, _ in stages] == sorted(p for p, _ in stages)
    assert stages[-1][0] == 100 and len(stages) >= 5
    with pytest.raises(ZeroDivisionError):
        es.sharpen(*cube, progress=lambda percent, stage: 1 / 0)
    # A callback may run the package itself; the outer call keeps its own callback.
    outer = []
    def nested(percent, stage):
        outer.append(percent)
        if percent == 40:
            es.sharpen(OCTAHEDRON_V, OCTAHEDRON_F, progress=lambda p, s: None)
    es.sharpen(*cube, progress=nested)
    assert outer == [p for p, _ in stages]
    with pytest.raises(TypeError, match="callable"):
        es.sharpen(*cube, progress=5)


def test_threads_run_concurrently_with_identical_results(cube):
    # The GIL is released while the core runs: threads sharpen at once, each
    # with its own progress callback, and get what a single call gets.
    expected = es.sharpen(*cube, method="extended")
    results, stages = [None] * 4, [[] for _ in range(4)]

    def work(i):
        results[i] = es.sharpen(*cube, method="extended",
                                progress=lambda p, s: stages[i].append(p))

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i, (vertices, faces, _) in enumerate(results):
        assert np.array_equal(vertices, expected[0]) and np.array_equal(faces, expected[1])
        assert stages[i][-1] == 100


def test_the_gil_is_released_while_the_core_runs():
    # With a switch interval far beyond the run, Python threads change hands
    # only where one releases the GIL. The main thread releases it on every
    # loop (sleep(0), so that the worker's progress callbacks can run); it sees
    # the worker between two stages only if the core runs without the GIL.
    mesh = sample("lblock_mc2")
    stages, seen = [], set()
    worker = threading.Thread(target=lambda: es.sharpen(
        mesh["vertices"], mesh["faces"], method="extended", progress=lambda p, s: stages.append(p)))
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000)
    try:
        worker.start()
        while worker.is_alive():
            seen.add(len(stages))
            time.sleep(0)
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert len(stages) == 6
    assert seen & {1, 2, 3, 4, 5}, seen


def non_manifold_edge():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], np.float32)
    return v, np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])


def non_manifold_vertex():
    # Two tetrahedra sharing one vertex.
    v = np.concatenate([OCTAHEDRON_V[[0, 2, 4, 5]], OCTAHEDRON_V[[0, 2, 4, 5]] * -1 + [2, 0, 0]])
    v[4] = v[0]
    tet = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    faces = np.concatenate([tet, np.where(tet == 0, 0, tet + 4)])
    return v.astype(np.float32), faces


def flipped_face():
    f = OCTAHEDRON_F.copy()
    f[0] = f[0][::-1]
    return OCTAHEDRON_V, f


def with_value(row, column, value, dtype=np.float64):
    v = OCTAHEDRON_V.astype(dtype)
    v[row, column] = value
    return v, OCTAHEDRON_F


BAD_INPUTS = {
    "vertices 2 columns": ((OCTAHEDRON_V[:, :2], OCTAHEDRON_F), "vertices must be an array of shape \\(n, 3\\), got shape \\(6, 2\\)"),
    "vertices 1-d": ((OCTAHEDRON_V.ravel(), OCTAHEDRON_F), "got shape \\(18,\\)"),
    "faces 4 columns": ((OCTAHEDRON_V, np.zeros((2, 4), int)), "faces must be an array of shape \\(n, 3\\)"),
    "faces 3-d": ((OCTAHEDRON_V, OCTAHEDRON_F[None]), "faces must be an array of shape"),
    "int vertices": ((OCTAHEDRON_V.astype(int), OCTAHEDRON_F), "vertices must hold float32 or float64 numbers, got int64"),
    "float16 vertices": ((OCTAHEDRON_V.astype(np.float16), OCTAHEDRON_F), "got float16"),
    "complex vertices": ((OCTAHEDRON_V.astype(complex), OCTAHEDRON_F), "got complex128"),
    "object vertices": ((OCTAHEDRON_V.astype(object), OCTAHEDRON_F), "got object"),
    "string vertices": (("vertices", OCTAHEDRON_F), "vertices must be an array of shape"),
    "ragged vertices": (([[0, 0, 0], [1, 0]], OCTAHEDRON_F), "vertices must be an array of shape"),
    "float faces": ((OCTAHEDRON_V, OCTAHEDRON_F.astype(float)), "faces must hold integers, got float64"),
    "bool faces": ((OCTAHEDRON_V, OCTAHEDRON_F > 2), "faces must hold integers, got bool"),
    "index out of range": ((OCTAHEDRON_V, np.where(OCTAHEDRON_F == 5, 6, OCTAHEDRON_F)), "face 4 has vertex index 6 out of range \\[0, 6\\)"),
    "negative index": ((OCTAHEDRON_V, np.where(OCTAHEDRON_F == 5, -1, OCTAHEDRON_F)), "face 4 has vertex index -1 out of range"),
    "huge unsigned index": ((OCTAHEDRON_V, np.where(OCTAHEDRON_F == 5, np.uint64(2**64 - 1), OCTAHEDRON_F.astype(np.uint64))), "vertex index 18446744073709551615 out of range"),
    "NaN": (with_value(3, 1, np.nan), "vertex 3 has a NaN or infinite coordinate"),
    "infinity float32": (with_value(2, 0, np.inf, np.float32), "vertex 2 has a NaN or infinite coordinate"),
    "misoriented": (flipped_face(), "faces are not consistently oriented"),
    "repeated vertex": ((OCTAHEDRON_V, np.array([[0, 0, 1]])), "face 0 repeats a vertex"),
    "empty": ((np.zeros((0, 3)), np.zeros((0, 3), int)), "mesh is empty"),
    "no faces": ((OCTAHEDRON_V, np.zeros((0, 3), int)), "mesh has no faces"),
}


def spotted_mesh(mesh):
    if mesh == "spots":
        m = read_ply(SAMPLES / "lblock_mc2_spots.ply")
        return m["vertices"], m["faces"]
    return non_manifold_edge() if mesh == "fin" else non_manifold_vertex()


@pytest.mark.parametrize("mesh", ["spots", "fin", "two tetrahedra"])
def test_non_manifold_spots_are_held_as_they_came(mesh):
    """Faces at a non-manifold vertex or edge come out as they came (same vertex indices,
    identical positions); the rest is sharpened as on the clean mesh; the report says
    where they are."""
    vertices, faces = spotted_mesh(mesh)
    copies = frozen_copies(vertices, faces)
    out_v, out_f, report = es.sharpen(vertices, faces)
    assert_unchanged([vertices, faces], copies)
    held = spot_faces(vertices, faces)
    assert held and spot_faces(out_v, out_f) == held
    assert (out_v[:len(vertices)] == vertices).all()
    assert report["non_manifold"]["held_faces"] >= len(held)
    assert "non-manifold: " in report["input_notes"]
    if mesh == "spots":
        clean = read_ply(SAMPLES / "lblock_mc2.ply")
        clean_v, _, clean_report = es.sharpen(clean["vertices"], clean["faces"])
        n = len(clean["vertices"])
        assert (out_v[:n] == clean_v[:n]).all()
        verdicts = report["evidence"]["verdicts"]
        assert verdicts["at_non_manifold_spot"] >= 1
        assert 0 < verdicts["restored"] < clean_report["evidence"]["verdicts"]["restored"]


@pytest.mark.parametrize("mesh", ["spots", "fin", "two tetrahedra"])
def test_detect_leaves_non_manifold_spots_unlabelled(mesh):
    vertices, faces = spotted_mesh(mesh)
    labels = es.detect(vertices, faces)
    assert len(labels) == len(faces)
    held = spot_faces(vertices, faces)
    at_spots = [i for i, f in enumerate(faces) if tuple(sorted(map(int, f))) in held]
    assert all(es.FACE_LABELS[labels[i]] not in ("chamfer", "corner") for i in at_spots)


def bevelled_block():
    """bevelled_block_mc2 and, per face, whether it lies on the block's wide designed bevel
    (the list generate-test-meshes --bevel-faces writes)."""
    mesh = sample("bevelled_block_mc2")
    on_bevel = np.zeros(len(mesh["faces"]), dtype=bool)
    on_bevel[np.loadtxt(SAMPLES / "bevelled_block_mc2_bevel.txt", dtype=np.int64)] = True
    return mesh["vertices"], mesh["faces"], on_bevel


def test_face_mask_leaves_a_designed_bevel_as_it_came():
    """face_mask=~bevel: the bevel's vertices come out bit for bit, the other features are
    sharpened, the output is nearer the exact block than the input (without the mask the
    default bends the bevel: farther)."""
    vertices, faces, on_bevel = bevelled_block()
    copies = frozen_copies(vertices, faces, on_bevel)
    mask = ~on_bevel
    out_v, out_f, report = es.sharpen(vertices, faces, face_mask=mask)
    assert_unchanged([vertices, faces, on_bevel], copies)
    bevel_vertices = np.unique(faces[on_bevel])
    assert len(bevel_vertices) > 50
    assert (out_v[bevel_vertices] == vertices[bevel_vertices]).all()
    assert report["selection"] == {"selected_faces_only": True, "selected_faces": int(mask.sum())}
    verdicts = report["evidence"]["verdicts"]
    assert verdicts["outside_selection"] >= 1 and verdicts["restored"] >= 10
    assert report["input_notes"].startswith(f"selection: {mask.sum()} of {len(faces)} faces")
    # Every feature listed with its verdict; those left for the selection reach the bevel.
    listed = [f["verdict"] for f in report["features"]]
    assert {v: listed.count(v) for v in set(listed)} == {v: n for v, n in verdicts.items() if n}
    for feature in report["features"]:
        if feature["verdict"] == "outside_selection":
            assert on_bevel[feature["faces"]].any(), feature
    exact = sample("bevelled_block_reference")
    def max_distance(v, f):
        return es.mesh_distance(v, f, exact["vertices"], exact["faces"], seed=1)["symmetric"]["max"]
    whole_v, whole_f, _ = es.sharpen(vertices, faces)
    assert max_distance(out_v, out_f) < max_distance(vertices, faces) < max_distance(whole_v, whole_f)


def test_face_mask_selecting_nothing_returns_the_mesh():
    vertices, faces, _ = bevelled_block()
    out_v, out_f, report = es.sharpen(vertices, faces, face_mask=np.zeros(len(faces), dtype=bool))
    assert np.array_equal(out_v, vertices) and np.array_equal(out_f, faces)
    assert report["summary"] == "nothing selected: the mesh is left as it came"


@pytest.mark.parametrize("mask, message", [
    (np.ones(5, dtype=bool), "face_mask must be an array of shape (6460,), one bool per face, "
                             "got shape (5,)"),
    (np.ones((6460, 1), dtype=bool), "got shape (6460, 1)"),
    (np.ones(6460, dtype=np.int64), "face_mask must hold booleans, got int64"),
    ("all", "face_mask must be an array of shape (6460,)"),
])
def test_bad_face_mask_is_refused(mask, message):
    vertices, faces, _ = bevelled_block()
    copies = frozen_copies(vertices, faces)
    with pytest.raises(es.InputError) as error:
        es.sharpen(vertices, faces, face_mask=mask)
    assert message in str(error.value)
    assert_unchanged([vertices, faces], copies)


@pytest.mark.parametrize("function", [es.sharpen, es.detect])
@pytest.mark.parametrize("case", BAD_INPUTS, ids=str)
def test_bad_input_is_refused_with_the_core_message(case, function):
    (vertices, faces), message = BAD_INPUTS[case]
    arrays = [a for a in (vertices, faces) if isinstance(a, np.ndarray)]
    copies = frozen_copies(*arrays)
    with pytest.raises(es.InputError, match=message):
        function(vertices, faces)
    assert_unchanged(arrays, copies)
    assert issubclass(es.InputError, ValueError)


BAD_OPTIONS = [
    ({"nonsense": 1}, TypeError, "unexpected keyword argument 'nonsense'"),
    ({"vertices": 1}, TypeError, "incompatible function arguments"),
    ({"multiplier": 0}, es.InputError, "option multiplier must be in \\(0, 100\\]"),
    ({"multiplier": -1.0}, es.InputError, "option multiplier must be in"),
    ({"multiplier": float("nan")}, es.InputError, "must be a finite number"),
    ({"degenerate_angle_deg": 60}, es.InputError, "option degenerate_angle_deg must be in \\[0, 59\\] deg"),
    ({"tuning": {"support_rings": 2.5}}, es.InputError, "support_rings must be a whole number"),
    ({"tuning": {"support_rings": 0}}, es.InputError, "support_rings must be in \\[1, 20\\]"),
    ({"tuning": {"support_rings": "3"}}, TypeError, "support_rings must be a number, got str"),
    ({"tuning": {"region_planes": 2}}, es.InputError, "region_planes must be true or false"),
    ({"tuning": {"nonsense": 1}}, es.InputError, "unknown tuning option 'nonsense' \\(help"),
    ({"tuning": {"max_label_hop": 4}}, es.InputError,
     "unknown tuning option 'max_label_hop'; did you mean 'max_label_hops'"),
    ({"tuning": {1: 4}}, es.InputError, "unknown tuning option '1'"),
    ({"tuning": {"multiplier": 2}}, es.InputError,
     "'multiplier' is no tuning option: give it as the keyword argument multiplier="),
    ({"tuning": [("support_rings", 3)]}, TypeError, "tuning must be a dict of tuning options"),
    ({"tuning": 3}, TypeError, "tuning must be a dict of tuning options .* got int"),
    ({"max_label_hops": 4}, TypeError,
     "unexpected keyword argument 'max_label_hops': a tuning option goes in the tuning dict"),
    ({"colorize": 2}, es.InputError, "colorize must be true or false"),
    ({"method": "best"}, es.InputError, "method has no such choice 'best' \\('paper', 'extended', 'auto'\\)"),
    ({"method": 1}, TypeError, "method must be one of 'paper', 'extended', 'auto'"),
    ({"multiplier": "2"}, TypeError, "multiplier must be a number, got str"),
    ({"multiplier": None}, TypeError, "multiplier must be a number, got NoneType"),
    ({"multiplier": [2]}, TypeError, "multiplier must be a number, got list"),
]


@pytest.mark.parametrize("options, error, message", BAD_OPTIONS, ids=lambda x: str(x)[:40])
def test_bad_options_are_refused(options, error, message):
    copies = frozen_copies(OCTAHEDRON_V, OCTAHEDRON_F)
    for function in (es.sharpen, es.detect):
        with pytest.raises(error, match=message):
            function(OCTAHEDRON_V, OCTAHEDRON_F, **options)
    assert_unchanged((OCTAHEDRON_V, OCTAHEDRON_F), copies)


def test_mesh_distance_bad_input():
    v, f = OCTAHEDRON_V, OCTAHEDRON_F
    assert es.mesh_distance(v, f, v, f)["symmetric"]["max"] < 1e-12
    cases = [
        ((v, f[:0], v, f), {}, "a mesh has no faces"),
        ((v, f, with_value(0, 0, np.nan)[0], f), {}, "b mesh has NaN or infinite"),
        ((v, f + 1, v, f), {}, "out of range"),
        ((v[:, :2], f, v, f), {}, "a_vertices must be an array of shape"),
        ((v, f, v, f.astype(float)), {}, "b_faces must hold integers"),
        ((np.zeros((3, 3)), [[0, 1, 2]], v, f), {}, "zero surface area"),
        ((v, f, v, f), {"samples": 0}, "samples must be in"),
        ((v, f, v, f), {"seed": -1}, "seed must be in"),
    ]
    for arrays, kwargs, message in cases:
        with pytest.raises(es.InputError, match=message):
            es.mesh_distance(*arrays, **kwargs)


def test_vertex_colors_follow_the_vertices(cube):
    """A coloured mesh: the original vertices keep their colours (by index,
    with the paper's method, which moves only new vertices), and each new
    vertex gets the mean colour of the vertices it was made between (blue is
    7 everywhere, so on every new vertex too; red follows x)."""
    vertices, faces = cube
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    red = np.round(250 * (vertices[:, 0] - lo[0]) / (hi[0] - lo[0])).astype(np.uint8)
    colors = np.stack([red, np.full_like(red, 100), np.full_like(red, 7)], axis=1)
    copies = frozen_copies(colors)
    out_v, _, report = es.sharpen(vertices, faces, method="paper", vertex_colors=colors)
    assert_unchanged((colors,), copies)
    out_c = report["vertex_colors"]
    assert out_c.shape == (len(out_v), 4) and out_c.dtype == np.uint8
    n = len(vertices)
    assert len(out_v) > n
    assert np.array_equal(out_c[:n, :3], colors) and (out_c[:, 3] == 255).all()
    assert (out_c[n:, 1] == 100).all() and (out_c[n:, 2] == 7).all()
    assert out_c[n:, 0].min() < 50 and out_c[n:, 0].max() > 200  # blends along x, not white
    # Floats in [0, 1] give the same bytes; without vertex_colors there is no entry.
    as_float = es.sharpen(vertices, faces, method="paper", vertex_colors=colors / 255.0)[2]
    assert np.array_equal(as_float["vertex_colors"], out_c)
    assert "vertex_colors" not in es.sharpen(vertices, faces, method="paper")[2]


@pytest.mark.parametrize("colors, message", [
    (np.zeros((5, 3), np.uint8), "shape"),
    (np.zeros((1, 2), np.uint8), "shape"),
    ("red", "shape"),
    (np.full((6, 3), 256, np.int32), "outside [0, 255]"),
    (np.full((6, 4), 1.5), "outside [0, 1]"),
    (np.full((6, 3), np.nan), "outside [0, 1]"),
    (np.zeros((6, 3), bool), "integers in [0, 255] or floats"),
])
def test_bad_vertex_colors_are_refused(colors, message):
    with pytest.raises(es.InputError, match=message.replace("[", r"\[").replace("]", r"\]")):
        es.sharpen(OCTAHEDRON_V, OCTAHEDRON_F, vertex_colors=colors)


def test_sharp_edges_are_the_restored_feature_lines(cube):
    """The report's restored vertices lie on the cube's edges (two coordinates
    on its faces), its sharp edges are output edges joining two of them along
    one cube edge, and together they run the twelve unit edges' length. A
    mesh with nothing to restore (the octahedron, already sharp) has none."""
    vertices, faces, report = es.sharpen(*cube)
    restored, edges = report["restored_vertices"], report["sharp_edges"]
    assert restored.dtype == np.int64 and edges.dtype == np.int64 and edges.shape[1] == 2
    assert len(restored) == report["placement"]["moved"] > 0
    on_faces = np.abs(np.abs(vertices) - 0.5) < 0.005  # a seventh of a cell
    assert (on_faces[restored].sum(axis=1) >= 2).all()
    assert np.isin(edges, restored).all() and (edges[:, 0] < edges[:, 1]).all()
    face_edges = {tuple(sorted(e)) for f in faces for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    assert all(tuple(e) in face_edges for e in edges)
    assert ((on_faces[edges[:, 0]] & on_faces[edges[:, 1]]).sum(axis=1) >= 2).all()
    length = np.linalg.norm(vertices[edges[:, 0]] - vertices[edges[:, 1]], axis=1).sum()
    assert 0.9 * 12 < length < 12.01
    none = es.sharpen(OCTAHEDRON_V, OCTAHEDRON_F)[2]
    assert none["restored_vertices"].shape == (0,) and none["sharp_edges"].shape == (0, 2)
