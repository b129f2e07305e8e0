#!/usr/bin/env python3
"""Writes the golden closure scenes of theory.md §7–9 and §14.3 with their expected verdicts.

Each scene is NAME.scene.json; NAME.expected.json holds the verdicts the theory states. This
script re-derives every verdict with an independent brute force in Python's exact fractions
(force closure <=> rank 3 and no candidate ray +-(g_i x g_j) has power >= 0 against all g) and
refuses to write a file whose stated verdict disagrees. Run it from anywhere:
    python3 tests/golden/make_golden.py
"""
import json
import os
from fractions import Fraction as F
from itertools import combinations

HERE = os.path.dirname(os.path.abspath(__file__))


def num(q):
    q = F(q)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def gens(contacts, frictionless):
    out = []
    for c in contacts:
        if "wrench" in c:
            out.append(tuple(F(x) for x in c["wrench"]))
            continue
        px, py = (F(x) for x in c["at"])
        nx, ny = (F(x) for x in c["normal"])
        mu = F(c.get("mu", 0))
        forces = [(nx, ny)] if frictionless or mu == 0 else \
            [(nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx)]
        out += [(fx, fy, px * fy - py * fx) for fx, fy in forces]
    return out


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def rank(g):
    if any(dot(cross(a, b), c) != 0 for a, b, c in combinations(g, 3)):
        return 3
    if any(cross(a, b) != (0, 0, 0) for a, b in combinations(g, 2)):
        return 2
    return 1 if g else 0


def closure(g):
    if rank(g) < 3:
        return False
    for a, b in combinations(g, 2):
        t = cross(a, b)
        if t == (0, 0, 0):
            continue
        for s in (1, -1):
            if all(s * dot(t, x) >= 0 for x in g):
                return False
    return True


def pt(*xs):
    return [num(x) for x in xs]


def contact(at, normal, mu=None):
    c = {"at": pt(*at), "normal": pt(*normal)}
    if mu is not None:
        c["mu"] = num(mu)
    return c


SCENES = []


def scene(name, title, contacts, force, form, ref, body=None):
    SCENES.append((name, title, contacts, force, form, ref, body))


# theory.md §8.7 / §14.3 items 2–3: Mason's Example 3 analogue.
tri = [[0, 0], [6, 0], [0, 6]]
for mu, tag in [(0, "0"), (F(1, 1000), "1_1000"), (F(1, 10), "1_10"), (F(1, 5), "1_5"), (F(1, 2), "1_2")]:
    scene(f"triangle_example3_mu_{tag}", f"Mason Example 3: triangle made secure by friction (mu = {num(mu)})",
          [contact((1, 0), (0, 1), mu), contact((0, 1), (1, 0), mu), contact((3, 3), (-1, -1), mu)],
          mu > 0, False, "theory.md §8.7", {"outline": tri, "com": [2, 2]})

# §5.5 / §14.3 item 4: the vertical-walls squeeze is NOT force closure (only infinity is labeled).
scene("vertical_walls_squeeze", "square squeezed between vertical walls, frictionless",
      [contact((-1, 1), (1, 0)), contact((-1, -1), (1, 0)), contact((1, 1), (-1, 0)), contact((1, -1), (-1, 0))],
      False, False, "theory.md §5.5", {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]})

# §7 / §14.3 item 8: square [0,2]^2 with four frictionless contacts.
sq = {"outline": [[0, 0], [2, 0], [2, 2], [0, 2]]}
scene("square_crossed_couples", "square, four frictionless contacts forming crossed couples",
      [contact((F(3, 2), 0), (0, 1)), contact((F(1, 2), 2), (0, -1)), contact((0, F(3, 2)), (1, 0)),
       contact((2, F(1, 2)), (-1, 0))], True, True, "theory.md §7", sq)
scene("square_pinwheel", "square, pinwheel contacts: a clockwise rotation escapes",
      [contact((F(1, 2), 0), (0, 1)), contact((F(3, 2), 2), (0, -1)), contact((0, F(3, 2)), (1, 0)),
       contact((2, F(1, 2)), (-1, 0))], False, False, "theory.md §7", sq)
scene("square_aligned", "square, aligned contacts: rank 2",
      [contact((F(1, 2), 0), (0, 1)), contact((F(1, 2), 2), (0, -1)), contact((0, 1), (1, 0)),
       contact((2, 1), (-1, 0))], False, False, "theory.md §7", sq)

