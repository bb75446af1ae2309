//! Partial derivatives of any order of a rational surface and its normal
//! (The NURBS Book, A3.6 and A4.4).

use super::tensor_product::NurbsSurface;
use crate::error::Error;
use crate::nurbs::derivatives::{basis_derivatives, binomial, check_order};
use crate::place::Direction;
use crate::vector::{cross, euclidean_norm};

impl<const D: usize> NurbsSurface<D> {
    /// The partial derivatives `out[k][l] = ∂ᵏ⁺ˡS / ∂uᵏ∂vˡ (u, v)` for
    /// `k + l ≤ order` (`out[k]` has `order − k + 1` entries; `out[0][0]` is
    /// the point).
    ///
    /// The homogeneous surface `Sʷ = (A, w)`, `A = Σ wᵢⱼNᵢMⱼPᵢⱼ`,
    /// `w = Σ wᵢⱼNᵢMⱼ`, is differentiated with the basis derivatives of each
    /// direction (The NURBS Book, A3.6 with A2.3); the rational derivatives
    /// follow from Leibniz's rule (A4.4, Eq. 4.20):
    ///
    /// ```text
    /// S⁽ᵏˡ⁾ = ( A⁽ᵏˡ⁾ − Σⱼ₌₁ˡ C(l, j)·w⁽⁰ʲ⁾·S⁽ᵏ,ˡ⁻ʲ⁾
    ///               − Σᵢ₌₁ᵏ C(k, i)·w⁽ⁱ⁰⁾·S⁽ᵏ⁻ⁱ,ˡ⁾
    ///               − Σᵢ₌₁ᵏ C(k, i)·Σⱼ₌₁ˡ C(l, j)·w⁽ⁱʲ⁾·S⁽ᵏ⁻ⁱ,ˡ⁻ʲ⁾ ) / w
    /// ```
    /// Any order is allowed. The derivatives are those of the polynomial piece
    /// on the span rectangle that [`NurbsSurface::eval`] uses: one-sided at
    /// interior knots (from the right) and at the ends of the domain.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `u` or `v` is
    /// outside its domain; [`Error::OutOfRange`] if `order` exceeds
    /// [`MAX_DERIVATIVE_ORDER`](crate::nurbs::MAX_DERIVATIVE_ORDER).
    ///
    /// # Examples
    /// The bilinear patch `S(u, v) = (u, v, u·v)`:
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0; 2]; 2])?;
    /// let d = s.derivatives(0.25, 0.5, 2)?;
    /// assert_eq!(d[0][0], [0.25, 0.5, 0.125]);
    /// assert_eq!(d[1][0], [1.0, 0.0, 0.5]); // S_u
    /// assert_eq!(d[0][1], [0.0, 1.0, 0.25]); // S_v
    /// assert_eq!(d[1][1], [0.0, 0.0, 1.0]); // S_uv
    /// assert_eq!(d[2][0], [0.0, 0.0, 0.0]); // S_uu
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn derivatives(&self, u: f64, v: f64, order: usize) -> Result<Vec<Vec<[f64; D]>>, Error> {
        self.check(u, v)?;
        check_order(order)?;
        Ok(self.derivatives_unchecked(u, v, order))
    }

    /// [`NurbsSurface::derivatives`] for `(u, v)` in the domain.
    pub(crate) fn derivatives_unchecked(&self, u: f64, v: f64, order: usize) -> Vec<Vec<[f64; D]>> {
        let (ku, kv) = (self.knots(Direction::U), self.knots(Direction::V));
        self.derivatives_in_spans([ku.find_span(u), kv.find_span(v)], u, v, order)
    }

    /// The partial derivatives of the polynomial piece of the non-empty span
    /// rectangle `spans` at `(u, v)` in its closure (one-sided from inside on
    /// its borders), as [`NurbsSurface::derivatives`].
    pub(crate) fn derivatives_in_spans(
        &self,
        [su, sv]: [usize; 2],
        u: f64,
        v: f64,
        order: usize,
    ) -> Vec<Vec<[f64; D]>> {
        let (ku, kv) = (self.knots(Direction::U), self.knots(Direction::V));
        let (p, q) = (ku.degree(), kv.degree());
        let nv = kv.count();
        let du = basis_derivatives(ku.as_slice(), p, su, u, order.min(p));
        let dv = basis_derivatives(kv.as_slice(), q, sv, v, order.min(q));
        let (fu, fv) = (su - p, sv - q);
        // Homogeneous derivatives A⁽ᵏˡ⁾ and w⁽ᵏˡ⁾ (A3.6); zero above the degrees.
        let mut a = vec![vec![[0.0; D]; order + 1]; order + 1];
        let mut w = vec![vec![0.0; order + 1]; order + 1];
        for (k, nk) in du.iter().enumerate() {
            for (l, ml) in dv.iter().enumerate().take(order + 1 - k) {
                for (i, n) in nk.iter().enumerate() {
                    let base = (fu + i) * nv + fv;
                    for (j, m) in ml.iter().enumerate() {
                        let (pij, wij) =
                            (self.control_points()[base + j], self.weights()[base + j]);
                        let c = n * m * wij;
                        w[k][l] += c;
                        for (x, y) in a[k][l].iter_mut().zip(pij) {
                            *x += c * y;
                        }
                    }
                }
            }
        }
        // Rational derivatives (A4.4).
        let mut s: Vec<Vec<[f64; D]>> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let mut row: Vec<[f64; D]> = Vec::with_capacity(order + 1 - k);
            for l in 0..=order - k {
                let mut value = a[k][l];
                let mut subtract = |c: f64, x: &[f64; D]| {
                    for (v, y) in value.iter_mut().zip(x) {
                        *v -= c * y;
                    }
                };
                for j in 1..=l {
                    subtract(binomial(l, j) * w[0][j], &row[l - j]);
                }
                for i in 1..=k {
                    let bi = binomial(k, i);
                    subtract(bi * w[i][0], &s[k - i][l]);
                    for j in 1..=l {
                        subtract(bi * binomial(l, j) * w[i][j], &s[k - i][l - j]);
                    }
                }
                row.push(value.map(|x| x / w[0][0]));
            }
            s.push(row);
        }
        s
    }
}

