#!/usr/bin/python3
"""Smoke test of the placements route (CTest grasp_regions_peers_smoke), a few seconds: docs/grasp-regions' parts as
a corpus of one's own (`wrenchkit reference --scenes`), placements.py's answers by both methods read by `wrenchkit
compare --json` (every placement compared, none refused), and the wiring: the same placements with every verdict
flipped must come back all wrong — unsafe where the flip claims closed, lost where it claims open.

  /usr/bin/python3 smoke.py [PATH/TO/wrenchkit]
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))


def main():
    cli = sys.argv[1] if len(sys.argv) > 1 else "wrenchkit"
    with tempfile.TemporaryDirectory() as tmp:
        corpus = os.path.join(tmp, "corpus")
        subprocess.run([cli, "reference", "--scenes", os.path.join(ROOT, "docs", "grasp-regions"), "--out", corpus],
                       check=True, capture_output=True)
        for method in ("libicr", "nguyen"):
            out = subprocess.run([sys.executable, os.path.join(HERE, "placements.py"),
                                  os.path.join(corpus, "reference.jsonl"), "--method", method],
                                 check=True, capture_output=True, text=True).stdout
            lines = [json.loads(l) for l in out.splitlines()]
            total = sum(len(l["placements"]) for l in lines)
            flipped = "".join(json.dumps(dict(l, placements=[dict(p, closed=not p["closed"]) for p in l["placements"]]))
                              + "\n" for l in lines)
            reports = []
            for text in (out, flipped):
                r = subprocess.run([cli, "compare", "--json", corpus, "-"], input=text, capture_output=True, text=True)
                if r.returncode not in (0, 1):
                    print(f"{method}: compare exit {r.returncode}: {r.stderr}")
                    return 1
                reports.append(json.loads(r.stdout)["fields"]["placements"])
            f, g = reports
            if len(lines) != 3 or total < 300 or int(f["compared"]) != total or int(g["compared"]) != total:
                print(f"{method}: {len(lines)} parts, {total} placements; compared {f['compared']} and {g['compared']}")
                return 1
            if int(g["agree"]) != int(f["disagree"]) or int(g["unsafe"]) + int(g["lost"]) != int(f["agree"]):
                print(f"{method}: flipping every verdict should swap agreement: {f} vs {g}")
                return 1
            print(f"{method}: {total} placements, {f['agree']} agree, unsafe {f['unsafe']}, lost {f['lost']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
