//! Centroids of interval type-2 sets given by samples `(x, lmf, umf)`: the
//! discrete algorithms of the type-2 literature, for sets of any shape.
//!
//! The centroid of a sampled interval type-2 set is the interval of the
//! centroids `Σ xᵢθᵢ / Σ θᵢ` of its embedded sets, `lmfᵢ ≤ θᵢ ≤ umfᵢ`. Its left
//! end takes `θ = umf` on the first `m` samples and `θ = lmf` on the rest for
//! the best switch point `m` (the right end `lmf` first, then `umf`):
//! ```text
//! y_l(m) = (Σ_{i<m} xᵢ·umfᵢ + Σ_{i≥m} xᵢ·lmfᵢ) / (Σ_{i<m} umfᵢ + Σ_{i≥m} lmfᵢ),  c_l = min_m y_l(m)
//! y_r(m) = (Σ_{i<m} xᵢ·lmfᵢ + Σ_{i≥m} xᵢ·umfᵢ) / (Σ_{i<m} lmfᵢ + Σ_{i≥m} umfᵢ),  c_r = max_m y_r(m)
//! ```
//! The algorithms differ in how they find `m`:
//!
//! | method | search | source |
//! |---|---|---|
//! | [`SampledSet::km`] | from the Nie–Tan point, `m` ← the samples left of `y(m)`, until `m` repeats | Karnik and Mendel 2001 |
//! | [`SampledSet::ekm`] | the same from `m = N/2.4` (left) and `N/1.7` (right), sums updated between switch points | Wu and Mendel 2009 |
//! | [`SampledSet::eiasc`] | moves `m` one sample at a time from the end, until `y(m)` passes the next sample | Wu and Nie 2011 |
//!
//! All three give the exact discrete centroid (the tests compare them with
//! the minimum and maximum over every switch point). [`SampledSet::nie_tan`]
//! is the centroid of `(lmf + umf)/2` (Nie and Tan 2008). On samples of a
//! number's membership functions, all converge to the exact values of
//! [`Nt2Number::centroid`](crate::Nt2Number::centroid) as `N` grows, with an
//! error of order `1/N²` when the functions have no vertical edges.
//!
//! Sums are formed relative to the middle of the support, so that a set far
//! from 0 keeps its digits.
//!
//! [`SampledSet`] borrows the user's `x, lmf, umf` without a copy once they are
//! checked; EKM recomputes its final value from scratch once, so its
//! incremental updates leave no rounding behind.

use crate::error::Error;
use crate::fuzzy::{Membership, Nt2Number};
use crate::limits::{within_magnitude, MAX_WEIGHT};

/// Sampled membership functions: `(x, lmf, umf)`.
pub type Samples = (Vec<f64>, Vec<f64>, Vec<f64>);

/// Samples `(x, lmf, umf)` of a number's LMF and UMF (docs/method.md §1) at `count`
/// uniform points of its support `[upper.left, upper.right]`, both ends
/// included (`count` below 2 is taken as 2): the input of the discrete
/// algorithms for a number, e.g. to compare them with the exact
/// [`Nt2Number::centroid`].
///
/// # Errors
/// [`Error::Memory`] if `count` samples cannot be held in memory (the
/// allocation is tried, not assumed).
///
/// # Examples
/// ```
/// # use t2spline::Nt2Number;
/// # use t2spline::reduction::discrete::{sample, SampledSet};
/// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
/// let (xs, lmf, umf) = sample(&x, 1001)?;
/// let discrete = SampledSet::try_new(&xs, &lmf, &umf)?.ekm();
/// assert!((discrete.left() - x.centroid().left()).abs() < 1e-6);
/// assert!(sample(&x, usize::MAX).is_err());
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn sample(x: &Nt2Number, count: usize) -> Result<Samples, Error> {
    let count = count.max(2);
    let (a, b) = (x.upper().left(), x.upper().right());
    let last = (count - 1) as f64;
    let mut out: [Vec<f64>; 3] = Default::default();
    for v in &mut out {
        v.try_reserve_exact(count)
            .map_err(|_| Error::Memory { values: count })?;
    }
    let [mut xs, mut lmf, mut umf] = out;
    // a + (b − a)·i/last, with the last point exactly b.
    xs.extend((0..count).map(|i| {
        if i + 1 == count {
            b
        } else {
            a + (b - a) * (i as f64 / last)
        }
    }));
    lmf.extend(xs.iter().map(|&v| x.membership(Membership::Lower, v)));
    umf.extend(xs.iter().map(|&v| x.membership(Membership::Upper, v)));
    Ok((xs, lmf, umf))
}

