//! Fuzzy weights of a curve (docs/method.md §16) from Python and back: the
//! `weights` argument of `FuzzyCurve` as crisp weights or as one
//! `FuzzyNumber` (or plain number, a crisp weight) per control point, and
//! the numbers as a list of `FuzzyNumber`.

use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use t2spline::{Error, Nt2Number};

use crate::arrays::optional_vector;
use crate::errors::core_error;
use crate::keyword;
use crate::number::PyFuzzyNumber;

/// The weights of a curve as given: crisp values, or numbers.
pub(crate) enum WeightsArg {
    /// One crisp weight per control point (`None`: all 1).
    Crisp(Option<Vec<f64>>),
    /// One fuzzy number per control point (`FuzzyCurve::with_weight_numbers`).
    Numbers(Vec<Nt2Number>),
}

/// Whether `arg` is a list, a tuple or a numpy array of objects: the forms
/// that may hold `FuzzyNumber`s.
fn may_hold_numbers(arg: &Bound<'_, PyAny>) -> bool {
    if arg.is_instance_of::<PyList>() || arg.is_instance_of::<PyTuple>() {
        return true;
    }
    arg.getattr("dtype")
        .and_then(|d| d.getattr("kind"))
        .and_then(|k| k.extract::<String>())
        .is_ok_and(|k| k == "O")
}

/// A crisp weight `value` as a number whose every value is `value`, as a
/// job's bare number is; a value that is no number at all (NaN, infinite)
/// is refused as the core refuses that weight, naming `weights[i]`.
fn crisp_number(value: f64, index: usize) -> PyResult<Nt2Number> {
    if !value.is_finite() {
        return Err(core_error(Error::Weight { index, value }));
    }
    Nt2Number::try_new(value, [value; 2], [value; 2], [value; 2], 1.0).map_err(core_error)
}

impl WeightsArg {
    /// The `weights` argument: numbers where it is a sequence with a
    /// `FuzzyNumber` in it (its plain numbers crisp weights), crisp
    /// weights otherwise.
    ///
    /// # Errors
    /// The errors of [`optional_vector`] for crisp weights; `TypeError`
    /// naming `weights[i]` for an entry that is neither a `FuzzyNumber`
    /// nor a real number; `ValueError` naming `weights[i]` for NaN or
    /// infinity.
    pub(crate) fn read(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let Some(arg) = arg.filter(|a| !a.is_none() && may_hold_numbers(a)) else {
            return optional_vector(arg, "weights").map(WeightsArg::Crisp);
        };
        let items: Vec<Bound<'_, PyAny>> = arg.try_iter()?.collect::<PyResult<_>>()?;
        if !items.iter().any(|x| x.is_instance_of::<PyFuzzyNumber>()) {
            return optional_vector(Some(arg), "weights").map(WeightsArg::Crisp);
        }
        items
            .iter()
            .enumerate()
            .map(|(i, x)| match x.cast::<PyFuzzyNumber>() {
                Ok(n) => Ok(n.get().0),
                Err(_) => crisp_number(keyword::real(x, &format!("weights[{i}]"))?, i),
            })
            .collect::<PyResult<_>>()
            .map(WeightsArg::Numbers)
    }
}

/// The fuzzy weights of a curve as a list of `FuzzyNumber`, or `None`
/// where they are crisp.
pub(crate) fn number_list(numbers: Option<&[Nt2Number]>) -> Option<Vec<PyFuzzyNumber>> {
    numbers.map(|w| w.iter().map(|&x| PyFuzzyNumber(x)).collect())
}
