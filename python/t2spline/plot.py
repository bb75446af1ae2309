"""Drawing the stages of Algorithm 1.1 into matplotlib axes.

Each function draws one stage of a result of ``t2spline.run`` (or one fuzzy
number) into an ``Axes`` you give it, and returns that ``Axes``; titles,
limits and legends stay yours. The figures follow those of ``t2spline plot``
(paper Figs. 5.1–5.4): upper layers blue, primary green, lower vermillion,
left layers dashed, the crisp curve black, the solution purple.

Needs matplotlib (``pip install t2spline[plot]``); ``import t2spline`` alone
does not.

Every number drawn comes from the result or from the Rust engine: this
module only draws.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> from matplotlib.figure import Figure
>>> import t2spline, t2spline.plot
>>> result = t2spline.run(t2spline.plot._EXAMPLE_JOB)
>>> fig = Figure(figsize=(10, 8))
>>> axes = fig.subplots(2, 2)
>>> t2spline.plot.stage1(axes[0, 0], result)       # doctest: +ELLIPSIS
<Axes: ...>
>>> t2spline.plot.stage4(axes[1, 1], result).get_title()
'Stage 4: crisp and defuzzified curve'
"""

from __future__ import annotations

from typing import Any, Literal, Mapping, Optional, Tuple

import numpy as np
from numpy.typing import NDArray

try:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
except ImportError:  # pragma: no cover - exercised without matplotlib only
    raise ImportError(
        "t2spline.plot needs matplotlib: pip install 't2spline[plot]'"
    ) from None

from ._t2spline import FuzzyNumber, NurbsCurve

__all__ = ["stage1", "stage2", "stage3", "stage4", "stages", "membership"]

Result = Mapping[str, Any]
Coords = Tuple[int, int]

#: Colours of the three membership functions (Okabe–Ito), as ``t2spline plot``.
UPPER, PRIMARY, LOWER = "#0072B2", "#009E73", "#D55E00"
CRISP, SOLUTION, GREY = "black", "#CC79A7", "#999999"
_FUNCTIONS: Tuple[Tuple[Literal["upper", "primary", "lower"], str, float], ...] = (
    ("upper", UPPER, 1.2), ("primary", PRIMARY, 2.6), ("lower", LOWER, 4.4))

# A small job for the examples of this module's docstrings.
_EXAMPLE_JOB = {
    "order": 3,
    "alpha": 0.5,
    "lower_height": 0.6,
    "points": [
        {
            "x": {"crisp": x, "upper": [x - 0.6, x + 0.9], "primary": [x - 0.4, x + 0.6],
                  "lower": [x - 0.2, x + 0.3]},
            "y": {"crisp": y, "upper": [y - 0.5, y + 0.8], "primary": [y - 0.3, y + 0.5],
                  "lower": [y - 0.1, y + 0.2]},
        }
        for x, y in [(0.0, 0.0), (1.0, 2.0), (3.0, 2.5), (4.0, 0.5)]
    ],
}


def _xy(points: NDArray[np.float64], coords: Coords) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    i, j = coords
    return points[..., i], points[..., j]


def _check(result: Result, coords: Coords) -> None:
    d = int(result["dimension"])
    if len(coords) != 2 or not all(0 <= c < d for c in coords):
        raise ValueError(
            f"coords: expected two coordinate indices in [0, {d - 1}] (the result is {d}-D), got {coords}"
        )


def _band(ax: Axes, left: Optional[NDArray[np.float64]], right: Optional[NDArray[np.float64]],
          coords: Coords, color: str, alpha: float, label: Optional[str]) -> None:
    """The region between two curves: one forward, the other back."""
    if left is None or right is None:
        return
    polygon = np.concatenate([left, right[::-1]])
    ax.fill(*_xy(polygon, coords), color=color, alpha=alpha, linewidth=0, label=label)


