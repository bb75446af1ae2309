//! Where a job given as a dict holds a value that has no form in a job file
//! (a set, an object of a class of its own, a dict key that is a tuple):
//! `json.dumps` says only its type, so the dict is walked as `json.dumps`
//! writes it to name the value by its place, written as the I/O crate
//! writes every place of a job (`points[1].x.crisp`, `["odd key"]`).

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use t2spline_io::job::{child, element};

/// The place (JSON path) and the rule of the first value of `obj` (at
/// `path`) that `json.dumps` cannot write, numpy arrays and numbers written
/// by their `tolist`; `None` when every value has a form.
///
/// # Errors
/// Those of Python while reading the values.
pub(crate) fn unwritable(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Option<(String, String)>> {
    if obj.is_none()
        || obj.is_instance_of::<PyBool>()
        || obj.is_instance_of::<PyInt>()
        || obj.is_instance_of::<PyFloat>()
        || obj.is_instance_of::<PyString>()
    {
        return Ok(None);
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        for (k, v) in d.iter() {
            let key_written = k.is_none()
                || k.is_instance_of::<PyString>()
                || k.is_instance_of::<PyInt>()
                || k.is_instance_of::<PyFloat>();
            if !key_written {
                return Ok(Some((
                    path.to_owned(),
                    format!("a key of type {} is not a string", k.get_type().name()?),
                )));
            }
            let key = k.str()?.to_cow()?.into_owned();
            if let Some(found) = unwritable(&v, &child(path, &key))? {
                return Ok(Some(found));
            }
        }
        return Ok(None);
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        for (i, item) in obj.try_iter()?.enumerate() {
            if let Some(found) = unwritable(&item?, &element(path, i))? {
                return Ok(Some(found));
            }
        }
        return Ok(None);
    }
    if obj.hasattr("tolist")? {
        return unwritable(&obj.call_method0("tolist")?, path);
    }
    Ok(Some((
        path.to_owned(),
        format!(
            "a value of type {} has no form in a job file",
            obj.get_type().name()?
        ),
    )))
}
