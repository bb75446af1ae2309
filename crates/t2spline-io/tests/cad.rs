//! CAD writers: the structure of each format, names, full precision, pieces
//! at jumps, unclamped knot vectors kept or clamped as the format needs.
//! (`peer/cad` reads the files back with ezdxf and OpenCASCADE.)

use serde_json::json;
use t2spline::job::{Geometry, Overrides};
use t2spline_io::{parse_job, render_cad, CadFormat, CadMeta};

const NAMES: [&str; 8] = [
    "crisp",
    "defuzzified",
    "upper_left",
    "primary_left",
    "lower_left",
    "lower_right",
    "primary_right",
    "upper_right",
];

fn number(c: f64) -> serde_json::Value {
    json!({"crisp": c, "upper": [c - 1.0, c + 2.0], "primary": [c - 0.5, c + 1.0], "lower": [c - 0.25, c + 0.5]})
}

/// A planar job of degree 2 with the given knots (or the default) and `n`
/// points, the first x coordinate 0.1 + 0.2 (not a short decimal).
fn geometry(n: usize, degree: usize, knots: Option<Vec<f64>>) -> Geometry {
    let points: Vec<_> = (0..n)
        .map(|i| json!({"x": number(if i == 0 { 0.1 + 0.2 } else { i as f64 }), "y": number((i * i) as f64 / 3.0)}))
        .collect();
    let mut job = json!({"degree": degree, "alpha": 0.5, "lower_height": 0.5, "points": points,
                         "weights": (0..n).map(|i| 1.0 + i as f64 / 7.0).collect::<Vec<_>>()});
    if let Some(u) = knots {
        job["knots"] = json!(u);
    }
    let job = parse_job(&job.to_string(), "job.json").unwrap();
    job.geometry(&job.settings(&Overrides::default()).unwrap())
        .unwrap()
}

fn render(format: CadFormat, g: &Geometry) -> String {
    let meta = CadMeta::new(
        format!("curves.{format}"),
        Some("a beach's profile, café".into()),
        "2026-01-02T03:04:05",
        Default::default(),
    )
    .unwrap();
    render_cad(format, g, &meta, "job.json").unwrap()
}

#[test]
fn dxf_has_a_spline_per_curve_on_its_layer() {
    let g = geometry(5, 2, None);
    let text = render(CadFormat::Dxf, &g);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len() % 2, 0);
    let pairs: Vec<(i32, &str)> = lines
        .chunks(2)
        .map(|p| (p[0].trim().parse().expect("a group code"), p[1]))
        .collect();
    assert_eq!(pairs.last(), Some(&(0, "EOF")));
    let splines: Vec<usize> = (0..pairs.len())
        .filter(|&i| pairs[i] == (0, "SPLINE"))
        .collect();
    assert_eq!(splines.len(), 8);
    for (&at, name) in splines.iter().zip(NAMES) {
        let entity: Vec<_> = pairs[at + 1..].iter().take_while(|p| p.0 != 0).collect();
        let value = |code| entity.iter().find(|p| p.0 == code).map(|p| p.1);
        assert_eq!(value(8), Some(name));
        assert_eq!(value(70), Some("12"), "planar and rational");
        assert_eq!(value(71), Some("2"));
        assert_eq!(value(72), Some("8"));
        assert_eq!(value(73), Some("5"));
        assert_eq!(
            entity.iter().filter(|p| p.0 == 41).count(),
            5,
            "a weight per control point"
        );
        assert_eq!(entity.iter().filter(|p| p.0 == 40).count(), 8);
    }
    // Full precision: 0.1 + 0.2 is 0.30000000000000004.
    assert!(text.contains("\n 10\n0.30000000000000004\n"), "{text}");
    // Each curve has its layer in the LAYER table.
    for name in NAMES {
        assert!(
            text.contains(&format!("\n  2\n{name}\n 70\n0\n 62\n")),
            "{name}"
        );
    }
}

