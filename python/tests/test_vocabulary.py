"""One vocabulary across the classes: calling a curve or surface evaluates it
(as splipy's objects are called), and what a fuzzy surface offers per layer
a fuzzy curve offers too, each equal to the layer objects' own answers."""

from __future__ import annotations

import inspect
import json
import subprocess
from pathlib import Path

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


# The core's capabilities (t2spline::capability) and the method that offers
# each on each class: every class has the capability under the name given,
# crisp objects in the singular, fuzzy objects per layer.
CAPABILITIES = {
    "Parametric": {
        "NurbsCurve": "eval",
        "NurbsSurface": "eval",
        "FuzzyCurve": "eval_layers",
        "FuzzySurface": "eval_layers",
    },
    "Differentiable": dict.fromkeys(
        ["NurbsCurve", "NurbsSurface", "FuzzyCurve", "FuzzySurface"], "derivatives"
    ),
    "Curvature": {
        "NurbsCurve": "curvature",
        "NurbsSurface": "curvature",
        "FuzzyCurve": "curvatures",
        "FuzzySurface": "curvatures",
    },
    "Bounded": dict.fromkeys(
        ["NurbsCurve", "NurbsSurface", "FuzzyCurve", "FuzzySurface"], "bounding_box"
    ),
    "Closest": {
        "NurbsCurve": "closest_point",
        "NurbsSurface": "closest_point",
        "FuzzyCurve": "closest_points",
        "FuzzySurface": "closest_points",
    },
}
KNOT_OPERATIONS = ["insert_knot", "refine_knots", "elevate_degree", "split_at", "segment"]

# What a curve class has and its surface class lacks, or the other way
# round, and why; any other difference fails the test below, and so does a
# reason for a difference that no longer exists.
CURVE_ONLY = {
    "NurbsCurve": {
        "arc_length": "a length is a curve's measure; a surface has no such parameter",
        "param_at_length": "a surface has no arc-length parameter",
        "tangent": "a surface has a normal instead",
        "clamped": "surfaces are built clamped",
        "knots": "a surface has knots_u and knots_v",
    },
    "FuzzyCurve": {
        "knots": "a surface has knots_u and knots_v",
        "layer_curve": "its surface counterpart is layer_surface",
        "crisp_curve": "its surface counterpart is crisp_surface",
        "region": "alpha-regions are polygons of plane curves; a surface has envelopes and contours",
        "membership_grid": "a surface's grades over a plan are its envelope (t2spline envelope)",
        "envelope": "the range at one parameter over weights and points in their cuts; a surface's "
        "weights are crisp and its envelope is over a plan (t2spline envelope)",
        "weight_numbers": "fuzzy weights are read for curves only (docs/method.md §16)",
    },
}
SURFACE_ONLY = {
    "NurbsSurface": {
        "isocurve": "a curve has no isocurves",
        "normal": "a curve in space has no single normal",
        "shape": "a curve's control points are a list, not a net",
        "degree_u": "deprecated: degree[0]",
        "degree_v": "deprecated: degree[1]",
        "knots_u": "a curve has one knot vector",
        "knots_v": "a curve has one knot vector",
    },
    "FuzzySurface": {
        "isocurve": "a curve has no isocurves",
        "shape": "a curve's control points are a list, not a net",
        "degree_u": "deprecated: degree[0]",
        "degree_v": "deprecated: degree[1]",
        "knots_u": "a curve has one knot vector",
        "knots_v": "a curve has one knot vector",
        "layer_surface": "its curve counterpart is layer_curve",
        "crisp_surface": "its curve counterpart is crisp_curve",
    },
}


def public(cls: type) -> set:
    return {name for name in dir(cls) if not name.startswith("_")}


def test_every_class_has_every_capability_under_its_name() -> None:
    for capability, names in CAPABILITIES.items():
        for cls, method in names.items():
            assert callable(getattr(getattr(t2spline, cls), method, None)), (capability, cls, method)
    for cls in ["NurbsCurve", "NurbsSurface", "FuzzyCurve", "FuzzySurface"]:
        for method in KNOT_OPERATIONS:
            assert callable(getattr(getattr(t2spline, cls), method, None)), (cls, method)


@pytest.mark.parametrize(
    "curve, surface", [("NurbsCurve", "NurbsSurface"), ("FuzzyCurve", "FuzzySurface")]
)
def test_curves_and_surfaces_differ_only_where_a_reason_is_stated(curve: str, surface: str) -> None:
    c, s = public(getattr(t2spline, curve)), public(getattr(t2spline, surface))
    assert c - s == set(CURVE_ONLY[curve]), f"{curve} only: {sorted(c - s)}"
    assert s - c == set(SURFACE_ONLY[surface]), f"{surface} only: {sorted(s - c)}"


