//! The section of the set `S(t)` of a curve with uncertain weights at one
//! parameter: the values of one coordinate `y` among the points of `S(t)`
//! whose coordinate `x` is `X₀` (docs/method.md §15).
//!
//! **The problem.** By the primal condition of
//! [`membership`](super::membership), the largest `y` is
//! ```text
//! max  Σ wᵢNᵢP̄ᵢᵧ / Σ wᵢNᵢ   subject to  Σ wᵢNᵢ(P̲ᵢₓ − X₀) ≤ 0 ≤ Σ wᵢNᵢ(P̄ᵢₓ − X₀),  w̲ᵢ ≤ wᵢ ≤ w̄ᵢ
//! ```
//! (the least: `min` with `P̲ᵢᵧ`), a linear-fractional program. The
//! Charnes–Cooper transformation `u = w/Σ wᵢNᵢ`, `s = 1/Σ wᵢNᵢ` makes it the
//! linear program
//! ```text
//! max Σ uᵢNᵢP̄ᵢᵧ   s.t.  Σ uᵢNᵢ = 1,  s·w̲ᵢ ≤ uᵢ ≤ s·w̄ᵢ,  Σ uᵢNᵢ(P̲ᵢₓ − X₀) ≤ 0 ≤ Σ uᵢNᵢ(P̄ᵢₓ − X₀),  s ≥ 0,
//! ```
//! whose dual is `min over λ of h(λ, 1) − λ·X₀`, `h` the support function
//! of the projection of `S(t)` on the `(x, y)` plane
//! ([`support`](super::support)): each `(λ, 1)` bounds the section from
//! above, `y ≤ h(λ, 1) − λX₀` for every point `(X₀, y)` of the set.
//!
//! **The method: the crossing edge by support queries.** The projection
//! `S₂` of `S(t)` is a convex polygon (the projection of a polytope;
//! [`membership`](super::membership)), and the largest `y` at `X₀` lies on
//! the edge of its upper boundary that crosses the line `x = X₀`. Start from
//! two points of `S₂`, `L` with `x ≤ X₀` and `R` with `x > X₀` (the vertices
//! of the least and largest x), and repeat: with the chord's upward normal
//! `n = (−(R_y − L_y), R_x − L_x)`, ask the support function for the vertex
//! `V` of `S₂` farthest in direction `n`; if it is no farther than the chord
//! (`h(n) = n·L`), the chord is an edge of `S₂` and the answer is where it
//! meets `x = X₀`; else `V` replaces `L` or `R`, whichever side of `X₀` it
//! is on. Every step finds a vertex strictly beyond the chord, which no
//! later chord can reach again, so the loop ends after at most as many steps
//! as `S₂` has vertices between `L` and `R`. At every step
//! `(h(n) − n_x·X₀)/n_y` is an upper bound (the dual above with
//! `λ = n_x/n_y`); the least of them is returned, so rounding or the step
//! limit can only widen the section, never narrow it, and at the end it
//! equals the chord's value: the program's optimum, exactly up to rounding.
//! The least `y` is the largest of the set reflected in `y`.
//!
//! The section lies inside the `y` envelope and may be strictly narrower:
//! the envelope's extremes need weights that put `x` elsewhere.

use crate::error::{Error, Place};
use crate::fuzzy::{Axis, Interval};

use super::terms::IntervalTerms;

/// The most support queries for one end of a section; a bound, not an
/// iteration count that arises (the loop ends at an edge of the polygon).
const MAX_STEPS: usize = 10_000;

impl<const D: usize> IntervalTerms<D> {
    /// The section `{ q_of : q ∈ S(t), q_along = at }` as an interval,
    /// `None` if the set does not reach `at` (module docs; docs/method.md
    /// §15). A line within [`slack`](Self::slack) of the set meets it; if
    /// the set's `along` extent is itself within the slack, the section is
    /// the whole `of` envelope.
    ///
    /// # Errors
    /// [`Error::SectionAxes`] if `along` and `of` are the same or not both
    /// coordinates of the points; [`Error::NotFinite`] if `at` is not finite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Axis, interval_weights::IntervalTerms};
    /// // Points (0, 0) and (1, 2) with weights in [1, 3]: the segment from
    /// // (1/4, 1/2) to (3/4, 3/2); at x = 1/2 only y = 1, though y's envelope is [1/2, 3/2].
    /// let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 3.0]; 2], &[[[0.0, 0.0]; 2], [[1.0, 1.0], [2.0, 2.0]]])?;
    /// let s = terms.section(Axis::X, 0.5, Axis::Y)?.unwrap();
    /// assert!((s.left() - 1.0).abs() < 1e-12 && (s.right() - 1.0).abs() < 1e-12);
    /// assert_eq!(terms.section(Axis::X, 0.9, Axis::Y)?, None);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn section(&self, along: Axis, at: f64, of: Axis) -> Result<Option<Interval>, Error> {
        let (kx, ky) = (along.index(), of.index());
        if kx == ky || kx >= D || ky >= D {
            return Err(Error::SectionAxes {
                along,
                of,
                dimension: D,
            });
        }
        if !at.is_finite() {
            return Err(Error::NotFinite {
                place: Place {
                    axis: Some(along),
                    ..Place::NONE
                },
                what: "at",
                value: at,
            });
        }
        let plane = Plane {
            terms: self,
            kx,
            ky,
        };
        let env = self.envelope();
        let (x, y) = (env[kx], env[ky]);
        let slack = self.slack();
        if at < x.left() - slack || at > x.right() + slack {
            return Ok(None);
        }
        if x.width() <= slack {
            return Ok(Some(y));
        }
        let x0 = at.clamp(x.left(), x.right());
        // The section lies in the y envelope: rounding may not take it out.
        let top = plane.top(x0, false).clamp(y.left(), y.right());
        let bottom = (-plane.top(x0, true)).clamp(y.left(), y.right());
        Ok(Some(Interval::new_unchecked(
            bottom.min(top),
            top.max(bottom),
        )))
    }
}

