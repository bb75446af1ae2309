"""`NurbsSurface`, `FuzzySurface` and `SurfaceSolution` against closed
forms (a bilinear patch, a plane by linear precision, a quarter cylinder with
exact weights) and the invariants of docs/method.md: operations that keep the surface,
the grid engine against the straightforward evaluator, seven ordered layers,
shapes and dtypes of every output, broadcasting, reprs."""

from __future__ import annotations

import numpy as np
import pytest

import t2spline

LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right",
          "upper_right"]

BILINEAR = t2spline.NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], degree=1)

R, H = 2.0, 3.0
W = np.sqrt(0.5)
CYLINDER = t2spline.NurbsSurface(
    [[[R, 0, 0], [R, 0, H]], [[R, R, 0], [R, R, H]], [[0, R, 0], [0, R, H]]],
    weights=[[1, 1], [W, W], [1, 1]],
    degree=(2, 1),
)


def radius(points: np.ndarray) -> np.ndarray:
    return np.asarray(np.hypot(points[..., 0], points[..., 1]))


def test_the_bilinear_patch_is_u_v_uv() -> None:
    rng = np.random.default_rng(1)
    u, v = rng.uniform(0, 1, (2, 40))
    u[:2], v[:2] = [0.0, 1.0], [1.0, 0.0]
    want = np.stack([u, v, u * v], axis=-1)
    assert np.abs(BILINEAR.eval(u, v) - want).max() <= 1e-15
    d = BILINEAR.derivatives(u, v, order=2)
    assert d.shape == (40, 3, 3, 3)
    ones, zeros = np.ones_like(u), np.zeros_like(u)
    close = np.testing.assert_allclose
    close(d[:, 1, 0], np.stack([ones, zeros, v], axis=-1), rtol=0, atol=1e-15)   # S_u
    close(d[:, 0, 1], np.stack([zeros, ones, u], axis=-1), rtol=0, atol=1e-15)   # S_v
    close(d[:, 1, 1], np.stack([zeros, zeros, ones], axis=-1), rtol=0, atol=1e-15)
    close(d[:, 2, 0], 0.0, rtol=0, atol=1e-15)
    close(d[:, 0, 2], 0.0, rtol=0, atol=1e-15)
    assert np.isnan(d[:, 1, 2]).all() and np.isnan(d[:, 2, 2]).all()  # k + l > 2
    n = np.stack([-v, -u, ones], axis=-1) / np.sqrt(1 + u**2 + v**2)[:, None]
    close(BILINEAR.normal(u, v), n, rtol=0, atol=1e-15)
    # A bilinear rational basis: the four products, summing to one.
    b = BILINEAR.rational_basis(u, v)
    assert b.shape == (40, 2, 2)
    close(b[:, 1, 1], u * v, rtol=0, atol=1e-15)
    close(b.sum(axis=(1, 2)), 1.0, rtol=0, atol=1e-15)


def greville(knots: np.ndarray, p: int) -> np.ndarray:
    """The Greville abscissae: averages of p consecutive inner knots."""
    n = len(knots) - p - 1
    return np.array([knots[i + 1:i + p + 1].mean() for i in range(n)])


def test_linear_precision_gives_the_plane_exactly() -> None:
    """Control points at the Greville abscissae of the plane z = a·u + b·v + c
    (weights 1) reproduce it: S(u, v) = (u, v, a·u + b·v + c) for any degrees
    and knots (the linear precision of B-splines)."""
    a, b, c = 0.7, -1.3, 2.0
    ku = np.array([0, 0, 0, 0, 0.2, 0.5, 0.5, 0.9, 1, 1, 1, 1.0])
    kv = np.array([-1, -1, -1, 0.3, 2, 2, 2.0])
    gu, gv = greville(ku, 3), greville(kv, 2)
    x, y = np.meshgrid(gu, gv, indexing="ij")
    plane = t2spline.NurbsSurface(np.stack([x, y, a * x + b * y + c], axis=-1), None, ku, kv)
    assert (plane.degree, plane.shape) == ((3, 2), (8, 4))
    u = np.linspace(0, 1, 37)[:, None]
    v = np.linspace(-1, 2, 23)[None, :]
    want = np.stack(np.broadcast_arrays(u, v, a * u + b * v + c), axis=-1)
    assert np.abs(plane.eval(u, v) - want).max() <= 1e-14
    assert np.abs(plane.sample(u[:, 0], v[0]) - want).max() <= 1e-14
    normal = np.array([-a, -b, 1.0]) / np.sqrt(a * a + b * b + 1)
    assert np.abs(plane.normal(u, v) - normal).max() <= 1e-14
    # Any weights keep every point in the plane (the rational basis sums to 1).
    rng = np.random.default_rng(2)
    weighted = t2spline.NurbsSurface(plane.control_points, rng.uniform(0.2, 5, (8, 4)), ku, kv)
    p = weighted.sample(41, 31)
    assert np.abs(p[..., 2] - (a * p[..., 0] + b * p[..., 1] + c)).max() <= 1e-13
    assert np.abs(weighted.normal(0.3, 0.4) - normal).max() <= 1e-14


