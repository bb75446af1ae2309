//! The Nelder–Mead simplex search for a minimum of a function of two
//! variables in a rectangle (Nelder and Mead 1965; the coefficients of Lagarias
//! et al., *SIAM J. Optim.* 9, 1998). Used to refine the extrema found by
//! the patch search of surfaces (`nurbs/surface/patches.rs`): the maximum of
//! the distance between two surfaces ([`crate::SurfaceDistance`]), the
//! closest point and the bounding box.

/// The smallest value of `f` found near `start` in the rectangle
/// `[lo₀, hi₀] × [lo₁, hi₁]`, as `(f(x), x)`.
///
/// The rectangle is made unconstrained by the change of variables
///
/// ```text
/// x = lo + (hi − lo)·(1 − cos(π·y))/2,   y ∈ ℝ
/// ```
/// (Box 1966): every `y` is a point of the rectangle, and a minimum on an
/// edge or in a corner is a smooth stationary point in `y`, which the simplex
/// reaches as it reaches an interior one (clamping trial points to the
/// rectangle instead can collapse the simplex onto an edge, away from the
/// minimum). The first simplex is `start` and `start` moved by about `step[k]`
/// along each axis. Reflection 1, expansion 2, contraction ½, shrinking ½; the
/// search stops when the simplex spans at most `tolerance[k] / (hi − lo)` in
/// each `y` (so at most about `1.6·tolerance[k]` in `x`), or after
/// `max_evaluations`. The result is never worse than `f(start)`.
pub(crate) fn nelder_mead_min(
    f: impl Fn([f64; 2]) -> f64,
    start: [f64; 2],
    step: [f64; 2],
    [lo, hi]: [[f64; 2]; 2],
    tolerance: [f64; 2],
    max_evaluations: usize,
) -> (f64, [f64; 2]) {
    let pi = std::f64::consts::PI;
    let width = [hi[0] - lo[0], hi[1] - lo[1]];
    let to_x = |y: [f64; 2]| -> [f64; 2] {
        std::array::from_fn(|k| {
            (lo[k] + width[k] * (1.0 - (pi * y[k]).cos()) / 2.0).clamp(lo[k], hi[k])
        })
    };
    let to_y = |x: [f64; 2]| -> [f64; 2] {
        std::array::from_fn(|k| {
            if width[k] > 0.0 {
                (1.0 - 2.0 * (x[k] - lo[k]) / width[k])
                    .clamp(-1.0, 1.0)
                    .acos()
                    / pi
            } else {
                0.0
            }
        })
    };
    let scaled = |v: [f64; 2]| -> [f64; 2] {
        std::array::from_fn(|k| if width[k] > 0.0 { v[k] / width[k] } else { 0.0 })
    };
    let (dy, tol) = (scaled(step), scaled(tolerance));
    let evaluations = std::cell::Cell::new(0usize);
    let eval = |y: [f64; 2]| {
        evaluations.set(evaluations.get() + 1);
        (f(to_x(y)), y)
    };
    let y0 = to_y(start);
    let mut s = [
        eval(y0),
        eval([y0[0] + dy[0], y0[1]]),
        eval([y0[0], y0[1] + dy[1]]),
    ];
    let along =
        |a: [f64; 2], b: [f64; 2], t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    loop {
        s.sort_by(|a, b| a.0.total_cmp(&b.0));
        let spread = |k: usize| {
            let (a, b) = s
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v.1[k]), b.max(v.1[k]))
                });
            b - a
        };
        if (spread(0) <= tol[0] && spread(1) <= tol[1]) || evaluations.get() >= max_evaluations {
            return (s[0].0, to_x(s[0].1));
        }
        let c = along(s[0].1, s[1].1, 0.5);
        let worst = s[2];
        let r = eval(along(c, worst.1, -1.0));
        if r.0 < s[0].0 {
            let e = eval(along(c, worst.1, -2.0));
            s[2] = if e.0 < r.0 { e } else { r };
        } else if r.0 < s[1].0 {
            s[2] = r;
        } else {
            // Contract outside (towards the reflected point) or inside.
            let (target, bound) = if r.0 < worst.0 {
                (r, r.0)
            } else {
                (worst, worst.0)
            };
            let k = eval(along(c, target.1, 0.5));
            if k.0 < bound {
                s[2] = k;
            } else {
                let best = s[0].1;
                s[1] = eval(along(best, s[1].1, 0.5));
                s[2] = eval(along(best, s[2].1, 0.5));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_an_interior_minimum_of_a_skew_quadratic() {
        // (x − 0.3)² + 10·(y − 0.7 − 0.5·(x − 0.3))², minimum 1 at (0.3, 0.7).
        let f =
            |[x, y]: [f64; 2]| 1.0 + (x - 0.3).powi(2) + 10.0 * (y - 0.7 - 0.5 * (x - 0.3)).powi(2);
        let (v, x) = nelder_mead_min(
            f,
            [0.9, 0.1],
            [0.1, 0.1],
            [[0.0, 0.0], [1.0, 1.0]],
            [1e-10; 2],
            5000,
        );
        assert!(
            (x[0] - 0.3).abs() < 1e-8 && (x[1] - 0.7).abs() < 1e-8,
            "{x:?}"
        );
        assert!((v - 1.0).abs() < 1e-15, "{v}");
    }

    #[test]
    fn finds_a_minimum_on_an_edge_and_in_a_corner() {
        // Linear in x (smallest at x = 1), quadratic in y (smallest at 0.4).
        let f = |[x, y]: [f64; 2]| -x + (y - 0.4).powi(2);
        let (v, x) = nelder_mead_min(
            f,
            [0.5, 0.5],
            [0.05, 0.05],
            [[0.0, 0.0], [1.0, 1.0]],
            [1e-11; 2],
            5000,
        );
        assert!(
            (x[0] - 1.0).abs() < 1e-12 && (x[1] - 0.4).abs() < 1e-6,
            "{x:?}"
        );
        assert!((v + 1.0).abs() < 1e-12);
        let (_, x) = nelder_mead_min(
            |[x, y]| x + y,
            [0.5, 0.5],
            [0.1, 0.1],
            [[0.0, 0.0], [1.0, 1.0]],
            [1e-12; 2],
            5000,
        );
        assert!(x[0] < 1e-11 && x[1] < 1e-11, "{x:?}");
    }
}
