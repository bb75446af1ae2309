"""Fuzzy weights of curves in the Python API (docs/method.md §16,
docs/python.md "Fuzzy weights"): `FuzzyCurve(weights=[FuzzyNumber, ...])`
equal to the job's curve, and what it computes equal to what `t2spline`
(the command-line tool, the reference) writes for examples/fuzzy-weights.json:
the stage curves and weights, the envelope at every sample, the membership
grades; what is not available says so as the core does; pickling keeps
the numbers; crisp numbers are plain weights."""

from __future__ import annotations

import copy
import csv
import io
import json
import pickle
import subprocess
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest

import t2spline
from t2spline import FuzzyCurve, FuzzyNumber

from conftest import ROOT, assert_same, cli_run

JOB = ROOT / "examples" / "fuzzy-weights.json"
AXES = ("x", "y")
CUT_LAYERS = ["upper_left", "primary_left", "lower_left", "lower_right", "primary_right", "upper_right"]


def job() -> Dict[str, Any]:
    data: Dict[str, Any] = json.loads(JOB.read_text())
    return data


def number(value: Any, height: float) -> FuzzyNumber:
    """A job's number as a `FuzzyNumber` (the job's height where it gives
    none)."""
    return FuzzyNumber(
        value["crisp"], value["upper"], value["primary"], value["lower"],
        value.get("lower_height", height),
    )


def from_arrays(weights: List[Any]) -> FuzzyCurve:
    """The example's curve from arrays, with `weights` as given."""
    j = job()
    points = j["points"]
    crisp = [[p[a]["crisp"] for a in AXES] for p in points]
    feet = {k: [[p[a][k] for a in AXES] for p in points] for k in ("upper", "primary", "lower")}
    return FuzzyCurve(crisp, feet["upper"], feet["primary"], feet["lower"],
                      lower_height=j["lower_height"], weights=weights, order=j["order"])


def example_weights() -> List[Any]:
    """The example's weights as `FuzzyNumber`s: a bare weight of the job is
    a crisp number with the job's lower height (a plain number given to
    `FuzzyCurve` is one of height 1, as `FuzzyNumber(w)`)."""
    j = job()
    h = j["lower_height"]
    return [FuzzyNumber(w, lower_height=h) if isinstance(w, (int, float)) else number(w, h) for w in j["weights"]]


@pytest.fixture(scope="module")
def result(cli: Path) -> Dict[str, Any]:
    return cli_run(cli, JOB)


@pytest.fixture(scope="module")
def curve() -> FuzzyCurve:
    return from_arrays(example_weights())


def test_the_curve_from_arrays_is_the_jobs(curve: FuzzyCurve) -> None:
    assert curve == FuzzyCurve.from_job(JOB)
    numbers = curve.weight_numbers
    assert numbers is not None and len(numbers) == 4
    assert numbers[2] == number(job()["weights"][2], 0.6)
    assert numbers[2].upper == (2.0, 4.5) and numbers[2].lower_height == 0.6
    # Bare weights are crisp numbers; `weights` holds the crisp values.
    assert numbers[0].upper == numbers[0].lower == (1.0, 1.0)
    np.testing.assert_array_equal(curve.weights, [1.0, 1.0, 3.0, 1.0])
    # Plain numbers beside a `FuzzyNumber` are `FuzzyNumber(w)`, height 1:
    # the same curve but for the heights of the crisp weights, which change
    # no value (only where their lower cut ends, above every point's here).
    plain = from_arrays([1.0, 1, numbers[2], 1.0])
    plain_numbers = plain.weight_numbers
    assert plain_numbers is not None
    assert plain_numbers[0] == FuzzyNumber(1.0) and plain_numbers[2] == numbers[2]
    for alpha in (0.3, 0.8):
        a, b = plain.solve(alpha).sample(33), curve.solve(alpha).sample(33)
        np.testing.assert_array_equal(a["defuzzified"], b["defuzzified"])
        for layer in CUT_LAYERS:
            if b["alpha_cut"][layer] is not None:
                np.testing.assert_array_equal(a["alpha_cut"][layer], b["alpha_cut"][layer])
    assert repr(curve).endswith("domain=(0.0, 1.0), fuzzy_weights=True)")
    assert "fuzzy (docs/method.md §16)" in curve._repr_html_()
    assert "fuzzy_weights" not in repr(t2spline.FuzzyCurve.from_job(ROOT / "examples" / "paper-alg-1-1.json"))
    # The job written back is the example's curve.
    assert FuzzyCurve.from_job(curve.to_job(0.8)) == curve


