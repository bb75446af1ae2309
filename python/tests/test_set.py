"""The fuzzy curve or surface as a set (docs/method.md §10) from Python:
membership grades of points of any leading shape, equal to `t2spline
membership`; regions that shapely opens through `__geo_interface__`;
station sections equal to `t2spline section` and nested level by level;
membership maps; and errors that name the argument."""

from __future__ import annotations

import csv
import io
import json
import subprocess
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest
import shapely.geometry

import t2spline

from conftest import EXAMPLE, ROOT

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"


@pytest.fixture(scope="module")
def curve() -> t2spline.FuzzyCurve:
    return t2spline.FuzzyCurve.from_job(EXAMPLE)


def segment(lower_height: float = 0.5) -> t2spline.FuzzyCurve:
    """The segment (0, 0)–(4, 0), ends moving ±1 (upper), ±0.5 (primary),
    ±0.25 (lower) at level 0."""
    c = np.array([[0.0, 0.0], [4.0, 0.0]])
    s = np.array([-1.0, 1.0])
    return t2spline.FuzzyCurve(
        c, c[..., None] + s, c[..., None] + 0.5 * s, c[..., None] + 0.25 * s,
        lower_height=lower_height, degree=1,
    )


def space_curve() -> t2spline.FuzzyCurve:
    c = np.array([[0.0, 0.0, 0.0], [2.0, 1.0, 3.0], [4.0, 0.0, 1.0]])
    s = np.array([-0.5, 0.5])
    return t2spline.FuzzyCurve(
        c, c[..., None] + s, c[..., None] + 0.6 * s, c[..., None] + 0.3 * s,
        lower_height=0.7, degree=2,
    )


def cli_membership(cli: Path, tmp_path: Path, job: Path, points: np.ndarray) -> Dict[str, np.ndarray]:
    """The grades that `t2spline membership JOB POINTS.csv` writes."""
    axes = "xyz"[: points.shape[-1]]
    path = tmp_path / "points.csv"
    with path.open("w") as f:
        f.write(",".join(axes) + "\n")
        for p in points:
            f.write(",".join(repr(float(v)) for v in p) + "\n")
    out = subprocess.run(
        [str(cli), "membership", str(job), str(path)], check=True, capture_output=True, text=True
    ).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == len(points)
    for row, p in zip(rows, points):
        assert [float(row[a]) for a in axes] == [float(v) for v in p]
    return {m: np.array([float(r[m]) for r in rows]) for m in ("upper", "primary", "lower")}


def cli_section(cli: Path, job: Path, *args: str) -> List[Dict[str, Any]]:
    out = subprocess.run(
        [str(cli), "section", str(job), *args], check=True, capture_output=True, text=True
    ).stdout
    levels: List[Dict[str, Any]] = json.loads(out)["levels"]
    return levels


# Membership grades.


@pytest.mark.parametrize("lead", [(), (7,), (3, 4), (2, 1, 3), (0,)], ids=str)
def test_grades_have_the_leading_shape_of_the_points(
    curve: t2spline.FuzzyCurve, lead: tuple
) -> None:
    rng = np.random.default_rng(1)
    points = rng.uniform(-1.0, 9.0, size=lead + (2,))
    g = curve.membership(points)
    assert list(g) == ["upper", "primary", "lower"]
    flat = curve.membership(points.reshape(-1, 2))
    for m in g:
        assert g[m].shape == lead and g[m].dtype == np.float64
        # Each point graded on its own: the same numbers in any shape.
        assert np.array_equal(g[m].reshape(-1), flat[m])
    assert np.all(g["lower"] <= g["primary"]) and np.all(g["primary"] <= g["upper"])
    assert np.all((0.0 <= g["lower"]) & (g["upper"] <= 1.0))


def test_a_list_of_points_and_a_single_point_are_read(curve: t2spline.FuzzyCurve) -> None:
    many = curve.membership([[1.0, 2.0], [3.0, 4.0]])
    one = curve.membership((3.0, 4.0))
    assert one["upper"].shape == ()
    assert float(one["upper"]) == many["upper"][1]


def test_grades_equal_the_cli(cli: Path, tmp_path: Path, curve: t2spline.FuzzyCurve) -> None:
    rng = np.random.default_rng(7)
    points = np.concatenate([rng.uniform(-1.0, 9.0, size=(40, 2)), curve.crisp])
    got = curve.membership(points)
    want = cli_membership(cli, tmp_path, EXAMPLE, points)
    assert np.any(want["upper"] > 0) and np.any(want["upper"] == 0)
    for m in want:
        np.testing.assert_allclose(got[m], want[m], rtol=1e-15, atol=0, err_msg=m)


