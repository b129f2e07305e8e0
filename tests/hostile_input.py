#!/usr/bin/env python3
"""Hostile input cannot exhaust memory or time (issue 21; docs/scene-format.md "Limits").

Runs the command line on scenes a hostile user would write, each under an address-space limit (RLIMIT_AS,
as `prlimit --as`), a CPU-time limit and a wall-clock limit, and checks the exit code, the message and the
peak resident memory (the child's ru_maxrss):

  * the scene of issue 21: 100 000 contacts, every number "1e9999" (7.8 MB): refused by the budget (exit 2,
    the message names the budget, the measured value and the option) with < 100 MB resident; the checker
    (`wrenchkit check`) refuses it too; raising one budget, the other refuses it;
  * long fractions (500 contacts of 10 000-digit fractions, 25 MB): refused by the budget;
  * 100 000 coincident contacts (within budget): answered, force and form closure false;
  * huge supports: 100 000 support points of "1e9999" refused; 100 000 plain support points with a twist
    (the polygons' tables): refused with the table limit, not built;
  * out of memory within budget (300 contacts of 10 000-digit fractions under 32–44 MiB of address space,
    where GMP's allocations fail): exit 70 with "out of memory", never GMP's abort;
  * issue 34: small scenes whose questions cost minutes (a region and 59 legs whose force is not given, 60 such
    points at 10^9990, a 900-gon at 10^9990): undecided by the work budget (--max-work) or answered, within 10 s
    of CPU, 2 GB and 10 MB of output; in batch an undecided line;
  * `batch closure` of 1 000 lines, every tenth the hostile scene: the 900 good lines answered exactly as when
    they are alone, the hostile ones error lines (exit_code 2), < 1 GB resident; and a batch where one line
    runs out of memory: that line an internal_error line (exit_code 70), the others answered, exit 70.

Every scene is generated here (nothing big is committed). Usage: hostile_input.py WRENCHKIT WORKDIR
"""
import json
import math
import os
import resource
import subprocess
import sys
import threading

MiB = 1 << 20
FAILURES = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        FAILURES.append(what)


def run(args, stdin_path=None, stdin_iter=None, as_bytes=1 << 30, cpu_seconds=20, wall_seconds=60):
    """Runs args under RLIMIT_AS and RLIMIT_CPU; returns (exit code, stdout, stderr, max RSS in MiB)."""
    def limits():
        resource.setrlimit(resource.RLIMIT_AS, (as_bytes, as_bytes))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu_seconds, cpu_seconds))
    stdin = open(stdin_path, "rb") if stdin_path else (subprocess.PIPE if stdin_iter else subprocess.DEVNULL)
    p = subprocess.Popen(args, stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=limits)
    out, err = [], []
    readers = [threading.Thread(target=lambda: out.append(p.stdout.read())),
               threading.Thread(target=lambda: err.append(p.stderr.read()))]
    for t in readers:
        t.start()
    if stdin_iter:
        try:
            for chunk in stdin_iter:
                p.stdin.write(chunk)
            p.stdin.close()
        except BrokenPipeError:
            pass
    timer = threading.Timer(wall_seconds, p.kill)
    timer.start()
    _, status, usage = os.wait4(p.pid, 0)
    timer.cancel()
    for t in readers:
        t.join()
    p.returncode = os.waitstatus_to_exitcode(status)
    if stdin_path:
        stdin.close()
    return p.returncode, out[0].decode(), err[0].decode(), usage.ru_maxrss / 1024.0


def contacts_scene(n, number):
    c = '{"at": [%s, %s], "normal": [%s, %s], "mu": %s}' % ((number,) * 5)
    return '{"wrenchkit": 1, "contacts": [' + ", ".join([c] * n) + "]}"


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def ngon(n, radius):
    """n integer points near a circle (a convex polygon, counter-clockwise)."""
    return [[round(radius * math.cos(2 * math.pi * k / n)), round(radius * math.sin(2 * math.pi * k / n))]
            for k in range(n)]


def unknown_support(region_sides, legs, exponent=0, load=True):
    """Issue 34's scenes: a region of `region_sides` (none when 0) beside `legs` points whose force is not given;
    every coordinate times 10^exponent."""
    def c(v):
        return "%de%d" % (v, exponent) if exponent else v
    support = {"mu": "1/2", "weight": 60, "pressure_center": [0, 0],
               "points": [{"at": [c(x), c(y)]} for x, y in ngon(legs, 1500)]}
    if region_sides:
        support["regions"] = [{"outline": [[c(x), c(y)] for x, y in ngon(region_sides, 1000)],
                               "pressure": "uniform", "force": 1}]
    scene = {"wrenchkit": 1, "support": support}
    if load:
        scene["load"] = {"force": [10, 5], "at": [0, 0]}
    return json.dumps(scene)


