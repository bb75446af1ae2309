//! How each series of the method looks, the same in every figure: the one
//! place that gives each layer, cut, region and reduction its colour, line and
//! marker, from the chart engine's vocabulary (`chart/paint.rs`).

use t2spline::{Layer, TypeReduction};

use crate::chart::paint::{
    Color, Fill, Marker, Shape, Stroke, BLACK, BLUE, GREEN, GREY, INK, ORANGE, PURPLE, SKY,
    VERMILLION, WHITE,
};

/// The layers of each function, for legends and bars: (left, right, name).
pub const FUNCTIONS: [(Layer, Layer, &str); 3] = [
    (Layer::UpperLeft, Layer::UpperRight, "upper"),
    (Layer::PrimaryLeft, Layer::PrimaryRight, "primary"),
    (Layer::LowerLeft, Layer::LowerRight, "lower"),
];

/// The line of a layer curve (left and right ends of one function look alike).
#[must_use]
pub fn layer_stroke(layer: Layer) -> Stroke {
    match layer {
        Layer::UpperLeft | Layer::UpperRight => Stroke::dashed(BLUE, 1.3, "7 4"),
        Layer::PrimaryLeft | Layer::PrimaryRight => Stroke::dashed(GREEN, 1.3, "10 3 2 3"),
        Layer::LowerLeft | Layer::LowerRight => Stroke::dashed(VERMILLION, 1.7, "2 2.5"),
        Layer::Crisp => crisp_stroke(),
    }
}

/// The marker of a layer's control points.
#[must_use]
pub fn layer_marker(layer: Layer) -> Marker {
    match layer {
        Layer::UpperLeft | Layer::UpperRight => Marker::open(Shape::Square, 6.5, BLUE),
        Layer::PrimaryLeft | Layer::PrimaryRight => Marker::open(Shape::Triangle, 7.0, GREEN),
        Layer::LowerLeft | Layer::LowerRight => Marker::open(Shape::Circle, 6.5, VERMILLION),
        Layer::Crisp => crisp_marker(),
    }
}

/// The crisp curve.
#[must_use]
pub fn crisp_stroke() -> Stroke {
    Stroke::solid(BLACK, 1.9)
}

/// The crisp control points.
#[must_use]
pub fn crisp_marker() -> Marker {
    Marker::filled(Shape::Circle, 6.5, BLACK)
}

/// The control polygon.
#[must_use]
pub fn polygon_stroke() -> Stroke {
    Stroke::dashed(GREY, 0.9, "3 3")
}

/// The light fill of the upper function's region (of a surface: the
/// envelope between the upper layer surfaces), and of the footprint of a
/// number.
#[must_use]
pub fn upper_band() -> Fill {
    Fill {
        color: BLUE,
        opacity: 0.12,
    }
}

/// The darker fill of the lower function's region.
#[must_use]
pub fn lower_band() -> Fill {
    Fill {
        color: VERMILLION,
        opacity: 0.32,
    }
}

/// The middle fill of the primary function's region (the fuzzy shoreline's
/// primary band), between the upper's and the lower's.
#[must_use]
pub fn primary_band() -> Fill {
    Fill {
        color: GREEN,
        opacity: 0.22,
    }
}

/// The crisp surface's contour lines under a terrain figure: thin grey.
#[must_use]
pub fn level_stroke() -> Stroke {
    Stroke::solid(GREY, 0.6)
}

/// The contours of a membership map (the outlines of its regions): thin
/// ink, drawn over a white halo so that they show on every colour of the
/// map.
#[must_use]
pub fn contour_stroke() -> Stroke {
    Stroke::solid(INK, 0.8)
}

/// The white halo under a contour.
#[must_use]
pub fn halo_stroke() -> Stroke {
    Stroke::solid(WHITE, 2.4)
}

/// The type-reduced left curve: purple, long dashes.
#[must_use]
pub fn left_stroke() -> Stroke {
    Stroke::dashed(PURPLE, 1.7, "8 3")
}

/// The type-reduced right curve: orange, short dashes, so that left and
/// right differ in grey too.
#[must_use]
pub fn right_stroke() -> Stroke {
    Stroke::dashed(ORANGE, 1.9, "2.5 2.5")
}

