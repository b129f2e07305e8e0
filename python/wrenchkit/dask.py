"""wrenchkit batch on a Dask cluster (Debian: python3-dask, python3-distributed). docs/python.md, "Dask".

    python3 -m wrenchkit.dask batch COMMAND [--workers N | --scheduler ADDRESS] [--lines-per-part L]
        IN.jsonl [IN2.jsonl ...] [-- COMMAND'S OPTIONS ...]

writes to standard output exactly the lines of `cat IN.jsonl IN2.jsonl | wrenchkit batch COMMAND [OPTIONS]`
(files that end with a newline), in the same order. The input is cut into parts of whole lines; each part is
one Dask task that runs wrenchkit.batch (the command line's own batch lines) numbered from the part's first
line. Tasks are pure functions of their part, so a worker that dies mid-run loses nothing: Dask reruns its
tasks elsewhere, and the client writes each part once, in order. Input paths must be readable by the workers.

    wrenchkit.dask.batch(command, paths_or_bag, *options, client=None, lines_per_part=20000, **keywords)

returns a dask.bag of the output lines (str) in order, from paths (one or a list) or from a dask.bag of scenes
(dicts, JSON lines, Scenes); with a client, the parts' futures in order (each a list of lines).
"""

import argparse
import os
import sys

import dask
import dask.bag

import wrenchkit

__all__ = ["batch", "parts"]


def _line_count(path, start, end):
    """The number of lines in the bytes [start, end) of path (each part starts at a line's first byte)."""
    with open(path, "rb") as f:
        f.seek(start)
        data = f.read(end - start)
    return data.count(b"\n") + (1 if data and not data.endswith(b"\n") else 0)


def parts(path, lines_per_part=20000, sample=1 << 20):
    """[start, end) byte ranges of path, each of whole lines, about lines_per_part lines each."""
    size = os.path.getsize(path)
    if size == 0:
        return []
    with open(path, "rb") as f:
        head = f.read(min(size, sample))
        per_line = max(1, len(head) // max(1, head.count(b"\n")))
        step = max(1, per_line * lines_per_part)
        cuts = [0]
        while cuts[-1] + step < size:
            f.seek(cuts[-1] + step)
            rest = f.readline()  # to the end of the line under the cut
            nxt = f.tell()
            if not rest or nxt >= size:
                break
            cuts.append(nxt)
        cuts.append(size)
    return list(zip(cuts[:-1], cuts[1:]))


def _read_lines(path, start, end):
    with open(path, "rb") as f:
        f.seek(start)
        data = f.read(end - start)
    lines = data.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    return lines


def _run_range(command, words, path, start, end, first_line):
    return list(wrenchkit.batch(command, _read_lines(path, start, end), *words, jobs=1, first_line=first_line))


def _run_range_bytes(command, words, path, start, end, first_line):
    """The part's output as the command line writes it (lines and newlines), without a Python str per line."""
    lines, code = wrenchkit._core.Batch([command] + words).run(_read_lines(path, start, end), first_line, 1)
    if code:
        raise wrenchkit.InternalError(f"batch {command}: the command line would exit {code} on lines from {first_line}")
    return b"".join(line + b"\n" for line in lines)


def _run_list(command, words, scenes, first_line):
    return list(wrenchkit.batch(command, scenes, *words, jobs=1, first_line=first_line))


def _offsets(counts):
    first, out = 1, []
    for c in counts:
        out.append(first)
        first += c
    return out


def _parts(command, words, paths_or_bag, lines_per_part, run):
    """One dask.delayed per part: run(command, words, <the part>, first_line) after the parts' line counts."""
    if isinstance(paths_or_bag, dask.bag.Bag):
        pieces = paths_or_bag.to_delayed()
        counts = [dask.delayed(len)(p) for p in pieces]
        first = dask.delayed(_offsets)(counts)
        return [dask.delayed(_run_list, pure=True)(command, words, p, first[k]) for k, p in enumerate(pieces)]
    paths = [paths_or_bag] if isinstance(paths_or_bag, (str, os.PathLike)) else list(paths_or_bag)
    ranges = [(os.fspath(p), s, e) for p in paths for s, e in parts(os.fspath(p), lines_per_part)]
    counts = [dask.delayed(_line_count, pure=True)(p, s, e) for p, s, e in ranges]
    first = dask.delayed(_offsets)(counts)
    return [dask.delayed(run, pure=True)(command, words, p, s, e, first[k]) for k, (p, s, e) in enumerate(ranges)]


def batch(command, paths_or_bag, *options, client=None, lines_per_part=20000, **keywords):
    """The lines of `wrenchkit batch COMMAND OPTIONS` on the input, in order (module docstring): a dask.bag (one
    partition per part), or with `client` the parts submitted to it: a list of futures in order, each with its
    part's lines. Options are checked here, before anything is computed (InputError as wrenchkit.batch).
    """
    words = wrenchkit._batch_options(options, keywords)
    wrenchkit._core.Batch([command] + words)  # usage errors now, not on a worker
    out = _parts(command, words, paths_or_bag, lines_per_part, _run_range)
    if client is not None:
        return client.compute(out)
    return dask.bag.from_delayed(out) if out else dask.bag.from_sequence([], npartitions=1)


def _write_in_order(client, parts, out):
    """Compute the parts (bytes) on the client's workers and write them in order, each once."""
    futures = client.compute(parts)
    for f in futures:
        out.write(f.result())
        f.release()
    out.flush()


def main(argv=None):
    from dask.distributed import Client, LocalCluster

    p = argparse.ArgumentParser(prog="python3 -m wrenchkit.dask",
                                description="wrenchkit batch COMMAND on a Dask cluster: the same lines in the same "
                                            "order as `cat IN... | wrenchkit batch COMMAND [OPTIONS]`.")
    p.add_argument("batch", choices=["batch"])
    p.add_argument("command")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=None, help="a LocalCluster of N worker processes (default: cores)")
    where.add_argument("--scheduler", default=None, help="the address of a running Dask scheduler")
    p.add_argument("--lines-per-part", type=int, default=20000, help="lines per task (default 20000)")
    p.add_argument("inputs", nargs="+", help="JSON-lines files, then -- and the command's options")
    argv = sys.argv[1:] if argv is None else argv
    words = []
    if "--" in argv:
        k = argv.index("--")
        argv, words = argv[:k], argv[k + 1:]
    a = p.parse_args(argv)
    try:
        wrenchkit._core.Batch([a.command] + words)  # usage errors before any cluster starts
        parts_ = _parts(a.command, words, a.inputs, a.lines_per_part, _run_range_bytes)
    except (ValueError, OSError) as e:
        print(f"wrenchkit.dask: {e}", file=sys.stderr)
        return 2
    if a.scheduler:
        client = Client(a.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=a.workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        _write_in_order(client, parts_, sys.stdout.buffer)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
