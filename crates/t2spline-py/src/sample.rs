//! Where and how to evaluate: parameters given as a count or an array (one
//! list along a curve, two for a surface's grid `u × v`), functions of `t`
//! or of `(u, v)` evaluated at every value of arrays (broadcast as numpy
//! does), and output buffers that the sampling engine writes into and numpy
//! then owns.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyInt};
use rayon::prelude::*;
use t2spline::sampling::{Params, SampleBuffer};
use t2spline::{Error, Layer};

use crate::arrays::{array, broadcast_shape, coords_last, floats, shape_text};
use crate::errors::{compute, core_error};

/// The most bytes the arrays of one sampling call may take (8 GiB, the limit
/// of `t2spline bench`): larger requests are refused before anything is
/// allocated.
pub(crate) const MAX_OUTPUT_BYTES: u64 = t2spline::sampling::MAX_OUTPUT_BYTES;

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
            let n = crate::keyword::int(arg, name)?;
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

    /// The curve sampled at the parameters by `fill` with the GIL released:
    /// `fill(params, channels)` writes `lead`'s product of `d` channels of
    /// `len` values each (structure of arrays); seen as an array of shape
    /// `lead + (len, d)`, points last, without a copy.
    ///
    /// # Errors
    /// An output beyond the size limit (naming `params`); the error of
    /// `fill`.
    pub(crate) fn sample<'py>(
        &self,
        py: Python<'py>,
        [lead, d]: [&[usize]; 2],
        fill: impl FnOnce(Params<'_>, &mut [&mut [f64]]) -> Result<(), Error> + Send,
    ) -> PyResult<Bound<'py, PyAny>> {
        let n = self.len();
        let buffer = output_buffer(n, lead.iter().chain(d).product(), "params")?;
        filled(py, buffer, [lead, d, &[n]], |out| fill(self.params(), out))
    }
}

/// Refuses an output of `params × per_param` values beyond
/// [`MAX_OUTPUT_BYTES`], before anything is allocated: a request beyond the
/// machine must be an error, not an abort.
///
/// # Errors
/// `ValueError` naming `name` and the size.
pub(crate) fn check_output(params: usize, per_param: usize, name: &str) -> PyResult<()> {
    check_bytes(params as u128 * per_param as u128, || {
        format!("{name}: {params} parameters")
    })
}

/// Refuses `values` floats beyond [`MAX_OUTPUT_BYTES`]; `what()` says whose.
fn check_bytes(values: u128, what: impl FnOnce() -> String) -> PyResult<()> {
    let bytes = values * 8;
    if bytes > u128::from(MAX_OUTPUT_BYTES) {
        return Err(PyValueError::new_err(format!(
            "{} would take {:.1} GB of output, more than the limit of {:.1} GB",
            what(),
            bytes as f64 / 1e9,
            MAX_OUTPUT_BYTES as f64 / 1e9
        )));
    }
    Ok(())
}

/// A buffer of `params × per_param` values for the engine to overwrite, within [`check_output`]'s limit.
///
/// # Errors
/// The error of [`check_output`].
pub(crate) fn output_buffer(params: usize, per_param: usize, name: &str) -> PyResult<SampleBuffer> {
    check_output(params, per_param, name)?;
    // Untouched memory (a zeroed allocation, or a huge-page mapping when
    // large, perhaps a dropped one's): the engine's threads write first,
    // with no extra pass over it.
    Ok(SampleBuffer::for_overwrite(params * per_param))
}

/// Where to sample a surface: the grid `u × v`, each a count of uniform
/// parameters or the parameters themselves.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct GridArg {
    /// Along u.
    pub(crate) u: ParamsArg,
    /// Along v.
    pub(crate) v: ParamsArg,
}

impl GridArg {
    /// Reads `u` and `v` as [`ParamsArg::extract`] does.
    ///
    /// # Errors
    /// As [`ParamsArg::extract`], naming `u` or `v`.
    pub(crate) fn extract(u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(GridArg {
            u: ParamsArg::extract(u, "u")?,
            v: ParamsArg::extract(v, "v")?,
        })
    }

    /// `[su, sv]`: the parameters along u and along v.
    pub(crate) fn shape(&self) -> [usize; 2] {
        [self.u.len(), self.v.len()]
    }

