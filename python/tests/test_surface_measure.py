"""Volumes, plan area and surface area of a fuzzy surface (docs/method.md
§14) from Python: `FuzzySurface.measure` gives the numbers `t2spline
measure` writes for a surface job; a flat square's volumes have their
closed form; the intervals nest; a surface whose x or y is fuzzy is refused
with the control point named."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import t2spline

from conftest import ROOT

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"
CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"
QUANTITIES = ("volume_below", "volume_above", "plan_area_below")


def flat(height: float, spread: float) -> t2spline.FuzzySurface:
    x, y = np.meshgrid([0.0, 2.0], [0.0, 2.0], indexing="ij")
    crisp = np.stack([x, y, height + 0 * x], axis=-1)
    s = np.array([0.0, 0.0, 1.0])[:, None] * np.array([-spread, spread])
    return t2spline.FuzzySurface(
        crisp,
        crisp[..., None] + s,
        crisp[..., None] + 0.5 * s,
        crisp[..., None] + 0 * s,
        lower_height=1.0,
        degree=1,
    )


def test_python_gives_what_the_command_writes(cli: Path) -> None:
    done = subprocess.run(
        [str(cli), "measure", str(TERRAIN), "--levels", "2", "--datum", "103", "--no-area"],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    want = json.loads(done.stdout)
    got = t2spline.FuzzySurface.from_job(TERRAIN).measure(levels=2, datum=103.0, area=False)
    assert "area" not in got
    assert got["datum"] == want["datum"] == 103.0
    np.testing.assert_array_equal(got["levels"], want["levels"])
    for q in QUANTITIES:
        for f in ("upper", "primary", "lower"):
            assert got[q][f] == want[q][f], (q, f)


def test_a_flat_square_has_its_closed_form_volumes() -> None:
    # Height 1 ± 0.5 over a 2 × 2 square, measured from datum 1.25.
    m = flat(1.0, 0.5).measure(levels=[0.0, 1.0], datum=1.25)
    below, above, flooded = (m[q]["upper"] for q in QUANTITIES)
    assert below[0]["min"] == pytest.approx(0.0, abs=1e-12)
    assert below[0]["max"] == pytest.approx(4 * 0.75, rel=1e-12)
    assert above[0]["max"] == pytest.approx(4 * 0.25, rel=1e-12)
    assert flooded[0]["max"] == pytest.approx(4.0, rel=1e-12)
    assert below[1]["min"] == pytest.approx(4 * 0.25, rel=1e-12)
    assert below[1]["max"] == pytest.approx(4 * 0.25, rel=1e-12)
    assert all(level["exact"] for level in below + above + flooded)
    area = m["area"]["upper"]
    # Every net of equal heights is flat: area 4 at the crisp level.
    assert area[1]["min"] == pytest.approx(4.0, rel=1e-9)
    assert area[0]["min"] <= 4.0 + 1e-9 <= area[0]["max"] + 2e-9


def test_the_terrain_intervals_nest() -> None:
    m = t2spline.FuzzySurface.from_job(TERRAIN).measure(levels=3, datum=103.0, area=False)
    for q in QUANTITIES:
        for f in ("upper", "primary", "lower"):
            levels = m[q][f]
            for outer, inner in zip(levels, levels[1:]):
                assert outer["min"] <= inner["min"] and inner["max"] <= outer["max"], (q, f)
        for outer, inner in ((m[q]["upper"], m[q]["primary"]), (m[q]["primary"], m[q]["lower"])):
            for o, i in zip(outer, inner):
                assert o["alpha"] == i["alpha"]
                assert o["min"] <= i["min"] and i["max"] <= o["max"], q


def test_a_fuzzy_plan_and_bad_arguments_are_refused() -> None:
    with pytest.raises(ValueError, match=r"points\[\d+\]\[\d+\]\.[xy] is fuzzy"):
        t2spline.FuzzySurface.from_job(CYLINDER).measure(levels=2)
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    with pytest.raises(ValueError, match="datum"):
        terrain.measure(datum=float("nan"))
    with pytest.raises(ValueError, match="levels"):
        terrain.measure(levels=1)


def test_a_function_without_a_cut_at_a_level_is_an_empty_list() -> None:
    # The terrain's lower functions end below level 1: an empty list of
    # levels, as the command writes `[]`, not an empty array.
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    m = terrain.measure(levels=[1.0], area=False)
    for q in QUANTITIES:
        assert m[q]["lower"] == [] and isinstance(m[q]["lower"], list)
        assert isinstance(m[q]["upper"], list) and len(m[q]["upper"]) == 1
    curve = t2spline.FuzzyCurve.from_job(ROOT / "examples" / "paper-alg-1-1.json")
    c = curve.measure(levels=[1.0])
    assert c["length"]["lower"] == [] and isinstance(c["length"]["lower"], list)
    assert c["at"] == [] and isinstance(c["at"], list)


RESURVEY = ROOT / "fixtures" / "fuzzy-terrain-resurvey.json"


def test_cut_and_fill_as_the_command_writes_them(cli: Path) -> None:
    done = subprocess.run(
        [str(cli), "measure", str(RESURVEY), "--against", str(TERRAIN), "--levels", "3"]
        + ["--no-area"],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    want = json.loads(done.stdout)
    new = t2spline.FuzzySurface.from_job(RESURVEY)
    got = new.measure(levels=3, area=False, against=t2spline.FuzzySurface.from_job(TERRAIN))
    for q in ("cut", "fill", *QUANTITIES):
        for f in ("upper", "primary", "lower"):
            assert got[q][f] == want[q][f], (q, f)
    assert "cut" not in new.measure(levels=3, area=False)


def test_two_flat_squares_have_their_closed_form_cut_and_fill() -> None:
    # 1 ± 0.5 against 0.75 ± 0.25 over a 2 × 2 square: at level α the
    # difference 0.25 + δ, |δ| ≤ 0.75 (1 − α), is flat, so the cut is
    # 4·max(0.25 + δ, 0) and the fill 4·max(−0.25 − δ, 0).
    m = flat(1.0, 0.5).measure(levels=[0.0, 0.5, 1.0], area=False, against=flat(0.75, 0.25))
    for level, cut, fill in zip((0.0, 0.5, 1.0), m["cut"]["upper"], m["fill"]["upper"]):
        d = 0.75 * (1.0 - level)
        assert cut["alpha"] == fill["alpha"] == level
        assert cut["min"] == pytest.approx(4 * max(0.25 - d, 0.0), abs=1e-9)
        assert cut["max"] == pytest.approx(4 * (0.25 + d), abs=1e-9)
        assert fill["min"] == pytest.approx(0.0, abs=1e-9)
        assert fill["max"] == pytest.approx(4 * max(d - 0.25, 0.0), abs=1e-9)
        assert cut["exact"] and fill["exact"]


def test_against_a_plan_that_does_not_overlap_is_refused() -> None:
    x, y = np.meshgrid([5.0, 8.0], [0.0, 2.0], indexing="ij")
    crisp = np.stack([x, y, 0 * x], axis=-1)
    crisp_cut = crisp[..., None] + np.zeros(2)
    wider = t2spline.FuzzySurface(
        crisp, crisp_cut, crisp_cut, crisp_cut, lower_height=1.0, degree=1
    )
    with pytest.raises(ValueError, match=r"plans cannot be compared \(the plans do not overlap\)"):
        flat(1.0, 0.5).measure(levels=2, against=wider)
