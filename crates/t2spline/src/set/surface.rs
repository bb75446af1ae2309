//! The fuzzy surface as a set (docs/method.md §10): the membership grade of a
//! point, `sup over (u, v)` of the box grade, and the fuzzy height at a
//! location `(x0, y0)`.

use crate::error::Error;
use crate::fuzzy::Alpha;
use crate::nurbs::basis::basis_functions;
use crate::nurbs::surface::patches::{patch_min, Patch};
use crate::nurbs::Direction;
use crate::nurbs::NurbsSurface;
use crate::pipeline::FuzzySurface;
use crate::set::bernstein::bezier_matrix;
use crate::set::certify::{Form, Work, GRADE_TOLERANCE};
use crate::set::cut_lines::{slack, CutLines, MEMBERSHIPS};
use crate::set::grades::Grades;
use crate::set::membership::{check_point, sup_of};
use crate::set::section::SectionLevel;

/// Scan cells per patch and direction for the station's heights.
const STATION_STEPS: usize = 48;
/// Bisections of an interval end of a station section: from a bracket of
/// 1/24 of the height to about 1e-11 of it.
const END_BISECTIONS: usize = 32;

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
    /// Per function, per patch: the Bézier forms the grades are certified on.
    forms: [Vec<Form<D>>; 3],
    /// The slack of "on the set" ([`slack`]).
    slack: f64,
}

