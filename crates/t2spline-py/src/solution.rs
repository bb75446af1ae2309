//! `Solution`: stages 2–4 of Algorithm 1.1 at one level alpha (docs/method.md §7) —
//! the alpha-cut, type-reduced and defuzzified control points (shared with
//! `SurfaceSolution`, `stage_methods.rs`), their curves, their samples and
//! the distance between the crisp and the defuzzified curve.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::array;
use crate::classes::{PyFuzzyCurve, PyNurbsCurve, PySolution};
use crate::construct::{layer, side};
use crate::dim::by_dim;
use crate::errors::compute;
use crate::sample::{check_output, ParamsArg};
use crate::stage_methods::{stage_methods, stage_samples, stage_samples_dict};

/// One weight per control point as an array of shape `(n,)`.
fn weight_array(py: Python<'_>, weights: Vec<f64>) -> PyResult<Bound<'_, PyAny>> {
    let n = weights.len();
    array(py, weights, &[n])
}

stage_methods!(PySolution, fuzzy_curve, "n" {

    /// Pickling and copying: ``FuzzyCurve.solve`` again at this alpha and type
    /// reduction, the same computation and so an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        let uses_alpha = by_dim!(&slf.get().0, |s| s.type_reduction().uses_alpha());
        crate::pickle::by_solve(slf, "fuzzy_curve", uses_alpha)
    }
    /// The fuzzy curve (stage 1) this solves.
    #[getter]
    fn fuzzy_curve(&self) -> PyFuzzyCurve {
        by_dim!(&self.0, |s| s.fuzzy_curve().clone().into())
    }

    /// The curve through one alpha-cut layer; ``None`` for a lower layer when
    /// some number has no lower cut at this level.
    fn alpha_cut_curve(&self, layer: &Bound<'_, PyAny>) -> PyResult<Option<PyNurbsCurve>> {
        let l = self::layer(layer, "layer")?;
        Ok(by_dim!(&self.0, |s| s.alpha_cut_curve(l).map(Into::into)))
    }

    /// The curve through the left or the right type-reduced values.
    fn type_reduced_curve(&self, side: &Bound<'_, PyAny>) -> PyResult<PyNurbsCurve> {
        let side = self::side(side)?;
        Ok(by_dim!(&self.0, |s| s.type_reduced_curve(side).into()))
    }

    /// The crisp type-2 solution: the curve through the defuzzified control
    /// points.
    fn defuzzified_curve(&self) -> PyNurbsCurve {
        by_dim!(&self.0, |s| s.defuzzified_curve().into())
    }

    /// Stage 2: the weights of ``alpha_cut_curve(layer)``, shape ``(n,)``:
    /// with fuzzy weights (docs/method.md §16) the layer's values of the
    /// weights' alpha-cuts, else the curve's weights; ``None`` where that
    /// curve is ``None`` (a lower layer with some point or weight cut above
    /// its lower height).
    ///
    /// Examples
    /// --------
    /// >>> w = FuzzyNumber(2.0, upper=(1.0, 3.0), primary=(1.5, 2.5))
    /// >>> line = FuzzyCurve([[0.0, 0.0], [1.0, 1.0]], weights=[1.0, w], degree=1)
    /// >>> s = line.solve(0.5)
    /// >>> s.alpha_cut_weights("upper_right").tolist()        # 3 cut at 0.5 toward 2
    /// [1.0, 2.5]
    /// >>> s.type_reduced_weights("left").tolist(), s.defuzzified_weights().tolist()
    /// ([1.0, 1.75], [1.0, 2.0])
    fn alpha_cut_weights<'py>(
        &self,
        py: Python<'py>,
        layer: &Bound<'py, PyAny>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        let l = self::layer(layer, "layer")?;
        let weights = by_dim!(&self.0, |s| match s.alpha_cut_weights(l) {
            Some(fuzzy) => fuzzy,
            None => s
                .alpha_cut_layer(l)
                .map(|_| s.fuzzy_curve().weights().to_vec()),
        });
        weights.map(|w| weight_array(py, w)).transpose()
    }

    /// Stage 3: the weights of ``type_reduced_curve(side)``, shape ``(n,)``:
    /// with fuzzy weights their left or right type-reduced values (each
    /// weight reduced as a coordinate is, docs/method.md §16), else the
    /// curve's weights.
    fn type_reduced_weights<'py>(
        &self,
        py: Python<'py>,
        side: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let side = self::side(side)?;
        let weights = by_dim!(&self.0, |s| s
            .type_reduced_weights(side)
            .unwrap_or_else(|| s.fuzzy_curve().weights().to_vec()));
        weight_array(py, weights)
    }

    /// Stage 4: the weights of ``defuzzified_curve()``, shape ``(n,)``: with
    /// fuzzy weights their defuzzified values (docs/method.md §16), else the
    /// curve's weights.
    fn defuzzified_weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let weights = by_dim!(&self.0, |s| s
            .defuzzified_weights()
            .unwrap_or_else(|| s.fuzzy_curve().weights().to_vec()));
        weight_array(py, weights)
    }

    /// The crisp curve, through the crisp control points.
    fn crisp_curve(&self) -> PyNurbsCurve {
        by_dim!(&self.0, |s| s.crisp_curve().into())
    }

    /// The distance ``d(t) = |D(t) − C(t)|`` between the defuzzified curve
    /// ``D`` and the crisp curve ``C`` at equal ``t`` (docs/method.md §7)::
    ///
    ///     max = max_t d(t)   (at t = max_at),   rms = sqrt( 1/(b − a) ∫ d(t)² dt )
    ///
    /// properties of the curves, not of a sampling: a scan per knot span
    /// refined by golden-section search, and Gauss–Legendre quadrature per
    /// span. Zero for symmetric spreads. The numbers of ``run``'s
    /// ``error`` for the same job, level and type reduction, bit for bit.
    fn distance<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = by_dim!(&self.0, |s| compute(py, || Ok(s.distance())))?;
        let out = PyDict::new(py);
        out.set_item("max", d.max)?;
        out.set_item("max_at", d.max_at)?;
        out.set_item("rms", d.rms)?;
        Ok(out)
    }

    /// The curves of stages 2–4 at many parameters by the sampling engine.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"params"`` (shape ``(m,)``); ``"alpha_cut"``: the six alpha-cut
    ///     layer curves (shape ``(m, d)``, ``None`` for an absent lower layer);
    ///     ``"type_reduced"``: ``"left"`` and ``"right"``; and
    ///     ``"defuzzified"`` (shape ``(m, d)``): the keys of the result
    ///     file's ``curves``. The flat keys of earlier releases
    ///     (``"type_reduced_left"``) still answer, with a
    ///     ``DeprecationWarning``.
    fn sample<'py>(
        &self,
        py: Python<'py>,
        params: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let params = ParamsArg::extract(params, "params")?;
        let n = params.len();
        check_output(n, 9 * self.0.dimension(), "params")?;
        let out = PyDict::new(py);
        let domain = by_dim!(&self.0, |s| s.fuzzy_curve().domain());
        out.set_item("params", array(py, params.values(domain)?, &[n])?)?;
        by_dim!(&self.0, |s| {
            let stages = compute(py, || s.sample_stages(params.params()))?;
            stage_samples(&out, &stages, &[n])
        })?;
        stage_samples_dict(out)
    }

    /// The picture in a notebook: the four stages (fuzzy curve, alpha-cut,
    /// type-reduced, defuzzified with the largest distance magnified),
    /// drawn by the figure code of ``t2spline plot`` as it draws this
    /// solution's job, as inline SVG under a table of alpha, the type
    /// reduction and the distance; a large curve is drawn thinned and the
    /// figures say so.
    fn _repr_html_(&self) -> PyResult<String> {
        use crate::dim::ToModel as _;
        let (fuzzy, alpha, method, d): (crate::dim::ByDim<crate::dim::Fuzzy>, _, _, _) =
            by_dim!(&self.0, |s| (
                s.fuzzy_curve().clone().into(),
                s.alpha(),
                s.type_reduction(),
                s.distance()
            ));
        let figures = crate::picture::stage_figures(
            fuzzy.to_model()?,
            alpha,
            method,
            t2spline_plot::Stages::All,
        )?;
        let rows = [
            ("alpha", format!("{:?}", alpha.get())),
            ("type reduction", method.name().to_owned()),
            ("distance max", format!("{:?} at t = {:?}", d.max, d.max_at)),
            ("distance rms", format!("{:?}", d.rms)),
        ];
        Ok(crate::picture::page(&figures, &rows))
    }

    fn __repr__(&self) -> String {
        by_dim!(&self.0, |s| format!(
            "Solution(alpha={:?}, control_points=({}, {}), degree={})",
            s.alpha().get(),
            s.fuzzy_curve().points().len(),
            self.0.dimension(),
            s.fuzzy_curve().degree(),
        ))
    }
});