def big_region(sides, exponent):
    return json.dumps({"wrenchkit": 1, "support": {"mu": "1/2", "regions": [
        {"outline": [["%de%d" % (x, exponent), "%de%d" % (y, exponent)] for x, y in ngon(sides, 10 ** 6)],
         "pressure": "uniform", "force": 1}]}})


def main():
    cli, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    hostile_text = contacts_scene(100000, '"1e9999"')
    hostile = write(os.path.join(work, "hostile.json"), hostile_text)
    cert = write(os.path.join(work, "cert.json"), '{"format": "wrenchkit-certificate", "version": 1}')

    # The scene of issue 21.
    code, out, err, rss = run([cli, "closure", "--json", hostile], as_bytes=1 << 30, cpu_seconds=10)
    check(code == 2 and "5000000001 digits" in err and "20000000" in err and "--max-total-digits" in err and out == "",
          "hostile scene refused by the budget: exit %d, %r" % (code, err.strip()))
    check(rss < 100, "hostile scene refused with %.1f MB resident (< 100)" % rss)
    code, out, err, rss = run([cli, "check", hostile, cert], as_bytes=1 << 30, cpu_seconds=10)
    check(code == 2 and "digits" in err, "the checker refuses it too: exit %d, %r" % (code, err.strip()[:200]))
    code, out, err, rss = run([cli, "closure", "--json", "--max-total-digits", "10000000000", hostile],
                              as_bytes=1 << 30, cpu_seconds=10)
    check(code == 2 and "--max-digits-times-contacts" in err and "1000000000 digits times contacts" in err,
          "the other budget refuses it when one is raised: exit %d, %r" % (code, err.strip()))

    # Long fractions: 500 contacts of 5 numbers of 5 000 + 5 000 digits.
    fraction = '"%s/%s"' % ("7" * 5000, "3" * 5000)
    path = write(os.path.join(work, "fractions.json"), contacts_scene(500, fraction))
    code, out, err, rss = run([cli, "closure", "--json", path], as_bytes=1 << 30, cpu_seconds=10)
    check(code == 2 and "25000001 digits" in err and "--max-total-digits" in err,
          "long fractions refused by the budget: exit %d, %r (%.1f MB)" % (code, err.strip(), rss))

    # 100 000 coincident contacts: within budget, answered.
    path = write(os.path.join(work, "coincident.json"), contacts_scene(100000, '0').replace(
        '"normal": [0, 0], "mu": 0', '"normal": [0, 1], "mu": "1/2"'))
    code, out, err, rss = run([cli, "closure", "--json", path], as_bytes=2 << 30, cpu_seconds=30)
    answer = json.loads(out) if code == 0 else {}
    check(code == 0 and answer.get("force_closure") is False and answer.get("form_closure") is False,
          "100 000 coincident contacts answered: exit %d (%.1f MB) %r" % (code, rss, err.strip()))

    # Huge supports.
    point = '{"at": ["1e9999", "1e9999"], "force": "1e9999"}'
    path = write(os.path.join(work, "support_huge.json"),
                 '{"wrenchkit": 1, "support": {"mu": 1, "points": [' + ", ".join([point] * 100000) + "]}}")
    code, out, err, rss = run([cli, "limit-surface", "--json", path], as_bytes=1 << 30, cpu_seconds=10)
    check(code == 2 and "--max-total-digits" in err and rss < 100,
          "huge support refused by the budget: exit %d, %r (%.1f MB)" % (code, err.strip(), rss))
    points = ", ".join('{"at": [%d, %d], "force": 1}' % (i % 1000, i // 1000) for i in range(100000))
    path = write(os.path.join(work, "support_many.json"), '{"wrenchkit": 1, "support": {"mu": 1, "points": [' + points + "]}}")
    code, out, err, rss = run([cli, "sliding", "--json", "--twist", "1,0,0", path], as_bytes=2 << 30, cpu_seconds=30)
    check(code == 2 and "more than the limit of 512 MiB" in err,
          "100 000 support points with a twist: the polygons refused, not built: exit %d, %r (%.1f MB)" %
          (code, err.strip(), rss))

    # Out of memory within budget (300 contacts of 10 000-digit fractions: 15 M digits, answered in ~50 MB
    # when memory allows): under tighter address-space limits, exit 70 "out of memory", never GMP's abort.
    fractions = ['"%d%s/%d%s"' % (1 + k % 9, "7" * 4990, 1 + (k * 7) % 9, "3" * 4990) for k in range(1500)]
    oom_text = '{"wrenchkit": 1, "contacts": [' + ", ".join(
        '{"at": [%s, %s], "normal": [%s, %s], "mu": %s}' % tuple(fractions[5 * i:5 * i + 5]) for i in range(300)) + "]}"
    path = write(os.path.join(work, "oom.json"), oom_text)
    for mib in (32, 36, 40, 44):
        code, out, err, rss = run([cli, "closure", "--json", "--mode", "exact", path], as_bytes=mib * MiB, cpu_seconds=60)
        check(code == 70 and "out of memory" in err,
              "out of memory under %d MiB is exit 70, not an abort: exit %d, %r" % (mib, code, err.strip()))

    # batch closure: 1 000 lines, every tenth the hostile scene.
    good = []
    for i in range(1000):
        if i % 10 == 9:
            continue
        cs = ", ".join('{"at": [%d, %d], "normal": [%d, %d], "mu": "%d/%d"}' %
                       ((k * 7 + i) % 19 - 9, (k * 5 + 3 * i) % 17 - 8, [1, 0, -1, 0, 1, -1][(i + k) % 6],
                        [0, 1, 0, -1, 1, 2][(i + k) % 6], (i + k) % 4, 1 + k % 3) for k in range(2 + i % 5))
        good.append('{"wrenchkit": 1, "name": "good %d", "contacts": [%s]}' % (i, cs))
    alone_path = write(os.path.join(work, "good.jsonl"), "\n".join(good) + "\n")
    code, alone, err, _ = run([cli, "batch", "closure", "--jobs", "2"], stdin_path=alone_path, as_bytes=2 << 30)
    check(code == 0, "the good lines alone: exit %d" % code)
    hostile_line = hostile_text.encode() + b"\n"

    def mixed():
        g = iter(good)
        for i in range(1000):
            yield hostile_line if i % 10 == 9 else (next(g) + "\n").encode()

    code, out, err, rss = run([cli, "batch", "closure", "--jobs", "2"], stdin_iter=mixed(), as_bytes=4 << 30,
                              cpu_seconds=120, wall_seconds=300)
    lines = [json.loads(l) for l in out.splitlines()]
    answers = [l for l in lines if "error" not in l]
    errors = [l for l in lines if "error" in l]
    strip = lambda d: {k: v for k, v in d.items() if k != "line"}
    same = [strip(a) for a in answers] == [strip(json.loads(l)) for l in alone.splitlines()]
    check(code == 0 and len(lines) == 1000 and len(answers) == 900 and same,
          "batch: the 900 good lines answered as when alone: exit %d, %d lines, %d answers, same %s" %
          (code, len(lines), len(answers), same))
    check(len(errors) == 100 and all(e["exit_code"] == 2 and "--max-total-digits" in e["error"] and e["line"] % 10 == 0
                                     for e in errors), "batch: the 100 hostile lines are error lines (exit_code 2)")
    check(rss < 1024, "batch of 1 000 lines, every tenth hostile: %.1f MB resident (< 1 GB)" % rss)

    # batch: one line runs out of memory; the others are answered, the stream goes on, exit 70.
    small = [(good[i] + "\n").encode() for i in range(4)]
    code, out, err, rss = run([cli, "batch", "closure", "--jobs", "1", "--mode", "exact"],
                              stdin_iter=iter(small[:2] + [oom_text.encode() + b"\n"] + small[2:]), as_bytes=44 * MiB,
                              cpu_seconds=60)
    lines = [json.loads(l) for l in out.splitlines()]
    check(code == 70 and len(lines) == 5 and lines[2].get("exit_code") == 70 and "internal_error" in lines[2] and
          all("force_closure" in lines[k] for k in (0, 1, 3, 4)),
          "batch: the line out of memory is an internal_error line (70), the others answered, exit %d" % code)

    # Issue 34: small scenes whose questions cost minutes and gigabytes, each within the work budget now: undecided
    # (exit 3) with what it would cost and the option, or answered, within 10 s of CPU, 2 GB of address space and
    # 10 MB of output.
    GB2 = 2 * 1000 ** 3
    load = ["--load", "10,5,20000"]
    cases = [
        ("a 40-gon region + 59 unknown legs, limit-surface --load", unknown_support(40, 59), ["limit-surface", "--json"] + load),
        ("the same, hold", unknown_support(40, 59), ["hold", "--json"]),
        ("a 400-gon region + 59 unknown legs", unknown_support(400, 59), ["limit-surface", "--json"] + load),
        ("a triangle region + 59 unknown legs", unknown_support(3, 59), ["limit-surface", "--json"] + load),
        ("60 unknown points at 10^9990, hold", unknown_support(0, 60, 9990), ["hold", "--json"]),
        ("a 900-gon region at 10^9990", big_region(900, 9990), ["limit-surface", "--json"] + load),
        ("60 unknown points on a circle, limit-surface --load", unknown_support(0, 60), ["limit-surface", "--json"] + load),
    ]
    for k, (what, text, args) in enumerate(cases):
        path = write(os.path.join(work, "work_%d.json" % k), text)
        code, out, err, rss = run([cli] + args + [path], as_bytes=GB2, cpu_seconds=10, wall_seconds=60)
        check(code in (0, 3) and (code == 0 or "--max-work" in err or "--max-certificate-size" in err) and
              len(out) <= 10 * MiB,
              "%s (%d bytes): exit %d, %.0f MB resident, %d bytes out, %r" % (what, len(text), code, rss, len(out),
                                                                          err.strip()[:160]))
    # Scale-free: 12 unknown points written at 10^-9990 (minutes before: every extreme distribution's polygons in
    # 33 000-bit fractions) are answered as the same points at 1 are, under the same limits.
    twelve = write(os.path.join(work, "work_twelve.json"), unknown_support(0, 12, load=False))
    tiny = write(os.path.join(work, "work_twelve_tiny.json"), unknown_support(0, 12, -9990, load=False))
    for args in (["--load", "40,0,0"], ["--load", "10,5,20000"]):
        code, out, err, rss = run([cli, "limit-surface", "--json"] + args + [twelve], as_bytes=GB2, cpu_seconds=10)
        want = json.loads(out).get("motion") if code == 0 else None
        small = args[:1] + [args[1] + "e-9990"]
        code, out, err, rss = run([cli, "limit-surface", "--json"] + small + [tiny], as_bytes=GB2, cpu_seconds=10,
                                  wall_seconds=60)
        check(code == 0 and want is not None and json.loads(out).get("motion") == want,
              "12 unknown points at 10^-9990, load %s: %s as at scale 1 (exit %d, %r)" % (small[1], want, code,
                                                                                          err.strip()[:160]))
    # A moderate scene is answered by default; a small budget makes it undecided, naming the option; raised, answered.
    moderate = write(os.path.join(work, "work_moderate.json"), unknown_support(40, 10))
    code, out, err, rss = run([cli, "limit-surface", "--json"] + load + [moderate], as_bytes=GB2, cpu_seconds=10)
    check(code == 0 and json.loads(out).get("motion") in ("sticks", "slides", "impending", "depends"),
          "a 40-gon region + 10 unknown legs answered by default: exit %d %r" % (code, err.strip()[:160]))
    code, out, err, rss = run([cli, "limit-surface", "--json", "--max-work", "1000"] + load + [moderate],
                              as_bytes=GB2, cpu_seconds=10)
    check(code == 3 and err.startswith("wrenchkit: undecided: the work budget of 1000 units (--max-work)") and
          "use --mode" not in err and out == "",
          "--max-work 1000: undecided, exit %d, %r" % (code, err.strip()[:200]))
    # The certificate's size: a question whose certificate would pass --max-certificate-size is undecided; `check`
    # rejects a longer certificate before reading it.
    thirty = write(os.path.join(work, "work_thirty.json"), unknown_support(0, 30, load=False))
    cert30 = os.path.join(work, "work_thirty.cert.json")
    code, out, err, rss = run([cli, "limit-surface", "--certificate", cert30] + load + [thirty], as_bytes=GB2,
                              cpu_seconds=10)
    size = os.path.getsize(cert30) if code == 0 else 0
    check(code == 0 and size > 100000, "30 unknown points: answered, a certificate of %d bytes" % size)
    code, out, err, rss = run([cli, "limit-surface", "--max-certificate-size", str(size // 2), "--json"] + load + [thirty],
                              as_bytes=GB2, cpu_seconds=10)
    check(code == 3 and "--max-certificate-size" in err and "use --mode" not in err and out == "",
          "a certificate twice --max-certificate-size: undecided, exit %d, %r" % (code, err.strip()[:200]))
    code, out, err, rss = run([cli, "check", "--max-certificate-size", str(size - 1), thirty, cert30], as_bytes=GB2,
                              cpu_seconds=10)
    check(code == 1 and "more than the limit" in (out + err) and "--max-certificate-size" in (out + err),
          "check rejects a certificate over --max-certificate-size: exit %d, %r" % (code, (out + err).strip()[:200]))
    # batch: the line over budget is an undecided line (exit_code 3), the others answered in order.
    lines = [moderate_text + "\n" for moderate_text in [json.dumps(json.loads(unknown_support(40, 10)))]] * 2
    hostile_line = json.dumps(json.loads(unknown_support(40, 59))) + "\n"
    code, out, err, rss = run([cli, "batch", "hold", "--jobs", "1"],
                              stdin_iter=iter([lines[0].encode(), hostile_line.encode(), lines[1].encode()]),
                              as_bytes=GB2, cpu_seconds=20)
    got = [json.loads(l) for l in out.splitlines()]
    check(len(got) == 3 and got[1].get("exit_code") == 3 and "--max-work" in json.dumps(got[1]) and
          all("holds" in got[i] for i in (0, 2)),
          "batch hold: the line over the work budget is undecided (3), the others answered: exit %d, %r" %
          (code, out[:300]))

    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
