//! A surface's operations in one direction take the arguments of the
//! curve's operation of the same name, then the direction as a keyword:
//! `surface.insert_knot(t, times, direction="u")` beside
//! `curve.insert_knot(t, times)`. The older form, the direction first
//! (`surface.insert_knot("u", t, times=2)`), works for one more release with
//! a `DeprecationWarning`; the names `degree_u` and `degree_v` likewise give
//! way to `degree`, a pair as `order` is.

use std::ffi::CString;

use pyo3::exceptions::{PyDeprecationWarning, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};
use t2spline::Direction;

/// Warns that `old` is deprecated in favour of `new` (a `DeprecationWarning`
/// pointing at the caller's line).
///
/// # Errors
/// The warning raised as an error, when warnings are errors (`-W error`).
pub(crate) fn deprecated(py: Python<'_>, old: &str, new: &str) -> PyResult<()> {
    let message = format!("{old} is deprecated and will be removed in the next release: use {new}");
    // The text comes from this crate's literals and a str's repr: a NUL
    // byte would be escaped by the repr.
    let message = CString::new(message).unwrap_or_default();
    PyErr::warn(py, &py.get_type::<PyDeprecationWarning>(), &message, 1)
}

/// The arguments of the directed operation `method` of the class `class`
/// (a Rust name such as `PyNurbsSurface`; messages drop the `Py`), whose
/// own arguments are `names` (the curve operation's, in order): each taken
/// from the positional `args` or else from its keyword in `keywords`. In
/// the new form the direction is the keyword `direction`; in the old one
/// (no keyword, and the first positional argument a `str`) it is the first
/// positional argument, with a `DeprecationWarning`.
///
/// Returns the direction and the operation's arguments in the order of
/// `names`, `None` where neither form gave one.
///
/// # Errors
/// `TypeError` when the direction is missing, for too many positional
/// arguments, or for an argument given both ways; `ValueError` for a
/// direction other than `"u"` or `"v"`; the warning raised as an error.
pub(crate) fn directed<'py, const N: usize>(
    class: &str,
    method: &str,
    names: [&str; N],
    args: &Bound<'py, PyTuple>,
    keywords: [Option<&Bound<'py, PyAny>>; N],
    direction: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Direction, [Option<Bound<'py, PyAny>>; N])> {
    let method = format!("{}.{method}", class.trim_start_matches("Py"));
    let mut positional: Vec<Bound<'py, PyAny>> = args.iter().collect();
    let direction = match (direction, positional.first()) {
        (Some(given), _) => crate::construct::direction(given)?,
        (None, Some(first)) if first.is_instance_of::<PyString>() => {
            let first = positional.remove(0);
            deprecated(
                args.py(),
                &format!("{method}(direction, …) with the direction first"),
                &format!("{method}(…, direction={})", first.repr()?),
            )?;
            crate::construct::direction(&first)?
        }
        (None, _) => {
            return Err(PyTypeError::new_err(format!(
                "{method}: missing the keyword argument direction ('u' or 'v')"
            )))
        }
    };
    if positional.len() > N {
        return Err(PyTypeError::new_err(format!(
            "{method}: takes at most {N} positional argument(s) besides direction=, got {}",
            positional.len()
        )));
    }
    let mut positional = positional.into_iter();
    let mut out: [Option<Bound<'py, PyAny>>; N] = std::array::from_fn(|_| None);
    for ((slot, keyword), name) in out.iter_mut().zip(keywords).zip(names) {
        *slot = match (positional.next(), keyword) {
            (Some(_), Some(_)) => {
                return Err(PyTypeError::new_err(format!(
                    "{method}: got two values for {name}"
                )))
            }
            (Some(value), None) => Some(value),
            (None, keyword) => keyword.cloned(),
        };
    }
    Ok((direction, out))
}

/// A required argument `name` of `method` that neither form gave.
///
/// # Errors
/// `TypeError` naming the argument when it is missing.
pub(crate) fn required<'py>(
    arg: Option<Bound<'py, PyAny>>,
    method: &str,
    name: &str,
) -> PyResult<Bound<'py, PyAny>> {
    arg.ok_or_else(|| PyTypeError::new_err(format!("{method}: missing the argument {name}")))
}
