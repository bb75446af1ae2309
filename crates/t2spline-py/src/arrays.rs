//! numpy in and out: arguments read as checked `float64` arrays (shape,
//! dtype, finite values, each error naming the argument), and results handed
//! to numpy without copies.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// An argument read as a C-ordered `float64` array: its shape and a copy of
/// its values, every one finite.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Floats {
    pub(crate) shape: Vec<usize>,
    pub(crate) data: Vec<f64>,
}

/// `(5, 2)`, `(5,)`, `()`: a shape as numpy prints it.
pub(crate) fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Reads `arg` (a numpy array, a list, a number: anything `numpy.asarray`
/// takes) as real numbers.
///
/// # Errors
/// `TypeError` naming `name` for values that are not real numbers (strings,
/// objects, booleans, complex numbers); `ValueError` for a ragged list and
/// for NaN or infinity, naming the index.
pub(crate) fn floats(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    let py = arg.py();
    let numpy = py.import("numpy")?;
    let array = numpy.call_method1("asarray", (arg,)).map_err(|e| {
        PyValueError::new_err(format!(
            "{name}: cannot be read as an array of numbers: {}",
            e.value(py)
        ))
    })?;
    let dtype = array.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers (float64), got an array of dtype {}",
            dtype.str()?
        )));
    }
    // `ascontiguousarray` would turn a number into shape (1,).
    let kwargs = pyo3::types::PyDict::new(py);
    kwargs.set_item("dtype", numpy.getattr("float64")?)?;
    kwargs.set_item("order", "C")?;
    let array = numpy
        .call_method("asarray", (array,), Some(&kwargs))?
        .cast_into::<PyArrayDyn<f64>>()?;
    let shape = array.shape().to_vec();
    let data = array
        .readonly()
        .as_slice()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?
        .to_vec();
    if let Some((i, value)) = data.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        let place = if shape.is_empty() {
            name.to_owned()
        } else {
            format!("{name}[{}]", index_text(i, &shape))
        };
        return Err(PyValueError::new_err(format!(
            "{place} = {value} is not a finite number (NaN and infinity are refused)"
        )));
    }
    Ok(Floats { shape, data })
}

/// The multi-index of the `flat`-th value of a C-ordered array: `3, 1`.
fn index_text(mut flat: usize, shape: &[usize]) -> String {
    let mut index = vec![0; shape.len()];
    for (k, &n) in shape.iter().enumerate().rev() {
        index[k] = flat % n.max(1);
        flat /= n.max(1);
    }
    index
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

impl Floats {
    /// `Ok` if the shape is `want`.
    ///
    /// # Errors
    /// `ValueError` naming `name`, the shape expected (`what`, e.g.
    /// `"(5, 2, 2): [left, right] per coordinate of crisp"`) and the shape given.
    pub(crate) fn expect_shape(&self, name: &str, want: &[usize], what: &str) -> PyResult<()> {
        if self.shape == want {
            Ok(())
        } else {
            Err(PyValueError::new_err(format!(
                "{name}: expected shape {}{what}, got {}",
                shape_text(want),
                shape_text(&self.shape)
            )))
        }
    }

    /// The number of points `n` and their dimension `d` of an `(n, d)` array
    /// of points in the plane or in space.
    ///
    /// # Errors
    /// `ValueError` naming `name` for any other shape.
    pub(crate) fn points_shape(&self, name: &str) -> PyResult<(usize, usize)> {
        match self.shape[..] {
            [n, d @ (2 | 3)] => Ok((n, d)),
            _ => Err(PyValueError::new_err(format!(
                "{name}: expected shape (n, 2) or (n, 3): n points in the plane or in space, got {}",
                shape_text(&self.shape)
            ))),
        }
    }

    /// The rows of an `(n, D)` array as points.
    pub(crate) fn rows<const D: usize>(&self) -> Vec<[f64; D]> {
        self.data
            .chunks_exact(D)
            .map(|r| std::array::from_fn(|d| r[d]))
            .collect()
    }
}

/// An optional argument read as a 1-D array of `n` values (weights, one per
/// control point), or `None`.
///
/// # Errors
/// The errors of [`floats`]; `ValueError` for another shape.
pub(crate) fn optional_vector(
    arg: Option<&Bound<'_, PyAny>>,
    name: &str,
) -> PyResult<Option<Vec<f64>>> {
    arg.filter(|a| !a.is_none())
        .map(|a| {
            let f = floats(a, name)?;
            if f.shape.len() != 1 {
                return Err(PyValueError::new_err(format!(
                    "{name}: expected a 1-D array, got shape {}",
                    shape_text(&f.shape)
                )));
            }
            Ok(f.data)
        })
        .transpose()
}

/// A numpy array of `shape` that takes over `data` (C order) without a copy.
pub(crate) fn array<'py>(
    py: Python<'py>,
    data: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    Ok(PyArray1::from_vec(py, data)
        .reshape(shape.to_vec())?
        .into_any())
}

/// `array.transpose(axes)`: a view, no copy.
pub(crate) fn transposed<'py>(
    array: &Bound<'py, PyAny>,
    axes: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    array.call_method1("transpose", (axes.to_vec(),))
}

/// Points given as one vector per coordinate (structure of arrays) as an
/// `(n, d)` array: a view of one `(d, n)` buffer, so each coordinate stays
/// contiguous.
pub(crate) fn columns_array<'py>(
    py: Python<'py>,
    columns: &[impl AsRef<[f64]>],
) -> PyResult<Bound<'py, PyAny>> {
    let n = columns.first().map_or(0, |c| c.as_ref().len());
    let data: Vec<f64> = columns
        .iter()
        .flat_map(|c| c.as_ref().iter().copied())
        .collect();
    transposed(&array(py, data, &[columns.len(), n])?, &[1, 0])
}

/// Fixed-size points as an `(n, D)` array.
pub(crate) fn rows_array<'py, const D: usize>(
    py: Python<'py>,
    rows: Vec<[f64; D]>,
) -> PyResult<Bound<'py, PyAny>> {
    let n = rows.len();
    array(py, rows.into_flattened(), &[n, D])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_and_indices_read_as_numpy_prints_them() {
        assert_eq!(shape_text(&[5, 2]), "(5, 2)");
        assert_eq!(shape_text(&[5]), "(5,)");
        assert_eq!(shape_text(&[]), "()");
        assert_eq!(index_text(7, &[4, 2, 2]), "1, 1, 1");
    }
}
