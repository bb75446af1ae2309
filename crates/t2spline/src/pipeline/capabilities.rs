//! The capabilities of the fuzzy curve and the fuzzy surface
//! ([`crate::capability`]): each is [`Layered`], evaluates its seven layers
//! from one rational basis, and takes the layered derivatives, curvatures,
//! bounding box and closest points written once in
//! [`crate::capability::layered`].

use crate::capability::knots::{curve_knot_operations, surface_knot_operations};
use crate::capability::layered;
use crate::capability::{Bounded, Closest, Curvature, Differentiable, Layered, Parametric};
use crate::error::Error;
use crate::fuzzy::{Layers, Nt2Number, Nt2Point};
use crate::nurbs::{
    BoundingBox, ClosestPoint, ClosestSurfacePoint, Direction, NurbsCurve, NurbsSurface,
    SurfaceCurvature,
};
use crate::pipeline::{FuzzyCurve, FuzzySurface};

impl<const D: usize> Layered<D> for FuzzyCurve<D> {
    type Crisp = NurbsCurve<D>;

    fn fuzzy_points(&self) -> &[Nt2Point<D>] {
        self.points()
    }

    fn through(&self, points: Vec<[f64; D]>) -> NurbsCurve<D> {
        self.with_control_points(points)
    }

    fn weight_numbers(&self) -> Option<&[Nt2Number]> {
        FuzzyCurve::weight_numbers(self)
    }

    fn through_weighted(&self, points: Vec<[f64; D]>, weights: Vec<f64>) -> NurbsCurve<D> {
        NurbsCurve::from_parts_unchecked(points, weights, self.knots().clone())
    }
}

impl<const D: usize> Layered<D> for FuzzySurface<D> {
    type Crisp = NurbsSurface<D>;

    fn fuzzy_points(&self) -> &[Nt2Point<D>] {
        self.points()
    }

    fn through(&self, points: Vec<[f64; D]>) -> NurbsSurface<D> {
        self.with_control_points(points)
    }

    fn weight_numbers(&self) -> Option<&[Nt2Number]> {
        FuzzySurface::weight_numbers(self)
    }

    fn through_weighted(&self, points: Vec<[f64; D]>, weights: Vec<f64>) -> NurbsSurface<D> {
        NurbsSurface::from_parts_unchecked(
            points,
            weights,
            [Direction::U, Direction::V].map(|d| self.knots(d).clone()),
        )
    }
}

impl<const D: usize> Parametric for FuzzyCurve<D> {
    type Param = f64;
    type Point = Layers<[f64; D]>;

    fn check_param(&self, t: f64) -> Result<(), Error> {
        self.domain().check(t)
    }

    fn point_at(&self, t: f64) -> Result<Layers<[f64; D]>, Error> {
        self.eval_layers(t)
    }
}

impl<const D: usize> Parametric for FuzzySurface<D> {
    type Param = [f64; 2];
    type Point = Layers<[f64; D]>;

    fn check_param(&self, [u, v]: [f64; 2]) -> Result<(), Error> {
        self.check(u, v)
    }

    fn point_at(&self, [u, v]: [f64; 2]) -> Result<Layers<[f64; D]>, Error> {
        self.eval_layers(u, v)
    }
}

impl<const D: usize> Differentiable for FuzzyCurve<D> {
    type Derivatives = Layers<Vec<[f64; D]>>;

    fn derivatives_at(&self, t: f64, order: usize) -> Result<Self::Derivatives, Error> {
        layered::derivatives(self, t, order)
    }
}

impl<const D: usize> Differentiable for FuzzySurface<D> {
    type Derivatives = Layers<Vec<Vec<[f64; D]>>>;

    fn derivatives_at(&self, at: [f64; 2], order: usize) -> Result<Self::Derivatives, Error> {
        layered::derivatives(self, at, order)
    }
}

impl<const D: usize> Curvature for FuzzyCurve<D> {
    type Curvature = Layers<f64>;

    fn curvature_at(&self, t: f64) -> Result<Layers<f64>, Error> {
        layered::curvatures(self, t)
    }
}

impl Curvature for FuzzySurface<3> {
    type Curvature = Layers<SurfaceCurvature>;

    fn curvature_at(&self, at: [f64; 2]) -> Result<Layers<SurfaceCurvature>, Error> {
        layered::curvatures(self, at)
    }
}

impl<const D: usize> Bounded<D> for FuzzyCurve<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        layered::bounding_box(self)
    }
}

impl<const D: usize> Bounded<D> for FuzzySurface<D> {
    fn bounding_box(&self) -> BoundingBox<D> {
        layered::bounding_box(self)
    }
}

impl<const D: usize> Closest<D> for FuzzyCurve<D> {
    type Nearest = Layers<ClosestPoint<D>>;

    fn closest_to(&self, target: [f64; D]) -> Result<Self::Nearest, Error> {
        layered::closest(self, target)
    }
}

impl<const D: usize> Closest<D> for FuzzySurface<D> {
    type Nearest = Layers<ClosestSurfacePoint<D>>;

    fn closest_to(&self, target: [f64; D]) -> Result<Self::Nearest, Error> {
        self.closest_points(target)
    }
}

curve_knot_operations!(FuzzyCurve);
surface_knot_operations!(FuzzySurface);
