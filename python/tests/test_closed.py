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
