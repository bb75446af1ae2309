//! The fuzzy surface as a set (docs/method.md §10): the membership grade of a
//! point, `sup over (u, v)` of the box grade, and the fuzzy height at a
//! location `(x0, y0)`.

use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::nurbs::basis::basis_functions;
use crate::nurbs::surface::patches::{patch_min, Patch};
use crate::nurbs::Direction;
use crate::pipeline::FuzzySurface;
use crate::set::cut_lines::{CutLines, MEMBERSHIPS};
use crate::set::membership::{check_point, Grades};
use crate::set::section::SectionLevel;

/// Scan cells per patch and direction for the station's heights.
const STATION_STEPS: usize = 48;
/// Bisections of an interval end of a station section.
const END_BISECTIONS: usize = 48;

/// One patch of a surface under one membership function: the lines of the
/// `ku·kv` control points acting there (row by row), their top and their box
/// at level 0.
struct PatchLines<const D: usize> {
    patch: Patch,
    lines: CutLines<D>,
    top: f64,
    hull: [[f64; 2]; D],
}

/// A surface's membership functions, ready to grade many points.
pub(crate) struct SurfaceGrader<'a, const D: usize> {
    surface: &'a FuzzySurface<D>,
    /// Per function, per patch.
    patches: [Vec<PatchLines<D>>; 3],
}

impl<'a, const D: usize> SurfaceGrader<'a, D> {
    pub(crate) fn new(surface: &'a FuzzySurface<D>) -> Self {
        let crisp = surface.crisp_surface();
        let ([ku, kv], nv) = (crisp.order(), surface.shape()[1]);
        let patches = MEMBERSHIPS.map(|m| {
            let all = CutLines::of(surface.points(), m);
            crisp
                .patches()
                .into_iter()
                .map(|patch| {
                    let [su, sv] = patch.0;
                    let mut ends = Vec::with_capacity(ku * kv);
                    let mut top = Vec::with_capacity(ku * kv);
                    for i in su + 1 - ku..=su {
                        for j in sv + 1 - kv..=sv {
                            ends.push(all.ends[i * nv + j]);
                            top.push(all.top[i * nv + j]);
                        }
                    }
                    let lines = CutLines { ends, top };
                    let mut hull = [[f64::INFINITY, f64::NEG_INFINITY]; D];
                    for e in &lines.ends {
                        for (h, c) in hull.iter_mut().zip(e) {
                            h[0] = h[0].min(c.foot_left);
                            h[1] = h[1].max(c.foot_right);
                        }
                    }
                    let top = lines.top_of(0, ku * kv);
                    PatchLines {
                        patch,
                        lines,
                        top,
                        hull,
                    }
                })
                .collect()
        });
        SurfaceGrader { surface, patches }
    }

    /// The `ku·kv` rational basis functions of a patch at `(u, v)`, row by row.
    fn basis(&self, &([su, sv], _): &Patch, [u, v]: [f64; 2], out: &mut Vec<f64>) {
        let s = self.surface;
        let (ku, kv) = (s.degree()[0] + 1, s.degree()[1] + 1);
        let nv = s.shape()[1];
        let mut bu = [0.0; 32];
        let mut bv = [0.0; 32];
        let mut hu = Vec::new();
        let mut hv = Vec::new();
        let nu: &mut [f64] = if ku <= 32 {
            &mut bu[..ku]
        } else {
            hu.resize(ku, 0.0);
            &mut hu
        };
        let nvb: &mut [f64] = if kv <= 32 {
            &mut bv[..kv]
        } else {
            hv.resize(kv, 0.0);
            &mut hv
        };
        basis_functions(s.knots(Direction::U).as_slice(), ku - 1, su, u, nu);
        basis_functions(s.knots(Direction::V).as_slice(), kv - 1, sv, v, nvb);
        out.clear();
        let w = s.weights();
        let mut sum = 0.0;
        for (a, i) in nu.iter().zip(su + 1 - ku..) {
            for (b, j) in nvb.iter().zip(sv + 1 - kv..) {
                let r = a * b * w[i * nv + j];
                sum += r;
                out.push(r);
            }
        }
        for r in out.iter_mut() {
            *r /= sum;
        }
    }