#[test]
fn step_has_named_rational_curves_in_one_product() {
    let g = geometry(5, 2, None);
    let text = render(CadFormat::Step, &g);
    assert!(text.starts_with("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION("));
    assert!(text.ends_with("ENDSEC;\nEND-ISO-10303-21;\n"));
    assert!(text.contains("FILE_NAME('curves.step','2026-01-02T03:04:05',"));
    assert!(text.contains("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));"));
    assert!(text.contains("'a beach''s profile, caf\\X2\\00E9\\X0\\'"));
    for name in NAMES {
        assert_eq!(
            text.matches(&format!("REPRESENTATION_ITEM('{name}'))"))
                .count(),
            1,
            "{name}"
        );
        assert!(text.contains(&format!(
            "PRESENTATION_LAYER_ASSIGNMENT('{name}','{name}',(#"
        )));
    }
    assert!(text.contains("B_SPLINE_CURVE_WITH_KNOTS((3,1,1,3),(0.0,0.3333333333333333,0.6666666666666666,1.0),.UNSPECIFIED.)"));
    assert!(text.contains("CARTESIAN_POINT('',(0.30000000000000004,"));
    // Every reference is to an entity of the file.
    let defined: std::collections::HashSet<&str> = text
        .lines()
        .filter_map(|l| l.strip_prefix('#')?.split('=').next())
        .collect();
    for reference in text.split('#').skip(1) {
        let id: String = reference.chars().take_while(char::is_ascii_digit).collect();
        assert!(defined.contains(id.as_str()), "#{id}");
    }
}

#[test]
fn iges_has_80_column_records_and_named_entities_126() {
    let g = geometry(5, 2, None);
    let text = render(CadFormat::Iges, &g);
    assert!(text.lines().all(|l| l.len() == 80));
    let letters: String = text.lines().map(|l| &l[72..73]).collect();
    let order: String = letters.chars().fold(String::new(), |mut s, c| {
        if !s.ends_with(c) {
            s.push(c);
        }
        s
    });
    assert_eq!(order, "SGDPT");
    let directory: Vec<&str> = text.lines().filter(|l| &l[72..73] == "D").collect();
    let types: Vec<&str> = directory.iter().step_by(2).map(|l| l[..8].trim()).collect();
    assert_eq!(types.iter().filter(|t| **t == "126").count(), 8);
    assert_eq!(types.iter().filter(|t| **t == "406").count(), 8);
    for name in NAMES {
        assert!(
            text.contains(&format!("406,1,{}H{name};", name.len())),
            "{name}"
        );
    }
    // Sequence numbers count up in every section.
    for letter in ["S", "G", "D", "P"] {
        let numbers: Vec<usize> = text
            .lines()
            .filter(|l| &l[72..73] == letter)
            .map(|l| l[73..].trim().parse().unwrap())
            .collect();
        assert_eq!(numbers, (1..=numbers.len()).collect::<Vec<_>>(), "{letter}");
    }
    assert!(text.contains("0.30000000000000004"));
}

#[test]
fn obj_has_a_group_per_curve() {
    let g = geometry(5, 2, None);
    let text = render(CadFormat::Obj, &g);
    for name in NAMES {
        assert_eq!(text.matches(&format!("\ng {name}\n")).count(), 1, "{name}");
    }
    assert_eq!(text.matches("cstype rat bspline\ndeg 2\n").count(), 8);
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 40);
    assert!(text.contains("curv 0.0 1.0 36 37 38 39 40\nparm u 0.0 0.0 0.0 0.3333333333333333 0.6666666666666666 1.0 1.0 1.0\nend\n"));
    assert!(text.contains("v 0.30000000000000004 "));
}

#[test]
fn unclamped_curves_are_kept_where_the_format_allows() {
    let u = vec![-1.0, -0.5, 0.0, 0.25, 1.0, 1.5, 2.0, 3.0];
    let g = geometry(5, 2, Some(u));
    let step = render(CadFormat::Step, &g);
    assert!(step.contains(
        "B_SPLINE_CURVE_WITH_KNOTS((1,1,1,1,1,1,1,1),(-1.0,-0.5,0.0,0.25,1.0,1.5,2.0,3.0),"
    ));
    let obj = render(CadFormat::Obj, &g);
    assert!(
        obj.contains("curv 0.0 1.5 ")
            && obj.contains("parm u -1.0 -0.5 0.0 0.25 1.0 1.5 2.0 3.0\n")
    );
    let iges = render(CadFormat::Iges, &g);
    assert!(
        iges.contains("-1.0,-0.5,0.0,0.25,1.0,1.5,2.0,3.0,"),
        "{iges}"
    );
    // DXF gets the same curve clamped to its domain [0, 1.5], whether the
    // caller clamped it or not.
    assert!(CadFormat::Dxf.clamps());
    let dxf = render(CadFormat::Dxf, &g.clamped());
    assert!(
        dxf.contains(
            " 40\n0.0\n 40\n0.0\n 40\n0.0\n 40\n0.25\n 40\n1.0\n 40\n1.5\n 40\n1.5\n 40\n1.5\n"
        ),
        "{dxf}"
    );
    assert_eq!(render(CadFormat::Dxf, &g), dxf);
}

