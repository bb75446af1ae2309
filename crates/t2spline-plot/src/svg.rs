//! Writing a laid-out figure as SVG text: fixed decimals and a stable element
//! order, so files diff well and golden tests compare them as text.
//!
//! A figure is written as a list of keyed [`Part`]s (background, titles, each
//! panel's frame, each item, labels, legend, colour bar). A plain SVG file is
//! their concatenation; the HTML report wraps each in an element with an id and
//! swaps the parts that change with alpha.

use std::fmt::Write as _;

use crate::font::{cap_height, SVG_FONT_STACK};
use crate::geometry::{Obstacles, Px};
use crate::labels::{place, Placed};
use crate::layout::{self, Layout, PanelLayout, LEGEND_ROW, LEGEND_SWATCH, TICK_LEN};
use crate::scene::{ColorBar, Figure, LegendEntry, Mark};
use crate::style::{font_size, Fill, Marker, Shape, Stroke, GREY, GRID, INK, WHITE};
use crate::ticks::{coord, short};

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
/// use t2spline_plot::scene::{Figure, Mark, Panel};
/// use t2spline_plot::style::{Stroke, BLACK};
/// let mut panel = Panel::curves("x", "y");
/// panel.push("c", Mark::Line { points: vec![[0.0, 0.0], [1.0, 1.0]], stroke: Stroke::solid(BLACK, 1.0) });
/// let fig = Figure { name: "demo", title: "Demo".into(), subtitle: String::new(),
///                    panels: vec![panel], legend: vec![], colorbar: None };
/// let svg = t2spline_plot::svg::render(&fig);
/// assert!(svg.starts_with("<svg") && svg.contains("<polyline"));
/// ```
#[must_use]
pub fn render(fig: &Figure) -> String {
    let layout = layout::fit(&[fig]);
    document(&layout, &fig.title, &parts(fig, &layout, ""), None)
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
    push(
        "title".into(),
        format!(
            "<text x=\"{centre}\" y=\"{}\" font-size=\"{}\" text-anchor=\"middle\" fill=\"{INK}\">{}</text>\n",
            coord(layout.title_baseline),
            font_size::TITLE,
            escape(&fig.title)
        ),
    );
    push(
        "subtitle".into(),
        format!(
            "<text x=\"{centre}\" y=\"{}\" font-size=\"{}\" text-anchor=\"middle\" fill=\"{INK}\">{}</text>\n",
            coord(layout.subtitle_baseline),
            font_size::SUBTITLE,
            escape(&fig.subtitle)
        ),
    );
    for (i, (panel, pl)) in fig.panels.iter().zip(&layout.panels).enumerate() {
        let clip = format!("{prefix}clip{i}");
        push(format!("p{i}-frame"), frame(panel, pl, &clip));
        for item in &panel.items {
            push(
                format!("p{i}-{}", item.key),
                mark(&item.mark, pl, &clip, layout.tolerance),
            );
        }
        let obstacles: Obstacles = layout::panel_obstacles(panel, pl);
        let legend: Vec<_> = layout
            .legend
            .iter()
            .filter(|l| l.panel == Some(i))
            .map(|l| l.rect.grow(2.0))
            .collect();
        for (item, placed) in panel
            .items
            .iter()
            .zip(place(panel, pl, &obstacles, &legend))
        {
            // Every text item gets a part, empty when it found no place, so that
            // figures of one kind keep the same parts.
            let text = match &item.mark {
                Mark::Label { text, .. } | Mark::HRule { label: text, .. } => text.as_str(),
                _ => continue,
            };
            let svg = placed.map_or_else(String::new, |p| label(&p, text));
            push(format!("p{i}-{}-text", item.key), svg);
        }
    }
    if let Some(l) = &layout.legend {
        push("legend".into(), legend(&fig.legend, l));
    }
    if let (Some(cb), Some(rect)) = (&fig.colorbar, &layout.colorbar) {
        push("colorbar".into(), colorbar(cb, *rect));
    }
    out
}

