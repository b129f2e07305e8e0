"""Throughput of the Python front ends beside the command line's batch, in one run (docs/benchmarks.md, "(d)").

    PYTHONPATH=build/python python3 bench/python_bench.py --cli build/wrenchkit --out docs/benchmarks/python.json

Random six-contact frictional grasps (uniform doubles in [-1, 1], mu 0.5; seed 7), hybrid mode:
Wall time and CPU time (user + sys, children included) are both recorded: on a loaded machine the CPU time
is the cost per core, the wall time shows what jobs and workers gain.
  * closure_arrays on --rows grasps (default 10^6), jobs 1 and 2: force and form closure per row, the array
    validation included; beside `wrenchkit batch closure --verdict-only --jobs 1` on --cli-rows of the same
    grasps written as JSON lines (repr of each double, what a sampler writes), the process's I/O included;
  * certificates: closure_arrays(certificates=True, jobs=1) on --cert-rows grasps (both certificates built,
    checked by the independent checker, returned as dicts) against `wrenchkit batch closure --jobs 1` on the
    same scenes (their canonical text: the same exact numbers);
  * Dask: `python3 -m wrenchkit.dask batch closure --verdict-only` with --workers 1 and 2 on --dask-lines lines
    (default 10^6), wall time including the LocalCluster's start.
The machine may be shared: compare the ratios of one run, not the absolute numbers of different runs.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

import wrenchkit


def grasps(rows, seed=7):
    rng = np.random.default_rng(seed)
    return rng.uniform(-1, 1, (rows, 6, 2)), rng.uniform(-1, 1, (rows, 6, 2)), np.full((rows, 6), 0.5)


def lines_of(p, n, mu):
    for i in range(len(p)):
        yield json.dumps({"wrenchkit": 1, "contacts": [
            {"at": p[i, k].tolist(), "normal": n[i, k].tolist(), "mu": float(mu[i, k])} for k in range(6)]})


def cpu_seconds():
    """CPU time (user + sys) of this process and of its waited-for children: on a shared machine, the cost."""
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


def timed(f, cpu=None):
    """Wall seconds of f(); with a dict `cpu`, also its CPU seconds in cpu["s"]."""
    t, c = time.perf_counter(), cpu_seconds()
    f()
    if cpu is not None:
        cpu["s"] = cpu_seconds() - c
    return time.perf_counter() - t


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--cli", required=True)
    a.add_argument("--out")
    a.add_argument("--rows", type=int, default=1_000_000)
    a.add_argument("--cli-rows", type=int, default=200_000)
    a.add_argument("--cert-rows", type=int, default=20_000)
    a.add_argument("--dask-lines", type=int, default=1_000_000)
    o = a.parse_args()
    r = {"machine_cores": os.cpu_count(), "load_average_at_start": os.getloadavg()[0],
         "when": time.strftime("%Y-%m-%d", time.gmtime()), "rows": o.rows, "dask_lines": o.dask_lines}
    p, n, mu = grasps(o.rows)
    for jobs in (1, 2):
        cpu = {}
        dt = timed(lambda: wrenchkit.closure_arrays(p, n, mu, jobs=jobs), cpu)
        r[f"arrays_jobs{jobs}_rows_per_s"] = o.rows / dt
        r[f"arrays_jobs{jobs}_rows_per_cpu_s"] = o.rows / cpu["s"]
        print(f"closure_arrays, {o.rows} rows, jobs {jobs}: {dt:.2f} s wall, {cpu['s']:.2f} s CPU, "
              f"{o.rows / dt:,.0f} rows/s, {o.rows / cpu['s']:,.0f} rows per CPU second", flush=True)
    r["arrays_jobs2_over_jobs1"] = r["arrays_jobs2_rows_per_s"] / r["arrays_jobs1_rows_per_s"]
    with tempfile.TemporaryDirectory() as tmp:
        text = os.path.join(tmp, "grasps.jsonl")
        with open(text, "w") as f:
            for line in lines_of(p[:o.cli_rows], n[:o.cli_rows], mu[:o.cli_rows]):
                f.write(line + "\n")
        cmd = f"{o.cli} batch closure --verdict-only --jobs 1 < {text} > /dev/null"
        cpu = {}
        dt = timed(lambda: subprocess.run(cmd, shell=True, check=True), cpu)
        r["cli_verdict_only_jobs1_scenes_per_s"] = o.cli_rows / dt
        r["cli_verdict_only_jobs1_scenes_per_cpu_s"] = o.cli_rows / cpu["s"]
        print(f"wrenchkit batch closure --verdict-only --jobs 1, {o.cli_rows} lines: {o.cli_rows / dt:,.0f} scenes/s",
              flush=True)
        m = o.cert_rows
        res = {}
        cpu = {}
        dt = timed(lambda: res.update(wrenchkit.closure_arrays(p[:m], n[:m], mu[:m], certificates=True, jobs=1)), cpu)
        r["arrays_certificates_jobs1_rows_per_s"] = m / dt
        r["arrays_certificates_jobs1_rows_per_cpu_s"] = m / cpu["s"]
        canon = os.path.join(tmp, "canonical.jsonl")
        with open(canon, "w") as f:
            for c in res["certificates"]:
                f.write(" ".join(c["scene_json"].split()) + "\n")
        cpu = {}
        dt = timed(lambda: subprocess.run(f"{o.cli} batch closure --jobs 1 < {canon} > /dev/null", shell=True,
                                          check=True), cpu)
        r["cli_certified_jobs1_scenes_per_s"] = m / dt
        r["cli_certified_jobs1_scenes_per_cpu_s"] = m / cpu["s"]
        r["cli_certified_over_arrays_certificates"] = (r["cli_certified_jobs1_scenes_per_cpu_s"] /
                                                      r["arrays_certificates_jobs1_rows_per_cpu_s"])
        print(f"certificates, {m} rows: arrays {r['arrays_certificates_jobs1_rows_per_s']:,.0f} rows/s, "
              f"batch closure {r['cli_certified_jobs1_scenes_per_s']:,.0f} scenes/s", flush=True)
        del res
        big = os.path.join(tmp, "dask.jsonl")
        with open(text) as f:
            block = f.read()
        with open(big, "w") as f:
            left = o.dask_lines
            while left > 0:
                take = min(left, o.cli_rows)
                f.write(block if take == o.cli_rows else "".join(block.splitlines(True)[:take]))
                left -= take
        for workers in (1, 2):
            cmd = [sys.executable, "-m", "wrenchkit.dask", "batch", "closure", "--workers", str(workers), big, "--",
                   "--verdict-only"]
            with open(os.devnull, "wb") as null:
                dt = timed(lambda: subprocess.run(cmd, check=True, stdout=null))
            r[f"dask_workers{workers}_lines_per_s"] = o.dask_lines / dt
            print(f"wrenchkit.dask --workers {workers}, {o.dask_lines} lines: {dt:.1f} s, "
                  f"{o.dask_lines / dt:,.0f} lines/s", flush=True)
        r["dask_workers2_over_workers1"] = r["dask_workers2_lines_per_s"] / r["dask_workers1_lines_per_s"]
    r["load_average_at_end"] = os.getloadavg()[0]
    print(json.dumps(r, indent=1))
    if o.out:
        with open(o.out, "w") as f:
            json.dump(r, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
