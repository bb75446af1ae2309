//! The curve operations on a fuzzy curve: every layer with the same knots and
//! weights (docs/method.md §6), so that the result is again a fuzzy curve.
//!
//! Knot insertion, refinement, splitting and degree elevation are linear maps
//! of the homogeneous control points `(wᵢPᵢ, wᵢ)` whose coefficients depend only
//! on knots and weights. The seven layers are stacked into one homogeneous row
//! per control point, `(w·x_upper_left, …, w·x_upper_right, w)`, and the crisp
//! algorithm runs once on those rows, so every layer sees the same
//! coefficients and the crisp layer of the result is bit for bit the result of
//! the crisp algorithm.
//!
//! **Why the order of docs/method.md §1 survives.** A new Cartesian point is
//! `Qⱼ = Σᵢ cⱼᵢwᵢPᵢ / Σᵢ cⱼᵢwᵢ`: with `cⱼᵢ ≥ 0` a convex combination of old
//! points with coefficients `cⱼᵢwᵢ/Σ cⱼᵢwᵢ` common to all seven layers, so the
//! order of the old values carries over to every new value. Insertion,
//! refinement and splitting compute the rows by steps `α·a + (1 − α)·b` with
//! `α ∈ [0, 1]`, which are monotone in floating point too: their order holds
//! bit for bit. Degree elevation (A5.9) has non-negative coefficients as a map
//! (Prautzsch, 1984), but A5.9 gets there by knot removal, an extrapolation;
//! its rounding can swap two almost equal values by an ulp. Such swaps are
//! repaired by clamping outward from the crisp value (`lower.left ← min(lower.left,
//! crisp)`, then `primary.left ← min(primary.left, lower.left)`, …); the tests
//! check that nothing larger than rounding is ever repaired.

use crate::capability::layered;
use crate::error::{Error, Place};
use crate::fuzzy::{Axis, Height, Layer, Layers, Nt2Number, Nt2Point};
use crate::nurbs::degree_elevation::{check_elevation, elevate};
use crate::nurbs::homogeneous::{check_rows, Row};
use crate::nurbs::knot_insertion::{insert, refine};
use crate::nurbs::split::{segment, split};
use crate::nurbs::{BoundingBox, ClosestPoint, KnotVector};
use crate::pipeline::FuzzyCurve;

/// The lower height of each coordinate, shared by every point; `place(k, axis)`
/// names the number of `points[k]` in an error.
///
/// # Errors
/// [`Error::MixedHeights`] naming the first number whose height differs
/// from the first point's.
pub(crate) fn common_heights<const D: usize>(
    points: &[Nt2Point<D>],
    place: impl Fn(usize, Axis) -> Place,
) -> Result<[Height; D], Error> {
    // Curves and surfaces hold at least one point (their constructors check
    // the count), so the error is never returned for them.
    let Some(first) = points.first() else {
        return Err(Error::TooFewControlPoints { order: 1, count: 0 });
    };
    let first = first.coords().map(|x| x.height());
    for (i, p) in points.iter().enumerate() {
        for (axis, (x, h)) in Axis::of::<D>()
            .into_iter()
            .zip(p.coords().iter().zip(&first))
        {
            if x.height() != *h {
                return Err(Error::MixedHeights {
                    place: place(i, axis),
                    height: x.height().get(),
                    expected: h.get(),
                });
            }
        }
    }
    Ok(first)
}

/// One homogeneous row per control point: the seven layers, then the weight.
pub(crate) fn stacked_rows<const D: usize>(points: &[Nt2Point<D>], weights: &[f64]) -> Vec<Row> {
    points
        .iter()
        .zip(weights)
        .map(|(p, &w)| {
            Layer::ALL
                .iter()
                .flat_map(|&l| p.layer(l).map(|x| w * x))
                .chain([w])
                .collect()
        })
        .collect()
}

