//! Knot insertion and knot refinement (The NURBS Book, §5.2, A5.1 and A5.4).
//!
//! Both change the representation, never the curve: the new homogeneous
//! control points are convex combinations `αPʷᵢ + (1 − α)Pʷᵢ₋₁`, `α ∈ [0, 1]`,
//! of the old ones. In Cartesian form each new point is a convex combination of
//! old points whose coefficients depend only on knots and weights, so the seven
//! layers of a fuzzy curve stay ordered (see `pipeline/fuzzy_ops.rs`).
//!
//! Boehm's formula is written with `αᵢ = clamp((u − U[i]) / (U[i+p] − U[i]), 0, 1)`
//! over every `i` rather than with A5.1's span-based indexing: the clamped form
//! holds for every `u` in the domain, at existing knots, at both ends of an
//! unclamped domain and up to full multiplicity, where the indexed form needs
//! special cases (geomdl's A5.1 refuses insertion to full multiplicity and,
//! forced with `check_num=False`, leaves an empty control point).

use crate::error::Error;
use crate::nurbs::homogeneous::{blend, Row};
use crate::nurbs::{KnotVector, NurbsCurve};

/// Checks that `u` lies in the domain and may be inserted `times` more times.
fn check_insertion(knots: &KnotVector, u: f64, times: usize) -> Result<(), Error> {
    knots.domain().check(u)?;
    let multiplicity = knots.multiplicity(u);
    let order = knots.degree() + 1;
    if multiplicity.saturating_add(times) > order {
        return Err(Error::KnotInsertion {
            knot: u,
            times,
            multiplicity,
            order,
        });
    }
    Ok(())
}

/// Inserts `u` once (Boehm's algorithm, The NURBS Book Eq. 5.15):
///
/// ```text
/// Qʷᵢ = αᵢ Pʷᵢ + (1 − αᵢ) Pʷᵢ₋₁,   αᵢ = clamp((u − U[i]) / (U[i+p] − U[i]), 0, 1),   i = 0 … n
/// ```
/// Written without a span index, the formula holds for every `u` in the domain,
/// both ends and existing knots included, as long as the multiplicity of `u`
/// stays at most `p + 1`.
fn insert_once(knots: &[f64], p: usize, rows: &[Row], u: f64) -> (Vec<f64>, Vec<Row>) {
    let n = rows.len();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        // α = 1 for i = 0 (u ≥ U[p]) and α = 0 for i = n (u ≤ U[n]), since the
        // multiplicity of u stays at most p + 1. Inside, 1 − α is computed from
        // the knots too (see `blend`).
        out.push(if u >= knots[i + p] {
            rows[i].clone()
        } else if u <= knots[i] {
            rows[i - 1].clone()
        } else {
            let width = knots[i + p] - knots[i];
            let alpha = (u - knots[i]) / width;
            let beta = (knots[i + p] - u) / width;
            blend(alpha, beta, &rows[i], &rows[i - 1])
        });
    }
    let at = knots.partition_point(|&v| v <= u);
    let mut new_knots = knots.to_vec();
    new_knots.insert(at, u);
    (new_knots, out)
}

/// Inserts `u` `times` times into homogeneous control points (A5.1, one
/// insertion at a time).
pub(crate) fn insert(
    knots: &KnotVector,
    rows: &[Row],
    u: f64,
    times: usize,
) -> Result<(KnotVector, Vec<Row>), Error> {
    check_insertion(knots, u, times)?;
    let p = knots.degree();
    let mut values = knots.as_slice().to_vec();
    let mut rows = rows.to_vec();
    for _ in 0..times {
        (values, rows) = insert_once(&values, p, &rows, u);
    }
    Ok((KnotVector::from_parts_unchecked(values, p), rows))
}

/// Inserts all knots of `new` at once (knot refinement, The NURBS Book A5.4).
pub(crate) fn refine(
    knots: &KnotVector,
    rows: &[Row],
    new: &[f64],
) -> Result<(KnotVector, Vec<Row>), Error> {
    let mut x = new.to_vec();
    x.sort_by(f64::total_cmp);
    for run in x.chunk_by(|a, b| a == b) {
        check_insertion(knots, run[0], run.len())?;
    }
    let p = knots.degree();
    if x.is_empty() {
        return Ok((knots.clone(), rows.to_vec()));
    }
    let u = knots.as_slice();
    // The book's indices: n is the last control point, m the last knot, r the
    // last new knot.
    let n = rows.len() - 1;
    let m = n + p + 1;
    let r = x.len() - 1;
    let a = knots.find_span(x[0]);
    let b = knots.find_span(x[r]) + 1;
    let mut q: Vec<Row> = vec![Vec::new(); n + r + 2];
    let mut ubar = vec![0.0; m + r + 2];
    q[..=a - p].clone_from_slice(&rows[..=a - p]);
    for j in b - 1..=n {
        q[j + r + 1].clone_from(&rows[j]);
    }
    ubar[..=a].copy_from_slice(&u[..=a]);
    for j in b + p..=m {
        ubar[j + r + 1] = u[j];
    }
    let mut i = b + p - 1;
    let mut k = b + p + r;
    for j in (0..=r).rev() {
        while x[j] <= u[i] && i > a {
            q[k - p - 1].clone_from(&rows[i - p - 1]);
            ubar[k] = u[i];
            k -= 1;
            i -= 1;
        }
        q[k - p - 1] = q[k - p].clone();
        for l in 1..=p {
            let ind = k - p + l;
            let alpha = ubar[k + l] - x[j];
            if alpha == 0.0 {
                q[ind - 1] = q[ind].clone();
            } else {
                let width = ubar[k + l] - u[i - p + l];
                let beta = (x[j] - u[i - p + l]) / width;
                q[ind - 1] = blend(alpha / width, beta, &q[ind - 1], &q[ind]);
            }
        }
        ubar[k] = x[j];
        k = k.saturating_sub(1);
    }
    Ok((KnotVector::from_parts_unchecked(ubar, p), q))
}

