//! The cut ends of every control point as straight lines in alpha: the
//! numbers the set view (docs/method.md §10) combines with the basis.
//!
//! A coordinate's cut at `alpha` under one membership function with top `top`
//! (1 for the upper and primary functions, the number's `h` for the lower) is
//! (docs/method.md §2)
//!
//! ```text
//! left(alpha)  = foot_l + alpha · (crisp − foot_l)/top
//! right(alpha) = foot_r − alpha · (foot_r − crisp)/top,      0 ≤ alpha ≤ top
//! ```
//! Both are linear in alpha, so at a parameter `t` the box corners
//! `Σ Rᵢ(t)·leftᵢ(alpha)` are again linear in alpha with the slopes
//! `Σ Rᵢ(t)·slopeᵢ`, and the level at which a value enters the box has a
//! closed form (`set/certify.rs` bounds it over whole spans).

use crate::fuzzy::{Membership, Nt2Point};

/// The three membership functions, in the order of every array of the set view.
pub const MEMBERSHIPS: [Membership; 3] =
    [Membership::Upper, Membership::Primary, Membership::Lower];

/// The cut ends of one coordinate of one control point, under one membership
/// function, as lines in alpha.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CutEnds {
    /// The left foot (the cut's left end at alpha 0).
    pub(crate) foot_left: f64,
    /// How fast the left end moves right per unit of alpha.
    pub(crate) slope_left: f64,
    /// The right foot.
    pub(crate) foot_right: f64,
    /// How fast the right end moves left per unit of alpha.
    pub(crate) slope_right: f64,
}

/// Every control point's cut ends under one membership function, and the top
/// of each point (the largest alpha at which it has a cut: the least height of
/// its coordinates).
#[derive(Clone, Debug)]
pub(crate) struct CutLines<const D: usize> {
    /// `ends[i][c]`: control point `i`, coordinate `c`.
    pub(crate) ends: Vec<[CutEnds; D]>,
    /// `top[i]`: 1 for the upper and primary functions, the least `h` of
    /// point `i`'s coordinates for the lower.
    pub(crate) top: Vec<f64>,
}

impl<const D: usize> CutLines<D> {
    /// The lines of `points` under `membership`.
    pub(crate) fn of(points: &[Nt2Point<D>], membership: Membership) -> Self {
        let mut ends = Vec::with_capacity(points.len());
        let mut top = Vec::with_capacity(points.len());
        for p in points {
            let mut least = 1.0_f64;
            let e = p.coords().map(|x| {
                let (feet, h) = match membership {
                    Membership::Upper => (x.upper(), 1.0),
                    Membership::Primary => (x.primary(), 1.0),
                    Membership::Lower => (x.lower(), x.height().get()),
                };
                least = least.min(h);
                CutEnds {
                    foot_left: feet.left(),
                    slope_left: (x.crisp() - feet.left()) / h,
                    foot_right: feet.right(),
                    slope_right: (feet.right() - x.crisp()) / h,
                }
            });
            ends.push(e);
            top.push(least);
        }
        CutLines { ends, top }
    }

    /// The box of the curve at a parameter whose non-zero rational basis
    /// functions are `basis`, starting at control point `first`, at level
    /// `alpha`: per coordinate `[Σ Rᵢ leftᵢ(alpha), Σ Rᵢ rightᵢ(alpha)]`.
    pub(crate) fn box_at(&self, first: usize, basis: &[f64], alpha: f64) -> [[f64; 2]; D] {
        let mut out = [[0.0; 2]; D];
        for (r, ends) in basis.iter().zip(&self.ends[first..]) {
            for (o, e) in out.iter_mut().zip(ends) {
                o[0] += r * (e.foot_left + alpha * e.slope_left);
                o[1] += r * (e.foot_right - alpha * e.slope_right);
            }
        }
        out
    }

    /// The least top of the points `first .. first + count`: above it one of
    /// them has no cut, and so the curve has no box where all of them count.
    pub(crate) fn top_of(&self, first: usize, count: usize) -> f64 {
        self.top[first..first + count]
            .iter()
            .fold(1.0_f64, |m, &h| m.min(h))
    }
}

impl<const D: usize> CutLines<D> {
    /// Per coordinate `[A, G, B, G']`: the feet and slopes of the box at this
    /// parameter, `Σ Rᵢ·foot_left`, `Σ Rᵢ·slope_left`, `Σ Rᵢ·foot_right`,
    /// `Σ Rᵢ·slope_right`.
    pub(crate) fn sums(&self, first: usize, basis: &[f64]) -> [[f64; 4]; D] {
        let mut sums = [[0.0_f64; 4]; D];
        for (r, ends) in basis.iter().zip(&self.ends[first..]) {
            for (s, e) in sums.iter_mut().zip(ends) {
                s[0] += r * e.foot_left;
                s[1] += r * e.slope_left;
                s[2] += r * e.foot_right;
                s[3] += r * e.slope_right;
            }
        }
        sums
    }
}

/// The slack of "on the set", relative to the job's extent: a point counts
/// as in a box when it lies within `RELATIVE_SLACK · E` of it in every
/// coordinate (docs/set.md, "On the set"). Every part of the set view
/// (grades, regions, sections, of curves and surfaces) uses this one slack.
pub const RELATIVE_SLACK: f64 = 1e-12;

/// The slack of the set view of `points` ([`RELATIVE_SLACK`] of their
/// extent): `E` is the largest side of the box of every upper cut at level 0,
/// or 1/16 of the largest magnitude of a foot if that is larger (a computed
/// point far from the origin is rounded by about 2⁻⁵³ of its magnitude).
pub(crate) fn slack<const D: usize>(points: &[Nt2Point<D>]) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    let mut magnitude = 0.0_f64;
    for p in points {
        for (c, x) in p.coords().iter().enumerate() {
            let u = x.upper();
            lo[c] = lo[c].min(u.left());
            hi[c] = hi[c].max(u.right());
            magnitude = magnitude.max(u.left().abs()).max(u.right().abs());
        }
    }
    let side = lo
        .iter()
        .zip(&hi)
        .map(|(l, h)| h - l)
        .fold(0.0_f64, f64::max);
    RELATIVE_SLACK * side.max(magnitude / 16.0)
}
