//! The operations that curves and surfaces share, one small trait each, in
//! the manner of kurbo's `ParamCurve` family and truck's
//! `ParametricCurve`/`ParametricSurface`: generic code names the capability
//! it needs, not the type.
//!
//! | trait | what | curve | surface |
//! |---|---|---|---|
//! | [`Parametric`] | the point at a parameter | `C(t)` | `S(u, v)` |
//! | [`Differentiable`] | derivatives up to an order | `C⁽ᵏ⁾(t)` | `∂ᵏ⁺ˡS/∂uᵏ∂vˡ` |
//! | [`Curvature`] | curvature at a parameter | `κ(t)` | Gaussian, mean, principal (space only) |
//! | [`Bounded`] | an axis-aligned box holding the whole object | | |
//! | [`Closest`] | the point nearest a target, over the whole domain | | |
//! | [`KnotOperations`] | knot insertion, refinement, degree elevation, splitting | one direction | a [`Direction`](crate::Direction) |
//! | [`Layered`] | a fuzzy object as its seven layers (docs/method.md §6) | | |
//!
//! The crisp types ([`NurbsCurve`](crate::NurbsCurve),
//! [`NurbsSurface`](crate::NurbsSurface)) implement the traits directly. A
//! fuzzy type ([`FuzzyCurve`](crate::FuzzyCurve),
//! [`FuzzySurface`](crate::FuzzySurface)) is [`Layered`]: every layer is a
//! crisp object with the fuzzy object's weights and knots, and its
//! derivatives, curvatures, bounding box and closest points are those of its
//! layers, computed once for both kinds in [`layered`]. Each type's inherent
//! methods of the same names remain, so code that knows its type needs no
//! trait in scope.

mod bounded;
mod closest;
mod curvature;
pub(crate) mod knots;
pub mod layered;
mod parametric;

pub use bounded::Bounded;
pub use closest::Closest;
pub use curvature::Curvature;
pub use knots::KnotOperations;
pub use layered::Layered;
pub use parametric::{Differentiable, Parametric};
