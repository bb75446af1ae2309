//! The chart engine: figures as data ([`scene`]: panels of keyed marks, a
//! legend, notes), placed on a page ([`layout`], [`panel_layout`], [`labels`],
//! [`obstacles`]) and written as SVG ([`svg`]) and PNG ([`png`]).
//!
//! It knows nothing of curves, surfaces or fuzzy numbers and imports nothing
//! of the method: the figures (`crate::figures`) build scenes from numbers
//! the core computes and hand them here. Its drawing vocabulary (colours,
//! strokes, markers) is [`paint`]; which series of the method gets which is
//! decided in one place, `figures/style.rs`.

pub(crate) mod font;
pub(crate) mod geometry;
pub(crate) mod labels;
pub(crate) mod layout;
pub(crate) mod obstacles;
pub(crate) mod paint;
pub(crate) mod panel_layout;
#[cfg(feature = "png")]
pub(crate) mod png;
pub(crate) mod scene;
pub(crate) mod simplify;
pub(crate) mod svg;
pub(crate) mod ticks;
