"""pytest suite of the wrenchkit Python package (run by CTest as python_pytest; docs/python.md).

Golden cases of theory.md (block in a corner, the ladder's mu* = 1/7, two-finger grasps, the barbell),
exact number reading from every Python type, certificates through the independent checker, errors
with the command line's messages.
"""
import json
import os
import subprocess
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest

import wrenchkit

SOURCE = Path(os.environ.get("WRENCHKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
GOLDEN = SOURCE / "tests" / "golden"
CLI = os.environ.get("WRENCHKIT_CLI")


def two_fingers(y2, mu):
    return {"contacts": [{"at": [0, "1/2"], "normal": [1, 0], "mu": mu},
                         {"at": [1, y2], "normal": [-1, 0], "mu": mu}]}


# ---- golden textbook cases --------------------------------------------------------------------------

def test_two_finger_grasp_closes_iff_mu_exceeds_the_slope():
    # d = (1, y2 - 1/2): force closure iff mu > |y2 - 1/2| (Nguyen); exactly at the slope it is not.
    assert wrenchkit.closure(two_fingers("1/2", "1/10"))["force_closure"] is True
    assert wrenchkit.closure(two_fingers(1, "1/2"))["force_closure"] is False
    assert wrenchkit.closure(two_fingers(1, "0.5000000000000000000000000000000000000001"))["force_closure"] is True
    r = wrenchkit.closure(two_fingers("1/2", Fraction(1, 10)))
    assert r["form_closure"] is False and r["rank"] == {"force": 3, "form": 1}


@pytest.mark.parametrize("scene_file", sorted(p.name for p in GOLDEN.glob("*.scene.json")))
def test_every_closure_golden_matches_its_expected_file(scene_file):
    expected = json.loads((GOLDEN / scene_file.replace(".scene.", ".expected.")).read_text())
    r = wrenchkit.closure(GOLDEN / scene_file, mode="exact")
    assert r["force_closure"] == expected["force_closure"]
    assert r["form_closure"] == expected["form_closure"]
    assert r["rank"] == expected["rank"]
    for key in ("certificate", "form_certificate"):
        assert wrenchkit.check(GOLDEN / scene_file, r[key]) == {"accepted": True, "reason": ""}
        assert wrenchkit.check(GOLDEN / scene_file, r[key + "_json"])["accepted"]


@pytest.mark.parametrize("scene_file", sorted(p.name for p in (GOLDEN / "equilibrium").glob("*.scene.json")))
def test_every_equilibrium_golden(scene_file):
    path = GOLDEN / "equilibrium" / scene_file
    expected = json.loads(path.with_name(scene_file.replace(".scene.", ".expected.")).read_text())
    r = wrenchkit.equilibrium(path)
    assert r["balanced"] == expected["balanced"]
    assert wrenchkit.check(path, r["certificate"])["accepted"]


EXAMPLES = SOURCE / "proofs" / "examples"


@pytest.mark.parametrize("name,holds", [("fixture_pin_push", True), ("fixture_pin_lift", False),
                                        ("fixture_pin_pull", "impending"), ("table_pinned_nudged", True),
                                        ("table_pinned_shoved", False), ("table_pinned_pushed", "depends"),
                                        ("square_region_pin_push", True), ("square_region_pin_turn", False)])
def test_hold_of_the_worked_fixtures(name, holds):
    path = EXAMPLES / f"{name}.scene.json"
    for mode in ("hybrid", "exact"):
        r = wrenchkit.hold(path, mode=mode)
        assert r["holds"] == holds
        assert wrenchkit.check(path, r["certificate"])["accepted"]
        assert wrenchkit.check(path, r["certificate_json"])["accepted"]
    if holds is False:
        assert r["motion"]["kind"] in ("rotation", "translation")
    if name.startswith("square_region"):  # hold over a support region: the certificate carries its cells
        assert r["regions"] == 1 and r["region_cells"] > 0 and '"regions"' in r["certificate_json"]


def test_hold_reads_the_motion_and_agrees_with_the_command():
    r = wrenchkit.hold(EXAMPLES / "fixture_pin_lift.scene.json", mode="exact")
    assert r["motion"]["kind"] == "rotation" and r["motion"]["center"] == (Fraction(-1), Fraction(0))
    assert r["motion"]["sense"] == "counter-clockwise"
    scene = json.loads((EXAMPLES / "fixture_pin_push.scene.json").read_text())
    held = wrenchkit.hold(scene)
    assert held["holds"] is True and len(held["support_forces"]) == 4
    with pytest.raises(wrenchkit.UndecidedError):
        wrenchkit.hold(EXAMPLES / "table_pinned_pushed.scene.json", mode="float")
    with pytest.raises(wrenchkit.InputError, match="load: the scene has no load"):
        wrenchkit.hold({"contacts": [{"at": [0, 0], "normal": [0, 1]}]})
    if CLI:
        out = subprocess.run([CLI, "hold", "--json", str(EXAMPLES / "fixture_pin_lift.scene.json")],
                             capture_output=True, text=True, check=True).stdout
        assert json.loads(out)["certificate"] == wrenchkit.hold(EXAMPLES / "fixture_pin_lift.scene.json")["certificate"]


def ladder(mu):
    return {"body": {"com": ["-1/2", "7/2"]},
            "contacts": [{"at": [0, 0], "normal": [0, 1], "mu": mu}, {"at": [-4, 3], "normal": [1, 0], "mu": mu}],
            "load": {"gravity": 1}}


def test_ladder_stands_iff_mu_at_least_one_seventh():
    # theory.md section 9: the leaning square stands iff mu >= 1/7, exactly, also at 1/7 +- 10^-40.
    assert wrenchkit.equilibrium(ladder(Fraction(1, 7)))["balanced"] is True
    assert wrenchkit.equilibrium(ladder(Fraction(1, 8)))["balanced"] is False
    tiny = Fraction(1, 10**40)
    assert wrenchkit.equilibrium(ladder(Fraction(1, 7) + tiny))["balanced"] is True
    assert wrenchkit.equilibrium(ladder(Fraction(1, 7) - tiny))["balanced"] is False
    r = wrenchkit.equilibrium(ladder("1/7"), mode="exact")
    assert r["load"] == (0, -1, Fraction(1, 2))
    weights = {(t["contact"], t["edge"]): t["weight"] for t in r["certificate"]["combination"]}
    assert all(isinstance(w, Fraction) and w > 0 for w in weights.values())
    # The weights balance the load exactly: sum of w * generator + load = 0, recomputed here.
    total = [Fraction(0)] * 3
    gens = {(0, "left"): (-Fraction(1, 7), 1, 0), (0, "right"): (Fraction(1, 7), 1, 0),
            (1, "left"): (1, Fraction(1, 7)), (1, "right"): (1, -Fraction(1, 7))}
    for (c, e), w in weights.items():
        f = gens[(c, e)]
        p = (0, 0) if c == 0 else (-4, 3)
        wrench = (f[0], f[1], p[0] * f[1] - p[1] * f[0])
        total = [t + w * x for t, x in zip(total, wrench)]
    assert [t + l for t, l in zip(total, r["load"])] == [0, 0, 0]


def block_in_corner(mu):
    return {"body": {"com": ["1/2", "1/2"]},
            "contacts": [{"at": [0, 0], "normal": [0, 1], "mu": mu}, {"at": [1, 0], "normal": [0, 1], "mu": mu},
                         {"at": [0, 0], "normal": [1, 0], "mu": mu}, {"at": [0, 1], "normal": [1, 0], "mu": mu}]}


def test_block_in_a_corner_labels():
    # Frictionless block in a corner (theory.md section 5): + region the wedge at (0, 1) opening to
    # (0, 1) and (-1, 0); - region the wedge at (1, 0); translations up-left at infinity.
    lab = wrenchkit.labels(block_in_corner(0))
    assert lab["force_closure"] is False
    assert lab["plus"]["shape"] == "wedge" and lab["plus"]["vertices"] == [(0, 1)]
    assert lab["plus"]["directions"] == [(0, 1), (-1, 0)]
    assert lab["minus"]["vertices"] == [(1, 0)]
    assert lab["infinity"] == [{"from": (0, 1), "to": (-1, 0)}]
    assert all(isinstance(x, Fraction) for v in lab["plus"]["vertices"] for x in v)
    # With mu = 1/2 the + corner moves to (-2/3, 4/3).
    assert wrenchkit.labels(block_in_corner("1/2"))["plus"]["vertices"] == [(Fraction(-2, 3), Fraction(4, 3))]
    # Reuleaux reading: the same contacts frictionless.
    assert wrenchkit.labels(block_in_corner("1/2"), reading="frictionless")["plus"]["vertices"] == [(0, 1)]


def test_block_in_a_corner_under_a_push():
    s = dict(block_in_corner("1/2"), load={"force": [0, -1], "at": [1, 1]})
    assert wrenchkit.equilibrium(s)["balanced"] is True
    assert wrenchkit.labels(s)["load"]["balanced"] is True


def test_dual_covers_all_iff_force_closure():
    assert wrenchkit.dual(two_fingers("1/2", "1/10"))["covers_all"] is True
    d = wrenchkit.dual(block_in_corner(0))
    assert d["covers_all"] is False
    assert len(d["generators"]) == 4 and d["generators"][0]["dual"]["sheet"] in ("+", "-", "infinity")


BARBELL = {"support": {"mu": 1, "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": "1/2"}]}}


