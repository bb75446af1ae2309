//! Fewer vertices for the same drawing: polylines simplified to within a
//! fraction of a pixel before they are written.

use crate::chart::geometry::Px;

/// Drops polyline vertices that lie within `tolerance` pixels of the drawn
/// line; the ends are kept.
///
/// First every vertex closer than `tolerance / 2` to the last one kept is
/// dropped (one pass, `O(n)`; dense samples of a long curve shrink to a few
/// per pixel), then Douglas–Peucker at `tolerance / 2` keeps the vertices
/// that shape the line (Douglas and Peucker 1973; `O(m log m)` for curves
/// whose farthest vertex splits a run near its middle, as smooth curves do).
/// Together they keep every dropped vertex within `tolerance` of the result.
///
/// # Examples
/// ```
/// let line: Vec<[f64; 2]> = (0..=10).map(|i| [f64::from(i), 0.0]).collect();
/// assert_eq!(t2spline_plot::simplify(&line, 0.1), vec![[0.0, 0.0], [10.0, 0.0]]);
/// ```
#[must_use]
pub fn simplify(points: &[Px], tolerance: f64) -> Vec<Px> {
    if points.len() < 3 || tolerance <= 0.0 {
        return points.to_vec();
    }
    let half = 0.5 * tolerance;
    let mut near: Vec<Px> = Vec::with_capacity(points.len());
    near.push(points[0]);
    for &p in &points[1..points.len() - 1] {
        let q = near[near.len() - 1];
        if (p[0] - q[0]).hypot(p[1] - q[1]) > half || !(p[0].is_finite() && p[1].is_finite()) {
            near.push(p);
        }
    }
    near.push(points[points.len() - 1]);
    douglas_peucker(&near, half)
}

fn douglas_peucker(points: &[Px], tolerance: f64) -> Vec<Px> {
    if points.len() < 3 {
        return points.to_vec();
    }
    let mut keep = vec![false; points.len()];
    keep[0] = true;
    keep[points.len() - 1] = true;
    let mut stack = vec![(0, points.len() - 1)];
    while let Some((a, b)) = stack.pop() {
        let (p, q) = (points[a], points[b]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let len = (dx * dx + dy * dy).sqrt();
        let dist = |r: Px| {
            if len == 0.0 {
                ((r[0] - p[0]).powi(2) + (r[1] - p[1]).powi(2)).sqrt()
            } else {
                ((r[0] - p[0]) * dy - (r[1] - p[1]) * dx).abs() / len
            }
        };
        let far = (a + 1..b)
            .map(|k| (k, dist(points[k])))
            .fold((a, 0.0), |m, c| if c.1 > m.1 { c } else { m });
        if far.1 > tolerance {
            keep[far.0] = true;
            stack.push((a, far.0));
            stack.push((far.0, b));
        }
    }
    points
        .iter()
        .zip(keep)
        .filter(|(_, k)| *k)
        .map(|(p, _)| *p)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance from `p` to the segment `a`–`b`.
    fn to_segment(p: Px, a: Px, b: Px) -> f64 {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len2 = dx * dx + dy * dy;
        let t = if len2 == 0.0 {
            0.0
        } else {
            (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
        };
        (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
    }

    #[test]
    fn every_dropped_vertex_stays_within_the_tolerance() {
        // A spiral of 20 000 samples over a few hundred pixels.
        let pts: Vec<Px> = (0..20_000)
            .map(|i| {
                let t = f64::from(i) / 400.0;
                [300.0 + 6.0 * t * t.cos(), 300.0 + 6.0 * t * t.sin()]
            })
            .collect();
        let s = simplify(&pts, 0.5);
        assert!(s.len() < pts.len() / 4, "{} of {}", s.len(), pts.len());
        assert_eq!(s[0], pts[0]);
        assert_eq!(s[s.len() - 1], pts[pts.len() - 1]);
        // Each original vertex lies within 0.5 px of the simplified line.
        let mut seg = 0;
        for p in &pts {
            while seg + 2 < s.len() && to_segment(*p, s[seg], s[seg + 1]) > 0.5 {
                seg += 1;
            }
            let d = to_segment(*p, s[seg], s[seg + 1]);
            assert!(d <= 0.5 + 1e-9, "{p:?} is {d} px off");
        }
    }
}
