#!/usr/bin/python3
"""Smoke test of the peer comparison (CTest quality_peers_smoke): compare.py's core on the first 12 lines of
families.jsonl and on handcheck.py's square, in a few seconds.

Fails (exit 1) when wrenchkit's eps (`batch quality --only epsilon`, L1 and Linf, unit-normal, about the origin,
torque scale 1) disagrees with
  * peers.py's brute-force rational reference (--exact): eps^2 and closure, on every scene;
  * the hand formulas for the square [-1,1]^2 held at its side middles with friction mu (handcheck.py):
    L1 eps = mu, Linf eps^2 = 16 mu^2 (1+mu^2) / (1+3mu^2), and eps = 0 at mu = 0;
or when the corpus route fails: the square as a corpus of one's own (`wrenchkit reference --scenes`), the ports'
answers by corpus_answers.py, `wrenchkit compare --rtol 1e-3` agreeing on every square; or when the comparison's
wiring is off: on the square with mu > 0 every peer (Dex-Net with cvxopt when
importable, else nnls; GraspIt! L1 and Linf) must be within 1e-3 relative of wrenchkit's eps (cvxopt's early stop
gives up to 7e-5; a convention mismatch between the two sides would show as an O(1) error).

  /usr/bin/python3 smoke.py [PATH/TO/wrenchkit]
Needs NumPy and SciPy (Debian's python3-numpy, python3-scipy); cvxopt is optional.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction as Fr

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True   # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import compare  # noqa: E402
import handcheck  # noqa: E402

SQUARE_MUS = (Fr(0), Fr(1, 100), Fr(1, 10), Fr(1, 4), Fr(1, 2))


def square_scene(mu):
    cs = [{'at': [str(c['at'][0]), str(c['at'][1])], 'normal': [str(c['normal'][0]), str(c['normal'][1])],
           'mu': str(mu)} for c in handcheck.square(mu)]
    return {'wrenchkit': 1, 'name': 'square mu=%s' % mu, 'contacts': cs}


def main():
    t0 = time.perf_counter()
    cli = sys.argv[1] if len(sys.argv) > 1 else compare.DEFAULT_CLI
    items = compare.load_scenes(os.path.join(HERE, 'families.jsonl'), 12)
    lines = [l for l, _ in items]
    for mu in SQUARE_MUS:
        lines.append(json.dumps(square_scene(mu), separators=(',', ':')))
    scenes = [json.loads(l, parse_float=str, parse_int=str) for l in lines]
    failures = []

    pr = compare.run_peers(scenes, qp='auto', do_time=False, exact=True)
    wk, disagree, _ = compare.wrenchkit_references(cli, scenes, lines, pr)
    failures += disagree
    for i, sc in enumerate(scenes):
        for norm in ('L1', 'Linf'):
            if pr[i].get('exact_' + norm) is None:
                failures.append('%s [%s]: no rational reference (the smoke scenes all have rational normals)'
                                % (sc['name'], norm))

    # the hand formulas
    for k, mu in enumerate(SQUARE_MUS):
        i = len(items) + k
        hand = {'L1': mu * mu, 'Linf': 16 * mu * mu * (1 + mu * mu) / (1 + 3 * mu * mu)}
        for norm in ('L1', 'Linf'):
            r = wk[norm][i]
            ok = r['sq'] == hand[norm] and r['closed'] == (mu > 0)
            if norm == 'L1':
                ok = ok and r['lo'] <= mu <= r['hi']
            if not ok:
                failures.append('square mu=%s [%s]: wrenchkit eps^2 %s, bracket [%s, %s], closed %s; by hand eps^2 '
                                '= %s\n    scene: %s' % (mu, norm, r['sq'], r['lo'], r['hi'], r['closed'],
                                                      hand[norm], lines[i]))
            if mu > 0 and r['closed']:
                for key, label, pnorm in compare.PEERS:
                    if pnorm != norm:
                        continue
                    v = pr[i][key]['value']
                    err = compare.rel_error(v, r) if v > 0 else float('inf')
                    if not err <= 1e-3:
                        failures.append('square mu=%s: %s gives %r, wrenchkit eps in [%s, %s] (rel. err %.3g): the '
                                        'two sides do not compute the same wrench space' % (mu, label, v, r['lo'],
                                                                                           r['hi'], err))

    # the corpus route: the square's scenes as a corpus of one's own (`reference --scenes`), the ports' answers by
    # corpus_answers.py, and `wrenchkit compare` within 1e-3 (the QP's precision): every one agrees
    with tempfile.TemporaryDirectory() as tmp:
        own = os.path.join(tmp, 'square.jsonl')
        with open(own, 'w') as f:
            for mu in SQUARE_MUS:
                f.write(json.dumps({'id': 'square.' + str(mu).replace('/', '_'), 'scene': square_scene(mu)}) + '\n')
        corpus, out = os.path.join(tmp, 'corpus'), os.path.join(tmp, 'answers')
        steps = [[cli, 'reference', '--scenes', own, '--out', corpus],
                 [sys.executable, os.path.join(HERE, 'corpus_answers.py'), corpus, out]]
        steps += [[cli, 'compare', '--json', '--rtol', '1e-3', corpus, os.path.join(out, p + '.jsonl')]
                  for p in ('dexnet', 'graspit_l1')]
        for step in steps:
            r = subprocess.run(step, capture_output=True, text=True)
            if r.returncode != 0:
                failures.append('%s: exit %d\n%s%s' % (' '.join(step[:3]), r.returncode, r.stdout[-2000:], r.stderr))
            elif step[1] == 'compare':
                t = json.loads(r.stdout)['fields'].get('epsilon', {})
                if t.get('agree') != len(SQUARE_MUS):
                    failures.append('compare on the square corpus: %s (want %d agreeing)' % (t, len(SQUARE_MUS)))

    stats, wrong = compare.compare(scenes, wk, pr)
    print(compare.markdown_table(stats, {}))
    dt = time.perf_counter() - t0
    print('\n%d scenes (families.jsonl lines 1-%d, the square at mu = %s), Dex-Net QP %s, %.1f s' % (
        len(scenes), len(items), ', '.join(str(m) for m in SQUARE_MUS),
        'cvxopt' if compare.peers.HAVE_CVXOPT else 'nnls', dt))
    if failures:
        print('\nFAILED: wrenchkit disagrees with the exact reference or the hand formula:', file=sys.stderr)
        for f in failures:
            print('  ' + f, file=sys.stderr)
        return 1
    print('ok: wrenchkit eps = the rational reference on %d (scene, norm) pairs and the hand formulas on the square'
          % (2 * len(scenes)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
