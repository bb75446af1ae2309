//! The one place figures get their numbers from the library.
//!
//! Every figure and the report read a [`RunOutput`] computed here by the core
//! crate's one run path ([`Job::run`]), so plotting never recomputes the
//! method.

use t2spline::job::{Job, Model, ModelVisitor, Overrides, RunOutput};
use t2spline::{Alpha, Axis, FuzzyCurve, FuzzySurface, Nt2Number, TypeReduction};

use crate::Error;

/// Samples per curve in figures: enough for a smooth line at print resolution,
/// independent of the job's `samples` (which sets the result file's sampling).
pub const FIGURE_SAMPLES: usize = 241;

/// The result of the job at `alpha` with the job's type reduction, sampled
/// for figures: what `t2spline run --alpha A` computes (a reduction other
/// than the paper's does not use `alpha` and cuts stage 2 at 0).
///
/// # Errors
/// [`Error::Surface`] for a surface job; [`Error::Core`] if the run fails (it
/// does not for a validated curve job without derivatives).
pub fn compute(job: &Job, alpha: Alpha) -> Result<RunOutput, Error> {
    compute_with(job, alpha, job.type_reduction)
}

/// The result of the job at `alpha` with the type reduction `method`
/// (SPEC §10), sampled for figures, as [`compute`].
///
/// # Errors
/// As [`compute`].
pub fn compute_with(job: &Job, alpha: Alpha, method: TypeReduction) -> Result<RunOutput, Error> {
    if job.model.is_surface() {
        return Err(Error::Surface);
    }
    let settings = job.settings(&Overrides {
        alpha: Some(alpha.get()),
        type_reduction: Some(method),
        samples: Some(vec![FIGURE_SAMPLES as u64]),
        derivatives: None,
    })?;
    Ok(job.run(&settings)?)
}

/// The parameter where a curve's distance is largest (results of [`compute`]
/// are curves).
#[must_use]
pub fn max_at(r: &RunOutput) -> f64 {
    r.error.max_at.t().unwrap_or(f64::NAN)
}

/// The crisp and the defuzzified curve of the type reduction `method` at
/// parameter `t` (where the distance between them is largest), from the
/// library's curves.
///
/// # Errors
/// [`Error::Core`] if `t` is outside the domain (it never is for `max_at`).
pub fn curves_at(
    model: &Model,
    alpha: Alpha,
    method: TypeReduction,
    t: f64,
) -> Result<(Vec<f64>, Vec<f64>), Error> {
    struct At(Alpha, TypeReduction, f64);
    impl ModelVisitor for At {
        type Output = Result<(Vec<f64>, Vec<f64>), Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            let s = c.solve_with(self.0, self.1);
            Ok((
                s.crisp_curve().eval(self.2)?.to_vec(),
                s.defuzzified_curve().eval(self.2)?.to_vec(),
            ))
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> Self::Output {
            Err(Error::Surface)
        }
    }
    model.visit(At(alpha, method, t))
}

/// The fuzzy number of one coordinate of one control point.
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if the point or the axis
/// does not exist in the model.
pub fn number(model: &Model, point: usize, axis: Axis) -> Result<Nt2Number, Error> {
    let count = model.control_point_count();
    if point >= count {
        return Err(Error::NoSuchPoint { point, count });
    }
    let dimension = model.dimension();
    model
        .number(point, axis)
        .ok_or(Error::NoSuchAxis { axis, dimension })
}
