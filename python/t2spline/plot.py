"""Drawing the stages of Algorithm 1.1 into matplotlib axes.

Each function draws one stage of a result of ``t2spline.run`` (or one fuzzy
number) into an ``Axes`` you give it, and returns that ``Axes``; titles,
limits and legends stay yours. The figures follow those of ``t2spline plot``
(paper Figs. 5.1–5.4): upper layers blue, primary green, lower vermillion,
left layers dashed, the crisp curve black, the solution purple.

Given the job's ``FuzzyCurve`` (``curve=t2spline.FuzzyCurve.from_job(job)``),
``stage1`` and ``stage2`` shade the regions the curve can occupy (the upper
and the lower function's, docs/method.md §10), computed by the Rust set
view: at each ``t`` the curve can pass anywhere in the box whose corners lie
on the layer curves, so the band between two layer curves is not that set.
``membership_map`` draws a plane curve's grades in the plane, ``section`` the
fuzzy value of y at a station.

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
>>> curve = t2spline.FuzzyCurve.from_job(t2spline.plot._EXAMPLE_JOB)
>>> ax = t2spline.plot.stage2(axes[0, 1], result, curve=curve)   # shades the regions at alpha
>>> t2spline.plot.membership_map(axes[1, 0], curve).get_title()
'upper membership grade'
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

from matplotlib.patches import PathPatch
from matplotlib.path import Path

from ._t2spline import FuzzyCurve, FuzzyNumber, NurbsCurve, Region, _palette

__all__ = ["stage1", "stage2", "stage3", "stage4", "stages", "membership",
           "region", "membership_map", "section"]

Result = Mapping[str, Any]
Coords = Tuple[int, int]

#: The colours of the figures by series, from the table that ``t2spline plot``
#: draws with (Okabe–Ito and greys): ``upper``, ``primary``, ``lower``,
#: ``crisp``, ``polygon``, ``type_reduced_left``, ``type_reduced_right``,
#: ``solution``, ``distance``.
PALETTE: Mapping[str, str] = dict(_palette())
UPPER, PRIMARY, LOWER = PALETTE["upper"], PALETTE["primary"], PALETTE["lower"]
CRISP, SOLUTION, GREY = PALETTE["crisp"], PALETTE["solution"], PALETTE["polygon"]
LEFT, RIGHT = PALETTE["type_reduced_left"], PALETTE["type_reduced_right"]
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


_PLANES: Mapping[Tuple[int, int], Literal["xy", "xz", "yz"]] = {
    (0, 1): "xy", (0, 2): "xz", (1, 2): "yz"}
_SHADES: Tuple[Tuple[Literal["upper", "lower"], str, float], ...] = (
    ("upper", UPPER, 0.12), ("lower", LOWER, 0.32))


def region(ax: Axes, region: Optional[Region], *, color: str = UPPER, alpha: float = 0.12,
           label: Optional[str] = None) -> Axes:
    """Fills a ``Region`` (``FuzzyCurve.region``): its polygons with their
    holes, as one compound path (exteriors counter-clockwise, holes
    clockwise, so a hole stays empty). ``None`` (no cut at the level) draws
    nothing."""
    if region is None:
        return ax
    vertices, codes = [], []
    for exterior, holes in region.polygons:
        for ring in (exterior, *holes):
            ring = np.asarray(ring, dtype=float)
            vertices.extend([*ring, ring[0]])
            codes.extend([Path.MOVETO] + [Path.LINETO] * (len(ring) - 1) + [Path.CLOSEPOLY])
    if vertices:
        ax.add_patch(PathPatch(Path(np.asarray(vertices), codes), facecolor=color, alpha=alpha,
                               linewidth=0, label=label))
        ax.autoscale_view()
    return ax


def _regions(ax: Axes, curve: Optional[FuzzyCurve], level: float, coords: Coords) -> None:
    """The upper and the lower region at ``level`` in the plane of ``coords``."""
    if curve is None:
        return
    plane = _PLANES.get((coords[0], coords[1]))
    if plane is None:
        raise ValueError(f"coords: regions are drawn in the planes xy, xz, yz, got {coords}")
    for which, color, shade in _SHADES:
        r = curve.region(level, membership=which, plane=plane)
        region(ax, r, color=color, alpha=shade, label=f"{which} region at alpha = {level:g}")


def _layer_curves(ax: Axes, curves: Mapping[str, Optional[NDArray[np.float64]]], coords: Coords,
                  what: str) -> None:
    for name, color, _ in _FUNCTIONS:
        for side, style in (("left", "--"), ("right", "-")):
            points = curves.get(f"{name}_{side}")
            if points is not None:
                ax.plot(*_xy(points, coords), style, color=color, linewidth=1.2,
                        label=f"{what} {name} {side}")


def stage1(ax: Axes, result: Result, *, coords: Coords = (0, 1),
           curve: Optional[FuzzyCurve] = None) -> Axes:
    """Stage 1 (paper Fig. 5.1): the fuzzy curve.

    Draws the control polygon, each fuzzy control point as the crisp point
    with bars for its upper, primary and lower interval in each coordinate,
    and the seven layer curves (left dashed, right solid); given ``curve``,
    the regions the curve can occupy at level 0 under the upper function
    (light) and the lower (darker), from ``curve.region``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    result : dict
        A result of ``t2spline.run``.
    coords : (int, int)
        The coordinates to draw (a projection, for 3-D curves).
    curve : FuzzyCurve, optional
        The job's fuzzy curve (``FuzzyCurve.from_job(job)``), whose regions
        are shaded; without it no region is drawn.
    """
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    layers = curves["layers"]
    _regions(ax, curve, 0.0, coords)
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


def stage2(ax: Axes, result: Result, *, coords: Coords = (0, 1),
           curve: Optional[FuzzyCurve] = None) -> Axes:
    """Stage 2 (paper Fig. 5.2): the alpha-cut control points and curves.

    A lower layer is drawn only where every number has a lower cut at the
    result's alpha; absent lower ends (NaN) are left out. Given ``curve``
    (as for ``stage1``), the upper and lower regions at the result's alpha
    are shaded (the lower only where it has a cut).
    """
    _check(result, coords)
    curves, cps = result["curves"], result["control_points"]
    cut = curves["alpha_cut"]
    _regions(ax, curve, float(result["alpha"]), coords)
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
    _band(ax, left, right, coords, LEFT, 0.15, "between left and right")
    ax.plot(*_xy(left, coords), "--", color=LEFT, label="type-reduced left")
    ax.plot(*_xy(right, coords), ":", color=RIGHT, linewidth=2, label="type-reduced right")
    ax.plot(*_xy(cps["type_reduced_left"], coords), "^", color=LEFT, markersize=5)
    ax.plot(*_xy(cps["type_reduced_right"], coords), "D", color=RIGHT, markersize=5)
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
    ax.plot(*_xy(ends, coords), "-o", color=PALETTE["distance"], linewidth=2.5, markersize=9,
            markerfacecolor="none", label=f"max distance {error['max']:.3g} (rms {error['rms']:.3g})")
    ax.set_title("Stage 4: crisp and defuzzified curve")
    return ax


def _curve(result: Result, control_points: NDArray[np.float64]) -> NurbsCurve:
    """The curve of the result's weights and knots through `control_points`."""
    return NurbsCurve(control_points, result["weights"], result["knots"], degree=result["degree"])


