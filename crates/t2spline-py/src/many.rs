//! Many jobs at once: `t2spline.run_many` (a sequence of jobs, one result
//! each) and the rows behind `t2spline.run_table` (job texts from an Arrow
//! column, one summary row each and, if asked, the samples of every job as
//! one long table).
//!
//! Each job takes the one path of `run` ([`run::prepare`],
//! [`run::execute`]: the job file's rules, `Job::settings`, `Job::run`, the
//! finite check) on rayon's pool, with the GIL released for all of them;
//! results come back in the jobs' order, and a failing job fails alone.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyModule};
use rayon::prelude::*;
use t2spline::job::{Distance, Overrides, Parameter, Regime, RunOutput, Settings};
use t2spline::TypeReduction;
use t2spline_io::{RunError, Status};

use crate::errors::{internal_error, without_gil};
use crate::keyword;
use crate::run::{self, execute, prepare, Failure};
use crate::value::Value;

/// What `errors=` says to do with a failing job.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum OnError {
    /// The job's exception takes its place in the results.
    Collect,
    /// The first failing job's exception is raised.
    Raise,
}

fn on_error(arg: Option<&Bound<'_, PyAny>>) -> PyResult<OnError> {
    match keyword::opt_text(arg, "errors")?.as_deref() {
        None | Some("collect") => Ok(OnError::Collect),
        Some("raise") => Ok(OnError::Raise),
        Some(other) => Err(PyValueError::new_err(format!(
            "errors: expected 'collect' or 'raise', got '{other}'"
        ))),
    }
}

/// How messages name job `k` of many given as a dict or a text.
fn source_name(k: usize) -> String {
    format!("<jobs[{k}]>")
}

/// A job's text and its name: a `str` whose first character that is not
/// white space is `{` is the job's JSON text, any other `str` (or an
/// `os.PathLike`) the path of a job file, a dict the job itself.
fn text_of(job: &Bound<'_, PyAny>, k: usize) -> PyResult<(String, String)> {
    if let Ok(text) = job.cast::<pyo3::types::PyString>() {
        let text = text.to_cow()?;
        if text.trim_start().starts_with('{') {
            return Ok((text.into_owned(), source_name(k)));
        }
    }
    run::job_text_named(job, &source_name(k))
}

/// One job prepared and run off the GIL: its settings (for the warning on
/// an unused alpha) and its result's tree.
type Ran = Result<(Settings, Value), Failure>;

fn prepare_and_run(text: &str, source: &str, overrides: &Overrides) -> Ran {
    let prepared = prepare(text, source, overrides).map_err(Failure::Run)?;
    Ok((*prepared.settings(), execute(&prepared)?))
}

/// `e` with the attribute `index`: which job of many raised it.
fn indexed(py: Python<'_>, e: PyErr, k: usize) -> PyErr {
    match e.value(py).setattr("index", k) {
        Ok(()) => e,
        Err(other) => other,
    }
}

