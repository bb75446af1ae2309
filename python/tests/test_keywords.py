# The calls pass wrong types on purpose.
# mypy: disable-error-code="arg-type"
"""Scalar arguments of the wrong type or beyond 64 bits: a `TypeError` or a
`ValueError` whose message names the argument and says what it takes, for
every function and method of the package (never a Rust type name, never a
bare `must be real number, not str` or `OverflowError`)."""

from __future__ import annotations

import inspect
from typing import Any, Callable

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, ROOT

C = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
S = np.array([-0.5, 0.8])
BIG = 2**64
HUGE = 10**400  # beyond a float


def fuzzy_curve() -> t2spline.FuzzyCurve:
    return t2spline.FuzzyCurve(C, C[..., None] + S, C[..., None] + 0.5 * S, C[..., None] + 0.2 * S,
                               lower_height=0.6, degree=2)


def fuzzy_surface() -> t2spline.FuzzySurface:
    return t2spline.FuzzySurface.from_job(ROOT / "examples" / "fuzzy-terrain.json")


def surface() -> t2spline.NurbsSurface:
    return t2spline.NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], degree=1)


def number() -> t2spline.FuzzyNumber:
    return t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)


def fit(**changes: Any) -> Any:
    t = np.linspace(0, 1, 8)
    crisp = np.stack([4 * t, np.sin(3 * t)], axis=1)
    s = np.array([-0.2, 0.3])
    args: dict[str, Any] = dict(degree=3)
    args.update(changes)
    return t2spline.fit(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
                        crisp[..., None] + 0.2 * s, 0.5, **args)


REAL = "expected a real number (float or int), got"
INT = "expected an int, got"
TEXT = "expected a str, got"
BEYOND = "is outside the range of a 64-bit integer [-2**63, 2**63 - 1]"

