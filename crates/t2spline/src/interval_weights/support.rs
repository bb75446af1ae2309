//! The support function of the set `S(t)` of a curve with uncertain weights
//! at one parameter (docs/method.md §15):
//! ```text
//! h(d) = max_{q ∈ S(t)} d·q = max_{θᵢ ∈ [w̲ᵢNᵢ, w̄ᵢNᵢ]} Σ θᵢ vᵢ(d) / Σ θᵢ,    vᵢ(d) = max_{c ∈ Bᵢ} d·c = Σ_k max(d_k P̲ᵢₖ, d_k P̄ᵢₖ)
//! ```
//! **Derivation.** For fixed weights, `d·C = Σ θᵢ (d·Pᵢ) / Σ θᵢ` is a
//! weighted average with non-negative weights, so it is largest with every
//! `Pᵢ` at the corner of its box that maximises `d·Pᵢ` (each coordinate at
//! `P̄` where `d_k > 0`, at `P̲` where `d_k < 0`; either where `d_k = 0`).
//! What is left is the Karnik–Mendel problem on the values `vᵢ(d)`, solved
//! exactly at its switch point ([`km`](super::km)). `h` is convex and
//! positively homogeneous; since `S(t)` is convex and closed
//! ([`membership`](super::membership)), it is the intersection of the
//! half-spaces `d·q ≤ h(d)`.

use crate::error::{Error, Place};
use crate::fuzzy::Axis;
use crate::limits::{within_magnitude, MAGNITUDE_RANGE};

use super::km::{max_switch, SwitchPoint};
use super::terms::{IntervalTerms, Vertex};

impl<const D: usize> IntervalTerms<D> {
    /// The support function `h(d) = max over S(t) of d·q` in the direction
    /// `direction` (module docs; docs/method.md §15). `h(−e_k)` and `h(e_k)`
    /// are the envelope's ends of coordinate `k`, negated for the first.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::OutOfRange`] (outside
    /// `[-1e150, 1e150]`) for a component of `direction`, named by its axis.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::interval_weights::IntervalTerms;
    /// // One term: the set is its box [0, 1] × [0, 2]; h(1, 1) = 1 + 2.
    /// let terms = IntervalTerms::try_new(&[1.0], &[[1.0, 4.0]], &[[[0.0, 1.0], [0.0, 2.0]]])?;
    /// assert_eq!(terms.support([1.0, 1.0])?, 3.0);
    /// assert_eq!(terms.support([-1.0, 0.0])?, 0.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn support(&self, direction: [f64; D]) -> Result<f64, Error> {
        check_direction(&direction)?;
        Ok(self.support_unchecked(&direction).0)
    }

    /// A vertex choice whose point attains [`support`](Self::support) in
    /// `direction` (its corners maximise `d·Pᵢ`, at `P̲` where `d_k = 0`;
    /// its weights are the Karnik–Mendel switch point).
    ///
    /// # Errors
    /// As [`support`](Self::support).
    pub fn support_vertex(&self, direction: [f64; D]) -> Result<Vertex<D>, Error> {
        check_direction(&direction)?;
        let (_, switch) = self.support_unchecked(&direction);
        Ok(self.vertex(&switch.at_upper, |_, k| direction[k] > 0.0))
    }

    /// `h(d)` and its switch point, for a finite `d` within the range of
    /// coordinates: computed for `d` divided by its largest component and
    /// scaled back (`h` is positively homogeneous).
    pub(crate) fn support_unchecked(&self, d: &[f64; D]) -> (f64, SwitchPoint) {
        let size = d.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let unit: [f64; D] = if size > 0.0 {
            std::array::from_fn(|k| d[k] / size)
        } else {
            [0.0; D]
        };
        let values: Vec<f64> = self
            .points()
            .iter()
            .map(|p| {
                (0..D)
                    .map(|k| {
                        let [lo, hi] = p[k];
                        (unit[k] * lo).max(unit[k] * hi)
                    })
                    .sum()
            })
            .collect();
        let s = max_switch(&values, self.lower(), self.upper());
        (s.value * size, s)
    }
}

/// `Ok` if every component of a direction is finite and within the range of
/// coordinates.
pub(crate) fn check_direction<const D: usize>(direction: &[f64; D]) -> Result<(), Error> {
    for (k, &value) in direction.iter().enumerate() {
        let place = Place {
            axis: Axis::from_index(k),
            ..Place::NONE
        };
        if !value.is_finite() {
            return Err(Error::NotFinite {
                place,
                what: "direction",
                value,
            });
        }
        if !within_magnitude(value) {
            return Err(Error::OutOfRange {
                place,
                what: "direction",
                value,
                range: MAGNITUDE_RANGE,
            });
        }
    }
    Ok(())
}
