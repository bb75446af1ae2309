//! The cells of a contour band and their outline: which cells of the grid
//! the band touches (the envelope's interval over the cell contains the
//! height, grown by the bilinear interpolation error), and the union of
//! those cells as polygons with holes.

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;

use crate::set::polygon::Polygon;
use crate::set::region::overlay_options;

/// Per corner, `|Δ²x f| + |Δ²y f|` (second differences along x and y;
/// 0 where a neighbour is missing or NaN).
fn curvature(f: &[f64], [cx, cy]: [usize; 2]) -> Vec<f64> {
    let at = |i: usize, j: usize| f[j * cx + i];
    let mut c = vec![0.0; f.len()];
    for j in 0..cy {
        for i in 0..cx {
            let mut s = 0.0;
            if i > 0 && i + 1 < cx {
                let d = at(i - 1, j) - 2.0 * at(i, j) + at(i + 1, j);
                if d.is_finite() {
                    s += d.abs();
                }
            }
            if j > 0 && j + 1 < cy {
                let d = at(i, j - 1) - 2.0 * at(i, j) + at(i, j + 1);
                if d.is_finite() {
                    s += d.abs();
                }
            }
            c[j * cx + i] = s;
        }
    }
    c
}

/// The largest value of `c` over the corners of cell `(i, j)` and their
/// neighbours (a 4 × 4 block of corners, clipped to the grid).
fn stencil_max(c: &[f64], [cx, cy]: [usize; 2], i: usize, j: usize) -> f64 {
    let mut m = 0.0_f64;
    for jj in j.saturating_sub(1)..(j + 3).min(cy) {
        for ii in i.saturating_sub(1)..(i + 3).min(cx) {
            m = m.max(c[jj * cx + ii]);
        }
    }
    m
}

/// Whether each of the `nx × ny` cells (row by row) belongs to the band of
/// height `z`, from the envelope `least`, `greatest` at the
/// `(nx + 1) × (ny + 1)` corners (NaN: no data):
///
/// ```text
/// min corners(least) − s_least ≤ z ≤ max corners(greatest) + s_greatest,
/// s = ¼ · max over the 4 × 4 corners around the cell of (|Δ²x f| + |Δ²y f|)
/// ```
/// `s` is twice the bilinear interpolation error `(hx²|f_xx| + hy²|f_yy|)/8`
/// with the second derivatives estimated by second differences. A cell whose
/// corners all lack data is out. Also returns the largest widening that
/// kept a cell its corners alone would not have kept (0 if none): the
/// height tolerance of the band.
pub(crate) fn band_cells(
    least: &[f64],
    greatest: &[f64],
    [nx, ny]: [usize; 2],
    z: f64,
) -> (Vec<bool>, f64) {
    let corners = [nx + 1, ny + 1];
    let (cl, cg) = (curvature(least, corners), curvature(greatest, corners));
    let mut keep = vec![false; nx * ny];
    let mut widened = 0.0_f64;
    for j in 0..ny {
        for i in 0..nx {
            let mut lo = f64::INFINITY;
            let mut hi = f64::NEG_INFINITY;
            for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let k = (j + dj) * corners[0] + i + di;
                if least[k].is_finite() && greatest[k].is_finite() {
                    lo = lo.min(least[k]);
                    hi = hi.max(greatest[k]);
                }
            }
            if lo > hi {
                continue;
            }
            let sl = 0.25 * stencil_max(&cl, corners, i, j);
            let sg = 0.25 * stencil_max(&cg, corners, i, j);
            let kept = lo - sl <= z && z <= hi + sg;
            if kept && !(lo <= z && z <= hi) {
                widened = widened.max(if z < lo { lo - z } else { z - hi });
            }
            keep[j * nx + i] = kept;
        }
    }
    (keep, widened)
}

