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

mod axes;
mod legend;
mod spacing;
mod texts;

pub use legend::{LegendLayout, LEGEND_ROW, LEGEND_SWATCH};
pub use spacing::{NOTE_ROW, TICK_LEN};
pub use texts::{wrap, FixedLabels};

use crate::chart::font::{cap_height, line_height};
use crate::chart::geometry::Rect;
use crate::chart::obstacles::{add_panel, Obstacles};
use crate::chart::paint::font_size;
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Figure, Priority};
use axes::{data_ranges, label_width, placed, with_ranges};
use legend::LegendSize;
use spacing::{COLORBAR_SPACE, PAD};

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
            *pl = with_ranges(pl, p);
        }
        out
    }
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

/// The page around the panels: its width, the title's and subtitle's
/// baselines, where the panels start and how wide each column is.
struct Page {
    width: f64,
    cols: usize,
    title_baseline: f64,
    subtitle_baseline: f64,
    /// Top of the first row's plot areas.
    top: f64,
    /// Height of a panel title, when panels have titles.
    title_h: f64,
    cell: f64,
    bottom_margin: f64,
}

impl Page {
    fn of(figures: &[&Figure]) -> Page {
        let fig = figures[0];
        let (cols, _) = grid(fig.panels.len());
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
        Page {
            width,
            cols,
            title_baseline,
            subtitle_baseline,
            top: subtitle_baseline
                + (subtitle_lines - 1) as f64 * line_height(font_size::SUBTITLE)
                + 12.0
                + title_h,
            title_h,
            cell: (width - cbar - 2.0 * PAD) / cols as f64,
            bottom_margin: TICK_LEN
                + 4.0
                + line_height(font_size::TICK)
                + 6.0
                + line_height(font_size::AXIS),
        }
    }
}

/// The panels' boxes and axes. Tick label widths depend on the ranges, which
/// depend on the plot size under equal aspect: two passes settle it. A zoom's
/// ticks change from figure to figure, so its margin fits the widest of them.
fn panel_boxes(figures: &[&Figure], page: &Page) -> Vec<PanelLayout> {
    let fig = figures[0];
    let ranges: Vec<Vec<([f64; 2], [f64; 2])>> = (0..fig.panels.len())
        .map(|i| data_ranges(figures, i))
        .collect();
    let mut left_margins = vec![50.0; fig.panels.len()];
    let mut panels = Vec::new();
    for _pass in 0..2 {
        let plot_w: Vec<f64> = left_margins.iter().map(|l| page.cell - l - 14.0).collect();
        let min_w = plot_w.iter().copied().fold(f64::INFINITY, f64::min);
        let plot_h = if fig.panels.iter().all(|p| p.equal_aspect) {
            let aspect = ranges
                .iter()
                .map(|r| (r[0].1[1] - r[0].1[0]) / (r[0].0[1] - r[0].0[0]))
                .fold(0.0, f64::max);
            let tallest = if page.cols > 1 { 1.0 } else { 0.8 };
            // Not `clamp`: with labels wider than a cell (numbers of 1e130)
            // `min_w` is negative and the bounds cross.
            (min_w * aspect).max(0.3 * min_w).min(tallest * min_w)
        } else {
            0.6 * min_w
        };
        let row_step = plot_h + page.bottom_margin + 10.0 + page.title_h;
        let mut margins = Vec::with_capacity(fig.panels.len());
        panels = fig
            .panels
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let plot = Rect {
                    x: PAD + (i % page.cols) as f64 * page.cell + left_margins[i],
                    y: page.top + (i / page.cols) as f64 * row_step,
                    w: plot_w[i],
                    h: plot_h,
                };
                let fixed = p.x_range.is_some() && p.y_range.is_some();
                let shown = if fixed { ranges[i].len() } else { 1 };
                let axes: Vec<PanelLayout> = ranges[i][..shown]
                    .iter()
                    .map(|&(x, y)| placed(p, plot, x, y))
                    .collect();
                margins.push(
                    axes.iter().map(|a| label_width(&a.y)).fold(0.0, f64::max)
                        + TICK_LEN
                        + 6.0
                        + line_height(font_size::AXIS)
                        + 6.0,
                );
                axes.into_iter()
                    .next()
                    .unwrap_or_else(|| placed(p, plot, [0.0, 1.0], [0.0, 1.0]))
            })
            .collect();
        left_margins = margins;
    }
    panels
}

/// What the probe figures draw in each panel.
fn probe_obstacles(panels: &[PanelLayout], probes: &[&Figure]) -> Vec<Obstacles> {
    panels
        .iter()
        .enumerate()
        .map(|(i, pl)| {
            let mut o = Obstacles::new(pl.plot);
            for f in probes {
                add_panel(&mut o, &f.panels[i], &with_ranges(pl, &f.panels[i]));
            }
            o
        })
        .collect()
}

/// The legend, sized for every figure's, inside a panel where it covers
/// none of `taken` (drawing, annotations and their rooms), else below the
/// panels.
fn place_legend(
    figures: &[&Figure],
    panels: &[PanelLayout],
    taken: &[Obstacles],
    width: f64,
    below_top: f64,
) -> Option<LegendLayout> {
    let size = LegendSize::of(figures.iter().map(|f| f.legend.as_slice()));
    if size.count == 0 {
        return None;
    }
    Some(
        legend::inside(size, panels, taken)
            .unwrap_or_else(|| legend::below(size, width, below_top)),
    )
}

