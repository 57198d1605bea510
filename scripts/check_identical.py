#!/usr/bin/env python3
"""Checks that a refactoring left the outputs byte-identical.

Runs two builds of the edge-sharpener CLI (BEFORE and AFTER) on the same inputs with every
method and variant, and compares the output files byte for byte, and their JSON reports. Where they differ it
measures both outputs against each other with mesh-distance (max, in % of the diagonal), so a
rounding change can be told from a behaviour change.

  scripts/check_identical.py BEFORE_CLI AFTER_CLI [--inputs DIR_OR_FILE ...]
                             [--generated] [--distance MESH_DISTANCE] [--jobs N]
                             [--variants a,b] [--removed-fields PATH,...]
                             [--added-fields PATH,...]

--generated adds the project's exact shapes resampled by its own marching cubes at 2, 1 and
0.5% (generate-test-meshes from AFTER's build). Inputs the CLI refuses must be refused by
both builds. --removed-fields names the report fields (dotted paths: a key or a whole
object) that AFTER no longer writes: they are left out of the comparison, but BEFORE must
report them as zero or false on every run ("removed field not zero" otherwise).
--added-fields names the report fields (dotted paths: a key or a whole object) that AFTER
writes and BEFORE does not: AFTER's report is compared without them (a field BEFORE does
write still shows as a report difference). Exit status 0 when every output is identical
(or refused by both).
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import os
import subprocess
import sys
import tempfile

VARIANTS = {
    "paper": ["--method", "paper"],
    "paper-colorize": ["--method", "paper", "--colorize"],
    "paper-m1.5": ["--method", "paper", "--multiplier", "1.5"],
    "paper-m3": ["--method", "paper", "--multiplier", "3"],
    "extended": ["--method", "extended"],
    "extended-colorize": ["--method", "extended", "--colorize"],
    "extended-m1.5": ["--method", "extended", "--multiplier", "1.5"],
    "extended-m3": ["--method", "extended", "--multiplier", "3"],
    "extended-detect": ["--method", "extended", "--detect-only"],
    "auto": ["--method", "auto"],
    "auto-colorize": ["--method", "auto", "--colorize"],
    "auto-m1.5": ["--method", "auto", "--multiplier", "1.5"],
    "auto-m3": ["--method", "auto", "--multiplier", "3"],
}
MESH_SUFFIXES = (".ply", ".off", ".obj", ".stl")


def digest(path):
    with open(path, "rb") as f:
        return hashlib.md5(f.read()).hexdigest()


# Report fields that name the run rather than describe its result.
RUN_FIELDS = ("seconds", "input_file", "output_file", "options")


def run(cli, mesh, out, args):
    """The output's digest and the JSON report without the run's own fields."""
    p = subprocess.run([cli, mesh, out, "--json", *args], capture_output=True, text=True)
    if p.returncode != 0:
        return None, (p.stderr.strip().splitlines() or ["?"])[-1]
    report = json.loads(p.stdout)
    for key in RUN_FIELDS:
        report.pop(key, None)
    return (digest(out), report), ""


def is_zero(value):
    """Whether a report value (or every value of an object) is 0, 0.0 or false."""
    if isinstance(value, dict):
        return all(is_zero(v) for v in value.values())
    return value is None or value == 0


def pop_path(report, path):
    """Removes the dotted `path` from `report`; returns its value (None when absent)."""
    *parents, last = path.split(".")
    for key in parents:
        report = report.get(key)
        if not isinstance(report, dict):
            return None
    return report.pop(last, None)


def compare(job):
    before_cli, after_cli, mesh, variant, workdir, distance, removed, added = job
    # The path's digest too: inputs of the same name from different folders run side by side.
    stem = f"{hashlib.md5(mesh.encode()).hexdigest()[:8]}.{os.path.basename(mesh)}.{variant}"
    out_a = os.path.join(workdir, stem + ".before.ply")
    out_b = os.path.join(workdir, stem + ".after.ply")
    a, err_a = run(before_cli, mesh, out_a, VARIANTS[variant])
    b, err_b = run(after_cli, mesh, out_b, VARIANTS[variant])
    result = {"mesh": mesh, "variant": variant}
    not_zero = []
    if a is not None and b is not None:
        for path in removed:
            if not is_zero(pop_path(a[1], path)):
                not_zero.append(path)
            pop_path(b[1], path)
        for path in added:
            pop_path(b[1], path)
    if a is None or b is None:
        result["status"] = "refused by both" if a is None and b is None else "refused by one"
        result["detail"] = err_a or err_b
    elif not_zero:
        result["status"] = "removed field not zero"
        result["detail"] = ", ".join(not_zero)
    elif a == b:
        result["status"] = "identical"
    elif a[0] == b[0]:
        result["status"] = "report differs"
        result["detail"] = ", ".join(report_differences(a[1], b[1]))
    else:
        result["status"] = "different"
        if distance:
            p = subprocess.run([distance, out_b, out_a], capture_output=True, text=True)
            result["detail"] = p.stdout.strip().splitlines()[-1] if p.stdout else p.stderr
    for path in (out_a, out_b):
        if os.path.exists(path):
            os.remove(path)
    return result


def report_differences(a, b, prefix=""):
    """The dotted paths of the fields in which two reports differ."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = []
        for key in sorted(set(a) | set(b)):
            out += report_differences(a.get(key), b.get(key), f"{prefix}{key}.")
        return out
    return [] if a == b else [f"{prefix[:-1]}: {a} -> {b}"]


