//! The fuzzy curve as a set (docs/method.md §10): the membership grade of any
//! point, the region the curve can occupy at each level, and the fuzzy value
//! at a station.
//!
//! At a parameter `t` and level `alpha`, the curves whose control points lie
//! inside their cuts pass exactly through the **box** whose corners are the
//! curves of the cut ends, `Σ Rᵢ(t)·leftᵢ` and `Σ Rᵢ(t)·rightᵢ` per
//! coordinate (every `Rᵢ ≥ 0`, and the coordinates are independent). The
//! region at `alpha` is the union of the boxes over `t`; the membership grade
//! of a point is the largest level whose region holds it (Zadeh's extension
//! principle with the minimum across coordinates):
//!
//! ```text
//! region_m(alpha) = ∪ over t of B_m(t, alpha)
//! mu_m(p)         = sup { alpha : p ∈ region_m(alpha) }
//! ```
//! for each membership function `m` (upper, primary, lower). The band between
//! two layer curves is not this set: the curve can pass anywhere in the box,
//! not only along its diagonal.
//!
//! - [`FuzzyCurve::membership`], [`FuzzyCurve::memberships`]: [`Grades`] of points.
//! - [`FuzzyCurve::region`] (plane curves), [`FuzzyCurve::region_projections`]
//!   (space curves): [`Region`]s of [`Polygon`]s, to a stated tolerance.
//! - [`FuzzyCurve::section`], [`FuzzyCurve::sections`]: the fuzzy y at `x = x0`.
//! - [`FuzzyCurve::membership_grid`]: the footprint of uncertainty as maps.
//! - [`FuzzySurface::membership`](crate::FuzzySurface::membership) and
//!   [`FuzzySurface::sections`](crate::FuzzySurface::sections): the same for
//!   surfaces (the fuzzy height of a terrain at a location).
//! - [`FuzzySurface::envelope`](crate::FuzzySurface::envelope): the least and
//!   greatest height of a surface above every cell of a plan grid.
//! - [`FuzzySurface::contour`](crate::FuzzySurface::contour): the plan
//!   points where a surface can cross a height, as polygons.

pub(crate) mod bernstein;
mod certify;
mod contour;
mod curve_envelope;
mod cut_lines;
mod envelope;
mod grades;
mod grid;
mod intervals;
pub(crate) mod membership;
mod polygon;
pub(crate) mod region;
mod scan;
mod section;
pub(crate) mod surface;
mod sweep;
mod weighted_grades;
mod weighted_section;
mod weighted_terms;

pub use certify::GRADE_TOLERANCE;
pub use contour::{
    Contour, ContourLevel, CONTOUR_CELLS_PER_SPAN, MAX_CONTOUR_CELLS, MIN_CONTOUR_CELLS,
};
pub use cut_lines::{MEMBERSHIPS, RELATIVE_SLACK};
pub use envelope::{
    Envelope, EnvelopeBounds, EnvelopeLevel, PlanGrid, MAX_ENVELOPE_VALUES,
    MAX_FUZZY_ENVELOPE_CELLS,
};
pub use grades::Grades;
pub use grid::{MembershipGrid, MAX_GRID_CELLS};
pub use polygon::{Polygon, Region};
pub use region::{Plane, DEFAULT_RELATIVE_TOLERANCE, LEAST_RELATIVE_TOLERANCE};
pub use section::SectionLevel;

#[cfg(doc)]
use crate::pipeline::FuzzyCurve;
