"""Pictures in notebooks: `_repr_html_` of numbers, curves, surfaces,
solutions and regions, drawn by the figure code of `t2spline plot` (the
stage figures compared with the command's SVG files, bit for bit), small,
well-formed, with ids distinct between pictures; `repr()` stays one line."""

from __future__ import annotations

import re
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import t2spline

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"
CYLINDER = ROOT / "examples" / "fuzzy-cylinder.json"

SVG = re.compile(r"<svg .*?</svg>", re.S)
PREFIX = re.compile(r"t2s\d+-")


def svgs(html: str) -> list[str]:
    """The inline SVG documents of a picture, each parsed to check it is
    well-formed XML."""
    found = SVG.findall(html)
    for s in found:
        ET.fromstring(s)
    return found


def clip_ids(html: str) -> set[str]:
    return set(re.findall(r'<clipPath id="([^"]+)"', html))


@pytest.fixture(scope="module")
def curve() -> t2spline.FuzzyCurve:
    return t2spline.FuzzyCurve.from_job(str(EXAMPLE))


def test_number_draws_the_number_figure() -> None:
    x = t2spline.FuzzyNumber(1.0, upper=(0.4, 1.9), primary=(0.6, 1.6), lower=(0.8, 1.3), lower_height=0.6)
    html = x._repr_html_()
    (svg,) = svgs(html)
    assert "<title>Fuzzy number</title>" in svg
    assert "membership grade" in svg
    # The table gives the numbers and the level of the cut shown (h/2).
    assert "<th style=\"text-align:left\">crisp</th><td style=\"text-align:left\">1.0</td>" in html
    assert "α = h/2 = 0.3" in html
    assert "\n" not in repr(x)


def test_fuzzy_curve_draws_stage_1_as_the_command_does(curve: t2spline.FuzzyCurve, cli: Path, tmp_path: Path) -> None:
    html = curve._repr_html_()
    (svg,) = svgs(html)
    subprocess.run(
        [str(cli), "plot", str(EXAMPLE), "-o", str(tmp_path), "--format", "svg"],
        check=True,
        capture_output=True,
    )
    expected = (tmp_path / "stage1-fuzzy.svg").read_text(encoding="utf-8")
    assert PREFIX.sub("", svg) + "\n" == expected
    assert "control points</th><td style=\"text-align:left\">4</td>" in html
    r = repr(curve)
    assert "\n" not in r and r.startswith("FuzzyCurve(dimension=2, degree=2")


def test_solution_draws_the_four_stages_as_the_command_does(
    curve: t2spline.FuzzyCurve, cli: Path, tmp_path: Path
) -> None:
    # The example's alpha (0.8), the paper's type reduction: the job as
    # `t2spline plot` draws it.
    solution = curve.solve(0.8)
    html = solution._repr_html_()
    found = svgs(html)
    assert len(found) == 4
    subprocess.run(
        [str(cli), "plot", str(EXAMPLE), "-o", str(tmp_path), "--format", "svg"],
        check=True,
        capture_output=True,
    )
    for svg, name in zip(found, ["stage1-fuzzy", "stage2-alpha-cut", "stage3-type-reduced", "stage4-defuzzified"]):
        expected = (tmp_path / f"{name}.svg").read_text(encoding="utf-8")
        assert PREFIX.sub("", svg) + "\n" == expected, name
    d = solution.distance()
    assert f"{d['max']!r} at t = {d['max_at']!r}" in html
    # Small enough for a notebook: at most 150 kB for the shipped example.
    assert len(html.encode("utf-8")) <= 150_000, len(html.encode("utf-8"))
    assert "\n" not in repr(solution)


def test_pictures_on_one_page_keep_distinct_ids(curve: t2spline.FuzzyCurve) -> None:
    a, b = curve._repr_html_(), curve._repr_html_()
    assert clip_ids(a) and clip_ids(b)
    assert not clip_ids(a) & clip_ids(b)
    # Every clip path a picture refers to is its own.
    for html in (a, b):
        used = set(re.findall(r'url\(#([^)]+)\)', html))
        assert used <= clip_ids(html)


