//! Scalar arguments (`degree=`, `alpha=`, `samples=`, `type_reduction=`, …)
//! read from Python with errors that name the argument and say what it
//! takes: `TypeError: samples: expected an int or a pair (u, v) of ints, got
//! str`, `ValueError: degree: 18446744073709551616 is outside the range of a
//! 64-bit integer`. PyO3's own conversion would name Rust types
//! (`failed to extract enum PerDirection`) or nothing at all (`must be real
//! number, not str`, `OverflowError: Python int too large to convert to C
//! long`); every function and method of the package takes its scalar
//! arguments as Python objects and reads them here.
//!
//! The rules of each argument (a degree in `[0, 63]`, alpha in `[0, 1]`)
//! are checked after reading, by the code that knows them.

use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyString, PyTuple};

/// The Python type name of `arg`, for messages (`str`, `float`, `NoneType`).
fn type_name(arg: &Bound<'_, PyAny>) -> String {
    arg.get_type()
        .name()
        .map_or_else(|_| "an object".to_owned(), |n| n.to_string())
}

/// The items of a tuple or a list, else `None`.
fn pair_items<'py>(arg: &Bound<'py, PyAny>) -> Option<Vec<Bound<'py, PyAny>>> {
    if let Ok(t) = arg.cast::<PyTuple>() {
        Some(t.iter().collect())
    } else if let Ok(l) = arg.cast::<PyList>() {
        Some(l.iter().collect())
    } else {
        None
    }
}

/// What `arg` is, for messages: its type, and the length of a tuple or a
/// list (`str`, `a tuple of 3 items`).
fn described(arg: &Bound<'_, PyAny>) -> String {
    match pair_items(arg) {
        Some(items) => format!("a {} of {} item(s)", type_name(arg), items.len()),
        None => type_name(arg),
    }
}

/// `arg`'s `repr`, for messages.
fn shown(arg: &Bound<'_, PyAny>) -> String {
    arg.repr()
        .map_or_else(|_| "the value".to_owned(), |r| r.to_string())
}

/// An integer argument: a Python `int` or anything with `__index__` (numpy
/// integers).
///
/// # Errors
/// `TypeError` naming `name` for anything else (a `str`, a `float`);
/// `ValueError` naming `name` for an int beyond 64 bits.
pub(crate) fn int(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<i64> {
    arg.extract::<i64>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(arg.py()) {
            PyValueError::new_err(format!(
                "{name}: {} is outside the range of a 64-bit integer [-2**63, 2**63 - 1]",
                shown(arg)
            ))
        } else {
            PyTypeError::new_err(format!("{name}: expected an int, got {}", type_name(arg)))
        }
    })
}

/// [`int`] for an argument that may be `None` or left out.
///
/// # Errors
/// As [`int`].
pub(crate) fn opt_int(arg: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<i64>> {
    arg.filter(|a| !a.is_none())
        .map(|a| int(a, name))
        .transpose()
}

/// A real argument: a Python `float` or `int`, or anything with `__float__`
/// (numpy numbers). NaN and infinity are read; the argument's rule refuses
/// them where it must.
///
/// # Errors
/// `TypeError` naming `name` for anything else (a `str`, a list);
/// `ValueError` naming `name` for an int too large for a float.
pub(crate) fn real(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if arg.is_instance_of::<PyString>() {
        // `float("0.5")` would read it; a number given as text is refused.
        return Err(expected_real(arg, name));
    }
    arg.extract::<f64>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(arg.py()) {
            PyValueError::new_err(format!(
                "{name}: {} is too large for a 64-bit float (about 1.8e308)",
                shown(arg)
            ))
        } else {
            expected_real(arg, name)
        }
    })
}

fn expected_real(arg: &Bound<'_, PyAny>, name: &str) -> PyErr {
    PyTypeError::new_err(format!(
        "{name}: expected a real number (float or int), got {}",
        type_name(arg)
    ))
}

/// [`real`] for an argument that may be `None` or left out.
///
/// # Errors
/// As [`real`].
pub(crate) fn opt_real(arg: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    arg.filter(|a| !a.is_none())
        .map(|a| real(a, name))
        .transpose()
}