#[test]
fn jumps_make_pieces_under_one_name() {
    // Degree 2, knot 0.5 of full multiplicity 3: two pieces.
    let u = vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0];
    let g = geometry(6, 2, Some(u));
    assert!(g.curves.iter().all(|c| c.pieces.len() == 2));
    let step = render(CadFormat::Step, &g);
    assert_eq!(step.matches("REPRESENTATION_ITEM('crisp'))").count(), 2);
    assert!(step.contains("B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.0,0.5),"));
    let obj = render(CadFormat::Obj, &g);
    assert_eq!(obj.matches("cstype rat bspline").count(), 16);
    let dxf = render(CadFormat::Dxf, &g);
    assert_eq!(dxf.matches("\nSPLINE\n").count(), 16);
}

#[test]
fn degree_0_is_refused() {
    let g = geometry(3, 0, None);
    let meta = CadMeta::new(
        "a.step".into(),
        None,
        "2026-01-01T00:00:00",
        Default::default(),
    )
    .unwrap();
    let e = render_cad(CadFormat::Step, &g, &meta, "job.json").unwrap_err();
    assert_eq!(
        e.to_string(),
        "job.json: the curves have degree 0 (piecewise constant: a set of points), which STEP cannot hold; export needs degree 1 or more"
    );
}

/// A surface job of degrees [2, 1] over a 3 × `nv` net, `v` knots given.
fn surface_geometry(nv: usize, v_knots: Option<Vec<f64>>) -> Geometry {
    let job = surface_job(nv, v_knots);
    job.geometry(
        &job.settings(&Overrides {
            alpha: Some(0.5),
            ..Overrides::default()
        })
        .unwrap(),
    )
    .unwrap()
}

/// The job of [`surface_geometry`].
fn surface_job(nv: usize, v_knots: Option<Vec<f64>>) -> t2spline::job::Job {
    use t2spline::job::{Job, Model};
    use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    let n = |c: f64| {
        Nt2Number::try_new(
            c,
            [c - 1.0, c + 2.0],
            [c - 0.5, c + 1.0],
            [c - 0.25, c + 0.5],
            0.5,
        )
        .unwrap()
    };
    let points = (0..3)
        .map(|i| {
            (0..nv)
                .map(|j| Nt2Point::new([n(i as f64), n(j as f64), n((i * j) as f64 / 4.0)]))
                .collect()
        })
        .collect();
    let weights = (0..3)
        .map(|i| (0..nv).map(|j| 1.0 + (i + j) as f64 / 5.0).collect())
        .collect();
    let surface = FuzzySurface::try_new([2, 1], points, weights, [None, v_knots]).unwrap();
    Job::new(Model::Surface(surface))
}

#[test]
fn surfaces_are_written_as_nurbs_surfaces_except_in_dxf() {
    let g = surface_geometry(2, None);
    assert_eq!((g.curves.len(), g.surfaces.len()), (0, 8));
    let step = render(CadFormat::Step, &g);
    assert!(step.contains("GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION('curves.step',("));
    for name in NAMES {
        assert_eq!(
            step.matches(&format!("REPRESENTATION_ITEM('{name}') SURFACE())"))
                .count(),
            1,
            "{name}"
        );
    }
    assert!(
        step.contains("B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.0,1.0),(0.0,1.0),.UNSPECIFIED.)")
    );
    assert!(
        step.contains("RATIONAL_B_SPLINE_SURFACE(((1.0,1.2),(1.2,1.4),(1.4,1.6)))"),
        "{step}"
    );
    let iges = render(CadFormat::Iges, &g);
    let types: Vec<&str> = iges
        .lines()
        .filter(|l| &l[72..73] == "D")
        .step_by(2)
        .map(|l| l[..8].trim())
        .collect();
    assert_eq!(types.iter().filter(|t| **t == "128").count(), 8);
    // 128, K1, K2, M1, M2, five flags (rational: not polynomial).
    assert!(
        iges.contains("128,2,1,2,1,0,0,0,0,0,0.0,0.0,0.0,1.0,1.0,1.0,0.0,0.0,1.0,1.0,"),
        "{iges}"
    );
    let obj = render(CadFormat::Obj, &g);
    assert_eq!(
        obj.matches("cstype rat bspline\ndeg 2 1\nsurf 0.0 1.0 0.0 1.0 ")
            .count(),
        8
    );
    // The u index varies fastest: the second vertex is P(1, 0) = (1, 0, 0).
    assert!(
        obj.contains("g crisp\nv 0.0 0.0 0.0 1.0\nv 1.0 0.0 0.0 1.2\n"),
        "{obj}"
    );
    let meta = CadMeta::new(
        "s.dxf".into(),
        None,
        "2026-01-01T00:00:00",
        Default::default(),
    )
    .unwrap();
    let e = render_cad(CadFormat::Dxf, &g, &meta, "job.json").unwrap_err();
    assert_eq!(
        e.to_string(),
        "job.json: DXF holds NURBS curves (SPLINE) but no NURBS surfaces (only ACIS solids); export surfaces as STEP, IGES or OBJ"
    );
}

