"""The fuzzy contour of a fuzzy surface from the command line (docs/method.md
§13): `t2spline contour` on the shipped seabed at z = 0 (the fuzzy
shoreline), the GeoJSON opened by shapely. Checked: one Feature per level and
membership function and one for the crisp contour; every geometry valid,
every ring closed and wound as RFC 7946 says (exteriors counter-clockwise,
holes clockwise); the bands nested (lower ⊆ primary ⊆ upper, a higher
level's inside a lower one's); the crisp contour inside the upper band; and
bad options refused without writing a file."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any, Dict, List

import pytest

from conftest import ROOT

shapely = pytest.importorskip("shapely")
from shapely.geometry import shape  # noqa: E402

SEABED = ROOT / "examples" / "salish-sea-seabed.json"


def run(cli: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def contour(cli: Path, tmp_path: Path, *args: str) -> Dict[str, Any]:
    out = tmp_path / "shore.geojson"
    done = run(cli, "contour", SEABED, "--z", "0", *args, "-o", out)
    assert done.returncode == 0, (args, done.stderr)
    data: Dict[str, Any] = json.loads(out.read_text())
    return data


def bands(data: Dict[str, Any]) -> List[Dict[str, Any]]:
    return [f for f in data["features"] if not f["properties"].get("crisp")]


def test_shoreline_is_valid_geojson_wound_as_rfc_7946_says(cli: Path, tmp_path: Path) -> None:
    data = contour(cli, tmp_path)
    assert data["type"] == "FeatureCollection"
    fs = bands(data)
    assert [f["properties"]["membership"] for f in fs] == ["upper", "primary", "lower"]
    assert all(f["properties"]["alpha"] == 0.5 and f["properties"]["z"] == 0.0 for f in fs)
    for f in fs:
        assert f["geometry"]["type"] == "MultiPolygon"
        g = shape(f["geometry"])
        assert g.is_valid, shapely.is_valid_reason(g)
        assert not g.is_empty
        for poly in f["geometry"]["coordinates"]:
            for k, ring in enumerate(poly):
                assert ring[0] == ring[-1], "ring not closed"
                ccw = shapely.is_ccw(shapely.LinearRing(ring))
                assert ccw == (k == 0), ("exterior" if k == 0 else "hole") + " wound the wrong way"
        assert abs(g.area - f["properties"]["area"]) <= 1e-6 * g.area
    crisp = [f for f in data["features"] if f["properties"].get("crisp")]
    assert len(crisp) == 1 and crisp[0]["geometry"]["type"] == "MultiLineString"
    line = shape(crisp[0]["geometry"])
    assert not line.is_empty
    upper = shape(fs[0]["geometry"])
    tolerance = fs[0]["properties"]["tolerance"]
    # The crisp contour lies in the upper band (points on its outline to
    # rounding; i_overlay snaps vertices to its integer grid).
    assert upper.buffer(1e-6 * tolerance).covers(line)


def test_bands_nest_across_functions_and_levels(cli: Path, tmp_path: Path) -> None:
    data = contour(cli, tmp_path, "--levels", "3", "--grid", "60,80")
    fs = bands(data)
    by = {(f["properties"]["alpha"], f["properties"]["membership"]): shape(f["geometry"]) for f in fs}
    assert {a for a, _ in by} == {0.0, 0.5, 1.0}
    slack = 1e-6 * fs[0]["properties"]["tolerance"]
    for (a, m), g in by.items():
        assert g.is_valid
        if m != "upper":
            outer = by[(a, "upper" if m == "primary" else "primary")]
            assert outer.buffer(slack).covers(g), (a, m)
        for (b, n), h in by.items():
            if n == m and b < a:
                assert h.buffer(slack).covers(g), (a, b, m)


def test_bad_options_name_the_option_and_write_nothing(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "shore.geojson"
    for args, option in [
        (["--z", "nan"], "--z"),
        (["--z", "0", "--alpha", "1.5"], "--alpha"),
        (["--z", "0", "--grid", "0,3"], "--grid"),
        (["--z", "0", "--extent", "1,0,0,1"], "--extent"),
    ]:
        done = run(cli, "contour", SEABED, *args, "-o", out)
        assert done.returncode == 2, (args, done.stderr)
        assert done.stderr.startswith(f"t2spline: {option}"), done.stderr
        assert not out.exists()
    curve = ROOT / "examples" / "paper-alg-1-1.json"
    done = run(cli, "contour", curve, "--z", "0", "-o", out)
    assert done.returncode == 2 and "curve" in done.stderr
    assert not out.exists()
