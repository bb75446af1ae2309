"""The objects for notebook work against closed forms and the
invariants: fuzzy numbers by hand, the quarter circle, operations that keep
the curve, the engine against the straightforward evaluator, shapes and
dtypes of every output, reprs."""

from __future__ import annotations

import numpy as np
import pytest

import t2spline

X = t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right",
          "upper_right"]


def test_alpha_cut_type_reduction_and_defuzzification_by_hand() -> None:
    # alpha = 0.3 <= h: s = 0.3 for upper and primary ends, 0.3/0.6 = 0.5 for lower.
    cut = X.alpha_cut(0.3)
    assert cut.upper == pytest.approx((0.4 + 0.3 * 0.6, 1.9 - 0.3 * 0.9), abs=1e-15)
    assert cut.primary == pytest.approx((0.6 + 0.3 * 0.4, 1.6 - 0.3 * 0.6), abs=1e-15)
    assert cut.lower == pytest.approx((0.9, 1.15), abs=1e-15)
    left = (0.58 + 0.72 + 0.9) / 3
    right = (1.15 + 1.42 + 1.63) / 3
    assert X.type_reduce(0.3) == pytest.approx((left, 1.0, right), abs=1e-15)
    assert X.defuzzify(0.3) == pytest.approx((left + 1.0 + right) / 3, abs=1e-15)
    # alpha = 0.8 > h: no lower cut, two-term means.
    assert X.alpha_cut(0.8).lower is None
    assert X.type_reduce(0.8) == pytest.approx((0.9, 1.0, 1.15), abs=1e-15)
    # The jump at alpha = h (docs/method.md §3): three-term means at h, two just above.
    at, above = X.type_reduce(0.6), X.type_reduce(0.6 + 1e-12)
    assert abs(at[0] - above[0]) > 0.01
    assert X.alpha_cut(0.6).lower == (1.0, 1.0)
    assert X.alpha_cut(0.5).type_reduce() == X.type_reduce(0.5)


def test_membership_functions_are_the_three_triangles() -> None:
    x = np.array([[0.3, 0.4, 0.7], [1.0, 1.15, 2.0]])
    upper = X.membership(x)
    assert upper.shape == (2, 3) and upper.dtype == np.float64
    close = np.testing.assert_allclose
    close(upper, [[0, 0, 0.5], [1, (1.9 - 1.15) / 0.9, 0]], rtol=0, atol=1e-15)
    close(X.membership(x, which="primary"), [[0, 0, 0.25], [1, 0.75, 0]], rtol=0, atol=1e-15)
    close(X.membership(x, which="lower"), [[0, 0, 0], [0.6, 0.3, 0]], rtol=0, atol=1e-15)
    assert X.membership(1.0).shape == ()
    # LMF <= primary <= UMF everywhere (docs/method.md §9's nesting).
    grid = np.linspace(0, 2.5, 501)
    lmf, pmf, umf = (X.membership(grid, which=w) for w in ("lower", "primary", "upper"))
    assert np.all(lmf <= pmf) and np.all(pmf <= umf)