# §7 / §14.3 item 9: triangle with four frictionless contacts.
t4 = {"outline": [[0, 0], [4, 0], [0, 4]]}
scene("triangle_four_contacts", "triangle, four frictionless contacts: form closure",
      [contact((1, 0), (0, 1)), contact((3, 0), (0, 1)), contact((0, 2), (1, 0)), contact((2, 2), (-1, -1))],
      True, True, "theory.md §7", t4)
scene("triangle_four_concurrent", "triangle, three normals concurrent at (1,1): only (1,1) is labeled +",
      [contact((1, 0), (0, 1)), contact((3, 0), (0, 1)), contact((0, 1), (1, 0)), contact((2, 2), (-1, -1))],
      False, False, "theory.md §7", t4)

# §8.5 / §14.3 item 5: two-finger grasps of the unit square (Nguyen).
for y2, mu, fc in [(F(1, 2), F(1, 10), True), (F(9, 10), F(1, 4), False), (F(9, 10), F(1, 2), True),
                   (1, F(1, 2), False)]:
    scene(f"two_finger_y{num(y2).replace('/', '_')}_mu{num(mu).replace('/', '_')}",
          f"two fingers on the unit square, y2 = {num(y2)}, mu = {num(mu)}",
          [contact((0, F(1, 2)), (1, 0), mu), contact((1, y2), (-1, 0), mu)], fc, False, "theory.md §8.5",
          {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]})

# §9 / §14.3 item 7: block in a corner, leaning square (ladder).
corner = {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]], "com": [F(1, 2), F(1, 2)]}
for mu, tag in [(0, "0"), (F(1, 2), "1_2")]:
    scene(f"block_corner_mu_{tag}", f"block in a corner, mu = {num(mu)}",
          [contact((0, 0), (0, 1), mu), contact((1, 0), (0, 1), mu), contact((0, 0), (1, 0), mu),
           contact((0, 1), (1, 0), mu)], False, False, "theory.md §9", corner)
ladder = {"outline": [[0, 0], [3, 4], [-1, 7], [-4, 3]], "com": [F(-1, 2), F(7, 2)]}
for mu, tag in [(0, "0"), (F(1, 8), "1_8"), (F(1, 7), "1_7")]:
    scene(f"ladder_mu_{tag}", f"leaning square (ladder), mu = {num(mu)}",
          [contact((0, 0), (0, 1), mu), contact((-4, 3), (1, 0), mu)], False, False, "theory.md §9", ladder)
# The ladder's two contacts are a two-finger grasp: force closure iff mu > 4/3 (Nguyen, §8.5):
# p2 - p1 = (-4, 3) must be strictly inside both friction cones. Thresholds exactly and +-1e-40.
eps = F(1, 10**40)
for mu, tag, fc in [(F(4, 3), "at", False), (F(4, 3) + eps, "above_1e-40", True), (F(4, 3) - eps, "below_1e-40", False)]:
    scene(f"ladder_threshold_{tag}", f"ladder contacts as a two-finger grasp, mu = 4/3 {tag}",
          [contact((0, 0), (0, 1), mu), contact((-4, 3), (1, 0), mu)], fc, False, "theory.md §8.5, §9", ladder)

# §9 / §14.3 item 6: pipe clamp contacts (never force closure by themselves).
scene("pipe_clamp_L4_h1_mu_1_4", "pipe clamp jaw, L = 4, h = 1, mu = 1/4",
      [contact((0, F(1, 2)), (0, 1), F(1, 4)), contact((4, F(-1, 2)), (0, -1), F(1, 4))], False, False,
      "theory.md §9", None)

# §5.6 degenerate fixtures.
scene("no_contacts", "no contacts at all: W = {0}", [], False, False, "theory.md §5.6", None)
scene("single_force", "a single frictionless contact at the origin", [contact((0, 0), (1, 0))], False, False,
      "theory.md §14.3 item 1", None)
scene("opposite_forces_one_line", "two opposite forces on one line: rank 1",
      [contact((0, 0), (1, 0)), contact((3, 0), (-1, 0))], False, False, "theory.md §5.6", None)
scene("parallel_same_sense", "parallel forces, same sense",
      [contact((0, 0), (0, 1)), contact((1, 0), (0, 1)), contact((5, 0), (0, 2))], False, False, "theory.md §5.6", None)
scene("concurrent_spanning", "lines concurrent at (1,1), directions spanning the plane: rank 2",
      [contact((1, 0), (0, 1)), contact((0, 1), (1, 0)), contact((2, 2), (-1, -1)), contact((3, 1), (-1, 0))],
      False, False, "theory.md §5.6", None)
