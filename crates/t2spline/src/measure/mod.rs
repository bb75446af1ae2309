//! Quantities measured on a fuzzy curve (docs/method.md §11): derivatives,
//! tangent angle, arc length, area and curvature as type-2 fuzzy quantities;
//! and on a fuzzy surface of crisp plan (§14): the volumes above and below a
//! plane, the plan area below it and the surface area, and the cut and fill
//! between two surfaces (of one plan map, or over their plans' overlap).
//!
//! For a quantity `Q` of the control points (weights and knots crisp), a
//! membership function `m` and a level `alpha`, the value is the interval
//! of `Q` over the box of cut control points (Zadeh's extension principle):
//!
//! ```text
//! Q_m(alpha) = [ min Q, max Q ]  over  K_m(alpha) = Π over i, c of [l_ic, r_ic]
//! ```
//! Over alpha each function gives a fuzzy number, and the three nest
//! (upper ⊇ primary ⊇ lower). Each interval is a [`Bracket`]: exact (to
//! rounding or a stated tolerance) or a certified enclosure with its gap,
//! never narrower than the truth.
//!
//! | quantity | how | exact? |
//! |---|---|---|
//! | derivative of order k at t | signed coefficients `Rᵢ⁽ᵏ⁾(t)` | exact |
//! | tangent angle at t (plane) | corners of the derivative box | exact, undefined where the box holds 0 |
//! | arc length, least | projected Newton on a convex function, dual bound | to 1e-9, certified |
//! | arc length, largest | every vertex (≤ 2¹⁶), else branch and bound | exact, else a certified bracket |
//! | area (plane) | every x-vertex (≤ 2²⁰), else branch and bound | exact, else a certified bracket |
//! | curvature at t | interval arithmetic with subdivision | certified enclosure |
//!
//! A layer curve's length is not a bound: the shortest and the longest
//! admissible curves put each control point at the end its neighbours ask
//! for, not all at their left or right ends.

mod area;
mod bracket;
mod closure;
mod coefficients;
mod crossing;
mod curvature;
mod cut_box;
mod cut_fill;
mod derivative;
mod extreme_nets;
mod inverse;
mod length;
mod measures;
mod options;
mod overlap;
mod plan;
mod roots;
mod rule;
mod surface_area;
mod surface_measures;
mod vertices;
mod volume;

pub use area::{AreaKind, MAX_ENUMERATED_AREA_VARIABLES};
pub use bracket::Bracket;
pub(crate) use closure::extent;
pub use closure::{Closure, CLOSURE_TOLERANCE};
pub use length::{LENGTH_MIN_TOLERANCE, MAX_ENUMERATED_LENGTH_VARIABLES};
pub use measures::{
    AreaMeasure, AtMeasure, DerivativeLevel, Level, Measures, PartialLevel, PerMembership,
};
pub use options::{
    uniform_levels, MeasureOptions, SurfaceMeasureOptions, DEFAULT_MEASURE_LEVELS,
    MAX_MEASURE_LEVELS, MAX_MEASURE_PARAMETERS,
};
pub use surface_area::{MAX_ENUMERATED_SURFACE_AREA_VARIABLES, SURFACE_AREA_TOLERANCE};
pub use surface_measures::SurfaceMeasures;
pub use volume::VOLUME_TOLERANCE;