def test_fuzzy_number_attributes_and_repr() -> None:
    assert (X.crisp, X.upper, X.primary, X.lower, X.lower_height) == (
        1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    assert repr(X) == ("FuzzyNumber(crisp=1.0, upper=(0.4, 1.9), primary=(0.6, 1.6), "
                       "lower=(0.8, 1.3), lower_height=0.6)")
    assert X == t2spline.FuzzyNumber(1, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)
    assert X != t2spline.FuzzyNumber(1, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.5)
    assert repr(X.alpha_cut(0.8)).endswith("lower=None)")


QUARTER = t2spline.NurbsCurve([[1, 0], [1, 1], [0, 1]], weights=[1, np.sqrt(0.5), 1], degree=2)


def test_the_quarter_circle_has_radius_one_everywhere() -> None:
    t = np.linspace(0, 1, 257)
    for points in (QUARTER.eval(t), QUARTER.sample(t), QUARTER.sample(257)):
        assert points.shape == (257, 2)
        assert np.abs(np.hypot(points[:, 0], points[:, 1]) - 1).max() < 1e-14
    assert QUARTER.arc_length() == pytest.approx(np.pi / 2, rel=1e-10)
    assert QUARTER.arc_length(0.0, 0.5) == pytest.approx(np.pi / 4, rel=1e-10)
    assert QUARTER.param_at_length(np.pi / 4) == pytest.approx(0.5, abs=1e-9)
    assert QUARTER.curvature(t) == pytest.approx(np.ones(257), abs=1e-12)
    tangent = QUARTER.tangent(0.0)
    assert tangent == pytest.approx([0.0, 1.0], abs=1e-15)
    t_near, point, distance = QUARTER.closest_point([2.0, 2.0])
    assert point == pytest.approx([np.sqrt(0.5)] * 2, abs=1e-12)
    assert distance == pytest.approx(2 * np.sqrt(2) - 1, abs=1e-12)
    lo, hi = QUARTER.bounding_box()
    assert lo == pytest.approx([0, 0], abs=1e-15) and hi == pytest.approx([1, 1], abs=1e-15)


def test_evaluation_is_vectorised_over_any_shape() -> None:
    t = np.array([[0.0, 0.25], [0.5, 1.0]])
    assert QUARTER.eval(t).shape == (2, 2, 2)
    assert QUARTER.eval(0.5).shape == (2,)
    assert QUARTER.derivatives(t, order=3).shape == (2, 2, 4, 2)
    assert QUARTER.derivatives(0.5, order=2).shape == (3, 2)
    assert np.abs(QUARTER.derivatives(t, order=0)[..., 0, :] - QUARTER.eval(t)).max() < 1e-15
    basis = QUARTER.rational_basis(t)
    assert basis.shape == (2, 2, 3)
    assert np.all(basis >= 0) and basis.sum(axis=-1) == pytest.approx(np.ones((2, 2)), abs=1e-15)
    assert isinstance(QUARTER.curvature(0.5), float)
    ts, points, distances = QUARTER.closest_point([[2.0, 2.0], [0.0, 0.0]])
    assert ts.shape == (2,) and points.shape == (2, 2) and distances.shape == (2,)


def test_operations_keep_the_curve() -> None:
    t = np.linspace(0, 1, 101)
    before = QUARTER.eval(t)
    for changed in (QUARTER.insert_knot(0.3, times=2), QUARTER.refine_knots([0.2, 0.7, 0.7]),
                    QUARTER.elevate_degree(2), QUARTER.clamped()):
        assert np.abs(changed.eval(t) - before).max() < 1e-14
    assert QUARTER.insert_knot(0.3, times=2).control_points.shape == (5, 2)
    assert QUARTER.elevate_degree(2).degree == 4
    left, right = QUARTER.split_at(0.4)
    assert left.domain == (0.0, 0.4) and right.domain == (0.4, 1.0)
    assert np.abs(left.eval(t * 0.4) - QUARTER.eval(t * 0.4)).max() < 1e-14
    assert np.abs(QUARTER.segment(0.2, 0.6).eval(0.3) - QUARTER.eval(0.3)).max() < 1e-15


def test_nurbs_curve_attributes() -> None:
    c = t2spline.NurbsCurve(np.zeros((5, 3)) + np.arange(5)[:, None], knots=[0, 0, 0, 0.5, 0.5, 1, 1, 1])
    assert (c.dimension, c.degree, c.order) == (3, 2, 3)  # degree from the knots
    assert c.control_points.shape == (5, 3) and c.weights.tolist() == [1.0] * 5
    assert c.knots.tolist() == [0, 0, 0, 0.5, 0.5, 1, 1, 1]
    assert c.uniform_params(5).tolist() == [0, 0.25, 0.5, 0.75, 1.0]
    assert repr(c) == ("NurbsCurve(dimension=3, degree=2, order=3, control_points=(5, 3), "
                       "knots=(8,), domain=(0.0, 1.0))")


def spiral(n: int = 7) -> t2spline.FuzzyCurve:
    """A 3-D fuzzy curve with unequal spreads and heights per number."""
    rng = np.random.default_rng(7)
    a = np.linspace(0, 3, n)
    crisp = np.stack([np.cos(a), np.sin(a), a / 3], axis=1)
    left = np.cumsum(rng.uniform(0, 0.2, size=(n, 3, 3)), axis=2)
    right = np.cumsum(rng.uniform(0, 0.3, size=(n, 3, 3)), axis=2)
    feet = [np.stack([crisp - left[..., k], crisp + right[..., k]], axis=-1) for k in (2, 1, 0)]
    heights = rng.choice([0.4, 0.7, 1.0], size=(n, 3))
    return t2spline.FuzzyCurve(crisp, *feet, lower_height=heights,
                               weights=rng.uniform(0.5, 2, n), degree=3)


def test_the_engine_equals_the_straightforward_evaluator_and_keeps_the_order() -> None:
    curve = spiral()
    t = np.sort(np.random.default_rng(3).uniform(0, 1, 500))
    t[:3] = [0.0, 1.0, 0.5]
    samples = curve.sample(t)
    reference = curve.eval_layers(t)  # (500, 7, 3)
    assert list(samples) == ["params", *LAYERS]
    assert np.array_equal(samples["params"], t)
    scale = np.abs(curve.upper).max()
    for k, name in enumerate(LAYERS):
        assert samples[name].shape == (500, 3) and samples[name].dtype == np.float64
        assert np.abs(samples[name] - reference[:, k]).max() <= 1e-12 * scale, name
    stacked = np.stack([samples[name] for name in LAYERS])
    assert np.all(np.diff(stacked, axis=0) >= 0), "the docs/method.md §1 order of the layers"
    uniform = curve.sample(11)
    assert np.array_equal(uniform["params"], curve.uniform_params(11))
    assert curve.sample(0)["crisp"].shape == (0, 3)


def test_lower_heights_broadcast_as_numpy_arrays_do() -> None:
    curve = spiral()
    args = (curve.crisp, curve.upper, curve.primary, curve.lower)
    per_axis = t2spline.FuzzyCurve(*args, lower_height=[0.6, 1.0, 0.3], degree=3)
    per_point = t2spline.FuzzyCurve(*args, lower_height=np.linspace(0.1, 0.7, 7)[:, None], degree=3)
    assert np.array_equal(per_axis.lower_height, np.tile([0.6, 1.0, 0.3], (7, 1)))
    assert np.array_equal(per_point.lower_height, np.repeat(np.linspace(0.1, 0.7, 7)[:, None], 3, axis=1))
    assert np.array_equal(t2spline.FuzzyCurve(*args, lower_height=0.5, degree=3).lower_height,
                          np.full((7, 3), 0.5))


def test_layer_curves_and_control_points_are_the_layers() -> None:
    curve = spiral()
    assert curve.eval_layers(0.4).shape == (7, 3)
    for k, name in enumerate(LAYERS):
        assert np.array_equal(curve.layer_curve(name).eval(0.4), curve.eval_layers(0.4)[k])
        assert np.array_equal(curve.layer_curve(name).control_points, curve.layer_control_points(name))
    assert np.array_equal(curve.crisp_curve().control_points, curve.crisp)
    assert np.array_equal(curve.upper[..., 0], curve.layer_control_points("upper_left"))
    assert np.array_equal(curve.lower[..., 1], curve.layer_control_points("lower_right"))
    x, y, z = curve.point(2)
    assert (x.crisp, y.upper[1], z.lower_height) == (
        curve.crisp[2, 0], curve.upper[2, 1, 1], curve.lower_height[2, 2])
    assert curve.lower_height.shape == (7, 3)


def test_symmetric_spreads_give_the_crisp_curve_as_solution() -> None:
    c = np.array([[0.0, 0.0], [1.0, 3.0], [2.5, 2.0], [4.0, 0.5], [5.0, 1.0]])
    s = np.array([-1.0, 1.0])
    curve = t2spline.FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s, c[..., None] + 0.2 * s,
                                lower_height=0.5, degree=3)
    for alpha in (0.0, 0.3, 0.5, 0.7, 1.0):
        solution = curve.solve(alpha)
        assert np.abs(solution.defuzzified - c).max() <= 1e-15, alpha
        distance = solution.distance()
        assert distance["max"] <= 1e-15 and distance["rms"] <= 1e-15, (alpha, distance)


