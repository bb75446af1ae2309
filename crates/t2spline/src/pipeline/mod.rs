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

mod capabilities;
mod distance;
mod fuzzy_curve;
mod fuzzy_ops;
mod fuzzy_surface;
pub(crate) mod point_stages;
mod solution;
mod stages;
mod surface_distance;
mod surface_solution;
mod weight_numbers;

pub use distance::Distance;
pub use fuzzy_curve::FuzzyCurve;
pub use fuzzy_surface::FuzzySurface;
pub use point_stages::Side;
pub use solution::Solution;
pub use stages::Stages;
pub use surface_distance::SurfaceDistance;
pub use surface_solution::SurfaceSolution;
