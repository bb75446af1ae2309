//! The roots of a polynomial on `[0, 1]` in Bernstein form. The number of
//! sign changes of the Bernstein coefficients bounds the number of roots
//! (Descartes' rule of signs in the Bernstein basis, Farouki and Rajan
//! 1988): none for one strict sign, exactly one for a single change. With
//! more, the roots of the derivative (the same way, one degree lower) cut
//! `[0, 1]` into pieces where the polynomial is monotone, each holding a
//! root exactly where the values at its ends differ in sign. Each root is
//! found by Newton's method kept inside a bracket that shrinks with each
//! step (bisection where a step would leave it), to `10⁻¹⁵`.

/// The value at `s` by de Casteljau's algorithm (on the stack up to 16
/// coefficients).
fn eval(c: &[f64], s: f64) -> f64 {
    let n = c.len();
    let mut stack = [0.0; 16];
    let mut heap = Vec::new();
    let b: &mut [f64] = if n <= 16 {
        &mut stack[..n]
    } else {
        heap.resize(n, 0.0);
        &mut heap
    };
    b.copy_from_slice(c);
    for r in 1..n {
        for j in 0..n - r {
            b[j] = (1.0 - s) * b[j] + s * b[j + 1];
        }
    }
    b.first().copied().unwrap_or(0.0)
}

/// The value and the first two derivatives at `s` by de Casteljau's
/// algorithm.
fn eval_and_slopes(c: &[f64], s: f64) -> (f64, f64, f64) {
    let n = c.len();
    if n < 3 {
        let (f, d) = eval_and_slope(c, s);
        return (f, d, 0.0);
    }
    let mut stack = [0.0; 16];
    let mut heap = Vec::new();
    let b: &mut [f64] = if n <= 16 {
        &mut stack[..n]
    } else {
        heap.resize(n, 0.0);
        &mut heap
    };
    b.copy_from_slice(c);
    for r in 1..n - 2 {
        for j in 0..n - r {
            b[j] = (1.0 - s) * b[j] + s * b[j + 1];
        }
    }
    let d = (n - 1) as f64;
    let second = d * (d - 1.0) * (b[2] - 2.0 * b[1] + b[0]);
    let (l, r) = ((1.0 - s) * b[0] + s * b[1], (1.0 - s) * b[1] + s * b[2]);
    ((1.0 - s) * l + s * r, d * (r - l), second)
}

/// The value and the slope at `s` by de Casteljau's algorithm.
fn eval_and_slope(c: &[f64], s: f64) -> (f64, f64) {
    let n = c.len();
    if n < 2 {
        return (c.first().copied().unwrap_or(0.0), 0.0);
    }
    let mut stack = [0.0; 16];
    let mut heap = Vec::new();
    let b: &mut [f64] = if n <= 16 {
        &mut stack[..n]
    } else {
        heap.resize(n, 0.0);
        &mut heap
    };
    b.copy_from_slice(c);
    for r in 1..n - 1 {
        for j in 0..n - r {
            b[j] = (1.0 - s) * b[j] + s * b[j + 1];
        }
    }
    ((1.0 - s) * b[0] + s * b[1], (n - 1) as f64 * (b[1] - b[0]))
}

/// The places in `(0, 1)` where the polynomial with Bernstein
/// coefficients `c` changes sign, increasing (a root of even multiplicity,
/// where it does not, may be listed too when rounding makes the values at
/// its sides differ in sign: harmless for splitting an integral).
pub(crate) fn sign_changes_in_unit(c: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    roots(c, &mut out);
    out
}

/// [`sign_changes_in_unit`] appended to `out`, for a polynomial given both ways: its Bernstein
/// coefficients `c` count the sign changes, its power coefficients `a`
/// (`Σ aₖ·sᵏ`, the same polynomial) give the values by Horner's rule, a
/// third of de Casteljau's work at degree 3.
pub(crate) fn sign_changes_power_into(c: &[f64], a: &[f64], out: &mut Vec<f64>) {
    roots_power(c, a, out);
}

