//! Rational B-spline (NURBS) curves of any order (SPEC §6, paper Def. 5.1).
//!
//! [`KnotVector`] validates knots and finds spans; [`basis`] holds the B-spline
//! basis functions (The NURBS Book, A2.1–A2.2); [`NurbsCurve`] evaluates
//! `C(t) = Σ wᵢ Nᵢ,ₚ(t) Pᵢ / Σ wᵣ Nᵣ,ₚ(t)`.

pub mod basis;
pub(crate) mod curve;
mod knots;

pub use curve::NurbsCurve;
pub use knots::{Domain, KnotVector};
