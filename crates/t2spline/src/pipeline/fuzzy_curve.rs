//! Stage 1: the normal type-2 fuzzy rational B-spline curve (NT2FRBsC) and its
//! seven layer curves (docs/method.md §6–§7, paper Eq. 5.1, Fig. 5.1).

use crate::capability::Layered;
use crate::error::Error;
use crate::fuzzy::{Alpha, Axis, Height, Layer, Layers, Nt2Number, Nt2Point};
use crate::nurbs::curve::{check_weights, rational_basis_span};
use crate::nurbs::{Domain, KnotVector, NurbsCurve};
use crate::pipeline::weight_numbers::{crisp_only, weights_of};
use crate::pipeline::Solution;
use crate::reduction::TypeReduction;

/// A rational B-spline curve whose control points are normal type-2 fuzzy points
/// (docs/method.md §6, paper Def. 5.1):
///
/// ```text
/// C̃(t) = Σᵢ wᵢ Nᵢ,ₚ(t) P̃ᵢ / Σᵣ wᵣ Nᵣ,ₚ(t)
/// ```
/// evaluated layer by layer: one rational B-spline through each of the seven
/// values of every control point, all with the same weights and knots. Because
/// the rational basis is non-negative and sums to 1, the seven layer curves keep
/// the order of docs/method.md §1 at every `t`.
///
/// # Examples
/// ```
/// # use t2spline::{FuzzyCurve, Layer, Nt2Number, Nt2Point};
/// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
/// let points = vec![
///     Nt2Point::new([n(0.0)?, n(0.0)?]),
///     Nt2Point::new([n(1.0)?, n(2.0)?]),
///     Nt2Point::new([n(2.0)?, n(0.0)?]),
/// ];
/// let c = FuzzyCurve::try_new(2, points, vec![1.0, 1.0, 1.0], None)?;
/// let at = c.eval_layers(0.5)?;
/// assert_eq!(at[Layer::Crisp], [1.0, 1.0]);
/// assert_eq!(at[Layer::UpperRight], [3.0, 3.0]);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzyCurve<const D: usize> {
    points: Vec<Nt2Point<D>>,
    /// The crisp weights, or the crisp values of the fuzzy weights.
    weights: Vec<f64>,
    /// The fuzzy weights (docs/method.md §16), `None` where they are crisp.
    weight_numbers: Option<Vec<Nt2Number>>,
    knots: KnotVector,
}

impl<const D: usize> FuzzyCurve<D> {
    /// Makes a fuzzy curve of degree `degree`; `knots = None` selects the clamped
    /// uniform default (docs/method.md §6).
    ///
    /// # Errors
    /// [`Error::Dimension`] unless `1 ≤ D ≤ 3`; [`Error::TooFewControlPoints`],
    /// [`Error::WeightCount`], [`Error::Weight`], [`Error::WeightOutOfRange`],
    /// and the knot errors of [`KnotVector::try_new`].
    pub fn try_new(
        degree: usize,
        points: Vec<Nt2Point<D>>,
        weights: Vec<f64>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self, Error> {
        Axis::first::<D>()?;
        let n = points.len();
        let knots = match knots {
            Some(values) => KnotVector::try_new(values, degree, n)?,
            None => KnotVector::clamped_uniform(degree, n)?,
        };
        check_weights(&weights, n)?;
        Ok(FuzzyCurve {
            points,
            weights,
            weight_numbers: None,
            knots,
        })
    }

    /// This curve with fuzzy weights (docs/method.md §16): one normal
    /// type-2 fuzzy number per control point, every value of each (its
    /// upper cut's feet included) a valid weight. The crisp values become
    /// [`FuzzyCurve::weights`]. Numbers that are all crisp (every value
    /// equal) leave the curve with crisp weights.
    ///
    /// # Errors
    /// [`Error::WeightCount`] unless there is one number per control point;
    /// [`Error::Weight`] or [`Error::WeightOutOfRange`] for the first value
    /// (the least first) that is not a valid weight.
    pub fn with_weight_numbers(self, numbers: Vec<Nt2Number>) -> Result<Self, Error> {
        let (weights, weight_numbers) = weights_of(numbers, self.points.len())?;
        Ok(FuzzyCurve {
            weights,
            weight_numbers,
            ..self
        })
    }

    /// A fuzzy curve from parts that an exact algorithm derived from a valid
    /// curve.
    pub(crate) fn from_parts_unchecked(
        points: Vec<Nt2Point<D>>,
        weights: Vec<f64>,
        knots: KnotVector,
    ) -> Self {
        debug_assert_eq!(points.len(), knots.count());
        debug_assert_eq!(weights.len(), knots.count());
        FuzzyCurve {
            points,
            weights,
            weight_numbers: None,
            knots,
        }
    }

    /// The fuzzy control points.
    #[must_use]
    pub fn points(&self) -> &[Nt2Point<D>] {
        &self.points
    }

    /// The weights: with fuzzy weights, their crisp values.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The fuzzy weights (docs/method.md §16), or `None` where the weights
    /// are crisp.
    #[must_use]
    pub fn weight_numbers(&self) -> Option<&[Nt2Number]> {
        self.weight_numbers.as_deref()
    }

    /// `Err(`[`Error::FuzzyWeights`]`)` naming `what` where the weights are
    /// fuzzy: the guard of the operations that take crisp weights only.
    pub(crate) fn crisp_weights_for(&self, what: &'static str) -> Result<(), Error> {
        crisp_only(self.weight_numbers(), what)
    }

    /// The knot vector.
    #[must_use]
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The degree `p`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The order `k = p + 1`.
    #[must_use]
    pub fn order(&self) -> usize {
        self.degree() + 1
    }

    /// The parameter domain.
    #[must_use]
    pub fn domain(&self) -> Domain {
        self.knots.domain()
    }

    /// A crisp curve with this curve's weights and knots through `control_points`
    /// (one per fuzzy control point).
    pub(crate) fn with_control_points(&self, control_points: Vec<[f64; D]>) -> NurbsCurve<D> {
        NurbsCurve::from_parts_unchecked(control_points, self.weights.clone(), self.knots.clone())
    }

    /// The layer curve through one value of every control point (docs/method.md §6).
    #[must_use]
    pub fn layer_curve(&self, layer: Layer) -> NurbsCurve<D> {
        Layered::layer(self, layer)
    }

    /// The curve through the crisp values: the crisp rational B-spline.
    #[must_use]
    pub fn crisp_curve(&self) -> NurbsCurve<D> {
        self.layer_curve(Layer::Crisp)
    }

    /// The seven layer curves at `t`, from one evaluation of the rational basis.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    pub fn eval_layers(&self, t: f64) -> Result<Layers<[f64; D]>, Error> {
        self.domain().check(t)?;
        if self.weight_numbers.is_some() {
            // Each layer has weights of its own (docs/method.md §16).
            return Ok(Layers::from_fn(|layer| {
                self.layer_curve(layer).eval_unchecked(t)
            }));
        }
        // All layer curves share one rational basis.
        let (first, r) = rational_basis_span(&self.knots, &self.weights, t);
        let mut out = Layers::from_fn(|_| [0.0; D]);
        for (ri, p) in r.iter().zip(&self.points[first..]) {
            for layer in Layer::ALL {
                for (o, x) in out[layer].iter_mut().zip(p.layer(layer)) {
                    *o += ri * x;
                }
            }
        }
        Ok(out)
    }

