//! Rational B-spline surfaces: the tensor product of docs/method.md §6 (docs/method.md §8).
//!
//! A [`NurbsSurface`] holds a net of `nu × nv` control points `Pᵢⱼ` (row `i`
//! along u, column `j` along v), one weight per point and one [`KnotVector`](crate::nurbs::KnotVector)
//! per [`Direction`]. Every rule of a curve (docs/method.md §6) holds in each direction:
//! clamped uniform knots by default, the domain `[U[p], U[nu]] × [V[q], V[nv]]`,
//! interior knots of full multiplicity (the value there is taken from the
//! right, at the end of a domain from the last non-empty span).
//!
//! | operation | method | source |
//! |---|---|---|
//! | point, rational basis | [`NurbsSurface::eval`], [`NurbsSurface::rational_basis`] | docs/method.md §8 |
//! | partial derivatives of any order, normal | [`NurbsSurface::derivatives`], [`NurbsSurface::normal`] | The NURBS Book A3.6, A4.4 |
//! | Gaussian, mean and principal curvatures, principal directions | [`NurbsSurface::curvature`] | do Carmo §3-3 |
//! | isoparametric curves | [`NurbsSurface::isocurve`] | §4.5 |
//! | knot insertion, refinement | [`NurbsSurface::insert_knot`], [`NurbsSurface::refine_knots`] | A5.1, A5.4 on stacked rows (as A5.3, A5.5) |
//! | degree elevation | [`NurbsSurface::elevate_degree`] | A5.9 on stacked rows (§5.5) |
//! | splitting, sub-rectangle | [`NurbsSurface::split_at`], [`NurbsSurface::segment`] | §5.3 |
//! | closest point | [`NurbsSurface::closest_point`] | §6.1, Eqs. 6.6–6.8 |
//! | bounding box | [`NurbsSurface::bounding_box`] | — |
//!
//! The operations in one direction are the curve algorithms of
//! `nurbs/knot_insertion.rs`, `degree_elevation.rs` and `split.rs` run on
//! rows that stack a whole line of the net (`operations.rs`): no algorithm
//! is written twice.

mod bounding_box;
pub(crate) mod closest_point;
pub use closest_point::ClosestSurfacePoint;
mod curvature;
pub use curvature::SurfaceCurvature;
pub(crate) mod derivatives;
mod net_rules;
pub(crate) mod operations;
pub(crate) mod patches;
mod tensor_basis;
mod tensor_product;

pub use net_rules::net_weight_problems;
pub(crate) use net_rules::{check_params, knots_in, net_shape, net_weights, net_weights_flat};
pub(crate) use tensor_basis::TensorBasis;
pub use tensor_product::NurbsSurface;

pub use crate::place::Direction;

#[cfg(test)]
mod curvature_tests;
#[cfg(test)]
mod extrema_tests;
#[cfg(test)]
mod tests;