def test_the_quarter_cylinder_with_exact_weights() -> None:
    u, v = np.linspace(0, 1, 101), np.linspace(0, 1, 7)
    grid = CYLINDER.sample(u, v)
    assert grid.shape == (101, 7, 3) and grid.dtype == np.float64
    assert np.abs(radius(grid) / R - 1).max() <= 1e-15
    assert np.abs(grid[..., 2] - H * v[None, :]).max() <= 1e-15
    assert np.abs(CYLINDER.eval(u[:, None], v[None, :]) - grid).max() <= 1e-15 * H
    # S_u(0, v) = 2·(w1/w0)·(P1 − P0) = (0, √2·R, 0), S_v = (0, 0, H).
    d = CYLINDER.derivatives(0.0, v, order=1)
    assert np.abs(d[:, 1, 0] - [0, np.sqrt(2) * R, 0]).max() <= 1e-14
    assert np.abs(d[:, 0, 1] - [0, 0, H]).max() <= 1e-15
    # The normal is radial.
    n = CYLINDER.normal(u[:, None], v[None, :])
    assert np.abs(n - np.concatenate([grid[..., :2] / R, np.zeros((101, 7, 1))], axis=-1)).max() <= 1e-14
    # Every operation keeps the cylinder.
    probe = CYLINDER.eval(u[:, None], v[None, :])
    for changed in (
        CYLINDER.insert_knot(0.3, times=2, direction="u"),
        CYLINDER.insert_knot(0.5, direction="v"),
        CYLINDER.refine_knots([0.1, 0.6, 0.6], direction="u"),
        CYLINDER.elevate_degree(direction="u"),
        CYLINDER.elevate_degree(times=2, direction="v"),
    ):
        assert np.abs(changed.eval(u[:, None], v[None, :]) - probe).max() <= 1e-14
        assert np.abs(radius(changed.sample(33, 5)) / R - 1).max() <= 1e-14
    assert CYLINDER.insert_knot(0.3, times=2, direction="u").shape == (5, 2)
    assert CYLINDER.elevate_degree(times=2, direction="v").order == (3, 4)
    low, high = CYLINDER.split_at(0.4, direction="u")
    assert low.domain == ((0.0, 0.4), (0.0, 1.0)) and high.domain == ((0.4, 1.0), (0.0, 1.0))
    assert np.abs(high.eval(0.7, v) - CYLINDER.eval(0.7, v)).max() <= 1e-14
    piece = CYLINDER.segment((0.2, 0.6), (0.25, 0.5))
    assert piece.domain == ((0.2, 0.6), (0.25, 0.5))
    assert np.abs(piece.eval(0.3, 0.3) - CYLINDER.eval(0.3, 0.3)).max() <= 1e-14
    # The isocurve at a height is the quarter circle of radius R there.
    ring = CYLINDER.isocurve(0.5, direction="v")
    assert isinstance(ring, t2spline.NurbsCurve) and ring.dimension == 3
    assert np.abs(radius(ring.sample(65)) / R - 1).max() <= 1e-15
    assert ring.curvature(np.linspace(0, 1, 9)) == pytest.approx(np.full(9, 1 / R), rel=1e-12)
    line = CYLINDER.isocurve(0.5, direction="u")
    assert np.abs(line.eval(v) - CYLINDER.eval(0.5, v)).max() <= 1e-15


