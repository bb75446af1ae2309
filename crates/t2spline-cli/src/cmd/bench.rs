//! `t2spline bench [--case crisp|fuzzy|sweep|surface|surface-fuzzy|all] [--points N]
//! [--threads T] [--curve JOB.json] [--reuse | --compare]`.

mod harness;

use std::io::Write;

use t2spline::job::Model;
use t2spline::sampling::{benchmark_curve, benchmark_surface};

use super::prepare::about_option;
use crate::cli::BenchArgs;
use crate::output::read_job;
use harness::{run_case, BenchCase};

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
    // A job's model, or the built-in curve and surface; with `all`, a job
    // runs only the cases of its kind.
    let job = args.curve.as_deref().map(read_job).transpose()?;
    let (curve, surface) = (
        Model::Planar(benchmark_curve()),
        Model::Surface(benchmark_surface()),
    );
    let plan: Vec<(BenchCase, &Model)> = cases
        .into_iter()
        .filter_map(|case| match &job {
            Some(job) if args.case == "all" && case.is_surface() != job.model.is_surface() => None,
            Some(job) => Some((case, &job.model)),
            None if case.is_surface() => Some((case, &surface)),
            None => Some((case, &curve)),
        })
        .collect();
    // Every case's points are checked before the first is timed.
    for &(case, model) in &plan {
        harness::check_points(args.points, case, model.dimension()).map_err(about_option)?;
    }
    let mut out = std::io::stdout().lock();
    let modes: &[bool] = if args.compare {
        &[false, true]
    } else {
        std::slice::from_ref(&args.reuse)
    };
    for (case, model) in plan {
        let mut seconds = Vec::with_capacity(modes.len());
        for &reuse in modes {
            let result =
                run_case(model, case, args.points, threads, reuse).map_err(about_option)?;
            // One line per case as soon as it is measured.
            writeln!(out, "{result}")?;
            out.flush()?;
            seconds.push(result.seconds);
        }
        if let [fresh, reused] = seconds[..] {
            writeln!(out, "ratio {case} fresh/reused={:.3}", fresh / reused)?;
            out.flush()?;
        }
    }
    Ok(())
}