    /// Refuses a grid of `per_point` values per point beyond
    /// [`MAX_OUTPUT_BYTES`].
    ///
    /// # Errors
    /// `ValueError` naming `u, v` and the size.
    pub(crate) fn check_output(&self, per_point: usize) -> PyResult<()> {
        let [su, sv] = self.shape();
        check_bytes(su as u128 * sv as u128 * per_point as u128, || {
            format!("u, v: a grid of {su} × {sv} parameters")
        })
    }

    /// A buffer of `per_point` values per grid point for the engine to
    /// overwrite (as [`output_buffer`]), within
    /// [`GridArg::check_output`]'s limit.
    ///
    /// # Errors
    /// As [`GridArg::check_output`].
    pub(crate) fn buffer(&self, per_point: usize) -> PyResult<SampleBuffer> {
        self.check_output(per_point)?;
        let [su, sv] = self.shape();
        Ok(SampleBuffer::for_overwrite(su * sv * per_point))
    }

    /// The surface sampled on the grid by `fill` with the GIL released:
    /// `fill([u, v], channels)` writes `lead`'s product of `d` channels of
    /// `su·sv` values each (structure of arrays); seen as an array of shape
    /// `lead + (su, sv, d)`, points last, without a copy.
    ///
    /// # Errors
    /// An output beyond the size limit; the error of `fill`.
    pub(crate) fn sample<'py>(
        &self,
        py: Python<'py>,
        [lead, d]: [&[usize]; 2],
        fill: impl FnOnce([Params<'_>; 2], &mut [&mut [f64]]) -> Result<(), Error> + Send,
    ) -> PyResult<Bound<'py, PyAny>> {
        let buffer = self.buffer(lead.iter().chain(d).product())?;
        let grid = [self.u.params(), self.v.params()];
        filled(py, buffer, [lead, d, &self.shape()], |out| fill(grid, out))
    }

    /// The parameters along u and along v as arrays: the uniform ones over
    /// the `domains` for counts.
    ///
    /// # Errors
    /// The errors of [`ParamsArg::values`].
    pub(crate) fn arrays<'py>(
        &self,
        py: Python<'py>,
        domains: [t2spline::Domain; 2],
    ) -> PyResult<[Bound<'py, PyAny>; 2]> {
        let [su, sv] = self.shape();
        Ok([
            array(py, self.u.values(domains[0])?, &[su])?,
            array(py, self.v.values(domains[1])?, &[sv])?,
        ])
    }
}

/// `buffer` cut into `count` slices of `len` values (empty slices for
/// `len = 0`): one per channel of the sampling engine.
pub(crate) fn channels(buffer: &mut [f64], count: usize, len: usize) -> Vec<&mut [f64]> {
    if len == 0 {
        return (0..count).map(|_| <&mut [f64]>::default()).collect();
    }
    buffer.chunks_mut(len).collect()
}

/// `buffer` filled by `fill` with the GIL released, as the engine writes:
/// `lead`'s product of `d` channels (`d = [dimension]`), each of `samples`'
/// product of values; seen as an array of shape `lead + samples + d`,
/// points last, without a copy.
///
/// # Errors
/// The error of `fill`.
fn filled<'py>(
    py: Python<'py>,
    mut buffer: SampleBuffer,
    [lead, d, samples]: [&[usize]; 3],
    fill: impl FnOnce(&mut [&mut [f64]]) -> Result<(), Error> + Send,
) -> PyResult<Bound<'py, PyAny>> {
    let count = lead.iter().chain(d).product();
    let mut out = channels(&mut buffer, count, samples.iter().product());
    compute(py, || fill(&mut out))?;
    coords_last(py, buffer, lead, d.iter().product(), samples)
}

/// The dict of a fuzzy object's sample: the `parameters` (name and array),
/// then for each layer name (`"upper_left"` … `"upper_right"`) its points,
/// the views `layers[i]` of one `(7, …)` array.
///
/// # Errors
/// Those of setting a dict's items.
pub(crate) fn layer_dict<'py, const N: usize>(
    py: Python<'py>,
    parameters: [(&str, Bound<'py, PyAny>); N],
    layers: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (name, values) in parameters {
        out.set_item(name, values)?;
    }
    for l in Layer::ALL {
        out.set_item(l.name(), layers.get_item(l.index())?)?;
    }
    Ok(out)
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
    at_each(py, &t.shape, tail, |k, out| f(t.data[k], out))
}

/// `f(u, v, out)` at every pair of values of `u` and `v` (numbers, or
/// arrays that broadcast together as numpy's arrays do), each call
/// appending `tail`'s product of values to `out`; the result has the
/// broadcast shape followed by `tail`, and is a `float` for two numbers when
/// `tail` is empty. Runs with the GIL released.
///
/// # Errors
/// The errors of reading `u` and `v`; `ValueError` for shapes that do not
/// broadcast; the first error of `f`.
pub(crate) fn at_pairs<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    tail: &[usize],
    f: impl Fn(f64, f64, &mut Vec<f64>) -> Result<(), t2spline::Error> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let Pairs { shape, u, v } = Pairs::extract(u, v)?;
    at_each(py, &shape, tail, |k, out| f(u[k], v[k], out))
}

