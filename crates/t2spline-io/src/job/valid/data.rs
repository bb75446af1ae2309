//! A data file for `t2spline fit` with no problem at all, read in one typed
//! pass by the readers of a job ([`raw`](super::raw)) and built as the
//! validator's `Walker::data` builds it.
//!
//! A data file holds the keys of a curve job but `weights` and `knots`,
//! which the fit makes; each of them refuses, as do a degree of 0, fewer than
//! `degree + 1` points or more than [`MAX_POINTS`], a pair where one number
//! belongs (or one number where a net's pair belongs), a net of fewer than
//! `p + 1` rows or `q + 1` points per row, and every rule the job's reading
//! refuses. The text then goes to
//! the validator, whose messages are the only ones a user sees.

use t2spline::fit::FuzzyData;

use super::fuzzy_points::fuzzy_points;
use super::header::{degree_of, header, sample_count, Header};
use super::raw::{self, Whole};
use crate::fit_data::FitData;
use crate::limits::{check_net_size, MAX_POINTS};

/// The data file in `text` (without a byte-order mark) if it has no problem
/// at all; `None` if it has one, or anything this reading does not expect.
pub(in super::super) fn data(text: &str) -> Option<FitData> {
    let raw = raw::read(text)?;
    if raw.weights.is_some() || raw.knots.is_some() || raw.closed.is_some() || raw.units.is_some() {
        return None;
    }
    let Header {
        key,
        order,
        alpha,
        height,
    } = header(&raw)?;
    let points = raw.points?;
    let samples = match raw.samples {
        None => None,
        Some(Whole::One(s)) => Some(sample_count(s)?),
        Some(Whole::Pair(_)) => return None,
    };
    let (degree, degree_v, points) = match (points.net, order) {
        (None, Whole::One(order)) => {
            let degree = degree_of(key, order)?;
            let n = points.numbers.len() / points.dimension;
            if degree == 0 || n <= degree || n > MAX_POINTS {
                return None;
            }
            let points = if points.dimension == 3 {
                FuzzyData::Spatial(fuzzy_points::<3>(&points.numbers, height)?)
            } else {
                FuzzyData::Planar(fuzzy_points::<2>(&points.numbers, height)?)
            };
            (degree, None, points)
        }
        (Some([nu, nv]), Whole::Pair([ku, kv])) => {
            let [p, q] = [degree_of(key, ku)?, degree_of(key, kv)?];
            if points.dimension != 3 || p == 0 || q == 0 || nu <= p || nv <= q {
                return None;
            }
            check_net_size(nu.checked_mul(nv)?).ok()?;
            let flat = fuzzy_points::<3>(&points.numbers, height)?;
            let mut rest = flat.into_iter();
            let net: Vec<Vec<_>> = (0..nu).map(|_| rest.by_ref().take(nv).collect()).collect();
            (p, Some(q), FuzzyData::Net(net))
        }
        _ => return None,
    };
    Some(FitData {
        // Set by the caller, which knows the file's name.
        source: String::new(),
        description: raw.description,
        degree_key: key,
        degree,
        degree_v,
        alpha,
        type_reduction: raw.type_reduction,
        lower_height: height,
        samples,
        points,
    })
}

#[cfg(test)]
mod tests;
