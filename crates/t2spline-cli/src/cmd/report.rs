//! `t2spline report JOB.json -o DIR [--alpha A]`: writes `DIR/report.html`.

use t2spline::Alpha;

use super::alpha;
use crate::cli::ReportArgs;
use crate::output::{read_job_text, Outputs};

/// Where the slider starts when neither `--alpha` nor the job gives alpha.
const DEFAULT_START: f64 = 0.5;

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    let option = alpha::parse_option(args.alpha)?;
    let (job, text) = read_job_text(&args.job)?;
    let start = match option.or(job.alpha) {
        Some(a) => a,
        None => Alpha::try_new(DEFAULT_START)?,
    };
    let html = t2spline_plot::report::render(&job, &text, start)?;
    let mut out = Outputs::default();
    out.in_dir(&args.output, "report.html", html.into_bytes());
    out.to(
        None,
        format!("{}\n", args.output.join("report.html").display()).into_bytes(),
    );
    out.commit()
}
