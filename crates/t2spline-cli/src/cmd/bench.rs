//! `t2spline bench [--case crisp|fuzzy|sweep|all] [--points N] [--threads T] [--curve JOB.json] [--reuse]`.

use std::io::Write;

use t2spline_io::bench::{default_curve, run_case, BenchCase};
use t2spline_io::{Error, JobCurve};

use crate::cli::BenchArgs;
use crate::output::read_job;

/// A benchmark with every input validated.
struct Plan {
    cases: Vec<BenchCase>,
    points: usize,
    threads: usize,
    curve: JobCurve,
    reuse: bool,
}

impl Plan {
    fn new(args: &BenchArgs) -> anyhow::Result<Plan> {
        let cases = match args.case.as_str() {
            "all" => BenchCase::ALL.to_vec(),
            name => BenchCase::ALL
                .into_iter()
                .filter(|c| c.name() == name)
                .collect(),
        };
        let points = usize::try_from(args.points)
            .ok()
            .filter(|&n| n >= 2)
            .ok_or_else(|| option("--points", format!("{} must be at least 2", args.points)))?;
        let threads = match args.threads {
            Some(t) => usize::try_from(t)
                .ok()
                .filter(|&t| (1..=1024).contains(&t))
                .ok_or_else(|| option("--threads", format!("{t} must be in 1 ..= 1024")))?,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let curve = match &args.curve {
            Some(path) => read_job(path)?.curve,
            None => JobCurve::Planar(default_curve()),
        };
        Ok(Plan {
            cases,
            points,
            threads,
            curve,
            reuse: args.reuse,
        })
    }
}

fn option(option: &'static str, message: String) -> Error {
    Error::Option { option, message }
}

pub fn bench(args: &BenchArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let mut out = std::io::stdout().lock();
    for case in plan.cases {
        let result = run_case(&plan.curve, case, plan.points, plan.threads, plan.reuse)?;
        // One line per case as soon as it is measured.
        writeln!(out, "{result}")?;
        out.flush()?;
    }
    Ok(())
}
