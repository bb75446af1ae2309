//! `t2spline report JOB.json -o DIR [--alpha A] [--point I --axis x|y|z]
//! [--aspect equal|auto]`: writes `DIR/report.html`.

use t2spline::job::Overrides;
use t2spline::Alpha;

use super::plot::{about_number, figure_options};
use super::settings::about_option;
use crate::cli::ReportArgs;
use crate::output::{read_job_text, Outputs};

/// Where the slider starts when neither `--alpha` nor the job gives alpha.
const DEFAULT_START: f64 = 0.5;

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    let (job, text) = read_job_text(&args.job)?;
    let overrides = Overrides {
        alpha: args.alpha,
        ..Overrides::default()
    };
    let start = match job.settings(&overrides) {
        Ok(s) => s.alpha,
        Err(t2spline::Error::MissingAlpha) => Alpha::try_new(DEFAULT_START)?,
        Err(e) => return Err(about_option(e)),
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