#[test]
fn surfaces_that_jump_are_written_as_patches() {
    // Degree 1 in v with the knot 0.5 twice (full multiplicity): two patches.
    let g = surface_geometry(4, Some(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0]));
    assert!(g.surfaces.iter().all(|s| s.patches.len() == 2));
    let step = render(CadFormat::Step, &g);
    assert_eq!(
        step.matches("REPRESENTATION_ITEM('crisp') SURFACE())")
            .count(),
        2
    );
    let obj = render(CadFormat::Obj, &g);
    assert_eq!(obj.matches("\nsurf ").count(), 16);
}

/// The curves of an OBJ file read back (`v`, `deg`, `curv`, `parm u`), by
/// group, each as a core curve: the file's own numbers, not the writer's.
fn obj_curves(text: &str) -> Vec<(String, t2spline::NurbsCurve<3>)> {
    use t2spline::{KnotVector, NurbsCurve};
    let (mut vertices, mut out) = (Vec::new(), Vec::new());
    let (mut group, mut degree, mut indices) = (String::new(), 0, Vec::new());
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["v", rest @ ..] => {
                let v: Vec<f64> = rest.iter().map(|w| w.parse().unwrap()).collect();
                vertices.push(([v[0], v[1], v[2]], v[3]));
            }
            ["g", name] => group = (*name).to_owned(),
            ["deg", p] => degree = p.parse().unwrap(),
            ["curv", _, _, rest @ ..] => {
                indices = rest
                    .iter()
                    .map(|w| w.parse::<usize>().unwrap() - 1)
                    .collect();
            }
            ["parm", "u", rest @ ..] => {
                let knots: Vec<f64> = rest.iter().map(|w| w.parse().unwrap()).collect();
                let (points, weights) = indices.iter().map(|&i| vertices[i]).unzip();
                let u = KnotVector::try_new(knots, degree, indices.len()).unwrap();
                out.push((
                    group.clone(),
                    NurbsCurve::try_new(points, weights, u).unwrap(),
                ));
            }
            _ => {}
        }
    }
    out
}

/// The multiplicity lists of every `B_SPLINE_CURVE_WITH_KNOTS(…)` (one) or
/// `B_SPLINE_SURFACE_WITH_KNOTS(…)` (two) of a STEP file, with the degrees
/// of its `B_SPLINE_CURVE(p,…` or `B_SPLINE_SURFACE(p,q,…`.
fn step_knot_runs(step: &str) -> Vec<(usize, Vec<usize>)> {
    let list = |s: &str| -> Vec<usize> {
        let inner = &s[1..s.find(')').unwrap()];
        inner.split(',').map(|m| m.parse().unwrap()).collect()
    };
    let mut out = Vec::new();
    for entity in step.lines() {
        if let Some(at) = entity.find("B_SPLINE_CURVE_WITH_KNOTS(") {
            let p = entity.split("B_SPLINE_CURVE(").nth(1).unwrap();
            let p: usize = p[..p.find(',').unwrap()].parse().unwrap();
            out.push((p, list(&entity[at + 26..])));
        }
        if let Some(at) = entity.find("B_SPLINE_SURFACE_WITH_KNOTS(") {
            let pq = entity.split("B_SPLINE_SURFACE(").nth(1).unwrap();
            let pq: Vec<usize> = pq.split(',').take(2).map(|d| d.parse().unwrap()).collect();
            let rest = &entity[at + 28..];
            let second = &rest[rest.find("),").unwrap() + 2..];
            out.push((pq[0], list(rest)));
            out.push((pq[1], list(second)));
        }
    }
    out
}

