//! Where the legend goes: one column inside a panel where it covers nothing
//! drawn (a corner first, then the middle of an edge), otherwise in as many
//! columns as fit below the panels.

use crate::chart::font::text_width;
use crate::chart::geometry::{Px, Rect};
use crate::chart::obstacles::Obstacles;
use crate::chart::paint::font_size;
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::LegendEntry;

use super::spacing::PAD;

/// Legend: sample width, gap, row height, padding.
pub const LEGEND_SWATCH: f64 = 30.0;
const LEGEND_GAP: f64 = 6.0;
/// Height of one legend row.
pub const LEGEND_ROW: f64 = 16.0;
const LEGEND_PAD: f64 = 7.0;
/// Space between columns of a legend below the panels.
const COLUMN_GAP: f64 = 18.0;

/// The placed legend: its box and its grid of entries.
#[derive(Clone, Debug, PartialEq)]
pub struct LegendLayout {
    /// The frame.
    pub rect: Rect,
    /// Columns of entries.
    pub cols: usize,
    /// Rows of entries.
    pub rows: usize,
    /// Index of the panel it sits in; `None` when below the panels.
    pub panel: Option<usize>,
}

impl LegendLayout {
    /// The top-left corner of each of `count` entries, column by column (as
    /// matplotlib's `ncol`).
    #[must_use]
    pub fn entries(&self, count: usize) -> Vec<Px> {
        let col_w = if self.cols > 1 {
            (self.rect.w - 2.0 * LEGEND_PAD + COLUMN_GAP) / self.cols as f64
        } else {
            0.0
        };
        (0..count)
            .map(|k| {
                let (col, row) = (k / self.rows.max(1), k % self.rows.max(1));
                [
                    self.rect.x + LEGEND_PAD + col as f64 * col_w,
                    self.rect.y + LEGEND_PAD + row as f64 * LEGEND_ROW,
                ]
            })
            .collect()
    }
}

/// The size a legend must have to hold each of several legends: the widest
/// entry and the most entries.
#[derive(Clone, Copy, Debug)]
pub struct LegendSize {
    /// Width of the widest entry's row.
    pub entry_w: f64,
    /// The most entries.
    pub count: usize,
}

impl LegendSize {
    /// The size fitting every legend of `legends`.
    pub fn of<'a>(legends: impl IntoIterator<Item = &'a [LegendEntry]>) -> LegendSize {
        let mut size = LegendSize {
            entry_w: 0.0,
            count: 0,
        };
        for l in legends {
            size.count = size.count.max(l.len());
            for e in l {
                let w = LEGEND_SWATCH + LEGEND_GAP + text_width(&e.label, font_size::LEGEND);
                size.entry_w = size.entry_w.max(w);
            }
        }
        size
    }
}

/// The legend as one column in a corner or at an edge of a panel, covering
/// nothing; `None` if no such place exists.
pub fn inside(
    size: LegendSize,
    panels: &[PanelLayout],
    obstacles: &[Obstacles],
) -> Option<LegendLayout> {
    let w = size.entry_w + 2.0 * LEGEND_PAD;
    let h = size.count as f64 * LEGEND_ROW + 2.0 * LEGEND_PAD - 2.0;
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
            if r.contains_rect(&rect) && obstacles[i].is_free(&rect.grow(3.0)) {
                return Some(LegendLayout {
                    rect,
                    cols: 1,
                    rows: size.count,
                    panel: Some(i),
                });
            }
        }
    }
    None
}

/// The legend below the panels, in as many columns as fit `width`.
pub fn below(size: LegendSize, width: f64, top: f64) -> LegendLayout {
    let col_w = size.entry_w + COLUMN_GAP;
    let n = size.count.max(1);
    let cols = (((width - 2.0 * PAD - 2.0 * LEGEND_PAD) / col_w).floor() as usize).clamp(1, n);
    let rows = n.div_ceil(cols);
    let w = cols as f64 * col_w - COLUMN_GAP + 2.0 * LEGEND_PAD;
    let h = rows as f64 * LEGEND_ROW + 2.0 * LEGEND_PAD - 2.0;
    LegendLayout {
        rect: Rect {
            x: 0.5 * (width - w),
            y: top,
            w,
            h,
        },
        cols,
        rows,
        panel: None,
    }
}
