//! `FuzzyCurve`: stage 1 of Algorithm 1.1 (SPEC §6–§7), a rational B-spline
//! whose control points are fuzzy points; its seven layer curves sampled by
//! the engine straight into one numpy buffer, its operations on all layers
//! at once, and `solve` for stages 2–4.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use t2spline::{FuzzyCurve, Layer};

use crate::arrays::{array, coords_last, optional_vector};
use crate::classes::{PyFuzzyCurve, PyNurbsCurve, PySolution};
use crate::construct::{degree, layer, FuzzyArrays};
use crate::curve_methods::curve_methods;
use crate::dim::by_dim;
use crate::errors::compute;
use crate::fuzzy_methods::{fuzzy_methods, index, numbers};
use crate::keyword;
use crate::sample::{at_params, channels, output_buffer, ParamsArg};

fuzzy_methods!("curve", "n", PySolution => curve_methods!(PyFuzzyCurve {
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
        degree: Option<&Bound<'_, PyAny>>,
        order: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let (degree, order) = (
            keyword::opt_int(degree, "degree")?,
            keyword::opt_int(order, "order")?,
        );
        let data = FuzzyArrays::read([crisp, upper, primary, lower, lower_height], 1)?;
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

    /// The fuzzy control point ``index``: one ``FuzzyNumber`` per coordinate.
    fn point<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let n = by_dim!(&self.0, |c| c.points().len());
        let i = self::index(keyword::int(index, "index")?, n, "index")?;
        by_dim!(&self.0, |c| numbers(py, &c.points()[i]))
    }

    /// The layer curve through one value of every control point, as a
    /// ``NurbsCurve`` (``"crisp"``: the crisp curve).
    fn layer_curve(&self, layer: &Bound<'_, PyAny>) -> PyResult<PyNurbsCurve> {
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
        let layers = coords_last(py, buffer, &[7], d, &[n])?;
        for l in Layer::ALL {
            out.set_item(l.name(), layers.get_item(l.index())?)?;
        }
        Ok(out)
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
}));
