"""The package gives the CLI's results: same vertices and faces (bit for bit),
same report, same labels, same distances, on the committed sample meshes."""
import json
import subprocess

import numpy as np
import pytest

import edge_sharpener as es
from conftest import DISTANCE_CLI, SAMPLES, run_cli, sample, split_options
from ply import read_ply

MESHES = ["cube_mc2", "lblock_mc2", "pyramid_mc2"]
OPTION_SETS = [
    {},
    {"method": "extended"},
    {"method": "extended", "open_region_contacts": False, "multiplier": 1.5},
    {"method": "paper", "convexity_check": False},
    {"max_feature_off_plane_spacings": 0.3, "min_feature_vertices": 5},
    {"multiplier": 3.0, "edge_length_check": False, "degenerate_angle_deg": 2.0},
]
# Fields of the CLI's JSON that describe the run, not the result.
RUN_FIELDS = {"seconds", "input_file", "output_file"}


@pytest.mark.parametrize("options", OPTION_SETS, ids=lambda o: ",".join(map(str, o.items())) or "defaults")
@pytest.mark.parametrize("name", MESHES)
def test_sharpen_matches_cli(name, options, cli, tmp_path):
    mesh = sample(name)
    cli_report = run_cli(SAMPLES / f"{name}.ply", tmp_path / "out.ply", options)
    cli_out = read_ply(tmp_path / "out.ply")

    vertices, faces, report = es.sharpen(mesh["vertices"], mesh["faces"], **split_options(options))

    assert vertices.dtype == np.float32 and faces.dtype == np.int64
    assert np.array_equal(vertices, cli_out["vertices"])
    assert np.array_equal(faces, cli_out["faces"])
    for field in RUN_FIELDS:
        cli_report.pop(field, None)
    assert report.pop("seconds") >= 0
    # Beyond the CLI's report: the restored vertices (those the report counts as moved).
    assert len(report.pop("restored_vertices")) == report["placement"]["moved"]
    assert report.pop("sharp_edges").shape[1] == 2
    assert report == cli_report
    assert report["output"] == {"vertices": len(vertices), "faces": len(faces)}


@pytest.mark.parametrize("method", ["paper", "extended"])
@pytest.mark.parametrize("name", MESHES)
def test_detect_matches_cli(name, method, cli, tmp_path):
    mesh = sample(name)
    run_cli(SAMPLES / f"{name}.ply", tmp_path / "labels.ply", {"method": method}, detect_only=True)
    painted = read_ply(tmp_path / "labels.ply")

    labels = es.detect(mesh["vertices"], mesh["faces"], method=method)

    assert labels.shape == (len(mesh["faces"]),) and labels.dtype == np.uint8
    # The CLI writes the labels as the palette's face colours and selects chamfer
    # and corner faces: both must agree with the labels.
    colors = np.stack([painted["face_red"], painted["face_green"], painted["face_blue"]], axis=1)
    for label in range(len(es.FACE_LABELS)):
        assert len(np.unique(colors[labels == label], axis=0)) <= 1
    palette = {tuple(colors[labels == label][0]) for label in range(4) if (labels == label).any()}
    assert len(palette) == len(set(labels.tolist()))  # one colour per label, distinct
    selected = (painted["face_flags"] & 0x20) != 0  # vcg's SELECTED face flag
    split = labels >= es.FACE_LABELS.index("chamfer")
    if method == "paper":
        assert np.array_equal(selected, split)
    else:  # every face of a feature zone: those Sharpen may change, never a smooth region's
        assert selected[split].all()
        assert not selected[labels == es.FACE_LABELS.index("smooth_region")].any()
    assert (labels == es.FACE_LABELS.index("chamfer")).any()


def test_sharpen_colorize_matches_cli(cli, tmp_path):
    mesh = sample("cube_mc2")
    run_cli(SAMPLES / "cube_mc2.ply", tmp_path / "out.ply", {"colorize": True, "method": "extended"})
    cli_out = read_ply(tmp_path / "out.ply")
    _, _, report = es.sharpen(mesh["vertices"], mesh["faces"], colorize=True, method="extended")
    for element, key in (("face", "faces"), ("vertex", "vertices")):
        expected = np.stack([cli_out[f"{element}_{c}"] for c in ("red", "green", "blue", "alpha")], axis=1)
        assert np.array_equal(report["colors"][key], expected)


RESTORED_GREEN = (40, 170, 70)  # docs/plugin.md, colours by verdict


@pytest.mark.parametrize("colors", ["verdict", "paper"])
def test_default_colorize_matches_cli(colors, cli, tmp_path):
    """The default paints by verdict (the restored features green), or the paper's labels."""
    mesh = sample("lblock_mc2")
    run_cli(SAMPLES / "lblock_mc2.ply", tmp_path / "out.ply", {"colorize": True, "colors": colors})
    cli_out = read_ply(tmp_path / "out.ply")
    _, _, report = es.sharpen(mesh["vertices"], mesh["faces"], colorize=True, colors=colors)
    faces = np.stack([cli_out[f"face_{c}"] for c in ("red", "green", "blue", "alpha")], axis=1)
    assert np.array_equal(report["colors"]["faces"], faces)
    green = (faces[:, :3] == RESTORED_GREEN).all(axis=1).sum()
    restored = sum(f["verdict"] == "restored" for f in report["features"])
    assert (green > 0) == (colors == "verdict") and restored > 0


@pytest.mark.parametrize("sampling", ["uniform", "meshlab"])
@pytest.mark.parametrize("name", ["cube", "lblock"])
def test_mesh_distance_matches_cli(name, sampling, tmp_path):
    measured, reference = sample(f"{name}_mc2"), sample(f"{name}_reference")
    done = subprocess.run([DISTANCE_CLI, str(SAMPLES / f"{name}_mc2.ply"),
                           str(SAMPLES / f"{name}_reference.ply"), "--json", "--samples", "20000",
                           "--sampling", sampling], check=True, capture_output=True, text=True)
    expected = json.loads(done.stdout)
    got = es.mesh_distance(measured["vertices"], measured["faces"], reference["vertices"],
                           reference["faces"], samples=20000, sampling=sampling)
    for field in ("a", "b"):
        expected.pop(field)
    assert got == expected
    assert got["symmetric"]["max"] > 0
