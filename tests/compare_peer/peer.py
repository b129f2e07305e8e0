"""A small peer for the end-to-end test of `wrenchkit reference --scenes` and `wrenchkit compare`
(CTest compare_peer_end_to_end): the two-finger force-closure test as such code is often written, with
two deliberate bugs that compare must find and classify.

* A documented tolerance: a grasp counts as closed only when the line between the fingers lies inside
  both friction cones by more than TOL = 1e-3 rad (grasps closer to the threshold are called open:
  lost grasps, within the tolerance of a boundary).
* An orientation bug: the angle between a finger's normal and the line to the other finger is taken
  from abs(cos), ignoring on which side of the finger the other one is (unsafe: two fingers pushing
  the same way are called closed).

Scenes with a load on a support get a fixture answer instead (`hold`, and `motion` on a support region), as
a quick fixture check is often written: the load is taken to be a force through the support's centre of
pressure, the contacts are ignored, and the body is held (sticks) when |F| <= mu W + ATOL. Two more deliberate
bugs:

* An absolute tolerance ATOL = 1e-3 (in force units) on the friction limit: a push 5e-4 above mu W is called
  held (unsafe: falsely holds; on a support region, falsely sticks).
* Any support force not given is answered "depends", without checking whether every admissible distribution
  holds (lost: falsely depends, where every one does).
A support region gets no hold answer (null): only its motion.

Reads the user's scenes (JSON lines {"id", "scene"}) and writes one answer per line with 0/1 verdicts
(NumPy integers when NumPy is installed, as json.dumps(default=int) writes them). Scenes with other than
two point contacts get "error".

    python3 peer.py scenes.jsonl > answers.jsonl
"""
import json
import math
from fractions import Fraction
import sys

try:
    import numpy as np
    verdict = np.int64
except ImportError:  # the same 0/1 text without NumPy
    verdict = int

TOL = 1e-3
ATOL = 1e-3


def closed(scene):
    c = scene["contacts"]
    (p1, n1, mu1), (p2, n2, mu2) = [((float(x["at"][0]), float(x["at"][1])),
                                     (float(x["normal"][0]), float(x["normal"][1])), float(x.get("mu", 0)))
                                    for x in c]
    d = (p2[0] - p1[0], p2[1] - p1[1])
    length = math.hypot(*d)

    def inside(n, towards, mu):
        cos = (n[0] * towards[0] + n[1] * towards[1]) / (math.hypot(*n) * length)
        angle = math.acos(min(1.0, abs(cos)))  # BUG: abs() ignores the finger's side
        return angle < math.atan(mu) - TOL     # documented tolerance

    return inside(n1, d, mu1) and inside(n2, (-d[0], -d[1]), mu2)


def fixture(scene):
    s = scene["support"]
    mu = float(Fraction(str(s["mu"])))  # "1/2"
    if "regions" in s:
        weight = sum(float(r["force"]) for r in s["regions"])
    elif all("force" in p for p in s["points"]):
        weight = sum(float(p["force"]) for p in s["points"])
    else:
        return {"hold": "depends"}  # BUG: never checks the admissible distributions
    load = scene["load"]
    force = load["force"] if "force" in load else load["wrench"][:2]
    held = math.hypot(float(force[0]), float(force[1])) <= mu * weight + ATOL  # BUG: absolute tolerance
    if "regions" in s:
        return {"hold": None, "motion": "sticks" if held else "slides"}
    return {"hold": verdict(held)}


for line in open(sys.argv[1]):
    if not line.strip():
        continue
    entry = json.loads(line)
    scene = entry["scene"]
    if "load" in scene and "support" in scene:
        print(json.dumps(dict({"id": entry["id"]}, **fixture(scene)), default=int))
        continue
    if len(scene.get("contacts", [])) != 2:
        print(json.dumps({"id": entry["id"], "force_closure": None, "error": "not a two-finger grasp"}))
        continue
    print(json.dumps({"id": entry["id"], "force_closure": verdict(closed(scene))}, default=int))
