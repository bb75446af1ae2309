"""Types for annotating code that uses t2spline.

The dicts that t2spline returns are plain dicts; these ``TypedDict``s name
their keys for type checkers::

    from t2spline.types import LayerSamples

    def widest(samples: LayerSamples) -> float:
        return float((samples["upper_right"] - samples["upper_left"]).max())

Every array is a ``float64`` numpy array (``Floats``).
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Literal, Optional, Tuple, TypedDict, Union

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "AlphaCutCurves",
    "AlphaCuts",
    "Centroid",
    "CentroidMethod",
    "Deviation",
    "DirectionName",
    "Distance",
    "DistanceSweep",
    "FitSummary",
    "Floats",
    "GeoMultiPolygon",
    "Grades",
    "Job",
    "LayerDeviations",
    "LayerName",
    "LayerSamples",
    "AreaMeasure",
    "AtMeasure",
    "DerivativeLevel",
    "DerivativeLevels",
    "MeasureLevel",
    "MeasureLevels",
    "Measures",
    "SurfaceMeasures",
    "MembershipGrid",
    "NetCounts",
    "PartialLevel",
    "PartialLevels",
    "PerDirection",
    "PlaneName",
    "SectionLevel",
    "SideName",
    "StageSamples",
    "SurfaceCurvature",
    "SurfaceDistance",
    "SurfaceLayerSamples",
    "SurfaceStageSamples",
    "TypeReducedSamples",
    "TypeReductionName",
    "Which",
]

#: A ``float64`` numpy array.
Floats = NDArray[np.float64]

# The choices are written as unions of one-value literals: the same type as
# one literal of several values, and a union at run time too (which the stub
# checker, mypy's stubtest, compares).

#: The seven layers of docs/method.md §1, in order.
LayerName = Union[
    Literal["upper_left"], Literal["primary_left"], Literal["lower_left"], Literal["crisp"],
    Literal["lower_right"], Literal["primary_right"], Literal["upper_right"],
]

#: A membership function of a fuzzy number.
Which = Union[Literal["upper"], Literal["primary"], Literal["lower"]]

#: A coordinate plane of a space curve's region (``FuzzyCurve.region``).
PlaneName = Union[Literal["xy"], Literal["xz"], Literal["yz"]]

#: A side of a type-reduced number.
SideName = Union[Literal["left"], Literal["right"]]

#: A parameter direction of a surface: ``u`` along the rows of the net,
#: ``v`` along its columns.
DirectionName = Union[Literal["u"], Literal["v"]]

#: One value for both directions of a surface, or ``(u, v)``.
PerDirection = Union[int, Tuple[int, int]]

#: A type reduction of stages 3–4 (docs/method.md §9), as in a job's ``"type_reduction"``.
TypeReductionName = Union[
    Literal["paper"], Literal["centroid"], Literal["nie-tan"], Literal["alpha-planes"],
]

#: An algorithm of ``centroid``.
CentroidMethod = Union[Literal["km"], Literal["ekm"], Literal["eiasc"], Literal["nie-tan"]]

#: A job: a dict with the keys of a job file, or the path of one.
Job = Union[Dict[str, Any], str, "os.PathLike[str]"]


class _SevenLayers(TypedDict):
    """The seven layers of docs/method.md §1, each sampled."""

    upper_left: Floats
    primary_left: Floats
    lower_left: Floats
    crisp: Floats
    lower_right: Floats
    primary_right: Floats
    upper_right: Floats


class LayerSamples(_SevenLayers):
    """``FuzzyCurve.sample``: the parameters ``(m,)`` and each layer ``(m, d)``."""

    params: Floats


class AlphaCuts(TypedDict):
    """``Solution.alpha_cut``: each layer's cut control points ``(n, d)``
    (``SurfaceSolution.alpha_cut``: ``(nu, nv, d)``), NaN where a lower cut
    is absent."""

    upper_left: Floats
    primary_left: Floats
    lower_left: Floats
    lower_right: Floats
    primary_right: Floats
    upper_right: Floats


class AlphaCutCurves(TypedDict):
    """The sampled alpha-cut curves ``(m, d)`` (or surfaces ``(su, sv, d)``);
    ``None`` for a lower layer that some number does not have at this
    alpha."""

    upper_left: Floats
    primary_left: Floats
    lower_left: Optional[Floats]
    lower_right: Optional[Floats]
    primary_right: Floats
    upper_right: Floats


class TypeReducedSamples(TypedDict):
    """The type-reduced curves (surfaces) of stage 3, as in the result
    file's ``curves.type_reduced``."""

    left: Floats
    right: Floats


