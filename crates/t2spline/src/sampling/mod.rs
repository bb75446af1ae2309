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
//!
//! # Why it is built this way
//!
//! Every curve of a fuzzy curve and of its stages shares one knot vector and
//! one set of weights, so the weighted basis `wⱼNⱼ,ₚ` of a span is the same for
//! all of them. The sampler converts it once per non-empty span into
//! polynomials in the span's local variable and treats each coordinate of each
//! curve as one more channel of `p + 1` coefficients: a parameter then costs
//! one Horner evaluation and one division for the common denominator, and one
//! Horner evaluation and one multiplication per channel. A sweep computes each
//! level's stage-2–4 control points as `FuzzyCurve::solve` does and samples
//! them as further channels, so stages act on control points here as they do
//! everywhere (docs/method.md §6), mixed lower heights need no case of their
//! own, and a further level costs one Horner evaluation per coordinate of
//! each of its curves.
//!
//! Converting a span costs more than evaluating one parameter from the basis,
//! so a job with fewer parameters than knot spans builds no power form at all
//! and evaluates every span directly (`run` at 101 samples of 100 000 control
//! points: building every span's table took a third of such a run and 1.8 GB).
//! The same direct path serves spans whose power form is ill-conditioned
//! (`direct.rs`).
//!
//! The power form rounds differently from the convex combination of
//! [`NurbsCurve::eval`](crate::NurbsCurve::eval), so two layer curves a few
//! ulps apart could swap. A [`Bound`] clamps each sampled curve to the
//! neighbours the exact curves provably respect: each layer to its inner
//! neighbour, and for the paper's reduction the type-reduced curves around the
//! crisp one with the defuzzified curve between them. A centroid interval can
//! lie wholly on one side of `crisp` (docs/method.md §9), and the paper's
//! bounds moved such a left curve onto the crisp curve (0.009 off on a test
//! curve), so for the other reductions the bounds are `left ≤ right` and
//! `left ≤ defuzzified ≤ right` (`plan.rs`). The clamp removes rounding only
//! and never adds error beyond the neighbour's.
//!
//! Jobs of at least 2¹⁶ channel values (feature `parallel`, on by default) are
//! cut into chunks of whole blocks and run on rayon's current pool. Every value
//! is computed by the same operations in any chunking, so the results are those
//! of one thread bit for bit (tested); without the feature the core has no
//! rayon. Output is exactly one [`SampleBuffer`] per channel and nothing else
//! grows with the number of parameters (uniform parameters are never stored).
//! Fresh output used to cost page faults on first write that dominated at
//! 10⁶–10⁷ points: a large buffer is now a huge-page mapping first touched by
//! the threads that fill it, and dropped ones are kept for the next output
//! (`buffer.rs`, `mapping.rs`); the `_into` forms reuse a caller's buffers. A job's run samples the
//! solution it has already computed (one sampler for the layers and the
//! stages) rather than asking a sweep to solve again, since the alpha-plane
//! reduction integrates per number.
//!
//! The criterion benchmark `benches/sampling.rs` samples the same curve with
//! curvo in the same run, after checking that both agree to 1e-12; curvo is a
//! dev-dependency only.

mod benchmark;
mod buffer;
mod curves;
mod direct;
mod distance_sweep;
mod grid;
mod kernel;
#[cfg(target_os = "linux")]
mod mapping;
mod memory;
mod params;
mod plan;
mod power_form;
mod sampler;
mod samples;
mod surfaces;
mod weighted;

pub use benchmark::{benchmark_curve, benchmark_levels, benchmark_surface};
pub use buffer::{release_cached_memory, SampleBuffer, LARGE_BYTES};
pub use distance_sweep::DistanceSweep;
pub use grid::GridSampler;
pub use memory::{CACHE_BYTES, MAX_OUTPUT_BYTES};
pub use params::Params;
pub use sampler::{Bound, Sampler};
pub use samples::{CurveSamples, Grid, LayerSamples, StageSamples, SweepSamples};
