//! The two surface examples, read from `examples/` and run through
//! `Job::run`, against closed forms written here from docs/method.md §2–§4 (not from
//! the library): the quarter cylinder of fuzzy radius stays a cylinder at
//! every stage, of the radius the stages' factors predict; the terrain's
//! solution lies below the crisp surface, furthest at the corner farthest
//! from the benchmark.

use std::path::Path;

use serde_json::Value;
use t2spline::job::{Job, Overrides, Parameter, Parameters, RunOutput, Spline};
use t2spline::Layer;

fn example(name: &str) -> (Job, Value) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    let job = t2spline_io::read_job(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    (job, serde_json::from_str(&text).unwrap())
}

fn run(job: &Job, alpha: f64, samples: [u64; 2]) -> RunOutput {
    let overrides = Overrides {
        alpha: Some(alpha),
        samples: Some(samples.to_vec()),
        ..Overrides::default()
    };
    job.run(&job.settings(&overrides).unwrap()).unwrap()
}

/// The value of the number `n` (a job file's number) at one end of every
/// stage, by docs/method.md §2–§4 directly: the alpha-cut feet `cut(e) = e + s·(crisp −
/// e)` (`s = α` for upper and primary, `α/h` for lower, absent above h), the
/// type-reduced ends (means of the cut feet of each side), and the
/// defuzzified value (their centroid with the crisp value).
struct Stages {
    /// `[upper.left, primary.left, lower.left, crisp, lower.right,
    /// primary.right, upper.right]` after the cut (`None`: no lower cut).
    cut: [Option<f64>; 7],
    left: f64,
    right: f64,
    defuzzified: f64,
}

fn stages(n: &Value, h: f64, alpha: f64) -> Stages {
    let get = |key: &str, side: usize| n[key][side].as_f64().expect("a number");
    let c = n["crisp"].as_f64().expect("a number");
    let cut = |e: f64, s: f64| e + s * (c - e);
    let lower = |side| (alpha <= h).then(|| cut(get("lower", side), alpha / h));
    let cuts = [
        Some(cut(get("upper", 0), alpha)),
        Some(cut(get("primary", 0), alpha)),
        lower(0),
        Some(c),
        lower(1),
        Some(cut(get("primary", 1), alpha)),
        Some(cut(get("upper", 1), alpha)),
    ];
    let mean = |xs: &[Option<f64>]| {
        let xs: Vec<f64> = xs.iter().flatten().copied().collect();
        xs.iter().sum::<f64>() / xs.len() as f64
    };
    let (left, right) = (mean(&cuts[..3]), mean(&cuts[4..]));
    Stages {
        cut: cuts,
        left,
        right,
        defuzzified: (left + c + right) / 3.0,
    }
}

/// The grid parameters of a surface result.
fn grid(out: &RunOutput) -> (&[f64], &[f64]) {
    match &out.samples.params {
        Parameters::Grid { u, v } => (u, v),
        Parameters::Along(_) => panic!("a surface result has a grid"),
    }
}

// ---------------------------------------------------------------------------
// The quarter cylinder of fuzzy radius
// ---------------------------------------------------------------------------

/// The spreads of the example's radius, as fractions of the coordinate:
/// the number `1` scaled by each control value.
fn unit_number() -> Value {
    serde_json::json!({"crisp": 1.0, "upper": [0.94, 1.09], "primary": [0.96, 1.06], "lower": [0.98, 1.03]})
}

