#!/usr/bin/python3
"""Label a grasp dataset (docs/python.md, "Label a grasp dataset").

A Dex-Net-style sampler proposes grasps on an object as NumPy arrays; wrenchkit.closure_arrays labels every
candidate with the exact force-closure verdict (all cores, the GIL released); the candidates where your own
metric disagrees are listed with wrenchkit's certificate, which the independent checker accepted. Here "your
metric" is the usual qhull test of docs/examples/qhull_closure.py (the hull of the contact wrenches in
doubles, origin strictly inside by 1e-12). With --cli and --corpus, the same metric is then run over the
reference corpus and `wrenchkit compare` tells its bugs (disagreements far from any degenerate boundary) from
its tolerance issues (near one).

    /usr/bin/python3 docs/examples/label_grasps.py --grasps 100000
    /usr/bin/python3 docs/examples/label_grasps.py --grasps 20000 --cli build/wrenchkit --corpus corpus
"""
import argparse
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import wrenchkit

sys.path.insert(0, str(Path(__file__).resolve().parent))
from qhull_closure import origin_strictly_inside  # noqa: E402
from scipy.spatial import QhullError  # noqa: E402


def sample_grasps(n, seed=0, mu=0.5):
    """Antipodal-style candidates on the ellipse x²/a² + y²/b² = 1 (a = 1, b = 0.6), as a Dex-Net-style sampler
    proposes them: a first contact at a random angle; a second where a ray from it meets the ellipse again — along
    its normal jittered (a noisy mesh), or, for a quarter of the candidates, exactly along the edge of its friction
    cone (what an antipodality test at its limit accepts: the boundary cases that decide a dataset's labels); and
    a third finger on a third of them (ragged rows: counts 2 or 3). Returns points, inward normals (n, 3, 2),
    mu (n, 3), counts (n,)."""
    rng = np.random.default_rng(seed)
    a, b = 1.0, 0.6
    t = rng.uniform(0, 2 * np.pi, (n, 3))
    p1 = np.stack([a * np.cos(t[:, 0]), b * np.sin(t[:, 0])], axis=-1)
    n1 = -np.stack([np.cos(t[:, 0]) / a, np.sin(t[:, 0]) / b], axis=-1)
    n1 /= np.hypot(n1[:, 0], n1[:, 1])[:, None]
    edge = rng.uniform(size=n) < 0.25
    angle = np.where(edge, np.arctan(mu) * rng.choice([-1, 1], n), rng.normal(0, 0.35, n))
    c, s = np.cos(angle), np.sin(angle)
    d = np.stack([c * n1[:, 0] - s * n1[:, 1], s * n1[:, 0] + c * n1[:, 1]], axis=-1)
    # p1 + u d on the ellipse again: u = -B / A for A u² + B u = 0.
    A = (d[:, 0] / a) ** 2 + (d[:, 1] / b) ** 2
    B = 2 * (p1[:, 0] * d[:, 0] / a ** 2 + p1[:, 1] * d[:, 1] / b ** 2)
    p2 = p1 + (-B / A)[:, None] * d
    n2 = -np.stack([p2[:, 0] / a ** 2, p2[:, 1] / b ** 2], axis=-1)
    p3 = np.stack([a * np.cos(t[:, 2]), b * np.sin(t[:, 2])], axis=-1)
    n3 = -np.stack([np.cos(t[:, 2]) / a, np.sin(t[:, 2]) / b], axis=-1)
    points, normals = np.stack([p1, p2, p3], axis=1), np.stack([n1, n2, n3], axis=1)
    counts = np.where(rng.uniform(size=n) < 1 / 3, 3, 2)
    return points, normals, np.full((n, 3), mu), counts


def qhull_metric(points, normals, mu, counts, tolerance=1e-12):
    """Your metric: force closure by qhull (True, False, or None when qhull fails on a flat wrench set)."""
    out = []
    for p, nrm, m, c in zip(points, normals, mu, counts):
        w = []
        for (px, py), (nx, ny), f in zip(p[:c], nrm[:c], m[:c]):
            length = np.hypot(nx, ny)
            nx, ny = nx / length, ny / length
            for fx, fy in ((nx - f * ny, ny + f * nx), (nx + f * ny, ny - f * nx)):
                w.append([fx, fy, px * fy - py * fx])
        try:
            out.append(origin_strictly_inside(np.array(w), tolerance, False))
        except QhullError:
            out.append(None)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--grasps", type=int, default=100000)
    ap.add_argument("--show", type=int, default=3, help="disagreements to print with their certificates")
    ap.add_argument("--cli", help="the wrenchkit command, to compare the metric with the reference corpus")
    ap.add_argument("--corpus", help="directory for the reference corpus (made with --cli if missing)")
    o = ap.parse_args()

    points, normals, mu, counts = sample_grasps(o.grasps)
    t = time.perf_counter()
    r = wrenchkit.closure_arrays(points, normals, mu, counts)
    dt = time.perf_counter() - t
    exact = r["force_closure"]
    print(f"{o.grasps} candidates labelled in {dt:.2f} s ({o.grasps / dt:,.0f}/s): {int(exact.sum())} in force "
          f"closure; decided by the float twin alone: {int((r['decided_by'] == 0).sum())}, with an exact fallback: "
          f"{int((r['exact_predicates'] > 0).sum())}")

    t = time.perf_counter()
    metric = qhull_metric(points, normals, mu, counts)
    print(f"the qhull metric took {time.perf_counter() - t:.2f} s")
    failed = np.array([m is None for m in metric])
    said = np.array([bool(m) for m in metric])
    differ = np.flatnonzero(~failed & (said != exact))
    print(f"qhull failed on {int(failed.sum())} candidates; it disagrees with the exact verdict on {len(differ)}")

    if len(differ):
        shown = differ[: o.show]
        c = wrenchkit.closure_arrays(points[shown], normals[shown], mu[shown], counts[shown], certificates=True)
        for row, cert in zip(shown, c["certificates"]):
            scene = wrenchkit.Scene(cert["scene_json"])
            checked = wrenchkit.check(scene, cert["certificate"])["accepted"]
            proof = cert["certificate"]
            what = (f"positive weights on {len(proof['combination'])} generators summing to zero" if proof["holds"]
                    else f"a twist {tuple(str(x) for x in proof['twist'])} no contact force can resist")
            print(f"  candidate {row}: qhull says {said[row]}, wrenchkit says {bool(exact[row])}: {what}, "
                  f"accepted by the independent checker: {checked}")

    if o.cli and o.corpus:
        corpus = Path(o.corpus)
        if not (corpus / "reference.jsonl").exists():
            subprocess.run([o.cli, "reference", "--out", str(corpus)], check=True, stdout=subprocess.DEVNULL)
        answers = corpus.parent / "qhull_answers.jsonl"
        with open(answers, "w") as f:
            subprocess.run([sys.executable, str(Path(__file__).resolve().parent / "qhull_closure.py"), str(corpus),
                            "--errors-as-false"], check=True, stdout=f)
        report = subprocess.run([o.cli, "compare", str(corpus), str(answers)], capture_output=True, text=True)
        print("\nwrenchkit compare (the metric on the reference corpus):")
        print("\n".join(report.stdout.splitlines()[:4]))
        if report.returncode not in (0, 1):
            sys.exit(report.returncode)
    return 0


if __name__ == "__main__":
    sys.exit(main())
