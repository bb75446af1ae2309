//! The figures of a report that change from stop to stop (the number and
//! stages 2–4), drawn from one run; both the frames (`computed.rs`) and the
//! sizing of the stops (`file_stops.rs`) draw them.

use t2spline::job::{Job, RunOutput};
use t2spline::{Alpha, TypeReduction};

use crate::chart::scene::Figure;
use crate::error::Error;
use crate::figures::curve::{stage2_figure, stage3_figure, stage4_figure, CurveScene, Zoom};
use crate::figures::surface::{self, SurfaceScene};
use crate::figures::{number_figure, FigureOptions};
use crate::{data, set_view};

/// The figures that change with alpha and the type reduction `method`: the
/// number and stages 2–4, with the run (at the figures' samples) they were
/// drawn from.
pub(super) fn stop_figures(
    job: &Job,
    alpha: Alpha,
    method: TypeReduction,
    heights: &[f64],
    options: &FigureOptions,
) -> Result<([Figure; 4], RunOutput), Error> {
    let r = data::compute_within(job, alpha, method, data::REPORT_SURFACE_GRID)?;
    let figures = if job.model.is_surface() {
        let scene = SurfaceScene::new(&r, heights, options.view, options.aspect);
        [
            number_figure(job, alpha, method, options.number)?,
            surface::stage2_figure(&scene),
            surface::stage3_figure(&scene),
            surface::stage4_figure(job, &scene)?,
        ]
    } else {
        let scene = CurveScene::new(&r, heights, options.aspect);
        // The regions at the level stage 2 cuts at (0 for a reduction that
        // does not use alpha), so the slider shows the region at each stop.
        let at = set_view::regions(&job.model, Alpha::try_new(r.alpha)?, &scene.axes())?;
        [
            number_figure(job, alpha, method, options.number)?,
            stage2_figure(&scene, &at),
            stage3_figure(&scene),
            stage4_figure(job, &scene, Zoom::Always)?,
        ]
    };
    Ok((figures, r))
}
