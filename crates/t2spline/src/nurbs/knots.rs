//! Knot vectors and parameter domains (docs/method.md §6).

use crate::error::Error;
use crate::limits::within_magnitude;

/// The parameter interval `[start, end]` of a curve, both ends included.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Domain {
    /// `U[p]`.
    pub start: f64,
    /// `U[n]`.
    pub end: f64,
}

impl Domain {
    /// The point at fraction `s` of the way from `start` to `end`; `s = 1` gives
    /// `end` exactly.
    #[must_use]
    pub fn lerp(&self, s: f64) -> f64 {
        if s >= 1.0 {
            self.end
        } else {
            self.start + (self.end - self.start) * s
        }
    }

    /// Whether `t` lies in the domain (NaN does not).
    #[must_use]
    pub fn contains(&self, t: f64) -> bool {
        self.start <= t && t <= self.end
    }

    /// `Ok` if `t` lies in the domain.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    pub fn check(&self, t: f64) -> Result<(), Error> {
        if self.contains(t) {
            Ok(())
        } else {
            Err(Error::OutOfDomain {
                t,
                start: self.start,
                end: self.end,
            })
        }
    }

    /// `samples` uniform parameters (docs/jobs.md):
    /// ```text
    /// tᵢ = a + (b − a)·i/(samples − 1),  i = 0 … samples − 1,  the last exactly b
    /// ```
    /// `samples = 1` gives `[a]`; `0` gives nothing.
    ///
    /// # Errors
    /// [`Error::Memory`](crate::Error::Memory) if `samples` values cannot be
    /// held in memory (the allocation is tried, not assumed).
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Domain;
    /// let d = Domain { start: 0.0, end: 0.3 };
    /// assert_eq!(d.uniform(4)?.last(), Some(&0.3));
    /// assert!(d.uniform(usize::MAX).is_err());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn uniform(&self, samples: usize) -> Result<Vec<f64>, crate::error::Error> {
        let mut out = Vec::new();
        out.try_reserve_exact(samples)
            .map_err(|_| crate::error::Error::Memory { values: samples })?;
        out.extend(self.uniform_iter(samples));
        Ok(out)
    }

    /// [`Domain::uniform`] for the small counts the crate itself asks for
    /// (scans of a span: a few hundred at most), which always fit.
    pub(crate) fn uniform_small(&self, samples: usize) -> Vec<f64> {
        self.uniform_iter(samples).collect()
    }

    /// The values of [`Domain::uniform`], one by one.
    fn uniform_iter(&self, samples: usize) -> impl Iterator<Item = f64> + '_ {
        let last = samples.saturating_sub(1).max(1) as f64;
        (0..samples).map(move |i| self.lerp(i as f64 / last))
    }
}

/// A validated knot vector `U` for a curve of degree `p` with `n` control points.
///
/// Invariants (docs/method.md §6): `n + p + 1` finite, non-decreasing values of magnitude
/// at most [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE); no value repeated more than `k = p + 1` times; a non-empty domain `U[p] < U[n]`.
/// An interior knot of multiplicity `k` is allowed: the curve may jump there,
/// and its value at the knot is taken from the right.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct KnotVector {
    values: Vec<f64>,
    degree: usize,
}

