//! Where everything goes on the page: panel boxes, data-to-pixel transforms with
//! equal aspect where asked, ticks, the legend (inside a panel where it covers
//! nothing, otherwise below the panels) and the colour bar.
//!
//! A layout can be fitted to several figures of one kind at once (the report's
//! figures at every alpha), so that axes and legend stay put while the data move.

use crate::font::{cap_height, line_height, text_width};
use crate::geometry::{Obstacles, Px, Rect};
use crate::scene::{Figure, Mark, Panel, Xy};
use crate::style::font_size;
use crate::ticks::{decimals_for, nice_ticks, tick_label};

/// Outer margin of the page.
const PAD: f64 = 10.0;
/// Length of a tick mark.
pub const TICK_LEN: f64 = 5.0;
/// Legend: sample width, gap, row height, padding.
pub const LEGEND_SWATCH: f64 = 30.0;
const LEGEND_GAP: f64 = 6.0;
/// Height of one legend row.
pub const LEGEND_ROW: f64 = 16.0;
const LEGEND_PAD: f64 = 7.0;
/// Width reserved right of the panels for a colour bar and its labels.
const COLORBAR_SPACE: f64 = 96.0;

/// One axis of a panel: its range and ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisLayout {
    /// The data range shown.
    pub range: [f64; 2],
    /// Tick values.
    pub ticks: Vec<f64>,
    /// Decimals of the tick labels.
    pub decimals: usize,
}

impl AxisLayout {
    /// The tick labels.
    #[must_use]
    pub fn labels(&self) -> Vec<String> {
        self.ticks
            .iter()
            .map(|&t| tick_label(t, self.decimals))
            .collect()
    }
}

/// A placed panel.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelLayout {
    /// The plot area in pixels.
    pub plot: Rect,
    /// Horizontal axis.
    pub x: AxisLayout,
    /// Vertical axis.
    pub y: AxisLayout,
}

impl PanelLayout {
    /// Data coordinates to pixels.
    #[must_use]
    pub fn to_px(&self, p: Xy) -> Px {
        let [x0, x1] = self.x.range;
        let [y0, y1] = self.y.range;
        [
            self.plot.x + (p[0] - x0) / (x1 - x0) * self.plot.w,
            self.plot.bottom() - (p[1] - y0) / (y1 - y0) * self.plot.h,
        ]
    }

    /// The pixels of the marker centres that lie in the plot area (to within
    /// 0.01 px): markers are not clipped, so that one at the edge shows whole,
    /// but one whose centre lies outside a zoomed panel is left out.
    #[must_use]
    pub fn marker_px(&self, points: &[Xy]) -> Vec<Px> {
        let r = &self.plot;
        let shows = |px: &Px| {
            (r.x - 0.01..=r.right() + 0.01).contains(&px[0])
                && (r.y - 0.01..=r.bottom() + 0.01).contains(&px[1])
        };
        points
            .iter()
            .map(|&p| self.to_px(p))
            .filter(shows)
            .collect()
    }
}

/// The placed legend: its box and the top-left corner of each entry.
#[derive(Clone, Debug, PartialEq)]
pub struct LegendLayout {
    /// The frame.
    pub rect: Rect,
    /// Top-left corner of each entry's row.
    pub entries: Vec<Px>,
    /// Index of the panel it sits in; `None` when below the panels.
    pub panel: Option<usize>,
}

/// A whole page.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Page width in pixels.
    pub width: f64,
    /// Page height in pixels.
    pub height: f64,
    /// Baseline of the title.
    pub title_baseline: f64,
    /// Baseline of the subtitle.
    pub subtitle_baseline: f64,
    /// The panels.
    pub panels: Vec<PanelLayout>,
    /// The legend, if the figure has entries.
    pub legend: Option<LegendLayout>,
    /// The colour bar's swatch column, if any.
    pub colorbar: Option<Rect>,
    /// Polylines are simplified to within this many pixels ([`crate::svg::simplify`]).
    pub tolerance: f64,
}