    /// The grade of `p` at `(u, v)` of a patch under its lines.
    fn grade_at(&self, pl: &PatchLines<D>, uv: [f64; 2], p: &[f64; D]) -> f64 {
        let mut b = Vec::new();
        self.basis(&pl.patch, uv, &mut b);
        pl.lines.grade(0, &b, pl.top, p)
    }

    /// The grades of `p`.
    pub(crate) fn grades(&self, p: &[f64; D]) -> Grades {
        let mut best = [0.0_f64; 3];
        for (k, patches) in self.patches.iter().enumerate() {
            for pl in patches {
                // The slack of the crisp coordinates (below) lets a point on
                // the hull's edge, rounded out of it, count.
                let slack = 1e-9 * pl.hull.iter().map(|h| h[1] - h[0]).fold(0.0_f64, f64::max);
                if pl.top <= best[k]
                    || !pl
                        .hull
                        .iter()
                        .zip(p)
                        .all(|(h, &x)| h[0] - slack <= x && x <= h[1] + slack)
                {
                    continue;
                }
                let floor = best[k];
                let (neg, _) = patch_min(&pl.patch, |uv| -self.grade_at(pl, uv, p), |v| -v > floor);
                best[k] = best[k].max(-neg);
                best[k] = best[k].max(self.crisp_axes_grade(pl, p));
            }
        }
        Grades::ordered(best)
    }

    /// The grade of `p` where the surface passes through it in the
    /// coordinates whose cuts have no width on the patch (crisp positions, as
    /// in a terrain): there the box is a point in those coordinates, so the
    /// grade is positive only on that set of parameters, which a scan of the
    /// grade cannot find. The parameters nearest `p` in those coordinates are
    /// searched instead; within 1e-9 of the patch's size they count as
    /// passing through `p`, and the grade of the other coordinates there is
    /// returned (0 when no coordinate is crisp or none is near).
    fn crisp_axes_grade(&self, pl: &PatchLines<D>, p: &[f64; D]) -> f64 {
        let crisp: [bool; D] = std::array::from_fn(|c| {
            pl.lines.ends.iter().all(|e| {
                e[c].foot_left == e[c].foot_right
                    && e[c].slope_left == 0.0
                    && e[c].slope_right == 0.0
            })
        });
        if !crisp.contains(&true) {
            return 0.0;
        }
        let size = pl
            .hull
            .iter()
            .map(|h| h[1] - h[0])
            .fold(0.0_f64, f64::max)
            .max(f64::MIN_POSITIVE);
        let mut basis = Vec::new();
        let off = |uv: [f64; 2]| {
            let mut b = Vec::new();
            self.basis(&pl.patch, uv, &mut b);
            let sums = pl.lines.sums(0, &b);
            sums.iter()
                .zip(p)
                .zip(&crisp)
                .filter(|(_, &c)| c)
                .map(|((s, &x), _)| (s[0] - x) * (s[0] - x))
                .sum::<f64>()
                .sqrt()
        };
        let (d, uv) = patch_min(&pl.patch, off, |_| true);
        if d.is_nan() || d > 1e-9 * size {
            return 0.0;
        }
        self.basis(&pl.patch, uv, &mut basis);
        let sums = pl.lines.sums(0, &basis);
        // `p` moved onto the surface in its crisp coordinates.
        let on: [f64; D] = std::array::from_fn(|c| if crisp[c] { sums[c][0] } else { p[c] });
        pl.lines.grade(0, &basis, pl.top, &on).max(0.0)
    }
}

