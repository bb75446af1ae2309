//! The point of an object nearest a target.

use crate::error::Error;
use crate::nurbs::{ClosestPoint, ClosestSurfacePoint, NurbsCurve, NurbsSurface};

/// The point of the object nearest `target` over the whole domain, with its
/// parameter and distance: the global minimum of `‖C(t) − P‖` (The NURBS
/// Book, §6.1, Eqs. 6.3–6.4) or `‖S(u, v) − P‖` (Eqs. 6.5–6.8); per layer for a
/// fuzzy object.
pub trait Closest<const D: usize> {
    /// [`ClosestPoint`] for a curve, [`ClosestSurfacePoint`] for a surface,
    /// seven of them for a fuzzy object.
    type Nearest;

    /// The nearest point to `target`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::OutOfRange`] naming the axis for a
    /// target a surface cannot search (a curve takes every target).
    fn closest_to(&self, target: [f64; D]) -> Result<Self::Nearest, Error>;
}

impl<const D: usize> Closest<D> for NurbsCurve<D> {
    type Nearest = ClosestPoint<D>;

    fn closest_to(&self, target: [f64; D]) -> Result<ClosestPoint<D>, Error> {
        Ok(self.closest_point(target))
    }
}

impl<const D: usize> Closest<D> for NurbsSurface<D> {
    type Nearest = ClosestSurfacePoint<D>;

    fn closest_to(&self, target: [f64; D]) -> Result<ClosestSurfacePoint<D>, Error> {
        self.closest_point(target)
    }
}
