//! Piecewise-linear footprints of one number and the Karnik–Mendel function on
//! them: the machinery behind the exact centroid and the alpha-planes.
//!
//! Everything here works in *local* coordinates ([`Frame`]): `crisp` at 0 and
//! the support `[upper.left, upper.right]` of width 1. Then every area,
//! moment and cubic coefficient is of order 1 whatever the input's magnitude
//! (spreads of 1e150 would overflow a cubic term, spreads of 1e-300 underflow
//! a square), and a result is mapped back once.
//!
//! A footprint is a pair of membership functions, `upper ≥ lower`, linear on
//! each of the six pieces between the seven values of the number (docs/method.md §1
//! order, so the breakpoints are sorted already). The three triangles of docs/method.md
//! §1 and every alpha-plane between them are of this kind.

use crate::fuzzy::{Layer, Nt2Number};

/// The affine map between a number's values and local coordinates:
/// `local = (x − crisp) / (upper.right − upper.left)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    origin: f64,
    scale: f64,
    support: [f64; 2],
}

impl Frame {
    /// The frame of `x`, or `None` when its support is a single value (all
    /// seven values equal: a crisp number, whose every reduction is `crisp`).
    pub(crate) fn of(x: &Nt2Number) -> Option<Frame> {
        let (lo, hi) = (x.upper().left(), x.upper().right());
        // Both within 1e150 (the limits of docs/jobs.md), so the width is finite.
        let scale = hi - lo;
        (scale > 0.0).then_some(Frame {
            origin: x.crisp(),
            scale,
            support: [lo, hi],
        })
    }

    /// A value of the number in local coordinates.
    pub(crate) fn local(&self, v: f64) -> f64 {
        (v - self.origin) / self.scale
    }

    /// A local value mapped back, kept inside the support against rounding
    /// (every reduction of the number lies in its support).
    pub(crate) fn global(&self, u: f64) -> f64 {
        (self.origin + self.scale * u).clamp(self.support[0], self.support[1])
    }

    /// The seven values of `x` in local coordinates (ascending; `crisp` = 0
    /// at index 3).
    pub(crate) fn breakpoints(&self, x: &Nt2Number) -> [f64; 7] {
        let mut b = [0.0; 7];
        for (bi, layer) in b.iter_mut().zip(Layer::ALL) {
            *bi = self.local(x.layer(layer));
        }
        // Exactly 0, as `crisp − crisp` is; the map is monotone, so the order holds.
        b[3] = 0.0;
        b
    }
}

/// The three triangles of docs/method.md §1 in local coordinates: feet `[left, right]`
/// around the apex 0, and the height.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Triangles {
    upper: Side2,
    primary: Side2,
    lower: Side2,
    primary_feet: [f64; 2],
}

/// One triangle `T(x; a, 0, b, top)` as the slopes of its two sides, so that
/// a value costs a multiplication: `top·(x − a)/(−a)` left of the apex,
/// `top·(b − x)/b` right of it. A side of zero width is a vertical edge, 0 on
/// its outer side (slope 0 here: every piece on that side has zero width or
/// lies outside the triangle).
#[derive(Clone, Copy, Debug)]
struct Side2 {
    feet: [f64; 2],
    slope: [f64; 2],
}

impl Side2 {
    fn new(feet: [f64; 2], top: f64) -> Self {
        let [a, b] = feet;
        let left = if a < 0.0 { top / -a } else { 0.0 };
        let right = if b > 0.0 { top / b } else { 0.0 };
        Side2 {
            feet,
            slope: [left, right],
        }
    }

    /// The value at `x`, as the limit from inside a piece on the `right` side
    /// of the apex or not.
    fn at(&self, x: f64, right: bool) -> f64 {
        let [a, b] = self.feet;
        if right {
            (self.slope[1] * (b - x)).max(0.0)
        } else {
            (self.slope[0] * (x - a)).max(0.0)
        }
    }
}

impl Triangles {
    pub(crate) fn new(b: &[f64; 7], height: f64) -> Self {
        Triangles {
            upper: Side2::new([b[0], b[6]], 1.0),
            primary: Side2::new([b[1], b[5]], 1.0),
            lower: Side2::new([b[2], b[4]], height),
            primary_feet: [b[1], b[5]],
        }
    }

