//! The promises of the core crate on arbitrary input, as one function of raw
//! bytes: used by the libFuzzer target `fuzz/fuzz_targets/curve.rs` (which
//! includes this file) and by the proptest run over arbitrary bytes in
//! `tests/arbitrary_bytes.rs` (which runs in CI).
//!
//! The bytes are decoded into a degree, control points, weights, knots,
//! parameters, a level and fuzzy numbers; the decoder favours values that make
//! the constructors succeed (small numbers, sorted knots, ordered fuzzy values)
//! but also yields NaN, infinities, subnormals and values past the limits.
//! Whatever the constructors accept must then keep every promise:
//!
//! - no panic, anywhere;
//! - `eval` and `rational_basis` answer `Ok` exactly for parameters in the
//!   domain, with finite values, a basis that is non-negative and sums to 1,
//!   and points inside the box of the control points (convex hull);
//! - knot insertion keeps the curve (to rounding of the parameter where the
//!   curve is steep, and to about 1e-308 divided by the smallest weight for
//!   tiny coordinates); derivatives, degree elevation, splitting,
//!   the closest point and arc lengths return without panicking;
//! - the fuzzy curve's seven layers stay ordered and finite, and every stage
//!   and the distance are finite, with `rms ≤ max`.

#![allow(dead_code)]

use t2spline::{Alpha, FuzzyCurve, KnotVector, Layer, Nt2Number, Nt2Point, NurbsCurve, Side};

/// Reads values from the fuzzer's bytes; past the end everything is 0.
pub struct Bytes<'a>(pub &'a [u8]);

impl Bytes<'_> {
    pub fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }

    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }

    pub fn u64(&mut self) -> u64 {
        u64::from(self.u16())
            | u64::from(self.u16()) << 16
            | u64::from(self.u16()) << 32
            | u64::from(self.u16()) << 48
    }

    /// A float: raw bits, a small multiple of 1/8, a power of ten with a sign
    /// anywhere from 1e-330 to 1e330, or one of the special values.
    pub fn f64(&mut self) -> f64 {
        match self.u8() % 5 {
            0 => f64::from_bits(self.u64()),
            1 | 4 => f64::from(self.u8() as i8) / 8.0,
            2 => {
                let e = f64::from(self.u16() % 661) - 330.0;
                let m = 1.0 + f64::from(self.u8()) / 64.0;
                let s = if self.u8() % 2 == 0 { 1.0 } else { -1.0 };
                s * m * 10f64.powf(e)
            }
            _ => [
                0.0,
                -0.0,
                1.0,
                1e300,
                -1e300,
                1e-300,
                f64::MIN_POSITIVE,
                f64::from_bits(1),
                f64::MAX,
                f64::INFINITY,
                f64::NAN,
                1e150,
                -1e-150,
            ][usize::from(self.u8()) % 13],
        }
    }

    /// A positive weight, mostly in range.
    pub fn weight(&mut self) -> f64 {
        match self.u8() % 4 {
            0 => self.f64(),
            1 => 10f64.powf(f64::from(self.u16() % 601) - 300.0),
            _ => 0.25 + f64::from(self.u8()) / 32.0,
        }
    }
}

/// Tolerance for values computed from numbers of magnitude up to `scale`.
fn tol(scale: f64) -> f64 {
    1e-12 * scale.max(f64::MIN_POSITIVE)
}

/// The parameters to visit: the decoded ones, every knot, the ends of the
/// domain and the floats just beside them (just outside must be an error).
fn parameters(b: &mut Bytes, u: &[f64], domain: t2spline::Domain) -> Vec<f64> {
    let mut t: Vec<f64> = (0..usize::from(b.u8() % 6)).map(|_| b.f64()).collect();
    t.extend((0..4).map(|_| domain.lerp(f64::from(b.u8()) / 255.0)));
    t.extend(u.iter().copied());
    for x in [domain.start, domain.end] {
        t.push(x);
        t.push(f64::from_bits(x.to_bits().wrapping_add(1)));
        t.push(f64::from_bits(x.to_bits().wrapping_sub(1)));
    }
    t
}

