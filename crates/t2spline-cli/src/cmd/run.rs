//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--samples N] [--csv DIR]
//! [--derivatives K]`.

use std::path::PathBuf;

use t2spline::Alpha;
use t2spline_io::derivatives::check_derivative_order;
use t2spline_io::job::check_samples;
use t2spline_io::{render_csv, to_json_pretty, Error, Job, RunResult};

use crate::cli::RunArgs;
use crate::output::{read_job, Outputs};

/// A run with every input validated.
struct Plan {
    job: Job,
    alpha: Alpha,
    samples: usize,
    output: Option<PathBuf>,
    csv: Option<PathBuf>,
    /// The highest derivative order asked for, if any.
    derivatives: Option<usize>,
}

impl Plan {
    fn new(args: RunArgs) -> anyhow::Result<Plan> {
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
        let job = read_job(&args.job)?;
        let alpha = super::alpha::required(alpha, &job, &args.job)?;
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
            output: args.output,
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
    }
    let json = to_json_pretty(&serde_json::to_value(&result)?);
    // Everything is computed before anything is written.
    let mut out = Outputs::default();
    if let Some(dir) = &plan.csv {
        for (name, text) in render_csv(&result) {
            out.in_dir(dir, name, text.into_bytes());
        }
    }
    out.to(plan.output.as_deref(), json.into_bytes());
    out.commit()
}
