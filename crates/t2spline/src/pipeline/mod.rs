//! Algorithm 1.1 of the paper: the four stages from fuzzy control points to the
//! crisp type-2 solution curve (docs/method.md §7).
//!
//! Stage 1 is a [`FuzzyCurve`] (control points, weights, knots) with its seven
//! layer curves; [`FuzzyCurve::solve`] runs stages 2–4 on the control points
//! (with the paper's type reduction; [`FuzzyCurve::solve_with`] with any of
//! docs/method.md §9) and returns a [`Solution`], which also measures the [`Distance`] between the crisp
//! and the defuzzified curve. [`FuzzySurface`] and [`SurfaceSolution`] do the
//! same for surfaces (docs/method.md §8), with the same per-number stages, and measure
//! the [`SurfaceDistance`].

mod fuzzy_curve;
mod fuzzy_ops;
mod fuzzy_surface;
mod metrics;
pub(crate) mod point_stages;
mod stages;
mod surface_metrics;
mod surface_stages;

pub use fuzzy_curve::FuzzyCurve;
pub use fuzzy_surface::FuzzySurface;
pub use metrics::{euclidean_norm, Distance};
pub use point_stages::Side;
pub use stages::Solution;
pub use surface_metrics::SurfaceDistance;
pub use surface_stages::SurfaceSolution;
