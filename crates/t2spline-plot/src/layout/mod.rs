//! Where everything goes on the page: panel boxes (a row, or two rows of two
//! for four panels), data-to-pixel transforms with equal aspect where asked,
//! ticks, the legend (inside a panel where it covers nothing, otherwise below
//! the panels), the colour bar, notes, and the texts that are the same in
//! every figure laid out.
//!
//! A layout can be fitted to several figures of one kind at once (the report's
//! figures at every alpha), so that axes, legend and labels stay put while the
//! data move. Panels with fixed ranges (a zoom) keep their box but take their
//! ranges from each figure ([`Layout::for_figure`]).

mod legend;

pub use legend::{LegendLayout, LEGEND_ROW, LEGEND_SWATCH};

use crate::font::{cap_height, line_height, text_width};
use crate::geometry::{Px, Rect};
use crate::labels::{place, Placed};
use crate::obstacles::{add_panel, Obstacles};
use crate::scene::{Figure, Mark, Panel, Priority, Xy};
use crate::style::font_size;
use crate::ticks::{decimals_for, nice_ticks, tick_label};
use legend::LegendSize;

/// Outer margin of the page.
const PAD: f64 = 10.0;
/// Length of a tick mark.
pub const TICK_LEN: f64 = 5.0;
/// Width reserved right of the panels for a colour bar and its labels.
const COLORBAR_SPACE: f64 = 96.0;
/// Height of a line of notes.
pub const NOTE_ROW: f64 = 14.0;

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

/// The placement of each text item of a panel that is the same in every
/// figure laid out: `Some(placed)` (or `Some(None)`, left out) per such item,
/// `None` for items placed per figure and for other items.
pub type FixedLabels = Vec<Option<Option<Placed>>>;

/// A whole page.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Page width in pixels.
    pub width: f64,
    /// Page height in pixels.
    pub height: f64,
    /// Baseline of the title.
    pub title_baseline: f64,
    /// Baseline of the subtitle's first line.
    pub subtitle_baseline: f64,
    /// The panels.
    pub panels: Vec<PanelLayout>,
    /// The legend, if the figure has entries.
    pub legend: Option<LegendLayout>,
    /// The colour bar's swatch column, if any.
    pub colorbar: Option<Rect>,
    /// Top of the notes' first line.
    pub notes_top: f64,
    /// Texts placed once for every figure laid out, per panel.
    pub labels: Vec<FixedLabels>,
    /// Polylines are simplified to within this many pixels ([`crate::simplify`]).
    pub tolerance: f64,
}

/// The default simplification tolerance: a tenth of a pixel, invisible even in
/// the 3× PNG.
pub const TOLERANCE: f64 = 0.1;

impl Layout {
    /// This layout with the ranges of `fig`'s fixed-range panels (zooms that
    /// differ from figure to figure), each in the same box and with equal
    /// aspect where the panel asks for it.
    #[must_use]
    pub fn for_figure(&self, fig: &Figure) -> Layout {
        let mut out = self.clone();
        for (pl, p) in out.panels.iter_mut().zip(&fig.panels) {
            if let (Some(x), Some(y)) = (p.x_range, p.y_range) {
                let (x, y) = if p.equal_aspect {
                    equalise(x, y, pl.plot.w, pl.plot.h)
                } else {
                    (x, y)
                };
                pl.x = axis(x, pl.plot.w, 80.0);
                pl.y = axis(y, pl.plot.h, 55.0);
            }
        }
        out
    }
}

/// `text` in lines no wider than `width` at font `size`, broken at spaces.
#[must_use]
pub fn wrap(text: &str, width: f64, size: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if text_width(&format!("{line} {word}"), size) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    lines
}

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
            Mark::HRule { .. } | Mark::VRule { .. } | Mark::Empty => {}
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

