//! The one place figures get their numbers from the library.
//!
//! Every figure and the report read a [`RunOutput`] computed here by the core
//! crate's one run path ([`Job::run`]), or curves and distances asked of the
//! core's curves directly (a zoom's curves on its own parameters, the
//! distance at many alphas); plotting never recomputes the method.

use t2spline::job::{Job, Model, ModelVisitor, Overrides, Points, RunOutput, Samples, Spline};
use t2spline::sampling::DistanceSweep;
use t2spline::{Alpha, Axis, FuzzyCurve, FuzzySurface, Nt2Number, TypeReduction};

use crate::error::Error;

/// The fewest samples per curve in figures: a smooth line at print
/// resolution for curves of a few spans.
pub const MIN_FIGURE_SAMPLES: usize = 241;
/// Samples per knot span in figures, so that long curves stay smooth.
pub const SAMPLES_PER_SPAN: usize = 16;
/// The most samples per curve in figures: beyond, a curve has more spans than
/// a page has pixels along it.
pub const MAX_FIGURE_SAMPLES: usize = 65_537;

/// Samples per curve in figures of `model`: [`SAMPLES_PER_SPAN`] per knot
/// span, from [`MIN_FIGURE_SAMPLES`] to [`MAX_FIGURE_SAMPLES`]; independent
/// of the job's `samples` (which sets the result file's sampling).
#[must_use]
pub fn figure_samples(model: &Model) -> usize {
    struct Order;
    impl ModelVisitor for Order {
        type Output = usize;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> usize {
            c.order()
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> usize {
            1
        }
    }
    let spans = model
        .control_point_count()
        .saturating_sub(model.visit(Order))
        .saturating_add(1);
    spans
        .saturating_mul(SAMPLES_PER_SPAN)
        .saturating_add(1)
        .clamp(MIN_FIGURE_SAMPLES, MAX_FIGURE_SAMPLES)
}

/// The result of the job at `alpha` with the job's type reduction, sampled
/// for figures: a curve at [`figure_samples`], a surface on [`surface_grid`]
/// (a reduction other than the paper's does not use `alpha` and cuts stage 2
/// at 0, as `t2spline run` does).
///
/// # Errors
/// [`Error::Core`] if the run fails (it does not for a validated job without
/// derivatives).
pub fn compute(job: &Job, alpha: Alpha) -> Result<RunOutput, Error> {
    compute_with(job, alpha, job.type_reduction)
}

/// The result of the job at `alpha` with the type reduction `method`
/// (docs/method.md §9), sampled for figures, as [`compute`].
///
/// # Errors
/// As [`compute`].
pub fn compute_with(job: &Job, alpha: Alpha, method: TypeReduction) -> Result<RunOutput, Error> {
    compute_within(job, alpha, method, MAX_SURFACE_GRID)
}

/// The most grid points per direction of a surface in the report, whose
/// figures are stored at every slider stop: at most 24 × 24 quadrilaterals
/// per surface.
pub const REPORT_SURFACE_GRID: usize = 25;

/// [`compute_with`] with a surface's grid at most `max` points per direction.
///
/// # Errors
/// As [`compute`].
pub fn compute_within(
    job: &Job,
    alpha: Alpha,
    method: TypeReduction,
    max: usize,
) -> Result<RunOutput, Error> {
    let samples = match surface_grid(&job.model) {
        Some(grid) => Samples::Grid(grid.map(|n| n.min(max))),
        None => Samples::Along(figure_samples(&job.model)),
    };
    run_with(job, alpha, method, samples)
}

/// The result of the job at `alpha` with the type reduction `method` and
/// `samples`, as `t2spline run --alpha A --type-reduction M --samples S`
/// computes it (a curve or a surface), the settings checked by the core as
/// the command's are.
///
/// # Errors
/// [`Error::Core`] if the run fails (it does not for a validated job without
/// derivatives).
pub fn run_with(
    job: &Job,
    alpha: Alpha,
    method: TypeReduction,
    samples: Samples,
) -> Result<RunOutput, Error> {
    let samples = match samples {
        Samples::Along(n) => vec![n as u64],
        Samples::Grid(grid) => grid.map(|n| n as u64).to_vec(),
    };
    let settings = job.settings(&Overrides {
        alpha: Some(alpha.get()),
        type_reduction: Some(method),
        samples: Some(samples),
        derivatives: None,
    })?;
    Ok(job.run(&settings)?)
}

/// Grid points per knot span and direction in surface figures.
pub const SURFACE_SAMPLES_PER_SPAN: usize = 8;
/// The fewest grid points per direction in surface figures.
pub const MIN_SURFACE_GRID: usize = 17;
/// The most grid points per direction in surface figures: at most 48 × 48
/// quadrilaterals are drawn per surface, whatever the job's `samples` or the
/// size of its net, so a figure's cost is bounded.
pub const MAX_SURFACE_GRID: usize = 49;

/// The grid `[su, sv]` on which surface figures sample a surface model
/// ([`SURFACE_SAMPLES_PER_SPAN`] per knot span, from [`MIN_SURFACE_GRID`] to
/// [`MAX_SURFACE_GRID`] per direction); `None` for a curve.
#[must_use]
pub fn surface_grid(model: &Model) -> Option<[usize; 2]> {
    struct Grid;
    impl ModelVisitor for Grid {
        type Output = Option<[usize; 2]>;
        fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> Self::Output {
            None
        }
        fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Self::Output {
            let (shape, degree) = (s.shape(), s.degree());
            Some(std::array::from_fn(|k| {
                shape[k]
                    .saturating_sub(degree[k])
                    .saturating_mul(SURFACE_SAMPLES_PER_SPAN)
                    .saturating_add(1)
                    .clamp(MIN_SURFACE_GRID, MAX_SURFACE_GRID)
            }))
        }
    }
    model.visit(Grid)
}

/// What figures print of a curve's spline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveSpline<'a> {
    /// The order `k`.
    pub order: usize,
    /// The degree `k − 1`.
    pub degree: usize,
    /// The weights.
    pub weights: &'a [f64],
    /// The knots.
    pub knots: &'a [f64],
    /// The parameter where the distance is largest.
    pub max_at: f64,
}

