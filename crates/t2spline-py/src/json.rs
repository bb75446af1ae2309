//! Python values and JSON text: `t2spline.to_json` (a result, or any dict
//! of JSON values with numpy arrays, in the layout of ``t2spline run``'s
//! result file, by the I/O crate's writer) and `json.loads` for dicts made
//! from the I/O crate's JSON.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};
use t2spline_io::job::{child, element};

/// `json.loads(text)`.
///
/// # Errors
/// Those of `json.loads` (none for the I/O crate's JSON).
pub(crate) fn loads<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}

/// The JSON value of a Python value: dicts (string keys, in their order),
/// lists and tuples, numpy arrays and numbers (by ``tolist``), floats, ints,
/// bools, strings and None. NaN is ``null``, as the result file writes an
/// absent lower end; infinity is refused. Places are written as the I/O
/// crate writes every place (`result.curves.crisp`, `result["a b"]`).
fn value(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<Value> {
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if obj.is_instance_of::<PyInt>() {
        let n: i64 = obj.extract()?;
        return Ok(Value::Number(n.into()));
    }
    if let Ok(x) = obj.cast::<PyFloat>() {
        let x = x.value();
        return match Number::from_f64(x) {
            Some(n) => Ok(Value::Number(n)),
            None if x.is_nan() => Ok(Value::Null),
            None => Err(PyValueError::new_err(format!(
                "{path}: {x} is not a finite number"
            ))),
        };
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Value::String(s.to_cow()?.into_owned()));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut out = Map::new();
        for (k, v) in d.iter() {
            let Ok(key) = k.cast::<PyString>() else {
                return Err(PyTypeError::new_err(format!(
                    "{path}: a key of type {} is not a string",
                    k.get_type().name()?
                )));
            };
            let key = key.to_cow()?.into_owned();
            let inner = value(&v, &child(path, &key))?;
            out.insert(key, inner);
        }
        return Ok(Value::Object(out));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for (k, item) in obj.try_iter()?.enumerate() {
            out.push(value(&item?, &element(path, k))?);
        }
        return Ok(Value::Array(out));
    }
    if obj.hasattr("tolist")? {
        return value(&obj.call_method0("tolist")?, path);
    }
    Err(PyTypeError::new_err(format!(
        "{path}: a value of type {} has no form in JSON",
        obj.get_type().name()?
    )))
}

/// The JSON text of a result of ``run`` (or ``run_many``), byte for byte as
/// ``t2spline run`` writes the result file: indented by two spaces, every
/// array of numbers on one line, numbers in the shortest form that reads
/// back to the same float, a newline at the end. NaN (an absent lower end
/// of ``control_points.alpha_cut``) is written ``null``.
///
/// Any dict of JSON values (numpy arrays and numbers among them) is
/// written in the same layout, a job of ``FuzzyCurve.to_job`` too.
///
/// Raises
/// ------
/// TypeError
///     For a value with no form in JSON, named by its place
///     (``result.curves.crisp``).
/// ValueError
///     For infinity.
///
/// Examples
/// --------
/// >>> print(to_json({"alpha": 0.5, "points": [[0.0, 1.0], [2.5, float("nan")]]}), end="")
/// {
///   "alpha": 0.5,
///   "points": [
///     [0.0, 1.0],
///     [2.5, null]
///   ]
/// }
#[pyfunction]
pub(crate) fn to_json(result: &Bound<'_, PyAny>) -> PyResult<String> {
    Ok(t2spline_io::to_json_pretty(&value(result, "result")?))
}
