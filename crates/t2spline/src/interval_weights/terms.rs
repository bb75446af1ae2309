//! The terms of a rational B-spline with uncertain weights at one parameter
//! `t` and one level alpha (docs/method.md §15): the non-zero basis values
//! `Nᵢ(t)`, the cut `[w̲ᵢ, w̄ᵢ]` of every weight and the cut `[P̲ᵢₖ, P̄ᵢₖ]` of
//! every coordinate, checked once; and a [`Vertex`], one choice of every
//! weight at an end of its cut and every point at a corner of its box, with
//! the point of the curve it gives.
//!
//! ```text
//! C(t) = Σ wᵢNᵢ(t)Pᵢ / Σ wᵢNᵢ(t),   wᵢ ∈ [w̲ᵢ, w̄ᵢ],  Pᵢ ∈ Bᵢ = Π_k [P̲ᵢₖ, P̄ᵢₖ]
//! ```
//! is a weighted average of the points with the non-negative weights
//! `θᵢ = wᵢNᵢ ∈ [w̲ᵢNᵢ, w̄ᵢNᵢ]`: the set `S(t)` of all its values is what the
//! files beside this one describe.

use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE, MAX_WEIGHT, MIN_WEIGHT};

use super::km::binary_scale;

/// The most terms with a basis value above 0 at one parameter: a curve of
/// degree up to 127. Membership in three coordinates tries `O(n²)`
/// directions of `O(n)` work each; the limit keeps it below about 50 ms
/// a point (docs/performance.md).
pub const MAX_TERMS: usize = 128;

/// Checks the cuts of weights and points (the rules of
/// [`IntervalTerms::try_new`]), for terms or for a whole curve.
pub(crate) fn check_cuts<const D: usize>(
    weights: &[[f64; 2]],
    points: &[[[f64; 2]; D]],
) -> Result<(), Error> {
    let axes = Axis::first::<D>()?;
    for (index, &[left, right]) in weights.iter().enumerate() {
        for value in [left, right] {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::Weight { index, value });
            }
            if !(MIN_WEIGHT..=MAX_WEIGHT).contains(&value) {
                return Err(Error::WeightOutOfRange { index, value });
            }
        }
        if left > right {
            return Err(Error::WeightCut {
                index,
                left,
                right,
                rule: "is out of order: its left end is above its right end",
            });
        }
    }
    for (i, p) in points.iter().enumerate() {
        for (&axis, &[left, right]) in axes.iter().zip(p) {
            let place = Place::new(i, axis);
            for (what, value) in [("left", left), ("right", right)] {
                if !value.is_finite() {
                    return Err(Error::NotFinite { place, what, value });
                }
                if !within_magnitude(value) {
                    return Err(Error::OutOfRange {
                        place,
                        what,
                        value,
                        range: MAGNITUDE_RANGE,
                    });
                }
            }
            if left > right {
                return Err(Error::Order {
                    place,
                    rule: "left <= right",
                    left,
                    right,
                });
            }
        }
    }
    Ok(())
}

/// The checked terms of the weighted average at one parameter: basis values,
/// weight cuts and coordinate cuts (module docs; docs/method.md §15).
///
/// Built by [`IntervalTerms::try_new`] from the `p + 1` non-zero basis values
/// at `t` ([`try_basis_functions`](crate::nurbs::basis::try_basis_functions))
/// and the cuts of the same terms, or by
/// [`IntervalCurve::terms`](crate::interval_weights::IntervalCurve::terms).
#[derive(Clone, Debug, PartialEq)]
pub struct IntervalTerms<const D: usize> {
    basis: Vec<f64>,
    weights: Vec<[f64; 2]>,
    points: Vec<[[f64; 2]; D]>,
    /// `θ̲ᵢ = w̲ᵢNᵢ` and `θ̄ᵢ = w̄ᵢNᵢ`.
    lower: Vec<f64>,
    upper: Vec<f64>,
}

