//! Degree elevation (The NURBS Book, §5.5, A5.9).
//!
//! A5.9 assumes a clamped knot vector, so an unclamped curve is first cut to
//! its domain (`segment`) and the result is clamped with the same domain. Its
//! knot removal is an extrapolation and loses accuracy as knots come close:
//! 10⁻¹² of the curve's size for knots 10⁻⁴ of the domain apart, 1.8·10⁻¹¹
//! seen for 4.7·10⁻⁵ at degree 5. For a fuzzy curve the same rounding can swap
//! two nearly equal layer values, which `pipeline/fuzzy_ops.rs` clamps back
//! outward from the crisp value; the property tests bound that repair by the
//! accuracy the knot removal can keep for the curve's knots and weights
//! (`strategies::elevation_tolerance`).

use crate::error::{Error, Place};
use crate::nurbs::derivatives::binomial;
use crate::nurbs::homogeneous::Row;
use crate::nurbs::split::segment;
use crate::nurbs::{KnotVector, NurbsCurve};

/// The highest degree that elevation may reach. The Bézier elevation
/// coefficients `C(p, j)·C(t, i − j)/C(p + t, i)` span ever more orders of
/// magnitude as the degree grows; no practical curve needs more, and the bound
/// keeps a nonsense request from asking for unbounded memory.
pub const MAX_ELEVATED_DEGREE: usize = 64;

/// Checks that degree `p` raised `t` times stays within [`MAX_ELEVATED_DEGREE`],
/// and that a curve of degree 0 (piecewise constant, jumping at every interior
/// knot) is not raised: A5.9 needs segments of degree at least 1 and, given
/// degree 0, builds an invalid knot vector (found by fuzzing).
pub(crate) fn check_elevation(p: usize, t: usize) -> Result<(), Error> {
    if p == 0 && t > 0 {
        return Err(Error::OutOfRange {
            place: Place::NONE,
            what: "degree of the curve to elevate",
            value: 0.0,
            range: "[1, 64]",
        });
    }
    let degree = p.saturating_add(t);
    if degree > MAX_ELEVATED_DEGREE {
        return Err(Error::OutOfRange {
            place: Place::NONE,
            what: "degree after elevation",
            value: degree as f64,
            range: "[1, 64]",
        });
    }
    Ok(())
}

/// `Σ cⱼ·rowⱼ` over the pairs given.
fn combine<'a>(width: usize, terms: impl Iterator<Item = (f64, &'a Row)>) -> Row {
    let mut out = vec![0.0; width];
    for (c, row) in terms {
        for (o, x) in out.iter_mut().zip(row) {
            *o += c * x;
        }
    }
    out
}

