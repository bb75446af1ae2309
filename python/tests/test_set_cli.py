"""The set view from the command line, as a user runs it: `t2spline
membership`, `region` and `section` on the shipped examples and on jobs
written here, the GeoJSON opened by shapely, and every kind of bad input
(exit 2, the place named, no output file).

The facts checked are those of the fuzzy curve as a set (docs/method.md §10):
`lower <= primary <= upper`; the crisp curve has upper = primary = 1 and
lower = h; regions shrink as alpha grows and always hold the crisp curve; an
interval end of a section is a point whose grade is the level."""

from __future__ import annotations

import copy
import csv
import io
import json
import math
import subprocess
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import pytest
from shapely.geometry import MultiPolygon, Point, shape
from shapely.geometry.polygon import orient

from conftest import ROOT, cli_run

EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"
TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"
H = 0.6  # lower_height of the example


def run(cli: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def ok(cli: Path, *args: str) -> str:
    done = run(cli, *args)
    assert done.returncode == 0, (args, done.returncode, done.stderr)
    return done.stdout


def fails(cli: Path, *args: str) -> str:
    """The standard error of a command that must exit with 2 (invalid input)."""
    done = run(cli, *args)
    assert done.returncode == 2, (args, done.returncode, done.stdout[:300], done.stderr)
    assert done.stdout == ""
    assert "panicked" not in done.stderr
    return done.stderr


def write_points(path: Path, points: Sequence[Sequence[float]]) -> Path:
    header = "x,y" if len(points[0]) == 2 else "x,y,z"
    path.write_text(header + "\n" + "".join(",".join(repr(float(c)) for c in p) + "\n" for p in points))
    return path


def grades(cli: Path, job: Path, points: Sequence[Sequence[float]], tmp: Path) -> List[Dict[str, float]]:
    """The rows of `t2spline membership` for `points`, as dicts of floats."""
    pts = write_points(tmp / "points.csv", points)
    text = ok(cli, "membership", job, pts)
    return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(io.StringIO(text))]


def crisp_points(cli: Path, job: Path, samples: int = 41) -> List[List[float]]:
    return [list(p) for p in cli_run(cli, job, "--samples", str(samples))["curves"]["crisp"]]


def region(cli: Path, job: Path, alpha: float, *args: str) -> Dict[str, Any]:
    collection: Dict[str, Any] = json.loads(ok(cli, "region", job, "--alpha", repr(alpha), *args))
    assert collection["type"] == "FeatureCollection"
    return collection


def features(collection: Dict[str, Any]) -> Dict[tuple, Dict[str, Any]]:
    """Features keyed by (membership, plane)."""
    out = {}
    for f in collection["features"]:
        assert f["type"] == "Feature"
        assert f["geometry"]["type"] == "MultiPolygon"
        key = (f["properties"]["membership"], f["properties"]["plane"])
        assert key not in out, key
        out[key] = f
    return out


def fuzzy(c: float, spread: float) -> Dict[str, Any]:
    """A fuzzy number around `c`: upper ±spread, primary ±2/3, lower ±1/3 of it."""
    return {
        "crisp": c,
        "upper": [c - spread, c + spread],
        "primary": [c - 2 * spread / 3, c + 2 * spread / 3],
        "lower": [c - spread / 3, c + spread / 3],
    }


def circle_job(tmp: Path, spread: float = 0.15) -> Path:
    """The rational quadratic circle of radius 1 through nine control points,
    each coordinate fuzzy by ±`spread`: its region is an annulus."""
    corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    w = math.sqrt(0.5)
    job = {
        "order": 3,
        "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
        "weights": [1, w, 1, w, 1, w, 1, w, 1],
        "lower_height": H,
        "alpha": 0.5,
        "points": [{"x": fuzzy(x, spread), "y": fuzzy(y, spread)} for x, y in corners],
    }
    path = tmp / "circle.json"
    path.write_text(json.dumps(job))
    return path


def space_job(tmp: Path) -> Path:
    """The example lifted into space: z numbers around 0, 1, 2, 1."""
    job = json.loads(EXAMPLE.read_text())
    for p, z in zip(job["points"], [0.0, 1.0, 2.0, 1.0]):
        p["z"] = fuzzy(z, 0.3)
    path = tmp / "space.json"
    path.write_text(json.dumps(job))
    return path