/// The default simplification tolerance: a tenth of a pixel, invisible even in
/// the 3× PNG.
pub const TOLERANCE: f64 = 0.1;

/// Data bounds of a panel's items: `[x0, x1, y0, y1]`.
fn bounds(panel: &Panel) -> Option<[f64; 4]> {
    let mut b = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut add = |p: Xy| {
        if p[0].is_finite() && p[1].is_finite() {
            b = [
                b[0].min(p[0]),
                b[1].max(p[0]),
                b[2].min(p[1]),
                b[3].max(p[1]),
            ];
        }
    };
    for item in &panel.items {
        match &item.mark {
            Mark::Line { points, .. }
            | Mark::Area { points, .. }
            | Mark::Markers { points, .. } => {
                points.iter().copied().for_each(&mut add);
            }
            Mark::Segments { segments, .. } => {
                segments.iter().flatten().copied().for_each(&mut add)
            }
            Mark::Label { anchor, .. } => add(*anchor),
            Mark::HRule { .. } | Mark::Empty => {}
        }
    }
    (b[0] <= b[1]).then_some(b)
}

/// `[lo, hi]` padded by 5 % on each side (a degenerate range gets a unit width).
fn padded(lo: f64, hi: f64) -> [f64; 2] {
    let span = hi - lo;
    let pad = if span > 1e-12 * (lo.abs() + hi.abs()).max(1e-300) {
        0.05 * span
    } else {
        0.5 * lo.abs().max(1.0)
    };
    [lo - pad, hi + pad]
}

fn axis(range: [f64; 2], pixels: f64, spacing: f64) -> AxisLayout {
    let target = ((pixels / spacing).round() as usize).max(3);
    let (ticks, step) = nice_ticks(range[0], range[1], target);
    AxisLayout {
        range,
        ticks,
        decimals: decimals_for(step),
    }
}

/// The data ranges of each panel over all figures (fixed ranges win).
fn data_ranges(figures: &[&Figure]) -> Vec<([f64; 2], [f64; 2])> {
    let first = figures[0];
    (0..first.panels.len())
        .map(|i| {
            let mut b = [
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ];
            for f in figures {
                if let Some(c) = f.panels.get(i).and_then(bounds) {
                    b = [
                        b[0].min(c[0]),
                        b[1].max(c[1]),
                        b[2].min(c[2]),
                        b[3].max(c[3]),
                    ];
                }
            }
            if b[0] > b[1] {
                b = [0.0, 1.0, 0.0, 1.0];
            }
            let p = &first.panels[i];
            (
                p.x_range.unwrap_or_else(|| padded(b[0], b[1])),
                p.y_range.unwrap_or_else(|| padded(b[2], b[3])),
            )
        })
        .collect()
}

/// Expands the shorter range so that one unit has the same length on both axes.
fn equalise(x: [f64; 2], y: [f64; 2], w: f64, h: f64) -> ([f64; 2], [f64; 2]) {
    let scale = (w / (x[1] - x[0])).min(h / (y[1] - y[0]));
    let grow = |r: [f64; 2], len: f64| {
        let c = 0.5 * (r[0] + r[1]);
        let half = 0.5 * len / scale;
        [c - half, c + half]
    };
    (grow(x, w), grow(y, h))
}

/// Width of the widest tick label of an axis.
fn label_width(a: &AxisLayout) -> f64 {
    a.labels()
        .iter()
        .map(|l| text_width(l, font_size::TICK))
        .fold(0.0, f64::max)
}

