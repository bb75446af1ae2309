"""One vocabulary across the classes: calling a curve or surface evaluates it
(as splipy's objects are called), and what a fuzzy surface offers per layer
a fuzzy curve offers too, each equal to the layer objects' own answers."""

from __future__ import annotations

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, ROOT

CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"
LAYERS = [
    "upper_left",
    "primary_left",
    "lower_left",
    "crisp",
    "lower_right",
    "primary_right",
    "upper_right",
]


def test_calling_evaluates() -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    t = np.linspace(0.0, 1.0, 12).reshape(3, 4)
    np.testing.assert_array_equal(curve(t), curve.eval_layers(t))
    crisp = curve.crisp_curve()
    np.testing.assert_array_equal(crisp(t), crisp.eval(t))
    assert crisp(0.5).shape == (2,)
    surface = t2spline.FuzzySurface.from_job(CYLINDER)
    (u0, u1), (v0, v1) = surface.domain
    u = np.linspace(u0, u1, 5)[:, None]
    v = np.linspace(v0, v1, 4)[None, :]
    np.testing.assert_array_equal(surface(u, v), surface.eval_layers(u, v))
    net = surface.crisp_surface()
    np.testing.assert_array_equal(net(u, v), net.eval(u, v))
    with pytest.raises(ValueError, match="outside the domain"):
        crisp(2.0)


def test_a_fuzzy_curve_finds_the_closest_point_of_every_layer() -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    targets = np.array([[2.0, 3.0], [0.5, -1.0], [4.5, 1.5]])
    t, points, distances = curve.closest_points(targets)
    assert t.shape == (3, 7) and points.shape == (3, 7, 2) and distances.shape == (3, 7)
    for k, target in enumerate(targets):
        one = curve.closest_points(target)
        np.testing.assert_array_equal(one[0], t[k])
        for i, name in enumerate(LAYERS):
            lt, lp, ld = curve.layer_curve(name).closest_point(target)
            assert t[k, i] == lt and distances[k, i] == ld
            np.testing.assert_array_equal(points[k, i], lp)
            # No sample of the layer curve is closer.
            dense = curve.layer_curve(name).sample(20001)
            assert ld <= np.linalg.norm(dense - target, axis=1).min() + 1e-12
    with pytest.raises(ValueError, match=r"point: expected shape \(2,\) or \(m, 2\)"):
        curve.closest_points([1.0, 2.0, 3.0])
