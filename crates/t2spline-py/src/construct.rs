//! Reading the arguments that define curves: the degree (from `degree`,
//! `order` or the knots), counts, and fuzzy control or data points given as
//! arrays (`crisp (n, d)`, `upper`/`primary`/`lower (n, d, 2)`, a lower height
//! per number or for all).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::{Axis, Nt2Number, Nt2Point, Place};
use t2spline_io::job::MAX_ORDER;

use crate::arrays::{floats, shape_text, Floats};
use crate::dim::{ByDim, PointList};

/// The degree `p` from exactly one of `degree` and `order` (`p = k − 1`), or
/// when neither is given from the number of knots (`p = len(knots) − n − 1`).
/// The order is limited as in job files ([`MAX_ORDER`]).
///
/// # Errors
/// `ValueError` naming the keyword: both given, neither (and no knots), or
/// a value outside its range.
pub(crate) fn degree(
    degree: Option<i64>,
    order: Option<i64>,
    knots: Option<usize>,
    control_points: usize,
) -> PyResult<usize> {
    let max = MAX_ORDER as i64;
    match (degree, order) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(
            "degree, order: give one of them, not both (degree = order - 1)",
        )),
        (Some(p), None) if !(0..max).contains(&p) => Err(PyValueError::new_err(format!(
            "degree: {p} is outside [0, {}]",
            max - 1
        ))),
        (None, Some(k)) if !(1..=max).contains(&k) => Err(PyValueError::new_err(format!(
            "order: {k} is outside [1, {max}]"
        ))),
        // Both are within [0, MAX_ORDER] now.
        (Some(p), None) => Ok(p as usize),
        (None, Some(k)) => Ok(k as usize - 1),
        (None, None) => match knots {
            Some(m) if m > control_points && m - control_points <= MAX_ORDER => {
                Ok(m - control_points - 1)
            }
            Some(m) => Err(PyValueError::new_err(format!(
                "degree: not given, and {m} knots for {control_points} control points give no degree in [0, {}] (knots = control points + degree + 1)",
                max - 1
            ))),
            None => Err(PyValueError::new_err(
                "degree: missing: give degree or order (or knots)",
            )),
        },
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

/// The values of `f` broadcast to `shape` by numpy's rule (trailing
/// dimensions equal or 1, missing leading ones added): a number for all, a
/// row `(d,)` per coordinate, a column `(n, 1)` per point. `None` if they do
/// not broadcast.
fn broadcast(f: &Floats, shape: [usize; 2]) -> Option<Vec<f64>> {
    if f.shape.len() > 2 {
        return None;
    }
    let mut dims = [1, 1];
    dims[2 - f.shape.len()..].copy_from_slice(&f.shape);
    if dims.iter().zip(shape).any(|(&g, s)| g != s && g != 1) {
        return None;
    }
    let at = |i: usize, j: usize| f.data[(i % dims[0]) * dims[1] + j % dims[1]];
    Some(
        (0..shape[0])
            .flat_map(|i| (0..shape[1]).map(move |j| (i, j)))
            .map(|(i, j)| at(i, j))
            .collect(),
    )
}

/// Fuzzy points given as arrays, their shapes checked against each other.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FuzzyArrays {
    /// Number of points.
    pub(crate) n: usize,
    /// Coordinates per point: 2 or 3.
    pub(crate) d: usize,
    crisp: Floats,
    upper: Floats,
    primary: Floats,
    lower: Floats,
    /// The lower height of every number, `(n, d)` in C order.
    heights: Vec<f64>,
}

impl FuzzyArrays {
    /// Reads `crisp (n, d)`, `upper`, `primary`, `lower (n, d, 2)` (`[left,
    /// right]` last) and `lower_height` (a number, or `(n, d)`).
    ///
    /// # Errors
    /// `TypeError` / `ValueError` naming the argument and the shape expected.
    pub(crate) fn read(
        crisp: &Bound<'_, PyAny>,
        upper: &Bound<'_, PyAny>,
        primary: &Bound<'_, PyAny>,
        lower: &Bound<'_, PyAny>,
        lower_height: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let crisp = floats(crisp, "crisp")?;
        let (n, d) = crisp.points_shape("crisp")?;
        let feet = |arg, name| -> PyResult<Floats> {
            let f = floats(arg, name)?;
            f.expect_shape(name, &[n, d, 2], ": [left, right] per coordinate of crisp")?;
            Ok(f)
        };
        let (upper, primary, lower) = (
            feet(upper, "upper")?,
            feet(primary, "primary")?,
            feet(lower, "lower")?,
        );
        let h = floats(lower_height, "lower_height")?;
        let heights = broadcast(&h, [n, d]).ok_or_else(|| {
            PyValueError::new_err(format!(
                "lower_height: expected a number or an array that broadcasts to shape {}: one per coordinate of crisp, got {}",
                shape_text(&[n, d]),
                shape_text(&h.shape)
            ))
        })?;
        Ok(FuzzyArrays {
            n,
            d,
            crisp,
            upper,
            primary,
            lower,
            heights,
        })
    }

    /// The points in their dimension, every number checked (SPEC §1).
    ///
    /// # Errors
    /// The first broken rule, naming its place (`points[2].y: the order …`).
    pub(crate) fn points(&self) -> Result<ByDim<PointList>, t2spline::Error> {
        Ok(match self.d {
            2 => ByDim::Planar(self.points_of()?),
            _ => ByDim::Spatial(self.points_of()?),
        })
    }

    fn points_of<const D: usize>(&self) -> Result<Vec<Nt2Point<D>>, t2spline::Error> {
        debug_assert_eq!(D, self.d);
        let feet = |f: &Floats, k: usize| [f.data[2 * k], f.data[2 * k + 1]];
        (0..self.n)
            .map(|i| {
                let mut coords = Vec::with_capacity(D);
                for (d, axis) in Axis::ALL.into_iter().take(D).enumerate() {
                    let k = i * D + d;
                    let number = Nt2Number::try_new(
                        self.crisp.data[k],
                        feet(&self.upper, k),
                        feet(&self.primary, k),
                        feet(&self.lower, k),
                        self.heights[k],
                    )
                    .map_err(|e| e.at(Place::new(i, axis)))?;
                    coords.push(number);
                }
                // One number was pushed per coordinate, D of them: the error
                // is never made.
                let coords: [Nt2Number; D] =
                    coords
                        .try_into()
                        .map_err(|v: Vec<_>| t2spline::Error::Length {
                            what: "coordinates",
                            expected: D,
                            found: v.len(),
                        })?;
                Ok(Nt2Point::new(coords))
            })
            .collect()
    }
}