impl<const D: usize> FuzzyCurve<D> {
    /// The lower height of each coordinate, shared by every point.
    ///
    /// # Errors
    /// [`Error::MixedHeights`] naming the first number whose height differs
    /// from the first point's.
    fn common_heights(&self) -> Result<[Height; D], Error> {
        common_heights(self.points(), Place::new)
    }

    /// One homogeneous row per control point: the seven layers, then the weight.
    fn stacked_rows(&self) -> Vec<Row> {
        stacked_rows(self.points(), self.weights())
    }

    /// Runs an operation on the stacked rows and rebuilds the fuzzy curve; also
    /// returns the largest order violation that had to be repaired.
    pub(crate) fn map_rows(
        &self,
        op: impl FnOnce(&KnotVector, &[Row]) -> Result<(KnotVector, Vec<Row>), Error>,
    ) -> Result<(Self, f64), Error> {
        let heights = self.common_heights()?;
        let (knots, rows) = op(self.knots(), &self.stacked_rows())?;
        check_rows(&rows, "the operation on the fuzzy curve")?;
        Ok(rebuild(knots, &rows, heights))
    }

    /// The same fuzzy curve with the knot `u` inserted `times` times, in every
    /// layer (see [`NurbsCurve::insert_knot`](crate::NurbsCurve::insert_knot));
    /// the layer curves are unchanged, and so are the curves of every stage.
    ///
    /// # Errors
    /// Those of `NurbsCurve::insert_knot`, and [`Error::MixedHeights`] if a
    /// coordinate mixes lower heights.
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
    /// let c = FuzzyCurve::try_new(2, points, vec![1.0, 3.0, 1.0], None)?;
    /// let d = c.insert_knot(0.3, 1)?;
    /// assert_eq!(d.points().len(), 4);
    /// let (a, b) = (c.eval_layers(0.6)?, d.eval_layers(0.6)?);
    /// assert!((a[Layer::UpperRight][1] - b[Layer::UpperRight][1]).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self, Error> {
        self.crisp_weights_for("knot insertion")?;
        Ok(self.map_rows(|k, r| insert(k, r, u, times))?.0)
    }

    /// The same fuzzy curve with all knots of `new` inserted, in every layer
    /// (see [`NurbsCurve::refine_knots`](crate::NurbsCurve::refine_knots)).
    ///
    /// # Errors
    /// Those of `NurbsCurve::refine_knots`, and [`Error::MixedHeights`].
    pub fn refine_knots(&self, new: &[f64]) -> Result<Self, Error> {
        self.crisp_weights_for("knot refinement")?;
        Ok(self.map_rows(|k, r| refine(k, r, new))?.0)
    }

    /// The same fuzzy curve with its degree raised by `times`, in every layer
    /// (see [`NurbsCurve::elevate_degree`](crate::NurbsCurve::elevate_degree)).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the new degree would exceed 64;
    /// [`Error::MixedHeights`].
    pub fn elevate_degree(&self, times: usize) -> Result<Self, Error> {
        check_elevation(self.degree(), times)?;
        self.crisp_weights_for("degree elevation")?;
        Ok(self.map_rows(|k, r| Ok(elevate(k, r, times)))?.0)
    }

    /// The two fuzzy curves on `[a, t]` and `[t, b]`, every layer split at `t`
    /// (see [`NurbsCurve::split_at`](crate::NurbsCurve::split_at)).
    ///
    /// # Errors
    /// [`Error::SplitOutside`] unless `a < t < b`; [`Error::MixedHeights`].
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
    /// let c = FuzzyCurve::try_new(2, points, vec![1.0, 3.0, 1.0], None)?;
    /// let [left, right] = c.split_at(0.4)?;
    /// // The pieces meet in one fuzzy point: every layer is continuous.
    /// assert_eq!(left.points().last(), right.points().first());
    /// let (a, b) = (c.eval_layers(0.2)?, left.eval_layers(0.2)?);
    /// assert!((a[Layer::UpperLeft][0] - b[Layer::UpperLeft][0]).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn split_at(&self, t: f64) -> Result<[Self; 2], Error> {
        self.crisp_weights_for("splitting")?;
        let heights = self.common_heights()?;
        let pieces = split(self.knots(), &self.stacked_rows(), t)?;
        Ok(pieces.map(|(knots, rows)| rebuild(knots, &rows, heights).0))
    }

    /// The fuzzy curve over `[a, b]`, clamped at both ends (see
    /// [`NurbsCurve::segment`](crate::NurbsCurve::segment)).
    ///
    /// # Errors
    /// As `NurbsCurve::segment`, and [`Error::MixedHeights`].
    pub fn segment(&self, a: f64, b: f64) -> Result<Self, Error> {
        let domain = self.domain();
        domain.check(a)?;
        domain.check(b)?;
        if a >= b || b.is_nan() {
            return Err(Error::SplitOutside {
                t: b,
                start: a,
                end: domain.end,
            });
        }
        self.crisp_weights_for("a segment")?;
        Ok(self.map_rows(|k, r| segment(k, r, a, b))?.0)
    }

    /// The derivatives `C⁽⁰⁾ … C⁽ⁿ⁾` of every layer curve at `t` (see
    /// [`NurbsCurve::derivatives`](crate::NurbsCurve::derivatives)). Unlike the
    /// points, derivatives of the layers are not ordered.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain;
    /// [`Error::OutOfRange`] if `order` exceeds
    /// [`MAX_DERIVATIVE_ORDER`](crate::nurbs::derivatives::MAX_DERIVATIVE_ORDER).
    ///
    /// # Examples
    /// A straight fuzzy segment: every layer has the constant velocity of its
    /// own end points.
    /// ```
    /// # use t2spline::{FuzzyCurve, Layer, Nt2Number, Nt2Point};
    /// let n = |c: f64, s: f64| Nt2Number::try_new(c, [c - s, c + s], [c, c], [c, c], 1.0);
    /// let c = FuzzyCurve::try_new(1, vec![
    ///     Nt2Point::new([n(0.0, 0.0)?, n(0.0, 0.0)?]),
    ///     Nt2Point::new([n(4.0, 1.0)?, n(2.0, 0.5)?]),
    /// ], vec![1.0, 1.0], None)?;
    /// let d = c.derivatives(0.5, 1)?;
    /// assert_eq!(d[Layer::Crisp][1], [4.0, 2.0]);
    /// assert_eq!(d[Layer::UpperLeft][1], [3.0, 1.5]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn derivatives(&self, t: f64, order: usize) -> Result<Layers<Vec<[f64; D]>>, Error> {
        layered::derivatives(self, t, order)
    }

    /// The point of every layer curve closest to `target` (see
    /// [`NurbsCurve::closest_point`](crate::NurbsCurve::closest_point)). Other
    /// per-layer quantities (tangent, curvature, parameter at a length) come
    /// from [`FuzzyCurve::layer_curve`].
    #[must_use]
    pub fn closest_points(&self, target: [f64; D]) -> Layers<ClosestPoint<D>> {
        Layers::from_fn(|l| self.layer_curve(l).closest_point(target))
    }

    /// The arc length of every layer curve (see
    /// [`NurbsCurve::arc_length`](crate::NurbsCurve::arc_length)).
    #[must_use]
    pub fn arc_lengths(&self) -> Layers<f64> {
        Layers::from_fn(|l| self.layer_curve(l).arc_length())
    }

    /// The bounding box of all seven layer curves: the region the fuzzy curve
    /// can occupy. Since the layers are ordered at every `t`, its lower corner
    /// comes from the `upper_left` curve and its upper corner from the
    /// `upper_right` curve. With fuzzy weights, a box that contains the
    /// curve without being the least (see
    /// [`capability::layered::bounding_box`](crate::capability::layered::bounding_box)).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c, c], [c, c], 1.0);
    /// let c = FuzzyCurve::try_new(1, vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(1.0)?, n(3.0)?])], vec![1.0; 2], None)?;
    /// let b = c.bounding_box();
    /// assert_eq!((b.min, b.max), ([-1.0, -1.0], [3.0, 5.0]));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn bounding_box(&self) -> BoundingBox<D> {
        layered::bounding_box(self)
    }

    /// The curvature of every layer curve at `t` (see
    /// [`NurbsCurve::curvature`](crate::NurbsCurve::curvature)).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain;
    /// [`Error::InLayer`] naming the first layer (in the order of
    /// docs/method.md §1) whose first derivative vanishes at `t`, wrapping
    /// [`Error::Singular`].
    ///
    /// # Examples
    /// A quarter circle of radius 1 whose points spread radially: the layer
    /// `upper_left` has radius 0.5, `upper_right` radius 2.
    /// ```
    /// # use t2spline::{FuzzyCurve, Layer, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [0.5 * c, 2.0 * c], [c, c], [c, c], 0.5);
    /// let p = |x: f64, y: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?]));
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let c = FuzzyCurve::try_new(2, vec![p(1.0, 0.0)?, p(1.0, 1.0)?, p(0.0, 1.0)?], vec![1.0, w, 1.0], None)?;
    /// let k = c.curvatures(0.3)?;
    /// assert!((k[Layer::Crisp] - 1.0).abs() < 1e-14);
    /// assert!((k[Layer::UpperLeft] - 2.0).abs() < 1e-14);
    /// assert!((k[Layer::UpperRight] - 0.5).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn curvatures(&self, t: f64) -> Result<Layers<f64>, Error> {
        layered::curvatures(self, t)
    }
}

