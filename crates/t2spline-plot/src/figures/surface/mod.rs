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

mod bins;
pub mod camera;
mod crisp;
pub mod mesh;
mod points;
mod scene;
mod stage1;
mod stage2;
mod stage3;
mod stage4;

pub use camera::View;
pub use scene::SurfaceScene;
pub use stage1::stage1_figure;
pub use stage2::stage2_figure;
pub use stage3::stage3_figure;
pub use stage4::stage4_figure;
