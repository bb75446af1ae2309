//! Our side of `peer/cad`'s check of surfaces (not a user tool): until job
//! files of surfaces are read by `t2spline`, this program takes one fuzzy
//! surface as JSON on standard input, writes its STEP, IGES and OBJ files
//! into a folder as `t2spline export` would, and prints the run's sampled
//! surfaces as JSON for the script to compare with what OpenCASCADE and the
//! OBJ reader make of the files.
//!
//! Input: `{"degree": [p, q], "knots": [U or null, V or null], "weights":
//! [[…]], "points": [[{"x": number, "y": number, "z": number}, …], …],
//! "alpha": a, "samples": [su, sv], "folder": "…"}` with numbers as in job
//! files (`crisp`, `upper`, `primary`, `lower`, `lower_height`).
//! Output: `{"u": […], "v": […], "surfaces": {"crisp": [[[x, y, z], …], …], …}}`.

use std::io::Read;

use serde_json::{json, Value};
use t2spline::job::{Job, Model, Overrides, Parameters};
use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
use t2spline_io::{render_cad, CadFormat, CadMeta};

fn number(v: &Value) -> Result<Nt2Number, String> {
    let f = |x: &Value| x.as_f64().ok_or_else(|| format!("not a number: {x}"));
    let pair = |key: &str| -> Result<[f64; 2], String> { Ok([f(&v[key][0])?, f(&v[key][1])?]) };
    Nt2Number::try_new(
        f(&v["crisp"])?,
        pair("upper")?,
        pair("primary")?,
        pair("lower")?,
        f(&v["lower_height"])?,
    )
    .map_err(|e| e.to_string())
}

fn list(v: &Value) -> Result<&Vec<Value>, String> {
    v.as_array().ok_or_else(|| format!("not a list: {v}"))
}

fn main() -> Result<(), String> {
    let mut text = String::new();
    std::io::stdin()
        .read_to_string(&mut text)
        .map_err(|e| e.to_string())?;
    let input: Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    let whole = |v: &Value| v.as_u64().map(|x| x as usize).ok_or("not a whole number");
    let degree = [whole(&input["degree"][0])?, whole(&input["degree"][1])?];
    let points = list(&input["points"])?
        .iter()
        .map(|row| {
            list(row)?
                .iter()
                .map(|p| {
                    Ok(Nt2Point::new([
                        number(&p["x"])?,
                        number(&p["y"])?,
                        number(&p["z"])?,
                    ]))
                })
                .collect::<Result<Vec<_>, String>>()
        })
        .collect::<Result<Vec<_>, String>>()?;
    let weights = list(&input["weights"])?
        .iter()
        .map(|row| Ok(list(row)?.iter().filter_map(Value::as_f64).collect()))
        .collect::<Result<Vec<Vec<f64>>, String>>()?;
    let knots = [0, 1].map(|d| {
        input["knots"][d]
            .as_array()
            .map(|k| k.iter().filter_map(Value::as_f64).collect())
    });
    let surface =
        FuzzySurface::try_new(degree, points, weights, knots).map_err(|e| e.to_string())?;
    let job = Job::new(Model::Surface(surface));
    let samples = vec![
        input["samples"][0].as_u64().ok_or("samples")?,
        input["samples"][1].as_u64().ok_or("samples")?,
    ];
    let settings = job
        .settings(&Overrides {
            alpha: input["alpha"].as_f64(),
            samples: Some(samples),
            ..Overrides::default()
        })
        .map_err(|e| e.to_string())?;
    let geometry = job.geometry(&settings).map_err(|e| e.to_string())?;
    let folder = std::path::PathBuf::from(input["folder"].as_str().ok_or("folder")?);
    for (format, extension) in [
        (CadFormat::Step, "step"),
        (CadFormat::Iges, "iges"),
        (CadFormat::Obj, "obj"),
    ] {
        let meta = CadMeta::new(
            format!("surfaces.{extension}"),
            None,
            "1970-01-01T00:00:00",
            Default::default(),
        )
        .map_err(|e| e.to_string())?;
        let text = render_cad(format, &geometry, &meta, "<stdin>").map_err(|e| e.to_string())?;
        std::fs::write(folder.join(format!("surfaces.{extension}")), text)
            .map_err(|e| e.to_string())?;
    }
    let out = job.run(&settings).map_err(|e| e.to_string())?;
    let Parameters::Grid { u, v } = &out.samples.params else {
        return Err("a surface is sampled on a grid".into());
    };
    let s = &out.samples;
    let l = &s.layers;
    let named = [
        ("crisp", &s.crisp),
        ("defuzzified", &s.defuzzified),
        ("upper_left", &l.upper_left),
        ("primary_left", &l.primary_left),
        ("lower_left", &l.lower_left),
        ("lower_right", &l.lower_right),
        ("primary_right", &l.primary_right),
        ("upper_right", &l.upper_right),
    ];
    let mut surfaces = serde_json::Map::new();
    for (name, points) in named {
        let grid: Vec<Vec<Vec<f64>>> = (0..u.len())
            .map(|a| {
                (0..v.len())
                    .map(|b| points.point(a * v.len() + b).unwrap_or_default())
                    .collect()
            })
            .collect();
        surfaces.insert(name.into(), json!(grid));
    }
    println!("{}", json!({"u": u, "v": v, "surfaces": surfaces}));
    Ok(())
}
