"""Quantities measured on a fuzzy curve (docs/method.md §11), as a user
works with them: `t2spline measure` run as a subprocess on the shipped
example and on jobs written here (exit 2 and the flag named for bad input,
no output file), and `FuzzyCurve.measure`, which must give the same
numbers. Soundness is checked the way a user would distrust it: random
control points inside the cuts, evaluated by numpy from the curve's own
rational basis, never leave the reported intervals."""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path
from typing import Any, Dict

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, ROOT

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"


def run(cli: Path, *args: object) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def measured(cli: Path, *args: object) -> Dict[str, Any]:
    done = run(cli, "measure", *args)
    assert done.returncode == 0, done.stderr
    result: Dict[str, Any] = json.loads(done.stdout)
    return result


def test_the_example_from_the_command_line(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "m.json"
    done = run(cli, "measure", EXAMPLE, "--levels", 11, "--at", "0.25,0.5", "-o", out)
    assert done.returncode == 0, done.stderr
    assert done.stdout == ""
    m = json.loads(out.read_text())
    assert m["levels"] == [k / 10 for k in range(11)]
    half = m["length"]["upper"][5]
    assert half["alpha"] == 0.5 and half["exact"]
    assert abs(half["min"] - 7.2953) < 5e-5 and abs(half["max"] - 10.6953) < 5e-5
    assert [lv["alpha"] for lv in m["length"]["lower"]] == [k / 10 for k in range(7)]
    assert m["area"]["kind"] == "under"
    for quantity in (m["length"], m["area"]):
        for name in ("upper", "primary", "lower"):
            levels = quantity[name]
            for a, b in zip(levels, levels[1:]):
                assert a["min"] <= b["min"] + 1e-12 and b["max"] <= a["max"] + 1e-12
    assert [at["t"] for at in m["at"]] == [0.25, 0.5]


def test_python_gives_the_command_line_numbers(cli: Path) -> None:
    m = measured(cli, EXAMPLE, "--levels", 5, "--at", "0.5", "--order", 2)
    p = t2spline.FuzzyCurve.from_job(EXAMPLE).measure(levels=5, at=[0.5], order=2)
    assert isinstance(p["levels"], np.ndarray)
    np.testing.assert_array_equal(p["levels"], m["levels"])
    for key in ("length", "area"):
        for name in ("upper", "primary", "lower"):
            for a, b in zip(p[key][name], m[key][name]):
                assert a == b
    d_py = p["at"][0]["derivative"]["primary"][2]
    d_cli = m["at"][0]["derivative"]["primary"][2]
    assert isinstance(d_py["min"], np.ndarray) and d_py["min"].shape == (2,)
    np.testing.assert_array_equal(d_py["min"], d_cli["min"])
    np.testing.assert_array_equal(d_py["max"], d_cli["max"])
    assert p["at"][0]["order"] == 2
    for name in ("upper", "primary", "lower"):
        assert p["at"][0]["curvature"][name] == m["at"][0]["curvature"][name]
        assert p["at"][0]["tangent_angle"][name] == m["at"][0]["tangent_angle"][name]


def rational_basis(curve: t2spline.FuzzyCurve, t: np.ndarray) -> np.ndarray:
    """The rational basis `(len(t), n)`: each basis function as the curve
    through a unit control point."""
    n = curve.crisp.shape[0]
    rows = []
    for i in range(n):
        pts = np.zeros((n, 2))
        pts[i, 0] = 1.0
        c = t2spline.NurbsCurve(pts, curve.weights, curve.knots, degree=curve.degree)
        rows.append(c.eval(t)[:, 0])
    return np.stack(rows, axis=1)


def test_random_curves_inside_the_cuts_stay_inside(cli: Path) -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    m = curve.measure(levels=3, at=[0.5])
    domain = (float(curve.knots[curve.degree]), float(curve.knots[-curve.degree - 1]))
    t = np.linspace(*domain, 20001)
    basis = rational_basis(curve, t)
    dt = np.gradient(basis, t, axis=0)
    rng = np.random.default_rng(7)
    for name, feet_of in (("upper", curve.upper), ("primary", curve.primary)):
        for level in m["length"][name]:
            a = level["alpha"]
            crisp = curve.crisp
            lo = feet_of[..., 0] + a * (crisp - feet_of[..., 0])
            hi = feet_of[..., 1] - a * (feet_of[..., 1] - crisp)
            draws = lo + rng.random((400, *lo.shape)) * (hi - lo)
            corners = np.where(rng.random((100, *lo.shape)) < 0.5, lo, hi)
            for p in np.concatenate([draws, corners]):
                velocity = dt @ p
                speed = np.hypot(velocity[:, 0], velocity[:, 1])
                length = np.trapezoid(speed, t)
                assert level["min"] - 1e-6 <= length <= level["max"] + 1e-6
                y = basis @ p[:, 1]
                area = np.trapezoid(y * velocity[:, 0], t)
                area_level = next(x for x in m["area"][name] if x["alpha"] == a)
                assert area_level["min"] - 1e-5 <= area <= area_level["max"] + 1e-5


def test_bad_input_names_the_flag_and_writes_nothing(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "m.json"
    for args, words in [
        (("--at", "2"), "--at: at[0] = 2 is outside the domain [0, 1]"),
        (("--at", "0.1,,0.2"), "--at: item 2"),
        (("--levels", "0"), "--levels"),
        (("--order", "65"), "--order"),
    ]:
        done = run(cli, "measure", EXAMPLE, *args, "-o", out)
        assert done.returncode == 2, (args, done.stderr)
        assert words in done.stderr, done.stderr
        assert not out.exists()
    done = run(cli, "measure", TERRAIN, "--at", "0.5", "-o", out)
    assert done.returncode == 2 and "--at: parameters are measured on curves" in done.stderr
    assert not out.exists()


def test_python_arguments_are_checked() -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    with pytest.raises(ValueError, match=r"at\[1\] = 1.5 is outside the domain"):
        curve.measure(at=[0.5, 1.5])
    with pytest.raises(ValueError, match="levels"):
        curve.measure(levels=1)
    with pytest.raises(ValueError, match=r"levels\[0\]"):
        curve.measure(levels=[1.5])
    with pytest.raises(ValueError, match="order"):
        curve.measure(order=0)
    m = curve.measure(levels=[0.0, 0.6, 0.8])
    # The lower function has no cut above its height 0.6.
    assert [lv["alpha"] for lv in m["length"]["lower"]] == [0.0, 0.6]
    assert math.isclose(m["length"]["upper"][2]["min"], m["length"]["primary"][2]["min"], rel_tol=0.2)


README = ROOT / "README.md"
METHOD = ROOT / "docs" / "method.md"


def test_the_readme_transcript(cli: Path) -> None:
    """The `$ t2spline measure …` block of the README, as printed (`…`
    stands for lines left out)."""
    import re
    import shlex

    text = README.read_text()
    block = text.split("```text\n$ t2spline measure ", 1)[1].split("```", 1)[0]
    command, *shown = ("t2spline measure " + block).rstrip("\n").split("\n")
    argv = shlex.split(command)
    done = subprocess.run([str(cli), *argv[1:]], cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    pattern = ".*?".join(re.escape(part) for part in "\n".join(shown).split("…"))
    assert re.fullmatch(pattern, done.stdout.rstrip("\n"), flags=re.DOTALL), done.stdout[:2000]


def test_the_numbers_of_the_pages(cli: Path) -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    layers = [
        curve.layer_curve(name).arc_length()
        for name in ("upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right", "upper_right")
    ]
    assert min(layers) == layers[3]  # the crisp curve is the shortest
    half = measured(cli, EXAMPLE, "--levels", 11)["length"]["upper"][5]
    for page in (README.read_text(), METHOD.read_text()):
        words = " ".join(page.split())
        assert f"{min(layers):.2f} to {max(layers):.2f}" in words
        assert f"from {half['min']:.4f} to {half['max']:.4f}" in words
