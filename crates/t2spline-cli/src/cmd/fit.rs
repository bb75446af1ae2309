//! `t2spline fit DATA.json [-o JOB.json] [--parametrization M] [--control-points M]
//! [--closed] [--fuzzy-fit valid|independent] [--alpha A] [-q]`; a readings file (CSV) is
//! fuzzified first with `fuzzify`'s options.

use std::path::PathBuf;

use anyhow::anyhow;
use t2spline::fit::{
    Deviation, FitOptions, FitSummary, FuzzyData, FuzzyFitMode, Parametrization, SurfaceFitOptions,
};
use t2spline::{Alpha, Error, Layer};
use t2spline_io::{is_readings, parse_data, parse_job, printable, to_json_pretty, FitData};

use super::prepare::{about_option, OptionError};
use crate::clash::Claims;
use crate::cli::FitArgs;
use crate::output::{job_name, read_input, shown, Outputs};

/// Condition numbers above this get a warning: the control points may then
/// be wrong in their last eight digits or more.
const WARN_CONDITION: f64 = 1e8;

/// A fit with every input validated.
struct Plan {
    data: FitData,
    options: FitOptions,
    /// For a net of data points: the options of both directions.
    surface: Option<SurfaceFitOptions>,
    mode: FuzzyFitMode,
    output: Option<PathBuf>,
    quiet: bool,
    /// For a readings file: how its readings were fuzzified, for the report.
    fuzzified: Option<String>,
}

impl Plan {
    fn new(args: FitArgs) -> anyhow::Result<Plan> {
        // clap has checked the names; the parsers agree with its lists.
        let parametrization: Parametrization = args
            .parametrization
            .parse()
            .map_err(|e: String| anyhow!(e))?;
        let mode: FuzzyFitMode = args.fuzzy_fit.parse().map_err(|e: String| anyhow!(e))?;
        if let Some(output) = &args.output {
            Claims::new([args.data.as_path()]).file("--output", output)?;
        }
        let text = read_input(&args.data)?;
        let (data, fuzzified) = if is_readings(&args.data, &text) {
            let data =
                super::fuzzify::readings_data(&args.data, &text, &args.readings, args.alpha)?;
            let note = format!(
                "{}: a readings file (CSV), fuzzified first as `t2spline fuzzify` does: {}",
                printable(&data.source),
                printable(data.description.as_deref().unwrap_or_default())
            );
            (data, Some(note))
        } else {
            let given = [
                ("--tolerance", args.readings.tolerance.is_some()),
                ("--lower-height", args.readings.lower_height.is_some()),
                ("--degree", args.readings.degree.is_some()),
                ("--order", args.readings.order.is_some()),
            ];
            if let Some((option, _)) = given.iter().find(|(_, g)| *g) {
                return Err(OptionError {
                    option,
                    message: format!(
                        "only for a readings file (CSV); {} is a data file, whose numbers and degree are its own",
                        shown(&args.data)
                    ),
                }
                .into());
            }
            let mut data = parse_data(&text, &job_name(&args.data))?;
            if let Some(a) = args.alpha {
                data.alpha = Some(Alpha::try_new(a).map_err(|e| OptionError {
                    option: "--alpha",
                    message: e.to_string(),
                })?);
            }
            (data, None)
        };
        if args.closed {
            if let FuzzyData::Net(_) = data.points {
                return Err(OptionError {
                    option: "--closed",
                    message: format!(
                        "only for the data points of a curve, taken as a loop; {} holds a net of data points (a surface), which is not fitted closed",
                        printable(&data.source)
                    ),
                }
                .into());
            }
            let distinct = data.points.loop_len();
            if distinct <= data.degree {
                return Err(data
                    .fit_error(&Error::TooFewClosedDataPoints {
                        degree: data.degree,
                        count: distinct,
                        repeated: distinct < data.len(),
                    })
                    .into());
            }
        }
        let counts = args
            .control_points
            .as_deref()
            .map(control_point_counts)
            .transpose()?;
        let (control_points, surface) = match &data.points {
            FuzzyData::Net(rows) => {
                let shape = [rows.len(), rows.first().map_or(0, Vec::len)];
                let degree = [data.degree, data.degree_v.unwrap_or(data.degree)];
                let counts = counts.map(|c| match c[..] {
                    [m, n] => [m, n],
                    _ => [c[0]; 2],
                });
                if let Some(counts) = counts {
                    for (d, (direction, lines)) in
                        [("u", "rows"), ("v", "columns")].iter().enumerate()
                    {
                        check_count(
                            counts[d],
                            degree[d],
                            shape[d],
                            &format!(" in {direction}"),
                            &format!("{lines} of the net of {}", printable(&data.source)),
                        )?;
                    }
                }
                let surface = SurfaceFitOptions::new(degree, counts)
                    .map_err(about_option)?
                    .with_parametrization(parametrization);
                (counts.map(|[m, _]| m), Some(surface))
            }
            _ => {
                let m = match counts.as_deref() {
                    None => None,
                    Some([m]) => Some(*m),
                    Some(_) => {
                        return Err(OptionError {
                            option: "--control-points",
                            message: format!(
                                "a pair M,N is for a net of data points (a surface); {} holds the data of a curve: give one count",
                                printable(&data.source)
                            ),
                        }
                        .into())
                    }
                };
                if let Some(m) = m {
                    let (max, what) = if args.closed {
                        (
                            data.points.loop_len(),
                            "distinct data points around the loop of",
                        )
                    } else {
                        (data.len(), "data points of")
                    };
                    check_count(
                        m,
                        data.degree,
                        max,
                        "",
                        &format!("{what} {}", printable(&data.source)),
                    )?;
                }
                (m, None)
            }
        };
        let options = FitOptions::new(data.degree, control_points)
            .map_err(about_option)?
            .with_parametrization(parametrization);
        let options = if args.closed {
            options.closed()
        } else {
            options
        };
        Ok(Plan {
            options,
            surface,
            data,
            mode,
            output: args.output,
            quiet: args.quiet,
            fuzzified,
        })
    }
}