def test_attributes_shapes_and_broadcasting() -> None:
    s = CYLINDER
    assert (s.dimension, s.degree, s.order, s.shape) == (3, (2, 1), (3, 2), (3, 2))
    assert s.control_points.shape == (3, 2, 3) and s.weights.shape == (3, 2)
    assert s.weights[1].tolist() == [W, W]
    assert s.knots_u.tolist() == [0, 0, 0, 1, 1, 1] and s.knots_v.tolist() == [0, 0, 1, 1]
    u, v = s.uniform_params(5, 3)
    assert u.tolist() == [0, 0.25, 0.5, 0.75, 1] and v.tolist() == [0, 0.5, 1]
    assert s.eval(0.5, 0.5).shape == (3,)
    assert s.eval([0.1, 0.2], 0.5).shape == (2, 3)
    assert s.eval(np.zeros((4, 1)), np.zeros(5)).shape == (4, 5, 3)
    assert s.derivatives(0.5, 0.5, order=3).shape == (4, 4, 3)
    assert s.rational_basis(np.zeros((2, 2)), 0.5).shape == (2, 2, 3, 2)
    assert s.sample(0, 4).shape == (0, 4, 3)
    assert np.array_equal(s.sample(5, 3), s.sample(u, v))
    assert repr(s) == ("NurbsSurface(dimension=3, degree=(2, 1), order=(3, 2), control_points=(3, 2, 3), "
                       "knots=(6, 4), domain=((0.0, 1.0), (0.0, 1.0)))")
    assert s == t2spline.NurbsSurface(s.control_points, s.weights, s.knots_u, s.knots_v)
    # The degree from the knots, per direction; the order instead of the degree.
    assert t2spline.NurbsSurface(s.control_points, s.weights, s.knots_u, s.knots_v) == \
        t2spline.NurbsSurface(s.control_points, s.weights, order=(3, 2))
    planar = t2spline.NurbsSurface(np.zeros((2, 3, 2)), degree=1)
    assert planar.dimension == 2 and planar.sample(3, 4).shape == (3, 4, 2)


def test_the_grid_engine_equals_the_straightforward_evaluator() -> None:
    rng = np.random.default_rng(5)
    ku = np.array([0, 0, 0, 0, 0.3, 0.3, 0.3, 0.3, 0.8, 1, 1, 1, 1.0])  # a jump at 0.3
    kv = np.array([0, 0, 0, 0.5, 1, 1, 1.0])
    s = t2spline.NurbsSurface(rng.uniform(-5, 5, (9, 4, 3)), np.exp(rng.uniform(-3, 3, (9, 4))), ku, kv)
    u = np.sort(rng.uniform(0, 1, 60))
    u[:3] = [0.0, 0.3, 1.0]
    v = rng.uniform(0, 1, 20)
    grid = s.sample(u, v)
    assert np.abs(grid - s.eval(u[:, None], v[None, :])).max() <= 1e-13


def fuzzy_net(nu: int = 4, nv: int = 3, heights: object = 0.6) -> t2spline.FuzzySurface:
    """A 3-D fuzzy surface with unequal spreads, random per number."""
    rng = np.random.default_rng(7)
    x, y = np.meshgrid(np.arange(nu, dtype=float), np.arange(nv, dtype=float), indexing="ij")
    crisp = np.stack([x, y, np.sin(x) * np.cos(y)], axis=-1)
    left = np.cumsum(rng.uniform(0, 0.2, size=(nu, nv, 3, 3)), axis=-1)
    right = np.cumsum(rng.uniform(0, 0.3, size=(nu, nv, 3, 3)), axis=-1)
    feet = [np.stack([crisp - left[..., k], crisp + right[..., k]], axis=-1) for k in (2, 1, 0)]
    return t2spline.FuzzySurface(crisp, *feet, lower_height=heights,
                                 weights=rng.uniform(0.5, 2, (nu, nv)), degree=(2, 1))


def test_fuzzy_surface_layers_are_ordered_and_the_engine_agrees() -> None:
    s = fuzzy_net()
    u = np.sort(np.random.default_rng(3).uniform(0, 1, 30))
    v = np.linspace(0, 1, 9)
    samples = s.sample(u, v)
    assert list(samples) == ["u", "v", *LAYERS]
    assert np.array_equal(samples["u"], u) and np.array_equal(samples["v"], v)
    reference = s.eval_layers(u[:, None], v[None, :])  # (30, 9, 7, 3)
    assert reference.shape == (30, 9, 7, 3)
    scale = np.abs(s.upper).max()
    for k, name in enumerate(LAYERS):
        assert samples[name].shape == (30, 9, 3) and samples[name].dtype == np.float64
        assert np.abs(samples[name] - reference[:, :, k]).max() <= 1e-13 * scale, name
        assert np.array_equal(s.layer_surface(name).eval(0.4, 0.7), s.eval_layers(0.4, 0.7)[k])
        assert np.array_equal(s.layer_surface(name).control_points, s.layer_control_points(name))
    stacked = np.stack([samples[name] for name in LAYERS])
    assert np.all(np.diff(stacked, axis=0) >= 0), "the docs/method.md §1 order of the layers"
    uniform = s.sample(6, 4)
    assert [uniform["u"].tolist(), uniform["v"].tolist()] == [list(a) for a in s.uniform_params(6, 4)]
    assert np.array_equal(s.crisp_surface().control_points, s.crisp)


