"""Four closure tests as third-party grasp code often writes them, each with one kind of bug, for the
worked examples of docs/compare-example.md. Standard-library Python only (no NumPy or SciPy needed).

    python3 peer_bugs.py CORPUS --bug threshold|orientation|lp-bounds|scaling > answers.jsonl
    wrenchkit compare CORPUS answers.jsonl

Reads the corpus' reference.jsonl (the scene of each line; exact numbers "p/q" read as doubles) and writes
one answer per line with 0/1 verdicts, as such code writes them.

The generic test (threshold, lp-bounds, scaling): the contact wrenches g_i (friction-cone edges with unit
normal force, or the normals for form closure; moments about the origin) positively span R^3 iff their
rank is 3 and no twist t != 0 has t.g_i >= 0 for every i. Such a t, if one exists, can be taken among
+-(g_a x g_b), so the code tries those.

* threshold:   moments about the contacts' centroid over their RMS radius, unit vectors, and "closed" only
               when every candidate t has some t.g_i below -1e-3 (and the rank test |det| > 1e-3): an
               absolute margin, as documented tolerances of 1e-3 are (lost grasps near a boundary).
* lp-bounds:   the separating twist is sought only among t >= 0 componentwise, which is what an LP over t
               written with scipy.optimize.linprog's default bounds (0, None) for every variable does
               (unsafe: open grasps whose separating twist has a negative component are called closed).
* scaling:     raw (unnormalised) vectors against absolute thresholds 1e-9 (rank: |det| > 1e-9; margin:
               t.g_i < -1e-9): right at unit scale, wrong on the same grasp scaled down.
* orientation: the two-finger antipodal test, where the angle between a finger's normal and the line to
               the other finger is taken from abs(cos), ignoring the finger's side (a `use_abs_value`);
               two-finger scenes only (others: no answer).
"""
import argparse
import itertools
import json
import math
from fractions import Fraction
from pathlib import Path


def num(x):
    return float(Fraction(str(x)))


def generators(scene, friction, frame=False):
    """The contact wrenches; with frame, moments about the contacts' centroid over their RMS distance
    from it (the torque scaling such code uses so that a threshold means the same at every size)."""
    out = []
    pts = [(num(c["at"][0]), num(c["at"][1])) for c in scene.get("contacts", []) if "at" in c]
    cx = sum(p[0] for p in pts) / len(pts) if pts and frame else 0.0
    cy = sum(p[1] for p in pts) / len(pts) if pts and frame else 0.0
    rms = math.sqrt(sum((p[0] - cx) ** 2 + (p[1] - cy) ** 2 for p in pts) / len(pts)) if pts and frame else 1.0
    rms = rms if rms > 0 else 1.0
    for c in scene.get("contacts", []):
        if "wrench" in c:
            fx, fy, m = (num(v) for v in c["wrench"])
            out.append((fx, fy, (m - (cx * fy - cy * fx)) / rms))
            continue
        px, py = (num(v) for v in c["at"])
        px, py = (px - cx) / rms, (py - cy) / rms
        nx, ny = (num(v) for v in c["normal"])
        length = math.hypot(nx, ny)
        nx, ny = nx / length, ny / length
        mu = num(c.get("mu", 0)) if friction else 0.0
        forces = [(nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx)] if mu > 0 else [(nx, ny)]
        for fx, fy in forces:
            out.append((fx, fy, px * fy - py * fx))
    return out


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(v):
    n = math.sqrt(dot(v, v))
    return tuple(x / n for x in v) if n > 0 else v


def closed(g, bug):
    if bug == "threshold":
        g, eps = [unit(v) for v in g], 1e-3
    else:
        eps = 1e-9 if bug == "scaling" else 1e-12
        if bug != "scaling":
            g = [unit(v) for v in g]
    if len(g) < 4:
        return False
    if not any(abs(dot(cross(a, b), c)) > eps for a, b, c in itertools.combinations(g, 3)):
        return False  # rank < 3
    for a, b in itertools.combinations(g, 2):
        t = cross(a, b)
        if bug != "scaling":
            t = unit(t)
        for s in (1, -1):
            ts = tuple(s * x for x in t)
            if bug == "lp-bounds" and min(ts) < 0:
                continue  # linprog's default bounds: every variable >= 0
            if dot(ts, ts) > 0 and all(dot(ts, v) >= -eps for v in g):
                return False  # a twist on no generator's negative side: not closed
    return True


def two_finger_closed(scene):
    cs = scene["contacts"]
    (p1, n1, mu1), (p2, n2, mu2) = [((num(c["at"][0]), num(c["at"][1])), (num(c["normal"][0]), num(c["normal"][1])),
                                     num(c.get("mu", 0))) for c in cs]
    d = (p2[0] - p1[0], p2[1] - p1[1])
    length = math.hypot(*d)
    if length == 0:
        return False

    def inside(n, towards, mu):
        cos = (n[0] * towards[0] + n[1] * towards[1]) / (math.hypot(*n) * length)
        return math.acos(min(1.0, abs(cos))) < math.atan(mu)  # abs(): the finger's side is lost

    return inside(n1, d, mu1) and inside(n2, (-d[0], -d[1]), mu2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("corpus")
    ap.add_argument("--bug", required=True, choices=["threshold", "orientation", "lp-bounds", "scaling"])
    a = ap.parse_args()
    path = Path(a.corpus)
    if path.is_dir():
        path = path / "reference.jsonl"
    for line in path.open():
        ref = json.loads(line)
        scene = ref["scene"]
        if a.bug == "orientation":
            cs = scene.get("contacts", [])
            if len(cs) != 2 or any("wrench" in c for c in cs):
                continue
            print(json.dumps({"id": ref["id"], "force_closure": int(two_finger_closed(scene))}))
            continue
        frame = a.bug == "threshold"
        print(json.dumps({"id": ref["id"], "force_closure": int(closed(generators(scene, True, frame), a.bug)),
                          "form_closure": int(closed(generators(scene, False, frame), a.bug))}))


if __name__ == "__main__":
    main()