def collect_inputs(paths):
    meshes = []
    for p in paths:
        if os.path.isdir(p):
            meshes += sorted(q for q in glob.glob(os.path.join(p, "*"))
                             if q.lower().endswith(MESH_SUFFIXES))
        elif os.path.isfile(p):
            meshes.append(p)
        else:
            sys.exit(f"check_identical: no such input: {p}")
    return meshes


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before_cli")
    ap.add_argument("after_cli")
    ap.add_argument("--inputs", nargs="*", default=[])
    ap.add_argument("--generated", action="store_true")
    ap.add_argument("--distance", help="mesh-distance binary (to size differences)")
    ap.add_argument("--variants", default=",".join(VARIANTS))
    ap.add_argument("--removed-fields", default="",
                    help="comma-separated dotted report paths AFTER no longer writes")
    ap.add_argument("--added-fields", default="",
                    help="comma-separated dotted report paths only AFTER writes")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = ap.parse_args()

    with tempfile.TemporaryDirectory(prefix="check-identical-") as workdir:
        meshes = collect_inputs(args.inputs)
        if args.generated:
            generator = os.path.join(os.path.dirname(os.path.dirname(args.after_cli)),
                                     "test_meshes", "generate-test-meshes")
            gen_dir = os.path.join(workdir, "generated")
            subprocess.run([generator, gen_dir, "--cells", "0.02,0.01,0.005"], check=True,
                           capture_output=True)
            meshes += sorted(glob.glob(os.path.join(gen_dir, "*_mc*.ply")))
        variants = args.variants.split(",")
        removed = [p for p in args.removed_fields.split(",") if p]
        added = [p for p in args.added_fields.split(",") if p]
        jobs = [(args.before_cli, args.after_cli, m, v, workdir, args.distance, removed, added)
                for m in meshes for v in variants]
        counts = {}
        problems = []
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for r in pool.map(compare, jobs):
                counts[r["status"]] = counts.get(r["status"], 0) + 1
                if r["status"] in ("different", "report differs", "refused by one",
                                   "removed field not zero"):
                    problems.append(r)
                    print(f"{r['status']}: {r['mesh']} [{r['variant']}] {r.get('detail', '')}",
                          flush=True)
    summary = ", ".join(f"{n} {s}" for s, n in sorted(counts.items()))
    print(f"check_identical: {len(meshes)} inputs x {len(variants)} variants = {len(jobs)} runs: "
          f"{summary}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