def test_barbell_limit_surface_and_sliding():
    # theory.md section 14.2: translation load mu*f0 = 1; rotation about the centre: moment 1.
    ls = wrenchkit.limit_surface(BARBELL, 32, twist=(0, 0, 1), load=(0, 0, "1/2"))
    lam2 = ls["lambda_squared"]
    assert isinstance(lam2, Fraction) and Fraction(99, 100) < lam2 < 1
    assert ls["h_inner"] <= 1 <= ls["h_outer"]
    assert ls["motion"] == "sticks"
    assert wrenchkit.limit_surface(BARBELL, 32, load=(0, 0, 2))["motion"] == "slides"
    assert ls["inner"]["facets"] > 0 and ls["outer"]["vertices"] > 0
    t = wrenchkit.sliding(BARBELL, twist=(1, 0, 0))
    assert t["motion"] == "translation" and t["load"] == (1, 0, 0)
    r = wrenchkit.sliding(BARBELL, twist=(0, 0, 1))
    assert r["power_bracket"] == (1, 1)
    assert r["center_of_friction"] == (0, 0)
    assert wrenchkit.limit_surface(BARBELL, tolerance="0.01")["sides"] >= 4


# ---- exact numbers from Python values ---------------------------------------------------------------

def test_numbers_are_read_exactly_from_their_text():
    canon = wrenchkit.Scene(two_fingers("1/2", "1/10")).json
    for mu in ("0.1", Fraction(1, 10), Decimal("0.1"), 0.1, "1e-1"):
        assert wrenchkit.Scene(two_fingers("1/2", mu)).json == canon, mu
    # Fraction(0.1) is the double's exact binary value, a different scene.
    assert "3602879701896397/36028797018963968" in wrenchkit.Scene(two_fingers("1/2", Fraction(0.1))).json
    assert wrenchkit.Scene(two_fingers(Fraction(1, 2), 1)).json == wrenchkit.Scene(two_fingers("0.5", "1")).json