/// A validated interval type-2 set given by samples: `x` ascending,
/// `0 ≤ lmf ≤ umf` at every sample, some `umf > 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledSet<'a> {
    x: &'a [f64],
    lower: &'a [f64],
    upper: &'a [f64],
    /// First and last sample with `umf > 0`.
    first: usize,
    last: usize,
    /// The origin of the sums: the middle of `[x[first], x[last]]`.
    origin: f64,
}

/// The centroid `[left, right]` of a [`SampledSet`] and the work it took.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledCentroid {
    left: f64,
    right: f64,
    iterations: Iterations,
}

/// How many switch points an algorithm tried for each end of the centroid
/// (each one a centroid `y(m)` computed, from scratch or by an update).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Iterations {
    /// For the left end.
    pub left: usize,
    /// For the right end.
    pub right: usize,
}

impl SampledCentroid {
    /// The left end `c_l`.
    #[must_use]
    pub fn left(&self) -> f64 {
        self.left
    }

    /// The right end `c_r`.
    #[must_use]
    pub fn right(&self) -> f64 {
        self.right
    }

    /// The centre `(c_l + c_r)/2`, the usual defuzzified value.
    #[must_use]
    pub fn defuzzified(&self) -> f64 {
        (self.left + (self.right - self.left) / 2.0).clamp(self.left, self.right)
    }

    /// The switch points tried.
    #[must_use]
    pub fn iterations(&self) -> Iterations {
        self.iterations
    }
}

/// Which end of the centroid: which function is used before the switch point.
#[derive(Clone, Copy, Debug, PartialEq)]
enum End {
    /// `umf` on the first `m` samples.
    Left,
    /// `lmf` on the first `m` samples.
    Right,
}

impl<'a> SampledSet<'a> {
    /// Validates the samples.
    ///
    /// # Errors
    /// [`Error::Length`] if `lmf` or `umf` is not as long as `x`;
    /// [`Error::Sample`] for the first sample that is not finite, has `|x|`
    /// above [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE), an `x` less than the one
    /// before it, `lmf < 0`, `lmf > umf` or `umf` above
    /// [`MAX_WEIGHT`]; [`Error::ZeroUpperMembership`] if no
    /// `umf` is greater than 0.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let set = SampledSet::try_new(&[1.0, 2.0, 3.0], &[0.2, 0.5, 0.2], &[0.6, 1.0, 0.6])?;
    /// let c = set.km();
    /// assert!(c.left() < 2.0 && (c.defuzzified() - 2.0).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(x: &'a [f64], lmf: &'a [f64], umf: &'a [f64]) -> Result<Self, Error> {
        for (what, found) in [("lmf", lmf.len()), ("umf", umf.len())] {
            if found != x.len() {
                return Err(Error::Length {
                    what,
                    expected: x.len(),
                    found,
                });
            }
        }
        let fail = |what, index, value, rule| {
            Err(Error::Sample {
                what,
                index,
                value,
                rule,
            })
        };
        for i in 0..x.len() {
            for (what, value) in [("x", x[i]), ("lmf", lmf[i]), ("umf", umf[i])] {
                if !value.is_finite() {
                    return fail(what, i, value, "is not a finite number");
                }
            }
            if !within_magnitude(x[i]) {
                return fail("x", i, x[i], "is outside [-1e150, 1e150]");
            }
            if i > 0 && x[i] < x[i - 1] {
                return fail(
                    "x",
                    i,
                    x[i],
                    "is less than the x before it; x must not decrease",
                );
            }
            if lmf[i] < 0.0 {
                return fail(
                    "lmf",
                    i,
                    lmf[i],
                    "is negative; a sampled set needs 0 <= lmf <= umf",
                );
            }
            if lmf[i] > umf[i] {
                let rule =
                    "is greater than the umf at that index; a sampled set needs 0 <= lmf <= umf";
                return fail("lmf", i, lmf[i], rule);
            }
            if umf[i] > MAX_WEIGHT {
                return fail("umf", i, umf[i], "is above 1e150");
            }
        }
        let first = umf.iter().position(|&u| u > 0.0);
        let last = umf.iter().rposition(|&u| u > 0.0);
        let (Some(first), Some(last)) = (first, last) else {
            return Err(Error::ZeroUpperMembership);
        };
        let origin = x[first] + (x[last] - x[first]) / 2.0;
        Ok(SampledSet {
            x,
            lower: lmf,
            upper: umf,
            first,
            last,
            origin,
        })
    }
}

