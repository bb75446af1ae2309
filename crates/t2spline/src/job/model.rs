//! The fuzzy model of a job, and work written once for every kind of model.

use crate::fuzzy::{Axis, Nt2Number, Nt2Point};
use crate::pipeline::{FuzzyCurve, FuzzySurface};

/// The fuzzy model of a job: a curve in the plane or in space, or a surface.
///
/// Code that works for every kind of model is written once, as a
/// [`ModelVisitor`], and [`Model::visit`] is the one place that tells the
/// kinds apart.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Model {
    /// A curve through points with coordinates `x`, `y`.
    Planar(FuzzyCurve<2>),
    /// A curve through points with coordinates `x`, `y`, `z`.
    Spatial(FuzzyCurve<3>),
    /// A surface over a net of points with coordinates `x`, `y`, `z` (docs/method.md §8).
    Surface(FuzzySurface<3>),
}

/// Work done on any [`Model`]: one generic method per kind of model.
pub trait ModelVisitor {
    /// What the work gives.
    type Output;
    /// The work on a fuzzy curve of `D` dimensions.
    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output;
    /// The work on a fuzzy surface of `D` dimensions.
    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> Self::Output;
}

impl Model {
    /// Does `work` on the model, whatever its kind.
    pub fn visit<V: ModelVisitor>(&self, work: V) -> V::Output {
        match self {
            Model::Planar(c) => work.curve(c),
            Model::Spatial(c) => work.curve(c),
            Model::Surface(s) => work.surface(s),
        }
    }

    /// The numbers of every fuzzy control point (a surface's net row by row),
    /// one per coordinate.
    #[must_use]
    pub fn numbers(&self) -> Vec<Vec<Nt2Number>> {
        self.visit(Numbers)
    }

    /// The smallest lower height `h` of the model's numbers: the lowest
    /// level where the paper's reduction jumps (docs/method.md §3).
    #[must_use]
    pub fn least_height(&self) -> f64 {
        self.numbers()
            .iter()
            .flatten()
            .map(|x| x.height().get())
            .fold(1.0, f64::min)
    }

    /// Whether some weight of the model is a fuzzy number (docs/method.md
    /// §16).
    #[must_use]
    pub fn has_fuzzy_weights(&self) -> bool {
        match self {
            Model::Planar(c) => c.weight_numbers().is_some(),
            Model::Spatial(c) => c.weight_numbers().is_some(),
            Model::Surface(s) => s.weight_numbers().is_some(),
        }
    }

    /// Whether the model is a surface.
    #[must_use]
    pub fn is_surface(&self) -> bool {
        matches!(self, Model::Surface(_))
    }

    /// One line on the model: `2-D curve, 4 control points, order 3` or
    /// `surface, 5 × 4 control points, orders 3 × 2`.
    #[must_use]
    pub fn summary(&self) -> String {
        struct Summary;
        impl ModelVisitor for Summary {
            type Output = String;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> String {
                format!(
                    "{D}-D curve, {} control points, order {}",
                    c.points().len(),
                    c.order()
                )
            }
            fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> String {
                let ([nu, nv], [p, q]) = (s.shape(), s.degree());
                format!(
                    "{D}-D surface, {nu} × {nv} control points, orders {} × {}",
                    p + 1,
                    q + 1
                )
            }
        }
        self.visit(Summary)
    }

    /// The shape `[nu, nv]` of a surface's control net; `None` for a curve.
    #[must_use]
    pub fn net_shape(&self) -> Option<[usize; 2]> {
        struct NetShape;
        impl ModelVisitor for NetShape {
            type Output = Option<[usize; 2]>;
            fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> Option<[usize; 2]> {
                None
            }
            fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Option<[usize; 2]> {
                Some(s.shape())
            }
        }
        self.visit(NetShape)
    }

    /// The number of coordinates of a point (2 or 3).
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.visit(Dimension)
    }

    /// The number of fuzzy control points (of a surface: `nu · nv`).
    #[must_use]
    pub fn control_point_count(&self) -> usize {
        self.numbers().len()
    }

    /// The fuzzy number of one coordinate of one control point (of a
    /// surface: point `i·nv + j` of the net, row by row); `None` if the model
    /// has no such point or axis.
    #[must_use]
    pub fn number(&self, point: usize, axis: Axis) -> Option<Nt2Number> {
        self.numbers().get(point)?.get(axis.index()).copied()
    }

    /// The distinct lower heights of the model's numbers, ascending: the
    /// levels where the solution jumps (docs/method.md §3).
    #[must_use]
    pub fn heights(&self) -> Vec<f64> {
        let mut h: Vec<f64> = self
            .numbers()
            .iter()
            .flatten()
            .map(|x| x.height().get())
            .collect();
        h.sort_by(f64::total_cmp);
        h.dedup();
        h
    }
}

/// [`Model::numbers`].
struct Numbers;

impl ModelVisitor for Numbers {
    type Output = Vec<Vec<Nt2Number>>;
    fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
        numbers_of(c.points())
    }
    fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Self::Output {
        numbers_of(s.points())
    }
}

fn numbers_of<const D: usize>(points: &[Nt2Point<D>]) -> Vec<Vec<Nt2Number>> {
    points.iter().map(|p| p.coords().to_vec()).collect()
}

/// [`Model::dimension`].
struct Dimension;

impl ModelVisitor for Dimension {
    type Output = usize;
    fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> usize {
        D
    }
    fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> usize {
        D
    }
}
