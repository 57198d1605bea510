#!/usr/bin/python3
"""A fifth held-out check of the default method: depth scans at settings the benchmark never
used. The benchmark's scans (bench/samplers/tsdf_scan.py: 26 depth views fused in Open3D's
TSDF) all have a voxel of 1% of the diagonal and images 256 pixels wide; the rules for rough
inputs (a scan left whole, its planar faces flattened) were chosen on its tuning half. Here the
same scanner makes each reference at a finer and a coarser voxel, 0.7% and 1.4% of the
diagonal, with images scaled to keep the pixels per voxel, depth noise of 0.1 voxel and another
noise seed, and at the benchmark's voxel with a noisier camera (0.5 voxel; the benchmark's
noisiest is 0.2). No threshold is chosen on it; it says whether those rules hold at other
scales and noise.

  /usr/bin/python3 bench/heldout/scan_settings.py [--build BUILD] [--shared DIR]
      [--method auto] [--out FILE.md] [-- extra CLI options]

References as in open3d_poisson.py. The scans are written to BUILD/heldout-scans and reused.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldout  # noqa: E402
import run as quality_run  # noqa: E402  (bench/quality, on the path heldout set)

NOISE_VOXELS = 0.1
NOISY_VOXELS = 0.5
SEED = 7
TIMEOUT = 600  # seconds per scan, the quality benchmark's default
SCANNER = [quality_run.SYSTEM_PYTHON,
           os.path.join(heldout.SOURCE, "bench", "samplers", "tsdf_scan.py")]


def setting(key, fraction, width, noise=NOISE_VOXELS, seed=SEED):
    """(key, voxel as a fraction of the diagonal, image width in pixels, depth noise in voxels,
    noise seed, title)."""
    return (key, fraction, width, noise, seed,
            f"tsdf_scan.py, 26 views, voxel {fraction * 100:g}% of the diagonal, images {width} "
            f"pixels wide, depth noise {noise} voxel, seed {seed}")


SAMPLERS = (setting("scan07", 0.007, 366), setting("scan14", 0.014, 183),
            setting("scan10n05", 0.01, 256, NOISY_VOXELS, 3))
MADE = f"""Each reference is scanned by the benchmark's own scanner, `bench/samplers/tsdf_scan.py`
(26 depth images rendered around the shape, Gaussian depth noise, fused by Open3D's
ScalableTSDFVolume, truncation 4 voxels, extracted by its marching cubes, the largest connected
component kept), at three settings the benchmark does not use: a voxel of 0.7% and of 1.4% of
the diagonal (the benchmark: 1%), images 366 and 183 pixels wide (the benchmark's 256 scaled
with the voxel), depth noise {NOISE_VOXELS} voxel, seed {SEED}; and the benchmark's voxel and
images with depth noise {NOISY_VOXELS} voxel, seed 3. A mesh the sharpener refuses (not a
closed manifold) is listed with its message. The geometric means leave out the references
without sharp features (sphere, rocker-arm); chamfer-cube is left out, as its reference is
another shape."""
NOTES = """What it found (diagnosed by hand):

- Written the day the rule "bulges beyond a convex edge or corner go behind its planes" was
  added (2026-11-28, docs/auto-method-decisions.md), to see whether it holds at other scales. The same scans
  sharpened by the build before that rule: at 0.7% tuning max x1.02 / RMS x1.12, validation
  x1.00 / x1.15, worse 1 of 20 (plate_holes); at 1.4% tuning x1.00 / x1.11, validation
  x1.00 / x1.12, none worse. With it, the tables above.
- cross_prism at 0.7% reads worse by its max (1.53% -> 1.57%, +2.6%) with 100,000 samples
  a side. With a million: input 1.565%, output 1.555% (the same before the rule): not worse.
  The max is its saddle corner, which the cameras do not see, as in the benchmark's scans; the
  100,000 samples miss that point in the input and hit it in the output, whose faces moved.
