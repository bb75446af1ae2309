"""t2spline — normal type-2 fuzzy rational B-spline curves and surfaces, numpy in and out.

Models uncertain data with rational B-spline curves whose control points are
normal triangular type-2 fuzzy numbers (Zakaria, Wahab and Gobithaasan,
"Normal Type-2 Fuzzy Rational B-spline Curve"), computed by the Rust engine
of the t2spline project. Section numbers (§n) refer to docs/method.md, the project's
statement of the method.

One uncertain value is seven ordered numbers and a height (docs/method.md §1)::

    upper.left <= primary.left <= lower.left <= crisp
               <= lower.right <= primary.right <= upper.right,   0 < h <= 1

and Algorithm 1.1 runs in four stages (docs/method.md §7):

1. the fuzzy control points and the seven layer curves
   ``C(t) = Σ wᵢ Nᵢ,ₚ(t) Pᵢ / Σ wᵢ Nᵢ,ₚ(t)`` through each layer's values;
2. the alpha-cut of every number, ``cut(e) = e + s·(crisp − e)`` with
   ``s = α`` for upper and primary ends and ``s = α/h`` for lower ends
   (absent when ``α > h``);
3. type reduction to ``(left, crisp, right)``: the mean of the three left
   (right) cut ends when ``α <= h``, of the two otherwise — the result jumps
   at ``α = h``;
4. defuzzification ``(left + crisp + right)/3`` and the distance (max, rms)
   between the crisp curve and the defuzzified one.

Contents
--------
run
    A job (a dict with the job-file schema, or a path) through the same
    validator and engine as ``t2spline run``; the result file's keys, with
    numpy arrays. ``type_reduction=`` (or the job's ``"type_reduction"``)
    chooses ``"paper"`` (the default, stages 3–4 above), ``"centroid"``,
    ``"nie-tan"`` or ``"alpha-planes"`` (docs/method.md §9).
run_many, run_table
    Many jobs on all cores with the GIL released: a list of jobs (dicts,
    texts or paths) to a list of results; an Arrow table of job texts to a
    pyarrow table of summaries (and of samples), for Dask, Ray or Spark
    (docs/scale.md). Every object pickles, so curves go to worker processes.
JobError
    A job that breaks the rules (a ``ValueError``), one problem per line.
FuzzyNumber, AlphaCut
    One fuzzy number: alpha-cut, type reduction, defuzzification,
    membership functions.
NurbsCurve
    A rational B-spline curve: evaluation, derivatives, knot insertion,
    degree elevation, splitting, arc length, closest point.
FuzzyCurve, Solution
    Stage 1 from numpy arrays, sampled by the engine; stages 2–4 by
    ``FuzzyCurve.solve(alpha, type_reduction=)``.
NurbsSurface
    A rational B-spline surface (docs/method.md §8): evaluation broadcast over ``u``
    and ``v``, grids by the grid engine, partial derivatives, normal,
    curvature, isocurves, knot insertion, degree elevation, splitting,
    closest point, bounding box.
FuzzySurface, SurfaceSolution
    A net of fuzzy control points and its seven layer surfaces; stages 2–4
    on the net by ``FuzzySurface.solve(alpha, type_reduction=)``, and the
    distance between the crisp and the defuzzified surface.
FuzzyCurve.membership, .region, .section, .membership_grid; Region
    The fuzzy curve as a set (docs/method.md §10): membership grades of
    points, alpha-regions as polygons (``Region``, with a GeoJSON
    ``__geo_interface__`` that shapely opens), the fuzzy value at a station,
    membership maps; ``FuzzySurface.membership`` and ``.section`` for
    surfaces.
centroid
    The centroid ``[c_l, c_r]`` of an interval type-2 set given by samples
    (Karnik–Mendel, EKM, EIASC, or the Nie–Tan value).
fit
    Fuzzy data points → a fuzzy curve (a net of them → a fuzzy surface) and
    a summary of the fit.
fuzzify, fit_job, export, to_json, FuzzyCurve.to_job, FuzzySurface.to_job
    The loop of the command-line tool in Python, by its code: readings (a
    file, a net's arrays or long table, a raster array) to the data of a fit
    (``t2spline fuzzify``), the data to a job (``t2spline fit``), a job to a CAD file
    (``t2spline export``), a result to the bytes of ``t2spline run``'s
    result file, a model back to a job dict that ``run`` runs.
benchmark_curve
    The curve that ``t2spline bench`` times.
benchmark_surface
    The surface that ``t2spline bench --case surface`` times.
release_cached_memory
    Gives back the memory large samples leave behind when dropped (kept for
    the next large output, up to 256 MiB).
t2spline.plot
    Drawing the stages into matplotlib axes (``pip install t2spline[plot]``).
t2spline.types
    ``TypedDict``s of the returned dicts and other names for annotations.

Examples
--------
>>> import numpy as np, t2spline
>>> c = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
>>> spread = np.array([-0.6, 0.9])                 # unequal left and right spreads
>>> curve = t2spline.FuzzyCurve(
...     crisp=c,
...     upper=c[..., None] + spread,
...     primary=c[..., None] + 0.6 * spread,
...     lower=c[..., None] + 0.3 * spread,
...     lower_height=0.6,
...     degree=2,
... )
>>> curve
FuzzyCurve(dimension=2, degree=2, order=3, control_points=(4, 2), domain=(0.0, 1.0))
>>> layers = curve.sample(101)                     # the seven layer curves, (101, 2) each
>>> bool(np.all(layers["upper_left"] <= layers["crisp"]))
True
>>> solution = curve.solve(alpha=0.8)              # above h = 0.6: no lower cut
>>> solution.defuzzified - solution.crisp          # right spreads are wider: a shift
array([[0.016, 0.016],
       [0.016, 0.016],
       [0.016, 0.016],
       [0.016, 0.016]])
>>> round(solution.distance()["max"], 6)           # 0.016·√2
0.022627
"""

from . import types
from ._t2spline import (
    AlphaCut,
    FuzzyCurve,
    FuzzyNumber,
    FuzzySurface,
    JobError,
    NurbsCurve,
    NurbsSurface,
    Region,
    Solution,
    SurfaceSolution,
    __version__,
    benchmark_curve,
    benchmark_surface,
    centroid,
    export,
    fit,
    fit_job,
    fuzzify,
    release_cached_memory,
    run,
    run_many,
    to_json,
)
from .table import run_table

__all__ = [
    "AlphaCut",
    "FuzzyCurve",
    "FuzzyNumber",
    "FuzzySurface",
    "JobError",
    "NurbsCurve",
    "NurbsSurface",
    "Region",
    "Solution",
    "SurfaceSolution",
    "__version__",
    "benchmark_curve",
    "benchmark_surface",
    "centroid",
    "export",
    "fit",
    "fit_job",
    "fuzzify",
    "release_cached_memory",
    "run",
    "run_many",
    "run_table",
    "to_json",
    "types",
]