# ---------------------------------------------------------------- membership


def test_membership_rows_header_and_order(cli: Path, tmp_path: Path) -> None:
    points = [[3.0, 3.5], [100.0, -50.0], [1.0, 1.0], [2.5, 2.0], [-7.25, 0.5], [6.0, 1.0]]
    text = ok(cli, "membership", EXAMPLE, write_points(tmp_path / "p.csv", points))
    lines = text.splitlines()
    assert lines[0] == "x,y,upper,primary,lower"
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    assert len(rows) == len(points)
    for row, p in zip(rows, points):
        assert row[:2] == p  # the input point, in input order
        upper, primary, lower = row[2:]
        assert 0.0 <= lower <= primary <= upper <= 1.0
    # The end control points are on the crisp curve; the far ones are in no cut.
    assert rows[2][2:] == pytest.approx([1.0, 1.0, H], abs=1e-9)
    assert rows[5][2:] == pytest.approx([1.0, 1.0, H], abs=1e-9)
    assert rows[1][2:] == [0.0, 0.0, 0.0]
    assert rows[4][2:] == [0.0, 0.0, 0.0]


def test_the_crisp_curve_has_full_upper_and_primary_and_h_lower(cli: Path, tmp_path: Path) -> None:
    points = crisp_points(cli, EXAMPLE, 41)
    rows = grades(cli, EXAMPLE, points, tmp_path)
    assert len(rows) == 41
    for row in rows:
        assert row["upper"] == pytest.approx(1.0, abs=1e-9)
        assert row["primary"] == pytest.approx(1.0, abs=1e-9)
        assert row["lower"] == pytest.approx(H, abs=1e-9)


def test_grades_are_ordered_and_fall_off_away_from_the_curve(cli: Path, tmp_path: Path) -> None:
    # A grid over the example's box and beyond it.
    points = [[x / 4, y / 4] for x in range(-4, 33) for y in range(-4, 25)]
    rows = grades(cli, EXAMPLE, points, tmp_path)
    assert len(rows) == len(points)
    inside = 0
    for row, p in zip(rows, points):
        assert [row["x"], row["y"]] == p
        assert 0.0 <= row["lower"] <= row["primary"] <= row["upper"] <= 1.0, row
        if row["upper"] > 0:
            inside += 1
        # Outside the hull of every control point's upper support, grade 0.
        if p[0] < 0.4 or p[0] > 6.9 or p[1] < 0.2 or p[1] > 5.4:
            assert row["upper"] == 0.0, row
    assert 50 < inside < len(points) - 50  # the grid meets the set and its outside
    # The primary region is inside the upper one: some points are only in the latter.
    assert any(r["upper"] > 0 and r["primary"] == 0 for r in rows)


def test_membership_of_a_space_curve_and_a_surface(cli: Path, tmp_path: Path) -> None:
    space = space_job(tmp_path)
    points = crisp_points(cli, space, 9)
    assert len(points[0]) == 3
    text = ok(cli, "membership", space, write_points(tmp_path / "p3.csv", points + [[50.0, 50.0, 50.0]]))
    lines = text.splitlines()
    assert lines[0] == "x,y,z,upper,primary,lower"
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    for row in rows[:-1]:
        assert row[3:] == pytest.approx([1.0, 1.0, H], abs=1e-9)
    assert rows[-1][3:] == [0.0, 0.0, 0.0]


def crisp_axes_job(tmp: Path, axes: str) -> Path:
    """The example with the coordinates `axes` crisp (no spread)."""
    job = json.loads(EXAMPLE.read_text())
    for p in job["points"]:
        for a in axes:
            c = p[a]["crisp"]
            p[a] = {"crisp": c, "upper": [c, c], "primary": [c, c], "lower": [c, c]}
    path = tmp / f"crisp-{axes}.json"
    path.write_text(json.dumps(job))
    return path


