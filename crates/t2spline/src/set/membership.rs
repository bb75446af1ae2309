//! The membership grade of a point in the fuzzy curve (docs/method.md §10):
//!
//! ```text
//! mu_m(p) = sup over t of  min( top(t), min over c of mu_{m,c,t}(p_c) )
//! ```
//! found as the distance's maximum is: every piece of every knot span scanned,
//! every local peak of the scan refined.

use crate::error::Error;
use crate::fuzzy::Membership;
use crate::golden_section::golden_section_min;
use crate::pipeline::FuzzyCurve;
use crate::set::cut_lines::{CutLines, Sides, MEMBERSHIPS};
use crate::set::scan::{pieces, rational_basis, SpanPiece};

/// The grades of one point under the three membership functions, each in
/// `[0, 1]` (the lower in `[0, h]`), with `lower ≤ primary ≤ upper`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Grades {
    /// `mu_upper(p)`: the largest level at which some curve with control
    /// points inside their upper cuts passes through `p`.
    pub upper: f64,
    /// `mu_primary(p)`, the same with the primary cuts.
    pub primary: f64,
    /// `mu_lower(p)`, the same with the lower cuts.
    pub lower: f64,
}

impl Grades {
    /// The grade under `membership`.
    #[must_use]
    pub fn get(&self, membership: Membership) -> f64 {
        match membership {
            Membership::Upper => self.upper,
            Membership::Primary => self.primary,
            Membership::Lower => self.lower,
        }
    }

    /// The three grades from the sups found for each function, kept in the
    /// order `lower ≤ primary ≤ upper`, which holds exactly (every lower cut
    /// lies inside the primary cut at the same level, and that inside the
    /// upper) and which separate searches could break in the last bits.
    pub(crate) fn ordered([upper, primary, lower]: [f64; 3]) -> Self {
        let upper = upper.clamp(0.0, 1.0);
        let primary = primary.clamp(0.0, upper);
        Grades {
            upper,
            primary,
            lower: lower.clamp(0.0, primary),
        }
    }
}

/// Scan steps per piece of a knot span.
const SCAN_STEPS: usize = 64;
/// The width, relative to its piece, to which golden sections narrow the
/// bracket of a peak. The grade can have a corner at its peak (where two
/// coordinates' grades cross), so it is not flat there: the bracket is
/// narrowed far below the 1e-9 promised for the grade.
const REFINEMENT: f64 = 1e-13;
/// Bisections of a crossing of two functions: to the last bit of a piece.
const CROSSING_BISECTIONS: usize = 64;

/// The membership functions of a curve, ready to grade many points.
#[derive(Clone, Debug)]
pub(crate) struct Grader<'a, const D: usize> {
    curve: &'a FuzzyCurve<D>,
    lines: [CutLines<D>; 3],
    pieces: Vec<SpanPiece>,
    /// Per piece and function: the top, and the box at level 0 of the
    /// control points that count there (which holds every box of the piece).
    hulls: Vec<[(f64, [[f64; 2]; D]); 3]>,
}

impl<'a, const D: usize> Grader<'a, D> {
    pub(crate) fn new(curve: &'a FuzzyCurve<D>) -> Self {
        let lines = MEMBERSHIPS.map(|m| CutLines::of(curve.points(), m));
        let pieces = pieces(curve.knots(), curve.weights());
        let p = curve.degree();
        let hulls = pieces
            .iter()
            .map(|piece| {
                let first = piece.first(p);
                std::array::from_fn(|k| {
                    let l = &lines[k];
                    let mut hull = [[f64::INFINITY, f64::NEG_INFINITY]; D];
                    for ends in &l.ends[first..=first + p] {
                        for (h, e) in hull.iter_mut().zip(ends) {
                            h[0] = h[0].min(e.foot_left);
                            h[1] = h[1].max(e.foot_right);
                        }
                    }
                    (l.top_of(first, p + 1), hull)
                })
            })
            .collect();
        Grader {
            curve,
            lines,
            pieces,
            hulls,
        }
    }

    /// The grades of `p`.
    pub(crate) fn grades(&self, p: &[f64; D]) -> Grades {
        let mut best = [0.0_f64; 3];
        let mut basis = vec![0.0; self.curve.order()];
        let mut scan: Vec<(f64, Sides)> = Vec::with_capacity(SCAN_STEPS + 1);
        for (piece, hulls) in self.pieces.iter().zip(&self.hulls) {
            for k in 0..3 {
                let (top, hull) = &hulls[k];
                // The convex hull property: every box of the piece lies in the
                // box of its control points' cuts at level 0.
                // The slack lets a point on a crisp coordinate's edge,
                // rounded out of it, count (see `crisp_peak`).
                let slack = 1e-9 * hull.iter().map(|h| h[1] - h[0]).fold(0.0_f64, f64::max);
                if *top <= best[k]
                    || !hull
                        .iter()
                        .zip(p)
                        .all(|(h, &x)| h[0] - slack <= x && x <= h[1] + slack)
                {
                    continue;
                }
                best[k] = best[k].max(self.peak(piece, k, *top, p, &mut basis, &mut scan));
                best[k] = best[k].max(self.crisp_peak(piece, k, (*top, hull), p, &mut basis));
            }
        }
        Grades::ordered(best)
    }

