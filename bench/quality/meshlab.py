"""MeshLab filter scripts (.mlx) for the quality benchmark, and running meshlabserver.

Debian's meshlabserver 2020.09 keeps its asserts: a script that leaves out any
parameter of a filter aborts, so every filter below writes all of its parameters
(names taken from MeshLab 2020.09's plugin sources). Sizes are absolute: the
caller converts fractions of the reference's bounding-box diagonal.
"""
import os
import re
import subprocess
import time


def _p_float(name, value):
    return f'  <Param name="{name}" type="RichFloat" value="{value:.9g}"/>'


def _p_int(name, value):
    return f'  <Param name="{name}" type="RichInt" value="{int(value)}"/>'


def _p_bool(name, value):
    return f'  <Param name="{name}" type="RichBool" value="{"true" if value else "false"}"/>'


def _p_absperc(name, value, lo, hi):
    return (f'  <Param name="{name}" type="RichAbsPerc" value="{value:.9g}" '
            f'min="{lo:.9g}" max="{hi:.9g}"/>')


def _p_enum(name, value, labels):
    vals = " ".join(f'enum_val{i}="{v}"' for i, v in enumerate(labels))
    return (f'  <Param name="{name}" type="RichEnum" value="{int(value)}" '
            f'enum_cardinality="{len(labels)}" {vals}/>')


def _p_mesh(name, value):
    return f'  <Param name="{name}" type="RichMesh" value="{int(value)}"/>'


def _filter(name, params):
    return f' <filter name="{name}">\n' + "\n".join(params) + "\n </filter>"


def script(*filters):
    return "<!DOCTYPE FilterScript>\n<FilterScript>\n" + "\n".join(filters) + "\n</FilterScript>\n"


def uniform_resampling(cell, diag):
    """Marching cubes on the signed distance field (chamfers every sharp edge)."""
    return _filter("Uniform Mesh Resampling", [
        _p_absperc("CellSize", cell, 0, diag),
        _p_absperc("Offset", 0, -diag / 5, diag / 5),
        _p_bool("mergeCloseVert", False),
        _p_bool("discretize", False),
        _p_bool("multisample", False),
        _p_bool("absDist", False),
    ])


def isotropic_remeshing(target_len, diag, iterations=12):
    """Isotropic explicit remeshing with feature preservation off (crease angle 181)."""
    return _filter("Remeshing: Isotropic Explicit Remeshing", [
        _p_int("Iterations", iterations),
        _p_bool("Adaptive", False),
        _p_bool("SelectedOnly", False),
        _p_absperc("TargetLen", target_len, 0, diag),
        _p_float("FeatureDeg", 181),
        _p_bool("CheckSurfDist", False),
        _p_absperc("MaxSurfDist", 0.01 * diag, 0, diag),
        _p_bool("SplitFlag", True),
        _p_bool("CollapseFlag", True),
        _p_bool("SwapFlag", True),
        _p_bool("SmoothFlag", True),
        _p_bool("ReprojectFlag", True),
    ])


def quadric_decimation(fraction):
    """Quadric Edge Collapse Decimation to `fraction` of the faces, every other parameter at
    MeshLab 2020.09's defaults (optimal placement on, topology and normals not preserved)."""
    return _filter("Simplification: Quadric Edge Collapse Decimation", [
        _p_int("TargetFaceNum", 0),
        _p_float("TargetPerc", fraction),
        _p_float("QualityThr", 0.3),
        _p_bool("PreserveBoundary", False),
        _p_float("BoundaryWeight", 1),
        _p_bool("PreserveNormal", False),
        _p_bool("PreserveTopology", False),
        _p_bool("OptimalPlacement", True),
        _p_bool("PlanarQuadric", False),
        _p_float("PlanarWeight", 0.001),
        _p_bool("QualityWeight", False),
        _p_bool("AutoClean", True),
        _p_bool("Selected", False),
    ])


def csg_intersection(delta, diag):
    """Marching intersections: layer 0 intersected with its copy in layer 1.

    (The union of a mesh with itself hangs in MeshLab 2020.09; the intersection works.)"""
    return _filter("CSG Operation", [
        _p_mesh("FirstMesh", 0),
        _p_mesh("SecondMesh", 1),
        _p_absperc("Delta", delta, 0, diag),
        _p_int("SubDelta", 32),
        _p_enum("Operator", 0, ["Intersection", "Union", "Difference"]),
    ])


def montecarlo_sampling(samples):
    """A point set in a new layer, with normals interpolated from the (normalized) vertex normals.

    (Per-face normals are not normalized in MeshLab 2020.09: RIMLS then fails.)"""
    return _filter("Montecarlo Sampling", [
        _p_int("SampleNum", samples),
        _p_bool("Weighted", False),
        _p_bool("PerFaceNormal", False),
        _p_float("RadiusVariance", 1),
        _p_bool("ExactNum", True),
        _p_bool("EdgeSampling", False),
    ])


def screened_poisson(depth):
    return _filter("Surface Reconstruction: Screened Poisson", [
        _p_bool("visibleLayer", False),
        _p_int("depth", depth),
        _p_int("fullDepth", 5),
        _p_int("cgDepth", 0),
        _p_float("scale", 1.1),
        _p_float("samplesPerNode", 1.5),
        _p_float("pointWeight", 4),
        _p_int("iters", 8),
        _p_bool("confidence", False),
        _p_bool("preClean", False),
    ])