    /// The primary triangle's centroid `(primary.left + 0 + primary.right) / 3`
    /// and area `(primary.right − primary.left) / 2`.
    pub(crate) fn primary_centroid_and_area(&self) -> (f64, f64) {
        let [a, b] = self.primary_feet;
        ((a + b) / 3.0, (b - a) / 2.0)
    }
}

/// A footprint: `upper` and `lower` membership, linear on each piece
/// `[b[k], b[k+1]]`, given by their values at both ends of the piece (limits
/// from inside, so vertical edges at a breakpoint are represented exactly).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Footprint {
    b: [f64; 7],
    upper: [[f64; 2]; 6],
    lower: [[f64; 2]; 6],
}

impl Footprint {
    /// The alpha-plane at level `z` of the general type-2 reading (docs/method.md §9):
    /// ```text
    /// upper_z = (1 − z)·UMF + z·primary,   lower_z = (1 − z)·LMF + z·primary
    /// ```
    /// `z = 0` is the interval type-2 footprint between LMF and UMF.
    pub(crate) fn plane(b: &[f64; 7], t: &Triangles, z: f64) -> Self {
        let mut upper = [[0.0; 2]; 6];
        let mut lower = [[0.0; 2]; 6];
        for k in 0..6 {
            // Pieces 0–2 lie left of the apex (b[3] = 0), 3–5 right of it.
            let right = k >= 3;
            for end in 0..2 {
                let x = b[k + end];
                let p = t.primary.at(x, right);
                let u = t.upper.at(x, right);
                let l = t.lower.at(x, right);
                if z == 0.0 {
                    upper[k][end] = u;
                    lower[k][end] = l;
                } else {
                    upper[k][end] = (1.0 - z) * u + z * p;
                    lower[k][end] = (1.0 - z) * l + z * p;
                }
            }
        }
        Footprint {
            b: *b,
            upper,
            lower,
        }
    }

    /// The same footprint seen in the mirror `x ↦ −x`.
    pub(crate) fn mirrored(&self) -> Self {
        let mut m = *self;
        for i in 0..7 {
            m.b[i] = -self.b[6 - i];
        }
        for k in 0..6 {
            let [u0, u1] = self.upper[5 - k];
            let [l0, l1] = self.lower[5 - k];
            m.upper[k] = [u1, u0];
            m.lower[k] = [l1, l0];
        }
        m
    }

    /// The breakpoints.
    pub(crate) fn breakpoints(&self) -> &[f64; 7] {
        &self.b
    }
}

/// The Karnik–Mendel function of a footprint, whose root is the left end of its
/// centroid (Karnik and Mendel 2001, continuous form):
/// ```text
/// F(c) = ∫_{x<c} (x − c)·upper(x) dx + ∫_{x>c} (x − c)·lower(x) dx
/// F'(c) = −( ∫_{x<c} upper + ∫_{x>c} lower )          (< 0 inside the support)
/// F''(c) = lower(c) − upper(c),   F''' = slope(lower) − slope(upper)
/// ```
/// On a piece `[b_j, b_{j+1}]` of width `w`, with `c = b_j + w·s`, `s ∈ [0, 1]`,
/// `F` is the cubic of its Taylor expansion at `b_j`:
/// ```text
/// p(s) = F_j + w·s·( F'_j + w·s·( q_j/2 + r_j·s/6 ) )
/// q_j = lower(b_j⁺) − upper(b_j⁺),   r_j = Δlower_j − Δupper_j  (change over the piece)
/// ```
/// `F_j` and `F'_j` are sums over the pieces of the moments and areas of
/// linear functions (trapezoids): on a piece of width `w` with end values
/// `f0`, `f1`,
/// ```text
/// ∫ f = w·(f0 + f1)/2,   ∫ (x − left end)·f = w²·(f0 + 2·f1)/6,
/// ∫ (x − right end)·f = −w²·(2·f0 + f1)/6
/// ```
/// Each piece left of `b_j` contributes `∫ (x − b_j)·upper ≤ 0` (moment about
/// its right end plus its area times `b_{k+1} − b_j`, two terms of one sign),
/// each piece right of it `∫ (x − b_j)·lower ≥ 0`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct KmFunction {
    b: [f64; 7],
    value: [f64; 7],
    slope: [f64; 7],
    curvature: [f64; 6],
    jerk: [f64; 6],
}

