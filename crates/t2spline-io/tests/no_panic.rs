//! No reader or writer of the I/O crate panics: arbitrary bytes, and text
//! assembled from the formats' own pieces (keys, numbers, delimiters), go to
//! `parse_job`, `parse_data`, `parse_readings` and the readers of nets and
//! rasters under `catch_unwind`, and
//! whatever they accept goes on through every writer (job and data files,
//! CSV, pretty JSON, the four CAD formats).
//!
//! `limits.rs` checks the job reader's answers in depth (the fuzz target's
//! oracle); this file covers the other readers and the writers.

use std::path::Path;

#[path = "../../t2spline/tests/no_panic/returns.rs"]
mod returns;

use proptest::prelude::*;
use returns::returns;
use t2spline::fit::{FitOptions, FuzzifyRule, FuzzyFitMode};
use t2spline::job::Overrides;
use t2spline_io::{
    check_finite, data_json, fuzzify_net, is_readings, job_json, parse_ascii_grid, parse_data,
    parse_grid_csv, parse_job, parse_net_readings, parse_npy, parse_readings, render_cad,
    render_csv, to_json_pretty, CadFormat, CadMeta, NetReadings, RasterGeometry, ReadingsOptions,
};

/// The readings of a net, fuzzified and written as a data file read back.
fn net_on(net: &NetReadings) {
    let options = ReadingsOptions::new(None, None, [Some(1), None], [None, None], None).unwrap();
    if let Ok(data) = returns("fuzzify_net", || fuzzify_net(net, &options)) {
        let json = returns("data_json", || data_json(&data)).to_string();
        returns("parse_data of a net", || parse_data(&json, "d.json")).ok();
    }
}

/// The readers of nets and rasters on `text` (and on its bytes as `.npy`).
fn nets_and_rasters(text: &str) {
    if let Ok(net) = returns("parse_net_readings", || parse_net_readings(text, "n.csv")) {
        net_on(&net);
    }
    let rasters = [
        returns("parse_grid_csv", || parse_grid_csv(text, "g.csv")).ok(),
        returns("parse_ascii_grid", || parse_ascii_grid(text, "g.asc")).ok(),
        returns("parse_npy", || {
            let g = RasterGeometry {
                origin: [0.0, 0.0],
                spacing: [1.0, -1.0],
            };
            parse_npy(text.as_bytes(), "g.npy", &g)
        })
        .ok(),
    ];
    for raster in rasters.into_iter().flatten() {
        for k in [2, 3] {
            if let Ok((net, _)) = returns("blocks", || raster.blocks(k)) {
                net_on(&net);
            }
        }
    }
}

/// Every reader on `text`, and every writer on what they accept.
fn read_and_write(text: &str) {
    returns("is_readings", || is_readings(Path::new("x.csv"), text));
    returns("is_readings", || is_readings(Path::new("x"), text));
    nets_and_rasters(text);
    if let Ok(file) = returns("parse_readings", || parse_readings(text, "r.csv")) {
        let rule = FuzzifyRule::try_new(0.1, 0.5).unwrap();
        match returns("fuzzify", || file.readings.fuzzify(&rule)) {
            Ok(points) => {
                let data = returns("fit_data", || {
                    file.fit_data(points, &rule, "degree", 1, None)
                });
                let json = returns("data_json", || data_json(&data)).to_string();
                returns("parse_data of data_json", || parse_data(&json, "d.json")).ok();
            }
            Err(e) => {
                returns("fuzzify_error", || file.fuzzify_error(&e).lines());
            }
        }
    }
    if let Ok(data) = returns("parse_data", || parse_data(text, "d.json")) {
        returns("data_json", || data_json(&data));
        let options = returns("FitOptions", || FitOptions::interpolation(data.degree));
        let fitted = options.map(|o| returns("fit", || data.points.fit(&o, FuzzyFitMode::Valid)));
        if let Ok(Ok(outcome)) = fitted {
            if let Ok(model) = &outcome.model {
                returns("FitData::job_json", || data.job_json(model, false));
            }
        }
    }
    if let Ok(job) = returns("parse_job", || parse_job(text, "j.json")) {
        let json = returns("job_json", || job_json(&job));
        returns("to_json_pretty", || to_json_pretty(&json));
        let overrides = Overrides {
            alpha: Some(0.5),
            samples: Some(vec![3]),
            derivatives: Some(2),
            ..Overrides::default()
        };
        if let Ok(settings) = job.settings(&overrides).or_else(|_| {
            job.settings(&Overrides {
                derivatives: None,
                ..overrides.clone()
            })
        }) {
            if let Ok(result) = returns("run", || job.run(&settings)) {
                returns("check_finite", || check_finite(&result)).ok();
                returns("render_csv", || render_csv(&result));
            }
            if let Ok(geometry) = returns("geometry", || job.geometry(&settings)) {
                let meta = CadMeta::new(
                    "x".into(),
                    job.description.clone(),
                    "2000-01-01T00:00:00",
                    Default::default(),
                )
                .unwrap();
                for format in CadFormat::ALL {
                    returns("render_cad", || {
                        render_cad(format, &geometry, &meta, "j.json")
                    })
                    .ok();
                    returns("render_cad clamped", || {
                        render_cad(format, &geometry.clamped(), &meta, "j.json")
                    })
                    .ok();
                }
            }
        }
    }
}

