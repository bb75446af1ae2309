"""The stub's return types against what the calls really return: for each
method whose annotation is a `TypedDict` of `t2spline.types` (or a list or
tuple of them), a real result on the shipped jobs must have every required
key, no key the type does not name, and values of the annotated kinds (numpy
float64 arrays for `Floats`, numbers, strings of the `Literal`s, ...), all
the way down. The annotation is read from `_t2spline.pyi` itself, so a stub
that drifts from the code fails here."""

from __future__ import annotations

import ast
import typing
from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import pytest

import t2spline
import t2spline.types as types

from conftest import EXAMPLE, ROOT

STUB = Path(t2spline.__file__).with_name("_t2spline.pyi")
CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"


def stub_returns() -> Dict[str, ast.expr]:
    """`Class.method` → its return annotation in the stub."""
    tree = ast.parse(STUB.read_text())
    out: Dict[str, ast.expr] = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            for f in node.body:
                if isinstance(f, ast.FunctionDef) and f.returns is not None:
                    out[f"{node.name}.{f.name}"] = f.returns
        elif isinstance(node, ast.FunctionDef) and node.returns is not None:
            out[node.name] = node.returns
    return out


def resolve(annotation: ast.expr) -> Any:
    """The annotation as a typing object, names taken from `t2spline.types`
    and the package."""
    namespace: Dict[str, Any] = {
        **vars(typing),
        **vars(types),
        **{n: getattr(t2spline, n) for n in t2spline.__all__},
        "np": np,
        "list": list,
    }
    return eval(compile(ast.Expression(annotation), "<stub>", "eval"), namespace)


def conforms(value: Any, tp: Any, where: str) -> None:
    """Fails with `where` if `value` is not of the annotated type `tp`."""
    origin, args = typing.get_origin(tp), typing.get_args(tp)
    if tp is typing.Any:
        return
    if tp is types.Floats or (origin is np.ndarray):
        assert isinstance(value, np.ndarray) and value.dtype == np.float64, (where, type(value))
        return
    if typing.is_typeddict(tp):
        assert isinstance(value, dict), (where, type(value))
        hints = typing.get_type_hints(tp)
        missing = tp.__required_keys__ - value.keys()
        unknown = value.keys() - hints.keys()
        assert not missing and not unknown, (where, sorted(missing), sorted(unknown))
        for k, v in value.items():
            conforms(v, hints[k], f"{where}[{k!r}]")
        return
    if origin is typing.Union:
        errors = []
        for a in args:
            try:
                conforms(value, a, where)
                return
            except AssertionError as e:
                errors.append(str(e))
        raise AssertionError(f"{where}: {value!r:.80} is none of {args}: {errors}")
    if origin is typing.Literal:
        assert value in args, (where, value, args)
        return
    if origin in (list, List):
        assert isinstance(value, list), (where, type(value))
        for i, v in enumerate(value):
            conforms(v, args[0], f"{where}[{i}]")
        return
    if origin in (tuple, Tuple):
        assert isinstance(value, tuple) and len(value) == len(args), (where, value)
        for i, (v, a) in enumerate(zip(value, args)):
            conforms(v, a, f"{where}[{i}]")
        return
    if origin is dict:
        assert isinstance(value, dict), (where, type(value))
        for k, v in value.items():
            conforms(k, args[0], f"{where} key")
            conforms(v, args[1], f"{where}[{k!r}]")
        return
    if tp is float:
        assert isinstance(value, (float, int)) and not isinstance(value, bool), (where, value)
        return
    if tp is type(None):
        assert value is None, (where, value)
        return
    assert isinstance(value, tp), (where, type(value), tp)


def region_of(curve: t2spline.FuzzyCurve) -> t2spline.Region:
    region = curve.region(0.5)
    assert region is not None
    return region