def test_solution_stages_and_their_curves() -> None:
    curve = spiral()
    solution = curve.solve(0.55)
    assert solution.alpha == 0.55 and solution.fuzzy_curve == curve
    cut = solution.alpha_cut
    assert list(cut) == [name for name in LAYERS if name != "crisp"]
    # Heights 0.4 are below 0.55: those numbers have no lower cut (NaN).
    absent = curve.lower_height < 0.55
    assert np.array_equal(np.isnan(cut["lower_left"]), absent)
    assert solution.alpha_cut_curve("lower_left") is None
    assert solution.alpha_cut_curve("upper_left") is not None
    left, right = solution.type_reduced_left, solution.type_reduced_right
    assert np.all(left <= solution.crisp) and np.all(solution.crisp <= right)
    assert np.allclose(solution.defuzzified, (left + solution.crisp + right) / 3, rtol=0, atol=1e-15)
    assert np.array_equal(solution.type_reduced_curve("left").control_points, left)
    assert np.array_equal(solution.defuzzified_curve().control_points, solution.defuzzified)
    stages = solution.sample(41)
    assert stages["alpha_cut"]["lower_right"] is None
    assert stages["alpha_cut"]["upper_right"].shape == (41, 3)
    d = solution.defuzzified_curve().eval(stages["params"])
    assert np.abs(stages["defuzzified"] - d).max() < 1e-12
    gap = np.linalg.norm(stages["defuzzified"] - solution.crisp_curve().eval(stages["params"]), axis=1)
    distance = solution.distance()
    assert gap.max() <= distance["max"] * (1 + 1e-12)
    assert repr(solution) == "Solution(alpha=0.55, control_points=(7, 3), degree=3)"


