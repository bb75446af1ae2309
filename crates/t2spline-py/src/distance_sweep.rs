//! `FuzzyCurve.distance_sweep` and `FuzzySurface.distance_sweep`: the
//! distance between the crisp and the defuzzified curve (surface) of the
//! paper's type reduction at many levels, sampled at uniform parameters and
//! summarised by the trapezoidal rule (the core's
//! [`DistanceSweep`](t2spline::sampling::DistanceSweep)): the numbers the
//! figure of the distance against alpha draws.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::sampling::DistanceSweep;
use t2spline::{Alpha, Error};

use crate::arrays::{array, floats, shape_text};
use crate::dim::{by_dim, ByDim, Fuzzy, FuzzyNet};
use crate::errors::compute;
use crate::keyword::{self, PerDirection};
use crate::py_types::{DictResult, Obj};
use crate::sample::check_output;

/// The most levels of one sweep.
const MAX_SWEEP_LEVELS: usize = 100_001;

/// `alphas`: one level or a 1-D array of levels in [0, 1].
fn levels(arg: &Bound<'_, PyAny>) -> PyResult<Vec<Alpha>> {
    let given = floats(arg, "alphas")?;
    if given.shape.len() > 1 || given.data.is_empty() || given.data.len() > MAX_SWEEP_LEVELS {
        return Err(PyValueError::new_err(format!(
            "alphas: expected a level or a 1-D array of 1 to {MAX_SWEEP_LEVELS} levels, got shape {}",
            shape_text(&given.shape)
        )));
    }
    keyword::alphas(&given.data, "alphas")
}

/// A count of samples along one direction, at least 2.
fn samples_along(n: i64, name: &str) -> PyResult<usize> {
    keyword::count(n, name, 2)
}

/// The sweep as a dict: `alpha` `(L,)`, `max` and `rms` `(L,)`, `distance`
/// `(L,) + shape`.
fn to_dict<'py>(
    py: Python<'py>,
    alphas: &[Alpha],
    sweep: DistanceSweep,
    shape: &[usize],
) -> PyResult<Bound<'py, PyDict>> {
    let summary = sweep.summary();
    let l = alphas.len();
    let d = PyDict::new(py);
    d.set_item(
        "alpha",
        array(py, alphas.iter().map(|a| a.get()).collect(), &[l])?,
    )?;
    d.set_item(
        "max",
        array(py, summary.iter().map(|s| s[0]).collect(), &[l])?,
    )?;
    d.set_item(
        "rms",
        array(py, summary.iter().map(|s| s[1]).collect(), &[l])?,
    )?;
    let distances: Vec<f64> = (0..l)
        .flat_map(|k| sweep.distances(k).unwrap_or(&[]).iter().copied())
        .collect();
    let full: Vec<usize> = [l].into_iter().chain(shape.iter().copied()).collect();
    d.set_item("distance", array(py, distances, &full)?)?;
    Ok(d)
}

/// What a sweep runs on: a fuzzy curve (`samples` uniform parameters,
/// default 1001) or a fuzzy surface (a grid, default 101 × 101), of either
/// dimension.
pub(crate) trait Swept: Sync {
    /// The samples along each direction.
    ///
    /// # Errors
    /// `TypeError` or `ValueError` naming `samples`.
    fn samples(samples: Option<&Obj<'_>>) -> PyResult<Vec<usize>>;

    /// The core's sweep at `alphas` on the `samples`.
    ///
    /// # Errors
    /// The core's.
    fn sweep(&self, alphas: &[Alpha], samples: &[usize]) -> Result<DistanceSweep, Error>;
}

impl Swept for ByDim<Fuzzy> {
    fn samples(samples: Option<&Obj<'_>>) -> PyResult<Vec<usize>> {
        Ok(vec![match keyword::opt_int(samples, "samples")? {
            None => 1001,
            Some(n) => samples_along(n, "samples")?,
        }])
    }

    fn sweep(&self, alphas: &[Alpha], samples: &[usize]) -> Result<DistanceSweep, Error> {
        by_dim!(self, |c| c.distance_sweep(alphas, samples[0]))
    }
}

impl Swept for ByDim<FuzzyNet> {
    fn samples(samples: Option<&Obj<'_>>) -> PyResult<Vec<usize>> {
        let [u, v] = keyword::opt_per_direction(samples, "samples")?
            .unwrap_or(PerDirection::One(101))
            .pair();
        Ok(vec![
            samples_along(u, "samples[0]")?,
            samples_along(v, "samples[1]")?,
        ])
    }

    fn sweep(&self, alphas: &[Alpha], samples: &[usize]) -> Result<DistanceSweep, Error> {
        by_dim!(self, |s| s.distance_sweep(alphas, [samples[0], samples[1]]))
    }
}

/// `FuzzyCurve.distance_sweep(alphas, samples=1001)` and
/// `FuzzySurface.distance_sweep(alphas, samples=(101, 101))`.
pub(crate) fn distance_sweep<'py, S: Swept>(
    py: Python<'py>,
    value: &S,
    alphas: &Obj<'py>,
    samples: Option<&Obj<'py>>,
) -> DictResult<'py> {
    let alphas = levels(alphas)?;
    let samples = S::samples(samples)?;
    let points = samples.iter().fold(1, |n: usize, &k| n.saturating_mul(k));
    check_output(points, alphas.len(), "samples")?;
    let sweep = compute(py, || value.sweep(&alphas, &samples))?;
    to_dict(py, &alphas, sweep, &samples)
}
