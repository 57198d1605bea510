"""Shared parts of the quality tests' Python checkers (tests/quality/*.py).

The checkers run as scripts (tests/quality/*.sh), so this directory is first on sys.path and
`import checks` finds this module; importing it puts bench/quality there too, for the
benchmark's modules (run, meshlab, families). Environment from tests/quality_tests.cmake:
ES_BUILD_DIR, ES_MESHLAB_PREFIX, ES_WORK_DIR (scratch).
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench",
                                "quality"))


def load_results():
    """The results JSON of bench/quality/run.py named by the first argument, with the cases of
    the results JSONs named by any further arguments appended."""
    with open(sys.argv[1]) as f:
        results = json.load(f)
    for path in sys.argv[2:]:
        with open(path) as f:
            results["cases"] += json.load(f)["cases"]
    return results


def finish(failures, passed):
    """Prints the failures and exits 1 when there are any, else prints `passed`."""
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures), file=sys.stderr)
        sys.exit(1)
    print(passed)


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-30)


def default_method_outcomes(cases, failures, multiplier=2.0, width=28):
    """(case, before, after) of every case whose input was made and on which the default
    method (auto) ran at `multiplier`, each printed; failures appended for the others and for
    outputs worse than their input (families.is_worse: max up > 2% or RMS up > 1%)."""
    import families
    out = []
    for c in cases:
        name = f"{c['model']} {c['input']} {c['resolution']}"
        if c["make"]["status"] != "ok" or "before" not in c:
            failures.append(f"{name}: input not made: {c['make'].get('why', c['make']['status'])}")
            continue
        runs = [r for r in c["runs"] if r["method"] == "auto" and r.get("multiplier") == multiplier]
        if len(runs) != 1 or runs[0]["status"] != "ok":
            failures.append(f"{name}: the default method did not run: {runs}")
            continue
        before, after = c["before"], runs[0]["after"]
        print(f"  {name:{width}s} max {before['max']:.4f} -> {after['max']:.4f}  "
              f"RMS {before['rms']:.5f} -> {after['rms']:.5f}")
        if families.is_worse(before, after):
            failures.append(f"{name}: worse (max {before['max']:.4g} -> {after['max']:.4g}, "
                            f"RMS {before['rms']:.4g} -> {after['rms']:.4g})")
        out.append((c, before, after))
    return out


def require_factor(case, before, after, quantity, bound, failures):
    """Appends a failure when the default method lowered the case's `quantity` ("max" or
    "rms") by less than the factor `bound`."""
    if before[quantity] < bound * after[quantity]:
        failures.append(f"{case['model']} {case['input']} {case['resolution']}: "
                        f"{'RMS' if quantity == 'rms' else quantity} "
                        f"x{before[quantity] / after[quantity]:.2f} < x{bound}")


def check_default_method(fields, expected, passed, factors=None, multiplier=2.0, width=28,
                         each=None):
    """The whole check of a results JSON: each case made, sharpened by the default method at
    `multiplier` and measured, none worse (default_method_outcomes); the cases, keyed by the
    tuple of their `fields`, exactly `expected` (require_measured); each case's reduction
    factors at least the bounds `factors(case)` gives ({"max" or "rms": bound}, none when
    `factors` is None); `each(case, failures)`, when given, checks each case further. Exits
    like finish()."""
    failures = []
    outcomes = default_method_outcomes(load_results()["cases"], failures, multiplier, width)
    for c, before, after in outcomes:
        for quantity, bound in (factors(c) if factors else {}).items():
            require_factor(c, before, after, quantity, bound, failures)
        if each:
            each(c, failures)
    require_measured(outcomes, fields, expected, failures)
    finish(failures, passed)


def check_min_factors(min_factors, resolution, passed, multiplier=2.0, width=24):
    """check_default_method on a results JSON with one input per model of `min_factors`, all at
    `resolution`: its max and RMS reduction factors at least min_factors[model] = (max, RMS)."""
    check_default_method(("model", "resolution"), {(model, resolution) for model in min_factors},
                         passed, lambda c: dict(zip(("max", "rms"), min_factors[c["model"]])),
                         multiplier, width)


def check_rms_factors_by_resolution(input_key, min_rms_factors, passed, multiplier=2.0,
                                    each=None):
    """check_default_method on a results JSON with one model's inputs `input_key` at the
    resolutions of `min_rms_factors`: its RMS reduction factor at least
    min_rms_factors[resolution]; `each(case, run, failures)`, when given, checks each case's
    default run further."""
    def each_run(c, failures):
        each(c, next(r for r in c["runs"] if r["method"] == "auto"
                      and r.get("multiplier") == multiplier), failures)

    check_default_method(("input", "resolution"),
                         {(input_key, resolution) for resolution in min_rms_factors}, passed,
                         lambda c: {"rms": min_rms_factors[c["resolution"]]}, multiplier, 16,
                         each_run if each else None)


def check_max_factors_by_model(min_max_factors, passed, multiplier=2.0):
    """check_default_method on a results JSON whose inputs are the (model, resolution) keys of
    `min_max_factors`: its max reduction factor at least min_max_factors[(model, resolution)]."""
    check_default_method(("model", "resolution"), min_max_factors, passed,
                         lambda c: {"max": min_max_factors[(c["model"], c["resolution"])]},
                         multiplier)


def require_measured(outcomes, fields, expected, failures):
    """Appends a failure unless the cases of `outcomes` (default_method_outcomes), each keyed by
    the tuple of its `fields`, are exactly the set `expected`: no input may go missing."""
    seen = {tuple(c[f] for f in fields) for c, _, _ in outcomes}
    if seen != set(expected):
        failures.append(f"measured {sorted(seen)}, expected {sorted(expected)}")


# --------------------------------------------------------------------------- MeshLab cross-checks
def meshlab_setup(shapes):
    """(run.Tools, meshlab.Server, work directory) with the generated shapes `shapes` (exact
    references and the project's marching cubes at 1% cells) written to the work directory."""
    import meshlab
    import run
    work = os.environ["ES_WORK_DIR"]
    tools = run.Tools(os.environ["ES_BUILD_DIR"])
    server = meshlab.Server(os.path.join(os.environ["ES_MESHLAB_PREFIX"], "bin", "meshlabserver"),
                            os.path.join(work, "home"))
    subprocess.run([tools.generator, work, "--cells", "0.01", "--shapes", ",".join(shapes)],
                   check=True, stdout=subprocess.DEVNULL)
    return tools, server, work


def hausdorff_both_ways(server, a, b, filters, samples, tag):
    """[(min, max, mean, RMS) of A -> B, of B -> A] from MeshLab's Hausdorff Distance filters
    `filters` (sampling `samples` points) run on meshes A and B, or None. The run's directory
    in ES_WORK_DIR is named after `tag`."""
    import meshlab
    # A Hausdorff abort on one sample count is a known MeshLab bug: retry once with another.
    for attempt, n in enumerate((samples, samples + 1357)):
        text = meshlab.script(*filters).replace(f'value="{samples}"', f'value="{n}"')
        wd = os.path.join(os.environ["ES_WORK_DIR"], f"{tag.replace(' ', '-')}-{attempt}")
        ok, _, why = server.run([a, b], None, text, wd, 300)
        if ok:
            rows = meshlab.Server.hausdorff_results(os.path.join(wd, "log.txt"))
            if len(rows) == 2:
                return rows
        print(f"  {tag}: MeshLab attempt {attempt + 1} failed: {why}")
    return None


def agree(failures, label, side, what, ours, theirs, tol, widths=(15, 28)):
    """Prints mesh-distance's figure against MeshLab's; a failure when they differ by more
    than `tol` (relative). `widths`: of the label and `what` columns."""
    r = rel(ours, theirs)
    print(f"  {label:{widths[0]}s} {side:8s} {what:{widths[1]}s} mesh-distance {ours:.6g}  "
          f"MeshLab {theirs:.6g}  difference {100 * r:.2f}% (tolerance {100 * tol:.0f}%)")
    if r > tol:
        failures.append(f"{label} {side} {what}: {ours:.6g} vs MeshLab {theirs:.6g} "
                        f"({100 * r:.2f}% > {100 * tol:.0f}%)")
