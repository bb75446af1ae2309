//! `t2spline run JOB.json [-o OUT.json] [--alpha A] [--samples N] [--csv DIR]`.

use std::path::PathBuf;

use t2spline::Alpha;
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
        Ok(Plan {
            alpha,
            samples: samples.unwrap_or(job.samples),
            job,
            output: args.output,
            csv: args.csv,
        })
    }
}

pub fn run(args: RunArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let result = RunResult::compute(&plan.job, plan.alpha, plan.samples);
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