def test_fuzzy_surface_attributes() -> None:
    s = fuzzy_net()
    assert (s.dimension, s.degree, s.order, s.shape) == (3, (2, 1), (3, 2), (4, 3))
    assert s.crisp.shape == (4, 3, 3) and s.upper.shape == (4, 3, 3, 2)
    assert s.lower_height.shape == (4, 3, 3) and np.all(s.lower_height == 0.6)
    assert np.array_equal(s.upper[..., 0], s.layer_control_points("upper_left"))
    assert np.array_equal(s.lower[..., 1], s.layer_control_points("lower_right"))
    x, y, z = s.point(2, 1)
    assert (x.crisp, y.upper[1], z.lower_height) == (s.crisp[2, 1, 0], s.upper[2, 1, 1, 1], 0.6)
    assert s.knots_u.tolist() == [0, 0, 0, 0.5, 1, 1, 1] and s.knots_v.tolist() == [0, 0, 0.5, 1, 1]
    assert repr(s) == ("FuzzySurface(dimension=3, degree=(2, 1), order=(3, 2), control_points=(4, 3, 3), "
                       "domain=((0.0, 1.0), (0.0, 1.0)))")
    per_axis = fuzzy_net(heights=[0.3, 0.6, 1.0])
    assert np.array_equal(per_axis.lower_height, np.broadcast_to([0.3, 0.6, 1.0], (4, 3, 3)))
    per_row = fuzzy_net(heights=np.linspace(0.2, 0.8, 4)[:, None, None])
    assert np.array_equal(per_row.lower_height[:, 0, 0], np.linspace(0.2, 0.8, 4))


def test_fuzzy_operations_keep_every_layer() -> None:
    s = fuzzy_net()
    u, v = np.linspace(0, 1, 13)[:, None], np.linspace(0, 1, 7)[None, :]
    before = s.eval_layers(u, v)
    for changed in (s.insert_knot(0.35, direction="u"), s.insert_knot(0.2, times=2, direction="v"),
                    s.refine_knots([0.1, 0.9], direction="v"), s.elevate_degree(direction="u"), s.elevate_degree(direction="v")):
        assert np.abs(changed.eval_layers(u, v) - before).max() <= 1e-12
    a, b = s.split_at(0.5, direction="v")
    assert a.domain[1] == (0.0, 0.5) and np.abs(b.eval_layers(0.3, 0.75) - s.eval_layers(0.3, 0.75)).max() <= 1e-13
    assert s.segment((0.2, 0.4), (0.0, 1.0)).domain == ((0.2, 0.4), (0.0, 1.0))
    iso = s.isocurve(0.3, direction="u")  # v ↦ S(0.3, v), every layer
    assert isinstance(iso, t2spline.FuzzyCurve)
    t = np.linspace(0, 1, 11)
    assert np.abs(iso.eval_layers(t) - s.eval_layers(0.3, t)).max() <= 1e-13
    mixed = fuzzy_net(heights=np.linspace(0.2, 0.8, 4)[:, None, None])
    with pytest.raises(ValueError, match="this operation needs one lower height per coordinate"):
        mixed.insert_knot(0.5, direction="u")


