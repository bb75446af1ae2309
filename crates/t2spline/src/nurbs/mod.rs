//! Rational B-spline (NURBS) curves of any order (docs/method.md §6, paper Def. 5.1).
//!
//! [`KnotVector`] validates knots and finds spans; [`basis`] holds the B-spline
//! basis functions (The NURBS Book, A2.1–A2.2) and [`derivatives`] their
//! derivatives (A2.3); [`NurbsCurve`] evaluates
//! `C(t) = Σ wᵢ Nᵢ,ₚ(t) Pᵢ / Σ wᵣ Nᵣ,ₚ(t)` and offers the curve operations:
//!
//! | operation | method | source |
//! |---|---|---|
//! | derivatives of any order, tangent, curvature | [`NurbsCurve::derivatives`], [`NurbsCurve::tangent`], [`NurbsCurve::curvature`] | A3.2, A4.2 |
//! | knot insertion, refinement | [`NurbsCurve::insert_knot`], [`NurbsCurve::refine_knots`] | A5.1, A5.4 |
//! | degree elevation | [`NurbsCurve::elevate_degree`] | A5.9 |
//! | splitting, pieces, clamping | [`NurbsCurve::split_at`], [`NurbsCurve::segment`], [`NurbsCurve::clamped`] | §5.3 |
//! | arc length, parameter at a length | [`NurbsCurve::arc_length`], [`NurbsCurve::param_at_length`] | Gauss–Kronrod |
//! | closest point | [`NurbsCurve::closest_point`] | §6.1 |
//! | bounding box | [`NurbsCurve::bounding_box`] | — |
//!
//! [`NurbsSurface`] is the tensor product of two such curves (docs/method.md §8), with
//! the same operations in either [`Direction`], run by the same row
//! algorithms (`surface/operations.rs`).
//!
//! Fuzzy curves apply the same operations to their seven layers with shared
//! knots and weights ([`FuzzyCurve`](crate::FuzzyCurve)).

mod arc_length;
pub use arc_length::LENGTH_TOLERANCE;
pub mod basis;
mod bounding_box;
pub(crate) mod closest_point;
mod curvature;
pub(crate) mod curve;
pub(crate) mod degree_elevation;
pub mod derivatives;
#[cfg(test)]
pub(crate) mod fixtures;
pub(crate) mod homogeneous;
pub(crate) mod knot_insertion;
mod knots;
pub(crate) mod pieces;
pub(crate) mod span_eval;
pub(crate) mod split;
pub(crate) mod surface;

pub use bounding_box::BoundingBox;
pub use closest_point::ClosestPoint;
pub use curve::{weight_problems, NurbsCurve};
pub use degree_elevation::MAX_ELEVATED_DEGREE;
pub use derivatives::MAX_DERIVATIVE_ORDER;
pub use knots::{Domain, KnotVector};
pub use surface::{
    net_weight_problems, ClosestSurfacePoint, Direction, NurbsSurface, SurfaceCurvature,
};
