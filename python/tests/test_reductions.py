"""Type reductions from Python (docs/method.md §9): `run`'s `type_reduction=` and the
job key equal `t2spline run --type-reduction` bit for bit, `solve(alpha,
type_reduction=)` of curves and surfaces equals `run`'s, an unused alpha is
warned about, and `centroid` of sampled sets against a brute force over every
switch point and against the exact centroid of a number."""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any, List

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, assert_same, bits, cli_run

REDUCTIONS: List[Any] = ["paper", "centroid", "nie-tan", "alpha-planes"]

# The example carries alpha 0.8, which only the paper's reduction uses; the
# warning about it is tested on its own.
pytestmark = pytest.mark.filterwarnings("ignore:type reduction .* does not use alpha")


@pytest.mark.parametrize("name", REDUCTIONS)
def test_the_keyword_equals_the_cli_option(cli: Path, name: Any) -> None:
    got = t2spline.run(EXAMPLE, type_reduction=name, samples=17)
    assert_same(got, cli_run(cli, EXAMPLE, "--type-reduction", name, "--samples", "17"))
    assert got["type_reduction"] == name
    assert got["alpha_used"] is (name == "paper")
    assert (got["regime"] is None) is (name != "paper")


@pytest.mark.parametrize("name", REDUCTIONS)
def test_a_surface_job_takes_the_keyword_as_the_cli_takes_the_option(cli: Path, name: Any) -> None:
    terrain = EXAMPLE.parent / "fuzzy-terrain.json"
    got = t2spline.run(terrain, type_reduction=name, samples=(5, 4))
    assert_same(got, cli_run(cli, terrain, "--type-reduction", name, "--samples", "5,4"))
    assert got["type_reduction"] == name


@pytest.mark.parametrize("name", REDUCTIONS[1:])
def test_the_job_key_equals_the_cli(cli: Path, tmp_path: Path, name: str) -> None:
    job = json.loads(EXAMPLE.read_text())
    job["type_reduction"] = name
    del job["alpha"]  # not needed by these reductions
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job, indent=2))
    got = t2spline.run(job)
    assert_same(got, cli_run(cli, path))
    assert got["alpha"] == 0.0
    # The keyword overrides the key.
    assert t2spline.run(job, type_reduction="paper", alpha=0.8)["type_reduction"] == "paper"


def test_the_reductions_of_the_shipped_example() -> None:
    """The distances of docs/reductions.md, and the Nie–Tan value on both sides."""
    want = {
        "paper": (0.022439, 0.017069),
        "centroid": (0.106747, 0.081312),
        "nie-tan": (0.123455, 0.091905),
        "alpha-planes": (0.096948, 0.073612),
    }
    for name, (max_, rms) in want.items():
        r = t2spline.run(EXAMPLE, type_reduction=name)
        assert (round(r["error"]["max"], 6), round(r["error"]["rms"], 6)) == (max_, rms), name
    cps = t2spline.run(EXAMPLE, type_reduction="nie-tan")["control_points"]
    assert np.array_equal(cps["type_reduced_left"], cps["defuzzified"])
    assert np.array_equal(cps["type_reduced_right"], cps["defuzzified"])


def test_an_alpha_that_is_not_used_is_warned_about() -> None:
    with pytest.warns(UserWarning, match="centroid does not use alpha; alpha=0.3 is ignored"):
        t2spline.run(EXAMPLE, type_reduction="centroid", alpha=0.3)
    with pytest.warns(UserWarning, match="the job's alpha 0.8 is ignored"):
        t2spline.run(EXAMPLE, type_reduction="alpha-planes")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        t2spline.run(EXAMPLE, type_reduction="paper", alpha=0.3)


TERRAIN = EXAMPLE.parent / "fuzzy-terrain.json"


