//! numpy in and out: arguments read as checked `float64` arrays (shape,
//! dtype, finite values, each error naming the argument), and results handed
//! to numpy without copies.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods, ToPyArray};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use t2spline::sampling::SampleBuffer;

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
    floats_with(arg, name, false)
}

/// [`floats`] with NaN allowed (a missing reading, a cell without data);
/// infinity is still refused.
///
/// # Errors
/// As [`floats`], but for NaN.
pub(crate) fn floats_or_nan(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    floats_with(arg, name, true)
}

fn floats_with(arg: &Bound<'_, PyAny>, name: &str, nan: bool) -> PyResult<Floats> {
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
    let refused = |v: &f64| !(v.is_finite() || (nan && v.is_nan()));
    if let Some((i, value)) = data.iter().enumerate().find(|(_, v)| refused(v)) {
        let place = if shape.is_empty() {
            name.to_owned()
        } else {
            format!("{name}[{}]", index_text(i, &shape))
        };
        let rule = if nan {
            "infinity is refused; NaN marks a missing value"
        } else {
            "NaN and infinity are refused"
        };
        return Err(PyValueError::new_err(format!(
            "{place} = {value} is not a finite number ({rule})"
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
        let (net, d) = self.net_shape(name, 1)?;
        Ok((net[0], d))
    }

    /// The net and the dimension `d` of an array of points in the plane or
    /// in space: `(n, d)` for a curve (`rank` 1), `(nu, nv, d)` for a
    /// surface (`rank` 2).
    ///
    /// # Errors
    /// `ValueError` naming `name` for any other shape.
    pub(crate) fn net_shape(&self, name: &str, rank: usize) -> PyResult<(Vec<usize>, usize)> {
        match self.shape.split_last() {
            Some((&d @ (2 | 3), net)) if net.len() == rank => Ok((net.to_vec(), d)),
            _ => {
                let (net, what) = match rank {
                    1 => ("n", "n points"),
                    _ => ("nu, nv", "a net of nu × nv points"),
                };
                Err(PyValueError::new_err(format!(
                    "{name}: expected shape ({net}, 2) or ({net}, 3): {what} in the plane or in space, got {}",
                    shape_text(&self.shape)
                )))
            }
        }
    }

    /// The values broadcast to `shape` by numpy's rule (trailing dimensions
    /// equal or 1, missing leading ones added), in C order; `None` if they
    /// do not broadcast.
    pub(crate) fn broadcast_to(&self, shape: &[usize]) -> Option<Vec<f64>> {
        let rank = shape.len();
        if self.shape.len() > rank {
            return None;
        }
        let mut dims = vec![1; rank];
        dims[rank - self.shape.len()..].copy_from_slice(&self.shape);
        if dims.iter().zip(shape).any(|(&g, &s)| g != s && g != 1) {
            return None;
        }
        // The stride of each dimension in the data, 0 where it is repeated.
        let mut strides = vec![0; rank];
        let mut stride = 1;
        for k in (0..rank).rev() {
            if dims[k] != 1 {
                strides[k] = stride;
            }
            stride *= dims[k];
        }
        let count: usize = shape.iter().product();
        let mut index = vec![0; rank];
        let mut out = Vec::with_capacity(count);
        for _ in 0..count {
            out.push(
                self.data[index
                    .iter()
                    .zip(&strides)
                    .map(|(i, s)| i * s)
                    .sum::<usize>()],
            );
            // The next multi-index in C order.
            for k in (0..rank).rev() {
                index[k] += 1;
                if index[k] < shape[k] {
                    break;
                }
                index[k] = 0;
            }
        }
        Some(out)
    }

    /// The rows of an `(n, D)` array as points.
    pub(crate) fn rows<const D: usize>(&self) -> Vec<[f64; D]> {
        self.data
            .chunks_exact(D)
            .map(|r| std::array::from_fn(|d| r[d]))
            .collect()
    }
}

/// The shape that arrays of shapes `a` and `b` broadcast to (numpy's rule);
/// `None` if they do not.
pub(crate) fn broadcast_shape(a: &[usize], b: &[usize]) -> Option<Vec<usize>> {
    let rank = a.len().max(b.len());
    let dim = |s: &[usize], k: usize| (k + s.len()).checked_sub(rank).map_or(1, |i| s[i]);
    (0..rank)
        .map(|k| match (dim(a, k), dim(b, k)) {
            (x, y) if x == y || y == 1 => Some(x),
            (1, y) => Some(y),
            _ => None,
        })
        .collect()
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

/// Arrays of at most this many numbers are copied into numpy's own memory.
const SMALL_ARRAY: usize = 4096;

/// A numpy array of `shape` holding `data` (C order). A large one takes
/// `data` over without a copy; a small one (a result of a tiny job holds
/// dozens) is copied into one numpy allocation, which costs a third of
/// handing the buffer over and reshaping it.
pub(crate) fn array<'py>(
    py: Python<'py>,
    data: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    if data.len() <= SMALL_ARRAY {
        let view = numpy::ndarray::ArrayViewD::from_shape(shape, &data)
            .map_err(|e| crate::errors::internal_error(&format!("an array's shape: {e}")))?;
        return Ok(view.to_pyarray(py).into_any());
    }
    Ok(PyArray1::from_vec(py, data)
        .reshape(shape.to_vec())?
        .into_any())
}

/// The engine's output (structure of arrays: one buffer of shape `lead +
/// (d,) + samples`, each coordinate contiguous) seen as an array of shape
/// `lead + samples + (d,)`, points last: a transposed view, no copy.
/// `(d, n)` becomes `(n, d)`, `(7, d, su, sv)` becomes `(7, su, sv, d)`.
pub(crate) fn coords_last<'py>(
    py: Python<'py>,
    buffer: SampleBuffer,
    lead: &[usize],
    d: usize,
    samples: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let shape: Vec<usize> = lead.iter().chain([&d]).chain(samples).copied().collect();
    let (l, r) = (lead.len(), samples.len());
    let axes: Vec<usize> = (0..l).chain(l + 1..=l + r).chain([l]).collect();
    crate::memory::owned_array(py, buffer, &shape)?.call_method1("transpose", (axes,))
}

/// Points given as one vector per coordinate (structure of arrays) at
/// sample points of shape `samples` (`(n,)` along a curve, `(su, sv)` on a
/// grid) as an array of shape `samples + (d,)`: a view of one buffer, so
/// each coordinate stays contiguous. The coordinates are copied into the
/// buffer with the GIL released (the stages of a 1000 × 1000 grid are
/// hundreds of megabytes).
pub(crate) fn columns_array<'py>(
    py: Python<'py>,
    columns: &[impl AsRef<[f64]> + Sync],
    samples: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let data: Vec<f64> = crate::errors::without_gil(py, || {
        columns
            .iter()
            .flat_map(|c| c.as_ref().iter().copied())
            .collect()
    })?;
    coords_last(py, data.into(), &[], columns.len(), samples)
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

    #[test]
    fn broadcasting_follows_numpy() {
        assert_eq!(broadcast_shape(&[3, 1], &[4]), Some(vec![3, 4]));
        assert_eq!(broadcast_shape(&[], &[2, 5]), Some(vec![2, 5]));
        assert_eq!(broadcast_shape(&[3], &[4]), None);
        let column = Floats {
            shape: vec![2, 1],
            data: vec![1.0, 2.0],
        };
        assert_eq!(
            column.broadcast_to(&[2, 3]),
            Some(vec![1.0, 1.0, 1.0, 2.0, 2.0, 2.0])
        );
        let row = Floats {
            shape: vec![3],
            data: vec![1.0, 2.0, 3.0],
        };
        assert_eq!(
            row.broadcast_to(&[2, 3]),
            Some(vec![1.0, 2.0, 3.0, 1.0, 2.0, 3.0])
        );
        assert_eq!(row.broadcast_to(&[3, 2]), None);
        let number = Floats {
            shape: vec![],
            data: vec![0.5],
        };
        assert_eq!(number.broadcast_to(&[2, 2]), Some(vec![0.5; 4]));
        assert_eq!(number.broadcast_to(&[0, 2]), Some(vec![]));
    }
}