impl KnotVector {
    /// Validates `values` as the knots of a curve of degree `degree` with `count`
    /// control points.
    ///
    /// # Errors
    /// The first of [`KnotVector::problems`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::KnotVector;
    /// let u = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], 2, 4)?;
    /// assert_eq!(u.domain().end, 1.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(values: Vec<f64>, degree: usize, count: usize) -> Result<Self, Error> {
        match Self::problems(&values, degree, count).into_iter().next() {
            Some(e) => Err(e),
            None => Ok(KnotVector { values, degree }),
        }
    }

    /// Every rule of docs/method.md §6 that `values` breaks as the knots of a curve of
    /// degree `degree` with `count` control points; empty if none.
    ///
    /// A wrong count or too few control points is reported alone, since the other
    /// rules depend on it; the domain is checked only when the values are
    /// otherwise valid.
    #[must_use]
    pub fn problems(values: &[f64], degree: usize, count: usize) -> Vec<Error> {
        // A degree of usize::MAX saturates to an order no list can reach.
        let order = degree.saturating_add(1);
        if count < order {
            return vec![Error::TooFewControlPoints { order, count }];
        }
        if values.len() != count + order {
            return vec![Error::KnotCount {
                expected: count + order,
                found: values.len(),
            }];
        }
        let mut out: Vec<Error> = values
            .iter()
            .enumerate()
            .filter_map(|(index, &value)| {
                if !value.is_finite() {
                    Some(Error::KnotNotFinite { index, value })
                } else if !within_magnitude(value) {
                    Some(Error::KnotOutOfRange { index, value })
                } else {
                    None
                }
            })
            .collect();
        for (i, w) in values.windows(2).enumerate() {
            if w[1] < w[0] {
                out.push(Error::KnotDecreasing {
                    index: i + 1,
                    previous: w[0],
                    value: w[1],
                });
            }
        }
        let mut first = 0;
        while first < values.len() {
            let run = values[first..]
                .iter()
                .take_while(|&&v| v == values[first])
                .count();
            if run > order {
                out.push(Error::KnotMultiplicity {
                    first,
                    value: values[first],
                    multiplicity: run,
                    order,
                });
            }
            first += run.max(1);
        }
        if out.is_empty() && values[degree] >= values[count] {
            out.push(Error::EmptyDomain {
                degree,
                count,
                start: values[degree],
                end: values[count],
            });
        }
        out
    }

    /// A knot vector that an exact algorithm derived from a valid one.
    pub(crate) fn from_parts_unchecked(values: Vec<f64>, degree: usize) -> Self {
        debug_assert!(
            values.len() > degree + 1
                && Self::problems(&values, degree, values.len() - degree - 1).is_empty(),
            "{values:?} (degree {degree})"
        );
        KnotVector { values, degree }
    }

    /// Whether the curve is clamped: its first `k` and its last `k` knots are
    /// equal, so that it starts and ends at its first and last control points.
    #[must_use]
    pub fn is_clamped(&self) -> bool {
        let k = self.degree + 1;
        let u = &self.values;
        u[..k].iter().all(|&v| v == u[0]) && u[u.len() - k..].iter().all(|&v| v == u[u.len() - 1])
    }

    /// The clamped uniform knot vector (docs/method.md §6 default): `k` zeros, `n − k`
    /// uniform interior knots `i/(n − k + 1)`, `k` ones.
    ///
    /// # Errors
    /// [`Error::TooFewControlPoints`] if `count < degree + 1`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::KnotVector;
    /// let u = KnotVector::clamped_uniform(2, 4)?;
    /// assert_eq!(u.as_slice(), &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn clamped_uniform(degree: usize, count: usize) -> Result<Self, Error> {
        let order = degree.saturating_add(1);
        if count < order {
            return Err(Error::TooFewControlPoints { order, count });
        }
        let interior = count - order;
        let mut values = vec![0.0; order];
        values.extend((1..=interior).map(|i| i as f64 / (interior + 1) as f64));
        values.extend(std::iter::repeat_n(1.0, order));
        Ok(KnotVector { values, degree })
    }

    /// The knots.
    #[must_use]
    pub fn as_slice(&self) -> &[f64] {
        &self.values
    }

    /// The degree `p`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The number of control points `n = len − p − 1`.
    #[must_use]
    pub fn count(&self) -> usize {
        self.values.len() - self.degree - 1
    }

    /// The domain `[U[p], U[n]]`.
    #[must_use]
    pub fn domain(&self) -> Domain {
        Domain {
            start: self.values[self.degree],
            end: self.values[self.count()],
        }
    }

    /// The span index `i` with `U[i] ≤ t < U[i+1]`, `p ≤ i < n` (The NURBS Book,
    /// A2.1). At the right end of the domain the last non-empty span is used;
    /// at an interior knot the span to its right. Parameters outside the domain
    /// are clamped to it; NaN gives the first span.
    #[must_use]
    pub fn find_span(&self, t: f64) -> usize {
        let (p, n) = (self.degree, self.count());
        let u = &self.values;
        if t >= u[n] {
            // The last non-empty span; it exists because U[p] < U[n].
            return (p..n).rev().find(|&i| u[i] < u[n]).unwrap_or(p);
        }
        // First index with U[j] > t, minus one, kept inside [p, n − 1].
        let j = u.partition_point(|&v| v <= t);
        j.saturating_sub(1).clamp(p, n - 1)
    }

    /// The non-empty spans `(i, [U[i], U[i+1]])`, `p ≤ i < n`, in order.
    pub fn spans(&self) -> impl Iterator<Item = (usize, [f64; 2])> + '_ {
        let u = &self.values;
        (self.degree..self.count())
            .filter(move |&i| u[i] < u[i + 1])
            .map(move |i| (i, [u[i], u[i + 1]]))
    }

    /// Multiplicity of the knot value `u` in the vector.
    #[must_use]
    pub fn multiplicity(&self, u: f64) -> usize {
        self.values.iter().filter(|&&v| v == u).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn problems_lists_every_fault() {
        let p = KnotVector::problems(&[0.0, 0.0, 0.5, 0.2, f64::NAN, 1.0, 1.0], 2, 4);
        assert!(matches!(p[0], Error::KnotNotFinite { index: 4, .. }));
        assert!(matches!(p[1], Error::KnotDecreasing { index: 3, .. }));
        assert_eq!(p.len(), 2);
    }

    #[test]
    fn find_span_walks_full_multiplicity_knots_from_the_right() {
        // Degree 1, interior knot 0.5 of multiplicity 2 = k: spans [0,.5) and [.5,1].
        let u = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).unwrap();
        assert_eq!(u.find_span(0.0), 1);
        assert_eq!(u.find_span(0.49), 1);
        assert_eq!(u.find_span(0.5), 3);
        assert_eq!(u.find_span(1.0), 3);
        assert_eq!(u.spans().count(), 2);
    }

    #[test]
    fn find_span_at_the_right_end_uses_last_non_empty_span() {
        let u = KnotVector::clamped_uniform(3, 6).unwrap();
        let n = u.count();
        assert_eq!(u.find_span(1.0), n - 1);
        assert_eq!(u.find_span(0.0), 3);
    }

    #[test]
    fn unclamped_domain() {
        let u = KnotVector::try_new(vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], 2, 4).unwrap();
        assert_eq!(
            u.domain(),
            Domain {
                start: 2.0,
                end: 4.0
            }
        );
        assert_eq!(u.find_span(2.0), 2);
        assert_eq!(u.find_span(4.0), 3);
    }

    #[test]
    fn uniform_samples_end_exactly() {
        let d = Domain {
            start: 0.1,
            end: 0.7,
        };
        let t = d.uniform(7).unwrap();
        assert_eq!(t[0], 0.1);
        assert_eq!(t[6], 0.7);
        assert_eq!(d.uniform(1).unwrap(), vec![0.1]);
        assert_eq!(d.uniform_small(7), t);
    }

    #[test]
    fn counts_beyond_memory_are_errors() {
        let d = Domain {
            start: 0.0,
            end: 1.0,
        };
        for n in [usize::MAX, usize::MAX / 8, 1 << 60] {
            assert_eq!(d.uniform(n), Err(crate::error::Error::Memory { values: n }));
        }
    }
}
