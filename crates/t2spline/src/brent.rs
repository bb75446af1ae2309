//! The minimum of a function of one variable in a bracket by Brent's method:
//! golden sections sped up by parabolic interpolation (R. P. Brent,
//! *Algorithms for Minimization without Derivatives*, 1973, ch. 5; Press et
//! al., *Numerical Recipes*, §10.3), for the distance's maximum
//! ([`crate::Distance`]).

/// `(3 − √5)/2`, one minus the golden ratio's inverse: the golden step into the
/// larger part.
const STEP: f64 = 0.381_966_011_250_105_1;

/// The smallest value of `f` found on `[lo, hi]` by Brent's method, as
/// `(f(t), t)`, starting from a point `(x, f(x))` inside the bracket with
/// `f(x)` no larger than at its ends.
///
/// Each step fits a parabola through the three best points and goes to its
/// vertex when that lies well inside the bracket and the step shrinks fast
/// enough; otherwise it takes a golden section of the larger part. It ends
/// when the best point lies within `tolerance` (at least 4 units in the last
/// place) of the middle of a bracket of width `4·tolerance`, or after 100
/// steps. Near a smooth minimum the parabolic steps converge superlinearly: a
/// dozen evaluations where golden sections need forty. Probes stay inside the
/// starting bracket.
pub(crate) fn brent_min(
    mut f: impl FnMut(f64) -> f64,
    [mut lo, mut hi]: [f64; 2],
    (mut x, mut fx): (f64, f64),
    tolerance: f64,
) -> (f64, f64) {
    let (a, b) = (lo, hi);
    // The best point x, the second best w, the previous w as v.
    let (mut w, mut fw, mut v, mut fv) = (x, fx, x, fx);
    // The step before last (e) and the last step (d).
    let (mut d, mut e) = (0.0_f64, 0.0_f64);
    for _ in 0..100 {
        let middle = lo + (hi - lo) / 2.0;
        let tol = tolerance.max(4.0 * f64::EPSILON * x.abs());
        if (x - middle).abs() <= 2.0 * tol - (hi - lo) / 2.0 {
            break;
        }
        let mut golden = true;
        if e.abs() > tol {
            // The vertex of the parabola through (x, fx), (w, fw), (v, fv),
            // as x + p/q.
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let previous = e;
            e = d;
            // Accept only a step inside the bracket and less than half the
            // step before last.
            if p.abs() < (0.5 * q * previous).abs() && p > q * (lo - x) && p < q * (hi - x) {
                d = p / q;
                let u = x + d;
                if u - lo < 2.0 * tol || hi - u < 2.0 * tol {
                    d = tol.copysign(middle - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= middle { lo - x } else { hi - x };
            d = STEP * e;
        }
        let u = if d.abs() >= tol {
            x + d
        } else {
            x + tol.copysign(d)
        }
        .clamp(a, b);
        let fu = f(u);
        if fu <= fx {
            if u >= x {
                lo = x;
            } else {
                hi = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                lo = u;
            } else {
                hi = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    (fx, x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::golden_section::golden_section_min;

    #[test]
    fn brent_finds_the_vertex_in_few_evaluations() {
        // (t − 0.3)² + 2 on [−1, 4]: a parabola is fitted exactly.
        let calls = std::cell::Cell::new(0);
        let f = |t: f64| {
            calls.set(calls.get() + 1);
            (t - 0.3) * (t - 0.3) + 2.0
        };
        let (v, t) = brent_min(f, [-1.0, 4.0], (0.0, f(0.0)), 1e-12);
        assert!((t - 0.3).abs() < 1e-7 && v == 2.0, "{t} {v}");
        // A smooth, non-parabolic peak: −cos near 0, from an offset start.
        calls.set(0);
        let g = |t: f64| {
            calls.set(calls.get() + 1);
            -(t - 0.123).cos() / (1.0 + t * t)
        };
        let (v, t) = brent_min(g, [-0.5, 0.5], (0.0, g(0.0)), 1e-10);
        let brent = calls.replace(0);
        let (gv, gt) = golden_section_min(g, [-0.5, 0.5], 1e-10);
        let golden = calls.get();
        assert!(
            (v - gv).abs() <= 2.0 * f64::EPSILON && (t - gt).abs() < 1e-7,
            "{t} {gt}"
        );
        assert!(
            brent <= 20 && golden >= 45,
            "{brent} and {golden} evaluations"
        );
    }

    #[test]
    fn brent_keeps_probes_inside_and_ends_on_a_monotone_function() {
        let (lo, hi) = (1.0, 2.0);
        let (v, t) = brent_min(
            |t| {
                assert!((lo..=hi).contains(&t), "{t}");
                t
            },
            [lo, hi],
            (lo, lo),
            1e-13,
        );
        assert_eq!((v, t), (lo, lo));
        let (lo, hi) = (0.0, 1.354e-321);
        let (_, t) = brent_min(
            |t| {
                assert!((lo..=hi).contains(&t), "{t}");
                -t
            },
            [lo, hi],
            (hi / 2.0, -hi / 2.0),
            0.0,
        );
        assert!((lo..=hi).contains(&t));
    }
}