@pytest.mark.parametrize("axes", ["x", "xy"])
def test_crisp_coordinates_grade_the_crisp_curve(cli: Path, tmp_path: Path, axes: str) -> None:
    """Crisp stations (x) or crisp numbers: the grade is positive only where
    the curve passes exactly through the point's crisp coordinates, and the
    crisp curve's sampled points are still graded 1, 1 and h."""
    job = crisp_axes_job(tmp_path, axes)
    rows = grades(cli, job, crisp_points(cli, job, 23), tmp_path)
    for row in rows:
        assert (row["upper"], row["primary"], row["lower"]) == pytest.approx((1.0, 1.0, H), abs=1e-9), row
    if axes == "x":
        levels = section(cli, job, "--x", "3.5", "--levels", "11")["levels"]
        ends = [
            (lv["alpha"], name, y)
            for lv in levels
            for name in ("upper", "primary", "lower")
            for interval in lv[name] or []
            for y in interval
        ]
        rows = grades(cli, job, [[3.5, y] for _, _, y in ends], tmp_path)
        for (alpha, name, y), row in zip(ends, rows):
            assert row[name] == pytest.approx(alpha, abs=1e-4), (alpha, name, y)


# ---------------------------------------------------------------- region


def check_geometry(feature: Dict[str, Any]) -> MultiPolygon:
    """The feature's MultiPolygon, valid, wound as RFC 7946 asks, with the
    area its properties state."""
    geom = shape(feature["geometry"])
    assert isinstance(geom, MultiPolygon)
    assert geom.is_valid, feature["properties"]
    for polygon in geom.geoms:
        assert polygon.exterior.is_ccw, "an exterior ring must be counterclockwise"
        for hole in polygon.interiors:
            assert not hole.is_ccw, "a hole must be clockwise"
        assert orient(polygon, 1.0).equals_exact(polygon, 0.0)
        ring = feature["geometry"]["coordinates"][0][0]
        assert ring[0] == ring[-1]  # closed rings
    props = feature["properties"]
    assert props["area"] == pytest.approx(geom.area, rel=1e-9, abs=1e-12)
    assert props["tolerance"] > 0
    return geom


def test_the_example_region_at_zero(cli: Path) -> None:
    collection = region(cli, EXAMPLE, 0.0)
    found = features(collection)
    assert sorted(found) == [("lower", "xy"), ("primary", "xy"), ("upper", "xy")]
    geoms = {}
    for (m, _), f in found.items():
        assert f["properties"]["alpha"] == 0.0
        geoms[m] = check_geometry(f)
    assert found[("upper", "xy")]["properties"]["area"] == pytest.approx(18.9186, abs=1e-3)
    tol = found[("upper", "xy")]["properties"]["tolerance"]
    # The lower region lies inside the primary, which lies inside the upper.
    assert geoms["lower"].within(geoms["primary"].buffer(2 * tol))
    assert geoms["primary"].within(geoms["upper"].buffer(2 * tol))
    assert geoms["lower"].area < geoms["primary"].area < geoms["upper"].area
    # The whole first control point's box at alpha 0 is in the upper region:
    # the curve passes through P0, anywhere in its support.
    for corner in [(0.4, 0.2), (1.9, 0.2), (1.9, 1.5), (0.4, 1.5)]:
        assert geoms["upper"].buffer(2 * tol).contains(Point(corner))


def test_regions_are_nested_and_hold_the_crisp_curve(cli: Path) -> None:
    crisp = [Point(p) for p in crisp_points(cli, EXAMPLE, 61)]
    previous: Dict[str, Any] = {}
    for alpha in [0.0, 0.25, 0.5, 0.6, 0.75, 0.9, 1.0]:
        found = features(region(cli, EXAMPLE, alpha))
        names = {m for m, _ in found}
        assert names == ({"upper", "primary", "lower"} if alpha <= H else {"upper", "primary"})
        for (m, _), f in found.items():
            geom = check_geometry(f)
            tol = f["properties"]["tolerance"]
            for p in crisp:
                assert geom.distance(p) <= 2 * tol, (m, alpha, p)
            if m in previous:
                assert geom.within(previous[m].buffer(2 * tol)), (m, alpha)
                assert geom.area <= previous[m].area + 1e-9
            previous[m] = geom


