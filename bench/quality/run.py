#!/usr/bin/env python3
"""Edge-Sharpener quality benchmark: the paper's Metro experiments with real remeshers.

For every reference mesh (the exact generated test shapes, the real parts in
test_meshes/real, and every mesh in ../shared/meshes when present; each in the tuning or
the validation half fixed by bench/quality/split.json) it
  1. makes feature-insensitive remeshings (the sampler families) with the real meshlabserver
     (Uniform Mesh Resampling at several cell sizes, Isotropic Explicit Remeshing with
     features off, CSG intersection = marching intersections, Screened Poisson from a point
     sampling), the feature-preserving competitor "Marching Cubes (RIMLS)" from the same
     points, OpenVDB's voxel remesher (bench/samplers/vdb-remesh; also as Blender 3.4's
     voxel remesh with Preserve Volume, vertices cast onto the input) and depth-camera scans fused
     in a TSDF (bench/samplers/tsdf_scan.py); they are cached in CACHE/inputs (a failure or
     time-out is cached and reported, not fatal);
  2. sharpens each with the edge-sharpener CLI (identical to the MeshLab filter): every
     method (paper, extended, auto) at the default multiplier, and a multiplier sweep; and
     MeshLab's stock "UnSharp Mask Geometry" at its defaults as the peer (cached like the
     inputs);
  3. measures every mesh against the reference with mesh-distance --json --sampling meshlab
     (two-sided, samples spread as MeshLab's Hausdorff Distance filter spreads them);
  4. writes CACHE/results.json and, unless --no-report, docs/results.md and
     docs/images/results-*.png (report.py); --report-only rewrites them from the results
     JSON, the references' designed features read afresh from designed.json.

Python 3 standard library only; the figures need matplotlib (Debian python3-matplotlib)
and are skipped with a note without it.

  bench/quality/run.py --build BUILD_DIR [--fast] [--models a,b] [--inputs umr,ier] [--jobs N]
                       [--cache DIR] [--refresh] [--distance-samples N]

An output of the default method that is worse or near the line is measured again with
DENSE_SAMPLES, with its input, and judged on that reading (the sampled max only under-reads;
docs/auto-method-decisions.md, "How exact the sampled max is").
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import math
import os
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import families  # noqa: E402
import meshlab  # noqa: E402

METHODS = ("paper", "extended", "auto")
# Every run is one of these variants of the CLI (the name is the run's "method").
VARIANTS = {"paper": ["--method", "paper"], "extended": ["--method", "extended"],
            "auto": ["--method", "auto"]}
SWEPT_VARIANTS = METHODS
# Issue 61: the default with the user's selection, where the designed bevels and fillets of a
# generated shape are known exactly (test_meshes/designed_faces.h): their faces are left out
# with --skip-faces, as a user who knows the part deselects them.
SELECTION_VARIANT = "auto-selection"
DESIGNED_SHAPES = ("bevelled_block", "finished_hexprism")
# The designed features of the other references (bench/quality/designed.json).
DESIGNED_FILE = os.path.join(HERE, "designed.json")
DEFAULT_MULTIPLIER = 2.0
SWEEP = (1.5, 2.0, 2.5, 3.0)
# --fast (the CTest subset) keeps the shapes its floors (tests/quality/check_fast_subset.py)
# were measured on: the curved-edge shapes of issue 60 run in the full benchmark only.
FAST_SHAPES = ("cube", "lblock", "lblock_tilted", "wedge", "pyramid", "cross_prism",
               "cylinder_block", "sphere", "bevelled_block", "finished_hexprism")
GENERATED_SHAPES = FAST_SHAPES + ("cylinder_cut", "cone_cut", "torus_cut", "two_cylinders",
                                   "octahedron", "hexagonal_pyramid")
POINT_SAMPLES = 100000
# mesh-distance in MeshLab's sampling mode: this many vertex, edge and face samples per side.
DISTANCE_SAMPLES = 100000
_distance_sampling = ["--sampling", "meshlab"]  # --distance-sampling
_distance_samples = [DISTANCE_SAMPLES]  # --distance-samples
# An output of the default method that is worse or near the line (families.may_be_worse) is
# measured again with this many samples, with its input, and judged on that reading: the
# sampled max is an estimate whose spread at a small feature can exceed the worse rule's 2%.
DENSE_SAMPLES = 1000000
# The peer: MeshLab's stock filter, run on every input (not a variant of our CLI).
PEER = "unsharp-mask"
# Inputs made by the project's own sampler tools, not by meshlabserver: made in parallel.
LOCAL_KINDS = ("vdb", "vdbproj", "scan")
# Grid samplers: their information limit (issue 60) is dual contouring with exact Hermite data
# on a grid of the same cell size (test_meshes/dual_contouring.h), for the generated shapes.
GRID_KINDS = ("mc", "umr", "vdb", "vdbproj")
SPLIT_FILE = os.path.join(HERE, "split.json")
REAL_DIR = os.path.join(SOURCE, "test_meshes", "real")

_print_lock = threading.Lock()


def log(*args):
    with _print_lock:
        print("[quality]", *args, flush=True)


# --------------------------------------------------------------------------- inputs
class InputSpec:
    """One way of making a chamfered (or competitor) mesh from a reference."""

    def __init__(self, kind, res_label, res_value, order):
        self.kind = kind
        self.res_label = res_label
        self.res_value = res_value  # cell size as a fraction of the diagonal (or depth/grid)
        self.order = order

    @property
    def key(self):
        return f"{self.kind}_{self.res_label.replace('%', 'pct').replace(' ', '')}"


INPUT_TITLES = {
    "asis": "the reference itself",
    "umr": "Uniform Mesh Resampling (MC)",
    "mc": "the project's marching cubes (vcglib, exact SDF)",
    "ier": "Isotropic Explicit Remeshing, features off",
    "csg": "CSG intersection with itself (marching intersections)",
    "poisson": "Screened Poisson from 100k points",
    "rimls": "Marching Cubes (RIMLS) from 100k points",
    "vdb": "OpenVDB volumeToMesh (voxel remesher, adaptivity 0, quads split)",
    "vdbproj": "OpenVDB volumeToMesh as Blender 3.4's voxel remesh with Preserve Volume "
               "(surface 0.3 voxel out, vertices cast along their normals onto the input)",
    "scan": "depth-camera scan: 26 depth views fused in a TSDF (voxel 1%)",
}


def input_specs(fast):
    if fast:
        return [InputSpec("asis", "-", None, 0), InputSpec("umr", "1%", 0.01, 2),
                InputSpec("mc", "1%", 0.01, 2.5)]
    return [
        InputSpec("asis", "-", None, 0),
        InputSpec("vdb", "2%", 0.02, 11),
        InputSpec("vdb", "1%", 0.01, 12),
        InputSpec("vdb", "0.5%", 0.005, 13),
        InputSpec("vdbproj", "2%", 0.02, 17),
        InputSpec("vdbproj", "1%", 0.01, 18),
        InputSpec("vdbproj", "0.5%", 0.005, 19),
        InputSpec("scan", "noise 0", 0.0, 14),
        InputSpec("scan", "noise 0.1 voxel", 0.1, 15),
        InputSpec("scan", "noise 0.2 voxel", 0.2, 16),
        InputSpec("umr", "2%", 0.02, 1),
        InputSpec("umr", "1%", 0.01, 2),
        InputSpec("umr", "0.5%", 0.005, 3),
        InputSpec("mc", "1%", 0.01, 3.5),
        InputSpec("ier", "2%", 0.02, 4),
        InputSpec("ier", "1%", 0.01, 5),
        InputSpec("ier", "0.5%", 0.005, 6),
        InputSpec("csg", "1%", 0.01, 7),
        InputSpec("poisson", "depth 7", 7, 8),
        InputSpec("rimls", "grid 100", 100, 10),
    ]


def mlx_for(spec, diag):
    if spec.kind == "umr":
        return meshlab.script(meshlab.uniform_resampling(spec.res_value * diag, diag))
    if spec.kind == "ier":
        return meshlab.script(meshlab.isotropic_remeshing(spec.res_value * diag, diag))
    if spec.kind == "csg":
        return meshlab.script(meshlab.csg_intersection(spec.res_value * diag, diag))
    if spec.kind == "poisson":
        return meshlab.script(meshlab.montecarlo_sampling(POINT_SAMPLES),
                              meshlab.screened_poisson(spec.res_value))
    if spec.kind == "rimls":
        return meshlab.script(meshlab.montecarlo_sampling(POINT_SAMPLES),
                              meshlab.rimls_marching_cubes(spec.res_value))
    raise ValueError(spec.kind)


# --------------------------------------------------------------------------- tools
class Tools:
    def __init__(self, build):
        self.build = build
        self.cli = self._find("edge-sharpener")
        self.distance = self._find("mesh-distance")
        self.generator = self._find("generate-test-meshes")
        self.server = os.path.join(build, "meshlab-prefix", "bin", "meshlabserver")
        vdb = os.path.join(build, "bench", "samplers", "vdb-remesh")
        self.vdb = vdb if os.access(vdb, os.X_OK) else None
        dual = os.path.join(build, "test_meshes", "dual-contour")
        self.dual = dual if os.access(dual, os.X_OK) else None
        self.scan = [SYSTEM_PYTHON, os.path.join(SOURCE, "bench", "samplers", "tsdf_scan.py")]
        self.scan_missing = _open3d_missing()

    def _find(self, name):
        for sub in ("apps", "test_meshes", "."):
            p = os.path.join(self.build, sub, name)
            if os.access(p, os.X_OK):
                return p
        sys.exit(f"bench/quality: {name} not found in {self.build} (build the project first)")


SYSTEM_PYTHON = "/usr/bin/python3"  # Debian's, where python3-open3d is installed


def _open3d_missing():
    """Why depth-camera scans cannot be made here ("" when they can)."""
    if not os.access(SYSTEM_PYTHON, os.X_OK):
        return f"{SYSTEM_PYTHON} not found"
    p = subprocess.run([SYSTEM_PYTHON, "-c", "import open3d"], capture_output=True)
    return "" if p.returncode == 0 else "Open3D (Debian python3-open3d) not installed"


def run_json(cmd, timeout):
    """Runs a command printing JSON. Returns (json or None, seconds, error message)."""
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.monotonic() - start, f"time limit ({timeout} s) exceeded"
    seconds = time.monotonic() - start
    if p.returncode != 0:
        err = (p.stderr.strip().splitlines() or [f"exit status {p.returncode}"])[-1]
        if p.returncode < 0:
            err = f"killed by signal {-p.returncode}: {err}"
        return None, seconds, err[:200]
    try:
        return json.loads(p.stdout), seconds, ""
    except json.JSONDecodeError as e:
        return None, seconds, f"bad JSON: {e}"


class DistanceMemo:
    """mesh-distance's answers keyed by what determines them: the two files' contents, the
    arguments and the mesh-distance binary itself. Outputs that several variants share are
    measured once (within a run), and the distances of the cached meshes (inputs, the peer's
    outputs) are kept in the cache between runs, like those meshes; the sharpener's outputs are
    measured anew by every run. A rebuilt mesh-distance or a changed file misses the memo."""

    def __init__(self, path, binary):
        self.path = path
        self.lock = threading.Lock()
        self.entries = {}
        self.kept = set()
        self.tool = _file_digest(binary)
        if os.path.exists(path):
            with open(path) as f:
                self.entries = json.load(f)
            self.kept = set(self.entries)

    def key(self, mesh, reference, args):
        return "|".join([self.tool, _file_digest(mesh), _file_digest(reference), *args])

    def get(self, key):
        with self.lock:
            return self.entries.get(key)

    def put(self, key, value, keep):
        with self.lock:
            self.entries[key] = value
            if keep:
                self.kept.add(key)

    def save(self):
        with self.lock:
            with open(self.path + ".tmp", "w") as f:
                json.dump({k: v for k, v in self.entries.items() if k in self.kept}, f)
            os.replace(self.path + ".tmp", self.path)


_digests = {}  # (path, size, mtime) -> sha1: a reference is measured against many times
_digests_lock = threading.Lock()


def _file_digest(path):
    st = os.stat(path)
    key = (os.path.abspath(path), st.st_size, st.st_mtime_ns)
    with _digests_lock:
        if key in _digests:
            return _digests[key]
    h = hashlib.sha1()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    with _digests_lock:
        _digests[key] = h.hexdigest()
    return _digests[key]


_memo = [None]  # the run's DistanceMemo (set in main)


def measure(tools, mesh, reference, timeout, samples=None, keep=False):
    """Two-sided distance. DISTANCE_SAMPLES in MeshLab's mode; the uniform mode keeps
    mesh-distance's own default, which the floors of the older tests were measured with.
    keep: `mesh` is a cached input whose distance the memo keeps between runs."""
    if samples is None and _distance_sampling[1] == "meshlab":
        samples = _distance_samples[0]
    count = ["--samples", str(samples)] if samples is not None else []
    args = ["--json", *_distance_sampling, *count]
    memo = _memo[0]
    key = memo.key(mesh, reference, args) if memo else None
    d = memo.get(key) if memo else None
    if d is None:
        d, _, err = run_json([tools.distance, mesh, reference, *args], timeout)
        if d is None:
            return None, err
        if memo:
            memo.put(key, d, keep)
    return {"max": d["symmetric"]["max_percent"], "mean": d["symmetric"]["mean_percent"],
            "rms": d["symmetric"]["rms_percent"], "max_fwd": d["forward"]["max_percent"],
            "max_bwd": d["backward"]["max_percent"], "faces": d["a"]["faces"],
            "vertices": d["a"]["vertices"], "diag": d["reference_diagonal"],
            "sampling": d.get("sampling", "uniform")}, ""


# --------------------------------------------------------------------------- models
class Model:
    def __init__(self, name, reference, source, group, note=""):
        self.half = None  # "tuning" or "validation" (split.json)
        self.name = name
        self.reference = reference  # what distances are measured against
        self.source = source  # what MeshLab remeshes (and the "as is" input)
        self.group = group
        self.note = note
        self.diag = None


def write_box_off(path, lo, hi):
    """The sharp cube of chamfer-cube.off: the box its face planes bound."""
    v = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    with open(path, "w") as f:
        f.write(f"OFF\n8 12 0\n")
        for p in v:
            f.write("%.9g %.9g %.9g\n" % p)
        for a, b, c, d in quads:
            f.write(f"3 {a} {b} {c}\n3 {a} {c} {d}\n")


def off_bbox(path):
    with open(path) as f:
        tokens = f.read().split()
    assert tokens[0] == "OFF"
    nv = int(tokens[1])
    xs = [float(t) for t in tokens[4:4 + 3 * nv]]
    lo = [min(xs[i::3]) for i in range(3)]
    hi = [max(xs[i::3]) for i in range(3)]
    return lo, hi


def collect_models(tools, cache, shared_dir, fast, only):
    models = []
    gen_dir = os.path.join(cache, "generated")
    os.makedirs(gen_dir, exist_ok=True)
    shapes = FAST_SHAPES if fast else GENERATED_SHAPES
    missing = [s for s in shapes
               if not os.path.exists(os.path.join(gen_dir, f"{s}_reference.ply"))]
    if missing:
        subprocess.run([tools.generator, gen_dir, "--cells", "0.01", "--shapes", ",".join(missing)],
                       check=True, stdout=subprocess.DEVNULL)
    for s in shapes:
        ref = os.path.join(gen_dir, f"{s}_reference.ply")
        note = "no sharp edges: must stay unchanged" if s == "sphere" else ""
        models.append(Model(s, ref, ref, "generated", note))
    real = {}
    if not fast:
        for path in sorted(glob.glob(os.path.join(REAL_DIR, "*"))):
            stem, ext = os.path.splitext(os.path.basename(path))
            if ext.lower() in (".off", ".obj", ".stl", ".ply"):
                real[stem] = path
                models.append(Model(stem, path, path, "real"))
    if not fast and shared_dir and os.path.isdir(shared_dir):
        for path in sorted(glob.glob(os.path.join(shared_dir, "*"))):
            base = os.path.basename(path)
            stem, ext = os.path.splitext(base)
            if ext.lower() not in (".off", ".obj", ".stl", ".ply") or stem in real:
                continue
            name = stem
            if stem == "chamfer-cube":
                box = os.path.join(cache, "chamfer-cube_sharp-box.off")
                lo, hi = off_bbox(path)
                write_box_off(box, lo, hi)
                models.append(Model(name, box, path, "shared",
                                    "already chamfered: reference = the box of its face planes; "
                                    "remeshers are not applied"))
                continue
            note = ("a scan with rounded edges: reference = the scan itself; must not be damaged"
                    if stem == "rocker-arm" else "")
            models.append(Model(name, path, path, "shared", note))
    if only:
        models = [m for m in models if m.name in only]
    assign_halves(models)
    return models


def load_split():
    with open(SPLIT_FILE) as f:
        return json.load(f)


def assign_halves(models):
    """Puts every model in its half (split.json); an unlisted reference is an error, so that
    no mesh enters the benchmark without its half being fixed by the stated rule."""
    split = load_split()
    tuning, validation = set(split["tuning"]), set(split["validation"])
    for m in models:
        if m.name in tuning:
            m.half = "tuning"
        elif m.name in validation:
            m.half = "validation"
        else:
            sys.exit(f"bench/quality: {m.name} is in neither half of {SPLIT_FILE}: add it by "
                     f"the rule stated there")


# --------------------------------------------------------------------------- steps
def make_input(server, model, spec, cache, refresh, timeout, tools_for_local=None):
    """Creates (or reuses) the chamfered input. Returns (path or None, info dict)."""
    if spec.kind == "asis":
        return model.source, {"status": "ok", "seconds": 0.0}
    if spec.kind == "mc":  # made by generate-test-meshes with the references
        if model.group != "generated":
            return None, {"status": "not applied", "why": "only for the generated exact shapes"}
        return os.path.join(cache, "generated", f"{model.name}_mc1.ply"), {"status": "ok"}
    if model.name == "chamfer-cube":
        return None, {"status": "not applied", "why": "already chamfered: only measured as is"}
    key = f"{model.name}__{spec.key}"
    if spec.kind in LOCAL_KINDS:
        return make_local_input(tools_for_local, model, spec, cache, refresh, timeout, key)
    hit = cached_info(cache, key, refresh)
    if hit is not None:
        return hit
    out = os.path.join(cache, "inputs", key + ".ply")
    if server is None:
        return None, {"status": "skipped", "why": "meshlabserver not available"}
    inputs = [model.source, model.source] if spec.kind == "csg" else [model.source]
    os.makedirs(os.path.dirname(out), exist_ok=True)  # MeshLab does not make it
    workdir = os.path.join(cache, "work", key)
    ok, seconds, why = server.run(inputs, out, mlx_for(spec, model.diag), workdir, timeout)
    if not ok and ("no output" in why or "empty mesh" in why):  # seen once in a while: retry
        ok, seconds, why = server.run(inputs, out, mlx_for(spec, model.diag), workdir, timeout)
    info = {"status": "ok" if ok else "failed", "seconds": round(seconds, 2)}
    if not ok:
        info["why"] = why
        log(f"{key}: MeshLab step failed ({why}); skipped")
    else:
        log(f"{key}: made in {seconds:.1f} s")
    store_info(cache, key, info)
    return (out if ok else None), info


def cached_info(cache, key, refresh):
    """(output path, info) of a cached step, or None when it must be (re)made."""
    out = os.path.join(cache, "inputs", key + ".ply")
    status_path = os.path.join(cache, "inputs", key + ".json")
    if not refresh and os.path.exists(status_path):
        with open(status_path) as f:
            info = json.load(f)
        if info["status"] != "ok" or os.path.exists(out):
            return (out if info["status"] == "ok" else None), info
    return None


def store_info(cache, key, info):
    status_path = os.path.join(cache, "inputs", key + ".json")
    os.makedirs(os.path.dirname(status_path), exist_ok=True)
    with open(status_path, "w") as f:
        json.dump(info, f)


def make_local_input(tools, model, spec, cache, refresh, timeout, key):
    """An input made by the project's own sampler tools (OpenVDB remesher, without or with
    projection onto the input's surface; TSDF scan)."""
    hit = cached_info(cache, key, refresh)
    if hit is not None:
        return hit
    out = os.path.join(cache, "inputs", key + ".ply")
    if spec.kind in ("vdb", "vdbproj"):
        if tools.vdb is None:
            return None, {"status": "skipped", "why": "vdb-remesh not built (OpenVDB not installed)"}
        cmd = [tools.vdb, model.source, out, "--voxel-fraction", str(spec.res_value)]
        if spec.kind == "vdbproj":
            cmd.append("--project")
    else:
        if tools.scan_missing:
            return None, {"status": "skipped", "why": tools.scan_missing}
        cmd = [*tools.scan, model.source, out, "--voxel-fraction", "0.01",
               "--noise", str(spec.res_value)]
    os.makedirs(os.path.dirname(out), exist_ok=True)
    made, seconds, why = run_json(cmd, timeout)
    info = {"status": "ok" if made is not None else "failed", "seconds": round(seconds, 2)}
    if made is None:
        info["why"] = why
        log(f"{key}: sampler failed ({why}); skipped")
    else:
        info["sampler"] = made
        log(f"{key}: made in {seconds:.1f} s")
    store_info(cache, key, info)
    return (out if made is not None else None), info


