//! Knot insertion, refinement, degree elevation and splitting: exact
//! changes of representation that keep the object (The NURBS Book, A5.1,
//! A5.4, A5.9, §5.3).

use crate::error::Error;
use crate::nurbs::{NurbsCurve, NurbsSurface};

/// The knot operations, along one parameter direction: a curve has one
/// (`Along = ()`), a surface two (`Along = `[`Direction`](crate::nurbs::Direction)). Each returns an
/// object equal to this one at every parameter (to rounding); a fuzzy
/// object applies the operation to its seven layers at once, so that the
/// result is again a fuzzy object with ordered layers (docs/method.md §6).
pub trait KnotOperations: Sized {
    /// `()` for a curve, [`Direction`](crate::nurbs::Direction) for a surface.
    type Along: Copy;

    /// Inserts the knot `t` `times` times (A5.1).
    ///
    /// # Errors
    /// The type's error for `t` outside the domain or a knot that would
    /// exceed the degree's multiplicity.
    fn insert_knot_along(&self, along: Self::Along, t: f64, times: usize) -> Result<Self, Error>;

    /// Inserts every knot of `new`, in order (A5.4).
    ///
    /// # Errors
    /// As [`KnotOperations::insert_knot_along`].
    fn refine_knots_along(&self, along: Self::Along, new: &[f64]) -> Result<Self, Error>;

    /// Raises the degree `times` times (A5.9).
    ///
    /// # Errors
    /// The type's error for a degree above the limit of elevation.
    fn elevate_degree_along(&self, along: Self::Along, times: usize) -> Result<Self, Error>;

    /// Splits at `t` into the pieces before and after it (§5.3).
    ///
    /// # Errors
    /// The type's error for `t` not inside the domain.
    fn split_along(&self, along: Self::Along, t: f64) -> Result<[Self; 2], Error>;
}

/// The operations of a curve, whose one direction needs no name, from its
/// inherent methods of the same names.
macro_rules! curve_knot_operations {
    ($ty:ident) => {
        impl<const D: usize> $crate::capability::KnotOperations for $ty<D> {
            type Along = ();

            fn insert_knot_along(
                &self,
                (): (),
                t: f64,
                times: usize,
            ) -> Result<Self, $crate::error::Error> {
                self.insert_knot(t, times)
            }

            fn refine_knots_along(
                &self,
                (): (),
                new: &[f64],
            ) -> Result<Self, $crate::error::Error> {
                self.refine_knots(new)
            }

            fn elevate_degree_along(
                &self,
                (): (),
                times: usize,
            ) -> Result<Self, $crate::error::Error> {
                self.elevate_degree(times)
            }

            fn split_along(&self, (): (), t: f64) -> Result<[Self; 2], $crate::error::Error> {
                self.split_at(t)
            }
        }
    };
}

/// The operations of a surface, along a [`Direction`](crate::nurbs::Direction).
macro_rules! surface_knot_operations {
    ($ty:ident) => {
        impl<const D: usize> $crate::capability::KnotOperations for $ty<D> {
            type Along = $crate::nurbs::Direction;

            fn insert_knot_along(
                &self,
                along: $crate::nurbs::Direction,
                t: f64,
                times: usize,
            ) -> Result<Self, $crate::error::Error> {
                self.insert_knot(along, t, times)
            }

            fn refine_knots_along(
                &self,
                along: $crate::nurbs::Direction,
                new: &[f64],
            ) -> Result<Self, $crate::error::Error> {
                self.refine_knots(along, new)
            }

            fn elevate_degree_along(
                &self,
                along: $crate::nurbs::Direction,
                times: usize,
            ) -> Result<Self, $crate::error::Error> {
                self.elevate_degree(along, times)
            }

            fn split_along(
                &self,
                along: $crate::nurbs::Direction,
                t: f64,
            ) -> Result<[Self; 2], $crate::error::Error> {
                self.split_at(along, t)
            }
        }
    };
}

pub(crate) use {curve_knot_operations, surface_knot_operations};

curve_knot_operations!(NurbsCurve);
surface_knot_operations!(NurbsSurface);