/// A number as a file could write it: mostly a small one, sometimes an
/// extreme value or not a number at all.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        24 => (-8.0..8.0f64).prop_map(|x| x.to_string()),
        8 => (-20i32..20).prop_map(|k| k.to_string()),
        1 => prop::sample::select(vec![
            "1e400", "-1e400", "1e-400", "NaN", "inf", "-0", "1e150", "1e300", "18446744073709551616",
            "0.5", "", "\"1\"", "1e", "null",
        ])
        .prop_map(str::to_owned),
    ]
}

/// A whole number, mostly small.
fn whole() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => (0u32..4).prop_map(|k| k.to_string()),
        1 => number(),
    ]
}

/// Readings text: a header, then rows of a few stations with two or more
/// readings each, mostly in order; sometimes with quotes, missing values or
/// other line ends.
fn readings_text() -> impl Strategy<Value = String> {
    (2..4usize, prop::collection::vec((0..3usize, any::<u8>()), 0..12)).prop_flat_map(|(d, stations)| {
        let header = prop_oneof![
            8 => Just(if d == 2 { "station,x,y" } else { "station,x,y,z" }),
            1 => prop::sample::select(vec!["Station;X;Y", "station,x", "x,y,station", "station,x,y,y", ""]),
        ];
        let rows: Vec<_> = stations
            .into_iter()
            .map(|(k, odd)| {
                let station = if odd < 8 { ["\"C,D\"", "\"E", "", "a\u{0}"][usize::from(odd % 4)] } else { ["A", "B", "C"][k] };
                let width = if odd == 9 { d + 1 } else { d };
                prop::collection::vec(number(), width).prop_map(move |v| format!("{station},{}", v.join(",")))
            })
            .collect();
        (header, rows, prop_oneof![8 => Just("\n"), 1 => Just("\r\n"), 1 => Just("\r")], any::<bool>())
    })
    .prop_map(|(h, mut rows, end, sorted)| {
        if sorted {
            rows.sort();
        }
        let delimited = format!("{h}{end}{}", rows.join(end));
        if h.contains(';') { delimited.replace(',', ";") } else { delimited }
    })
}

/// The readings of a net or a raster as text: a header (`row,col,x,y,z`,
/// `x,y,z` or an ESRI grid's) and rows of numbers, whole numbers first.
fn net_text() -> impl Strategy<Value = String> {
    let header = prop::sample::select(vec![
        "row,col,x,y,z",
        "x,y,z",
        "ncols 2\nnrows 3\nxllcorner 0\nyllcenter 1\ncellsize 0.5\nnodata_value -1",
        "ncols 4 nrows 4 xllcenter 0 yllcorner 1 cellsize 2",
    ]);
    let row = (whole(), whole(), prop::collection::vec(number(), 1..4))
        .prop_map(|(i, j, v)| format!("{i},{j},{}", v.join(",")));
    (header, prop::collection::vec(row, 0..40), any::<bool>()).prop_map(|(h, rows, spaces)| {
        let body = rows.join("\n");
        let body = if spaces { body.replace(',', " ") } else { body };
        format!("{h}\n{body}\n")
    })
}

