//! `t2spline validate JOB.json`: report every problem, or a one-line summary.

use t2spline::job::UnusedBy;
use t2spline_io::printable;

use crate::cli::ValidateArgs;
use crate::output::{job_name, read_job, to_stdout};

pub fn validate(args: &ValidateArgs) -> anyhow::Result<()> {
    let job = read_job(&args.job)?;
    let alpha = match job.alpha {
        None => "not set".to_owned(),
        Some(a) if job.type_reduction.uses_alpha() => a.get().to_string(),
        // The note of the commands that run the job (`unused_alpha`).
        Some(a) => format!("{} (unused: {})", a.get(), UnusedBy(job.type_reduction)),
    };
    let line = format!(
        "{}: ok: {}, alpha {alpha}, {} samples\n",
        printable(&job_name(&args.job)),
        job.model.summary(),
        job.samples,
    );
    Ok(to_stdout(|w| w.write_all(line.as_bytes()))?)
}
