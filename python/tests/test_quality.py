"""wrenchkit.quality: the Ferrari-Canny epsilon and the critical friction coefficient from Python (docs/quality.md),
the same answers as `wrenchkit quality --json`: the two fingers of proofs/examples (epsilon^2 = 1/3 by hand), the
unit-force bracket around 1/sqrt(6), the ladder's mu* = 1/7 (theory.md section 9), options validated by the command's
own table, float mode undecided."""
import math
from fractions import Fraction

import pytest

import wrenchkit

TWO_FINGERS = {"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1},
                                             {"at": [1, 0], "normal": [-1, 0], "mu": 1}]}
LADDER = {"wrenchkit": 1, "body": {"com": ["-1/2", "7/2"]},
          "contacts": [{"at": [0, 0], "normal": [0, 1]}, {"at": [-4, 3], "normal": [1, 0]}], "load": {"gravity": 1}}


def test_epsilon_by_hand():
    r = wrenchkit.quality(TWO_FINGERS, normalize="as-given", about=(0, 0))
    assert r["force_closure"] is True
    assert r["epsilon"]["squared"] == Fraction(1, 3)
    assert r["epsilon"]["lower"] ** 2 <= Fraction(1, 3) <= r["epsilon"]["upper"] ** 2
    assert r["certificate_checked"] is True and r["certificate"]["property"] == "quality"
    assert wrenchkit.quality(TWO_FINGERS, norm="Linf")["epsilon"]["squared"] == Fraction(2, 3)


def test_unit_force_bracket():
    e = wrenchkit.quality(TWO_FINGERS, normalize="unit-force", tolerance="1/1000", only="epsilon")["epsilon"]
    assert "squared" not in e
    assert e["lower"] <= Fraction(1 / math.sqrt(6)) * (1 + Fraction(1, 10**12))
    assert e["upper"] >= Fraction(1 / math.sqrt(6)) * (1 - Fraction(1, 10**12))
    assert e["upper"] - e["lower"] <= Fraction(1, 1000) * e["lower"]


def test_critical_mu_of_the_ladder():
    r = wrenchkit.quality(LADDER, only="critical-mu")
    assert "epsilon" not in r
    assert r["critical_mu"]["closure"]["lower"] == Fraction(4, 3) and r["critical_mu"]["closure"]["exact"] is True
    eq = r["critical_mu"]["equilibrium"]
    assert eq["kind"] == "value" and eq["lower"] == eq["upper"] == Fraction(1, 7)
    assert eq["certificate"]["property"] == "critical_mu"


def test_friction_margin():
    fingers = {"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1},
                                            {"at": [1, 1], "normal": [-1, 0], "mu": "3/4"}]}
    m = wrenchkit.quality(fingers, only="critical-mu")["friction_margin"]
    assert m["lower"] == m["upper"] == Fraction(2, 3) and m["certificate"]["scaling"] == "proportional"


def test_options_and_modes():
    with pytest.raises(wrenchkit.InputError, match="--norm"):
        wrenchkit.quality(TWO_FINGERS, norm="L3")
    with pytest.raises(wrenchkit.InputError, match="--torque-scale"):
        wrenchkit.quality(TWO_FINGERS, torque_scale=0)
    with pytest.raises(wrenchkit.UndecidedError):
        wrenchkit.quality(TWO_FINGERS, mode="float")
    assert wrenchkit.quality(TWO_FINGERS, mode="exact")["epsilon"] == wrenchkit.quality(TWO_FINGERS)["epsilon"]
    assert "<svg" in wrenchkit.render(TWO_FINGERS, "quality")


def test_quality_arrays_agree_with_quality():
    import numpy as np
    rng = np.random.default_rng(31)
    B, K = 40, 3
    ang = rng.uniform(0, 2 * np.pi, (B, K))
    pts = np.stack([np.cos(ang), np.sin(ang)], -1)
    nrm = -pts + rng.uniform(-0.3, 0.3, (B, K, 2))
    r = wrenchkit.quality_arrays(pts, nrm, 0.5, critical_mu=True)
    c = wrenchkit.quality_arrays(pts, nrm, 0.5, certificates=True)
    # without certificates the float twin certifies most rows (a bracket ~1e-14 wide), the exact engine the rest
    assert r["epsilon_twin"].sum() > B // 2 and not c["epsilon_twin"].any()
    assert (r["force_closure"] == c["force_closure"]).all()
    assert (r["epsilon_lower"] <= c["epsilon_upper"]).all() and (c["epsilon_lower"] <= r["epsilon_upper"]).all()
    exact_rows = ~r["epsilon_twin"]
    assert (r["epsilon_lower"][exact_rows] == c["epsilon_lower"][exact_rows]).all()
    assert (r["force_closure"] == wrenchkit.closure_arrays(pts, nrm, 0.5)["force_closure"]).all()
    for i in range(0, B, 7):
        scene = {"wrenchkit": 1, "contacts": [{"at": [pts[i, k, 0], pts[i, k, 1]], "normal": [nrm[i, k, 0], nrm[i, k, 1]],
                                               "mu": 0.5} for k in range(K)]}
        q = wrenchkit.quality(scene, about=(0, 0))
        e = q["epsilon"]
        assert Fraction(c["epsilon_lower"][i]) <= e["lower"] and e["upper"] <= Fraction(c["epsilon_upper"][i])
        assert Fraction(r["epsilon_lower"][i]) <= e["upper"] and e["lower"] <= Fraction(r["epsilon_upper"][i])
        m = q["critical_mu"]["closure"]
        if m["kind"] == "value":
            assert Fraction(r["critical_mu_lower"][i]) <= m["lower"] and m["upper"] <= Fraction(r["critical_mu_upper"][i])
    with pytest.raises(ValueError, match="norm"):
        wrenchkit.quality_arrays(pts, nrm, 0.5, norm="L2")
