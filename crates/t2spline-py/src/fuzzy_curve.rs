//! `FuzzyCurve`: stage 1 of Algorithm 1.1 (SPEC §6–§7), a rational B-spline
//! whose control points are fuzzy points; its seven layer curves sampled by
//! the engine straight into one numpy buffer, its operations on all layers
//! at once, and `solve` for stages 2–4.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use t2spline::{FuzzyCurve, Layer, Nt2Point};

use crate::arrays::{array, optional_vector, rows_array, transposed};
use crate::construct::{degree, FuzzyArrays};
use crate::curve_methods::curve_methods;
use crate::dim::{by_dim, ByDim, Fuzzy};
use crate::errors::compute;
use crate::number::{alpha, PyFuzzyNumber};
use crate::nurbs_curve::PyNurbsCurve;
use crate::run::{job_text, parse};
use crate::sample::{at_params, channels, output_buffer, ParamsArg};
use crate::solution::PySolution;

/// A normal type-2 fuzzy rational B-spline curve: stage 1 of Algorithm 1.1
/// (SPEC §6–§7, paper Def. 5.1 and Fig. 5.1).
///
/// The control points are fuzzy points, one fuzzy number (``FuzzyNumber``)
/// per coordinate. The seven *layer curves* go through one value of every
/// number, with the curve's weights and knots::
///
///     C_L(t) = Σᵢ wᵢ Nᵢ,ₚ(t) Pᵢ,L / Σᵢ wᵢ Nᵢ,ₚ(t),
///     L in upper_left, primary_left, lower_left, crisp, lower_right, primary_right, upper_right
///
/// and since the rational basis is non-negative and sums to 1, they keep the
/// order of the values at every ``t``.
///
/// Parameters
/// ----------
/// crisp : array_like, shape (n, d)
///     The crisp control points, ``d`` = 2 or 3.
/// upper, primary, lower : array_like, shape (n, d, 2)
///     The ``[left, right]`` feet of each number's triangles.
/// lower_height : float or array_like
///     ``h`` of every number: shape ``(n, d)``, or anything that broadcasts
///     to it (one number for all, ``(d,)`` one per coordinate, ``(n, 1)``
///     one per point).
/// weights : array_like, shape (n,), optional
///     Default: all 1.
/// knots : array_like, shape (n + degree + 1,), optional
///     Default: clamped uniform.
/// degree, order : int, optional
///     Exactly one of them; when both are left out, the degree follows from
///     the number of knots.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For a wrong dtype or shape (naming the argument and the shape
///     expected), NaN or infinity, and every rule of SPEC §1 and §6, naming
///     the place: ``points[2].y: the order lower.left <= crisp is broken: 2.1 > 2``.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> c = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
/// >>> spread = np.array([-0.6, 0.9])          # [left, right] offsets
/// >>> curve = FuzzyCurve(c, c[..., None] + spread, c[..., None] + 0.6 * spread,
/// ...                    c[..., None] + 0.3 * spread, lower_height=0.6, degree=2)
/// >>> curve.upper.shape, curve.lower_height.shape
/// ((4, 2, 2), (4, 2))
/// >>> s = curve.sample(5)
/// >>> s["upper_right"][2] - s["crisp"][2]     # the upper right spread at t = 0.5
/// array([0.9, 0.9])
#[pyclass(frozen, eq, module = "t2spline", name = "FuzzyCurve")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PyFuzzyCurve(pub(crate) ByDim<Fuzzy>);

impl From<FuzzyCurve<2>> for PyFuzzyCurve {
    fn from(curve: FuzzyCurve<2>) -> Self {
        PyFuzzyCurve(curve.into())
    }
}

impl From<FuzzyCurve<3>> for PyFuzzyCurve {
    fn from(curve: FuzzyCurve<3>) -> Self {
        PyFuzzyCurve(curve.into())
    }
}