def make_peer_output(server, model, spec, in_path, cache, refresh, timeout):
    """MeshLab's "UnSharp Mask Geometry" (defaults) applied to the input, cached like it."""
    key = f"{model.name}__{spec.key}__{PEER}"
    hit = cached_info(cache, key, refresh)
    if hit is not None:
        return hit
    if server is None:
        return None, {"status": "skipped", "why": "meshlabserver not available"}
    out = os.path.join(cache, "inputs", key + ".ply")
    os.makedirs(os.path.dirname(out), exist_ok=True)  # MeshLab does not make it
    workdir = os.path.join(cache, "work", key)
    ok, seconds, why = server.run([in_path], out, meshlab.script(meshlab.unsharp_mask_geometry()),
                                  workdir, timeout)
    info = {"status": "ok" if ok else "failed", "seconds": round(seconds, 2)}
    if not ok:
        info["why"] = why
        log(f"{key}: MeshLab's UnSharp Mask failed ({why})")
    store_info(cache, key, info)
    return (out if ok else None), info


def measure_run(tools, out, reference, timeout, row, keep=False):
    """Measures a run's output against the reference into its row; False when that failed."""
    d, err = measure(tools, out, reference, timeout, keep=keep)
    if d is None:
        row.update(status="measure failed", why=err)
        return False
    row["after"] = d
    row["status"] = "ok"
    return True