def test_run_takes_a_dict_with_fuzzy_weights_as_the_cli_does(result: Dict[str, Any]) -> None:
    got = t2spline.run(job())
    assert "weight_stages" in got and "envelope" in got["curves"]
    assert_same(got, result)


def test_the_stages_are_the_cli_result(curve: FuzzyCurve, result: Dict[str, Any]) -> None:
    solution = curve.solve(result["alpha"])
    stages = solution.sample(len(result["curves"]["params"]))
    curves = result["curves"]
    np.testing.assert_array_equal(stages["params"], curves["params"])
    for layer in CUT_LAYERS:
        want = curves["alpha_cut"][layer]
        got = stages["alpha_cut"][layer]
        if want is None:
            assert got is None, layer
        else:
            np.testing.assert_array_equal(got, want, err_msg=layer)
    for side in ("left", "right"):
        np.testing.assert_array_equal(stages["type_reduced"][side], curves["type_reduced"][side])
    np.testing.assert_array_equal(stages["defuzzified"], curves["defuzzified"])
    # The weights of every stage: the result's `weight_stages`, and the
    # weights of the stage's curve.
    ws = result["weight_stages"]
    numbers = curve.weight_numbers
    assert numbers is not None
    assert [w.crisp for w in numbers] == ws["crisp"]
    for layer in CUT_LAYERS:
        function, side = layer.split("_")
        values = [getattr(w, function)[0 if side == "left" else 1] for w in numbers]
        assert values == ws["layers"][layer], layer
    for layer in CUT_LAYERS:
        # An absent cut (alpha above the lower height) is null in the result.
        want = ws["alpha_cut"][layer]
        got = solution.alpha_cut_weights(layer)
        crisp_curve = solution.alpha_cut_curve(layer)
        if all(w is None for w in want):
            assert got is None and crisp_curve is None, layer
        else:
            assert got is not None and crisp_curve is not None
            np.testing.assert_array_equal(got, want, err_msg=layer)
            np.testing.assert_array_equal(crisp_curve.weights, got, err_msg=layer)
    for side in ("left", "right"):
        got = solution.type_reduced_weights(side)
        np.testing.assert_array_equal(got, ws[f"type_reduced_{side}"])
        np.testing.assert_array_equal(solution.type_reduced_curve(side).weights, got)
    np.testing.assert_array_equal(solution.defuzzified_weights(), ws["defuzzified"])
    np.testing.assert_array_equal(solution.defuzzified_curve().weights, ws["defuzzified"])


def test_crisp_weights_give_the_curves_weights_at_every_stage() -> None:
    solution = FuzzyCurve.from_job(ROOT / "examples" / "paper-alg-1-1.json").solve(0.8)
    w = solution.fuzzy_curve.weights
    assert solution.fuzzy_curve.weight_numbers is None
    for layer in CUT_LAYERS:
        got = solution.alpha_cut_weights(layer)
        c = solution.alpha_cut_curve(layer)
        assert (got is None) == (c is None), layer
        if got is not None and c is not None:
            np.testing.assert_array_equal(got, w)
            np.testing.assert_array_equal(c.weights, w)
    np.testing.assert_array_equal(solution.type_reduced_weights("right"), w)
    np.testing.assert_array_equal(solution.defuzzified_weights(), w)
    with pytest.raises(ValueError, match="side"):
        solution.type_reduced_weights("middle")  # type: ignore[arg-type]


