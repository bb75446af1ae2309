//! Drawn things as SVG elements: lines, areas, markers, segments, rules and
//! placed texts.

use std::fmt::Write as _;

use super::number::coord;
use crate::chart::geometry::Px;
use crate::chart::labels::Placed;
use crate::chart::paint::{font_size, Marker, Shape, GREY, WHITE};
use crate::chart::panel_layout::PanelLayout;
use crate::chart::scene::{Facet, Mark, Xy};
use crate::chart::simplify::simplify;

use super::element::{points_attr, stroke_attrs, text_el};

/// The stretches of a polyline between its gaps (non-finite points), in
/// pixels, each simplified to within `tolerance`.
fn stretches(points: &[Xy], pl: &PanelLayout, tolerance: f64) -> Vec<Vec<Px>> {
    points
        .split(|p| !(p[0].is_finite() && p[1].is_finite()))
        .filter(|s| !s.is_empty())
        .map(|s| {
            simplify(
                &s.iter().map(|&p| pl.to_px(p)).collect::<Vec<_>>(),
                tolerance,
            )
        })
        .collect()
}

/// A line: one `<polyline>`, or a `<path>` of several stretches when it has
/// gaps (a jump that no line may bridge).
fn line(
    points: &[Xy],
    stroke: &crate::chart::paint::Stroke,
    pl: &PanelLayout,
    clip_attr: &str,
    tolerance: f64,
) -> String {
    let runs = stretches(points, pl, tolerance);
    if let [one] = runs.as_slice() {
        return format!(
            "<polyline points=\"{}\" {}{clip_attr}/>\n",
            points_attr(one),
            stroke_attrs(stroke)
        );
    }
    let mut d = String::new();
    for run in &runs {
        for (k, p) in run.iter().enumerate() {
            let _ = write!(
                d,
                "{}{} {}",
                if k == 0 { 'M' } else { 'L' },
                coord(p[0]),
                coord(p[1])
            );
        }
    }
    format!("<path d=\"{d}\" {}{clip_attr}/>\n", stroke_attrs(stroke))
}

pub(super) fn mark(m: &Mark, pl: &PanelLayout, clip: &str, tolerance: f64) -> String {
    let clip_attr = format!(" clip-path=\"url(#{clip})\"");
    match m {
        Mark::Line { points, stroke } => line(points, stroke, pl, &clip_attr, tolerance),
        Mark::Area { points, fill } => {
            let px = stretches(points, pl, tolerance).concat();
            format!(
                "<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke=\"none\"{clip_attr}/>\n",
                points_attr(&px),
                fill.color,
                coord(fill.opacity)
            )
        }
        Mark::Region { rings, fill } => region(rings, fill, pl, &clip_attr, tolerance),
        Mark::Tiles { tiles } => tiles_el(tiles, pl, &clip_attr),
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
        Mark::VRule { x, stroke, .. } => {
            let px = pl.to_px([*x, 0.0])[0];
            format!(
                "<path d=\"M{} {}V{}\" {}/>\n",
                coord(px),
                coord(pl.plot.y),
                coord(pl.plot.bottom()),
                stroke_attrs(stroke)
            )
        }
        Mark::Mesh { facets } => mesh(facets, pl, &clip_attr),
        Mark::Text { at, text } => {
            let [x, y] = pl.to_px(*at);
            text_el(
                x,
                y + 0.5 * crate::chart::font::cap_height(font_size::TICK),
                font_size::TICK,
                "middle",
                &format!(" stroke=\"{WHITE}\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\""),
                text,
            )
        }
        Mark::Label { .. } | Mark::Empty => String::new(),
    }
}

