//! The rules of a surface's net: its shape, weights and knots, and the
//! domain of its parameters.

use crate::error::Error;
use crate::limits::{MAX_WEIGHT, MIN_WEIGHT};
use crate::nurbs::KnotVector;
use crate::place::Direction;

/// Checks that `(u, v)` lies in the domain of the knot vectors `[U, V]`.
pub(crate) fn check_params(knots: &[KnotVector; 2], u: f64, v: f64) -> Result<(), Error> {
    for (direction, t) in Direction::BOTH.into_iter().zip([u, v]) {
        knots[direction.index()]
            .domain()
            .check(t)
            .map_err(|e| e.in_direction(direction))?;
    }
    Ok(())
}

/// The clamped uniform knot vectors of degrees `[p, q]` for a net of `shape`.
pub(crate) fn default_knots(
    degree: [usize; 2],
    shape: [usize; 2],
) -> Result<[KnotVector; 2], Error> {
    let make = |d: Direction| {
        KnotVector::clamped_uniform(degree[d.index()], shape[d.index()])
            .map_err(|e| e.in_direction(d))
    };
    Ok([make(Direction::U)?, make(Direction::V)?])
}

/// Validates knot values of one direction (`None`: the clamped uniform
/// default), naming the direction in the error.
pub(crate) fn knots_in(
    direction: Direction,
    values: Option<Vec<f64>>,
    degree: usize,
    count: usize,
) -> Result<KnotVector, Error> {
    match values {
        Some(values) => KnotVector::try_new(values, degree, count),
        None => KnotVector::clamped_uniform(degree, count),
    }
    .map_err(|e| e.in_direction(direction))
}

/// The shape `[rows, columns]` of a net given as rows, which must all have
/// the length of the first.
///
/// # Errors
/// [`Error::NetShape`] naming the first row of another length.
pub(crate) fn net_shape<T>(rows: &[Vec<T>], what: &'static str) -> Result<[usize; 2], Error> {
    let columns = rows.first().map_or(0, Vec::len);
    match rows.iter().position(|r| r.len() != columns) {
        Some(row) => Err(Error::NetShape {
            what,
            row,
            reference: "points[0]",
            expected: columns,
            found: rows[row].len(),
        }),
        None => Ok([rows.len(), columns]),
    }
}

/// The weights of a net of `shape`, row by row, each finite and within
/// [[`MIN_WEIGHT`], [`MAX_WEIGHT`]].
///
/// # Errors
/// [`Error::NetShape`] for a wrong number of rows or of entries in a row;
/// [`Error::NetWeight`] for the first bad weight.
pub(crate) fn net_weights(weights: &[Vec<f64>], shape: [usize; 2]) -> Result<Vec<f64>, Error> {
    if weights.len() != shape[0] {
        return Err(Error::NetShape {
            what: "weights",
            row: weights.len().min(shape[0]),
            reference: "points",
            expected: shape[0],
            found: weights.len(),
        });
    }
    if let Some(row) = weights.iter().position(|r| r.len() != shape[1]) {
        return Err(Error::NetShape {
            what: "weights",
            row,
            reference: "points",
            expected: shape[1],
            found: weights[row].len(),
        });
    }
    let flat: Vec<f64> = weights.concat();
    net_weights_flat(&flat, shape)?;
    Ok(flat)
}

/// Checks the weights of a net of `shape` given row by row in one list.
///
/// # Errors
/// [`Error::Length`] for a wrong number of weights; [`Error::NetWeight`] for
/// the first weight that is not finite and positive or outside
/// [[`MIN_WEIGHT`], [`MAX_WEIGHT`]].
pub(crate) fn net_weights_flat(weights: &[f64], shape: [usize; 2]) -> Result<(), Error> {
    if weights.len() != shape[0] * shape[1] {
        return Err(Error::Length {
            what: "weights (one per control point of the net)",
            expected: shape[0] * shape[1],
            found: weights.len(),
        });
    }
    let first = weights
        .chunks(shape[1].max(1))
        .enumerate()
        .find_map(|(row, w)| net_weight_problems(row, w).into_iter().next());
    first.map_or(Ok(()), Err)
}

/// Every weight of row `row` of a net that is not finite and positive or
/// lies outside [[`MIN_WEIGHT`], [`MAX_WEIGHT`]] ([`Error::NetWeight`]);
/// empty if none. The counterpart of
/// [`weight_problems`](crate::nurbs::weight_problems) for the rows of a
/// surface, for validators that list every problem.
///
/// # Examples
/// ```
/// # use t2spline::nurbs::net_weight_problems;
/// let p = net_weight_problems(2, &[1.0, 0.0, 1e-200]);
/// let lines: Vec<String> = p.iter().map(ToString::to_string).collect();
/// assert_eq!(lines, [
///     "weights[2][1] = 0 must be finite and greater than 0",
///     "weights[2][2] = 1e-200 is outside [1e-150, 1e150]",
/// ]);
/// ```
#[must_use]
pub fn net_weight_problems(row: usize, weights: &[f64]) -> Vec<Error> {
    weights
        .iter()
        .enumerate()
        .filter_map(|(column, &value)| {
            let rule = if !(value.is_finite() && value > 0.0) {
                "must be finite and greater than 0"
            } else if !(MIN_WEIGHT..=MAX_WEIGHT).contains(&value) {
                "is outside [1e-150, 1e150]"
            } else {
                return None;
            };
            Some(Error::NetWeight {
                row,
                column,
                value,
                rule,
            })
        })
        .collect()
}
