"""Surface jobs from Python: `t2spline.run` equals `t2spline run` bit for
bit on the shipped surface examples, grids come back as `(su, sv, d)`
arrays, a broken surface job gives the CLI's problem lines, and
`FuzzySurface.from_job(job).solve(alpha)` is the run's solution to the
bit."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any, Dict

import numpy as np
import pytest

import t2spline

from conftest import ROOT, assert_same, bits, cli_errors, cli_run

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"
CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"


@pytest.mark.parametrize("example", [TERRAIN, CYLINDER], ids=["terrain", "cylinder"])
def test_the_shipped_surfaces_equal_the_cli(cli: Path, example: Path) -> None:
    assert_same(t2spline.run(example), cli_run(cli, example))


@pytest.mark.parametrize(
    "kwargs, args",
    [
        ({"samples": (5, 4)}, ["--samples", "5,4"]),
        ({"samples": 7}, ["--samples", "7"]),
        ({"alpha": 0.9, "samples": (2, 3)}, ["--alpha", "0.9", "--samples", "2,3"]),
    ],
)
def test_keywords_equal_the_cli_options(cli: Path, kwargs: Dict[str, Any], args: list) -> None:
    assert_same(t2spline.run(TERRAIN, **kwargs), cli_run(cli, TERRAIN, *args))


def test_grids_are_arrays_of_rows_of_points() -> None:
    job = json.loads(TERRAIN.read_text())
    rows, columns = len(job["points"]), len(job["points"][0])
    r = t2spline.run(TERRAIN, samples=(6, 4))
    surfaces, cps = r["surfaces"], r["control_points"]
    assert surfaces["params"]["u"].shape == (6,) and surfaces["params"]["v"].shape == (4,)
    for key in ("crisp", "defuzzified"):
        assert surfaces[key].shape == (6, 4, 3) and surfaces[key].dtype == np.float64
        assert cps[key].shape == (rows, columns, 3)
    for name, grid in surfaces["layers"].items():
        assert grid.shape == (6, 4, 3), name
    assert r["weights"].shape == (rows, columns)
    assert r["error"]["max_at"].shape == (2,)
    # The corners of a clamped surface are its corner control points.
    assert np.array_equal(surfaces["crisp"][0, 0], cps["crisp"][0, 0])
    assert np.array_equal(surfaces["crisp"][-1, -1], cps["crisp"][-1, -1])
    # The seven-value order of a fuzzy number holds at every grid point in z
    # (the terrain's uncertain heights).
    layers = surfaces["layers"]
    order = ["upper_left", "primary_left", "lower_left"]
    z = [layers[name][..., 2] for name in order]
    assert np.all(z[0] <= z[1]) and np.all(z[1] <= z[2])
    assert np.all(z[2] <= surfaces["crisp"][..., 2] + 1e-9)


def test_a_broken_surface_job_gives_the_cli_lines(cli: Path, tmp_path: Path) -> None:
    job = json.loads(TERRAIN.read_text())
    broken = copy.deepcopy(job)
    del broken["points"][1][2]["z"]  # a 2-D point in a 3-D net
    broken["points"][3].pop()  # a ragged row
    path = tmp_path / "job.json"
    path.write_text(json.dumps(broken, indent=2))
    want = [line.replace(str(path), "<dict>") for line in cli_errors(cli, path)]
    assert len(want) >= 2
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(broken)
    assert e.value.problems == want


def test_one_sample_in_a_direction_is_refused() -> None:
    with pytest.raises(ValueError, match="samples"):
        t2spline.run(TERRAIN, samples=(1, 5))


@pytest.mark.parametrize("example", [TERRAIN, CYLINDER], ids=["terrain", "cylinder"])
def test_fuzzy_surface_solve_equals_run_bit_for_bit(example: Path) -> None:
    """`FuzzySurface.from_job(job).solve(alpha)` is the run's solution: the
    distance, every control net of stages 2–4 and every grid, to the bit."""
    r = t2spline.run(example)
    surface = t2spline.FuzzySurface.from_job(example)
    solution = surface.solve(json.loads(example.read_text())["alpha"])
    d = solution.distance()
    got = np.array([d["max"], d["rms"], *d["max_at"]])
    want = np.array([r["error"]["max"], r["error"]["rms"], *r["error"]["max_at"]])
    assert np.array_equal(bits(got), bits(want))
    assert d["max"] > 0 and d["rms"] > 0
    assert np.array_equal(surface.weights, r["weights"])
    assert np.array_equal(surface.knots_u, r["knots"]["u"]) and np.array_equal(surface.knots_v, r["knots"]["v"])
    assert list(surface.degree) == r["degree"]
    cps = r["control_points"]
    for key in ("crisp", "type_reduced_left", "type_reduced_right", "defuzzified"):
        assert np.array_equal(bits(getattr(solution, key)), bits(cps[key])), key
    for name, values in cps["alpha_cut"].items():
        assert np.array_equal(bits(solution.alpha_cut[name]), bits(values)), name
    for name, values in cps["layers"].items():
        assert np.array_equal(surface.layer_control_points(name), values), name
    grids = r["surfaces"]
    su, sv = len(grids["params"]["u"]), len(grids["params"]["v"])
    layers = surface.sample(su, sv)
    assert np.array_equal(layers["u"], grids["params"]["u"]) and np.array_equal(layers["v"], grids["params"]["v"])
    assert np.array_equal(bits(layers["crisp"]), bits(grids["crisp"]))
    for name, grid in grids["layers"].items():
        assert np.array_equal(bits(layers[name]), bits(grid)), name
    stages = solution.sample(su, sv)
    assert np.array_equal(bits(stages["defuzzified"]), bits(grids["defuzzified"]))
    for side in ("left", "right"):
        assert np.array_equal(bits(stages["type_reduced"][side]), bits(grids["type_reduced"][side]))
    for name, grid in grids["alpha_cut"].items():
        assert np.array_equal(bits(stages["alpha_cut"][name]), bits(grid)), name


def test_from_job_takes_a_dict_and_refuses_a_curve() -> None:
    job = json.loads(TERRAIN.read_text())
    assert t2spline.FuzzySurface.from_job(job) == t2spline.FuzzySurface.from_job(TERRAIN)
    with pytest.raises(ValueError, match=r"the job is not a surface$"):
        t2spline.FuzzySurface.from_job(ROOT / "examples" / "paper-alg-1-1.json")
    with pytest.raises(ValueError, match=r"^<dict>: the job is not a curve$"):
        t2spline.FuzzyCurve.from_job(job)
    broken = copy.deepcopy(job)
    broken["points"][3].pop()
    with pytest.raises(t2spline.JobError):
        t2spline.FuzzySurface.from_job(broken)
