//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--type-reduction NAME]
//! [--samples N] [--csv DIR] [--parquet FILE] [--derivatives K]`; with
//! several jobs, `cmd/batch.rs`.

use std::path::{Path, PathBuf};

use t2spline::job::{Job, Overrides, RunOutput, Settings};
use t2spline_io::{
    check_finite, stage_csv, write_json_pretty, write_parquet, Error, Staged, CSV_FILES,
    DERIVATIVES_CSV,
};

use super::settings::{note_unused_alpha, settings};
use crate::cli::RunArgs;
use crate::output::{is_stdio, read_job_text, to_stdout, Inputs, NewFolders};

/// Where the files of one result go.
#[derive(Debug, Default)]
pub struct Destinations {
    /// The result file (`None`: standard output, or none in a run of many).
    pub json: Option<PathBuf>,
    /// The folder of the CSV files.
    pub csv: Option<PathBuf>,
    /// The Parquet file.
    pub parquet: Option<PathBuf>,
}

impl Destinations {
    /// An error if a file written to these destinations would overwrite
    /// one of `inputs`.
    pub fn check(&self, inputs: &Inputs) -> anyhow::Result<()> {
        if let Some(p) = &self.json {
            inputs.check("--output", p)?;
        }
        if let Some(p) = &self.parquet {
            inputs.check("--parquet", p)?;
        }
        if let Some(dir) = &self.csv {
            for name in CSV_FILES.iter().map(|f| f.0).chain([DERIVATIVES_CSV]) {
                inputs.check("--csv", &dir.join(name))?;
            }
        }
        Ok(())
    }

    /// Stages every file of `result` (the CSV folder created, and recorded
    /// in `folders`); the caller commits.
    pub fn stage<'a>(
        &self,
        staged: &mut Staged<'a>,
        folders: &mut NewFolders,
        result: &'a RunOutput,
    ) -> Result<(), Error> {
        if let Some(dir) = &self.csv {
            folders.create(dir)?;
            stage_csv(staged, dir, result)?;
        }
        if let Some(path) = &self.parquet {
            staged.add(path, |w| write_parquet(w, result))?;
        }
        if let Some(path) = &self.json {
            staged.add(path, |w| write_json_pretty(w, result))?;
        }
        Ok(())
    }

    /// Writes every file of `result`, all or nothing: each complete in a
    /// temporary file before any is renamed; folders made for the CSV files
    /// are removed again on failure.
    pub fn write<'a>(&self, mut staged: Staged<'a>, result: &'a RunOutput) -> Result<(), Error> {
        let mut folders = NewFolders::default();
        let files = self
            .stage(&mut staged, &mut folders, result)
            .and_then(|()| staged.commit());
        if files.is_err() {
            folders.remove();
        }
        files
    }
}

/// What an alpha does in a run whose type reduction does not use it.
pub const ALPHA_IGNORED: &str = "is ignored (stage 2 is cut at alpha = 0, the whole footprint)";

/// The settings of a run from the options.
pub fn overrides(args: &RunArgs) -> Overrides {
    Overrides {
        alpha: args.alpha,
        type_reduction: args.reduction.type_reduction,
        samples: args.samples.clone(),
        derivatives: args.derivatives,
    }
}

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
