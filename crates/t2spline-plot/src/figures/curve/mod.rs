//! The figures of a curve job: the four stages of Algorithm 1.1, the distance
//! along the curve for several alphas, the distance against alpha, and the
//! type reductions compared.
//!
//! Each builder reads a [`RunOutput`](t2spline::job::RunOutput) (or asks [`crate::data`] for more) and
//! is written with the series helpers of `series.rs`, one per thing drawn, so that a
//! figure's function lists what it shows.

mod density;
mod distance;
mod largest;
mod membership;
mod phrases;
mod projection;
mod reductions;
mod scene;
mod section;
mod series;
mod stage1;
mod stage2;
mod stage3;
mod stage4;
mod sweep;
mod zoom;

pub use distance::{alpha_rule, distance_figure};
pub use largest::largest_distance;
pub use membership::membership_figure;
pub use phrases::{alpha_phrase, reduction_phrase, weights_phrase};
pub use reductions::reductions_figure;
pub use scene::CurveScene;
pub use section::section_figure;
pub use series::region_mark;
pub use stage1::stage1_figure;
pub use stage2::stage2_figure;
pub use stage3::stage3_figure;
pub use stage4::{stage4_figure, Zoom};
pub use sweep::sweep_figure;
