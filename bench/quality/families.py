"""The generalization sections of docs/results.md (issue 19): every sampler family, the
validation half before the tuning half, every method and variant and the stock peer, with
worse counts by a stated rule and the list of worse cases.

Pure functions of the results JSON written by run.py; report.py places the returned
markdown at the top of docs/results.md.
"""
import math
import statistics

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


# A max read with 100,000 samples can lie this far below the true max of a small feature
# (docs/auto-method-decisions.md, "The maximum read with 100,000 samples moves by up to 12%");
# an RMS, which averages every sample, moves far less.
SAMPLED_MAX_SPREAD = 0.15
SAMPLED_RMS_SPREAD = 0.03


def may_be_worse(before, after):
    """Whether an output could be worse than its input once both are read exactly: worse as
    read, or within the sampled readings' spread of the line (either side may under-read)."""
    spread = {"max": after["max"] * (1 + SAMPLED_MAX_SPREAD),
              "rms": after["rms"] * (1 + SAMPLED_RMS_SPREAD)}
    return is_worse(before, after) or is_worse(before, spread)


def run_is_worse(case, run):
    """The worse rule for one run: on its reading with run.DENSE_SAMPLES where it has one
    (run.py takes it for every default output that may_be_worse), else on the benchmark's."""
    dense = run.get("dense")
    if dense:
        return is_worse(dense["before"], dense["after"])
    return is_worse(case["before"], run["after"])


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
        if run_is_worse(c, r):
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
            if r is None or r["status"] != "ok" or not run_is_worse(c, r):
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
    """The default's outputs worse as read with the benchmark's samples or with
    run.DENSE_SAMPLES (run.py measures every default output near the line again, with its
    input); the verdict is the dense reading's (run_is_worse)."""
    rows = ["| half | family | model | resolution | max before -> after | RMS before -> after "
            "| with a million samples: max, RMS |", "|---|---|---|---|---|---|---|"]
    for c in cases:
        r = _run(c, DEFAULT_METHOD, mult)
        if r and r["status"] == "ok" and (is_worse(c["before"], r["after"])
                                          or run_is_worse(c, r)):
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


# Issue 61, point 4: a designed bevel, fillet or narrow face up to this many sample spacings
# wide can give the very mesh a sampler gives a sharp edge (bench/study/bevel_ambiguity.py):
# no rule on the mesh alone tells them apart, the user's selection does.
AMBIGUOUS_SPACINGS = 1.5
SELECTION_VARIANT = "auto-selection"  # run.py: the default with the designed faces left out


def narrowest_designed(case, mult):
    """The case's narrowest designed feature (run.py: case["designed"]) in its own sample
    spacings (the default's run), or None when it has none known or no spacing was
    reported."""
    features = case.get("designed") or []
    r = _run(case, DEFAULT_METHOD, mult)
    if not features or r is None or not r.get("sample_spacing"):
        return None
    return min(f["width"] for f in features) / r["sample_spacing"]


def _worse_of(cases, method, mult):
    """The cases whose run of `method` came out worse, and the count measured."""
    worse, measured = [], 0
    for c in cases:
        r = _run(c, method, mult)
        if r is None or r["status"] != "ok":
            continue
        measured += 1
        if run_is_worse(c, r):
            worse.append(c)
    return worse, measured