- plate_holes at 0.7% is worse by its RMS (0.179% -> 0.185%), the same before the rule. This
  scan is not left whole as a rough input: its noise, 0.017 sample spacings, is under the
  smooth bound (0.018), so the evidence guard judges it feature by feature (53% of the moves
  refused, under the 60% bound of a smooth part made of planes) and sharpens it. 325 vertices
  move away from the reference, the worst on the side walls at mid-height (x = -3.2, z = 7,
  1.4-1.8 units outwards), where the plate's bottom fillet (radius 6.35, 2.5 voxels) meets the
  wall. Not diagnosed further.
- Planes grown face by face (2026-11-28, the same day; chosen on the benchmark's tuning half):
  at 0.7% tuning x1.16 / x1.19 -> x1.20 / x1.18, validation x1.00 / x1.29 -> x1.16 / x1.43,
  worse 2 -> 1 of 20 (cross_prism's max now 1.53% -> 1.53%); at 1.4% tuning x1.07 / x1.21 ->
  x1.11 / x1.32, validation x1.08 / x1.38 -> x1.13 / x1.53, none worse. plate_holes at 0.7%
  is sharpened (not left whole), so they do not reach it.
- Grown planes fitted by least squares (2026-11-28, the same day; chosen on the benchmark's
  tuning half): at 0.7% tuning x1.20 / x1.18 -> x1.20 / x1.21, validation x1.16 / x1.43 ->
  x1.16 / x1.47; at 1.4% tuning x1.11 / x1.32 -> x1.11 / x1.35, validation x1.13 / x1.53 ->
  x1.13 / x1.55, none worse. cross_prism at 0.7% reads worse again by its 100,000-sample
  max (1.526% -> 1.572%); with a million samples (MeshLab's sampling) the input reads 1.565%
  and the output 1.555%, as the output before this change did (1.555%); with two million
  uniform samples 1.543% and 1.552% (before 1.561%): the saddle corner's spike, sampled, as
  above. So 2 of 20 at 0.7% read worse (plate_holes, as before, and this one; before: 1).
- The noisier camera (0.5 voxel at the benchmark's voxel) was added the same day, after the
  least-squares grown planes: none of 20 worse, tuning max x1.07 / RMS x1.14, validation
  x1.06 / x1.24; the build before that change (4c54571) read x1.06 / x1.13 and x1.06 / x1.20,
  none worse. Twelve of the 20 read exactly their input's figures (7_8ths_cube, abc6, block,
  cross_prism, cube, cylinder_block, fandisk, octa-flower17k, tube, twirl and the two without
  sharp features); cube, cylinder_block and abc6, checked vertex by vertex, come back as they
  went in (left whole, nothing flattened; noise 0.06-0.07 sample spacings).
- Since 2026-12-04 an output near the worse line is judged on a million samples a side (as
  the benchmark's): cross_prism at 0.7% is no longer counted; plate_holes at 0.7% stays worse
  (its fillet 2.5 voxels in radius: wider than the ambiguous width)."""


def scan(reference, out, fraction, width, noise, seed):
    """The scan of `reference` into `out`: "" or the scanner's message when it fails."""
    made, _, why = quality_run.run_json(
        [*SCANNER, reference, out, "--voxel-fraction", str(fraction), "--noise", str(noise),
         "--resolution", str(width), "--seed", str(seed)], TIMEOUT)
    return "" if made is not None else why


def table(sampler, refs, half, work, args):
    """One setting's table (heldout.Table)."""
    key, fraction, width, noise, seed, title = sampler
    table = heldout.Table(title, args)
    for name, ref in sorted(refs.items()):
        made = os.path.join(work, f"{name}__{key}.ply")
        table.make_and_measure(name, half.get(name, "?"), made, ref,
                               lambda: scan(ref, made, fraction, width, noise, seed))
    return table.text()


def main():
    args = heldout.parse_args(__doc__, "scan_settings.py")
    heldout.run_samplers(args, SAMPLERS, table, "heldout-scans",
                         "Held-out check: depth scans at other settings", 5, MADE, NOTES)


if __name__ == "__main__":
    main()
