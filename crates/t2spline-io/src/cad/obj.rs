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
//! OBJ has no units; coordinates are the job's.

use std::fmt::Write as _;

use t2spline::job::Geometry;

use super::{real, CadMeta};

/// The OBJ text of `geometry`.
pub(super) fn render(geometry: &Geometry, meta: &CadMeta) -> String {
    let r = |x: f64| real(x, 'e');
    let mut out = String::new();
    out.push_str("# t2spline: the exact curves of a run as rational B-splines\n");
    if let Some(d) = &meta.description {
        for line in d.lines() {
            let _ = writeln!(out, "# {line}");
        }
    }
    let _ = writeln!(
        out,
        "# written {} UTC; no units (the job's)",
        meta.timestamp
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
    out
}
