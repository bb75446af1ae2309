//! `t2spline report JOB.json -o DIR [--alpha A] [--type-reduction NAME]
//! [--point I --axis x|y|z] [--aspect equal|auto]`: writes `DIR/report.html`.

use t2spline::job::{Job, Overrides};
use t2spline::{Alpha, TypeReduction};

use super::plot::{about_number, figure_options};
use super::settings::{about_option, note_unused_alpha};
use crate::cli::ReportArgs;
use crate::output::{read_job_text, Outputs};

/// Where the slider starts when neither `--alpha` nor the job gives alpha.
const DEFAULT_START: f64 = 0.5;

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    let (job, text) = read_job_text(&args.job)?;
    let overrides = Overrides {
        alpha: args.alpha,
        type_reduction: args.reduction.type_reduction,
        ..Overrides::default()
    };
    let default_start = Alpha::try_new(DEFAULT_START)?;
    let (start, method) = match job.settings(&overrides) {
        Ok(s) if s.type_reduction.uses_alpha() => (s.alpha, s.type_reduction),
        Ok(s) => {
            note_unused_alpha(
                "report",
                &s,
                args.alpha.is_some(),
                "only sets where the alpha slider of the paper's reduction starts",
            );
            (s.unused_alpha.unwrap_or(default_start), s.type_reduction)
        }
        Err(t2spline::Error::MissingAlpha) => (default_start, TypeReduction::Paper),
        Err(e) => return Err(about_option(e)),
    };
    let job = Job {
        type_reduction: method,
        ..job
    };
    let html =
        t2spline_plot::render_report(&job, &text, start, &figure_options(&args.figures, &job)?)
            .map_err(about_number)?;
    let mut out = Outputs::default();
    out.in_dir(&args.output, "report.html", html.into_bytes());
    out.to(
        None,
        format!("{}\n", args.output.join("report.html").display()).into_bytes(),
    );
    out.commit()
}