/// Runs many jobs as ``run`` runs one, in parallel on all cores with the GIL
/// released, and returns their results in the jobs' order.
///
/// Every job takes the path of ``run`` (the job file's rules, the settings
/// checked once, ``Job.run``, every number finite), so each result equals
/// ``run(job, ...)`` with the same keywords, bit for bit.
///
/// Parameters
/// ----------
/// jobs : iterable of dict, str or os.PathLike
///     Each a dict with the keys of a job file, a job's JSON text (a ``str``
///     whose first character other than white space is ``{``), or the path
///     of a job file. A dict or text is named ``<jobs[k]>`` in messages.
///     ``jobs`` itself may not be one job (a ``str``, ``bytes``, a dict or
///     a path): that is a ``TypeError``.
/// samples, alpha : optional
///     As for ``run``, for every job.
/// errors : {"collect", "raise"}, optional
///     ``"collect"`` (the default): a job that fails takes its place in the
///     list as its exception (a ``JobError``, ``ValueError``, ``OSError`` …)
///     with the attribute ``index``; ``"raise"``: the exception of the first
///     failing job in the jobs' order is raised, with ``index``.
/// derivatives, type_reduction : optional
///     As for ``run``, for every job.
///
/// Returns
/// -------
/// list
///     One item per job: ``run``'s dict, or (``errors="collect"``) the
///     exception of a job that failed.
///
/// Warns
/// -----
/// UserWarning
///     For each job whose alpha its type reduction does not use, naming the
///     job: ``jobs[3]: type reduction centroid does not use alpha; the job's
///     alpha 0.5 is ignored (...)``.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For a keyword of the wrong type or out of range (before any job
///     runs); under ``errors="raise"``, the first failing job's exception.
///
/// Examples
/// --------
/// >>> job = {
/// ...     "degree": 1, "lower_height": 0.5, "samples": 3,
/// ...     "points": [
/// ...         {"x": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.3]},
/// ...          "y": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]}},
/// ...         {"x": {"crisp": 4, "upper": [3, 6], "primary": [3.5, 5], "lower": [3.8, 4.3]},
/// ...          "y": {"crisp": 2, "upper": [1, 3], "primary": [1.5, 2.5], "lower": [1.8, 2.2]}},
/// ...     ],
/// ... }
/// >>> results = run_many([{**job, "alpha": a} for a in (0.25, 0.75)] + [{"points": []}])
/// >>> [r["regime"] for r in results[:2]]
/// ['alpha <= h', 'alpha > h']
/// >>> results[2].index, type(results[2]).__name__
/// (2, 'JobError')
#[pyfunction]
#[pyo3(
    signature = (jobs, samples=None, alpha=None, errors=None, *, derivatives=None, type_reduction=None),
    text_signature = "(jobs, samples=None, alpha=None, errors='collect', *, derivatives=None, type_reduction=None)"
)]
pub(crate) fn run_many<'py>(
    py: Python<'py>,
    jobs: &Bound<'py, PyAny>,
    samples: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    errors: Option<&Bound<'py, PyAny>>,
    derivatives: Option<&Bound<'py, PyAny>>,
    type_reduction: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    refuse_one_job(jobs)?;
    let overrides = run::keywords(alpha, samples, derivatives, type_reduction)?;
    let on_error = on_error(errors)?;
    let mut texts = Vec::new();
    let mut unread = Vec::new();
    for (k, job) in jobs.try_iter()?.enumerate() {
        match text_of(&job?, k) {
            Ok(text) => texts.push(Some(text)),
            Err(e) => {
                texts.push(None);
                unread.push((k, e));
            }
        }
    }
    let mut unread = unread.into_iter().peekable();
    let results = PyList::empty(py);
    // Python's cyclic collector would walk every result made so far each
    // time it runs: quadratic in the jobs. Results hold no cycles; it is
    // paused while they are made, and restored as it was.
    let _paused = PausedCollector::new(py)?;
    // The jobs run a chunk at a time, each chunk's results made Python
    // objects before the next runs: the memory is that of the results kept
    // and one chunk's trees, not of every job's tree at once.
    for (c, chunk) in texts.chunks(CHUNK).enumerate() {
        let ran: Vec<Option<Ran>> = without_gil(py, || {
            chunk
                .par_iter()
                .map(|t| {
                    t.as_ref()
                        .map(|(text, source)| prepare_and_run(text, source, &overrides))
                })
                .collect()
        })?;
        for (i, ran) in ran.into_iter().enumerate() {
            let k = c * CHUNK + i;
            let outcome = match ran {
                Some(Ok((settings, tree))) => {
                    let prefix = format!("jobs[{k}]: ");
                    run::warn_alpha(py, &settings, overrides.alpha.is_some(), &prefix)?;
                    tree.into_py(py)
                }
                Some(Err(failure)) => Err(failure.into_err(py)),
                None => match unread.next_if(|(at, _)| *at == k) {
                    Some((_, e)) => Err(e),
                    None => Err(internal_error("a job without its text")),
                },
            };
            match outcome {
                Ok(result) => results.append(result)?,
                Err(e) => {
                    let e = indexed(py, e, k);
                    match on_error {
                        OnError::Raise => return Err(e),
                        OnError::Collect => results.append(e.into_value(py))?,
                    }
                }
            }
        }
    }
    Ok(results)
}

/// Python's cyclic garbage collector paused while it lives, then enabled
/// again if it was.
struct PausedCollector<'py> {
    gc: Bound<'py, PyModule>,
    was_enabled: bool,
}

impl<'py> PausedCollector<'py> {
    fn new(py: Python<'py>) -> PyResult<Self> {
        let gc = py.import("gc")?;
        let was_enabled = gc.call_method0("isenabled")?.extract::<bool>()?;
        gc.call_method0("disable")?;
        Ok(PausedCollector { gc, was_enabled })
    }
}

impl Drop for PausedCollector<'_> {
    fn drop(&mut self) {
        if self.was_enabled {
            // Enabling cannot fail short of a broken interpreter.
            let _ = self.gc.call_method0("enable");
        }
    }
}

/// Jobs run between two conversions of their results to Python objects.
const CHUNK: usize = 2048;

/// `jobs` must be many: a `str`, `bytes`, a path or a dict is one job (its
/// characters or keys would each be taken for a job).
fn refuse_one_job(jobs: &Bound<'_, PyAny>) -> PyResult<()> {
    let one = if jobs.is_instance_of::<pyo3::types::PyString>() {
        Some("a str")
    } else if jobs.is_instance_of::<pyo3::types::PyBytes>() {
        Some("bytes")
    } else if jobs.is_instance_of::<PyDict>() {
        Some("a dict")
    } else if jobs.hasattr("__fspath__")? {
        Some("a path")
    } else {
        None
    };
    match one {
        Some(kind) => Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "jobs: expected an iterable of jobs (a list of dicts, job texts or paths), got {kind}; for one job use t2spline.run(job)"
        ))),
        None => Ok(()),
    }
}