def test_the_envelope_is_the_cli_result_at_every_sample(curve: FuzzyCurve, result: Dict[str, Any]) -> None:
    envelope = result["curves"]["envelope"]
    alpha = result["alpha"]
    for membership in ("upper", "primary", "lower"):
        want = envelope[membership]
        for i, t in enumerate(result["curves"]["params"]):
            got = curve.envelope(t, membership, alpha)
            if want is None:
                assert got is None, (membership, t)
                continue
            assert got is not None and got.shape == (2, 2) and got.dtype == np.float64
            np.testing.assert_array_equal(got[:, 0], want["left"][i], err_msg=f"{membership} {t}")
            np.testing.assert_array_equal(got[:, 1], want["right"][i], err_msg=f"{membership} {t}")
    # Defaults: the upper function at level 0, which holds every other.
    t = 0.37
    wide = curve.envelope(t)
    assert wide is not None
    np.testing.assert_array_equal(wide, curve.envelope(t, "upper", 0.0))
    for membership in ("primary", "lower"):
        inner = curve.envelope(t, membership, 0.3)  # type: ignore[arg-type]
        assert inner is not None
        assert np.all(wide[:, 0] <= inner[:, 0]) and np.all(inner[:, 1] <= wide[:, 1])
    # At alpha 1 every cut is the crisp value: the crisp curve.
    top = curve.envelope(t, "upper", 1.0)
    assert top is not None
    np.testing.assert_allclose(top[:, 0], top[:, 1], rtol=0, atol=1e-15)
    np.testing.assert_allclose(top[:, 0], curve.crisp_curve().eval(t), rtol=0, atol=1e-14)
    with pytest.raises(ValueError, match="outside the domain"):
        curve.envelope(1.5)
    with pytest.raises(ValueError, match="membership"):
        curve.envelope(0.5, "uper")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="alpha"):
        curve.envelope(0.5, "upper", 1.5)


def test_with_crisp_weights_the_envelope_is_the_box_of_the_layer_curves() -> None:
    crisp_weights = FuzzyCurve.from_job(ROOT / "examples" / "paper-alg-1-1.json")
    for t in np.linspace(0.0, 1.0, 9):
        layers = crisp_weights.eval_layers(t)  # (7, d): upper_left ... upper_right
        for membership, (left, right) in (("upper", (0, 6)), ("primary", (1, 5))):
            got = crisp_weights.envelope(t, membership)  # type: ignore[arg-type]
            assert got is not None
            np.testing.assert_allclose(got[:, 0], layers[left], rtol=0, atol=1e-12)
            np.testing.assert_allclose(got[:, 1], layers[right], rtol=0, atol=1e-12)


def test_the_membership_is_the_cli_result(cli: Path, tmp_path: Path, curve: FuzzyCurve) -> None:
    rng = np.random.default_rng(7)
    points = np.column_stack([rng.uniform(0.5, 6.5, 24), rng.uniform(0.5, 5.0, 24)])
    points = np.vstack([points, curve.crisp_curve().sample(5)])
    path = tmp_path / "points.csv"
    path.write_text("x,y\n" + "".join(f"{float(x)!r},{float(y)!r}\n" for x, y in points))
    out = subprocess.run(
        [str(cli), "membership", str(JOB), str(path)], check=True, capture_output=True, text=True
    ).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == len(points)
    got = curve.membership(points)
    for m in ("upper", "primary", "lower"):
        np.testing.assert_array_equal(got[m], [float(r[m]) for r in rows], err_msg=m)
    # The crisp curve's points grade (1, 1, h).
    np.testing.assert_array_equal(got["upper"][-5:], 1.0)