/// A pair of reals `(a, b)` (a tuple or a list of two), its items named
/// `name[0]`, `name[1]`.
///
/// # Errors
/// `TypeError` naming `name` for anything else; the errors of [`real`].
pub(crate) fn real_pair(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<(f64, f64)> {
    match pair_items(arg).as_deref() {
        Some([a, b]) => Ok((
            real(a, &format!("{name}[0]"))?,
            real(b, &format!("{name}[1]"))?,
        )),
        _ => Err(PyTypeError::new_err(format!(
            "{name}: expected a pair (a, b) of real numbers, got {}",
            described(arg)
        ))),
    }
}

/// The `times=` of the knot operations: a count of at least 1, 1 when not
/// given.
///
/// # Errors
/// As [`int`], and `ValueError` for a count below 1.
pub(crate) fn times(arg: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    match opt_int(arg, "times")? {
        None => Ok(1),
        Some(n) => count(n, "times", 1),
    }
}

/// A name among choices (`type_reduction=`, `layer=`, `direction=`): a
/// `str`; which names are known is said by the code that reads it.
///
/// # Errors
/// `TypeError` naming `name` for anything but a `str`.
pub(crate) fn text(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    match arg.cast::<PyString>() {
        Ok(s) => Ok(s.to_cow()?.into_owned()),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name}: expected a str, got {}",
            type_name(arg)
        ))),
    }
}

/// [`text`] for an argument that may be `None` or left out.
///
/// # Errors
/// As [`text`].
pub(crate) fn opt_text(arg: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<String>> {
    arg.filter(|a| !a.is_none())
        .map(|a| text(a, name))
        .transpose()
}

/// A bool (`True` or `False`, not a number) for an argument that may be
/// `None` or left out.
///
/// # Errors
/// `TypeError` naming `name` for anything else.
pub(crate) fn opt_bool(arg: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<bool>> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return Ok(None);
    };
    match arg.cast::<pyo3::types::PyBool>() {
        Ok(b) => Ok(Some(b.is_true())),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name}: expected True, False or None, got {}",
            type_name(arg)
        ))),
    }
}

/// One int for both directions of a surface, or a pair `(u, v)` (a tuple or
/// a list of two ints); the ints of a pair are named `name[0]`, `name[1]`.
///
/// # Errors
/// `TypeError` naming `name` for anything else; the errors of [`int`].
pub(crate) fn per_direction(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<PerDirection> {
    let expected = || {
        PyTypeError::new_err(format!(
            "{name}: expected an int or a pair (u, v) of ints, got {}",
            described(arg)
        ))
    };
    match pair_items(arg).as_deref() {
        Some([u, v]) => Ok(PerDirection::Two(
            int(u, &format!("{name}[0]"))?,
            int(v, &format!("{name}[1]"))?,
        )),
        Some(_) => Err(expected()),
        None => int(arg, name).map(PerDirection::One).map_err(|e| {
            if e.is_instance_of::<PyTypeError>(arg.py()) {
                expected()
            } else {
                e
            }
        }),
    }
}

/// [`per_direction`] for an argument that may be `None` or left out.
///
/// # Errors
/// As [`per_direction`].
pub(crate) fn opt_per_direction(
    arg: Option<&Bound<'_, PyAny>>,
    name: &str,
) -> PyResult<Option<PerDirection>> {
    arg.filter(|a| !a.is_none())
        .map(|a| per_direction(a, name))
        .transpose()
}

/// One value for both directions of a surface, or one per direction
/// (`samples=(21, 11)`, `degree=(2, 1)`), read by
/// [`per_direction`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PerDirection {
    /// The same value along u and along v.
    One(i64),
    /// The values along u and along v.
    Two(i64, i64),
}

impl PerDirection {
    /// The values along u and along v.
    pub(crate) fn pair(self) -> [i64; 2] {
        match self {
            PerDirection::One(n) => [n, n],
            PerDirection::Two(u, v) => [u, v],
        }
    }
}

/// A count from Python (`times=`, `count=`), at least `min`.
///
/// # Errors
/// `ValueError` naming `name` for a smaller value.
pub(crate) fn count(value: i64, name: &str, min: usize) -> PyResult<usize> {
    usize::try_from(value)
        .ok()
        .filter(|&v| v >= min)
        .ok_or_else(|| {
            PyValueError::new_err(format!("{name}: must be at least {min}, got {value}"))
        })
}

/// Levels given as floats (`levels=`, `alphas=`), each in [0, 1].
///
/// # Errors
/// `ValueError` naming `name[i]` for the first level outside [0, 1].
pub(crate) fn alphas(values: &[f64], name: &str) -> PyResult<Vec<t2spline::Alpha>> {
    values
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            t2spline::Alpha::try_new(v)
                .map_err(|_| PyValueError::new_err(format!("{name}[{i}]: {v} is outside [0, 1]")))
        })
        .collect()
}
