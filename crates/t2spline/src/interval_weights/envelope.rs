//! The envelope of a curve with uncertain weights at one parameter: the
//! least and largest value of each coordinate over every weight and point in
//! their cuts (docs/method.md §15).
//! ```text
//! C̲ₖ(t) = min_{θᵢ ∈ [w̲ᵢNᵢ, w̄ᵢNᵢ]} Σ θᵢ P̲ᵢₖ / Σ θᵢ,     C̄ₖ(t) = max_θ Σ θᵢ P̄ᵢₖ / Σ θᵢ
//! ```
//! **Derivation.** For fixed weights the coordinate `Cₖ = Σ θᵢPᵢₖ / Σ θᵢ` is
//! a weighted average with non-negative weights, increasing in every
//! `Pᵢₖ`: it is least with every `Pᵢₖ` at its left end `P̲ᵢₖ`. What is left
//! is the Karnik–Mendel problem with interval weights `[w̲ᵢNᵢ, w̄ᵢNᵢ]`, solved
//! exactly at its switch point ([`km`](super::km)): the weights of the
//! smallest values at their upper ends, the rest at their lower ends. The
//! ends are `−h(−e_k)` and `h(e_k)` of the support function
//! ([`support`](super::support)). With crisp weights (`w̲ = w̄`) every switch
//! point gives the same average: the envelope is the crisp-weight curve of
//! the left ends and of the right ends. The envelopes of the coordinates are
//! a box around `S(t)`, not `S(t)`: the coordinates share the weights, so the
//! corners of the box are in general not reached
//! ([`membership`](super::membership)).

use crate::error::Error;
use crate::fuzzy::{Axis, Interval};

use super::km::{max_switch, min_switch};
use super::terms::{IntervalTerms, Vertex};

/// The relative slack of membership and sections: `1e-12` of the set's
/// extent ([`IntervalTerms::slack`]; docs/method.md §15).
pub const MEMBERSHIP_SLACK: f64 = 1e-12;

impl<const D: usize> IntervalTerms<D> {
    /// The envelope `[C̲ₖ(t), C̄ₖ(t)]` of every coordinate (module docs;
    /// docs/method.md §15), exact at the Karnik–Mendel switch points.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::interval_weights::IntervalTerms;
    /// // Crisp weights 1 and 3: the weighted averages of the ends.
    /// let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 1.0], [3.0, 3.0]], &[[[0.0, 1.0]], [[4.0, 8.0]]])?;
    /// let [x] = terms.envelope();
    /// assert!((x.left() - 3.0).abs() < 1e-15 && (x.right() - 6.25).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn envelope(&self) -> [Interval; D] {
        std::array::from_fn(|k| {
            let [lo, hi] = self.coordinate_ends(k);
            let (lo, hi) = (lo.value, hi.value);
            Interval::new_unchecked(lo.min(hi), hi)
        })
    }

    /// The slack `τ` of [`contains`](Self::contains) and
    /// [`section`](Self::section): a point within `τ` of the set in every
    /// coordinate counts as a member, a line within `τ` meets it.
    /// `τ = MEMBERSHIP_SLACK·E + 64u·M`, `E` the largest width of the
    /// envelope ([`MEMBERSHIP_SLACK`] = 1e-12), `M` the largest magnitude of
    /// its ends and `u` the unit roundoff: the extent of the set, as the
    /// set view of crisp weights counts it (docs/method.md §10), and the
    /// rounding of a point computed as a weighted average.
    #[must_use]
    pub fn slack(&self) -> f64 {
        let (mut extent, mut magnitude) = (0.0_f64, 0.0_f64);
        for range in self.envelope() {
            extent = extent.max(range.width());
            magnitude = magnitude.max(range.left().abs()).max(range.right().abs());
        }
        MEMBERSHIP_SLACK * extent + 64.0 * f64::EPSILON * magnitude
    }

    /// The vertex choices that attain the two ends of coordinate `axis`'s
    /// envelope: every point at the left (right) corner, the weights at the
    /// switch point.
    ///
    /// # Errors
    /// [`Error::Index`] if `axis` is not a coordinate of the points.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Axis, interval_weights::IntervalTerms};
    /// let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 2.0], [1.0, 1.0]], &[[[0.0, 1.0]], [[2.0, 3.0]]])?;
    /// let [least, _] = terms.envelope_vertices(Axis::X)?;
    /// assert_eq!(least.weights(), [2.0, 1.0]);
    /// assert!((least.point()[0] - terms.envelope()[0].left()).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn envelope_vertices(&self, axis: Axis) -> Result<[Vertex<D>; 2], Error> {
        let k = axis.index();
        if k >= D {
            return Err(Error::Index {
                what: "axis",
                index: k,
                count: D,
            });
        }
        let [lo, hi] = self.coordinate_ends(k);
        Ok([
            self.vertex(&lo.at_upper, |_, _| false),
            self.vertex(&hi.at_upper, |_, _| true),
        ])
    }

    /// The switch points of the two ends of coordinate `k`.
    fn coordinate_ends(&self, k: usize) -> [super::km::SwitchPoint; 2] {
        let left: Vec<f64> = self.points().iter().map(|p| p[k][0]).collect();
        let right: Vec<f64> = self.points().iter().map(|p| p[k][1]).collect();
        [
            min_switch(&left, self.lower(), self.upper()),
            max_switch(&right, self.lower(), self.upper()),
        ]
    }
}
