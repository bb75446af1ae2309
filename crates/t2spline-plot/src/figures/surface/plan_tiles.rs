//! A map over a regular plan grid as tiles: the cells of one colour merged
//! into rectangles, cells without a colour (NODATA) left out.

use crate::chart::paint::Color;
use crate::chart::scene::Xy;

/// A run of equal cells in a row: first column, end column, colour.
type Run = (usize, usize, Color);

/// The cells of a grid of `[nx, ny]` cells over `extent = [x0, y0, x1, y1]`
/// (values row by row, y outer) as tiles, one list per colour: in each row
/// a run of cells of one colour is one rectangle, and a rectangle that
/// repeats the one below it (same columns, same colour) extends it; a cell
/// whose `colour` is `None` is left out (the page shows through).
#[must_use]
pub fn tiles(
    extent: [f64; 4],
    [nx, ny]: [usize; 2],
    values: &[f64],
    colour: impl Fn(f64) -> Option<Color>,
) -> Vec<(Color, Vec<[Xy; 2]>)> {
    let [x0, y0, x1, y1] = extent;
    let (dx, dy) = ((x1 - x0) / nx.max(1) as f64, (y1 - y0) / ny.max(1) as f64);
    let mut out: Vec<(Color, Vec<[Xy; 2]>)> = Vec::new();
    // The rectangles ending at the row below: (first, end column, colour)
    // → (list, index).
    let mut open: Vec<(Run, (usize, usize))> = Vec::new();
    for (j, row) in values.chunks(nx.max(1)).take(ny).enumerate() {
        let top = y0 + (j + 1) as f64 * dy;
        let mut next = Vec::new();
        let mut i = 0;
        while i < row.len() {
            let c = colour(row[i]);
            let mut e = i + 1;
            while e < row.len() && colour(row[e]) == c {
                e += 1;
            }
            if let Some(c) = c {
                let key = (i, e, c);
                if let Some(&(_, (list, at))) = open.iter().find(|(o, _)| *o == key) {
                    out[list].1[at][1][1] = top;
                    next.push((key, (list, at)));
                } else {
                    let list = match out.iter().position(|(k, _)| *k == c) {
                        Some(l) => l,
                        None => {
                            out.push((c, Vec::new()));
                            out.len() - 1
                        }
                    };
                    let bottom = y0 + j as f64 * dy;
                    let (left, right) = (x0 + i as f64 * dx, x0 + e as f64 * dx);
                    out[list].1.push([[left, bottom], [right, top]]);
                    next.push((key, (list, out[list].1.len() - 1)));
                }
            }
            i = e;
        }
        open = next;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_merge_and_nodata_is_left_out() {
        let red = Color(255, 0, 0);
        let colour = |v: f64| (!v.is_nan()).then_some(red);
        // 3 × 2 cells over [0, 3] × [0, 2]: a NODATA cell at (1, 0).
        let t = tiles(
            [0.0, 0.0, 3.0, 2.0],
            [3, 2],
            &[1.0, f64::NAN, 1.0, 1.0, 1.0, 1.0],
            colour,
        );
        assert_eq!(t.len(), 1);
        let area: f64 = t[0]
            .1
            .iter()
            .map(|[a, b]| (b[0] - a[0]) * (b[1] - a[1]))
            .sum();
        assert_eq!(area, 5.0);
        assert!(t[0].1.contains(&[[0.0, 0.0], [1.0, 1.0]]));
        assert!(t[0].1.contains(&[[0.0, 1.0], [3.0, 2.0]]));
    }
}
