//! Writing a laid-out figure as SVG text: fixed decimals and a stable element
//! order, so files diff well and golden tests compare them as text.
//!
//! A figure is written as a list of keyed [`Part`]s (background, titles, each
//! panel's frame, each item, labels, legend, colour bar). A plain SVG file is
//! their concatenation; the HTML report wraps each in an element with an id and
//! swaps the parts that change with alpha.

use std::fmt::Write as _;

mod element;
mod legend;
mod marks;
pub(crate) mod number;

use crate::chart::font::{cap_height, line_height, SVG_FONT_STACK};
use crate::chart::geometry::Rect;
use crate::chart::labels::{place, Placed};
use crate::chart::layout::{self, Layout, TICK_LEN};
use crate::chart::obstacles::panel_obstacles;
use crate::chart::paint::{font_size, GRID, INK, WHITE};
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Figure, Item, Mark, Panel};
pub use element::escape;
use element::{rect_attrs, text_el};
use number::coord;

/// One piece of a figure's SVG, with a key stable across figures of one kind.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// Unique within the figure.
    pub key: String,
    /// SVG elements.
    pub svg: String,
}

/// Renders a figure as a complete SVG document.
///
/// # Examples
/// ```
/// use t2spline_plot::{Figure, Mark, Panel, Stroke, palette::BLACK};
/// let mut panel = Panel::curves("x", "y");
/// panel.push("c", Mark::Line { points: vec![[0.0, 0.0], [1.0, 1.0]], stroke: Stroke::solid(BLACK, 1.0) });
/// let fig = Figure::new("demo", "Demo", "", vec![panel], vec![]);
/// let svg = t2spline_plot::render_svg(&fig);
/// assert!(svg.starts_with("<svg") && svg.contains("<polyline"));
/// ```
#[must_use]
pub fn render(fig: &Figure) -> String {
    let layout = layout::fit(&[fig]);
    document(&layout, &fig.title, &parts(fig, &layout, ""), None)
}

/// Renders a figure as a complete SVG document whose element ids begin
/// with `prefix`, so that several figures can share one HTML page (a
/// notebook) without their clip paths mixing; `render(fig)` is
/// `render_prefixed(fig, "")`.
#[must_use]
pub fn render_prefixed(fig: &Figure, prefix: &str) -> String {
    let layout = layout::fit(&[fig]);
    document(&layout, &fig.title, &parts(fig, &layout, prefix), None)
}

/// The SVG document around `parts`; with `wrap = Some(prefix)` each part is
/// wrapped in `<g id="{prefix}{index}">`.
#[must_use]
pub fn document(layout: &Layout, title: &str, parts: &[Part], wrap: Option<&str>) -> String {
    let (w, h) = (coord(layout.width), coord(layout.height));
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{SVG_FONT_STACK}\">\n<title>{}</title>\n",
        escape(title)
    );
    for (i, p) in parts.iter().enumerate() {
        match wrap {
            Some(prefix) => {
                let _ = writeln!(s, "<g id=\"{prefix}{i}\">{}</g>", p.svg);
            }
            None => s.push_str(&p.svg),
        }
    }
    s.push_str("</svg>\n");
    s
}

/// The parts of a figure placed by `layout` (which may have been fitted to
/// several figures). `prefix` makes element ids unique within a page.
#[must_use]
pub fn parts(fig: &Figure, layout: &Layout, prefix: &str) -> Vec<Part> {
    let mut out = Vec::new();
    let mut push = |key: String, svg: String| out.push(Part { key, svg });
    push(
        "background".into(),
        format!(
            "<rect width=\"{}\" height=\"{}\" fill=\"{WHITE}\"/>\n",
            coord(layout.width),
            coord(layout.height)
        ),
    );
    let centre = coord(0.5 * layout.width);
    let lines = layout::wrap(&fig.subtitle, layout.width - 20.0, font_size::SUBTITLE);
    for (key, baseline, size, lines) in [
        (
            "title",
            layout.title_baseline,
            font_size::TITLE,
            vec![fig.title.clone()],
        ),
        (
            "subtitle",
            layout.subtitle_baseline,
            font_size::SUBTITLE,
            lines,
        ),
    ] {
        let mut svg = String::new();
        for (k, line) in lines.iter().enumerate() {
            let _ = writeln!(
                svg,
                "<text x=\"{centre}\" y=\"{}\" font-size=\"{size}\" text-anchor=\"middle\" fill=\"{INK}\">{}</text>",
                coord(baseline + k as f64 * line_height(size)),
                escape(line)
            );
        }
        push(key.into(), svg);
    }
    for (i, (panel, pl)) in fig.panels.iter().zip(&layout.panels).enumerate() {
        let clip = format!("{prefix}clip{i}");
        push(format!("p{i}-frame"), frame(panel, pl, &clip));
        for item in &panel.items {
            push(
                format!("p{i}-{}", item.key),
                marks::mark(&item.mark, pl, &clip, layout.tolerance),
            );
        }
        let fixed = layout.labels.get(i).map_or(&[][..], Vec::as_slice);
        for (item, placed) in panel.items.iter().zip(texts(panel, pl, layout, i, fixed)) {
            // Every text item gets a part, empty when it found no place, so that
            // figures of one kind keep the same parts.
            let text = match &item.mark {
                Mark::Label { text, .. }
                | Mark::HRule { label: text, .. }
                | Mark::VRule { label: text, .. } => text.as_str(),
                _ => continue,
            };
            let svg = placed.map_or_else(String::new, |p| marks::label(&p, text));
            push(format!("p{i}-{}-text", item.key), svg);
        }
    }
    if let Some(l) = &layout.legend {
        push("legend".into(), legend::legend(&fig.legend, l));
    }
    if let (Some(cb), Some(rect)) = (&fig.colorbar, &layout.colorbar) {
        push("colorbar".into(), legend::colorbar(cb, *rect));
    }
    if !fig.notes.is_empty() {
        push("notes".into(), legend::notes(&fig.notes, layout.notes_top));
    }
    out
}

