//! Errors as Python exceptions, and the guard around every computation.
//!
//! | Rust | Python |
//! |---|---|
//! | a job that breaks the schema (`t2spline_io::Error::Invalid`), a missing alpha | [`JobError`] (a `ValueError`), one problem line each, as the CLI prints them |
//! | a job file that cannot be read | `OSError` (`FileNotFoundError`, …) naming the file |
//! | a setting out of range (`Error::Setting`) | `ValueError`: `samples: samples = 1: at least 2 are needed …` |
//! | any other core error | `ValueError` with the core's message (point, coordinate, rule) |
//! | a panic (a bug) | `RuntimeError`, never an abort of the interpreter |

use std::panic::{self, AssertUnwindSafe};

use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use t2spline::job::Setting;

pyo3::create_exception!(
    t2spline,
    JobError,
    PyValueError,
    "A job (a dict or a job file) that breaks the rules of the job file\n\
     (docs/jobs.md); a ValueError.\n\n\
     The message holds one line per problem, as ``t2spline run`` prints them\n\
     (``file:line:column: place: rule``); ``problems`` is the list of those\n\
     lines. Every problem is reported, not only the first.\n\n\
     Examples\n\
     --------\n\
     >>> try:\n\
     ...     run({\"order\": 2, \"alhpa\": 0.5, \"points\": []})\n\
     ... except JobError as e:\n\
     ...     print(*e.problems, sep=\"\\n\")\n\
     <dict>:3:3: alhpa: unknown key (did you mean `alpha`?)\n\
     <dict>:4:3: points: a curve of order 2 needs at least 2 control points, got 0\n"
);

/// A [`JobError`] whose message is `lines`, one per problem, and whose
/// attribute `problems` is the list of them.
pub(crate) fn job_error(py: Python<'_>, lines: Vec<String>) -> PyErr {
    let err = JobError::new_err(lines.join("\n"));
    match err.value(py).setattr("problems", lines) {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// An error of the core library as a `ValueError`; an error about a setting
/// of a run is prefixed with the keyword that sets it (`samples: …`).
pub(crate) fn core_error(e: t2spline::Error) -> PyErr {
    match e {
        t2spline::Error::Setting { setting, message } => setting_error(setting, &message),
        other => PyValueError::new_err(other.to_string()),
    }
}

/// A `ValueError` about the keyword argument that sets `setting`.
pub(crate) fn setting_error(setting: Setting, message: &str) -> PyErr {
    PyValueError::new_err(format!("{}: {message}", setting.name()))
}

/// An error of the I/O crate: the problems of a job as a [`JobError`], a
/// file that cannot be read as an `OSError` carrying the operating system's
/// error number (so Python picks `FileNotFoundError`, `PermissionError`, …).
pub(crate) fn io_error(py: Python<'_>, e: t2spline_io::Error) -> PyErr {
    match e {
        t2spline_io::Error::Invalid { .. } => job_error(py, e.lines()),
        t2spline_io::Error::Read {
            ref path,
            ref source,
        } => match source.raw_os_error() {
            // As Python's own: `[Errno 2] No such file or directory: 'job.json'`.
            Some(errno) => {
                let text = source.to_string();
                let reason = text
                    .strip_suffix(&format!(" (os error {errno})"))
                    .unwrap_or(&text);
                PyOSError::new_err((errno, reason.to_owned(), path.display().to_string()))
            }
            None => PyOSError::new_err(e.lines().join("\n")),
        },
        other => internal_error(&other.to_string()),
    }
}

/// A `RuntimeError` for what valid input can never cause (a bug).
pub(crate) fn internal_error(message: &str) -> PyErr {
    PyRuntimeError::new_err(format!(
        "internal error: {message} (please report this with the input that caused it)"
    ))
}

/// Runs `work` with the GIL released, so that other Python threads go on
/// while the Rust engine computes; a panic in `work` becomes a
/// `RuntimeError` instead of unwinding into the interpreter.
pub(crate) fn without_gil<T: Send>(py: Python<'_>, work: impl FnOnce() -> T + Send) -> PyResult<T> {
    py.detach(|| panic::catch_unwind(AssertUnwindSafe(work)))
        .map_err(|payload| {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_owned());
            internal_error(&format!("the Rust code panicked: {message}"))
        })
}

/// [`without_gil`] for work that returns a core result: its error becomes a
/// Python exception by [`core_error`].
pub(crate) fn compute<T: Send>(
    py: Python<'_>,
    work: impl FnOnce() -> Result<T, t2spline::Error> + Send,
) -> PyResult<T> {
    without_gil(py, work)?.map_err(core_error)
}

/// Panics inside [`without_gil`], so that the tests can check that a panic
/// becomes a `RuntimeError` and the interpreter lives on. Not part of the API.
#[pyfunction]
#[allow(clippy::panic)] // the panic is this function's purpose
pub(crate) fn _panic_for_tests(py: Python<'_>, message: &str) -> PyResult<()> {
    let message = message.to_owned();
    without_gil(py, move || -> () { panic!("{message}") })
}
