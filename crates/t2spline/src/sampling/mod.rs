//! Fast sampling: many curves that share knots and weights, at many parameters.
//!
//! Figures, reports, alpha sweeps and fitting evaluate one curve at many
//! parameters for its seven layers and many alpha levels. The [`Sampler`] turns
//! the rational basis into power form once per knot span and applies it to
//! every *channel* (one coordinate of one curve): for a parameter it evaluates
//! the common denominator once, and each channel with one Horner evaluation.
//! Sorted parameters are walked span by span; output is structure of arrays
//! ([`CurveSamples`]: one vector per coordinate); large jobs run on rayon's
//! threads (feature `parallel`, on by default) with results identical bit for
//! bit to one thread.
//!
//! The curve types use it:
//!
//! | call | samples |
//! |---|---|
//! | [`NurbsCurve::sample_soa`](crate::NurbsCurve::sample_soa) | one crisp curve |
//! | [`FuzzyCurve::sample_layers`](crate::FuzzyCurve::sample_layers) | the seven layer curves (stage 1) |
//! | [`FuzzyCurve::sample_sweep`](crate::FuzzyCurve::sample_sweep) | stage 1 and stages 2–4 at many alpha levels |
//! | [`FuzzyCurve::sample_sweep_with`](crate::FuzzyCurve::sample_sweep_with) | the same with another type reduction (docs/method.md §9) |
//! | [`Solution::sample_stages`](crate::Solution::sample_stages) | stages 2–4 at one level, by the solution's type reduction |
//!
//! Surfaces (docs/method.md §8) are sampled on grids `u_a × v_b` by the [`GridSampler`],
//! which evaluates the basis in u once per grid row and in v once per grid
//! column for all channels, into the same containers wrapped in a [`Grid`]:
//!
//! | call | samples |
//! |---|---|
//! | [`NurbsSurface::sample_grid`](crate::NurbsSurface::sample_grid) | one crisp surface |
//! | [`FuzzySurface::sample_layers`](crate::FuzzySurface::sample_layers) | the seven layer surfaces |
//! | [`FuzzySurface::sample_sweep`](crate::FuzzySurface::sample_sweep) | stage 1 and stages 2–4 at many alpha levels |
//! | [`FuzzySurface::sample_sweep_with`](crate::FuzzySurface::sample_sweep_with) | the same with another type reduction (docs/method.md §9) |
//! | [`SurfaceSolution::sample_stages`](crate::SurfaceSolution::sample_stages) | stages 2–4 at one level, by the solution's type reduction |
//!
//! The straightforward evaluators ([`NurbsCurve::eval`](crate::NurbsCurve::eval),
//! [`FuzzyCurve::eval_layers`](crate::FuzzyCurve::eval_layers)) stay as the
//! reference that the tests hold this engine to (1e-12 relative). A span whose
//! power form would lose that accuracy (weights spread over many orders of
//! magnitude, very high degrees) is evaluated from the basis directly, as they
//! do, at their speed.

mod benchmark;
mod curves;
mod direct;
mod grid;
mod kernel;
mod params;
mod plan;
mod power_form;
mod sampler;
mod samples;
mod surfaces;

pub use benchmark::{benchmark_curve, benchmark_levels, benchmark_surface};
pub use grid::GridSampler;
pub use params::Params;
pub use sampler::{Bound, Sampler};
pub use samples::{CurveSamples, Grid, LayerSamples, StageSamples, SweepSamples};