/// The placement of every item of panel `i` (`None` for items that are not
/// texts or found no place): the layout's where it placed the text for every
/// figure, otherwise placed here around this figure's drawing.
fn texts(
    panel: &Panel,
    pl: &PanelLayout,
    layout: &Layout,
    i: usize,
    fixed: &[Option<Option<Placed>>],
) -> Vec<Option<Placed>> {
    let is_fixed = |k: usize| matches!(fixed.get(k), Some(Some(_)));
    let pending = panel.items.iter().enumerate().any(|(k, it)| {
        !is_fixed(k)
            && matches!(
                it.mark,
                Mark::Label { .. } | Mark::HRule { .. } | Mark::VRule { .. }
            )
    });
    let mut placed: Vec<Option<Placed>> = (0..panel.items.len())
        .map(|k| fixed.get(k).cloned().flatten().flatten())
        .collect();
    if !pending {
        return placed;
    }
    let obstacles = panel_obstacles(panel, pl);
    let mut forbidden: Vec<Rect> = layout
        .legend
        .iter()
        .filter(|l| l.panel == Some(i))
        .map(|l| l.rect.grow(2.0))
        .collect();
    forbidden.extend(placed.iter().flatten().map(|p| p.rect.grow(1.0)));
    let rest = Panel {
        items: panel
            .items
            .iter()
            .enumerate()
            .map(|(k, it)| Item {
                key: it.key.clone(),
                mark: if is_fixed(k) {
                    Mark::Empty
                } else {
                    it.mark.clone()
                },
            })
            .collect(),
        ..panel.clone()
    };
    for (k, p) in place(&rest, pl, &obstacles, &forbidden)
        .into_iter()
        .enumerate()
    {
        if !is_fixed(k) {
            placed[k] = p;
        }
    }
    placed
}

/// Grid, frame, ticks, tick labels, axis labels and panel title; also the clip
/// path of the plot area.
fn frame(panel: &Panel, pl: &PanelLayout, clip: &str) -> String {
    let r = pl.plot;
    let mut s = format!(
        "<clipPath id=\"{clip}\"><rect{}/></clipPath>\n",
        rect_attrs(&r)
    );
    if !panel.frame {
        if let Some(t) = &panel.title {
            s.push_str(&text_el(
                r.x + 0.5 * r.w,
                r.y - 7.0,
                font_size::AXIS,
                "middle",
                "",
                t,
            ));
        }
        return s;
    }
    let xs: Vec<f64> = pl.x.ticks.iter().map(|&t| pl.to_px([t, 0.0])[0]).collect();
    let ys: Vec<f64> = pl.y.ticks.iter().map(|&t| pl.to_px([0.0, t])[1]).collect();
    let mut grid = String::new();
    let mut ticks = String::new();
    for &x in &xs {
        let _ = write!(grid, "M{} {}V{}", coord(x), coord(r.y), coord(r.bottom()));
        let _ = write!(
            ticks,
            "M{} {}v{}",
            coord(x),
            coord(r.bottom()),
            coord(TICK_LEN)
        );
    }
    for &y in &ys {
        let _ = write!(grid, "M{} {}H{}", coord(r.x), coord(y), coord(r.right()));
        let _ = write!(ticks, "M{} {}h{}", coord(r.x), coord(y), coord(-TICK_LEN));
    }
    let _ = writeln!(
        s,
        "<path d=\"{grid}\" fill=\"none\" stroke=\"{GRID}\" stroke-width=\"0.8\"/>\n<path d=\"{ticks}\" fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\"/>"
    );
    let _ = writeln!(
        s,
        "<rect{} fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\"/>",
        rect_attrs(&r)
    );
    let tick_base = r.bottom() + TICK_LEN + 3.0 + cap_height(font_size::TICK);
    for (x, l) in xs.iter().zip(pl.x.labels()) {
        s.push_str(&text_el(*x, tick_base, font_size::TICK, "middle", "", &l));
    }
    for (y, l) in ys.iter().zip(pl.y.labels()) {
        let base = y + 0.5 * cap_height(font_size::TICK);
        s.push_str(&text_el(
            r.x - TICK_LEN - 3.0,
            base,
            font_size::TICK,
            "end",
            "",
            &l,
        ));
    }
    let xl_base = tick_base + 8.0 + cap_height(font_size::AXIS);
    s.push_str(&text_el(
        r.x + 0.5 * r.w,
        xl_base,
        font_size::AXIS,
        "middle",
        "",
        &panel.x_label,
    ));
    let widest =
        pl.y.labels()
            .iter()
            .map(|l| crate::chart::font::text_width(l, font_size::TICK))
            .fold(0.0, f64::max);
    let yl_x = r.x - TICK_LEN - 3.0 - widest - 6.0;
    let yc = r.y + 0.5 * r.h;
    s.push_str(&text_el(
        yl_x,
        yc,
        font_size::AXIS,
        "middle",
        &format!(" transform=\"rotate(-90 {} {})\"", coord(yl_x), coord(yc)),
        &panel.y_label,
    ));
    if let Some(t) = &panel.title {
        s.push_str(&text_el(
            r.x + 0.5 * r.w,
            r.y - 7.0,
            font_size::AXIS,
            "middle",
            "",
            t,
        ));
    }
    s
}
