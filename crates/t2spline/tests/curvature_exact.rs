//! The curvature of rational Bézier curves against exact rational
//! arithmetic (`num-rational`), on the cases where a careless formula loses
//! every digit: nearly straight parts, the neighbourhood of an inflection,
//! and the neighbourhood of a cusp (a speed near 0, a curvature near ∞).
//!
//! The reference shares no code with the library. A Bézier curve of degree
//! `n` with points `Pᵢ` and weights `wᵢ` is `C = A / W`, `A = Σ Bᵢ wᵢ Pᵢ`,
//! `W = Σ Bᵢ wᵢ` (Bernstein `Bᵢ`), so by the quotient rule
//!
//! ```text
//! C'  = (A' − W' C) / W
//! C'' = (A'' − 2 W' C' − W'' C) / W
//! κ²  = ‖C' ∧ C''‖² / ‖C'‖⁶
//! ```
//! all exact at a parameter that is an `f64` (every `f64` is a rational).
//!
//! What can be asked of `f64`: the derivatives themselves carry a rounding
//! of `u‖C'‖` and `u‖C''‖` (`u = 2⁻⁵³`), so the wedge carries about
//! `u‖C'‖‖C''‖` whatever the formula; its relative error is that over
//! `‖C' ∧ C''‖`, the condition number `‖C'‖‖C''‖ / ‖C' ∧ C''‖` times `u`. The
//! tests ask for 1e-12 relative wherever that condition number is at most
//! 1e3, and on nearly straight parts beyond it, where the components of the
//! derivatives carry their own small relative errors and the minors
//! `x'y'' − y'x''` do not cancel: there the form
//! √(‖C'‖²‖C''‖² − (C'·C'')²) cancels to 0 and keeps no digit.

use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use proptest::prelude::*;
use t2spline::{strategies, NurbsCurve};

type Q = BigRational;

fn q(x: f64) -> Q {
    Q::from_float(x).expect("finite")
}

/// `(C', C'')` of the rational Bézier curve at `t`, exactly.
fn exact_derivatives(points: &[[f64; 2]], weights: &[f64], t: f64) -> ([Q; 2], [Q; 2]) {
    let n = points.len() - 1;
    let t = q(t);
    let s = Q::one() - &t;
    // Bernstein polynomials of degree m at t, and their first two
    // derivatives from the differences of the coefficients.
    let bernstein = |m: usize| -> Vec<Q> {
        (0..=m)
            .map(|i| {
                let binom = (0..i).fold(Q::one(), |b, k| {
                    b * Q::from_integer((m - k).into()) / Q::from_integer((k + 1).into())
                });
                binom * pow(&t, i) * pow(&s, m - i)
            })
            .collect()
    };
    // Homogeneous coefficients (w x, w y, w).
    let h: Vec<[Q; 3]> = points
        .iter()
        .zip(weights)
        .map(|(p, &w)| [q(w) * q(p[0]), q(w) * q(p[1]), q(w)])
        .collect();
    let diff = |c: &[[Q; 3]]| -> Vec<[Q; 3]> {
        c.windows(2)
            .map(|w| std::array::from_fn(|k| &w[1][k] - &w[0][k]))
            .collect()
    };
    let combine = |c: &[[Q; 3]], b: &[Q], scale: Q| -> [Q; 3] {
        std::array::from_fn(|k| {
            c.iter()
                .zip(b)
                .fold(Q::zero(), |acc, (ci, bi)| acc + &ci[k] * bi)
                * &scale
        })
    };
    let nq = Q::from_integer(n.into());
    let h0 = combine(&h, &bernstein(n), Q::one());
    let d1 = diff(&h);
    let h1 = combine(&d1, &bernstein(n - 1), nq.clone());
    let h2 = if n >= 2 {
        let scale = nq.clone() * Q::from_integer((n - 1).into());
        combine(&diff(&d1), &bernstein(n - 2), scale)
    } else {
        std::array::from_fn(|_| Q::zero())
    };
    let w = &h0[2];
    let c: [Q; 2] = std::array::from_fn(|k| &h0[k] / w);
    let c1: [Q; 2] = std::array::from_fn(|k| (&h1[k] - &h1[2] * &c[k]) / w);
    let c2: [Q; 2] = std::array::from_fn(|k| {
        (&h2[k] - Q::from_integer(2.into()) * &h1[2] * &c1[k] - &h2[2] * &c[k]) / w
    });
    (c1, c2)
}

fn pow(x: &Q, k: usize) -> Q {
    (0..k).fold(Q::one(), |p, _| p * x)
}

/// κ exactly (as the nearest `f64` of κ², rooted) and the condition number
/// `‖C'‖‖C''‖ / ‖C' ∧ C''‖` (∞ where the wedge is 0).
fn exact_curvature(points: &[[f64; 2]], weights: &[f64], t: f64) -> (f64, f64) {
    let (a, b) = exact_derivatives(points, weights, t);
    let wedge = &a[0] * &b[1] - &a[1] * &b[0];
    let a2 = &a[0] * &a[0] + &a[1] * &a[1];
    let b2 = &b[0] * &b[0] + &b[1] * &b[1];
    // κ = (|wedge| / ‖C'‖²) / ‖C'‖, each factor rounded once (no
    // underflow of κ² for κ down to 1e-200).
    let ratio = (num_traits::Signed::abs(&wedge) / &a2)
        .to_f64()
        .expect("finite");
    let kappa = ratio / a2.to_f64().expect("finite").sqrt();
    let condition = if wedge.is_zero() {
        f64::INFINITY
    } else {
        ((a2 * b2) / (&wedge * &wedge))
            .to_f64()
            .expect("finite")
            .sqrt()
    };
    (kappa, condition)
}