def test_scene_from_json_text_and_path(tmp_path):
    text = json.dumps({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1]}]})
    p = tmp_path / "s.json"
    p.write_text(text)
    assert wrenchkit.Scene(text).json == wrenchkit.Scene(p).json == wrenchkit.Scene(str(p)).json
    assert len(wrenchkit.Scene(p)) == 1


def test_numpy_numbers_if_available():
    np = pytest.importorskip("numpy")
    a = wrenchkit.Scene(two_fingers(np.int64(1), np.float64(0.5))).json
    assert a == wrenchkit.Scene(two_fingers(1, "0.5")).json


# ---- certificates and the checker ------------------------------------------------------------------

def test_a_tampered_certificate_is_rejected_with_a_reason():
    s = wrenchkit.Scene(two_fingers("1/2", "1/10"))
    cert = wrenchkit.closure(s)["certificate"]
    assert cert["holds"] is True
    bad = json.loads(json.dumps(cert, default=str))
    bad["combination"][0]["weight"] = str(cert["combination"][0]["weight"] * 2)
    r = wrenchkit.check(s, bad)
    assert r["accepted"] is False and r["reason"]


def test_float_mode_may_be_undecided():
    # Exactly on the cone edge: the twin cannot certify a zero of decimal input that is not a double.
    s = two_fingers("0.6", "0.1")
    with pytest.raises(wrenchkit.UndecidedError, match="float twin could not certify"):
        wrenchkit.closure(s, mode="float")
    assert wrenchkit.closure(s, mode="hybrid")["force_closure"] is False


# ---- errors: InputError with the command line's message ---------------------------------------------

BAD = [
    ({"contacts": [{"at": [0, 0], "normal": [0, 0]}]}, "contacts[0].normal: zero vector"),
    ({"contacts": [{"at": [0, 0], "normal": [0, 1], "mu": "-1/2"}]}, "contacts[0].mu"),
    ({"contacts": [{"at": [0, 0], "normal": [0, 1], "mu": "abc"}]}, 'contacts[0].mu: "abc" is not a number'),
    ({"contacts": [{"at": [0, 0], "normal": [0, 1], "muu": 1}]}, "muu"),
    ({"contacts": [{"at": [0, 0], "normal": [0, 1], "mu": "1/0"}]}, "contacts[0].mu"),
]


@pytest.mark.parametrize("scene,message", BAD)
def test_bad_scenes_raise_input_error(scene, message):
    with pytest.raises(wrenchkit.InputError, match=None) as e:
        wrenchkit.Scene(scene)
    assert message in str(e.value)
    assert isinstance(e.value, ValueError)


@pytest.mark.skipif(not CLI, reason="WRENCHKIT_CLI not set")
@pytest.mark.parametrize("scene,message", BAD)
def test_messages_are_the_command_lines(scene, message, tmp_path):
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(json.loads(wrenchkit._to_json(dict({"wrenchkit": 1}, **scene)))))
    cli = subprocess.run([CLI, "closure", str(p)], capture_output=True, text=True)
    assert cli.returncode == 2
    with pytest.raises(wrenchkit.InputError) as e:
        wrenchkit.Scene(p)
    assert cli.stderr.strip() == "wrenchkit: error: " + str(e.value)