/// Lays out figures that share one structure (same panels, legend, colour bar),
/// fitting the ranges to the data of all of them.
///
/// # Panics
/// If `figures` is empty.
#[must_use]
pub fn fit(figures: &[&Figure]) -> Layout {
    let fig = figures[0];
    let n = fig.panels.len().max(1) as f64;
    let cbar = if fig.colorbar.is_some() {
        COLORBAR_SPACE
    } else {
        0.0
    };
    let width = match fig.panels.len() {
        0 | 1 => 640.0,
        2 => 1000.0,
        _ => 1240.0,
    } + cbar;
    let title_baseline = PAD + cap_height(font_size::TITLE) + 4.0;
    let subtitle_baseline = title_baseline + line_height(font_size::SUBTITLE) + 5.0;
    let has_panel_title = fig.panels.iter().any(|p| p.title.is_some());
    let top = subtitle_baseline
        + 12.0
        + if has_panel_title {
            line_height(font_size::AXIS) + 4.0
        } else {
            0.0
        };
    let cell = (width - cbar - 2.0 * PAD) / n;
    let bottom_margin =
        TICK_LEN + 4.0 + line_height(font_size::TICK) + 6.0 + line_height(font_size::AXIS);
    let ranges = data_ranges(figures);
    let all_equal = fig.panels.iter().all(|p| p.equal_aspect);

    // Tick label widths depend on the ranges, which depend on the plot size under
    // equal aspect: two passes settle it.
    let mut left_margins = vec![50.0; fig.panels.len()];
    let mut panels = Vec::new();
    for _pass in 0..2 {
        let plot_w: Vec<f64> = left_margins.iter().map(|l| cell - l - 14.0).collect();
        let min_w = plot_w.iter().copied().fold(f64::INFINITY, f64::min);
        let plot_h = if all_equal {
            let aspect = ranges
                .iter()
                .map(|(x, y)| (y[1] - y[0]) / (x[1] - x[0]))
                .fold(0.0, f64::max);
            (min_w * aspect).clamp(0.45 * min_w, if n > 1.0 { 1.0 } else { 0.8 } * min_w)
        } else {
            0.6 * min_w
        };
        panels = fig
            .panels
            .iter()
            .zip(&ranges)
            .enumerate()
            .map(|(i, (p, &(xr, yr)))| {
                let (xr, yr) = if p.equal_aspect {
                    equalise(xr, yr, plot_w[i], plot_h)
                } else {
                    (xr, yr)
                };
                PanelLayout {
                    plot: Rect {
                        x: PAD + i as f64 * cell + left_margins[i],
                        y: top,
                        w: plot_w[i],
                        h: plot_h,
                    },
                    x: axis(xr, plot_w[i], 80.0),
                    y: axis(yr, plot_h, 55.0),
                }
            })
            .collect::<Vec<_>>();
        left_margins = panels
            .iter()
            .map(|p| label_width(&p.y) + TICK_LEN + 6.0 + line_height(font_size::AXIS) + 6.0)
            .collect();
    }
    let plot_bottom = panels.iter().map(|p| p.plot.bottom()).fold(top, f64::max);
    let mut height = plot_bottom + bottom_margin + PAD;
    let colorbar = fig.colorbar.as_ref().map(|_| {
        let last = panels.last().map_or(width - cbar, |p| p.plot.right());
        Rect {
            x: last + 26.0,
            y: top + 14.0,
            w: 16.0,
            h: panels.first().map_or(200.0, |p| p.plot.h) - 14.0,
        }
    });
    let legend = if fig.legend.is_empty() {
        None
    } else {
        let obstacles: Vec<Obstacles> = (0..panels.len())
            .map(|i| {
                let mut o = Obstacles::default();
                for f in figures {
                    o.extend(&panel_obstacles(&f.panels[i], &panels[i]));
                    o.rects.extend(label_room(&f.panels[i], &panels[i]));
                }
                o
            })
            .collect();
        let inside = legend_inside(fig, &panels, &obstacles);
        Some(inside.unwrap_or_else(|| {
            let below = legend_below(fig, width, plot_bottom + bottom_margin);
            height = below.rect.bottom() + PAD;
            below
        }))
    };
    Layout {
        width,
        // Whole pixels, so the PNG is exactly `PNG_SCALE` times the SVG.
        height: height.ceil(),
        title_baseline,
        subtitle_baseline,
        panels,
        legend,
        colorbar,
        tolerance: TOLERANCE,
    }
}