/// What became of one row of a table of jobs.
struct Row {
    /// The job's settings, if it was prepared.
    settings: Option<Settings>,
    /// The smallest lower height of its numbers, if it was read.
    h: Option<f64>,
    /// Its run, or why there is none: the status and message of
    /// `t2spline run`'s summary of many jobs.
    result: Result<RowRun, (&'static str, String)>,
}

/// What a row's run gave: the summary's figures, and the whole result only
/// when its samples are asked for (a result holds every curve).
struct RowRun {
    type_reduction: TypeReduction,
    regime: Option<Regime>,
    /// The level, if the type reduction uses it.
    alpha: Option<f64>,
    error: Distance,
    output: Option<RunOutput>,
}

impl RowRun {
    fn of(output: RunOutput, keep: bool) -> RowRun {
        RowRun {
            type_reduction: output.type_reduction,
            regime: output.regime,
            alpha: output.alpha_used.then_some(output.alpha),
            error: output.error,
            output: keep.then_some(output),
        }
    }
}

/// A failure's status ([`Status::of_run`]) and its message: the error's
/// lines joined by `; `, as `t2spline run`'s summary writes them.
fn status(e: &RunError) -> (&'static str, String) {
    let status = Status::of_run(e).word();
    let text = match e {
        RunError::File(e) => e.lines().join("; "),
        RunError::Setting { setting, message } => format!("{}: {message}", setting.name()),
        RunError::Core(e) => e.to_string(),
    };
    (status, text)
}

/// Runs the job of one row: `text` (or `None` for a null), named `source`;
/// its result kept if `keep`.
fn run_row(text: Option<&[u8]>, source: &str, overrides: &Overrides, keep: bool) -> Row {
    let failed = |status, message| Row {
        settings: None,
        h: None,
        result: Err((status, message)),
    };
    let Some(bytes) = text else {
        return failed(Status::Invalid.word(), format!("{source}: no job (null)"));
    };
    let Ok(text) = std::str::from_utf8(bytes) else {
        return failed(
            Status::Invalid.word(),
            format!("{source}: the job is not UTF-8 text"),
        );
    };
    match prepare(text, source, overrides) {
        Err(e) => {
            let (s, m) = status(&e);
            failed(s, m)
        }
        Ok(prepared) => Row {
            settings: Some(*prepared.settings()),
            h: Some(prepared.job().model.least_height()),
            result: prepared
                .run()
                .map(|output| RowRun::of(output, keep))
                .map_err(|e| status(&e)),
        },
    }
}

/// A float column with its validity: `NaN` where absent.
#[derive(Default)]
struct Floats {
    values: Vec<f64>,
    valid: Vec<bool>,
}

impl Floats {
    fn push(&mut self, value: Option<f64>) {
        self.values.push(value.unwrap_or(f64::NAN));
        self.valid.push(value.is_some());
    }

    /// `(values, valid)` as numpy arrays, the values without a copy.
    fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
        let values = PyArray1::from_vec(py, self.values).into_any();
        let valid = PyArray1::from_vec(py, self.valid).into_any();
        Ok((values, valid).into_pyobject(py)?.into_any())
    }
}

