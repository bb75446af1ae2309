//! `t2spline.run`: a job (a dict or a job file) through the same validator
//! and the same `Job::run` as `t2spline run`, its result as a dict of numpy
//! arrays.

use std::path::PathBuf;

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use t2spline::job::{check_samples, Job, Model, Overrides, Setting, Settings, ALPHA_IGNORED};
use t2spline::TypeReduction;
use t2spline_io::{MissingAlpha, Prepared, RunError};

use crate::construct::PerDirection;
use crate::errors::{core_error, internal_error, io_error, setting_error, without_gil};
use crate::keyword;
use crate::reduction;
use crate::value::{to_value, Value};

/// How a Python user gives a missing alpha.
const GIVE_ALPHA: MissingAlpha<'static> = MissingAlpha::Refuse {
    advice: "give it in the job or as alpha=",
};

/// How messages name a job given as a dict.
pub(crate) const DICT_SOURCE: &str = "<dict>";

/// A job's text and how messages name it: a dict is written as JSON with
/// `json.dumps(job, indent=2)` (numpy arrays and numbers as lists and
/// numbers), a path is read as `t2spline run` reads it.
///
/// # Errors
/// `TypeError` for anything else, and for a value of a dict that has no form
/// in a job file, named by its place ([`crate::dict_place`]); `JobError`
/// for NaN or infinity in a dict,
/// each named at its place by the I/O crate, as `t2spline run` names them in
/// a file ([`t2spline_io::job::non_finite`]); the errors of reading a
/// file.
pub(crate) fn job_text(job: &Bound<'_, PyAny>) -> PyResult<(String, String)> {
    job_text_named(job, DICT_SOURCE)
}

/// [`job_text`], a dict named `dict_source` in messages.
///
/// # Errors
/// As [`job_text`].
pub(crate) fn job_text_named(
    job: &Bound<'_, PyAny>,
    dict_source: &str,
) -> PyResult<(String, String)> {
    let py = job.py();
    if job.is_instance_of::<PyDict>() {
        let json = py.import("json")?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("indent", 2)?;
        kwargs.set_item("default", wrap_pyfunction!(json_default, py)?)?;
        let text: String = match json.call_method("dumps", (job,), Some(&kwargs)) {
            Ok(text) => text.extract()?,
            Err(e) if e.is_instance_of::<PyTypeError>(py) => {
                // `json.dumps` names the type alone: name the place too.
                return Err(match crate::dict_place::unwritable(job, "")? {
                    Some((place, rule)) => {
                        let shown = if place.is_empty() { "job" } else { &place };
                        PyTypeError::new_err(format!("job: {shown}: {rule}"))
                    }
                    None => e,
                });
            }
            Err(e) => return Err(e),
        };
        // `json.dumps` writes NaN and infinity as words that are not JSON.
        let problems = t2spline_io::job::non_finite(&text);
        if !problems.is_empty() {
            return Err(io_error(
                py,
                t2spline_io::Error::Invalid {
                    file: dict_source.to_owned(),
                    problems,
                },
            ));
        }
        return Ok((text, dict_source.to_owned()));
    }
    let is_path = job.is_instance_of::<PyString>() || job.hasattr("__fspath__")?;
    if !is_path {
        return Err(PyTypeError::new_err(format!(
            "job: expected a dict with the keys of a job file, or the path of a job file (str or os.PathLike), got {}",
            job.get_type().name()?
        )));
    }
    let path: PathBuf = py.import("os")?.call_method1("fspath", (job,))?.extract()?;
    let text =
        without_gil(py, || t2spline_io::job::read_text(&path))?.map_err(|e| io_error(py, e))?;
    Ok((text, path.display().to_string()))
}

/// The JSON form of what `json` cannot write by itself: numpy arrays and
/// numpy numbers (by their `tolist`).
#[pyfunction]
fn json_default<'py>(value: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    if value.hasattr("tolist")? {
        value.call_method0("tolist")
    } else {
        Err(PyTypeError::new_err(format!(
            "job: a value of type {} has no form in a job file",
            value.get_type().name()?
        )))
    }
}

/// The fuzzy model of a job (a dict or a path, validated as `t2spline run`
/// validates it), and how messages name the job.
///
/// # Errors
/// As [`job_text`]; `JobError` for a job that breaks the rules.
pub(crate) fn job_model(job: &Bound<'_, PyAny>) -> PyResult<(Model, String)> {
    let (text, source) = job_text(job)?;
    Ok((parse(job.py(), &text, &source)?.model, source))
}

/// A validated job from its text, with the problems of the job file as a
/// `JobError`.
pub(crate) fn parse(py: Python<'_>, text: &str, source: &str) -> PyResult<Job> {
    without_gil(py, || t2spline_io::parse_job(text, source))?.map_err(|e| io_error(py, e))
}

