//! Texts of a layout: subtitles wrapped to the page, and the labels that are
//! the same in every figure laid out, placed once.

use crate::font::text_width;
use crate::geometry::Rect;
use crate::labels::{place, Placed};
use crate::obstacles::Obstacles;
use crate::scene::{Figure, Mark, Panel, Priority};

use super::{LegendLayout, PanelLayout};

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

/// Places, once, the texts of panel `i` that are the same in every figure
/// (in a panel whose ranges are too), against the drawings of the probes,
/// keeping off the places the changing annotations need.
pub(super) fn fixed_labels(
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