/// The texts that are the same in every figure, placed once: annotations
/// first, then (in `names`, after the legend is placed) names where free.
struct Texts {
    fixed: Vec<Vec<bool>>,
    placed: Vec<FixedLabels>,
    /// What is drawn and the annotations placed, per panel.
    taken: Vec<Obstacles>,
}

impl Texts {
    /// The annotations of every panel, placed against the probes' drawings
    /// and the rooms of the annotations that change from figure to figure.
    fn annotations(
        figures: &[&Figure],
        probes: &[&Figure],
        panels: &[PanelLayout],
        drawn: Vec<Obstacles>,
    ) -> Texts {
        let mut out = Texts {
            fixed: Vec::new(),
            placed: Vec::new(),
            taken: drawn,
        };
        for (i, pl) in panels.iter().enumerate() {
            let fixed = texts::fixed_items(figures, i);
            for r in texts::changing_rooms(probes, i, pl, &fixed) {
                out.taken[i].add_rect(r);
            }
            let placed = texts::place_fixed(
                &figures[0].panels[i],
                pl,
                &fixed,
                Priority::Always,
                &out.taken[i],
                &[],
            );
            for p in placed.iter().flatten().flatten() {
                out.taken[i].add_rect(p.rect.grow(1.0));
            }
            out.fixed.push(fixed);
            out.placed.push(placed);
        }
        out
    }

    /// The names of every panel, where they cover nothing placed so far and
    /// not the legend; then every fixed text's placement.
    fn names(
        mut self,
        figures: &[&Figure],
        panels: &[PanelLayout],
        legend: Option<&LegendLayout>,
    ) -> Vec<FixedLabels> {
        for (i, pl) in panels.iter().enumerate() {
            let mut forbidden: Vec<Rect> = legend
                .filter(|l| l.panel == Some(i))
                .map(|l| l.rect.grow(2.0))
                .into_iter()
                .collect();
            forbidden.extend(
                self.placed[i]
                    .iter()
                    .flatten()
                    .flatten()
                    .map(|p| p.rect.grow(1.0)),
            );
            let names = texts::place_fixed(
                &figures[0].panels[i],
                pl,
                &self.fixed[i],
                Priority::IfRoom,
                &self.taken[i],
                &forbidden,
            );
            for (a, n) in self.placed[i].iter_mut().zip(names) {
                if a.is_none() {
                    *a = n;
                }
            }
        }
        self.placed
    }
}

/// Lays out figures that share one structure (same panels, items and
/// colour bar), fitting the ranges to the data of all of them and placing the
/// legend and the unchanging texts where they cover nothing in any of them.
/// No figure at all is laid out as a figure without panels.
#[must_use]
pub fn fit(figures: &[&Figure]) -> Layout {
    let all: Vec<usize> = (0..figures.len()).collect();
    fit_probed(figures, &all)
}

/// [`fit`], with the legend and the unchanging texts placed against the
/// drawings of the figures `probes` (indices into `figures`) only: a handful
/// of representative figures instead of every one (probes out of range are
/// left out).
#[must_use]
pub fn fit_probed(figures: &[&Figure], probes: &[usize]) -> Layout {
    if figures.is_empty() {
        let empty = Figure::new("", "", "", Vec::new(), Vec::new());
        return fit_probed(&[&empty], &[0]);
    }
    // `Page::of` and `panel_boxes` read the first figure: there is one.
    let page = Page::of(figures);
    let panels = panel_boxes(figures, &page);
    let plot_bottom = panels
        .iter()
        .map(|p| p.plot.bottom())
        .fold(page.top, f64::max);
    let colorbar = figures[0].colorbar.as_ref().and_then(|_| {
        let last = panels.last()?;
        Some(Rect {
            x: last.plot.right() + 26.0,
            y: page.top + 14.0,
            w: 16.0,
            h: last.plot.h - 14.0,
        })
    });
    let probe_figs: Vec<&Figure> = probes
        .iter()
        .filter_map(|&k| figures.get(k).copied())
        .collect();
    let texts = Texts::annotations(
        figures,
        &probe_figs,
        &panels,
        probe_obstacles(&panels, &probe_figs),
    );
    let below_top = plot_bottom + page.bottom_margin;
    let legend = place_legend(figures, &panels, &texts.taken, page.width, below_top);
    let mut height = match &legend {
        Some(l) if l.panel.is_none() => l.rect.bottom() + PAD,
        _ => below_top + PAD,
    };
    let notes = figures.iter().map(|f| f.notes.len()).max().unwrap_or(0);
    let notes_top = height - PAD + 4.0;
    if notes > 0 {
        height = notes_top + notes as f64 * NOTE_ROW + PAD;
    }
    let labels = texts.names(figures, &panels, legend.as_ref());
    Layout {
        width: page.width,
        // Whole pixels, so the PNG is exactly `PNG_SCALE` times the SVG.
        height: height.ceil(),
        title_baseline: page.title_baseline,
        subtitle_baseline: page.subtitle_baseline,
        panels,
        legend,
        colorbar,
        notes_top,
        labels,
        tolerance: TOLERANCE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::paint::{Stroke, BLACK};
    use crate::chart::scene::LegendEntry;
    use crate::chart::scene::{Mark, Panel, Xy};

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
        let o = crate::chart::obstacles::panel_obstacles(&f.panels[0], &l.panels[0]);
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
