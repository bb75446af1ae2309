//! Rational B-splines whose weights are uncertain as well as their control
//! points (docs/method.md §15): at a level alpha every weight has a cut
//! `[w̲ᵢ, w̄ᵢ]` (all `> 0`) and every coordinate a cut `[P̲ᵢₖ, P̄ᵢₖ]`, and at a
//! parameter `t` the curve
//! ```text
//! C(t) = Σ wᵢNᵢ(t)Pᵢ / Σ wᵢNᵢ(t)
//! ```
//! is a weighted average with the non-negative weights `wᵢNᵢ(t)`. The set
//! `S(t)` of its values over every admissible choice is convex: the
//! projective image of a polytope. This module computes, exactly:
//!
//! | what | how | file |
//! |---|---|---|
//! | the weighted average's range with interval weights | every Karnik–Mendel switch point | `km.rs` ([`weighted_average_range`]) |
//! | the envelope of each coordinate | KM on the left (right) ends | `envelope.rs` ([`IntervalTerms::envelope`]) |
//! | the support function `h(d)` | KM on the values `d·Pᵢ` at their extreme corners | `support.rs` ([`IntervalTerms::support`]) |
//! | membership of a point | `h` in the finitely many directions where `g` may turn | `membership.rs` ([`IntervalTerms::contains`]) |
//! | the section at `x = X₀` | the Charnes–Cooper LP, solved as its crossing edge by support queries | `section.rs` ([`IntervalTerms::section`]) |
//!
//! [`IntervalTerms`] (`terms.rs`) holds the terms at one parameter, from the
//! basis values a caller has (or [`try_basis_functions`]);
//! [`IntervalCurve`] (`curve.rs`) finds them for a curve given by its knots,
//! degree and cuts. No I/O, and no job reads these yet.
//!
//! No linear-programming library is used: each program here is small and
//! special (a box of weights and at most two constraints per coordinate),
//! and the support function answers it exactly with a proof of termination,
//! where a general simplex code decides feasibility up to its own
//! tolerances.
//!
//! [`try_basis_functions`]: crate::nurbs::basis::try_basis_functions

mod curve;
mod envelope;
mod km;
mod membership;
mod section;
mod support;
mod terms;

pub use curve::IntervalCurve;
pub use envelope::MEMBERSHIP_SLACK;
pub use km::weighted_average_range;
pub use terms::{IntervalTerms, Vertex, MAX_TERMS};
