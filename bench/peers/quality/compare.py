#!/usr/bin/python3
"""The peers' epsilon (peers.py) against wrenchkit's exact answer (`wrenchkit batch quality`), per family.

Both sides use the same wrench space: unit-normal edges n^ +- mu rot90(n^), moments about the origin (the scenes
have no body.com; peers.py takes body.com else the origin, and the script refuses a scene with a body.com),
torque scale 1.  wrenchkit runs as

  wrenchkit batch quality --only epsilon --norm L1|Linf --normalize unit-normal --about 0,0 --torque-scale 1 --jobs 1

and its [lower, upper] (exact rationals; `squared` = eps^2 when rational) is the reference.  Dex-Net's
ferrari_canny_L1 and GraspIt!'s L1 QualEpsilon are compared with wrenchkit's L1 eps, GraspIt!'s L-inf one with
its Linf eps.  Per peer and family: threw (qhull raised), false+ (peer > 0 where eps = 0), false- (peer <= 0,
or NaN, where eps > 0), the relative error |peer - eps| / eps for grasps both call closed (against the nearest
end of the bracket, 0 inside it), and the wrenchkit eps of every wrong answer (its distance to eps = 0).

Checks (printed loudly, exit 1): wrenchkit's eps^2 equals peers.py's brute-force rational reference (--exact)
wherever that exists, the bracket holds sqrt(eps^2), force_closure agrees with eps > 0, and the answer states
the conventions asked for.

Time: wrenchkit = the batch's wall time / number of grasps (--jobs 1; the whole file, and per family with its
lines repeated up to >= --min-lines so that start-up is amortised), median of --repeat runs; the peers =
peers.py's time_per_call (median of 5 batches per grasp), averaged over the family's grasps.

  /usr/bin/python3 compare.py [--wrenchkit PATH] [--families families.jsonl] [--qp auto|cvxopt|nnls]
                              [--min-time 0.03] [--no-time] [--details wrong-answers.md] [--limit N]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time
import warnings
from collections import OrderedDict
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True   # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import peers  # noqa: E402

DEFAULT_CLI = os.path.normpath(os.path.join(HERE, '..', '..', '..', 'build', 'wrenchkit'))
FAMILIES = ('a-sym', 'a-anti', 'b-conc', 'b-near', 'b-frictionless', 'c-parallel', 'c-axial', 'c-thin',
            'd-circle', 'd-polygon', 'square')
# (key in peers.py output, label, wrenchkit norm it is compared with)
PEERS = (('dexnet_L1', 'Dex-Net L1', 'L1'), ('graspit_L1', 'GraspIt! L1', 'L1'),
         ('graspit_Linf', 'GraspIt! L∞', 'Linf'))
WK_OPTIONS = ['--only', 'epsilon', '--normalize', 'unit-normal', '--about', '0,0', '--torque-scale', '1']


def family(name):
    for p in FAMILIES:
        if name.startswith(p):
            return p
    return 'other'


def load_scenes(path, limit=None):
    """[(text line, scene dict with the numbers' text kept)]; refuses body.com (the conventions would differ)."""
    out = []
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line:
                continue
            sc = json.loads(line, parse_float=str, parse_int=str)
            if 'com' in sc.get('body', {}):
                raise SystemExit('compare.py: %r has a body.com; this comparison takes moments about the origin'
                                 % sc.get('name'))
            out.append((line, sc))
            if limit is not None and len(out) >= limit:
                break
    return out


# ----------------------------------------------------------------------------------------------------------------
# wrenchkit
# ----------------------------------------------------------------------------------------------------------------

def run_wrenchkit(cli, lines, norm, jobs=1):
    """`wrenchkit batch quality` on the lines: (answers in order, wall seconds)."""
    cmd = [cli, 'batch', 'quality', '--norm', norm, '--jobs', str(jobs)] + WK_OPTIONS
    data = ('\n'.join(lines) + '\n').encode()
    t0 = time.perf_counter()
    p = subprocess.run(cmd, input=data, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise SystemExit('compare.py: %s exited %d: %s' % (' '.join(cmd), p.returncode, p.stderr.decode()[:2000]))
    ans = [json.loads(l) for l in p.stdout.decode().splitlines() if l.strip()]
    if len(ans) != len(lines) or [a.get('line') for a in ans] != list(range(1, len(lines) + 1)):
        raise SystemExit('compare.py: wrenchkit answered %d lines for %d scenes' % (len(ans), len(lines)))
    return ans, wall


def time_wrenchkit(cli, lines, norm, repeat=3, min_lines=0):
    """Seconds per grasp: the batch's wall time / number of lines (--jobs 1), median of `repeat` runs; the lines
    are repeated (whole copies) until there are at least min_lines of them, so that start-up is amortised."""
    reps = max(1, -(-min_lines // max(1, len(lines)))) if min_lines else 1
    ls = list(lines) * reps
    ts = sorted(run_wrenchkit(cli, ls, norm, 1)[1] / len(ls) for _ in range(repeat))
    return ts[len(ts) // 2]


def F(s):
    return peers.parse_number(s)


def reference(answer, norm):
    """wrenchkit's eps as {lo, hi, sq (Fraction or None), closed, approx}, after checking the answer's
    conventions; raises on an error line."""
    if 'error' in answer or 'undecided' in answer:
        raise ValueError('wrenchkit line %s: %s' % (answer.get('line'), answer.get('error') or answer))
    e = answer['epsilon']
    want = {'norm': norm, 'normalize': 'unit-normal', 'torque_scale': '1', 'about': ['0', '0']}
    got = {k: e.get(k) for k in want}
    if got != want:
        raise ValueError('wrenchkit line %s states %r, not %r' % (answer.get('line'), got, want))
    lo, hi = F(e['lower']), F(e['upper'])
    sq = F(e['squared']) if 'squared' in e else None
    return {'lo': lo, 'hi': hi, 'sq': sq, 'closed': lo > 0, 'force_closure': answer['force_closure'],
            'approx': float(lo + hi) / 2}


def check_reference(scene, line, ref, exact, norm):
    """Disagreements between wrenchkit's answer and itself / peers.py's --exact reference (list of strings)."""
    bad = []
    if not (0 <= ref['lo'] <= ref['hi']):
        bad.append('bracket not ordered: [%s, %s]' % (ref['lo'], ref['hi']))
    if ref['force_closure'] != ref['closed']:
        bad.append('force_closure %s but eps lower %s' % (ref['force_closure'], ref['lo']))
    if ref['sq'] is not None and not (ref['lo'] ** 2 <= ref['sq'] <= ref['hi'] ** 2):
        bad.append('bracket [%s, %s] does not hold sqrt(%s)' % (ref['lo'], ref['hi'], ref['sq']))
    if exact is not None:
        ex = F(exact['eps2'])
        if ref['sq'] is None:
            bad.append('peers.py has the rational eps^2 %s, wrenchkit gives no "squared"' % ex)
        elif ex != ref['sq']:
            bad.append('eps^2: wrenchkit %s, peers.py --exact %s' % (ref['sq'], ex))
        if bool(exact['closure']) != ref['closed']:
            bad.append('closure: wrenchkit %s, peers.py --exact %s' % (ref['closed'], exact['closure']))
    return ['%s [%s] %s\n    scene: %s' % (scene.get('name'), norm, b, line) for b in bad]


# ----------------------------------------------------------------------------------------------------------------
# peers and the comparison
# ----------------------------------------------------------------------------------------------------------------

def run_peers(scenes, qp='auto', do_time=False, min_time=0.03, exact=True, progress=False):
    out = []
    for i, sc in enumerate(scenes):
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')
            out.append(peers.evaluate_scene(sc, 1.0, qp, min_time, do_time, exact))
        if progress and (i + 1) % 50 == 0:
            print('  peers: %d / %d' % (i + 1, len(scenes)), file=sys.stderr, flush=True)
    return out


def rel_error(v, ref):
    """|v - eps| / eps against the nearest end of [lo, hi] (0 inside); v a float > 0, ref closed."""
    x = Fraction(v)
    if ref['lo'] <= x <= ref['hi']:
        return 0.0
    end = ref['lo'] if x < ref['lo'] else ref['hi']
    return float(abs(x - end) / end) if end > 0 else float('inf')


def classify(v, ref):
    """'ok' | 'F+' | 'F-' for a peer value against wrenchkit's reference (NaN counts as 'not closed')."""
    peer_closed = (not math.isnan(v)) and v > 0
    if peer_closed and not ref['closed']:
        return 'F+'
    if ref['closed'] and not peer_closed:
        return 'F-'
    return 'ok'


def compare(scenes, wk, pr):
    """wk: {'L1': [ref], 'Linf': [ref]}, pr: peers.py results.  Returns (stats per (family, peer), wrong list)."""
    stats = OrderedDict()
    wrong = []
    for f in FAMILIES + ('other',):
        for key, _, _ in PEERS:
            stats[(f, key)] = {'n': 0, 'closed': 0, 'threw': 0, 'F+': 0, 'F-': 0, 'nan': 0, 'rel': [], 'us': [],
                               'fn_eps': [], 'fp_val': []}
    for i, sc in enumerate(scenes):
        f = family(sc['name'])
        for key, label, norm in PEERS:
            ref = wk[norm][i]
            p = pr[i][key]
            v = float(p['value'])
            st = stats[(f, key)]
            st['n'] += 1
            st['closed'] += ref['closed']
            st['threw'] += bool(p['threw'])
            st['nan'] += math.isnan(v)
            if 'time' in p:
                st['us'].append(p['time']['median_us'])
            c = classify(v, ref)
            if c != 'ok':
                st[c] += 1
                (st['fn_eps'] if c == 'F-' else st['fp_val']).append(ref['approx'] if c == 'F-' else v)
                wrong.append({'line': i + 1, 'name': sc['name'], 'peer': label, 'kind': c, 'peer_value': v,
                              'threw': bool(p['threw']), 'wk_lo': ref['lo'], 'wk_hi': ref['hi'],
                              'wk_eps': ref['approx'], 'decision': p.get('decision')})
            elif ref['closed']:
                st['rel'].append(rel_error(v, ref))
    return OrderedDict((k, v) for k, v in stats.items() if v['n']), wrong


def fmt_e(x):
    if x is None:
        return '–'
    if x == 0:
        return '0'
    return '%.1e' % x


def fmt_us(x):
    return '–' if x is None else ('%.0f' % x if x >= 10 else '%.1f' % x)


def markdown_table(stats, wk_us):
    """wk_us: {(family or 'all', norm): µs per grasp}."""
    rows = ['| family | peer | n / closed | threw | F+ | F− | rel. err worst · median (both closed) | '
            'F−: wrenchkit ε (max) | F+: peer value (max) | µs/grasp peer · wrenchkit |',
            '|---|---|---|---|---|---|---|---|---|---|']
    tot = OrderedDict()
    for (f, key), st in stats.items():
        label, norm = next((l, n) for k, l, n in PEERS if k == key)
        t = tot.setdefault(key, {'n': 0, 'closed': 0, 'threw': 0, 'F+': 0, 'F-': 0, 'rel': [], 'us': [],
                                 'fn_eps': [], 'fp_val': [], 'label': label, 'norm': norm})
        for k in ('n', 'closed', 'threw', 'F+', 'F-'):
            t[k] += st[k]
        for k in ('rel', 'us', 'fn_eps', 'fp_val'):
            t[k] += st[k]
        rows.append(_row(f, label, st, wk_us.get((f, norm))))
    for key, t in tot.items():
        rows.append(_row('**all**', t['label'], t, wk_us.get(('all', t['norm']))))
    return '\n'.join(rows)


def _row(f, label, st, wk):
    rel = sorted(st['rel'])
    relc = ('%s · %s' % (fmt_e(rel[-1]), fmt_e(rel[len(rel) // 2]))) if rel else '–'
    us = (sum(st['us']) / len(st['us'])) if st['us'] else None
    return '| %s | %s | %d / %d | %d | %d | %d | %s | %s | %s | %s · %s |' % (
        f, label, st['n'], st['closed'], st['threw'], st['F+'], st['F-'], relc,
        fmt_e(max(st['fn_eps'])) if st['fn_eps'] else '–', fmt_e(max(st['fp_val'])) if st['fp_val'] else '–',
        fmt_us(us), fmt_us(None if wk is None else wk * 1e6))


def details_markdown(wrong):
    rows = ['| line | scene | peer | kind | peer value | wrenchkit ε (≈) | peer decision |', '|---|---|---|---|---|---|---|']
    for w in wrong:
        rows.append('| %d | %s | %s | %s | %.6g%s | %s | %s |' % (
            w['line'], w['name'], w['peer'], w['kind'], w['peer_value'], ' (threw)' if w['threw'] else '',
            '0' if w['wk_hi'] == 0 else '%.6g' % w['wk_eps'], w['decision'] or '–'))
    return '\n'.join(rows)


def wrenchkit_references(cli, scenes, lines, pr, jobs=1):
    """Run wrenchkit on both norms; (refs per norm, disagreements with peers.py --exact, wall per norm)."""
    wk, disagree, wall = {}, [], {}
    for norm in ('L1', 'Linf'):
        ans, wall[norm] = run_wrenchkit(cli, lines, norm, jobs)
        refs = []
        for i, a in enumerate(ans):
            try:
                r = reference(a, norm)
            except ValueError as e:
                disagree.append('%s [%s] %s\n    scene: %s' % (scenes[i].get('name'), norm, e, lines[i]))
                r = {'lo': Fraction(0), 'hi': Fraction(0), 'sq': None, 'closed': False, 'force_closure': False,
                     'approx': float('nan'), 'failed': True}
            refs.append(r)
            if pr is not None and not r.get('failed'):
                disagree += check_reference(scenes[i], lines[i], r, pr[i].get('exact_' + norm), norm)
        wk[norm] = refs
    for i in range(len(scenes)):   # eps > 0 in one norm iff in the other (both: force closure)
        if wk['L1'][i]['closed'] != wk['Linf'][i]['closed']:
            disagree.append('%s: L1 closed %s, Linf closed %s\n    scene: %s' % (
                scenes[i].get('name'), wk['L1'][i]['closed'], wk['Linf'][i]['closed'], lines[i]))
    return wk, disagree, wall


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--wrenchkit', default=DEFAULT_CLI)
    ap.add_argument('--families', default=os.path.join(HERE, 'families.jsonl'))
    ap.add_argument('--limit', type=int, default=None, help='only the first N scenes')
    ap.add_argument('--qp', choices=['auto', 'cvxopt', 'nnls'], default='auto',
                    help="Dex-Net's QP (auto: cvxopt when importable, else nnls)")
    ap.add_argument('--min-time', type=float, default=0.03, help="peers.py's seconds of repetitions per peer and grasp")
    ap.add_argument('--no-time', action='store_true')
    ap.add_argument('--repeat', type=int, default=5, help='wrenchkit batch runs per timing (median)')
    ap.add_argument('--min-lines', type=int, default=300, help='per-family wrenchkit timing: repeat the lines to this')
    ap.add_argument('--details', help='write every wrong answer (markdown) to this file')
    a = ap.parse_args(argv)

    items = load_scenes(a.families, a.limit)
    lines = [l for l, _ in items]
    scenes = [s for _, s in items]
    qp = a.qp if a.qp != 'auto' else ('cvxopt' if peers.HAVE_CVXOPT else 'nnls')
    print('compare.py: %d scenes from %s; wrenchkit %s; Dex-Net QP %s; timing %s' % (
        len(scenes), a.families, a.wrenchkit, qp, 'off' if a.no_time else 'min-time %gs' % a.min_time),
        file=sys.stderr, flush=True)
    pr = run_peers(scenes, qp, not a.no_time, a.min_time, exact=True, progress=True)
    wk, disagree, _ = wrenchkit_references(a.wrenchkit, scenes, lines, pr)
    stats, wrong = compare(scenes, wk, pr)

    wk_us = {}
    if not a.no_time:
        for norm in ('L1', 'Linf'):
            wk_us[('all', norm)] = time_wrenchkit(a.wrenchkit, lines, norm, a.repeat)
            for f in FAMILIES:
                fl = [l for l, s in zip(lines, scenes) if family(s['name']) == f]
                if fl:
                    wk_us[(f, norm)] = time_wrenchkit(a.wrenchkit, fl, norm, max(3, a.repeat // 2), a.min_lines)

    n_exact = sum(1 for r in pr for m in ('L1', 'Linf') if r.get('exact_' + m) is not None)
    print('Reference: wrenchkit `batch quality --only epsilon %s --norm L1|Linf --jobs 1` (%d scenes); '
          "peers.py's rational reference exists for %d of the %d (scene, norm) pairs and %s." % (
              ' '.join(WK_OPTIONS[2:]), len(scenes), n_exact, 2 * len(scenes),
              'agrees on every one' if not disagree else 'DISAGREES (below)'))
    print('Dex-Net QP: %s.  Peer times: mean over the grasps of peers.py time_per_call (median of 5 batches); '
          'wrenchkit: batch wall time / grasps on --jobs 1 (median of runs; per family the lines repeated to >= %d; '
          'whole file: all %s at once, L1 %s µs, L∞ %s µs per grasp).' % (
              qp, a.min_lines, len(scenes), fmt_us(wk_us.get(('all', 'L1'), 0) * 1e6 if wk_us else None),
              fmt_us(wk_us.get(('all', 'Linf'), 0) * 1e6 if wk_us else None)))
    nan = sum(st['nan'] for st in stats.values())
    if nan:
        print('NaN peer values (counted as "not closed"): %d.' % nan)
    print()
    print(markdown_table(stats, wk_us))
    if a.details:
        with open(a.details, 'w') as fh:
            fh.write('# Every wrong peer answer (compare.py)\n\nwrenchkit ε is its exact answer (0 exactly for F+: '
                     'the grasp is not in force closure).\n\n')
            fh.write(details_markdown(wrong) + '\n')
    if disagree:
        print('\n!!!!!!!! REFERENCE DISAGREEMENT: wrenchkit vs peers.py --exact (a bug in one of them) !!!!!!!!',
              file=sys.stderr)
        for d in disagree:
            print('  ' + d, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