impl<'a, const D: usize> SurfaceGrader<'a, D> {
    pub(crate) fn new(surface: &'a FuzzySurface<D>) -> Self {
        let crisp = surface.crisp_surface();
        let ([ku, kv], nv) = (crisp.order(), surface.shape()[1]);
        let patches: [Vec<PatchLines<D>>; 3] = MEMBERSHIPS.map(|m| {
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
        let weights = surface.weights();
        let forms = patches.each_ref().map(|patches| {
            patches
                .iter()
                .map(|pl| {
                    let [su, sv] = pl.patch.0;
                    let mu = bezier_matrix(surface.knots(Direction::U).as_slice(), ku - 1, su);
                    let mv = bezier_matrix(surface.knots(Direction::V).as_slice(), kv - 1, sv);
                    let w: Vec<f64> = (su + 1 - ku..=su)
                        .flat_map(|i| (sv + 1 - kv..=sv).map(move |j| weights[i * nv + j]))
                        .collect();
                    Form::new([&mu, &mv], [ku, kv], &w, &pl.lines.ends, pl.top)
                })
                .collect()
        });
        SurfaceGrader {
            surface,
            patches,
            forms,
            slack: slack(surface.points()),
        }
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

    /// The largest level at which function `k` has a cut on some patch.
    pub(crate) fn top(&self, k: usize) -> f64 {
        self.patches[k]
            .iter()
            .map(|pl| pl.top)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// The grades of `p`.
    pub(crate) fn grades(&self, p: &[f64; D]) -> Grades {
        self.grades_with(p, &mut Work::default())
    }

    /// The grades of `p`, searched in the buffers `work`.
    pub(crate) fn grades_with(&self, p: &[f64; D], work: &mut Work) -> Grades {
        Grades::ordered(
            self.forms
                .each_ref()
                .map(|f| sup_of(f, p, self.slack, [0.0, 0.0, f64::INFINITY], work)),
        )
    }

    /// Whether `p` is in the region of function `k` at `alpha`: a grade of
    /// at least `alpha` less [`GRADE_TOLERANCE`] is reached at some `(u, v)`,
    /// or the certified bound comes within the tolerance of it; at level 0,
    /// whether `p` is within the slack of the support. Cells whose bound is
    /// below that level are dropped without a search.
    fn reaches(&self, k: usize, p: &[f64; D], alpha: f64, work: &mut Work) -> bool {
        let goal = alpha - GRADE_TOLERANCE;
        let found = sup_of(
            &self.forms[k],
            p,
            self.slack,
            [f64::NEG_INFINITY, goal, goal],
            work,
        );
        found >= goal
    }
}

impl<const D: usize> FuzzySurface<D> {
    /// The membership grades of the point `p` in the fuzzy surface as a set
    /// (docs/method.md §10): for each membership function, the largest level
    /// at which some surface with control points inside their cuts passes
    /// through `p` (within the set view's slack,
    /// [`RELATIVE_SLACK`](crate::set::RELATIVE_SLACK) of the job's extent).
    /// The sup over `(u, v)` is certified as for curves
    /// ([`FuzzyCurve::membership`](crate::FuzzyCurve::membership)): a branch
    /// and bound over the span rectangles on the Bernstein forms of the cut
    /// ends, the upper bound returned within
    /// [`GRADE_TOLERANCE`](crate::set::GRADE_TOLERANCE) of the lower;
    /// patches whose control points' box at level 0 misses `p` are skipped.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] if a coordinate of `p` is NaN or infinite; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
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
        self.crisp_weights_for("membership")?;
        check_point(0, p)?;
        Ok(SurfaceGrader::new(self).grades(p))
    }

    /// The slack of "on the set", as [`FuzzyCurve::set_slack`](crate::FuzzyCurve::set_slack).
    #[must_use]
    pub fn set_slack(&self) -> f64 {
        slack(self.points())
    }

    /// [`FuzzySurface::membership`] of many points, sharing the preparation.
    ///
    /// # Errors
    /// [`Error::QueryPoint`] naming the first point that is not finite; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn memberships(&self, points: &[[f64; D]]) -> Result<Vec<Grades>, Error> {
        self.crisp_weights_for("membership")?;
        for (i, p) in points.iter().enumerate() {
            check_point(i, p)?;
        }
        let grader = SurfaceGrader::new(self);
        let mut work = Work::default();
        Ok(points
            .iter()
            .map(|p| grader.grades_with(p, &mut work))
            .collect())
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
    /// [`Error::QueryPoint`] if `x0` or `y0` is not finite; [`Error::FuzzyWeights`] where the weights are fuzzy (docs/method.md §16).
    pub fn sections(
        &self,
        [x0, y0]: [f64; 2],
        levels: &[Alpha],
    ) -> Result<Vec<SectionLevel>, Error> {
        self.crisp_weights_for("a section of a surface")?;
        check_point(0, &[x0, y0])?;
        Ok(self.sections_with(&SurfaceGrader::new(self), [x0, y0], levels))
    }

    /// [`FuzzySurface::sections`] at a finite location with a grader made
    /// once for many locations.
    pub(crate) fn sections_with(
        &self,
        grader: &SurfaceGrader<'_, 3>,
        [x0, y0]: [f64; 2],
        levels: &[Alpha],
    ) -> Vec<SectionLevel> {
        let inverses = self.crisp_through([x0, y0]);
        let mut out = Vec::with_capacity(levels.len());
        for &alpha in levels {
            let [upper, primary, lower] =
                [0, 1, 2].map(|k| self.station(grader, &inverses, k, [x0, y0], alpha.get()));
            out.push(SectionLevel {
                alpha: alpha.get(),
                upper,
                primary,
                lower,
            });
        }
        out
    }

    /// Per patch (in the order of `patches()`), the parameters where the
    /// crisp surface passes through the vertical line `(x0, y0)`: the
    /// smallest horizontal distance found on the patch (a 17 × 17 scan refined
    /// by Nelder–Mead), kept if it is within the set view's slack.
    fn crisp_through(&self, [x0, y0]: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
        let crisp = self.crisp_surface();
        // Within the set view's slack, the line is met.
        let slack = slack(self.points());
        crisp
            .patches()
            .iter()
            .map(|patch| {
                let b = crisp.patch_box(patch);
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
                // The search ends near the point; Newton's method on the
                // plan map takes it to the precision the slack asks for.
                let uv = polish(&crisp, patch, uv, [x0, y0]);
                if off(uv).min(d) <= slack {
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
            // With crisp x and y on the patch every box is a point across
            // the line, met only where the crisp surface meets it (above):
            // no scan.
            let crisp_xy = pl.lines.ends.iter().all(|e| {
                e[..2].iter().all(|c| {
                    c.foot_left == c.foot_right && c.slope_left == 0.0 && c.slope_right == 0.0
                })
            });
            if crisp_xy {
                continue;
            }
            let [[a0, b0], [a1, b1]] = pl.patch.1;
            let n = STATION_STEPS;
            // The z-range of every node whose box holds the line; nodes next
            // to each other on the scan are one piece of the parameters that
            // hold it, whose z-ranges make one interval (a union of intervals
            // with continuous ends over a connected set): joined here, so
            // that a crisp z (one value per node) does not leave an interval
            // per node to refine.
            let mut nodes: Vec<Option<[f64; 2]>> = Vec::with_capacity((n + 1) * (n + 1));
            for i in 0..=n {
                for j in 0..=n {
                    let uv = [
                        a0 + (b0 - a0) * i as f64 / n as f64,
                        a1 + (b1 - a1) * j as f64 / n as f64,
                    ];
                    grader.basis(&pl.patch, [uv[0].min(b0), uv[1].min(b1)], &mut basis);
                    let b = pl.lines.box_at(0, &basis, alpha);
                    let holds = b[0][0] <= x0 && x0 <= b[0][1] && b[1][0] <= y0 && y0 <= b[1][1];
                    nodes.push(holds.then_some(b[2]));
                }
            }
            let pieces = pieces_of(&nodes, n + 1);
            from_grid |= !pieces.is_empty();
            found.extend(pieces);
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
        // Refine each end outward by bisection on the region: the scan's ends
        // lie inside the true interval.
        let mut work = Work::default();
        let mut holds = |z: f64| grader.reaches(k, &[x0, y0, z], alpha, &mut work);
        let reach = (2.0 * scale / STATION_STEPS as f64).max(f64::MIN_POSITIVE);
        for iv in joined.iter_mut().filter(|_| from_grid) {
            iv[0] = refine_end(&mut holds, iv[0], iv[0] - reach);
            iv[1] = refine_end(&mut holds, iv[1], iv[1] + reach);
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

/// The z-interval of every piece of neighbouring nodes (4-neighbours on a
/// `side × side` scan, row by row) that hold the line: the least and the
/// largest z of the piece's nodes.
fn pieces_of(nodes: &[Option<[f64; 2]>], side: usize) -> Vec<[f64; 2]> {
    let mut seen = vec![false; nodes.len()];
    let mut out = Vec::new();
    let mut stack = Vec::new();
    for start in 0..nodes.len() {
        if seen[start] || nodes[start].is_none() {
            continue;
        }
        seen[start] = true;
        stack.push(start);
        let mut range = [f64::INFINITY, f64::NEG_INFINITY];
        while let Some(q) = stack.pop() {
            if let Some([lo, hi]) = nodes[q] {
                range = [range[0].min(lo), range[1].max(hi)];
            }
            let (i, j) = (q / side, q % side);
            let mut visit = |r: usize| {
                if !seen[r] && nodes[r].is_some() {
                    seen[r] = true;
                    stack.push(r);
                }
            };
            if i > 0 {
                visit(q - side);
            }
            if i + 1 < side {
                visit(q + side);
            }
            if j > 0 {
                visit(q - 1);
            }
            if j + 1 < side {
                visit(q + 1);
            }
        }
        out.push(range);
    }
    out
}

/// Moves `inside` (in the region) towards `outside` as far as the region
/// holds, by bisection.
fn refine_end(holds: &mut impl FnMut(f64) -> bool, inside: f64, outside: f64) -> f64 {
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

/// `uv` moved by Newton's method on the plan map `(u, v) ↦ (x, y)` of
/// `crisp` towards the plan point `target`, staying in `patch` (its own
/// polynomial piece): at most 8 steps, each kept only if it comes closer.
fn polish(crisp: &NurbsSurface<3>, patch: &Patch, mut uv: [f64; 2], target: [f64; 2]) -> [f64; 2] {
    let (spans, [[a0, b0], [a1, b1]]) = (patch.0, patch.1);
    let miss = |uv: [f64; 2]| {
        let p = crisp.derivatives_in_spans(spans, uv[0], uv[1], 0)[0][0];
        (p[0] - target[0]).hypot(p[1] - target[1])
    };
    let mut best = miss(uv);
    for _ in 0..8 {
        let d = crisp.derivatives_in_spans(spans, uv[0], uv[1], 1);
        let (p, su, sv) = (d[0][0], d[1][0], d[0][1]);
        let (rx, ry) = (target[0] - p[0], target[1] - p[1]);
        let det = su[0] * sv[1] - su[1] * sv[0];
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let du = (rx * sv[1] - ry * sv[0]) / det;
        let dv = (su[0] * ry - su[1] * rx) / det;
        let next = [(uv[0] + du).clamp(a0, b0), (uv[1] + dv).clamp(a1, b1)];
        let m = miss(next);
        if m.is_nan() || m >= best {
            break;
        }
        (uv, best) = (next, m);
    }
    uv
}