class StageSamples(TypedDict):
    """``Solution.sample``: the curves of stages 2–4 at the parameters, under
    the keys of the result file's ``curves``."""

    params: Floats
    alpha_cut: AlphaCutCurves
    type_reduced: TypeReducedSamples
    defuzzified: Floats


class Distance(TypedDict):
    """``Solution.distance``: the largest distance (and its ``t``) and the root
    mean square distance between the crisp and the defuzzified curve."""

    max: float
    max_at: float
    rms: float


class SurfaceLayerSamples(_SevenLayers):
    """``FuzzySurface.sample``: the parameters ``u`` ``(su,)`` and ``v``
    ``(sv,)``, and each layer on the grid ``(su, sv, d)``."""

    u: Floats
    v: Floats


class SurfaceStageSamples(TypedDict):
    """``SurfaceSolution.sample``: the surfaces of stages 2–4 on the grid
    ``u × v``, each ``(su, sv, d)``."""

    u: Floats
    v: Floats
    alpha_cut: AlphaCutCurves
    type_reduced: TypeReducedSamples
    defuzzified: Floats


class SurfaceDistance(TypedDict):
    """``SurfaceSolution.distance``: the largest distance (and its ``(u,
    v)``) and the root mean square distance between the crisp and the
    defuzzified surface."""

    max: float
    max_at: Tuple[float, float]
    rms: float


class SurfaceCurvature(TypedDict):
    """``NurbsSurface.curvature``: at every ``(u, v)`` (shape ``s``, the
    broadcast shape of ``u`` and ``v``) the Gaussian curvature ``gaussian``
    ``s``, the mean curvature ``mean`` ``s``, the principal curvatures
    ``principal`` ``s + (2,)`` (``k1 >= k2``) and their unit directions
    ``directions`` ``s + (2, 3)``. ``FuzzySurface.curvatures``: the same with
    the seven layers after ``s`` (``s + (7,)``, ``s + (7, 2)``, ``s + (7, 2,
    3)``)."""

    gaussian: Floats
    mean: Floats
    principal: Floats
    directions: Floats


class Centroid(TypedDict):
    """``centroid``: the ends ``c_l``, ``c_r`` of the centroid, their midpoint,
    and the switch points tried for each end ``(left, right)``."""

    left: float
    right: float
    defuzzified: float
    iterations: Tuple[int, int]


class Deviation(TypedDict):
    """The largest deviation of a fitted layer from its data, and where."""

    max: float
    point: int
    axis: str


class LayerDeviations(TypedDict):
    """One ``Deviation`` per layer."""

    upper_left: Deviation
    primary_left: Deviation
    lower_left: Deviation
    crisp: Deviation
    lower_right: Deviation
    primary_right: Deviation
    upper_right: Deviation


class NetCounts(TypedDict):
    """The shape of a fitted net (``FitSummary.net``): rows and columns of
    the data, control points in u and in v."""

    data: List[int]
    control: List[int]


class FitSummary(TypedDict):
    """The summary of ``fit``; ``net`` is ``None`` for a curve."""

    data_points: int
    control_points: int
    mode: str
    condition: float
    deviations: LayerDeviations
    spread_deviations: LayerDeviations
    independent_violations: List[str]
    mixed_heights: Dict[str, float]
    net: Optional[NetCounts]


class Grades(TypedDict):
    """``FuzzyCurve.membership``, ``FuzzySurface.membership``: the grade of
    every point under each membership function (docs/method.md §10), arrays
    of the points' leading shape, ``lower <= primary <= upper``."""

    upper: Floats
    primary: Floats
    lower: Floats


class SectionLevel(TypedDict):
    """One level of ``FuzzyCurve.section`` (intervals of y) or
    ``FuzzySurface.section`` (intervals of z), as ``t2spline section``
    writes it: each function's intervals ``[lo, hi]`` in increasing order,
    ``None`` where it has no cut at the level, ``[]`` where the region does
    not reach the station."""

    alpha: float
    upper: Optional[List[List[float]]]
    primary: Optional[List[List[float]]]
    lower: Optional[List[List[float]]]


class MembershipGrid(TypedDict):
    """``FuzzyCurve.membership_grid``: the cell centres ``xs`` ``(columns,)``
    and ``ys`` ``(rows,)``, and each function's grades ``(rows, columns)``,
    row ``j`` at ``ys[j]``."""

    xs: Floats
    ys: Floats
    upper: Floats
    primary: Floats
    lower: Floats