CASES: list[tuple[str, Callable[[], Any], type, str]] = [
    # run: each keyword
    ("run samples", lambda: t2spline.run(EXAMPLE, samples="5"), TypeError,
     "samples: expected an int or a pair (u, v) of ints, got str"),
    ("run samples triple", lambda: t2spline.run(EXAMPLE, samples=(5, 5, 5)), TypeError,
     "samples: expected an int or a pair (u, v) of ints, got a tuple of 3 item(s)"),
    ("run samples pair", lambda: t2spline.run(EXAMPLE, samples=(5, "5")), TypeError,
     f"samples[1]: {INT} str"),
    ("run samples big", lambda: t2spline.run(EXAMPLE, samples=BIG), ValueError,
     f"samples: 18446744073709551616 {BEYOND}"),
    ("run alpha", lambda: t2spline.run(EXAMPLE, alpha="0.5"), TypeError, f"alpha: {REAL} str"),
    ("run alpha huge", lambda: t2spline.run(EXAMPLE, alpha=HUGE), ValueError,
     "alpha: 1000"),
    ("run derivatives", lambda: t2spline.run(EXAMPLE, derivatives=1.5), TypeError,
     f"derivatives: {INT} float"),
    ("run derivatives big", lambda: t2spline.run(EXAMPLE, derivatives=-BIG), ValueError,
     f"derivatives: -18446744073709551616 {BEYOND}"),
    ("run type_reduction", lambda: t2spline.run(EXAMPLE, type_reduction=1), TypeError,
     f"type_reduction: {TEXT} int"),
    # constructors
    ("NurbsCurve degree", lambda: t2spline.NurbsCurve(C, degree="2"), TypeError, f"degree: {INT} str"),
    ("NurbsCurve degree big", lambda: t2spline.NurbsCurve(C, degree=BIG), ValueError,
     f"degree: 18446744073709551616 {BEYOND}"),
    ("NurbsCurve order", lambda: t2spline.NurbsCurve(C, order=2.0), TypeError, f"order: {INT} float"),
    ("FuzzyCurve degree", lambda: t2spline.FuzzyCurve(C, C[..., None] + S, C[..., None] + 0.5 * S,
                                                      C[..., None] + 0.2 * S, 0.6, degree="2"),
     TypeError, f"degree: {INT} str"),
    ("NurbsSurface degree", lambda: t2spline.NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
                                                          degree=(1, "1")),
     TypeError, f"degree[1]: {INT} str"),
    ("NurbsSurface order", lambda: t2spline.NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
                                                         order="2"),
     TypeError, "order: expected an int or a pair (u, v) of ints, got str"),
    ("FuzzyNumber crisp", lambda: t2spline.FuzzyNumber("1", (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6),
     TypeError, f"crisp: {REAL} str"),
    # None is the default (a crisp number's height, 1); a str is wrong.
    ("FuzzyNumber lower_height", lambda: t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), "0.6"),
     TypeError, f"lower_height: {REAL} str"),
    # fit and centroid
    ("fit degree", lambda: fit(degree="3"), TypeError, "degree: expected an int or a pair (u, v) of ints, got str"),
    ("fit degree big", lambda: fit(degree=BIG), ValueError, f"degree: 18446744073709551616 {BEYOND}"),
    ("fit control_points", lambda: fit(control_points=5.0), TypeError, "control_points: expected an int or a pair (u, v) of ints, got float"),
    ("fit parametrization", lambda: fit(parametrization=1), TypeError, f"parametrization: {TEXT} int"),
    ("fit mode", lambda: fit(mode=True), TypeError, f"mode: {TEXT} bool"),
    ("centroid method", lambda: t2spline.centroid([1, 2], [0, 0.5], [1, 1], method=1), TypeError,
     f"method: {TEXT} int"),
    # FuzzyNumber
    ("alpha_cut", lambda: number().alpha_cut("0.5"), TypeError, f"alpha: {REAL} str"),
    ("type_reduce", lambda: number().type_reduce([0.5]), TypeError, f"alpha: {REAL} list"),
    ("defuzzify", lambda: number().defuzzify(HUGE), ValueError, "alpha: 1000"),
    ("membership", lambda: number().membership(0.5, which=1), TypeError, f"which: {TEXT} int"),
    # curves
    ("derivatives order", lambda: fuzzy_curve().crisp_curve().derivatives(0.5, order="2"), TypeError,
     f"order: {INT} str"),
    ("arc_length a", lambda: fuzzy_curve().crisp_curve().arc_length(a="0"), TypeError, f"a: {REAL} str"),
    ("arc_length b", lambda: fuzzy_curve().crisp_curve().arc_length(0.0, b="1"), TypeError, f"b: {REAL} str"),
    ("param_at_length", lambda: fuzzy_curve().crisp_curve().param_at_length("1"), TypeError,
     f"length: {REAL} str"),
    ("insert_knot t", lambda: fuzzy_curve().insert_knot("0.5"), TypeError, f"t: {REAL} str"),
    ("insert_knot times", lambda: fuzzy_curve().insert_knot(0.5, times="2"), TypeError, f"times: {INT} str"),
    ("insert_knot times big", lambda: fuzzy_curve().crisp_curve().insert_knot(0.5, times=BIG), ValueError,
     f"times: 18446744073709551616 {BEYOND}"),
    ("elevate_degree", lambda: fuzzy_curve().elevate_degree(times=1.0), TypeError, f"times: {INT} float"),
    ("split_at", lambda: fuzzy_curve().split_at("0.5"), TypeError, f"t: {REAL} str"),
    ("segment", lambda: fuzzy_curve().crisp_curve().segment(0.0, "1"), TypeError, f"b: {REAL} str"),
    ("uniform_params", lambda: fuzzy_curve().uniform_params("5"), TypeError, f"count: {INT} str"),
    ("sample big", lambda: fuzzy_curve().sample(BIG), ValueError, f"params: 18446744073709551616 {BEYOND}"),
    ("point", lambda: fuzzy_curve().point("0"), TypeError, f"index: {INT} str"),
    ("point big", lambda: fuzzy_curve().point(BIG), ValueError, f"index: 18446744073709551616 {BEYOND}"),
    ("layer_curve", lambda: fuzzy_curve().layer_curve(3), TypeError, f"layer: {TEXT} int"),
    ("layer_control_points", lambda: fuzzy_curve().layer_control_points(None), TypeError,
     f"layer: {TEXT} NoneType"),
    ("solve alpha", lambda: fuzzy_curve().solve("0.5"), TypeError, f"alpha: {REAL} str"),
    ("solve type_reduction", lambda: fuzzy_curve().solve(0.5, type_reduction=2), TypeError,
     f"type_reduction: {TEXT} int"),
    ("alpha_cut_curve", lambda: fuzzy_curve().solve(0.5).alpha_cut_curve(1), TypeError, f"layer: {TEXT} int"),
    ("type_reduced_curve", lambda: fuzzy_curve().solve(0.5).type_reduced_curve(0), TypeError,
     f"side: {TEXT} int"),
    # surfaces
    ("isocurve direction", lambda: surface().isocurve(0.5, direction=0), TypeError, f"direction: {TEXT} int"),
    ("isocurve t", lambda: surface().isocurve("0.5", direction="u"), TypeError, f"t: {REAL} str"),
    ("surface insert_knot", lambda: surface().insert_knot(0.5, times="1", direction="u"), TypeError,
     f"times: {INT} str"),
    ("surface refine_knots", lambda: surface().refine_knots([0.5], direction=1), TypeError, f"direction: {TEXT} int"),
    ("surface elevate_degree", lambda: surface().elevate_degree(times=0.5, direction="v"), TypeError,
     f"times: {INT} float"),
    ("surface split_at", lambda: surface().split_at(None, direction="u"), TypeError, f"t: {REAL} NoneType"),
    ("surface segment v", lambda: surface().segment((0, 1), "ab"), TypeError,
     "v: expected a pair (a, b) of real numbers, got str"),
    ("surface segment u", lambda: surface().segment((0, "x"), (0, 1)), TypeError, f"u[1]: {REAL} str"),
    ("surface uniform_params", lambda: surface().uniform_params(3, "4"), TypeError, f"count_v: {INT} str"),
    ("surface derivatives", lambda: surface().derivatives(0.5, 0.5, order="1"), TypeError,
     f"order: {INT} str"),
    ("fuzzy surface point", lambda: fuzzy_surface().point(0, "1"), TypeError, f"j: {INT} str"),
    ("layer_surface", lambda: fuzzy_surface().layer_surface(1), TypeError, f"layer: {TEXT} int"),
    ("surface solve", lambda: fuzzy_surface().solve(alpha="1"), TypeError, f"alpha: {REAL} str"),
    ("alpha_cut_surface", lambda: fuzzy_surface().solve(0.5).alpha_cut_surface(1), TypeError,
     f"layer: {TEXT} int"),
    ("type_reduced_surface", lambda: fuzzy_surface().solve(0.5).type_reduced_surface(1), TypeError,
     f"side: {TEXT} int"),
]


