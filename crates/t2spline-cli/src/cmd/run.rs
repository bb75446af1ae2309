//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--type-reduction NAME]
//! [--samples N] [--csv DIR] [--parquet FILE] [--jsonl FILE] [--derivatives K]`; with
//! several jobs, `cmd/batch.rs`.

use std::path::Path;

use t2spline::job::ALPHA_IGNORED;
use t2spline_io::{write_jobs_jsonl, write_json_pretty, Prepared, Staged};

use super::batch::output_name;
use super::prepare::{about_run, note_alpha, prepare};
use super::results::{overrides, Destinations};
use crate::clash::Claims;
use crate::cli::RunArgs;
use crate::output::{is_stdio, to_stdout};

/// A run of one job with every input validated.
struct Plan {
    prepared: Prepared,
    out: Destinations,
    /// The JSON Lines file of the samples (`--jsonl`), and the job's name
    /// in it (as a run of many jobs names it).
    jsonl: Option<(std::path::PathBuf, String)>,
}

impl Plan {
    fn new(args: RunArgs, path: &Path) -> anyhow::Result<Plan> {
        let out = Destinations {
            json: args.output.clone().filter(|p| !is_stdio(p)),
            csv: args.csv.clone(),
            parquet: args.parquet.clone(),
        };
        if let Some(json) = &out.json {
            crate::output::refuse_extension(
                "--output",
                json,
                &["csv", "tsv", "txt", "parquet", "jsonl"],
                "run -o writes the result as JSON: use --csv DIR for CSV files, --parquet FILE.parquet or --jsonl FILE",
            )?;
        }
        let mut claims = Claims::new([path]);
        out.claim(&mut claims)?;
        if let Some(file) = &args.jsonl {
            claims.file("--jsonl", file)?;
        }
        let jsonl = args.jsonl.clone().map(|f| (f, output_name(path)));
        let prepared = prepare(path, &overrides(&args))?;
        note_alpha(
            "run",
            prepared.settings(),
            args.alpha.is_some(),
            ALPHA_IGNORED,
        );
        Ok(Plan {
            prepared,
            out,
            jsonl,
        })
    }
}

pub fn run(mut args: RunArgs) -> anyhow::Result<()> {
    if args.job.len() != 1 || args.jobs.is_some() {
        return super::batch::run(args);
    }
    let path = args.job.remove(0);
    let plan = Plan::new(args, &path)?;
    // Nothing is written unless every number is finite (serde_json would write
    // NaN as null): the run checks it.
    let result = plan.prepared.run().map_err(about_run)?;
    let mut staged = Staged::default();
    if let Some((file, name)) = &plan.jsonl {
        staged.add(file, |w| write_jobs_jsonl(w, &[(name.as_str(), &result)]))?;
    }
    plan.out.write(staged, &result)?;
    if plan.out.json.is_none() {
        to_stdout(|w| write_json_pretty(w, &result))?;
    }
    Ok(())
}