def rimls_marching_cubes(resolution, filter_scale=4):
    """Robust implicit MLS (feature-preserving) + marching cubes on the point set."""
    return _filter("Marching Cubes (RIMLS)", [
        _p_float("FilterScale", filter_scale),
        _p_float("ProjectionAccuracy", 1e-4),
        _p_int("MaxProjectionIters", 15),
        _p_float("SigmaN", 0.75),
        _p_int("MaxRefittingIters", 3),
        _p_int("Resolution", resolution),
    ])


def unsharp_mask_geometry():
    """MeshLab's stock "UnSharp Mask Geometry" at its default parameters (filter_unsharp.cpp):
    the peer a MeshLab user already has for sharpening a mesh."""
    return _filter("UnSharp Mask Geometry", [
        _p_float("weight", 0.3),
        _p_float("weightOrig", 1.0),
        _p_int("iterations", 5),
    ])


def hausdorff(sampled, target, samples, max_dist, diag):
    """One-sided Hausdorff Distance (vertices + edges + faces sampled); logs min/max/mean/RMS."""
    return _filter("Hausdorff Distance", [
        _p_mesh("SampledMesh", sampled),
        _p_mesh("TargetMesh", target),
        _p_bool("SaveSample", False),
        _p_bool("SampleVert", True),
        _p_bool("SampleEdge", True),
        _p_bool("SampleFauxEdge", False),
        _p_bool("SampleFace", True),
        _p_int("SampleNum", samples),
        _p_absperc("MaxDist", max_dist, 0, diag),
    ])


class Server:
    """meshlabserver (the project's private prefix, so that our plugin is there too) under Xvfb."""

    def __init__(self, executable, home, memory_gib=6):
        self.memory_gib = memory_gib
        self.executable = executable
        self.home = home
        os.makedirs(os.path.join(home, "runtime"), exist_ok=True)
        os.chmod(os.path.join(home, "runtime"), 0o700)

    def available(self):
        return os.access(self.executable, os.X_OK) and _which("xvfb-run") is not None

    def run(self, inputs, output, mlx_text, workdir, timeout):
        """Runs one script. Returns (ok, seconds, message); never raises on a MeshLab failure."""
        os.makedirs(workdir, exist_ok=True)
        mlx = os.path.join(workdir, "script.mlx")
        with open(mlx, "w") as f:
            f.write(mlx_text)
        log = os.path.join(workdir, "log.txt")
        # A memory cap turns MeshLab's runaway allocations (Uniform Mesh Resampling on sliver
        # fans) into a quick bad_alloc instead of the kernel's OOM killer.
        cmd = ["timeout", "-k", "10", str(int(timeout)), "bash", "-c",
               f'ulimit -v {int(self.memory_gib * 1024 * 1024)} && exec "$@"', "meshlabserver",
               "xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", self.executable]
        for path in inputs:
            cmd += ["-i", path]
        if output:
            cmd += ["-o", output]
        cmd += ["-s", mlx, "-l", log]
        env = dict(os.environ, HOME=self.home, XDG_RUNTIME_DIR=os.path.join(self.home, "runtime"))
        env.pop("QT_QPA_PLATFORM", None)
        start = time.monotonic()
        with open(os.path.join(workdir, "server.out"), "w") as out:
            rc = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT, env=env, cwd=workdir)
        seconds = time.monotonic() - start
        with open(os.path.join(workdir, "server.out"), errors="replace") as f:
            text = f.read()
        if rc == 124 or (rc == 137 and seconds >= timeout):
            return False, seconds, f"time limit ({int(timeout)} s) exceeded"
        if "bad_alloc" in text or rc == 137:
            return False, seconds, (f"meshlabserver ran out of memory (capped at "
                                    f"{self.memory_gib:g} GiB)")
        if "Failed saving" in text:
            return False, seconds, "meshlabserver made an empty mesh (\"Failed saving\")"
        if rc != 0:
            m = re.search(r"(Assertion [^\n]*|terminate called[^\n]*|what\(\):[^\n]*|"
                          r"[Ff]ailed[^\n]*)", text)
            why = m.group(1).strip() if m else text.strip().splitlines()[-1:] or ["?"]
            if isinstance(why, list):
                why = why[0]
            kind = "aborted" if rc in (134, 250, 6) or rc > 128 else f"exit status {rc}"
            return False, seconds, f"meshlabserver {kind}: {why[:160]}"
        if output and not os.path.exists(output):
            return False, seconds, "meshlabserver wrote no output"
        return True, seconds, ""

    @staticmethod
    def hausdorff_results(log_path):
        """The (min, max, mean, RMS) absolute results of each Hausdorff Distance, in order.

        meshlabserver prints the whole log after every filter: read the last copy."""
        with open(log_path, errors="replace") as f:
            lines = f.read().splitlines()
        last = 0
        for i, line in enumerate(lines):
            if line.startswith("filter: "):
                last = i + 1
        rows = []
        for line in lines[last:]:
            m = re.match(r"\s+min : (\S+)\s+max (\S+)\s+mean : (\S+)\s+RMS : (\S+)", line)
            if m:
                rows.append(tuple(float(x) for x in m.groups()))
        # Each filter logs the absolute numbers, then the same relative to the diagonal.
        return rows[0::2]


def _which(name):
    for d in os.environ.get("PATH", "").split(os.pathsep):
        p = os.path.join(d, name)
        if os.access(p, os.X_OK):
            return p
    return None