/// The example's x and y numbers are `c` times the unit number, z is crisp,
/// and the net is the rational quadratic quarter circle in u (weights 1,
/// √2/2, 1) times a line in v: the premises of the closed form below.
#[test]
fn the_cylinder_example_is_the_quarter_cylinder_with_proportional_spreads() {
    let (job, file) = example("fuzzy-cylinder.json");
    let t2spline::job::Model::Surface(s) = &job.model else {
        panic!("a surface job")
    };
    assert_eq!((s.degree(), s.shape()), ([2, 1], [3, 2]));
    let w = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(s.weights(), &[1.0, 1.0, w, w, 1.0, 1.0]);
    let unit = unit_number();
    for row in file["points"].as_array().unwrap() {
        for p in row.as_array().unwrap() {
            for axis in ["x", "y"] {
                let c = p[axis]["crisp"].as_f64().unwrap();
                for key in ["upper", "primary", "lower"] {
                    for side in 0..2 {
                        let given = p[axis][key][side].as_f64().unwrap();
                        let want = c * unit[key][side].as_f64().unwrap();
                        assert!(
                            (given - want).abs() <= 1e-15 * c,
                            "{axis} {key}: {given} vs {want}"
                        );
                    }
                }
            }
            let z = &p["z"];
            let c = z["crisp"].as_f64().unwrap();
            assert!(["upper", "primary", "lower"]
                .iter()
                .all(|k| z[k] == serde_json::json!([c, c])));
        }
    }
}

/// Every control value `c` of x and y is `c` times the unit number, and every
/// stage of docs/method.md §2–§4 is linear in the number's values with coefficients
/// that do not depend on them (one height): each stage maps `c` to `c·f`,
/// with `f` the stage's value of the unit number. A rational surface is
/// linear in its control points, so each stage's surface is the crisp
/// cylinder scaled about the z axis by `f`: of radius `f·r`, with `z`
/// unchanged. In particular the defuzzified surface has radius `κ·r`,
///
/// ```text
/// κ = (1 − λ + 1 + 1 + ρ)/3 = 1 + (ρ − λ)/3,
/// 1 − λ = (cut(0.94, α) + cut(0.96, α) + cut(0.98, α/h))/3  (α ≤ h; two terms above),
/// 1 + ρ = (cut(1.03, α/h) + cut(1.06, α) + cut(1.09, α))/3,  cut(e, s) = e + s(1 − e),
/// ```
/// and its distance to the crisp surface is `|κ − 1|·r` at every `(u, v)`,
/// so `max = rms = |κ − 1|·r`.
#[test]
fn the_fuzzy_cylinder_is_a_cylinder_of_the_predicted_radius_at_every_stage() {
    let (job, _) = example("fuzzy-cylinder.json");
    let (r, height, h) = (2.5, 3.0, 0.6);
    let unit = unit_number();
    // The figures the example's description quotes, at its alpha 0.5.
    let at_half = stages(&unit, h, 0.5);
    assert!((at_half.defuzzified - 1.002_962_962_962_963).abs() < 1e-15);
    assert!((at_half.defuzzified * r - 2.50741).abs() < 5e-6);
    assert!(((at_half.defuzzified - 1.0) * r - 0.00741).abs() < 5e-6);

    for alpha in [0.0, 0.3, 0.5, 0.6, 0.61, 0.8, 1.0] {
        let out = run(&job, alpha, [31, 5]);
        let f = stages(&unit, h, alpha);
        let (_, v) = grid(&out);
        let expect = |points: &t2spline::job::Points, factor: f64, what: &str| {
            for a in 0..31 {
                for (b, &vb) in v.iter().enumerate() {
                    let p = points.point(a * v.len() + b).unwrap();
                    let radius = p[0].hypot(p[1]);
                    assert!(
                        (radius - factor * r).abs() <= 1e-12 * r,
                        "alpha {alpha}, {what} at ({a}, {b}): radius {radius}, want {}",
                        factor * r
                    );
                    assert!(
                        (p[2] - height * vb).abs() <= 1e-12 * height,
                        "{what}: z {}",
                        p[2]
                    );
                }
            }
        };
        let s = &out.samples;
        expect(&s.crisp, 1.0, "crisp");
        expect(&s.defuzzified, f.defuzzified, "defuzzified");
        expect(&s.type_reduced.left, f.left, "type-reduced left");
        expect(&s.type_reduced.right, f.right, "type-reduced right");
        for (k, layer) in Layer::ALL.into_iter().enumerate() {
            if layer == Layer::Crisp {
                continue;
            }
            let before = unit[["upper", "primary", "lower", "", "lower", "primary", "upper"][k]]
                [usize::from(k > 3)]
            .as_f64()
            .unwrap();
            expect(s.layer(layer), before, layer.name());
            let cut = s.alpha_cut.get(layer).unwrap();
            match (cut, f.cut[k]) {
                (Some(points), Some(factor)) => expect(points, factor, layer.name()),
                (None, None) => assert!(alpha > h && layer.is_lower()),
                _ => panic!("alpha {alpha}, {layer}: the cut surface and the closed form disagree"),
            }
        }
        let want = (f.defuzzified - 1.0).abs() * r;
        let e = out.error;
        assert!(
            (e.max - want).abs() <= 1e-12 * r && (e.rms - want).abs() <= 1e-12 * r,
            "alpha {alpha}: {e:?}, want max = rms = {want}"
        );
        let expected_regime = if alpha <= h {
            "alpha <= h"
        } else {
            "alpha > h"
        };
        assert_eq!(out.regime.map(|r| r.as_str()), Some(expected_regime));
    }
}

