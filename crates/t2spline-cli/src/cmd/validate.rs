//! `t2spline validate JOB.json`: report every problem, or a one-line summary.

use crate::cli::ValidateArgs;
use crate::output::{job_name, read_job, to_stdout};

pub fn validate(args: &ValidateArgs) -> anyhow::Result<()> {
    let job = read_job(&args.job)?;
    let alpha = job
        .alpha
        .map_or("not set".to_owned(), |a| a.get().to_string());
    let line = format!(
        "{}: ok: {}, alpha {alpha}, {} samples\n",
        job_name(&args.job),
        job.model.summary(),
        job.samples,
    );
    Ok(to_stdout(|w| w.write_all(line.as_bytes()))?)
}
