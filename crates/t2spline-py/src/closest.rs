//! The targets of a closest-point query, one point `(dimension,)` or many
//! `(m, dimension)`, and the results given back in the same form: shared by
//! curves and surfaces (`closest_point`) and fuzzy surfaces
//! (`closest_points`).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::arrays::{array, floats, shape_text, Floats};

/// `(u, v, point, distance)` of a surface's closest points.
pub(crate) type ClosestArrays<'py> = (
    Bound<'py, PyAny>,
    Bound<'py, PyAny>,
    Bound<'py, PyAny>,
    Bound<'py, PyAny>,
);

/// The points of a closest-point query.
pub(crate) struct Targets {
    points: Floats,
    /// Whether a stack `(m, dimension)` was given (else one point).
    many: bool,
}

impl Targets {
    /// Reads `point` as one point of `d` coordinates or a stack of them.
    ///
    /// # Errors
    /// Those of [`floats`]; `ValueError` for another shape.
    pub(crate) fn extract(point: &Bound<'_, PyAny>, d: usize) -> PyResult<Self> {
        let points = floats(point, "point")?;
        let many = match points.shape[..] {
            [k] if k == d => false,
            [_, k] if k == d => true,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "point: expected shape ({d},) or (m, {d}), got {}",
                    shape_text(&points.shape)
                )))
            }
        };
        Ok(Targets { points, many })
    }

    /// The target points.
    pub(crate) fn rows<const D: usize>(&self) -> Vec<[f64; D]> {
        self.points.rows()
    }

    /// Values of shape `inner` per target: for one point a float (`inner`
    /// empty) or an array of shape `inner`, for `m` points an array
    /// `(m,) + inner`.
    pub(crate) fn pack<'py>(
        &self,
        py: Python<'py>,
        values: Vec<f64>,
        inner: &[usize],
    ) -> PyResult<Bound<'py, PyAny>> {
        if self.many {
            let shape: Vec<usize> = [self.points.shape[0]]
                .iter()
                .chain(inner)
                .copied()
                .collect();
            array(py, values, &shape)
        } else if inner.is_empty() {
            Ok(values
                .first()
                .copied()
                .unwrap_or(f64::NAN)
                .into_pyobject(py)?
                .into_any())
        } else {
            array(py, values, inner)
        }
    }
}