def test_other_input_errors():
    with pytest.raises(wrenchkit.InputError, match="load: "):
        wrenchkit.equilibrium(two_fingers("1/2", "1/10"))
    with pytest.raises(wrenchkit.InputError, match='support: the scene has no "support"'):
        wrenchkit.limit_surface(two_fingers("1/2", "1/10"))
    with pytest.raises(wrenchkit.InputError, match="sides: 5 must be even"):
        wrenchkit.limit_surface(BARBELL, 5)
    with pytest.raises(wrenchkit.InputError, match="twist: the zero twist"):
        wrenchkit.sliding(BARBELL, twist=(0, 0, 0))
    with pytest.raises(wrenchkit.InputError, match='mode: "fast" is not one of'):
        wrenchkit.closure(two_fingers(1, 1), mode="fast")
    with pytest.raises(wrenchkit.InputError, match="nan is not a finite number"):
        wrenchkit.Scene(two_fingers(1, float("nan")))
    with pytest.raises(wrenchkit.InputError, match="cannot open"):
        wrenchkit.Scene("/nonexistent/scene.json")
    with pytest.raises(wrenchkit.InputError, match="invalid JSON"):
        wrenchkit.Scene('{"wrenchkit": 1,')
    with pytest.raises(wrenchkit.InputError, match="max_contacts|contacts"):
        wrenchkit.Scene(two_fingers(1, 1), limits={"max_contacts": 1})


def test_the_scene_budget_and_its_limits_keys():
    # issue 21: 10 numbers of 3 digits ("1/2" counts 2, "101" 3) in two contacts; the budget names its option.
    s = {"contacts": [{"at": [0, "101"], "normal": [1, 0], "mu": "1/2"}, {"at": [1, "101"], "normal": [-1, 0], "mu": "1/2"}]}
    with pytest.raises(wrenchkit.InputError, match=r"digits in all, more than the budget of 5 \(--max-total-digits\)"):
        wrenchkit.Scene(s, limits={"max_total_digits": 5})
    with pytest.raises(wrenchkit.InputError, match=r"3 digits and it has 2 contacts .* \(--max-digits-times-contacts\)"):
        wrenchkit.Scene(s, limits={"max_digits_times_contacts": 5})
    # A scene read with raised limits keeps them for its questions and for the checker of its certificates
    # (mu = 10^12000 is beyond the default digit and exponent limits: the checker with the defaults would
    # refuse the scene's canonical text).
    big = {"contacts": [{"at": [0, "1/2"], "normal": [1, 0], "mu": "1e12000"}, {"at": [1, "1/2"], "normal": [-1, 0], "mu": "1e12000"}]}
    raised = {"max_digits": 20000, "max_exponent": 20000}
    with pytest.raises(wrenchkit.InputError, match="--max-digits-times-contacts"):
        wrenchkit.Scene(big, limits=dict(raised, max_digits_times_contacts=20000))
    scene = wrenchkit.Scene(big, limits=raised)
    assert wrenchkit.closure(scene, mode="exact")["force_closure"] is True
    lines = list(wrenchkit.batch("closure", [big], verdict_only=True, max_digits=20000, max_exponent=20000,
                                 max_digits_times_contacts=20000))
    assert '"exit_code": 2' in lines[0] and "--max-digits-times-contacts" in lines[0]