def no_harm_table(cases, mult):
    """Issue 61's worse count in two parts, per family: inputs whose designed features are all
    wider than AMBIGUOUS_SPACINGS (or that have none), and inputs with one within it (each
    worse one listed with its width); then the default with the user's selection."""
    rows = [f"| family | designed features all wider than {AMBIGUOUS_SPACINGS:g} spacings "
            f"(target 0) | one within {AMBIGUOUS_SPACINGS:g} spacings: worse, and their widths "
            "| with the user's selection (designed faces left out; target 0) |",
            "|---|---|---|---|"]
    totals = [0, 0, 0, 0, 0, 0]
    for kind, cs in _families(cases):
        narrowest = [narrowest_designed(c, mult) for c in cs]
        clear = [c for c, n in zip(cs, narrowest) if n is None or n > AMBIGUOUS_SPACINGS]
        within = {id(c): n for c, n in zip(cs, narrowest) if c not in clear}
        wa, ma = _worse_of(clear, DEFAULT_METHOD, mult)
        wb, mb = _worse_of([c for c in cs if id(c) in within], DEFAULT_METHOD, mult)
        ws, ms = _worse_of(cs, SELECTION_VARIANT, mult)
        harmed = ", ".join(f"{c['model']} {c['resolution']}" for c in wa)
        listed = ", ".join(f"{c['model']} {c['resolution']} ({within[id(c)]:.2f} spacings)"
                           for c in wb)
        rows.append(f"| {FAMILY_TITLES.get(kind, kind)} | {len(wa)}/{ma} ({_mark(not wa)})"
                    + (f": {harmed}" if harmed else "")
                    + f" | {len(wb)}/{mb}" + (f": {listed}" if listed else "")
                    + f" | {f'{len(ws)}/{ms} ({_mark(not ws)})' if ms else '–'} |")
        for i, n in enumerate((len(wa), ma, len(wb), mb, len(ws), ms)):
            totals[i] += n
    rows.append(f"| all | {totals[0]}/{totals[1]} ({_mark(totals[0] == 0)}) | "
                f"{totals[2]}/{totals[3]} | {totals[4]}/{totals[5]} "
                f"({_mark(totals[4] == 0)}) |")
    return "\n".join(rows)


def gap_closed(case, run, measure):
    """The fraction of the gap to the information limit a run closed on `measure` ("max" or
    "rms"): (before - after) / (before - limit), errors floored; None where the case has no
    limit or its input is already within WORSE_MAX of it (no gap to close)."""
    if "limit" not in case:
        return None
    b, a, lim = (_floored(x[measure]) for x in (case["before"], run["after"], case["limit"]))
    if b <= lim * (1 + WORSE_MAX):
        return None
    return (b - a) / (b - lim)


def limit_table(cases, mult):
    """Issue 60, point 1: per grid family, the default against the information limit (dual
    contouring with exact Hermite data on a grid of the input's cell size): geometric means of
    the max and RMS errors of the input, the default and the limit, and the fraction of the gap
    closed, median and minimum, with the inputs that close the least of the max gap. Inputs
    with a designed feature within AMBIGUOUS_SPACINGS are counted apart: there the mesh alone
    cannot tell the feature from a sampling chamfer, while the limit's exact normals can."""
    rows = ["| family | inputs (designed feature within "
            f"{AMBIGUOUS_SPACINGS:g} spacings, apart) | max: input / default / limit (% of "
            "diagonal) | gap closed, median (min) | RMS: input / default / limit | gap closed, "
            "median (min) | least max gap closed |",
            "|---|---|---|---|---|---|---|"]
    for kind, cs in _families(cases):
        pairs = [(c, _run(c, DEFAULT_METHOD, mult)) for c in cs if "limit" in c
                 and c["model"] not in NO_SHARP_FEATURES]
        pairs = [(c, r) for c, r in pairs if r is not None and r["status"] == "ok"]
        clear = []
        for c, r in pairs:
            narrowest = narrowest_designed(c, mult)
            if narrowest is None or narrowest > AMBIGUOUS_SPACINGS:
                clear.append((c, r))
        if not clear:
            continue
        cells, closed = [], {}
        for measure in ("max", "rms"):
            means = [_gmean([_floored(x[measure]) for x in xs]) for xs in
                     ([c["before"] for c, _ in clear], [r["after"] for _, r in clear],
                      [c["limit"] for c, _ in clear])]
            closed[measure] = [(g, c) for g, c in ((gap_closed(c, r, measure), c)
                                                   for c, r in clear) if g is not None]
            gaps = [g for g, _ in closed[measure]]
            cells += [" / ".join(f"{m:.3g}" for m in means),
                      f"{statistics.median(gaps):.2f} ({min(gaps):.2f}), {len(gaps)} inputs"
                      if gaps else "–"]
        least = sorted((g, c["model"], c["resolution"]) for g, c in closed["max"])
        cells.append(", ".join(f"{m} {res} {g:.2f}" for g, m, res in least[:3]) or "–")
        rows.append(f"| {FAMILY_TITLES.get(kind, kind)} | {len(clear)} "
                    f"({len(pairs) - len(clear)}) | " + " | ".join(cells) + " |")
    return "\n".join(rows) if len(rows) > 2 else ""


