#!/usr/bin/env python3
"""Prints, from a results JSON of bench/quality/run.py, one line per half, family and
method: the geometric means of the max / RMS reduction factors and the worse count by the
benchmark's rule (families.py), and with --worse the worse cases.

  bench/quality/summary.py RESULTS.json [--methods auto,paper] [--worse]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import families  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("results")
    ap.add_argument("--methods")
    ap.add_argument("--worse", action="store_true", help="list the worse cases")
    args = ap.parse_args()
    results = json.load(open(args.results))
    methods = args.methods.split(",") if args.methods else results["methods"] + ["unsharp-mask"]
    mult = results["default_multiplier"]
    for half in ("validation", "tuning"):
        cases = [c for c in results["cases"] if c.get("half") == half and "before" in c]
        for kind, cs in families._families(cases):
            for method in methods:
                gmax, grms, worse, measured, failed = families.family_stats(cs, method, mult)
                if measured + failed == 0:
                    continue
                print(f"{half:10s} {kind:8s} {method:22s} {families._fx(gmax)} / "
                      f"{families._fx(grms)}  worse {worse}/{measured}"
                      + (f", {failed} failed" if failed else ""))
                if not args.worse:
                    continue
                for c in cs:
                    r = families._run(c, method, mult)
                    if r and r["status"] == "ok" and families.run_is_worse(c, r):
                        print(f"{'':44s}{c['model']} {c['resolution']}: "
                              + families.before_after(c["before"], r["after"]))


if __name__ == "__main__":
    main()
