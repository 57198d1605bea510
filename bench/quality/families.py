"""The generalization sections of docs/results.md (issue 19): every sampler family, the
validation half before the tuning half, every method and variant and the stock peer, with
worse counts by a stated rule and the list of worse cases.

Pure functions of the results JSON written by run.py; report.py places the returned
markdown at the top of docs/results.md.
"""
import math

# "Worse" (issue 19): the max error up by more than 2% or the RMS error up by more than 1%,
# relative to the input's. Errors are floored at FLOOR first (the measurement noise of float
# meshes), so an exact input that stays exact is not worse.
WORSE_MAX = 0.02
WORSE_RMS = 0.01
FLOOR = 1e-4  # % of the diagonal
# References without sharp features: they are in the worse counts (they must not be
# damaged) but not in the geometric means (there is nothing to reduce).
NO_SHARP_FEATURES = ("sphere", "rocker-arm")
COLUMNS = (("paper", "paper"), ("auto", "auto (default)"), ("extended", "extended"),
           ("unsharp-mask", "UnSharp Mask (MeshLab)"))
FAMILY_ORDER = ("umr", "mc", "vdb", "vdbproj", "ier", "csg", "poisson", "scan", "rimls", "asis")
FAMILY_TITLES = {
    "umr": "MeshLab Uniform Mesh Resampling (marching cubes)",
    "mc": "the project's marching cubes (exact SDF)",
    "vdb": "OpenVDB volumeToMesh (voxel remesher)",
    "vdbproj": "OpenVDB volumeToMesh as Blender's voxel remesh with Preserve Volume (vertices "
               "cast onto the input's surface)",
    "ier": "MeshLab Isotropic Explicit Remeshing, features off",
    "csg": "MeshLab CSG intersection (marching intersections)",
    "poisson": "MeshLab Screened Poisson (depth 7)",
    "scan": "depth-camera scan (26 views, TSDF, voxel 1%)",
    "rimls": "MeshLab Marching Cubes (RIMLS): a feature-preserving competitor",
    "asis": "the reference passed through as it is",
}


def _floored(x):
    return max(x, FLOOR)


def is_worse(before, after):
    return (_floored(after["max"]) > _floored(before["max"]) * (1 + WORSE_MAX) or
            _floored(after["rms"]) > _floored(before["rms"]) * (1 + WORSE_RMS))


def _gmean(values):
    values = [v for v in values if v > 0 and math.isfinite(v)]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def _run(case, method, mult):
    for r in case["runs"]:
        if r["method"] == method and abs(r["multiplier"] - mult) < 1e-9:
            return r
    return None


def _fx(x):
    return "–" if not math.isfinite(x) else f"×{x:.2f}"


def before_after(before, after, fmt=lambda x: f"{x:.3g}"):
    """The "max before -> after | RMS before -> after" cells of a worse-case row."""
    return (f"{fmt(before['max'])} -> {fmt(after['max'])} | "
            f"{fmt(before['rms'])} -> {fmt(after['rms'])}")


def _factors(case, run):
    """A run's max and RMS reduction factors (before/after, both floored)."""
    b, a = case["before"], run["after"]
    return _floored(b["max"]) / _floored(a["max"]), _floored(b["rms"]) / _floored(a["rms"])


def family_stats(cases, method, mult):
    """Geometric means of the max and RMS reduction factors (references with sharp features),
    worse count, outputs measured and runs that failed (refusals included)."""
    fmax, frms, worse, measured, failed = [], [], 0, 0, 0
    for c in cases:
        r = _run(c, method, mult)
        if r is None:
            continue
        if r["status"] != "ok":
            failed += 1
            continue
        measured += 1
        if is_worse(c["before"], r["after"]):
            worse += 1
        if c["model"] not in NO_SHARP_FEATURES and c["input"] != "asis":
            fm, fr = _factors(c, r)
            fmax.append(fm)
            frms.append(fr)
    return _gmean(fmax), _gmean(frms), worse, measured, failed


def _cell(stats):
    gmax, grms, worse, measured, failed = stats
    if measured == 0 and failed == 0:
        return "–"
    text = f"{_fx(gmax)} / {_fx(grms)}, {worse}/{measured} worse"
    if failed:
        text += f", {failed} failed"
    return text


def _families(cases):
    out = {}
    for c in cases:
        out.setdefault(c["input"], []).append(c)
    return [(k, out[k]) for k in FAMILY_ORDER if k in out] + \
           [(k, v) for k, v in out.items() if k not in FAMILY_ORDER]


