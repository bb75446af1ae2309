//! `FuzzyCurve.to_job` / `FuzzySurface.to_job`: a model written back as a
//! job (the I/O crate's `job_json`, the canonical form of job files:
//! explicit weights, knots and type reduction, every number with its own
//! `lower_height`), checked by the job validator, as a dict.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::job::{Job, Model, Samples};
use t2spline::Alpha;

use crate::errors::{internal_error, without_gil};
use crate::json::loads;
use crate::keyword::{self, PerDirection};
use crate::reduction;

/// The job of `model` with the keywords of `to_job`, as a dict.
///
/// # Errors
/// `ValueError` or `TypeError` naming a keyword; a job that does not
/// validate is an internal error.
pub(crate) fn job_dict<'py>(
    py: Python<'py>,
    model: Model,
    alpha: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    type_reduction: Option<&Bound<'py, PyAny>>,
    description: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let surface = matches!(model, Model::Surface(_));
    let mut job = Job::new(model);
    job.alpha = keyword::opt_real(alpha, "alpha")?
        .map(|a| Alpha::try_new(a).map_err(|e| PyValueError::new_err(format!("alpha: {e}"))))
        .transpose()?;
    let reduction = keyword::opt_text(type_reduction, "type_reduction")?;
    if let Some(r) = reduction::type_reduction(reduction.as_deref())? {
        job.type_reduction = r;
    }
    job.description = keyword::opt_text(description, "description")?;
    if let Some(given) = keyword::opt_per_direction(samples, "samples")? {
        job.samples = match (surface, given) {
            (false, PerDirection::One(n)) => Samples::Along(keyword::count(n, "samples", 2)?),
            (false, PerDirection::Two(..)) => {
                return Err(PyValueError::new_err(
                    "samples: a curve takes one number of samples, not a pair",
                ))
            }
            (true, per) => {
                let [u, v] = per.pair();
                Samples::Grid([
                    keyword::count(u, "samples", 2)?,
                    keyword::count(v, "samples", 2)?,
                ])
            }
        };
    }
    let text = without_gil(py, || {
        let text = t2spline_io::job_json(&job).to_string();
        // The last guard: what is given is a valid job file.
        t2spline_io::parse_job(&text, "<to_job>").map(|_| text)
    })?
    .map_err(|e| internal_error(&format!("the job does not validate: {e}")))?;
    loads(py, &text)
}
