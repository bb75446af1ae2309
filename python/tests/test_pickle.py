"""Every class pickles (each protocol) and copies (`copy.copy`,
`copy.deepcopy`) to an equal object that computes the same numbers, and
curves travel to `multiprocessing` workers and back (fork and spawn)."""

from __future__ import annotations

import copy
import json
import multiprocessing
import operator
import pickle
from typing import Any, List

import numpy as np
import pytest

import t2spline
from conftest import EXAMPLE, ROOT, bits, random_job

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"


def curves_of(seed: int, n: int) -> List[t2spline.FuzzyCurve]:
    """`n` fuzzy curves of random valid jobs."""
    rng = np.random.default_rng(seed)
    out: List[t2spline.FuzzyCurve] = []
    while len(out) < n:
        try:
            out.append(t2spline.FuzzyCurve.from_job(random_job(rng)))
        except t2spline.JobError:
            pass  # a random repeated knot beyond the order
    return out


def number(lower_height: float = 0.6) -> t2spline.FuzzyNumber:
    return t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), lower_height)


def objects() -> List[Any]:
    """One object or more of every class, of either dimension."""
    curves = curves_of(24, 6)
    curves.append(t2spline.FuzzyCurve.from_job(EXAMPLE))
    surface = t2spline.FuzzySurface.from_job(TERRAIN)
    arc = t2spline.NurbsCurve(
        [[1, 0, 0], [1, 1, 0.5], [0, 1, 1]], weights=[1, np.sqrt(0.5), 1], degree=2
    )
    plane = t2spline.NurbsSurface(
        [[[0, 0], [0, 1]], [[1, 0], [1, 1.5]]], knots_u=[0, 0, 2, 2], knots_v=[0, 0, 1, 1]
    )
    out: List[Any] = [number(), number(1.0), number().alpha_cut(0.5), number().alpha_cut(0.8)]
    out += [arc, plane, surface, surface.solve(0.3), surface.solve(type_reduction="nie-tan")]
    for c in curves:
        out += [c, c.solve(0.7), c.solve(type_reduction="centroid")]
    planar = next(c for c in curves if c.dimension == 2)
    region = planar.region(0.4, tolerance=0.05)
    assert region is not None
    out.append(region)
    return out


OBJECTS = objects()
IDS = [f"{type(o).__name__}-{k}" for k, o in enumerate(OBJECTS)]


def same_numbers(a: Any, b: Any) -> None:
    """Two objects of a class compute the same numbers, bit for bit."""
    if isinstance(a, (t2spline.FuzzyCurve, t2spline.NurbsCurve)):
        sa, sb = a.sample(37), b.sample(37)
        if isinstance(sa, dict):
            for key in sa:
                assert np.array_equal(bits(sa[key]), bits(sb[key])), key
        else:
            assert np.array_equal(bits(sa), bits(sb))
    elif isinstance(a, t2spline.Solution):
        assert a.distance() == b.distance()
    elif isinstance(a, t2spline.Region):
        assert (a.area, a.tolerance, a.__geo_interface__) == (b.area, b.tolerance, b.__geo_interface__)
    elif isinstance(a, t2spline.AlphaCut):
        assert (a.upper, a.primary, a.lower, a.type_reduce()) == (
            b.upper, b.primary, b.lower, b.type_reduce()
        )


@pytest.mark.parametrize("obj", OBJECTS, ids=IDS)
def test_every_object_pickles_to_an_equal_one(obj: Any) -> None:
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(obj, protocol=protocol))
        assert type(back) is type(obj)
        assert back == obj, protocol
        assert not (back != obj)
        same_numbers(back, obj)
    assert repr(pickle.loads(pickle.dumps(obj))) == repr(obj)


@pytest.mark.parametrize("obj", OBJECTS, ids=IDS)
def test_every_object_copies_to_an_equal_one(obj: Any) -> None:
    for made in (copy.copy(obj), copy.deepcopy(obj), copy.deepcopy([obj, obj])[1]):
        assert type(made) is type(obj)
        assert made == obj
        same_numbers(made, obj)


