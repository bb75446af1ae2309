//! What a figure shows, in data coordinates: panels of keyed items, a legend
//! and an optional colour bar. [`crate::chart::layout`] places it on a page and
//! [`crate::chart::svg`] writes it; nothing here knows about pixels.

use crate::chart::paint::{Color, Fill, Marker, Stroke};

/// A point in a panel's data coordinates.
pub type Xy = [f64; 2];

/// A figure: a title, one or more panels side by side, a legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// The file stem (`number`, `stage1-fuzzy`, ...).
    pub name: &'static str,
    /// The title, at the top.
    pub title: String,
    /// One line under the title (parameters such as alpha and h).
    pub subtitle: String,
    /// Panels, drawn left to right (in rows of two when there are four).
    pub panels: Vec<Panel>,
    /// Legend entries, in order.
    pub legend: Vec<LegendEntry>,
    /// A colour bar to the right of the panels.
    pub colorbar: Option<ColorBar>,
    /// Lines of small print under the figure: what was left out or thinned
    /// to keep it readable, and why.
    pub notes: Vec<String>,
}

impl Figure {
    /// A figure without colour bar or notes.
    #[must_use]
    pub fn new(
        name: &'static str,
        title: impl Into<String>,
        subtitle: impl Into<String>,
        panels: Vec<Panel>,
        legend: Vec<LegendEntry>,
    ) -> Figure {
        Figure {
            name,
            title: title.into(),
            subtitle: subtitle.into(),
            panels,
            legend,
            colorbar: None,
            notes: Vec::new(),
        }
    }
}

/// One set of axes.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    /// A title above the axes (e.g. "x–y projection").
    pub title: Option<String>,
    /// Label of the horizontal axis.
    pub x_label: String,
    /// Label of the vertical axis.
    pub y_label: String,
    /// One data unit has the same length on both axes (for curves).
    pub equal_aspect: bool,
    /// Fixed horizontal range; otherwise fitted to the data.
    pub x_range: Option<[f64; 2]>,
    /// Fixed vertical range; otherwise fitted to the data.
    pub y_range: Option<[f64; 2]>,
    /// What is drawn, in order (later on top).
    pub items: Vec<Item>,
    /// Whether the panel has a frame with grid, ticks and axis labels; a 3-D
    /// view draws its own box instead.
    pub frame: bool,
}

impl Panel {
    /// A panel for curves: equal aspect, ranges fitted to the data.
    #[must_use]
    pub fn curves(x_label: &str, y_label: &str) -> Panel {
        Panel {
            equal_aspect: true,
            ..Panel::graph(x_label, y_label)
        }
    }

    /// A panel for a graph of a function: each axis fitted to its data.
    #[must_use]
    pub fn graph(x_label: &str, y_label: &str) -> Panel {
        Panel {
            title: None,
            x_label: x_label.to_owned(),
            y_label: y_label.to_owned(),
            equal_aspect: false,
            x_range: None,
            y_range: None,
            items: Vec::new(),
            frame: true,
        }
    }

    /// A panel without frame, ticks or axis labels, one data unit the same
    /// length on both axes: a projected 3-D view that draws its own box.
    #[must_use]
    pub fn view() -> Panel {
        Panel {
            frame: false,
            ..Panel::curves("", "")
        }
    }

    /// Adds an item with a key unique within the panel.
    pub fn push(&mut self, key: impl Into<String>, mark: Mark) {
        self.items.push(Item {
            key: key.into(),
            mark,
        });
    }
}

/// A drawn thing with a stable key. Figures of one kind at different alphas
/// have the same keys in the same order, so a report can swap only what changes.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// Unique within its panel; used as an element id.
    pub key: String,
    /// What is drawn.
    pub mark: Mark,
}

