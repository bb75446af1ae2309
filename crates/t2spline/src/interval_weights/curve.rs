//! A rational B-spline at one level alpha with every coordinate and every
//! weight an interval (its cut): the convenience entry to the functions at
//! one parameter (docs/method.md §15). It picks the span of `t`, the `p + 1`
//! non-zero basis values (The NURBS Book, A2.1 and A2.2) and the cuts of
//! those terms, and hands them to [`IntervalTerms`].

use crate::error::Error;
use crate::fuzzy::{Axis, Interval};
use crate::nurbs::basis::try_basis_functions;
use crate::nurbs::KnotVector;

use super::terms::{check_cuts, IntervalTerms, MAX_TERMS};

/// A rational B-spline whose coordinates and weights are intervals: the cuts
/// `[P̲ᵢₖ, P̄ᵢₖ]` and `[w̲ᵢ, w̄ᵢ]` of a curve with uncertain points and weights
/// at one level (docs/method.md §15). No crisp weight is assumed.
#[derive(Clone, Debug, PartialEq)]
pub struct IntervalCurve<const D: usize> {
    points: Vec<[[f64; 2]; D]>,
    weights: Vec<[f64; 2]>,
    knots: KnotVector,
}

impl<const D: usize> IntervalCurve<D> {
    /// Makes the curve of degree `degree` from the coordinate cuts
    /// `points[i][k] = [P̲ᵢₖ, P̄ᵢₖ]` and the weight cuts
    /// `weights[i] = [w̲ᵢ, w̄ᵢ]`; `knots = None` selects the clamped uniform
    /// default (docs/method.md §6).
    ///
    /// # Errors
    /// [`Error::Dimension`] unless `1 ≤ D ≤ 3`; [`Error::TooManyTerms`] for a
    /// degree of [`MAX_TERMS`] or more; [`Error::TooFewControlPoints`]
    /// and the knot errors of [`KnotVector::try_new`]; [`Error::WeightCount`]
    /// if there is not one weight per point; the errors of
    /// [`IntervalTerms::try_new`] for a cut.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::interval_weights::IntervalCurve;
    /// let curve = IntervalCurve::try_new(1, vec![[[0.0, 0.0]], [[1.0, 1.0]]], vec![[1.0, 3.0]; 2], None)?;
    /// let [x] = curve.envelope(0.5)?;
    /// assert!((x.left() - 0.25).abs() < 1e-15 && (x.right() - 0.75).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(
        degree: usize,
        points: Vec<[[f64; 2]; D]>,
        weights: Vec<[f64; 2]>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self, Error> {
        Axis::first::<D>()?;
        let n = points.len();
        let knots = match knots {
            Some(values) => KnotVector::try_new(values, degree, n)?,
            None => KnotVector::clamped_uniform(degree, n)?,
        };
        if weights.len() != n {
            return Err(Error::WeightCount {
                expected: n,
                found: weights.len(),
            });
        }
        if degree >= MAX_TERMS {
            return Err(Error::TooManyTerms {
                count: degree.saturating_add(1),
                limit: MAX_TERMS,
            });
        }
        check_cuts(&weights, &points)?;
        Ok(IntervalCurve {
            points,
            weights,
            knots,
        })
    }

    /// The coordinate cuts.
    #[must_use]
    pub fn points(&self) -> &[[[f64; 2]; D]] {
        &self.points
    }

    /// The weight cuts.
    #[must_use]
    pub fn weights(&self) -> &[[f64; 2]] {
        &self.weights
    }

    /// The knot vector.
    #[must_use]
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The terms at `t`: the span's `p + 1` basis values and their cuts.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    pub fn terms(&self, t: f64) -> Result<IntervalTerms<D>, Error> {
        self.knots.domain().check(t)?;
        let p = self.knots.degree();
        let span = self.knots.find_span(t);
        let basis = try_basis_functions(self.knots.as_slice(), p, span, t)?;
        let first = span - p;
        let range = first..first + basis.len();
        match (self.weights.get(range.clone()), self.points.get(range)) {
            (Some(w), Some(pts)) => Ok(IntervalTerms::new_unchecked(&basis, w, pts)),
            _ => Err(Error::Index {
                what: "span",
                index: span,
                count: self.points.len(),
            }),
        }
    }

    /// The envelope of every coordinate at `t` ([`IntervalTerms::envelope`]).
    ///
    /// # Errors
    /// As [`terms`](Self::terms).
    pub fn envelope(&self, t: f64) -> Result<[Interval; D], Error> {
        Ok(self.terms(t)?.envelope())
    }

    /// The support function at `t` in `direction` ([`IntervalTerms::support`]).
    ///
    /// # Errors
    /// As [`terms`](Self::terms) and [`IntervalTerms::support`].
    pub fn support(&self, t: f64, direction: [f64; D]) -> Result<f64, Error> {
        self.terms(t)?.support(direction)
    }

    /// Whether `q` is a point of the curve at `t` for some weights and
    /// points in their cuts ([`IntervalTerms::contains`]).
    ///
    /// # Errors
    /// As [`terms`](Self::terms) and [`IntervalTerms::contains`].
    pub fn contains(&self, t: f64, q: [f64; D]) -> Result<bool, Error> {
        self.terms(t)?.contains(q)
    }

    /// The section at `t` of coordinate `of` where coordinate `along` is
    /// `at` ([`IntervalTerms::section`]).
    ///
    /// # Errors
    /// As [`terms`](Self::terms) and [`IntervalTerms::section`].
    pub fn section(
        &self,
        t: f64,
        along: Axis,
        at: f64,
        of: Axis,
    ) -> Result<Option<Interval>, Error> {
        self.terms(t)?.section(along, at, of)
    }
}
