"""`t2spline.plot` draws each stage into the axes it is given, from the
numbers of the result (and the Rust engine); `import t2spline` alone does not
need matplotlib."""

from __future__ import annotations

import io
import json
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.patches import PathPatch, Polygon  # noqa: E402
from matplotlib.path import Path as MplPath  # noqa: E402

import t2spline  # noqa: E402
import t2spline.plot as tp  # noqa: E402

from conftest import EXAMPLE  # noqa: E402

RESULT = t2spline.run(EXAMPLE)


def axes() -> "matplotlib.axes.Axes":
    return Figure().subplots()


def labels(ax: "matplotlib.axes.Axes") -> list:
    return [line.get_label() for line in ax.get_lines()]


CURVE = t2spline.FuzzyCurve.from_job(EXAMPLE)


def test_stage1_draws_the_seven_layers_the_regions_and_the_intervals() -> None:
    ax = axes()
    assert tp.stage1(ax, RESULT, curve=CURVE) is ax
    names = labels(ax)
    for function in ("upper", "primary", "lower"):
        for side in ("left", "right"):
            assert f"layer {function} {side}" in names
    assert "crisp curve" in names and "control polygon" in names
    layer = ax.get_lines()[names.index("layer upper right")]
    assert np.array_equal(np.column_stack(layer.get_data()), RESULT["curves"]["layers"]["upper_right"])
    # No band between layer curves: the regions the Rust set view computes.
    assert not [p for p in ax.patches if isinstance(p, Polygon)]
    regions = [p for p in ax.patches if isinstance(p, PathPatch)]
    assert [p.get_label() for p in regions] == ["upper region at alpha = 0", "lower region at alpha = 0"]
    bars = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert len(bars) == 6  # horizontal and vertical bars of three intervals
    # Without the curve, nothing is shaded.
    assert not tp.stage1(axes(), RESULT).patches


def test_a_region_is_drawn_with_its_holes() -> None:
    """The drawn path is the Region's polygons: a fuzzy circle's annulus,
    rendered, leaves its centre empty where shapely's region has its hole
    (matplotlib fills by the non-zero rule, and holes run clockwise)."""
    shapely = pytest.importorskip("shapely.geometry")
    circle = t2spline.FuzzyCurve.from_job(EXAMPLE.parent.parent / "fixtures" / "circle.json")
    region = circle.region(0.0)
    fig = Figure(figsize=(4, 4), dpi=100)
    ax = fig.add_axes((0, 0, 1, 1))
    tp.region(ax, region, alpha=1.0)
    ax.set_xlim(-1.3, 1.3)
    ax.set_ylim(-1.3, 1.3)
    ax.set_axis_off()
    (patch,) = ax.patches
    codes = patch.get_path().codes
    assert len([c for c in codes if c == MplPath.MOVETO]) == 2  # exterior and hole
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    pixels = np.asarray(canvas.buffer_rgba())
    shape = shapely.shape(region)
    for p in [(0.0, 0.0), (0.5, 0.5), (1.0, 0.0), (-0.75, 0.75), (0.0, -1.05), (1.25, 0.0)]:
        col, row = ax.transData.transform(p)
        r, g, b, _ = pixels[int(round(pixels.shape[0] - row)), int(round(col))]
        filled = (r, g, b) != (255, 255, 255)
        assert filled == shape.contains(shapely.Point(p)), p


def test_stage2_shades_the_regions_at_the_results_alpha() -> None:
    at_08 = tp.stage2(axes(), RESULT, curve=CURVE)  # above h = 0.6: no lower region
    assert [p.get_label() for p in at_08.patches] == ["upper region at alpha = 0.8"]
    at_04 = tp.stage2(axes(), t2spline.run(EXAMPLE, alpha=0.4), curve=CURVE)
    assert len(at_04.patches) == 2
    (drawn,) = at_08.patches
    region = CURVE.region(0.8)
    exterior = region.polygons[0][0]
    assert np.array_equal(drawn.get_path().vertices[: len(exterior)], exterior)


