"""What the held-out checks (bench/heldout/*.py) share: their command line, the references and
halves, the sharpening and measuring of one input, and the table each sampler prints.

A held-out check remeshes every reference with a tool outside the benchmark, sharpens it with
one method and measures both (mesh-distance --sampling meshlab; "worse" by the benchmark's
rule, bench/quality/families.py, read with a million samples near the line, and counted apart
where a designed feature lies within the ambiguous width). No threshold is chosen on it.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

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


def distance(tool, mesh, reference, samples=quality_run.DISTANCE_SAMPLES):
    p = subprocess.run([tool, mesh, reference, "--json", "--sampling", "meshlab", "--samples",
                        str(samples)], capture_output=True, text=True, check=True)
    d = json.loads(p.stdout)["symmetric"]
    return {"max": d["max_percent"], "rms": d["rms_percent"]}


def narrowest_designed(generator, name, mesh, spacing):
    """The narrowest designed feature of reference `name` (a bevel, fillet or face the part
    was designed with: bench/quality/designed.json, or the generator's own list for a
    generated shape), in `mesh`'s sample spacings; None when it has none or no spacing."""
    if not spacing:
        return None
    if name in quality_run.DESIGNED_SHAPES:
        with tempfile.TemporaryDirectory() as work:
            subprocess.run([generator, work, "--designed-faces", mesh, "--shapes", name],
                           check=True, stdout=subprocess.DEVNULL)
            stem = os.path.splitext(os.path.basename(mesh))[0]
            features = quality_run.read_designed_faces(os.path.join(work, stem + "_designed.txt"))
    else:
        features = quality_run.designed_features(name)
    return min(f["width"] for f in features) / spacing if features else None


class Table:
    """One sampler's rows (reference, half, max and RMS before -> after, worse), with the
    geometric means of the reduction factors per half and the worse count."""

    def __init__(self, title, args):
        self.title, self.args = title, args
        self.sharpener = os.path.join(args.build, "apps", "edge-sharpener")
        self.tool = os.path.join(args.build, "apps", "mesh-distance")
        self.generator = os.path.join(args.build, "test_meshes", "generate-test-meshes")
        self.rows, self.worse, self.worse_within, self.skipped = [], [], [], 0
        self.factors = {"tuning": [], "validation": []}

    def skip(self, name, half, why):
        self.rows.append(f"| {name} | {half} | {why} | | | |")
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
        """Sharpens `made` (into made__METHOD.ply) and adds its row. An output near the worse
        line is read again with a million samples a side, its input too, and judged on that
        reading (families.may_be_worse), as the benchmark judges the default's outputs."""
        sharpened = f"{os.path.splitext(made)[0]}__{self.args.method}.ply"
        run = subprocess.run([self.sharpener, made, sharpened, "--method", self.args.method,
                              "--json", *self.args.extra], capture_output=True, text=True)
        if run.returncode != 0:
            self.skip(name, half, f"refused: {run.stderr.strip()}")
            return
        spacing = json.loads(run.stdout).get("extended", {}).get("sample_spacing")
        before = distance(self.tool, made, reference)
        after = distance(self.tool, sharpened, reference)
        if families.may_be_worse(before, after):
            before = distance(self.tool, made, reference, quality_run.DENSE_SAMPLES)
            after = distance(self.tool, sharpened, reference, quality_run.DENSE_SAMPLES)
        narrowest = narrowest_designed(self.generator, name, made, spacing)
        bad = families.is_worse(before, after)
        if bad:
            within = narrowest is not None and narrowest <= families.AMBIGUOUS_SPACINGS
            (self.worse_within if within else self.worse).append(
                f"{name} {narrowest:.2g}" if within else name)
        if half in self.factors and name not in families.NO_SHARP_FEATURES:
            self.factors[half].append((before["max"] / after["max"], before["rms"] / after["rms"]))
        width = "" if narrowest is None else f"{narrowest:.2g}"
        self.rows.append(f"| {name} | {half} | {before['max']:.3g} -> {after['max']:.3g} | "
                         f"{before['rms']:.3g} -> {after['rms']:.3g} | {width} | "
                         f"{'**worse**' if bad else ''} |")

    def text(self):
        lines = [f"{self.title}; `--method {self.args.method}` {' '.join(self.args.extra)}", "",
                 "| reference | half | max (% diag) | RMS (% diag) | narrowest designed feature "
                 "(sample spacings) | |", "|---|---|---|---|---|---|", *self.rows, ""]
        for h, fs in self.factors.items():
            if fs:
                lines.append(f"{h}: geometric means max ×{families._gmean([f[0] for f in fs]):.2f}"
                             f" / RMS ×{families._gmean([f[1] for f in fs]):.2f} over {len(fs)}")
        measured = len(self.rows) - self.skipped
        amb = f"{families.AMBIGUOUS_SPACINGS:g}"
        lines.append(f"worse: {len(self.worse)} of {measured} with designed features all wider "
                     f"than {amb} sample spacings or none"
                     + (f" ({', '.join(self.worse)})" if self.worse else "")
                     + f"; {len(self.worse_within)} with one within {amb} spacings, where the "
                     "mesh alone cannot tell it from a sampled sharp edge"
                     + (f" ({', '.join(self.worse_within)} spacings)" if self.worse_within else "")
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
                "1%, read again with a million samples a side where the first reading lies "
                "near that line. A worse output is counted apart where the reference has a "
                f"designed feature within {families.AMBIGUOUS_SPACINGS:g} sample spacings (the "
                "ambiguous width: bench/quality/families.py, AMBIGUOUS_SPACINGS).\n\n" + body)


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
