"""Shared helpers of the Python tests: paths from CTest's environment, a
binary PLY reader (what the CLI writes), the CLI run with a table's keywords."""
import json
import os
import pathlib
import subprocess

import pytest

from ply import read_ply

SOURCE_DIR = pathlib.Path(os.environ.get("ES_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SAMPLES = SOURCE_DIR / "test_meshes" / "generated"
CLI = os.environ.get("ES_CLI", "")
DISTANCE_CLI = os.environ.get("ES_DISTANCE_CLI", "")


def cli_arguments(options):
    """The edge-sharpener command-line arguments that set `options` (keyword -> value),
    from the option table's CLI flags."""
    import edge_sharpener as es
    args = []
    for spec in es.OPTIONS:
        if spec["key"] not in options:
            continue
        value = options[spec["key"]]
        if spec["type"] == "flag":
            if bool(value) != spec["default"]:  # a flag switches from the default
                args.append(spec["cli_flag"])
        else:
            args += [spec["cli_flag"], str(value)]
    return args


def split_options(options):
    """`options` (key -> value, any option of the table) as the package takes them:
    the ordinary ones as keywords, each method's tuning in the `tuning` dict."""
    import edge_sharpener as es
    tuning_keys = {o["key"] for o in es.tuning_options()}
    keywords = {k: v for k, v in options.items() if k not in tuning_keys}
    tuning = {k: v for k, v in options.items() if k in tuning_keys}
    if tuning:
        keywords["tuning"] = tuning
    return keywords


def run_cli(input_path, output_path, options, detect_only=False):
    """Runs the edge-sharpener CLI; returns its --json report."""
    command = [CLI, str(input_path), str(output_path), "--json", *cli_arguments(options)]
    if detect_only:
        command.append("--detect-only")
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(done.stdout)


@pytest.fixture(scope="session")
def cli():
    if not CLI or not os.path.exists(CLI):
        pytest.fail("ES_CLI must name the edge-sharpener program (CTest sets it)")
    return CLI


def sample(name):
    return read_ply(SAMPLES / f"{name}.ply")
