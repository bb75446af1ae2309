//! Evaluation and derivatives at a parameter: a curve's `t`, a surface's
//! `(u, v)`.

use crate::error::Error;
use crate::nurbs::{NurbsCurve, NurbsSurface};

/// A map from a parameter domain: `C(t) = Σ Nᵢ,ₚ(t) wᵢ Pᵢ / Σ Nᵢ,ₚ(t) wᵢ` for a
/// curve, `S(u, v) = Σᵢⱼ Nᵢ,ₚ(u) Nⱼ,q(v) wᵢⱼ Pᵢⱼ / Σᵢⱼ Nᵢ,ₚ(u) Nⱼ,q(v) wᵢⱼ`
/// for a surface (docs/method.md §4, §8).
pub trait Parametric {
    /// `f64` (`t`) for a curve, `[f64; 2]` (`[u, v]`) for a surface.
    type Param: Copy;
    /// What one parameter gives: `[f64; D]` for a crisp object, the seven
    /// layers' points for a fuzzy one.
    type Point;

    /// Checks a parameter against the domain.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] (inside [`Error::InDirection`] for a surface) if
    /// a parameter is NaN or outside the domain.
    fn check_param(&self, at: Self::Param) -> Result<(), Error>;

    /// The point at a parameter.
    ///
    /// # Errors
    /// As [`Parametric::check_param`].
    fn point_at(&self, at: Self::Param) -> Result<Self::Point, Error>;
}

/// Derivatives with respect to the parameters, from order 0 (the point) up
/// to `order` (The NURBS Book, A4.2 for curves, A4.4 for surfaces).
pub trait Differentiable: Parametric {
    /// `Vec<[f64; D]>` (`C⁽ᵏ⁾`, `k = 0..=order`) for a curve,
    /// `Vec<Vec<[f64; D]>>` (`[k][l]` = `∂ᵏ⁺ˡS/∂uᵏ∂vˡ`, `k + l ≤ order`) for a
    /// surface; per layer for a fuzzy object.
    type Derivatives;

    /// The derivatives at a parameter up to `order`.
    ///
    /// # Errors
    /// As [`Parametric::check_param`]; [`Error::OutOfRange`] for an order
    /// above [`MAX_DERIVATIVE_ORDER`](crate::nurbs::MAX_DERIVATIVE_ORDER).
    fn derivatives_at(&self, at: Self::Param, order: usize) -> Result<Self::Derivatives, Error>;
}

impl<const D: usize> Parametric for NurbsCurve<D> {
    type Param = f64;
    type Point = [f64; D];

    fn check_param(&self, t: f64) -> Result<(), Error> {
        self.domain().check(t)
    }

    fn point_at(&self, t: f64) -> Result<[f64; D], Error> {
        self.eval(t)
    }
}

impl<const D: usize> Differentiable for NurbsCurve<D> {
    type Derivatives = Vec<[f64; D]>;

    fn derivatives_at(&self, t: f64, order: usize) -> Result<Vec<[f64; D]>, Error> {
        self.derivatives(t, order)
    }
}

impl<const D: usize> Parametric for NurbsSurface<D> {
    type Param = [f64; 2];
    type Point = [f64; D];

    fn check_param(&self, [u, v]: [f64; 2]) -> Result<(), Error> {
        self.check(u, v)
    }

    fn point_at(&self, [u, v]: [f64; 2]) -> Result<[f64; D], Error> {
        self.eval(u, v)
    }
}

impl<const D: usize> Differentiable for NurbsSurface<D> {
    type Derivatives = Vec<Vec<[f64; D]>>;

    fn derivatives_at(&self, [u, v]: [f64; 2], order: usize) -> Result<Self::Derivatives, Error> {
        self.derivatives(u, v, order)
    }
}