    /// The lower height shared by every number of each coordinate, or `None` if
    /// some coordinate mixes heights.
    #[must_use]
    pub fn coordinate_heights(&self) -> Option<[Height; D]> {
        let first = self.points.first()?;
        let heights = first.coords().map(|x| x.height());
        self.points
            .iter()
            .all(|p| {
                p.coords()
                    .iter()
                    .zip(&heights)
                    .all(|(x, h)| x.height() == *h)
            })
            .then_some(heights)
    }

    /// The fuzzy curve at `t` as a fuzzy point, when each coordinate has one
    /// lower height for all control points (then the point's numbers have that
    /// height) and the weights are crisp; `Ok(None)` otherwise, since a mix
    /// of heights does not combine into one number (docs/method.md §6), nor
    /// do layers with weights of their own, which need not be ordered
    /// (docs/method.md §16).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    pub fn eval(&self, t: f64) -> Result<Option<Nt2Point<D>>, Error> {
        let layers = self.eval_layers(t)?;
        if self.weight_numbers.is_some() {
            return Ok(None);
        }
        Ok(self.coordinate_heights().map(|heights| {
            Nt2Point::new(std::array::from_fn(|d| {
                let values = layers.map(|p| p[d]);
                Nt2Number::from_layers_unchecked(&values, heights[d])
            }))
        }))
    }

    /// Runs stages 2–4 of Algorithm 1.1 at level `alpha` with the paper's
    /// type reduction (docs/method.md §7); the same as
    /// `self.solve_with(alpha, TypeReduction::Paper)`.
    #[must_use]
    pub fn solve(&self, alpha: Alpha) -> Solution<D> {
        self.solve_with(alpha, TypeReduction::Paper)
    }

    /// Runs stages 2–4 with the type reduction `method` (docs/method.md §7, §9): the
    /// cut at `alpha` (stage 2), then every control point's numbers reduced
    /// by [`Nt2Number::reduce`] (stage 3: left and right; stage 4: the
    /// defuzzified value). Only [`TypeReduction::Paper`] reduces the cut;
    /// the other reductions read the whole number and do not depend on
    /// `alpha`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point, TypeReduction};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 0.6, c + 0.9], [c - 0.4, c + 0.6], [c - 0.2, c + 0.3], 0.6);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
    /// let curve = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// let (low, high) = (Alpha::try_new(0.0)?, Alpha::try_new(0.8)?);
    /// let centroid = curve.solve_with(low, TypeReduction::Centroid);
    /// // Every control point is reduced as its numbers are, whatever alpha.
    /// let c = curve.points()[1].coords()[0].centroid();
    /// assert_eq!(centroid.type_reduced_points()[1][0].left(), c.left());
    /// assert_eq!(centroid.defuzzified_points(), curve.solve_with(high, TypeReduction::Centroid).defuzzified_points());
    /// // The right sides are longer: the solution moves right, by another amount per reduction.
    /// for method in TypeReduction::ALL {
    ///     assert!(curve.solve_with(high, method).distance().max > 0.0, "{method}");
    /// }
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn solve_with(&self, alpha: Alpha, method: TypeReduction) -> Solution<D> {
        Solution::new(self.clone(), alpha, method)
    }

    /// The axes of this curve's points.
    #[must_use]
    pub fn axes(&self) -> [Axis; D] {
        Axis::of::<D>()
    }
}
