#!/usr/bin/python3
"""Faithful planar ports of two peers' Ferrari-Canny grasp quality (epsilon).

  * Dex-Net   PointGraspMetrics3D.ferrari_canny_L1   (src/dexnet/grasping/quality.py)
  * GraspIt!  QualEpsilon over an L1 ("sum") or L-inf ("max") GWS   (src/gws.cpp, src/quality/qualEpsilon.cpp)

See CONVENTIONS.md beside this file for the peer code each step reproduces (repository, path, commit, quotes).

Planar: the wrench space is 3-D, (fx, fy, s*m) with m = (p - about) x f = rx*fy - ry*fx and s the torque scale.
A planar friction cone has exactly two edges, n^ + mu t^ and n^ - mu t^ with n^ the unit inward normal and
t^ = rot90(n^) = (-n^y, n^x): the peers' "unit-normal" convention (normal component 1).  'unit-force'
((n^ +- mu t^)/sqrt(1+mu^2)) and 'as-given' (n +- mu rot90(n), n not normalised) are offered for comparison with
wrenchkit's --normalize modes; neither peer uses them.

Only NumPy, SciPy (ConvexHull = qhull, nnls) and, when it is importable, cvxopt (Debian: python3-cvxopt) are used.

  python3 peers.py FILE.jsonl [--torque-scale S] [--qp auto|cvxopt|nnls] [--min-time SEC] [--no-time] [--exact]
"""
import argparse
import itertools
import json
import math
import sys
import time
import warnings
from fractions import Fraction

import numpy as np
from scipy.optimize import nnls
from scipy.spatial import ConvexHull

try:  # SciPy >= 1.11 exports QhullError from scipy.spatial; 1.10 has it in scipy.spatial._qhull
    from scipy.spatial import QhullError
except ImportError:  # pragma: no cover
    from scipy.spatial._qhull import QhullError

try:
    import cvxopt as cvx
    cvx.solvers.options['show_progress'] = False   # quality.py line 55: the only option Dex-Net sets
    HAVE_CVXOPT = True
except ImportError:  # pragma: no cover
    cvx = None
    HAVE_CVXOPT = False

# Dex-Net defaults (quality.py ferrari_canny_L1 signature; test/config.yaml robust_ferrari_canny uses the same)
DEXNET_WRENCH_NORM_THRESH = 1e-3
DEXNET_WRENCH_REGULARIZER = 1e-10
DEXNET_SUPPORT_THRESH = 1e-4          # "np.sum(v > 1e-4) <= G.shape[0]-1"
# Dex-Net's hull: pyhull.convex_hull.ConvexHull(G.T) runs "qconvex i Qt"; scipy's ConvexHull(points) with no
# options runs "qhull i Qt" (dim <= 4): the same qhull flags.
DEXNET_QHULL_OPTIONS = None
# GraspIt!: gws.cpp buildHyperplanesFromWrenches: sprintf(options, "qhull Pp n Qx QJ C-0.0001");
# 'n' is an output format (normals), meaningless for scipy, which adds 'i' and the required 'Qt'.
GRASPIT_QHULL_OPTIONS = "Pp Qx QJ C-0.0001"


# ----------------------------------------------------------------------------------------------------------------
# input
# ----------------------------------------------------------------------------------------------------------------