/// The value of the power form `Σ aₖ·sᵏ` at `s` by Horner's rule.
pub(crate) fn horner(a: &[f64], s: f64) -> f64 {
    a.iter().rev().fold(0.0, |v, &x| v * s + x)
}

fn roots_power(c: &[f64], a: &[f64], out: &mut Vec<f64>) {
    let n = c.len();
    let changes = sign_changes(c);
    if changes == 0 || n < 2 || a.len() != n {
        return;
    }
    let (first, last) = (c[0], c[n - 1]);
    if changes == 1 && first != 0.0 && last != 0.0 {
        // Start where the chord through the ends crosses zero.
        let chord = first / (first - last);
        let start = if chord > 0.0 && chord < 1.0 {
            chord
        } else {
            0.5
        };
        out.push(bracketed_by(
            |x| horner_slope(a, x),
            [0.0, 1.0],
            first > 0.0,
            start,
        ));
        return;
    }
    // Monotone pieces between the derivative's sign changes (as `roots`).
    let degree = (n - 1) as f64;
    let slope: Vec<f64> = c.windows(2).map(|w| degree * (w[1] - w[0])).collect();
    let slope_power: Vec<f64> = a
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, x)| k as f64 * x)
        .collect();
    let mut ends = vec![0.0];
    roots_power(&slope, &slope_power, &mut ends);
    ends.push(1.0);
    let mut previous = (0.0, first);
    for &x in &ends[1..] {
        let fx = if x == 1.0 { last } else { horner(a, x) };
        let (lo, fa) = previous;
        if x > lo && fa != 0.0 && fx != 0.0 && (fa > 0.0) != (fx > 0.0) {
            let guess = |e: f64, toward: f64| {
                let (f, _, f2) = horner_slopes(a, e);
                e + toward * (-2.0 * f / f2).sqrt()
            };
            let start = if fa.abs() <= fx.abs() && lo > 0.0 {
                guess(lo, 1.0)
            } else if x < 1.0 {
                guess(x, -1.0)
            } else {
                0.5 * (lo + x)
            };
            let start = if start > lo && start < x {
                start
            } else {
                0.5 * (lo + x)
            };
            out.push(bracketed_by(
                |t| horner_slope(a, t),
                [lo, x],
                fa > 0.0,
                start,
            ));
        } else if fx == 0.0 && x > 0.0 && x < 1.0 {
            out.push(x);
        }
        previous = (x, fx);
    }
}

/// The value and the slope of the power form at `s` by Horner's rule.
fn horner_slope(a: &[f64], s: f64) -> (f64, f64) {
    a.iter()
        .rev()
        .fold((0.0, 0.0), |(v, d), &x| (v * s + x, d * s + v))
}

/// The value and the first two derivatives of the power form at `s`.
fn horner_slopes(a: &[f64], s: f64) -> (f64, f64, f64) {
    a.iter().rev().fold((0.0, 0.0, 0.0), |(v, d, d2), &x| {
        (v * s + x, d * s + v, d2 * s + 2.0 * d)
    })
}

fn sign_changes(c: &[f64]) -> usize {
    let mut last = 0.0;
    let mut count = 0;
    for &x in c {
        if x != 0.0 {
            if last != 0.0 && (x > 0.0) != (last > 0.0) {
                count += 1;
            }
            last = x;
        }
    }
    count
}

