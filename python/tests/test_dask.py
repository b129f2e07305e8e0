"""pytest: wrenchkit batch on a Dask LocalCluster of 2 worker processes (CTest python_dask; docs/python.md, "Dask").

`python3 -m wrenchkit.dask batch ...` and wrenchkit.dask.batch write the command line's lines in its order,
byte for byte, also when a worker process is killed (SIGKILL) during the run: Dask reruns its parts, and
nothing is lost or written twice.
"""
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

dask = pytest.importorskip("dask")
distributed = pytest.importorskip("distributed")
import dask.bag  # noqa: E402

import wrenchkit  # noqa: E402
import wrenchkit.dask  # noqa: E402

SOURCE = Path(os.environ.get("WRENCHKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("WRENCHKIT_CLI")
pytestmark = pytest.mark.skipif(not CLI, reason="needs WRENCHKIT_CLI (CTest sets it)")


def write_input(path, rows, seed):
    """Random six-contact grasps (doubles, as a sampler writes them), golden scenes and bad lines."""
    rng = np.random.default_rng(seed)
    lines = [" ".join(s.read_text().split()) for s in sorted((SOURCE / "tests" / "golden").glob("*.scene.json"))]
    for i in range(rows):
        p, n = rng.uniform(-1, 1, (6, 2)), rng.uniform(-1, 1, (6, 2))
        lines.append(json.dumps({"wrenchkit": 1, "name": f"g{i}", "contacts": [
            {"at": p[k].tolist(), "normal": n[k].tolist(), "mu": 0.3} for k in range(6)]}))
    lines[len(lines) // 2] = "not json"
    path.write_text("".join(line + "\n" for line in lines))
    return path


def cli_batch(args, paths):
    data = b"".join(Path(p).read_bytes() for p in paths)
    return subprocess.run([CLI, "batch", *args], input=data, capture_output=True, check=True).stdout


@pytest.fixture(scope="module")
def client():
    from dask.distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_command_line_equals_wrenchkit_batch(tmp_path):
    a = write_input(tmp_path / "a.jsonl", 700, 1)
    b = write_input(tmp_path / "b.jsonl", 300, 2)
    want = cli_batch(["closure", "--mode", "exact"], [a, b])
    env = dict(os.environ)
    got = subprocess.run([sys.executable, "-m", "wrenchkit.dask", "batch", "closure", "--workers", "2",
                          "--lines-per-part", "97", str(a), str(b), "--", "--mode", "exact"],
                         capture_output=True, check=True, env=env).stdout
    assert got == want
    bad = subprocess.run([sys.executable, "-m", "wrenchkit.dask", "batch", "closure", "--workers", "2", str(a), "--",
                          "--sides", "8"], capture_output=True, env=env)
    assert bad.returncode == 2 and b"--sides is not an option of batch closure" in bad.stderr


def test_bag_of_scenes_and_of_files(client, tmp_path):
    a = write_input(tmp_path / "a.jsonl", 400, 3)
    want = cli_batch(["equilibrium"], [a]).decode().splitlines()
    lines = a.read_text().splitlines()
    got = wrenchkit.dask.batch("equilibrium", dask.bag.from_sequence(lines, npartitions=7)).compute()
    assert got == want
    assert wrenchkit.dask.batch("equilibrium", str(a), lines_per_part=50).compute() == want
    futures = wrenchkit.dask.batch("equilibrium", [str(a)], lines_per_part=50, client=client)
    assert len(futures) > 5 and [line for f in futures for line in f.result()] == want


def test_a_killed_worker_loses_and_duplicates_nothing(client, tmp_path):
    a = write_input(tmp_path / "a.jsonl", 6000, 4)
    want = cli_batch(["closure"], [a])
    futures = client.compute(wrenchkit.dask.batch("closure", str(a), lines_per_part=150).to_delayed())
    while not any(f.done() for f in futures):
        time.sleep(0.01)
    pending = sum(not f.done() for f in futures)
    victim = next(iter(client.run(os.getpid).values()))
    os.kill(victim, signal.SIGKILL)
    out = b"".join(line.encode() + b"\n" for f in futures for line in f.result())
    assert pending > 0, "the run ended before the worker was killed: nothing was tested"
    assert out == want


def test_the_command_line_on_a_running_cluster_survives_a_killed_worker(client, tmp_path):
    # python3 -m wrenchkit.dask --scheduler ADDRESS: once its first lines are out, a worker process is killed.
    a = write_input(tmp_path / "a.jsonl", 6000, 5)
    want = cli_batch(["closure"], [a])
    run = subprocess.Popen([sys.executable, "-m", "wrenchkit.dask", "batch", "closure", "--scheduler",
                            client.scheduler.address, "--lines-per-part", "150", str(a)], stdout=subprocess.PIPE)
    first = run.stdout.read(1)
    victim = next(iter(client.run(os.getpid).values()))
    os.kill(victim, signal.SIGKILL)
    rest = run.stdout.read()
    assert run.wait() == 0
    assert len(rest) > len(want) // 2, "the run was nearly over when the worker was killed: nothing was tested"
    assert first + rest == want