/// The type-reduced left control points.
#[must_use]
pub fn left_marker() -> Marker {
    Marker::filled(Shape::Triangle, 7.5, PURPLE)
}

/// The type-reduced right control points.
#[must_use]
pub fn right_marker() -> Marker {
    Marker::filled(Shape::Diamond, 8.0, ORANGE)
}

/// The band between the type-reduced curves.
#[must_use]
pub fn reduced_band() -> Fill {
    Fill {
        color: PURPLE,
        opacity: 0.16,
    }
}

/// The defuzzified (solution) curve.
#[must_use]
pub fn solution_stroke() -> Stroke {
    Stroke::dashed(BLUE, 1.9, "6 3")
}

/// The defuzzified control points.
#[must_use]
pub fn solution_marker() -> Marker {
    Marker::open(Shape::Diamond, 8.0, BLUE)
}

/// The segment of the largest distance between the curves.
#[must_use]
pub fn distance_stroke() -> Stroke {
    Stroke::solid(BLACK, 1.4)
}

/// The ends of the largest distance.
#[must_use]
pub fn distance_marker() -> Marker {
    Marker::open(Shape::Circle, 4.0, BLACK)
}

/// A type reduction's name in legends, subtitles and the report's selector.
#[must_use]
pub fn reduction_label(method: TypeReduction) -> &'static str {
    match method {
        TypeReduction::Paper => "paper",
        TypeReduction::Centroid => "centroid (Karnik–Mendel)",
        TypeReduction::NieTan => "Nie–Tan",
        TypeReduction::AlphaPlanes => "alpha-planes",
    }
}

/// A type reduction's solution curve: a colour and a dash pattern each, so
/// that the four stay apart in grey print too. The paper's is the purple of
/// the type-reduced curves (stage 3); the others avoid the colours of the
/// membership functions (blue, green, vermillion) where they are drawn
/// beside them (the `number` figure) — Nie–Tan's blue only as a marker there.
#[must_use]
pub fn reduction_stroke(method: TypeReduction) -> Stroke {
    match method {
        TypeReduction::Paper => Stroke::dashed(PURPLE, 1.8, "7 3"),
        TypeReduction::Centroid => Stroke::solid(SKY, 1.8),
        TypeReduction::NieTan => Stroke::dashed(BLUE, 1.8, "2 2"),
        TypeReduction::AlphaPlanes => Stroke::dashed(ORANGE, 1.8, "9 3 2 3"),
    }
}

/// The marker of a type reduction's defuzzified value or largest distance.
#[must_use]
pub fn reduction_marker(method: TypeReduction) -> Marker {
    match method {
        TypeReduction::Paper => Marker::filled(Shape::Diamond, 8.0, PURPLE),
        TypeReduction::Centroid => Marker::filled(Shape::Square, 6.5, SKY),
        TypeReduction::NieTan => Marker::filled(Shape::Triangle, 7.5, BLUE),
        TypeReduction::AlphaPlanes => Marker::filled(Shape::Circle, 6.5, ORANGE),
    }
}

/// The colour of each series of the method, by name, as the figures draw
/// it: `upper`, `primary` and `lower` (a function's layers), `crisp`,
/// `polygon` (the control polygon), `type_reduced_left`,
/// `type_reduced_right`, `solution` (the defuzzified curve) and `distance`.
/// Taken from the strokes above, so that a plotting front end that reads
/// this table (the Python package's `t2spline.plot`) draws as `plot` does.
#[must_use]
pub fn palette() -> [(&'static str, Color); 9] {
    [
        ("upper", layer_stroke(Layer::UpperLeft).color),
        ("primary", layer_stroke(Layer::PrimaryLeft).color),
        ("lower", layer_stroke(Layer::LowerLeft).color),
        ("crisp", crisp_stroke().color),
        ("polygon", polygon_stroke().color),
        ("type_reduced_left", left_stroke().color),
        ("type_reduced_right", right_stroke().color),
        ("solution", solution_stroke().color),
        ("distance", distance_stroke().color),
    ]
}