fn bezier(points: &[[f64; 2]], weights: &[f64]) -> NurbsCurve<2> {
    NurbsCurve::try_clamped(points.len() - 1, points.to_vec(), weights.to_vec()).expect("a curve")
}

fn assert_close(points: &[[f64; 2]], weights: &[f64], t: f64, tolerance: f64) {
    let (kappa, condition) = exact_curvature(points, weights, t);
    let got = bezier(points, weights).curvature(t).expect("regular");
    assert!(
        condition <= 1e3,
        "the case is ill-conditioned ({condition:e}); choose another"
    );
    assert!(
        (got - kappa).abs() <= tolerance * kappa,
        "{points:?} {weights:?} t = {t}: {got:e} against {kappa:e} (condition {condition:e})"
    );
}

#[test]
fn nearly_straight_parts_keep_every_digit() {
    // The last point lifted by e off the line: C' = 2(1 + t, t e) and
    // C'' = 2(1, e), so the wedge is 4e while ‖C'‖‖C''‖ is about 4. The
    // norm-wise condition is about 1/e, yet nothing cancels component by
    // component (the minor is 4(1 + t)e − 4te): the library's minors keep
    // every digit down to e = 1e-200, where the other form gives 0.
    for e in [1e-3, 1e-9, 1e-15, 1e-100, 1e-200] {
        for t in [0.0, 0.25, 0.5, 1.0] {
            let points = [[0.0, 0.0], [1.0, 0.0], [3.0, e]];
            let (kappa, _) = exact_curvature(&points, &[1.0; 3], t);
            let got = bezier(&points, &[1.0; 3]).curvature(t).expect("regular");
            assert!(
                (got - kappa).abs() <= 1e-12 * kappa,
                "e = {e}, t = {t}: {got:e} against {kappa:e}"
            );
        }
    }
}

#[test]
fn next_to_an_inflection() {
    // An S-shaped cubic: the curvature crosses 0 at t = 1/2. At a distance
    // δ the wedge is about δ times the product of the speeds, so the
    // condition is about 1/δ: 1e-12 holds down to δ = 1e-3.
    let points = [[0.0, 0.0], [1.0, 1.0], [2.0, -1.0], [3.0, 0.0]];
    for weights in [[1.0; 4], [1.0, 2.0, 0.5, 1.0]] {
        for delta in [0.25, 0.1, 1e-2, 2e-3] {
            for t in [0.5 - delta, 0.5 + delta] {
                assert_close(&points, &weights, t, 1e-12);
            }
        }
    }
    // At the inflection itself the exact curvature is 0 and the library's
    // is rounding of the size u‖C''‖ / ‖C'‖².
    let got = bezier(&points, &[1.0; 4]).curvature(0.5).expect("regular");
    assert!(got.abs() <= 1e-14, "{got:e}");
}

#[test]
fn next_to_a_cusp() {
    // P₁ close to P₀: the speed at t = 0 is 2ε, the curvature 1 / (2ε²)
    // (huge), and the condition about 1.4 for t up to a tenth of ε (beyond
    // it C' turns along C'').
    for eps in [1e-2, 1e-4, 1e-6, 1e-8] {
        let points = [[0.0, 0.0], [eps, 0.0], [1.0, 1.0]];
        for t in [0.0, eps / 1e3, eps / 10.0] {
            assert_close(&points, &[1.0; 3], t, 1e-12);
        }
        let (kappa, _) = exact_curvature(&points, &[1.0; 3], 0.0);
        assert!((kappa - 0.5 / (eps * eps)).abs() <= 1e-9 * kappa);
    }
    // A cubic whose polygon folds back: the curve has a cusp between the
    // two middle points when they swap; just before, the speed is small
    // and the curvature large.
    for gap in [1e-2, 1e-3] {
        let points = [[0.0, 0.0], [1.0 + gap, 1.0], [-gap, 1.0], [1.0, 0.0]];
        for t in [0.3, 0.45, 0.5, 0.55, 0.7] {
            let (_, condition) = exact_curvature(&points, &[1.0; 4], t);
            if condition <= 1e3 {
                assert_close(&points, &[1.0; 4], t, 1e-12);
            }
        }
    }
}

proptest! {
    #![proptest_config(strategies::cases(64, 1000))]
    /// Random rational Bézier curves of degree 2 to 5, weights from 0.1 to
    /// 10, at random parameters: 1e-12 relative wherever the condition is
    /// at most 1e2 (the quotient rule of the weights adds its own rounding:
    /// at a condition of 1e3, 1.5e-12 was seen in 5 000 cases).
    #[test]
    fn random_rational_curves_match_exact_arithmetic(
        points in prop::collection::vec([-10.0..10.0f64, -10.0..10.0f64], 3..=6),
        weights in prop::collection::vec(0.1..10.0f64, 6),
        t in 0.0..=1.0f64,
    ) {
        let weights = &weights[..points.len()];
        let (kappa, condition) = exact_curvature(&points, weights, t);
        prop_assume!(condition <= 1e2 && kappa > 0.0);
        let got = bezier(&points, weights).curvature(t);
        prop_assert!(got.is_ok());
        let got = got.unwrap();
        prop_assert!((got - kappa).abs() <= 1e-12 * kappa, "{} against {}", got, kappa);
    }
}
