//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--type-reduction NAME]
//! [--samples N] [--csv DIR] [--parquet FILE] [--derivatives K]`; with
//! several jobs, `cmd/batch.rs`.

use std::path::Path;

use t2spline::job::{Job, Settings};
use t2spline_io::{check_finite, write_json_pretty, Staged};

use super::results::{overrides, Destinations, ALPHA_IGNORED};
use super::settings::{note_unused_alpha, settings};
use crate::cli::RunArgs;
use crate::output::{is_stdio, read_job_text, to_stdout, Inputs};

/// A run of one job with every input validated.
struct Plan {
    job: Job,
    settings: Settings,
    out: Destinations,
}

impl Plan {
    fn new(args: RunArgs, path: &Path) -> anyhow::Result<Plan> {
        let out = Destinations {
            json: args.output.clone().filter(|p| !is_stdio(p)),
            csv: args.csv.clone(),
            parquet: args.parquet.clone(),
        };
        out.check(&Inputs::of([path]))?;
        let (job, text) = read_job_text(path)?;
        let settings = settings(&job, &overrides(&args), path, &text)?;
        note_unused_alpha("run", &settings, args.alpha.is_some(), ALPHA_IGNORED);
        Ok(Plan { job, settings, out })
    }
}

pub fn run(mut args: RunArgs) -> anyhow::Result<()> {
    if args.job.len() != 1 || args.jobs.is_some() {
        return super::batch::run(args);
    }
    let path = args.job.remove(0);
    let plan = Plan::new(args, &path)?;
    let result = plan
        .job
        .run(&plan.settings)
        .map_err(super::settings::about_derivatives)?;
    // Nothing is written unless every number is finite (serde_json would write
    // NaN as null).
    check_finite(&result)?;
    plan.out.write(Staged::default(), &result)?;
    if plan.out.json.is_none() {
        to_stdout(|w| write_json_pretty(w, &result))?;
    }
    Ok(())
}