/// Width of a legend entry's row.
fn entry_width(label: &str) -> f64 {
    LEGEND_SWATCH + LEGEND_GAP + text_width(label, font_size::LEGEND)
}

/// The legend as one column in a corner or at an edge of a panel, covering
/// nothing; `None` if no such place exists.
fn legend_inside(
    fig: &Figure,
    panels: &[PanelLayout],
    obstacles: &[Obstacles],
) -> Option<LegendLayout> {
    let w = fig
        .legend
        .iter()
        .map(|e| entry_width(&e.label))
        .fold(0.0, f64::max)
        + 2.0 * LEGEND_PAD;
    let h = fig.legend.len() as f64 * LEGEND_ROW + 2.0 * LEGEND_PAD - 2.0;
    const INSET: f64 = 6.0;
    for (i, p) in panels.iter().enumerate() {
        let r = p.plot;
        let (l, c, rt) = (r.x + INSET, r.x + 0.5 * (r.w - w), r.right() - INSET - w);
        let (t, m, b) = (r.y + INSET, r.y + 0.5 * (r.h - h), r.bottom() - INSET - h);
        for (x, y) in [
            (rt, t),
            (l, t),
            (rt, b),
            (l, b),
            (c, t),
            (c, b),
            (rt, m),
            (l, m),
        ] {
            let rect = Rect { x, y, w, h };
            if r.contains_rect(&rect) && obstacles[i].hits(&rect.grow(3.0)) == 0 {
                return Some(legend_rows(fig, rect, 1, Some(i)));
            }
        }
    }
    None
}

/// The legend below the panels, in as many columns as fit.
fn legend_below(fig: &Figure, width: f64, top: f64) -> LegendLayout {
    let col_w = fig
        .legend
        .iter()
        .map(|e| entry_width(&e.label))
        .fold(0.0, f64::max)
        + 18.0;
    let n = fig.legend.len();
    let cols = (((width - 2.0 * PAD - 2.0 * LEGEND_PAD) / col_w).floor() as usize).clamp(1, n);
    let rows = n.div_ceil(cols);
    let w = cols as f64 * col_w - 18.0 + 2.0 * LEGEND_PAD;
    let h = rows as f64 * LEGEND_ROW + 2.0 * LEGEND_PAD - 2.0;
    let rect = Rect {
        x: 0.5 * (width - w),
        y: top,
        w,
        h,
    };
    legend_rows(fig, rect, cols, None)
}

fn legend_rows(fig: &Figure, rect: Rect, cols: usize, panel: Option<usize>) -> LegendLayout {
    let col_w = if cols > 1 {
        (rect.w - 2.0 * LEGEND_PAD + 18.0) / cols as f64
    } else {
        0.0
    };
    let rows = fig.legend.len().div_ceil(cols);
    let entries = (0..fig.legend.len())
        .map(|k| {
            // Column-major, like matplotlib's ncol.
            let (col, row) = (k / rows, k % rows);
            [
                rect.x + LEGEND_PAD + col as f64 * col_w,
                rect.y + LEGEND_PAD + row as f64 * LEGEND_ROW,
            ]
        })
        .collect();
    LegendLayout {
        rect,
        entries,
        panel,
    }
}

/// Half the side of a marker's box, in pixels, with its outline.
pub fn marker_half(size: f64) -> f64 {
    0.5 * size + 1.0
}