    /// The largest grade of `p` on one piece under function `k` where the
    /// curve passes through `p` in the coordinates whose cuts have no width
    /// on the piece (crisp stations, or crisp numbers): there the box is a
    /// point in those coordinates, so the grade is positive only at isolated
    /// parameters, which a scan of the grade cannot hit. The parameters
    /// nearest `p` in those coordinates are found (every local minimum of a
    /// scan, refined); within 1e-9 of the piece's size they count as passing
    /// through `p`, and the grade of the other coordinates there is taken
    /// (0 when no coordinate is crisp or none is near).
    fn crisp_peak(
        &self,
        piece: &SpanPiece,
        k: usize,
        (top, hull): (f64, &[[f64; 2]; D]),
        p: &[f64; D],
        basis: &mut [f64],
    ) -> f64 {
        let first = piece.first(self.curve.degree());
        let lines = &self.lines[k];
        let acting = &lines.ends[first..first + self.curve.order()];
        let crisp: [bool; D] = std::array::from_fn(|c| {
            acting.iter().all(|e| {
                e[c].foot_left == e[c].foot_right
                    && e[c].slope_left == 0.0
                    && e[c].slope_right == 0.0
            })
        });
        if !crisp.contains(&true) {
            return 0.0;
        }
        let size = hull
            .iter()
            .map(|h| h[1] - h[0])
            .fold(0.0_f64, f64::max)
            .max(f64::MIN_POSITIVE);
        let (knots, weights) = (self.curve.knots(), self.curve.weights());
        let mut buffer = vec![0.0; basis.len()];
        let mut sums_at = |t: f64| {
            rational_basis(knots, weights, piece.span, t, &mut buffer);
            lines.sums(first, &buffer)
        };
        let mut off = |t: f64| {
            let sums = sums_at(t);
            sums.iter()
                .zip(p)
                .zip(&crisp)
                .filter(|(_, &c)| c)
                .map(|((s, &x), _)| (s[0] - x) * (s[0] - x))
                .sum::<f64>()
                .sqrt()
        };
        let scan: Vec<(f64, f64)> = piece.params(SCAN_STEPS).map(|t| (off(t), t)).collect();
        let tolerance = REFINEMENT * (piece.hi - piece.lo);
        let mut best = 0.0_f64;
        for j in 0..=SCAN_STEPS {
            let (d, _) = scan[j];
            let falls = j == 0 || scan[j - 1].0 > d;
            let rises = j == SCAN_STEPS || scan[j + 1].0 >= d;
            if !(falls && rises) {
                continue;
            }
            let bracket = [scan[j.saturating_sub(1)].1, scan[(j + 1).min(SCAN_STEPS)].1];
            let (d, t) = golden_section_min(&mut off, bracket, tolerance);
            if d.is_nan() || d > 1e-9 * size {
                continue;
            }
            rational_basis(knots, weights, piece.span, t, basis);
            let sums = lines.sums(first, basis);
            // `p` moved onto the curve in its crisp coordinates.
            let on: [f64; D] = std::array::from_fn(|c| if crisp[c] { sums[c][0] } else { p[c] });
            best = best.max(lines.grade(first, basis, top, &on));
        }
        best
    }