impl<const D: usize> FuzzySurface<D> {
    /// The membership grades of the point `p` in the fuzzy surface as a set
    /// (docs/method.md §10): for each membership function, the largest level
    /// at which some surface with control points inside their cuts passes
    /// through `p`. The sup over `(u, v)` is found patch by patch: patches
    /// whose control points' box at level 0 misses `p` are skipped, the rest
    /// scanned on a 17 × 17 grid with every local peak refined by Nelder–Mead.
    /// Coordinates whose cuts have no width (crisp positions, as in a
    /// terrain) are met where the surface passes within 1e-9 of the patch's
    /// size of `p` in them; the grade of the other coordinates is taken there.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if a coordinate of `p` is NaN or infinite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c - 0.25, c + 0.25], 0.5);
    /// let p = |x: f64, y: f64, z: f64| Ok::<_, t2spline::Error>(Nt2Point::new([n(x)?, n(y)?, n(z)?]));
    /// let net = vec![vec![p(0.0, 0.0, 0.0)?, p(0.0, 2.0, 0.0)?], vec![p(2.0, 0.0, 0.0)?, p(2.0, 2.0, 0.0)?]];
    /// let flat = FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None])?;
    /// let g = flat.membership(&[1.0, 1.0, 0.5])?;
    /// assert!((g.upper - 0.5).abs() < 1e-9 && (g.lower - 0.0).abs() < 1e-12);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn membership(&self, p: &[f64; D]) -> Result<Grades, Error> {
        check_point(0, p)?;
        Ok(SurfaceGrader::new(self).grades(p))
    }

    /// [`FuzzySurface::membership`] of many points, sharing the preparation.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] naming the first point that is not finite.
    pub fn memberships(&self, points: &[[f64; D]]) -> Result<Vec<Grades>, Error> {
        for (i, p) in points.iter().enumerate() {
            check_point(i, p)?;
        }
        let grader = SurfaceGrader::new(self);
        Ok(points.iter().map(|p| grader.grades(p)).collect())
    }
}

impl FuzzySurface<3> {
    /// The fuzzy height at the location `(x0, y0)`: for each level and
    /// membership function, the intervals of `z` where the vertical line
    /// meets the surface's region, `{ z : mu((x0, y0, z)) ≥ alpha }` (`None`
    /// where the function has no cut at that level, empty where the region
    /// does not reach the line).
    ///
    /// Each patch whose control points' box at level 0 holds `(x0, y0)` is
    /// scanned on a 49 × 49 grid of `(u, v)`: where the box at a node holds
    /// the line at the level, its z-range counts. The intervals so found are
    /// joined, and each end is then refined by bisection on the membership
    /// grade (accurate to about 1e-9 of the region's height).
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if `x0` or `y0` is not finite.
    pub fn sections(
        &self,
        [x0, y0]: [f64; 2],
        levels: &[Alpha],
    ) -> Result<Vec<SectionLevel>, Error> {
        check_point(0, &[x0, y0])?;
        let grader = SurfaceGrader::new(self);
        let inverses = self.crisp_through([x0, y0]);
        let mut out = Vec::with_capacity(levels.len());
        for &alpha in levels {
            let [upper, primary, lower] =
                [0, 1, 2].map(|k| self.station(&grader, &inverses, k, [x0, y0], alpha.get()));
            out.push(SectionLevel {
                alpha: alpha.get(),
                upper,
                primary,
                lower,
            });
        }
        Ok(out)
    }