/// One vertex choice: every weight at an end of its cut, every point at a
/// corner of its box, and the point `Σ wᵢNᵢcᵢ / Σ wᵢNᵢ` they give. The
/// extremes of the envelope and of the support function are reached at
/// such choices (docs/method.md §15).
#[derive(Clone, Debug, PartialEq)]
pub struct Vertex<const D: usize> {
    weights: Vec<f64>,
    corners: Vec<[f64; D]>,
    point: [f64; D],
}

impl<const D: usize> Vertex<D> {
    /// The weight chosen for each term: `w̲ᵢ` or `w̄ᵢ`, exactly as given.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The corner chosen for each term's point, coordinates exactly as given.
    #[must_use]
    pub fn corners(&self) -> &[[f64; D]] {
        &self.corners
    }

    /// The point `Σ wᵢNᵢcᵢ / Σ wᵢNᵢ` of this choice.
    #[must_use]
    pub fn point(&self) -> [f64; D] {
        self.point
    }
}

impl<const D: usize> IntervalTerms<D> {
    /// Checks the terms of the weighted average at one parameter: `basis[i]`
    /// is `Nᵢ(t)`, `weights[i] = [w̲ᵢ, w̄ᵢ]` and `points[i][k] = [P̲ᵢₖ, P̄ᵢₖ]`
    /// the cuts of the same term at the level.
    ///
    /// # Errors
    /// [`Error::Dimension`] unless `1 ≤ D ≤ 3`; [`Error::Length`] if
    /// `basis` is empty or `weights` or `points` is not as long;
    /// [`Error::Basis`] for a basis value that is not finite, negative or
    /// above `1e150`, or if every one is 0; [`Error::TooManyTerms`] for more
    /// than [`MAX_TERMS`] basis values above 0; [`Error::Weight`] for a weight
    /// end that is not finite and greater than 0, [`Error::WeightOutOfRange`]
    /// outside `[1e-150, 1e150]`, [`Error::WeightCut`] for `w̲ > w̄`;
    /// [`Error::NotFinite`], [`Error::OutOfRange`] (outside `[-1e150, 1e150]`)
    /// and [`Error::Order`] (`left <= right`) for a coordinate cut, with its
    /// place `points[i].axis`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::interval_weights::IntervalTerms;
    /// // Two terms, N = (1/2, 1/2): points [0, 1] and [2, 3], weights [1, 2] and [1, 1].
    /// let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 2.0], [1.0, 1.0]], &[[[0.0, 1.0]], [[2.0, 3.0]]])?;
    /// let [x] = terms.envelope();
    /// // Least: all on the left ends, weight 2 on the smaller point: (2·0 + 1·2)/3.
    /// assert!((x.left() - 2.0 / 3.0).abs() < 1e-15 && (x.right() - 2.0).abs() < 1e-15);
    /// let e = IntervalTerms::try_new(&[1.0], &[[0.0, 1.0]], &[[[0.0, 1.0]]]).unwrap_err();
    /// assert_eq!(e.to_string(), "weights[0] = 0 must be finite and greater than 0");
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(
        basis: &[f64],
        weights: &[[f64; 2]],
        points: &[[[f64; 2]; D]],
    ) -> Result<Self, Error> {
        Axis::first::<D>()?;
        if basis.is_empty() {
            return Err(Error::Length {
                what: "basis",
                expected: 1,
                found: 0,
            });
        }
        for (what, found) in [("weights", weights.len()), ("points", points.len())] {
            if found != basis.len() {
                return Err(Error::Length {
                    what,
                    expected: basis.len(),
                    found,
                });
            }
        }
        for (index, &value) in basis.iter().enumerate() {
            let rule = if !(value.is_finite() && value >= 0.0) {
                Some("must be a finite number at least 0")
            } else if value > MAX_WEIGHT {
                Some("is above 1e150")
            } else {
                None
            };
            if let Some(rule) = rule {
                return Err(Error::Basis { index, value, rule });
            }
        }
        if basis.iter().all(|&n| n == 0.0) {
            return Err(Error::Basis {
                index: 0,
                value: 0.0,
                rule: "is 0, as every basis value is; at least one must be greater than 0",
            });
        }
        let count = basis.iter().filter(|&&n| n > 0.0).count();
        if count > MAX_TERMS {
            return Err(Error::TooManyTerms {
                count,
                limit: MAX_TERMS,
            });
        }
        check_cuts(weights, points)?;
        Ok(Self::new_unchecked(basis, weights, points))
    }