def test_region_at_half_is_within_region_at_zero(cli: Path) -> None:
    zero = features(region(cli, EXAMPLE, 0.0))
    half = features(region(cli, EXAMPLE, 0.5))
    for key, f in half.items():
        tol = zero[key]["properties"]["tolerance"]
        assert shape(f["geometry"]).within(shape(zero[key]["geometry"]).buffer(tol)), key


def test_above_h_there_is_no_lower_feature(cli: Path) -> None:
    found = features(region(cli, EXAMPLE, 0.7))
    assert sorted(found) == [("primary", "xy"), ("upper", "xy")]


def test_the_tolerance_is_the_one_asked_for_and_bounds_the_outline(cli: Path) -> None:
    fine = features(region(cli, EXAMPLE, 0.3, "--tolerance", "1e-4"))
    coarse = features(region(cli, EXAMPLE, 0.3, "--tolerance", "0.02"))
    for key in fine:
        assert fine[key]["properties"]["tolerance"] == 1e-4
        assert coarse[key]["properties"]["tolerance"] == 0.02
        a, b = check_geometry(fine[key]), check_geometry(coarse[key])
        # Both outlines are within their tolerances of the true region, so of each other.
        assert a.hausdorff_distance(b) <= 0.02 + 1e-4 + 1e-9, key


def test_a_closed_curve_has_a_region_with_a_hole(cli: Path, tmp_path: Path) -> None:
    job = circle_job(tmp_path)
    found = features(region(cli, job, 0.0))
    upper = check_geometry(found[("upper", "xy")])
    assert len(upper.geoms) == 1
    ring = upper.geoms[0]
    assert len(ring.interiors) == 1
    # The unit circle is inside the annulus and the centre is in the hole.
    assert not upper.contains(Point(0.0, 0.0))
    for k in range(16):
        t = 2 * math.pi * k / 16
        assert upper.contains(Point(math.cos(t), math.sin(t)))
    # The crisp curve's grades say the same.
    rows = grades(cli, job, [[0.0, 0.0], [math.sqrt(0.5), math.sqrt(0.5)]], tmp_path)
    assert rows[0]["upper"] == 0.0
    assert rows[1]["upper"] == pytest.approx(1.0, abs=1e-9)


def test_a_space_curve_has_three_planes_per_function(cli: Path, tmp_path: Path) -> None:
    job = space_job(tmp_path)
    found = features(region(cli, job, 0.2))
    assert sorted(found) == sorted((m, p) for m in ("upper", "primary", "lower") for p in ("xy", "xz", "yz"))
    crisp = crisp_points(cli, job, 21)
    axes = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
    for (m, plane), f in found.items():
        geom = check_geometry(f)
        i, j = axes[plane]
        for p in crisp:
            assert geom.distance(Point(p[i], p[j])) <= 2 * f["properties"]["tolerance"], (m, plane)
    # The xy projection is the plane example's region (z does not matter to it).
    plane = features(region(cli, EXAMPLE, 0.2))
    assert found[("upper", "xy")]["properties"]["area"] == pytest.approx(
        plane[("upper", "xy")]["properties"]["area"], rel=1e-6
    )