def test_fuzzy_operations_keep_every_layer() -> None:
    mixed = spiral()
    # New control points need one lower height per coordinate.
    curve = t2spline.FuzzyCurve(mixed.crisp, mixed.upper, mixed.primary, mixed.lower,
                                lower_height=[0.6, 1.0, 0.3], weights=mixed.weights, degree=3)
    with pytest.raises(ValueError, match="this operation needs one lower height per coordinate"):
        mixed.insert_knot(0.35)
    t = np.linspace(0, 1, 61)
    before = curve.eval_layers(t)
    for changed in (curve.insert_knot(0.35), curve.refine_knots([0.1, 0.9]), curve.elevate_degree()):
        assert np.abs(changed.eval_layers(t) - before).max() < 1e-12
    assert curve.elevate_degree().degree == 4
    a, b = curve.split_at(0.5)
    assert a.domain == (0.0, 0.5) and np.abs(b.eval_layers(0.75) - curve.eval_layers(0.75)).max() < 1e-13
    assert curve.segment(0.2, 0.4).domain == (0.2, 0.4)
    assert repr(curve) == "FuzzyCurve(dimension=3, degree=3, order=4, control_points=(7, 3), domain=(0.0, 1.0))"


def test_fit_recovers_what_it_was_given() -> None:
    # Data taken from a fuzzy curve: interpolation passes through them.
    curve = spiral(9)
    t = np.linspace(0, 1, 12)
    layers = curve.eval_layers(t)  # (12, 7, 3)
    crisp = layers[:, 3]
    feet = [np.stack([layers[:, k], layers[:, 6 - k]], axis=-1) for k in range(3)]
    fitted, summary = t2spline.fit(crisp, *feet, lower_height=1.0, degree=3)
    assert fitted.crisp.shape == (12, 3)
    assert summary["data_points"] == 12 and summary["control_points"] == 12
    assert summary["deviations"]["crisp"]["max"] < 1e-12
    assert set(summary["deviations"]) == set(LAYERS)
    assert summary["mode"] == "valid" and summary["mixed_heights"] == {}
    least, s2 = t2spline.fit(crisp, *feet, lower_height=1.0, degree=2, control_points=6,
                             parametrization="centripetal")
    assert least.crisp.shape == (6, 3) and s2["control_points"] == 6
    assert np.isfinite(s2["condition"]) and s2["condition"] >= 1


def test_the_benchmark_curve_is_the_engines() -> None:
    c = t2spline.benchmark_curve()
    assert c.crisp[:, 0].tolist() == list(range(10))
    assert c.weights.tolist() == [1, 0.5, 2, 1, 3, 0.7, 1, 1.5, 0.8, 1]
    assert np.allclose(c.upper[..., 1] - c.crisp, 0.45)
