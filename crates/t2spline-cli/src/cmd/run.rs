//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--type-reduction NAME]
//! [--samples N] [--csv DIR] [--derivatives K]`.

use std::path::PathBuf;

use t2spline::job::{Job, Overrides, Settings};
use t2spline_io::{check_finite, stage_csv, write_json_pretty, Staged};

use super::settings::{note_unused_alpha, settings};
use crate::cli::RunArgs;
use crate::output::{is_stdio, read_job_text, to_stdout, NewFolders};

/// A run with every input validated.
struct Plan {
    job: Job,
    settings: Settings,
    /// `None`: standard output.
    output: Option<PathBuf>,
    csv: Option<PathBuf>,
}

impl Plan {
    fn new(args: RunArgs) -> anyhow::Result<Plan> {
        let (job, text) = read_job_text(&args.job)?;
        let overrides = Overrides {
            alpha: args.alpha,
            type_reduction: args.reduction.type_reduction,
            samples: args.samples,
            derivatives: args.derivatives,
        };
        let settings = settings(&job, &overrides, &args.job, &text)?;
        note_unused_alpha(
            "run",
            &settings,
            args.alpha.is_some(),
            "is ignored (stage 2 is cut at alpha = 0, the whole footprint)",
        );
        Ok(Plan {
            job,
            settings,
            output: args.output.filter(|p| !is_stdio(p)),
            csv: args.csv,
        })
    }
}

pub fn run(args: RunArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let result = plan
        .job
        .run(&plan.settings)
        .map_err(super::settings::about_derivatives)?;
    // Nothing is written unless every number is finite (serde_json would write
    // NaN as null).
    check_finite(&result)?;
    // Every file is complete in a temporary file before any is renamed, so a
    // failure leaves all existing outputs as they were; folders made for the
    // CSV files are removed again.
    let mut folders = NewFolders::default();
    let mut staged = Staged::default();
    let files = (|| {
        if let Some(dir) = &plan.csv {
            folders.create(dir)?;
            stage_csv(&mut staged, dir, &result)?;
        }
        if let Some(path) = &plan.output {
            staged.add(path, |w| write_json_pretty(w, &result))?;
        }
        staged.commit()
    })();
    if files.is_err() {
        folders.remove();
    }
    files?;
    if plan.output.is_none() {
        to_stdout(|w| write_json_pretty(w, &result))?;
    }
    Ok(())
}