/// The overrides of a run's keywords, read from Python: `alpha`, `samples`,
/// `derivatives` and `type_reduction` as `run` takes them.
///
/// # Errors
/// `TypeError` or `ValueError` naming the keyword.
pub(crate) fn keywords(
    alpha: Option<&Bound<'_, PyAny>>,
    samples: Option<&Bound<'_, PyAny>>,
    derivatives: Option<&Bound<'_, PyAny>>,
    type_reduction: Option<&Bound<'_, PyAny>>,
) -> PyResult<Overrides> {
    let alpha = keyword::opt_real(alpha, "alpha")?;
    let samples = keyword::opt_per_direction(samples, "samples")?;
    let derivatives = keyword::opt_int(derivatives, "derivatives")?;
    let type_reduction = keyword::opt_text(type_reduction, "type_reduction")?;
    let type_reduction = reduction::type_reduction(type_reduction.as_deref())?;
    overrides(alpha, type_reduction, samples, derivatives)
}

/// The overrides of a run's keywords.
///
/// # Errors
/// `ValueError` naming `samples` for a negative count (the core takes
/// counts as `u64`; the rule is written as given).
fn overrides(
    alpha: Option<f64>,
    type_reduction: Option<TypeReduction>,
    samples: Option<PerDirection>,
    derivatives: Option<i64>,
) -> PyResult<Overrides> {
    let samples = match samples {
        None => None,
        Some(counts) => {
            let counts = match counts {
                PerDirection::One(n) => vec![n],
                PerDirection::Two(u, v) => vec![u, v],
            };
            if let Some(n) = counts.iter().find(|&&n| n < 0) {
                let message = match check_samples(0, &n.to_string()) {
                    Err(message) => message,
                    Ok(_) => format!("samples = {n}: at least 2 are needed"),
                };
                return Err(setting_error(Setting::Samples, &message));
            }
            Some(counts.into_iter().map(i64::unsigned_abs).collect())
        }
    };
    Ok(Overrides {
        alpha,
        type_reduction,
        samples,
        derivatives,
    })
}

/// A failure of the shared run path as a Python exception: the job's
/// problems as a `JobError` (a missing alpha placed at the job's top level,
/// as `t2spline run` places it), a setting's as a `ValueError` naming the
/// keyword, a number that is not finite as an internal error.
pub(crate) fn run_error(py: Python<'_>, e: RunError) -> PyErr {
    match e {
        RunError::File(e @ t2spline_io::Error::NotFinite { .. }) => internal_error(&e.to_string()),
        RunError::File(e) => io_error(py, e),
        RunError::Setting { setting, message } => setting_error(setting, &message),
        RunError::Core(e) => core_error(e),
    }
}

