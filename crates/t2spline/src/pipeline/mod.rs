//! Algorithm 1.1 of the paper: the four stages from fuzzy control points to the
//! crisp type-2 solution curve (SPEC §7).
//!
//! Stage 1 is a [`FuzzyCurve`] (control points, weights, knots) with its seven
//! layer curves; [`FuzzyCurve::solve`] runs stages 2–4 on the control points and
//! returns a [`Solution`], which also measures the [`Distance`] between the crisp
//! and the defuzzified curve.

mod fuzzy_curve;
mod fuzzy_ops;
mod metrics;
mod stages;

pub use fuzzy_curve::FuzzyCurve;
pub use metrics::{euclidean_norm, Distance};
pub use stages::{Side, Solution};