def stages(result: Result, *, coords: Coords = (0, 1),
           figsize: Tuple[float, float] = (11, 9),
           curve: Optional[FuzzyCurve] = None) -> Figure:
    """All four stages in a 2 × 2 ``matplotlib.figure.Figure`` (no pyplot
    needed: save it with ``fig.savefig``, or show it in a notebook); given
    ``curve``, stages 1 and 2 shade its regions."""
    fig = Figure(figsize=figsize, layout="constrained")
    axes = fig.subplots(2, 2)
    stage1(axes[0, 0], result, coords=coords, curve=curve)
    stage2(axes[0, 1], result, coords=coords, curve=curve)
    stage3(axes[1, 0], result, coords=coords)
    stage4(axes[1, 1], result, coords=coords)
    for ax in axes.flat:
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


#: The levels whose regions ``membership_map`` outlines.
CONTOUR_LEVELS = (0.2, 0.4, 0.6, 0.8)


def _bounds(r: Region) -> Tuple[Tuple[float, float], Tuple[float, float]]:
    """The box of a region's exteriors."""
    points = np.concatenate([np.asarray(exterior) for exterior, _ in r.polygons])
    lo, hi = points.min(axis=0), points.max(axis=0)
    return (float(lo[0]), float(hi[0])), (float(lo[1]), float(hi[1]))


