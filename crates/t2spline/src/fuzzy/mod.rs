//! Normal triangular type-2 fuzzy numbers and points (docs/method.md §1–§5).
//!
//! The flow through this module is the flow of one uncertain value through the
//! method: an [`Nt2Number`] is cut at a level [`Alpha`] into an [`AlphaCut`]
//! (docs/method.md §2), type-reduced to a type-1 triangle [`Tfn`] (docs/method.md §3) and defuzzified
//! to one real number (docs/method.md §4). An [`Nt2Point`] does the same per coordinate.

mod alpha;
mod alpha_cut;
mod interval;
mod layer;
mod number;
mod point;
mod tfn;

pub use alpha::Alpha;
pub use alpha_cut::AlphaCut;
pub use interval::Interval;
pub use layer::{Layer, Layers};
pub(crate) use number::RULES;
pub use number::{Height, Membership, Nt2Number};
pub use point::{Axis, Nt2Point, Nt2Point2, Nt2Point3};
pub use tfn::Tfn;