def calls() -> Dict[str, Callable[[], Any]]:
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    solution = curve.solve(0.5)
    surface = t2spline.FuzzySurface.from_job(CYLINDER)
    (u0, u1), (v0, v1) = surface.domain
    net = surface.solve(0.5)
    terrain = t2spline.FuzzySurface.from_job(ROOT / "examples" / "fuzzy-terrain.json")
    x = np.linspace(0.0, 1.0, 101)
    return {
        "FuzzyCurve.sample": lambda: curve.sample(11),
        "FuzzyCurve.membership": lambda: curve.membership([[2.0, 1.5], [0.0, 9.0]]),
        "FuzzyCurve.section": lambda: curve.section(2.0, levels=3),
        "FuzzyCurve.membership_grid": lambda: curve.membership_grid((0.0, 4.0), (0.0, 3.0), 8),
        "FuzzyCurve.measure": lambda: curve.measure(levels=3, at=[0.5]),
        "FuzzyCurve.distance_sweep": lambda: curve.distance_sweep([0.0, 0.5], samples=11),
        "FuzzyCurve.closest_points": lambda: curve.closest_points([2.0, 3.0]),
        "Region.__geo_interface__": lambda: region_of(curve).__geo_interface__,
        "Solution.alpha_cut": lambda: solution.alpha_cut,
        "Solution.sample": lambda: solution.sample(11),
        "Solution.distance": lambda: solution.distance(),
        "FuzzySurface.sample": lambda: surface.sample(5, 4),
        "FuzzySurface.curvatures": lambda: surface.curvatures(0.5 * (u0 + u1), 0.5 * (v0 + v1)),
        "FuzzySurface.membership": lambda: surface.membership([[0.5, 0.5, 0.5]]),
        "FuzzySurface.section": lambda: surface.section(0.5, 0.5, levels=3),
        "FuzzySurface.distance_sweep": lambda: surface.distance_sweep(0.5, samples=(5, 4)),
        # With `against`, the optional keys `cut` and `fill` too.
        "FuzzySurface.measure": lambda: terrain.measure(levels=[0.5], datum=103.0, against=terrain),
        "SurfaceSolution.alpha_cut": lambda: net.alpha_cut,
        "SurfaceSolution.sample": lambda: net.sample(5, 4),
        "SurfaceSolution.distance": lambda: net.distance(),
        "centroid": lambda: t2spline.centroid(x, np.minimum(x, 1 - x), np.ones_like(x)),
    }


CALLS = calls()


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_real_result_is_what_the_stub_says(name: str) -> None:
    returns = stub_returns()
    assert name in returns, f"{name} has no return annotation in the stub"
    tp = resolve(returns[name])
    conforms(CALLS[name](), tp, name)


def test_every_typed_dict_of_the_stub_is_checked_here() -> None:
    named = {
        n
        for n, a in stub_returns().items()
        if any(
            isinstance(node, ast.Name) and typing.is_typeddict(getattr(types, node.id, None))
            for node in ast.walk(a)
        )
    }
    # Property getters are called without parentheses; the rest are calls.
    unchecked = named - CALLS.keys() - {"fit", "NurbsSurface.curvature"}
    assert not unchecked, sorted(unchecked)


def test_the_checker_itself_refuses_what_does_not_conform() -> None:
    good = {"max": 1.0, "max_at": 0.5, "rms": 0.25}
    conforms(good, types.Distance, "good")
    with pytest.raises(AssertionError):
        conforms({**good, "extra": 1}, types.Distance, "extra key")
    with pytest.raises(AssertionError):
        conforms({"max": 1.0, "rms": 0.25}, types.Distance, "missing key")
    with pytest.raises(AssertionError):
        conforms({**good, "max": "1"}, types.Distance, "wrong kind")
    with pytest.raises(AssertionError):
        conforms([1.0, 2.0], types.Floats, "a list for an array")


def test_fit_and_the_surface_curvature_conform_too() -> None:
    returns = stub_returns()
    nurbs = t2spline.FuzzySurface.from_job(CYLINDER).crisp_surface()
    (u0, u1), (v0, v1) = nurbs.domain
    conforms(
        nurbs.curvature(0.5 * (u0 + u1), 0.5 * (v0 + v1)),
        resolve(returns["NurbsSurface.curvature"]),
        "NurbsSurface.curvature",
    )
    x = np.linspace(0.0, 4.0, 9)
    points = np.stack([x, 0.25 * x * (4.0 - x)], axis=-1)
    spread = np.array([-0.3, 0.3])
    result = t2spline.fit(
        points,
        points[..., None] + spread,
        points[..., None] + 0.6 * spread,
        points[..., None] + 0.3 * spread,
        lower_height=0.6,
        degree=2,
        control_points=4,
    )
    conforms(result, resolve(returns["fit"]), "fit")


def test_fit_of_a_net_conforms() -> None:
    returns = stub_returns()
    u, v = np.meshgrid(np.linspace(0.0, 1.0, 5), np.linspace(0.0, 1.0, 4), indexing="ij")
    net = np.stack([u, v, u * v], axis=-1)
    spread = np.array([-0.3, 0.3])
    result = t2spline.fit(
        net,
        net[..., None] + spread,
        net[..., None] + 0.6 * spread,
        net[..., None] + 0.3 * spread,
        lower_height=0.6,
        degree=(2, 1),
        control_points=(4, 3),
    )
    conforms(result, resolve(returns["fit"]), "fit")
    assert result[1]["net"] == {"data": [5, 4], "control": [4, 3]}