def membership_map(ax: Axes, curve: FuzzyCurve, *, which: Literal["upper", "primary", "lower"] = "upper",
                   cells: int = 240, levels: Tuple[float, ...] = CONTOUR_LEVELS) -> Axes:
    """A plane curve's grades in the plane, as ``t2spline plot`` draws the
    ``membership`` figure: ``curve.membership_grid`` over the upper region
    at level 0 (``cells`` along the longer side) as a viridis map from 0 to 1
    (grade 0 left blank), the regions at ``levels`` outlined, and the crisp
    curve on top. Returns ``ax``; the image is ``ax.images[0]``."""
    support = curve.region(0.0)
    if support is None:  # pragma: no cover - the upper function always has a cut at 0
        return ax
    (x0, x1), (y0, y1) = _bounds(support)
    pad = 0.04 * max(x1 - x0, y1 - y0)
    x0, x1, y0, y1 = x0 - pad, x1 + pad, y0 - pad, y1 + pad
    step = max(x1 - x0, y1 - y0) / cells
    shape = (max(1, min(cells, round((x1 - x0) / step))), max(1, min(cells, round((y1 - y0) / step))))
    grid = curve.membership_grid((x0, x1), (y0, y1), shape)
    grades = np.ma.masked_equal(grid[which], 0.0)
    ax.imshow(grades, extent=(x0, x1, y0, y1), origin="lower", cmap="viridis", vmin=0.0, vmax=1.0,
              interpolation="nearest")
    for level in levels:
        r = curve.region(level, membership=which)
        for exterior, holes in (r.polygons if r is not None else []):
            for ring in (exterior, *holes):
                ring = np.asarray(ring)
                closed = np.vstack([ring, ring[:1]])
                ax.plot(closed[:, 0], closed[:, 1], color="white", linewidth=2.2)
                ax.plot(closed[:, 0], closed[:, 1], color="#222222", linewidth=0.8)
    crisp = curve.sample(401)["crisp"]
    ax.plot(crisp[:, 0], crisp[:, 1], color=CRISP, linewidth=1.5, label="crisp curve")
    ax.set_aspect("equal")
    ax.set_title(f"{which} membership grade")
    return ax


def section(ax: Axes, curve: FuzzyCurve, x0: float, *, alpha: Optional[float] = None,
            samples: int = 401) -> Axes:
    """The fuzzy value of y at the station ``x = x0`` of a plane curve, as
    ``membership`` draws one number: the grades of the points ``(x0, y)``
    (``curve.membership``) under the three functions, the footprint between
    upper and lower, and, given ``alpha``, the ends of the section's
    intervals there (``curve.section``: several where the curve passes the
    station more than once)."""
    levels = np.linspace(0.0, 1.0, 21)
    cuts = curve.section(x0, levels)
    upper0 = cuts[0]["upper"] or []
    if not upper0:
        ax.set_title(f"Section at x = {x0:g}: the region does not reach it")
        return ax
    lo, hi = upper0[0][0], upper0[-1][1]
    pad = 0.08 * max(hi - lo, 1e-12)
    ends = [e for c in cuts for which, _, _ in _FUNCTIONS for iv in (c[which] or []) for e in iv]
    y = np.unique(np.concatenate([np.linspace(lo - pad, hi + pad, samples), ends]))
    grades = curve.membership(np.column_stack([np.full_like(y, x0), y]))
    ax.fill_between(y, grades["lower"], grades["upper"], color=UPPER, alpha=0.15, linewidth=0,
                    label="footprint of uncertainty")
    for which, color, _ in _FUNCTIONS:
        ax.plot(y, grades[which], color=color, label=f"{which} membership of y")
    if alpha is not None:
        (at,) = curve.section(x0, [alpha])
        for which, color, _ in _FUNCTIONS:
            for a, b in at[which] or []:
                ax.plot([a, b], [alpha, alpha], "s", color=color, markersize=4)
        ax.axhline(alpha, color="#222222", linewidth=0.8)
    ax.set_ylim(0, 1.05)
    ax.set_xlabel(f"y at x = {x0:g}")
    ax.set_title(f"Section at x = {x0:g}: the fuzzy value of y")
    return ax
