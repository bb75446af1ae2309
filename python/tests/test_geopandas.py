"""The GeoJSON of `t2spline contour` and `t2spline region` opened by GeoPandas
(pyogrio, GDAL's reader), as docs/terrain.md and docs/set.md say: one row per
Feature with the properties as columns, every geometry valid, its area the
file's `area`; the terrain page's snippet runs as written."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import geopandas

from conftest import ROOT

SEABED = ROOT / "examples" / "salish-sea-seabed.json"
CURVE = ROOT / "examples" / "paper-alg-1-1.json"


def run(cli: Path, *args: object) -> None:
    done = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, (args, done.stderr)


def snippet(page: str, marker: str) -> str:
    """The ```python block of `page` that contains `marker`."""
    text = (ROOT / "docs" / page).read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    found = [b for b in blocks if marker in b]
    assert len(found) == 1, (page, marker, len(found))
    return found[0]


def test_the_shoreline_opens_in_geopandas_as_the_terrain_page_says(
    cli: Path, tmp_path: Path
) -> None:
    out = tmp_path / "shoreline.geojson"
    run(cli, "contour", SEABED, "--z", "0", "--alpha", "0.5", "-o", out)
    features = json.loads(out.read_text())["features"]

    # The job's coordinates are EPSG:3857 (GeoJSON without a CRS is read as
    # EPSG:4326, whose areas GeoPandas would not compute in the plane).
    bands = geopandas.read_file(out).set_crs("EPSG:3857", allow_override=True)
    assert len(bands) == len(features)
    assert {"membership", "alpha", "area"} <= set(bands.columns)
    polygons = bands[bands.geometry.geom_type == "MultiPolygon"]
    assert list(polygons["membership"]) == ["upper", "primary", "lower"]
    assert (polygons["alpha"] == 0.5).all()
    assert polygons.geometry.is_valid.all()
    for area, given in zip(polygons.geometry.area, polygons["area"]):
        assert abs(area - given) <= 1e-6 * given
    # The crisp contour: one MultiLineString row.
    assert list(bands.geometry.geom_type).count("MultiLineString") == 1

    # The page's snippet, run where the file is: the CRS it sets and the
    # columns it prints.
    code = snippet("terrain.md", 'geopandas.read_file("shoreline.geojson")')
    code += "\nprint(bands.crs.to_epsg())\n"
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.strip().splitlines()
    assert lines[-1] == "3857"
    assert lines[0].split() == ["membership", "alpha", "area"]
    assert [line.split()[1] for line in lines[1:4]] == ["upper", "primary", "lower"]


def test_a_region_opens_in_geopandas_one_row_per_feature(cli: Path, tmp_path: Path) -> None:
    out = tmp_path / "region.geojson"
    run(cli, "region", CURVE, "-o", out)
    features = json.loads(out.read_text())["features"]
    rows = geopandas.read_file(out)
    assert len(rows) == len(features)
    for (_, row), feature in zip(rows.iterrows(), features):
        for key, value in feature["properties"].items():
            if isinstance(value, (int, float, str)):
                assert row[key] == value, key
        if feature["geometry"] is not None:
            assert row.geometry.is_valid