/// Drops polyline vertices that lie within `tolerance` pixels of the line
/// through their neighbours (Douglas–Peucker); the ends are kept.
///
/// # Examples
/// ```
/// let line: Vec<[f64; 2]> = (0..=10).map(|i| [f64::from(i), 0.0]).collect();
/// assert_eq!(t2spline_plot::svg::simplify(&line, 0.1), vec![[0.0, 0.0], [10.0, 0.0]]);
/// ```
#[must_use]
pub fn simplify(points: &[Px], tolerance: f64) -> Vec<Px> {
    if points.len() < 3 || tolerance <= 0.0 {
        return points.to_vec();
    }
    let mut keep = vec![false; points.len()];
    keep[0] = true;
    keep[points.len() - 1] = true;
    let mut stack = vec![(0, points.len() - 1)];
    while let Some((a, b)) = stack.pop() {
        let (p, q) = (points[a], points[b]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let len = (dx * dx + dy * dy).sqrt();
        let dist = |r: Px| {
            if len == 0.0 {
                ((r[0] - p[0]).powi(2) + (r[1] - p[1]).powi(2)).sqrt()
            } else {
                ((r[0] - p[0]) * dy - (r[1] - p[1]) * dx).abs() / len
            }
        };
        let far = (a + 1..b)
            .map(|k| (k, dist(points[k])))
            .fold((a, 0.0), |m, c| if c.1 > m.1 { c } else { m });
        if far.1 > tolerance {
            keep[far.0] = true;
            stack.push((a, far.0));
            stack.push((far.0, b));
        }
    }
    points
        .iter()
        .zip(keep)
        .filter(|(_, k)| *k)
        .map(|(p, _)| *p)
        .collect()
}

/// Escapes text for SVG/XML.
#[must_use]
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn stroke_attrs(s: &Stroke) -> String {
    let mut a = format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
        s.color,
        coord(s.width)
    );
    if let Some(d) = s.dash {
        let _ = write!(a, " stroke-dasharray=\"{d}\"");
    }
    a
}

fn points_attr(pts: &[Px]) -> String {
    let mut s = String::with_capacity(pts.len() * 14);
    for (k, p) in pts.iter().enumerate() {
        if k > 0 {
            s.push(' ');
        }
        let _ = write!(s, "{},{}", coord(p[0]), coord(p[1]));
    }
    s
}

fn text_el(x: f64, y: f64, size: f64, anchor: &str, extra: &str, text: &str) -> String {
    format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"{size}\" text-anchor=\"{anchor}\" fill=\"{INK}\"{extra}>{}</text>\n",
        coord(x),
        coord(y),
        escape(text)
    )
}

