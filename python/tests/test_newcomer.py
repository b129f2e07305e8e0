"""pytest: what a newcomer to the Python package hits first (run by CTest as python_pytest; docs/python.md).

NumPy values inside dict scenes, wrenchkit.batch as dicts, every command's question from Python (reuleaux with a
motion, render, compare), messages that name the likely fix, and the "Use" example of docs/python.md run from
another directory than the checkout.
"""
import json
import os
import re
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

import wrenchkit

SOURCE = Path(os.environ.get("WRENCHKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
GOLDEN = SOURCE / "tests" / "golden"
CLI = os.environ.get("WRENCHKIT_CLI")
LADDER = GOLDEN / "equilibrium" / "ladder_mu_1_7_gravity.scene.json"


def test_numpy_arrays_and_scalars_in_a_dict_are_read_as_the_array_api_reads_them():
    np = pytest.importorskip("numpy")
    s = wrenchkit.Scene({"contacts": [
        {"at": np.array([0, 0.5]), "normal": np.array([1, 0]), "mu": np.float64(0.1)},
        {"at": [np.int64(1), np.float32(0.5)], "normal": [-1, 0], "mu": np.float32(0.1)}]})
    same = wrenchkit.Scene({"contacts": [
        {"at": [0, "1/2"], "normal": [1, 0], "mu": Fraction(0.1)},
        {"at": [1, "1/2"], "normal": [-1, 0], "mu": Fraction(float(np.float32(0.1)))}]})
    assert s.json == same.json
    assert "3602879701896397/36028797018963968" in s.json  # the double 0.1, not 1/10
    # A 2-D array is a list of points; a 0-d array is its number.
    body = wrenchkit.Scene({"body": {"outline": np.array([[0, 0], [1, 0], [0, 1]]), "com": [np.array(0.25), 0]}})
    assert body.json == wrenchkit.Scene({"body": {"outline": [[0, 0], [1, 0], [0, 1]], "com": ["1/4", 0]}}).json
    # The array API and a dict scene of the same doubles give the same answer.
    points = np.array([[[0, 0], [1, 0.3]]])
    normals = np.array([[[1, 0], [-1, 0]]], dtype=float)
    mu = np.array([[0.3, 0.3]])
    arrays = wrenchkit.closure_arrays(points, normals, mu)
    scene = {"contacts": [{"at": points[0, i], "normal": normals[0, i], "mu": mu[0, i]} for i in range(2)]}
    assert bool(arrays["force_closure"][0]) == wrenchkit.closure(scene)["force_closure"]
    # Twists and loads too.
    barbell = {"support": {"mu": 1, "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": "1/2"}]}}
    assert wrenchkit.sliding(barbell, twist=np.array([0, 0, 1.0]))["power_bracket"] == (1, 1)
    for bad, message in [(np.array([0, np.nan]), "contacts[0].at[1]: nan is not a finite number"),
                         (np.array([True, False]), "contacts[0].at[0]: True is a boolean, not a number"),
                         (np.array([1 + 1j, 0]), "contacts[0].at[0]: "),
                         (np.float64(np.inf), "contacts[0].at: inf is not a finite number")]:
        with pytest.raises(wrenchkit.InputError) as e:
            wrenchkit.Scene({"contacts": [{"at": bad, "normal": [1, 0]}]})
        assert str(e.value).startswith(message), str(e.value)


def test_batch_yields_dicts_as_well_as_lines():
    scenes = [{"contacts": [{"at": [0, "1/2"], "normal": [1, 0], "mu": "1/10"},
                            {"at": [1, "1/2"], "normal": [-1, 0], "mu": "1/10"}]},
              {"contacts": [{"at": [0, 0], "nromal": [1, 0]}]}]
    lines = list(wrenchkit.batch("closure", scenes, verdict_only=True))
    dicts = list(wrenchkit.batch("closure", scenes, verdict_only=True, as_dict=True))
    assert dicts == [json.loads(x) for x in lines]
    assert dicts[0]["force_closure"] is True and dicts[0]["line"] == 1
    assert dicts[1] == {"line": 2, "error": 'contacts[0]: unknown key "nromal" (did you mean "normal"?)',
                        "exit_code": 2}


def test_reuleaux_with_a_motion_is_the_command_s():
    ladder = wrenchkit.Scene(LADDER)
    plain = wrenchkit.reuleaux(ladder)
    assert "query" not in plain and plain["form_closure"] is False
    assert {k: plain[k] for k in ("plus", "minus", "both", "infinity")} == \
        {k: v for k, v in wrenchkit.labels(ladder, "frictionless").items() if k in ("plus", "minus", "both", "infinity")}
    q = wrenchkit.reuleaux(ladder, center=(-1, 4))["query"]
    assert q["feasible"] is True and q["marginal"] is False
    assert q["twist"] == (4, 1, 1) and q["reading"] == {"label": "+", "point": (-1, 4)}
    assert [m["mode"] for m in q["modes"]] == ["break", "break"]
    cw = wrenchkit.reuleaux(ladder, center=(-4, 0), sense="cw")["query"]
    assert cw["feasible"] is False and [m["mode"] for m in cw["modes"]] == ["penetrate", "break"]
    assert wrenchkit.reuleaux(ladder, twist=(0, -4, -1))["query"]["modes"] == cw["modes"]
    assert wrenchkit.reuleaux(ladder, direction="1,0")["query"]["twist"] == (0, -1, 0)
    for kwargs, message in [(dict(center=(0, 0), direction=(1, 0)), "give at most one of --center, --direction, --twist"),
                            (dict(sense="cw"), "--sense goes with --center"),
                            (dict(center=(0, 0), sense="up"), "--sense"),
                            (dict(twist=(0, 0, 0)), "--twist")]:
        with pytest.raises(wrenchkit.InputError, match=re.escape(message)):
            wrenchkit.reuleaux(ladder, **kwargs)