def test_surface_grades_equal_the_cli(cli: Path, tmp_path: Path) -> None:
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    lo, hi = terrain.bounding_box()
    rng = np.random.default_rng(3)
    points = rng.uniform(lo, hi, size=(12, 3))
    got = terrain.membership(points.reshape(3, 4, 3))
    want = cli_membership(cli, tmp_path, TERRAIN, points)
    for m in want:
        assert got[m].shape == (3, 4)
        np.testing.assert_allclose(got[m].reshape(-1), want[m], rtol=1e-15, atol=0, err_msg=m)


def test_points_of_the_crisp_curve_grade_one_one_and_h() -> None:
    line = segment(lower_height=0.5)
    on = line.membership(np.stack([np.linspace(0.0, 4.0, 9), np.zeros(9)], axis=-1))
    assert np.all(on["upper"] == 1.0) and np.all(on["primary"] == 1.0)
    np.testing.assert_allclose(on["lower"], 0.5, rtol=0, atol=1e-12)
    # Half-way to the upper cut's edge: upper 1/2; on the primary cut's edge: 0.
    # Grades are certified upper bounds within 1e-7 (docs/set.md), and the
    # slack of "on the set" adds its share on the edge.
    off = line.membership([2.0, 0.5])
    assert 0.5 <= float(off["upper"]) <= 0.5 + 1e-7 and 0.0 <= float(off["primary"]) <= 1e-7


def test_the_crisp_control_points_of_the_example_grade_one_one_and_h(
    curve: t2spline.FuzzyCurve,
) -> None:
    # The example's curve is clamped: its ends are on the crisp curve.
    ends = curve.crisp[[0, -1]]
    g = curve.membership(ends)
    assert np.all(g["upper"] == 1.0) and np.all(g["primary"] == 1.0)
    np.testing.assert_allclose(g["lower"], curve.lower_height[[0, -1]].min(axis=1), atol=1e-12)


def test_space_curves_and_surfaces_take_points_of_three_coordinates() -> None:
    c = space_curve()
    g = c.membership(c.crisp[[0, -1]])
    assert np.all(g["upper"] == 1.0)
    with pytest.raises(ValueError, match=r"points: expected shape \(\.\.\., 3\).*got \(2, 2\)"):
        c.membership(np.zeros((2, 2)))


# Regions.


def test_shapely_opens_the_region_of_the_example(curve: t2spline.FuzzyCurve) -> None:
    r = curve.region(0.0)
    assert r is not None
    assert (r.membership, r.alpha, r.plane) == ("upper", 0.0, "xy")
    assert abs(r.area - 18.9186) < 2e-4
    g = shapely.geometry.shape(r)
    assert g.geom_type == "MultiPolygon" and g.is_valid
    assert abs(g.area - r.area) < 1e-9
    # The crisp curve lies in the region; a point far away does not.
    for p in curve.sample(50)["crisp"]:
        assert r.contains(p)
        assert g.covers(shapely.geometry.Point(p))
    assert not r.contains([100.0, 100.0])


def test_the_geo_interface_is_rfc_7946(curve: t2spline.FuzzyCurve) -> None:
    r = curve.region(0.3, "primary")
    assert r is not None
    geo = r.__geo_interface__
    assert geo["type"] == "MultiPolygon"
    assert len(geo["coordinates"]) == len(r.polygons) >= 1
    for rings, (exterior, holes) in zip(geo["coordinates"], r.polygons):
        assert len(rings) == 1 + len(holes)
        for k, (ring, open_ring) in enumerate(zip(rings, [exterior, *holes])):
            assert ring[0] == ring[-1], "closed"
            assert np.array_equal(np.array(ring[:-1]), open_ring)
            ccw = shapely.geometry.LinearRing(ring).is_ccw
            assert ccw == (k == 0), "exterior counter-clockwise, holes clockwise"


def test_regions_grow_as_alpha_falls_and_nest_by_function(curve: t2spline.FuzzyCurve) -> None:
    areas = {}
    for m in ("upper", "primary", "lower"):
        r = [curve.region(a, m) for a in (0.0, 0.3, 0.6)]
        assert all(x is not None for x in r), m
        assert r[0].area > r[1].area > r[2].area, m  # type: ignore[union-attr]
        areas[m] = r[1].area  # type: ignore[union-attr]
    assert areas["upper"] > areas["primary"] > areas["lower"]


def test_no_region_where_the_function_has_no_cut(curve: t2spline.FuzzyCurve) -> None:
    h = float(curve.lower_height.max())
    assert curve.region(min(1.0, h + 0.1), "lower") is None
    assert curve.region(1.0, "upper") is not None  # a band of the tolerance's width


