"""The envelope of a fuzzy surface from the command line (docs/method.md
§12): `t2spline envelope` on the shipped seabed, the GeoTIFF read by rasterio
(GDAL) and the long table by pyarrow. Checked: one float64 band per level,
membership function and bound, each described as GDAL shows it; the
geotransform of the grid, north-up; the CRS; NODATA as NaN outside the
seabed; and every raster value equal, bit for bit, to the table's row of its
cell (cells without a row are NODATA)."""

from __future__ import annotations

import json
import math
import re
import shlex
import subprocess
from pathlib import Path
from typing import Dict, List, Tuple

import numpy as np
import pytest

from conftest import ROOT

rasterio = pytest.importorskip("rasterio")
pq = pytest.importorskip("pyarrow.parquet")

SEABED = ROOT / "examples" / "salish-sea-seabed.json"
GRID = (40, 30)
LEVELS = 3


def run(cli: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def ok(cli: Path, *args: str) -> None:
    done = run(cli, *args)
    assert done.returncode == 0, (args, done.returncode, done.stderr)


def seabed_extent() -> Tuple[float, float, float, float]:
    """The control points' plan box, widened by a tenth on every side so
    that cells beyond the seabed are NODATA."""
    job = json.loads(SEABED.read_text())
    xs = [p["x"]["crisp"] for row in job["points"] for p in row]
    ys = [p["y"]["crisp"] for row in job["points"] for p in row]
    wx, wy = max(xs) - min(xs), max(ys) - min(ys)
    return (min(xs) - wx / 10, min(ys) - wy / 10, max(xs) + wx / 10, max(ys) + wy / 10)


@pytest.fixture(scope="module")
def outputs(cli: Path, tmp_path_factory: pytest.TempPathFactory) -> Dict[str, Path]:
    d = tmp_path_factory.mktemp("envelope")
    extent = ",".join(repr(v) for v in seabed_extent())
    common = ["envelope", SEABED, "--grid", f"{GRID[0]},{GRID[1]}", "--levels", str(LEVELS), "--extent", extent]
    out = {"tif": d / "seabed.tif", "parquet": d / "seabed.parquet", "geographic": d / "geographic.tif"}
    ok(cli, *common, "--crs", "EPSG:3857", "-o", out["tif"])
    ok(cli, *common, "-o", out["parquet"])
    ok(cli, *common, "--crs", "EPSG:4326", "-o", out["geographic"])
    return out


def descriptions() -> List[str]:
    out = []
    for k in range(LEVELS):
        alpha = k / (LEVELS - 1)
        text = f"{alpha:g}"
        # The lower function stops at the seabed's lower height, 0.5.
        for m in ["upper", "primary"] + (["lower"] if alpha <= 0.5 else []):
            out += [f"alpha={text} membership={m} bound={b}" for b in ("lower", "upper")]
    return out


def test_bands_geotransform_crs_and_nodata(outputs: Dict[str, Path]) -> None:
    x0, y0, x1, y1 = seabed_extent()
    with rasterio.open(outputs["tif"]) as ds:
        assert (ds.width, ds.height) == GRID
        assert list(ds.descriptions) == descriptions()
        assert set(ds.dtypes) == {"float64"}
        assert math.isnan(ds.nodata)
        assert ds.crs.to_epsg() == 3857 and ds.crs.is_projected
        t = ds.transform
        assert t.c == pytest.approx(x0, rel=1e-15) and t.f == pytest.approx(y1, rel=1e-15)
        assert t.a == pytest.approx((x1 - x0) / GRID[0], rel=1e-12)
        assert t.e == pytest.approx(-(y1 - y0) / GRID[1], rel=1e-12)
        assert t.b == 0 and t.d == 0
        band = ds.read(1)
        # The widened margin is NODATA, the middle is not.
        assert np.isnan(band[0, 0]) and not np.isnan(band[GRID[1] // 2, GRID[0] // 2])
    with rasterio.open(outputs["geographic"]) as ds:
        assert ds.crs.to_epsg() == 4326 and ds.crs.is_geographic


def test_the_raster_equals_the_table(outputs: Dict[str, Path]) -> None:
    table = pq.read_table(outputs["parquet"])
    assert table.column_names == ["x", "y", "alpha", "membership", "lower", "upper"]
    meta = {k.decode(): json.loads(v) for k, v in table.schema.metadata.items() if k.decode() in ("extent", "shape", "exact")}
    assert meta["shape"] == list(GRID) and meta["exact"] is True
    x0, y0, x1, y1 = meta["extent"]
    dx, dy = (x1 - x0) / GRID[0], (y1 - y0) / GRID[1]
    with rasterio.open(outputs["tif"]) as ds:
        bands = ds.read()
        index = {d: k for k, d in enumerate(ds.descriptions)}
    seen = np.zeros(bands.shape, dtype=bool)
    cols = table.to_pydict()
    for x, y, alpha, m, lo, hi in zip(cols["x"], cols["y"], cols["alpha"], cols["membership"], cols["lower"], cols["upper"]):
        col = int(round((x - x0) / dx - 0.5))
        row = GRID[1] - 1 - int(round((y - y0) / dy - 0.5))
        for bound, value in (("lower", lo), ("upper", hi)):
            k = index[f"alpha={alpha:g} membership={m} bound={bound}"]
            assert bands[k, row, col] == value, (x, y, alpha, m, bound)
            seen[k, row, col] = True
        assert lo <= hi
    # Every value without a row is NODATA, and some are.
    assert np.isnan(bands[~seen]).all() and (~seen).any()


def page_commands() -> List[List[str]]:
    """The commands of docs/terrain.md's shell block on the envelope."""
    text = (ROOT / "docs" / "terrain.md").read_text(encoding="utf-8")
    section = text.split("## Between which depths: the envelope", 1)[1]
    block = re.search(r"```sh\n(.*?)```", section, re.S)
    assert block, "docs/terrain.md has no shell block on the envelope"
    return [shlex.split(line) for line in block.group(1).splitlines() if line.strip()]


def test_the_commands_of_the_terrain_page(cli: Path, tmp_path: Path) -> None:
    outputs = {}
    for command in page_commands():
        assert command[:2] == ["t2spline", "envelope"], command
        args = command[1:]
        k = args.index("-o")
        outputs[Path(args[k + 1]).suffix] = out = tmp_path / args[k + 1]
        args[k + 1] = str(out)
        done = subprocess.run([str(cli), *args], cwd=ROOT, capture_output=True, text=True)
        assert done.returncode == 0, (command, done.stderr)
    with rasterio.open(outputs[".tif"]) as ds:
        # What the page says of the file.
        assert (ds.count, ds.crs.to_epsg(), ds.descriptions[0]) == (16, 3857, "alpha=0 membership=upper bound=lower")
        spread = ds.read(2) - ds.read(1)
        assert np.nanmin(spread) >= 0
    assert pq.read_table(outputs[".parquet"]).num_rows > 0
    rows = outputs[".csv"].read_text().splitlines()
    assert rows[0] == "x,y,alpha,membership,lower,upper" and len(rows) == 1 + 4 * 3 * 3
