//! A fuzzy object as its seven layers: the crisp object through one value of
//! every control point, with the fuzzy object's weights and knots
//! (docs/method.md §6) — with fuzzy weights, the same value of every weight
//! (docs/method.md §16). What is measured on a layer — derivatives,
//! curvature, closest point — is measured on the fuzzy object layer by
//! layer, written here once for curves and surfaces.

use crate::capability::{Bounded, Closest, Curvature, Differentiable, Parametric};
use crate::error::Error;
use crate::fuzzy::{Layer, Layers, Nt2Number, Nt2Point};
use crate::nurbs::BoundingBox;

/// A fuzzy curve or surface: its fuzzy control points, and the crisp object
/// through any choice of one point per control point with its weights and
/// knots.
pub trait Layered<const D: usize> {
    /// The crisp object of a layer: [`NurbsCurve`](crate::NurbsCurve) or
    /// [`NurbsSurface`](crate::NurbsSurface).
    type Crisp;

    /// The fuzzy control points (a surface's net row by row).
    fn fuzzy_points(&self) -> &[Nt2Point<D>];

    /// The crisp object with this object's weights and knots through
    /// `points` (one per fuzzy control point, in the same order); with fuzzy
    /// weights, their crisp values.
    fn through(&self, points: Vec<[f64; D]>) -> Self::Crisp;

    /// The fuzzy weights, one per control point in the order of
    /// [`Layered::fuzzy_points`], or `None` where the weights are crisp
    /// (docs/method.md §16).
    fn weight_numbers(&self) -> Option<&[Nt2Number]>;

    /// The crisp object with this object's knots through `points` with the
    /// weights `weights` (one per control point, each a value of its fuzzy
    /// weight, so valid weights).
    fn through_weighted(&self, points: Vec<[f64; D]>, weights: Vec<f64>) -> Self::Crisp;

    /// The layer object through one value of every control point
    /// (docs/method.md §6) and, with fuzzy weights, the same value of every
    /// weight (docs/method.md §16).
    fn layer(&self, layer: Layer) -> Self::Crisp {
        let points = self.fuzzy_points().iter().map(|p| p.layer(layer)).collect();
        match self.weight_numbers() {
            None => self.through(points),
            Some(w) => self.through_weighted(points, w.iter().map(|w| w.layer(layer)).collect()),
        }
    }
}

/// `f` of every layer object, in the order of [`Layer::ALL`]; an error of a
/// layer is returned as that layer's ([`Error::InLayer`]).
///
/// # Errors
/// The first layer's error, wrapped in [`Error::InLayer`].
pub fn per_layer<const D: usize, T: Layered<D> + ?Sized, R>(
    fuzzy: &T,
    mut f: impl FnMut(&T::Crisp) -> Result<R, Error>,
) -> Result<Layers<R>, Error> {
    Layers::try_from_fn(|layer| f(&fuzzy.layer(layer)).map_err(|e| e.in_layer(layer)))
}

/// The derivatives of every layer at a parameter the fuzzy object checks
/// first, so that a parameter outside the domain is the object's error, not
/// a layer's.
///
/// # Errors
/// As [`Parametric::check_param`] and [`Differentiable::derivatives_at`].
pub fn derivatives<const D: usize, T>(
    fuzzy: &T,
    at: T::Param,
    order: usize,
) -> Result<Layers<<T::Crisp as Differentiable>::Derivatives>, Error>
where
    T: Layered<D> + Parametric,
    T::Crisp: Differentiable<Param = T::Param>,
{
    fuzzy.check_param(at)?;
    crate::nurbs::derivatives::check_order(order)?;
    per_layer(fuzzy, |c| c.derivatives_at(at, order))
}

/// The curvature of every layer at a parameter the fuzzy object checks
/// first.
///
/// # Errors
/// As [`Parametric::check_param`]; a layer's error wrapped in
/// [`Error::InLayer`].
pub fn curvatures<const D: usize, T>(
    fuzzy: &T,
    at: T::Param,
) -> Result<Layers<<T::Crisp as Curvature>::Curvature>, Error>
where
    T: Layered<D> + Parametric,
    T::Crisp: Curvature<Param = T::Param>,
{
    fuzzy.check_param(at)?;
    per_layer(fuzzy, |c| c.curvature_at(at))
}

/// A box the fuzzy object can occupy. With crisp weights it is the union
/// of the seven layers' bounding boxes, the least such box: since the
/// layers are ordered at every parameter, its lower corner comes from the
/// `upper_left` layer and its upper corner from the `upper_right` layer.
/// With fuzzy weights the layers are not ordered and do not bound the
/// object, and the box is that of every upper cut at level 0 of the control
/// points: every admissible choice is a weighted average of points inside
/// them with non-negative weights (docs/method.md §16). It contains the
/// object, but need not be the least box that does.
pub fn bounding_box<const D: usize, T>(fuzzy: &T) -> BoundingBox<D>
where
    T: Layered<D> + ?Sized,
    T::Crisp: Bounded<D>,
{
    if fuzzy.weight_numbers().is_some() {
        let mut boxes = fuzzy.fuzzy_points().iter().map(|p| BoundingBox {
            min: p.layer(Layer::UpperLeft),
            max: p.layer(Layer::UpperRight),
        });
        if let Some(first) = boxes.next() {
            return boxes.fold(first, BoundingBox::union);
        }
    }
    let [first, rest @ ..] = Layer::ALL;
    rest.iter()
        .fold(fuzzy.layer(first).bounding_box(), |b, &l| {
            b.union(fuzzy.layer(l).bounding_box())
        })
}

/// The point of every layer nearest `target`.
///
/// # Errors
/// As [`Closest::closest_to`] of a layer, wrapped in [`Error::InLayer`].
pub fn closest<const D: usize, T>(
    fuzzy: &T,
    target: [f64; D],
) -> Result<Layers<<T::Crisp as Closest<D>>::Nearest>, Error>
where
    T: Layered<D> + ?Sized,
    T::Crisp: Closest<D>,
{
    per_layer(fuzzy, |c| c.closest_to(target))
}
