"""Surface jobs from Python: `t2spline.run` equals `t2spline run` bit for
bit on the shipped surface examples, grids come back as `(su, sv, d)`
arrays, and a broken surface job gives the CLI's problem lines."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any, Dict

import numpy as np
import pytest

import t2spline

from conftest import ROOT, assert_same, cli_errors, cli_run

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
