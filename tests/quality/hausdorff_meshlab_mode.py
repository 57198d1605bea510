#!/usr/bin/env python3
"""mesh-distance in MeshLab's sampling mode against MeshLab's "Hausdorff Distance" filter.

Pairs: marching-cubes meshes of generated shapes (the project's MC at 1% and MeshLab's Uniform
Mesh Resampling at 1%) against their exact references. MeshLab runs the filter both ways
(A -> B and B -> A) with vertices, edges and faces sampled, SAMPLES of each; mesh-distance runs
with --sampling meshlab --samples SAMPLES. Asserted, per side and pair: max and RMS within 5%
(relative) of the filter's, the agreement issue 19 asks for. Both start their sampling
generator at the same state (mesh-distance's MeshLab mode defaults to the seed a fresh
meshlabserver's generator has, and the backward side continues the sequence as MeshLab's second
filter does), so they draw the same points: measured, the figures agree to the 4-6 digits
MeshLab prints (at most 0.04% apart). A larger difference means the sampling drifted from
MeshLab's.
"""
import os
import subprocess
import sys

SOURCE = os.environ["ES_SOURCE_DIR"]
BUILD = os.environ["ES_BUILD_DIR"]
WORK = os.environ["ES_WORK_DIR"]
sys.path.insert(0, os.path.join(SOURCE, "bench", "quality"))
import meshlab  # noqa: E402
import run  # noqa: E402

SAMPLES = 100000  # the benchmark's count (run.DISTANCE_SAMPLES)
TOLERANCE = 0.05
SHAPES = ("lblock_tilted", "cylinder_block", "pyramid")


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-30)


def meshlab_both_ways(server, a, b, diag, tag):
    """[(min, max, mean, RMS) of A -> B, of B -> A] from MeshLab's filter, or None."""
    filters = [meshlab.hausdorff(s, t, SAMPLES, 0.1 * diag, diag) for s, t in ((0, 1), (1, 0))]
    # A Hausdorff abort on one sample count is a known MeshLab bug: retry once with another.
    for attempt, n in enumerate((SAMPLES, SAMPLES + 1357)):
        text = meshlab.script(*filters).replace(f'value="{SAMPLES}"', f'value="{n}"')
        wd = os.path.join(WORK, f"{tag}-{attempt}")
        ok, _, why = server.run([a, b], None, text, wd, 300)
        if ok:
            rows = meshlab.Server.hausdorff_results(os.path.join(wd, "log.txt"))
            if len(rows) == 2:
                return rows
        print(f"  {tag}: MeshLab attempt {attempt + 1} failed: {why}")
    return None


def main():
    tools = run.Tools(BUILD)
    server = meshlab.Server(os.path.join(os.environ["ES_MESHLAB_PREFIX"], "bin", "meshlabserver"),
                            os.path.join(WORK, "home"))
    subprocess.run([tools.generator, WORK, "--cells", "0.01", "--shapes", ",".join(SHAPES)],
                   check=True, stdout=subprocess.DEVNULL)
    pairs = []
    for shape in SHAPES:
        ref = os.path.join(WORK, f"{shape}_reference.ply")
        pairs.append((f"{shape} (project MC 1%)", os.path.join(WORK, f"{shape}_mc1.ply"), ref))
    # One pair made by MeshLab's own marching cubes too.
    ref = os.path.join(WORK, "lblock_tilted_reference.ply")
    umr = os.path.join(WORK, "lblock_tilted_umr1.ply")
    diag = run.diagonal(tools, ref)
    ok, _, why = server.run([ref], umr, meshlab.script(meshlab.uniform_resampling(0.01 * diag, diag)),
                            os.path.join(WORK, "umr"), 300)
    if ok:
        pairs.append(("lblock_tilted (MeshLab UMR 1%)", umr, ref))
    else:
        print(f"  MeshLab's Uniform Mesh Resampling failed ({why}): that pair is left out")

    failures = []
    for label, a, b in pairs:
        ours, _, err = run.run_json([tools.distance, a, b, "--json", "--sampling", "meshlab",
                                     "--samples", str(SAMPLES)], 300)
        assert ours, err
        assert ours["sampling"] == "meshlab", ours.get("sampling")
        rows = meshlab_both_ways(server, a, b, ours["reference_diagonal"], label.split()[0])
        if rows is None:
            failures.append(f"{label}: MeshLab's Hausdorff Distance did not run")
            continue
        for side, ml in (("forward", rows[0]), ("backward", rows[1])):
            o = ours[side]
            for what, x, y in (("max", o["max"], ml[1]), ("RMS", o["rms"], ml[3])):
                r = rel(x, y)
                print(f"  {label:32s} {side:8s} {what:4s} mesh-distance {x:.6g}  MeshLab {y:.6g}  "
                      f"difference {100 * r:.2f}% (tolerance {100 * TOLERANCE:.0f}%)")
                if r > TOLERANCE:
                    failures.append(f"{label} {side} {what}: {x:.6g} vs MeshLab {y:.6g} "
                                    f"({100 * r:.2f}% > {100 * TOLERANCE:.0f}%)")
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures), file=sys.stderr)
        sys.exit(1)
    print("mesh-distance --sampling meshlab agrees with MeshLab's Hausdorff Distance")


if __name__ == "__main__":
    main()
