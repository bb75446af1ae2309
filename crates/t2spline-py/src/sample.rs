//! Where and how to evaluate: parameters given as a count or an array,
//! functions of `t` evaluated at every value of an array, and output buffers
//! that the sampling engine writes into and numpy then owns.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyInt};
use t2spline::sampling::Params;

use crate::arrays::{array, floats, shape_text};
use crate::errors::{compute, core_error};

/// The most bytes the arrays of one sampling call may take (8 GiB, the limit
/// of `t2spline bench`): larger requests are refused before anything is
/// allocated.
pub(crate) const MAX_OUTPUT_BYTES: u64 = t2spline::bench::MAX_OUTPUT_BYTES;

/// Where to sample: a count of uniform parameters over the domain (an `int`),
/// or the parameters themselves (a 1-D array).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ParamsArg {
    /// `n` uniform parameters `tᵢ = a + (b − a)·i/(n − 1)`.
    Count(usize),
    /// The given parameters, in any order.
    Given(Vec<f64>),
}

impl ParamsArg {
    /// Reads `arg`: an `int` is a count, anything else a 1-D array of
    /// parameters.
    ///
    /// # Errors
    /// `ValueError` for a negative count or an array that is not 1-D; the
    /// errors of [`floats`].
    pub(crate) fn extract(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<ParamsArg> {
        if arg.is_instance_of::<PyInt>() && !arg.is_instance_of::<PyBool>() {
            let n: i128 = arg.extract()?;
            return usize::try_from(n).map(ParamsArg::Count).map_err(|_| {
                PyValueError::new_err(format!(
                    "{name}: a count of uniform parameters must be at least 0, got {n}"
                ))
            });
        }
        let f = floats(arg, name)?;
        if f.shape.len() != 1 {
            return Err(PyValueError::new_err(format!(
                "{name}: expected a count (int) or a 1-D array of parameters, got shape {}",
                shape_text(&f.shape)
            )));
        }
        Ok(ParamsArg::Given(f.data))
    }

    /// The parameters for the sampling engine.
    pub(crate) fn params(&self) -> Params<'_> {
        match self {
            ParamsArg::Count(n) => Params::Uniform(*n),
            ParamsArg::Given(t) => Params::Given(t),
        }
    }

    /// The parameters themselves: the uniform ones over `domain` for a count.
    pub(crate) fn values(&self, domain: t2spline::Domain) -> PyResult<Vec<f64>> {
        match self {
            ParamsArg::Count(n) => domain.uniform(*n).map_err(core_error),
            ParamsArg::Given(t) => Ok(t.clone()),
        }
    }

    /// The number of parameters.
    pub(crate) fn len(&self) -> usize {
        self.params().len()
    }
}

/// Refuses an output of `params × per_param` values beyond
/// [`MAX_OUTPUT_BYTES`], before anything is allocated: a request beyond the
/// machine must be an error, not an abort.
///
/// # Errors
/// `ValueError` naming `name` and the size.
pub(crate) fn check_output(params: usize, per_param: usize, name: &str) -> PyResult<()> {
    let bytes = (params as u128) * (per_param as u128) * 8;
    if bytes > u128::from(MAX_OUTPUT_BYTES) {
        return Err(PyValueError::new_err(format!(
            "{name}: {params} parameters would take {:.1} GB of output, more than the limit of {:.1} GB",
            bytes as f64 / 1e9,
            MAX_OUTPUT_BYTES as f64 / 1e9
        )));
    }
    Ok(())
}

/// A zeroed buffer of `params × per_param` values for the engine to write
/// into, within [`check_output`]'s limit.
///
/// # Errors
/// The error of [`check_output`].
pub(crate) fn output_buffer(params: usize, per_param: usize, name: &str) -> PyResult<Vec<f64>> {
    check_output(params, per_param, name)?;
    // Zeroed memory comes from the system untouched (calloc), so the engine's
    // writes are the first: no extra pass over the output.
    Ok(vec![0.0; params * per_param])
}

/// `buffer` cut into `count` slices of `len` values (empty slices for
/// `len = 0`): one per channel of the sampling engine.
pub(crate) fn channels(buffer: &mut [f64], count: usize, len: usize) -> Vec<&mut [f64]> {
    if len == 0 {
        return (0..count).map(|_| <&mut [f64]>::default()).collect();
    }
    buffer.chunks_mut(len).collect()
}

/// `f(t, out)` at every value of `t` (a number, or an array of any shape),
/// each call appending `tail`'s product of values to `out`; the result has
/// shape `t.shape + tail`, and is a `float` for a number when `tail` is
/// empty. Runs with the GIL released.
///
/// # Errors
/// The errors of reading `t`; the first error of `f`.
pub(crate) fn at_params<'py>(
    py: Python<'py>,
    t: &Bound<'py, PyAny>,
    tail: &[usize],
    f: impl Fn(f64, &mut Vec<f64>) -> Result<(), t2spline::Error> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let t = floats(t, "t")?;
    let width = tail.iter().product::<usize>();
    let values = compute(py, || {
        let mut out = Vec::with_capacity(t.data.len() * width);
        for &v in &t.data {
            f(v, &mut out)?;
        }
        Ok(out)
    })?;
    if t.shape.is_empty() && tail.is_empty() {
        return Ok(values[0].into_pyobject(py)?.into_any());
    }
    let shape: Vec<usize> = t.shape.iter().chain(tail).copied().collect();
    array(py, values, &shape)
}
