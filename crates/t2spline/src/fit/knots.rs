//! Knot vectors for fitting (The NURBS Book §9.2.1 Eq. 9.8, §9.4.1 Eqs. 9.68–9.69).

use crate::error::Error;
use crate::nurbs::KnotVector;

/// The knots of global interpolation by averaging (The NURBS Book Eq. 9.8):
/// for `m + 1` parameters `ū₀ = 0 < … < ū_m = 1` and degree `p ≥ 1`, a clamped
/// vector with `n + 1 = m + 1` control points,
///
/// ```text
/// u₀ = … = u_p = 0,   u_{j+p} = (1/p)·Σ_{i=j}^{j+p−1} ūᵢ  (j = 1 … n − p),   u_{m+1} = … = u_{m+p+1} = 1
/// ```
/// Averaging makes every knot span contain a parameter, so the interpolation
/// matrix is non-singular (Schoenberg–Whitney) and totally positive.
///
/// # Errors
/// [`Error::ZeroDegreeFit`] for `p = 0`; [`Error::TooFewDataPoints`] if there
/// are fewer than `p + 1` parameters; the knot errors of [`KnotVector::try_new`]
/// if the parameters do not increase.
///
/// # Examples
/// ```
/// # use t2spline::fit::averaging_knots;
/// let u = averaging_knots(&[0.0, 0.25, 0.5, 0.75, 1.0], 2)?;
/// assert_eq!(u.as_slice(), &[0.0, 0.0, 0.0, 0.375, 0.625, 1.0, 1.0, 1.0]);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn averaging_knots(params: &[f64], degree: usize) -> Result<KnotVector, Error> {
    check_counts(params.len(), degree)?;
    let (p, m) = (degree, params.len() - 1);
    let mut u = vec![0.0; p + 1];
    u.extend((1..=m - p).map(|j| params[j..j + p].iter().sum::<f64>() / p as f64));
    u.extend(std::iter::repeat_n(1.0, p + 1));
    KnotVector::try_new(u, p, m + 1)
}

/// The knots of least-squares approximation with `count = n + 1` control
/// points (The NURBS Book Eqs. 9.68–9.69): for `m + 1` parameters and degree `p`,
///
/// ```text
/// d = (m + 1)/(n − p + 1)
/// u_{p+j} = (1 − α)·ū_{i−1} + α·ūᵢ,   i = ⌊j·d⌋,  α = j·d − i,   j = 1 … n − p
/// ```
/// clamped with `p + 1` zeros and ones. Every knot span then contains at least
/// one parameter, which keeps the normal matrix `NᵀN` positive definite.
///
/// # Errors
/// [`Error::ZeroDegreeFit`] for `p = 0`; [`Error::ControlPointCount`] unless
/// `p + 1 ≤ count ≤ m + 1`; the knot errors of [`KnotVector::try_new`] if the
/// parameters do not increase.
///
/// # Examples
/// ```
/// # use t2spline::fit::approximation_knots;
/// // Five parameters, degree 1, three control points: d = 5/2, one interior knot
/// // at j·d = 2.5: halfway between ū₁ and ū₂.
/// let u = approximation_knots(&[0.0, 0.2, 0.4, 0.7, 1.0], 1, 3)?;
/// assert_eq!(u.as_slice(), &[0.0, 0.0, 0.30000000000000004, 1.0, 1.0]);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn approximation_knots(
    params: &[f64],
    degree: usize,
    count: usize,
) -> Result<KnotVector, Error> {
    check_counts(params.len(), degree)?;
    let (p, m) = (degree, params.len() - 1);
    if count < p + 1 || count > m + 1 {
        return Err(Error::ControlPointCount {
            count,
            min: p + 1,
            max: m + 1,
        });
    }
    let n = count - 1;
    let d = (m + 1) as f64 / (n - p + 1) as f64;
    let mut u = vec![0.0; p + 1];
    for j in 1..=n - p {
        let jd = j as f64 * d;
        // 1 ≤ i ≤ m: d > 1 and j·d < m + 1 (see the bounds on j and count).
        let i = (jd.floor() as usize).clamp(1, m);
        let alpha = jd - i as f64;
        u.push((1.0 - alpha) * params[i - 1] + alpha * params[i]);
    }
    u.extend(std::iter::repeat_n(1.0, p + 1));
    KnotVector::try_new(u, p, count)
}

