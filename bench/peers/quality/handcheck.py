#!/usr/bin/python3
"""Hand check: the square [-1,1]^2 held at the middles of its four sides, inward normals, friction mu, torque
scale s = 1, moments about the centre, unit-normal edges n^ +- mu t^.

The 8 generators are (-1,-mu,-mu), (-1,mu,mu), (1,mu,-mu), (1,-mu,mu), (mu,-1,-mu), (-mu,-1,mu), (-mu,1,-mu),
(mu,1,mu): every moment is +-mu, so the planes m = +mu and m = -mu carry four generators each.
  L1:   eps = mu (the facets m = +-mu; the side facets are ~1/sqrt(2) away)            for mu <= 1
  Linf: facet normal d = (mu(1-mu), mu(1+mu), -(1+mu^2)) (a parallelogram: the segments [0, e] of the contacts
        at (1,0) and (0,1) plus one edge each of the other two), support h(d) = 4mu(1+mu^2), so
        eps^2 = 16 mu^2 (1+mu^2) / (1+3mu^2)                                           for mu <= 1/2
  mu = 0: all moments 0, the generators are flat (m = 0): no closure; qhull throws.
"""
import math
import sys
from fractions import Fraction as F

sys.path.insert(0, __file__.rsplit('/', 1)[0] if '/' in __file__ else '.')
import peers  # noqa: E402


def square(mu):
    return [{'at': (F(1), F(0)), 'normal': (F(-1), F(0)), 'mu': mu},
            {'at': (F(-1), F(0)), 'normal': (F(1), F(0)), 'mu': mu},
            {'at': (F(0), F(1)), 'normal': (F(0), F(-1)), 'mu': mu},
            {'at': (F(0), F(-1)), 'normal': (F(0), F(1)), 'mu': mu}]


def main():
    print('%-6s %-12s %-14s %-14s %-14s | %-12s %-14s %-14s' % ('mu', 'L1 by hand', 'dexnet cvxopt', 'dexnet nnls',
                                                                  'graspit L1', 'Linf by hand', 'graspit Linf',
                                                                  'graspit Linf 8e'))
    for mu in (F(0), F(1, 100), F(1, 10), F(1, 4), F(1, 2)):
        c = square(mu)
        l1 = float(mu)
        li = math.sqrt(16 * mu * mu * (1 + mu * mu) / (1 + 3 * mu * mu))
        e1, s1 = peers.exact_eps_squared(c, 'L1', 1)
        ei, si = peers.exact_eps_squared(c, 'Linf', 1)
        assert (s1 > 0) == (mu > 0) and (mu == 0 or e1 == mu * mu), (mu, e1)
        assert mu == 0 or ei == 16 * mu * mu * (1 + mu * mu) / (1 + 3 * mu * mu), (mu, ei)
        dc = peers.dexnet_ferrari_canny_L1(c, 1.0, qp='cvxopt') if peers.HAVE_CVXOPT else None
        dn = peers.dexnet_ferrari_canny_L1(c, 1.0, qp='nnls')
        g1 = peers.graspit_epsilon(c, 'L1', 1.0)
        gi = peers.graspit_epsilon(c, 'Linf', 1.0)
        gi8 = peers.graspit_epsilon(c, 'Linf', 1.0, edges=8)

        def v(r):
            if r is None:
                return 'n/a'
            return ('%.12g' % r['value']) + (' (threw)' if r['threw'] else '')
        print('%-6s %-12.10g %-14s %-14s %-14s | %-12.10g %-14s %-14s' % (mu, l1, v(dc), v(dn), v(g1), li, v(gi),
                                                                         v(gi8)))
    print('exact (rational brute force) agrees with both hand formulas: eps_L1^2 = mu^2, '
          'eps_Linf^2 = 16mu^2(1+mu^2)/(1+3mu^2)')


if __name__ == '__main__':
    main()
