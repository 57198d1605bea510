"""The --within X,Y,Z,R option the study tools share: spheres that keep a tool to parts of a
reference (designed_faces_near.py, narrow_facets.py)."""
import sys

import numpy as np


def add_option(parser, help_text):
    """Adds the repeatable --within X,Y,Z,R to an argparse parser."""
    parser.add_argument("--within", action="append", default=[], metavar="X,Y,Z,R",
                        help=help_text)


def spheres(args, tool):
    """The parsed --within spheres (x, y, z, r); one line and a non-zero exit when malformed."""
    try:
        parsed = [tuple(float(x) for x in w.split(",")) for w in args.within]
    except ValueError:
        parsed = [()]
    if any(len(s) != 4 for s in parsed):
        sys.exit(f"{tool}: --within takes X,Y,Z,R")
    return parsed


def inside(points, spheres_):
    """Per point, whether it lies within one of the spheres."""
    mask = np.zeros(len(points), dtype=bool)
    for x, y, z, r in spheres_:
        mask |= np.linalg.norm(points - np.array([x, y, z]), axis=1) <= r
    return mask


