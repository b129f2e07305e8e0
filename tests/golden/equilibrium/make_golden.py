#!/usr/bin/env python3
"""Writes the golden equilibrium scenes of theory.md §9 with their expected verdicts.

A load w_ext is balanced iff -w_ext is a non-negative combination of the contact wrench generators
(with friction). This script re-derives every stated verdict by brute force in exact fractions
(Carathéodory: try every set of at most three generators, solve exactly, accept non-negative
coefficients) and refuses to write a scene whose stated verdict disagrees.
    python3 tests/golden/equilibrium/make_golden.py
"""
import json
import os
from fractions import Fraction as F
from itertools import combinations

HERE = os.path.dirname(os.path.abspath(__file__))


def num(q):
    q = F(q)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def gens(contacts):
    out = []
    for c in contacts:
        px, py = (F(x) for x in c["at"])
        nx, ny = (F(x) for x in c["normal"])
        mu = F(c.get("mu", 0))
        forces = [(nx, ny)] if mu == 0 else [(nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx)]
        out += [(fx, fy, px * fy - py * fx) for fx, fy in forces]
    return out


def solve(cols, x):
    """Exact least-squares-free solve of sum a_i cols_i = x for 1..3 columns; None if inconsistent."""
    k = len(cols)
    # Gaussian elimination on the 3 x k system, exact.
    m = [[cols[j][r] for j in range(k)] + [x[r]] for r in range(3)]
    piv_cols, row = [], 0
    for col in range(k):
        p = next((r for r in range(row, 3) if m[r][col] != 0), None)
        if p is None:
            return None  # dependent columns: a smaller subset covers it
        m[row], m[p] = m[p], m[row]
        for r in range(3):
            if r != row and m[r][col] != 0:
                f = m[r][col] / m[row][col]
                m[r] = [a - f * b for a, b in zip(m[r], m[row])]
        piv_cols.append(col)
        row += 1
    if any(m[r][k] != 0 for r in range(row, 3)):
        return None
    return [m[i][k] / m[i][i] for i in range(k)]


def balanced(contacts, w):
    target = tuple(-x for x in w)
    if target == (0, 0, 0):
        return True
    g = gens(contacts)
    for k in (1, 2, 3):
        for idx in combinations(range(len(g)), k):
            a = solve([g[i] for i in idx], target)
            if a is not None and all(v >= 0 for v in a):
                return True
    return False


def contact(at, normal, mu):
    return {"at": [num(x) for x in at], "normal": [num(x) for x in normal], "mu": num(mu)}


SCENES = []


def scene(name, title, contacts, load, want, body=None):
    SCENES.append((name, title, contacts, load, want, body))


def load_wrench(load, body):
    if "gravity" in load:
        w = F(load["gravity"])
        return (F(0), -w, -w * F(body["com"][0]))
    if "wrench" in load:
        return tuple(F(x) for x in load["wrench"])
    fx, fy = (F(x) for x in load["force"])
    x, y = (F(v) for v in load["at"])
    return (fx, fy, x * fy - y * fx)


# Block in a corner (theory.md §9): the same verdicts for mu = 0 and mu = 1/2.
for mu, tag in [(0, "0"), (F(1, 2), "1_2")]:
    cs = [contact((0, 0), (0, 1), mu), contact((1, 0), (0, 1), mu), contact((0, 0), (1, 0), mu),
          contact((0, 1), (1, 0), mu)]
    body = {"outline": [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]], "com": ["1/2", "1/2"]}
    for lname, load, want in [
        ("gravity", {"gravity": "1"}, True),
        ("push_left_at_1_half", {"force": ["-1", "0"], "at": ["1", "1/2"]}, True),
        ("push_down_left_at_1_1", {"force": ["-1", "-1"], "at": ["1", "1"]}, True),
        ("push_down_at_1_1", {"force": ["0", "-1"], "at": ["1", "1"]}, True),
        ("pull_right_at_0_half", {"force": ["1", "0"], "at": ["0", "1/2"]}, False),
        ("push_up_left_at_1_0", {"force": ["-1", "1"], "at": ["1", "0"]}, False),
        ("push_down_at_3_1", {"force": ["0", "-1"], "at": ["3", "1"]}, False),
    ]:
        scene(f"block_corner_mu_{tag}_{lname}", f"block in a corner, mu = {num(mu)}, load {lname}", cs, load, want, body)

# Leaning square (ladder): balanced under gravity iff mu >= 1/7.
eps = F(1, 10**40)
for mu, tag, want in [(0, "0", False), (F(1, 8), "1_8", False), (F(1, 7), "1_7", True),
                      (F(1, 7) + eps, "1_7_plus_1e-40", True), (F(1, 7) - eps, "1_7_minus_1e-40", False),
                      (F(1, 2), "1_2", True)]:
    label = tag.replace("_plus_", " + ").replace("_minus_", " - ").replace("_", "/")
    body = {"outline": [["0", "0"], ["3", "4"], ["-1", "7"], ["-4", "3"]], "com": ["-1/2", "7/2"]}
    scene(f"ladder_mu_{tag}_gravity", f"leaning square (ladder) under gravity, mu = {label}",
          [contact((0, 0), (0, 1), mu), contact((-4, 3), (1, 0), mu)], {"gravity": "1"}, want, body)

# Pipe clamp (L = 4, h = 1): the jaw locks iff d >= L / (2 mu).
for mu, d, want in [(F(1, 4), 7, False), (F(1, 4), 8, True), (F(1, 4), 9, True),
                    (F(1, 2), 3, False), (F(1, 2), 4, True), (F(1, 2), 5, True)]:
    scene(f"pipe_clamp_mu_{num(mu).replace('/', '_')}_d_{d}", f"pipe clamp, L = 4, h = 1, mu = {num(mu)}, d = {d}",
          [contact((0, F(1, 2)), (0, 1), mu), contact((4, F(-1, 2)), (0, -1), mu)],
          {"force": ["-1", "0"], "at": ["2", num(d)]}, want)

# Degenerate loads: a zero load is balanced by nothing; a pure moment with no contacts is not.
scene("zero_load_no_contacts", "no contacts, zero load", [], {"wrench": ["0", "0", "0"]}, True)
scene("pure_moment_no_contacts", "no contacts, a pure moment", [], {"wrench": ["0", "0", "1"]}, False)


def main():
    for name, title, cs, load, want, body in SCENES:
        got = balanced(cs, load_wrench(load, body))
        if got != want:
            raise SystemExit(f"{name}: stated {want}, brute force {got}")
        s = {"wrenchkit": 1, "name": title}
        if body:
            s["body"] = body
        s["contacts"] = cs
        s["load"] = load
        c = lambda v: json.dumps(v, separators=(", ", ": "), ensure_ascii=False)
        lines = [f"  {c(k)}: {c(v)}" for k, v in s.items() if k != "contacts"]
        lines.insert(len(lines) - 1, '  "contacts": [\n' + ",\n".join("    " + c(x) for x in cs) + "\n  ]"
                     if cs else '  "contacts": []')
        with open(os.path.join(HERE, name + ".scene.json"), "w") as f:
            f.write("{\n" + ",\n".join(lines) + "\n}\n")
        with open(os.path.join(HERE, name + ".expected.json"), "w") as f:
            f.write(json.dumps({"balanced": want, "source": "theory.md §9"}, ensure_ascii=False) + "\n")
    print(f"wrote {len(SCENES)} equilibrium scenes, every verdict confirmed by brute force")


main()
