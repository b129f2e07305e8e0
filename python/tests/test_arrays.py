"""pytest: the array API and the streaming batch (docs/python.md, "Arrays", "Streams").

Row for row, closure_arrays / equilibrium_arrays / stick_slide_arrays equal wrenchkit.closure / equilibrium /
limit_surface on scenes built with Fraction(x) of the same doubles (random and near-degenerate arrays, fixed
seeds: a failure prints the seed and the row); bad arrays raise ValueError naming row, contact and value;
wrenchkit.batch writes the command line's bytes.
"""
import os
import subprocess
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import wrenchkit

SOURCE = Path(os.environ.get("WRENCHKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
GOLDEN = SOURCE / "tests" / "golden"
CLI = os.environ.get("WRENCHKIT_CLI")


def scene_of(points, normals, mu, n, load=None):
    s = {"contacts": [{"at": [Fraction(points[k][0]), Fraction(points[k][1])],
                       "normal": [Fraction(normals[k][0]), Fraction(normals[k][1])],
                       "mu": Fraction(mu[k])} for k in range(n)]}
    if load is not None:
        s["load"] = {"wrench": [Fraction(x) for x in load]}
    return s


def random_rows(seed, rows, width):
    """Generic doubles (uniform in [-1, 1], mu in [0, 1)) with ragged counts."""
    rng = np.random.default_rng(seed)
    p = rng.uniform(-1, 1, (rows, width, 2))
    n = rng.uniform(-1, 1, (rows, width, 2))
    mu = rng.uniform(0, 1, (rows, width))
    mu[rng.uniform(size=(rows, width)) < 0.1] = 0.0  # some frictionless contacts
    counts = rng.integers(0, width + 1, rows)
    return p, n, mu, counts


def degenerate_rows(seed, rows):
    """Near-degenerate doubles: two- and three-finger grasps exactly at their friction threshold and one ulp
    either side, contacts on small integer grids (concurrent and parallel lines, exact zeros), huge and tiny
    scales, and nearly antiparallel normals."""
    rng = np.random.default_rng(seed)
    p = np.zeros((rows, 4, 2))
    n = np.zeros((rows, 4, 2))
    mu = np.zeros((rows, 4))
    counts = np.zeros(rows, dtype=np.int64)
    for i in range(rows):
        kind = i % 4
        if kind == 0:  # two fingers (0, 0) and (1, s), normals ±x: closure iff mu > |s| (Nguyen)
            s = float(rng.choice([0.5, 0.25, 0.125, 0.75]))
            m = np.nextafter(s, [0, 1, 2][i // 4 % 3] * s) if i // 4 % 3 != 1 else s
            p[i, :2] = [[0, 0], [1, s]]
            n[i, :2] = [[1, 0], [-1, 0]]
            mu[i, :2] = m
            counts[i] = 2
        elif kind == 1:  # small integer grid: exact zeros everywhere
            p[i] = rng.integers(-2, 3, (4, 2))
            n[i] = rng.integers(-1, 2, (4, 2))
            n[i][(n[i] == 0).all(axis=1)] = [1, 0]
            mu[i] = rng.choice([0, 0.5, 1], 4)
            counts[i] = 4
        elif kind == 2:  # huge or tiny scale
            sc = float(rng.choice([1e200, 1e-200, 2.0 ** 900, 2.0 ** -1000]))
            p[i] = rng.integers(-3, 4, (4, 2)) * sc
            n[i] = rng.uniform(-1, 1, (4, 2))
            mu[i] = 0.25
            counts[i] = 4
        else:  # nearly antiparallel normals, one ulp apart
            a = rng.uniform(0.1, 1)
            p[i, :3] = [[0, 0], [1, 0], [0.5, 1]]
            n[i, :3] = [[1, a], [-1, -np.nextafter(a, 2)], [0, -1]]
            mu[i, :3] = rng.choice([0, 1e-16, 0.1])
            counts[i] = 3
    return p, n, mu, counts


def check_rows(p, n, mu, counts, seed, mode="hybrid"):
    r = wrenchkit.closure_arrays(p, n, mu, counts, mode=mode, certificates=True)
    for i in range(len(counts)):
        want = wrenchkit.closure(scene_of(p[i], n[i], mu[i], counts[i]), mode=mode)
        got = (bool(r["force_closure"][i]), bool(r["form_closure"][i]))
        assert got == (want["force_closure"], want["form_closure"]), f"seed {seed} row {i}: {p[i]} {n[i]} {mu[i]}"
        c = r["certificates"][i]
        assert c["certificate"] == want["certificate"], f"seed {seed} row {i}"
        assert c["form_certificate"] == want["form_certificate"], f"seed {seed} row {i}"
        scene = wrenchkit.Scene(c["scene_json"])
        assert scene.json == wrenchkit.Scene(scene_of(p[i], n[i], mu[i], counts[i])).json
        assert wrenchkit.check(scene, c["certificate_json"])["accepted"], f"seed {seed} row {i}"
    plain = wrenchkit.closure_arrays(p, n, mu, counts, mode=mode, jobs=2)
    assert (plain["force_closure"] == r["force_closure"]).all() and (plain["form_closure"] == r["form_closure"]).all()
    return r


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_closure_arrays_equal_closure_of_fraction_scenes_random(seed):
    check_rows(*random_rows(seed, 150, 6), seed)


@pytest.mark.parametrize("seed", [11, 12])
@pytest.mark.parametrize("mode", ["hybrid", "exact"])
def test_closure_arrays_equal_closure_of_fraction_scenes_near_degenerate(seed, mode):
    r = check_rows(*degenerate_rows(seed, 160), seed, mode)
    assert r["force_closure"].any() and not r["force_closure"].all()
    if mode == "exact":
        assert (r["decided_by"] == 2).all()


def test_thresholds_exactly_and_one_ulp_either_side():
    # Two fingers at (0, 0), (1, 1/2): force closure iff mu > 1/2, exactly, for the doubles next to 1/2.
    mus = [np.nextafter(0.5, 0), 0.5, np.nextafter(0.5, 1)]
    p = np.array([[[0, 0], [1, 0.5]]] * 3, dtype=float)
    n = np.array([[[1, 0], [-1, 0]]] * 3, dtype=float)
    mu = np.array([[m, m] for m in mus])
    r = wrenchkit.closure_arrays(p, n, mu)
    assert r["force_closure"].tolist() == [False, False, True]
    assert r["decided_by"].dtype == np.int8 and set(r["decided_by"].tolist()) <= set(wrenchkit.DECIDED_BY)


def test_a_double_is_its_binary_value_not_its_decimal_text():
    # Fingers at (0, 0) and (3, 0.3): in decimal the slope is 1/10 and mu "0.1" is exactly at the threshold (no
    # closure); as doubles the slope is 0.29999999999999998889…/3 < 0.1000000000000000055… = mu: closure.
    p = np.array([[[0, 0], [3, 0.3]]])
    n = np.array([[[1, 0], [-1, 0]]], dtype=float)
    assert wrenchkit.closure_arrays(p, n, 0.1)["force_closure"][0]
    assert wrenchkit.closure(scene_of(p[0], n[0], [0.1, 0.1], 2))["force_closure"]
    assert not wrenchkit.closure({"contacts": [{"at": [0, 0], "normal": [1, 0], "mu": "0.1"},
                                               {"at": [3, "0.3"], "normal": [-1, 0], "mu": "0.1"}]})["force_closure"]


@pytest.mark.parametrize("seed", [5, 6])
def test_equilibrium_arrays_equal_equilibrium_of_fraction_scenes(seed):
    p, n, mu, counts = random_rows(seed, 120, 5)
    loads = np.random.default_rng(seed).uniform(-1, 1, (120, 3))
    loads[::7] = 0.0
    r = wrenchkit.equilibrium_arrays(p, n, mu, loads, counts, certificates=True)
    for i in range(120):
        want = wrenchkit.equilibrium(scene_of(p[i], n[i], mu[i], counts[i], loads[i]))
        assert bool(r["balanced"][i]) == want["balanced"], f"seed {seed} row {i}"
        assert r["certificates"][i]["certificate"] == want["certificate"], f"seed {seed} row {i}"
    assert r["balanced"].any() and not r["balanced"].all()


def test_stick_slide_arrays_equal_limit_surface_motion():
    rng = np.random.default_rng(21)
    rows = 12
    p = rng.uniform(-1, 1, (rows, 4, 2))
    f = rng.uniform(0.1, 1, (rows, 4))
    counts = np.array([4, 3, 2, 1] * 3)
    loads = rng.uniform(-1, 1, (rows, 3)) * rng.choice([0.2, 3.0], (rows, 1))
    r = wrenchkit.stick_slide_arrays(p, f, 0.5, loads, counts, certificates=True)
    for i in range(rows):
        scene = {"support": {"points": [{"at": [Fraction(p[i, k, 0]), Fraction(p[i, k, 1])], "force": Fraction(f[i, k]),
                                         "mu": Fraction(0.5)} for k in range(counts[i])]}}
        want = wrenchkit.limit_surface(scene, 32, load=[Fraction(x) for x in loads[i]])
        assert wrenchkit.MOTION[int(r["motion"][i])] == want["motion"], f"row {i}"
        assert wrenchkit.MOTION_DECIDED_BY[int(r["motion_decided_by"][i])] == want["motion_decided_by"], f"row {i}"
        c = r["certificates"][i]
        if c["certificate_json"]:
            assert wrenchkit.check(wrenchkit.Scene(c["scene_json"]), c["certificate_json"])["accepted"]
    assert set(r["motion"].tolist()) == {0, 1}


def test_ragged_rows_ignore_what_lies_beyond_their_count():
    p, n, mu, counts = random_rows(8, 40, 6)
    p2, n2 = p.copy(), n.copy()
    for i, c in enumerate(counts):
        p2[i, c:] = np.nan
        n2[i, c:] = 0.0
    a = wrenchkit.closure_arrays(p, n, mu, counts)
    b = wrenchkit.closure_arrays(p2, n2, mu, counts)
    assert (a["force_closure"] == b["force_closure"]).all() and (a["form_closure"] == b["form_closure"]).all()


def test_integer_and_float32_arrays_are_read_exactly():
    p = np.array([[[0, 0], [1, 0]]], dtype=np.int32)
    n = np.array([[[1, 0], [-1, 0]]], dtype=np.float32)
    r = wrenchkit.closure_arrays(p, n, 1)
    assert r["force_closure"][0] and not r["form_closure"][0]  # two fingers on one line, mu = 1 (Nguyen)
    q = wrenchkit.closure_arrays(p, n.astype(np.float64), np.array([[1.0, 1.0]], dtype=np.float32))
    assert q["force_closure"][0] and not q["form_closure"][0]


@pytest.mark.parametrize("change, message", [
    (lambda a: a.update(points=a["points"][:, :, :1]), "points: shape (3, 4, 1) is not (any, any, 2)"),
    (lambda a: a.update(normals=a["normals"][:2]), "normals: shape (2, 4, 2) is not (3, 4, 2)"),
    (lambda a: a.update(points=a["points"].astype(complex)), "points: dtype complex128 is not a real"),
    (lambda a: a.update(mu=np.ones((3, 4), dtype=bool)), "mu: dtype bool is not a real"),
    (lambda a: a["points"].__setitem__((2, 1, 0), np.nan), "points: row 2, contact 1, coordinate 0: nan is not a finite"),
    (lambda a: a["normals"].__setitem__((1, 3, 1), np.inf), "normals: row 1, contact 3, coordinate 1: inf is not a finite"),
    (lambda a: a["normals"].__setitem__((1, 2), 0.0), "normals: row 1, contact 2: (0.0, 0.0) is a zero normal"),
    (lambda a: a["mu"].__setitem__((0, 3), -0.5), "mu: row 0, contact 3: -0.5 is negative"),
    (lambda a: a.update(counts=np.array([4, 5, 1])), "counts: row 1: 5 is not a contact count between 0 and 4"),
    (lambda a: a.update(points=np.array([[[2 ** 60 + 1, 0]] * 4] * 3)), "is not exactly a double"),
])
def test_bad_arrays_raise_value_error_naming_row_contact_and_value(change, message):
    rng = np.random.default_rng(0)
    a = {"points": rng.uniform(-1, 1, (3, 4, 2)), "normals": rng.uniform(-1, 1, (3, 4, 2)),
         "mu": np.full((3, 4), 0.5), "counts": None}
    change(a)
    with pytest.raises(ValueError) as e:
        wrenchkit.closure_arrays(a["points"], a["normals"], a["mu"], a["counts"])
    assert message in str(e.value)
    with pytest.raises(ValueError):
        wrenchkit.closure_arrays(np.zeros((1, 1, 2)), np.ones((1, 1, 2)), 0, mode="fast")
    with pytest.raises(ValueError, match="all forces are zero"):
        wrenchkit.stick_slide_arrays(np.zeros((2, 2, 2)), np.array([[1.0, 0], [0, 0]]), 0.5, np.zeros((2, 3)))
    with pytest.raises(ValueError, match="loads: row 0, contact 2: nan"):
        wrenchkit.equilibrium_arrays(np.zeros((1, 1, 2)), np.ones((1, 1, 2)), 0, np.array([[0, 0, np.nan]]))


def test_empty_batches():
    r = wrenchkit.closure_arrays(np.zeros((0, 3, 2)), np.zeros((0, 3, 2)), 0.5)
    assert r["force_closure"].shape == (0,)


# ---- streams ------------------------------------------------------------------------------------------

def cli_batch(args, text):
    return subprocess.run([CLI, "batch", *args], input=text, capture_output=True, check=False).stdout


@pytest.mark.skipif(not CLI, reason="needs WRENCHKIT_CLI (CTest sets it)")
@pytest.mark.parametrize("args", [["closure"], ["closure", "--verdict-only", "--mode", "exact"], ["equilibrium"],
                                  ["labels"], ["limit-surface", "--sides", "8"], ["analyze"]])
def test_batch_is_the_command_lines_bytes(args):
    scenes = sorted(GOLDEN.rglob("*.scene.json"))
    lines = [" ".join(s.read_text().split()) for s in scenes]
    lines += ["not json", "", '{"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 0]}]}']
    text = "".join(line + "\n" for line in lines).encode()
    want = cli_batch(args, text)
    for chunk in (None, 7):
        got = "".join(line + "\n" for line in wrenchkit.batch(args[0], lines, *args[1:], chunk=chunk, jobs=2))
        assert got.encode() == want, args
    assert list(wrenchkit.batch(args[0], (lines[i].encode() + b"\n" for i in range(3)), *args[1:])) == \
        want.decode().splitlines()[:3]


def test_batch_dicts_keywords_and_line_numbers():
    s = {"contacts": [{"at": [0, "1/2"], "normal": [1, 0], "mu": Fraction(1, 10)},
                      {"at": [1, "1/2"], "normal": [-1, 0], "mu": 0.1}]}
    out = list(wrenchkit.batch("closure", [s, s], mode="exact", verdict_only=True, first_line=41))
    assert out[0].startswith('{"line": 41, "command": "closure"') and out[1].startswith('{"line": 42,')
    assert '"force_closure": true' in out[0]
    assert list(wrenchkit.batch("closure", [wrenchkit.Scene(s)], mode="exact", verdict_only=True, first_line=41)) == out[:1]
    with pytest.raises(wrenchkit.InputError, match="--sides is not an option of batch closure"):
        list(wrenchkit.batch("closure", [s], sides=8))
    with pytest.raises(wrenchkit.InputError, match="not a command that answers per scene"):
        list(wrenchkit.batch("check", [s]))


def test_float_mode_marks_undecided_rows_and_agrees_where_it_decides():
    # Three frictionless contacts whose normal lines nearly meet at the origin (1e-15 off): the twin alone
    # cannot certify some of them; those rows are -1 (verdicts False, no certificate), as closure() raises.
    rng = np.random.default_rng(3)
    rows = 300
    ang, rad = rng.uniform(0, 2 * np.pi, (rows, 3)), rng.uniform(0.5, 2, (rows, 3))
    p = np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=-1)
    n = np.stack([-np.cos(ang) + rng.normal(0, 1e-15, (rows, 3)), -np.sin(ang)], axis=-1)
    f = wrenchkit.closure_arrays(p, n, 0.0, mode="float", certificates=True)
    h = wrenchkit.closure_arrays(p, n, 0.0)
    undecided = f["decided_by"] == -1
    assert 0 < undecided.sum() < rows
    assert (f["force_closure"][undecided] == False).all() and all(f["certificates"][i] is None for i in np.flatnonzero(undecided))  # noqa: E712
    assert (f["force_closure"][~undecided] == h["force_closure"][~undecided]).all()
    for i in range(60):
        s = scene_of(p[i], n[i], [0.0] * 3, 3)
        if undecided[i]:
            with pytest.raises(wrenchkit.UndecidedError):
                wrenchkit.closure(s, mode="float")
        else:
            assert wrenchkit.closure(s, mode="float")["force_closure"] == bool(f["force_closure"][i])
    # Equilibrium in float mode abstains on rank < 3 (one frictionless contact); hybrid decides exactly.
    pts, nrm, loads = np.zeros((2, 1, 2)), np.array([[[0, 1.0]], [[0, 1.0]]]), np.array([[0, -1, 0], [0, 1, 0.0]])
    assert wrenchkit.equilibrium_arrays(pts, nrm, 0, loads, mode="float")["decided_by"].tolist() == [-1, -1]
    assert wrenchkit.equilibrium_arrays(pts, nrm, 0, loads)["balanced"].tolist() == [True, False]
