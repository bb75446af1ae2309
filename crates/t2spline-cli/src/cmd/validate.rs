//! `t2spline validate JOB.json`: report every problem, or a one-line summary.

use crate::cli::ValidateArgs;
use crate::output::{job_name, read_job, to_stdout};
use t2spline_io::JobCurve;

pub fn validate(args: &ValidateArgs) -> anyhow::Result<()> {
    let job = read_job(&args.job)?;
    let (points, order) = match &job.curve {
        JobCurve::Planar(c) => (c.points().len(), c.order()),
        JobCurve::Spatial(c) => (c.points().len(), c.order()),
    };
    let alpha = job
        .alpha
        .map_or("not set".to_owned(), |a| a.get().to_string());
    let line = format!(
        "{}: ok: {}-D, {points} points, order {order}, alpha {alpha}, {} samples\n",
        job_name(&args.job),
        job.curve.dimension(),
        job.samples,
    );
    Ok(to_stdout(|w| w.write_all(line.as_bytes()))?)
}