impl KmFunction {
    pub(crate) fn new(fp: &Footprint) -> Self {
        let b = fp.b;
        let mut width = [0.0; 6];
        let mut area_upper = [0.0; 6];
        let mut area_lower = [0.0; 6];
        for k in 0..6 {
            let w = b[k + 1] - b[k];
            width[k] = w;
            area_upper[k] = w * (fp.upper[k][0] + fp.upper[k][1]) / 2.0;
            area_lower[k] = w * (fp.lower[k][0] + fp.lower[k][1]) / 2.0;
        }
        let mut value = [0.0; 7];
        let mut slope = [0.0; 7];
        for j in 0..7 {
            let (mut v, mut mass) = (0.0, 0.0);
            for k in 0..6 {
                let w = width[k];
                if k < j {
                    let [f0, f1] = fp.upper[k];
                    v -= w * w * (2.0 * f0 + f1) / 6.0 + (b[j] - b[k + 1]) * area_upper[k];
                    mass += area_upper[k];
                } else {
                    let [f0, f1] = fp.lower[k];
                    v += w * w * (f0 + 2.0 * f1) / 6.0 + (b[k] - b[j]) * area_lower[k];
                    mass += area_lower[k];
                }
            }
            value[j] = v;
            slope[j] = -mass;
        }
        let mut curvature = [0.0; 6];
        let mut jerk = [0.0; 6];
        for k in 0..6 {
            let [u0, u1] = fp.upper[k];
            let [l0, l1] = fp.lower[k];
            curvature[k] = l0 - u0;
            jerk[k] = (l1 - l0) - (u1 - u0);
        }
        KmFunction {
            b,
            value,
            slope,
            curvature,
            jerk,
        }
    }

    /// `p(s)` and `p'(s)` on piece `j`.
    fn cubic(&self, j: usize, s: f64) -> (f64, f64) {
        let w = self.b[j + 1] - self.b[j];
        let (q, r) = (self.curvature[j], self.jerk[j]);
        let ws = w * s;
        let value = self.value[j] + ws * (self.slope[j] + ws * (q / 2.0 + r * s / 6.0));
        let derivative = w * (self.slope[j] + ws * (q + r * s / 2.0));
        (value, derivative)
    }

    /// `F(c)` for `c` in the support `[b_0, b_6]` (clamped into it).
    pub(crate) fn eval(&self, c: f64) -> f64 {
        let c = c.clamp(self.b[0], self.b[6]);
        let j = (0..6).rev().find(|&j| self.b[j] <= c).unwrap_or(0);
        let w = self.b[j + 1] - self.b[j];
        if w > 0.0 {
            self.cubic(j, ((c - self.b[j]) / w).min(1.0)).0
        } else {
            self.value[j]
        }
    }

    /// The root of `F`: the left end of the footprint's centroid.
    ///
    /// `F(b_0) ≥ 0 ≥ F(b_6)` and `F` decreases, so the root lies on the first
    /// piece whose right end has `F < 0`; there the cubic `p` decreases from
    /// `p(0) ≥ 0` to `p(1) < 0` and Newton's method, started at the secant
    /// point and kept inside a shrinking bracket (bisection when a step would
    /// leave it), finds `s` to about one unit in the last place: the answer is
    /// `b_j + w·s`. A footprint of zero upper area (impossible here: the
    /// support has width 1) would have no root and gives `b_6`.
    pub(crate) fn root(&self) -> f64 {
        let Some(j) = (0..6).find(|&j| self.value[j + 1] < 0.0) else {
            return self.b[6];
        };
        let w = self.b[j + 1] - self.b[j];
        let (p0, p1) = (self.value[j], self.cubic(j, 1.0).0);
        if p0 <= 0.0 {
            return self.b[j];
        }
        if p1 >= 0.0 {
            return self.b[j + 1];
        }
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        let mut s = p0 / (p0 - p1);
        // Quadratic convergence needs a handful of steps; bisection alone
        // would need 53. The bound only guards against a cycle.
        for _ in 0..100 {
            let (v, d) = self.cubic(j, s);
            if v == 0.0 {
                break;
            }
            if v > 0.0 {
                lo = s;
            } else {
                hi = s;
            }
            let newton = s - v / d;
            let next = if d < 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let done = (next - s).abs() <= f64::EPSILON || hi - lo <= f64::EPSILON;
            s = next;
            if done {
                break;
            }
        }
        (self.b[j] + w * s).clamp(self.b[j], self.b[j + 1])
    }
}