    /// Terms with the bounds `θᵢ ∈ [lower[i], upper[i]]` of the weighted
    /// average's weights given directly (basis values 1), for supersets of
    /// the sets over a range of parameters: `0 ≤ lowerᵢ ≤ upperᵢ` finite,
    /// `Σ lowerᵢ > 0`, checked by the caller. A lower bound may be 0.
    pub(crate) fn from_bounds(
        lower: Vec<f64>,
        upper: Vec<f64>,
        points: Vec<[[f64; 2]; D]>,
    ) -> Self {
        debug_assert!(lower.iter().sum::<f64>() > 0.0);
        IntervalTerms {
            basis: vec![1.0; lower.len()],
            weights: lower.iter().zip(&upper).map(|(&l, &u)| [l, u]).collect(),
            points,
            lower,
            upper,
        }
    }

    /// The terms from values a caller has checked.
    pub(crate) fn new_unchecked(
        basis: &[f64],
        weights: &[[f64; 2]],
        points: &[[[f64; 2]; D]],
    ) -> Self {
        let lower = basis.iter().zip(weights).map(|(n, w)| n * w[0]).collect();
        let upper = basis.iter().zip(weights).map(|(n, w)| n * w[1]).collect();
        IntervalTerms {
            basis: basis.to_vec(),
            weights: weights.to_vec(),
            points: points.to_vec(),
            lower,
            upper,
        }
    }

    /// The basis values `Nᵢ(t)`.
    #[must_use]
    pub fn basis(&self) -> &[f64] {
        &self.basis
    }

    /// The weight cuts `[w̲ᵢ, w̄ᵢ]`.
    #[must_use]
    pub fn weights(&self) -> &[[f64; 2]] {
        &self.weights
    }

    /// The coordinate cuts `[P̲ᵢₖ, P̄ᵢₖ]`.
    #[must_use]
    pub fn points(&self) -> &[[[f64; 2]; D]] {
        &self.points
    }

    /// The bounds `w̲ᵢNᵢ` of the weighted average's weights `θᵢ`.
    pub(crate) fn lower(&self) -> &[f64] {
        &self.lower
    }

    /// The bounds `w̄ᵢNᵢ` of the weighted average's weights `θᵢ`.
    pub(crate) fn upper(&self) -> &[f64] {
        &self.upper
    }

    /// The vertex with weight `w̄ᵢ` where `at_upper[i]` (else `w̲ᵢ`) and
    /// corner coordinate `corner(i, k)` (`true`: `P̄ᵢₖ`), its point summed
    /// relative to the middle of each coordinate's corners, with the weights
    /// divided by a power of two near the largest.
    pub(crate) fn vertex(
        &self,
        at_upper: &[bool],
        corner: impl Fn(usize, usize) -> bool,
    ) -> Vertex<D> {
        let n = self.basis.len();
        let weights: Vec<f64> = (0..n)
            .map(|i| self.weights[i][usize::from(at_upper[i])])
            .collect();
        let corners: Vec<[f64; D]> = (0..n)
            .map(|i| std::array::from_fn(|k| self.points[i][k][usize::from(corner(i, k))]))
            .collect();
        let theta: Vec<f64> = (0..n)
            .map(|i| {
                if at_upper[i] {
                    self.upper[i]
                } else {
                    self.lower[i]
                }
            })
            .collect();
        let scale = binary_scale(&theta);
        let point = std::array::from_fn(|k| {
            let (lo, hi) = corners
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), c| {
                    (l.min(c[k]), h.max(c[k]))
                });
            let origin = lo + (hi - lo) / 2.0;
            let (mut num, mut den) = (0.0, 0.0);
            for (c, &th) in corners.iter().zip(&theta) {
                num += th / scale * (c[k] - origin);
                den += th / scale;
            }
            if den > 0.0 {
                (origin + num / den).clamp(lo, hi)
            } else {
                origin
            }
        });
        Vertex {
            weights,
            corners,
            point,
        }
    }
}
