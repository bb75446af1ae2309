//! Membership of a point in the set `S(t)` of a curve with uncertain weights
//! at one parameter (docs/method.md §15): exact, by the support function in
//! finitely many directions.
//!
//! **The set is convex: a projective image of a polytope.** Write a term in
//! homogeneous coordinates, `Kᵢ = {(w·c, w) : w ∈ [w̲ᵢ, w̄ᵢ], c ∈ Bᵢ} ⊂ R^{D+1}`.
//! `Kᵢ` is convex (for `wc, w'c'` in it, `λwc + (1−λ)w'c' = w''c''` with
//! `w'' = λw + (1−λ)w'` and `c''` a convex combination of `c, c'`), and it is
//! the convex hull of its `2·2^D` vertices `(w c, w)`, `w` an end of the cut,
//! `c` a corner of the box. So `H = Σᵢ Nᵢ Kᵢ` is a polytope, whose vertices
//! are sums of vertices, and `S(t) = π(H)` with `π(z, s) = z/s` (`s > 0` on
//! `H`). `π` maps every segment of `{s > 0}` onto the segment between the
//! images (`π((1−λ)h + λh')` runs monotonically from `π(h)` to `π(h')`), so
//! `S(t)` is convex, and it is the convex hull of the images of the vertices
//! of `H`:
//! ```text
//! S(t) = conv { Σ wᵢNᵢcᵢ / Σ wᵢNᵢ : wᵢ ∈ {w̲ᵢ, w̄ᵢ}, cᵢ a corner of Bᵢ }
//! ```
//! (the independent check of the tests, for few terms).
//!
//! **The primal condition.** `q ∈ S(t)` iff `Σ wᵢNᵢ(Pᵢ − q) = 0` for some
//! admissible `w, P`. For fixed `w` the `k`-th component ranges over exactly
//! `[Σ wᵢNᵢ(P̲ᵢₖ − qₖ), Σ wᵢNᵢ(P̄ᵢₖ − qₖ)]`, independently for each `k`, so
//! `q ∈ S(t)` iff some `w` in its box has
//! ```text
//! Σ wᵢNᵢ(P̲ᵢₖ − qₖ) ≤ 0 ≤ Σ wᵢNᵢ(P̄ᵢₖ − qₖ)   for every coordinate k,
//! ```
//! a linear feasibility problem in the weights (the coordinates are coupled
//! through them: the box of per-coordinate envelopes is larger than the set).
//!
//! **The decision, exact in finitely many directions.** `S(t)` is convex and
//! closed, so `q ∈ S(t)` iff `d·q ≤ h(d)` for every `d`, i.e. iff
//! ```text
//! g(d) = max_θ Σ θᵢ mᵢ(d) = Σ ( θ̄ᵢ mᵢ(d) if mᵢ(d) ≥ 0, θ̲ᵢ mᵢ(d) else ) ≥ 0,   mᵢ(d) = Σ_k max(d_k(P̲ᵢₖ − qₖ), d_k(P̄ᵢₖ − qₖ))
//! ```
//! for every `d` (`θ̲ᵢ = w̲ᵢNᵢ`, `θ̄ᵢ = w̄ᵢNᵢ`; `g(d)` has the sign of
//! `h(d) − d·q`). In a closed orthant `σ` of directions each `mᵢ` is linear,
//! `mᵢ(d) = d·nᵢ^σ` with `nᵢ^σ_k = P̄ᵢₖ − qₖ` where `σ_k > 0`, `P̲ᵢₖ − qₖ`
//! where `σ_k < 0`; so `g` is linear on every cell of the arrangement of
//! the hyperplanes `nᵢ^σ·d = 0` and `d_k = 0` within the orthant. A cell is a
//! pointed polyhedral cone (inside an orthant), the positive hull of its
//! extreme rays, and a linear function is negative somewhere on it iff at
//! one of them. Every extreme ray lies on `D − 1` independent hyperplanes of
//! the arrangement. So `q ∈ S(t)` iff `g ≥ 0` on the finitely many rays
//! where `D − 1` of these hyperplanes meet: `±1` for `D = 1`, the normals
//! turned by a right angle for `D = 2`, the cross products of pairs for
//! `D = 3` (at most `8·(n+3)(n+2)` rays for `n` terms, each `O(n)`). A ray
//! that is not extreme, or outside its orthant, is a valid test too (any
//! direction is), so the candidates need no filtering.
//!
//! **Slack.** Rounding makes every vertex and every envelope end a computed
//! point, a few units in the last place off the set. So the test is the
//! exact one above for the boxes widened by the slack `τ` in every
//! coordinate (`P̲ᵢₖ − τ`, `P̄ᵢₖ + τ`), whose set is `S(t) + [−τ, τ]^D` (the
//! average of offsets in `[−τ, τ]^D` lies in it, and one offset for every
//! term reaches all of it): a point within `τ` of the set in every
//! coordinate counts in, one farther out is outside up to the rounding of
//! `g`. `τ` = [`IntervalTerms::slack`], [`MEMBERSHIP_SLACK`](super::envelope::MEMBERSHIP_SLACK) of the set's
//! extent. A point outside the widened envelope is refused at once, with
//! `±e_k` as the witness (this also keeps every difference `P − q` within
//! the range of coordinates).

use crate::error::Error;
use crate::fuzzy::Axis;

use super::km::binary_scale;
use super::terms::IntervalTerms;

