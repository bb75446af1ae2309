"""Closed curves from Python: the periodic construction's area is enclosed
and positive whichever way it runs, `closed=True` asks that the curve
close and `closed=False` measures the area under it (docs/method.md §11)."""

import numpy as np
import pytest

import t2spline


def periodic_circle(clockwise: bool) -> t2spline.FuzzyCurve:
    t = np.linspace(0.0, 2.0 * np.pi, 8, endpoint=False)
    c = np.stack([5.0 * np.cos(t), (-5.0 if clockwise else 5.0) * np.sin(t)], axis=-1)
    c = np.concatenate([c, c[:3]])
    s = np.array([-0.3, 0.3])
    return t2spline.FuzzyCurve(
        c, c[..., None] + s, c[..., None] + s / 2, c[..., None] + s / 4, 0.8,
        knots=np.arange(len(c) + 4, dtype=float), degree=3,
    )


def test_the_periodic_circle_encloses_a_positive_area_either_way() -> None:
    areas = []
    for clockwise in (False, True):
        m = periodic_circle(clockwise).measure(levels=3)
        assert m["area"]["kind"] == "enclosed"
        assert "note" not in m["area"]
        areas.append([(lv["min"], lv["max"]) for lv in m["area"]["upper"]])
        assert all(0 < lo <= hi for lo, hi in areas[-1])
    assert np.allclose(areas[0], areas[1], rtol=1e-9)


def test_closed_asks_or_declines() -> None:
    c = periodic_circle(False)
    assert c.measure(levels=2, closed=False)["area"]["kind"] == "under"
    crisp = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    line = t2spline.FuzzyCurve(crisp, degree=1)
    with pytest.raises(ValueError, match=r"does not close: it starts at \(0, 0\) and ends at \(1, 1\)"):
        line.measure(levels=2, closed=True)
    with pytest.raises(TypeError, match="closed"):
        line.measure(levels=2, closed="yes")  # type: ignore[arg-type]


POND = "docs/fit-example/pond-readings.csv"


def test_a_closed_fit_is_the_command_s(cli, tmp_path, monkeypatch) -> None:
    """`fit_job(data, closed=True)` writes the job of `t2spline fit --closed`,
    and `fit(..., closed=True)` the same curve: periodic, closed, its area
    enclosed and near the pond's πr² (r = 20 m)."""
    import json
    import subprocess

    from conftest import ROOT

    monkeypatch.chdir(ROOT)
    out = tmp_path / "pond.json"
    subprocess.run([str(cli), "fit", POND, "--closed", "--tolerance", "0.05", "--alpha", "0.5",
                    "-o", str(out)], check=True, capture_output=True)
    data = t2spline.fuzzify(POND, tolerance=0.05, alpha=0.5)
    job = t2spline.fit_job(data, closed=True)
    assert job == json.loads(out.read_text())
    assert job["closed"] is True
    curve = t2spline.FuzzyCurve.from_job(job)
    p = curve.degree
    np.testing.assert_array_equal(curve.crisp[:p], curve.crisp[-p:])
    crisp = np.array([[pt[k]["crisp"] for k in ("x", "y")] for pt in data["points"]])
    fitted, summary = t2spline.fit(crisp, degree=3, closed=True)
    np.testing.assert_allclose(fitted.crisp, curve.crisp, rtol=0, atol=1e-9)
    area = fitted.measure(levels=2, closed=True)["area"]
    assert area["kind"] == "enclosed"
    crisp_area = area["upper"][-1]["min"]
    assert abs(crisp_area - np.pi * 20.0**2) < 0.01 * np.pi * 20.0**2
    with pytest.raises(ValueError, match="closed=True is for a loop of points of a curve"):
        t2spline.fit(np.zeros((3, 3, 3)) + np.arange(3)[:, None, None], degree=1, closed=True)