/// The periodic knots of a closed fit with `count = n` distinct control
/// points (the curve has `n + p`, its last `p` repeating its first `p`), for
/// the `N` loop parameters `ū₀ = 0 < … < ū_{N−1} < 1` of
/// [`Parametrization::loop_parameters`](crate::fit::Parametrization::loop_parameters)
/// (`ū_N = 1` closes the loop):
///
/// ```text
/// d = N/n,   δ = 0 for odd p, ½ for even p,   ū(x) = (1 − α)·ū_i + α·ū_{i+1},  i = ⌊x⌋, α = x − i
/// t₀ = 0,   t_j = ū((j − δ)·d)  (j = 1 … n − 1),   t_n = 1,   t_{j+n} = t_j + 1 for every j
/// knots: t_{−p} … t_{n+p}  (n + 2p + 1 values; domain [t₀, t_n] = [0, 1])
/// ```
/// For interpolation (`n = N`) the interior knots are the parameters for odd
/// `p` and the midpoints of neighbouring parameters for even `p`: FITPACK's
/// rule for periodic interpolation (Dierckx 1993, §6.1, routine `fpperi`,
/// which scipy's `splprep(per=1, s=0)` runs), the periodic counterpart of
/// averaging (Eq. 9.8): every site lies in its own span (odd `p`) or mid-span
/// (even `p`), as Schoenberg–Whitney asks; sites on the knots of an even
/// degree would make uniform data singular. With fewer control points it is
/// the periodic counterpart of Eqs. 9.68–9.69: each span holds at least one
/// parameter. The spacing repeats with period 1, so the first `2p` spans are
/// as long as the last `2p` (docs/method.md §11). Uniform parameters and odd
/// `p` give uniform knots `j/n`.
///
/// # Errors
/// [`Error::ZeroDegreeFit`] for `p = 0`; [`Error::TooFewClosedDataPoints`]
/// for fewer than `p + 1` parameters; [`Error::ControlPointCount`] unless
/// `p + 1 ≤ count ≤ N`; the knot errors of [`KnotVector::try_new`] if the
/// parameters do not increase within `[0, 1)`.
///
/// # Examples
/// ```
/// # use t2spline::fit::periodic_knots;
/// let params = [0.0, 0.25, 0.5, 0.75];
/// // Cubic: the knots are the parameters, a quarter apart, and go on by periodicity.
/// let u = periodic_knots(&params, 3, 4)?;
/// assert_eq!(u.as_slice(), &[-0.75, -0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75]);
/// assert_eq!((u.count(), u.domain().start, u.domain().end), (7, 0.0, 1.0));
/// // Quadratic: the midpoints of the parameters.
/// let u = periodic_knots(&params, 2, 4)?;
/// assert_eq!(u.as_slice(), &[-0.625, -0.375, 0.0, 0.125, 0.375, 0.625, 1.0, 1.125, 1.375]);
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn periodic_knots(params: &[f64], degree: usize, count: usize) -> Result<KnotVector, Error> {
    check_loop_counts(params.len(), degree, false)?;
    let (p, big_n, n) = (degree, params.len(), count);
    if n < p + 1 || n > big_n {
        return Err(Error::ControlPointCount {
            count: n,
            min: p + 1,
            max: big_n,
        });
    }
    let at = |k: usize| if k >= big_n { 1.0 } else { params[k] };
    let fractional = |x: f64| {
        // 0 ≤ x < N: j ≤ n − 1 and d ≥ 1 keep (j − δ)·d ≤ N − d.
        let i = (x.floor() as usize).min(big_n - 1);
        let alpha = x - i as f64;
        if alpha == 0.0 {
            at(i)
        } else {
            (1.0 - alpha) * at(i) + alpha * at(i + 1)
        }
    };
    let shift = if p % 2 == 0 { 0.5 } else { 0.0 };
    let d = big_n as f64 / n as f64;
    let mut t = Vec::with_capacity(n + 1);
    t.push(0.0);
    t.extend((1..n).map(|j| fractional((j as f64 - shift) * d)));
    t.push(1.0);
    let n_signed = n as isize;
    let knots = (-(p as isize)..=n_signed + p as isize)
        .map(|j| t[j.rem_euclid(n_signed) as usize] + j.div_euclid(n_signed) as f64)
        .collect();
    KnotVector::try_new(knots, p, n + p)
}

