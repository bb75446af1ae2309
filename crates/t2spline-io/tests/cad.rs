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
    let meta = CadMeta {
        name: format!("curves.{format}"),
        description: Some("a beach's profile, café".into()),
        timestamp: "2026-01-02T03:04:05".into(),
    };
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
    // DXF gets the same curve clamped to its domain [0, 1.5].
    assert!(CadFormat::Dxf.clamps());
    let dxf = render(CadFormat::Dxf, &g.clamped());
    assert!(
        dxf.contains(
            " 40\n0.0\n 40\n0.0\n 40\n0.0\n 40\n0.25\n 40\n1.0\n 40\n1.5\n 40\n1.5\n 40\n1.5\n"
        ),
        "{dxf}"
    );
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
    let meta = CadMeta {
        name: "a.step".into(),
        description: None,
        timestamp: "2026-01-01T00:00:00".into(),
    };
    let e = render_cad(CadFormat::Step, &g, &meta, "job.json").unwrap_err();
    assert_eq!(
        e.to_string(),
        "job.json: the curves have degree 0 (piecewise constant: a set of points), which STEP cannot hold; export needs degree 1 or more"
    );
}

/// A surface job of degrees [2, 1] over a 3 × `nv` net, `v` knots given.
fn surface_geometry(nv: usize, v_knots: Option<Vec<f64>>) -> Geometry {
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
    let job = Job::new(Model::Surface(surface));
    job.geometry(
        &job.settings(&Overrides {
            alpha: Some(0.5),
            ..Overrides::default()
        })
        .unwrap(),
    )
    .unwrap()
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
    let meta = CadMeta {
        name: "s.dxf".into(),
        description: None,
        timestamp: "2026-01-01T00:00:00".into(),
    };
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