/// Everything drawn in `panel` as pixel obstacles (labels excluded: they are
/// placed last, around what is drawn).
#[must_use]
pub fn panel_obstacles(panel: &Panel, pl: &PanelLayout) -> Obstacles {
    let mut o = Obstacles::default();
    for item in &panel.items {
        match &item.mark {
            Mark::Line { points, .. } => {
                let px: Vec<Px> = points.iter().map(|&p| pl.to_px(p)).collect();
                o.add_polyline(&px);
            }
            Mark::Area { points, .. } => {
                o.areas.push(points.iter().map(|&p| pl.to_px(p)).collect())
            }
            Mark::Markers { points, marker } => {
                let r = marker_half(marker.size);
                o.rects
                    .extend(pl.marker_px(points).into_iter().map(|[x, y]| Rect {
                        x: x - r,
                        y: y - r,
                        w: 2.0 * r,
                        h: 2.0 * r,
                    }));
            }
            Mark::Segments { segments, .. } => o
                .segments
                .extend(segments.iter().map(|s| [pl.to_px(s[0]), pl.to_px(s[1])])),
            Mark::HRule { y, .. } => {
                let py = pl.to_px([0.0, *y])[1];
                o.segments.push([[pl.plot.x, py], [pl.plot.right(), py]]);
            }
            Mark::Label { .. } | Mark::Empty => {}
        }
    }
    o
}

/// A box around each label's anchor: the legend keeps off it, so that it does
/// not take the only place a label could go.
#[must_use]
pub fn label_room(panel: &Panel, pl: &PanelLayout) -> Vec<Rect> {
    panel
        .items
        .iter()
        .filter_map(|item| match &item.mark {
            Mark::Label { anchor, .. } => {
                let [x, y] = pl.to_px(*anchor);
                Some(Rect {
                    x: x - 14.0,
                    y: y - 14.0,
                    w: 28.0,
                    h: 28.0,
                })
            }
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::LegendEntry;
    use crate::style::{Stroke, BLACK};

    fn figure(points: Vec<Xy>) -> Figure {
        let mut p = Panel::curves("x", "y");
        p.push(
            "curve",
            Mark::Line {
                points,
                stroke: Stroke::solid(BLACK, 1.0),
            },
        );
        Figure {
            name: "t",
            title: "t".into(),
            subtitle: String::new(),
            panels: vec![p],
            legend: vec![LegendEntry::line("curve", Stroke::solid(BLACK, 1.0))],
            colorbar: None,
        }
    }

    #[test]
    fn equal_aspect_gives_equal_pixels_per_unit() {
        let f = figure(vec![[0.0, 0.0], [6.0, 1.0], [3.0, 4.0]]);
        let l = fit(&[&f]);
        let p = &l.panels[0];
        let sx = p.plot.w / (p.x.range[1] - p.x.range[0]);
        let sy = p.plot.h / (p.y.range[1] - p.y.range[0]);
        assert!((sx - sy).abs() < 1e-9, "{sx} {sy}");
        assert!(p.x.range[0] < 0.0 && p.x.range[1] > 6.0);
        assert!(p.y.range[0] < 0.0 && p.y.range[1] > 4.0);
    }

    #[test]
    fn the_legend_covers_no_curve() {
        // A curve along the diagonal leaves two corners free.
        let pts: Vec<Xy> = (0..=50)
            .map(|i| [f64::from(i) / 10.0, f64::from(i) / 10.0])
            .collect();
        let f = figure(pts);
        let l = fit(&[&f]);
        let legend = l.legend.expect("a legend");
        assert_eq!(legend.panel, Some(0));
        let o = panel_obstacles(&f.panels[0], &l.panels[0]);
        assert_eq!(o.hits(&legend.rect), 0);
    }

    #[test]
    fn a_full_panel_puts_the_legend_below() {
        // A dense zig-zag fills the whole panel.
        let pts: Vec<Xy> = (0..=200)
            .map(|i| [f64::from(i) / 20.0, if i % 2 == 0 { 0.0 } else { 10.0 }])
            .collect();
        let f = figure(pts);
        let l = fit(&[&f]);
        let legend = l.legend.expect("a legend");
        assert_eq!(legend.panel, None);
        assert!(legend.rect.y > l.panels[0].plot.bottom());
        assert!(l.height >= legend.rect.bottom());
    }
}
