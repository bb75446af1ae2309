"""The distance between the crisp and the defuzzified curve (surface) at
many levels at once, `distance_sweep`: each level's distances equal numpy's
norm of the two curves sampled by their own `sample`, the summary is the
trapezoidal rule of those samples, and its largest value comes within a
fraction of a per cent of the exact `error.max` that `t2spline run` prints
(never above it)."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, ROOT

CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"


def trapezoid_rms(d: np.ndarray) -> float:
    """The rms of samples `d` (1-D or 2-D) by the trapezoidal rule."""
    w = np.ones(d.shape)
    for axis in range(d.ndim):
        index = [slice(None)] * d.ndim
        for end in (0, -1):
            index[axis] = end
            w[tuple(index)] *= 0.5
    return float(np.sqrt((w * d**2).sum() / w.sum()))


def test_a_curve_sweep_equals_its_curves_sampled_by_numpy() -> None:
    job = json.loads(EXAMPLE.read_text())
    curve = t2spline.FuzzyCurve.from_job(job)
    alphas = np.linspace(0.0, 1.0, 21)
    sweep = curve.distance_sweep(alphas, samples=501)
    assert sweep["distance"].shape == (21, 501)
    np.testing.assert_array_equal(sweep["alpha"], alphas)
    for k, a in enumerate(alphas):
        s = curve.solve(float(a))
        d = np.linalg.norm(
            s.defuzzified_curve().sample(501) - s.crisp_curve().sample(501), axis=1
        )
        np.testing.assert_allclose(sweep["distance"][k], d, rtol=1e-12, atol=1e-14)
        assert sweep["max"][k] == pytest.approx(d.max(), rel=1e-12)
        assert sweep["rms"][k] == pytest.approx(trapezoid_rms(d), rel=1e-12)


@pytest.mark.parametrize("alpha", [0.2, 0.5, 0.6, 0.9])
def test_its_largest_value_is_within_a_fraction_of_a_per_cent_of_runs(
    cli: Path, alpha: float
) -> None:
    done = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", str(alpha)],
        capture_output=True,
        text=True,
        check=True,
    )
    exact = json.loads(done.stdout)["error"]
    curve = t2spline.FuzzyCurve.from_job(json.loads(EXAMPLE.read_text()))
    sweep = curve.distance_sweep(alpha, samples=2001)
    assert sweep["max"][0] <= exact["max"] * (1 + 1e-12)
    assert sweep["max"][0] == pytest.approx(exact["max"], rel=2e-3)
    assert sweep["rms"][0] == pytest.approx(exact["rms"], rel=2e-3)


def test_a_surface_sweep_equals_its_surfaces_sampled_by_numpy(cli: Path) -> None:
    job = json.loads(CYLINDER.read_text())
    surface = t2spline.FuzzySurface.from_job(job)
    sweep = surface.distance_sweep([0.3, 0.8], samples=(41, 31))
    assert sweep["distance"].shape == (2, 41, 31)
    for k, a in enumerate([0.3, 0.8]):
        s = surface.solve(a)
        d = np.linalg.norm(
            s.defuzzified_surface().sample(41, 31) - s.crisp_surface().sample(41, 31),
            axis=-1,
        )
        np.testing.assert_allclose(sweep["distance"][k], d, rtol=1e-12, atol=1e-14)
        assert sweep["rms"][k] == pytest.approx(trapezoid_rms(d), rel=1e-12)
        done = subprocess.run(
            [str(cli), "run", str(CYLINDER), "--alpha", str(a)],
            capture_output=True,
            text=True,
            check=True,
        )
        assert sweep["max"][k] <= json.loads(done.stdout)["error"]["max"] * (1 + 1e-12)


def test_bad_levels_and_samples_are_named() -> None:
    curve = t2spline.FuzzyCurve.from_job(json.loads(EXAMPLE.read_text()))
    with pytest.raises(ValueError, match=r"alphas\[1\]: 1.5 is outside \[0, 1\]"):
        curve.distance_sweep([0.5, 1.5])
    with pytest.raises(ValueError, match="alphas: expected a level or a 1-D array"):
        curve.distance_sweep(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="samples: must be at least 2, got 1"):
        curve.distance_sweep(0.5, samples=1)
    surface = t2spline.FuzzySurface.from_job(json.loads(CYLINDER.read_text()))
    with pytest.raises(ValueError, match=r"samples\[1\]: must be at least 2, got 0"):
        surface.distance_sweep(0.5, samples=(5, 0))