fn roots(c: &[f64], out: &mut Vec<f64>) {
    let n = c.len();
    let changes = sign_changes(c);
    if changes == 0 || n < 2 {
        return;
    }
    let (first, last) = (c[0], c[n - 1]);
    if changes == 1 && first != 0.0 && last != 0.0 {
        // Start where the chord through the ends crosses zero.
        let chord = first / (first - last);
        let start = if chord > 0.0 && chord < 1.0 {
            chord
        } else {
            0.5
        };
        out.push(bracketed(c, [0.0, 1.0], first > 0.0, start));
        return;
    }
    // Monotone pieces between the derivative's sign changes.
    let degree = (n - 1) as f64;
    let slope: Vec<f64> = c.windows(2).map(|w| degree * (w[1] - w[0])).collect();
    let mut ends = vec![0.0];
    roots(&slope, &mut ends);
    ends.push(1.0);
    let mut previous = (0.0, first);
    for &x in &ends[1..] {
        let fx = if x == 1.0 { last } else { eval(c, x) };
        let (a, fa) = previous;
        if x > a && fa != 0.0 && fx != 0.0 && (fa > 0.0) != (fx > 0.0) {
            // Start from the quadratic model at the end that is a
            // critical point (the one nearer the root where two roots are
            // close): f(e) + f''(e)·(x − e)²/2 = 0.
            let guess = |e: f64, toward: f64| {
                let (f, _, f2) = eval_and_slopes(c, e);
                e + toward * (-2.0 * f / f2).sqrt()
            };
            let start = if fa.abs() <= fx.abs() && a > 0.0 {
                guess(a, 1.0)
            } else if x < 1.0 {
                guess(x, -1.0)
            } else {
                0.5 * (a + x)
            };
            let start = if start > a && start < x {
                start
            } else {
                0.5 * (a + x)
            };
            out.push(bracketed(c, [a, x], fa > 0.0, start));
        } else if fx == 0.0 && x > 0.0 && x < 1.0 {
            out.push(x);
        }
        previous = (x, fx);
    }
}

/// The one root in `[lo, hi]`, where the polynomial is positive at `lo`
/// exactly when `positive_at_lo`.
fn bracketed(c: &[f64], bracket: [f64; 2], positive_at_lo: bool, start: f64) -> f64 {
    bracketed_by(|x| eval_and_slope(c, x), bracket, positive_at_lo, start)
}

/// [`bracketed`] with the value and slope from `f`.
fn bracketed_by(
    f: impl Fn(f64) -> (f64, f64),
    [mut lo, mut hi]: [f64; 2],
    positive_at_lo: bool,
    start: f64,
) -> f64 {
    let mut x = start;
    for _ in 0..200 {
        let (f, slope) = f(x);
        if f == 0.0 {
            return x;
        }
        if (f > 0.0) == positive_at_lo {
            lo = x;
        } else {
            hi = x;
        }
        let step = f / slope;
        if step.abs() <= 1e-15 {
            return (x - step).clamp(lo, hi);
        }
        let mut next = x - step;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if hi - lo <= 1e-15 || next <= lo || next >= hi {
            return next.clamp(lo, hi);
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_a_cubic_with_three_sign_changes() {
        // (s − 0.2)(s − 0.5)(s − 0.9) in Bernstein form, from its values at
        // 0, 1/3, 2/3, 1 by the inverse of the Bernstein matrix.
        let f = |s: f64| (s - 0.2) * (s - 0.5) * (s - 0.9);
        // Power to Bernstein: a + b s + c s² + d s³.
        let (a, b, c, d) = (-0.09, 0.73, -1.6, 1.0);
        let beta = [a, a + b / 3.0, a + 2.0 * b / 3.0 + c / 3.0, a + b + c + d];
        assert!((eval(&beta, 0.3) - f(0.3)).abs() < 1e-15);
        let r = sign_changes_in_unit(&beta);
        assert_eq!(r.len(), 3, "{r:?}");
        for (x, want) in r.iter().zip([0.2, 0.5, 0.9]) {
            assert!((x - want).abs() < 1e-14, "{r:?}");
        }
        // The same by Horner's rule on the power form.
        let mut p = Vec::new();
        sign_changes_power_into(&beta, &[a, b, c, d], &mut p);
        assert_eq!(p.len(), 3, "{p:?}");
        for (x, y) in p.iter().zip(&r) {
            assert!((x - y).abs() < 1e-14, "{p:?}");
        }
        assert!((horner(&[a, b, c, d], 0.3) - f(0.3)).abs() < 1e-15);
    }
}