def default_section(results):
    """Issue 20: the default method against its targets, per half (a list of lines)."""
    mult = results["default_multiplier"]
    cases = [c for c in results["cases"] if "before" in c]
    L = ["## The default method (auto) against its targets (issue 20)", "",
         "Decided on the tuning half; each rule's validation figures were measured only after "
         "it was fixed, and where a rule saw the validation half first, its record says so. "
         "Every rule of the default, every rule tried and dropped, with its figures on both "
         "halves, and what the default cannot tell from the mesh alone: "
         "[`auto-method-decisions.md`](auto-method-decisions.md). "
         "Targets: no output worse in any family (max up > 2% or RMS up > 1%), gains as listed, "
         "ahead of MeshLab's UnSharp Mask on both max and RMS. Where the targets and no harm "
         "conflict, no harm wins: a feature the evidence does not support stays chamfered.", ""]
    for half in ("validation", "tuning"):
        hc = [c for c in cases if c.get("half") == half]
        L += [f"### {half.capitalize()} half", "", targets_table(hc, mult), "",
              f"Outputs of the default method that came out worse ({half} half; read with "
              "100,000 samples a side, then, for every output near the line, with a million, "
              "the reading the worse counts use):", "",
              default_worse_list(sorted(hc, key=lambda c: (c["input"], c["order"], c["model"])),
                                 mult), "",
              f"No harm as it can be met (issue 61, {half} half): the worse count of the default "
              "in two parts, by the input's narrowest designed feature (a bevel, fillet or narrow "
              "face the part was designed with: test_meshes/designed_faces.h for the generated "
              "shapes, bench/quality/designed.json for the others) in the input's own sample "
              f"spacings: all wider than {AMBIGUOUS_SPACINGS:g} (or none), where a worse output is "
              "harm the default must not do; and one within it, where the mesh alone cannot "
              "tell the feature from a sampling chamfer. Then the default with the user's "
              "selection: the generated shapes' designed faces (those within one sample spacing "
              "of a designed feature) left out with `--skip-faces`.", "",
              no_harm_table(hc, mult), "",
              f"The information limit (issue 60, {half} half): the generated shapes by the grid "
              "samplers beside dual contouring with exact Hermite data (Ju et al. 2002: exact "
              "edge crossings, the surface's normals, the QEF solved by SVD with truncation; "
              "`dual-contour`) on a grid of the same cell size, which a post-process on a bare "
              "mesh can at best approach. Gap closed: (input − default) / (input − limit), per "
              "input whose error is more than 2% above the limit's. Inputs with a designed "
              f"feature within {AMBIGUOUS_SPACINGS:g} sample spacings are counted apart (in "
              "brackets): the mesh alone cannot tell such a feature from a chamfer, and dual "
              "contouring itself cuts a bevel about a cell wide off (one vertex per cell). One "
              "corner three ways (input, default, limit): "
              "[`images/corner-limit.png`](images/corner-limit.png) "
              "(`bench/study/corner_figure.py`); corners of four or more faces, each sampler "
              "at 1% and 0.5%: [`corners.md`](corners.md) (`bench/study/corner_table.py`).", "",
              limit_table(hc, mult) or "(no input with a limit in this half)", "",
              f"Where the default misses a gain target ({half} half), input by input: what the "
              "default did (its report) and the input's max error in its own sample spacings "
              "(the sharpener's median edge length). Deeper than "
              f"{LOST_PART_SPACINGS:g} spacings, that error is not a chamfer but a part the "
              "sampler lost (a wall IER collapsed, a thin part the voxels dropped), which no "
              "sharpener gives back; each family's gain is also given without those inputs.",
              "",
              *default_misses(hc, mult)]
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
      "references, every resolution of the family) out of the outputs measured (the default's "
      "outputs near the line read again with a million samples a side, input and output, and "
      "judged on that reading); *failed* = the "
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
