#!/usr/bin/python3
"""Near-degenerate planar grasp families for the epsilon-quality peer comparison (peers.py).

Every line is a wrenchkit scene (docs/scene-format.md, version 1) whose numbers are exact strings ("3/4",
"0.1", "-3/5"), so wrenchkit reads exactly what the peers are given.  Torque scale and normalisation are not
scene keys (unknown keys are errors): pass them to wrenchkit's quality query and to peers.py --torque-scale.

  a  two fingers on the x-axis at (-1,0), (1,0), each normal at angle theta to the contact line with
     tan(theta) = t rational (Pythagorean, so |n| is rational), mu = t, t + 10^-k, t - 10^-k (k = 1..12).
     mu = t is exactly the friction-cone boundary (eps = 0); mu > t closes, mu < t does not.
     'a-sym': normals (a, b) and (-a, b) (mirror); 'a-anti': (a, b) and (-a, -b) (parallel lines, offset angle).
  b  three fingers on the triangle (1,0), (-3/5,4/5), (-3/5,-4/5) (unit circle):
     b-conc-k:   normals -p_i, exactly concurrent at the origin, mu = 10^-k: eps ~ mu -> 0 (thin hull)
     b-near-k:   normals aimed at three points 10^-k apart (nearly concurrent), mu = 10^-k
     b-frictionless-k: nearly concurrent normals, mu = 0: 3 generators, never closure (qhull: too few points)
  c  flat input: contacts on the x-axis with normals (0, +-1) (all parallel), mu = 0: the generators lie in the
     plane fx = 0 (qhull must throw); c-axial: normals along the line (+-1, 0), generators on one line;
     c-thin-k: the same parallel set with mu = 10^-k (thickness 10^-k).
  d  random 3-6 finger grasps (seed fixed): on the unit circle at rational points ((1-u^2)/(1+u^2), 2u/(1+u^2))
     with inward normals -p (unit, concurrent) or on a rational convex polygon inscribed in it with the edges'
     inward normals; mu from a list of rationals.

  python3 families.py [--seed N] [--random N] > families.jsonl
"""
import argparse
import json
import random
from fractions import Fraction as F


def s(x):
    """Exact string of a rational: 'p' or 'p/q'."""
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else '%d/%d' % (x.numerator, x.denominator)


def contact(at, normal, mu):
    return {'at': [s(at[0]), s(at[1])], 'normal': [s(normal[0]), s(normal[1])], 'mu': s(mu)}


def scene(name, contacts, family, extra=None):
    sc = {'wrenchkit': 1, 'name': name, 'contacts': contacts}
    if extra:
        sc.update(extra)
    return sc


PYTH = [(4, 3), (12, 5), (15, 8), (24, 7), (21, 20), (1, 0)]   # (a, b): tan(theta) = b/a, |n| = c integer


def family_a():
    out = []
    for a, b in PYTH[:5]:
        t = F(b, a)
        for variant, n2 in (('sym', (-a, b)), ('anti', (-a, -b))):
            mus = [('eq', t)]
            for k in range(1, 13):
                e = F(1, 10 ** k)
                mus.append(('plus%d' % k, t + e))
                if t - e >= 0:
                    mus.append(('minus%d' % k, t - e))
            for tag, mu in mus:
                out.append(scene('a-%s t=%s mu=t%s' % (variant, s(t), '' if tag == 'eq' else
                                                          ('+1e-' if tag.startswith('plus') else '-1e-') +
                                                          tag.lstrip('plusminu')),
                                 [contact((-1, 0), (a, b), mu), contact((1, 0), n2, mu)], 'a'))
    return out


TRI = [(F(1), F(0)), (F(-3, 5), F(4, 5)), (F(-3, 5), F(-4, 5))]


def family_b():
    out = []
    for k in range(1, 13):
        e = F(1, 10 ** k)
        out.append(scene('b-conc-%d mu=1e-%d' % (k, k), [contact(p, (-p[0], -p[1]), e) for p in TRI], 'b'))
        aims = [(F(0), F(0)), (e, F(0)), (F(0), e)]
        near = [contact(p, (q[0] - p[0], q[1] - p[1]), e) for p, q in zip(TRI, aims)]
        out.append(scene('b-near-%d delta=1e-%d mu=1e-%d' % (k, k, k), near, 'b'))
        fl = [contact(p, (q[0] - p[0], q[1] - p[1]), 0) for p, q in zip(TRI, aims)]
        out.append(scene('b-frictionless-%d delta=1e-%d mu=0' % (k, k), fl, 'b'))
    return out


