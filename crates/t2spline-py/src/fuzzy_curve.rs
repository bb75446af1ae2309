//! `FuzzyCurve`: stage 1 of Algorithm 1.1 (docs/method.md §6–§7), a rational B-spline
//! whose control points are fuzzy points; its seven layer curves sampled by
//! the engine straight into one numpy buffer, its operations on all layers
//! at once, and `solve` for stages 2–4.

use pyo3::prelude::*;
use pyo3::types::PyTuple;
use t2spline::FuzzyCurve;

use crate::arrays::{array, optional_vector};
use crate::capability;
use crate::classes::{PyFuzzyCurve, PyNurbsCurve, PySolution};
use crate::construct::{degree, layer, FuzzyArrays};
use crate::curve_methods::curve_methods;
use crate::dim::by_dim;
use crate::errors::compute;
use crate::fuzzy_methods::{fuzzy_methods, index, numbers};
use crate::keyword;
use crate::number::PyFuzzyNumber;
use crate::py_types::{DictResult, Obj, ObjResult, Pair, Triple};
use crate::sample::{layer_dict, ParamsArg};
use crate::weight_numbers::{number_list, WeightsArg};

fuzzy_methods!("curve", "n", PySolution => curve_methods!(PyFuzzyCurve {

    /// Pickling and copying: the constructor with ``(crisp, upper, primary, lower, lower_height, weights, knots)``
    /// (the degree following from the knots), fuzzy weights as their
    /// numbers (``weight_numbers``), an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        let fuzzy = by_dim!(&slf.get().0, |c| c.weight_numbers().is_some());
        let weights = if fuzzy { "weight_numbers" } else { "weights" };
        crate::pickle::by_constructor(slf, &["crisp", "upper", "primary", "lower", "lower_height", weights, "knots"])
    }
    #[new]
    #[pyo3(signature = (crisp, upper=None, primary=None, lower=None, lower_height=None, weights=None, knots=None, *, degree=None, order=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        crisp: &Obj<'_>,
        upper: Option<&Obj<'_>>,
        primary: Option<&Obj<'_>>,
        lower: Option<&Obj<'_>>,
        lower_height: Option<&Obj<'_>>,
        weights: Option<&Obj<'_>>,
        knots: Option<&Obj<'_>>,
        degree: Option<&Obj<'_>>,
        order: Option<&Obj<'_>>,
    ) -> PyResult<Self> {
        let (degree, order) = (
            keyword::opt_int(degree, "degree")?,
            keyword::opt_int(order, "order")?,
        );
        let data = FuzzyArrays::read(crisp, [upper, primary, lower, lower_height], 1)?;
        let (weights, numbers) = match WeightsArg::read(weights)? {
            WeightsArg::Crisp(w) => (w.unwrap_or_else(|| vec![1.0; data.n]), None),
            // Valid crisp weights first: the numbers' own values are checked
            // by `with_weight_numbers`, its message naming `weights[i]`.
            WeightsArg::Numbers(w) => (vec![1.0; data.n], Some(w)),
        };
        let knots = optional_vector(knots, "knots")?;
        let degree = self::degree(degree, order, knots.as_ref().map(Vec::len), data.n)?;
        compute(py, move || {
            Ok(by_dim!(data.points()?, |p| {
                let curve = FuzzyCurve::try_new(degree, p, weights, knots)?;
                match numbers {
                    Some(w) => curve.with_weight_numbers(w)?,
                    None => curve,
                }
                .into()
            }))
        })
    }

    /// The fuzzy weights (docs/method.md §16): one ``FuzzyNumber`` per
    /// control point, or ``None`` where the weights are crisp. ``weights``
    /// holds their crisp values.
    #[getter]
    fn weight_numbers(&self) -> Option<Vec<PyFuzzyNumber>> {
        by_dim!(&self.0, |c| number_list(c.weight_numbers()))
    }

    /// The envelope of the curve at the parameter ``t`` (docs/method.md
    /// §15–§16): the least and the largest value of each coordinate over
    /// every choice of control points and weights inside their cuts under
    /// ``membership`` at ``alpha``, as the result file's
    /// ``curves.envelope`` gives it at each sample. With crisp weights it
    /// is the box between the curves through the cuts' ends; with fuzzy
    /// weights each end is a Karnik–Mendel weighted average, exact at its
    /// switch point. The stage curves, each with one choice of weights, do
    /// not bound the curve; this does.
    ///
    /// Parameters
    /// ----------
    /// t : float
    ///     A parameter in the domain.
    /// membership : {"upper", "primary", "lower"}, optional
    ///     Default ``"upper"``.
    /// alpha : float, optional
    ///     The level in ``[0, 1]``, default 0.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray or None
    ///     Shape ``(d, 2)``: ``[min, max]`` per coordinate; ``None`` where a
    ///     number that counts at ``t`` has no cut (the lower function above
    ///     its height).
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside the domain, an alpha outside ``[0, 1]``
    ///     or an unknown membership, naming the argument.
    ///
    /// Examples
    /// --------
    /// Points 0 and 1 (crisp), weights 1 and 1 to 3: at t = 1/2 the curve
    /// runs from 1/2 (equal weights) to 3/4 (weight 3 on the second point).
    ///
    /// >>> line = FuzzyCurve([[0.0, 0.0], [1.0, 1.0]], degree=1,
    /// ...                   weights=[1.0, FuzzyNumber(2.0, upper=(1.0, 3.0), primary=(1.5, 2.5))])
    /// >>> line.envelope(0.5).tolist()
    /// [[0.5, 0.75], [0.5, 0.75]]
    /// >>> line.envelope(0.5, "upper", alpha=1.0).tolist()      # the crisp weights 1, 2
    /// [[0.6666666666666666, 0.6666666666666666], [0.6666666666666666, 0.6666666666666666]]
    #[pyo3(
        signature = (t, membership=None, alpha=None),
        text_signature = "($self, t, membership='upper', alpha=0.0)"
    )]
    fn envelope<'py>(
        &self,
        py: Python<'py>,
        t: &Obj<'py>,
        membership: Option<&Obj<'py>>,
        alpha: Option<&Obj<'py>>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        let t = keyword::real(t, "t")?;
        let membership = crate::set::membership(membership)?;
        let alpha = crate::number::alpha(keyword::opt_real(alpha, "alpha")?.unwrap_or(0.0))?;
        let Some(ranges) = by_dim!(&self.0, |c| compute(py, || Ok(c
            .envelope_at(t, membership, alpha)?
            .map(|e| e.iter().flat_map(|i| [i.left(), i.right()]).collect::<Vec<_>>()))))?
        else {
            return Ok(None);
        };
        let d = self.dimension();
        array(py, ranges, &[d, 2]).map(Some)
    }

    /// The fuzzy control point ``index``: one ``FuzzyNumber`` per coordinate.
    fn point<'py>(&self, py: Python<'py>, index: &Obj<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let n = by_dim!(&self.0, |c| c.points().len());
        let i = self::index(keyword::int(index, "index")?, n, "index")?;
        by_dim!(&self.0, |c| numbers(py, &c.points()[i]))
    }

    /// The layer curve through one value of every control point, as a
    /// ``NurbsCurve`` (``"crisp"``: the crisp curve).
    fn layer_curve(&self, layer: &Obj<'_>) -> PyResult<PyNurbsCurve> {
        let l = self::layer(layer, "layer")?;
        Ok(by_dim!(&self.0, |c| c.layer_curve(l).into()))
    }

    /// The crisp rational B-spline through the crisp values.
    fn crisp_curve(&self) -> PyNurbsCurve {
        by_dim!(&self.0, |c| c.crisp_curve().into())
    }

    /// The seven layer curves at every value of ``t`` by the straightforward
    /// evaluator (one rational basis for all layers); the reference that
    /// ``sample`` is tested against.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (7, d)``, layers in the order of docs/method.md §1 (``upper_left`` …
    ///     ``upper_right``, ``crisp`` at index 3).
    fn eval_layers<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_points(py, c, t, self.dimension()))
    }

    /// The point of every layer curve closest to ``point`` (see
    /// ``NurbsCurve.closest_point``), layers in the order of docs/method.md
    /// §1 (``upper_left`` … ``upper_right``, ``crisp`` at index 3), as
    /// ``FuzzySurface.closest_points`` gives them for surfaces.
    ///
    /// Parameters
    /// ----------
    /// point : array_like, shape (dimension,) or (m, dimension)
    ///
    /// Returns
    /// -------
    /// (t, point, distance)
    ///     For one point: arrays ``(7,)``, ``(7, dimension)`` and ``(7,)``;
    ///     for ``m`` points: ``(m, 7)``, ``(m, 7, dimension)`` and
    ///     ``(m, 7)``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])
    /// >>> s = np.array([[[0.0, 0.0], [-1.0, 1.0]], [[0.0, 0.0], [-1.0, 1.0]]])
    /// >>> band = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s,
    /// ...                   c[..., None] + 0.25 * s, lower_height=0.5, degree=1)
    /// >>> t, p, d = band.closest_points([2.0, 3.0])
    /// >>> t.shape, p.shape, [round(float(x), 12) for x in d]
    /// ((7,), (7, 2), [4.0, 3.5, 3.25, 3.0, 2.75, 2.5, 2.0])
    fn closest_points<'py>(&self, py: Python<'py>, point: &Obj<'py>) -> PyResult<Triple<'py>> {
        let [t, p, d] = by_dim!(&self.0, |c| capability::closest(py, c, point))?;
        Ok((t, p, d))
    }

    /// The derivatives ``C⁽⁰⁾ … C⁽ᵒʳᵈᵉʳ⁾`` of every layer curve at every value
    /// of ``t`` (see ``NurbsCurve.derivatives``); unlike the points, the
    /// layers' derivatives are not ordered.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (7, order + 1, dimension)``, layers in the order
    ///     of docs/method.md §1; ``[..., i, 0, :]`` is the point of layer ``i``.
    #[pyo3(signature = (t, order=None), text_signature = "($self, t, order=1)")]
    fn derivatives<'py>(
        &self, py: Python<'py>, t: &Obj<'py>, order: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_derivatives(py, c, t, order, self.dimension()))
    }

    /// The curvature of every layer curve at every value of ``t`` (see
    /// ``NurbsCurve.curvature``), as ``FuzzySurface.curvatures`` gives it for
    /// surfaces.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (7,)``, layers in the order of docs/method.md §1.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside the domain; where a layer curve stands
    ///     still (the message names the layer).
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> w = np.sqrt(0.5)                      # a quarter circle, radius 1
    /// >>> c = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    /// >>> arc = FuzzyCurve(c, np.stack([0.5 * c, 2 * c], -1), np.stack([c, c], -1),
    /// ...                  np.stack([c, c], -1), lower_height=0.5, weights=[1, w, 1], degree=2)
    /// >>> arc.curvatures(0.3).round(12).tolist()   # radii 0.5, 1 and 2
    /// [2.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.5]
    fn curvatures<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_curvature(py, c, t))
    }

    /// The tight axis-aligned box ``(min, max)`` of all seven layer curves,
    /// each of shape ``(dimension,)``: the region the fuzzy curve can occupy
    /// (as ``FuzzySurface.bounding_box``).
    fn bounding_box<'py>(&self, py: Python<'py>) -> PyResult<Pair<'py>> {
        by_dim!(&self.0, |c| capability::bounding_box(py, c))
    }

    /// ``curve(t)`` is ``curve.eval_layers(t)``: the seven layer curves at
    /// ``t``, shape ``t.shape + (7, d)``.
    fn __call__<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        self.eval_layers(py, t)
    }

    /// The seven layer curves at many parameters by the sampling engine: one
    /// power form of the rational basis per knot span for all layers, written
    /// straight into one numpy buffer (no per-point work in Python), the docs/method.md
    /// §1 order of the layers kept exactly, multi-threaded for large jobs.
    ///
    /// Parameters
    /// ----------
    /// params : int or array_like
    ///     A count of uniform parameters, or a 1-D array of parameters in the
    ///     domain, in any order.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"params"``: the parameters, shape ``(m,)``; and for each layer name
    ///     (``"upper_left"`` … ``"upper_right"``) the points, shape ``(m, d)``.
    ///     The layers are views of one ``(7, d, m)`` array.
    fn sample<'py>(&self, py: Python<'py>, params: &Obj<'py>) -> DictResult<'py> {
        let params = ParamsArg::extract(params, "params")?;
        // (layer, parameter, coordinate), seen through the engine's (layer,
        // coordinate, parameter).
        let d = self.dimension();
        let layers = by_dim!(&self.0, |c| params.sample(py, [&[7], &[d]], |t, out| c
            .sample_layers_into_slices(t, out)))?;
        let domain = by_dim!(&self.0, |c| c.domain());
        let t = array(py, params.values(domain)?, &[params.len()])?;
        layer_dict(py, [("params", t)], &layers)
    }

    /// The membership grades of points in the fuzzy curve as a set
    /// (docs/method.md §10): for each membership function, the largest level
    /// alpha at which some curve with its control points inside their cuts
    /// passes through the point; 0 where none does. A point on the crisp
    /// curve has the grades ``(1, 1, h)``.
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (..., d)
    ///     Any leading shape (a single point ``(d,)`` too), the coordinates
    ///     last.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"upper"``, ``"primary"``, ``"lower"``: arrays of the leading
    ///     shape ``(...)``, with ``lower <= primary <= upper``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For another last dimension than ``d``, and NaN or infinity, naming
    ///     the index (``points[3, 1] = nan ...``).
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])
    /// >>> s = np.array([-1.0, 1.0])
    /// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s,
    /// ...                   c[..., None] + 0.25 * s, lower_height=0.5, degree=1)
    /// >>> g = line.membership([[2.0, 0.0], [2.0, 0.5], [2.0, 3.0]])
    /// >>> [np.round(g[k], 9) for k in ("upper", "primary", "lower")]
    /// [array([1. , 0.5, 0. ]), array([1., 0., 0.]), array([0.5, 0. , 0. ])]
    ///
    /// A grade is certified to 1e-7 and never below the truth; a point on a
    /// foot, as (2, 0.5) is on the primary one, may grade a few 1e-12 above
    /// 0 (the one slack of docs/set.md), hence the rounding.
    fn membership<'py>(&self, py: Python<'py>, points: &Obj<'py>) -> DictResult<'py> {
        crate::set::curve_membership(py, &self.0, points)
    }

    /// The region of one membership function at level ``alpha``
    /// (docs/method.md §10): every place some curve with its control points
    /// inside their cuts passes through, as polygons with holes within
    /// ``tolerance`` of the true region. The band between two layer curves
    /// is not this set: a curve can pass anywhere in the box of its cut ends.
    ///
    /// Parameters
    /// ----------
    /// alpha : float
    ///     The level in ``[0, 1]``.
    /// membership : {"upper", "primary", "lower"}, optional
    ///     Default ``"upper"``.
    /// tolerance : float, optional
    ///     Default: 1e-6 of the diagonal of the crisp control points'
    ///     bounding box.
    /// plane : {"xy", "xz", "yz"}, optional
    ///     The coordinate plane a space curve's region is projected on;
    ///     default ``"xy"``, the only plane of a plane curve.
    ///
    /// Returns
    /// -------
    /// Region or None
    ///     ``None`` where the function has no cut at ``alpha`` (the lower
    ///     function above every height).
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For an alpha outside ``[0, 1]``, an unknown membership or plane,
    ///     a tolerance that is not positive or finer than the outline can be
    ///     computed, naming the argument.
    #[pyo3(
        signature = (alpha, membership=None, tolerance=None, *, plane=None),
        text_signature = "($self, alpha, membership='upper', tolerance=None, *, plane='xy')"
    )]
    fn region(
        &self,
        py: Python<'_>,
        alpha: &Obj<'_>,
        membership: Option<&Obj<'_>>,
        tolerance: Option<&Obj<'_>>,
        plane: Option<&Obj<'_>>,
    ) -> PyResult<Option<crate::set::PyRegion>> {
        crate::set::curve_region(py, &self.0, alpha, membership, tolerance, plane)
    }

    /// The fuzzy value of y at the station ``x = x0`` of a plane curve
    /// (docs/method.md §10): at each level and for each membership function,
    /// the intervals of y where the vertical line meets the region, as
    /// ``t2spline section --x X0`` writes them.
    ///
    /// Parameters
    /// ----------
    /// x0 : float
    /// levels : int or array_like, optional
    ///     A count of levels equally spaced from 0 to 1 (2 to 1001, default
    ///     11), or the levels themselves.
    /// tolerance : float, optional
    ///     The largest error of an interval end; default as for ``region``.
    ///
    /// Returns
    /// -------
    /// list of dict
    ///     One per level: ``{"alpha": a, "upper": [[lo, hi], ...],
    ///     "primary": ..., "lower": ...}``, intervals increasing; ``None``
    ///     where the function has no cut at the level, ``[]`` where the
    ///     region does not reach the station.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 2.0]])
    /// >>> s = np.array([-1.0, 1.0])
    /// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s,
    /// ...                   c[..., None] + 0 * s, lower_height=1.0, degree=1)
    /// >>> at = line.section(2.0, levels=[0.0, 1.0], tolerance=1e-6)
    /// >>> [round(v, 5) for v in at[0]["upper"][0]]       # y from 0.5 - 1 to 1.5 + 1
    /// [-0.5, 2.5]
    #[pyo3(
        signature = (x0, levels=None, tolerance=None),
        text_signature = "($self, x0, levels=11, tolerance=None)"
    )]
    fn section<'py>(
        &self,
        py: Python<'py>,
        x0: &Obj<'py>,
        levels: Option<&Obj<'py>>,
        tolerance: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        crate::set::curve_section(py, &self.0, x0, levels, tolerance)
    }

    /// The uncertainty of what is measured on the curve (docs/method.md
    /// §11): the arc length (and a plane curve's area: under it, or enclosed
    /// where it is closed), and at each parameter of ``at`` the derivative of
    /// order ``order``, the tangent angle (plane curves, radians) and the
    /// curvature, each as the interval of its values over the control points
    /// inside their cuts, per membership function and level, as
    /// ``t2spline measure`` writes them.
    ///
    /// Parameters
    /// ----------
    /// levels : int or array_like, optional
    ///     A count of levels equally spaced from 0 to 1 (2 to 51, default
    ///     11), or the levels themselves (at most 51).
    /// at : float or array_like, optional
    ///     Parameters in the domain (at most 1 000).
    /// order : int, optional
    ///     The derivative's order (1 to 64, default 1).
    /// closed : bool, optional
    ///     ``True``: the curve must close (``ValueError`` naming its ends
    ///     otherwise) and its area is enclosed; ``False``: the area under it,
    ///     even if it closes; ``None`` (default): enclosed where the crisp
    ///     curve ends where it starts (docs/method.md §11). An enclosed area
    ///     is positive whichever way the curve runs; ``"note"`` says when only
    ///     the crisp layer closes.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"levels"``; ``"length"`` and ``"area"`` (with ``"kind"``
    ///     ``"under"`` or ``"enclosed"``): per function ``"upper"``,
    ///     ``"primary"``, ``"lower"`` a list of ``{"alpha", "min", "max",
    ///     "exact", "gap"}`` (the lower function's up to its height);
    ///     ``"at"``: per parameter ``{"t", "order", "derivative"`` (``"min"``,
    ///     ``"max"`` arrays per coordinate), ``"tangent_angle"``,
    ///     ``"curvature"}`` (``"defined"`` false where some admissible curve
    ///     stands still there). ``min`` and ``max`` are never narrower than
    ///     the truth; ``gap`` says how far either may lie outside it.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])
    /// >>> s = np.array([[[-1.0, 1.0], [0.0, 0.0]], [[-1.0, 1.0], [0.0, 0.0]]])
    /// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s,
    /// ...                   c[..., None] + 0 * s, lower_height=1.0, degree=1)
    /// >>> m = line.measure(levels=3)
    /// >>> [(round(l["min"], 6), round(l["max"], 6)) for l in m["length"]["upper"]]
    /// [(2.0, 6.0), (3.0, 5.0), (4.0, 4.0)]
    #[pyo3(
        signature = (levels=None, at=None, order=None, *, closed=None),
        text_signature = "($self, levels=11, at=None, order=1, *, closed=None)"
    )]
    fn measure<'py>(
        &self,
        py: Python<'py>,
        levels: Option<&Obj<'py>>,
        at: Option<&Obj<'py>>,
        order: Option<&Obj<'py>>,
        closed: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        crate::measure::curve_measure(py, &self.0, levels, at, order, closed)
    }

    /// The distance between the crisp curve and the defuzzified curve of
    /// the paper's type reduction at each level of ``alphas``, sampled at
    /// ``samples`` uniform parameters (docs/method.md §7): what the figure
    /// of the distance against alpha draws, for a hundred levels at once.
    /// ``max`` and ``rms`` are those of the samples (the trapezoidal rule);
    /// ``solve(alpha).distance`` gives the exact ones of one level.
    ///
    /// Parameters
    /// ----------
    /// alphas : float or array_like
    ///     The levels, each in [0, 1].
    /// samples : int, optional
    ///     Uniform parameters over the domain (at least 2, default 1001).
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"alpha"``, ``"max"``, ``"rms"``: arrays of shape ``(L,)``;
    ///     ``"distance"``: ``(L, samples)``, ``‖D(t) − C(t)‖`` at each level.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])
    /// >>> s = np.array([[[-1.0, 2.0], [0.0, 0.0]], [[-1.0, 2.0], [0.0, 0.0]]])
    /// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0 * s,
    /// ...                   c[..., None] + 0 * s, lower_height=1.0, degree=1)
    /// >>> d = line.distance_sweep([0.0, 1.0], samples=5)
    /// >>> d["distance"].shape, [round(float(m), 12) for m in d["max"]]
    /// ((2, 5), [0.111111111111, 0.0])
    #[pyo3(signature = (alphas, samples=None), text_signature = "($self, alphas, samples=1001)")]
    fn distance_sweep<'py>(
        &self, py: Python<'py>, alphas: &Obj<'py>, samples: Option<&Obj<'py>>,
    ) -> DictResult<'py> {
        crate::distance_sweep::distance_sweep(py, &self.0, alphas, samples)
    }

    /// The membership grades of the cell centres of a regular grid over a
    /// plane curve: the footprint of uncertainty as maps, for
    /// ``matplotlib.pyplot.pcolormesh`` or ``imshow``. Each value is the
    /// grade of its cell's centre to within the change of the grade over
    /// half a cell.
    ///
    /// Parameters
    /// ----------
    /// x_range, y_range : (float, float)
    ///     The grid's extent, ``lo < hi``.
    /// shape : int or (int, int)
    ///     The cells ``(columns, rows)`` along x and y (one int: as many
    ///     both ways); at most 4096 × 4096 cells.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"xs"`` ``(columns,)`` and ``"ys"`` ``(rows,)``: the cell centres;
    ///     ``"upper"``, ``"primary"``, ``"lower"``: ``(rows, columns)``, row
    ///     ``j`` at ``ys[j]``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])
    /// >>> s = np.array([-1.0, 1.0])
    /// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s,
    /// ...                   c[..., None] + 0.25 * s, lower_height=0.5, degree=1)
    /// >>> g = line.membership_grid((-2.0, 6.0), (-2.0, 2.0), (80, 40))
    /// >>> g["xs"].shape, g["ys"].shape, g["upper"].shape
    /// ((80,), (40,), (40, 80))
    fn membership_grid<'py>(
        &self, py: Python<'py>, x_range: &Obj<'py>, y_range: &Obj<'py>, shape: &Obj<'py>,
    ) -> DictResult<'py> {
        crate::set::curve_membership_grid(py, &self.0, x_range, y_range, shape)
    }

    /// The picture in a notebook: stage 1 (the fuzzy control points, the
    /// seven layer curves and the regions at level 0), drawn by the figure
    /// code of ``t2spline plot``, as inline SVG under a short table; a large
    /// curve is drawn thinned and the figure says so. The table says
    /// where the weights are fuzzy.
    fn _repr_html_(&self) -> PyResult<String> {
        use crate::dim::ToModel as _;
        let mut rows = self.facts().rows();
        if by_dim!(&self.0, |c| c.weight_numbers().is_some()) {
            rows.push(("weights", "fuzzy (docs/method.md §16)".to_owned()));
        }
        crate::picture::first_stage_page(self.0.to_model()?, &rows)
    }

    /// ``FuzzyCurve(dimension=…, …, domain=(a, b))``, with
    /// ``fuzzy_weights=True`` at the end where the weights are fuzzy.
    fn __repr__(&self) -> String {
        let repr = self.facts().repr("FuzzyCurve", None);
        match by_dim!(&self.0, |c| c.weight_numbers().is_some()) {
            true => format!("{}, fuzzy_weights=True)", repr.strip_suffix(')').unwrap_or(&repr)),
            false => repr,
        }
    }
}));
