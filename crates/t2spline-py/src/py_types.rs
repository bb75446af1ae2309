//! Short names for the PyO3 types that the bindings' signatures repeat: a
//! borrowed Python object and the results made of them. A method then reads
//! as its arguments, not as PyO3's lifetimes.

use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A Python object bound to the interpreter for `'py`: an argument as PyO3
/// hands it over (`&Obj<'py>`), or a result.
pub(crate) type Obj<'py> = Bound<'py, PyAny>;

/// A Python object, or the exception raised instead.
pub(crate) type ObjResult<'py> = PyResult<Bound<'py, PyAny>>;

/// A dict, or the exception raised instead.
pub(crate) type DictResult<'py> = PyResult<Bound<'py, PyDict>>;

/// Two objects: a box's `(min, max)`.
pub(crate) type Pair<'py> = (Bound<'py, PyAny>, Bound<'py, PyAny>);

/// Three objects: a curve's closest points `(t, point, distance)`.
pub(crate) type Triple<'py> = (Bound<'py, PyAny>, Bound<'py, PyAny>, Bound<'py, PyAny>);