def family_c():
    out = []
    xs = [F(-1), F(0), F(1, 2), F(1)]
    for n in (2, 3, 4):
        pts = xs[:n] if n > 2 else [xs[0], xs[3]]
        par = [contact((x, 0), (0, 1 if i % 2 == 0 else -1), 0) for i, x in enumerate(pts)]
        out.append(scene('c-parallel-%d mu=0' % n, par, 'c'))
        ax = [contact((x, 0), (1 if i % 2 == 0 else -1, 0), 0) for i, x in enumerate(pts)]
        out.append(scene('c-axial-%d mu=0' % n, ax, 'c'))
    pts = xs
    for k in range(1, 13):
        e = F(1, 10 ** k)
        par = [contact((x, 0), (0, 1 if i % 2 == 0 else -1), e) for i, x in enumerate(pts)]
        out.append(scene('c-thin-%d mu=1e-%d' % (k, k), par, 'c'))
    return out


def circle_point(u):
    return (F(1) - u * u) / (1 + u * u), 2 * u / (1 + u * u)


MUS = [F(0), F(1, 10), F(1, 5), F(1, 4), F(3, 10), F(1, 3), F(2, 5), F(1, 2), F(3, 5), F(3, 4), F(1)]


def family_d(rng, count):
    out = []
    for i in range(count):
        nf = rng.randint(3, 6)
        mu = rng.choice(MUS)
        if rng.random() < 0.5:
            us = set()
            while len(us) < nf:
                us.add(F(rng.randint(-40, 40), rng.randint(1, 20)))
            cs = []
            for u in sorted(us):
                p = circle_point(u)
                if rng.random() < 0.5:
                    p = (p[0], -p[1])
                cs.append(contact(p, (-p[0], -p[1]), mu))
            out.append(scene('d-circle-%d n=%d mu=%s' % (i, nf, s(mu)), cs, 'd'))
        else:
            m = rng.randint(max(3, nf), 8)          # polygon with m vertices on the circle
            us = set()
            while len(us) < m:
                us.add(F(rng.randint(-60, 60), rng.randint(1, 12)))
            verts = sorted((circle_point(u) for u in us),
                           key=lambda p: _angle_key(p))
            cs = []
            edges = rng.sample(range(m), nf) if nf <= m else [rng.randrange(m) for _ in range(nf)]
            for j in edges:
                a, b = verts[j], verts[(j + 1) % m]
                lam = F(rng.randint(1, 9), 10)
                p = (a[0] + lam * (b[0] - a[0]), a[1] + lam * (b[1] - a[1]))
                # counter-clockwise vertices: the inward normal of edge a->b is rot90(b - a)
                n = (-(b[1] - a[1]), b[0] - a[0])
                g = _scale_int(n)
                cs.append(contact(p, g, mu))
            out.append(scene('d-polygon-%d n=%d m=%d mu=%s' % (i, nf, m, s(mu)), cs, 'd',
                             {'body': {'outline': [[s(v[0]), s(v[1])] for v in verts]}}))
    return out


def _angle_key(p):
    import math
    return math.atan2(float(p[1]), float(p[0]))


def _scale_int(n):
    """A positive multiple of a rational vector with small integer components (direction kept exactly)."""
    from math import gcd
    den = 1
    for c in n:
        den = den * c.denominator // gcd(den, c.denominator)
    v = [int(c * den) for c in n]
    g = gcd(abs(v[0]), abs(v[1])) or 1
    return (F(v[0] // g), F(v[1] // g))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--seed', type=int, default=20250612)
    ap.add_argument('--random', type=int, default=40, help='how many family-d grasps')
    ap.add_argument('--only', default='abcd')
    a = ap.parse_args()
    rng = random.Random(a.seed)
    lines = []
    if 'a' in a.only:
        lines += family_a()
    if 'b' in a.only:
        lines += family_b()
    if 'c' in a.only:
        lines += family_c()
    if 'd' in a.only:
        lines += family_d(rng, a.random)
    for sc in lines:
        print(json.dumps(sc, separators=(',', ':')))


if __name__ == '__main__':
    main()