def test_region_writes_a_file(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "upper.geojson"
    assert ok(cli, "region", EXAMPLE, "--alpha", "0", "-o", out) == ""
    assert json.loads(out.read_text()) == region(cli, EXAMPLE, 0.0)


# ---------------------------------------------------------------- section


def section(cli: Path, job: Path, *args: str) -> Dict[str, Any]:
    result: Dict[str, Any] = json.loads(ok(cli, "section", job, *args))
    return result


def within(inner: List[List[float]], outer: List[List[float]], slack: float) -> bool:
    return all(any(o[0] - slack <= a and b <= o[1] + slack for o in outer) for a, b in inner)


def test_section_levels_and_nesting(cli: Path) -> None:
    result = section(cli, EXAMPLE, "--x", "3.5", "--levels", "11")
    assert result["x"] == 3.5
    levels = result["levels"]
    assert [lv["alpha"] for lv in levels] == pytest.approx([k / 10 for k in range(11)], abs=1e-15)
    assert [lv["alpha"] for lv in section(cli, EXAMPLE, "--x", "3.5", "--levels", "5")["levels"]] == [
        0.0, 0.25, 0.5, 0.75, 1.0,
    ]
    for name in ("upper", "primary", "lower"):
        prev: Optional[List[List[float]]] = None
        for lv in levels:
            intervals = lv[name]
            if name == "lower" and lv["alpha"] > H:
                assert intervals is None, lv
                continue
            assert intervals, (name, lv["alpha"])  # the crisp curve crosses x = 3.5
            for a, b in intervals:
                assert a <= b
            if prev is not None:
                assert within(intervals, prev, 1e-6), (name, lv["alpha"])
            prev = intervals
    # upper ⊇ primary ⊇ lower at each level.
    for lv in levels:
        assert within(lv["primary"], lv["upper"], 1e-6)
        if lv["lower"] is not None:
            assert within(lv["lower"], lv["primary"], 1e-6)


def test_section_ends_have_the_level_as_grade(cli: Path, tmp_path: Path) -> None:
    x0 = 3.5
    levels = section(cli, EXAMPLE, "--x", repr(x0), "--levels", "11")["levels"]
    ends = []
    for lv in levels:
        for name in ("upper", "primary", "lower"):
            for interval in lv[name] or []:
                for y in interval:
                    ends.append((lv["alpha"], name, y))
    rows = grades(cli, EXAMPLE, [[x0, y] for _, _, y in ends], tmp_path)
    for (alpha, name, y), row in zip(ends, rows):
        assert row["y"] == y
        assert row[name] == pytest.approx(alpha, abs=1e-4), (alpha, name, y)


def test_section_at_one_is_the_crisp_curve(cli: Path) -> None:
    # At x = 6 the crisp curve ends at (6, 1) (its last control point).
    levels = section(cli, EXAMPLE, "--x", "6", "--levels", "11")["levels"]
    top = levels[-1]
    assert top["alpha"] == 1.0
    for name in ("upper", "primary"):
        ((a, b),) = top[name]
        assert a == pytest.approx(1.0, abs=1e-5) and b == pytest.approx(1.0, abs=1e-5)
    lower_at_h = [lv for lv in levels if lv["alpha"] == pytest.approx(H)][0]["lower"]
    ((a, b),) = lower_at_h
    assert a == pytest.approx(1.0, abs=1e-5) and b == pytest.approx(1.0, abs=1e-5)


def test_a_closed_curve_crosses_a_station_twice(cli: Path, tmp_path: Path) -> None:
    levels = section(cli, circle_job(tmp_path), "--x", "0", "--levels", "5")["levels"]
    for lv in levels:
        for name in ("upper", "primary", "lower"):
            if lv[name] is None:
                continue
            (a, b), (c, d) = lv[name]  # below and above the centre
            assert a <= b < 0 < c <= d, (name, lv)
            assert a == pytest.approx(-d) and b == pytest.approx(-c)
    ((a, b), (c, d)) = levels[-1]["upper"]
    assert (a, b, c, d) == pytest.approx((-1, -1, 1, 1), abs=1e-6)


def test_terrain_section_holds_the_crisp_height(cli: Path) -> None:
    result = section(cli, TERRAIN, "--at", "250,200", "--levels", "11")
    assert (result["x"], result["y"]) == (250.0, 200.0)
    levels = result["levels"]
    assert len(levels) == 11
    # The net is symmetric in x about 250 and in y about 200, with symmetric
    # clamped uniform knots, so (250, 200) is the crisp surface at (0.5, 0.5).
    run_result = cli_run(cli, TERRAIN, "--samples", "3,3")
    surfaces = run_result["surfaces"]
    centre = surfaces["crisp"][1][1]  # rows of u, v changing along a row
    assert centre[:2] == pytest.approx([250.0, 200.0], abs=1e-9)
    z = centre[2]
    for lv in levels:
        for name in ("upper", "primary", "lower"):
            intervals = lv[name]
            if name == "lower" and lv["alpha"] > H:
                assert intervals is None
                continue
            assert len(intervals) == 1, (name, lv)
            a, b = intervals[0]
            assert a - 1e-6 <= z <= b + 1e-6, (name, lv["alpha"], z, a, b)
    ((a, b),) = levels[-1]["upper"]
    assert a == pytest.approx(z, abs=1e-6) and b == pytest.approx(z, abs=1e-6)


def test_the_terrain_grades_its_crisp_surface_and_its_section_ends(cli: Path, tmp_path: Path) -> None:
    """The terrain's positions are crisp: a point is graded where the surface
    passes through its (x, y), the crisp surface's points 1, 1 and h."""
    grid = cli_run(cli, TERRAIN, "--samples", "5,4")["surfaces"]["crisp"]
    crisp = [p for row in grid for p in row]
    rows = grades(cli, TERRAIN, crisp, tmp_path)
    for row in rows:
        assert (row["upper"], row["primary"], row["lower"]) == pytest.approx((1.0, 1.0, H), abs=1e-9), row
    levels = section(cli, TERRAIN, "--at", "250,200", "--levels", "11")["levels"]
    ends = [
        (lv["alpha"], name, z)
        for lv in levels
        for name in ("upper", "primary", "lower")
        for interval in lv[name] or []
        for z in interval
    ]
    rows = grades(cli, TERRAIN, [[250.0, 200.0, z] for _, _, z in ends], tmp_path)
    for (alpha, name, z), row in zip(ends, rows):
        assert row[name] == pytest.approx(alpha, abs=1e-4), (alpha, name, z)
    far = grades(cli, TERRAIN, [[250.0, 200.0, 120.0], [600.0, 200.0, 111.0]], tmp_path)
    assert [r["upper"] for r in far] == [0.0, 0.0]


# ---------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "text, where, words",
    [
        ("x,y\n1,2\n3,two\n", "3:3", "`two` is not a number"),
        ("x,y\n1,2\n4\n", "3:2", "y (column 2) is missing"),
        ("x,z\n1,2\n", "1:1", "the header must be x,y or x,y,z"),
        ("x,y\n1,nan\n", "2:3", "`nan` is not a number"),
        ("x,y\n1,inf\n", "2:3", "`inf` is not a number"),
        ("x,y\n1,2,3\n", "2:5", "column 3 is one too many"),
        ("x,y\n1,1e200\n", "2:3", "outside [-1e150, 1e150]"),
    ],
    ids=["word", "missing", "header", "nan", "inf", "extra", "huge"],
)
def test_a_bad_points_file_names_its_place(cli: Path, tmp_path: Path, text: str, where: str, words: str) -> None:
    points = tmp_path / "bad.csv"
    points.write_text(text)
    out = tmp_path / "out.csv"
    err = fails(cli, "membership", EXAMPLE, points, "-o", out)
    assert f"{points}:{where}: " in err, err
    assert words in err, err
    assert not out.exists()