    /// The largest grade of `p` on one piece under function `k`.
    ///
    /// The grade is the minimum of smooth functions (the top and each
    /// coordinate side's admitted level, [`CutLines::sides`]), so its sup on
    /// the piece is reached at an end, at a local maximum of one of them, or
    /// where two of them cross. The piece is scanned; every local maximum of
    /// each function on the scan is refined by golden sections, and every
    /// change of sign of the difference of two functions between scan points
    /// by bisection; the grade is evaluated at each of these candidates, and
    /// every local peak of the grade on the scan is refined as well.
    /// (Refining the minimum itself would not do: between two scan points it
    /// can have two peaks, where a narrow side crosses a wide one twice.)
    #[allow(clippy::too_many_arguments)]
    fn peak(
        &self,
        piece: &SpanPiece,
        k: usize,
        top: f64,
        p: &[f64; D],
        basis: &mut [f64],
        scan: &mut Vec<(f64, Sides)>,
    ) -> f64 {
        let (knots, weights) = (self.curve.knots(), self.curve.weights());
        let first = piece.first(self.curve.degree());
        let lines = &self.lines[k];
        let mut sides = |t: f64| {
            rational_basis(knots, weights, piece.span, t, basis);
            lines.sides(first, basis, top, p)
        };
        let min = |s: &Sides| s.iter().copied().fold(f64::INFINITY, f64::min);
        scan.clear();
        scan.extend(piece.params(SCAN_STEPS).map(|t| (t, sides(t))));
        let tolerance = REFINEMENT * (piece.hi - piece.lo);
        let mut best = scan
            .iter()
            .map(|(_, s)| min(s))
            .fold(f64::NEG_INFINITY, f64::max);
        let used = 1 + 2 * D;
        // A peak on the scan at an end of the piece is refined towards the
        // inside: the maximum may lie between the end and the next scan point.
        let around = |j: usize| [scan[j.saturating_sub(1)].0, scan[(j + 1).min(SCAN_STEPS)].0];
        for j in 0..=SCAN_STEPS {
            // Every local peak of the grade itself on the scan, refined.
            let g = min(&scan[j].1);
            let rises = j == 0 || min(&scan[j - 1].1) < g;
            let falls = j == SCAN_STEPS || min(&scan[j + 1].1) <= g;
            if rises && falls && g.is_finite() {
                let bracket = around(j);
                let (neg, _) = golden_section_min(|t| -min(&sides(t)), bracket, tolerance);
                best = best.max(-neg);
            }
        }
        for j in 0..=SCAN_STEPS {
            for a in 1..used {
                // A local maximum of side `a` on the scan.
                let v = scan[j].1[a];
                let rises = j == 0 || scan[j - 1].1[a] < v;
                let falls = j == SCAN_STEPS || scan[j + 1].1[a] <= v;
                if rises && falls && v.is_finite() {
                    let bracket = around(j);
                    let (_, t) = golden_section_min(|t| -sides(t)[a], bracket, tolerance);
                    best = best.max(min(&sides(t)));
                }
            }
            if j == SCAN_STEPS {
                break;
            }
            // Crossings of two functions between scan points j and j + 1.
            let (t0, s0) = scan[j];
            let (t1, s1) = scan[j + 1];
            for a in 0..used {
                for b in a + 1..used {
                    let (d0, d1) = (s0[a] - s0[b], s1[a] - s1[b]);
                    if !(d0.is_finite() && d1.is_finite()) || (d0 < 0.0) == (d1 < 0.0) {
                        continue;
                    }
                    let (mut lo, mut hi) = (t0, t1);
                    for _ in 0..CROSSING_BISECTIONS {
                        let m = 0.5 * (lo + hi);
                        if m <= lo || m >= hi {
                            break;
                        }
                        let s = sides(m);
                        if ((s[a] - s[b]) < 0.0) == (d0 < 0.0) {
                            lo = m;
                        } else {
                            hi = m;
                        }
                    }
                    best = best.max(min(&sides(lo))).max(min(&sides(hi)));
                }
            }
        }
        best
    }
}

impl<const D: usize> FuzzyCurve<D> {
    /// The membership grades of the point `p` in the fuzzy curve as a set
    /// (docs/method.md §10): for each membership function `m`, the largest
    /// level `alpha` at which some curve whose control points lie inside
    /// their `m`-cuts at `alpha` passes through `p`; 0 where none does.
    ///
    /// Coordinates whose cuts have no width on a piece (crisp stations, or
    /// crisp numbers) are met where the curve passes within 1e-9 of the
    /// piece's size of `p` in them, and the grade of the other coordinates is
    /// taken there.
    ///
    /// The sup over the domain is found by a scan of every piece of every
    /// knot span with each local peak refined by golden sections, accurate to
    /// about 1e-12 (the grade is continuous and, on a piece, a minimum of
    /// ratios of polynomials). Numbers with their own heights are handled:
    /// the lower function's top at `t` is the least height of the control
    /// points that count there.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if a coordinate of `p` is NaN or infinite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(4.0)?, n(0.0)?])];
    /// let line = FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?;
    /// // On the crisp curve: 1, 1 and h.
    /// let on = line.membership(&[2.0, 0.0])?;
    /// assert_eq!((on.upper, on.primary, on.lower), (1.0, 1.0, 0.5));
    /// // Half-way to the upper cut's edge in y: the upper grade is 1/2.
    /// let off = line.membership(&[2.0, 0.5])?;
    /// assert!((off.upper - 0.5).abs() < 1e-12 && off.primary.abs() < 1e-12);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn membership(&self, p: &[f64; D]) -> Result<Grades, Error> {
        check_point(0, p)?;
        Ok(Grader::new(self).grades(p))
    }

    /// [`FuzzyCurve::membership`] of many points, sharing the preparation.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] naming the first point with a coordinate that
    /// is NaN or infinite.
    pub fn memberships(&self, points: &[[f64; D]]) -> Result<Vec<Grades>, Error> {
        for (i, p) in points.iter().enumerate() {
            check_point(i, p)?;
        }
        let grader = Grader::new(self);
        Ok(points.iter().map(|p| grader.grades(p)).collect())
    }
}

/// Refuses a query point with a coordinate that is not finite; `index` names
/// it in the message.
pub(crate) fn check_point<const D: usize>(index: usize, p: &[f64; D]) -> Result<(), Error> {
    for (axis, &value) in crate::Axis::of::<D>().into_iter().zip(p) {
        if !value.is_finite() {
            return Err(Error::QueryPoint { index, axis, value });
        }
    }
    Ok(())
}