/// Runs a job as ``t2spline run`` does: every stage of Algorithm 1.1 at
/// level alpha, every curve sampled at uniform parameters, and the distance
/// between the crisp and the defuzzified curve (docs/method.md §7–§8).
///
/// The job goes through the same validator as job files
/// (``t2spline_io::parse_job``) and the same ``Job.run`` as the command-line
/// tool, so the numbers are those of ``t2spline run`` bit for bit.
///
/// Parameters
/// ----------
/// job : dict or str or os.PathLike
///     A dict with the keys of a job file (docs/jobs.md; numpy arrays and numbers
///     are accepted as values), or the path of a job file.
/// alpha : float, optional
///     The level alpha in ``[0, 1]``, in place of the job's. Only the
///     paper's type reduction uses it: with another one, stage 2 is cut at
///     alpha = 0 (the whole footprint), the result has ``alpha_used`` false
///     and ``regime`` None, and an alpha given anyway (here or in the job)
///     is checked and set aside with a ``UserWarning``.
/// samples : int or (int, int), optional
///     The number of uniform parameters (2 … 1 000 000), in place of the
///     job's (default 101); for a surface job one count for both directions
///     or ``(u, v)`` (default ``(21, 21)``, at most 1 000 000 grid points).
/// derivatives : int, optional
///     With ``K``, also the derivatives of orders ``1 … K`` of the crisp and the
///     defuzzified curve, and their arc lengths.
/// type_reduction : {"paper", "centroid", "nie-tan", "alpha-planes"}, optional
///     The type reduction of stages 3–4 (docs/method.md §9), in place of the job's
///     ``"type_reduction"`` (default ``"paper"``). The result names it.
///
/// Returns
/// -------
/// dict
///     Exactly the keys of ``t2spline run``'s JSON, in its order, with every
///     array of numbers a ``float64`` numpy array: ``curves.params`` of shape
///     ``(samples,)``, ``curves.crisp`` and every other curve of shape
///     ``(samples, d)``, ``control_points.*`` of shape ``(n, d)``,
///     ``curves.derivatives.*`` of shape ``(K, samples, d)``. Scalars are
///     floats (``alpha``, ``error.max``) or ints (``order``). Where the JSON
///     has ``null`` the dict has ``None`` (an alpha-cut curve of a lower layer
///     when some number has no lower cut), and inside
///     ``control_points.alpha_cut.*`` an absent lower end is NaN.
///
/// Raises
/// ------
/// JobError
///     For a job that breaks the rules, with the lines ``t2spline run``
///     prints (``file:line:column: place: rule``; a dict is named ``<dict>``
///     and placed in its ``json.dumps(job, indent=2)`` text); NaN or
///     infinity in a dict too: ``<dict>:47:9: points[1].x.crisp: NaN is not
///     a finite number (NaN and infinity are refused)``.
/// ValueError
///     For a keyword out of range, named: ``samples: samples = 1: at least 2
///     are needed (both ends of the domain)``; for an unknown
///     ``type_reduction``.
/// TypeError
///     For a keyword of the wrong type, named with what it takes:
///     ``samples: expected an int or a pair (u, v) of ints, got str``.
/// OSError
///     For a job file that cannot be read.
///
/// Examples
/// --------
/// >>> job = {
/// ...     "degree": 1, "alpha": 0.5, "lower_height": 0.5, "samples": 3,
/// ...     "points": [
/// ...         {"x": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.3]},
/// ...          "y": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]}},
/// ...         {"x": {"crisp": 4, "upper": [3, 6], "primary": [3.5, 5], "lower": [3.8, 4.3]},
/// ...          "y": {"crisp": 2, "upper": [1, 3], "primary": [1.5, 2.5], "lower": [1.8, 2.2]}},
/// ...     ],
/// ... }
/// >>> result = run(job)
/// >>> result["curves"]["params"]
/// array([0. , 0.5, 1. ])
/// >>> result["curves"]["crisp"].shape, result["curves"]["crisp"].dtype
/// ((3, 2), dtype('float64'))
/// >>> result["regime"]
/// 'alpha <= h'
/// >>> run(job, samples=1)
/// Traceback (most recent call last):
///     ...
/// ValueError: samples: samples = 1: at least 2 are needed (both ends of the domain)
#[pyfunction]
#[pyo3(signature = (job, alpha=None, samples=None, derivatives=None, type_reduction=None))]
pub(crate) fn run<'py>(
    py: Python<'py>,
    job: &Bound<'py, PyAny>,
    alpha: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    derivatives: Option<&Bound<'py, PyAny>>,
    type_reduction: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let overrides = keywords(alpha, samples, derivatives, type_reduction)?;
    let (text, source) = job_text(job)?;
    let prepared =
        without_gil(py, || prepare(&text, &source, &overrides))?.map_err(|e| run_error(py, e))?;
    warn_alpha(py, prepared.settings(), overrides.alpha.is_some(), "")?;
    match without_gil(py, move || execute(&prepared))? {
        Ok(tree) => tree.into_py(py),
        Err(failure) => Err(failure.into_err(py)),
    }
}

/// A job's text (named `source` in messages) prepared for its run with the
/// keywords' `overrides` by the one path of every front end
/// ([`Prepared`]: the job file's rules, the settings checked once by the
/// core); a missing alpha is refused.
///
/// # Errors
/// The shared path's [`RunError`]; [`run_error`] makes it Python's.
pub(crate) fn prepare(
    text: &str,
    source: &str,
    overrides: &Overrides,
) -> Result<Prepared, RunError> {
    Prepared::from_text(text, source, overrides, GIVE_ALPHA)
}

/// A prepared job run ([`Prepared::run`]: `Job::run` and every number
/// checked finite), its result as the tree of Python values `run` returns.
///
/// # Errors
/// The run's [`Failure`].
pub(crate) fn execute(prepared: &Prepared) -> Result<Value, Failure> {
    let output = prepared.run().map_err(Failure::Run)?;
    to_value(&output).map_err(|e| Failure::Internal(e.to_string()))
}

/// The notes on a run's alpha ([`Settings::alpha_notes`]): the alpha given
/// by `alpha=` if `from_keyword`, else by the job; none if alpha is as
/// meant.
pub(crate) fn alpha_notes(settings: &Settings, from_keyword: bool) -> Vec<String> {
    let source = if from_keyword {
        "alpha="
    } else {
        "the job's alpha "
    };
    settings
        .alpha_notes()
        .iter()
        .map(|note| note.sentence(source, ALPHA_IGNORED))
        .collect()
}

/// A `UserWarning` for each of [`alpha_notes`], after `prefix` (which job
/// of many).
///
/// # Errors
/// The warning itself, under ``-W error``.
pub(crate) fn warn_alpha(
    py: Python<'_>,
    settings: &Settings,
    from_keyword: bool,
    prefix: &str,
) -> PyResult<()> {
    for note in alpha_notes(settings, from_keyword) {
        reduction::warn(py, &format!("{prefix}{note}"))?;
    }
    Ok(())
}

/// Why a run gave no result.
#[derive(Debug)]
pub(crate) enum Failure {
    /// The shared run path's error.
    Run(RunError),
    /// What a valid job never causes.
    Internal(String),
}

impl Failure {
    /// The failure as a Python exception.
    pub(crate) fn into_err(self, py: Python<'_>) -> PyErr {
        match self {
            Failure::Run(e) => run_error(py, e),
            Failure::Internal(message) => internal_error(&message),
        }
    }
}