def test_the_work_budget_makes_a_dear_question_undecided():
    # issue 34: a table on four legs whose forces are not given: answered by default; under a budget of 100 work
    # units undecided (UndecidedError naming --max-work), in batch an undecided line, and raised again, answered.
    table = {"support": {"mu": 1, "weight": 1, "pressure_center": [0, 0],
                         "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]},
             "load": {"force": ["1/2", 0], "at": [0, 0]}}
    assert wrenchkit.hold(table)["holds"] is True
    with pytest.raises(wrenchkit.UndecidedError, match=r"the work budget of 100 units \(--max-work\)"):
        wrenchkit.hold(wrenchkit.Scene(table, limits={"max_work": 100}))
    assert wrenchkit.hold(wrenchkit.Scene(table, limits={"max_work": 100000}))["holds"] is True
    lines = list(wrenchkit.batch("hold", [table, table], max_work=100))
    assert all('"exit_code": 3' in l and "--max-work" in l for l in lines)
    with pytest.raises(wrenchkit.UndecidedError, match=r"more than the limit of 10 \(--max-certificate-size"):
        wrenchkit.hold(wrenchkit.Scene(table, limits={"max_certificate_size": 10}))


# ---- one pipeline: every question takes the mode, parsed once, and answers as the CLI does --------------

def test_an_unknown_mode_is_a_value_error_everywhere():
    calls = [
        lambda m: wrenchkit.closure(two_fingers(1, 1), mode=m),
        lambda m: wrenchkit.equilibrium(ladder("1/7"), mode=m),
        lambda m: wrenchkit.labels(two_fingers(1, 1), mode=m),
        lambda m: wrenchkit.labels(two_fingers(1, 1), reading="frictionless", mode=m),
        lambda m: wrenchkit.dual(two_fingers(1, 1), mode=m),
        lambda m: wrenchkit.limit_surface(BARBELL, 8, mode=m),
        lambda m: wrenchkit.sliding(BARBELL, twist=(0, 0, 1), mode=m),
    ]
    for call in calls:
        with pytest.raises(ValueError, match='mode: "exacto" is not one of exact, hybrid, float'):
            call("exacto")
        assert call("exact") == call("exact")  # the same answer twice: deterministic


def test_constructions_are_the_same_in_hybrid_and_exact():
    for s in (two_fingers(1, 1), two_fingers("1/2", "1/10"), ladder("1/7")):
        assert wrenchkit.labels(s, mode="hybrid")["plus"] == wrenchkit.labels(s, mode="exact")["plus"]
        assert wrenchkit.dual(s, mode="hybrid")["covers_all"] == wrenchkit.dual(s, mode="exact")["covers_all"]
    with pytest.raises(wrenchkit.InputError, match='"float" is not offered by wrenchkit.labels'):
        wrenchkit.labels(two_fingers(1, 1), mode="float")


def test_limit_surface_motion_by_mode_as_the_command_line():
    # A load just inside the barbell's true limit surface (moment 1 about the centre): the 8-gon polygons
    # cannot tell, the exact polygon rounds refined where friction acts can (exact: sticks, by the polygons), and so
    # can the twin's certified search on the true surface (hybrid: sticks, by the float search).
    near = (0, 0, "0.999")
    exact = wrenchkit.limit_surface(BARBELL, 8, load=near, mode="exact")
    hybrid = wrenchkit.limit_surface(BARBELL, 8, load=near, mode="hybrid")
    assert exact["motion"] == "sticks" and exact["motion_decided_by"] == "polygons"
    assert hybrid["motion"] == "sticks" and hybrid["motion_decided_by"] == "float"
    if CLI:
        p = json.dumps(json.loads(wrenchkit._to_json(dict({"wrenchkit": 1}, **BARBELL))))
        out = subprocess.run([CLI, "limit-surface", "--json", "--sides", "8", "--load", "0,0,0.999", "-"],
                             input=p, capture_output=True, text=True, check=True)
        assert json.loads(out.stdout)["motion"] == hybrid["motion"]


TABLE = {"support": {"mu": 1, "weight": 1, "pressure_center": [0, 0],
                     "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}}


def test_sliding_over_every_admissible_distribution_of_the_table():
    # Rotation about a leg (1, 1): the diagonal through it has power sqrt(2), the other 2 (theory-sliding §6).
    r = wrenchkit.sliding(TABLE, twist=(1, -1, 1))
    assert r["distribution"] == "unknown" and r["unknown_points"] == [0, 1, 2, 3]
    lo, hi = r["power"]
    assert lo * lo < 2 < (lo + Fraction(1, 10**9)) ** 2 and 2 <= hi < 2 + Fraction(1, 10**9)
    assert r["min_distribution"] == (Fraction(1, 2), 0, Fraction(1, 2), 0)
    assert r["max_distribution"] == (0, Fraction(1, 2), 0, Fraction(1, 2))
    assert len(r["extreme_distributions"]) == 2
    with pytest.raises(wrenchkit.InputError, match="outside the convex hull"):
        wrenchkit.Scene({"support": dict(TABLE["support"], pressure_center=[2, 0])})


def test_limit_surface_over_every_admissible_distribution_of_the_table():
    assert wrenchkit.limit_surface(TABLE, load=("1/2", 0, 0))["motion"] == "sticks"
    s = wrenchkit.limit_surface(TABLE, load=(0, 0, "3/2"))
    assert s["motion"] == "slides" and len(s["separating_twist"]) == 3
    d = wrenchkit.limit_surface(TABLE, load=("1/2", "1/2", "9/10"))
    assert d["motion"] == "depends"
    assert d["witnesses"]["sticks"] == (Fraction(1, 2), 0, Fraction(1, 2), 0)
    assert d["witnesses"]["slides"] == (0, Fraction(1, 2), 0, Fraction(1, 2))


# ---- reference corpus of the user's own scenes ------------------------------------------------------

def test_reference_of_own_scenes_is_the_command_s_corpus(tmp_path):
    scenes = tmp_path / "mine.jsonl"
    scenes.write_text(
        json.dumps({"id": "pinch", "family": "pinch", "scene": {"wrenchkit": 1, "contacts": [
            {"at": [0, 1], "normal": [0, -1], "mu": 0.3}, {"at": [0, -1], "normal": [0, 1], "mu": 0.3}]}}) + "\n"
        + json.dumps({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]}],
                      "load": {"wrench": [-1, 0, 0]}}) + "\n")
    summary = wrenchkit.reference(scenes, tmp_path / "py")
    # 2 (closure) + 3 (closure, equilibrium) + 1 (hold: the scene with a load) + 2 (quality: both have contacts)
    assert summary["scenes"] == 2 and summary["certificates_checked"] == 8
    lines = [json.loads(l) for l in (tmp_path / "py" / "reference.jsonl").read_text().splitlines()]
    assert [l["id"] for l in lines] == ["pinch", "line.2"]
    assert lines[0]["force_closure"] is True and lines[1]["equilibrium"] is True
    assert lines[0]["quality"]["epsilon"]["norm"] == "L1" and lines[1]["quality"]["epsilon"]["upper"] == "0"
    assert lines[0]["approx"]["scene"]["contacts"][0]["mu"] == 0.3
    if CLI:
        subprocess.run([CLI, "reference", "--scenes", str(scenes), "--out", str(tmp_path / "cli")], check=True,
                       capture_output=True)
        for f in ("reference.jsonl", "expected.csv", "manifest.json"):
            assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"wrenchkit": 1}\n{"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 0]}]}\n')
    with pytest.raises(wrenchkit.InputError, match="bad.jsonl:2: contacts\\[0\\].normal: zero vector"):
        wrenchkit.reference(bad, tmp_path / "nothing")
    assert not (tmp_path / "nothing").exists()


SQUARE_REGION = {"support": {"mu": 1, "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
                                                    "pressure": "uniform", "force": 1}]}}


