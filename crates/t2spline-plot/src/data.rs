//! The one place figures get their numbers from the library.
//!
//! Every figure and the report read a [`RunResult`] computed here, so plotting
//! never recomputes the method; a different sampling engine only has to change
//! [`compute`].

use t2spline::{Alpha, Axis, Nt2Number};
use t2spline_io::{Job, JobCurve, RunResult};

use crate::Error;

/// Samples per curve in figures: enough for a smooth line at print resolution,
/// independent of the job's `samples` (which sets the result file's sampling).
pub const FIGURE_SAMPLES: usize = 241;

/// The result of the job at `alpha`, sampled for figures.
#[must_use]
pub fn compute(job: &Job, alpha: Alpha) -> RunResult {
    RunResult::compute(job, alpha, FIGURE_SAMPLES)
}

/// The crisp and the defuzzified curve at parameter `t` (where the distance
/// between them is largest), from the library's curves.
///
/// # Errors
/// [`Error::Core`] if `t` is outside the domain (it never is for `max_at`).
pub fn curves_at(job: &Job, alpha: Alpha, t: f64) -> Result<(Vec<f64>, Vec<f64>), Error> {
    fn at<const D: usize>(
        c: &t2spline::FuzzyCurve<D>,
        alpha: Alpha,
        t: f64,
    ) -> Result<(Vec<f64>, Vec<f64>), Error> {
        let s = c.solve(alpha);
        Ok((
            s.crisp_curve().eval(t)?.to_vec(),
            s.defuzzified_curve().eval(t)?.to_vec(),
        ))
    }
    match &job.curve {
        JobCurve::Planar(c) => at(c, alpha, t),
        JobCurve::Spatial(c) => at(c, alpha, t),
    }
}

/// The fuzzy number of one coordinate of one control point.
///
/// # Errors
/// [`Error::Option`] if the point or the axis does not exist in the job.
pub fn number(job: &Job, point: usize, axis: Axis) -> Result<Nt2Number, Error> {
    fn get<const D: usize>(
        c: &t2spline::FuzzyCurve<D>,
        point: usize,
        axis: Axis,
    ) -> Result<Nt2Number, Error> {
        let n = c.points().len();
        let p = c.points().get(point).ok_or_else(|| Error::Option {
            option: "--point",
            message: format!(
                "point {point} does not exist: the job has {n} points, 0 to {}",
                n - 1
            ),
        })?;
        if axis.index() >= D {
            return Err(Error::Option {
                option: "--axis",
                message: format!("coordinate {axis} does not exist in a {D}-D job"),
            });
        }
        Ok(*p.coord(axis))
    }
    match &job.curve {
        JobCurve::Planar(c) => get(c, point, axis),
        JobCurve::Spatial(c) => get(c, point, axis),
    }
}

/// The distinct lower heights of the job's numbers, ascending.
#[must_use]
pub fn heights(job: &Job) -> Vec<f64> {
    fn all<const D: usize>(c: &t2spline::FuzzyCurve<D>) -> Vec<f64> {
        c.points()
            .iter()
            .flat_map(|p| p.coords().iter().map(|x| x.height().get()))
            .collect()
    }
    let mut h = match &job.curve {
        JobCurve::Planar(c) => all(c),
        JobCurve::Spatial(c) => all(c),
    };
    h.sort_by(f64::total_cmp);
    h.dedup();
    h
}