@pytest.mark.parametrize("call, kind, message", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_a_scalar_argument_of_the_wrong_kind_is_named(call: Callable[[], Any], kind: type, message: str) -> None:
    with pytest.raises(kind) as e:
        call()
    assert type(e.value) is kind, repr(e.value)
    assert str(e.value).startswith(message), str(e.value)
    assert "PerDirection" not in str(e.value) and "C long" not in str(e.value)


def test_defaults_are_as_documented_and_numpy_scalars_are_numbers() -> None:
    curve = fuzzy_curve().crisp_curve()
    assert inspect.signature(t2spline.centroid).parameters["method"].default == "km"
    assert inspect.signature(t2spline.fit).parameters["mode"].default == "valid"
    assert inspect.signature(t2spline.fit).parameters["parametrization"].default == "chord"
    assert inspect.signature(curve.insert_knot).parameters["times"].default == 1
    assert inspect.signature(curve.derivatives).parameters["order"].default == 1
    assert inspect.signature(number().membership).parameters["which"].default == "upper"
    assert curve.insert_knot(0.5).knots.tolist() == curve.insert_knot(np.float32(0.5), times=np.int8(1)).knots.tolist()
    assert curve.derivatives(0.5).shape == (2, 2)
    run = t2spline.run(EXAMPLE, samples=np.int64(5), alpha=np.float64(0.25), derivatives=np.uint8(1))
    assert run["curves"]["params"].shape == (5,) and run["alpha"] == 0.25
    assert t2spline.run(ROOT / "examples" / "fuzzy-terrain.json", samples=[3, np.int32(4)])[
        "surfaces"]["crisp"].shape[:2] == (3, 4)