def test_membership_map_is_the_grid_with_its_regions_outlined() -> None:
    ax = tp.membership_map(axes(), CURVE, which="lower", cells=80)
    (image,) = ax.images
    grades = image.get_array()
    assert grades.max() <= 0.6 + 1e-12  # the lower grades reach h
    x0, x1, y0, y1 = image.get_extent()
    grid = CURVE.membership_grid((x0, x1), (y0, y1), grades.shape[::-1])
    assert np.array_equal(np.ma.filled(grades, 0.0), grid["lower"])
    assert "crisp curve" in labels(ax)


def test_section_draws_the_grades_at_the_station_and_its_cut() -> None:
    ax = tp.section(axes(), CURVE, 3.5, alpha=0.5)
    line = ax.get_lines()[labels(ax).index("upper membership of y")]
    y, mu = line.get_data()
    grades = CURVE.membership(np.column_stack([np.full_like(y, 3.5), y]))
    assert np.array_equal(mu, grades["upper"])
    # The crisp curve crosses x = 3.5: the samples include the section's ends
    # at level 1, within the section's tolerance of the crisp point.
    assert mu.max() == pytest.approx(1.0, abs=1e-4)


def test_stage2_leaves_out_absent_lower_cuts() -> None:
    ax = tp.stage2(axes(), RESULT)  # alpha 0.8 > h: no lower cut
    names = labels(ax)
    assert "alpha-cut upper left" in names and "alpha-cut primary right" in names
    assert "alpha-cut lower left" not in names
    below = tp.stage2(axes(), t2spline.run(EXAMPLE, alpha=0.4))
    assert "alpha-cut lower left" in labels(below)
    assert ax.get_title() == "Stage 2: alpha-cut at alpha = 0.8"


def test_stage3_draws_left_and_right() -> None:
    ax = tp.stage3(axes(), RESULT)
    names = labels(ax)
    line = ax.get_lines()[names.index("type-reduced left")]
    assert np.array_equal(np.column_stack(line.get_data()), RESULT["curves"]["type_reduced"]["left"])


def test_stage4_marks_the_largest_distance_between_the_curves() -> None:
    ax = tp.stage4(axes(), RESULT)
    names = labels(ax)
    (mark,) = [line for line in ax.get_lines() if line.get_label().startswith("max distance")]
    ends = np.column_stack(mark.get_data())
    # C(t) and D(t) at the reported t: their distance is the reported max.
    assert np.linalg.norm(ends[1] - ends[0]) == pytest.approx(RESULT["error"]["max"], rel=1e-12)
    assert "defuzzified curve" in names


def test_a_projection_of_a_3d_result() -> None:
    result = t2spline.run(EXAMPLE.parent.parent / "fixtures" / "spiral-3d.json")
    assert result["dimension"] == 3
    ax = tp.stage1(axes(), result, coords=(0, 2))
    line = ax.get_lines()[labels(ax).index("crisp curve")]
    assert np.array_equal(line.get_ydata(), result["curves"]["crisp"][:, 2])
    with pytest.raises(ValueError, match=r"coords: expected two coordinate indices in \[0, 2\]"):
        tp.stage4(axes(), result, coords=(0, 3))


def test_all_stages_in_one_figure_render_to_png() -> None:
    fig = tp.stages(RESULT, curve=CURVE)
    assert len(fig.axes) == 4
    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=50)
    assert out.getvalue()[:8] == b"\x89PNG\r\n\x1a\n"


def test_membership_draws_the_three_functions_and_the_footprint() -> None:
    x = t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    ax = tp.membership(axes(), x)
    assert labels(ax) == ["upper MF", "primary MF", "lower MF"]
    lower = ax.get_lines()[2]
    xs, ys = lower.get_data()
    assert max(ys) == 0.6 and xs[np.argmax(ys)] == 1.0  # the apex at h
    assert len(ax.collections) == 1  # the footprint of uncertainty


def test_importing_t2spline_does_not_import_matplotlib() -> None:
    code = "import sys, t2spline; t2spline.run({}); print('matplotlib' in sys.modules)"
    job = json.dumps(json.loads(EXAMPLE.read_text()))
    out = subprocess.run([sys.executable, "-c", code.format(job)], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "False"