@pytest.mark.parametrize("name", REDUCTIONS)
@pytest.mark.parametrize("kind", ["curve", "surface"])
def test_solve_takes_the_reduction_as_run_takes_it(kind: str, name: Any) -> None:
    """The solution of `solve(alpha, type_reduction=name)` is the run's with
    `type_reduction=name`, to the bit: the distance, the control points of
    stages 3–4, the sampled defuzzified curve or surface."""
    job = EXAMPLE if kind == "curve" else TERRAIN
    alpha = json.loads(job.read_text())["alpha"]
    r = t2spline.run(job, type_reduction=name)
    if kind == "curve":
        solution: Any = t2spline.FuzzyCurve.from_job(job).solve(alpha, type_reduction=name)
        samples = solution.sample(len(r["curves"]["params"]))
        assert np.array_equal(bits(samples["defuzzified"]), bits(r["curves"]["defuzzified"]))
    else:
        solution = t2spline.FuzzySurface.from_job(job).solve(alpha, type_reduction=name)
        grids = r["surfaces"]
        samples = solution.sample(len(grids["params"]["u"]), len(grids["params"]["v"]))
        assert np.array_equal(bits(samples["defuzzified"]), bits(grids["defuzzified"]))
    assert solution.type_reduction == name
    assert solution.alpha == r["alpha"] == (alpha if name == "paper" else 0.0)
    d = solution.distance()
    got = np.array([d["max"], d["rms"], *np.atleast_1d(d["max_at"])])
    want = np.array([r["error"]["max"], r["error"]["rms"], *np.atleast_1d(r["error"]["max_at"])])
    assert np.array_equal(bits(got), bits(want))
    cps = r["control_points"]
    for key in ("type_reduced_left", "type_reduced_right", "defuzzified"):
        assert np.array_equal(bits(getattr(solution, key)), bits(cps[key])), key
    for layer, values in cps["alpha_cut"].items():
        assert np.array_equal(bits(solution.alpha_cut[layer]), bits(values)), layer


def test_the_reductions_of_solve_differ_as_docs_reductions_says() -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    maxima = {name: round(curve.solve(0.8, name).distance()["max"], 6) for name in REDUCTIONS}
    assert maxima == {"paper": 0.022439, "centroid": 0.106747, "nie-tan": 0.123455,
                      "alpha-planes": 0.096948}


def test_solve_warns_about_an_alpha_it_does_not_use() -> None:
    for model in (t2spline.FuzzyCurve.from_job(EXAMPLE), t2spline.FuzzySurface.from_job(TERRAIN)):
        with pytest.warns(UserWarning, match="centroid does not use alpha; alpha=0.3 is ignored"):
            solution = model.solve(0.3, type_reduction="centroid")
        assert solution.alpha == 0.0
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            assert model.solve(type_reduction="nie-tan").alpha == 0.0
            assert model.solve(0.3).alpha == 0.3
            assert model.solve(alpha=0.3, type_reduction="paper").type_reduction == "paper"
        with pytest.raises(ValueError, match="^alpha: missing: the paper's type reduction needs"):
            model.solve()
        with pytest.raises(ValueError, match=r"^alpha = 1.5 is outside \[0, 1\]"):
            model.solve(1.5, type_reduction="centroid")  # checked even when unused
        with pytest.raises(ValueError, match="^type_reduction: unknown type reduction `nietan`"):
            model.solve(0.3, type_reduction="nietan")  # type: ignore[arg-type]


def test_an_unknown_reduction_is_a_value_error() -> None:
    with pytest.raises(ValueError, match="type_reduction: unknown type reduction `nietan`"):
        t2spline.run(EXAMPLE, type_reduction="nietan")  # type: ignore[arg-type]
    job = json.loads(EXAMPLE.read_text())
    job["type_reduction"] = "nietan"
    with pytest.raises(t2spline.JobError, match="did you mean `nie-tan`"):
        t2spline.run(job)