/// The spline of a curve result (a surface's gives empty lists and `max_at`
/// NaN).
#[must_use]
pub fn curve_spline(r: &RunOutput) -> CurveSpline<'_> {
    let max_at = r.error.max_at.t().unwrap_or(f64::NAN);
    match &r.spline {
        Spline::Curve {
            order,
            degree,
            weights,
            knots,
            ..
        } => CurveSpline {
            order: *order,
            degree: *degree,
            weights,
            knots,
            max_at,
        },
        Spline::Surface { .. } => CurveSpline {
            order: 0,
            degree: 0,
            weights: &[],
            knots: &[],
            max_at,
        },
    }
}

/// The smallest alpha above `h`: the one-sided limit from above of a
/// quantity that jumps at `h` (every stage is continuous in alpha on each
/// side of a lower height, so the next float is that limit to rounding).
/// `None` for `h = 1`, which has no level above it.
#[must_use]
pub fn just_above(h: f64) -> Option<f64> {
    // Positive floats are ordered as their bits.
    (0.0..1.0)
        .contains(&h)
        .then(|| f64::from_bits(h.to_bits() + 1))
}

/// The crisp and the defuzzified curve of `model` at `alpha` with the type
/// reduction `method` (the result's [`RunOutput::type_reduction`]), at the
/// given parameters (any order; all in the domain).
///
/// # Errors
/// [`Error::Core`] if a parameter lies outside the domain.
pub fn curves_at(
    model: &Model,
    alpha: Alpha,
    method: TypeReduction,
    params: &[f64],
) -> Result<(Points, Points), Error> {
    struct At<'a>(Alpha, TypeReduction, &'a [f64]);
    impl ModelVisitor for At<'_> {
        type Output = Result<(Points, Points), Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            let s = c.solve_with(self.0, self.1);
            let crisp = s.crisp_curve().sample_soa(self.2)?;
            let solution = s.defuzzified_curve().sample_soa(self.2)?;
            Ok((Points::from(crisp), Points::from(solution)))
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> Self::Output {
            Err(Error::Surface)
        }
    }
    model.visit(At(alpha, method, params))
}

