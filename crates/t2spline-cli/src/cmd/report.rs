//! `t2spline report JOB.json -o DIR [--alpha A] [--type-reduction NAME]
//! [--point I --axis x|y|z] [--aspect equal|auto]`: writes `DIR/report.html`.

use t2spline::Alpha;
use t2spline_io::MissingAlpha;

use super::plot::{about_number, figure_options};
use super::prepare::{note_alpha, prepare_with, reduction_overrides};
use crate::clash::Claims;
use crate::cli::ReportArgs;
use crate::output::Outputs;

/// The file written in the output folder.
const REPORT: &str = "report.html";

/// Where the slider starts when neither `--alpha` nor the job gives alpha.
const DEFAULT_START: f64 = 0.5;

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    crate::output::refuse_extension(
        "--output",
        &args.output,
        &["html", "htm"],
        &format!("report writes a folder (the page `{REPORT}` and the files it offers for download): name a folder, e.g. `report`"),
    )?;
    Claims::new([args.job.as_path()]).folder("--output", &args.output, [REPORT])?;
    let default_start = Alpha::try_new(DEFAULT_START)?;
    let overrides = reduction_overrides(args.alpha, &args.reduction);
    // The page shows the job's text as given.
    let (prepared, text) =
        prepare_with(&args.job, &overrides, MissingAlpha::Default(default_start))?;
    let settings = prepared.settings();
    let start = if settings.type_reduction().uses_alpha() {
        settings.alpha()
    } else {
        note_alpha(
            "report",
            settings,
            args.alpha.is_some(),
            "only sets where the alpha slider of the paper's reduction starts",
        );
        settings.unused_alpha().unwrap_or(default_start)
    };
    let job = prepared.job();
    let html =
        t2spline_plot::render_report(job, &text, start, &figure_options(&args.figures, job)?)
            .map_err(about_number)?;
    let mut out = Outputs::default();
    out.in_dir(&args.output, REPORT, html.into_bytes());
    out.to(
        None,
        format!("{}\n", args.output.join(REPORT).display()).into_bytes(),
    );
    out.commit()
}