def test_solutions_of_constant_and_symmetric_spreads() -> None:
    x, y = np.meshgrid(np.arange(3.0), np.arange(4.0), indexing="ij")
    crisp = np.stack([x, y, x * y], axis=-1)
    spread = np.array([-0.6, 0.9])
    s = t2spline.FuzzySurface(crisp, crisp[..., None] + spread, crisp[..., None] + 0.6 * spread,
                              crisp[..., None] + 0.3 * spread, lower_height=0.6, degree=2)
    # alpha = 0.8 > h: two-term means of the upper and primary cut ends,
    # left = c − 0.2·(0.6 + 0.36)/2 = c − 0.096, right = c + 0.2·(0.9 + 0.54)/2
    # = c + 0.144; defuzzified (left + c + right)/3 = c + 0.016 in x, y and z.
    solution = s.solve(0.8)
    shift = 0.016
    assert np.abs(solution.defuzzified - crisp - shift).max() <= 1e-14
    d = solution.distance()
    assert set(d) == {"max", "max_at", "rms"} and len(d["max_at"]) == 2
    assert d["max"] == pytest.approx(shift * np.sqrt(3), rel=1e-12)
    assert d["rms"] == pytest.approx(shift * np.sqrt(3), rel=1e-12)
    symmetric = t2spline.FuzzySurface(crisp, crisp[..., None] + [-1, 1], crisp[..., None] + [-0.5, 0.5],
                                      crisp[..., None] + [-0.2, 0.2], lower_height=0.5, degree=1)
    for alpha in (0.0, 0.3, 0.5, 0.7, 1.0):
        d = symmetric.solve(alpha).distance()
        assert d["max"] <= 1e-15 and d["rms"] <= 1e-15, (alpha, d)


def test_surface_solution_stages_and_their_surfaces() -> None:
    s = fuzzy_net(heights=np.where(np.arange(3) == 1, 0.4, 0.9))  # y numbers of height 0.4
    solution = s.solve(0.55)
    assert solution.alpha == 0.55 and solution.type_reduction == "paper"
    assert solution.fuzzy_surface == s
    cut = solution.alpha_cut
    assert list(cut) == [name for name in LAYERS if name != "crisp"]
    assert all(a.shape == (4, 3, 3) for a in cut.values())
    assert np.array_equal(np.isnan(cut["lower_left"]), s.lower_height < 0.55)
    assert solution.alpha_cut_surface("lower_left") is None
    assert solution.alpha_cut_surface("upper_left") is not None
    left, right = solution.type_reduced_left, solution.type_reduced_right
    assert np.all(left <= solution.crisp) and np.all(solution.crisp <= right)
    assert np.allclose(solution.defuzzified, (left + solution.crisp + right) / 3, rtol=0, atol=1e-15)
    assert np.array_equal(solution.type_reduced_surface("right").control_points, right)
    assert np.array_equal(solution.defuzzified_surface().control_points, solution.defuzzified)
    assert np.array_equal(solution.crisp_surface().control_points, s.crisp)
    stages = solution.sample(21, 11)
    assert list(stages) == ["u", "v", "alpha_cut", "type_reduced", "defuzzified"]
    assert list(stages["type_reduced"]) == ["left", "right"]
    assert stages["alpha_cut"]["lower_right"] is None
    assert stages["alpha_cut"]["upper_right"].shape == (21, 11, 3)
    u, v = stages["u"][:, None], stages["v"][None, :]
    assert np.abs(stages["defuzzified"] - solution.defuzzified_surface().eval(u, v)).max() <= 1e-13
    gap = np.linalg.norm(stages["defuzzified"] - solution.crisp_surface().eval(u, v), axis=-1)
    distance = solution.distance()
    assert gap.max() <= distance["max"] * (1 + 1e-12)
    at = solution.defuzzified_surface().eval(*distance["max_at"]) - solution.crisp_surface().eval(*distance["max_at"])
    assert np.linalg.norm(at) == pytest.approx(distance["max"], rel=1e-14)
    assert repr(solution) == ("SurfaceSolution(alpha=0.55, type_reduction='paper', "
                              "control_points=(4, 3, 3), degree=(2, 1))")


def test_a_net_in_the_plane() -> None:
    x, y = np.meshgrid(np.arange(3.0), np.arange(2.0), indexing="ij")
    crisp = np.stack([x, y], axis=-1)
    s = t2spline.FuzzySurface(crisp, crisp[..., None] + [-1, 2], crisp[..., None] + [-0.5, 1],
                              crisp[..., None] + [-0.2, 0.3], lower_height=0.5, degree=1)
    assert s.dimension == 2 and s.sample(3, 2)["crisp"].shape == (3, 2, 2)
    assert s.solve(0.2).distance()["max"] > 0
    with pytest.raises(ValueError, match="^normal: a surface in the plane has none"):
        s.crisp_surface().normal(0.5, 0.5)
