//! Large sample buffers handed to numpy without a copy: an array over a
//! huge-page mapping (`t2spline::sampling::SampleBuffer`) is a view whose
//! base owns the mapping.
//!
//! numpy can own a `Vec<f64>` (`PyArray1::from_vec`), not a mapping. The
//! owner here is a small Python object that keeps the `SampleBuffer` and
//! describes its memory by numpy's array interface (`__array_interface__`:
//! address, length, `float64`); `numpy.asarray` of it makes an array that
//! keeps the owner alive as its `base`, and the mapping is unmapped when
//! the last view goes. No `unsafe` is needed: the address is handed over as
//! a number. Rust never reads or writes the values after handing them
//! over, so numpy's writes through the array race with nothing.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::sampling::SampleBuffer;

/// The owner of a mapped sample buffer that numpy arrays view.
#[pyclass(frozen, module = "t2spline._t2spline", name = "_SampleMemory")]
struct SampleMemory {
    buffer: SampleBuffer,
}

#[pymethods]
impl SampleMemory {
    /// numpy's array interface, version 3: a writable one-dimensional
    /// `float64` array of the buffer's values at their address.
    #[getter]
    fn __array_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("shape", (self.buffer.len(),))?;
        let order = if cfg!(target_endian = "little") {
            "<f8"
        } else {
            ">f8"
        };
        d.set_item("typestr", order)?;
        d.set_item("data", (self.buffer.as_ptr() as usize, false))?;
        d.set_item("version", 3)?;
        Ok(d)
    }
}

/// `buffer` as a numpy array of shape `shape` (whose product is its
/// length) without a copy: an ordinary vector moves into numpy, a mapping
/// is viewed through its owner.
///
/// # Errors
/// numpy's, if it cannot make the array.
pub(crate) fn owned_array<'py>(
    py: Python<'py>,
    buffer: SampleBuffer,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    if !buffer.is_mapped() {
        return Ok(PyArray1::from_vec(py, buffer.into_vec())
            .reshape(shape.to_vec())?
            .into_any());
    }
    let owner = Bound::new(py, SampleMemory { buffer })?;
    py.import("numpy")?
        .call_method1("asarray", (owner,))?
        .call_method1("reshape", (shape.to_vec(),))
}