def test_the_section_is_the_cli_result(cli: Path, curve: FuzzyCurve) -> None:
    out = subprocess.run(
        [str(cli), "section", str(JOB), "--x", "3.5", "--levels", "3"], check=True, capture_output=True, text=True
    ).stdout
    got = curve.section(3.5, levels=3)
    assert got == json.loads(out)["levels"]
    assert got[0]["upper"], "the station meets the curve's region"


def test_what_takes_crisp_weights_only_says_so_as_the_core_does(curve: FuzzyCurve) -> None:
    def refused(what: str) -> str:
        return f"^{what} is not available for a model with fuzzy weights$"

    with pytest.raises(ValueError, match=refused("knot insertion")):
        curve.insert_knot(0.5)
    for call in (lambda: curve.refine_knots([0.3]), lambda: curve.elevate_degree(),
                 lambda: curve.split_at(0.5), lambda: curve.segment(0.2, 0.6),
                 lambda: curve.region(0.2), lambda: curve.measure(levels=3),
                 lambda: curve.membership_grid((0, 7), (0, 6), 8)):
        with pytest.raises(ValueError, match="is not available for a model with fuzzy weights$"):
            call()


def test_pickling_keeps_the_weight_numbers(curve: FuzzyCurve) -> None:
    for again in (pickle.loads(pickle.dumps(curve)), copy.deepcopy(curve), copy.copy(curve)):
        assert again == curve
        assert again.weight_numbers == curve.weight_numbers
    solution = curve.solve(0.8)
    back = pickle.loads(pickle.dumps(solution))
    assert back == solution
    np.testing.assert_array_equal(back.defuzzified_weights(), solution.defuzzified_weights())


def test_crisp_numbers_as_weights_are_plain_weights(curve: FuzzyCurve) -> None:
    plain = from_arrays([1.0, 2.0, 3.0, 0.5])
    for given in (
        [FuzzyNumber(1.0), 2, FuzzyNumber(3.0, (3.0, 3.0), (3.0, 3.0), (3.0, 3.0), 0.4), 0.5],
        (1.0, FuzzyNumber(2.0), 3.0, FuzzyNumber(0.5)),
        np.array([FuzzyNumber(1.0), 2.0, 3.0, FuzzyNumber(0.5)], dtype=object),
        np.array([1.0, 2.0, 3.0, 0.5]),
    ):
        made = from_arrays(list(given) if isinstance(given, tuple) else given)  # type: ignore[arg-type]
        assert made == plain and made.weight_numbers is None
        assert pickle.loads(pickle.dumps(made)) == plain
    np.testing.assert_array_equal(plain.solve(0.5).defuzzified_weights(), [1.0, 2.0, 3.0, 0.5])
    # The fuzzy curve's crisp-weight twin has the same crisp layer.
    twin = from_arrays([1.0, 1.0, 3.0, 1.0])
    np.testing.assert_array_equal(twin.crisp_curve().sample(9), curve.crisp_curve().sample(9))


def test_bad_weights_are_named(curve: FuzzyCurve) -> None:
    w = example_weights()
    w[1] = FuzzyNumber(1.0, upper=(-0.5, 2.0))
    with pytest.raises(ValueError, match=r"^weights\[1\] = -0\.5 must be finite and greater than 0$"):
        from_arrays(w)
    w = example_weights()
    w[3] = FuzzyNumber(1.0, upper=(1e-151, 1.0))
    with pytest.raises(ValueError, match=r"^weights\[3\] = 1e-151 is outside \[1e-150, 1e150\]$"):
        from_arrays(w)
    with pytest.raises(ValueError, match=r"^weights\[0\] = NaN"):
        from_arrays([float("nan"), *example_weights()[1:]])
    with pytest.raises(TypeError, match=r"weights\[0\]: expected a real number"):
        from_arrays(["1", *example_weights()[1:]])
    with pytest.raises(ValueError, match="weights"):
        from_arrays(example_weights()[:3])