/// The projection of the set on the plane of coordinates `kx` (x) and `ky`
/// (y), possibly reflected in y.
struct Plane<'a, const D: usize> {
    terms: &'a IntervalTerms<D>,
    kx: usize,
    ky: usize,
}

impl<const D: usize> Plane<'_, D> {
    /// `h(nx, ny)` of the projection (reflected: `y → −y`) and a point of it
    /// that attains it.
    fn support(&self, nx: f64, ny: f64, reflected: bool) -> (f64, [f64; 2]) {
        let mut d = [0.0; D];
        d[self.kx] = nx;
        d[self.ky] = if reflected { -ny } else { ny };
        let (h, switch) = self.terms.support_unchecked(&d);
        let p = self
            .terms
            .vertex(&switch.at_upper, |_, k| d[k] > 0.0)
            .point();
        let y = if reflected { -p[self.ky] } else { p[self.ky] };
        (h, [p[self.kx], y])
    }

    /// An upper bound on `y` over the points of the projection with `x = x0`
    /// (`x0` within the x envelope, which has positive width), equal to the
    /// largest such `y` up to rounding: the crossing edge by support queries
    /// (module docs).
    fn top(&self, x0: f64, reflected: bool) -> f64 {
        let (_, mut l) = self.support(-1.0, 0.0, reflected);
        let (_, mut r) = self.support(1.0, 0.0, reflected);
        let (hy, _) = self.support(0.0, 1.0, reflected);
        let mut best = hy;
        if l[0] >= r[0] {
            return best;
        }
        let x0 = x0.clamp(l[0], r[0]);
        for _ in 0..MAX_STEPS {
            let n = [-(r[1] - l[1]), r[0] - l[0]];
            let (h, v) = self.support(n[0], n[1], reflected);
            if n[1] > 0.0 {
                best = best.min((h - n[0] * x0) / n[1]);
            }
            let chord = (n[0] * l[0] + n[1] * l[1]).max(n[0] * r[0] + n[1] * r[1]);
            let size = v
                .iter()
                .chain(&l)
                .chain(&r)
                .fold(0.0_f64, |m, c| m.max(c.abs()));
            let rounding = 16.0 * f64::EPSILON * (n[0].abs() + n[1].abs()) * size;
            if h - chord <= rounding || v == l || v == r {
                break;
            }
            if v[0] < x0 || (v[0] == x0 && r[0] > x0) {
                l = v;
            } else {
                r = v;
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use crate::fuzzy::Axis;
    use crate::interval_weights::terms::IntervalTerms;

    #[test]
    fn a_crisp_x_gives_the_y_envelope_at_that_x_only() {
        // Every x is 2: the set is a vertical segment; at x = 2 the whole y
        // envelope, elsewhere nothing.
        let terms = IntervalTerms::try_new(
            &[0.3, 0.7],
            &[[1.0, 2.0], [0.5, 4.0]],
            &[[[2.0, 2.0], [0.0, 1.0]], [[2.0, 2.0], [3.0, 5.0]]],
        )
        .unwrap();
        let y = terms.envelope()[1];
        assert_eq!(terms.section(Axis::X, 2.0, Axis::Y).unwrap(), Some(y));
        assert_eq!(terms.section(Axis::X, 2.0 + 1e-9, Axis::Y).unwrap(), None);
        assert!(terms.contains([2.0, y.left()]).unwrap());
        assert!(!terms.contains([2.0 + 1e-9, y.left()]).unwrap());
    }

    #[test]
    fn extreme_magnitudes_stay_finite() {
        // Coordinates at the range's ends and weights from 1e-150 to 1e150.
        let terms = IntervalTerms::try_new(
            &[0.25, 0.5, 0.25],
            &[[1e-150, 1e150], [1.0, 1.0], [1e-150, 1e-149]],
            &[
                [[-1e150, 1e150], [-1e150, -1e150]],
                [[0.0, 1.0], [1e150, 1e150]],
                [[1e150, 1e150], [-1.0, 1.0]],
            ],
        )
        .unwrap();
        for range in terms.envelope() {
            assert!(range.left().is_finite() && range.right().is_finite());
        }
        for d in [[1.0, 0.0], [-1e150, 1e150], [1e-300, 1.0]] {
            assert!(terms.support(d).unwrap().is_finite(), "{d:?}");
        }
        for q in [
            [0.0, 0.0],
            [1e150, -1e150],
            [f64::MAX, f64::MIN],
            [1e-300, 5e149],
        ] {
            terms.contains(q).unwrap();
        }
        assert!(!terms.contains([f64::MAX, 0.0]).unwrap());
        for at in [0.0, 1e149, -1e150, f64::MAX] {
            if let Some(s) = terms.section(Axis::X, at, Axis::Y).unwrap() {
                assert!(s.left().is_finite() && s.right().is_finite(), "{at}: {s:?}");
            }
        }
    }

    #[test]
    fn one_coordinate() {
        // D = 1: the set is the envelope; membership is the interval test.
        let terms =
            IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 3.0]; 2], &[[[0.0, 0.0]], [[1.0, 1.0]]])
                .unwrap();
        assert!(terms.contains([0.5]).unwrap());
        assert!(terms.contains([0.25]).unwrap());
        assert!(!terms.contains([0.2]).unwrap());
        assert_eq!(terms.separating_direction([0.8]).unwrap(), Some([1.0]));
    }
}
