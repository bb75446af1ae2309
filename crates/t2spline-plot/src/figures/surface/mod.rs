//! The figures of a surface job: the four stages of Algorithm 1.1 on a
//! tensor-product net (docs/method.md §8), each a shaded 3-D view beside a map over
//! the parameters `(u, v)`.
//!
//! The 3-D view ([`camera`]) is an orthographic projection from a documented
//! direction ([`View`]), its surfaces drawn as depth-sorted quadrilaterals
//! ([`mesh`]: the painter's algorithm, Lambert shading), inside a box with
//! ticks. Spreads are read from the map: a colour per grid cell, with the
//! colour bar ([`bins::Bins`]). Legend, colour bar, labels, styles and the SVG/PNG
//! output are the curve figures' own.
//!
//! A terrain (x and y crisp, the graph of a height) also gets maps over its
//! plan: the envelope's width ([`width`]) and the fuzzy shoreline
//! ([`shoreline`]), whose cells are tiles ([`plan_tiles`]).

mod bins;
pub mod camera;
mod crisp;
pub mod mesh;
mod plan_tiles;
mod points;
mod scene;
mod shoreline;
mod stage1;
mod stage2;
mod stage3;
mod stage4;
mod width;

pub use camera::View;
pub use scene::SurfaceScene;
pub use shoreline::shoreline_figure;
pub use stage1::stage1_figure;
pub use stage2::stage2_figure;
pub use stage3::stage3_figure;
pub use stage4::stage4_figure;
pub use width::width_figure;
