//! `t2spline bench [--case crisp|fuzzy|sweep|all] [--points N] [--threads T] [--curve JOB.json] [--reuse]`.

use std::io::Write;

use t2spline::bench::{run_case, BenchCase};
use t2spline::job::Model;
use t2spline::sampling::benchmark_curve;

use super::settings::about_option;
use crate::cli::BenchArgs;
use crate::output::read_job;

pub fn bench(args: &BenchArgs) -> anyhow::Result<()> {
    let cases = match args.case.as_str() {
        "all" => BenchCase::ALL.to_vec(),
        name => BenchCase::ALL
            .into_iter()
            .filter(|c| c.name() == name)
            .collect(),
    };
    let threads = match args.threads {
        // Out of range values are refused by the core with the rule.
        Some(t) => usize::try_from(t).unwrap_or(usize::MAX),
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let model = match &args.curve {
        Some(path) => read_job(path)?.model,
        None => Model::Planar(benchmark_curve()),
    };
    // Every case's points are checked before the first is timed.
    for &case in &cases {
        t2spline::bench::check_points(args.points, case, model.dimension())
            .map_err(about_option)?;
    }
    let mut out = std::io::stdout().lock();
    for case in cases {
        let result =
            run_case(&model, case, args.points, threads, args.reuse).map_err(about_option)?;
        // One line per case as soon as it is measured.
        writeln!(out, "{result}")?;
        out.flush()?;
    }
    Ok(())
}