def family_table(cases, mult, by_resolution=False):
    head = "| family | inputs | " + " | ".join(label for _, label in COLUMNS) + " |"
    rows = [head, "|---|---|" + "---|" * len(COLUMNS)]
    for kind, cs in _families(cases):
        groups = [(FAMILY_TITLES.get(kind, kind), cs)]
        if by_resolution:
            res = {}
            for c in cs:
                res.setdefault((c["order"], c["resolution"]), []).append(c)
            groups = [(f"{FAMILY_TITLES.get(kind, kind)}, {r}", v)
                      for (_, r), v in sorted(res.items())]
        for title, group in groups:
            cells = [_cell(family_stats(group, method, mult)) for method, _ in COLUMNS]
            rows.append(f"| {title} | {len(group)} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def worse_list(cases, mult, causes):
    rows = []
    for c in cases:
        for method, label in COLUMNS:
            r = _run(c, method, mult)
            if r is None or r["status"] != "ok" or not is_worse(c["before"], r["after"]):
                continue
            rows.append(f"| {c['half']} | {c['input']} {c['resolution']} | {c['model']} | {label} | "
                        f"{before_after(c['before'], r['after'])} | {_cause(c, method, causes)} |")
    if not rows:
        return "No output came out worse."
    return ("| half | input | model | method | max before -> after | RMS before -> after | "
            "cause |\n|---|---|---|---|---|---|---|\n" + "\n".join(rows))


def _cause(case, method, causes):
    if method == "unsharp-mask":
        return "unsharp masking displaces every vertex along its Laplacian, sharp or not"
    if case["input"] == "scan":
        return ("scan: the TSDF's marching cubes leave a bumpy surface (and the depth noise): "
                "planes fitted to it are off; not diagnosed case by case")
    if case["input"] == "asis":
        return "the reference itself sharpened; not diagnosed yet"
    if case["model"] in causes:
        return ("a cause found on this model for some of its inputs is under *Causes found* "
                "below (" + case["model"] + "); this case not checked against it")
    return "not diagnosed yet"


def failures_list(cases):
    rows = []
    for c in cases:
        for r in c["runs"]:
            if r["status"] != "ok":
                rows.append(f"- {c['half']}: {c['model']} {c['input']} {c['resolution']} "
                            f"{r['method']} m{r['multiplier']:g}: {r['status']}: "
                            f"{r.get('why', '')}")
    return "\n".join(rows) if rows else "None."


def sampler_table(results):
    """What the project's own samplers made: sizes and closed-manifold checks."""
    rows = ["| model | half | input | made? | faces | closed 2-manifold | components (kept the largest) |",
            "|---|---|---|---|---|---|---|"]
    for c in results["cases"]:
        if c["input"] not in ("vdb", "vdbproj", "scan"):
            continue
        mk = c["make"]
        s = mk.get("sampler", {})
        closed = s.get("closed_manifold")
        rows.append(f"| {c['model']} | {c.get('half')} | {c['input']} {c['resolution']} | "
                    f"{mk['status']}{': ' + mk['why'] if mk.get('why') else ''} | "
                    f"{s.get('faces', '–')} | "
                    f"{'–' if closed is None else ('yes' if closed else 'no')} | "
                    f"{s.get('components', '–')} |")
    return "\n".join(rows)


# Issue 20's targets for the default method: per family (and, for scans, per noise level)
# the geometric means of the max and RMS reduction factors it must reach. Every family, and
# the references passed through as they are, must have no worse output (no harm).
# Families absent from GAIN_TARGETS (csg, rimls, the reference as is, the middle scan noise,
# and vdbproj: OpenVDB as Blender's voxel remesh with Preserve Volume) have no gain target,
# only the no-harm rule.
DEFAULT_METHOD = "auto"
PEER_METHOD = "unsharp-mask"
GAIN_TARGETS = {("umr", None): (2.5, 6), ("mc", None): (2.5, 6), ("vdb", None): (2.5, 6),
                ("ier", None): (2.5, 8), ("poisson", None): (1.3, 1.6),
                ("scan", "noise 0"): (1.2, 1.3), ("scan", "noise 0.2 voxel"): (1.05, 1.1)}


def _mark(ok):
    return "met" if ok else "**missed**"


def _target_groups(cases):
    """The families as issue 20 sets their targets: one group each, scans one per noise."""
    groups = []
    for kind, cs in _families(cases):
        if kind == "scan":
            res = {}
            for c in cs:
                res.setdefault(c["resolution"], []).append(c)
            groups += [((kind, r), v) for r, v in sorted(res.items())]
        else:
            groups.append(((kind, None), cs))
    return groups


def targets_table(cases, mult):
    """The default method against issue 20's targets, one row per family (scans per noise)."""
    rows = ["| family | inputs | default (auto): max / RMS | gain target | worse (no harm: 0) "
            "| UnSharp Mask: max / RMS | ahead of UnSharp Mask |",
            "|---|---|---|---|---|---|---|"]
    for (kind, res), cs in _target_groups(cases):
        gmax, grms, worse, measured, failed = family_stats(cs, DEFAULT_METHOD, mult)
        pmax, prms, _, pmeasured, _ = family_stats(cs, PEER_METHOD, mult)
        target = GAIN_TARGETS.get((kind, res))
        if target is None:
            tcell = "–"
        else:
            tcell = (f"×{target[0]:g} / ×{target[1]:g}: "
                     + _mark(gmax >= target[0] and grms >= target[1]))
        if pmeasured and math.isfinite(gmax) and math.isfinite(pmax):
            ahead = _mark(gmax > pmax and grms > prms)
        else:
            ahead = "–"
        title = FAMILY_TITLES.get(kind, kind) + (f", {res}" if res else "")
        rows.append(f"| {title} | {len(cs)} | {_fx(gmax)} / {_fx(grms)} | {tcell} | "
                    f"{worse}/{measured} ({_mark(worse == 0)})"
                    + (f", {failed} refused" if failed else "") + f" | {_fx(pmax)} / {_fx(prms)} | "
                    f"{ahead} |")
    return "\n".join(rows)


def default_worse_list(cases, mult):
    """The default's worse outputs, each also as measured with run.DENSE_SAMPLES (run.py
    measures a worse output of the default again, with its input)."""
    rows = ["| half | family | model | resolution | max before -> after | RMS before -> after "
            "| with a million samples: max, RMS |", "|---|---|---|---|---|---|---|"]
    for c in cases:
        r = _run(c, DEFAULT_METHOD, mult)
        if r and r["status"] == "ok" and is_worse(c["before"], r["after"]):
            dense = r.get("dense")
            again = ("not measured" if not dense else
                     before_after(dense["before"], dense["after"]).replace(" | ", ", ")
                     + (": worse" if is_worse(dense["before"], dense["after"])
                        else ": not worse"))
            rows.append(f"| {c['half']} | {c['input']} | {c['model']} | {c['resolution']} | "
                        + before_after(c["before"], r["after"]) + f" | {again} |")
    return "\n".join(rows) if len(rows) > 2 else "None."


# An input whose max error is deeper than this many sample spacings has lost more than a
# chamfer (a thin part or a hole the sampler closed): sharpening cannot give it back. A chamfer
# two samples wide across a 30-degree edge lies 3.7 spacings below its tip.
LOST_PART_SPACINGS = 4.0


def _spacings(case, run):
    """The input's max error in its own sample spacings (the sharpener's median edge length),
    or None when the run did not report its spacing."""
    spacing = run.get("sample_spacing")
    diag = case["before"].get("diag")
    if not spacing or not diag:
        return None
    return case["before"]["max"] / (100.0 * spacing / diag)


def _max_unchanged(case, run):
    """Whether the run left the max error within the worse rule's 2% of the input's."""
    return _floored(run["after"]["max"]) * (1 + WORSE_MAX) >= _floored(case["before"]["max"])


def _what_default_did(case, run):
    """What the default method did to one input, from its report (run.py keeps the evidence)."""
    ev = run.get("evidence")
    if run.get("chamfer_edges", 0) == 0:
        return "found no chamfer"
    if ev and ev["whole_mesh_left"]:
        flat = ev.get("flattened_vertices", 0)
        flat = f"; {flat} vertices of its planar faces flattened" if flat else ""
        if ev["refused_fraction"] > ev["refused_bound"]:
            return (f"left whole: {ev['refused_fraction']:.0%} of its moves refused (bound "
                    f"{ev['refused_bound']:.0%}; noise {ev['noise_spacings']:.3f} spacings, "
                    f"{ev['planar_fraction']:.0%} of its area on planes){flat}")
        return (f"left whole: its moves slide along it (median lift "
                f"{ev['median_lift']:.2f}){flat}")
    text = "sharpened"
    if ev:
        text += f", {ev['weak_features']} of {ev['features']} features left as they were"
        if ev.get("already_sharp_features"):
            text += f" ({ev['already_sharp_features']} already sharp)"
    if _max_unchanged(case, run):
        text += "; max unchanged"
    return text


def _miss_kind(case, run):
    sp = _spacings(case, run)
    if sp is not None and sp > LOST_PART_SPACINGS:
        return "lost a part"
    if run.get("chamfer_edges", 0) == 0:
        return "no chamfer"
    ev = run.get("evidence")
    if ev and ev["whole_mesh_left"]:
        return "left whole"
    if _max_unchanged(case, run):
        return "max unchanged"
    return "short"


MISS_KINDS = (("lost a part", "a part lost by the sampler (max error deeper than "
                              f"{LOST_PART_SPACINGS:g} sample spacings)"),
              ("no chamfer", "no chamfer found"),
              ("left whole", "left whole (weak evidence over the whole mesh)"),
              ("max unchanged", "sharpened, max error unchanged"),
              ("short", "sharpened, by less than the target"))


def default_misses(cases, mult):
    """Issue 20's acceptance: per family whose gain target the default misses, the inputs below
    the target on max or RMS, what the default did to each (its report) and why the gain is
    short; then the family's gain without the inputs that lost a part."""
    L = []
    for (kind, res), cs in _target_groups(cases):
        target = GAIN_TARGETS.get((kind, res))
        if target is None:
            continue
        gmax, grms, _, _, _ = family_stats(cs, DEFAULT_METHOD, mult)
        if gmax >= target[0] and grms >= target[1]:
            continue
        rows, kinds, kept, lost = [], {}, [], 0
        for c in sorted(cs, key=lambda c: (c["model"], c["order"])):
            r = _run(c, DEFAULT_METHOD, mult)
            if (r is None or r["status"] != "ok" or c["model"] in NO_SHARP_FEATURES
                    or c["input"] == "asis"):
                continue
            fmax, frms = _factors(c, r)
            k = _miss_kind(c, r)
            if k == "lost a part":
                lost += 1
            else:
                kept.append(c)
            if fmax >= target[0] and frms >= target[1]:
                continue
            kinds[k] = kinds.get(k, 0) + 1
            sp = _spacings(c, r)
            rows.append(f"| {c['model']} | {c['resolution']} | {c['before']['max']:.3g} -> "
                        f"{r['after']['max']:.3g} ({_fx(fmax)}) | {_fx(frms)} | "
                        + ("–" if sp is None else f"{sp:.1f}") + f" | {_what_default_did(c, r)} |")
        title = FAMILY_TITLES.get(kind, kind) + (f", {res}" if res else "")
        kmax, krms, _, _, _ = family_stats(kept, DEFAULT_METHOD, mult)
        without = (f"; without the {lost} that lost a part {_fx(kmax)} / {_fx(krms)}"
                   if lost else "")
        L += [f"**{title}** (target ×{target[0]:g} / ×{target[1]:g}; all inputs {_fx(gmax)} / "
              f"{_fx(grms)}{without}). Below the target: "
              + "; ".join(f"{text}: {kinds[k]}" for k, text in MISS_KINDS if k in kinds) + ".", "",
              "| model | resolution | max before -> after | RMS | input's max error, spacings "
              "| what the default did |", "|---|---|---|---|---|---|", *rows, ""]
    return L


def default_section(results):
    """Issue 20: the default method against its targets, per half (a list of lines)."""
    mult = results["default_multiplier"]
    cases = [c for c in results["cases"] if "before" in c]
    L = ["## The default method (auto) against its targets (issue 20)", "",
         "Decided on the tuning half (`bench/study/`: per-feature evidence and harm of the "
         "extended method's moves, then each rule and threshold compared on the tuning half's "
         "benchmark); each rule's validation figures were measured only after it was fixed. "
         "One rule was dropped after its validation run (a per-feature lift test, which cost "
         "gains on the validation half's marching cubes) and replaced by a mesh-wide one chosen "
         "on the tuning half: that choice saw the validation half once. Two later rules came from "
         "the cause of the validation half's worst cases (the tube's wall, under two cells "
         "thick): a new vertex whose target lies nearer the other side of a wall than its own "
         "counts as refused (the medial axis: no threshold fitted), and the 20-degree bound on "
         "the angle at which an edge's flank planes meet, chosen on the tuning half for shallow "
         "creases, also applies to knife edges. Both left the tuning half's figures as they were "
         "(one RMS moved by 0.3%), except for the case the 20-degree bound was chosen for. "
         "Then, on the tuning half: a feature is held to the whole mesh's bound, 40% of its new "
         "vertices refused (the study showed the features refused at 20-50% lowered the error "
         "on the whole; the bound was 20%), and a split face at rest gets its input face back "
         "even beside a moved one. Raising the whole mesh's bound to 50% gained on the tuning "
         "half but sharpened a smooth model (rocker-arm) made by a tool outside the benchmark "
         "(`bench/heldout/open3d_poisson.py`, `docs/heldout.md`), which it made worse: the bound "
         "stayed at 40%. Two later rules again came from the tube (validation half), each "
         "with a bound the tuning half could not fix: where opening the contacts of two "
         "regions would leave a region without an interior vertex, a region at least 10 sample "
         "spacings long keeps its faces (a coarse cylinder's facet two cells wide: opened, the "
         "planes on either side met inside the wall; on the tuning half 5 spacings made mixed "
         "changes, 10 and 20 the same single change, 40 none), and an edge whose flanks' "
         "planes meet on a line turned more than 45 degrees out of its chamfer stays as it was "
         "(the two walls beside a thin wall's cap; on the tuning half 30 to 75 degrees change "
         "nothing; 45: as much across as along). "
         "Last, on the tuning half: a smooth part made of planes may have up to 60% of its "
         "moves refused before it is left whole (`guards/surface_measures.h`). Smooth: its "
         "noise, the median change of a vertex's umbrella curvature from its neighbours', is "
         "at most 0.018 sample spacings (the tuning half's Screened Poisson meshes measure up "
         "to 0.016, its scans from 0.020). Made of planes: at least 30% of its area lies within "
         "3 degrees of its region's mean normal. Its refusals come from its shape (the rounded "
         "blend Poisson leaves at every edge), which the per-feature rules judge feature by "
         "feature. A first version without the planar condition sharpened rocker-arm, a "
         "freeform part with 1% of its area on planes, at VDB 1% (validation half: max up 3%) "
         "and from Open3D's Poisson (held out: RMS up 35%): the planar condition came from "
         "that, so this rule saw the validation half once. The tuning half does not place the "
         "planar bound (among the smooth meshes it reaches, the freeform ones have at most 22% "
         "of their area on planes, the others at least 49%; 20%, 30% and 40% change the same "
         "cases), nor 60% against 70% (the same cases; 60% is the more cautious). "
         "Tried and dropped in the same session: letting a feature keep one sample off its "
         "plane (up to 0.7 sample spacings; the tuning half's OpenVDB meshes gained, at "
         "7_8ths_cube's concave corner) made abc6 at VDB 0.5% worse on the validation half "
         "(max 0.395% -> 0.476%: its designed bevels), and beyond 0.7 spacings a notch's edge "
         "on the tuning half (plate_holes IER 1%). "
         "Later, on the tuning half: the auto method no longer applies the paper's convexity "
         "check (section 3). At a saddle corner, where a concave edge meets convex ones "
         "(cross_prism, 7_8ths_cube), the chamfer edges and corners near the corner lie between "
         "a concave and a convex side; the check kept them at rest, as it must in the paper, "
         "which cannot tell them from a step. The auto method judges them by its own tests (a "
         "step's planes meet far away, on the wrong side: still at rest). Tuning half: UMR "
         "×1.28 / ×3.14 -> ×1.29 / ×3.20, own MC ×2.26 / ×10.44 -> ×2.37 / ×11.18, IER "
         "×1.34 / ×2.40 -> ×1.39 / ×2.65, CSG ×1.56 / ×2.62 -> ×1.64 / ×2.95, none worse; the "
         "validation half as before (one RMS mean ×7.40 -> ×7.41); held out, ADIS16480's max "
         "0.371% -> 0.282%. "
         "Two robustness fixes followed, with no threshold: the intersection guard took two "
         "faces meeting at one point through distinct vertices (marching cubes leave them "
         "where the surface passes through a grid node) for crossing faces once sharpening "
         "made them coplanar, and the cleanup sent back a corner whose needle is the input's "
         "own short edge (two input vertices 0.0007 units apart beside 7_8ths_cube's corner at "
         "UMR 2%), which no revert cures. Tuning half: UMR ×1.29 / ×3.20 -> ×1.37 / ×3.60, own "
         "MC ×2.37 / ×11.18 -> ×2.67 / ×11.58, CSG ×1.64 / ×2.95 -> ×1.65 / ×3.02; validation "
         "half, measured once after: UMR ×3.94 / ×7.41 -> ×4.10 / ×8.08, own MC RMS ×20.14 -> "
         "×20.53, CSG ×2.67 / ×4.14 -> ×2.92 / ×4.38; none worse in either half. Both fixes "
         "are in stages every method shares: on the validation half the paper's method went "
         "from ×3.06 / ×3.21 to ×3.06 / ×3.23 on UMR and from ×2.35 / ×3.61 to ×2.50 / ×3.74 on "
         "CSG (fandisk at UMR 1% as before). "
         "Two more cleanup fixes followed, again without a threshold, decided on the tuning "
         "half: a needle's collapse was refused when a face beside it already had two corners "
         "at one point (two new vertices and an input vertex moved onto one target: "
         "7_8ths_cube's saddle corner at UMR 1%, where a marching-cubes vertex sits on a grid "
         "node), and the moves went back; such a face has no orientation to lose and no "
         "longer counts as a fold. And a cap between two new vertices placed side by side on "
         "one line, which no flip cured, sent both back; its shortest edge is now collapsed "
         "(a corner's vertex stays). Tuning half: UMR ×1.37 / ×3.60 -> ×1.53 / ×3.92 "
         "(7_8ths_cube at UMR 1%: max ×1.74 -> ×9.08), own MC RMS ×11.58 -> ×11.97; "
         "validation half, measured once after: UMR ×4.10 / ×8.08 -> ×4.63 / ×8.28, OpenVDB "
         "RMS ×3.69 -> ×3.83, CSG max ×2.92 -> ×2.94, own MC RMS ×20.53 -> ×20.55; none worse "
         "in either half, the paper's method unchanged. "
         "Then two generated shapes with designed bevels and fillets beside sharp edges joined "
         "the benchmark, one per half (bevelled_block, tuning: bevels 0.03 and 0.07 wide, "
         "fillets of radii 0.03 and 0.07; finished_hexprism, validation: other sizes and "
         "angles): a designed bevel or fillet is what a sharpener must keep. The default "
         "method made none of their 32 inputs worse before any change (the extended method "
         "16, the paper's 8); they lower the families' means, since their designed features stay "
         "as they are. A study of every feature of the tuning half (`evidence-study`: the "
         "quantiles of its samples' distances from their planes, and those distances over "
         "their reach to the new vertex) found no measure that tells a bevel 1.5 cells wide "
         "from a grid-aligned marching-cubes edge (both sit 0.1-0.2 spacings off their "
         "planes along their length); a bevel that narrow is cut back by 0.35 of its width, "
         "less than the sampler's own error at the corners beside it. It did find edges left "
         "chamfered whole for one far sample: on a remesher that reprojects onto the surface "
         "(IER), nine in ten of an edge's samples lie on their planes and one, where the edge "
         "meets another part, lies 1-5 spacings off. Such a feature is now sharpened, and "
         "the new vertices its far samples source stay at rest (sharpened whole, a notch's "
         "edge of plate_holes at IER 1% rose from 0.625% to 0.985% of the diagonal at those "
         "vertices). On the tuning half the bound was 0.1 spacings first, which made "
         "bevelled_block at UMR 0.5% worse (max +2.0%, two of its bevels' edges), and is "
         "0.05: tuning half IER RMS ×2.38 -> ×2.47 over the 27 inputs measured before "
         "(lblock_tilted at IER 2% ×1.55, plate_holes at IER 1% ×1.30, twirl at IER 0.5% "
         "×1.10), nothing else changed, none worse; validation half, measured once after: "
         "IER RMS ×4.87 -> ×4.99, UMR RMS ×8.28 -> ×8.42 (tube at UMR 0.5%), OpenVDB tube 0.5% "
         "max ×1.10, none worse. "
         "A per-vertex study of the tuning half (`evidence-study --vertices`: each kept "
         "feature's moved vertices, their move, their farthest sample's distance from its "
         "plane and their own change of distance to the reference) located the last worse "
         "input of the tuning half, octa-flower17k by Screened Poisson: edge vertices at a "
         "petal's rounded tip moved 2.1-2.4 spacings (their feature's median: 0.95) from "
         "samples 0.4-0.56 spacings off their planes (under the feature's bound, 0.6), and "
         "landed up to 1.56 spacings from the reference. A long extrapolation magnifies a "
         "curved flank's misfit: an edge vertex moved more than 2 spacings now stays at rest "
         "when one of its samples lies more than 0.3 spacings off its plane. Over the tuning "
         "half's 116,000 kept moves this catches 20 (octa-flower17k and twirl at Screened "
         "Poisson, 7_8ths_cube at IER 0.5%, bevelled_block at IER 1%); octa-flower17k's max "
         "0.870% -> 0.847% (the input's), nothing else changed by more than 2%. Measured once "
         "on the validation half, it first also caught the wedge's two acute corners at VDB 1% "
         "(moves of 2.1-2.2 spacings that landed on the reference's corners; left at rest among "
         "sharpened edges they made notches: max ×4.11 / RMS ×24.4 fell to ×2.60 / ×8.73, still "
         "better than the input); a corner's point is pinned by three planes and an acute corner's move is "
         "long by its shape, so the rule holds for edge vertices only. That narrowing was "
         "decided after seeing the validation half, which is therefore not blind to it; it "
         "changes nothing in the tuning half and leaves the validation half as it was before "
         "the rule. On Open3D's Poisson (`docs/heldout.md`, same inputs) octa-flower17k 0.461% "
         "-> 0.448% and wedge 0.547% -> 0.540%, both still worse. "
         "See `docs/heldout.md` for a tool outside the benchmark. "
         "Targets: no "
         "output worse in any family (max up > 2% or RMS up > 1%), gains as listed, ahead of "
         "MeshLab's UnSharp Mask on both max and RMS. Where the targets and no harm conflict, "
         "no harm wins: a feature the evidence does not support stays chamfered.", ""]
    for half in ("validation", "tuning"):
        hc = [c for c in cases if c.get("half") == half]
        L += [f"### {half.capitalize()} half", "", targets_table(hc, mult), "",
              f"Outputs of the default method that came out worse ({half} half):", "",
              default_worse_list(sorted(hc, key=lambda c: (c["input"], c["order"], c["model"])),
                                 mult), "",
              f"Where the default misses a gain target ({half} half), input by input: what the "
              "default did (its report) and the input's max error in its own sample spacings "
              "(the sharpener's median edge length). Deeper than "
              f"{LOST_PART_SPACINGS:g} spacings, that error is not a chamfer but a part the "
              "sampler lost (a wall IER collapsed, a thin part the voxels dropped), which no "
              "sharpener gives back; each family's gain is also given without those inputs.",
              "",
              *default_misses(hc, mult)]
    L += ["**A rough input's planar faces are flattened** (2026-11-27, chosen on the tuning "
          "half). Where the scans' error lies (`bench/study/scan_error_bands.py`, the tuning "
          "half's generated shapes at noise 0): 69-78% of the squared error lies 1-4 voxels "
          "from the sharp edges, where the fusion bulges each planar face outwards, and the "
          "max at concave corners the cameras do not see "
          "(cross_prism's saddle corners, 2.09% of the diagonal), which is no chamfer. "
          "Sharpening does not help there: with the whole-mesh bound, the bend and the spread "
          "tests all off, every tuning scan's RMS rose (by 2-11%). So on a rough input (noise "
          "above the smooth bound, 0.018 spacings) that the evidence guard leaves whole, the "
          "vertices of every region that is a plane in its core (the planar regions of "
          "`planarRegionPlanes`) and lie outside that plane by at most one sample spacing move "
          "onto it (`flattenPlanarRegions`; `--keep-rough-planes` turns it off). Only outside: "
          "moving the vertices inside their plane too flattened plate_holes' bottom fillet "
          "(radius 1.7 voxels, absorbed by the walls' regions) and made its scan at noise 0.2 "
          "worse (RMS +2.7%); a convex blend or bevel lies inside the planes it joins, the "
          "fusion's bulge outside. Tuning half, no input worse, every other output identical: "
          "scans RMS ×1.00 -> ×1.11 (noise 0), ×1.13 (0.1 voxel), ×1.10 (0.2 voxel), max "
          "unchanged (lblock_tilted at 0.2 voxel 0.174% -> 0.131%, bevelled_block at noise 0 "
          "0.164% -> 0.118%; the freeform octa-flower17k and twirl have no planar region). Half "
          "a spacing gained less (×1.08 at noise 0), two spacings the same; at both, "
          "cross_prism's sampled max at noise 0.1 read 2.09% against 2.04% (the same point, "
          "the saddle corner, at 2.090% when sampled densely: the Montecarlo samples move with "
          "the faces' areas). The first version flattened every rough input before its "
          "detection; measured once on the validation half, the flattened planes let the guard "
          "sharpen lblock's scans, worse at noise 0 (max 1.519% -> 1.588%) and 0.2 voxel "
          "(+2.1%). Flattening only a mesh the guard leaves whole (decided after that "
          "validation run, which is therefore not blind to it) keeps every verdict as it was. "
          "Validation half: scans RMS ×1.00 -> ×1.11, ×1.11, ×1.10, max unchanged, none worse "
          "(pyramid at noise 0 0.259% -> 0.200%, cube 0.211% -> 0.179%), every other output "
          "identical. `ctest -R rough_planes`.", ""]
    L += ["**The zones beside a rough input's planar faces flattened too** (2026-11-27, later "
          "the same day, chosen on the tuning half). The first rule left the feature zones' "
          "vertices as they were, and with them much of the fusion's bulge beside each edge. "
          "Now every vertex labelled with a planar region, the region's own or its zone's, "
          "that lies outside the region's plane by at most two sample spacings moves onto it "
          "where that place is on the region's face: on the side of every other planar "
          "region's plane within three rings where the region's own vertices within those "
          "rings lie (`onSideOf`; a zone vertex with none of them stays). At a convex edge a "
          "point outside a face's plane is outside the solid, and moving it onto that plane "
          "brings it nearer every point of the solid; at a concave edge the side test keeps it "
          "from landing past the other face. Tuning half, every output but the scans' "
          "identical: scans RMS ×1.11 -> ×1.18 (noise 0), ×1.13 -> ×1.21 (0.1 voxel), ×1.10 -> "
          "×1.16 (0.2 voxel), max ×1.00 -> ×1.01 (7_8ths_cube at 0.2 voxel 1.917% -> 1.836%, "
          "bevelled_block at noise 0 1.652% -> 1.571%). One spacing gained less (×1.16, ×1.19, "
          "×1.14); three and five spacings the same as two. One scan reads worse: cross_prism "
          "at noise 0.1, max 2.035% -> 2.090% (+2.7%), RMS 0.268% -> 0.176%. Its max is the "
          "same point in the input and the output, the saddle corner the cameras miss, at "
          "2.090% in both when every face is sampled on a grid; with a million samples the "
          "input reads 2.078%, the output 2.090% (+0.6%, not worse). The 100,000 samples "
          "missed that point in the input and hit it in the output, whose faces moved (the "
          "next paragraph). Validation half, measured once after: scans RMS ×1.11 -> ×1.19 at "
          "each noise level, max ×1.00, ×1.00, ×1.01 (cube at 0.2 voxel 1.917% -> 1.837%, "
          "wedge at 0.2 voxel RMS 0.302% -> 0.208%), none worse with 100,000 samples or a "
          "million, every other output identical. `ctest -R rough_planes`. Bosses and ribs 1-3 "
          "scan voxels high on a scanned slab, authored by `ctest -R raised_features` (not in "
          "the benchmark), are kept: the reference's samples on them lie as near the output "
          "as the input, the whole slab's RMS ×1.14-×1.25.", ""]
    L += ["**Bulges beyond a convex edge or corner go behind its planes** (2026-11-28). "
          "After the two rules above, the cube's scan at noise 0 (validation half) still "
          "read 1.81% of the diagonal, the input's max: vertices 1.8 voxels outside a face "
          "beside its corners. The fusion bulges there beyond two or three faces' planes at "
          "once, and the bulge's vertices take the labels of small regions that are no plane "
          "(1,419 of the 3,472 vertices more than 0.6 voxel outside the cube), of none (114), "
          "or of a face whose plane they leave off the face (18), so the rule above left "
          "them. Such a vertex now goes to the nearest point behind the planes of the planar "
          "regions around it (`nearestPointBehindPlanes`: the faces, edges and corners of up "
          "to three planes), when at least two planes are there (one plane alone does not "
          "show that the solid lies behind it: a boss standing on a face), no two of them "
          "meet concave (one's own vertices outside the other's plane), it lies at most two "
          "spacings outside each, and no own vertex of its region nearby lies farther (the "
          "region's own shape rising there). That point lies nearer every point of the solid "
          "behind the planes than the vertex did. The planes are read within six rings "
          "(`kFlattenCornerRings`): the rule came from the cube's scan, where six rings "
          "first reach two faces' own vertices past a corner's zone, so the ring count was "
          "chosen on the tuning half alone: 4, 5, 6, 7 and 8 rings gave scans max ×1.010, "
          "×1.030, ×1.046, ×1.049 and ×1.058 (RMS ×1.206 to ×1.245), and 7 and 8 left "
          "cross_prism's scan at noise 0.1 worse as before (2.090% against 2.035%), 6 not. "
          "One plane instead of two gained a little more on the tuning half (max ×1.053, "
          "RMS ×1.250) and was not kept, for the boss; checking every vertex nearby instead "
          "of the region's own lost cylinder_block's scan at 0.1 voxel RMS +6%. Tuning half, "
          "every output but the scans' identical: scans ×1.01 / ×1.18 -> ×1.06 / ×1.28 "
          "(noise 0), ×1.00 / ×1.21 -> ×1.09 / ×1.32 (0.1 voxel; cross_prism no longer "
          "worse), ×1.01 / ×1.16 -> ×1.01 / ×1.21 (0.2 voxel); 7_8ths_cube at noise 0 "
          "1.813% -> 1.380%, bevelled_block 1.652% -> 1.286%. Validation half, measured once "
          "after: scans ×1.00 / ×1.19 -> ×1.21 / ×1.38 (noise 0, now meeting its target), "
          "×1.00 / ×1.19 -> ×1.20 / ×1.34 (0.1 voxel), ×1.01 / ×1.19 -> ×1.07 / ×1.33 "
          "(0.2 voxel, meeting its target); cube at noise 0 1.813% -> 0.392% (a box's bulge "
          "clamped onto the box reads 0.392% too), lblock at 0.1 voxel 1.529% -> 0.833%; none "
          "worse, every other output identical. A finer scan outside the benchmark "
          "(7_8ths_cube, voxel 0.25%, noise 0.3 voxel, 1.09 M faces; input 0.368% / 0.0322%): "
          "0.368% / 0.0294% -> 0.309% / 0.0286%, in 1.5 s -> 1.6-1.7 s. The "
          "scanned slab's bosses and ribs (`ctest -R raised_features`) are kept as before, "
          "the whole slab's RMS ×1.38-×1.61. `ctest -R \"rough_planes|raised_features|"
          "PlanarRegions.Flattening|NearestPointBehindPlanes\"`.", ""]
    L += ["**Planes grown face by face on a scan** (2026-11-28). The two rules above read "
          "the planes of the segmentation's regions, and a scan rounds some edges so smoothly "
          "that the segmentation merges two faces of the solid across them into one region, "
          "which is then no plane: lblock_tilted's scans kept their max at every noise level "
          "(4 of its 63 regions planes), and at 0.2 voxel the side faces of cylinder_block, "
          "bevelled_block and 7_8ths_cube failed the bend test. Where the first flattening "
          "moved at least 1% of the vertices (the planes bulge as a fused scan's do; an exact "
          "CAD mesh's move none, and a scan without planes none), the same flattening now runs "
          "again on planes grown face by face (`extended/plane_patches.h`): from the flattest "
          "face left, a patch takes the neighbours whose normals turn from its plane by less "
          "than a feature's angle (20 degrees) and whose vertices lie within half a spacing of "
          "it, refitted as it grows; it is kept when it covers 60 square spacings and passes "
          "the regions' planarity tests, and only when another kept patch within six rings "
          "meets it at 20 degrees or more (the faces of a solid meet at edges, pieces of a "
          "curved surface bend gently into each other). Chosen on the tuning half: the turn "
          "at 10, 15, 20 and 30 degrees gave scans ×1.08 / ×1.24 (cross_prism at 0.1 voxel "
          "worse), ×1.11 / ×1.28, ×1.15 / ×1.29 and ×1.13 / ×1.28, so the feature angle was "
          "kept; at 15 degrees the area (20, 60, 100 square spacings) and the distance (0.3, "
          "0.5, 1 spacing) moved the means by less than 0.01. Without the partner rule "
          "octa-flower17k passed as it is (a CAD mesh counted rough, left whole) was changed "
          "by 0.415% of its diagonal: a patch of a gently curved petal; without the 1% gate "
          "and with a 10-degree turn it was changed again, so both stay. Tuning half, every "
          "output but the scans' identical: scans ×1.06 / ×1.28 -> ×1.21 / ×1.34 (noise 0, "
          "now meeting its target), ×1.09 / ×1.32 -> ×1.13 / ×1.33 (0.1 voxel), ×1.01 / ×1.21 "
          "-> ×1.15 / ×1.33 (0.2 voxel, meeting its target); lblock_tilted at noise 0 1.579% "
          "-> 1.046%, cylinder_block at noise 0 1.654% -> 1.111%, bevelled_block at 0.2 voxel "
          "1.676% -> 0.961%; a few RMS figures rose against the rules above (cylinder_block "
          "at 0.1 voxel 0.129% -> 0.142%, bevelled_block 0.0955% -> 0.0997%), each far under "
          "its input's. Validation half, measured once after: scans ×1.21 / ×1.38 -> ×1.38 / "
          "×1.50 (noise 0), ×1.20 / ×1.34 -> ×1.33 / ×1.44 (0.1 voxel), ×1.07 / ×1.33 -> "
          "×1.34 / ×1.41 (0.2 voxel); finished_hexprism at noise 0 1.489% -> 0.785%, cube at "
          "0.2 voxel 1.823% -> 0.430%; lblock at 0.1 voxel RMS 0.108% -> 0.115% (its input "
          "0.228%); none worse, every other output identical. The finer scan above (1.09 M "
          "faces, outside the benchmark): max 0.309% -> 0.282%, but RMS 0.0286% -> 0.0315% "
          "(its input's 0.0322%): at that noise (0.3 voxel) the second pass moves vertices "
          "that lay on the faces by up to a quarter spacing, likely because the grown planes "
          "are fitted after the first pass moved only the vertices outside its planes (not "
          "diagnosed further). Three ways round it were measured, after the "
          "validation run above: planes grown on the input's positions and fitted on their "
          "cores (three rings in, as a region's) read that scan 0.303% / 0.0285% and the "
          "tuning half ×1.14 / ×1.28, none worse, but made two validation scans worse (abc6 "
          "at noise 0 max 1.015% -> 1.481%, lblock at 0.2 voxel 1.557% -> 1.782%); the grown "
          "planes moving only the vertices the first pass left read 0.282% / 0.0290% and "
          "×1.14 / ×1.31, but cross_prism at 0.1 voxel worse by the 100,000-sample max "
          "(2.090%, its unseen saddle corner); on the input's positions without cores, "
          "0.0306%. So the rule stays as described, chosen after seeing the validation half "
          "twice. The same kind of scan made by a command anyone can rerun "
          "(`bench/samplers/tsdf_scan.py 7_8ths_cube.stl OUT --voxel-fraction 0.0025 "
          "--noise 0.3 --resolution 1024`, seed 1, 1.11 M faces) reads 0.368% / 0.0325% as "
          "input, 0.335% / 0.0304% before this rule and 0.258% / 0.0327% with it: RMS +0.6% "
          "over its input's, under the benchmark's 1% but no gain. Time on that scan 1.7 s -> 2.8 s (the flattening now decides on every "
          "core; 3.5 s on one), peak memory 292 MB -> 346 MB. `ctest -R \"PlanePatches|"
          "rough_planes|raised_features\"`.", ""]
    L += ["**Grown planes fitted by least squares** (2026-11-28, chosen on the tuning half). "
          "A grown patch's plane was the area-weighted sum of its faces' normals through "
          "their centroid. On a scan a face's normal tilts with the noise, and that sum "
          "tilted the plane of a large face: on the finer scan above the second pass moved "
          "vertices that lay on the faces. The plane is now fitted by least squares to the "
          "faces' centroids (area-weighted; `fitPlaneLeastSquares`), then once more without "
          "the faces farther from it than 1.5 times their RMS distance, the bulge along a "
          "face's rim (`fitPlaneTrimmed`, `PlanePatchSettings::trimRmsFactor`). Tuning half, "
          "run by run: no trim, 1, 1.5 and 2 times the RMS gave scans ×1.150 / ×1.306, "
          "×1.151 / ×1.318, ×1.154 / ×1.316 and ×1.153 / ×1.314 (×1.147 / ×1.295 before); "
          "no trim, 1 and 2 read cross_prism at 0.1 voxel worse by the 100,000-sample max "
          "(2.088% against 2.035%; at a million samples the input and the output both read "
          "2.078%, and 2 million uniform samples read 2.070% for the input and the output "
          "alike: the unseen saddle corner's spike, sampled), 1.5 not. The means do not "
          "separate the trims; 1.5 was kept for its max. Tuning half, every output but the "
          "scans' identical, none worse: scans ×1.21 / ×1.34 -> ×1.24 / ×1.36 (noise 0), "
          "×1.13 / ×1.33 -> ×1.13 / ×1.36 (0.1 voxel), ×1.15 / ×1.33 -> ×1.15 / ×1.36 (0.2 "
          "voxel); cylinder_block at noise 0 1.111% -> 0.856%, its RMS at 0.2 voxel -13%; "
          "lblock_tilted at 0.1 voxel max 0.872% -> 0.918% (RMS -3%); seven scans' RMS rose, "
          "by at most 0.35% (plate_holes, ADIS16480, cross_prism at 0.2 voxel). Validation half, "
          "measured once after: scans ×1.38 / ×1.50 -> ×1.37 / ×1.56 (noise 0), ×1.33 / "
          "×1.44 -> ×1.31 / ×1.50 (0.1 voxel), ×1.34 / ×1.41 -> ×1.33 / ×1.45 (0.2 voxel), "
          "none worse, every RMS lower (-0.7% to -13%); the max rose on finished_hexprism "
          "(0.785% -> 0.882% at noise 0, +10-12% at each noise; its input 1.49%) and block at "
          "0.1 voxel (1.152% -> 1.181%). The finer scan anyone can remake (above): 0.258% / "
          "0.0327% -> 0.257% / 0.0307% (its input 0.368% / 0.0325%): RMS 6% under the input's "
          "instead of 0.6% over. Time on it 2.43 s -> 2.52 s on two cores, memory as before. "
          "Tried in the same session and not kept: the regions' own planes fitted the same "
          "way for the first flattening (all of a planar region's faces, trimmed at 1.5): "
          "that scan's RMS 0.0244%, tuning scans RMS ×1.316 -> ×1.348 but max ×1.154 -> "
          "×1.136 (cylinder_block at noise 0 0.856% -> 1.041%, lblock_tilted at 0.2 voxel "
          "1.066% -> 1.282%), the same trade of max for RMS as the untrimmed fit the session "
          "before. `ctest -R \"PlanePatches|FitPlane|rough_planes|families_subset\"`.", ""]
    L += ["**How exact the sampled max is** (2026-11-27). `run.py --distance-samples N` "
          "measures with N samples a side instead of 100,000. Both halves, the default "
          "method before the rule above, at a million samples: the same verdicts (abc6's two "
          "at UMR), family means within 4% (the largest moves: own MC tuning max ×2.57 -> "
          "×2.48, IER 0.5% validation max ×3.61 -> ×3.48). Of the 534 max readings (inputs and "
          "outputs), 32 read more than 2% below their million-sample reading and none more "
          "than 1% above: a sampled max can only miss the farthest point. It misses most on "
          "small features: cross_prism's outputs at UMR 0.5% and 1% read 16% and 14% below, "
          "the cube's near-exact outputs (max under 0.01%) up to 90%. So run.py now measures "
          "every worse output of the default again with a million samples, with its input, "
          "and the lists of worse outputs give both readings; the verdicts and the means "
          "stay those of the 100,000 samples, MeshLab's filter as the benchmark runs it.", ""]
    L += ["**Edges stopped at corners** (2026-11-27, chosen on the tuning half). The own "
          "planes were kept away from corners: the flanks' fits next to a corner see the third "
          "face, and the flanks' own line runs on past it. Where every other region near an "
          "edge vertex is a plane too, the vertex now takes its flanks' own line and stops at "
          "the corner where that line meets the third plane (`keepBeforeEndPlane`: the edge "
          "lies on the side of the third plane where both flanks' cores lie; a third plane "
          "with the flanks on both sides keeps the fitted target), within the same 0.1-1 "
          "spacing of the fitted planes' target. Screened Poisson rounds the faces most near "
          "its corners, where its max error sits. Tuning half, none worse and no input's "
          "figure worse than before beyond bevelled_block UMR 2% RMS +0.5%: Screened Poisson "
          "RMS ×1.45 -> ×1.46 (lblock_tilted 0.894% -> 0.862%), UMR RMS ×3.89 -> ×3.91, own "
          "MC RMS ×8.01 -> ×8.04, OpenVDB RMS ×2.08 -> ×2.09 (lblock_tilted 2% 1.136% -> "
          "1.055%). Validation half, measured once: Screened Poisson RMS ×1.59 -> ×1.60, own "
          "MC RMS ×13.56 -> ×13.74, OpenVDB ×1.50 / ×3.89 -> ×1.48 / ×3.95, worse 2 of 141 as "
          "before; the wedge by OpenVDB at 2% loses max 0.700% -> 0.994% (its input: "
          "2.584%): its edge vertices near the acute corner now land on the edge, and a zone "
          "vertex beside them can no longer move onto its plane without flipping a face, so "
          "it stays a spacing out; finished_hexprism OpenVDB 1% RMS +1.6%, pyramid OpenVDB "
          "2% 0.931% -> 0.857%. `ctest -R region_planes`.", ""]
    L += ["**Where Screened Poisson's max stays** (located 2026-11-29, tuning half; nothing "
          "changed: `mesh-distance REFERENCE SHARPENED --samples 1000000 --color-out F.ply` "
          "colours the reference's vertices by their distance, the largest at the corner "
          "named). Sharpened by the default, 7_8ths_cube "
          "and three of the generated shapes keep their max at a convex corner of the "
          "reference, still rounded (bevelled_block's lies beside its designed features): "
          "7_8ths_cube 0.83% at (20, -20, -20), cross_prism 0.93% at (-0.3, "
          "-0.9, -0.3), cylinder_block 0.72% at (0.8, 0.8, -0.5), lblock_tilted 0.86% at a "
          "corner of the tilted block. On 7_8ths_cube the corner's zone breaks into about ten "
          "small features, each weak (samples up to 1.15 spacings off their planes: the "
          "reconstruction's blend), and the edges are sharpened up to them. A corner whose "
          "edges are sharpened is pinned by their three planes, but a designed vertex blend "
          "looks the same to the guard; no rule was made.", ""]
    L += ["**Planar regions' own planes** (2026-11-27, chosen on the tuning half). Placement "
          "fits a region's plane next to the feature (two face rings of a border vertex), "
          "where Screened Poisson rounds a planar face into its features, so the new vertices "
          "land short of the edge. A region whose core (its faces 3 or more hops from the "
          "zone, at least 20) lies within 0.25 spacings RMS of one plane and whose two halves, "
          "split across either principal axis, turn by at most 3 degrees (a curved region "
          "bends; noise averages out) now gives its own plane to the new vertices of its "
          "features, where no third region lies near a source (at a corner the fitted planes "
          "see the third face) and the shift from the fitted planes' target is 0.1-1 spacing "
          "(the vetoes judged the move from there; closer, the fitted planes are as good, and "
          "exact planes make faces along concave edges coincide, which the cleanup and the "
          "intersection guard then resolve worse: cross_prism UMR 0.5% 0.028% -> 0.153% "
          "without that floor). `--local-planes-only` turns it off. Tolerances 0.1-0.5, bends "
          "3-5 degrees and core depths 2-5 hops gave the same tuning half. A merged band of a "
          "faceted cylinder (cylinder_block CSG) passes the distance test alone and fails the "
          "bend (7.8 degrees; Screened Poisson's flat cores: at most 1.0). Tuning half, none "
          "worse: Screened Poisson RMS ×1.33 -> ×1.45 (lblock_tilted ×1.70 -> ×2.35), own MC "
          "×2.49 / ×7.97 -> ×2.57 / ×8.01, UMR ×1.78 / ×3.86 -> ×1.77 / ×3.89, OpenVDB RMS "
          "×2.03 -> ×2.08; the cost is on bevelled_block's designed bevels (UMR 2% 1.262% -> "
          "1.331%, OpenVDB 2% 1.298% -> 1.331%; each still better than its input). Validation "
          "half, measured first without the 0.1-spacing floor (own MC RMS ×12.50 -> ×20.09, "
          "Screened Poisson ×1.48 -> ×1.59) and once with it: Screened Poisson ×1.18 / ×1.48 "
          "-> ×1.18 / ×1.59, own MC ×5.67 / ×12.50 -> ×5.52 / ×13.56, OpenVDB RMS ×3.72 -> "
          "×3.89, UMR ×4.12 / ×7.35 -> ×4.07 / ×7.29, worse 2 of 141 as before, but the "
          "designed features cost: abc6 UMR 2% (already worse) 1.47% -> 1.79%, abc6 OpenVDB "
          "0.5% 0.275% -> 0.369%, fandisk IER 1% 0.522% -> 0.592% and UMR 1% 0.403% -> 0.426% "
          "(under its 0.43% target still), finished_hexprism own MC 1% 0.522% -> 0.594%: a "
          "sharper edge cuts a designed bevel or blend more exactly. Held out (Open3D Screened "
          "Poisson): the same verdicts, RMS lower on 16 of 17 references. `ctest -R "
          "region_planes`.", "",
          "**Own planes only where the fit is the same surface** (2026-11-28). abc6 at UMR 2% "
          "(validation half, worse) diagnosed: its flat top and the conical chamfer that cuts "
          "its hexagonal prism's corners (a nut's chamfer) form one region at that sampling, "
          "whose core is the top. Edge vertices between the region and a side wall, whose "
          "planes fitted next to the feature follow the cone (turned 38 degrees from the top), "
          "took the top's own plane and went to the box edge the cone cuts away (up to 1.79% "
          "of the diagonal from the reference). A source whose fitted plane turns more than 30 "
          "degrees from its region's own plane now keeps the fitted planes' target "
          "(`kOwnPlaneMaxTurnRad`). Tuning half: at 30 degrees no output changed; at 20 four "
          "RMS moved by at most 0.4%; at 15 and below the own planes lost their gains (lblock_"
          "tilted OpenVDB 2% max +7.7%, Screened Poisson RMS up to +44% at 5). So the bound is "
          "the smallest tried that leaves the tuning half as it was; it came from a validation "
          "case, and the validation half is not blind to it. Validation half: only abc6 at "
          "UMR 2% changed, max 1.795% -> 1.475%, RMS 0.066% -> 0.059% (still worse than its "
          "input's 0.817%: the other planes fitted next to the cone still meet at the box "
          "edge, the cone narrower there than a sample spacing). Held out: of the 120 cached "
          "inputs of the three held-out tools, one output changed (Blender's voxel remesh of "
          "bevelled_block at 1%, RMS 0.0375% -> 0.0374%). `ctest -R OnRegionPlanes`.", "",
          "**Blender's voxel remesh, and samples off their planes on a mesh sampled exactly** "
          "(2026-11-28). The held-out check with Blender (`docs/heldout-blender.md`) found the "
          "default making 4 of 20 voxel remeshes worse at 1%, with Preserve Volume on (Blender's "
          "default). So the benchmark gained a family, *vdbproj*: OpenVDB as Blender 3.4's "
          "voxel remesh with Preserve Volume as its source does it (the surface meshed 0.3 "
          "voxel outside, every vertex cast along its normal both ways onto the input, to the "
          "nearer hit within 5 voxels; its vertices agree with Blender's own to 5e-7 of the "
          "diagonal). Measured first with the default as it was: 5 of 30 worse on each half "
          "(tuning: bevelled_block at 2%, 1%, 0.5%, plate_holes and octa-flower17k at 1%; "
          "validation: finished_hexprism at 1% and 0.5%, abc6 at 1% and 0.5%, tube at 2%). "
          "Casting puts every vertex on the input's surface: a sharp edge's samples lie on its "
          "flanks' planes (a feature's nine in ten within 1e-6 spacings), a designed bevel's on "
          "the bevel, 0.1-0.5 spacings off both (`evidence-study`). So where the median edge "
          "feature, weighted by its new vertices, has nine in ten of its samples within 0.001 "
          "spacings of their planes (`sampledExactly`, `--exact-sampling`), a feature half of "
          "whose samples lie farther than `--on-plane` (0.05 spacings) from their planes "
          "stays as it was, and such a sample vouches for none of the new vertices it sources "
          "(the sharp edge running into a bevel keeps its other vertices). Chosen on the "
          "tuning half: 0.01 spacings took marching-cubes meshes whose axis-aligned edges are "
          "exact for exact (7_8ths_cube and cross_prism at UMR lost their gains), 0.0001 lost "
          "bevelled_block's CSG gain; 0.1 and 0.2 spacings off the planes left bevelled_block "
          "by vdbproj at 2% and 1% worse. Tuning half: bevelled_block by vdbproj 1.103% / "
          "0.570% / 0.473% -> 0.728% / 0.359% / 0.179% (inputs 0.837% / 0.404% / 0.214%), CSG "
          "1% 0.640% -> 0.609%; lost: cylinder_block by vdbproj at 2% 0.153% -> 0.456% (input "
          "0.851%: its cylinder's samples off the planes fitted to it), lblock_tilted by "
          "vdbproj 2% RMS +2.2%; nothing else changed. Validation half, measured once after: "
          "finished_hexprism by vdbproj 0.594% -> 0.389% at 1% and 0.270% -> 0.236% at 0.5% "
          "(no longer worse), CSG RMS 0.0366% -> 0.0277%; lost: wedge by vdbproj at 2% 0.520% "
          "-> 0.841% (input 0.884%), finished_hexprism at 2% 0.567% -> 0.624% (input 1.037%), "
          "tube at 1% RMS +15% (still under its input's); abc6 (its conical chamfers) and the "
          "tube at 2% stay worse. Held out, on Blender's own meshes: bevelled_block and "
          "finished_hexprism no longer worse at 1% or 0.5%; scikit-image's marching cubes "
          "(exact on a cube's axis-aligned faces) loses gains it had (the cube at 0.5% left "
          "as it was, 7_8ths_cube at 1% 0.133% -> 0.461%, input 0.580%), none made worse. "
          "`ctest -R exact_sampling`.", "",
          "**Own planes only where the edge's fits turn alike** (2026-11-28). A new held-out "
          "check, MeshLab's UMR decimated by its own Quadric Edge Collapse Decimation "
          "(`docs/heldout-decimate.md`), read finished_hexprism at 0.5% decimated to a quarter "
          "0.307% -> 0.704%. Its edges between a cap and a side run into fillets of the "
          "prism's outline: there the planes fitted next to the feature turn 26 degrees from "
          "the side's own plane (the fillet's start), while along the rest of the edge they "
          "turn under one degree; the own planes' line runs on straight past the fillet "
          "(`evidence-study --vertices`: twelve targets 0.4-0.9 spacings from the reference, "
          "the fitted planes' within 0.01). A reconstruction rounds a whole edge alike, so "
          "its fits turn from the own planes about alike along it: an edge vertex now keeps "
          "the fitted planes' target where its fits turn more than 20 degrees beyond the "
          "median turn of its edge's vertices (`OwnPlaneTurns`, `kOwnPlaneMaxExtraTurnRad`). "
          "Chosen on the tuning half (the default's auto outputs, `cmp` of max and RMS at "
          "0.1%): 20 degrees changed no output; 15 bevelled_block OpenVDB 2% RMS +1.3%; 10 "
          "also lblock_tilted OpenVDB 2% RMS +6.9%; 5 degrees lost more (lblock_tilted UMR 2% "
          "RMS +8.7%, OpenVDB 1% +13%). Validation half, measured once after: no output "
          "changed. Held out: finished_hexprism decimated 0.704% -> 0.152% (input 0.307%); "
          "no other output of the four held-out checks changed. `ctest -R "
          "\"OnRegionPlanes|OwnPlaneTurns\"`.", "",
          "**Sharp in part: on a mesh sampled exactly, each feature's own lift** (2026-11-28, "
          "no threshold added). OpenVDB as Blender's voxel remesh with Preserve Volume casts its "
          "vertices onto the input along their normals: at a convex edge they land on the edge "
          "itself, while a concave edge stays chamfered (on 7_8ths_cube and cross_prism, its "
          "notch and its saddle corners). The moves of the convex edges' new vertices only "
          "slide along the input (lift 0), those of the concave ones lift it to their edges "
          "(median lift 0.79, `evidence-study`), and the median of all the moves slid, so the "
          "default took the whole mesh for a model already sharp and left it, chamfers and "
          "all (the tuning half's 7_8ths_cube by vdbproj at 2%, 1% and 0.5% and cross_prism at "
          "1% and 0.5%). On a mesh sampled exactly (`sampledExactly`) a mostly sliding median "
          "now leaves only the features whose own moves mostly slide (the same 0.07 bound, "
          "`--min-lift`), and the others are judged by their evidence; an edge left as "
          "already sharp does not make the corners it runs into weak, as an edge weak by its "
          "evidence does (the corner's point lies on the sharp edge's line already); on other "
          "meshes the "
          "rule is as before (a CAD mesh taken as it is slides too, but its lifting features "
          "are curved faces' facets: fandisk and octa-flower17k as they are would change by "
          "0.23% and 0.68% of the diagonal if it were applied to every mesh). Applied to every "
          "mesh that is not left whole, it also cost cross_prism by vdbproj at 2% (RMS "
          "0.0034% -> 0.0195%), whose sliding features' moves help: so it applies only where "
          "the median slid. Tuning half: 7_8ths_cube by vdbproj 0.919% / 0.442% / 0.218% -> "
          "0.388% / 0.391% / 0.152% at 2% / 1% / 0.5% (RMS x41.7 / x4.3 / x11.8; with the "
          "corners inheriting the sharp edges' verdict, as first measured, 0.673% / 0.391% / "
          "0.172%, RMS x5.0 / x3.9 / x7.8), cross_prism by vdbproj RMS x1.33 at 1% and x1.92 "
          "at 0.5% (max as it was), the family x1.41 / x2.33 -> x1.49 / x3.20; nothing else "
          "changed. Validation half, "
          "measured once after: no output changed (its cube by vdbproj, exact and already "
          "sharp, still left as it was). Held out, on Blender's own voxel remesh "
          "(`docs/heldout-blender.md`): 7_8ths_cube 0.442% -> 0.361% at 1% and 0.218% -> "
          "0.075% at 0.5% (RMS x4.3 and x19), cross_prism RMS x1.32 and x1.94; no other "
          "output of the five held-out checks changed. `ctest -R \"partly_sharp|OnAMeshSampledExactly\"`.", "",
          "**A face without area does not refuse the zone projection** (2026-11-28, no "
          "threshold added). On 7_8ths_cube by OpenVDB (tuning half) the zone projection "
          "refused 65 vertices, the remesher's middle row along the convex edges, 0.43 cells "
          "off both faces. Placement had put two new vertices on one point of the edge's line "
          "(a grid-aligned edge gives neighbouring new vertices the same target), so the faces "
          "between them had lost their area, and the projection's fold test took their zero "
          "area for a face turned over. A face with no area faces no way: it no longer refuses "
          "a move (the cleanup collapses it later), and 4 of the 65 stay. Tuning half, every "
          "output compared with the build before: 7_8ths_cube by UMR 1% 0.0955% -> 0.0477%, "
          "the RMS of 7_8ths_cube by OpenVDB at each resolution, cylinder_block by OpenVDB 1%, "
          "cross_prism by own MC 1% and by OpenVDB 2% down 1-3%; plate_holes by vdbproj 1%, "
          "already worse (its fillet), RMS +1.0% and a max that reads 0.890% -> 0.923% with "
          "the benchmark's samples and 0.9096% -> 0.9075% with a million uniform ones. "
          "Validation half, measured once after: the cube by OpenVDB exact at 2% and 1% "
          "(0.434% -> 0.00001%), 0.184% -> 0.122% at 0.5%, the wedge by OpenVDB 0.994% -> "
          "0.634% at 2% and 0.369% -> 0.281% at 1%, lblock by UMR 0.0629% -> 0.016% at 0.5% and "
          "0.256% -> 0.184% at 2%, lblock by OpenVDB RMS -20% and -50%; none worse. The "
          "validation half's OpenVDB means went from x1.50 / x3.95 to x2.91 / x6.43, over the "
          "family's target, but only by the cube's two exact outputs (factors near 10^4 "
          "against the 1e-4% floor): without the cube they read x1.46 / x3.53. Tuning half: UMR "
          "x1.77 / x3.91 -> x1.83 / x3.93, OpenVDB RMS x2.09 -> x2.10; validation UMR x4.10 / "
          "x7.33 -> x4.40 / x7.79. "
          "The first form tested for exactly zero area, which a float64 mesh's rounding "
          "misses (the Python test of float32 against float64 caught the two precisions "
          "deciding differently); a face counts now when two corners lie at one point up to a "
          "float's rounding before the move and after it (`hasCoincidentCorners`, as the "
          "cleanup counts them). Against the first form's full run, the second changed 20 "
          "outputs of the two halves, by at most 1.4% of RMS but lblock by OpenVDB 1% (RMS "
          "0.00421% -> 0.00371%), maxima unchanged, none made worse; the tables here are from "
          "a full run of the second form (validation UMR RMS x7.79 -> x7.80, OpenVDB RMS "
          "x6.43 -> x6.46, without the cube x1.46 / x3.55; the rest as quoted above). "
          "`ctest -R \"coincident_corners|AFaceWithoutArea\"`.", "",
          "**A corner's cell onto a face** (2026-11-28, no threshold added). Locating the "
          "max errors the default leaves on the tuning half's OpenVDB meshes "
          "(7_8ths_cube at 1%) found, besides the concave edges (see \"Left rounded where "
          "OpenVDB cuts a concave edge in two\"), a dent at every convex corner: the voxel "
          "remesher puts one vertex in each cell the surface crosses, and in a corner's cell "
          "that vertex lies inside the solid, 0.43 spacings off all three faces. The corner "
          "and its edges were restored around it, but moving it onto its own region's plane "
          "would fold a face, so the zone projection refused it and it stayed (0.58% of the "
          "diagonal from the reference there). Where its own plane cannot take a zone "
          "vertex, the projection now tries the planes of the other regions near it, "
          "closest first, and takes the first that keeps every face and leaves the vertex no "
          "farther from any of its planes (`noFartherFromPlanes`): in a convex corner's cell "
          "each face's plane qualifies, while a plane turned towards another face, whose "
          "projection would carry the vertex away from it, does not. Tuning half (every "
          "output compared with the build before): cylinder_block by OpenVDB 0.254% -> "
          "0.193% at 1% and 0.141% -> 0.119% at 0.5%, lblock_tilted by OpenVDB 0.5% 0.249% "
          "-> 0.168%; one max read higher, lblock_tilted by the project's marching cubes at 1% "
          "0.343% -> 0.363% (the input's 0.834%), but the faces around that max are the "
          "same in both outputs (four vertices moved elsewhere, and the sampled measure's "
          "Montecarlo points move with the faces' areas): measured with 2 million uniform "
          "samples a side it reads 0.390% -> 0.386%. Other changes are within 0.5% of RMS; "
          "OpenVDB max x1.23 -> x1.27, own MC x2.57 -> x2.53 (that reading), none worse. Validation half, measured once after: "
          "cube by OpenVDB 0.5% 0.245% -> 0.184%, block by vdbproj 1% 0.323% -> 0.253%, "
          "lblock by OpenVDB 1% RMS -2.7%, wedge by UMR 1% RMS +1.8% (0.0154% -> 0.0156%, "
          "the input's 0.0677%); OpenVDB max x1.48 -> x1.50, vdbproj x1.51 -> x1.53, worse "
          "counts as before. `ctest -R \"corner_cells|ProjectZoneVertices\"`.", "",
          "**A bend near a corner moves with its feature** (2026-11-27, chosen on the tuning "
          "half). The bend test keeps a new vertex at rest when a flank's fitted faces curve "
          "away before its target, as a blend's or a curved face's do. Turned off on the "
          "tuning half (`--bend-fraction -1`), every family but the scans gained (UMR max "
          "×1.74 -> ×1.78, OpenVDB ×1.18 -> ×1.24, Screened Poisson RMS ×1.27 -> ×1.38; "
          "cylinder_block OpenVDB 2% 1.48% -> 0.70%, cross_prism Screened Poisson 0.98% -> "
          "0.89%): a sampler rounds a sharp edge most near its corners, and there the fitted "
          "faces bend like a blend's. But 23 of 30 scans and two CAD meshes taken as they are "
          "came out worse: the bend's refusals are what leaves them whole. So the bend now "
          "only marks a vertex whose move is at most one sample spacing: it moves when no "
          "other test refuses it, stays moved only with a feature whose evidence is strong, "
          "and counts as refused in the feature's and the whole mesh's evidence, whose "
          "verdicts are therefore the same as before (`--bent-move`, 0: off). Without the "
          "length bound, the held-out Open3D Poisson check's octa-flower17k (a tuning shape) "
          "rose 0.448% -> 0.509% at its petals' tips, where the flanks really curve and the "
          "moves are long; one spacing, the sampler's rounding, left the tuning half as it was "
          "without the bound and brought octa-flower17k back (0.438%). Tuning half, no input "
          "worse: UMR ×1.74 / ×3.81 -> ×1.78 / ×3.86, OpenVDB ×1.18 / ×1.99 -> ×1.23 / ×2.03, "
          "Screened Poisson ×1.11 / ×1.27 -> ×1.13 / ×1.33, CSG RMS ×2.92 -> ×2.98, IER RMS "
          "×2.70 -> ×2.73 (lblock_tilted UMR 2% 0.889% -> 0.580%); own MC ×2.51 -> ×2.49, under "
          "its ×2.5 target again: lblock_tilted at own MC 1% reads 0.375% -> 0.386%, though "
          "only one vertex moved, at (0.80, -0.33, -0.74), far from the max at (-0.14, 0.02, "
          "-0.36): the sampled measure's own spread. Validation half, measured "
          "once after: Screened Poisson ×1.13 / ×1.41 -> ×1.18 / ×1.48, now ahead of UnSharp "
          "Mask's max, OpenVDB ×1.49 / ×3.66 -> ×1.51 / ×3.72, worse 2 of 141 as before; the "
          "cost is on finished_hexprism's designed fillets, whose RMS rose 4-6% at own MC 1%, "
          "UMR 1% and 2% and OpenVDB 1% (0.0350% -> 0.0367% at own MC 1%; each still better "
          "than its input). `ctest -R bend_with_feature`.", "",
          "**Features mostly on their planes; features mostly refused** (2026-11-27, chosen "
          "on the tuning half with `evidence_study.py`). Two feature-level rules of the "
          "evidence guard changed. (1) A feature with one sample more than 0.6 spacings off "
          "its plane was weak unless nine in ten of its samples lay within 0.05 spacings; it "
          "is now also kept when half of them lie within 0.1 spacings and none beyond one "
          "spacing, both bounds times the sine of the angle its flanks meet at (an acute "
          "edge's line moves by the planes' errors over that sine); as before, the far "
          "samples' own new vertices stay at rest. On the tuning half the features the old "
          "rule left weak and this one keeps (38, not counting corners' inherited weakness) "
          "moved their vertices closer by a summed 977 spacings and farther by 6 "
          "(evidence-study's per-feature sums): a reconstruction "
          "or a voxel remesher rounds a few samples near an edge or a corner cell, where a "
          "blend or a designed bevel moves most of them off. (2) A feature now stays as it "
          "was when most of its vertices were refused by the other tests (more than half; "
          "it was 40%): below that, each refusal stays a vertex's own. Tuning half, no input "
          "worse: Screened Poisson ×1.08 / ×1.17 -> ×1.11 / ×1.27, own MC ×2.40 / ×7.13 -> "
          "×2.51 / ×7.94, OpenVDB ×1.17 / ×1.88 -> ×1.18 / ×1.99, IER ×1.41 -> ×1.44 "
          "(octa-flower17k Screened Poisson max 0.847% -> 0.752%, IER 2% 4.21% -> 2.38%, "
          "cylinder_block Screened Poisson 0.846% -> 0.731%, 7_8ths_cube OpenVDB 1% RMS 0.073% -> "
          "0.055%, its concave corner still at rest). Validation half, measured once "
          "after: UMR RMS ×7.24 -> ×7.34, OpenVDB ×3.60 -> ×3.66, Screened Poisson ×1.11 / "
          "×1.37 -> ×1.13 / ×1.41, own MC ×5.71 / ×12.68 -> ×5.67 / ×12.60, worse 2 of 141 "
          "as before; one max rose, finished_hexprism own MC 1% 0.501% -> 0.522% (the input's "
          "0.696%), and fandisk CSG's RMS 0.0209% -> 0.0215%. The sine was added after the "
          "held-out Open3D Poisson check showed the wedge's acute edge at 0.608% against "
          "0.540% without it (`docs/heldout.md`); with it the wedge reads 0.540% again and the "
          "tuning half loses a little on twirl (Screened Poisson RMS 0.0851% -> 0.0886%). "
          "`ctest -R mostly_on_planes`.", "",
          "**Saddle corners: a flat patch folded over itself is tiled again** (2026-11-26; "
          "diagnosed on cross_prism at UMR 1%, tuning half). Where a concave edge meets the "
          "top, the top has a reflex corner, and an input face of the top joins a sample of "
          "one arm to a sample of the other across the notch (from (0.290, 0.317) to (0.317, "
          "0.290) at z = 0.2994, passing (0.3036, 0.3036), outside both walls). Once the corner "
          "and edge vertices reach the sharp lines, that face juts past the corner and a child "
          "of the chamfer beside it folds back over it; the raised walls pierced both, and the "
          "intersection guard sent back the corner vertex and one edge vertex at each of the 8 "
          "saddle corners, where the max error stayed (0.454% -> 0.308%). All of these faces "
          "lie on the top's plane, so the default now tiles the flat patch around such a fold "
          "again (`guards/planar_folds.h`: grown from the fold one face on the plane at a "
          "time, never closing a vertex's fan, until its outline is one simple loop; ear "
          "clipping, no tile under the degenerate angle): the same flat surface, ending at the "
          "corner. cross_prism UMR 1%: max 0.308% -> 0.094%, 0.5%: 0.153% -> 0.028% "
          "(`ctest -R saddle_corners`). Chosen on the tuning half (UMR max ×1.46 -> ×1.74, own "
          "MC ×2.10 -> ×2.40, IER ×1.34 -> ×1.41, CSG ×1.54 -> ×2.13, none worse); the "
          "validation half, measured once after, gained too (UMR ×3.91 -> ×4.11, OpenVDB ×1.47 "
          "-> ×1.49, none worse), with one input whose max rose: pyramid at UMR 2%, 0.122% -> "
          "0.149% (the input's 0.992%). The patch keeps its faces' slots, so the guards' "
          "snapshot still restores the mesh; the paper's method is unchanged.", "",
          "**Left rounded where OpenVDB cuts a concave edge in two** (diagnosed on 7_8ths_cube "
          "at OpenVDB 0.5-2%, tuning half, with `evidence-study --sources`; max 1.155% at 1%, "
          "left as it was). At the notch's concave edges the voxel remesher's chamfer has a "
          "middle row of vertices, half a cell off both planes (0.5 spacings off each); "
          "segmentation gives that row to one flank's region, and the row's end at the concave "
          "corner lies 0.67 spacings off all three planes. That one far sample makes two of "
          "the three concave edges and the corner weak (the off-plane bound is 0.6 spacings), "
          "though every vertex they would move lands on the reference (each move brings its "
          "vertex closer). A sample as far from the other flank's plane as from its own is the "
          "sampler's cut, not a blend; but across the tuning half, features with such samples "
          "also include harmful ones (a designed bevel at UMR 0.5%, ADIS16480 at OpenVDB "
          "0.5%), so no rule was made of it. Measured again on 2026-11-28 in another form: "
          "each new vertex judged by the nearer of its two samples (the median over a "
          "feature's new vertices of that sample's distance from its plane, instead of the "
          "median over its samples, where the cut row and the flank's row tie). It kept 28 "
          "more features of the tuning half, and every figure that moved by more than 0.5% fell "
          "(7_8ths_cube "
          "by OpenVDB max -18% at each resolution, RMS -46% to -68%; bevelled_block by Screened "
          "Poisson 0.739% -> 0.621%; two RMS figures rose by 0.1%); but `evidence-study --vertices` showed "
          "ADIS16480 by OpenVDB 0.5% losing a fillet about one spacing in radius: 282 vertices "
          "each moved farther from the reference (0.22 -> 0.43 spacings), which the mesh's "
          "figures hide behind the input's own max (6.3%); and at IER three short features "
          "moved up to 0.8 spacings away. So it was not adopted. The row is not a region's "
          "(segmentation leaves it in the zone and labels it with one flank): the cure would "
          "be a zone vertex that stands for both flanks, placed on the line their planes meet "
          "on.", "",
          "**Corners beside blends stay at rest** (tried and rejected on 2026-11-26). An edge "
          "feature whose placement refused more than 40% of its vertices (now: most; a blend, by "
          "placement's own tests) makes the corners at its ends weak with it. Letting only "
          "the edges weak for another reason (off-plane samples, a shallow angle, too short, "
          "crossings) take their corners improved six inputs of the tuning half and harmed "
          "none (cylinder_block Screened Poisson max 0.846% -> 0.797%, lblock_tilted own MC "
          "0.413% -> 0.363%, octa-flower17k OpenVDB 0.5% 0.677% -> 0.554%); on the validation "
          "half, measured once, pyramid Screened Poisson 1.439% -> 1.320% but "
          "finished_hexprism own MC 1% 0.501% -> 0.550% (its designed fillets' corners; still "
          "better than the input's 0.696%), and own MC's mean ×5.71 -> ×5.61. A corner "
          "placed on three planes beside a designed fillet is the harm the guard exists to "
          "avoid, so the rule stays as it was.", "",
          "**Small flat pieces of a chamfer band stay regions** (tried and rejected on "
          "2026-11-27). On lblock_tilted at UMR 1% (tuning half) the max, 0.507%, sits on a "
          "convex edge where 7 chamfer faces around one vertex lie in one plane: segmentation "
          "makes them a region one hop deep, the edge is cut into five features around it, "
          "three come out weak and the stretch stays chamfered. Returning every region one hop "
          "deep to the zone (`--min-region-depth 2`) gained there but harmed the tuning half "
          "(cylinder_block CSG 1% worse than its input). Returning only those spanning less "
          "than a facet's 10 spacings still lost on curved shapes (octa-flower17k IER 2% left "
          "whole: max 2.34% -> 4.21%); less than 3 spacings (about one vertex's umbrella) "
          "gained on the tuning half with none worse (UMR ×1.77 / ×3.91 -> ×1.87 / ×4.10, "
          "OpenVDB ×1.23 / ×2.09 -> ×1.26 / ×2.13; lblock_tilted UMR 1% 0.507% -> 0.263%, "
          "OpenVDB 1% 0.758% -> 0.348%, 7_8ths_cube UMR 0.5% 0.167% -> 0.095%). Measured once "
          "on the validation half, it lost: Screened Poisson max ×1.18 -> ×1.14 (cube 0.635% "
          "-> 0.879%, its input's), own MC RMS ×13.74 -> ×13.02 and finished_hexprism UMR 0.5% "
          "0.275% -> 0.307% (its designed bevels' small facets dissolved), UMR ×4.07 / ×7.30 "
          "-> ×4.05 / ×7.21. A flat umbrella inside a band and a small designed facet look the "
          "same to segmentation, so regions stay as they are.", "",
          "**A mesh sampled exactly whose features are mostly blends** (studied on 2026-11-29, "
          "not adopted). plate_holes by vdbproj 1% (tuning half, worse: RMS 0.0487% -> "
          "0.105%) is sampled exactly, its vertices cast onto the input, but the default does "
          "not take it as such (`sampledExactly`): the fillets of the plate's bottom outline "
          "(radius 1.7 cells) and the holes' rims carry most of the features' new vertices, "
          "nine in ten of their samples within 0.31-0.47 spacings of their planes, so the "
          "median over the features' new vertices reads 0.28 spacings against the bound of "
          "0.001; the straight edges read 0.004-0.005. Taken as exact, its fillets would go "
          "back (`evidence-study`: the features with half their samples off their planes "
          "moved the vertices 500 sample spacings farther from the reference, summed). Gates "
          "tried on the tuning half's features (`bench/study/evidence_study.py`): the median "
          "at 0.01 spacings, the lower quartile at 0.001 or 0.01, a third at 0.01, the median "
          "over features instead of vertices. Each also takes marching-cubes meshes of "
          "axis-aligned shapes for exact (7_8ths_cube and cross_prism by UMR, cross_prism and "
          "cylinder_block by the project's MC: the grid samples an axis-aligned face exactly "
          "and cuts the chamfers), whose cut chamfers would then go back: on the tuning half "
          "each gate loses more than it gains (summed over the features that would go back, net "
          "250 to 456 sample spacings nearer the reference given up; with the lower quartile "
          "at 0.01, 693 gained, 679 of them on plate_holes and ADIS16480 by vdbproj 1%, "
          "against 1037 given up). Nor does a marching-cubes lattice tell the two apart: the "
          "voxel remesher's vertices on an axis-aligned face keep the grid's coordinates after "
          "the cast along the face's normal (plate_holes by vdbproj 1%: 91% of its vertices "
          "share two coordinates with at least three others; by UMR: 100%; by IER: none). "
          "Tried all the same and rejected after its validation run: a mesh whose vertices "
          "are not on a sampling grid (fewer than 99% sharing two coordinates so) counted as "
          "exact when a quarter of its features' new vertices had their samples within 0.01 "
          "spacings of their planes. Tuning half, every default output compared with the "
          "run above: plate_holes by vdbproj 1% no longer worse (max 0.923% -> 0.895%, its "
          "input 0.880%; RMS 0.105% -> 0.044%, its input 0.049%), plate_holes by IER 1% at "
          "multiplier 1.5 RMS +2.9% (still under its input's), nothing else by more than 0.5%. "
          "Validation half, measured once: abc6 by vdbproj at 1% and 0.5% no longer worse "
          "(0.316% -> 0.230% and 0.206% -> 0.167%), but fandisk passed through as it is "
          "changed by 0.23% of the diagonal (taken for exact, its curved faces' facets were "
          "judged feature by feature and sharpened), and most of the gains went on block and "
          "fandisk by IER (block at 2%: 1.04% -> 1.99%, its input's), block by vdbproj (at 2%: "
          "0.445% -> 1.08%) and tube by OpenVDB 0.5% (0.257% -> 0.329%, its input's). "
          "Reverted; the validation half has seen this gate. "
          "`bench/study/exact_sampling_gates.py` prints the gates' figures from "
          "`evidence_study.py --half tuning` (with `--inputs`, the grid share).", "",
          "**Corners on their regions' own planes** (studied on 2026-11-29, not adopted). "
          "Sharpened by the default, lblock_tilted by Screened Poisson keeps 6 of the 14 "
          "vertices of its reference 0.48-0.86% of the diagonal off, all convex corners (the "
          "others within 0.12%). At each a "
          "corner face was found and its new vertex refused: by the flank-bend test at four, "
          "by the intermediate-region test at one (the fits next to the corner see the "
          "reconstruction's rounding), and at the sixth its feature came out weak, beside a "
          "remnant region of a few faces left by the opening of region contacts. Tried: a "
          "corner vertex whose three regions are planes (their own planes, as for edges), "
          "with no other region near a source and fits turned at most 30 degrees from them, "
          "takes the own planes' corner where that lies more than 0.1 spacings from the "
          "fitted planes', judged by the apex and distance tests only. Tuning half, every "
          "default output compared with the full run: three changed, all better (lblock_tilted "
          "by Screened Poisson RMS 0.0828% -> 0.0784%, five of its six corners now within 0.12 "
          "spacings, its max unchanged at the sixth; lblock_tilted by OpenVDB 2% RMS -14%, "
          "bevelled_block by OpenVDB 2% RMS -1.9%), none worse. Validation half, measured "
          "once: abc6 by Screened Poisson max 0.609% -> 0.746% (a corner placed on its top, "
          "where the designed conical chamfers are), fandisk by IER 1% max 0.593% -> 0.656% "
          "at every multiplier, Screened Poisson max ×1.18 -> ×1.15; gains only on "
          "finished_hexprism by OpenVDB 2% (0.926% -> 0.904%) and lblock by Screened Poisson "
          "(RMS -2.5%). The curvature tests refuse designed corners too, so they stay. "
          "Reverted; the validation half has seen this rule "
          "(`git apply bench/study/own_plane_corners.patch` restores it for a rerun). Returning to the zone the "
          "remnant regions smaller than one sample spacing also restored the sixth corner "
          "(lblock_tilted by Screened Poisson max 0.862% -> 0.819%, where its concave edge "
          "then holds the max) but made octa-flower17k by UMR 1% at multiplier 1.5 worse "
          "(1.065% -> 1.338%, a petal's tip) on the tuning half: not taken further.", "",
          "**Blend gates per feature** (studied on 2026-11-29 on the tuning half only, not "
          "adopted). The fillet that makes plate_holes by vdbproj 1% worse (radius 1.7 cells) "
          "is also the one held-out tools square off (scikit-image's marching cubes, "
          "Blender's QuadriFlow and voxel remesh: `docs/heldout-skimage.md`, "
          "`docs/heldout-blender.md`). Two gates were weighed over the tuning half's kept "
          "edge features (`bench/study/blend_gates.py` on `evidence_study.py --half tuning` "
          "and `--sources`; a feature's harm or gain is the summed change of its moved "
          "vertices' distance to the reference, in sample spacings). A feature's median "
          "roundness (a moved vertex's farther source: its distance from its plane over its "
          "distance from the target; 0 on a plane, up to sin 45 degrees on a circular blend) "
          "over 0.3-0.6 sends back 236-1982 of harm but gives up 4079-9992 of gain: OpenVDB's "
          "own chamfers are as round (a dual vertex half a cell off both faces lies on the "
          "fillet of radius 1.7 cells that touches them). Its share of blend-like sources "
          "(0.15 spacings or more off their plane and 1.5 times as far from the other "
          "flank's) from 0.2 to 0.7 sends back 210-1309 and gives up 197-4552 (Screened "
          "Poisson and OpenVDB edges of cylinder_block and ADIS16480, whose reconstruction "
          "rounds a sharp edge as a fillet is round); where the two balance (0.6 and above) it "
          "reaches only 165-184 of plate_holes' 456. A fillet under two cells in radius and a "
          "sampler's rounding of a sharp edge leave the same samples: no gate was made.", "",
          "**The same output in any unit** (2026-11-29, a fix). The intersection guard tests "
          "two faces that share one vertex as vcglib does: the edge opposite the shared vertex "
          "in one, pulled halfway towards it, must pass through the other. vcglib's segment "
          "test (`IntersectionSegmentTriangle`) calls the segment parallel to the face when a "
          "determinant measured in squared units is below 1e-6, so the guard's answer "
          "depended on the model's unit: on abc6 (diagonal 0.0074) and ADIS16480 (0.069) it "
          "never saw such a fold, on plate_holes (366) it was exact, and on the models of "
          "about unit size it let segments within 0.03-0.4 degrees of the face's plane graze "
          "it; its box test also dropped a segment ending on the face only where the face "
          "was axis-aligned. The guard now uses its own test "
          "(`segmentThroughTriangle`), with the bound as an angle: a segment within 0.01 "
          "radians (about half a degree) of the plane lies in it, and one that ends on the "
          "face does not pass through it. The same model in metres, millimetres or "
          "kilometres (scaled by powers of two, which floating point keeps exact) now gives "
          "the same output to the bit (`SharpenShapes.SameOutputInAnyUnit`: three shapes, "
          "the three methods, scales 2^-14 and 2^10; lblock_tilted failed it before). A first "
          "version bounded the angle at 1e-6 radians and kept the segment's ends: in the "
          "full run (both halves seen) the guard then took the nearly flat folds OpenVDB "
          "leaves in its meshes for crossings and sent whole stretches back (pyramid by "
          "vdbproj 1%: 59 rounds, RMS 0.0070% -> 0.0594%, its input 0.0668%; tuning half: "
          "lblock_tilted by vdbproj 0.5% RMS +15%, cross_prism by IER 2% RMS +64% from the "
          "segment's ends). As adopted, against the run before: tuning half, lblock_tilted "
          "by OpenVDB 0.5% max 0.168% -> 0.192% (its input 0.526%), octa-flower17k by "
          "vdbproj 0.5% 0.305% -> 0.273%, RMS at 1% -0.6%; validation half, abc6 by UMR 1% "
          "RMS +0.8% and +1.0% (multipliers 2 and 1.5; 0.0123%, its input 0.0483%: its folds "
          "through a shared vertex are now seen), fandisk by vdbproj 0.5% RMS +0.6%; no "
          "other output changed by more than 0.5%, no family's mean moved by more than 0.01, "
          "none worse. Scalings that are not powers of two (x1000, x0.001) round the "
          "coordinates differently, and the outputs can still differ at a few vertices (by "
          "up to 0.5% of the diagonal: lblock_tilted by UMR 1%; fandisk 0.3%): contacts "
          "between faces made coplanar are decided at the floats' rounding. "
          "`ctest -R \"SameOutputInAnyUnit|SegmentThroughTriangle|FoldThroughASharedVertex\"`.", "",
          "**Features already sharp, judged move by move** (2026-11-29, tuning half). On a "
          "mesh sampled exactly whose moves mostly slide along it (a remesher casting its "
          "vertices onto the input: vdbproj, Blender's voxel remesh), a feature whose own moves "
          "slide was left whole as already sharp. cross_prism by vdbproj at 1% kept its max "
          "(0.504%, the paper's method 0.071%) at the four ends of each concave edge: where a "
          "concave edge meets a cap at a saddle corner, the remesher bridged it with one face, "
          "and the moves that would restore the edge's end belong to the concave edge's "
          "feature, sharp along the rest of its length. Of such a feature only the moves that "
          "slide now go back; a move that lifts its vertex off the input (its own lift at "
          "least the median bound, 0.07: the same bound, per vertex) stays, and so does the "
          "corner vertex of a face one of whose edge vertices stays so (the edge restored "
          "runs into that corner; sent back, the corner vertex sat at the bridging face's "
          "centroid, 0.33% of the diagonal off). These moves rest on their own evidence only: "
          "where the intersection guard can part two crossing faces as far out by sending "
          "back one vertex or another, it sends these back first (without that, on Blender's "
          "own voxel remesh of 7_8ths_cube, a new crossing at a saddle corner sent back a "
          "vertex sharpened before, and the max at 0.5% rose from 0.075% to 0.152%; sending "
          "them back first whatever the other vertex's level raised 7_8ths_cube by vdbproj "
          "2% from 0.0019% to 0.0040% RMS). The vertices left because they slide count as "
          "neither moved nor refused in the whole-mesh bound after the guards (counted as "
          "refused, they took 7_8ths_cube by vdbproj 2% over the bound and it was left whole). "
          "Tuning half, against the run before: cross_prism by vdbproj 1% max 0.504% -> "
          "0.0136%, RMS 0.0107% -> 0.00023% (its input 0.0143%); 0.5% max 0.208% -> 0.182%, "
          "RMS 0.0066% -> 0.0022%; 7_8ths_cube by vdbproj 2% max 0.388% -> 0.326%, RMS "
          "0.0023% -> 0.0019%, 0.5% RMS -14%, 1% RMS -3%; nothing else changed by more than "
          "0.5%. Validation half, run once after each step: no output changed (its shapes "
          "have no saddle corner). Held out, Blender's voxel remesh: cross_prism at 1% 0.504% -> 0.0136%, at 0.5% 0.208% -> 0.182%; 7_8ths_cube at 1% 0.361% -> 0.356%, at 0.5% 0.0748% -> 0.0626%; nothing else changed. The "
          "per-vertex bound is the median's, not fitted: measured before the corner and "
          "retreat rules, 0.5 kept none of cross_prism's gain at 1%, and 0.2 and 0.5 moved the "
          "max of the other inputs up or down from one input to the next; a lift measured "
          "against the faces the vertex was inserted in, rather than all the faces around its "
          "sources, kept fewer of these moves. "
          "`ctest -R \"partly_sharp|AVertexFlaggedToRetreatFirst|OnlyTheFeaturesThatSlide\"`.", ""]
    return L


def section(results, causes):
    """The markdown of the generalization sections (a list of lines)."""
    mult = results["default_multiplier"]
    cases = [c for c in results["cases"] if "before" in c]
    halves = results.get("halves", {})
    for c in cases:
        c.setdefault("half", halves.get(c["model"], "?"))
    L = []
    w = L.append
    w("## Generalization: every sampler family, validation half first (issue 19)")
    w("")
    w("The honest baseline: no method was tuned for these tables. **Halves.** "
      + results.get("split_rule", "") + " The halves are listed in `bench/quality/split.json`: "
      f"tuning = {', '.join(sorted(m for m, h in halves.items() if h == 'tuning'))}; "
      f"validation = {', '.join(sorted(m for m, h in halves.items() if h == 'validation'))}.")
    w("")
    w("**Cells**: geometric means of the max / RMS reduction factors (before/after, errors floored "
      f"at {FLOOR:g}% of the diagonal) over the references with sharp features (not "
      f"{', '.join(NO_SHARP_FEATURES)}, not *as is*); then **worse** = outputs whose max error "
      f"went up by more than {WORSE_MAX:.0%} or RMS by more than {WORSE_RMS:.0%} (all "
      "references, every resolution of the family) out of the outputs measured; *failed* = the "
      "sharpener refused the input (open or non-manifold scans) or the tool failed (listed "
      "below). Default multiplier "
      f"{mult:g}. *UnSharp Mask (MeshLab)* = MeshLab 2020.09's stock \"UnSharp Mask "
      "Geometry\" at its defaults (weight 0.3, original weight 1, 5 iterations), the peer a "
      "MeshLab user already has. Distances: `mesh-distance --sampling "
      + " ".join(results.get("distance_sampling", ["uniform"])[1:]) + "` (vertices, edge "
      "samples and Montecarlo face samples as MeshLab's Hausdorff Distance filter spreads them).")
    w("")
    for half in ("validation", "tuning"):
        hc = [c for c in cases if c["half"] == half]
        w(f"### {half.capitalize()} half: by family")
        w("")
        w(family_table(hc, mult) if hc else "*(no inputs)*")
        w("")
    for half in ("validation", "tuning"):
        hc = [c for c in cases if c["half"] == half]
        w(f"### {half.capitalize()} half: by family and resolution")
        w("")
        w(family_table(hc, mult, by_resolution=True) if hc else "*(no inputs)*")
        w("")
    w("### Worse cases (default multiplier, every method and the peer)")
    w("")
    ordered = sorted(cases, key=lambda c: (c["half"] != "validation", c["input"], c["order"],
                                           c["model"]))
    w(worse_list(ordered, mult, causes))
    w("")
    w("### Refusals and failures")
    w("")
    w(failures_list(ordered))
    w("")
    w("### What the project's own samplers made")
    w("")
    w("`bench/samplers/vdb-remesh` (OpenVDB 10 `meshToLevelSet` + `volumeToMesh`, adaptivity 0, "
      "quads split in two; with `--project`, the *vdbproj* family, Blender 3.4's voxel remesh "
      "with Preserve Volume as its source does it: the surface 0.3 voxel outside, every vertex "
      "cast along its normal both ways onto the input and moved to the nearer hit within 5 "
      "voxels, quads split as bmesh's Beauty; on six references its vertices agree with "
      "Blender's own to 5e-7 of the diagonal) and `bench/samplers/tsdf_scan.py` (26 depth "
      "images, 256×256 pixels, "
      "rendered by our own z-buffer rasterizer from the directions of a 3×3×3 grid's outer "
      "cells; Gaussian depth noise of 0, 0.1 or 0.2 voxel, seeded; Open3D 0.16 "
      "`ScalableTSDFVolume`, voxel 1% of the diagonal, truncation 4 voxels; the largest "
      "connected component kept). A scan that is not a closed 2-manifold is refused by the "
      "sharpener and counted as *failed* above, not repaired.")
    w("")
    w(sampler_table(results))
    w("")
    return L