def measure_dense(tools, in_path, out, reference, timeout):
    """The input's and the output's max and RMS with DENSE_SAMPLES (None when that failed)."""
    rows = {}
    for side, path in (("before", in_path), ("after", out)):
        d, _ = measure(tools, path, reference, timeout, samples=DENSE_SAMPLES,
                       keep=side == "before")
        if d is None:
            return None
        rows[side] = {"max": d["max"], "rms": d["rms"]}
    return {"samples": DENSE_SAMPLES, **rows}


def measure_peer(tools, model, in_path, peer, timeout):
    """The peer's row, shaped like a sharpener run."""
    out, info = peer
    row = {"method": PEER, "multiplier": DEFAULT_MULTIPLIER, "peer": True}
    if out is None:
        row.update(status="peer failed", why=info.get("why", info["status"]))
        return row
    row["seconds"] = info.get("seconds")
    measure_run(tools, out, model.reference, timeout, row, keep=True)
    return row


def designed_mask(tools, model, in_path, cache, timeout):
    """For a generated shape with designed features: the faces of its input on them (a list
    file, made by generate-test-meshes --designed-faces, one sample spacing wide) and the
    features (kind, width across); (None, []) for the other shapes."""
    if model.group != "generated" or model.name not in DESIGNED_SHAPES:
        return None, []
    masks = os.path.join(cache, "masks")
    os.makedirs(masks, exist_ok=True)
    stem = os.path.splitext(os.path.basename(in_path))[0]
    path = os.path.join(masks, stem + "_designed.txt")
    subprocess.run([tools.generator, masks, "--designed-faces", in_path, "--shapes", model.name],
                   check=True, stdout=subprocess.DEVNULL, timeout=timeout)
    return path, read_designed_faces(path)