def test_a_points_file_of_the_wrong_dimension(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "out.csv"
    err = fails(cli, "membership", EXAMPLE, write_points(tmp_path / "p3.csv", [[1.0, 2.0, 3.0]]), "-o", out)
    assert "x,y" in err and "plane curve" in err, err
    assert not out.exists()
    err = fails(cli, "membership", TERRAIN, write_points(tmp_path / "p2.csv", [[1.0, 2.0]]), "-o", out)
    assert "x,y,z" in err and "surface" in err, err
    assert not out.exists()


@pytest.mark.parametrize(
    "args, words",
    [
        (["region", EXAMPLE, "--alpha", "1.5"], "--alpha"),
        (["region", EXAMPLE, "--alpha", "-0.1"], "--alpha"),
        (["region", EXAMPLE, "--alpha", "nan"], "--alpha"),
        (["region", EXAMPLE, "--alpha", "0.5", "--tolerance", "0"], "--tolerance"),
        (["region", EXAMPLE, "--alpha", "0.5", "--tolerance", "-1"], "--tolerance"),
        (["region", EXAMPLE, "--alpha", "0.5", "--tolerance", "nan"], "--tolerance"),
        (["region", EXAMPLE, "--alpha", "0.5", "--tolerance", "inf"], "--tolerance"),
        (["region", TERRAIN, "--alpha", "0.5"], "surface"),
        (["section", EXAMPLE, "--x", "3", "--levels", "1"], "--levels"),
        (["section", EXAMPLE, "--x", "3", "--levels", "0"], "--levels"),
        (["section", EXAMPLE, "--x", "3", "--tolerance", "0"], "--tolerance"),
        (["section", EXAMPLE, "--x", "3", "--tolerance", "nan"], "--tolerance"),
        (["section", EXAMPLE, "--x", "nan"], "--x: NaN is not a finite number"),
        (["section", EXAMPLE, "--x", "inf"], "--x: inf is not a finite number"),
        (["section", TERRAIN, "--x", "3"], "--at"),
        (["section", EXAMPLE, "--at", "3,2"], "--x"),
        (["section", TERRAIN, "--at", "3"], "--at"),
        (["section", TERRAIN, "--at", "3,nan"], "--at"),
        (["section", EXAMPLE], "--x"),
    ],
    ids=lambda v: " ".join(map(str, v)) if isinstance(v, list) else v,
)
def test_bad_options_exit_2_and_write_nothing(cli: Path, tmp_path: Path, args: List[Any], words: str) -> None:
    out = tmp_path / "out.json"
    err = fails(cli, *args, "-o", out)
    assert words in err, err
    assert err.startswith("t2spline: "), err
    assert len(err.splitlines()) <= 3, err
    assert not out.exists()


@pytest.mark.parametrize("command", ["membership", "region", "section"])
def test_the_output_may_not_be_the_job(cli: Path, tmp_path: Path, command: str) -> None:
    job = tmp_path / "job.json"
    job.write_text(EXAMPLE.read_text())
    points = write_points(tmp_path / "p.csv", [[1.0, 1.0]])
    extra = {"membership": [points], "region": ["--alpha", "0.5"], "section": ["--x", "3"]}[command]
    err = fails(cli, command, job, *extra, "-o", job)
    assert "job.json" in err, err
    assert job.read_text() == EXAMPLE.read_text()
    if command == "membership":
        err = fails(cli, command, job, points, "-o", points)
        assert "p.csv" in err, err
        assert points.read_text() == "x,y\n1.0,1.0\n"


def test_a_bad_job_is_reported_with_its_place(cli: Path, tmp_path: Path) -> None:
    job = json.loads(EXAMPLE.read_text())
    bad = copy.deepcopy(job)
    bad["points"][1]["x"]["upper"] = [2.5, 2.8]  # upper.left above crisp
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad, indent=1))
    out = tmp_path / "out.geojson"
    err = fails(cli, "region", path, "--alpha", "0.5", "-o", out)
    assert f"{path}:" in err and "points[1].x" in err, err
    assert not out.exists()


