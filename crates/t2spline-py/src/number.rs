//! `FuzzyNumber` and `AlphaCut`: one normal triangular type-2 fuzzy number
//! (SPEC §1), its alpha-cut (§2), type reduction (§3) and defuzzification
//! (§4), and its membership functions for plotting.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::{Alpha, AlphaCut, Membership, Nt2Number};

use crate::arrays::{array, floats};
use crate::errors::core_error;

/// A normal triangular type-2 fuzzy number (see the stub for the docs).
#[pyclass(frozen, eq, module = "t2spline", name = "FuzzyNumber")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PyFuzzyNumber(pub(crate) Nt2Number);

/// A level alpha from Python, checked.
pub(crate) fn alpha(value: f64) -> PyResult<Alpha> {
    Alpha::try_new(value).map_err(core_error)
}

fn pair(i: t2spline::Interval) -> (f64, f64) {
    (i.left(), i.right())
}

#[pymethods]
impl PyFuzzyNumber {
    #[new]
    #[pyo3(signature = (crisp, upper, primary, lower, lower_height))]
    fn new(
        crisp: f64,
        upper: [f64; 2],
        primary: [f64; 2],
        lower: [f64; 2],
        lower_height: f64,
    ) -> PyResult<Self> {
        Nt2Number::try_new(crisp, upper, primary, lower, lower_height)
            .map(PyFuzzyNumber)
            .map_err(core_error)
    }

    #[getter]
    fn crisp(&self) -> f64 {
        self.0.crisp()
    }

    #[getter]
    fn upper(&self) -> (f64, f64) {
        pair(self.0.upper())
    }

    #[getter]
    fn primary(&self) -> (f64, f64) {
        pair(self.0.primary())
    }

    #[getter]
    fn lower(&self) -> (f64, f64) {
        pair(self.0.lower())
    }

    #[getter]
    fn lower_height(&self) -> f64 {
        self.0.height().get()
    }

    fn alpha_cut(&self, alpha: f64) -> PyResult<PyAlphaCut> {
        let a = self::alpha(alpha)?;
        Ok(PyAlphaCut {
            alpha: a.get(),
            cut: self.0.alpha_cut(a),
        })
    }

    fn type_reduce(&self, alpha: f64) -> PyResult<(f64, f64, f64)> {
        Ok(self.alpha_cut(alpha)?.type_reduce())
    }

    fn defuzzify(&self, alpha: f64) -> PyResult<f64> {
        Ok(self
            .0
            .alpha_cut(self::alpha(alpha)?)
            .type_reduce()
            .defuzzify())
    }

    #[pyo3(signature = (x, which = "upper"))]
    fn membership<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        which: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        let which = match which {
            "upper" => Membership::Upper,
            "primary" => Membership::Primary,
            "lower" => Membership::Lower,
            other => {
                return Err(PyValueError::new_err(format!(
                    "which: expected 'upper', 'primary' or 'lower', got {other:?}"
                )))
            }
        };
        let x = floats(x, "x")?;
        let values = x.data.iter().map(|&v| self.0.membership(which, v)).collect();
        array(py, values, &x.shape)
    }

    fn __repr__(&self) -> String {
        format!(
            "FuzzyNumber(crisp={:?}, upper={:?}, primary={:?}, lower={:?}, lower_height={:?})",
            self.crisp(),
            self.upper(),
            self.primary(),
            self.lower(),
            self.lower_height()
        )
    }
}

/// The alpha-cut of a [`PyFuzzyNumber`] (see the stub for the docs).
#[pyclass(frozen, module = "t2spline", name = "AlphaCut")]
#[derive(Clone, Debug)]
pub(crate) struct PyAlphaCut {
    alpha: f64,
    cut: AlphaCut,
}

#[pymethods]
impl PyAlphaCut {
    #[getter]
    fn alpha(&self) -> f64 {
        self.alpha
    }

    #[getter]
    fn crisp(&self) -> f64 {
        self.cut.crisp()
    }

    #[getter]
    fn upper(&self) -> (f64, f64) {
        pair(self.cut.upper())
    }

    #[getter]
    fn primary(&self) -> (f64, f64) {
        pair(self.cut.primary())
    }

    #[getter]
    fn lower(&self) -> Option<(f64, f64)> {
        self.cut.lower().map(pair)
    }

    fn type_reduce(&self) -> (f64, f64, f64) {
        let t = self.cut.type_reduce();
        (t.left(), t.crisp(), t.right())
    }

    fn __repr__(&self) -> String {
        format!(
            "AlphaCut(alpha={:?}, crisp={:?}, upper={:?}, primary={:?}, lower={:?})",
            self.alpha,
            self.crisp(),
            self.upper(),
            self.primary(),
            self.lower().map_or("None".to_owned(), |l| format!("{l:?}"))
        )
    }
}