scene("pure_moments_and_forces", "wrench generators: forces both ways along x and y, moments both ways",
      [{"wrench": ["1", "0", "0"]}, {"wrench": ["-1", "0", "0"]}, {"wrench": ["0", "1", "0"]},
       {"wrench": ["0", "-1", "0"]}, {"wrench": ["0", "0", "1"]}, {"wrench": ["0", "0", "-1"]}],
      True, True, "theory.md §5.6", None)
scene("pure_moments_missing_down", "as pure_moments_and_forces without the downward force",
      [{"wrench": ["1", "0", "0"]}, {"wrench": ["-1", "0", "0"]}, {"wrench": ["0", "1", "0"]},
       {"wrench": ["0", "0", "1"]}, {"wrench": ["0", "0", "-1"]}], False, False, "theory.md §5.6", None)

# Scale: the two-finger grasp (y2 = 1/2, mu = 1/10) at 10^18 and 10^-20, and rotated by a rational
# rotation whose cosine and sine have 40-digit numerators and denominators.
def two_finger(scale, rot=(1, 0), shift=(0, 0)):
    c, s = rot
    R = lambda v: (c * v[0] - s * v[1], s * v[0] + c * v[1])
    P = lambda v: (R(v)[0] * scale + shift[0], R(v)[1] * scale + shift[1])
    return [contact(P((0, F(1, 2))), R((1, 0)), F(1, 10)), contact(P((1, F(1, 2))), R((-1, 0)), F(1, 10))]
scene("two_finger_scale_1e18", "two-finger grasp at scale 10^18", two_finger(10**18), True, False, "scale", None)
scene("two_finger_scale_1e-20", "two-finger grasp at scale 10^-20", two_finger(F(1, 10**20)), True, False, "scale", None)
a, b = 12345678901234567891, 98765432109876543211  # a Pythagorean rotation with 40-digit entries
rot = (F(a * a - b * b, a * a + b * b), F(2 * a * b, a * a + b * b))
scene("two_finger_rotated_40_digits", "two-finger grasp rotated by a 40-digit rational rotation, shifted",
      two_finger(1, rot, (F(10**39 + 7, 3), F(-(10**38) - 1, 7))), True, False, "scale", None)
# Near the edge of the friction cone: the segment between the fingers is on the cone edge for
# mu = 1/2 at y2 = 1; 10^-40 less steep is inside, 10^-40 steeper is outside.
for y2, tag, fc in [(1 - eps, "inside_1e-40", True), (1 + eps, "outside_1e-40", False)]:
    scene(f"two_finger_cone_edge_{tag}", f"two fingers, segment 10^-40 {tag.split('_')[0]} the friction cone edge",
          [contact((0, F(1, 2)), (1, 0), F(1, 2)), contact((1, y2), (-1, 0), F(1, 2))], fc, False, "theory.md §8.5",
          None)


def dump_scene(s):
    """One key per line, one contact per line: easy to read and to diff."""
    c = lambda v: json.dumps(v, separators=(", ", ": "), ensure_ascii=False)
    lines = []
    for k, v in s.items():
        if k == "contacts" and v:
            lines.append('  "contacts": [\n' + ",\n".join("    " + c(x) for x in v) + "\n  ]")
        else:
            lines.append(f"  {c(k)}: {c(v)}")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def main():
    written = 0
    for name, title, contacts, force, form, ref, body in SCENES:
        got_force = closure(gens(contacts, False))
        got_form = closure(gens(contacts, True))
        if (got_force, got_form) != (force, form):
            raise SystemExit(f"{name}: stated ({force}, {form}) but brute force says ({got_force}, {got_form})")
        s = {"wrenchkit": 1, "name": title}
        if body:
            s["body"] = {k: [pt(*p) for p in v] if k == "outline" else pt(*v) for k, v in body.items()}
        s["contacts"] = contacts
        with open(os.path.join(HERE, name + ".scene.json"), "w") as f:
            f.write(dump_scene(s))
        with open(os.path.join(HERE, name + ".expected.json"), "w") as f:
            json.dump({"force_closure": force, "form_closure": form,
                       "rank": {"force": rank(gens(contacts, False)), "form": rank(gens(contacts, True))},
                       "source": ref}, f, indent=2)
            f.write("\n")
        written += 1
    print(f"wrote {written} golden scenes, every verdict confirmed by brute force")


main()