/// The crisp and the defuzzified surface of `model` at `alpha` with the type
/// reduction `method`, at the parameters `uv` (the ends of the largest
/// distance, at `error.max_at`).
///
/// # Errors
/// [`Error::Surface`] for a curve model; [`Error::Core`] if `uv` lies
/// outside the domain.
pub fn surfaces_at(
    model: &Model,
    alpha: Alpha,
    method: TypeReduction,
    uv: [f64; 2],
) -> Result<[Vec<f64>; 2], Error> {
    struct At(Alpha, TypeReduction, [f64; 2]);
    impl ModelVisitor for At {
        type Output = Result<[Vec<f64>; 2], Error>;
        fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> Self::Output {
            Err(Error::Surface)
        }
        fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Self::Output {
            let solution = s.solve_with(self.0, self.1);
            let [u, v] = self.2;
            let crisp = solution.crisp_surface().eval(u, v)?;
            let defuzzified = solution.defuzzified_surface().eval(u, v)?;
            Ok([crisp.to_vec(), defuzzified.to_vec()])
        }
    }
    model.visit(At(alpha, method, uv))
}

/// The core's sampled distance between the crisp and the defuzzified curve
/// or surface of the paper's type reduction at each alpha
/// ([`FuzzyCurve::distance_sweep`], [`FuzzySurface::distance_sweep`]):
/// `samples` uniform parameters along a curve, or the model's figure grid on
/// a surface.
fn distance_sweep(model: &Model, alphas: &[Alpha], samples: usize) -> Result<DistanceSweep, Error> {
    struct Levels<'a>(&'a [Alpha], usize, Option<[usize; 2]>);
    impl ModelVisitor for Levels<'_> {
        type Output = Result<DistanceSweep, Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            Ok(c.distance_sweep(self.0, self.1)?)
        }
        fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Self::Output {
            let grid = self.2.ok_or(Error::Surface)?;
            Ok(s.distance_sweep(self.0, grid)?)
        }
    }
    model.visit(Levels(alphas, samples, surface_grid(model)))
}

/// The distance `‖D(t) − C(t)‖` between the defuzzified curve of the paper's
/// type reduction and the crisp curve at each of `samples` uniform
/// parameters, for each alpha: the parameters, then one list per alpha.
///
/// # Errors
/// [`Error::Surface`] for a surface; [`Error::Core`] if sampling fails (never
/// for a validated job).
pub fn distance_along(
    model: &Model,
    alphas: &[Alpha],
    samples: usize,
) -> Result<(Vec<f64>, Vec<Vec<f64>>), Error> {
    struct Params(usize);
    impl ModelVisitor for Params {
        type Output = Result<Vec<f64>, Error>;
        fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
            Ok(c.domain().uniform(self.0)?)
        }
        fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> Self::Output {
            Err(Error::Surface)
        }
    }
    let params = model.visit(Params(samples))?;
    let sweep = distance_sweep(model, alphas, samples)?;
    let along = (0..sweep.len())
        .map(|k| sweep.distances(k).unwrap_or_default().to_vec())
        .collect();
    Ok((params, along))
}

/// The largest and the root-mean-square distance between the defuzzified
/// curve (or surface) of the paper's type reduction and the crisp one at each
/// alpha, sampled by the core ([`DistanceSweep::summary`]: the trapezoidal
/// rule over `samples` uniform parameters, or over a surface's figure grid).
/// Sampled versions of `error.max` and `error.rms` (which the run computes
/// exactly, independent of sampling): cheap enough for a hundred alphas of a
/// curve of a hundred thousand control points, and within a fraction of a
/// per cent of the exact figures at [`figure_samples`] (tested).
///
/// # Errors
/// [`Error::Core`] if sampling fails (never for a validated job).
pub fn sampled_distances(
    model: &Model,
    alphas: &[Alpha],
    samples: usize,
) -> Result<Vec<[f64; 2]>, Error> {
    Ok(distance_sweep(model, alphas, samples)?.summary())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn just_above_is_the_next_float() {
        let a = just_above(0.6).unwrap();
        assert!(a > 0.6 && a - 0.6 < 1e-15);
        assert_eq!(just_above(1.0), None);
        assert_eq!(just_above(0.0), Some(f64::from_bits(1)));
    }
}