def read_designed_faces(path):
    """The features (kind, size, width across) a designed-face list of generate-test-meshes
    --designed-faces names in its header lines ("# bevel 0.05: 0.05 wide")."""
    features = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) == 5 and words[0] == "#" and words[4] == "wide":
                features.append({"kind": words[1], "size": float(words[2].rstrip(":")),
                                 "width": float(words[3])})
    return features


_designed = None


def designed_features(name):
    """The designed features of reference `name` when it is not a generated shape
    (designed.json)."""
    global _designed
    if _designed is None:
        with open(DESIGNED_FILE) as f:
            _designed = json.load(f)["references"]
    return _designed.get(name, {}).get("features", [])


def sharpen_and_measure(tools, model, spec, in_path, in_dist, method, mult, cache, timeout,
                        mask=None):
    key = f"{model.name}__{spec.key}__{method}_m{mult:g}"
    out = os.path.join(cache, "outputs", key + ".ply")
    row = {"method": method, "multiplier": mult}
    variant = (["--method", "auto", "--skip-faces", mask] if method == SELECTION_VARIANT
               else VARIANTS[method])
    cmd = [tools.cli, in_path, out, *variant, "--multiplier", str(mult), "--json", "-q"]
    rep, wall, err = run_json(cmd, timeout)
    if rep is None:
        row.update(status="sharpen failed", why=err)
        log(f"{key}: sharpening failed: {err}")
        return row
    row["seconds"] = rep.get("seconds", wall)
    row["chamfer_edges"] = rep["filters"]["chamfer_edges"]
    row["corner_faces"] = rep["filters"]["corner_faces"]
    row["moved"] = rep["placement"]["moved"]
    row["fallbacks"] = rep["placement"]["fallbacks"]
    row["geometry_changed"] = rep.get("geometry_changed", True)
    if "extended" in rep:
        row["sample_spacing"] = rep["extended"]["sample_spacing"]
    if "evidence" in rep:  # why the default left what it left (families.default_misses)
        row["evidence"] = {k: rep["evidence"][k] for k in (
            "features", "weak_features", "already_sharp_features", "refused_fraction",
            "refused_bound", "median_lift", "noise_spacings", "planar_fraction",
            "whole_mesh_left", "flattened_vertices")}
    if not measure_run(tools, out, model.reference, timeout, row):
        return row
    if (method == families.DEFAULT_METHOD and mult == DEFAULT_MULTIPLIER
            and _distance_sampling[1] == "meshlab" and families.may_be_worse(in_dist, row["after"])):
        row["dense"] = measure_dense(tools, in_path, out, model.reference, timeout)
    if spec.kind == "asis" or model.name in ("sphere", "rocker-arm"):
        # How much the sharpener changed its input (unchanged-ness of smooth meshes).
        c, _ = measure(tools, out, in_path, timeout)
        if c is not None:
            # in % of the reference's diagonal, like every other number
            scale = c["diag"] / in_dist["diag"] if in_dist["diag"] else 1.0
            row["change_max"] = c["max"] * scale
            row["change_rms"] = c["rms"] * scale
    return row