/// The kinds of drawn things.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// A polyline.
    Line {
        /// The vertices.
        points: Vec<Xy>,
        /// How it is drawn.
        stroke: Stroke,
    },
    /// A closed, filled polygon without outline.
    Area {
        /// The vertices.
        points: Vec<Xy>,
        /// How it is filled.
        fill: Fill,
    },
    /// A filled region bounded by several closed rings (polygons with
    /// holes), without outline: the rings are filled by the even–odd rule,
    /// so a hole inside its exterior stays empty (the core's polygons do not
    /// overlap, so even–odd and non-zero fill the same set).
    Region {
        /// The rings, each closed implicitly (exteriors and holes alike).
        rings: Vec<Vec<Xy>>,
        /// How it is filled.
        fill: Fill,
    },
    /// Opaque axis-aligned rectangles grouped by colour (the cells of a
    /// map), drawn without anti-aliasing so that neighbours show no seams.
    Tiles {
        /// Per colour, the rectangles as their lower-left and upper-right
        /// corners.
        tiles: Vec<(Color, Vec<[Xy; 2]>)>,
    },
    /// The same marker at several points.
    Markers {
        /// Where.
        points: Vec<Xy>,
        /// What.
        marker: Marker,
    },
    /// Separate straight segments in one style (footprint bars, distance marks).
    Segments {
        /// The segments.
        segments: Vec<[Xy; 2]>,
        /// How they are drawn.
        stroke: Stroke,
    },
    /// A horizontal line across the whole panel, labelled at its right end.
    HRule {
        /// Height in data units.
        y: f64,
        /// How it is drawn.
        stroke: Stroke,
        /// Text at the right end, above the line.
        label: String,
    },
    /// A vertical line across the whole panel, labelled at its top.
    VRule {
        /// Position in data units.
        x: f64,
        /// How it is drawn.
        stroke: Stroke,
        /// Text beside the line, at the top.
        label: String,
    },
    /// A text placed near `anchor` where it covers nothing (`labels`);
    /// far placements get a thin leader line.
    Label {
        /// The point the text is about.
        anchor: Xy,
        /// The text.
        text: String,
        /// Whether it may be left out when there is no room.
        priority: Priority,
    },
    /// Polygons and lines drawn in the given order, one after another (a
    /// depth-sorted 3-D view: farthest first).
    Mesh {
        /// What is drawn, in order.
        facets: Vec<Facet>,
    },
    /// A text centred on a fixed point (a tick label of a 3-D box), with a
    /// white halo; not moved by label placement.
    Text {
        /// The centre of the text.
        at: Xy,
        /// The text.
        text: String,
    },
    /// Nothing (an item absent at this alpha, kept so keys stay aligned).
    Empty,
}

/// One element of a [`Mark::Mesh`]: a filled polygon (none when `points` is
/// empty) and, drawn right after it, straight lines in one style.
#[derive(Clone, Debug, PartialEq)]
pub struct Facet {
    /// The polygon's corners; empty for lines alone.
    pub points: Vec<Xy>,
    /// The polygon's fill; an opaque fill also outlines the polygon in its
    /// own colour, so that neighbouring polygons show no seams.
    pub fill: Fill,
    /// Segments drawn after the polygon (lines of the surface along its
    /// edges), with `stroke`.
    pub lines: Vec<[Xy; 2]>,
    /// How `lines` are drawn.
    pub stroke: Option<Stroke>,
}

/// Whether a label must be shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Priority {
    /// An annotation: placed where it covers least if no place is free, but
    /// never on another text or the legend.
    Always,
    /// A name (of a control point): shown only where it covers nothing, near
    /// its anchor; left out otherwise.
    IfRoom,
}

/// One legend row: a sample of a line, an area and/or a marker, and a text.
#[derive(Clone, Debug, PartialEq)]
pub struct LegendEntry {
    /// The text.
    pub label: String,
    /// A line sample.
    pub line: Option<Stroke>,
    /// A filled box sample.
    pub fill: Option<Fill>,
    /// A marker sample.
    pub marker: Option<Marker>,
}

impl LegendEntry {
    /// An entry for a line.
    #[must_use]
    pub fn line(label: &str, stroke: Stroke) -> LegendEntry {
        LegendEntry {
            label: label.to_owned(),
            line: Some(stroke),
            fill: None,
            marker: None,
        }
    }

    /// An entry for a line with a marker.
    #[must_use]
    pub fn line_marker(label: &str, stroke: Stroke, marker: Marker) -> LegendEntry {
        LegendEntry {
            marker: Some(marker),
            ..LegendEntry::line(label, stroke)
        }
    }

    /// A line entry with a marker when there is one (a series whose points
    /// may be left out for want of room).
    #[must_use]
    pub fn line_maybe_marker(label: &str, stroke: Stroke, marker: Option<Marker>) -> LegendEntry {
        LegendEntry {
            marker,
            ..LegendEntry::line(label, stroke)
        }
    }

    /// An entry for a marker alone.
    #[must_use]
    pub fn marker(label: &str, marker: Marker) -> LegendEntry {
        LegendEntry {
            label: label.to_owned(),
            line: None,
            fill: None,
            marker: Some(marker),
        }
    }

    /// An entry for a filled area.
    #[must_use]
    pub fn area(label: &str, fill: Fill) -> LegendEntry {
        LegendEntry {
            label: label.to_owned(),
            line: None,
            fill: Some(fill),
            marker: None,
        }
    }
}

/// A discrete colour bar: one swatch per value.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorBar {
    /// The quantity (e.g. "α").
    pub label: String,
    /// Values in increasing order with their colours.
    pub stops: Vec<(f64, Color)>,
    /// Extra labelled marks on the bar (e.g. the height h).
    pub marks: Vec<(f64, String)>,
}