/// The data ranges of panel `i` of each figure: fixed ranges as given, others
/// fitted to the data of all figures together.
fn data_ranges(figures: &[&Figure], i: usize) -> Vec<([f64; 2], [f64; 2])> {
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
    figures
        .iter()
        .map(|f| {
            let p = &f.panels[i];
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

/// Columns and rows of the panel grid: one row of up to three, two rows of
/// two for four panels.
fn grid(panels: usize) -> (usize, usize) {
    let cols = match panels {
        0 => 1,
        4 => 2,
        n => n.min(3),
    };
    (cols, panels.max(1).div_ceil(cols))
}

/// Lays out figures that share one structure (same panels, items and
/// colour bar), fitting the ranges to the data of all of them and placing the
/// legend and the unchanging texts where they cover nothing in any of them.
///
/// # Panics
/// If `figures` is empty.
#[must_use]
pub fn fit(figures: &[&Figure]) -> Layout {
    let all: Vec<usize> = (0..figures.len()).collect();
    fit_probed(figures, &all)
}

/// [`fit`], with the legend and the unchanging texts placed against the
/// drawings of the figures `probes` (indices into `figures`) only: a handful
/// of representative figures instead of every one.
///
/// # Panics
/// If `figures` or `probes` is empty, or a probe is out of range.
#[must_use]
pub fn fit_probed(figures: &[&Figure], probes: &[usize]) -> Layout {
    let fig = figures[0];
    let (cols, _rows) = grid(fig.panels.len());
    let cbar = if fig.colorbar.is_some() {
        COLORBAR_SPACE
    } else {
        0.0
    };
    let width = match cols {
        1 => 640.0,
        2 => 1000.0,
        _ => 1240.0,
    } + cbar;
    let title_baseline = PAD + cap_height(font_size::TITLE) + 4.0;
    let subtitle_baseline = title_baseline + line_height(font_size::SUBTITLE) + 5.0;
    let subtitle_lines = figures
        .iter()
        .map(|f| wrap(&f.subtitle, width - 2.0 * PAD, font_size::SUBTITLE).len())
        .max()
        .unwrap_or(1)
        .max(1);
    let title_h = if fig.panels.iter().any(|p| p.title.is_some()) {
        line_height(font_size::AXIS) + 4.0
    } else {
        0.0
    };
    let top = subtitle_baseline
        + (subtitle_lines - 1) as f64 * line_height(font_size::SUBTITLE)
        + 12.0
        + title_h;
    let cell = (width - cbar - 2.0 * PAD) / cols as f64;
    let bottom_margin =
        TICK_LEN + 4.0 + line_height(font_size::TICK) + 6.0 + line_height(font_size::AXIS);
    let ranges: Vec<Vec<([f64; 2], [f64; 2])>> = (0..fig.panels.len())
        .map(|i| data_ranges(figures, i))
        .collect();
    let all_equal = fig.panels.iter().all(|p| p.equal_aspect);

    // Tick label widths depend on the ranges, which depend on the plot size under
    // equal aspect: two passes settle it. A zoom's ticks change from figure to
    // figure, so its margin fits the widest of them.
    let mut left_margins = vec![50.0; fig.panels.len()];
    let mut panels = Vec::new();
    let mut plot_h = 0.0;
    for _pass in 0..2 {
        let plot_w: Vec<f64> = left_margins.iter().map(|l| cell - l - 14.0).collect();
        let min_w = plot_w.iter().copied().fold(f64::INFINITY, f64::min);
        plot_h = if all_equal {
            let aspect = ranges
                .iter()
                .map(|r| (r[0].1[1] - r[0].1[0]) / (r[0].0[1] - r[0].0[0]))
                .fold(0.0, f64::max);
            let tallest = if cols > 1 { 1.0 } else { 0.8 };
            (min_w * aspect).clamp(0.3 * min_w, tallest * min_w)
        } else {
            0.6 * min_w
        };
        let row_step = plot_h + bottom_margin + 10.0 + title_h;
        let mut margins = Vec::with_capacity(fig.panels.len());
        panels = fig
            .panels
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let (col, row) = (i % cols, i / cols);
                let plot = Rect {
                    x: PAD + col as f64 * cell + left_margins[i],
                    y: top + row as f64 * row_step,
                    w: plot_w[i],
                    h: plot_h,
                };
                let fixed = p.x_range.is_some() && p.y_range.is_some();
                let axes: Vec<PanelLayout> = ranges[i]
                    .iter()
                    .take(if fixed { ranges[i].len() } else { 1 })
                    .map(|&(xr, yr)| {
                        let (xr, yr) = if p.equal_aspect {
                            equalise(xr, yr, plot.w, plot.h)
                        } else {
                            (xr, yr)
                        };
                        PanelLayout {
                            plot,
                            x: axis(xr, plot.w, 80.0),
                            y: axis(yr, plot.h, 55.0),
                        }
                    })
                    .collect();
                margins.push(
                    axes.iter().map(|a| label_width(&a.y)).fold(0.0, f64::max)
                        + TICK_LEN
                        + 6.0
                        + line_height(font_size::AXIS)
                        + 6.0,
                );
                axes.into_iter().next().unwrap_or(PanelLayout {
                    plot,
                    x: axis([0.0, 1.0], plot.w, 80.0),
                    y: axis([0.0, 1.0], plot.h, 55.0),
                })
            })
            .collect::<Vec<_>>();
        left_margins = margins;
    }
    let plot_bottom = panels.iter().map(|p| p.plot.bottom()).fold(top, f64::max);
    let mut height = plot_bottom + bottom_margin + PAD;
    let colorbar = fig.colorbar.as_ref().map(|_| {
        let last = panels.last().map_or(width - cbar, |p| p.plot.right());
        Rect {
            x: last + 26.0,
            y: top + 14.0,
            w: 16.0,
            h: plot_h - 14.0,
        }
    });
    let probe_figs: Vec<&Figure> = probes.iter().map(|&k| figures[k]).collect();
    let obstacles: Vec<Obstacles> = panels
        .iter()
        .enumerate()
        .map(|(i, pl)| {
            let mut o = Obstacles::new(pl.plot);
            for f in &probe_figs {
                let pl = &pl_for(pl, &f.panels[i]);
                add_panel(&mut o, &f.panels[i], pl);
            }
            o
        })
        .collect();
    let size = LegendSize::of(figures.iter().map(|f| f.legend.as_slice()));
    let legend = (size.count > 0).then(|| {
        let mut room: Vec<Obstacles> = Vec::with_capacity(panels.len());
        for (i, pl) in panels.iter().enumerate() {
            let mut o = Obstacles::new(pl.plot);
            o.extend(&obstacles[i]);
            for f in &probe_figs {
                for r in label_room(&f.panels[i], &pl_for(pl, &f.panels[i])) {
                    o.add_rect(r);
                }
            }
            room.push(o);
        }
        legend::inside(size, &panels, &room).unwrap_or_else(|| {
            let below = legend::below(size, width, plot_bottom + bottom_margin);
            height = below.rect.bottom() + PAD;
            below
        })
    });
    let notes = figures.iter().map(|f| f.notes.len()).max().unwrap_or(0);
    let notes_top = height - PAD + 4.0;
    if notes > 0 {
        height = notes_top + notes as f64 * NOTE_ROW + PAD;
    }
    let labels = panels
        .iter()
        .enumerate()
        .map(|(i, pl)| fixed_labels(figures, &probe_figs, i, pl, &obstacles[i], legend.as_ref()))
        .collect();
    Layout {
        width,
        // Whole pixels, so the PNG is exactly `PNG_SCALE` times the SVG.
        height: height.ceil(),
        title_baseline,
        subtitle_baseline,
        panels,
        legend,
        colorbar,
        notes_top,
        labels,
        tolerance: TOLERANCE,
    }
}

/// The panel layout with a fixed-range panel's own ranges.
fn pl_for(pl: &PanelLayout, p: &Panel) -> PanelLayout {
    match (p.x_range, p.y_range) {
        (Some(x), Some(y)) => {
            let (x, y) = if p.equal_aspect {
                equalise(x, y, pl.plot.w, pl.plot.h)
            } else {
                (x, y)
            };
            PanelLayout {
                plot: pl.plot,
                x: axis(x, pl.plot.w, 80.0),
                y: axis(y, pl.plot.h, 55.0),
            }
        }
        _ => pl.clone(),
    }
}

fn is_text(m: &Mark) -> bool {
    matches!(
        m,
        Mark::Label { .. } | Mark::HRule { .. } | Mark::VRule { .. }
    )
}

/// Places, once, the texts of panel `i` that are the same in every figure
/// (in a panel whose ranges are too), against the drawings of the probes,
/// keeping off the places the changing annotations need.
fn fixed_labels(
    figures: &[&Figure],
    probes: &[&Figure],
    i: usize,
    pl: &PanelLayout,
    obstacles: &Obstacles,
    legend: Option<&LegendLayout>,
) -> FixedLabels {
    let first = &figures[0].panels[i];
    let zoom = first.x_range.is_some() || first.y_range.is_some();
    let same = |k: usize| {
        figures
            .iter()
            .all(|f| f.panels[i].items.get(k).map(|it| &it.mark) == Some(&first.items[k].mark))
    };
    let fixed: Vec<bool> = first
        .items
        .iter()
        .enumerate()
        .map(|(k, it)| is_text(&it.mark) && (figures.len() == 1 || (!zoom && same(k))))
        .collect();
    if !fixed.contains(&true) {
        return vec![None; first.items.len()];
    }
    let mut o = Obstacles::new(pl.plot);
    o.extend(obstacles);
    // The changing annotations need their anchors' surroundings.
    for f in probes {
        let p = &f.panels[i];
        let changing = Panel {
            items: p
                .items
                .iter()
                .zip(&fixed)
                .filter(|(_, &fx)| !fx)
                .map(|(it, _)| it.clone())
                .collect(),
            ..p.clone()
        };
        for r in label_room(&changing, pl) {
            o.add_rect(r);
        }
    }
    let only = Panel {
        items: first
            .items
            .iter()
            .zip(&fixed)
            .map(|(it, &fx)| {
                let mut it = it.clone();
                if !fx {
                    it.mark = Mark::Empty;
                }
                it
            })
            .collect(),
        ..first.clone()
    };
    let forbidden: Vec<Rect> = legend
        .filter(|l| l.panel == Some(i))
        .map(|l| l.rect.grow(2.0))
        .into_iter()
        .collect();
    place(&only, pl, &o, &forbidden)
        .into_iter()
        .zip(&fixed)
        .map(|(p, &fx)| fx.then_some(p))
        .collect()
}

/// A box around each annotation's anchor: the legend and point names keep
/// off it, so that they do not take the only place an annotation could go.
#[must_use]
pub fn label_room(panel: &Panel, pl: &PanelLayout) -> Vec<Rect> {
    panel
        .items
        .iter()
        .filter_map(|item| match &item.mark {
            Mark::Label {
                anchor,
                priority: Priority::Always,
                ..
            } => {
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
        Figure::new(
            "t",
            "t",
            "",
            vec![p],
            vec![LegendEntry::line("curve", Stroke::solid(BLACK, 1.0))],
        )
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
        let o = crate::obstacles::panel_obstacles(&f.panels[0], &l.panels[0]);
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
