//! A figure at every stop of the slider as one SVG plus the parts that change:
//! one layout is fitted to all of them (axes, legend and unchanging labels
//! stay put; a magnified panel takes each figure's own ranges), each part
//! that differs between stops is stored once in a string table, and every
//! stop lists which string each changing part shows.

use serde_json::{json, Value};

use crate::chart::layout::{self, Layout};
use crate::chart::scene::Figure;
use crate::chart::svg::{self, Part};

/// Pixel tolerance of polylines in the report: half a screen pixel.
pub const REPORT_TOLERANCE: f64 = 0.5;

/// Strings shared by every figure of a report, each stored once.
#[derive(Debug, Default)]
pub struct Strings {
    list: Vec<String>,
    index: std::collections::HashMap<String, usize>,
}

impl Strings {
    /// The index of `s`, adding it if new.
    pub fn intern(&mut self, s: &str) -> usize {
        if let Some(&i) = self.index.get(s) {
            return i;
        }
        self.list.push(s.to_owned());
        self.index.insert(s.to_owned(), self.list.len() - 1);
        self.list.len() - 1
    }

    /// All strings, in index order.
    #[must_use]
    pub fn into_json(self) -> Value {
        json!(self.list)
    }
}

/// A figure kind across the slider: the SVG shown first, and for the data
/// block the changing parts and their strings per alpha.
#[derive(Debug)]
pub struct Frames {
    /// The SVG at the initial alpha, each part wrapped in `<g id="{prefix}{i}">`.
    pub svg: String,
    /// `{"prefix": …, "parts": [i, …], "frames": [[string, …] per alpha]}`.
    pub data: Value,
}

/// Lays out `figures` (one per stop, same structure) together, with the
/// legend and the unchanging labels placed around the figures `probes`, and
/// collects what changes. `initial` indexes the figure shown first.
///
/// # Panics
/// If `figures` is empty, or if two figures do not have the same parts (the
/// builders guarantee they do).
#[must_use]
pub fn frames(
    figures: &[Figure],
    initial: usize,
    probes: &[usize],
    prefix: &str,
    strings: &mut Strings,
) -> Frames {
    let refs: Vec<&Figure> = figures.iter().collect();
    let mut layout = layout::fit_probed(&refs, probes);
    layout.tolerance = REPORT_TOLERANCE;
    let zoom = figures[0]
        .panels
        .iter()
        .any(|p| p.x_range.is_some() && p.y_range.is_some());
    let layouts: Vec<Layout> = if zoom {
        figures.iter().map(|f| layout.for_figure(f)).collect()
    } else {
        Vec::new()
    };
    let all: Vec<Vec<Part>> = figures
        .iter()
        .enumerate()
        .map(|(k, f)| svg::parts(f, layouts.get(k).unwrap_or(&layout), prefix))
        .collect();
    let first = &all[0];
    for parts in &all {
        let keys = |p: &[Part]| p.iter().map(|x| x.key.clone()).collect::<Vec<_>>();
        assert_eq!(
            keys(parts),
            keys(first),
            "figures of one kind have the same parts"
        );
    }
    let changing: Vec<usize> = (0..first.len())
        .filter(|&i| all.iter().any(|parts| parts[i].svg != first[i].svg))
        .collect();
    let per_alpha: Vec<Vec<usize>> = all
        .iter()
        .map(|parts| {
            changing
                .iter()
                .map(|&i| strings.intern(&parts[i].svg))
                .collect()
        })
        .collect();
    let svg = svg::document(
        layouts.get(initial).unwrap_or(&layout),
        &figures[initial].title,
        &all[initial],
        Some(prefix),
    );
    Frames {
        svg,
        data: json!({ "prefix": prefix, "parts": changing, "frames": per_alpha }),
    }
}

/// A figure that does not change with alpha, as one SVG.
pub(super) fn static_svg(fig: &Figure) -> String {
    let mut l = layout::fit(&[fig]);
    l.tolerance = REPORT_TOLERANCE;
    svg::document(&l, &fig.title, &svg::parts(fig, &l, ""), None)
}