/// The centroid `[c_l, c_r]` of a footprint in local coordinates: `c_l` the
/// root of its Karnik–Mendel function, `c_r` minus the root of its mirror's
/// (swapping `upper` and `lower` in `F` is the same as mirroring `x`).
pub(crate) fn centroid(fp: &Footprint) -> [f64; 2] {
    let left = KmFunction::new(fp).root();
    let right = -KmFunction::new(&fp.mirrored()).root();
    // The exact ends satisfy c_l ≤ c_r; a thin footprint could swap them by
    // rounding.
    [left.min(right), right.max(left)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn number() -> Nt2Number {
        Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6).unwrap()
    }

    /// `F` straight from its definition, by composite Simpson's rule on the
    /// pieces (exact for the cubic integrands `(x − c)·linear`).
    fn km_by_quadrature(fp: &Footprint, c: f64) -> f64 {
        let b = fp.breakpoints();
        let mut total = 0.0;
        for k in 0..6 {
            let (a, e) = (b[k], b[k + 1]);
            let f = |x: f64, which: &[[f64; 2]; 6]| {
                let [f0, f1] = which[k];
                if e > a {
                    f0 + (f1 - f0) * (x - a) / (e - a)
                } else {
                    f0
                }
            };
            // Split the piece at c: upper left of it, lower right of it.
            let mut segment = |lo: f64, hi: f64, which: &[[f64; 2]; 6]| {
                if hi > lo {
                    let m = (lo + hi) / 2.0;
                    total += (hi - lo) / 6.0
                        * ((lo - c) * f(lo, which)
                            + 4.0 * (m - c) * f(m, which)
                            + (hi - c) * f(hi, which));
                }
            };
            segment(a, e.min(c), &fp.upper);
            segment(a.max(c), e, &fp.lower);
        }
        total
    }

    #[test]
    fn taylor_form_matches_the_definition() {
        let x = number();
        let frame = Frame::of(&x).unwrap();
        let b = frame.breakpoints(&x);
        let t = Triangles::new(&b, x.height().get());
        for z in [0.0, 0.3, 1.0] {
            let fp = Footprint::plane(&b, &t, z);
            let km = KmFunction::new(&fp);
            for i in 0..=40 {
                let c = b[0] + (b[6] - b[0]) * f64::from(i) / 40.0;
                let (ours, direct) = (km.eval(c), km_by_quadrature(&fp, c));
                assert!(
                    (ours - direct).abs() < 1e-15,
                    "z {z}, c {c}: {ours} vs {direct}"
                );
            }
        }
    }

    #[test]
    fn root_is_a_zero_of_f() {
        let x = number();
        let frame = Frame::of(&x).unwrap();
        let b = frame.breakpoints(&x);
        let fp = Footprint::plane(&b, &Triangles::new(&b, 0.6), 0.0);
        let km = KmFunction::new(&fp);
        let c = km.root();
        // |F'| ≥ the lower area, so |F(c)| ≤ 1e-16 puts c within about 1e-15.
        assert!(km.eval(c).abs() < 1e-16, "F({c}) = {}", km.eval(c));
    }

    #[test]
    fn mirror_twice_is_identity() {
        let x = number();
        let frame = Frame::of(&x).unwrap();
        let b = frame.breakpoints(&x);
        let fp = Footprint::plane(&b, &Triangles::new(&b, 0.6), 0.4);
        let back = fp.mirrored().mirrored();
        assert_eq!(back.b, fp.b);
        assert_eq!(back.upper, fp.upper);
        assert_eq!(back.lower, fp.lower);
    }
}
