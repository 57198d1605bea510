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

import checks  # first: puts bench/quality on sys.path
import meshlab
import run

SAMPLES = 100000  # the benchmark's count (run.DISTANCE_SAMPLES)
TOLERANCE = 0.05
SHAPES = ("lblock_tilted", "cylinder_block", "pyramid")


def meshlab_both_ways(server, a, b, diag, tag):
    """[(min, max, mean, RMS) of A -> B, of B -> A] from MeshLab's filter, or None."""
    filters = [meshlab.hausdorff(s, t, SAMPLES, 0.1 * diag, diag) for s, t in ((0, 1), (1, 0))]
    return checks.hausdorff_both_ways(server, a, b, filters, SAMPLES, tag)


def main():
    tools, server, work = checks.meshlab_setup(SHAPES)
    pairs = []
    for shape in SHAPES:
        ref = os.path.join(work, f"{shape}_reference.ply")
        pairs.append((f"{shape} (project MC 1%)", os.path.join(work, f"{shape}_mc1.ply"), ref))
    # One pair made by MeshLab's own marching cubes too.
    ref = os.path.join(work, "lblock_tilted_reference.ply")
    umr = os.path.join(work, "lblock_tilted_umr1.ply")
    diag = run.diagonal(tools, ref)
    ok, _, why = server.run([ref], umr, meshlab.script(meshlab.uniform_resampling(0.01 * diag, diag)),
                            os.path.join(work, "umr"), 300)
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
                checks.agree(failures, label, side, what, x, y, TOLERANCE, widths=(32, 4))
    checks.finish(failures,
                  "mesh-distance --sampling meshlab agrees with MeshLab's Hausdorff Distance")


if __name__ == "__main__":
    main()