/// ISO 10303-42's rule that OpenCASCADE applies to every STEP B-spline: at
/// most `p` equal knots inside the knot vector, at most `p + 1` at its ends.
fn assert_step_multiplicities(step: &str) {
    let runs = step_knot_runs(step);
    assert!(!runs.is_empty());
    for (p, m) in runs {
        let inner = &m[1..m.len() - 1];
        assert!(
            m[0] <= p + 1 && m[m.len() - 1] <= p + 1 && inner.iter().all(|&x| x <= p),
            "degree {p}, multiplicities {m:?}"
        );
    }
}

/// A planar job of degree 2 (`n` points, unit spreads) with these knots.
fn job_with_knots(n: usize, knots: &[f64]) -> t2spline::job::Job {
    let points: Vec<_> = (0..n)
        .map(|i| json!({"x": number(i as f64), "y": number(((i * 7) % 5) as f64)}))
        .collect();
    let job = json!({"degree": 2, "alpha": 0.5, "lower_height": 0.5, "points": points,
                     "knots": knots, "samples": 41,
                     "weights": (0..n).map(|i| 1.0 + i as f64 / 3.0).collect::<Vec<_>>()});
    parse_job(&job.to_string(), "job.json").unwrap()
}

#[test]
fn knots_of_full_multiplicity_at_a_domain_end_are_cut_off_before_writing() {
    // Order 3, domain [U[2], U[4]] = [0, 0.5]: P3 acts on [0.5, 1] only. STEP
    // wrote (3,3,1), which OpenCASCADE refuses ("Poles and degree mismatch").
    let job = job_with_knots(4, &[0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0]);
    let g = job
        .geometry(&job.settings(&Overrides::default()).unwrap())
        .unwrap();
    assert!(g.curves.iter().all(|c| c.pieces.len() == 1
        && c.pieces[0].control_points().len() == 3
        && c.pieces[0].knots().as_slice() == [0.0, 0.0, 0.0, 0.5, 0.5, 0.5]));
    let step = render(CadFormat::Step, &g);
    assert!(
        step.contains("B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.0,0.5),"),
        "{step}"
    );
    assert!(!step.contains("(3,3,1)"));
    assert_step_multiplicities(&step);
    // IGES 126: K = 2 (three control points), M = 2, the six knots, V(0) = 0,
    // V(1) = 0.5.
    let iges = render(CadFormat::Iges, &g);
    let params: String = iges
        .lines()
        .filter(|l| &l[72..73] == "P")
        .map(|l| l[..64].trim_end())
        .collect();
    assert_eq!(
        params
            .matches("126,2,2,1,0,0,0,0.0,0.0,0.0,0.5,0.5,0.5,")
            .count(),
        8,
        "{params}"
    );
    let obj = render(CadFormat::Obj, &g);
    assert_eq!(obj.matches("parm u 0.0 0.0 0.0 0.5 0.5 0.5\n").count(), 8);
    let dxf = render(CadFormat::Dxf, &g.clamped());
    assert_eq!(dxf.matches("\n 72\n6\n 73\n3\n").count(), 8, "{dxf}");
}