// ---------------------------------------------------------------------------
// The fuzzy terrain patch
// ---------------------------------------------------------------------------

/// What the terrain example shows: positions stay crisp, the solution lies
/// below the crisp surface everywhere (the spreads reach further down), and
/// the largest gap is at the corner farthest from the benchmark, where the
/// clamped surface passes through its corner control point: the gap there is
/// that number's crisp value minus its defuzzified value.
#[test]
fn the_terrain_solution_lies_below_the_crisp_surface_furthest_from_the_benchmark() {
    let (job, file) = example("fuzzy-terrain.json");
    let h = file["lower_height"].as_f64().unwrap();
    let alpha = file["alpha"].as_f64().unwrap();
    let out = run(&job, alpha, [51, 41]);
    let (crisp, solution) = (&out.samples.crisp, &out.samples.defuzzified);
    let mut largest = 0.0f64;
    for i in 0..crisp.len() {
        let (c, d) = (crisp.point(i).unwrap(), solution.point(i).unwrap());
        assert!((c[0] - d[0]).abs() <= 1e-12 * 500.0 && (c[1] - d[1]).abs() <= 1e-12 * 400.0);
        assert!(d[2] <= c[2], "point {i}: {d:?} above {c:?}");
        largest = largest.max(c[2] - d[2]);
    }
    // The benchmark's height is crisp: no spread at all.
    let bm1 = &file["points"][1][1]["z"];
    let c = bm1["crisp"].as_f64().unwrap();
    assert!(["upper", "primary", "lower"]
        .iter()
        .all(|k| bm1[k] == serde_json::json!([c, c])));
    assert!((stages(bm1, h, alpha).defuzzified - c).abs() <= 1e-12 * c);
    // The corner (500, 400) is the farthest from BM1 at (100, 100).
    let corner = &file["points"][5][4];
    assert_eq!(corner["x"]["crisp"], 500.0);
    assert_eq!(corner["y"]["crisp"], 400.0);
    let z = &corner["z"];
    let gap = z["crisp"].as_f64().unwrap() - stages(z, h, alpha).defuzzified;
    assert!(
        (out.error.max - gap).abs() <= 1e-12 * 100.0,
        "{:?} vs {gap}",
        out.error
    );
    assert_eq!(out.error.max_at, Parameter::Uv([1.0, 1.0]));
    assert!(
        (largest - gap).abs() <= 1e-12 * 100.0,
        "largest gap on the grid {largest}"
    );
    assert!(out.error.rms < out.error.max);
    let Spline::Surface { domain, .. } = out.spline else {
        panic!("a surface")
    };
    assert_eq!(domain, [[0.0, 1.0], [0.0, 1.0]]);
}
