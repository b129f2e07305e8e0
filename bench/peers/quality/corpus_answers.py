#!/usr/bin/python3
"""The peers' epsilon on the reference corpus, as answers for `wrenchkit compare` (docs/reference-format.md §5).

For every corpus line with a `quality` (a scene with contacts; the corpus states eps in the default conventions:
L1, unit-normal edges, moments about body.com else the origin, torque scale 1 — the same as peers.py's), write one
answers file per peer:

  dexnet.jsonl        Dex-Net's ferrari_canny_L1 (torque_scaling 1), what it returns (0.0 for "not in closure",
                      also when qhull throws: pyhull swallows it)
  graspit_l1.jsonl    GraspIt!'s L1 QualEpsilon with torque scale 1 (GraspIt! itself divides moments by the
                      object's max radius; here 1, the corpus's convention): its -1.0 ("not a force-closure
                      grasp", or qhull failed) written as 0, what a caller reads as "no closure"

A scene the ports cannot take (a wrench generator among the contacts) gets {"id", "epsilon": null, "error"}.
Then run

  wrenchkit compare CORPUS OUT/dexnet.jsonl;  wrenchkit compare CORPUS OUT/graspit_l1.jsonl

  /usr/bin/python3 corpus_answers.py CORPUS_DIR OUT_DIR [--qp auto|cvxopt|nnls]
Needs NumPy and SciPy (Debian's python3-numpy, python3-scipy); cvxopt is optional (else NNLS).
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import peers  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('corpus')
    ap.add_argument('out')
    ap.add_argument('--qp', default='auto', choices=('auto', 'cvxopt', 'nnls'))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    files = {name: open(os.path.join(a.out, name + '.jsonl'), 'w') for name in ('dexnet', 'graspit_l1')}
    counts = {'lines': 0, 'answered': 0, 'skipped': 0}
    with open(os.path.join(a.corpus, 'reference.jsonl')) as f:
        for line in f:
            d = json.loads(line)
            if 'quality' not in d:
                continue
            counts['lines'] += 1
            if d['quality'] is None:   # refused by the engine's work bound: nothing to compare with
                continue
            try:
                contacts, about = peers.scene_contacts(d['scene'])
            except ValueError as e:
                counts['skipped'] += 1
                for fh in files.values():
                    fh.write(json.dumps({'id': d['id'], 'epsilon': None, 'error': str(e)}) + '\n')
                continue
            aboutf = tuple(float(x) for x in about)
            dx = peers.dexnet_ferrari_canny_L1(contacts, 1.0, aboutf, qp=a.qp)
            gl = peers.graspit_epsilon(contacts, 'L1', 1.0, aboutf)
            files['dexnet'].write(json.dumps({'id': d['id'], 'epsilon': dx['value'], '_decision': dx['decision']}) + '\n')
            files['graspit_l1'].write(json.dumps({'id': d['id'], 'epsilon': max(gl['value'], 0.0),
                                                  '_threw': gl['threw']}) + '\n')
            counts['answered'] += 1
    for fh in files.values():
        fh.close()
    print(json.dumps(counts))


if __name__ == '__main__':
    main()