/// The values of `u` and `v` broadcast together (numpy's rule), in C order.
pub(crate) struct Pairs {
    /// The broadcast shape.
    pub(crate) shape: Vec<usize>,
    /// `u` at every index of `shape`.
    pub(crate) u: Vec<f64>,
    /// `v` at every index of `shape`.
    pub(crate) v: Vec<f64>,
}

impl Pairs {
    /// Reads `u` and `v` and broadcasts them together.
    ///
    /// # Errors
    /// The errors of reading `u` and `v`; `ValueError` for shapes that do not
    /// broadcast.
    pub(crate) fn extract(u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (u, v) = (floats(u, "u")?, floats(v, "v")?);
        let not_broadcast = || {
            PyValueError::new_err(format!(
                "u, v: shapes {} and {} do not broadcast together",
                shape_text(&u.shape),
                shape_text(&v.shape)
            ))
        };
        let shape = broadcast_shape(&u.shape, &v.shape).ok_or_else(not_broadcast)?;
        let (us, vs) = (u.broadcast_to(&shape), v.broadcast_to(&shape));
        let (u, v) = us.zip(vs).ok_or_else(not_broadcast)?;
        Ok(Pairs { shape, u, v })
    }
}

/// Indices per task of the thread pool; fewer run on the calling thread.
const CHUNK: usize = 8192;

/// `f(k, out)` for every flat index `k` of an array of `shape`: the result
/// of shape `shape + tail` (a `float` for a scalar and no tail), computed
/// with the GIL released within [`MAX_OUTPUT_BYTES`], on rayon's pool for
/// more than [`CHUNK`] indices.
fn at_each<'py>(
    py: Python<'py>,
    shape: &[usize],
    tail: &[usize],
    f: impl Fn(usize, &mut Vec<f64>) -> Result<(), t2spline::Error> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let count: usize = shape.iter().product();
    let width = tail.iter().product::<usize>();
    check_bytes(count as u128 * width as u128, || {
        format!("{count} parameters of {width} values each")
    })?;
    let values = compute(py, || each_index(count, width, &f))?;
    if shape.is_empty() && tail.is_empty() {
        return Ok(values[0].into_pyobject(py)?.into_any());
    }
    let shape: Vec<usize> = shape.iter().chain(tail).copied().collect();
    array(py, values, &shape)
}

/// The values `f(0, ·), f(1, ·), …, f(count − 1, ·)`, each `width` long, in
/// order: in chunks of [`CHUNK`] indices on rayon's pool (each chunk written
/// straight into its place of the result), on this thread when there is
/// only one chunk. The error is the one of the least index, as a loop gives.
fn each_index(
    count: usize,
    width: usize,
    f: &(impl Fn(usize, &mut Vec<f64>) -> Result<(), t2spline::Error> + Sync),
) -> Result<Vec<f64>, t2spline::Error> {
    if count <= CHUNK {
        let mut out = Vec::with_capacity(count * width);
        for k in 0..count {
            f(k, &mut out)?;
        }
        return Ok(out);
    }
    // A zeroed allocation: its pages are first touched by the tasks.
    let mut out = vec![0.0; count * width];
    let outcomes: Vec<Result<(), t2spline::Error>> = out
        .par_chunks_mut((CHUNK * width).max(1))
        .enumerate()
        .map(|(chunk, slots)| {
            let mut values = Vec::with_capacity(slots.len());
            let first = chunk * CHUNK;
            for k in first..(first + CHUNK).min(count) {
                f(k, &mut values)?;
            }
            debug_assert_eq!(values.len(), slots.len(), "f gives `width` values");
            for (slot, value) in slots.iter_mut().zip(values) {
                *slot = value;
            }
            Ok(())
        })
        .collect();
    match outcomes.into_iter().find_map(Result::err) {
        Some(error) => Err(error),
        None => Ok(out),
    }
}
