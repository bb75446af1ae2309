//! The contour of a crisp height field at `z` by marching squares (Lorensen
//! and Cline's cases in two dimensions): per cell, the points where the
//! edges cross `z`, by linear interpolation, joined into segments; segments
//! sharing an edge point chained into polylines.

use std::collections::HashMap;

/// The polylines where `f` (at the corners `(xs[i], ys[j])`, row by row)
/// crosses `z`. A corner at `z` counts as above; a cell with a NaN corner is
/// skipped. A saddle (corners alternating) is resolved by the mean of the
/// corners. Closed polylines repeat their first point at the end.
pub(crate) fn contour_lines(f: &[f64], xs: &[f64], ys: &[f64], z: f64) -> Vec<Vec<[f64; 2]>> {
    let (cx, cy) = (xs.len(), ys.len());
    if cx < 2 || cy < 2 {
        return Vec::new();
    }
    let at = |i: usize, j: usize| f[j * cx + i] - z;
    // Edge ids: 2·corner for the edge towards +x, 2·corner + 1 towards +y.
    let point = |edge: usize| -> [f64; 2] {
        let (corner, along_y) = (edge / 2, edge % 2 == 1);
        let (i, j) = (corner % cx, corner / cx);
        let (i2, j2) = if along_y { (i, j + 1) } else { (i + 1, j) };
        let (a, b) = (at(i, j), at(i2, j2));
        let t = (a / (a - b)).clamp(0.0, 1.0);
        [xs[i] + t * (xs[i2] - xs[i]), ys[j] + t * (ys[j2] - ys[j])]
    };
    let mut segments: Vec<[usize; 2]> = Vec::new();
    for j in 0..cy - 1 {
        for i in 0..cx - 1 {
            let v = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            if v.iter().any(|x| x.is_nan()) {
                continue;
            }
            let c = j * cx + i;
            // Edges in order around the cell: bottom, right, top, left.
            let edges = [2 * c, 2 * (c + 1) + 1, 2 * (c + cx), 2 * c + 1];
            let above = v.map(|x| x >= 0.0);
            let crossed: Vec<usize> = (0..4)
                .filter(|&k| above[k] != above[(k + 1) % 4])
                .map(|k| edges[k])
                .collect();
            match *crossed.as_slice() {
                [a, b] => segments.push([a, b]),
                [a, b, c2, d] => {
                    // Saddle: the mean on the side of corner 0 joins the
                    // crossings around corner 0 and corner 2.
                    let mean = 0.25 * v.iter().sum::<f64>();
                    if (mean >= 0.0) == above[0] {
                        segments.push([a, b]);
                        segments.push([c2, d]);
                    } else {
                        segments.push([d, a]);
                        segments.push([b, c2]);
                    }
                }
                _ => {}
            }
        }
    }
    chain(&segments)
        .into_iter()
        .map(|l| l.into_iter().map(point).collect())
        .collect()
}

/// Segments (pairs of edge ids) joined where they share an id: each id is on
/// at most two segments (the two cells beside its edge).
fn chain(segments: &[[usize; 2]]) -> Vec<Vec<usize>> {
    let mut by_edge: HashMap<usize, Vec<usize>> = HashMap::new();
    for (k, s) in segments.iter().enumerate() {
        for e in s {
            by_edge.entry(*e).or_default().push(k);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut lines = Vec::new();
    // Open lines start at an id on one segment only; closed ones anywhere.
    let mut starts: Vec<(usize, usize)> = Vec::new();
    for (k, s) in segments.iter().enumerate() {
        for e in s {
            if by_edge[e].len() == 1 {
                starts.push((k, *e));
            }
        }
    }
    starts.extend(segments.iter().enumerate().map(|(k, s)| (k, s[0])));
    for (first, start) in starts {
        if used[first] {
            continue;
        }
        let mut line = vec![start];
        let (mut k, mut at) = (first, start);
        loop {
            used[k] = true;
            let s = segments[k];
            let next = if s[0] == at { s[1] } else { s[0] };
            line.push(next);
            at = next;
            match by_edge[&at].iter().find(|&&m| !used[m]) {
                Some(&m) => k = m,
                None => break,
            }
        }
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cone_gives_one_closed_ring_near_the_circle() {
        let n = 41;
        let xs: Vec<f64> = (0..n)
            .map(|k| -1.0 + 2.0 * k as f64 / (n - 1) as f64)
            .collect();
        let f: Vec<f64> = xs
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| x.hypot(y)))
            .collect();
        let lines = contour_lines(&f, &xs, &xs, 0.5);
        assert_eq!(lines.len(), 1, "{lines:?}");
        let l = &lines[0];
        assert_eq!(l.first(), l.last());
        assert!(
            l.iter().all(|p| (p[0].hypot(p[1]) - 0.5).abs() < 2e-3),
            "{l:?}"
        );
    }

    #[test]
    fn a_plane_gives_one_open_line() {
        let xs = [0.0, 1.0, 2.0, 3.0];
        let f: Vec<f64> = xs.iter().flat_map(|_| xs.iter().copied()).collect();
        let lines = contour_lines(&f, &xs, &xs, 1.5);
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert_eq!(lines[0].len(), 4);
        assert!(lines[0].iter().all(|p| (p[0] - 1.5).abs() < 1e-12));
    }
}
