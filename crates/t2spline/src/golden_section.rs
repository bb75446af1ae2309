//! The minimum of a function of one variable in a bracket by golden-section
//! search (Kiefer 1953; Press et al., *Numerical Recipes*, §10.2), for the
//! closest point ([`crate::NurbsCurve::closest_point`]) and the peaks of
//! membership in the set view; Brent's method, which
//! speeds it up by parabolic steps, is in [`crate::brent`].

/// `(√5 − 1)/2`: each step keeps this fraction of the bracket.
const RATIO: f64 = 0.618_033_988_749_894_9;

/// The smallest value of `f` found on `[lo, hi]` by golden-section search,
/// assuming one valley there, as `(f(t), t)`.
///
/// The bracket shrinks by [`RATIO`] per evaluation until it is no wider than
/// `tolerance` (at most 200 steps). Every probe is kept inside the starting
/// bracket, so rounding in a bracket a few subnormal units wide cannot take it
/// out of the domain (found by fuzzing).
pub(crate) fn golden_section_min(
    mut f: impl FnMut(f64) -> f64,
    [mut lo, mut hi]: [f64; 2],
    tolerance: f64,
) -> (f64, f64) {
    let (a, b) = (lo, hi);
    let inside = |x: f64| x.clamp(a, b);
    let (mut x1, mut x2) = (
        inside(hi - RATIO * (hi - lo)),
        inside(lo + RATIO * (hi - lo)),
    );
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..200 {
        if hi - lo <= tolerance {
            break;
        }
        if f1 <= f2 {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = inside(hi - RATIO * (hi - lo));
            f1 = f(x1);
        } else {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = inside(lo + RATIO * (hi - lo));
            f2 = f(x2);
        }
    }
    if f1 <= f2 {
        (f1, x1)
    } else {
        (f2, x2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_is_the_golden_section() {
        assert!((RATIO - (5f64.sqrt() - 1.0) / 2.0).abs() <= f64::EPSILON);
    }

    #[test]
    fn finds_the_vertex_of_a_parabola() {
        // (t − 0.3)² + 2 on [−1, 4]: minimum 2 at 0.3.
        let (v, t) = golden_section_min(|t| (t - 0.3) * (t - 0.3) + 2.0, [-1.0, 4.0], 1e-12);
        assert!((t - 0.3).abs() < 1e-7, "{t}");
        assert!((v - 2.0).abs() < 1e-14, "{v}");
    }

    #[test]
    fn a_monotone_function_ends_at_the_low_end() {
        let (v, t) = golden_section_min(|t| t, [1.0, 2.0], 1e-13);
        assert!((1.0..1.0 + 1e-12).contains(&t), "{t}");
        assert_eq!(v, t);
    }

    #[test]
    fn probes_stay_inside_a_subnormal_bracket() {
        let (lo, hi) = (0.0, 1.354e-321);
        let (_, t) = golden_section_min(
            |t| {
                assert!((lo..=hi).contains(&t), "{t}");
                -t
            },
            [lo, hi],
            0.0,
        );
        assert!((lo..=hi).contains(&t));
    }
}