# ---------------------------------------------------------------- the pages

SET_PAGE = ROOT / "docs" / "set.md"
README = ROOT / "README.md"


def transcripts(page: Path) -> List[tuple]:
    """The `$ t2spline membership|region|section|envelope …` commands of the page's
    text blocks with the output shown under each (up to the next `$` line or
    the end of the block)."""
    found = []
    block: Optional[List[str]] = None
    for line in page.read_text().splitlines():
        if block is None:
            if line.startswith("```text"):
                block = []
            continue
        if line.startswith("```"):
            found.extend(split_block(block))
            block = None
        else:
            block.append(line)
    return found


def split_block(lines: List[str]) -> List[tuple]:
    out: List[tuple] = []
    for line in lines:
        if line.startswith("$ "):
            out.append((line[2:], []))
        elif out:
            out[-1][1].append(line)
    return [(cmd, shown) for cmd, shown in out if cmd.split()[1] in ("membership", "region", "section", "envelope")]


def matches(shown: List[str], got: str) -> bool:
    """`shown` is `got` with `…` standing for any text (an abridged output)."""
    import re

    pattern = ".*?".join(re.escape(part) for part in "\n".join(shown).split("…"))
    return re.fullmatch(pattern, got.rstrip("\n"), flags=re.DOTALL) is not None


@pytest.mark.parametrize("page, least", [(SET_PAGE, 7), (README, 2)], ids=["docs/set.md", "README.md"])
def test_the_transcripts_of_the_pages(cli: Path, page: Path, least: int) -> None:
    import shlex

    found = transcripts(page)
    assert len(found) >= least, found
    for command, shown in found:
        argv = shlex.split(command)
        assert argv[0] == "t2spline"
        done = subprocess.run([str(cli), *argv[1:]], cwd=ROOT, capture_output=True, text=True)
        got = done.stdout if done.returncode == 0 else done.stderr
        if done.returncode != 0:
            assert done.returncode == 2 and done.stdout == "", command
        assert matches(shown, got), f"{page.name}: `{command}` printed\n{got[:2000]}"


