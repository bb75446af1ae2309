//! A surface's operations in one direction take the arguments of the
//! curve's operation of the same name, then the direction as a keyword:
//! `surface.insert_knot(t, times, direction="u")` beside
//! `curve.insert_knot(t, times)`. The older form, the direction first
//! (`surface.insert_knot("u", t, times)`), works for one more release with a
//! `DeprecationWarning`; the names `degree_u` and `degree_v` likewise give
//! way to `degree`, a pair as `order` is.

use std::ffi::CString;

use pyo3::exceptions::{PyDeprecationWarning, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use t2spline::Direction;

/// Warns that `old` is deprecated in favour of `new` (a `DeprecationWarning`
/// pointing at the caller's line).
///
/// # Errors
/// The warning raised as an error, when warnings are errors (`-W error`).
pub(crate) fn deprecated(py: Python<'_>, old: &str, new: &str) -> PyResult<()> {
    let message = format!("{old} is deprecated and will be removed in the next release: use {new}");
    // The text comes from this crate's literals: it holds no NUL byte.
    let message = CString::new(message).unwrap_or_default();
    PyErr::warn(py, &py.get_type::<PyDeprecationWarning>(), &message, 1)
}

/// The positional arguments of a directed operation `method`, at most
/// `count` (1 or 2) of the curve's arguments, read in the new form (`slots`
/// are the operation's own arguments, `direction` the keyword) or in the old
/// one (no keyword and the first slot a `str`: the direction, the
/// operation's arguments after it, shifted by one, with a
/// `DeprecationWarning`).
///
/// Returns the direction and the operation's own arguments in order.
///
/// # Errors
/// `TypeError` when the direction is missing, or for too many
/// positional arguments; `ValueError` for a direction other than `"u"` or
/// `"v"`; the warning raised as an error.
pub(crate) fn directed<'a, 'py>(
    method: &str,
    count: usize,
    slots: [Option<&'a Bound<'py, PyAny>>; 3],
    direction: Option<&'a Bound<'py, PyAny>>,
) -> PyResult<(Direction, [Option<&'a Bound<'py, PyAny>>; 2])> {
    let [first, second, third] = slots;
    match first {
        Some(old) if old.is_instance_of::<PyString>() && direction.is_none() => {
            deprecated(
                old.py(),
                &format!("{method}(direction, …) with the direction first"),
                &format!("{method}(…, direction={})", old.repr()?),
            )?;
            Ok((crate::construct::direction(old)?, [second, third]))
        }
        _ => {
            if third.is_some() || (count < 2 && second.is_some()) {
                return Err(PyTypeError::new_err(format!(
                    "{method}: takes at most {count} positional argument(s) besides direction="
                )));
            }
            let direction = direction.ok_or_else(|| {
                PyTypeError::new_err(format!(
                    "{method}: missing the keyword argument direction ('u' or 'v')"
                ))
            })?;
            Ok((crate::construct::direction(direction)?, [first, second]))
        }
    }
}

/// A required argument `name` of `method` that the old form may have left
/// out.
///
/// # Errors
/// `TypeError` naming the argument when it is missing.
pub(crate) fn required<'a, 'py>(
    arg: Option<&'a Bound<'py, PyAny>>,
    method: &str,
    name: &str,
) -> PyResult<&'a Bound<'py, PyAny>> {
    arg.ok_or_else(|| PyTypeError::new_err(format!("{method}: missing the argument {name}")))
}