/// Decodes a crisp curve and checks it. Returns whether the curve was valid.
pub fn check_curve(b: &mut Bytes) -> bool {
    let degree = usize::from(b.u8() % 7);
    let n = degree + 1 + usize::from(b.u8() % 10);
    let points: Vec<[f64; 2]> = (0..n).map(|_| [b.f64(), b.f64()]).collect();
    let weights: Vec<f64> = (0..n).map(|_| b.weight()).collect();
    let mut knots: Vec<f64> = (0..n + degree + 1).map(|_| b.f64()).collect();
    let clamped_default = b.u8() % 4 == 0;
    if b.u8() % 4 != 0 {
        knots.sort_by(f64::total_cmp);
    }
    let curve = if clamped_default {
        NurbsCurve::try_clamped(degree, points, weights)
    } else {
        KnotVector::try_new(knots, degree, n).and_then(|u| NurbsCurve::try_new(points, weights, u))
    };
    let Ok(c) = curve else {
        return false;
    };
    let domain = c.domain();
    let u = c.knots().as_slice().to_vec();
    let lo: Vec<f64> = (0..2)
        .map(|d| {
            c.control_points()
                .iter()
                .map(|p| p[d])
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    let hi: Vec<f64> = (0..2)
        .map(|d| {
            c.control_points()
                .iter()
                .map(|p| p[d])
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .collect();
    let scale = lo.iter().chain(&hi).fold(0.0f64, |m, x| m.max(x.abs()));
    let params = parameters(b, &u, domain);
    check_sampling(&c, &params, scale);
    for t in params {
        let inside = domain.contains(t);
        let p = c.eval(t);
        assert_eq!(p.is_ok(), inside, "eval({t:e}) in {domain:?}: {p:?}");
        let r = c.rational_basis(t);
        assert_eq!(r.is_ok(), inside, "rational_basis({t:e}): {r:?}");
        if let (Ok(p), Ok(r)) = (p, r) {
            for d in 0..2 {
                assert!(p[d].is_finite(), "C({t:e}) = {p:?}");
                assert!(
                    lo[d] - tol(scale) <= p[d] && p[d] <= hi[d] + tol(scale),
                    "C({t:e}) = {p:?} outside the box {lo:?}..{hi:?}"
                );
            }
            assert!(
                r.iter().all(|x| x.is_finite() && *x >= 0.0),
                "R({t:e}) = {r:?}"
            );
            let sum: f64 = r.iter().sum();
            assert!((sum - 1.0).abs() <= 1e-12, "Σ R({t:e}) = {sum}: {r:?}");
        }
        if inside {
            // Derivatives may legitimately overflow for narrow spans; they must
            // not panic.
            let _ = c.derivatives(t, usize::from(b.u8() % 4));
            let times = 1 + usize::from(b.u8() % 2);
            // Insertion works on homogeneous coordinates w·P: below the
            // smallest normal float, w·P loses its digits, so coordinates under
            // about 1e-308/w keep an absolute accuracy, not a relative one.
            let min_weight = c.weights().iter().copied().fold(f64::INFINITY, f64::min);
            let floor = 4.0 * f64::MIN_POSITIVE / min_weight;
            if let Ok(d) = c.insert_knot(t, times) {
                for s in [domain.start, t, domain.end, domain.lerp(0.37)] {
                    let a = c.eval(s).expect("in the domain");
                    let e = d.eval(s).expect("same domain");
                    // Insertion is backward stable: the new curve at `s` is the
                    // old one at a parameter within a few ulps of `s`. Where
                    // the curve is steep (extreme weights) that moves it more
                    // than the rounding of values alone would.
                    let step =
                        8.0 * f64::EPSILON * s.abs().max(domain.start.abs()).max(domain.end.abs());
                    let near = [(s - step).max(domain.start), (s + step).min(domain.end)];
                    for k in 0..2 {
                        let steep = near
                            .iter()
                            .map(|&n| (c.eval(n).expect("in the domain")[k] - a[k]).abs())
                            .fold(0.0, f64::max);
                        assert!(
                            (a[k] - e[k]).abs() <= tol(scale) * 16.0 + 2.0 * steep + floor,
                            "inserting {t:e} ×{times} moved C({s:e}): {a:?} → {e:?} (steepness {steep:e})"
                        );
                    }
                }
            }
            let _ = c.split_at(t);
        }
    }
    // The heavier operations on one input in sixteen, so that the fuzzer
    // keeps its pace (a noisy speed costs 30 000 quadrature nodes per length).
    if b.u8() % 16 == 0 {
        let _ = c.elevate_degree(usize::from(b.u8() % 3));
        let _ = c.closest_point([b.f64(), b.f64()]);
        let _ = c.bounding_box();
        let _ = c.arc_length();
        let _ = c.param_at_length(b.f64());
    }
    true
}

/// The sampling engine against `eval` at the parameters inside the domain,
/// sorted (walked span by span) and in the given order (searched).
fn check_sampling(c: &NurbsCurve<2>, params: &[f64], scale: f64) {
    let domain = c.domain();
    let given: Vec<f64> = params
        .iter()
        .copied()
        .filter(|&t| domain.contains(t))
        .collect();
    let mut sorted = given.clone();
    sorted.sort_by(f64::total_cmp);
    // Values below about 1e-308/w lose their digits in `w·P` (as in insertion).
    let min_weight = c.weights().iter().copied().fold(f64::INFINITY, f64::min);
    let floor = 4.0 * f64::MIN_POSITIVE / min_weight;
    for ts in [given, sorted] {
        let samples = c.sample_soa(&ts).expect("parameters in the domain");
        for (i, &t) in ts.iter().enumerate() {
            let e = c.eval(t).expect("in the domain");
            let a = samples.point(i).unwrap();
            for k in 0..2 {
                assert!(
                    a[k].is_finite() && (a[k] - e[k]).abs() <= tol(scale) * 16.0 + floor,
                    "sample at {t:e}: {a:?}, eval {e:?}, curve {c:?}"
                );
            }
        }
    }
}

/// A fuzzy number: seven values (sorted, mostly) and a height.
fn number(b: &mut Bytes) -> Result<Nt2Number, t2spline::Error> {
    let mut v: [f64; 7] = std::array::from_fn(|_| b.f64());
    if b.u8() % 8 != 0 {
        v.sort_by(f64::total_cmp);
    }
    let h = match b.u8() % 4 {
        0 => b.f64(),
        1 => 1.0,
        _ => f64::from(b.u8()) / 255.0,
    };
    Nt2Number::try_new(v[3], [v[0], v[6]], [v[1], v[5]], [v[2], v[4]], h)
}

/// Decodes a fuzzy curve and a level and checks every stage. Returns whether
/// the curve was valid.
pub fn check_fuzzy_curve(b: &mut Bytes) -> bool {
    let degree = usize::from(b.u8() % 5);
    let n = degree + 1 + usize::from(b.u8() % 6);
    let points: Result<Vec<Nt2Point<2>>, t2spline::Error> = (0..n)
        .map(|_| Ok(Nt2Point::new([number(b)?, number(b)?])))
        .collect();
    let weights: Vec<f64> = (0..n).map(|_| b.weight()).collect();
    let knots = if b.u8() % 2 == 0 {
        None
    } else {
        let mut u: Vec<f64> = (0..n + degree + 1).map(|_| b.f64()).collect();
        u.sort_by(f64::total_cmp);
        Some(u)
    };
    let Ok(points) = points else {
        return false;
    };
    let Ok(c) = FuzzyCurve::try_new(degree, points, weights, knots) else {
        return false;
    };
    let alpha = match b.u8() % 4 {
        0 => b.f64(),
        1 => 0.0,
        2 => 1.0,
        _ => f64::from(b.u8()) / 255.0,
    };
    let Ok(alpha) = Alpha::try_new(alpha) else {
        return true;
    };
    let s = c.solve(alpha);
    let d = s.distance();
    assert!(
        d.max.is_finite() && d.rms.is_finite() && d.max_at.is_finite(),
        "{d:?}"
    );
    assert!(d.rms <= d.max * (1.0 + 1e-12), "{d:?}");
    assert!(c.domain().contains(d.max_at), "{d:?}");
    let domain = c.domain();
    let u = c.knots().as_slice().to_vec();
    let curves = [
        s.defuzzified_curve(),
        s.type_reduced_curve(Side::Left),
        s.type_reduced_curve(Side::Right),
    ];
    for t in parameters(b, &u, domain) {
        let layers = c.eval_layers(t);
        assert_eq!(layers.is_ok(), domain.contains(t), "eval_layers({t:e})");
        let Ok(layers) = layers else {
            continue;
        };
        for k in 0..2 {
            let v: Vec<f64> = Layer::ALL.iter().map(|&l| layers[l][k]).collect();
            assert!(v.iter().all(|x| x.is_finite()), "layers at {t:e}: {v:?}");
            assert!(v.windows(2).all(|w| w[0] <= w[1]), "layers at {t:e}: {v:?}");
        }
        for curve in &curves {
            let p = curve.eval(t).expect("same domain");
            assert!(
                p.iter().all(|x| x.is_finite()),
                "stage curve at {t:e}: {p:?}"
            );
        }
    }
    true
}

/// Everything: a crisp curve, then a fuzzy curve, from the same bytes.
pub fn check_bytes(data: &[u8]) {
    let mut b = Bytes(data);
    check_curve(&mut b);
    check_fuzzy_curve(&mut b);
}