def test_the_numbers_of_the_set_page(cli: Path) -> None:
    page = SET_PAGE.read_text()
    readme = README.read_text()
    areas = {}
    for alpha in ["0", "0.5", "0.8", "1"]:
        found = features(region(cli, EXAMPLE, float(alpha)))
        areas[alpha] = {m: f["properties"]["area"] for (m, _), f in found.items()}
    for alpha in ["0", "0.5", "0.8"]:
        cells = [f"{areas[alpha][m]:.4f}" if m in areas[alpha] else "—" for m in ("upper", "primary", "lower")]
        assert f"| {alpha} | {' | '.join(cells)} |" in page, (alpha, cells)
    assert set(areas["1"]) == {"upper", "primary"}
    assert all(a < 5e-5 for a in areas["1"].values())
    zero = areas["0"]
    for text in (page, readme):
        assert f"area of {zero['upper']:.2f}" in text
    assert f"(primary {zero['primary']:.2f}, lower\n{zero['lower']:.2f})" in readme
    # The band between the upper layer curves, as the page computes it.
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    layers = cli_run(cli, EXAMPLE, "--samples", "2001")["curves"]["layers"]
    a, b = layers["upper_left"], layers["upper_right"]
    band = unary_union([Polygon([a[k], a[k + 1], b[k + 1], b[k]]).buffer(0) for k in range(len(a) - 1)])
    assert f"covers {band.area:.2f} of it" in page
    assert f"the {band.area:.2f} of the band" in readme
    # The tolerance paragraph.
    upper_fine = features(region(cli, EXAMPLE, 0.0))[("upper", "xy")]
    upper_coarse = features(region(cli, EXAMPLE, 0.0, "--tolerance", "0.01"))[("upper", "xy")]

    def vertices(f: Dict[str, Any]) -> int:
        return sum(len(ring) for polygon in f["geometry"]["coordinates"] for ring in polygon)

    assert round(upper_fine["properties"]["tolerance"], 7) == 6.1e-6
    assert "(6.1e-6 on the example)" in page
    assert f"region at alpha 0 has {vertices(upper_coarse)} vertices" in page
    assert f"area of {upper_coarse['properties']['area']:.4f} instead of {vertices(upper_fine):,}".replace(",", " ") in page.replace("\n", " ")


def test_the_terrain_grades_of_the_set_page(cli: Path, tmp_path: Path) -> None:
    page = " ".join(SET_PAGE.read_text().split())
    on, near = grades(cli, TERRAIN, [[250.0, 200.0, 111.745625], [250.0, 200.0, 111.26]], tmp_path)
    assert (on["upper"], on["primary"], on["lower"]) == pytest.approx((1.0, 1.0, H), abs=1e-9)
    assert "`(250, 200, 111.745625)`, on the crisp surface, has grades 1, 1 and 0.6" in page
    assert f"`(250, 200, 111.26)`, just inside the upper interval of the section below, {near['upper']:.3f}" in page


def test_the_mixed_heights_example_of_the_set_page_is_what_the_program_prints(cli: Path) -> None:
    """docs/set.md's block on mixed lower heights, run as written: every
    line it prints is the program's."""
    page = (ROOT / "docs" / "set.md").read_text()
    block = page.split("<!-- mixed-heights: run by python/tests/test_set_cli.py -->\n```text\n", 1)[1]
    block = block.split("\n```", 1)[0]
    commands: list[tuple[str, list[str]]] = []
    for line in block.splitlines():
        if line.startswith("$ "):
            commands.append((line[2:], []))
        else:
            commands[-1][1].append(line)
    assert len(commands) == 2
    for command, printed in commands:
        shell = command.replace("t2spline ", f"{cli} ")
        out = subprocess.run(["bash", "-c", shell], cwd=ROOT, capture_output=True, text=True, check=True)
        assert out.stdout.splitlines() == printed, command