def _layer_curves(ax: Axes, curves: Mapping[str, Optional[NDArray[np.float64]]], coords: Coords,
                  what: str) -> None:
    for name, color, _ in _FUNCTIONS:
        for side, style in (("left", "--"), ("right", "-")):
            points = curves.get(f"{name}_{side}")
            if points is not None:
                ax.plot(*_xy(points, coords), style, color=color, linewidth=1.2,
                        label=f"{what} {name} {side}")


def stage1(ax: Axes, result: Result, *, coords: Coords = (0, 1)) -> Axes:
    """Stage 1 (paper Fig. 5.1): the fuzzy curve.

    Draws the bands between the upper layer curves (light) and between the
    lower ones (darker), the control polygon, each fuzzy control point as the
    crisp point with bars for its upper, primary and lower interval in each
    coordinate, and the seven layer curves (left dashed, right solid).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    result : dict
        A result of ``t2spline.run``.
    coords : (int, int)
        The coordinates to draw (a projection, for 3-D curves).
    """
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    layers = curves["layers"]
    _band(ax, layers["upper_left"], layers["upper_right"], coords, UPPER, 0.12,
          "between the upper layers")
    _band(ax, layers["lower_left"], layers["lower_right"], coords, LOWER, 0.18,
          "between the lower layers")
    crisp = cps["crisp"]
    ax.plot(*_xy(crisp, coords), ":", color=GREY, linewidth=1, label="control polygon")
    i, j = coords
    for name, color, width in _FUNCTIONS:
        lo, hi = cps["layers"][f"{name}_left"], cps["layers"][f"{name}_right"]
        ax.hlines(crisp[:, j], lo[:, i], hi[:, i], color=color, linewidth=width, alpha=0.7)
        ax.vlines(crisp[:, i], lo[:, j], hi[:, j], color=color, linewidth=width, alpha=0.7,
                  label=f"{name} intervals")
    _layer_curves(ax, layers, coords, "layer")
    ax.plot(*_xy(curves["crisp"], coords), color=CRISP, linewidth=1.5, label="crisp curve")
    ax.plot(*_xy(crisp, coords), "o", color=CRISP, markersize=4, label="crisp control points")
    ax.set_title("Stage 1: fuzzy curve")
    return ax


def stage2(ax: Axes, result: Result, *, coords: Coords = (0, 1)) -> Axes:
    """Stage 2 (paper Fig. 5.2): the alpha-cut control points and curves.

    A lower layer is drawn only where every number has a lower cut at the
    result's alpha; absent lower ends (NaN) are left out.
    """
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    cut = curves["alpha_cut"]
    _band(ax, cut["upper_left"], cut["upper_right"], coords, UPPER, 0.12, None)
    _band(ax, cut["lower_left"], cut["lower_right"], coords, LOWER, 0.18, None)
    _layer_curves(ax, cut, coords, "alpha-cut")
    for name, color, _ in _FUNCTIONS:
        for side in ("left", "right"):
            ax.plot(*_xy(cps["alpha_cut"][f"{name}_{side}"], coords), "s", color=color,
                    markersize=3)
    ax.plot(*_xy(curves["crisp"], coords), color=CRISP, linewidth=1, label="crisp curve")
    ax.set_title(f"Stage 2: alpha-cut at alpha = {result['alpha']:g}")
    return ax


def stage3(ax: Axes, result: Result, *, coords: Coords = (0, 1)) -> Axes:
    """Stage 3 (paper Fig. 5.3): the type-reduced control points and the
    curves through their left and their right values, with the band between."""
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    left, right = curves["type_reduced"]["left"], curves["type_reduced"]["right"]
    _band(ax, left, right, coords, PRIMARY, 0.15, "between left and right")
    ax.plot(*_xy(left, coords), "--", color=PRIMARY, label="type-reduced left")
    ax.plot(*_xy(right, coords), "-", color=PRIMARY, label="type-reduced right")
    ax.plot(*_xy(cps["type_reduced_left"], coords), "<", color=PRIMARY, markersize=5)
    ax.plot(*_xy(cps["type_reduced_right"], coords), ">", color=PRIMARY, markersize=5)
    ax.plot(*_xy(curves["crisp"], coords), color=CRISP, linewidth=1, label="crisp curve")
    ax.set_title(f"Stage 3: type reduction at alpha = {result['alpha']:g}")
    return ax