def parse_number(x):
    """Exact value of a wrenchkit number: a JSON number (given as its text) or a string 'decimal' or 'p/q'."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, int):
        return Fraction(x)
    if isinstance(x, float):
        return Fraction(repr(x))
    s = str(x).strip()
    if '/' in s:
        p, q = s.split('/')
        return Fraction(int(p), int(q))
    return Fraction(s)   # Fraction parses decimals with exponents exactly ("0.1" -> 1/10, "1e-12")


def scene_contacts(scene):
    """Point contacts of a wrenchkit scene as a list of dicts with exact Fractions; plus `about` (body.com or 0)."""
    mu0 = parse_number(scene['mu']) if 'mu' in scene else Fraction(0)
    out = []
    for c in scene.get('contacts', []):
        if 'wrench' in c:
            raise ValueError('wrench generators are not point contacts: the peers have no such thing')
        out.append({'at': tuple(parse_number(v) for v in c['at']),
                    'normal': tuple(parse_number(v) for v in c['normal']),
                    'mu': parse_number(c['mu']) if 'mu' in c else mu0})
    body = scene.get('body', {})
    about = tuple(parse_number(v) for v in body['com']) if 'com' in body else (Fraction(0), Fraction(0))
    return out, about


def _f(x):
    return float(x)


def contact_edges(contact, normalize='unit-normal', approach=None):
    """The two planar cone edges (forces) of one contact, floats, in Dex-Net's order j = 0 (+t) then the mirror.

    Returns (edges [2x2], ok).  `approach` (Dex-Net's in_direction, optional) scales the edges by
    normal_force_magnitude() = max(<d^, n^>, 0) and fails the cone ("Contact would slip") when the tangential part
    of d^ exceeds mu * that magnitude, as contacts.py friction_cone() does.
    """
    nx, ny = (_f(v) for v in contact['normal'])
    mu = _f(contact['mu'])
    nn = math.hypot(nx, ny)
    if normalize == 'as-given':
        n = np.array([nx, ny])
    else:
        n = np.array([nx, ny]) / nn           # contacts.py tangents(): direction = -normal_ (unit, from the SDF)
    t = np.array([-n[1], n[0]])               # rot90(n)
    E = np.array([n + mu * t, n - mu * t])    # cone_support[:, j] = force + friction_coef * tan_vec
    if normalize == 'unit-force':
        E = E / math.sqrt(1.0 + mu * mu)
    ok = True
    if approach is not None:
        d = np.asarray([_f(v) for v in approach], dtype=float)
        d = d / np.linalg.norm(d)
        nhat = np.array([nx, ny]) / nn
        mag = max(float(d @ nhat), 0.0)        # normal_force_magnitude()
        tan = abs(float(d @ np.array([-nhat[1], nhat[0]])))
        if mu * mag < tan:                     # "if friction_force_mag < tan_force_mag: ... Contact would slip"
            ok = False
        E = mag * E                            # forces = np.c_[forces, n * contact_forces]
    return E, ok


def wrench_matrix(contacts, torque_scale=1.0, about=(0.0, 0.0), normalize='unit-normal', approaches=None):
    """3 x 2N matrix of generator wrenches (fx, fy, s*m), contact by contact, and the per-contact ok flags."""
    cols, oks = [], []
    ax, ay = _f(about[0]), _f(about[1])
    for i, c in enumerate(contacts):
        E, ok = contact_edges(c, normalize, None if approaches is None else approaches[i])
        oks.append(ok)
        rx, ry = _f(c['at'][0]) - ax, _f(c['at'][1]) - ay      # moment arm: x - center_of_mass
        for fx, fy in E:
            # Dex-Net: torque = np.cross(moment_arm, force); G[3:, i] = torque_scaling * torque
            cols.append((fx, fy, torque_scale * (rx * fy - ry * fx)))
    return np.array(cols, dtype=float).T.reshape(3, -1), oks


# ----------------------------------------------------------------------------------------------------------------
# Dex-Net
# ----------------------------------------------------------------------------------------------------------------

def _min_norm_cvxopt(facet, wrench_regularizer):
    """quality.py min_norm_vector_in_facet, line for line (cvxopt.solvers.qp)."""
    dim = facet.shape[1]
    G = facet.T.dot(facet)
    grasp_matrix = G + wrench_regularizer * np.eye(G.shape[0])
    P = cvx.matrix(2 * grasp_matrix)
    q = cvx.matrix(np.zeros((dim, 1)))
    G = cvx.matrix(-np.eye(dim))
    h = cvx.matrix(np.zeros((dim, 1)))
    A = cvx.matrix(np.ones((1, dim)))
    b = cvx.matrix(np.ones(1))
    sol = cvx.solvers.qp(P, q, G, h, A, b)
    v = np.array(sol['x'])
    with np.errstate(invalid='ignore'):
        min_norm = np.sqrt(sol['primal objective'])   # NaN when the objective came out < 0: kept, as in Dex-Net
    return abs(min_norm), v


def _min_norm_nnls(facet, wrench_regularizer):
    """The same QP, min x'(F'F + r I)x over the simplex, solved to machine precision instead of to cvxopt's
    interior-point tolerances.  min ||Fx||^2 + r||x||^2, x >= 0, 1'x = 1, equals (Wolfe) the min-norm point of the
    lifted points [F; sqrt(r) I]; with y = argmin_{y >= 0} ||[F; sqrt(r) I; 1'] y - e_last||^2 (Lawson-Hanson
    NNLS), x = y / 1'y.  The objective r||x||^2 > 0 makes the QP strictly convex: x is unique (the min-2-norm
    convex combination when the origin is inside), so the support count v > 1e-4 is well defined.
    """
    m = facet.shape[1]
    A = np.vstack([facet, math.sqrt(wrench_regularizer) * np.eye(m), np.ones((1, m))])
    b = np.zeros(A.shape[0])
    b[-1] = 1.0
    y, _ = nnls(A, b, maxiter=50 * m)
    x = y / y.sum()
    obj = float(x @ (facet.T @ facet) @ x + wrench_regularizer * (x @ x))   # = sol['primal objective']
    return abs(math.sqrt(max(obj, 0.0))), x.reshape(-1, 1)


def min_norm_vector_in_facet(facet, wrench_regularizer=DEXNET_WRENCH_REGULARIZER, qp='auto'):
    if qp == 'auto':
        qp = 'cvxopt' if HAVE_CVXOPT else 'nnls'
    if qp == 'cvxopt':
        return _min_norm_cvxopt(facet, wrench_regularizer)
    return _min_norm_nnls(facet, wrench_regularizer)


def dexnet_ferrari_canny_L1(contacts, torque_scaling=1.0, about=(0.0, 0.0), *,
                            wrench_norm_thresh=DEXNET_WRENCH_NORM_THRESH,
                            wrench_regularizer=DEXNET_WRENCH_REGULARIZER,
                            qp='auto', normalize='unit-normal', approaches=None, all_contacts_required=True):
    """Dex-Net's ferrari_canny_L1 on the planar grasp matrix G (3 x 2N).  Returns a dict:
       value     what Dex-Net returns (0.0 for every 'not in closure' decision)
       decision  'ok' | 'qhull-error' | 'zero-not-in-hull' | 'zero-on-boundary' | 'contact-would-slip'
       threw     qhull raised (Dex-Net's pyhull swallows it: empty output, 'Convex hull could not be computed', 0.0)
       min_norm_in_hull, support (# v > 1e-4), facets, qp
    """
    if qp == 'auto':
        qp = 'cvxopt' if HAVE_CVXOPT else 'nnls'
    G, oks = wrench_matrix(contacts, torque_scaling, about, normalize, approaches)
    res = {'value': 0.0, 'decision': None, 'threw': False, 'qhull_message': None, 'min_norm_in_hull': None,
           'support': None, 'facets': 0, 'qp': qp}
    if approaches is not None and not all(oks) and all_contacts_required:
        res['decision'] = 'contact-would-slip'       # grasp_quality(): force_success False -> return 0
        return res
    # hull = cvh.ConvexHull(G.T); if len(hull.vertices) == 0: return 0.0
    try:
        hull = ConvexHull(G.T, qhull_options=DEXNET_QHULL_OPTIONS)
    except (QhullError, ValueError) as e:   # ValueError: fewer than 4 points / wrong shape, qhull never runs
        res.update(decision='qhull-error', threw=True, qhull_message=str(e).split('\n')[0])
        return res
    res['facets'] = int(len(hull.simplices))
    # min_norm_in_hull, v = min_norm_vector_in_facet(G, ...)
    min_norm_in_hull, v = min_norm_vector_in_facet(G, wrench_regularizer, qp)
    res['min_norm_in_hull'] = float(min_norm_in_hull)
    support = int(np.sum(v > 1e-4))
    res['support'] = support
    if min_norm_in_hull > wrench_norm_thresh:
        res['decision'] = 'zero-not-in-hull'
        return res
    if np.sum(v > 1e-4) <= G.shape[0] - 1:
        res['decision'] = 'zero-on-boundary'
        return res
    min_dist = sys.float_info.max
    for vv in hull.simplices:
        if np.max(np.array(vv)) < G.shape[1]:
            facet = G[:, vv]
            dist, _ = min_norm_vector_in_facet(facet, wrench_regularizer, qp)
            if dist < min_dist:
                min_dist = dist
    res['value'] = float(min_dist)
    res['decision'] = 'ok'
    return res


# ----------------------------------------------------------------------------------------------------------------
# GraspIt!
# ----------------------------------------------------------------------------------------------------------------

def graspit_max_radius(outline, com):
    """DynamicBody::computeDefaultMaxRadius(): max |CoG - vertex| over the body's vertices (here: the outline)."""
    return max(math.hypot(_f(x) - _f(com[0]), _f(y) - _f(com[1])) for x, y in outline)


def graspit_wrenches(contacts, mode, torque_scale, about, normalize='unit-normal', edges=2):
    """Generators of GraspIt!'s L1 GWS (the union of the contact wrenches) or L-inf GWS (minkowskiSum(): for every
    contact either no contribution or one of its edges; (edges+1)^N points, the origin among them)."""
    W, _ = wrench_matrix(contacts, torque_scale, about, normalize)
    per = [W[:, 2 * i:2 * i + 2].T for i in range(len(contacts))]
    if edges == 8:
        # PointContact: 8 edges n^ + mu (cos th tX + sin th tY); for an in-plane normal tX = +-z (normal x (1,0,0)),
        # so the projection to (fx, fy, tz) is n^ + mu sin(th) t^: th = 0, 45, ..., 315 deg.
        per8 = []
        for i in range(len(contacts)):
            e_plus, e_minus = per[i]
            mid = 0.5 * (e_plus + e_minus)
            half = 0.5 * (e_plus - e_minus)
            per8.append(np.array([mid + math.sin(2 * math.pi * j / 8) * half for j in range(8)]))
        per = per8
    if mode == 'L1':
        return np.vstack(per)
    pts = []
    for choice in itertools.product(*[[None] + list(range(len(p))) for p in per]):
        w = np.zeros(3)
        for i, j in enumerate(choice):
            if j is not None:
                w = w + per[i][j]
        pts.append(w)
    return np.array(pts)


def graspit_epsilon(contacts, mode='L1', torque_scale=1.0, about=(0.0, 0.0), *, normalize='unit-normal', edges=2,
                    qhull_options=GRASPIT_QHULL_OPTIONS):
    """QualEpsilon::evaluate() on the planar GWS (useDimensions 1,1,0,0,0,1: fx, fy, tz).  Returns a dict:
       value        what GraspIt! returns: min over facets of -offset, or -1.0 when a facet has -offset < 0
                    ("not a force-closure grasp") or when qhull failed (hyperPlanes NULL)
       threw        qhull failed (setjmp errexit -> FAILURE -> clearGWS)
       min_offset   min over facets of -offset (signed; what GraspIt! would report without the -1 rule)
       force_closure  computeHyperplaneMetrics(): no facet with offset > 0
    GraspIt!'s torque scale is 1/maxRadius of the object (contact.cpp: torque / object->getMaxRadius()).
    """
    P = graspit_wrenches(contacts, mode, torque_scale, about, normalize, edges)
    res = {'value': -1.0, 'threw': False, 'qhull_message': None, 'min_offset': None, 'facets': 0,
           'force_closure': False, 'points': int(P.shape[0])}
    try:
        hull = ConvexHull(P, qhull_options=qhull_options)
    except (QhullError, ValueError) as e:
        res.update(threw=True, qhull_message=str(e).split('\n')[0])
        return res
    off = hull.equations[:, -1]           # facet->offset; equations rows: unit normal, offset (n.x + offset = 0)
    res['facets'] = int(len(off))
    res['min_offset'] = float(np.min(-off))
    res['force_closure'] = bool(np.all(off <= 0))
    # for (i...) if (i == 0 || -(h[i][6]) < minOffset) { minOffset = -(h[i][6]); if (minOffset < 0) return -1.0; }
    min_offset = None
    for i, h6 in enumerate(off):
        if i == 0 or -h6 < min_offset:
            min_offset = -h6
            if min_offset < 0:
                return res
    res['value'] = float(min_offset)
    return res


# ----------------------------------------------------------------------------------------------------------------
# exact reference (not a peer): eps^2 of the unit-normal GWS in rational arithmetic, by brute force
# ----------------------------------------------------------------------------------------------------------------

def _exact_edges(contacts, torque_scale, about, normalize):
    """Rational generators per contact, or None when a normal's length is irrational (unit-normal/unit-force)."""
    s = Fraction(torque_scale)
    out = []
    for c in contacts:
        nx, ny = c['normal']
        mu = c['mu']
        q = nx * nx + ny * ny
        if normalize == 'as-given':
            k = Fraction(1)
        else:
            if normalize == 'unit-force':
                q = q * (1 + mu * mu)
            r = _rational_sqrt(q)
            if r is None:
                return None
            k = 1 / r
        rx, ry = c['at'][0] - about[0], c['at'][1] - about[1]
        gens = []
        for sg in (1, -1):
            fx = k * (nx - sg * mu * ny)
            fy = k * (ny + sg * mu * nx)
            gens.append((fx, fy, s * (rx * fy - ry * fx)))
        out.append(gens)
    return out


def _rational_sqrt(q):
    a, b = q.numerator, q.denominator
    ra, rb = math.isqrt(a), math.isqrt(b)
    if ra * ra == a and rb * rb == b:
        return Fraction(ra, rb)
    return None


def _cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _sub(u, v):
    return (u[0] - v[0], u[1] - v[1], u[2] - v[2])


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def exact_eps_squared(contacts, mode='L1', torque_scale=1, about=(0, 0), normalize='unit-normal'):
    """Exact signed eps^2 (Fraction) of the GWS about the origin: min over all directions d of h(d)/|d|, taken
    over a superset of the facet normals (L1: normals of every triple of generators; L-inf: each contact's
    triangle conv{0, e+, e-} normal and the cross products of two contacts' triangle edges).  Returns
    (eps2, sign): sign < 0 when the origin is outside (eps2 is then the squared distance of that separating
    witness, not meaningful), 0 on the boundary / flat hull.  None when the generators are not rational.
    """
    about = tuple(Fraction(a) for a in about)
    per = _exact_edges(contacts, Fraction(torque_scale), about, normalize)
    if per is None:
        return None
    gens = [g for p in per for g in p]
    if mode == 'L1':
        def h(d):
            return max(_dot(g, d) for g in gens)
        cands = []
        for a, b, c in itertools.combinations(gens, 3):
            d = _cross(_sub(b, a), _sub(c, a))
            if d != (0, 0, 0):
                cands.append(d)
    else:
        def h(d):
            return sum(max(0, max(_dot(g, d) for g in p)) for p in per)
        tri_edges = []
        cands = []
        for p in per:
            e1, e2 = p
            es = [e1, e2, _sub(e1, e2)]
            tri_edges.append(es)
            d = _cross(e1, e2)
            if d != (0, 0, 0):
                cands.append(d)
        for i, j in itertools.combinations(range(len(per)), 2):
            for u in tri_edges[i]:
                for v in tri_edges[j]:
                    d = _cross(u, v)
                    if d != (0, 0, 0):
                        cands.append(d)
        for e in (g for p in per for g in p):   # a contact with a single edge direction (mu = 0): segments
            for ax in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
                d = _cross(e, ax)
                if d != (0, 0, 0):
                    cands.append(d)
    if not cands:
        return (Fraction(0), 0)
    best = None
    for d0 in cands:
        for d in (d0, (-d0[0], -d0[1], -d0[2])):
            hv = h(d)
            key = (1 if hv > 0 else (0 if hv == 0 else -1), hv * hv / _dot(d, d))
            # order: any negative support beats zero beats positive; among positives the smallest ratio
            if best is None or _better(key, best):
                best = key
    sign, val = best
    return (val if sign > 0 else (Fraction(0) if sign == 0 else val), sign)


def _better(a, b):
    if a[0] != b[0]:
        return a[0] < b[0]
    if a[0] > 0:
        return a[1] < b[1]
    if a[0] < 0:
        return a[1] > b[1]
    return False


# ----------------------------------------------------------------------------------------------------------------
# CLI
# ----------------------------------------------------------------------------------------------------------------

def time_per_call(fn, min_time=0.05, batches=5):
    """µs per call: calibrate a batch of >= min_time/batches seconds, best (min) and median over `batches`."""
    n = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        dt = time.perf_counter() - t0
        if dt >= min_time / batches or n >= 1 << 20:
            break
        n = n * 2 if dt <= 0 else max(n * 2, int(n * (min_time / batches) / dt * 1.2) + 1)
    ts = []
    for _ in range(batches):
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        ts.append((time.perf_counter() - t0) / n * 1e6)
    ts.sort()
    return {'min_us': round(ts[0], 2), 'median_us': round(ts[len(ts) // 2], 2), 'reps': n * batches}


def evaluate_scene(scene, torque_scale=1.0, qp='auto', min_time=0.05, do_time=True, exact=False,
                   normalize='unit-normal', edges=2):
    contacts, about = scene_contacts(scene)
    out = {'name': scene.get('name'), 'contacts': len(contacts)}
    runs = {
        'dexnet_L1': lambda: dexnet_ferrari_canny_L1(contacts, torque_scale, about, qp=qp, normalize=normalize),
        'graspit_L1': lambda: graspit_epsilon(contacts, 'L1', torque_scale, about, normalize=normalize, edges=edges),
        'graspit_Linf': lambda: graspit_epsilon(contacts, 'Linf', torque_scale, about, normalize=normalize,
                                                edges=edges),
    }
    for key, fn in runs.items():
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')
            r = fn()
            if do_time:
                r['time'] = time_per_call(fn, min_time)
        out[key] = r
    if exact:
        for m in ('L1', 'Linf'):
            e = exact_eps_squared(contacts, m, Fraction(torque_scale).limit_denominator(10**12), about, normalize)
            if e is None:
                out['exact_' + m] = None
            else:
                e2, sign = e
                out['exact_' + m] = {'eps2': str(e2) if sign > 0 else '0',
                                     'eps': math.sqrt(e2) if sign > 0 else 0.0,
                                     'closure': sign > 0}
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('file', help='JSON lines, one wrenchkit scene per line ("-" for stdin)')
    ap.add_argument('--torque-scale', type=float, default=1.0,
                    help='s in (fx, fy, s*m) for every peer (Dex-Net torque_scaling; GraspIt! 1/maxRadius)')
    ap.add_argument('--qp', choices=['auto', 'cvxopt', 'nnls'], default='auto',
                    help="Dex-Net's QP: cvxopt (Dex-Net's own solver) or the same QP to machine precision (nnls)")
    ap.add_argument('--normalize', choices=['unit-normal', 'unit-force', 'as-given'], default='unit-normal')
    ap.add_argument('--graspit-edges', type=int, choices=[2, 8], default=2,
                    help="8: GraspIt!'s 8-edge PointContact cone projected to the plane (same hull, more points)")
    ap.add_argument('--min-time', type=float, default=0.05, help='seconds of repetitions per peer per grasp')
    ap.add_argument('--no-time', action='store_true')
    ap.add_argument('--exact', action='store_true', help='add the exact (rational) eps of L1 and L-inf when possible')
    a = ap.parse_args(argv)
    fh = sys.stdin if a.file == '-' else open(a.file)
    for line in fh:
        line = line.strip()
        if not line:
            continue
        scene = json.loads(line, parse_float=str, parse_int=str)   # keep the numbers' text: exact
        out = evaluate_scene(scene, a.torque_scale, a.qp, a.min_time, not a.no_time, a.exact, a.normalize,
                             a.graspit_edges)
        print(json.dumps(out), flush=True)


if __name__ == '__main__':
    main()
