//! One fuzzy number (paper Figs. 3.1 and 4.1–4.4): its three membership
//! functions, the footprint of uncertainty, the height h, the cut at alpha and
//! the type-reduced triangle with its centroid; and the other reductions of
//! docs/method.md §9 (`number_reductions.rs`).

use t2spline::job::Job;
use t2spline::{Alpha, AlphaCut, Axis, Interval, Layer, Nt2Number, Tfn, TypeReduction};

use super::number_reductions;
use super::style::{layer_marker, layer_stroke, upper_band};
use crate::chart::paint::{Marker, Shape, Stroke, GREY, INK, PURPLE};
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel, Priority, Xy};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;

/// Which number the `number` figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NumberChoice {
    /// Control point index, from 0 (of a surface: `i·nv + j`, the net row by
    /// row).
    pub point: usize,
    /// Coordinate.
    pub axis: Axis,
}

impl Default for NumberChoice {
    fn default() -> Self {
        NumberChoice {
            point: 0,
            axis: Axis::X,
        }
    }
}

impl NumberChoice {
    /// The chosen control point as a reader names it: its index `I` on a
    /// curve, `(i, j)` in a surface's net (`I = i·nv + j`).
    ///
    /// # Examples
    /// ```
    /// use t2spline_plot::NumberChoice;
    /// let job = t2spline_io::read_job("../../examples/fuzzy-terrain.json".as_ref())?;
    /// let [_, nv] = job.model.net_shape().unwrap();
    /// let choice = NumberChoice { point: 2 * nv + 1, ..NumberChoice::default() };
    /// assert_eq!(choice.point_name(&job.model), "(2, 1)");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn point_name(&self, model: &t2spline::job::Model) -> String {
        match model.net_shape() {
            Some([_, nv]) if nv > 0 => format!("({}, {})", self.point / nv, self.point % nv),
            _ => self.point.to_string(),
        }
    }
}

/// The type-reduced triangle.
fn tfn_stroke() -> Stroke {
    Stroke::solid(PURPLE, 2.0)
}

/// The defuzzified value.
fn centroid_marker() -> Marker {
    Marker::filled(Shape::Diamond, 8.0, PURPLE)
}

/// The triangle with feet `lo`, `hi`, apex at `crisp` and height `top`.
fn triangle(lo: f64, crisp: f64, top: f64, hi: f64) -> Vec<Xy> {
    vec![[lo, 0.0], [crisp, top], [hi, 0.0]]
}

/// The footprint of uncertainty (between UMF and LMF) and the three
/// membership functions.
fn membership(p: &mut Panel, x: &Nt2Number) {
    let (u, pr, l, c, h) = (
        x.upper(),
        x.primary(),
        x.lower(),
        x.crisp(),
        x.height().get(),
    );
    p.push(
        "fou",
        Mark::Area {
            points: vec![
                [u.left(), 0.0],
                [c, 1.0],
                [u.right(), 0.0],
                [l.right(), 0.0],
                [c, h],
                [l.left(), 0.0],
            ],
            fill: upper_band(),
        },
    );
    rules(p, h);
    for (key, iv, top, layer) in [
        ("umf", u, 1.0, Layer::UpperLeft),
        ("primary", pr, 1.0, Layer::PrimaryLeft),
        ("lmf", l, h, Layer::LowerLeft),
    ] {
        p.push(
            key,
            Mark::Line {
                points: triangle(iv.left(), c, top, iv.right()),
                stroke: layer_stroke(layer),
            },
        );
    }
}

/// The height h as a horizontal rule (the level α is added by [`cut`]).
pub(super) fn rules(p: &mut Panel, h: f64) {
    p.push(
        "h",
        Mark::HRule {
            y: h,
            stroke: Stroke::dashed(GREY, 1.0, "2 3"),
            label: format!("h = {}", short(h, 4)),
        },
    );
}

/// The level α and the cut ends of each function on it (none of the LMF
/// above its height).
fn cut(p: &mut Panel, cut: &AlphaCut, a: f64) {
    p.push(
        "alpha",
        Mark::HRule {
            y: a,
            stroke: Stroke::solid(INK, 0.9),
            label: format!("α = {}", short(a, 4)),
        },
    );
    let ends = |iv: Interval| vec![[iv.left(), a], [iv.right(), a]];
    for (key, iv, layer) in [
        ("cut-upper", Some(cut.upper()), Layer::UpperLeft),
        ("cut-primary", Some(cut.primary()), Layer::PrimaryLeft),
        ("cut-lower", cut.lower(), Layer::LowerLeft),
    ] {
        p.push(
            key,
            iv.map_or(Mark::Empty, |iv| Mark::Markers {
                points: ends(iv),
                marker: layer_marker(layer),
            }),
        );
    }
}