def stage4(ax: Axes, result: Result, *, coords: Coords = (0, 1)) -> Axes:
    """Stage 4 (paper Fig. 5.4): the crisp curve beside the defuzzified curve
    (the crisp type-2 solution), their control points, and the largest
    distance between the two curves at equal ``t`` marked by a segment
    between ``C(t)`` and ``D(t)`` at ``t = error.max_at`` (both evaluated by
    the Rust engine)."""
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    ax.plot(*_xy(curves["crisp"], coords), color=CRISP, label="crisp curve")
    ax.plot(*_xy(curves["defuzzified"], coords), color=SOLUTION, linewidth=2,
            label="defuzzified curve")
    ax.plot(*_xy(cps["crisp"], coords), "o", color=CRISP, markersize=4)
    ax.plot(*_xy(cps["defuzzified"], coords), "D", color=SOLUTION, markersize=4)
    error = result["error"]
    t = float(error["max_at"])
    ends = np.stack([
        _curve(result, cps["crisp"]).eval(t),
        _curve(result, cps["defuzzified"]).eval(t),
    ])
    # The distance may be a small fraction of the figure: open circles find it.
    ax.plot(*_xy(ends, coords), "-o", color="#E69F00", linewidth=2.5, markersize=9,
            markerfacecolor="none", label=f"max distance {error['max']:.3g} (rms {error['rms']:.3g})")
    ax.set_title("Stage 4: crisp and defuzzified curve")
    return ax


def _curve(result: Result, control_points: NDArray[np.float64]) -> NurbsCurve:
    """The curve of the result's weights and knots through `control_points`."""
    return NurbsCurve(control_points, result["weights"], result["knots"], degree=result["degree"])


def stages(result: Result, *, coords: Coords = (0, 1),
           figsize: Tuple[float, float] = (11, 9)) -> Figure:
    """All four stages in a 2 × 2 ``matplotlib.figure.Figure`` (no pyplot
    needed: save it with ``fig.savefig``, or show it in a notebook)."""
    fig = Figure(figsize=figsize, layout="constrained")
    axes = fig.subplots(2, 2)
    for ax, draw in zip(axes.flat, (stage1, stage2, stage3, stage4)):
        draw(ax, result, coords=coords)
        ax.set_aspect("equal", adjustable="datalim")
    axes[1, 1].legend(loc="best", fontsize="small")
    return fig


def membership(ax: Axes, number: FuzzyNumber, *, samples: int = 401) -> Axes:
    """The three membership functions of one fuzzy number (docs/method.md §1) and its
    footprint of uncertainty (between UMF and LMF), evaluated by the Rust
    engine at ``samples`` points over the number's support."""
    lo, hi = number.upper
    pad = 0.05 * max(hi - lo, 1e-12)
    # The feet and the apex exactly, so that the corners are drawn sharp.
    x = np.unique(np.concatenate([
        np.linspace(lo - pad, hi + pad, samples),
        [*number.upper, *number.primary, *number.lower, number.crisp],
    ]))
    umf = number.membership(x, which="upper")
    lmf = number.membership(x, which="lower")
    ax.fill_between(x, lmf, umf, color=UPPER, alpha=0.15, linewidth=0,
                    label="footprint of uncertainty")
    for which, color, _ in _FUNCTIONS:
        ax.plot(x, number.membership(x, which=which), color=color, label=f"{which} MF")
    ax.set_ylim(0, 1.05)
    ax.set_title(f"Fuzzy number (crisp {number.crisp:g}, h = {number.lower_height:g})")
    return ax