impl<const D: usize> IntervalTerms<D> {
    /// Whether `q` is a point of the curve for some weights and points in
    /// their cuts (module docs; docs/method.md §15), within
    /// [`slack`](Self::slack) in every coordinate.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] (index 0) for a coordinate of `q` that is not
    /// finite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::interval_weights::IntervalTerms;
    /// // Points (0, 0) and (1, 1) with weights in [1, 3]: the segment from
    /// // (1/4, 1/4) to (3/4, 3/4), not the box of the envelopes.
    /// let terms = IntervalTerms::try_new(&[0.5, 0.5], &[[1.0, 3.0]; 2], &[[[0.0, 0.0]; 2], [[1.0, 1.0]; 2]])?;
    /// assert!(terms.contains([0.5, 0.5])?);
    /// assert!(terms.contains([0.25, 0.25])?);
    /// assert!(!terms.contains([0.25, 0.75])?);
    /// assert!(!terms.contains([0.8, 0.8])?);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn contains(&self, q: [f64; D]) -> Result<bool, Error> {
        Ok(self.separating_direction(q)?.is_none())
    }

    /// A direction `d` with `d·q > h(d)` beyond the slack, proving `q`
    /// outside the set; `None` if `q` is a member (module docs).
    ///
    /// # Errors
    /// As [`contains`](Self::contains).
    pub fn separating_direction(&self, q: [f64; D]) -> Result<Option<[f64; D]>, Error> {
        for (k, &value) in q.iter().enumerate() {
            if !value.is_finite() {
                return Err(Error::QueryPoint {
                    index: 0,
                    axis: Axis::from_index(k).unwrap_or(Axis::Z),
                    value,
                });
            }
        }
        let n = self.basis().len();
        let tau = self.slack();
        for (k, range) in self.envelope().iter().enumerate() {
            let mut e = [0.0; D];
            if q[k] > range.right() + tau {
                e[k] = 1.0;
                return Ok(Some(e));
            }
            if q[k] < range.left() - tau {
                e[k] = -1.0;
                return Ok(Some(e));
            }
        }
        let scale = binary_scale(self.upper());
        // The differences to q of the widened boxes' ends.
        let lo: Vec<[f64; D]> = self
            .points()
            .iter()
            .map(|p| std::array::from_fn(|k| (p[k][0] - q[k]) - tau))
            .collect();
        let hi: Vec<[f64; D]> = self
            .points()
            .iter()
            .map(|p| std::array::from_fn(|k| (p[k][1] - q[k]) + tau))
            .collect();
        let separates = |d: &[f64; D]| -> bool {
            let size = d.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            if size == 0.0 || !size.is_finite() {
                return false;
            }
            let mut g = 0.0;
            for i in 0..n {
                let mut m = 0.0;
                for k in 0..D {
                    let dk = d[k] / size;
                    m += (dk * lo[i][k]).max(dk * hi[i][k]);
                }
                let (a, b) = (self.lower()[i] / scale, self.upper()[i] / scale);
                g += if m >= 0.0 { b * m } else { a * m };
            }
            g < 0.0
        };
        let mut normals: Vec<[f64; D]> = Vec::with_capacity(n + D);
        for orthant in 0..(1usize << D) {
            normals.clear();
            normals.extend((0..D).map(|k| std::array::from_fn(|j| f64::from(u8::from(j == k)))));
            // A term with θ̄ = 0 adds nothing to g: no hyperplane of its own.
            normals.extend((0..n).filter(|&i| self.upper()[i] > 0.0).map(|i| {
                std::array::from_fn(|k| {
                    if orthant >> k & 1 == 1 {
                        hi[i][k]
                    } else {
                        lo[i][k]
                    }
                })
            }));
            if let Some(d) = rays(&normals).find(|d| separates(d)) {
                return Ok(Some(d));
            }
            if D == 1 {
                // The rays of D = 1 do not depend on the orthant.
                break;
            }
        }
        Ok(None)
    }
}

/// The candidate rays where `D − 1` of the hyperplanes `nⱼ·d = 0` meet, both
/// signs: `±1` for `D = 1`, each normal turned by a right angle for `D = 2`,
/// the cross product of each pair for `D = 3`; zero vectors skipped.
fn rays<const D: usize>(normals: &[[f64; D]]) -> impl Iterator<Item = [f64; D]> + '_ {
    let m = normals.len();
    let padded: Vec<[f64; 3]> = normals.iter().map(pad).collect();
    let found: Vec<[f64; 3]> = match D {
        1 => vec![[1.0, 0.0, 0.0]],
        2 => padded.iter().map(|v| [-v[1], v[0], 0.0]).collect(),
        _ => (0..m)
            .flat_map(|a| ((a + 1)..m).map(move |b| (a, b)))
            .map(|(a, b)| cross(padded[a], padded[b]))
            .collect(),
    };
    found
        .into_iter()
        .filter(|r| r.iter().any(|&x| x != 0.0))
        .flat_map(|r| {
            let r: [f64; D] = std::array::from_fn(|k| r.get(k).copied().unwrap_or(0.0));
            [r, r.map(|x| -x)]
        })
}

/// The first three components of `v`, zeros after its end.
fn pad<const D: usize>(v: &[f64; D]) -> [f64; 3] {
    std::array::from_fn(|k| v.get(k).copied().unwrap_or(0.0))
}

/// `u × v` of the two directions scaled to a largest component of 1 first,
/// so that normals of size 2e150 cannot overflow; zero if either is zero.
fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    let su = u.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
    let sv = v.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
    if su == 0.0 || sv == 0.0 {
        return [0.0; 3];
    }
    let u = u.map(|x| x / su);
    let v = v.map(|x| x / sv);
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}
