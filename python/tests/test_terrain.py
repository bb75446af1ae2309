"""The walk of docs/terrain.md from matplotlib's real topography and
bathymetry grid (`topobathy.npz`) to a fuzzy seabed: its commands run as the
page gives them, the raster script prints the options the page passes, and
the fitted job is the shipped `examples/salish-sea-seabed.json` byte for
byte."""

from __future__ import annotations

import json
import re
import shlex
import subprocess
import sys
from pathlib import Path
from typing import List

import pytest

from conftest import ROOT

pytest.importorskip("matplotlib")

PAGE = ROOT / "docs" / "terrain.md"
EXAMPLE = ROOT / "examples" / "salish-sea-seabed.json"


def walk() -> List[List[str]]:
    """The commands of the page's `## The walk` shell block."""
    text = PAGE.read_text(encoding="utf-8")
    section = text.split("## The walk", 1)[1]
    block = re.search(r"```sh\n(.*?)```", section, re.S)
    assert block, "docs/terrain.md has no shell block under ## The walk"
    return [shlex.split(line) for line in block.group(1).splitlines() if line.strip()]


def test_the_walk_of_the_terrain_page_makes_the_shipped_seabed(cli: Path, tmp_path: Path) -> None:
    commands = walk()
    assert [c[0] for c in commands] == ["python", "t2spline", "t2spline", "t2spline", "t2spline"]
    # The raster script prints the options that the page's fuzzify line passes.
    script = commands[0]
    done = subprocess.run(
        [sys.executable, str(ROOT / script[1]), *script[2:]], cwd=tmp_path,
        capture_output=True, text=True, check=True,
    )
    printed = done.stdout.split()
    fuzzify = commands[1]
    assert printed == [a for a in fuzzify if a.startswith(("--origin=", "--spacing="))]
    reports = []
    for command in commands[1:]:
        done = subprocess.run([str(cli), *command[1:]], cwd=tmp_path, capture_output=True, text=True)
        assert done.returncode == 0, (command, done.stderr)
        reports.append(done.stderr)
    # The page's account of the blocks and of the fit.
    assert "the last 1 row(s)" in reports[0]
    data = json.loads((tmp_path / "seabed-data.json").read_text())
    assert (len(data["points"]), len(data["points"][0])) == (30, 40)
    crisp = re.search(r"crisp\s+(\S+)\s", reports[1])
    assert crisp, reports[1]
    assert round(float(crisp.group(1)), -1) == 850.0, "docs/terrain.md says: within 850 m"
    # The shipped example is what the walk makes.
    made = (tmp_path / "salish-sea-seabed.json").read_bytes()
    assert made == EXAMPLE.read_bytes()
    result = json.loads((tmp_path / "seabed-result.json").read_text())
    assert result["alpha"] == 0.5 and "surfaces" in result
    assert any(p.suffix == ".svg" for p in (tmp_path / "seabed-figures").iterdir())


def test_the_shipped_seabed_is_a_valid_surface_job(cli: Path) -> None:
    done = subprocess.run([str(cli), "validate", str(EXAMPLE)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "3-D surface, 16 × 20 control points, orders 4 × 4, alpha 0.5" in done.stdout