/// The type-reduced triangle and its centroid on the axis, with a drop line
/// from the triangle.
fn reduced(p: &mut Panel, tfn: &Tfn, c: f64) {
    let d = tfn.defuzzify();
    p.push(
        "tfn",
        Mark::Line {
            points: triangle(tfn.left(), c, 1.0, tfn.right()),
            stroke: tfn_stroke(),
        },
    );
    // The triangle's height above the centroid.
    let top = if d <= c {
        if c > tfn.left() {
            (d - tfn.left()) / (c - tfn.left())
        } else {
            1.0
        }
    } else if tfn.right() > c {
        (tfn.right() - d) / (tfn.right() - c)
    } else {
        1.0
    };
    p.push(
        "defuzzified-line",
        Mark::Segments {
            segments: vec![[[d, 0.0], [d, top]]],
            stroke: Stroke::dashed(PURPLE, 1.0, "3 2"),
        },
    );
    p.push(
        "defuzzified",
        Mark::Markers {
            points: vec![[d, 0.0]],
            marker: centroid_marker(),
        },
    );
    for (key, anchor, text) in [
        (
            "defuzzified-text",
            [d, 0.0],
            format!("defuzzified {}", short(d, 4)),
        ),
        ("crisp-text", [c, 1.0], format!("crisp {}", short(c, 4))),
    ] {
        p.push(
            key,
            Mark::Label {
                anchor,
                text,
                priority: Priority::Always,
            },
        );
    }
}

/// The legend of what is drawn (the LMF's cut ends only below its height),
/// the paper's defuzzified value `d` named as such.
fn legend(lower_cut: bool, d: f64) -> Vec<LegendEntry> {
    let lmf = if lower_cut {
        LegendEntry::line_marker(
            "LMF (lower, height h) and its cut ends",
            layer_stroke(Layer::LowerLeft),
            layer_marker(Layer::LowerLeft),
        )
    } else {
        LegendEntry::line(
            "LMF (lower, height h): no cut above h",
            layer_stroke(Layer::LowerLeft),
        )
    };
    vec![
        LegendEntry::line_marker(
            "UMF (upper) and its cut ends",
            layer_stroke(Layer::UpperLeft),
            layer_marker(Layer::UpperLeft),
        ),
        LegendEntry::line_marker(
            "primary MF and its cut ends",
            layer_stroke(Layer::PrimaryLeft),
            layer_marker(Layer::PrimaryLeft),
        ),
        lmf,
        LegendEntry::area("footprint of uncertainty", upper_band()),
        LegendEntry::line("type-reduced triangle", tfn_stroke()),
        LegendEntry::marker(
            &format!("paper: defuzzified {}", short(d, 4)),
            centroid_marker(),
        ),
    ]
}

/// The `number` figure for one coordinate of one control point at `alpha`:
/// the paper's cut and type reduction, and the other reductions of docs/method.md §9
/// (which do not use alpha) beside them. The subtitle states the reduction
/// `method` (the run's).
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if the job has no such
/// point or coordinate.
pub fn number_figure(
    job: &Job,
    alpha: Alpha,
    method: TypeReduction,
    choice: NumberChoice,
) -> Result<Figure, Error> {
    let x = data::number(&job.model, choice.point, choice.axis)?;
    let title = format!(
        "Fuzzy number: coordinate {} of control point {}",
        Axis::name(choice.axis),
        choice.point_name(&job.model)
    );
    Ok(lone_number_figure(
        &x,
        alpha,
        method,
        title,
        Axis::name(choice.axis),
    ))
}

/// The `number` figure of the number `x` at `alpha`, titled `title`: what
/// [`number_figure`] draws for a number of a job, for a number on its own
/// (a notebook's picture of one); `x_label` names the horizontal axis.
#[must_use]
pub fn lone_number_figure(
    x: &Nt2Number,
    alpha: Alpha,
    method: TypeReduction,
    title: String,
    x_label: &str,
) -> Figure {
    let c = x.alpha_cut(alpha);
    let tfn = c.type_reduce();
    let mut panel = Panel::graph(x_label, "membership grade");
    panel.y_range = Some([-0.07, 1.12]);
    membership(&mut panel, x);
    cut(&mut panel, &c, alpha.get());
    reduced(&mut panel, &tfn, x.crisp());
    let mut legend = legend(c.lower().is_some(), tfn.defuzzify());
    legend.extend(number_reductions::add_reductions(&mut panel, x));
    let regime = if c.lower().is_some() {
        "α ≤ h: three cut ends averaged"
    } else {
        "α > h: no lower cut, two ends averaged"
    };
    let subtitle = match method {
        TypeReduction::Paper => format!(
            "{regime}; type-reduced ({}, {}, {}), defuzzified {}",
            short(tfn.left(), 4),
            short(x.crisp(), 4),
            short(tfn.right(), 4),
            short(tfn.defuzzify(), 4)
        ),
        method => number_reductions::reduction_subtitle(x, method),
    };
    Figure::new("number", title, subtitle, vec![panel], legend)
}