pub fn fit(args: FitArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let outcome = match &plan.surface {
        Some(options) => plan.data.points.fit_net(options, plan.mode),
        None => plan.data.points.fit(&plan.options, plan.mode),
    }
    .map_err(|e| plan.data.fit_error(&e))?;
    if !plan.quiet {
        for line in report(&plan, &outcome.summary) {
            crate::output::note("fit", line);
        }
    }
    let job = match outcome.model {
        Ok(model) => plan.data.job_json(&model, plan.options.is_closed()),
        Err(violations) => {
            return Err(plan
                .data
                .order_error(
                    &violations,
                    "no job written: these control points are not valid fuzzy numbers; `--fuzzy-fit valid` (the default) fits the spreads so that they are",
                )
                .into());
        }
    };
    let text = to_json_pretty(&job);
    // The last guard: what is written must be a valid job file.
    let name = plan
        .output
        .as_deref()
        .map_or("<stdout>".to_owned(), job_name);
    parse_job(&text, &name)
        .map_err(|e| anyhow!("internal error: the fitted job does not validate:\n{e}"))?;
    let mut out = Outputs::default();
    out.to(plan.output.as_deref(), text.into_bytes());
    out.commit()
}

/// The lines of the report on standard error.
fn report(plan: &Plan, s: &FitSummary) -> Vec<String> {
    // A closed fit with as many control points as distinct data points
    // interpolates them: its knots are those of interpolation.
    let interpolates = match s.closed {
        Some(l) => s.control_points == l.data,
        None => plan.options.control_points().is_none(),
    };
    let method = match (interpolates, s.closed) {
        (true, None) => "interpolation",
        (false, None) => "least squares, end points interpolated",
        (true, Some(_)) => "periodic interpolation",
        (false, Some(_)) => "periodic least squares",
    };
    let mut lines: Vec<String> = plan.fuzzified.iter().cloned().collect();
    match (&plan.surface, s.net, s.closed) {
        (Some(o), Some(net), _) => lines.push(format!(
            "{}: a net of {} × {} data points, degree {} × {}, {} parameters averaged over rows and columns: {method}, {} × {} control points, condition number {:.1e} (the larger of u and v)",
            printable(&plan.data.source),
            net.data[0],
            net.data[1],
            o.degree()[0],
            o.degree()[1],
            o.parametrization(),
            net.control[0],
            net.control[1],
            s.condition,
        )),
        (_, _, Some(l)) => {
            let repeat = if l.repeated_last {
                " (the last repeats the first and is taken as it)"
            } else {
                ""
            };
            lines.push(format!(
                "{}: a closed loop of {} data points{repeat}, degree {}, {} parameters with the closing chord: {method}, periodic knots, {} control points and the first {} again at the end, condition number {:.1e}",
                printable(&plan.data.source),
                l.data,
                plan.options.degree(),
                plan.options.parametrization(),
                s.control_points,
                l.wrap,
                s.condition,
            ));
        }
        _ => lines.push(format!(
            "{}: {} data points, degree {}, {} parameters: {method}, {} control points, condition number {:.1e}",
            printable(&plan.data.source),
            s.data_points,
            plan.options.degree(),
            plan.options.parametrization(),
            s.control_points,
            s.condition,
        )),
    }
    if s.condition > WARN_CONDITION {
        lines.push(format!(
            "warning: the system is ill-conditioned: the control points may be wrong in their last {:.0} digits; fewer control points give a better-posed fit",
            s.condition.log10()
        ));
    }
    for (axis, h) in &s.mixed_heights {
        lines.push(format!(
            "{axis}: the data mix lower heights; the control points get the smallest, {}",
            h.get()
        ));
    }
    match (plan.mode, s.independent_violations.first()) {
        (_, None) => lines.push(
            "each layer fitted on its own gives valid fuzzy control points".to_owned(),
        ),
        (FuzzyFitMode::Valid, Some(first)) => lines.push(format!(
            "each layer fitted on its own would break the order of the seven values at {} place(s) (first: {first}); the spreads were fitted as nested non-negative increments instead",
            s.independent_violations.len()
        )),
        (FuzzyFitMode::Independent, Some(_)) => {}
    }
    lines.push(
        "largest deviation from the data at the data parameters, of each layer and of its spread (layer - crisp):"
            .to_owned(),
    );
    let at = |d: &Deviation| match (d.max > 0.0, s.net) {
        (false, _) => "-".to_owned(),
        (true, Some(net)) => {
            let columns = net.data[1].max(1);
            format!(
                "points[{}][{}].{}",
                d.point / columns,
                d.point % columns,
                d.axis
            )
        }
        (true, None) => format!("points[{}].{}", d.point, d.axis),
    };
    // The location column is as wide as its longest entry.
    let width = s
        .deviations
        .iter()
        .map(|(_, d)| at(d).len())
        .max()
        .unwrap_or(0)
        + 2;
    for (layer, d) in s.deviations.iter() {
        let spread = &s.spread_deviations[layer];
        let line = if layer == Layer::Crisp {
            let note = if interpolates {
                "interpolated"
            } else {
                "least squares"
            };
            format!(
                "  {:<14}{:>10.3e}  {:<width$}({note})",
                layer.name(),
                d.max,
                at(d)
            )
        } else {
            format!(
                "  {:<14}{:>10.3e}  {:<width$}spread {:>9.3e}  {}",
                layer.name(),
                d.max,
                at(d),
                spread.max,
                at(spread)
            )
        };
        lines.push(line);
    }
    lines
}

/// `--control-points` of `m` (in a direction, `place`) for a fit of degree
/// `degree` to `data` points (`what` says of what): at least degree + 1, at
/// most the data.
fn check_count(
    m: usize,
    degree: usize,
    data: usize,
    place: &str,
    what: &str,
) -> Result<(), OptionError> {
    let (min, max) = (degree + 1, data);
    if m < min || m > max {
        return Err(OptionError {
            option: "--control-points",
            message: format!(
                "{m}{place} is outside [{min}, {max}]: at least degree + 1, at most the {max} {what}"
            ),
        });
    }
    Ok(())
}

/// The counts of `--control-points`: `M` or `M,N`, each a whole number.
fn control_point_counts(text: &str) -> Result<Vec<usize>, OptionError> {
    let counts: Option<Vec<usize>> = text.split(',').map(|c| c.trim().parse().ok()).collect();
    match counts {
        Some(c) if (1..=2).contains(&c.len()) => Ok(c),
        _ => Err(OptionError {
            option: "--control-points",
            message: format!(
                "`{}` is not a count M or a pair M,N of whole numbers",
                printable(text)
            ),
        }),
    }
}