/// Every layout of knots of full multiplicity at the domain's ends (with
/// knots beyond them at the end, the start or both, with and without a jump
/// inside): the STEP file obeys ISO 10303-42, and the OBJ file read back
/// gives `run`'s samples of every curve.
#[test]
fn curves_cut_at_their_domain_ends_read_back_as_run_samples_them() {
    use t2spline::Layer;
    for (n, knots) in [
        (4, vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0]),
        (5, vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 0.5, 2.0]),
        (5, vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.7, 1.0]),
        (4, vec![-1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
        (5, vec![-2.0, -1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
        (6, vec![-1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 3.0]),
        (
            8,
            vec![-1.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0],
        ),
    ] {
        let job = job_with_knots(n, &knots);
        let settings = job.settings(&Overrides::default()).unwrap();
        let g = job.geometry(&settings).unwrap();
        let run = job.run(&settings).unwrap();
        assert_step_multiplicities(&render(CadFormat::Step, &g));
        let curves = obj_curves(&render(CadFormat::Obj, &g));
        assert!(
            curves.iter().all(|(_, c)| c.knots().is_clamped()),
            "{knots:?}"
        );
        for name in NAMES {
            let sampled = match name {
                "defuzzified" => &run.samples.defuzzified,
                _ => run
                    .samples
                    .layer(*Layer::ALL.iter().find(|l| l.name() == name).unwrap()),
            };
            let pieces: Vec<_> = curves
                .iter()
                .filter(|(g, _)| g == name)
                .map(|(_, c)| c)
                .collect();
            for (k, &t) in run.samples.params.along().iter().enumerate() {
                // The right piece at a jump, as `run` samples it.
                let piece = pieces.iter().rev().find(|c| c.domain().start <= t).unwrap();
                let got = piece.eval(t).unwrap();
                let want = sampled.point(k).unwrap();
                for a in 0..2 {
                    assert!(
                        (got[a] - want[a]).abs() <= 1e-12 * 8.0,
                        "{knots:?}, {name}, t = {t}: {got:?} against {want:?}"
                    );
                }
                assert_eq!(got[2], 0.0);
            }
        }
    }
}

#[test]
fn surfaces_cut_at_their_domain_ends_are_exact_and_obey_step_s_rule() {
    use t2spline::job::Model;
    use t2spline::{Direction, Layer};
    // v: degree 1, the knot 0.5 twice at the domain end V[3] with 1 beyond:
    // the net's fourth column acts on [0.5, 1] only.
    let v = vec![0.0, 0.0, 0.25, 0.5, 0.5, 1.0];
    let g = surface_geometry(4, Some(v.clone()));
    assert!(g.surfaces.iter().all(|s| s.patches.len() == 1
        && s.patches[0].shape() == [3, 3]
        && s.patches[0].knots(Direction::V).as_slice() == [0.0, 0.0, 0.25, 0.5, 0.5]));
    let step = render(CadFormat::Step, &g);
    assert!(
        step.contains("B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,1,2),"),
        "{step}"
    );
    assert_step_multiplicities(&step);
    let obj = render(CadFormat::Obj, &g);
    assert_eq!(obj.matches("parm v 0.0 0.0 0.25 0.5 0.5\n").count(), 8);
    // On its domain [0, 1] × [0, 0.5] each patch is the job's surface.
    let Model::Surface(fuzzy) = surface_job(4, Some(v)).model else {
        unreachable!("a surface job")
    };
    for s in &g.surfaces {
        let Some(layer) = Layer::ALL.iter().find(|l| l.name() == s.name) else {
            continue;
        };
        let whole = fuzzy.layer_surface(*layer);
        for a in 0..=8 {
            for b in 0..=8 {
                let (u, v) = (f64::from(a) / 8.0, f64::from(b) / 16.0);
                let (x, y) = (s.patches[0].eval(u, v).unwrap(), whole.eval(u, v).unwrap());
                for i in 0..3 {
                    assert!(
                        (x[i] - y[i]).abs() <= 1e-13,
                        "{} ({u}, {v}): {x:?} against {y:?}",
                        s.name
                    );
                }
            }
        }
    }
}

#[test]
fn control_characters_of_the_description_never_reach_a_file_raw() {
    let description = "line one \u{1b}[31mred\u{7}\r\nline two\tends\rthree\u{85}\u{7f}";
    let meta = CadMeta::new(
        "curves\u{1b}.x".into(),
        Some(description.into()),
        "2026-01-02T03:04:05",
        Default::default(),
    )
    .unwrap();
    let curves = geometry(5, 2, None);
    let surfaces = surface_geometry(2, None);
    for format in CadFormat::ALL {
        for g in [&curves, &surfaces] {
            if format == CadFormat::Dxf && g.curves.is_empty() {
                continue;
            }
            let text = render_cad(format, g, &meta, "job.json").unwrap();
            let raw: Vec<char> = text
                .chars()
                .filter(|&c| c.is_control() && c != '\n')
                .collect();
            assert!(raw.is_empty(), "{format}: {raw:?} in\n{text}");
            match format {
                CadFormat::Step => assert!(
                    text.contains("'line one \\X2\\001B\\X0\\[31mred\\X2\\0007\\X0\\"),
                    "{text}"
                ),
                CadFormat::Iges => {
                    assert!(
                        text.contains("line one ?[31mred? line two ends three ?"),
                        "{text}"
                    );
                    assert!(text.lines().all(|l| l.len() == 80));
                }
                CadFormat::Obj => assert!(
                    text.contains("# line one ?[31mred?\n# line two ends\n# three??\n"),
                    "{text}"
                ),
                CadFormat::Dxf => {}
            }
        }
    }
}

#[test]
fn a_surface_of_degree_0_in_one_direction_is_named_a_set_of_curves() {
    use t2spline::job::{Job, Model, Overrides};
    use t2spline::{FuzzySurface, Nt2Number, Nt2Point};
    // A 1 × 3 net: degree 0 along u, 1 along v.
    let n = |c: f64| {
        Nt2Number::try_new(c, [c - 1.0, c + 1.0], [c - 0.5, c + 0.5], [c, c], 1.0).unwrap()
    };
    let row: Vec<Nt2Point<3>> = (0..3)
        .map(|j| Nt2Point::new([n(0.0), n(j as f64), n(1.0)]))
        .collect();
    let surface =
        FuzzySurface::try_new([0, 1], vec![row], vec![vec![1.0; 3]], [None, None]).unwrap();
    let mut job = Job::new(Model::Surface(surface));
    job.alpha = Some(t2spline::Alpha::ZERO);
    let g = job
        .geometry(&job.settings(&Overrides::default()).unwrap())
        .unwrap();
    let meta = CadMeta::new(
        "a.step".into(),
        None,
        "2026-01-01T00:00:00",
        Default::default(),
    )
    .unwrap();
    let e = render_cad(CadFormat::Step, &g, &meta, "job.json").unwrap_err();
    assert_eq!(
        e.to_string(),
        "job.json: the surfaces have degree 0 in u (piecewise constant in u: a set of curves along v), which STEP cannot hold; export needs degree 1 or more in both directions"
    );
}

/// Each unit in each format's own words: DXF `$INSUNITS` and
/// `$MEASUREMENT`, the STEP context's length unit, the IGES unit flag and
/// name, an OBJ comment; the numbers themselves unchanged.
#[test]
fn every_format_records_the_unit() {
    use t2spline::job::LengthUnit;
    let g = geometry(5, 2, None);
    let with = |format: CadFormat, units: LengthUnit| {
        let meta = CadMeta::new(
            format!("curves.{format}"),
            None,
            "2026-01-02T03:04:05",
            units,
        )
        .unwrap();
        render_cad(format, &g, &meta, "job.json").unwrap()
    };
    let cases = [
        (
            LengthUnit::Millimetre,
            "4",
            "1",
            "SI_UNIT(.MILLI.,.METRE.))",
            "2,2HMM,",
        ),
        (
            LengthUnit::Centimetre,
            "5",
            "1",
            "SI_UNIT(.CENTI.,.METRE.))",
            "10,2HCM,",
        ),
        (LengthUnit::Metre, "6", "1", "SI_UNIT($,.METRE.))", "6,1HM,"),
        (
            LengthUnit::Inch,
            "1",
            "0",
            "(CONVERSION_BASED_UNIT('INCH',",
            "1,4HINCH,",
        ),
        (
            LengthUnit::Foot,
            "2",
            "0",
            "(CONVERSION_BASED_UNIT('FOOT',",
            "4,2HFT,",
        ),
    ];
    for (units, insunits, measurement, step, iges) in cases {
        let dxf = with(CadFormat::Dxf, units);
        assert!(
            dxf.contains(&format!("$INSUNITS\n 70\n{insunits}\n")),
            "{units:?}"
        );
        assert!(
            dxf.contains(&format!("$MEASUREMENT\n 70\n{measurement}\n")),
            "{units:?}"
        );
        assert!(with(CadFormat::Step, units).contains(step), "{units:?}");
        // The global section is cut into 72-column lines: join them first.
        let text = with(CadFormat::Iges, units);
        let global: String = text
            .lines()
            .filter(|l| l.as_bytes().get(72) == Some(&b'G'))
            .map(|l| &l[..72])
            .collect();
        assert!(global.contains(iges), "{units:?}: {global}");
        let obj = with(CadFormat::Obj, units);
        assert!(
            obj.contains(&format!("; units: {} (", units.name())),
            "{units:?}"
        );
        // The control points are the same numbers in every unit.
        let spline = |t: &str| {
            t.lines()
                .filter(|l| l.starts_with("v "))
                .collect::<Vec<_>>()
                .join("\n")
        };
        assert_eq!(
            spline(&obj),
            spline(&with(CadFormat::Obj, LengthUnit::Millimetre))
        );
    }
}