def test_a_fuzzy_curve_measures_its_layers_as_their_curves_do() -> None:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    t = np.linspace(0.05, 0.95, 7).reshape(7, 1)
    curvatures = curve.curvatures(t)
    derivatives = curve.derivatives(t, order=2)
    assert curvatures.shape == (7, 1, 7) and derivatives.shape == (7, 1, 7, 3, 2)
    lo, hi = curve.bounding_box()
    for i, name in enumerate(LAYERS):
        layer = curve.layer_curve(name)
        np.testing.assert_array_equal(curvatures[..., i], layer.curvature(t))
        np.testing.assert_array_equal(derivatives[..., i, :, :], layer.derivatives(t, order=2))
        llo, lhi = layer.bounding_box()
        assert np.all(lo <= llo) and np.all(lhi <= hi)
        assert np.all(layer.sample(2001) >= lo - 1e-12) and np.all(layer.sample(2001) <= hi + 1e-12)
    # The box is the union of the layers' boxes: each side is attained.
    boxes = np.array([curve.layer_curve(name).bounding_box() for name in LAYERS])
    np.testing.assert_array_equal(lo, boxes[:, 0].min(axis=0))
    np.testing.assert_array_equal(hi, boxes[:, 1].max(axis=0))
    with pytest.raises(ValueError, match="outside the domain"):
        curve.curvatures(1.5)


def test_a_fuzzy_surface_differentiates_its_layers_as_their_surfaces_do() -> None:
    surface = t2spline.FuzzySurface.from_job(CYLINDER)
    (u0, u1), (v0, v1) = surface.domain
    u = np.linspace(u0, u1, 4)[:, None]
    v = np.linspace(v0, v1, 3)[None, :]
    d = surface.derivatives(u, v, order=2)
    assert d.shape == (4, 3, 7, 3, 3, 3)
    for i, name in enumerate(LAYERS):
        np.testing.assert_array_equal(
            d[:, :, i], surface.layer_surface(name).derivatives(u, v, order=2)
        )
    assert np.isnan(d[..., 2, 1, :]).all() and not np.isnan(d[..., 1, 1, :]).any()


# A surface's operation in one direction takes the curve operation's
# arguments, then the direction as a keyword.
DIRECTED = ["insert_knot", "refine_knots", "elevate_degree", "split_at"]


@pytest.mark.parametrize(
    "curve, surface", [("NurbsCurve", "NurbsSurface"), ("FuzzyCurve", "FuzzySurface")]
)
@pytest.mark.parametrize("method", DIRECTED)
def test_a_surface_operation_takes_the_curve_arguments_then_a_direction(
    curve: str, surface: str, method: str
) -> None:
    c = inspect.signature(getattr(getattr(t2spline, curve), method))
    s = inspect.signature(getattr(getattr(t2spline, surface), method))
    assert list(s.parameters) == [*c.parameters, "direction"]
    assert s.parameters["direction"].kind is inspect.Parameter.KEYWORD_ONLY
    for name, p in c.parameters.items():
        assert s.parameters[name].default == p.default, (method, name)


def test_the_old_forms_still_work_with_a_deprecation_warning() -> None:
    surface = t2spline.FuzzySurface.from_job(CYLINDER)
    net = surface.crisp_surface()
    pairs = [
        (lambda s: s.insert_knot("u", 0.3, 2), lambda s: s.insert_knot(0.3, 2, direction="u")),
        (lambda s: s.refine_knots("v", [0.2, 0.7]), lambda s: s.refine_knots([0.2, 0.7], direction="v")),
        (lambda s: s.elevate_degree("v"), lambda s: s.elevate_degree(direction="v")),
        (lambda s: s.elevate_degree("u", times=2), lambda s: s.elevate_degree(2, direction="u")),
    ]
    for s in (surface, net):
        for old, new in pairs:
            with pytest.warns(DeprecationWarning, match="use .*direction="):
                before = old(s)
            np.testing.assert_array_equal(before.weights, new(s).weights)
            np.testing.assert_array_equal(before.knots_u, new(s).knots_u)
            np.testing.assert_array_equal(before.knots_v, new(s).knots_v)
        with pytest.warns(DeprecationWarning):
            a, b = s.split_at("u", 0.4)
        a2, b2 = s.split_at(0.4, direction="u")
        np.testing.assert_array_equal(a.knots_u, a2.knots_u)
        np.testing.assert_array_equal(b.knots_u, b2.knots_u)
        with pytest.warns(DeprecationWarning):
            iso = s.isocurve("v", 0.5)
        np.testing.assert_array_equal(iso.knots, s.isocurve(0.5, direction="v").knots)
        with pytest.warns(DeprecationWarning, match=r"use degree\[0\]"):
            assert s.degree_u == s.degree[0]
        with pytest.warns(DeprecationWarning, match=r"use degree\[1\]"):
            assert s.degree_v == s.degree[1]
        assert s.order == (s.degree[0] + 1, s.degree[1] + 1)
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    with pytest.warns(DeprecationWarning, match=r"insert_knot\(t="):
        old_curve = curve.insert_knot(u=0.3)
    np.testing.assert_array_equal(old_curve.knots, curve.insert_knot(t=0.3).knots)
    with pytest.raises(TypeError, match="missing the keyword argument direction"):
        net.insert_knot(0.3)
    with pytest.raises(TypeError, match="at most 2 positional"):
        net.insert_knot(0.3, 1, 2, direction="u")