/// A layer from its name (`"upper_left"`, …, `"crisp"`, …, `"upper_right"`).
///
/// # Errors
/// `ValueError` naming the argument and the names offered.
pub(crate) fn layer(name: &str, arg: &str) -> PyResult<Layer> {
    Layer::ALL
        .into_iter()
        .find(|l| l.name() == name)
        .ok_or_else(|| {
            let names: Vec<&str> = Layer::ALL.iter().map(|l| l.name()).collect();
            PyValueError::new_err(format!(
                "{arg}: expected one of {}, got {name:?}",
                names.join(", ")
            ))
        })
}

/// One value per control point and coordinate, `f(number)` each, as an
/// array of shape `(n, d)` followed by `tail`.
fn per_number<'py, const D: usize>(
    py: Python<'py>,
    points: &[Nt2Point<D>],
    tail: &[usize],
    f: impl Fn(&t2spline::Nt2Number, &mut Vec<f64>),
) -> PyResult<Bound<'py, PyAny>> {
    let mut values = Vec::new();
    for number in points.iter().flat_map(|p| p.coords()) {
        f(number, &mut values);
    }
    let shape: Vec<usize> = [points.len(), D].iter().chain(tail).copied().collect();
    array(py, values, &shape)
}

curve_methods!(PyFuzzyCurve {
    #[new]
    #[pyo3(signature = (crisp, upper, primary, lower, lower_height, weights=None, knots=None, *, degree=None, order=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        crisp: &Bound<'_, PyAny>,
        upper: &Bound<'_, PyAny>,
        primary: &Bound<'_, PyAny>,
        lower: &Bound<'_, PyAny>,
        lower_height: &Bound<'_, PyAny>,
        weights: Option<&Bound<'_, PyAny>>,
        knots: Option<&Bound<'_, PyAny>>,
        degree: Option<i64>,
        order: Option<i64>,
    ) -> PyResult<Self> {
        let data = FuzzyArrays::read(crisp, upper, primary, lower, lower_height)?;
        let weights = optional_vector(weights, "weights")?.unwrap_or_else(|| vec![1.0; data.n]);
        let knots = optional_vector(knots, "knots")?;
        let degree = self::degree(degree, order, knots.as_ref().map(Vec::len), data.n)?;
        compute(py, move || {
            Ok(by_dim!(data.points()?, |p| FuzzyCurve::try_new(
                degree, p, weights, knots
            )?
            .into()))
        })
    }

    /// The fuzzy curve of a job: a dict with the keys of a job file, or the
    /// path of one (validated as by ``t2spline run``).
    ///
    /// Raises
    /// ------
    /// JobError
    ///     For a job that breaks the rules; ``ValueError`` for a job that is not
    ///     a curve.
    #[staticmethod]
    fn from_job(py: Python<'_>, job: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (text, source) = job_text(job)?;
        let job = parse(py, &text, &source)?;
        ByDim::from_model(job.model)
            .map(PyFuzzyCurve)
            .ok_or_else(|| PyValueError::new_err(format!("{source}: the job is not a curve")))
    }

    /// The crisp values, shape ``(n, d)``.
    #[getter]
    fn crisp<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| per_number(py, c.points(), &[], |x, v| v
            .push(x.crisp())))
    }

    /// The upper feet ``[left, right]``, shape ``(n, d, 2)``.
    #[getter]
    fn upper<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| per_number(py, c.points(), &[2], |x, v| {
            v.extend([x.upper().left(), x.upper().right()]);
        }))
    }

    /// The primary feet ``[left, right]``, shape ``(n, d, 2)``.
    #[getter]
    fn primary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| per_number(py, c.points(), &[2], |x, v| {
            v.extend([x.primary().left(), x.primary().right()]);
        }))
    }

    /// The lower feet ``[left, right]``, shape ``(n, d, 2)``.
    #[getter]
    fn lower<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| per_number(py, c.points(), &[2], |x, v| {
            v.extend([x.lower().left(), x.lower().right()]);
        }))
    }

    /// The lower height of every number, shape ``(n, d)``.
    #[getter]
    fn lower_height<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| per_number(py, c.points(), &[], |x, v| v
            .push(x.height().get())))
    }

    /// The fuzzy control point ``index``: one ``FuzzyNumber`` per coordinate.
    fn point<'py>(&self, py: Python<'py>, index: i64) -> PyResult<Bound<'py, PyTuple>> {
        let n = by_dim!(&self.0, |c| c.points().len());
        let i = usize::try_from(index)
            .ok()
            .filter(|&i| i < n)
            .ok_or_else(|| {
                PyValueError::new_err(format!("index: {index} is outside [0, {}]", n - 1))
            })?;
        let numbers: Vec<PyFuzzyNumber> = by_dim!(&self.0, |c| c.points()[i]
            .coords()
            .iter()
            .map(|&x| PyFuzzyNumber(x))
            .collect());
        PyTuple::new(py, numbers)
    }

    /// The values of one layer at every control point, shape ``(n, d)``.
    fn layer_control_points<'py>(
        &self,
        py: Python<'py>,
        layer: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        let l = self::layer(layer, "layer")?;
        by_dim!(&self.0, |c| rows_array(
            py,
            c.points().iter().map(|p| p.layer(l)).collect()
        ))
    }

    /// The layer curve through one value of every control point, as a
    /// ``NurbsCurve`` (``"crisp"``: the crisp curve).
    fn layer_curve(&self, layer: &str) -> PyResult<PyNurbsCurve> {
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
    ///     Shape ``t.shape + (7, d)``, layers in SPEC order (``upper_left`` …
    ///     ``upper_right``, ``crisp`` at index 3).
    fn eval_layers<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let d = self.dimension();
        by_dim!(&self.0, |c| at_params(py, t, &[7, d], |v, out| {
            out.extend(c.eval_layers(v)?.as_array().iter().flatten());
            Ok(())
        }))
    }

    /// The seven layer curves at many parameters by the sampling engine: one
    /// power form of the rational basis per knot span for all layers, written
    /// straight into one numpy buffer (no per-point work in Python), the SPEC
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
    fn sample<'py>(
        &self,
        py: Python<'py>,
        params: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let params = ParamsArg::extract(params, "params")?;
        let (n, d) = (params.len(), self.dimension());
        let mut buffer = output_buffer(n, 7 * d, "params")?;
        let domain = by_dim!(&self.0, |c| c.domain());
        by_dim!(&self.0, |c| compute(py, || {
            c.sample_layers_into_slices(params.params(), &mut channels(&mut buffer, 7 * d, n))
        }))?;
        let out = PyDict::new(py);
        out.set_item("params", array(py, params.values(domain)?, &[n])?)?;
        // (layer, coordinate, parameter) seen as (layer, parameter, coordinate).
        let layers = transposed(&array(py, buffer, &[7, d, n])?, &[0, 2, 1])?;
        for l in Layer::ALL {
            out.set_item(l.name(), layers.get_item(l.index())?)?;
        }
        Ok(out)
    }

    /// Stages 2–4 at level ``alpha`` (SPEC §7): alpha-cut, type reduction and
    /// defuzzification of every control point; see ``Solution``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     If ``alpha`` is NaN or outside ``[0, 1]``.
    fn solve(&self, py: Python<'_>, alpha: f64) -> PyResult<PySolution> {
        let a = self::alpha(alpha)?;
        by_dim!(&self.0, |c| compute(py, || Ok(PySolution(
            c.solve(a).into()
        ))))
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.domain();
        by_dim!(&self.0, |c| {
            format!(
            "FuzzyCurve(dimension={}, degree={}, order={}, control_points=({}, {}), domain=({a:?}, {b:?}))",
            self.dimension(),
            c.degree(),
            c.order(),
            c.points().len(),
            self.dimension(),
        )
        })
    }
});