def brute_force(x: np.ndarray, lmf: np.ndarray, umf: np.ndarray) -> tuple[float, float]:
    """The discrete centroid by trying every switch point: c_l is the least
    centroid with umf up to the switch and lmf after it, c_r the greatest with
    lmf up to the switch and umf after it."""
    lefts, rights = [], []
    for k in range(len(x) + 1):
        w = np.concatenate([umf[:k], lmf[k:]])
        if w.sum() > 0:
            lefts.append(float((x * w).sum() / w.sum()))
        w = np.concatenate([lmf[:k], umf[k:]])
        if w.sum() > 0:
            rights.append(float((x * w).sum() / w.sum()))
    return min(lefts), max(rights)


def test_km_ekm_and_eiasc_give_the_brute_force_centroid() -> None:
    rng = np.random.default_rng(10)
    for case in range(200):
        n = int(rng.integers(1, 40))
        x = np.sort(rng.uniform(-5, 5, n))
        umf = rng.uniform(0, 1, n)
        lmf = umf * rng.uniform(0, 1, n)
        if case % 3 == 0:
            lmf[rng.uniform(size=n) < 0.5] = 0.0
        left, right = brute_force(x, lmf, umf)
        for method in ("km", "ekm", "eiasc"):
            c = t2spline.centroid(x, lmf, umf, method=method)
            assert c["left"] == pytest.approx(left, abs=1e-12), (case, method)
            assert c["right"] == pytest.approx(right, abs=1e-12), (case, method)
            assert c["defuzzified"] == pytest.approx((left + right) / 2, abs=1e-12)
            assert all(isinstance(i, int) and i >= 1 for i in c["iterations"])
        nie_tan = t2spline.centroid(x, lmf, umf, method="nie-tan")
        value = float((x * (lmf + umf)).sum() / (lmf + umf).sum())
        assert nie_tan["left"] == nie_tan["right"] == nie_tan["defuzzified"]
        assert nie_tan["left"] == pytest.approx(value, abs=1e-12)
        assert left - 1e-12 <= value <= right + 1e-12
        assert nie_tan["iterations"] == (0, 0)


def test_a_sampled_number_approaches_the_exact_centroid_of_a_run() -> None:
    """Sampling the first control point's x of the example finely, the
    discrete centroid approaches the run's exact one, with an error of order
    1/N²."""
    job = json.loads(EXAMPLE.read_text())
    n = job["points"][0]["x"]
    h = n.get("lower_height", job.get("lower_height"))
    number = t2spline.FuzzyNumber(n["crisp"], n["upper"], n["primary"], n["lower"], h)
    exact = t2spline.run(job, type_reduction="centroid")["control_points"]
    want = (exact["type_reduced_left"][0, 0], exact["type_reduced_right"][0, 0])
    errors = []
    for count in (101, 1001):
        x = np.linspace(n["upper"][0], n["upper"][1], count)
        c = t2spline.centroid(x, number.membership(x, "lower"), number.membership(x, "upper"))
        errors.append(max(abs(c["left"] - want[0]), abs(c["right"] - want[1])))
    assert errors[1] < 1e-5
    assert errors[1] < errors[0] / 50  # about 100 for 1/N²


def test_bad_samples_are_value_errors_naming_the_place() -> None:
    with pytest.raises(ValueError, match=r"lmf\[1\] = 0.9 is greater than the umf"):
        t2spline.centroid([0, 1, 2], [0, 0.9, 0], [0.5, 0.5, 0.5])
    with pytest.raises(ValueError, match=r"x\[2\] = 0.5 is less than the x before it"):
        t2spline.centroid([0, 1, 0.5], [0, 0, 0], [1, 1, 1])
    with pytest.raises(ValueError, match="lmf"):
        t2spline.centroid([0, 1], [0], [1, 1])
    with pytest.raises(ValueError, match="umf"):
        t2spline.centroid([0, 1], [0, 0], [0, 0])
    with pytest.raises(ValueError, match="x: expected a one-dimensional array"):
        t2spline.centroid([[0, 1]], [[0, 0]], [[1, 1]])
    with pytest.raises(ValueError, match="method: unknown method `kmm`"):
        t2spline.centroid([0, 1], [0, 0], [1, 1], method="kmm")  # type: ignore[arg-type]