def test_a_region_of_a_known_rectangle() -> None:
    line = segment()
    r = line.region(0.0, tolerance=1e-6)
    assert r is not None
    assert abs(r.area - 12.0) < 1e-4
    assert r.tolerance == 1e-6
    assert repr(r).startswith("Region(membership='upper', alpha=0.0, plane='xy', polygons=1,")
    (exterior, holes), = r.polygons
    assert exterior.shape[1] == 2 and holes == []
    np.testing.assert_allclose(exterior.min(axis=0), [-1.0, -1.0], atol=1e-5)
    np.testing.assert_allclose(exterior.max(axis=0), [5.0, 1.0], atol=1e-5)


def test_a_space_curve_projects_on_each_plane() -> None:
    c = space_curve()
    for plane, axes in (("xy", [0, 1]), ("xz", [0, 2]), ("yz", [1, 2])):
        r = c.region(0.0, plane=plane)
        assert r is not None and r.plane == plane
        g = shapely.geometry.shape(r)
        for p in c.sample(20)["crisp"][:, axes]:
            assert g.covers(shapely.geometry.Point(p)), plane


# Sections.


def test_sections_equal_the_cli(cli: Path, curve: t2spline.FuzzyCurve) -> None:
    got = curve.section(3.0, levels=5)
    want = cli_section(cli, EXAMPLE, "--x", "3", "--levels", "5")
    assert got == want
    assert curve.section(3.0) == cli_section(cli, EXAMPLE, "--x", "3", "--levels", "11")


def test_surface_sections_equal_the_cli(cli: Path) -> None:
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    lo, hi = terrain.bounding_box()
    x0, y0 = (float(v) for v in (lo[:2] + hi[:2]) / 2)
    got = terrain.section(x0, y0, levels=4)
    want = cli_section(cli, TERRAIN, "--at", f"{x0!r},{y0!r}", "--levels", "4")
    assert got == want
    assert got[0]["upper"], "the line meets the terrain's region"


def inside(inner: List[List[float]], outer: List[List[float]], slack: float) -> bool:
    return all(
        any(a[0] >= b[0] - slack and a[1] <= b[1] + slack for b in outer) for a in inner
    )


def test_sections_nest_across_levels_and_functions(curve: t2spline.FuzzyCurve) -> None:
    levels = curve.section(3.5, levels=11)
    assert [s["alpha"] for s in levels] == [k / 10 for k in range(11)]
    slack = 1e-5
    for s in levels:
        assert s["upper"] is not None and s["primary"] is not None
        assert inside(s["primary"], s["upper"], slack)
        if s["lower"] is not None:
            assert inside(s["lower"], s["primary"], slack)
    for below, above in zip(levels, levels[1:]):
        for m in ("upper", "primary", "lower"):
            if above[m] is not None:
                assert below[m] is not None and inside(above[m], below[m], slack), m
    # Above every height the lower function has no cut.
    assert levels[-1]["lower"] is None


def test_a_section_agrees_with_the_grades(curve: t2spline.FuzzyCurve) -> None:
    (s,) = curve.section(3.0, levels=[0.4])
    for lo, hi in s["upper"]:
        g = curve.membership([[3.0, lo], [3.0, hi], [3.0, (lo + hi) / 2]])
        np.testing.assert_allclose(g["upper"][:2], 0.4, atol=1e-4)
        assert g["upper"][2] >= 0.4 - 1e-9


# Membership maps.


def test_membership_grid_shapes_and_values() -> None:
    line = segment()
    g = line.membership_grid((-2.0, 6.0), (-2.0, 2.0), (80, 40))
    assert list(g) == ["xs", "ys", "upper", "primary", "lower"]
    assert g["xs"].shape == (80,) and g["ys"].shape == (40,)
    assert all(g[m].shape == (40, 80) for m in ("upper", "primary", "lower"))
    xx, yy = np.meshgrid(g["xs"], g["ys"])
    exact = line.membership(np.stack([xx, yy], axis=-1))
    for m in ("upper", "primary", "lower"):
        assert np.max(np.abs(g[m] - exact[m])) < 0.05, m
    square = line.membership_grid([-2, 6], [-2, 2], 16)
    assert square["upper"].shape == (16, 16)


# Errors.


def test_the_signatures_show_the_defaults(curve: t2spline.FuzzyCurve) -> None:
    import inspect

    region = inspect.signature(curve.region).parameters
    assert region["membership"].default == "upper" and region["plane"].default == "xy"
    assert region["plane"].kind is inspect.Parameter.KEYWORD_ONLY
    assert inspect.signature(curve.section).parameters["levels"].default == 11
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    assert inspect.signature(terrain.section).parameters["levels"].default == 11
    # None is the default too, as other methods of the package take it.
    assert curve.region(0.0, None, None, plane=None) is not None


