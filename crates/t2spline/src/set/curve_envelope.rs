//! The envelope of a fuzzy curve at one parameter (docs/method.md §15–§16):
//! for a membership function `m` and a level `alpha`, the least and the
//! largest value of each coordinate over every choice of points and weights
//! inside their `m`-cuts. With crisp weights it is the box between the
//! curves of the cut's ends (§10); with fuzzy weights the coordinates share
//! the weights and each end is a Karnik–Mendel weighted average, exact at
//! its switch point.

use crate::error::Error;
use crate::fuzzy::{Alpha, Interval, Layer, Membership, Nt2Number};
use crate::interval_weights::IntervalTerms;
use crate::nurbs::basis::basis_functions;
use crate::pipeline::FuzzyCurve;

impl<const D: usize> FuzzyCurve<D> {
    /// The range of each coordinate of the curve at `t` over every choice
    /// of control points and weights inside their cuts under `membership`
    /// at `alpha` (docs/method.md §15–§16), exact at the Karnik–Mendel switch
    /// points; `None` where a number that counts at `t` has no cut there
    /// (the lower function above its height).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `t` is NaN or outside the domain.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, FuzzyCurve, Membership, Nt2Number, Nt2Point};
    /// let n = |c: f64, s: f64| Nt2Number::try_new(c, [c - s, c + s], [c - s / 2.0, c + s / 2.0], [c, c], 1.0);
    /// // Points 0 and 1 (crisp), weights 1 and [1, 3]: at t = 1/2 the
    /// // average runs from 1/2 (equal weights) to 3/4 (weight 3 on 1).
    /// let points = vec![Nt2Point::new([n(0.0, 0.0)?]), Nt2Point::new([n(1.0, 0.0)?])];
    /// let c = FuzzyCurve::try_new(1, points, vec![1.0, 2.0], None)?
    ///     .with_weight_numbers(vec![n(1.0, 0.0)?, n(2.0, 1.0)?])?;
    /// let [x] = c.envelope_at(0.5, Membership::Upper, Alpha::ZERO)?.unwrap();
    /// assert!((x.left() - 0.5).abs() < 1e-15 && (x.right() - 0.75).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn envelope_at(
        &self,
        t: f64,
        membership: Membership,
        alpha: Alpha,
    ) -> Result<Option<[Interval; D]>, Error> {
        self.domain().check(t)?;
        let p = self.degree();
        let span = self.knots().find_span(t);
        let mut basis = vec![0.0; p + 1];
        basis_functions(self.knots().as_slice(), p, span, t, &mut basis);
        let first = span - p;
        let (mut ns, mut ws, mut boxes) = (Vec::new(), Vec::new(), Vec::new());
        for (k, &n) in basis.iter().enumerate() {
            if n <= 0.0 {
                continue;
            }
            let i = first + k;
            let (Some(point), Some(&crisp)) = (self.points().get(i), self.weights().get(i)) else {
                continue;
            };
            let w = match self.weight_numbers().and_then(|w| w.get(i)) {
                Some(w) => cut(w, membership, alpha),
                None => Some([crisp; 2]),
            };
            let mut b = [[0.0; 2]; D];
            for (b, x) in b.iter_mut().zip(point.coords()) {
                match cut(x, membership, alpha) {
                    Some(c) => *b = c,
                    None => return Ok(None),
                }
            }
            let Some(w) = w else {
                return Ok(None);
            };
            ns.push(n);
            ws.push(w);
            boxes.push(b);
        }
        Ok(Some(IntervalTerms::try_new(&ns, &ws, &boxes)?.envelope()))
    }
}

/// The cut `[left, right]` of `x` under `m` at `alpha`, if it has one.
pub(crate) fn cut(x: &Nt2Number, m: Membership, alpha: Alpha) -> Option<[f64; 2]> {
    let c = x.alpha_cut(alpha);
    let (l, r) = match m {
        Membership::Upper => (Layer::UpperLeft, Layer::UpperRight),
        Membership::Primary => (Layer::PrimaryLeft, Layer::PrimaryRight),
        Membership::Lower => (Layer::LowerLeft, Layer::LowerRight),
    };
    Some([c.layer(l)?, c.layer(r)?])
}