impl SampledSet<'_> {
    /// `xᵢ` relative to the origin of the sums.
    fn dx(&self, i: usize) -> f64 {
        self.x[i] - self.origin
    }

    /// The weight of sample `i` for switch point `m` at `end`.
    fn weight(&self, end: End, m: usize, i: usize) -> f64 {
        let before = i < m;
        if before == (end == End::Left) {
            self.upper[i]
        } else {
            self.lower[i]
        }
    }

    /// `y(m)` relative to the origin, from scratch: `(Σ dxᵢ·θᵢ, Σ θᵢ)`.
    fn sums(&self, end: End, m: usize) -> (f64, f64) {
        (0..self.x.len()).fold((0.0, 0.0), |(a, b), i| {
            let w = self.weight(end, m, i);
            (a + self.dx(i) * w, b + w)
        })
    }

    /// The switch point for a centroid `y` (relative): the samples at or left
    /// of `y` take `umf` (left end) or `lmf` (right end). Kept where the sum of
    /// weights is positive: the left end needs `umf[first]` before the switch,
    /// the right end `umf[last]` after it (the exact centroids lie between
    /// `x[first]` and `x[last]`; rounding could put `y` an ulp outside).
    fn switch(&self, end: End, y: f64) -> usize {
        let m = self.x.partition_point(|&xi| xi - self.origin <= y);
        match end {
            End::Left => m.max(self.first + 1),
            End::Right => m.min(self.last),
        }
    }

    /// The Karnik–Mendel algorithm (Karnik and Mendel 2001, "Centroid of a
    /// type-2 fuzzy set", Information Sciences 132:195–220; as stated in Wu
    /// and Mendel 2009, Table I):
    /// ```text
    /// y ← Σ xᵢ(lmfᵢ + umfᵢ) / Σ (lmfᵢ + umfᵢ)
    /// repeat: m ← #{i : xᵢ ≤ y};  y' ← y(m);  stop when m no longer changes
    /// ```
    /// Each switch point costs one pass over the samples; the number of
    /// passes is [`Iterations`]. KM converges monotonically, in at most `N`
    /// passes (Mendel and Liu 2007) and usually in two to six.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::reduction::discrete::SampledSet;
    /// // The footprint is symmetric about 2: the centroid is too.
    /// let set = SampledSet::try_new(&[1.0, 2.0, 3.0], &[0.2, 0.5, 0.2], &[0.6, 1.0, 0.6])?;
    /// let c = set.km();
    /// // c_l: umf on the first m samples, lmf on the rest:
    /// // m = 0: 1.8/0.9 = 2, m = 1: 2.2/1.3 = 22/13, m = 2: 3.2/1.8 = 16/9, m = 3: 4.4/2.2 = 2.
    /// assert!((c.left() - 22.0 / 13.0).abs() < 1e-15 && (c.right() - 30.0 / 13.0).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn km(&self) -> SampledCentroid {
        let start = self.nie_tan() - self.origin;
        let (left, l) = self.km_end(End::Left, start);
        let (right, r) = self.km_end(End::Right, start);
        self.result(left, right, l, r)
    }

    fn km_end(&self, end: End, start: f64) -> (f64, usize) {
        let mut m = self.switch(end, start);
        let mut passes = 0;
        loop {
            let (a, b) = self.sums(end, m);
            let y = a / b;
            passes += 1;
            let next = self.switch(end, y);
            // In exact arithmetic m moves monotonically and stops within N
            // passes; the bound only guards against rounding cycling.
            if next == m || passes > self.x.len() {
                return (y, passes);
            }
            m = next;
        }
    }

    /// The enhanced Karnik–Mendel algorithm (Wu and Mendel 2009, "Enhanced
    /// Karnik–Mendel algorithms", IEEE TFS 17(4):923–934, Table II): KM
    /// started at `m = round(N/2.4)` for the left end and `round(N/1.7)` for
    /// the right (where the switch points of typical sets lie), and between
    /// switch points `m → m'` the sums are updated by the samples that change
    /// sides only:
    /// ```text
    /// a' = a ± Σ_{between} xᵢ·(umfᵢ − lmfᵢ),   b' = b ± Σ_{between} (umfᵢ − lmfᵢ)
    /// ```
    /// The value at the final switch point is recomputed from scratch once,
    /// so that rounding accumulated by the updates does not remain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let x: Vec<f64> = (0..=100).map(|i| f64::from(i) / 10.0).collect();
    /// let umf: Vec<f64> = x.iter().map(|&v| (1.0 - (v - 5.0).abs() / 5.0).max(0.0)).collect();
    /// let lmf: Vec<f64> = umf.iter().map(|&u| 0.5 * u).collect();
    /// let set = SampledSet::try_new(&x, &lmf, &umf)?;
    /// let (e, k) = (set.ekm(), set.km());
    /// assert!((e.left() - k.left()).abs() < 1e-13 && (e.right() - k.right()).abs() < 1e-13);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn ekm(&self) -> SampledCentroid {
        let n = self.x.len() as f64;
        let (left, l) = self.ekm_end(End::Left, (n / 2.4).round() as usize);
        let (right, r) = self.ekm_end(End::Right, (n / 1.7).round() as usize);
        self.result(left, right, l, r)
    }

    fn ekm_end(&self, end: End, start: usize) -> (f64, usize) {
        let mut m = match end {
            End::Left => start.clamp(self.first + 1, self.x.len()),
            End::Right => start.min(self.last),
        };
        let (mut a, mut b) = self.sums(end, m);
        let mut passes = 0;
        loop {
            passes += 1;
            let next = self.switch(end, a / b);
            if next == m || passes > self.x.len() {
                let (a, b) = self.sums(end, m);
                return (a / b, passes);
            }
            // Samples between the two switch points change from lmf to umf
            // (+) or back (−); which way depends on the end and the direction.
            let (lo, hi) = (m.min(next), m.max(next));
            let gains_upper = (next > m) == (end == End::Left);
            let sign = if gains_upper { 1.0 } else { -1.0 };
            for i in lo..hi {
                let d = self.upper[i] - self.lower[i];
                a += sign * self.dx(i) * d;
                b += sign * d;
            }
            m = next;
            if b <= 0.0 {
                // Cancellation ate the denominator: start again from scratch
                // (positive there, see `switch`).
                (a, b) = self.sums(end, m);
            }
        }
    }

    /// The enhanced iterative algorithm with stop condition (Wu and Nie 2011,
    /// "Comparison and practical implementation of type-reduction algorithms
    /// for type-2 fuzzy sets and systems", Proc. FUZZ-IEEE 2011, 2131–2138):
    /// start with every sample on `lmf` and move the switch point one sample
    /// at a time from the outside in, updating the sums, until the centroid
    /// passes the next sample:
    /// ```text
    /// left:  m = 1, 2, …:    a += xₘ·(umfₘ − lmfₘ), b += umfₘ − lmfₘ, stop when a/b ≤ x_{m+1}
    /// right: m = N, N−1, …:  the same,                                stop when a/b ≥ x_{m−1}
    /// ```
    /// Fast when the switch points lie near the ends, as they do for the
    /// small N of rule-based systems; [`Iterations`] counts the steps.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let set = SampledSet::try_new(&[1.0, 2.0, 3.0], &[0.2, 0.5, 0.2], &[0.6, 1.0, 0.6])?;
    /// assert_eq!(set.eiasc().left(), set.km().left());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn eiasc(&self) -> SampledCentroid {
        let n = self.x.len();
        let (a0, b0) = (0..n).fold((0.0, 0.0), |(a, b), i| {
            (a + self.dx(i) * self.lower[i], b + self.lower[i])
        });
        // Left: samples 0..m on umf.
        let (mut a, mut b, mut left, mut l) = (a0, b0, 0.0, 0);
        for m in 1..=n {
            let d = self.upper[m - 1] - self.lower[m - 1];
            a += self.dx(m - 1) * d;
            b += d;
            l += 1;
            if b > 0.0 {
                left = a / b;
                if m == n || left <= self.dx(m) {
                    break;
                }
            }
        }
        // Right: samples m..n on umf.
        let (mut a, mut b, mut right, mut r) = (a0, b0, 0.0, 0);
        for m in (0..n).rev() {
            let d = self.upper[m] - self.lower[m];
            a += self.dx(m) * d;
            b += d;
            r += 1;
            if b > 0.0 {
                right = a / b;
                if m == 0 || right >= self.dx(m - 1) {
                    break;
                }
            }
        }
        self.result(left, right, l, r)
    }

    /// The Nie–Tan value: the centroid of `(lmf + umf)/2` (Nie and Tan 2008,
    /// "Towards an efficient type-reduction method for interval type-2 fuzzy
    /// logic systems", Proc. FUZZ-IEEE 2008, 1425–1432):
    /// ```text
    /// Σ xᵢ·(lmfᵢ + umfᵢ) / Σ (lmfᵢ + umfᵢ)
    /// ```
    /// It lies between the ends of the centroid.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::reduction::discrete::SampledSet;
    /// let set = SampledSet::try_new(&[0.0, 1.0], &[0.0, 0.5], &[1.0, 1.0])?;
    /// assert!((set.nie_tan() - 1.5 / 2.5).abs() < 1e-16);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn nie_tan(&self) -> f64 {
        let (a, b) = (0..self.x.len()).fold((0.0, 0.0), |(a, b), i| {
            let w = self.lower[i] + self.upper[i];
            (a + self.dx(i) * w, b + w)
        });
        self.global(a / b)
    }

    /// A relative centroid as a value of `x`, kept in `[x[first], x[last]]`
    /// where the exact one lies.
    fn global(&self, y: f64) -> f64 {
        (self.origin + y).clamp(self.x[self.first], self.x[self.last])
    }

    fn result(&self, left: f64, right: f64, l: usize, r: usize) -> SampledCentroid {
        let (left, right) = (self.global(left), self.global(right));
        SampledCentroid {
            // c_l ≤ c_r exactly; a very thin footprint could swap them by an ulp.
            left: left.min(right),
            right: right.max(left),
            iterations: Iterations { left: l, right: r },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_samples_are_named() {
        let e = SampledSet::try_new(&[0.0, 1.0], &[0.0], &[1.0, 1.0]).unwrap_err();
        assert_eq!(
            e,
            Error::Length {
                what: "lmf",
                expected: 2,
                found: 1
            }
        );
        let e = SampledSet::try_new(&[0.0, 1.0], &[0.0, -0.1], &[1.0, 1.0]).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Sample {
                    what: "lmf",
                    index: 1,
                    ..
                }
            ),
            "{e}"
        );
        let e = SampledSet::try_new(&[0.0, f64::NAN], &[0.0, 0.0], &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.to_string(), "x[1] = NaN is not a finite number");
        let e = SampledSet::try_new(&[0.0, 2e150], &[0.0, 0.0], &[1.0, 1.0]).unwrap_err();
        assert!(
            matches!(
                e,
                Error::Sample {
                    what: "x",
                    index: 1,
                    ..
                }
            ),
            "{e}"
        );
        let e = SampledSet::try_new(&[], &[], &[]).unwrap_err();
        assert_eq!(e, Error::ZeroUpperMembership);
    }

    #[test]
    fn one_sample_is_its_own_centroid() {
        let set = SampledSet::try_new(&[3.5], &[0.0], &[0.2]).unwrap();
        for c in [set.km(), set.ekm(), set.eiasc()] {
            assert_eq!((c.left(), c.right()), (3.5, 3.5));
        }
        assert_eq!(set.nie_tan(), 3.5);
    }

    #[test]
    fn mass_at_the_ends_only() {
        // umf is 0 except at the first and last samples; lmf is 0 throughout.
        // The embedded sets put any mass at 0 and at 10: c_l = 0, c_r = 10.
        let x: Vec<f64> = (0..=10).map(f64::from).collect();
        let mut umf = vec![0.0; 11];
        umf[0] = 1.0;
        umf[10] = 1.0;
        let lmf = vec![0.0; 11];
        let set = SampledSet::try_new(&x, &lmf, &umf).unwrap();
        for c in [set.km(), set.ekm(), set.eiasc()] {
            assert_eq!((c.left(), c.right()), (0.0, 10.0), "{c:?}");
        }
    }
}
