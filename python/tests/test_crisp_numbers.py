"""A bare number is a crisp number everywhere a fuzzy number is accepted:
in a job (file or dict), in a data file, and in the constructors, whose
feet default to the crisp value and whose lower height defaults to 1."""

import json
import subprocess
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import t2spline


def test_a_number_of_its_crisp_value_alone_is_crisp() -> None:
    n = t2spline.FuzzyNumber(2.5)
    assert n == t2spline.FuzzyNumber(2.5, (2.5, 2.5), (2.5, 2.5), (2.5, 2.5), 1.0)
    assert t2spline.FuzzyNumber(1.0, (0.0, 2.0), lower_height=0.5) == t2spline.FuzzyNumber(
        1.0, (0.0, 2.0), (1.0, 1.0), (1.0, 1.0), 0.5
    )


def test_curves_and_surfaces_from_crisp_values_alone() -> None:
    crisp = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
    full = t2spline.FuzzyCurve(
        crisp,
        np.stack([crisp, crisp], axis=-1),
        np.stack([crisp, crisp], axis=-1),
        np.stack([crisp, crisp], axis=-1),
        1.0,
        degree=2,
    )
    assert t2spline.FuzzyCurve(crisp, degree=2) == full
    net = np.array([[[0.0, 0.0, 1.0], [0.0, 1.0, 2.0]], [[1.0, 0.0, 3.0], [1.0, 1.0, 4.0]]])
    s = t2spline.FuzzySurface(net, degree=1)
    layers = s.eval_layers(0.5, 0.5)
    assert np.allclose(layers, layers[3])


def test_a_dict_job_with_bare_numbers_is_the_job_with_crisp_numbers() -> None:
    def job(bare: bool) -> dict[str, Any]:
        def c(x: float) -> object:
            return x if bare else {"crisp": x, "upper": [x, x], "primary": [x, x], "lower": [x, x]}

        fuzzy = {"crisp": 2.0, "upper": [1.0, 3.0], "primary": [1.5, 2.5], "lower": [1.8, 2.2]}
        return {
            "order": 2,
            "alpha": 0.5,
            "lower_height": 0.5,
            "points": [{"x": c(0.0), "y": c(0.0)}, {"x": c(1.0), "y": fuzzy}, {"x": c(2.0), "y": c(0.0)}],
        }

    def same(a: Any, b: Any) -> bool:
        if isinstance(a, dict):
            return isinstance(b, dict) and a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
        if isinstance(a, (list, tuple)):
            return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
        if isinstance(a, np.ndarray):
            return bool(np.array_equal(a, b))
        return bool(a == b)

    assert same(t2spline.run(job(True), samples=11), t2spline.run(job(False), samples=11))


def test_the_command_reads_bare_numbers_and_names_a_bad_one(cli: Path, tmp_path: Path) -> None:
    points: list[dict[str, Any]] = [{"x": 0, "y": 0}, {"x": 1, "y": 2}, {"x": 2, "y": "0"}]
    job: dict[str, Any] = {"order": 2, "alpha": 0.5, "points": points}
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job))
    bad = subprocess.run([cli, "validate", str(path)], capture_output=True, text=True)
    assert bad.returncode == 2
    assert "points[2].y: expected a fuzzy number (a JSON object, or a number for a crisp one), got a string" in bad.stderr
    points[2]["y"] = 0
    path.write_text(json.dumps(job))
    ok = subprocess.run([cli, "validate", str(path)], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    with pytest.raises(t2spline.JobError, match=r"points\[2\]\.y"):
        t2spline.run({**job, "points": [*points[:2], {"x": 2, "y": [0]}]})
