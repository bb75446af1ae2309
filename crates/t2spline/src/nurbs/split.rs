//! Splitting a curve at a parameter, extracting a piece, and clamping
//! (The NURBS Book, §5.3: knot insertion up to multiplicity `p`).

use crate::error::Error;
use crate::nurbs::homogeneous::Row;
use crate::nurbs::knot_insertion::insert;
use crate::nurbs::{KnotVector, NurbsCurve};

/// The piece of a curve over `[a, b]` (`U[p] ≤ a < b ≤ U[n]`), clamped at both
/// ends, from homogeneous control points.
///
/// `a` and `b` are first inserted until their multiplicity is at least `p`;
/// then the piece's knots are `a` (k times), the old knots strictly between `a`
/// and `b`, and `b` (k times), and its control points are those whose basis
/// functions are non-zero on `(a, b)`. At a knot of full multiplicity (where
/// the curve may jump) the piece to the left ends with the left limit.
pub(crate) fn segment(
    knots: &KnotVector,
    rows: &[Row],
    a: f64,
    b: f64,
) -> Result<(KnotVector, Vec<Row>), Error> {
    let p = knots.degree();
    let (mut knots, mut rows) = (knots.clone(), rows.to_vec());
    for u in [a, b] {
        let times = p.saturating_sub(knots.multiplicity(u));
        (knots, rows) = insert(&knots, &rows, u, times)?;
    }
    let u = knots.as_slice();
    // a occupies [f, f + ma), b occupies [g, g + mb).
    let f = u.partition_point(|&v| v < a);
    let ma = knots.multiplicity(a);
    let g = u.partition_point(|&v| v < b);
    let first = f + ma - 1 - p;
    let last = g - 1;
    let mut values = vec![a; p + 1];
    values.extend_from_slice(&u[f + ma..g]);
    values.extend(std::iter::repeat_n(b, p + 1));
    Ok((
        KnotVector::from_parts_unchecked(values, p),
        rows[first..=last].to_vec(),
    ))
}

/// The two pieces of a curve split at `t`, strictly inside the domain.
pub(crate) fn split(
    knots: &KnotVector,
    rows: &[Row],
    t: f64,
) -> Result<[(KnotVector, Vec<Row>); 2], Error> {
    let d = knots.domain();
    if !(d.start < t && t < d.end) {
        return Err(Error::SplitOutside {
            t,
            start: d.start,
            end: d.end,
        });
    }
    Ok([
        segment(knots, rows, d.start, t)?,
        segment(knots, rows, t, d.end)?,
    ])
}