/// The fuzzy curve from stacked homogeneous rows, with the order repaired;
/// also the largest repair made.
fn rebuild<const D: usize>(
    knots: KnotVector,
    rows: &[Row],
    heights: [Height; D],
) -> (FuzzyCurve<D>, f64) {
    let (points, weights, worst) = from_stacked_rows(rows, heights);
    (
        FuzzyCurve::from_parts_unchecked(points, weights, knots),
        worst,
    )
}

/// Fuzzy points and weights from stacked homogeneous rows (see
/// [`stacked_rows`]), the order of every number repaired against rounding;
/// also the largest repair made.
pub(crate) fn from_stacked_rows<const D: usize>(
    rows: &[Row],
    heights: [Height; D],
) -> (Vec<Nt2Point<D>>, Vec<f64>, f64) {
    let mut worst: f64 = 0.0;
    let mut weights = Vec::with_capacity(rows.len());
    let points = rows
        .iter()
        .map(|row| {
            let w = row[7 * D];
            weights.push(w);
            Nt2Point::new(std::array::from_fn(|d| {
                let mut v = Layers::from_fn(|l| row[l.index() * D + d] / w);
                worst = worst.max(repair_order(&mut v));
                Nt2Number::from_layers_unchecked(&v, heights[d])
            }))
        })
        .collect();
    (points, weights, worst)
}

/// Clamps the seven values outward from the crisp one so that they are
/// ordered; returns the largest change.
fn repair_order(v: &mut Layers<f64>) -> f64 {
    let mut worst: f64 = 0.0;
    let mut fix = |v: &mut Layers<f64>, l: Layer, inner: Layer, left: bool| {
        let (x, bound) = (v[l], v[inner]);
        let y = if left { x.min(bound) } else { x.max(bound) };
        worst = worst.max((y - x).abs());
        v[l] = y;
    };
    fix(v, Layer::LowerLeft, Layer::Crisp, true);
    fix(v, Layer::PrimaryLeft, Layer::LowerLeft, true);
    fix(v, Layer::UpperLeft, Layer::PrimaryLeft, true);
    fix(v, Layer::LowerRight, Layer::Crisp, false);
    fix(v, Layer::PrimaryRight, Layer::LowerRight, false);
    fix(v, Layer::UpperRight, Layer::PrimaryRight, false);
    worst
}

#[cfg(test)]
mod tests;
