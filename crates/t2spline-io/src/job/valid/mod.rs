//! The common case first: a job with no problem at all, read in one typed
//! pass.
//!
//! The validator ([`parse`](super::parse)) builds a `serde_json::Value` tree,
//! walks it collecting every problem by its JSON path, and scans the text
//! again for duplicate keys and positions: three passes and an allocation
//! per value, key and path, needed to report every problem at its place but
//! wasted on a file that has none. Here serde's visitors read the text
//! straight into plain values ([`raw`]), and the rules are checked by the
//! core's constructors and the limits of [`limits`](super::limits), as the
//! validator checks them. Anything unexpected, and any rule broken, refuses:
//! the text then goes to the validator, whose messages are the only ones a
//! user sees. So a job accepted here is one the validator accepts, built the
//! same; a test (`same_as_the_validator`) holds the two to it on broken and
//! valid jobs. A data file for `t2spline fit` is read the same way, by the
//! same readers ([`data`]).

mod data;
mod fuzzy_points;
mod header;
mod raw;

pub(super) use data::data;

use t2spline::job::{
    check_grid_samples, Job, LengthUnit, Model, Samples, DEFAULT_SAMPLES, DEFAULT_SURFACE_SAMPLES,
};
use t2spline::{FuzzyCurve, FuzzySurface, TypeReduction};

use super::common::closure_gap;
use crate::limits::{check_net_size, check_surface_work, MAX_POINTS};
use fuzzy_points::fuzzy_points;
use header::{degree_of, header, sample_count, Header};
use raw::{Knots, Points, RawJob, Weights, Whole};

/// The job in `text` (without a byte-order mark) if it has no problem at
/// all; `None` if it has one, or anything this reading does not expect.
pub(super) fn job(text: &str) -> Option<Job> {
    build(raw::read(text)?)
}

/// The job of `raw`, every rule checked.
fn build(raw: RawJob) -> Option<Job> {
    let Header {
        key,
        order,
        alpha,
        height,
    } = header(&raw)?;
    let points = raw.points?;
    let model = match points.net {
        None => {
            let Whole::One(order) = order else {
                return None;
            };
            let weights = match raw.weights {
                Some(Weights::List(w)) => Some(w),
                None => None,
                Some(Weights::Rows(_)) => return None,
            };
            let knots = match raw.knots {
                Some(Knots::List(k)) => Some(k),
                None => None,
                Some(Knots::Directions(_)) => return None,
            };
            curve(degree_of(key, order)?, &points, height, weights, knots)?
        }
        Some(shape) => {
            let Whole::Pair(orders) = order else {
                return None;
            };
            let weights = match raw.weights {
                Some(Weights::Rows(w)) => Some(w),
                None => None,
                Some(Weights::List(_)) => return None,
            };
            let knots = match raw.knots {
                Some(Knots::Directions(k)) => k,
                None => [None, None],
                Some(Knots::List(_)) => return None,
            };
            let degree = [degree_of(key, orders[0])?, degree_of(key, orders[1])?];
            surface(degree, shape, &points, height, weights, knots)?
        }
    };
    let samples = match (raw.samples, &model) {
        (None, Model::Surface(_)) => Samples::Grid([DEFAULT_SURFACE_SAMPLES; 2]),
        (None, _) => Samples::Along(DEFAULT_SAMPLES),
        (Some(Whole::One(n)), Model::Surface(_)) => Samples::Grid(grid([n, n])?),
        (Some(Whole::Pair(n)), Model::Surface(_)) => Samples::Grid(grid(n)?),
        (Some(Whole::One(n)), _) => Samples::Along(sample_count(n)?),
        (Some(Whole::Pair(_)), _) => return None,
    };
    let units = match raw.units {
        Some(name) => Some(LengthUnit::named(&name)?),
        None => None,
    };
    // A surface has no closure; a curve said to close must.
    match (raw.closed, &model) {
        (Some(_), Model::Surface(_)) => return None,
        (Some(true), _) => closure_gap(&model).ok()?,
        _ => {}
    }
    Some(Job {
        description: raw.description,
        alpha,
        type_reduction: raw.type_reduction.unwrap_or(TypeReduction::Paper),
        samples,
        closed: raw.closed,
        units,
        model,
    })
}

/// A grid of samples: each number and the whole grid within the limits.
fn grid(n: [u64; 2]) -> Option<[usize; 2]> {
    let grid = [sample_count(n[0])?, sample_count(n[1])?];
    check_grid_samples(grid).ok()?;
    Some(grid)
}

/// A curve of 2 or 3 coordinates per point, within [`MAX_POINTS`].
fn curve(
    degree: usize,
    points: &Points,
    height: Option<f64>,
    weights: Option<Vec<f64>>,
    knots: Option<Vec<f64>>,
) -> Option<Model> {
    let n = points.numbers.len() / points.dimension;
    if n > MAX_POINTS {
        return None;
    }
    let weights = weights.unwrap_or_else(|| vec![1.0; n]);
    if points.dimension == 3 {
        let p = fuzzy_points::<3>(&points.numbers, height)?;
        FuzzyCurve::try_new(degree, p, weights, knots)
            .ok()
            .map(Model::Spatial)
    } else {
        let p = fuzzy_points::<2>(&points.numbers, height)?;
        FuzzyCurve::try_new(degree, p, weights, knots)
            .ok()
            .map(Model::Planar)
    }
}

/// A surface of a net of `shape`, within the limits of its size and work.
fn surface(
    degree: [usize; 2],
    [nu, nv]: [usize; 2],
    points: &Points,
    height: Option<f64>,
    weights: Option<Vec<Vec<f64>>>,
    knots: [Option<Vec<f64>>; 2],
) -> Option<Model> {
    check_net_size(nu * nv).ok()?;
    check_surface_work([nu, nv], degree.map(|p| p + 1)).ok()?;
    let flat = fuzzy_points::<3>(&points.numbers, height)?;
    let mut net = Vec::with_capacity(nu);
    let mut rest = flat.into_iter();
    for _ in 0..nu {
        net.push(rest.by_ref().take(nv).collect());
    }
    let weights = weights.unwrap_or_else(|| vec![vec![1.0; nv]; nu]);
    FuzzySurface::try_new(degree, net, weights, knots)
        .ok()
        .map(Model::Surface)
}

#[cfg(test)]
mod tests;