    /// Per patch (in the order of `patches()`), the parameters where the
    /// crisp surface passes through the vertical line `(x0, y0)`: the
    /// smallest horizontal distance found on the patch (a 17 × 17 scan refined
    /// by Nelder–Mead), kept if it is below 1e-9 of the surface's size.
    fn crisp_through(&self, [x0, y0]: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
        let crisp = self.crisp_surface();
        // The size of the control points' upper cuts at level 0.
        let size = (0..3)
            .map(|c| {
                let (lo, hi) =
                    self.points()
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                            let u = p.coords()[c].upper();
                            (lo.min(u.left()), hi.max(u.right()))
                        });
                hi - lo
            })
            .fold(0.0_f64, f64::max)
            .max(f64::MIN_POSITIVE);
        crisp
            .patches()
            .iter()
            .map(|patch| {
                let b = crisp.patch_box(patch);
                let slack = 1e-9 * size;
                if !(b.min[0] - slack <= x0
                    && x0 <= b.max[0] + slack
                    && b.min[1] - slack <= y0
                    && y0 <= b.max[1] + slack)
                {
                    return Vec::new();
                }
                let off = |[u, v]: [f64; 2]| {
                    crisp
                        .eval(u, v)
                        .map_or(f64::INFINITY, |p| (p[0] - x0).hypot(p[1] - y0))
                };
                let (d, uv) = patch_min(patch, off, |_| true);
                if d <= 1e-9 * size {
                    vec![uv]
                } else {
                    Vec::new()
                }
            })
            .collect()
    }

    /// The z-intervals of function `k` at level `alpha` on the line `(x0, y0)`.
    #[allow(clippy::too_many_lines)]
    fn station(
        &self,
        grader: &SurfaceGrader<'_, 3>,
        inverses: &[Vec<[f64; 2]>],
        k: usize,
        [x0, y0]: [f64; 2],
        alpha: f64,
    ) -> Option<Vec<[f64; 2]>> {
        let patches = &grader.patches[k];
        if !patches.iter().any(|pl| pl.top >= alpha) {
            return None;
        }
        let mut found: Vec<[f64; 2]> = Vec::new();
        // Whether a scan node found a box holding the line: else only the
        // crisp surface's points count, where the boxes are exact.
        let mut from_grid = false;
        let mut scale = 0.0_f64;
        let mut basis = Vec::new();
        for (pl, crisp_uv) in patches.iter().zip(inverses) {
            scale = scale.max(pl.hull[2][1] - pl.hull[2][0]);
            if pl.top < alpha
                || !(pl.hull[0][0] <= x0
                    && x0 <= pl.hull[0][1]
                    && pl.hull[1][0] <= y0
                    && y0 <= pl.hull[1][1])
            {
                continue;
            }
            // Where the crisp surface passes through the line: its point is
            // in every box there, however thin the horizontal cuts (crisp x
            // and y, as in a terrain, or the top level).
            for &uv in crisp_uv.iter() {
                grader.basis(&pl.patch, uv, &mut basis);
                found.push(pl.lines.box_at(0, &basis, alpha)[2]);
            }
            let [[a0, b0], [a1, b1]] = pl.patch.1;
            let n = STATION_STEPS;
            for i in 0..=n {
                for j in 0..=n {
                    let uv = [
                        a0 + (b0 - a0) * i as f64 / n as f64,
                        a1 + (b1 - a1) * j as f64 / n as f64,
                    ];
                    grader.basis(&pl.patch, [uv[0].min(b0), uv[1].min(b1)], &mut basis);
                    let b = pl.lines.box_at(0, &basis, alpha);
                    if b[0][0] <= x0 && x0 <= b[0][1] && b[1][0] <= y0 && y0 <= b[1][1] {
                        found.push(b[2]);
                        from_grid = true;
                    }
                }
            }
        }
        found.sort_by(|a, b| a[0].total_cmp(&b[0]));
        // Intervals closer than the refinement's accuracy are one.
        let gap = 1e-9 * scale;
        let mut joined: Vec<[f64; 2]> = Vec::new();
        for iv in found {
            match joined.last_mut() {
                Some(last) if iv[0] <= last[1] + gap => last[1] = last[1].max(iv[1]),
                _ => joined.push(iv),
            }
        }
        // Refine each end outward by bisection on the grade: the scan's ends
        // lie inside the true interval.
        let membership = MEMBERSHIPS[k];
        let grade = |z: f64| grader.grades(&[x0, y0, z]).get(membership);
        let reach = (2.0 * scale / STATION_STEPS as f64).max(f64::MIN_POSITIVE);
        for iv in joined.iter_mut().filter(|_| from_grid) {
            iv[0] = refine_end(&grade, iv[0], iv[0] - reach, alpha);
            iv[1] = refine_end(&grade, iv[1], iv[1] + reach, alpha);
        }
        // Ends refined across a gap may now overlap.
        let mut out: Vec<[f64; 2]> = Vec::new();
        for iv in joined {
            match out.last_mut() {
                Some(last) if iv[0] <= last[1] + gap => last[1] = last[1].max(iv[1]),
                _ => out.push(iv),
            }
        }
        Some(out)
    }
}

/// Moves `inside` (grade ≥ alpha) towards `outside` as far as the grade stays
/// at least `alpha`, by bisection.
fn refine_end(grade: &impl Fn(f64) -> f64, inside: f64, outside: f64, alpha: f64) -> f64 {
    // In the region at `alpha`: a grade of at least `alpha`; at level 0 (every
    // grade is at least 0) a positive grade, whose closure is the region.
    let holds = |z: f64| {
        let g = grade(z);
        if alpha > 0.0 {
            g >= alpha - 1e-12
        } else {
            g > 0.0
        }
    };
    let (mut a, mut b) = (inside, outside);
    // Widen the bracket until its far end is outside.
    for _ in 0..20 {
        if !holds(b) {
            break;
        }
        (a, b) = (b, b + 2.0 * (b - a));
    }
    for _ in 0..END_BISECTIONS {
        let m = 0.5 * (a + b);
        if holds(m) {
            a = m;
        } else {
            b = m;
        }
    }
    a
}