class DistanceSweep(TypedDict):
    """``FuzzyCurve.distance_sweep`` and ``FuzzySurface.distance_sweep``: the
    levels ``alpha``, the sampled ``max`` and ``rms`` distance at each
    ``(L,)``, and the distances themselves, ``(L, samples)`` along a curve or
    ``(L, su, sv)`` on a surface's grid."""

    alpha: Floats
    max: Floats
    rms: Floats
    distance: Floats


class GeoMultiPolygon(TypedDict):
    """``Region.__geo_interface__``: a GeoJSON MultiPolygon (RFC 7946), each
    polygon its closed exterior ring (counter-clockwise) and closed holes
    (clockwise), each position ``[x, y]``."""

    type: Literal["MultiPolygon"]
    coordinates: List[List[List[List[float]]]]


class MeasureLevel(TypedDict):
    """One level of a quantity of ``FuzzyCurve.measure`` (docs/method.md
    §11): ``min`` and ``max`` bound the values over the control points
    inside their cuts, never narrower than the truth; ``gap`` is how far
    either may lie outside the values attained; ``exact`` that it is only
    rounding or the stated tolerance."""

    alpha: float
    min: float
    max: float
    exact: bool
    gap: float


class MeasureLevels(TypedDict):
    """A quantity per membership function (the lower up to its height)."""

    upper: List[MeasureLevel]
    primary: List[MeasureLevel]
    lower: List[MeasureLevel]


class _SurfaceMeasuresBase(TypedDict):
    levels: Floats
    datum: float
    tolerance: float
    plan_area: Floats
    volume_below: MeasureLevels
    volume_above: MeasureLevels
    plan_area_below: MeasureLevels


class SurfaceMeasures(_SurfaceMeasuresBase, total=False):
    """``FuzzySurface.measure`` (docs/method.md §14): the volumes between
    the surface and the plane ``z = datum``, the plan area below it and
    (unless ``area=False``) the surface area ``area``, per membership
    function and level; ``tolerance`` is the relative accuracy the volumes
    and plan areas are integrated to, each level's ``gap`` the bound
    reached; ``plan_area`` the plan's area and its error bound. With
    ``against=other``, ``cut`` and ``fill``: the volumes where the surface
    lies above and below ``other``."""

    area: MeasureLevels
    cut: MeasureLevels
    fill: MeasureLevels


class _AreaMeasureBase(TypedDict):
    kind: Literal["under", "enclosed"]
    upper: List[MeasureLevel]
    primary: List[MeasureLevel]
    lower: List[MeasureLevel]


class AreaMeasure(_AreaMeasureBase, total=False):
    """The area: ``"under"`` an open curve, ``"enclosed"`` by a closed one
    (positive whichever way it runs); ``note`` when only the crisp layer
    closes (the area of each curve closed by the chord between its ends)."""

    note: str


class PartialLevel(TypedDict):
    """A level of the tangent angle or the curvature: ``defined`` is false
    (and ``min``, ``max`` ``None``) where some admissible curve stands still
    at the parameter."""

    alpha: float
    defined: bool
    min: Optional[float]
    max: Optional[float]
    exact: bool
    gap: float


class PartialLevels(TypedDict):
    """Per membership function."""

    upper: List[PartialLevel]
    primary: List[PartialLevel]
    lower: List[PartialLevel]


class DerivativeLevel(TypedDict):
    """The exact range of the derivative at one level, per coordinate."""

    alpha: float
    min: Floats
    max: Floats


class DerivativeLevels(TypedDict):
    """Per membership function."""

    upper: List[DerivativeLevel]
    primary: List[DerivativeLevel]
    lower: List[DerivativeLevel]


class _AtMeasureBase(TypedDict):
    t: float
    order: int
    derivative: DerivativeLevels
    curvature: PartialLevels


class AtMeasure(_AtMeasureBase, total=False):
    """The quantities at one parameter; ``tangent_angle`` (radians) for
    plane curves only."""

    tangent_angle: PartialLevels


class _MeasuresBase(TypedDict):
    levels: Floats
    length: MeasureLevels
    at: List[AtMeasure]


class Measures(_MeasuresBase, total=False):
    """``FuzzyCurve.measure``, as ``t2spline measure`` writes it; ``area``
    for plane curves only."""

    area: AreaMeasure
