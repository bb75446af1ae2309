"""`t2spline.run` against `t2spline run`: the same keys, the same numbers
bit for bit (both come from `Job::run`), numpy arrays of the documented
shapes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, assert_same, cli_run, random_job


def test_the_shipped_example_equals_the_cli(cli: Path) -> None:
    assert_same(t2spline.run(EXAMPLE), cli_run(cli, EXAMPLE))


@pytest.mark.parametrize(
    "kwargs, args",
    [
        ({"alpha": 0.3}, ["--alpha", "0.3"]),
        ({"alpha": 0.6, "samples": 7}, ["--alpha", "0.6", "--samples", "7"]),
        ({"alpha": 1.0, "samples": 2}, ["--alpha", "1", "--samples", "2"]),
        ({"derivatives": 3, "samples": 11}, ["--derivatives", "3", "--samples", "11"]),
    ],
)
def test_keywords_equal_the_cli_options(cli: Path, kwargs: dict, args: list) -> None:
    assert_same(t2spline.run(EXAMPLE, **kwargs), cli_run(cli, EXAMPLE, *args))


def test_random_jobs_equal_the_cli(cli: Path, tmp_path: Path) -> None:
    rng = np.random.default_rng(20261201)
    for k in range(40):
        job = random_job(rng)
        path = tmp_path / f"job{k}.json"
        path.write_text(json.dumps(job, indent=2))
        want = cli_run(cli, path)
        assert_same(t2spline.run(job), want, f"job {k}")
        assert_same(t2spline.run(path), want, f"job {k} by path")


def test_a_dict_a_str_and_a_path_give_the_same_result(tmp_path: Path) -> None:
    job = json.loads(EXAMPLE.read_text())
    by_dict = t2spline.run(job)
    for source in (str(EXAMPLE), EXAMPLE):
        assert_same(by_dict, json.loads(json.dumps(_lists(t2spline.run(source)))))


def _lists(value: object) -> object:
    """A result with its arrays as lists (NaN as None), i.e. its JSON form."""
    if isinstance(value, dict):
        return {k: _lists(v) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        return json.loads(json.dumps(value.tolist()).replace("NaN", "null"))
    if isinstance(value, list):
        return [_lists(v) for v in value]
    return value


def test_numpy_values_in_a_job_dict_are_taken_as_numbers() -> None:
    job = json.loads(EXAMPLE.read_text())
    job["weights"] = np.array(job["weights"], dtype=np.float64)
    job["alpha"] = np.float64(job["alpha"])
    job["points"][0]["x"]["upper"] = np.array(job["points"][0]["x"]["upper"])
    assert_same(t2spline.run(job), _lists(t2spline.run(EXAMPLE)))


def test_shapes_dtypes_and_scalars() -> None:
    r = t2spline.run(EXAMPLE, samples=33, derivatives=2)
    n, d = 4, 2
    curves, cps = r["curves"], r["control_points"]
    assert curves["params"].shape == (33,)
    assert curves["params"][0] == 0.0 and curves["params"][-1] == 1.0
    for key in ("crisp", "defuzzified"):
        assert curves[key].shape == (33, d) and curves[key].dtype == np.float64
    for name, points in curves["layers"].items():
        assert points.shape == (33, d), name
    assert curves["derivatives"]["crisp"].shape == (2, 33, d)
    assert isinstance(curves["arc_length"]["crisp"], float)
    for key in ("crisp", "type_reduced_left", "type_reduced_right", "defuzzified"):
        assert cps[key].shape == (n, d), key
    assert r["weights"].shape == (n,) and r["knots"].shape == (n + 3,)
    assert r["domain"].tolist() == [0.0, 1.0]
    assert isinstance(r["alpha"], float) and isinstance(r["error"]["max"], float)
    assert isinstance(r["order"], int) and r["order"] == 3
    assert isinstance(r["regime"], str) and isinstance(r["description"], str)


def test_absent_lower_cuts_are_nan_points_and_none_curves() -> None:
    # The example's lower height is 0.6; alpha 0.8 is above it.
    r = t2spline.run(EXAMPLE)
    assert r["regime"] == "alpha > h"
    cut = r["control_points"]["alpha_cut"]
    assert np.isnan(cut["lower_left"]).all() and np.isnan(cut["lower_right"]).all()
    assert not np.isnan(cut["upper_left"]).any()
    assert r["curves"]["alpha_cut"]["lower_left"] is None
    assert r["curves"]["alpha_cut"]["upper_left"].shape == (101, 2)
    # With one number of height 0.5, at alpha 0.55 only the others have a
    # lower cut.
    job = json.loads(EXAMPLE.read_text())
    job["points"][1]["y"]["lower_height"] = 0.5
    mixed = t2spline.run(job, alpha=0.55)
    assert mixed["regime"] == "mixed"
    lower = mixed["control_points"]["alpha_cut"]["lower_left"]
    assert np.isnan(lower).tolist() == [[False, False], [False, True], [False, False], [False, False]]
    assert mixed["curves"]["alpha_cut"]["lower_left"] is None


def test_the_result_is_the_objects_result() -> None:
    """`run` and the objects share the engine: the same numbers."""
    r = t2spline.run(EXAMPLE)
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    layers = curve.sample(101)
    for name, points in r["curves"]["layers"].items():
        assert np.array_equal(points, layers[name]), name
    assert np.array_equal(r["curves"]["crisp"], layers["crisp"])
    solution = curve.solve(r["alpha"])
    cps = r["control_points"]
    assert np.array_equal(cps["defuzzified"], solution.defuzzified)
    assert np.array_equal(cps["type_reduced_left"], solution.type_reduced_left)
    for name, points in cps["alpha_cut"].items():
        assert np.array_equal(points, solution.alpha_cut[name], equal_nan=True), name
    assert solution.distance() == {k: r["error"][k] for k in ("max", "max_at", "rms")}
    stages = solution.sample(101)
    assert np.array_equal(stages["defuzzified"], r["curves"]["defuzzified"])