/// Grid, frame, ticks, tick labels, axis labels and panel title; also the clip
/// path of the plot area.
fn frame(panel: &crate::scene::Panel, pl: &PanelLayout, clip: &str) -> String {
    let r = pl.plot;
    let mut s = format!(
        "<clipPath id=\"{clip}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
        coord(r.x),
        coord(r.y),
        coord(r.w),
        coord(r.h)
    );
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
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"{INK}\" stroke-width=\"1\"/>",
        coord(r.x),
        coord(r.y),
        coord(r.w),
        coord(r.h)
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
            .map(|l| crate::font::text_width(l, font_size::TICK))
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

fn mark(m: &Mark, pl: &PanelLayout, clip: &str, tolerance: f64) -> String {
    let clip_attr = format!(" clip-path=\"url(#{clip})\"");
    match m {
        Mark::Line { points, stroke } => {
            let px = simplify(
                &points.iter().map(|&p| pl.to_px(p)).collect::<Vec<_>>(),
                tolerance,
            );
            format!(
                "<polyline points=\"{}\" {}{clip_attr}/>\n",
                points_attr(&px),
                stroke_attrs(stroke)
            )
        }
        Mark::Area { points, fill } => {
            let px = simplify(
                &points.iter().map(|&p| pl.to_px(p)).collect::<Vec<_>>(),
                tolerance,
            );
            format!(
                "<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke=\"none\"{clip_attr}/>\n",
                points_attr(&px),
                fill.color,
                coord(fill.opacity)
            )
        }
        Mark::Markers { points, marker } => markers(&pl.marker_px(points), marker),
        Mark::Segments { segments, stroke } => {
            let mut d = String::new();
            for [a, b] in segments {
                let (a, b) = (pl.to_px(*a), pl.to_px(*b));
                let _ = write!(
                    d,
                    "M{} {}L{} {}",
                    coord(a[0]),
                    coord(a[1]),
                    coord(b[0]),
                    coord(b[1])
                );
            }
            format!("<path d=\"{d}\" {}{clip_attr}/>\n", stroke_attrs(stroke))
        }
        Mark::HRule { y, stroke, .. } => {
            let py = pl.to_px([0.0, *y])[1];
            format!(
                "<path d=\"M{} {}H{}\" {}/>\n",
                coord(pl.plot.x),
                coord(py),
                coord(pl.plot.right()),
                stroke_attrs(stroke)
            )
        }
        Mark::Label { .. } | Mark::Empty => String::new(),
    }
}

/// Markers at pixel positions, in one group.
fn markers(px: &[Px], m: &Marker) -> String {
    if px.is_empty() {
        return String::new();
    }
    let fill = m.fill.unwrap_or(WHITE);
    let mut s = format!(
        "<g fill=\"{}\" stroke=\"{}\" stroke-width=\"1.2\">",
        if m.shape == Shape::Cross {
            "none".to_owned()
        } else {
            fill.to_string()
        },
        m.stroke
    );
    for p in px {
        s.push_str(&marker_shape(*p, m.shape, m.size));
    }
    s.push_str("</g>\n");
    s
}

fn marker_shape([x, y]: Px, shape: Shape, size: f64) -> String {
    let r = 0.5 * size;
    let c = coord;
    match shape {
        Shape::Circle => format!("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>", c(x), c(y), c(r)),
        Shape::Square => {
            let a = 0.85 * r;
            format!(
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>",
                c(x - a),
                c(y - a),
                c(2.0 * a),
                c(2.0 * a)
            )
        }
        Shape::Triangle => format!(
            "<path d=\"M{} {}L{} {}L{} {}Z\"/>",
            c(x),
            c(y - 1.1 * r),
            c(x + r),
            c(y + 0.7 * r),
            c(x - r),
            c(y + 0.7 * r)
        ),
        Shape::Diamond => format!(
            "<path d=\"M{} {}L{} {}L{} {}L{} {}Z\"/>",
            c(x),
            c(y - 1.15 * r),
            c(x + r),
            c(y),
            c(x),
            c(y + 1.15 * r),
            c(x - r),
            c(y)
        ),
        Shape::Cross => {
            let a = 0.8 * r;
            format!(
                "<path d=\"M{} {}L{} {}M{} {}L{} {}\" stroke-width=\"1.6\"/>",
                c(x - a),
                c(y - a),
                c(x + a),
                c(y + a),
                c(x - a),
                c(y + a),
                c(x + a),
                c(y - a)
            )
        }
    }
}

/// A placed label with a white halo so it reads over anything.
fn label(p: &Placed, text: &str) -> String {
    let mut s = String::new();
    if let Some([a, b]) = p.leader {
        let _ = writeln!(
            s,
            "<path d=\"M{} {}L{} {}\" stroke=\"{GREY}\" stroke-width=\"0.8\" fill=\"none\"/>",
            coord(a[0]),
            coord(a[1]),
            coord(b[0]),
            coord(b[1])
        );
    }
    s.push_str(&text_el(
        p.baseline[0],
        p.baseline[1],
        font_size::LABEL,
        "start",
        &format!(" stroke=\"{WHITE}\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\""),
        text,
    ));
    s
}

fn legend(entries: &[LegendEntry], l: &layout::LegendLayout) -> String {
    let r = l.rect;
    let mut s = format!(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{WHITE}\" fill-opacity=\"0.92\" stroke=\"#b0b0b0\" stroke-width=\"0.8\" rx=\"2\"/>\n",
        coord(r.x),
        coord(r.y),
        coord(r.w),
        coord(r.h)
    );
    for (e, &[x, y]) in entries.iter().zip(&l.entries) {
        let mid = y + 0.5 * (LEGEND_ROW - 2.0);
        if let Some(Fill { color, opacity }) = &e.fill {
            let _ = writeln!(
                s,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"10\" fill=\"{color}\" fill-opacity=\"{}\"/>",
                coord(x),
                coord(mid - 5.0),
                coord(LEGEND_SWATCH),
                coord(*opacity)
            );
        }
        if let Some(st) = &e.line {
            let _ = writeln!(
                s,
                "<path d=\"M{} {}h{}\" {}/>",
                coord(x),
                coord(mid),
                coord(LEGEND_SWATCH),
                stroke_attrs(st)
            );
        }
        if let Some(m) = &e.marker {
            s.push_str(&markers(&[[x + 0.5 * LEGEND_SWATCH, mid]], m));
        }
        s.push_str(&text_el(
            x + LEGEND_SWATCH + 6.0,
            mid + 0.5 * cap_height(font_size::LEGEND),
            font_size::LEGEND,
            "start",
            "",
            &e.label,
        ));
    }
    s
}

fn colorbar(cb: &ColorBar, r: crate::geometry::Rect) -> String {
    let n = cb.stops.len().max(1);
    let h = r.h / n as f64;
    // Swatch k (value stops[k]) is centred at this y; low values at the bottom.
    let centre = |k: f64| r.bottom() - (k + 0.5) * h;
    let mut s = String::new();
    for (k, (v, color)) in cb.stops.iter().enumerate() {
        let y = centre(k as f64);
        let _ = writeln!(
            s,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{color}\"/>",
            coord(r.x),
            coord(y - 0.5 * h),
            coord(r.w),
            coord(h)
        );
        let _ = writeln!(
            s,
            "<path d=\"M{} {}h4\" stroke=\"{INK}\" stroke-width=\"1\"/>",
            coord(r.right()),
            coord(y)
        );
        s.push_str(&text_el(
            r.right() + 7.0,
            y + 0.5 * cap_height(font_size::TICK),
            font_size::TICK,
            "start",
            "",
            &short(*v, 3),
        ));
    }
    let _ = writeln!(
        s,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"{INK}\" stroke-width=\"0.8\"/>",
        coord(r.x),
        coord(r.y),
        coord(r.w),
        coord(r.h)
    );
    s.push_str(&text_el(
        r.x + 0.5 * r.w,
        r.y - 8.0,
        font_size::AXIS,
        "middle",
        "",
        &cb.label,
    ));
    // Marks sit at their value, interpolated between swatch centres.
    let values: Vec<f64> = cb.stops.iter().map(|(v, _)| *v).collect();
    for (v, text) in &cb.marks {
        let k = match values.iter().position(|&s| s >= *v) {
            Some(0) | None if values.is_empty() => 0.0,
            Some(0) => 0.0,
            None => (values.len() - 1) as f64,
            Some(j) => (j - 1) as f64 + (v - values[j - 1]) / (values[j] - values[j - 1]),
        };
        let y = centre(k);
        let _ = writeln!(
            s,
            "<path d=\"M{} {}l-6 -4v8Z\" fill=\"{INK}\"/>",
            coord(r.x - 1.0),
            coord(y)
        );
        s.push_str(&text_el(
            r.x - 9.0,
            y + 0.5 * cap_height(font_size::TICK),
            font_size::TICK,
            "end",
            "",
            text,
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a < b & \"c\""), "a &lt; b &amp; &quot;c&quot;");
    }
}