def test_a_solution_samples_under_the_result_file_keys(cli: Path, tmp_path: Path) -> None:
    result = json.loads(
        subprocess.run(
            [str(cli), "run", str(EXAMPLE), "--samples", "9"], check=True, capture_output=True, text=True
        ).stdout
    )
    solution = t2spline.FuzzyCurve.from_job(EXAMPLE).solve(result["alpha"])
    stages = solution.sample(9)
    curves = result["curves"]
    assert set(stages) - {"params"} <= set(curves)
    np.testing.assert_array_equal(stages["params"], curves["params"])
    for side in ("left", "right"):
        np.testing.assert_array_equal(stages["type_reduced"][side], curves["type_reduced"][side])
        with pytest.warns(DeprecationWarning, match=rf"\['type_reduced'\]\['{side}'\]"):
            old = stages[f"type_reduced_{side}"]
        assert old is stages["type_reduced"][side]
    np.testing.assert_array_equal(stages["defuzzified"], curves["defuzzified"])
    with pytest.raises(KeyError):
        stages["type_reduced_middle"]
    surface = t2spline.FuzzySurface.from_job(CYLINDER).solve(0.5)
    assert list(surface.sample(3, 2)["type_reduced"]) == ["left", "right"]


def test_plot_draws_with_the_colours_of_the_figures(cli: Path, tmp_path: Path) -> None:
    """`t2spline.plot` takes its colours from the figures' own table, and the
    CLI's stage figures draw with those colours."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    import t2spline.plot as tplot

    palette = dict(t2spline._t2spline._palette())
    assert tplot.PALETTE == palette
    assert (tplot.UPPER, tplot.PRIMARY, tplot.LOWER) == (palette["upper"], palette["primary"], palette["lower"])
    subprocess.run([str(cli), "plot", str(EXAMPLE), "-o", str(tmp_path), "--format", "svg"], check=True,
                   capture_output=True)
    drawn = {path.stem: path.read_text().lower() for path in tmp_path.glob("*.svg")}
    for name in ("upper", "primary", "lower"):
        assert palette[name].lower() in drawn["stage1-fuzzy"], name
    for name in ("type_reduced_left", "type_reduced_right"):
        assert palette[name].lower() in drawn["stage3-type-reduced"], name
    assert palette["solution"].lower() in drawn["stage4-defuzzified"]
    ax = Figure().add_subplot()
    tplot.stage3(ax, t2spline.run(EXAMPLE))
    used = {matplotlib.colors.to_hex(line.get_color()) for line in ax.get_lines()}
    assert {palette["type_reduced_left"], palette["type_reduced_right"]} <= used


def test_eval_stacks_the_layers_and_sample_names_them_as_the_result_file(cli: Path) -> None:
    """`eval*` gives one array (parameters' axes, then the seven layers in
    order); `sample` gives what `run` writes: for a fuzzy curve the result
    file's `curves.layers` under the same names, with `params`."""
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    result = json.loads(
        subprocess.run([str(cli), "run", str(EXAMPLE), "--samples", "5"], check=True,
                       capture_output=True, text=True).stdout
    )
    samples = curve.sample(5)
    stacked = curve.eval_layers(samples["params"])
    assert stacked.shape == (5, 7, 2)
    np.testing.assert_array_equal(samples["params"], result["curves"]["params"])
    for i, name in enumerate(LAYERS):
        np.testing.assert_allclose(stacked[:, i], samples[name], rtol=0, atol=1e-12)
        if name != "crisp":
            np.testing.assert_array_equal(samples[name], result["curves"]["layers"][name])
    np.testing.assert_array_equal(samples["crisp"], result["curves"]["crisp"])
    crisp = curve.crisp_curve()
    assert crisp.sample(5).shape == crisp.eval(samples["params"]).shape == (5, 2)
