//! The inverse of a one-to-one plan map (docs/method.md §14): the
//! parameters `(u, v)` of a plan point `(x, y)`, by Newton's method on the
//! plan map from a nearby start (the last point found, else the nearest of
//! a table of the plan's points). Beyond the parameter rectangle the end
//! spans' polynomials are extended, so that a point just outside the plan
//! has parameters just outside the rectangle.

use crate::measure::plan::Plan;

/// A plan map and what its inverse starts from.
#[derive(Clone, Debug)]
pub(crate) struct Inverse {
    pub(crate) plan: Plan,
    /// The parameter rectangle.
    pub(crate) domain: [[f64; 2]; 2],
    /// Points of the plan: `(x, y)` and `(u, v)`, 3 × 3 per span rectangle.
    table: Vec<([f64; 2], [f64; 2])>,
}

impl Inverse {
    /// The inverse of `plan` (checked one to one by `Plan::check_graph`).
    pub(crate) fn new(plan: Plan) -> Self {
        let mut table = Vec::new();
        for &(s, [[u0, u1], [v0, v1]]) in &plan.spans {
            for a in 0..3_u8 {
                for b in 0..3_u8 {
                    let u = u0 + (u1 - u0) * (0.25 + 0.25 * f64::from(a));
                    let v = v0 + (v1 - v0) * (0.25 + 0.25 * f64::from(b));
                    let xy = plan.xy_of(&plan.local_at(s, u, v));
                    table.push((xy, [u, v]));
                }
            }
        }
        let domain = [plan.knots[0].domain(), plan.knots[1].domain()].map(|d| [d.start, d.end]);
        Inverse {
            plan,
            domain,
            table,
        }
    }

    /// A start for [`Inverse::invert`]: the middle of the first span.
    pub(crate) fn first(&self) -> [f64; 2] {
        self.table.get(4).map_or([0.0; 2], |t| t.1)
    }

    /// Whether `uv` lies in the parameter rectangle.
    pub(crate) fn contains(&self, [u, v]: [f64; 2]) -> bool {
        let [[a, b], [c, d]] = self.domain;
        (a..=b).contains(&u) && (c..=d).contains(&v)
    }

    /// The plan map at `uv` (the end spans extended beyond its
    /// rectangle): `(x, y)`, `[x_u, x_v, y_u, y_v]` and the span rectangle.
    pub(crate) fn map(&self, [u, v]: [f64; 2]) -> ([f64; 2], [f64; 4], [usize; 2]) {
        let spans = [
            self.plan.knots[0].find_span(u),
            self.plan.knots[1].find_span(v),
        ];
        let local = self.plan.local_at(spans, u, v);
        (self.plan.xy_of(&local), local.plan, spans)
    }

    /// `ξ` of the plan point `target` by Newton's method from `start`, or
    /// `None` where it does not converge near the rectangle.
    fn newton(&self, target: [f64; 2], start: [f64; 2]) -> Option<[f64; 2]> {
        let [[a, b], [c, d]] = self.domain;
        let (wu, wv) = (b - a, d - c);
        let [mut u, mut v] = start;
        for _ in 0..50 {
            let (xy, [xu, xv, yu, yv], _) = self.map([u, v]);
            let (ex, ey) = (xy[0] - target[0], xy[1] - target[1]);
            let det = xu * yv - xv * yu;
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let mut du = (yv * ex - xv * ey) / det;
            let mut dv = (xu * ey - yu * ex) / det;
            // A step of at most half the rectangle.
            let shrink = (0.5 * wu / du.abs()).min(0.5 * wv / dv.abs()).min(1.0);
            du *= shrink;
            dv *= shrink;
            u -= du;
            v -= dv;
            if !(u.is_finite() && v.is_finite())
                || u < a - wu
                || u > b + wu
                || v < c - wv
                || v > d + wv
            {
                return None;
            }
            if du.abs() <= 1e-15 * wu.max(u.abs()) && dv.abs() <= 1e-15 * wv.max(v.abs()) {
                return Some([u, v]);
            }
            if shrink == 1.0 && du.abs() <= 1e-13 * wu && dv.abs() <= 1e-13 * wv {
                // One more step: quadratic convergence takes it to rounding.
                let (xy, [xu, xv, yu, yv], _) = self.map([u, v]);
                let (ex, ey) = (xy[0] - target[0], xy[1] - target[1]);
                let det = xu * yv - xv * yu;
                if det != 0.0 && det.is_finite() {
                    u -= (yv * ex - xv * ey) / det;
                    v -= (xu * ey - yu * ex) / det;
                }
                return Some([u, v]);
            }
        }
        None
    }

    /// `ξ` of `target`: from `start`, else from the table's nearest point.
    pub(crate) fn invert(&self, target: [f64; 2], start: [f64; 2]) -> Option<[f64; 2]> {
        self.newton(target, start).or_else(|| {
            let near = self.table.iter().min_by(|p, q| {
                let d = |r: &([f64; 2], [f64; 2])| {
                    (r.0[0] - target[0]).powi(2) + (r.0[1] - target[1]).powi(2)
                };
                d(p).total_cmp(&d(q))
            })?;
            self.newton(target, near.1)
        })
    }
}
