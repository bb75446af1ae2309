//! What a text or legend must not cover, in pixels, indexed so that asking
//! whether a box is free costs time in proportion to what lies near the box,
//! not to everything drawn.
//!
//! Segments (curves, bars, rules) and boxes (markers, placed texts) go into a
//! uniform grid of cells; a query visits the cells under the box and tests only
//! the segments and boxes listed there. Filled areas are rasterised once, at
//! pixel centres (even–odd rule), into a coverage mask whose summed-area table
//! answers "does this box cover any filled pixel" in constant time. Building
//! the index is linear in what is drawn, each query in what lies near it, so
//! placing `n` labels and a legend costs `O(n)` queries of bounded size rather
//! than `O(n²)` tests.

use std::cell::OnceCell;

use crate::chart::geometry::{Px, Rect};
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Mark, Panel};

/// Side of a grid cell in pixels: a few times a curve's sampling step and
/// about a label's height.
const CELL: f64 = 12.0;

/// Tag of a box's id; segments have ids below it.
const RECT_TAG: u32 = 1 << 31;

/// Everything drawn in a panel that a text or legend must not cover.
#[derive(Debug)]
pub struct Obstacles {
    /// The region indexed; things outside are clamped into its edge cells (so
    /// they are still found) and areas are clipped to it.
    bounds: Rect,
    cols: usize,
    rows: usize,
    cells: Vec<Vec<u32>>,
    segments: Vec<[Px; 2]>,
    rects: Vec<Rect>,
    /// Filled pixels of the areas, row by row (`cols_px × rows_px`).
    fill: Vec<bool>,
    fill_size: [usize; 2],
    /// Summed-area table of `fill`, built at the first query after a change.
    sums: OnceCell<Vec<u32>>,
}

impl Obstacles {
    /// An empty index of the pixels in `bounds` (a panel's plot area).
    #[must_use]
    pub fn new(bounds: Rect) -> Obstacles {
        let count = |len: f64, size: f64| ((len / size).ceil().max(1.0) as usize).min(4096);
        let (cols, rows) = (count(bounds.w, CELL), count(bounds.h, CELL));
        let fill_size = [count(bounds.w, 1.0), count(bounds.h, 1.0)];
        Obstacles {
            bounds,
            cols,
            rows,
            cells: vec![Vec::new(); cols * rows],
            segments: Vec::new(),
            rects: Vec::new(),
            fill: Vec::new(),
            fill_size,
            sums: OnceCell::new(),
        }
    }

