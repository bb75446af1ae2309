"""`t2spline plot` and `report` as a user runs them on the figures of the
fuzzy curve as a set (docs/method.md §10): the `membership` and `section`
figures written beside the others, the SVG opened by an XML reader, the
regions stages 1 and 2 shade filled by the even-odd rule (a fuzzy circle's
hole left empty), and `--station` refused with exit 2 where it is bad."""

from __future__ import annotations

import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import ROOT

EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"
CIRCLE = ROOT / "fixtures" / "circle.json"
SVG = "{http://www.w3.org/2000/svg}"


def run(cli: Path, *args: object) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def test_plot_writes_the_membership_and_section_figures(cli: Path, tmp_path: Path) -> None:
    done = run(cli, "plot", EXAMPLE, "-o", tmp_path, "--format", "svg", "--station", "3.5")
    assert done.returncode == 0, done.stderr
    written = done.stdout.split()
    assert [Path(p).name for p in written[-2:]] == ["membership.svg", "section.svg"]
    section = ET.parse(tmp_path / "section.svg").getroot()
    assert section.find(f"{SVG}title").text == "Section at x = 3.5: the fuzzy value of y"
    stage1 = ET.parse(tmp_path / "stage1-fuzzy.svg").getroot()
    regions = [p for p in stage1.iter(f"{SVG}path") if p.get("fill-rule") == "evenodd"]
    assert len(regions) == 2  # upper and lower at level 0


def test_a_circles_region_is_drawn_with_its_hole(cli: Path, tmp_path: Path) -> None:
    done = run(cli, "plot", CIRCLE, "-o", tmp_path, "--format", "svg")
    assert done.returncode == 0, done.stderr
    stage1 = ET.parse(tmp_path / "stage1-fuzzy.svg").getroot()
    (upper, _) = [p for p in stage1.iter(f"{SVG}path") if p.get("fill-rule") == "evenodd"]
    assert upper.get("d").count("M") == 2  # the exterior and the hole


@pytest.mark.parametrize(
    "job, station, says",
    [
        (EXAMPLE, "nan", "--station: the station must be a finite x, got NaN"),
        (EXAMPLE, "inf", "--station: the station must be a finite x, got inf"),
        (ROOT / "fixtures" / "spiral-3d.json", "1", "--station: the section at a station is drawn for plane curves"),
        (ROOT / "examples" / "fuzzy-terrain.json", "1", "--station: the section at a station is drawn for plane curves"),
    ],
)
def test_a_bad_station_is_refused_and_nothing_is_written(
    cli: Path, tmp_path: Path, job: Path, station: str, says: str
) -> None:
    out = tmp_path / "figures"
    for command in ("plot", "report"):
        done = run(cli, command, job, "-o", out, "--station", station)
        assert done.returncode == 2, (command, done.stderr)
        assert says in done.stderr, done.stderr
        assert not out.exists() or not any(out.iterdir())