def measure_limit(tools, model, spec, cache, timeout):
    """The information limit of a grid sampler's input (issue 60): the distance of the dual
    contouring of the generated shape with exact Hermite data, on a grid of the input's cell
    size, to the reference; None where there is none (a reference mesh, a sampler without a
    grid, dual-contour not built)."""
    if model.group != "generated" or spec.kind not in GRID_KINDS or tools.dual is None:
        return None
    percent = f"{spec.res_value * 100:g}"
    out = os.path.join(cache, "limit", f"{model.name}__{percent}pct.ply")
    if not os.path.exists(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        # Two inputs on one grid (UMR and marching cubes at 1%) may make it at once: each
        # writes its own file, and either replace leaves the same mesh.
        tmp = f"{out}.{threading.get_ident()}.tmp"
        made = subprocess.run([tools.dual, model.name, percent, tmp],
                              capture_output=True, text=True, timeout=timeout)
        if made.returncode != 0:
            log(f"{model.name}__{spec.key}: dual-contour failed: {made.stderr.strip()}")
            return None
        os.replace(tmp, out)
    d, err = measure(tools, out, model.reference, timeout, keep=True)
    if d is None:
        log(f"{model.name}__{spec.key}: the limit is not measurable: {err}")
    return d


def run_case(tools, model, spec, in_path, info, cache, multipliers, timeout, peer=None):
    """Measures the input, sharpens it with every variant and measures each output; `peer`,
    when given, makes (or reads from the cache) the peer's output: (path or None, info)."""
    case = {"model": model.name, "group": model.group, "half": model.half, "input": spec.kind,
            "input_title": INPUT_TITLES[spec.kind], "resolution": spec.res_label,
            "res_value": spec.res_value, "order": spec.order, "make": info, "runs": []}
    if in_path is None:
        return case
    d, err = measure(tools, in_path, model.reference, timeout, keep=True)
    if d is None:
        case["make"] = dict(info, status="failed", why=f"input not measurable: {err}")
        return case
    case["before"] = d
    limit = measure_limit(tools, model, spec, cache, timeout)
    if limit is not None:
        case["limit"] = limit
    for method in VARIANTS:
        for mult in multipliers if method in SWEPT_VARIANTS else [DEFAULT_MULTIPLIER]:
            case["runs"].append(sharpen_and_measure(tools, model, spec, in_path, d, method, mult,
                                                    cache, timeout))
    mask, case["designed"] = designed_mask(tools, model, in_path, cache, timeout)
    if mask is None:
        case["designed"] = designed_features(model.name)
    elif "auto" in VARIANTS:
        case["runs"].append(sharpen_and_measure(tools, model, spec, in_path, d, SELECTION_VARIANT,
                                                DEFAULT_MULTIPLIER, cache, timeout, mask))
    if peer is not None:
        case["runs"].append(measure_peer(tools, model, in_path, peer(), timeout))
    return case


def diagonal(tools, path):
    d, err = measure(tools, path, path, 300, samples=4, keep=True)
    if d is None:
        raise RuntimeError(f"{path}: {err}")
    return d["diag"]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(SOURCE, "build"), help="build directory")
    ap.add_argument("--cache", help="cache/work directory (default BUILD/quality-cache)")
    ap.add_argument("--shared", default=os.path.join(SOURCE, "..", "shared", "meshes"),
                    help="reference meshes (skipped when absent)")
    ap.add_argument("--fast", action="store_true",
                    help="generated shapes only, UMR 1%% only, multiplier 2 (the CTest subset)")
    ap.add_argument("--models", help="comma-separated model names to run (default all)")
    ap.add_argument("--inputs", help="comma-separated input kinds to make (asis, umr, mc, ier, "
                    "csg, poisson, rimls, vdb, vdbproj, scan; default all)")
    ap.add_argument("--input-keys", help="comma-separated inputs by key, kind and resolution "
                    "as in the cache's file names (e.g. vdb_1pct,scan_noise0,umr_0.5pct)")
    ap.add_argument("--distance-sampling", choices=("meshlab", "uniform"), default="meshlab",
                    help="mesh-distance --sampling: meshlab (as MeshLab's Hausdorff Distance "
                    "filter, the default) or uniform (the project's own spreading)")
    ap.add_argument("--distance-samples", type=int, default=DISTANCE_SAMPLES,
                    help="samples per side in MeshLab's mode (default %(default)s; more makes "
                    "the sampled max error nearer the true one, and the run slower)")
    ap.add_argument("--variants", help="comma-separated variants to run (default all: "
                    + ", ".join(VARIANTS) + ")")
    ap.add_argument("--no-peer", action="store_true",
                    help="do not run MeshLab's UnSharp Mask Geometry (the peer row)")
    ap.add_argument("--jobs", type=int, default=2, help="parallel sharpen/measure jobs")
    ap.add_argument("--timeout", type=int, default=600, help="time limit of each step, seconds")
    ap.add_argument("--refresh", action="store_true", help="remake the cached MeshLab inputs")
    ap.add_argument("--results", help="results JSON (default CACHE/results.json)")
    ap.add_argument("--no-report", action="store_true", help="do not write docs/results.md")
    ap.add_argument("--inputs-only", action="store_true",
                    help="only make (or check) the cached inputs and the peer's outputs and "
                    "measure them; no sharpening, no report")
    ap.add_argument("--report-only", action="store_true",
                    help="only rewrite docs/results.md and the figures from the results JSON")
    ap.add_argument("--docs", default=os.path.join(SOURCE, "docs"), help="docs directory")
    args = ap.parse_args()

    build = os.path.abspath(args.build)
    _distance_sampling[1] = args.distance_sampling
    _distance_samples[0] = args.distance_samples
    cache = os.path.abspath(args.cache or os.path.join(build, "quality-cache"))
    os.makedirs(os.path.join(cache, "outputs"), exist_ok=True)
    tools = Tools(build)
    _memo[0] = DistanceMemo(os.path.join(cache, "distances.json"), tools.distance)
    server = meshlab.Server(tools.server, os.path.join(cache, "home"))
    if not server.available():
        log(f"meshlabserver not available ({tools.server}, xvfb-run): MeshLab inputs skipped")
        server = None

    out = args.results or os.path.join(cache, "results.json")
    if args.report_only:
        import report
        with open(out) as f:
            results = json.load(f)
        # The references' designed features are metadata (designed.json), not measurements:
        # read afresh, so that an entry added since the run splits its worse count.
        for case in results["cases"]:
            if case.get("group") != "generated":
                case["designed"] = designed_features(case["model"])
        report.write(results, tools, cache, args.docs)
        return

    if args.variants:
        for name in [v for v in VARIANTS if v not in args.variants.split(",")]:
            del VARIANTS[name]
    only = set(args.models.split(",")) if args.models else None
    models = collect_models(tools, cache, os.path.abspath(args.shared), args.fast, only)
    specs = input_specs(args.fast)
    if args.inputs:
        specs = [s for s in specs if s.kind in args.inputs.split(",")]
    if args.input_keys:
        specs = [s for s in specs if s.key in args.input_keys.split(",")]
    started = time.monotonic()

    # (a) Inputs. MeshLab's, one at a time (two Xvfb servers would race for a display), while
    # the project's own samplers (OpenVDB, TSDF scans) run beside them in a pool.
    plan = []
    local_pool = concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs))
    for model in models:
        model.diag = diagonal(tools, model.reference)
    for model in models:
        for spec in specs:
            if spec.kind in LOCAL_KINDS:
                made = local_pool.submit(make_input, server, model, spec, cache, args.refresh,
                                         args.timeout, tools)
            else:
                made = make_input(server, model, spec, cache, args.refresh, args.timeout)
            mults = [DEFAULT_MULTIPLIER]
            if not args.fast and spec.kind in ("umr", "ier") and spec.res_label == "1%":
                mults = list(SWEEP)
            plan.append([model, spec, made, mults])
    local_pool.shutdown(wait=True)
    for item in plan:
        if isinstance(item[2], concurrent.futures.Future):
            item[2] = item[2].result()
    # The peer (MeshLab again) on every input but the references themselves: made in the
    # sharpening pool below, under a lock (two Xvfb servers would race for a display).
    peers = []
    server_lock = threading.Lock()
    for model, spec, (in_path, _), _ in plan:
        use_peer = in_path and not args.no_peer and spec.kind != "asis"

        def peer(model=model, spec=spec, in_path=in_path):
            with server_lock:
                return make_peer_output(server, model, spec, in_path, cache, args.refresh,
                                        args.timeout)
        peers.append(peer if use_peer else None)
    log(f"inputs ready after {time.monotonic() - started:.0f} s; sharpening and measuring "
        f"{sum(1 for p in plan if p[2][0])} inputs")
    if args.inputs_only:
        for (model, _, (in_path, _), _), peer in zip(plan, peers):
            if in_path:
                measure(tools, in_path, model.reference, args.timeout, keep=True)
            if peer is not None:
                made, _ = peer()
                if made:
                    measure(tools, made, model.reference, args.timeout, keep=True)
            _memo[0].save()
        log(f"inputs, the peer's outputs and their distances cached after "
            f"{time.monotonic() - started:.0f} s")
        return

    # (b, c) sharpen + measure, in parallel; the validation half first. The results file is
    # rewritten as cases finish (marked partial), so an interrupted run still leaves a report
    # (--report-only) of what it measured.
    notes = {m.name: m.note for m in models if m.note}
    halves = {m.name: m.half for m in models}
    diags = {m.name: m.diag for m in models}
    work = sorted(zip(plan, peers), key=lambda item: item[0][0].half != "validation")

    def results_of(cases, partial):
        return {"generated_at": time.strftime("%Y-%m-%d %H:%M:%S"),
                "fast": args.fast, "seconds": round(time.monotonic() - started, 1),
                "partial": partial, "planned_inputs": len(work),
                "methods": list(VARIANTS), "default_multiplier": DEFAULT_MULTIPLIER,
                "sweep": list(SWEEP), "notes": notes, "diagonals": diags, "halves": halves,
                "split_rule": load_split()["rule"],
                "distance_sampling": [*_distance_sampling] + (
                    ["--samples", str(_distance_samples[0])] if _distance_sampling[1] == "meshlab"
                    else []),
                "cases": cases, "git": _git_describe()}

    def save(results):
        with open(out + ".tmp", "w") as f:
            json.dump(results, f, indent=1)
        os.replace(out + ".tmp", out)

    done = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_case, tools, m, s, made[0], made[1], cache, mults,
                               args.timeout, peer): i
                   for i, ((m, s, made, mults), peer) in enumerate(work)}
        for fut in concurrent.futures.as_completed(futures):
            done[futures[fut]] = fut.result()
            if len(done) % 5 == 0 and len(done) < len(work):
                save(results_of([done[i] for i in sorted(done)], partial=True))
                _memo[0].save()
    results = results_of([done[i] for i in sorted(done)], partial=False)
    save(results)
    _memo[0].save()
    log(f"results: {out} ({results['seconds']:.0f} s)")

    if not args.no_report:
        import report
        report.write(results, tools, cache, args.docs)


def _git_describe():
    try:
        rev = subprocess.run(["git", "-C", SOURCE, "rev-parse", "--short", "HEAD"],
                             capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", SOURCE, "status", "--porcelain", "--", "vcg_ext"],
                               capture_output=True, text=True).stdout.strip()
        return rev + (" + uncommitted vcg_ext changes" if dirty else "")
    except OSError:
        return "?"


if __name__ == "__main__":
    main()
