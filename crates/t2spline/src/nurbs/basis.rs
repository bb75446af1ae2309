//! B-spline basis functions (The NURBS Book, §2.2 and Algorithm A2.2).

use crate::error::Error;
#[cfg(doc)]
use crate::nurbs::KnotVector;

/// Checks that `span` has `degree` knots on either side in `knots`, as the
/// basis at `span` reads `knots[span + 1 − degree ..= span + degree]`.
///
/// # Errors
/// [`Error::Index`] naming the `span` if `span < degree` or
/// `span + degree ≥ knots.len()`.
pub(crate) fn check_span(knots: &[f64], degree: usize, span: usize) -> Result<(), Error> {
    let fits = span >= degree
        && span
            .checked_add(degree)
            .is_some_and(|end| end < knots.len());
    if fits {
        Ok(())
    } else {
        // The spans with `degree` knots on either side: `degree ..< len − degree`.
        Err(Error::Index {
            what: "span",
            index: span,
            count: knots.len().saturating_sub(degree),
        })
    }
}

/// The `p + 1` non-zero basis functions at `t` in `span` (The NURBS Book,
/// A2.2), checked, in a new vector: `N_{span−p,p}(t) … N_{span,p}(t)`.
///
/// # Errors
/// [`Error::Index`] if `span` does not have `degree` knots on either side
/// (`degree ≤ span` and `span + degree < knots.len()`).
///
/// # Examples
/// ```
/// # use t2spline::nurbs::basis::try_basis_functions;
/// let u = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
/// let n = try_basis_functions(&u, 2, 2, 0.5)?;
/// assert_eq!(n, [0.25, 0.5, 0.25]); // Bernstein polynomials at 1/2
/// assert!(try_basis_functions(&u, 2, 4, 0.5).is_err());
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn try_basis_functions(
    knots: &[f64],
    degree: usize,
    span: usize,
    t: f64,
) -> Result<Vec<f64>, Error> {
    check_span(knots, degree, span)?;
    let mut out = vec![0.0; degree + 1];
    basis_functions(knots, degree, span, t, &mut out);
    Ok(out)
}

/// The highest order whose evaluation needs no allocation (scratch on the
/// stack); higher orders allocate their scratch.
pub(crate) const STACK_ORDER: usize = 32;

/// The `p + 1` non-zero basis functions `N_{span−p,p}(t) … N_{span,p}(t)`, written
/// into `out[0..=p]` (The NURBS Book, A2.2, the Cox–de Boor recurrence in
/// triangular form):
///
/// ```text
/// N_{i,0}(t) = 1 if U[i] ≤ t < U[i+1], else 0
/// N_{i,p}(t) = (t − U[i])/(U[i+p] − U[i])·N_{i,p−1}(t) + (U[i+p+1] − t)/(U[i+p+1] − U[i+1])·N_{i+1,p−1}(t)
/// ```
/// `span` must be a non-empty span (`U[span] < U[span+1]`) with `p ≤ span`, so
/// that every denominator is positive. The values are non-negative and sum to 1
/// for `t` in `[U[span], U[span+1]]`.
///
/// Callers guarantee `out.len() > degree`, `degree ≤ span` and
/// `span + degree < knots.len()` (a span of a validated [`KnotVector`]);
/// [`try_basis_functions`] is the checked form.
pub(crate) fn basis_functions(knots: &[f64], degree: usize, span: usize, t: f64, out: &mut [f64]) {
    // Scratch on the stack up to order STACK_ORDER (no allocation per call),
    // on the heap beyond.
    let mut stack = [0.0; 2 * STACK_ORDER];
    let mut heap = Vec::new();
    let scratch: &mut [f64] = if degree < STACK_ORDER {
        &mut stack[..2 * (degree + 1)]
    } else {
        heap.resize(2 * (degree + 1), 0.0);
        &mut heap
    };
    let (left, right) = scratch.split_at_mut(degree + 1);
    out[0] = 1.0;
    for j in 1..=degree {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let sum = right[r + 1] + left[j - r];
            let temp = out[r] / sum;
            if temp.is_finite() {
                out[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            } else {
                // A span narrower than about 1e-308 makes `N/sum` overflow
                // (and then `0·∞` is NaN). `[U[span+1+r−j], U[span+1+r]]`
                // contains the span, so `right` and `left` are at most `sum`
                // and both fractions below lie in [0, 1].
                let n = out[r];
                out[r] = saved + (right[r + 1] / sum) * n;
                saved = (left[j - r] / sum) * n;
            }
        }
        out[j] = saved;
    }
}