impl<const D: usize> NurbsCurve<D> {
    /// The two curves `C` on `[a, t]` and on `[t, b]` (The NURBS Book, §5.3:
    /// insert `t` until its multiplicity is `p`, then cut the knot vector and
    /// the control points). Both are clamped and keep the parameters: the left
    /// piece at `s` is `C(s)`. At an interior knot of full multiplicity the left
    /// piece ends with the curve's left limit.
    ///
    /// # Errors
    /// [`Error::SplitOutside`] unless `a < t < b`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], vec![1.0, 3.0, 1.0])?;
    /// let [left, right] = c.split_at(0.4)?;
    /// assert_eq!(left.domain().end, 0.4);
    /// assert_eq!(left.control_points().last(), right.control_points().first());
    /// let (a, b) = (c.eval(0.7)?, right.eval(0.7)?);
    /// assert!((a[0] - b[0]).abs() < 1e-15 && (a[1] - b[1]).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn split_at(&self, t: f64) -> Result<[Self; 2], Error> {
        let pieces = split(self.knots(), &self.rows(), t)?;
        let [(k1, r1), (k2, r2)] = pieces;
        Ok([
            Self::try_from_rows(k1, &r1, "splitting")?,
            Self::try_from_rows(k2, &r2, "splitting")?,
        ])
    }

    /// The piece of the curve over `[a, b]`, a sub-interval of the domain with
    /// `a < b`, clamped at both ends, with the same parameters.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `a` or `b` lies outside the domain;
    /// [`Error::SplitOutside`] unless `a < b`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(3, vec![[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0]], vec![1.0; 4])?;
    /// let piece = c.segment(0.25, 0.5)?;
    /// assert_eq!(piece.control_points().len(), 4);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn segment(&self, a: f64, b: f64) -> Result<Self, Error> {
        self.domain().check(a)?;
        self.domain().check(b)?;
        if a >= b || b.is_nan() {
            return Err(Error::SplitOutside {
                t: b,
                start: a,
                end: self.domain().end,
            });
        }
        let (knots, rows) = segment(self.knots(), &self.rows(), a, b)?;
        Self::try_from_rows(knots, &rows, "splitting")
    }

    /// The same curve with a clamped knot vector (the first and last `k` knots
    /// equal), so that it starts and ends at its first and last control points;
    /// a clamped curve is returned unchanged.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{KnotVector, NurbsCurve};
    /// let u = KnotVector::try_new(vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], 2, 4)?;
    /// let c = NurbsCurve::try_new(vec![[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0]], vec![1.0; 4], u)?;
    /// let d = c.clamped();
    /// assert_eq!(d.knots().as_slice(), &[2.0, 2.0, 2.0, 3.0, 4.0, 4.0, 4.0]);
    /// assert_eq!(d.control_points()[0], c.eval(2.0)?);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn clamped(&self) -> Self {
        if self.knots().is_clamped() {
            return self.clone();
        }
        let d = self.domain();
        // `segment` fails only for a parameter outside the domain or an
        // insertion past the order; the domain's ends are inside it and are
        // inserted up to multiplicity p only.
        #[allow(clippy::expect_used)]
        let (knots, rows) = segment(self.knots(), &self.rows(), d.start, d.end)
            .expect("the domain ends lie in the domain");
        Self::from_rows(knots, &rows)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::fixtures::{assert_same_geometry, five_point_cubic, jump};

    #[test]
    fn split_pieces_reproduce_the_curve() {
        let c = five_point_cubic();
        for t in [0.1, 0.4, 0.77] {
            let [l, r] = c.split_at(t).unwrap();
            assert_eq!((l.domain().start, l.domain().end), (0.0, t));
            assert_eq!((r.domain().start, r.domain().end), (t, 1.0));
            for s in c.domain().uniform(101).unwrap() {
                let piece = if s <= t { &l } else { &r };
                let (p, q) = (c.eval(s).unwrap(), piece.eval(s).unwrap());
                assert!(
                    (p[0] - q[0]).abs() < 1e-13 && (p[1] - q[1]).abs() < 1e-13,
                    "{s}"
                );
            }
        }
        assert!(matches!(c.split_at(0.0), Err(Error::SplitOutside { .. })));
        assert!(matches!(
            c.split_at(f64::NAN),
            Err(Error::SplitOutside { .. })
        ));
    }

    #[test]
    fn split_at_a_jump_gives_both_limits() {
        let [l, r] = jump().split_at(0.5).unwrap();
        assert_eq!(l.control_points(), &[[0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(r.control_points(), &[[5.0, 5.0], [6.0, 5.0]]);
    }

    #[test]
    fn clamping_an_unclamped_curve_keeps_it() {
        let u = KnotVector::try_new(vec![-0.3, -0.1, 0.0, 0.2, 0.7, 1.0, 1.4, 1.5], 3, 4).unwrap();
        let c = NurbsCurve::try_new(
            vec![[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0]],
            vec![1.0, 2.0, 0.5, 1.5],
            u,
        )
        .unwrap();
        let d = c.clamped();
        assert!(d.knots().is_clamped());
        assert_eq!(d.domain(), c.domain());
        assert_same_geometry(&c, &d, 101, 1e-13);
    }
}
