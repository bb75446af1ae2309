//! Texts of a layout: subtitles wrapped to the page, and the labels that are
//! the same in every figure laid out, placed once.

use crate::chart::font::{line_height, text_width};
use crate::chart::geometry::Rect;
use crate::chart::labels::{place, Placed};
use crate::chart::obstacles::Obstacles;
use crate::chart::paint::font_size;
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Figure, Mark, Panel, Priority};

use super::axes::with_ranges;

/// The placement of each text item of a panel that is the same in every
/// figure laid out: `Some(placed)` (or `Some(None)`, left out) per such item,
/// `None` for items placed per figure and for other items.
pub type FixedLabels = Vec<Option<Option<Placed>>>;

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

fn is_text(m: &Mark) -> bool {
    matches!(
        m,
        Mark::Label { .. } | Mark::HRule { .. } | Mark::VRule { .. }
    )
}

/// The priority of a text item: rules' texts are annotations.
fn priority(m: &Mark) -> Priority {
    match m {
        Mark::Label { priority, .. } => *priority,
        _ => Priority::Always,
    }
}

/// Which items of panel `i` are texts that are the same in every figure (in
/// a panel whose ranges are too), and so are placed once.
pub(super) fn fixed_items(figures: &[&Figure], i: usize) -> Vec<bool> {
    let first = &figures[0].panels[i];
    let zoom = first.x_range.is_some() || first.y_range.is_some();
    let same = |k: usize| {
        figures
            .iter()
            .all(|f| f.panels[i].items.get(k).map(|it| &it.mark) == Some(&first.items[k].mark))
    };
    first
        .items
        .iter()
        .enumerate()
        .map(|(k, it)| is_text(&it.mark) && (figures.len() == 1 || (!zoom && same(k))))
        .collect()
}

/// The boxes the changing annotations of the probes need around their
/// anchors.
pub(super) fn changing_rooms(
    probes: &[&Figure],
    i: usize,
    pl: &PanelLayout,
    fixed: &[bool],
) -> Vec<Rect> {
    let mut rooms = Vec::new();
    for f in probes {
        let p = &f.panels[i];
        let changing = Panel {
            items: p
                .items
                .iter()
                .zip(fixed)
                .filter(|(_, &fx)| !fx)
                .map(|(it, _)| it.clone())
                .collect(),
            ..p.clone()
        };
        rooms.extend(label_room(&changing, &with_ranges(pl, p)));
    }
    rooms
}

/// Places, once, the fixed texts (`fixed`) of panel `i` of one `priority`
/// against `taken` (what is drawn, the texts placed before and the rooms of
/// changing annotations), never on `forbidden` boxes; `None` for the other
/// items.
pub(super) fn place_fixed(
    first: &Panel,
    pl: &PanelLayout,
    fixed: &[bool],
    only: Priority,
    taken: &Obstacles,
    forbidden: &[Rect],
) -> FixedLabels {
    let chosen: Vec<bool> = first
        .items
        .iter()
        .zip(fixed)
        .map(|(it, &fx)| fx && priority(&it.mark) == only)
        .collect();
    if !chosen.contains(&true) {
        return vec![None; first.items.len()];
    }
    let panel = Panel {
        items: first
            .items
            .iter()
            .zip(&chosen)
            .map(|(it, &c)| {
                let mut it = it.clone();
                // Fixed texts stay: labels keep off them.
                if !c && !matches!(it.mark, Mark::Text { .. }) {
                    it.mark = Mark::Empty;
                }
                it
            })
            .collect(),
        ..first.clone()
    };
    place(&panel, pl, taken, forbidden)
        .into_iter()
        .zip(&chosen)
        .map(|(p, &c)| c.then_some(p))
        .collect()
}

/// Around each annotation's anchor, the boxes its text would take up and
/// right or down and left of it: the legend and point names keep off them,
/// so that they do not take the only places an annotation could go.
#[must_use]
fn label_room(panel: &Panel, pl: &PanelLayout) -> Vec<Rect> {
    let (h, gap) = (
        line_height(font_size::LABEL),
        12.0 * std::f64::consts::FRAC_1_SQRT_2,
    );
    panel
        .items
        .iter()
        .filter_map(|item| match &item.mark {
            Mark::Label {
                anchor,
                text,
                priority: Priority::Always,
            } => Some((pl.to_px(*anchor), text_width(text, font_size::LABEL) + 2.0)),
            _ => None,
        })
        .flat_map(|([x, y], w)| {
            [
                Rect {
                    x: x + gap,
                    y: y - gap - h,
                    w,
                    h,
                },
                Rect {
                    x: x - gap - w,
                    y: y + gap,
                    w,
                    h,
                },
            ]
        })
        .collect()
}