/// Makes the kept cells nest as the true bands do: per level (`alphas`),
/// `lower ⊆ primary ⊆ upper`; per function, a band at a level inside the
/// band at every lower level.
pub(crate) fn nest(keeps: &mut [[Option<Vec<bool>>; 3]], alphas: &[f64]) {
    let or = |into: &mut Option<Vec<bool>>, from: &Option<Vec<bool>>| {
        if let (Some(a), Some(b)) = (into.as_mut(), from.as_ref()) {
            for (x, y) in a.iter_mut().zip(b) {
                *x |= *y;
            }
        }
    };
    for level in keeps.iter_mut() {
        let [upper, primary, lower] = level;
        or(primary, lower);
        or(upper, primary);
    }
    let mut order: Vec<usize> = (0..alphas.len()).collect();
    order.sort_by(|&a, &b| alphas[b].total_cmp(&alphas[a]));
    for w in order.windows(2) {
        let (higher, lower_level) = (w[0], w[1]);
        let from = keeps[higher].clone();
        for (into, from) in keeps[lower_level].iter_mut().zip(&from) {
            or(into, from);
        }
    }
}

/// The union of the kept cells (row by row, `xs.len() − 1` per row; cell
/// `(i, j)` spans `[xs[i], xs[i+1]] × [ys[j], ys[j+1]]`) as polygons with
/// holes: each row's runs of kept cells as rectangles, united by `i_overlay`
/// into OGC-valid polygons.
pub(crate) fn trace(keep: &[bool], xs: &[f64], ys: &[f64]) -> Vec<Polygon> {
    let nx = xs.len() - 1;
    let mut rectangles: Vec<Vec<[f64; 2]>> = Vec::new();
    for (j, row) in keep.chunks(nx).enumerate() {
        let mut i = 0;
        while i < nx {
            if !row[i] {
                i += 1;
                continue;
            }
            let start = i;
            while i < nx && row[i] {
                i += 1;
            }
            let (a, b, c, d) = (xs[start], xs[i], ys[j], ys[j + 1]);
            rectangles.push(vec![[a, c], [b, c], [b, d], [a, d]]);
        }
    }
    if rectangles.is_empty() {
        return Vec::new();
    }
    let shapes = FloatOverlay::with_subj_custom(&rectangles, overlay_options(), Default::default())
        .overlay(OverlayRule::Subject, FillRule::NonZero);
    let mut polygons: Vec<Polygon> = shapes.into_iter().filter_map(Polygon::from_rings).collect();
    // A stable order for the files: by the exterior's least vertex.
    let key = |g: &Polygon| {
        g.exterior.iter().fold([f64::INFINITY; 2], |m, v| {
            if (v[1], v[0]) < (m[1], m[0]) {
                *v
            } else {
                m
            }
        })
    };
    polygons.sort_by(|a, b| {
        let (ka, kb) = (key(a), key(b));
        ka[1].total_cmp(&kb[1]).then(ka[0].total_cmp(&kb[0]))
    });
    polygons
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ring_of_cells_is_a_polygon_with_a_hole() {
        // 3 × 3 cells, all but the middle one.
        let mut keep = vec![true; 9];
        keep[4] = false;
        let xs = [0.0, 1.0, 2.0, 3.0];
        let g = trace(&keep, &xs, &xs);
        assert_eq!(g.len(), 1, "{g:?}");
        assert_eq!(g[0].holes.len(), 1, "{g:?}");
        assert!((g[0].area() - 8.0).abs() < 1e-9, "{g:?}");
        assert!(g[0].contains([0.5, 0.5]) && !g[0].contains([1.5, 1.5]));
    }

    #[test]
    fn a_crest_between_corners_keeps_its_cell() {
        // f = 1 − 4·(x − ½)² on corners 0, ⅓, ⅔, 1: the middle cell's corners
        // are 8/9 while the crest inside it is 1, so z = 0.95 is off the hull
        // of every cell's corners but within the widening; z = 1.2 is not.
        let xs = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
        let f: Vec<f64> = xs
            .iter()
            .map(|x| 1.0 - 4.0 * (x - 0.5) * (x - 0.5))
            .collect();
        let rows: Vec<f64> = f.iter().chain(&f).copied().collect();
        let (keep, widened) = band_cells(&rows, &rows, [3, 1], 0.95);
        assert!((widened - (0.95 - 8.0 / 9.0)).abs() < 1e-12, "{widened}");
        assert!(keep[1], "{keep:?}");
        let (keep, _) = band_cells(&rows, &rows, [3, 1], 1.2);
        assert_eq!(keep, vec![false; 3], "{keep:?}");
    }
}