/// The rows of `t2spline.run_table` for one Arrow string array (not part of
/// the API): the job texts are `data[offsets[k]:offsets[k + 1]]` (the
/// array's buffers, read without a copy), row `k` null where `valid[k]` is
/// false, named ``<row first + k>`` in messages; the notes on a job's alpha
/// are its row's message (no warning per row). Returns a dict of columns:
/// lists of `str` or `None` (`status`, `message`, `type_reduction`,
/// `regime`), and `(values, valid)` numpy pairs (`alpha`, `h`,
/// `error_max`, `error_max_at`, `error_max_at_v`, `error_rms`); with
/// `with_samples`, `samples`: `(rows, columns)`, `rows` the row of each
/// sample and `columns` a dict of name → `(values, valid)` over every
/// column of [`t2spline_io::sample_column_names`].
#[pyfunction]
#[pyo3(signature = (data, offsets, valid, first, with_samples, samples=None, alpha=None, type_reduction=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn _run_rows<'py>(
    py: Python<'py>,
    data: PyReadonlyArray1<'py, u8>,
    offsets: PyReadonlyArray1<'py, i64>,
    valid: Option<PyReadonlyArray1<'py, bool>>,
    first: usize,
    with_samples: bool,
    samples: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    type_reduction: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let overrides = run::keywords(alpha, samples, None, type_reduction)?;
    let (data, offsets) = (data.as_slice()?, offsets.as_slice()?);
    let valid = valid.as_ref().map(|v| v.as_slice()).transpose()?;
    let n = offsets.len().saturating_sub(1);
    let texts = (0..n)
        .map(|k| {
            if valid.is_some_and(|v| !v.get(k).copied().unwrap_or(false)) {
                return Ok(None);
            }
            let (a, b) = (offsets[k], offsets[k + 1]);
            usize::try_from(a)
                .ok()
                .zip(usize::try_from(b).ok())
                .and_then(|(a, b)| data.get(a..b))
                .map(Some)
                .ok_or_else(|| {
                    PyValueError::new_err(format!("offsets: row {k} lies outside the data"))
                })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let rows: Vec<Row> = without_gil(py, || {
        texts
            .par_iter()
            .enumerate()
            .map(|(k, text)| {
                run_row(
                    *text,
                    &format!("<row {}>", first + k),
                    &overrides,
                    with_samples,
                )
            })
            .collect()
    })?;
    let out = PyDict::new(py);
    let mut status = Vec::with_capacity(n);
    let mut message = Vec::with_capacity(n);
    let mut reduction = Vec::with_capacity(n);
    let mut regime = Vec::with_capacity(n);
    let mut floats: [Floats; 6] = Default::default();
    for row in &rows {
        let notes = row
            .settings
            .map(|s| run::alpha_notes(&s, overrides.alpha.is_some()))
            .unwrap_or_default();
        let ok = row.result.as_ref().ok();
        let (max_at, max_at_v) = match ok.map(|r| r.error.max_at) {
            Some(Parameter::T(t)) => (Some(t), None),
            Some(Parameter::Uv([u, v])) => (Some(u), Some(v)),
            None => (None, None),
        };
        for (column, value) in floats.iter_mut().zip([
            ok.and_then(|r| r.alpha),
            row.h,
            ok.map(|r| r.error.max),
            max_at,
            max_at_v,
            ok.map(|r| r.error.rms),
        ]) {
            column.push(value);
        }
        reduction.push(ok.map(|r| r.type_reduction.name()));
        regime.push(ok.and_then(|r| r.regime).map(|r| r.as_str()));
        match &row.result {
            Ok(_) => {
                status.push(Status::Ok.word());
                message.push((!notes.is_empty()).then(|| notes.join("; ")));
            }
            Err((s, m)) => {
                status.push(*s);
                message.push(Some(m.clone()));
            }
        }
    }
    out.set_item("status", status)?;
    out.set_item("message", message)?;
    out.set_item("type_reduction", reduction)?;
    out.set_item("regime", regime)?;
    let names = [
        "alpha",
        "h",
        "error_max",
        "error_max_at",
        "error_max_at_v",
        "error_rms",
    ];
    for (name, column) in names.into_iter().zip(floats) {
        out.set_item(name, column.into_py(py)?)?;
    }
    if with_samples {
        out.set_item("samples", samples_table(py, &rows, first)?)?;
    }
    Ok(out)
}

/// Every row's samples in one long table: the row of each sample, and each
/// column of the one schema filled by the jobs that have it (absent
/// elsewhere).
fn samples_table<'py>(py: Python<'py>, rows: &[Row], first: usize) -> PyResult<Bound<'py, PyAny>> {
    let names = t2spline_io::sample_column_names();
    let (index, columns) = without_gil(py, || {
        let mut index: Vec<i64> = Vec::new();
        let mut columns: Vec<Floats> = names.iter().map(|_| Floats::default()).collect();
        for (k, row) in rows.iter().enumerate() {
            let Some(result) = row.result.as_ref().ok().and_then(|r| r.output.as_ref()) else {
                continue;
            };
            let (have, count) = t2spline_io::sample_columns(result);
            let row_index = i64::try_from(first + k).unwrap_or(i64::MAX);
            index.extend(std::iter::repeat_n(row_index, count));
            for (name, column) in names.iter().zip(columns.iter_mut()) {
                match have.iter().find(|c| c.name() == name) {
                    Some(c) => {
                        c.extend_into(count, &mut column.values);
                        column.valid.extend(std::iter::repeat_n(true, count));
                    }
                    None => {
                        column.values.extend(std::iter::repeat_n(f64::NAN, count));
                        column.valid.extend(std::iter::repeat_n(false, count));
                    }
                }
            }
        }
        (index, columns)
    })?;
    let out = PyDict::new(py);
    for (name, column) in names.iter().zip(columns) {
        out.set_item(name, column.into_py(py)?)?;
    }
    Ok((PyArray1::from_vec(py, index), out)
        .into_pyobject(py)?
        .into_any())
}
