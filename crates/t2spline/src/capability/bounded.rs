//! A box that holds the whole object.

use crate::nurbs::{BoundingBox, NurbsCurve, NurbsSurface};

/// An axis-aligned box that holds every point of the object over its whole
/// domain. For a rational B-spline with positive weights the curve or
/// surface lies in the convex hull of its control points (The NURBS Book,
/// P4.4), and the types tighten that hull to the extremes found on each span
/// or patch; a fuzzy object's box is the union of its seven layers' boxes.
pub trait Bounded<const D: usize> {
    /// The bounding box.
    fn bounding_box(&self) -> BoundingBox<D>;
}

impl<const D: usize> Bounded<D> for NurbsCurve<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        NurbsCurve::bounding_box(self)
    }
}

impl<const D: usize> Bounded<D> for NurbsSurface<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        NurbsSurface::bounding_box(self)
    }
}