def test_equality_tells_objects_apart() -> None:
    """`==` compares the values: objects that differ anywhere are unequal,
    so the equalities above say something."""
    assert number() != number(0.7)
    assert number().alpha_cut(0.5) != number().alpha_cut(0.55)
    assert number().alpha_cut(0.5) == number().alpha_cut(0.5)
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    assert curve.solve(0.5) != curve.solve(0.55)
    assert curve.solve(0.5) == curve.solve(0.5)
    assert curve.insert_knot(0.3) != curve
    job = json.loads(EXAMPLE.read_text())
    job["points"][1]["x"]["crisp"] += 1e-12
    assert t2spline.FuzzyCurve.from_job(job) != curve
    r1, r2 = curve.region(0.4, tolerance=0.05), curve.region(0.5, tolerance=0.05)
    assert r1 is not None and r2 is not None and r1 != r2
    assert r1 == curve.region(0.4, tolerance=0.05)


def test_a_region_restored_from_parts_of_another_form_is_refused() -> None:
    with pytest.raises(ValueError, match="membership"):
        t2spline.Region._restore([], 0.1, "middle", 0.5, "xy")
    with pytest.raises(TypeError):
        t2spline.Region._restore("polygons", 0.1, "upper", 0.5, "xy")


def test_a_restored_region_is_checked_as_a_computed_one() -> None:
    # What a pickle restores is not trusted: each of these once loaded into a
    # region with area NaN or -1 and invalid GeoJSON.
    square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    ok = t2spline.Region._restore([(square, [])], 0.1, "upper", 0.5, "xy")
    assert ok.area == 1.0
    hole = [[0.25, 0.25], [0.25, 0.75], [0.75, 0.75], [0.75, 0.25]]
    assert t2spline.Region._restore([(square, [hole])], 0.1, "upper", 0.5, "xy").area == 0.75
    bad = [
        ([([[0.0, 0.0], [float("nan"), 0.0], [1.0, 1.0]], [])], 0.1, 0.5,
         "polygon 0, ring 0 (the exterior): every coordinate must be a finite number"),
        ([(square[::-1], [])], 0.1, 0.5,
         "polygon 0, ring 0 (the exterior): the exterior must run counter-clockwise"),
        ([(square, [hole[::-1]])], 0.1, 0.5, "polygon 0, ring 1 (a hole): a hole must run clockwise"),
        ([([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.5, 2.0], [0.0, 1.0]], [])], 0.1, 0.5,
         "polygon 0, ring 0 (the exterior): the ring crosses itself"),
        ([(square + [square[0]], [])], 0.1, 0.5,
         "polygon 0, ring 0 (the exterior): rings are stored open"),
        ([(square[:2], [])], 0.1, 0.5, "polygon 0, ring 0 (the exterior): a ring needs at least three vertices"),
        ([(square, [])], float("nan"), 0.5, "tolerance = NaN is outside (0, inf)"),
        ([(square, [])], -1.0, 0.5, "tolerance = -1 is outside (0, inf)"),
        ([(square, [])], 0.1, 5.0, "alpha = 5 is outside [0, 1]"),
    ]
    for polygons, tolerance, alpha, message in bad:
        with pytest.raises(ValueError) as caught:
            t2spline.Region._restore(polygons, tolerance, "upper", alpha, "xy")
        assert str(caught.value).startswith(message), (message, str(caught.value))



@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_curves_go_through_a_multiprocessing_pool(method: str) -> None:
    if method not in multiprocessing.get_all_start_methods():
        pytest.skip(f"no {method} here")
    curves = curves_of(7, 8)
    context = multiprocessing.get_context(method)
    with context.Pool(2) as pool:
        # There and back: each curve pickled to a worker, copied, pickled back.
        back = pool.map(copy.copy, curves)
        solved = pool.map(operator.methodcaller("solve", 0.45), curves)
    assert back == curves
    assert solved == [c.solve(0.45) for c in curves]
    for c, s in zip(curves, solved):
        assert s.fuzzy_curve == c
        assert s.distance() == c.solve(0.45).distance()
