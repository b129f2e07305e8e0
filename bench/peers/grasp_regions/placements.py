#!/usr/bin/python3
"""Sampled finger placements on the reference corpus's polygon parts, decided the way float tools decide them, as
answers for `wrenchkit compare` (docs/reference-format.md §5, field "placements"; docs/grasp-regions.md).

For every line with "grasp_regions" (family polygon_part): two fingers on every edge pair at a 6x6 grid and 10^-k
(k = 3, 6, 9, 12, 15) beside every corner of the exact region, toward its centroid and away; three fingers on every
edge triple at a 3x3x3 grid and at each certified cube's centre. Each placement decided by one method:

  libicr   the convex hull of the friction-cone wrenches by qhull (scipy.spatial.ConvexHull), closed when every
           facet's offset is below -1e-10 (the origin strictly inside), open when qhull throws — libicr's rule
           (its EPSILON_FORCE_CLOSURE threshold; moments about the origin)
  nguyen   two fingers only: Nguyen's test in doubles, |cross(n, d)| < mu (n . d) at both fingers

  /usr/bin/python3 placements.py CORPUS/reference.jsonl --method libicr > answers.jsonl
  wrenchkit compare CORPUS answers.jsonl

Needs NumPy and SciPy (Debian's python3-numpy, python3-scipy).
"""
import argparse
import itertools
import json
import sys
import warnings
from fractions import Fraction

import numpy as np
from scipy.spatial import ConvexHull


def cones(outline, mu):
    V = [(float(Fraction(x)), float(Fraction(y))) for x, y in outline]
    n = len(V)
    area2 = sum(V[k][0] * V[(k + 1) % n][1] - V[(k + 1) % n][0] * V[k][1] for k in range(n))
    out = []
    for k in range(n):
        dx, dy = V[(k + 1) % n][0] - V[k][0], V[(k + 1) % n][1] - V[k][1]
        nx, ny = (-dy, dx) if area2 > 0 else (dy, -dx)
        tx, ty = -ny, nx
        out.append((V[k], (dx, dy), (nx, ny), [(nx - mu * tx, ny - mu * ty), (nx + mu * tx, ny + mu * ty)]))
    return out


def point(c, s):
    return (c[0][0] + s * c[1][0], c[0][1] + s * c[1][1])


def libicr(C, edges, s):
    W = []
    for e, t in zip(edges, s):
        px, py = point(C[e], t)
        W += [(fx, fy, px * fy - py * fx) for fx, fy in C[e][3]]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            hull = ConvexHull(np.array(W))
    except Exception:  # qhull's errors (a flat set): libicr calls the grasp open
        return False
    return bool(np.all(hull.equations[:, -1] < -1e-10))


def nguyen(C, edges, s, mu):
    if len(edges) != 2:
        return None
    p, q = point(C[edges[0]], s[0]), point(C[edges[1]], s[1])
    ok = True
    for c, d in ((C[edges[0]], (q[0] - p[0], q[1] - p[1])), (C[edges[1]], (p[0] - q[0], p[1] - q[1]))):
        nx, ny = c[2]
        along, side = nx * d[0] + ny * d[1], nx * d[1] - ny * d[0]
        ok = ok and along > 0 and abs(side) < mu * along
    return ok


def samples(line):
    g = line["grasp_regions"]
    for p in g["pairs"]:
        e = p["edges"]
        for a in range(6):
            for b in range(6):
                yield e, [Fraction(2 * a + 1, 12), Fraction(2 * b + 1, 12)]
        for poly in p["closed"]:
            P = [(Fraction(x), Fraction(y)) for x, y in poly]
            cx, cy = sum(x for x, _ in P) / len(P), sum(y for _, y in P) / len(P)
            for x, y in P:
                for k in (3, 6, 9, 12, 15):
                    for sign in (1, -1):
                        t = Fraction(sign, 10 ** k)
                        s = [x + t * (cx - x), y + t * (cy - y)]
                        if all(0 <= v <= 1 for v in s):
                            yield e, s
    for t in g.get("triples", []):
        e = t["edges"]
        for a, b, c in itertools.product(range(3), repeat=3):
            yield e, [Fraction(2 * a + 1, 6), Fraction(2 * b + 1, 6), Fraction(2 * c + 1, 6)]
        if "independent" in t:
            yield e, [(Fraction(lo) + Fraction(hi)) / 2 for lo, hi in t["independent"]]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("corpus", help="CORPUS/reference.jsonl")
    ap.add_argument("--method", choices=("libicr", "nguyen"), default="libicr")
    a = ap.parse_args()
    for raw in open(a.corpus, encoding="utf-8"):
        line = json.loads(raw)
        if not isinstance(line.get("grasp_regions"), dict):
            continue
        mu = float(Fraction(line["grasp_regions"]["mu"]))
        C = cones(line["scene"]["body"]["outline"], mu)
        out = []
        for e, s in samples(line):
            sd = [float(v) for v in s]
            closed = libicr(C, e, sd) if a.method == "libicr" else nguyen(C, e, sd, mu)
            if closed is None:
                continue
            out.append({"edges": e, "s": [str(v) for v in s], "closed": closed})
        print(json.dumps({"id": line["id"], "placements": out, "_method": a.method}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