def test_support_regions_power_motion_and_bad_regions():
    # The uniform square [-1,1]^2 (theory-sliding.md section 6): h(0,0,1) = (sqrt 2 + asinh 1)/3, exact centre.
    import math
    s = wrenchkit.sliding(SQUARE_REGION, twist=(0, 0, 1))
    lo, hi = s["power_bracket"]
    truth = (math.sqrt(2) + math.asinh(1)) / 3
    # (the float truth is itself within an ulp of the true value)
    assert isinstance(lo, Fraction) and lo <= truth * (1 + 1e-15) and truth * (1 - 1e-15) <= hi
    assert (hi - lo) / lo <= Fraction(1, 10**6)
    assert s["center_of_friction"] == (0, 0) and s["total_force"] == 1
    assert s["regions"][0]["area"] == 4 and s["regions"][0]["second_moments"] == (Fraction(1, 3), 0, Fraction(1, 3))
    coarse = wrenchkit.sliding(SQUARE_REGION, twist=(0, 0, 1), tolerance="1/100")
    assert coarse["power_bracket"][0] <= truth * (1 + 1e-15) and truth * (1 - 1e-15) <= coarse["power_bracket"][1]
    t = wrenchkit.sliding(SQUARE_REGION, twist=(3, 4, 0))
    assert t["motion"] == "translation" and t["load"] == (Fraction(3, 5), Fraction(4, 5), 0)
    stick = wrenchkit.limit_surface(SQUARE_REGION, load=(0, 0, "1/2"))
    slide = wrenchkit.limit_surface(SQUARE_REGION, load=(0, 0, "4/5"))
    assert stick["motion"] == "sticks" and slide["motion"] == "slides"
    assert wrenchkit.check(SQUARE_REGION, slide["certificate_json"])["accepted"]
    assert wrenchkit.limit_surface(SQUARE_REGION, load=(0, 0, "1/2"), mode="exact")["motion"] == "sticks"
    bad = {"support": {"mu": 1, "regions": [{"outline": [[0, 0], [1, 1], [1, 0], [0, 1]], "pressure": "uniform",
                                             "force": 1}]}}
    with pytest.raises(wrenchkit.InputError, match=r"support\.regions\[0\]\.outline: is not a simple polygon"):
        wrenchkit.Scene(bad)


