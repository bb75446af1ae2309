//! Curvature at a parameter.

use crate::capability::Parametric;
use crate::error::Error;
use crate::nurbs::{NurbsCurve, NurbsSurface, SurfaceCurvature};

/// Curvature at a parameter: for a curve `κ = ‖C′ ∧ C″‖ / ‖C′‖³`, for a
/// surface in space the Gaussian and mean curvature, the principal
/// curvatures and their directions from the first and second fundamental
/// forms (docs/method.md §10; The NURBS Book has the derivatives). A surface
/// in the plane has no normal, so only `NurbsSurface<3>` implements it.
pub trait Curvature: Parametric {
    /// `f64` for a curve, [`SurfaceCurvature`] for a surface, seven of them
    /// for a fuzzy object.
    type Curvature;

    /// The curvature at a parameter.
    ///
    /// # Errors
    /// As [`Parametric::check_param`]; [`Error::Singular`] where a curve's
    /// first derivative vanishes, [`Error::SingularNormal`] where a
    /// surface's normal does.
    fn curvature_at(&self, at: Self::Param) -> Result<Self::Curvature, Error>;
}

impl<const D: usize> Curvature for NurbsCurve<D> {
    type Curvature = f64;

    fn curvature_at(&self, t: f64) -> Result<f64, Error> {
        self.curvature(t)
    }
}

impl Curvature for NurbsSurface<3> {
    type Curvature = SurfaceCurvature;

    fn curvature_at(&self, [u, v]: [f64; 2]) -> Result<SurfaceCurvature, Error> {
        self.curvature(u, v)
    }
}
