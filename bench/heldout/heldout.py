"""What the held-out checks (bench/heldout/*.py) share: their command line, the references and
halves, the sharpening and measuring of one input, and the table each sampler prints.

A held-out check remeshes every reference with a tool outside the benchmark, sharpens it with
one method and measures both (mesh-distance --sampling meshlab; "worse" by the benchmark's
rule, bench/quality/families.py). No threshold is chosen on it.
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
sys.path[:0] = [os.path.join(SOURCE, "bench", "quality"), os.path.join(SOURCE, "bench", "study")]
import families  # noqa: E402
import run as quality_run  # noqa: E402
from evidence_study import references  # noqa: E402


def parse_args(doc, script):
    """--build, --shared, --method, --out and further edge-sharpener options after --, of the
    check bench/heldout/`script` (args.script). Every check reads meshes with Open3D: it exits
    when Open3D is not installed."""
    ap = argparse.ArgumentParser(description=doc,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(SOURCE, "build"))
    ap.add_argument("--shared", default=os.path.join(SOURCE, "..", "shared", "meshes"))
    ap.add_argument("--method", default="auto")
    ap.add_argument("--out", help="also write the table(s) to this markdown file")
    ap.add_argument("extra", nargs="*", help="further edge-sharpener options (after --)")
    args = ap.parse_args()
    # The samplers run in their own work directories: a relative --build would not be found.
    args.build = os.path.abspath(args.build)
    args.script = script
    require_open3d(os.path.splitext(script)[0])
    return args


def require_open3d(script):
    try:
        import open3d  # noqa: F401
    except ImportError:
        sys.exit(f"{script}: Open3D (Debian python3-open3d) is not installed")


def load_reference(reference):
    """The reference as Open3D reads it, duplicated vertices merged (STL repeats them)."""
    import open3d as o3d
    mesh = o3d.io.read_triangle_mesh(reference)
    mesh.remove_duplicated_vertices()
    return mesh


def held_out_references(args):
    """Name -> reference path: the generated shapes the quality benchmark wrote, test_meshes/real
    and ../shared/meshes; chamfer-cube left out (its reference is another shape)."""
    refs = references(os.path.join(args.build, "quality-cache"), args.shared)
    refs.pop("chamfer-cube", None)
    return refs


def halves():
    """Reference name -> "tuning" or "validation" (bench/quality/split.json)."""
    with open(os.path.join(SOURCE, "bench", "quality", "split.json")) as f:
        split = json.load(f)
    return {m: h for h in ("tuning", "validation") for m in split[h]}


def distance(tool, mesh, reference):
    p = subprocess.run([tool, mesh, reference, "--json", "--sampling", "meshlab", "--samples",
                        str(quality_run.DISTANCE_SAMPLES)], capture_output=True, text=True, check=True)
    d = json.loads(p.stdout)["symmetric"]
    return {"max": d["max_percent"], "rms": d["rms_percent"]}


class Table:
    """One sampler's rows (reference, half, max and RMS before -> after, worse), with the
    geometric means of the reduction factors per half and the worse count."""

    def __init__(self, title, args):
        self.title, self.args = title, args
        self.sharpener = os.path.join(args.build, "apps", "edge-sharpener")
        self.tool = os.path.join(args.build, "apps", "mesh-distance")
        self.rows, self.worse, self.skipped = [], [], 0
        self.factors = {"tuning": [], "validation": []}

    def skip(self, name, half, why):
        self.rows.append(f"| {name} | {half} | {why} | | |")
        self.skipped += 1

    def make_and_measure(self, name, half, made, reference, make):
        """Makes `made` by make() ("" or why not) unless it exists, then measures it."""
        if not os.path.exists(made):
            why = make()
            if why:
                self.skip(name, half, f"not made: {why}")
                return
        self.measure(name, half, made, reference)

    def measure(self, name, half, made, reference):
        """Sharpens `made` (into made__METHOD.ply) and adds its row."""
        sharpened = f"{os.path.splitext(made)[0]}__{self.args.method}.ply"
        run = subprocess.run([self.sharpener, made, sharpened, "--method", self.args.method,
                              "--quiet", *self.args.extra], capture_output=True, text=True)
        if run.returncode != 0:
            self.skip(name, half, f"refused: {run.stderr.strip()}")
            return
        before = distance(self.tool, made, reference)
        after = distance(self.tool, sharpened, reference)
        bad = families.is_worse(before, after)
        if bad:
            self.worse.append(name)
        if half in self.factors and name not in families.NO_SHARP_FEATURES:
            self.factors[half].append((before["max"] / after["max"], before["rms"] / after["rms"]))
        self.rows.append(f"| {name} | {half} | {before['max']:.3g} -> {after['max']:.3g} | "
                         f"{before['rms']:.3g} -> {after['rms']:.3g} | "
                         f"{'**worse**' if bad else ''} |")

    def text(self):
        lines = [f"{self.title}; `--method {self.args.method}` {' '.join(self.args.extra)}", "",
                 "| reference | half | max (% diag) | RMS (% diag) | |", "|---|---|---|---|---|",
                 *self.rows, ""]
        for h, fs in self.factors.items():
            if fs:
                lines.append(f"{h}: geometric means max ×{families._gmean([f[0] for f in fs]):.2f}"
                             f" / RMS ×{families._gmean([f[1] for f in fs]):.2f} over {len(fs)}")
        measured = len(self.rows) - self.skipped
        lines.append(f"worse: {len(self.worse)} of {measured}"
                     + (f" ({', '.join(self.worse)})" if self.worse else "")
                     + (f"; {self.skipped} not made or refused" if self.skipped else ""))
        return "\n".join(lines)


def write_markdown(args, heading, minutes, body):
    """The --out file: a heading, how it was written, the body."""
    with open(args.out, "w") as f:
        f.write(f"# {heading}\n\n"
                f"Written by `/usr/bin/python3 bench/heldout/{args.script} --out "
                f"{os.path.relpath(args.out, SOURCE)}` (about {minutes} minutes). No threshold "
                "was fitted to it. Distances in % of the reference's diagonal (mesh-distance "
                "--sampling meshlab); **worse** = max up by more than 2% or RMS by more than "
                "1%.\n\n" + body)


def run_samplers(args, samplers, table, work, heading, minutes, made, notes):
    """Each sampler's table, table(sampler, refs, half, work, args) with its meshes in `work`
    (a directory of --build), printed and, with --out, written between `made` (how the inputs
    were made) and `notes`."""
    work = os.path.join(args.build, work)
    os.makedirs(work, exist_ok=True)
    refs, half = held_out_references(args), halves()
    text = "\n\n".join(table(s, refs, half, work, args) for s in samplers)
    print(text)
    if args.out:
        write_markdown(args, heading, minutes, made + "\n\n" + text + "\n\n" + notes)