def test_crisp_curve_and_surface_draw_themselves() -> None:
    arc = t2spline.NurbsCurve([[1, 0], [1, 1], [0, 1]], weights=[1, np.sqrt(0.5), 1], degree=2)
    (svg,) = svgs(arc._repr_html_())
    assert "<title>NURBS curve</title>" in svg
    assert "<polyline" in svg
    w = np.sqrt(0.5)
    net = [[[1, 0, 0], [1, 0, 2]], [[1, 1, 0], [1, 1, 2]], [[0, 1, 0], [0, 1, 2]]]
    cylinder = t2spline.NurbsSurface(net, weights=[[1, 1], [w, w], [1, 1]], degree=(2, 1))
    html = cylinder._repr_html_()
    assert html is not None
    (svg,) = svgs(html)
    assert "<title>NURBS surface</title>" in svg
    # A surface in the plane has no 3-D picture: Jupyter falls back to repr.
    flat = t2spline.NurbsSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]], degree=1)
    assert flat._repr_html_() is None


def test_fuzzy_surface_and_its_solution_draw_themselves() -> None:
    surface = t2spline.FuzzySurface.from_job(str(CYLINDER))
    html = surface._repr_html_()
    assert html is not None
    (svg,) = svgs(html)
    assert "Stage 1" in svg
    solution = surface.solve(0.5)
    html = solution._repr_html_()
    assert html is not None
    assert len(svgs(html)) == 4


def test_region_draws_its_polygons(curve: t2spline.FuzzyCurve) -> None:
    region = curve.region(0.2)
    html = region._repr_html_()
    (svg,) = svgs(html)
    assert "upper region at α = 0.2" in svg
    assert "<path" in svg
    assert f"<td style=\"text-align:left\">{region.area!r}</td>" in html


def test_a_large_curve_is_thinned_and_says_so() -> None:
    n = 3000
    t = np.linspace(0.0, 60.0, n)
    crisp = np.stack([t, np.sin(t)], axis=1)
    spread = np.array([-0.1, 0.1])
    big = t2spline.FuzzyCurve(
        crisp,
        crisp[..., None] + spread,
        crisp[..., None] + 0.6 * spread,
        crisp[..., None] + 0.3 * spread,
        lower_height=0.6,
        degree=3,
    )
    html = big._repr_html_()
    (svg,) = svgs(html)
    assert "Thinned for the notebook: 4097 samples per curve" in svg
    assert "Regions of the set view left out" in svg
    assert len(html.encode("utf-8")) <= 1_000_000


def test_measures_draw_the_measures_figure_of_what_was_measured(curve: t2spline.FuzzyCurve) -> None:
    import pickle

    measures = curve.measure(levels=5)
    assert isinstance(measures, dict)
    html = measures._repr_html_()  # type: ignore[attr-defined]
    (svg,) = svgs(html)
    assert "Fuzzy measures: arc length and area" in svg
    assert "at the 5 levels measured" in svg
    # The figure's subtitle gives the crisp arc length of the measures.
    assert "crisp arc length" in svg
    # Otherwise the plain dict of `t2spline measure`, pickled as one.
    again = pickle.loads(pickle.dumps(measures))
    assert type(again) is dict and again.keys() == measures.keys()


def test_section_draws_the_section_figure_at_its_station(curve: t2spline.FuzzyCurve, cli: Path, tmp_path: Path) -> None:
    import pickle

    sections = curve.section(3.0, levels=3)
    assert isinstance(sections, list) and len(sections) == 3
    html = sections._repr_html_()  # type: ignore[attr-defined]
    (svg,) = svgs(html)
    assert "y at x = 3" in svg
    assert type(pickle.loads(pickle.dumps(sections))) is list
    # The figure of `t2spline plot --station 3` at alpha 0.
    subprocess.run(
        [str(cli), "plot", str(EXAMPLE), "-o", str(tmp_path), "--format", "svg", "--station", "3", "--alpha", "0"],
        check=True,
        capture_output=True,
    )
    expected = (tmp_path / "section.svg").read_text(encoding="utf-8")
    assert PREFIX.sub("", svg) + "\n" == expected


def test_a_space_curve_and_another_type_reduction_draw_themselves() -> None:
    c = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 1.0], [3.0, 2.0, 0.5], [4.0, 0.0, 2.0]])
    spread = np.array([-0.3, 0.4])
    curve = t2spline.FuzzyCurve(
        c, c[..., None] + spread, c[..., None] + 0.6 * spread, c[..., None] + 0.3 * spread,
        lower_height=0.6, degree=2,
    )
    (svg,) = svgs(curve._repr_html_())
    # One panel per projection.
    for name in ("x–y projection", "x–z projection", "y–z projection"):
        assert name in svg
    solution = curve.solve(type_reduction="centroid")
    html = solution._repr_html_()
    assert len(svgs(html)) == 4
    assert "<td style=\"text-align:left\">centroid</td>" in html
    assert "\n" not in repr(solution)