@pytest.mark.skipif(not CLI, reason="WRENCHKIT_CLI not set")
def test_reuleaux_and_render_are_the_command_lines():
    cli = subprocess.run([CLI, "reuleaux", "--json", "--center", "-1,4", str(LADDER)], capture_output=True, text=True)
    answer = json.loads(cli.stdout)
    q = wrenchkit.reuleaux(LADDER, center=(-1, 4))["query"]
    assert answer["query"]["feasible"] == q["feasible"]
    assert [m["mode"] for m in answer["query"]["modes"]] == [m["mode"] for m in q["modes"]]
    for what, scene in [("labels", LADDER), ("dual", LADDER), ("reuleaux", LADDER),
                        ("limit-surface", GOLDEN / "limit_surface" / "barbell.scene.json"),
                        ("hold", SOURCE / "proofs" / "examples" / "fixture_pin_lift.scene.json")]:
        svg = subprocess.run([CLI, "render", "--what", what, str(scene)], capture_output=True, text=True).stdout
        assert wrenchkit.render(str(scene), what) == svg, what
    svg8 = subprocess.run([CLI, "render", "--what", "limit-surface", "--sides", "8",
                           str(GOLDEN / "limit_surface" / "barbell.scene.json")], capture_output=True, text=True).stdout
    assert wrenchkit.render(GOLDEN / "limit_surface" / "barbell.scene.json", "limit-surface", sides=8) == svg8


def test_render_errors_are_the_command_lines():
    with pytest.raises(wrenchkit.InputError, match=re.escape('--what: "lables" is not one of')):
        wrenchkit.render(LADDER, "lables")
    with pytest.raises(wrenchkit.InputError, match="--sides goes with --what limit-surface"):
        wrenchkit.render(LADDER, "labels", sides=8)
    with pytest.raises(wrenchkit.InputError, match="support"):
        wrenchkit.render(LADDER, "limit-surface")


def test_compare_returns_the_report(tmp_path):
    scenes = tmp_path / "scenes.jsonl"
    scenes.write_text("".join(json.dumps(json.loads(p.read_text())) + "\n"
                              for p in sorted((GOLDEN / "equilibrium").glob("ladder*.scene.json"))))
    corpus = tmp_path / "corpus"
    wrenchkit.reference(scenes, corpus)
    report = wrenchkit.compare(corpus, corpus / "expected.csv")
    assert report["agree"] is True and report["command"] == "compare"
    assert report["fields"]["hold"]["compared"] == report["reference_scenes"]  # the CSV's hold column
    answers = tmp_path / "answers.jsonl"
    balanced = (corpus / "expected.csv").read_text().splitlines()[1].split(",")[3] == "true"
    answers.write_text(json.dumps({"id": "line.1", "equilibrium": not balanced}) + "\n")
    wrong = wrenchkit.compare(corpus, answers)
    assert wrong["agree"] is False and wrong["fields"]["equilibrium"]["disagree"] == 1
    if CLI:
        cli = subprocess.run([CLI, "compare", "--json", str(corpus), str(answers)], capture_output=True, text=True)
        assert cli.returncode == 1 and json.loads(cli.stdout) == wrong
    with pytest.raises(wrenchkit.InputError, match=re.escape('--rtol: "-1" must be >= 0')):
        wrenchkit.compare(corpus, answers, rtol=-1)
    answers.write_text('{"id": "nope", "force_closure": true}\n')
    with pytest.raises(wrenchkit.InputError, match='id: "nope" is not in the corpus'):
        wrenchkit.compare(corpus, answers)


def test_the_use_example_of_docs_python_runs_from_any_directory(tmp_path):
    text = (SOURCE / "docs" / "python.md").read_text()
    use = text[text.index("## Use"):]
    code = use[use.index("```python\n") + len("```python\n"):use.index("\n```", use.index("```python\n"))]
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        names = {}
        exec(compile(code, "docs/python.md", "exec"), names)  # noqa: S102 (the documentation's own example)
    finally:
        os.chdir(here)
    assert names["wrenchkit"].equilibrium(names["ladder"])["balanced"] is True
    assert names["svg"].startswith("<?xml")


def test_each_contact_force_as_a_vector_with_its_name():
    # The block in a tray corner under its weight: the floor's two contacts carry it, (1/4, 1/2) and (-1/4, 1/2).
    scene = SOURCE / "docs" / "quickstart" / "block_in_corner.json"
    forces = wrenchkit.equilibrium(scene)["forces"]
    assert [(f["contact"], f["name"], f["force"]) for f in forces] == [
        (0, "floor, left", (Fraction(1, 4), Fraction(1, 2))), (1, "floor, right", (Fraction(-1, 4), Fraction(1, 2)))]
    # They balance the weight (0, -1) at (1/2, 1/2) exactly: the forces' sum and moment.
    assert sum(f["force"][1] for f in forces) == 1 and sum(f["force"][0] for f in forces) == 0
    held = wrenchkit.hold(SOURCE / "docs" / "quickstart" / "pinned_part.json")
    assert held["holds"] is True and held["forces"][0]["name"] == "pin" and held["forces"][0]["force"][1] == 0