/// Raises the degree of a curve by `t` (A5.9, DegreeElevateCurve), on
/// homogeneous control points. An unclamped curve is clamped first (see
/// [`NurbsCurve::clamped`]); the result is clamped, every knot's multiplicity
/// grows by `t`.
///
/// A5.9 walks the knot vector once: it extracts each Bézier segment by knot
/// insertion, raises its degree with the coefficients
/// `C(p, j)·C(t, i − j) / C(p + t, i)` (Eq. 5.36) and removes the knots it
/// inserted. One change to the book's listing: after a knot of full
/// multiplicity `p + 1` (where the curve may jump) the next segment shares no
/// control point with the previous one, so its first point is kept too.
// The indices follow the book's listing, so that it can be checked line by line.
#[allow(clippy::needless_range_loop, clippy::explicit_counter_loop)]
pub(crate) fn elevate(knots: &KnotVector, rows: &[Row], t: usize) -> (KnotVector, Vec<Row>) {
    if t == 0 {
        return (knots.clone(), rows.to_vec());
    }
    let (knots, rows) = if knots.is_clamped() {
        (knots.clone(), rows.to_vec())
    } else {
        let d = knots.domain();
        // `segment` fails only for a parameter outside the domain or an
        // insertion past the order; the domain's ends are inside it and are
        // inserted up to multiplicity p only.
        #[allow(clippy::expect_used)]
        segment(knots, rows, d.start, d.end).expect("the domain ends lie in the domain")
    };
    let width = rows[0].len();
    let p = knots.degree();
    let u = knots.as_slice();
    let n = rows.len() - 1;
    let m = n + p + 1;
    let ph = p + t;
    let ph2 = ph / 2;
    // Bézier degree elevation coefficients.
    let mut bezalfs = vec![vec![0.0; p + 1]; ph + 1];
    bezalfs[0][0] = 1.0;
    bezalfs[ph][p] = 1.0;
    for i in 1..=ph2 {
        let inv = 1.0 / binomial(ph, i);
        for j in i.saturating_sub(t)..=p.min(i) {
            bezalfs[i][j] = inv * binomial(p, j) * binomial(t, i - j);
        }
    }
    for i in ph2 + 1..ph {
        for j in i.saturating_sub(t)..=p.min(i) {
            bezalfs[i][j] = bezalfs[ph - i][p - j];
        }
    }
    let zero = vec![0.0; width];
    let mut bpts: Vec<Row> = rows[..=p].to_vec();
    let mut next_bpts: Vec<Row> = vec![zero.clone(); p.saturating_sub(1).max(1)];
    let mut ebpts: Vec<Row> = vec![zero.clone(); ph + 1];
    let mut alfs = vec![0.0; p.max(1)];
    // 1 − alfs, from the knots (see `net::blend`).
    let mut bets = vec![0.0; p.max(1)];
    let mut qw: Vec<Row> = vec![rows[0].clone()];
    let mut uh: Vec<f64> = vec![u[0]; ph + 1];
    let mut ua = u[0];
    let (mut a, mut b) = (p, p + 1);
    let mut r: isize = -1;
    while b < m {
        let i0 = b;
        while b < m && u[b] == u[b + 1] {
            b += 1;
        }
        let mul = b - i0 + 1;
        let ub = u[b];
        let oldr = r;
        r = p as isize - mul as isize;
        // After the first segment, oldr = −1 means the previous knot had full
        // multiplicity: the segments share no point.
        let lbz = match oldr {
            o if o > 0 => ((o + 2) / 2) as usize,
            o if o < 0 && a != p => 0,
            _ => 1,
        };
        let rbz = if r > 0 {
            ph - ((r + 1) / 2) as usize
        } else {
            ph
        };
        if r > 0 {
            // Insert u[b] r times to get the Bézier segment.
            let numer = ub - ua;
            for k in (mul + 1..=p).rev() {
                alfs[k - mul - 1] = numer / (u[a + k] - ua);
                bets[k - mul - 1] = (u[a + k] - ub) / (u[a + k] - ua);
            }
            for j in 1..=r as usize {
                let save = r as usize - j;
                let s = mul + j;
                for k in (s..=p).rev() {
                    let (alpha, beta) = (alfs[k - s], bets[k - s]);
                    bpts[k] = crate::nurbs::homogeneous::blend(alpha, beta, &bpts[k], &bpts[k - 1]);
                }
                next_bpts[save] = bpts[p].clone();
            }
        }
        // Degree-elevate the Bézier segment.
        for (i, e) in ebpts.iter_mut().enumerate().skip(lbz) {
            *e = combine(
                width,
                (i.saturating_sub(t)..=p.min(i)).map(|j| (bezalfs[i][j], &bpts[j])),
            );
        }
        if oldr > 1 {
            // Remove the knot u = ua oldr times.
            let oldr = oldr as usize;
            let kind = uh.len();
            let mut first = kind - 2;
            let mut last = kind;
            let den = ub - ua;
            let bet = (ub - uh[kind - 1]) / den;
            for tr in 1..oldr {
                let (mut i, mut j) = (first, last);
                let mut kj = j - kind + 1;
                while j - i > tr {
                    if i < qw.len() {
                        let alf = (ub - uh[i]) / (ua - uh[i]);
                        qw[i] = crate::nurbs::homogeneous::lerp(alf, &qw[i], &qw[i - 1]);
                    }
                    if j >= lbz {
                        let factor = if j - tr <= kind - ph + oldr {
                            (ub - uh[j - tr]) / den
                        } else {
                            bet
                        };
                        ebpts[kj] =
                            crate::nurbs::homogeneous::lerp(factor, &ebpts[kj], &ebpts[kj + 1]);
                    }
                    i += 1;
                    j -= 1;
                    kj = kj.wrapping_sub(1);
                }
                first -= 1;
                last += 1;
            }
        }
        if a != p {
            // Load the knot ua.
            let copies = (ph as isize - oldr) as usize;
            uh.extend(std::iter::repeat_n(ua, copies));
        }
        qw.extend(ebpts[lbz..=rbz].iter().cloned());
        if b < m {
            // Set up for the next pass.
            let r0 = r.max(0) as usize;
            bpts[..r0].clone_from_slice(&next_bpts[..r0]);
            for j in r0..=p {
                bpts[j] = rows[b - p + j].clone();
            }
            a = b;
            b += 1;
            ua = ub;
        } else {
            uh.extend(std::iter::repeat_n(ub, ph + 1));
        }
    }
    (KnotVector::from_parts_unchecked(uh, ph), qw)
}

