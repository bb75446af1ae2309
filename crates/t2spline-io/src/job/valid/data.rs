//! A data file for `t2spline fit` with no problem at all, read in one typed
//! pass by the readers of a job ([`raw`](super::raw)) and built as the
//! validator's `Walker::data` builds it.
//!
//! A data file holds the keys of a curve job but `weights` and `knots`,
//! which the fit makes; each of them refuses, as does a net of points (a surface), a degree of 0, fewer than
//! `degree + 1` points or more than [`MAX_POINTS`], a pair where one number
//! belongs, and every rule the job's reading refuses. The text then goes to
//! the validator, whose messages are the only ones a user sees.

use t2spline::fit::FuzzyData;

use super::raw::{self, Whole};
use super::{fuzzy_points, header, Header};
use crate::fit_data::FitData;
use crate::limits::MAX_POINTS;

/// The data file in `text` (without a byte-order mark) if it has no problem
/// at all; `None` if it has one, or anything this reading does not expect.
pub(in super::super) fn data(text: &str) -> Option<FitData> {
    let raw = raw::read(text)?;
    if raw.weights.is_some() || raw.knots.is_some() {
        return None;
    }
    let Header {
        key,
        order,
        alpha,
        height,
    } = header(&raw)?;
    let Whole::One(order) = order else {
        return None;
    };
    let degree = super::degree_of(key, order)?;
    let points = raw.points?;
    let n = points.numbers.len() / points.dimension;
    if points.net.is_some() || degree == 0 || n <= degree || n > MAX_POINTS {
        return None;
    }
    let samples = match raw.samples {
        None => None,
        Some(Whole::One(s)) => Some(super::sample_count(s)?),
        Some(Whole::Pair(_)) => return None,
    };
    let points = if points.dimension == 3 {
        FuzzyData::Spatial(fuzzy_points::<3>(&points.numbers, height)?)
    } else {
        FuzzyData::Planar(fuzzy_points::<2>(&points.numbers, height)?)
    };
    Some(FitData {
        // Set by the caller, which knows the file's name.
        source: String::new(),
        description: raw.description,
        degree_key: key,
        degree,
        degree_v: None,
        alpha,
        type_reduction: raw.type_reduction,
        lower_height: height,
        samples,
        points,
    })
}

#[cfg(test)]
mod tests;