/// A region: one `<path>` of closed rings filled by the even–odd rule (a
/// hole stays empty whatever its orientation), each ring simplified to
/// within `tolerance` as a closed line (its first vertex kept).
fn region(
    rings: &[Vec<Xy>],
    fill: &crate::chart::paint::Fill,
    pl: &PanelLayout,
    clip_attr: &str,
    tolerance: f64,
) -> String {
    let mut d = String::new();
    for ring in rings {
        let Some(&first) = ring.first() else {
            continue;
        };
        let mut closed: Vec<Px> = ring.iter().map(|&p| pl.to_px(p)).collect();
        closed.push(pl.to_px(first));
        let mut px = simplify(&closed, tolerance);
        px.pop();
        if px.len() < 3 {
            continue;
        }
        for (k, p) in px.iter().enumerate() {
            let _ = write!(
                d,
                "{}{} {}",
                if k == 0 { 'M' } else { 'L' },
                coord(p[0]),
                coord(p[1])
            );
        }
        d.push('Z');
    }
    if d.is_empty() {
        return String::new();
    }
    format!(
        "<path d=\"{d}\" fill=\"{}\" fill-opacity=\"{}\" fill-rule=\"evenodd\" stroke=\"none\"{clip_attr}/>\n",
        fill.color,
        coord(fill.opacity)
    )
}

/// Tiles: one `<path>` of rectangles per colour, `crispEdges` (no
/// anti-aliasing, so tiles that touch show no seam between them).
fn tiles_el(
    tiles: &[(crate::chart::paint::Color, Vec<[Xy; 2]>)],
    pl: &PanelLayout,
    clip_attr: &str,
) -> String {
    let mut s = format!("<g shape-rendering=\"crispEdges\" stroke=\"none\"{clip_attr}>");
    for (color, rects) in tiles {
        if rects.is_empty() {
            continue;
        }
        s.push_str("<path d=\"");
        for [a, b] in rects {
            let ([x0, y0], [x1, y1]) = (pl.to_px(*a), pl.to_px(*b));
            let _ = write!(
                s,
                "M{} {}H{}V{}H{}Z",
                coord(x0),
                coord(y0),
                coord(x1),
                coord(y1),
                coord(x0)
            );
        }
        let _ = write!(s, "\" fill=\"{color}\"/>");
    }
    s.push_str("</g>\n");
    s
}

/// A mesh: one `<path>` per polygon (opaque ones outlined in their own
/// colour against seams) and one per facet's lines, in the facets' order.
fn mesh(facets: &[Facet], pl: &PanelLayout, clip_attr: &str) -> String {
    let mut s = format!("<g stroke-linejoin=\"round\"{clip_attr}>");
    for f in facets {
        if f.points.len() > 2 {
            s.push_str("<path d=\"");
            for (k, p) in f.points.iter().enumerate() {
                let [x, y] = pl.to_px(*p);
                let _ = write!(
                    s,
                    "{}{} {}",
                    if k == 0 { 'M' } else { 'L' },
                    coord(x),
                    coord(y)
                );
            }
            let c = f.fill.color;
            if f.fill.opacity >= 1.0 {
                let _ = write!(s, "Z\" fill=\"{c}\" stroke=\"{c}\" stroke-width=\"0.5\"/>");
            } else {
                let _ = write!(
                    s,
                    "Z\" fill=\"{c}\" fill-opacity=\"{}\"/>",
                    coord(f.fill.opacity)
                );
            }
        }
        if let (Some(stroke), false) = (&f.stroke, f.lines.is_empty()) {
            s.push_str("<path d=\"");
            let mut end = None;
            for [a, b] in &f.lines {
                // A segment that starts where the last ended continues its
                // stretch, so dashes run on.
                if end != Some(*a) {
                    let a = pl.to_px(*a);
                    let _ = write!(s, "M{} {}", coord(a[0]), coord(a[1]));
                }
                let p = pl.to_px(*b);
                let _ = write!(s, "L{} {}", coord(p[0]), coord(p[1]));
                end = Some(*b);
            }
            let _ = write!(s, "\" {}/>", stroke_attrs(stroke));
        }
    }
    s.push_str("</g>\n");
    s
}

/// Markers at pixel positions, in one group.
pub(super) fn markers(px: &[Px], m: &Marker) -> String {
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
pub(super) fn label(p: &Placed, text: &str) -> String {
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
