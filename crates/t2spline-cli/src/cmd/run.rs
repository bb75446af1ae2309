//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--samples N] [--csv DIR]
//! [--derivatives K]`.

use std::path::PathBuf;

use t2spline::Alpha;
use t2spline_io::derivatives::check_derivative_order;
use t2spline_io::job::check_samples;
use t2spline_io::{check_finite, stage_csv, write_json_pretty, Error, Job, RunResult, Staged};

use crate::cli::RunArgs;
use crate::output::{is_stdio, read_job_text, to_stdout, NewFolders};

/// A run with every input validated.
struct Plan {
    job: Job,
    alpha: Alpha,
    samples: usize,
    /// `None`: standard output.
    output: Option<PathBuf>,
    csv: Option<PathBuf>,
    /// The highest derivative order asked for, if any.
    derivatives: Option<usize>,
}

impl Plan {
    fn new(args: RunArgs) -> Result<Plan, Error> {
        let alpha = super::alpha::parse_option(args.alpha)?;
        let samples = args
            .samples
            .map(|n| {
                check_samples(n).map_err(|message| Error::Option {
                    option: "--samples",
                    message,
                })
            })
            .transpose()?;
        let (job, text) = read_job_text(&args.job)?;
        let alpha = super::alpha::required(alpha, &job, &args.job, &text)?;
        let samples = samples.unwrap_or(job.samples);
        let derivatives = args
            .derivatives
            .map(|k| {
                check_derivative_order(k, samples).map_err(|message| Error::Option {
                    option: "--derivatives",
                    message,
                })
            })
            .transpose()?;
        Ok(Plan {
            alpha,
            samples,
            job,
            output: args.output.filter(|p| !is_stdio(p)),
            csv: args.csv,
            derivatives,
        })
    }
}

pub fn run(args: RunArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let mut result = RunResult::compute(&plan.job, plan.alpha, plan.samples);
    if let Some(order) = plan.derivatives {
        result.add_derivatives(&plan.job, order);
        // A derivative grows like (coordinate / knot span)^order: narrow spans
        // or large coordinates can take it past the largest float. That is
        // the input's doing, not a bug, so it is an error about the option.
        let checks = [
            (
                "curves.derivatives",
                check_finite(&result.curves.derivatives),
            ),
            ("curves.arc_length", check_finite(&result.curves.arc_length)),
        ];
        for (name, check) in checks {
            if let Err(Error::NotFinite { key, value }) = check {
                return Err(Error::Option {
                    option: "--derivatives",
                    message: format!(
                        "{name}.{key} = {value} is beyond the range of a 64-bit float (about 1.8e308): the knot spans are too narrow or the coordinates too large for derivatives of order {order}"
                    ),
                }
                .into());
            }
        }
    }
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