impl<const D: usize> NurbsCurve<D> {
    /// The same curve with the knot `u` inserted `times` times (The NURBS Book,
    /// A5.1): one more control point per insertion, geometry unchanged.
    ///
    /// ```text
    /// Qʷᵢ = αᵢ Pʷᵢ + (1 − αᵢ) Pʷᵢ₋₁,   αᵢ = (u − U[i]) / (U[i+p] − U[i]) clamped to [0, 1]
    /// ```
    /// Inserting up to multiplicity `k = p + 1` is allowed (the curve is then
    /// stored as two pieces that meet at `u`).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `u` is NaN or outside the domain;
    /// [`Error::KnotInsertion`] if the multiplicity of `u` would exceed the order.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(2, vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], vec![1.0, 3.0, 1.0])?;
    /// let d = c.insert_knot(0.25, 2)?;
    /// assert_eq!(d.knots().as_slice(), &[0.0, 0.0, 0.0, 0.25, 0.25, 1.0, 1.0, 1.0]);
    /// let (a, b) = (c.eval(0.7)?, d.eval(0.7)?);
    /// assert!((a[0] - b[0]).abs() < 1e-15 && (a[1] - b[1]).abs() < 1e-15);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self, Error> {
        let (knots, rows) = insert(self.knots(), &self.rows(), u, times)?;
        Self::try_from_rows(knots, &rows, "knot insertion")
    }

    /// The same curve with all knots of `new` inserted (knot refinement, The
    /// NURBS Book A5.4); `new` need not be sorted and may repeat values.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a knot outside the domain;
    /// [`Error::KnotInsertion`] if a multiplicity would exceed the order.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::NurbsCurve;
    /// let c = NurbsCurve::try_clamped(3, vec![[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0]], vec![1.0, 0.5, 2.0, 1.0])?;
    /// let d = c.refine_knots(&[0.75, 0.25, 0.5, 0.5])?;
    /// assert_eq!(d.control_points().len(), 8);
    /// let (a, b) = (c.eval(0.6)?, d.eval(0.6)?);
    /// assert!((a[0] - b[0]).abs() < 1e-14 && (a[1] - b[1]).abs() < 1e-14);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn refine_knots(&self, new: &[f64]) -> Result<Self, Error> {
        let (knots, rows) = refine(self.knots(), &self.rows(), new)?;
        Self::try_from_rows(knots, &rows, "knot refinement")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::fixtures::{assert_same_geometry, six_point_quadratic, unclamped_quadratic};

    #[test]
    fn insertion_keeps_the_curve_at_new_and_existing_knots_and_the_ends() {
        let c = six_point_quadratic();
        for (u, times) in [
            (0.5, 1),
            (0.5, 3),
            (0.3, 1),
            (0.8, 2),
            (0.0, 0),
            (1.0, 0),
            (0.05, 2),
        ] {
            let d = c.insert_knot(u, times).unwrap();
            assert_eq!(d.control_points().len(), 6 + times);
            assert_eq!(d.knots().multiplicity(u), c.knots().multiplicity(u) + times);
            assert_same_geometry(&c, &d, 257, 1e-13);
        }
    }

    #[test]
    fn insertion_at_the_end_of_an_unclamped_curve() {
        let c = unclamped_quadratic();
        for u in [2.0, 4.0, 3.0] {
            let d = c.insert_knot(u, 2).unwrap();
            assert_eq!(d.domain(), c.domain());
            assert_same_geometry(&c, &d, 257, 1e-13);
        }
    }

    #[test]
    fn too_many_insertions_are_refused() {
        let c = six_point_quadratic();
        assert!(matches!(
            c.insert_knot(0.3, 2),
            Err(Error::KnotInsertion {
                multiplicity: 2,
                times: 2,
                order: 3,
                ..
            })
        ));
        assert!(matches!(
            c.insert_knot(0.5, usize::MAX),
            Err(Error::KnotInsertion { .. })
        ));
        assert!(matches!(
            c.insert_knot(1.5, 1),
            Err(Error::OutOfDomain { .. })
        ));
        assert!(matches!(
            c.refine_knots(&[0.5, 0.8, 0.5, 0.5, 0.5]),
            Err(Error::KnotInsertion { .. })
        ));
    }

    #[test]
    fn refinement_equals_repeated_insertion() {
        let c = six_point_quadratic();
        let x = [0.1, 0.3, 0.5, 0.5, 0.8, 0.95, 0.02];
        let refined = c.refine_knots(&x).unwrap();
        let mut one_by_one = c.clone();
        for &u in &x {
            one_by_one = one_by_one.insert_knot(u, 1).unwrap();
        }
        assert_eq!(refined.knots(), one_by_one.knots());
        for (p, q) in refined
            .control_points()
            .iter()
            .zip(one_by_one.control_points())
        {
            assert!((p[0] - q[0]).abs() < 1e-13 && (p[1] - q[1]).abs() < 1e-13);
        }
        assert_same_geometry(&c, &refined, 257, 1e-13);
    }
}
