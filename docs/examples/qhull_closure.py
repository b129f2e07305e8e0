#!/usr/bin/python3
"""Force and form closure the way GraspIt!/Dex-Net-style code decides it: the convex hull of the contact
wrenches (scipy.spatial.ConvexHull, i.e. qhull) and "is the origin strictly inside?" with a tolerance.

Reads a wrenchkit reference corpus and writes one answer line per scene, in the format of
`wrenchkit compare` (docs/reference-format.md section 5):

    wrenchkit reference --out corpus
    /usr/bin/python3 docs/examples/qhull_closure.py corpus > qhull.jsonl
    wrenchkit compare corpus qhull.jsonl

The worked example is docs/compare-example.md. This is deliberately the usual floating-point method,
not a good one: wrenches in doubles, a hull that needs full-dimensional input (qhull raises
QhullError on flat wrench sets, the very cases where closure fails for a reason), and a tolerance on
the facet offsets. Options:
    --tolerance T     the origin is inside when every facet offset is < -T (default 1e-12)
    --joggle          qhull option QJ: perturb the input instead of failing on flat sets
    --errors-as-false answer false when qhull raises (as `except QhullError: return False` does);
                      the default reports the error and gives no answer
"""
import argparse
import json
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
from scipy.spatial import ConvexHull, QhullError


def number(text):
    """A scene number (JSON number or "p/q" string) as the nearest double, as float code reads it."""
    return float(Fraction(str(text)))


def wrenches(scene, frictionless):
    """Contact wrench generators (fx, fy, m about the origin), unit normal force, as doubles."""
    out = []
    for c in scene.get("contacts", []):
        if "wrench" in c:
            out.append([number(x) for x in c["wrench"]])
            continue
        px, py = (number(x) for x in c["at"])
        nx, ny = (number(x) for x in c["normal"])
        length = np.hypot(nx, ny)
        nx, ny = nx / length, ny / length
        mu = 0.0 if frictionless else number(c.get("mu", 0))
        edges = [(nx, ny)] if mu == 0 else [(nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx)]
        for fx, fy in edges:
            out.append([fx, fy, px * fy - py * fx])
    return np.array(out, dtype=float).reshape(-1, 3)


def origin_strictly_inside(w, tolerance, joggle):
    """qhull's hull of the wrenches; the origin is inside when it is below every facet by > tolerance."""
    hull = ConvexHull(w, qhull_options="QJ" if joggle else None)
    offsets = hull.equations[:, -1]  # a.x + offset <= 0 inside; at the origin: offset
    return bool(np.all(offsets < -tolerance))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("corpus", type=Path, help="directory written by wrenchkit reference")
    ap.add_argument("--tolerance", type=float, default=1e-12)
    ap.add_argument("--joggle", action="store_true")
    ap.add_argument("--errors-as-false", action="store_true")
    args = ap.parse_args()
    with open(args.corpus / "reference.jsonl") as f:
        for line in f:
            ref = json.loads(line)
            answer = {"id": ref["id"]}
            errors = []
            for field, frictionless in (("force_closure", False), ("form_closure", True)):
                try:
                    answer[field] = origin_strictly_inside(wrenches(ref["scene"], frictionless), args.tolerance,
                                                           args.joggle)
                except (QhullError, ValueError) as e:  # flat or too few wrenches
                    answer[field] = False if args.errors_as_false else None
                    errors.append(f"{field}: {str(e).strip().splitlines()[0]}")
            if errors and not args.errors_as_false:
                answer["error"] = "; ".join(errors)
            sys.stdout.write(json.dumps(answer) + "\n")


if __name__ == "__main__":
    main()