/// A closed curve of degree `p ≥ 1` through `count ≥ p + 1` distinct data
/// points (`repeated`: the data's last point repeated the first and was
/// taken as the same point).
pub(crate) fn check_loop_counts(count: usize, degree: usize, repeated: bool) -> Result<(), Error> {
    if degree == 0 {
        return Err(Error::ZeroDegreeFit);
    }
    if count <= degree {
        return Err(Error::TooFewClosedDataPoints {
            degree,
            count,
            repeated,
        });
    }
    Ok(())
}

/// A curve of degree `p ≥ 1` through `count ≥ p + 1` data points.
pub(crate) fn check_counts(count: usize, degree: usize) -> Result<(), Error> {
    if degree == 0 {
        return Err(Error::ZeroDegreeFit);
    }
    if count <= degree {
        return Err(Error::TooFewDataPoints { degree, count });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averaging_knots_of_uniform_parameters_are_uniform_for_odd_degree() {
        // Degree 3 on uniform parameters k/m: averages of three consecutive
        // parameters are the middle one.
        let params: Vec<f64> = (0..=6).map(|k| f64::from(k) / 6.0).collect();
        let u = averaging_knots(&params, 3).unwrap();
        let interior = &u.as_slice()[4..7];
        for (got, want) in interior.iter().zip([2.0 / 6.0, 3.0 / 6.0, 4.0 / 6.0]) {
            assert!((got - want).abs() < 1e-15, "{u:?}");
        }
        assert_eq!(u.count(), 7);
    }

    #[test]
    fn too_few_points_and_degree_zero_are_errors() {
        assert_eq!(
            averaging_knots(&[0.0, 1.0], 2),
            Err(Error::TooFewDataPoints {
                degree: 2,
                count: 2
            })
        );
        assert_eq!(averaging_knots(&[0.0, 1.0], 0), Err(Error::ZeroDegreeFit));
        assert_eq!(
            approximation_knots(&[0.0, 0.5, 1.0], 1, 4),
            Err(Error::ControlPointCount {
                count: 4,
                min: 2,
                max: 3
            })
        );
    }

    #[test]
    fn periodic_knots_repeat_their_spacing_and_hold_a_parameter_in_every_span() {
        let params: Vec<f64> = (0..17).map(|k| (f64::from(k) / 17.0).powf(1.3)).collect();
        for p in 1..=5 {
            for count in p + 1..=17 {
                let u = periodic_knots(&params, p, count).unwrap();
                let k = u.as_slice();
                assert_eq!(k.len(), count + 2 * p + 1);
                assert_eq!((k[p], k[count + p]), (0.0, 1.0), "p {p}, count {count}");
                for i in 0..2 * p {
                    let (head, tail) = (k[i + 1] - k[i], k[i + count + 1] - k[i + count]);
                    assert!((head - tail).abs() < 1e-15, "p {p}, count {count}: {k:?}");
                }
                for (_, [a, b]) in u.spans() {
                    assert!(
                        params.iter().chain([&1.0]).any(|&t| a <= t && t <= b),
                        "p {p}, count {count}: span [{a}, {b}] has no parameter"
                    );
                }
            }
        }
        assert_eq!(
            periodic_knots(&params, 3, 18),
            Err(Error::ControlPointCount {
                count: 18,
                min: 4,
                max: 17
            })
        );
    }

    #[test]
    fn approximation_knots_put_a_parameter_in_every_span() {
        let params: Vec<f64> = (0..=20).map(|k| (f64::from(k) / 20.0).powi(2)).collect();
        for p in 1..=5 {
            for count in p + 1..=21 {
                let u = approximation_knots(&params, p, count).unwrap();
                for (_, [a, b]) in u.spans() {
                    assert!(
                        params.iter().any(|&t| a <= t && t <= b),
                        "p {p}, count {count}: span [{a}, {b}] has no parameter"
                    );
                }
            }
        }
    }
}