def test_bad_points_are_named(curve: t2spline.FuzzyCurve) -> None:
    with pytest.raises(ValueError, match=r"points: expected shape \(\.\.\., 2\).*got \(4, 3\)"):
        curve.membership(np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"points: expected shape \(\.\.\., 2\).*got \(\)"):
        curve.membership(1.0)
    points = np.zeros((2, 3, 2))
    points[1, 2, 0] = np.nan
    with pytest.raises(ValueError, match=r"points\[1, 2, 0\] = NaN is not a finite number"):
        curve.membership(points)
    with pytest.raises(ValueError, match=r"points\[1, 1\] = inf"):
        t2spline.FuzzySurface.from_job(TERRAIN).membership([[0, 0, 0], [0, np.inf, 0]])
    with pytest.raises(TypeError, match="points"):
        curve.membership(["a", "b"])


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"alpha": 1.5}, ValueError, r"alpha: 1\.5 is outside \[0, 1\]"),
        ({"alpha": float("nan")}, ValueError, r"alpha: NaN is outside \[0, 1\]"),
        ({"alpha": "0.5"}, TypeError, r"alpha: expected a real number"),
        ({"alpha": 0.0, "membership": "uper"}, ValueError, r"membership: expected 'upper', 'primary' or 'lower', got \"uper\""),
        ({"alpha": 0.0, "membership": 1}, TypeError, r"membership: expected a str"),
        ({"alpha": 0.0, "tolerance": 0.0}, ValueError, r"tolerance: 0 must be a positive finite number"),
        ({"alpha": 0.0, "tolerance": -1.0}, ValueError, r"tolerance: -1 must be a positive"),
        ({"alpha": 0.0, "tolerance": float("inf")}, ValueError, r"tolerance: inf must be"),
        ({"alpha": 0.0, "tolerance": 1e-14}, ValueError, r"tolerance: tolerance = 1e-14 must be a positive number of at least"),
        ({"alpha": 0.0, "plane": "xz"}, ValueError, r"plane: a plane curve has only the plane 'xy', got \"xz\""),
        ({"alpha": 0.0, "plane": "zx"}, ValueError, r"plane: expected 'xy', 'xz' or 'yz', got \"zx\""),
    ],
)
def test_bad_region_arguments_are_named(
    curve: t2spline.FuzzyCurve, kwargs: Dict[str, Any], error: type, message: str
) -> None:
    with pytest.raises(error, match=message):
        curve.region(**kwargs)


def test_bad_section_and_grid_arguments_are_named(curve: t2spline.FuzzyCurve) -> None:
    with pytest.raises(ValueError, match=r"x0 = NaN is not a finite number"):
        curve.section(float("nan"))
    with pytest.raises(ValueError, match=r"levels: must be at least 2, got 1"):
        curve.section(3.0, levels=1)
    with pytest.raises(ValueError, match=r"levels: 1002 is more than the limit of 1001"):
        curve.section(3.0, levels=1002)
    with pytest.raises(ValueError, match=r"levels\[1\]: 2 is outside \[0, 1\]"):
        curve.section(3.0, levels=[0.5, 2.0])
    with pytest.raises(ValueError, match=r"tolerance: -1 must be a positive"):
        curve.section(3.0, tolerance=-1.0)
    with pytest.raises(ValueError, match=r"section: taken of plane curves"):
        space_curve().section(1.0)
    with pytest.raises(ValueError, match=r"membership_grid: taken of plane curves"):
        space_curve().membership_grid((0, 1), (0, 1), 4)
    with pytest.raises(ValueError, match=r"x_range: \(1, 0\) is not a range"):
        curve.membership_grid((1.0, 0.0), (0.0, 1.0), 4)
    with pytest.raises(ValueError, match=r"y_range\[1\] = inf is not a finite number"):
        curve.membership_grid((0.0, 1.0), (0.0, float("inf")), 4)
    with pytest.raises(ValueError, match=r"shape\[1\]: must be at least 1, got 0"):
        curve.membership_grid((0.0, 1.0), (0.0, 1.0), (4, 0))
    with pytest.raises(ValueError, match=r"shape: a grid of 5000 × 5000 cells is more than the limit"):
        curve.membership_grid((0.0, 1.0), (0.0, 1.0), 5000)
    terrain = t2spline.FuzzySurface.from_job(TERRAIN)
    with pytest.raises(ValueError, match=r"y0 = inf is not a finite number"):
        terrain.section(0.0, float("inf"))