    /// The cells a box covers, as column and row ranges (clamped to the grid).
    fn cell_range(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> ([usize; 2], [usize; 2]) {
        let cell = |v: f64, origin: f64, n: usize| {
            let c = ((v - origin) / CELL).floor();
            if c.is_nan() || c < 0.0 {
                0
            } else {
                (c as usize).min(n - 1)
            }
        };
        let b = &self.bounds;
        (
            [cell(x0, b.x, self.cols), cell(x1, b.x, self.cols)],
            [cell(y0, b.y, self.rows), cell(y1, b.y, self.rows)],
        )
    }

    fn insert(&mut self, id: u32, x0: f64, y0: f64, x1: f64, y1: f64) {
        let (cx, cy) = self.cell_range(x0, y0, x1, y1);
        for row in cy[0]..=cy[1] {
            for col in cx[0]..=cx[1] {
                self.cells[row * self.cols + col].push(id);
            }
        }
    }

    /// Adds a line segment.
    pub fn add_segment(&mut self, a: Px, b: Px) {
        if !(a.iter().chain(&b).all(|v| v.is_finite())) {
            return;
        }
        let id = self.segments.len() as u32;
        self.segments.push([a, b]);
        self.insert(
            id,
            a[0].min(b[0]),
            a[1].min(b[1]),
            a[0].max(b[0]),
            a[1].max(b[1]),
        );
    }

    /// Adds a polyline as its segments.
    pub fn add_polyline(&mut self, pts: &[Px]) {
        for w in pts.windows(2) {
            self.add_segment(w[0], w[1]);
        }
    }

    /// Adds a box (a marker, a placed text, a legend).
    pub fn add_rect(&mut self, r: Rect) {
        if !(r.x.is_finite() && r.y.is_finite() && r.w.is_finite() && r.h.is_finite()) {
            return;
        }
        let id = self.rects.len() as u32 | RECT_TAG;
        self.rects.push(r);
        self.insert(id, r.x, r.y, r.right(), r.bottom());
    }

    /// Adds a filled polygon (even–odd rule), clipped to the bounds.
    pub fn add_area(&mut self, poly: &[Px]) {
        let [w, h] = self.fill_size;
        if self.fill.is_empty() {
            self.fill = vec![false; w * h];
        }
        let (x0, y0) = (self.bounds.x, self.bounds.y);
        // Each edge crosses the pixel-centre rows from `first` to `last`.
        let mut starts: Vec<Vec<usize>> = vec![Vec::new(); h];
        let mut edges = Vec::new();
        let n = poly.len();
        for k in 0..n {
            let (a, b) = (poly[k], poly[(k + 1) % n]);
            if !(a.iter().chain(&b).all(|v| v.is_finite())) || a[1] == b[1] {
                continue;
            }
            let (lo, hi) = (a[1].min(b[1]) - y0 - 0.5, a[1].max(b[1]) - y0 - 0.5);
            // Rows j with lo <= j < hi (half-open, so a shared vertex counts once).
            let first = lo.ceil().max(0.0);
            let last = (hi.ceil() - 1.0).min(h as f64 - 1.0);
            if first > last {
                continue;
            }
            starts[first as usize].push(edges.len());
            edges.push((a, b, last as usize));
        }
        let mut active: Vec<usize> = Vec::new();
        let mut xs: Vec<f64> = Vec::new();
        for (j, new) in starts.iter().enumerate() {
            active.retain(|&e| edges[e].2 >= j);
            active.extend(new);
            let y = y0 + j as f64 + 0.5;
            xs.clear();
            xs.extend(active.iter().map(|&e| {
                let (a, b, _) = edges[e];
                a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            }));
            xs.sort_by(f64::total_cmp);
            for pair in xs.chunks_exact(2) {
                // Pixel centres x0 + i + 0.5 in [pair[0], pair[1]).
                let from = (pair[0] - x0 - 0.5).ceil().max(0.0);
                let to = ((pair[1] - x0 - 0.5).ceil()).min(w as f64);
                if from < to {
                    let row = &mut self.fill[j * w..(j + 1) * w];
                    row[from as usize..to as usize].fill(true);
                }
            }
        }
        self.sums = OnceCell::new();
    }

    /// Adds everything of `other` (same bounds expected; boxes and segments
    /// are re-indexed, filled pixels merged where the bounds agree).
    pub fn extend(&mut self, other: &Obstacles) {
        for s in &other.segments {
            self.add_segment(s[0], s[1]);
        }
        for r in &other.rects {
            self.add_rect(*r);
        }
        if !other.fill.is_empty()
            && other.fill_size == self.fill_size
            && other.bounds == self.bounds
        {
            if self.fill.is_empty() {
                self.fill.clone_from(&other.fill);
            } else {
                for (a, b) in self.fill.iter_mut().zip(&other.fill) {
                    *a |= *b;
                }
            }
            self.sums = OnceCell::new();
        }
    }

    /// Whether `r` covers a filled pixel.
    fn covers_fill(&self, r: &Rect) -> bool {
        if self.fill.is_empty() {
            return false;
        }
        let [w, h] = self.fill_size;
        let sums = self.sums.get_or_init(|| {
            let mut s = vec![0u32; (w + 1) * (h + 1)];
            for j in 0..h {
                let mut row = 0u32;
                for i in 0..w {
                    row += u32::from(self.fill[j * w + i]);
                    s[(j + 1) * (w + 1) + i + 1] = s[j * (w + 1) + i + 1] + row;
                }
            }
            s
        });
        // Pixel centres x0 + i + 0.5 inside [r.x, r.right()].
        let range = |lo: f64, hi: f64, origin: f64, n: usize| {
            let a = (lo - origin - 0.5).ceil().clamp(0.0, n as f64) as usize;
            let b = ((hi - origin - 0.5).floor() + 1.0).clamp(0.0, n as f64) as usize;
            (a, b)
        };
        let (i0, i1) = range(r.x, r.right(), self.bounds.x, w);
        let (j0, j1) = range(r.y, r.bottom(), self.bounds.y, h);
        if i0 >= i1 || j0 >= j1 {
            return false;
        }
        let at = |i: usize, j: usize| sums[j * (w + 1) + i];
        at(i1, j1) + at(i0, j0) > at(i0, j1) + at(i1, j0)
    }

    /// The ids of segments and boxes listed in the cells under `r`, once each.
    fn near(&self, r: &Rect) -> Vec<u32> {
        let (cx, cy) = self.cell_range(r.x, r.y, r.right(), r.bottom());
        let mut ids = Vec::new();
        for row in cy[0]..=cy[1] {
            for col in cx[0]..=cx[1] {
                ids.extend_from_slice(&self.cells[row * self.cols + col]);
            }
        }
        ids.sort_unstable();
        ids.dedup();
        ids
    }

    fn meets(&self, id: u32, r: &Rect) -> bool {
        if id & RECT_TAG == 0 {
            let [a, b] = self.segments[id as usize];
            r.meets_segment(a, b)
        } else {
            self.rects[(id & !RECT_TAG) as usize].overlaps(r)
        }
    }

    /// How many obstacles `r` covers (0 means free); all filled areas together
    /// count as one.
    #[must_use]
    pub fn hits(&self, r: &Rect) -> usize {
        let near = self.near(r);
        near.iter().filter(|&&id| self.meets(id, r)).count() + usize::from(self.covers_fill(r))
    }

    /// Whether `r` covers nothing (a faster [`Obstacles::hits`]` == 0`).
    #[must_use]
    pub fn is_free(&self, r: &Rect) -> bool {
        !self.covers_fill(r) && !self.near(r).iter().any(|&id| self.meets(id, r))
    }

    /// Whether the segment `a`–`b` crosses a drawn segment or box (a leader
    /// line should not cut through the drawing).
    #[must_use]
    pub fn crosses(&self, a: Px, b: Px) -> bool {
        let bbox = Rect {
            x: a[0].min(b[0]),
            y: a[1].min(b[1]),
            w: (a[0] - b[0]).abs(),
            h: (a[1] - b[1]).abs(),
        };
        self.near(&bbox).iter().any(|&id| {
            if id & RECT_TAG == 0 {
                let [c, d] = self.segments[id as usize];
                segments_cross(a, b, c, d)
            } else {
                self.rects[(id & !RECT_TAG) as usize].meets_segment(a, b)
            }
        })
    }

    /// Whether `r` covers no line and no box; it may lie on a filled area
    /// (a text with a halo reads well on a pale band).
    #[must_use]
    pub fn is_clear(&self, r: &Rect) -> bool {
        !self.near(r).iter().any(|&id| self.meets(id, r))
    }

    /// Whether `r` overlaps one of the boxes (texts, markers, legend).
    #[must_use]
    pub fn overlaps_rect(&self, r: &Rect) -> bool {
        self.near(r)
            .iter()
            .any(|&id| id & RECT_TAG != 0 && self.meets(id, r))
    }
}

/// Whether the segments `a`–`b` and `c`–`d` share a point (orientation
/// test; touching counts).
fn segments_cross(a: Px, b: Px, c: Px, d: Px) -> bool {
    let orient =
        |p: Px, q: Px, r: Px| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: Px, q: Px, r: Px| {
        orient(p, q, r) == 0.0
            && r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    on(c, d, a) || on(c, d, b) || on(a, b, c) || on(a, b, d)
}

/// Half the side of a marker's box, in pixels, with its outline.
#[must_use]
pub fn marker_half(size: f64) -> f64 {
    0.5 * size + 1.0
}

/// Everything drawn in `panel` as pixel obstacles (texts excluded: they are
/// placed last, around what is drawn).
#[must_use]
pub fn panel_obstacles(panel: &Panel, pl: &PanelLayout) -> Obstacles {
    let mut o = Obstacles::new(pl.plot);
    add_panel(&mut o, panel, pl);
    o
}

/// The box of a [`Mark::Text`] centred at `at`.
#[must_use]
pub fn text_rect(pl: &PanelLayout, at: [f64; 2], text: &str) -> Rect {
    let [x, y] = pl.to_px(at);
    let w = crate::chart::font::text_width(text, crate::chart::paint::font_size::TICK);
    let h = crate::chart::font::line_height(crate::chart::paint::font_size::TICK);
    Rect {
        x: x - 0.5 * w,
        y: y - 0.5 * h,
        w,
        h,
    }
}

/// Adds what `panel` draws to `o`.
pub fn add_panel(o: &mut Obstacles, panel: &Panel, pl: &PanelLayout) {
    let px = |points: &[[f64; 2]]| points.iter().map(|&p| pl.to_px(p)).collect::<Vec<Px>>();
    for item in &panel.items {
        match &item.mark {
            Mark::Line { points, .. } => o.add_polyline(&px(points)),
            Mark::Area { points, .. } => o.add_area(&px(points)),
            // Holes count as covered: a label in a hole would sit on no
            // data, but between the region's edges.
            Mark::Region { rings, .. } => {
                for r in rings {
                    o.add_area(&px(r));
                }
            }
            Mark::Tiles { tiles } => {
                for [a, b] in tiles.iter().flat_map(|(_, t)| t) {
                    o.add_area(&px(&[*a, [b[0], a[1]], *b, [a[0], b[1]]]));
                }
            }
            Mark::Markers { points, marker } => {
                let r = marker_half(marker.size);
                for [x, y] in pl.marker_px(points) {
                    o.add_rect(Rect {
                        x: x - r,
                        y: y - r,
                        w: 2.0 * r,
                        h: 2.0 * r,
                    });
                }
            }
            Mark::Segments { segments, .. } => {
                for s in segments {
                    o.add_segment(pl.to_px(s[0]), pl.to_px(s[1]));
                }
            }
            Mark::HRule { y, .. } => {
                let py = pl.to_px([0.0, *y])[1];
                o.add_segment([pl.plot.x, py], [pl.plot.right(), py]);
            }
            Mark::VRule { x, .. } => {
                let px = pl.to_px([*x, 0.0])[0];
                o.add_segment([px, pl.plot.y], [px, pl.plot.bottom()]);
            }
            Mark::Mesh { facets } => {
                for f in facets {
                    if f.points.len() > 2 {
                        o.add_area(&px(&f.points));
                    }
                    for s in &f.lines {
                        o.add_segment(pl.to_px(s[0]), pl.to_px(s[1]));
                    }
                }
            }
            Mark::Text { at, text } => o.add_rect(text_rect(pl, *at, text)),
            Mark::Label { .. } | Mark::Empty => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 10-pixel square at (10, 10).
    const R: Rect = square(10.0, 10.0, 10.0);

    const fn square(x: f64, y: f64, side: f64) -> Rect {
        Rect {
            x,
            y,
            w: side,
            h: side,
        }
    }

    fn panel() -> Obstacles {
        Obstacles::new(Rect {
            x: 0.0,
            y: 0.0,
            w: 200.0,
            h: 100.0,
        })
    }

    #[test]
    fn segments_and_boxes_are_found_only_where_they_are() {
        let mut o = panel();
        o.add_segment([0.0, 15.0], [30.0, 15.0]);
        o.add_rect(Rect { x: 100.0, ..R });
        assert_eq!(o.hits(&R), 1);
        assert!(!o.is_free(&R));
        assert!(o.is_free(&Rect { y: 30.0, ..R }));
        assert_eq!(o.hits(&Rect { x: 105.0, ..R }), 1);
        assert!(o.overlaps_rect(&Rect { x: 105.0, ..R }));
        assert!(!o.overlaps_rect(&R));
        // A long diagonal is found far from its ends.
        o.add_segment([0.0, 100.0], [200.0, 0.0]);
        assert_eq!(
            o.hits(&Rect {
                x: 96.0,
                y: 46.0,
                w: 8.0,
                h: 8.0
            }),
            1
        );
        // Things beyond the bounds are still found.
        o.add_segment([-50.0, 5.0], [-40.0, 5.0]);
        assert_eq!(
            o.hits(&Rect {
                x: -60.0,
                y: 0.0,
                w: 30.0,
                h: 10.0
            }),
            1
        );
    }

    #[test]
    fn leaders_cross_what_lies_across_them() {
        let mut o = panel();
        o.add_segment([50.0, 0.0], [50.0, 100.0]);
        o.add_rect(Rect { x: 120.0, ..R });
        assert!(o.crosses([40.0, 50.0], [60.0, 40.0]));
        assert!(!o.crosses([40.0, 50.0], [45.0, 90.0]));
        assert!(o.crosses([110.0, 5.0], [130.0, 25.0]), "through the box");
        assert!(!o.crosses([110.0, 5.0], [115.0, 25.0]));
    }

    #[test]
    fn filled_areas_count_once_where_a_pixel_is_covered() {
        let mut o = panel();
        o.add_area(&[[0.0, 0.0], [50.0, 0.0], [50.0, 50.0], [0.0, 50.0]]);
        o.add_area(&[[20.0, 20.0], [80.0, 20.0], [80.0, 80.0]]);
        assert_eq!(o.hits(&R), 1);
        assert_eq!(
            o.hits(&Rect {
                x: 45.0,
                y: 25.0,
                w: 10.0,
                h: 10.0
            }),
            1
        );
        assert!(o.is_free(&Rect {
            x: 60.0,
            y: 5.0,
            w: 10.0,
            h: 10.0
        }));
        // Inside the triangle, far from its vertices and edges.
        assert!(!o.is_free(&Rect {
            x: 70.0,
            y: 40.0,
            w: 3.0,
            h: 3.0
        }));
        // Below the diagonal of the triangle: outside.
        assert!(o.is_free(&Rect {
            x: 60.0,
            y: 70.0,
            w: 3.0,
            h: 3.0
        }));
    }

    #[test]
    fn a_ring_leaves_its_hole_free() {
        // Even–odd: a square with a square hole, as one polygon.
        let mut o = panel();
        o.add_area(&[
            [0.0, 0.0],
            [90.0, 0.0],
            [90.0, 90.0],
            [0.0, 90.0],
            [0.0, 0.0],
            [30.0, 30.0],
            [60.0, 30.0],
            [60.0, 60.0],
            [30.0, 60.0],
            [30.0, 30.0],
        ]);
        assert!(o.is_free(&Rect {
            x: 40.0,
            y: 40.0,
            w: 10.0,
            h: 10.0
        }));
        assert!(!o.is_free(&Rect {
            x: 5.0,
            y: 40.0,
            w: 10.0,
            h: 10.0
        }));
    }

    #[test]
    fn extend_merges_everything() {
        let mut a = panel();
        let mut b = panel();
        b.add_segment([0.0, 15.0], [30.0, 15.0]);
        b.add_rect(Rect { x: 100.0, ..R });
        b.add_area(&[[150.0, 50.0], [190.0, 50.0], [190.0, 90.0]]);
        a.extend(&b);
        assert_eq!(a.hits(&R), 1);
        assert_eq!(a.hits(&Rect { x: 100.0, ..R }), 1);
        assert_eq!(
            a.hits(&Rect {
                x: 180.0,
                y: 70.0,
                w: 5.0,
                h: 5.0
            }),
            1
        );
    }
}