impl NurbsSurface<3> {
    /// The unit normal `n = S_u × S_v / ‖S_u × S_v‖` at `(u, v)`, one-sided at
    /// knots as [`NurbsSurface::derivatives`].
    ///
    /// The cross product counts as zero when `‖S_u × S_v‖·hu·hv ≤ 10⁻¹⁴·s²`,
    /// with `hu`, `hv` the lengths of the knot spans and `s` the size of the
    /// control net (the diagonal of its bounding box).
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `(u, v)` is
    /// outside the domain; [`Error::SingularNormal`] where `S_u` and `S_v` are
    /// parallel or zero.
    ///
    /// # Examples
    /// The quarter cylinder about the z axis has the radial normal:
    /// ```
    /// # use t2spline::NurbsSurface;
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let net = vec![
    ///     vec![[1.0, 0.0, 0.0], [1.0, 0.0, 2.0]],
    ///     vec![[1.0, 1.0, 0.0], [1.0, 1.0, 2.0]],
    ///     vec![[0.0, 1.0, 0.0], [0.0, 1.0, 2.0]],
    /// ];
    /// let s = NurbsSurface::try_clamped([2, 1], net, vec![vec![1.0; 2], vec![w; 2], vec![1.0; 2]])?;
    /// let [x, y, _] = s.eval(0.4, 0.5)?;
    /// let n = s.normal(0.4, 0.5)?;
    /// assert!((n[0] - x).abs() < 1e-15 && (n[1] - y).abs() < 1e-15 && n[2] == 0.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn normal(&self, u: f64, v: f64) -> Result<[f64; 3], Error> {
        self.check(u, v)?;
        let d = self.derivatives_unchecked(u, v, 1);
        Ok(self.unit_normal(u, v, &d[1][0], &d[0][1])?.0)
    }

    /// The unit normal `n = S_u × S_v / ‖S_u × S_v‖` at `(u, v)` from the
    /// partial derivatives `su`, `sv` there, and the sine of the angle between
    /// them; the test of [`NurbsSurface::normal`], shared by every quantity
    /// that needs the normal. The cross product is taken of
    /// the unit vectors, so that derivatives near the float range do not
    /// overflow it.
    ///
    /// # Errors
    /// [`Error::SingularNormal`] where `S_u` and `S_v` are parallel or zero.
    pub(crate) fn unit_normal(
        &self,
        u: f64,
        v: f64,
        su: &[f64; 3],
        sv: &[f64; 3],
    ) -> Result<([f64; 3], f64), Error> {
        let (lu, lv) = (euclidean_norm(su), euclidean_norm(sv));
        let cross = cross(&su.map(|x| x / lu), &sv.map(|x| x / lv));
        let sine = euclidean_norm(&cross);
        let span = |direction: Direction, t: f64| {
            let k = self.knots(direction);
            let i = k.find_span(t);
            k.as_slice()[i + 1] - k.as_slice()[i]
        };
        let (hu, hv) = (span(Direction::U, u), span(Direction::V, v));
        let size = self.net_size();
        // ‖S_u × S_v‖·hu·hv > 10⁻¹⁴·s²; NaN (from a zero derivative) counts
        // as singular.
        let ok = sine * (lu * hu) * (lv * hv) > 1e-14 * size * size;
        if !ok {
            return Err(Error::SingularNormal { u, v });
        }
        Ok((cross.map(|x| x / sine), sine))
    }

    /// The diagonal of the bounding box of the control points (at least the
    /// smallest normal float).
    fn net_size(&self) -> f64 {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in self.control_points() {
            for d in 0..3 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        euclidean_norm(&[hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]]).max(f64::MIN_POSITIVE)
    }
}