MAT_LEGS = {"support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0],
                        "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}],
                        "regions": [{"outline": [["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]],
                                     "pressure": "uniform", "force": 1}]}}


def test_regions_with_forces_not_given():
    # [RG-3] The mat and legs (proofs/examples/mat_legs.*): F's vertices (0, 4, 0) and (2, 0, 2).
    import math
    for load, motion in (((2, 0, 0), "sticks"), ((3, 0, 0), "slides"), ((0, 0, 1), "depends")):
        r = wrenchkit.limit_surface(MAT_LEGS, load=load)
        assert r["distribution"] == "unknown" and r["motion"] == motion
        assert r["extreme_distributions"] == [(0, 4, 0), (2, 0, 2)]
        assert r["regions"][0]["force"] == 1
        assert '"wrenchkit_certificate": 3' in r["certificate_json"]
        assert wrenchkit.check(MAT_LEGS, r["certificate_json"])["accepted"]
    s = wrenchkit.sliding(MAT_LEGS, twist=(0, 0, 1))
    mat = (math.sqrt(2) + math.asinh(1)) / 12
    lo, hi = s["regions_power_bracket"]
    assert lo <= mat * (1 + 1e-12) and mat * (1 - 1e-12) <= hi
    assert abs(float(s["power"][0] - lo)) < 1e-15 and abs(float(s["power"][1] - hi) - 4) < 1e-15


def test_outline_is_geometry_placed_contacts_and_refusals():
    # contacts placed on the outline by edge and parameter; their normals the edges' inward normals, exactly
    part = {"wrenchkit": 1, "mu": "1/2", "body": {"outline": [[0, 0], [4, 0], [0, 4]]},
            "contacts": [{"edge": 0, "s": "1/2"}, {"edge": 1, "s": "1/2"}, {"edge": 2, "s": "1/4"}]}
    assert wrenchkit.closure(part)["force_closure"] is True
    bad = {"wrenchkit": 1, "body": {"outline": [[0, 0], [4, 0], [0, 4]]},
           "contacts": [{"at": [2, 0], "normal": [0, -1]}]}
    with pytest.raises(wrenchkit.InputError, match=r"contacts\[0\]\.normal: \(0, -1\) does not point into the body"):
        wrenchkit.closure(bad)


def test_grasp_regions_square_opposite_sides():
    square = {"wrenchkit": 1, "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]}}
    r = wrenchkit.grasp_regions(square, mu="1/2")
    assert [p["edges"] for p in r["pairs"]] == [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
    closed = {tuple(p["edges"]): p["closed"] for p in r["pairs"]}
    # bottom finger at x = s, top finger at x = 1 - t: |1 - s - t| < 1/2
    assert closed[(0, 2)][0][0] == (Fraction(1, 2), Fraction(0))
    assert closed[(0, 1)] == []
    assert r["largest"]["area"] == Fraction(3, 4) and r["certificate_checked"] is True
    (s0, s1), (t0, t1) = [p for p in r["pairs"] if p["edges"] == [0, 2]][0]["independent"]
    assert s1 - s0 == t1 - t0 == Fraction(1, 2) * Fraction(1023, 1024)  # the largest square has side 1/2
    assert wrenchkit.grasp_regions(square, mu=1, edges=[0, 1])["pairs"][0]["closed"] == []  # the boundary: empty
    with pytest.raises(wrenchkit.InputError, match="--mu: missing"):
        wrenchkit.grasp_regions(square)


def test_grasp_regions_three_fingers_on_the_l_part():
    l_part = {"wrenchkit": 1, "body": {"outline": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]}}
    r = wrenchkit.grasp_regions(l_part, mu="1/2", edges=[1, 2, 3], fingers=3)
    # the right side, the foot's top and the inner side push -x, -y, -x: every cone edge has u . f <= 0 for
    # u = (1/2, 1) (mu = 1/2), so no placement closes
    (t,) = r["triples"]
    ux, uy, um = t["never"]
    assert um == 0 and ux > 0 and uy == 2 * ux and r["never_triples"] == 1 and r["certificate_checked"] is True
    r = wrenchkit.grasp_regions(l_part, mu="11/10", edges=[1, 2, 3], fingers=3)  # above mu = 1 they close
    (a0, b0), (a1, b1), (a2, b2) = r["triples"][0]["independent"]
    assert b0 - a0 == b1 - a1 == b2 - a2 == r["most_independent"]["independent_side"] > 0
    assert len(r["triples"][0]["wrenches"]) == 4
    with pytest.raises(wrenchkit.InputError, match="--fingers: \"4\" is not 2 or 3"):
        wrenchkit.grasp_regions(l_part, mu=1, fingers=4)


def test_grasp_regions_ranked_by_epsilon_and_lenient():
    l_part = {"wrenchkit": 1, "mu": "1/2", "body": {"outline": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]}}
    r = wrenchkit.grasp_regions(l_part, rank="epsilon")
    eps = [p["epsilon"]["lower"] for p in r["ranked"]]
    assert len(eps) == 4 and eps == sorted(eps, reverse=True) and all(isinstance(e, Fraction) for e in eps)
    best = r["best_by_epsilon"]
    assert wrenchkit.check(best["scene"], best["certificate"])["accepted"] is True
    assert [p["edges"] for p in wrenchkit.grasp_regions(l_part, min_side="1/2")["ranked"]] == [[1, 5], [0, 4]]
    off = dict(l_part, contacts=[{"at": [5, 5], "normal": [0, 1]}])
    with pytest.raises(wrenchkit.InputError, match=r"contacts\[0\]\.at: \(5, 5\) is not on body.outline"):
        wrenchkit.grasp_regions(off)
    # the regions do not use the contacts (their canonical scene writes mu into each contact: give the fingers' mu)
    assert wrenchkit.grasp_regions(off, mu="1/2", lenient=True)["closed_pairs"] == 4


def test_push_stable_line_pusher():
    square = {"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
              "support": {"mu": "1/2", "points": [{"at": [x, y], "force": 1} for x, y in
                                                  [(-1, -1), (1, -1), (1, 1), (-1, 1)]]},
              "pusher": {"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": "1/2", "velocity": [0, 1],
                         "omega": "1/10"}}
    r = wrenchkit.push(square)  # turning ccw about (-10, -1): stable for every distribution (PU-3)
    assert r["stable"]["verdict"] == "stable" and r["rotation"] == "ccw" and r["certificate_checked"] is True
    assert r["stable"]["rotation_centre"] == (-10, -1) and r["pusher"]["segment"][1] == (Fraction(1, 2), -1)
    square["pusher"]["omega"] = "1/2"  # about (-2, -1): two legs lean the load past the left edge
    r = wrenchkit.push(square)
    assert r["stable"]["verdict"] == "unstable" and r["stable"]["facet"] == "left edge"
    assert r["stable"]["witness"]["points"] == [(-1, 1), (1, -1)] and r["rotation"] == "undecided"
    g = wrenchkit.push(square, region=True)["stable_region"]  # the rotation centres certified stable (PU-3 section 6)
    assert [h["facet"] for h in g["ccw"]["halfplanes"]] == ["left edge", "right edge", "end 0", "end 1"]
    assert g["ccw"]["halfplanes"][2]["a"] == (1, 2) and g["ccw"]["halfplanes"][2]["b"] == Fraction(-5, 4)
    assert len(g["ccw"]["polygon"]) >= 3 and g["translations"] == [(Fraction(1, 2), 1), (Fraction(-1, 2), 1)]


def test_push_locus():
    square = {"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
              "support": {"mu": "1/2", "points": [{"at": [x, y], "force": 1} for x, y in
                                                  [(-1, -1), (1, -1), (1, 1), (-1, 1)]]},
              "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]}}
    r = wrenchkit.push(square, locus=True)  # where the body may turn about, for every distribution (PU-4)
    g = r["locus"]
    assert r["rotation"] == "ccw" and g["cw"] is None and r["certificate_checked"] is True
    stick = g["ccw"][0]
    assert stick["mode"] == "sticks" and stick["bounded"] is True and stick["polygon"][1] == (Fraction(1, 12), Fraction(-7, 12))
    assert [h["why"] for h in stick["halfplanes"]][:2] == ["bisector", "advance"]
    assert 3 < g["arm_hi"] < 4 and Fraction(186, 100) < g["arm_lo"] < Fraction(187, 100)
    assert g["slowest"] == {"forces": [1, 1, 1, 1], "mode": "sticks"}
    square["pusher"]["velocity"] = ["-1/2", 1]  # through the centre of friction: it translates
    g = wrenchkit.push(square, locus=True)["locus"]
    assert g["ccw"] is None and g["cw"] is None and "translates" in g["arm_why"]


def test_push_voting_theorem():
    square = {"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
              "support": {"mu": "1/2", "points": [{"at": [x, y], "force": 1} for x, y in
                                                  [(-1, -1), (1, -1), (1, 1), (-1, 1)]]}}
    # mu 1 at (1/2, -1): the edges vote apart, the velocity decides
    square["pusher"] = {"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]}
    r = wrenchkit.push(square)
    assert r["rotation"] == "ccw" and r["certificate_checked"] is True
    assert r["center_of_friction"] == (0, 0)
    assert [v["vote"] for v in r["votes"]] == ["cw", "ccw", "ccw"]
    assert r["votes"][0]["direction"] == (-1, 1) and r["pusher"]["at"] == (Fraction(1, 2), -1)
    c = wrenchkit.push(square, contact=True)["contact"]
    assert c["mode"] == "sticks" and Fraction(536, 1000) < c["omega"][0] < c["omega"][1] < Fraction(537, 1000)
    # mu 1/4: the contact slides on the right edge; the body slips and turns (brackets), as the CLI says
    square["pusher"]["mu"] = "1/4"
    c = wrenchkit.push(square, contact=True)["contact"]
    assert c["mode"] == "slides right" and "pivot" not in c
    assert Fraction(3184901, 10 ** 7) < c["slip"][0] <= c["slip"][1] < Fraction(3184902, 10 ** 7)
    assert Fraction(4257531, 10 ** 7) < c["omega"][0] <= c["omega"][1] < Fraction(4257532, 10 ** 7)
    # a sticking pivot (PU-2 section 7): the velocity perpendicular to the line to the leg at (0, 0)
    legs = {"wrenchkit": 1, "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [2, 0], "force": 1, "mu": 1},
                                                   {"at": [0, 2], "force": "1/8", "mu": 1}]},
            "pusher": {"at": [1, -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]}}
    c = wrenchkit.push(legs, contact=True)["contact"]
    assert c["mode"] == "sticks" and c["pivot"] == 0 and c["omega"] == (1, 1)
    assert c["force"] == (Fraction(9, 16), Fraction(27, 16))
    # mu 1/5: every force of that facet is beyond the right edge (PU-2 section 8): it slides from the facet
    legs["pusher"]["mu"] = "1/5"
    c = wrenchkit.push(legs, contact=True)["contact"]
    assert c["mode"] == "slides right" and c["sticking_pivot"] == 0 and c["sticking_omega"] == (1, 1)
    assert 0 < c["slip"][0] <= c["slip"][1] and Fraction(9, 10) < c["omega"][0] <= c["omega"][1] < 1
    # the picture: where the body turns, with contact=True only (the CLI's render --what push --contact)
    svg = wrenchkit.render(legs, "push", contact=True)
    assert svg.startswith("<?xml") and "rotation centre" in svg and "contact: slides right" in svg
    assert "rotation centre" not in wrenchkit.render(legs, "push")
    with pytest.raises(wrenchkit.InputError, match="--contact goes with --what push"):
        wrenchkit.render(legs, "labels", contact=True)
    square["pusher"]["mu"] = 1
    square["pusher"]["velocity"] = [-1, 2]  # along p -> c: a translation
    assert wrenchkit.push(square)["rotation"] == "none"
    square["pusher"]["velocity"] = [0, -1]
    with pytest.raises(wrenchkit.InputError, match=r"pusher\.velocity: \(0, -1\) moves away from the body"):
        wrenchkit.push(square)