/// A fuzzy number in a job file, in order mostly.
fn fuzzy_number() -> impl Strategy<Value = String> {
    prop_oneof![
        40 => (-8.0..8.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64).prop_map(|(c, a, b, l)| {
            format!(
                r#"{{"crisp": {c}, "upper": [{}, {}], "primary": [{}, {}], "lower": [{}, {}]}}"#,
                c - a - b - l, c + a + b + l, c - b - l, c + b + l, c - l, c + l
            )
        }),
        1 => (number(), number(), number(), number(), number(), number(), number()).prop_map(
            |(c, a, b, p, q, l, r)| {
                format!(r#"{{"crisp": {c}, "upper": [{a}, {b}], "primary": [{p}, {q}], "lower": [{l}, {r}]}}"#)
            },
        ),
    ]
}

/// A job or data file: the format's keys with mostly valid values, points as
/// a list (a curve) or as rows (a surface).
fn job_text() -> impl Strategy<Value = String> {
    let point = |d: usize| {
        prop::collection::vec(fuzzy_number(), d).prop_map(|coords: Vec<String>| {
            let body: Vec<String> = coords
                .iter()
                .zip(["x", "y", "z"])
                .map(|(c, k)| format!(r#""{k}": {c}"#))
                .collect();
            format!("{{{}}}", body.join(", "))
        })
    };
    // A curve's points and degree, or a surface's rows and degree pair.
    let points = prop_oneof![
        3 => (prop::collection::vec(point(2), 2..7), whole()).prop_map(|(p, d)| (format!("[{}]", p.join(", ")), d)),
        2 => (prop::collection::vec(point(3), 2..7), whole()).prop_map(|(p, d)| (format!("[{}]", p.join(", ")), d)),
        1 => (prop::collection::vec(prop::collection::vec(point(3), 3), 2..4), whole(), whole()).prop_map(
            |(rows, u, v): (Vec<Vec<String>>, String, String)| {
                let rows: Vec<String> = rows.iter().map(|r| format!("[{}]", r.join(", "))).collect();
                (format!("[{}]", rows.join(", ")), format!("[{u}, {v}]"))
            },
        ),
    ];
    let optional = |key: &'static str, p: f64, value: BoxedStrategy<String>| {
        prop::option::weighted(p, value)
            .prop_map(move |v| v.map(|v| format!(r#""{key}": {v}, "#)).unwrap_or_default())
    };
    let list = |len| {
        prop::collection::vec(number(), len)
            .prop_map(|v| format!("[{}]", v.join(", ")))
            .boxed()
    };
    let height = prop_oneof![8 => (0.05..1.0f64).prop_map(|h| h.to_string()), 1 => number()];
    (
        points,
        prop::sample::select(vec!["degree", "order"]),
        optional("alpha", 0.5, (0.0..1.0f64).prop_map(|a| a.to_string()).boxed()),
        height.prop_map(|h| format!(r#""lower_height": {h}, "#)),
        optional("knots", 0.1, list(0..10)),
        optional("weights", 0.1, list(0..7)),
        optional("samples", 0.3, whole().boxed()),
    )
        .prop_map(|((points, degree), key, alpha, h, knots, weights, samples)| {
            format!(r#"{{"{key}": {degree}, {alpha}{h}{knots}{weights}{samples}"points": {points}}}"#)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        read_and_write(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn readings_files_never_panic(text in readings_text()) {
        read_and_write(&text);
    }

    #[test]
    fn nets_and_rasters_never_panic(text in net_text()) {
        read_and_write(&text);
    }

    #[test]
    fn job_and_data_files_never_panic(text in job_text()) {
        read_and_write(&text);
    }
}
