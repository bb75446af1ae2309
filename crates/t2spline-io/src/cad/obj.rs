//! Wavefront OBJ free-form curves (the OBJ specification, "Free-form
//! curve/surface attributes" and "Free-form curve/surface body statements").
//!
//! ```text
//! g crisp                      a group per curve, named
//! v x y z w                    control points with their weights
//! cstype rat bspline           rational B-spline
//! deg p
//! curv u0 u1 i₁ … iₙ           the domain [u0, u1] and the control points (1-based, file-wide)
//! parm u U₀ … Uₙ₊ₚ             the whole knot vector
//! end
//! ```
//! Surfaces are `deg p q`, `surf u0 u1 v0 v1 …` (control points with the u
//! index varying fastest, as the specification orders them) and `parm u`,
//! `parm v`. OBJ has no units; coordinates are the job's.

use std::fmt::Write as _;

use t2spline::job::Geometry;
use t2spline::Direction;

use super::meta::CadMeta;
use super::real::real;

/// The OBJ text of `geometry`.
pub(super) fn render(geometry: &Geometry, meta: &CadMeta) -> String {
    let r = |x: f64| real(x, 'e');
    let mut out = String::new();
    out.push_str("# t2spline: a run's curves or surfaces as exact rational B-splines\n");
    if let Some(d) = meta.description() {
        for line in d.lines().flat_map(|l| l.split('\r')) {
            let _ = writeln!(out, "# {}", comment_text(line));
        }
    }
    let _ = writeln!(
        out,
        "# written {} UTC; units: {} (OBJ itself records none)",
        meta.timestamp(),
        meta.units().name()
    );
    let mut next = 1;
    for curve in &geometry.curves {
        let _ = writeln!(out, "g {}", curve.name);
        for piece in &curve.pieces {
            for (p, w) in piece.control_points().iter().zip(piece.weights()) {
                let _ = writeln!(out, "v {} {} {} {}", r(p[0]), r(p[1]), r(p[2]), r(*w));
            }
            let d = piece.domain();
            let _ = writeln!(out, "cstype rat bspline\ndeg {}", piece.degree());
            let _ = write!(out, "curv {} {}", r(d.start), r(d.end));
            let n = piece.control_points().len();
            for i in next..next + n {
                let _ = write!(out, " {i}");
            }
            next += n;
            out.push_str("\nparm u");
            for &u in piece.knots().as_slice() {
                let _ = write!(out, " {}", r(u));
            }
            out.push_str("\nend\n");
        }
    }
    for surface in &geometry.surfaces {
        let _ = writeln!(out, "g {}", surface.name);
        for patch in &surface.patches {
            let [nu, nv] = patch.shape();
            let [p, q] = patch.degree();
            // The specification's order: i = 0 … K1 for j = 0, then for j = 1, …
            // (the u index varying fastest).
            let (points, weights) = (patch.control_points(), patch.weights());
            for k in (0..nv).flat_map(|j| (0..nu).map(move |i| i * nv + j)) {
                if let (Some([x, y, z]), Some(&w)) = (points.get(k), weights.get(k)) {
                    let _ = writeln!(out, "v {} {} {} {}", r(*x), r(*y), r(*z), r(w));
                }
            }
            let (du, dv) = (patch.domain(Direction::U), patch.domain(Direction::V));
            let _ = writeln!(out, "cstype rat bspline\ndeg {p} {q}");
            let _ = write!(
                out,
                "surf {} {} {} {}",
                r(du.start),
                r(du.end),
                r(dv.start),
                r(dv.end)
            );
            for index in next..next + nu * nv {
                let _ = write!(out, " {index}");
            }
            next += nu * nv;
            for (name, direction) in [("u", Direction::U), ("v", Direction::V)] {
                let _ = write!(out, "\nparm {name}");
                for &u in patch.knots(direction).as_slice() {
                    let _ = write!(out, " {}", r(u));
                }
            }
            out.push_str("\nend\n");
        }
    }
    out
}

/// A line of a comment without control characters: a tab becomes a space,
/// every other control character (an escape, a bell, DEL, C1 controls) `?`,
/// so that no reader or terminal acts on the job's description.
fn comment_text(line: &str) -> String {
    line.chars()
        .map(|c| match c {
            '\t' => ' ',
            c if c.is_control() => '?',
            c => c,
        })
        .collect()
}
