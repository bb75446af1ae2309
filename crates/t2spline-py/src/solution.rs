//! `Solution`: stages 2–4 of Algorithm 1.1 at one level alpha (SPEC §7) —
//! the alpha-cut, type-reduced and defuzzified control points, their curves,
//! their samples and the distance between the crisp and the defuzzified
//! curve.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::{Layer, Side};

use crate::arrays::{array, columns_array, rows_array};
use crate::dim::{by_dim, ByDim, Solved};
use crate::errors::compute;
use crate::fuzzy_curve::{layer, PyFuzzyCurve};
use crate::nurbs_curve::PyNurbsCurve;
use crate::sample::ParamsArg;

/// Stages 2–4 of Algorithm 1.1 at one level alpha (SPEC §7, paper Figs.
/// 5.2–5.4), from ``FuzzyCurve.solve(alpha)``.
///
/// 2. alpha-cut control points (``alpha_cut``) and their curves;
/// 3. type-reduced control points ``(left, crisp, right)``
///    (``type_reduced_left``, ``type_reduced_right``) and the curves through
///    the left and the right values;
/// 4. defuzzified control points ``(left + crisp + right)/3``
///    (``defuzzified``), the crisp type-2 solution curve through them, and its
///    distance to the crisp curve (``distance``).
///
/// The stages act on the control points, number by number, as Algorithm 1.1
/// does; with one lower height for every number this equals applying them to
/// the curve (SPEC §6).
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> c = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
/// >>> s = np.array([-1.0, 1.0])               # symmetric spreads
/// >>> curve = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s, c[..., None] + 0.2 * s,
/// ...                    lower_height=0.5, degree=2)
/// >>> sol = curve.solve(0.3)
/// >>> bool(np.array_equal(sol.defuzzified, sol.crisp))   # symmetric: no shift
/// True
/// >>> sol.distance()["max"]
/// 0.0
#[pyclass(frozen, eq, module = "t2spline", name = "Solution")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PySolution(pub(crate) ByDim<Solved>);

/// A side from its name.
fn side(name: &str) -> PyResult<Side> {
    match name {
        "left" => Ok(Side::Left),
        "right" => Ok(Side::Right),
        other => Err(pyo3::exceptions::PyValueError::new_err(format!(
            "side: expected 'left' or 'right', got {other:?}"
        ))),
    }
}

/// The six non-crisp layers, in SPEC order.
fn six_layers() -> impl Iterator<Item = Layer> {
    Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp)
}

#[pymethods]
impl PySolution {
    /// The level alpha.
    #[getter]
    fn alpha(&self) -> f64 {
        by_dim!(&self.0, |s| s.alpha().get())
    }

    /// The fuzzy curve (stage 1) this solves.
    #[getter]
    fn fuzzy_curve(&self) -> PyFuzzyCurve {
        by_dim!(&self.0, |s| s.fuzzy_curve().clone().into())
    }

    /// The crisp control points, shape ``(n, d)``.
    #[getter]
    fn crisp<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |s| rows_array(
            py,
            s.fuzzy_curve().points().iter().map(|p| p.crisp()).collect()
        ))
    }

    /// Stage 2: the alpha-cut ends of every control point, a dict of the six
    /// non-crisp layer names to arrays of shape ``(n, d)``. A lower end is NaN
    /// where alpha is above that number's lower height (the cut is absent,
    /// SPEC §2.2).
    #[getter]
    fn alpha_cut<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for l in six_layers() {
            // An absent lower cut (alpha above that number's height) is NaN.
            let rows = by_dim!(&self.0, |s| s
                .alpha_cut_points()
                .iter()
                .flat_map(|cuts| cuts.iter().map(|c| c.layer(l).unwrap_or(f64::NAN)))
                .collect::<Vec<_>>());
            let n = by_dim!(&self.0, |s| s.alpha_cut_points().len());
            out.set_item(l.name(), array(py, rows, &[n, self.0.dimension()])?)?;
        }
        Ok(out)
    }

    /// Stage 3: the left type-reduced control points, shape ``(n, d)``.
    #[getter]
    fn type_reduced_left<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |s| rows_array(py, s.type_reduced_side(Side::Left)))
    }

    /// Stage 3: the right type-reduced control points, shape ``(n, d)``.
    #[getter]
    fn type_reduced_right<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |s| rows_array(
            py,
            s.type_reduced_side(Side::Right)
        ))
    }

    /// Stage 4: the defuzzified control points, shape ``(n, d)``.
    #[getter]
    fn defuzzified<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |s| rows_array(py, s.defuzzified_points().to_vec()))
    }

    /// The curve through one alpha-cut layer; ``None`` for a lower layer when
    /// some number has no lower cut at this level.
    fn alpha_cut_curve(&self, layer: &str) -> PyResult<Option<PyNurbsCurve>> {
        let l = self::layer(layer, "layer")?;
        Ok(by_dim!(&self.0, |s| s.alpha_cut_curve(l).map(Into::into)))
    }

    /// The curve through the left or the right type-reduced values.
    fn type_reduced_curve(&self, side: &str) -> PyResult<PyNurbsCurve> {
        let side = self::side(side)?;
        Ok(by_dim!(&self.0, |s| s.type_reduced_curve(side).into()))
    }

    /// The crisp type-2 solution: the curve through the defuzzified control
    /// points.
    fn defuzzified_curve(&self) -> PyNurbsCurve {
        by_dim!(&self.0, |s| s.defuzzified_curve().into())
    }

    /// The crisp curve, through the crisp control points.
    fn crisp_curve(&self) -> PyNurbsCurve {
        by_dim!(&self.0, |s| s.crisp_curve().into())
    }

    /// The distance ``d(t) = |D(t) − C(t)|`` between the defuzzified curve
    /// ``D`` and the crisp curve ``C`` at equal ``t`` (SPEC §7)::
    ///
    ///     max = max_t d(t)   (at t = max_at),   rms = sqrt( 1/(b − a) ∫ d(t)² dt )
    ///
    /// properties of the curves, not of a sampling: a scan per knot span
    /// refined by golden-section search, and Gauss–Legendre quadrature per
    /// span. Zero for symmetric spreads.
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
    ///     ``"type_reduced_left"``, ``"type_reduced_right"`` and
    ///     ``"defuzzified"`` (shape ``(m, d)``).
    fn sample<'py>(
        &self,
        py: Python<'py>,
        params: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let params = ParamsArg::extract(params, "params")?;
        crate::sample::check_output(params.len(), 9 * self.0.dimension(), "params")?;
        let out = PyDict::new(py);
        let domain = by_dim!(&self.0, |s| s.fuzzy_curve().domain());
        by_dim!(&self.0, |s| {
            let stages = compute(py, || s.sample_stages(params.params()))?;
            out.set_item(
                "params",
                array(py, params.values(domain)?, &[params.len()])?,
            )?;
            let cuts = PyDict::new(py);
            for l in six_layers() {
                match stages.alpha_cut(l) {
                    Some(c) => cuts.set_item(l.name(), columns_array(py, c.coords())?)?,
                    None => cuts.set_item(l.name(), py.None())?,
                }
            }
            out.set_item("alpha_cut", cuts)?;
            let left = stages.type_reduced(Side::Left);
            let right = stages.type_reduced(Side::Right);
            out.set_item("type_reduced_left", columns_array(py, left.coords())?)?;
            out.set_item("type_reduced_right", columns_array(py, right.coords())?)?;
            out.set_item(
                "defuzzified",
                columns_array(py, stages.defuzzified().coords())?,
            )?;
            PyResult::Ok(())
        })?;
        Ok(out)
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
}