impl<const D: usize> NurbsCurve<D> {
    /// The same curve as a curve of degree `p + times` (The NURBS Book, A5.9).
    ///
    /// Every knot's multiplicity grows by `times`, so the continuity at each knot
    /// is kept. An unclamped curve comes back clamped (same domain).
    ///
    /// **Accuracy.** A5.9 removes the knots it inserted, an extrapolation whose
    /// rounding grows with the inverse distance between neighbouring knots, and
    /// division by the weights adds the ratio of the largest to the smallest
    /// weight. The property tests bound the movement of the curve by
    /// `64 ε · size · (w_max/w_min) · (b − a)/(smallest knot gap)`; in practice it
    /// is about 10⁻¹¹ of the curve's size for knots 10⁻⁴ of the domain apart and
    /// weights 0.2–5, and knots 4.7·10⁻⁵ apart at degree 5 gave 1.8·10⁻¹¹ in the
    /// peer suite, far below its tolerance of 10⁻⁹.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the new degree would exceed
    /// [`MAX_ELEVATED_DEGREE`].
    ///
    /// # Examples
    /// A parabola as a cubic:
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], vec![1.0; 3])?;
    /// let d = c.elevate_degree(1)?;
    /// assert_eq!(d.degree(), 3);
    /// assert_eq!(d.control_points()[1], [2.0 / 3.0, 4.0 / 3.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn elevate_degree(&self, times: usize) -> Result<Self, Error> {
        check_elevation(self.degree(), times)?;
        let (knots, rows) = elevate(self.knots(), &self.rows(), times);
        Self::try_from_rows(knots, &rows, "degree elevation")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::fixtures::{self, unclamped_quadratic};

    fn assert_same_geometry<const D: usize>(a: &NurbsCurve<D>, b: &NurbsCurve<D>) {
        assert_eq!(a.domain(), b.domain());
        fixtures::assert_same_geometry(a, b, 301, 1e-12);
    }

    #[test]
    fn elevation_keeps_the_curve_and_raises_multiplicities() {
        let knots = [
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.6, 0.6, 1.0, 1.0, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0],
            vec![
                0.0, 0.0, 0.0, 0.0, 0.2, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0,
            ],
        ];
        for u in knots {
            let n = u.len() - 4;
            let points: Vec<[f64; 3]> = (0..n)
                .map(|i| {
                    let x = i as f64;
                    [x, (x * 1.7).sin() * 3.0, x * x * 0.2]
                })
                .collect();
            let weights = (0..n).map(|i| 0.5 + (i % 3) as f64).collect();
            let c = NurbsCurve::try_new(
                points,
                weights,
                KnotVector::try_new(u.clone(), 3, n).unwrap(),
            )
            .unwrap();
            for times in 1..=3 {
                let d = c.elevate_degree(times).unwrap();
                assert_eq!(d.degree(), 3 + times);
                for &v in &u {
                    assert_eq!(
                        d.knots().multiplicity(v),
                        c.knots().multiplicity(v) + times,
                        "{u:?}"
                    );
                }
                assert_same_geometry(&c, &d);
            }
        }
    }

    #[test]
    fn elevating_degree_one_and_an_unclamped_curve() {
        let line = NurbsCurve::try_clamped(
            1,
            vec![[0.0, 0.0], [1.0, 1.0], [3.0, 0.0]],
            vec![1.0, 2.0, 1.0],
        )
        .unwrap();
        assert_same_geometry(&line, &line.elevate_degree(2).unwrap());
        let c = unclamped_quadratic();
        let d = c.elevate_degree(1).unwrap();
        assert!(d.knots().is_clamped());
        assert_same_geometry(&c, &d);
        assert_eq!(c.elevate_degree(0).unwrap(), c);
        assert!(matches!(
            c.elevate_degree(usize::MAX),
            Err(Error::OutOfRange { .. })
        ));
    }
}
