"""`closest_point`, `closest_points` and `bounding_box` of the surfaces
against closed forms (a plane, the quarter cylinder with exact weights) and
dense numpy sampling of a random rational surface."""

from __future__ import annotations

import numpy as np
import pytest

import t2spline

LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right",
          "upper_right"]

R, H = 2.0, 3.0
W = np.sqrt(0.5)
CYLINDER = t2spline.NurbsSurface(
    [[[R, 0, 0], [R, 0, H]], [[R, R, 0], [R, R, H]], [[0, R, 0], [0, R, H]]],
    weights=[[1, 1], [W, W], [1, 1]],
    degree=(2, 1),
)


def wavy() -> t2spline.NurbsSurface:
    """A rational surface of degrees (3, 2) on a 6 × 5 net, random weights."""
    rng = np.random.default_rng(11)
    net = rng.uniform(-2, 2, (6, 5, 3))
    return t2spline.NurbsSurface(net, weights=rng.uniform(0.3, 3, (6, 5)), degree=(3, 2))


def test_the_closest_point_of_a_plane_is_the_projection_or_a_corner() -> None:
    plane = t2spline.NurbsSurface([[[0, 0, 0], [0, 2, 0]], [[3, 0, 0], [3, 2, 0]]], degree=1)
    u, v, p, d = plane.closest_point([1.2, 0.5, 4.0])
    assert isinstance(u, float) and isinstance(d, float) and p.shape == (3,)
    assert abs(u - 0.4) < 1e-14 and abs(v - 0.25) < 1e-14 and abs(d - 4.0) < 1e-14
    u, v, p, d = plane.closest_point([5.0, -1.0, 2.0])
    assert (u, v, p.tolist()) == (1.0, 0.0, [3.0, 0.0, 0.0])
    assert abs(d - 3.0) < 1e-14


def test_the_quarter_cylinder_projects_radially() -> None:
    theta = np.array([0.2, 0.7, 1.3])
    r = np.array([3.5, 0.5, 2.2])
    z = np.array([0.4, 2.9, 1.5])
    targets = np.stack([r * np.cos(theta), r * np.sin(theta), z], axis=-1)
    u, v, p, d = CYLINDER.closest_point(targets)
    assert u.shape == v.shape == d.shape == (3,) and p.shape == (3, 3)
    np.testing.assert_allclose(d, np.abs(r - R), rtol=0, atol=1e-13)
    want = np.stack([R * np.cos(theta), R * np.sin(theta), z], axis=-1)
    np.testing.assert_allclose(p, want, rtol=0, atol=1e-12)
    np.testing.assert_allclose(CYLINDER.eval(u, v), p, rtol=0, atol=1e-14)
    lo, hi = CYLINDER.bounding_box()
    np.testing.assert_allclose(lo, [0, 0, 0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(hi, [R, R, H], rtol=0, atol=1e-15)


def test_the_closest_point_beats_dense_sampling() -> None:
    s = wavy()
    grid = s.sample(241, 241).reshape(-1, 3)
    targets = np.random.default_rng(5).uniform(-4, 4, (12, 3))
    u, v, p, d = s.closest_point(targets)
    sampled = np.linalg.norm(grid[None, :, :] - targets[:, None, :], axis=-1).min(axis=1)
    assert np.all(d <= sampled * (1 + 1e-12)), d - sampled
    np.testing.assert_allclose(s.eval(u, v), p, rtol=0, atol=1e-13)
    np.testing.assert_allclose(np.linalg.norm(p - targets, axis=-1), d, rtol=1e-14, atol=1e-14)
    # One point at a time gives the same as the stack.
    one = s.closest_point(targets[4])
    assert one[0] == u[4] and one[1] == v[4] and one[3] == d[4]
    assert np.array_equal(one[2], p[4])


def test_the_box_holds_dense_samples_and_is_reached() -> None:
    s = wavy()
    lo, hi = s.bounding_box()
    assert lo.shape == hi.shape == (3,)
    grid = s.sample(301, 301).reshape(-1, 3)
    scale = np.abs(grid).max()
    assert np.all(grid >= lo - 1e-13 * scale) and np.all(grid <= hi + 1e-13 * scale)
    # The sampling comes as close to the faces as its resolution allows.
    assert np.all(grid.min(axis=0) - lo < 1e-3) and np.all(hi - grid.max(axis=0) < 1e-3)
    # Tighter than the box of the control points.
    net = s.control_points.reshape(-1, 3)
    assert np.all(net.min(axis=0) <= lo) and np.all(hi <= net.max(axis=0))


def fuzzy() -> t2spline.FuzzySurface:
    rng = np.random.default_rng(7)
    x, y = np.meshgrid(np.arange(4, dtype=float), np.arange(3, dtype=float), indexing="ij")
    crisp = np.stack([x, y, np.sin(x) * np.cos(y)], axis=-1)
    left = np.cumsum(rng.uniform(0, 0.2, size=(4, 3, 3, 3)), axis=-1)
    right = np.cumsum(rng.uniform(0, 0.3, size=(4, 3, 3, 3)), axis=-1)
    feet = [np.stack([crisp - left[..., k], crisp + right[..., k]], axis=-1) for k in (2, 1, 0)]
    return t2spline.FuzzySurface(crisp, *feet, lower_height=0.6,
                                 weights=rng.uniform(0.5, 2, (4, 3)), degree=(2, 1))


def test_fuzzy_closest_points_and_box_are_those_of_the_layers() -> None:
    s = fuzzy()
    u, v, p, d = s.closest_points([1.5, 0.7, 2.0])
    assert u.shape == v.shape == d.shape == (7,) and p.shape == (7, 3)
    for k, name in enumerate(LAYERS):
        one = s.layer_surface(name).closest_point([1.5, 0.7, 2.0])
        assert (one[0], one[1], one[3]) == (u[k], v[k], d[k]) and np.array_equal(one[2], p[k])
    many = s.closest_points([[1.5, 0.7, 2.0], [0.0, 5.0, -1.0]])
    assert [a.shape for a in many] == [(2, 7), (2, 7), (2, 7, 3), (2, 7)]
    assert np.array_equal(many[3][0], d)
    lo, hi = s.bounding_box()
    samples = s.sample(121, 121)
    for name in LAYERS:
        layer = samples[name].reshape(-1, 3)
        assert np.all(layer >= lo - 1e-13) and np.all(layer <= hi + 1e-13), name
    assert np.array_equal(lo, s.layer_surface("upper_left").bounding_box()[0])
    assert np.array_equal(hi, s.layer_surface("upper_right").bounding_box()[1])


@pytest.mark.parametrize("point", [[1.0, 2.0], [[1.0, 2.0, 3.0, 4.0]], [np.nan, 0.0, 0.0],
                                   [1e200, 0.0, 0.0]])
def test_bad_targets_raise(point: object) -> None:
    with pytest.raises(ValueError):
        CYLINDER.closest_point(point)
    with pytest.raises(ValueError):
        fuzzy().closest_points(point)
