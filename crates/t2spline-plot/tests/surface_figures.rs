//! Figures of surface jobs, without golden files: every SVG parses, each
//! stage has its panels, legend entries and colour bar, the view and the
//! number can be chosen, and large nets stay within the drawn grid.

use std::path::{Path, PathBuf};

use t2spline::job::Job;
use t2spline::{Alpha, Axis};
use t2spline_plot::{
    all_figures, render_svg, terrain_left_out, Error, Figure, FigureOptions, Mark, NumberChoice,
    View, TERRAIN_FIGURE_NAMES,
};

#[allow(dead_code)]
#[path = "../examples/many_points.rs"]
mod many_points;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn read(job: &str) -> Job {
    t2spline_io::read_job(&root().join(job)).unwrap()
}

fn figures(job: &Job, options: FigureOptions) -> Vec<Figure> {
    all_figures(job, Alpha::try_new(0.5).unwrap(), &options).unwrap()
}

const EXAMPLES: [&str; 2] = [
    "examples/fuzzy-terrain.json",
    "examples/fuzzy-cylinder.json",
];

const NAMES: [&str; 6] = [
    "number",
    "stage1-fuzzy",
    "stage2-alpha-cut",
    "stage3-type-reduced",
    "stage4-defuzzified",
    "distance-alpha",
];

/// The texts of an SVG document, which must parse as XML.
fn texts(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(str::to_owned))
        .collect()
}

fn keys(fig: &Figure, panel: usize) -> Vec<&str> {
    fig.panels[panel]
        .items
        .iter()
        .map(|i| i.key.as_str())
        .collect()
}

#[test]
fn every_stage_of_a_surface_job_is_drawn() {
    for path in EXAMPLES {
        let job = read(path);
        let figs = figures(&job, FigureOptions::default());
        let names: Vec<&str> = figs.iter().map(|f| f.name).collect();
        // The terrain has its terrain figures after the stages; the
        // cylinder (a fuzzy plan, not the graph of a height) has none.
        let mut want = NAMES.to_vec();
        if path.contains("terrain") {
            want.extend(TERRAIN_FIGURE_NAMES);
        }
        assert_eq!(names, want, "{path}");
        for fig in &figs {
            let svg = render_svg(fig);
            let texts = texts(&svg);
            for entry in &fig.legend {
                assert!(
                    texts.contains(&entry.label),
                    "{path} {}: legend {:?}",
                    fig.name,
                    entry.label
                );
            }
            if !fig.name.starts_with("stage") {
                continue;
            }
            // A 3-D view (no frame; box, surfaces, ticks) beside a framed map.
            assert_eq!(fig.panels.len(), 2, "{path} {}", fig.name);
            let (view, map) = (&fig.panels[0], &fig.panels[1]);
            assert!(!view.frame && map.frame);
            for key in ["box", "surfaces", "ticks"] {
                assert!(keys(fig, 0).contains(&key), "{path} {}: {key}", fig.name);
            }
            assert!(view
                .title
                .as_deref()
                .unwrap()
                .contains("azimuth −60°, elevation 30°"));
            for axis in ["x", "y", "z"] {
                assert!(
                    texts.iter().any(|t| t == axis),
                    "{path} {}: axis {axis}",
                    fig.name
                );
            }
            let Some(Mark::Mesh { facets }) = view
                .items
                .iter()
                .find(|i| i.key == "surfaces")
                .map(|i| &i.mark)
            else {
                panic!("{path} {}: no surfaces", fig.name)
            };
            assert!(facets.iter().filter(|f| !f.points.is_empty()).count() >= 16 * 16);
            assert_eq!((map.x_label.as_str(), map.y_label.as_str()), ("u", "v"));
            let bar = fig.colorbar.as_ref().expect("a colour bar");
            assert!(!bar.stops.is_empty());
            assert!(texts.contains(&bar.label));
        }
    }
}

#[test]
fn stage4_marks_the_largest_distance_on_the_map_and_the_colour_bar() {
    for path in EXAMPLES {
        let job = read(path);
        let figs = figures(&job, FigureOptions::default());
        let run = job
            .run(
                &job.settings(&t2spline::job::Overrides {
                    alpha: Some(0.5),
                    ..Default::default()
                })
                .unwrap(),
            )
            .unwrap();
        let t2spline::job::Parameter::Uv(uv) = run.error.max_at else {
            panic!("a surface's max_at is (u, v)")
        };
        let s4 = &figs[4];
        let marker = s4.panels[1]
            .items
            .iter()
            .find(|i| i.key == "max-at")
            .unwrap();
        let Mark::Markers { points, .. } = &marker.mark else {
            panic!("{path}: max_at is marked")
        };
        assert_eq!(points, &vec![uv], "{path}");
        let bar = s4.colorbar.as_ref().unwrap();
        assert_eq!(bar.marks, vec![(run.error.max, "max".to_owned())]);
        assert!(bar.stops.last().unwrap().0 >= run.error.max);
        assert!(s4.subtitle.contains("max distance"));
    }
}

#[test]
fn the_view_is_chosen_and_stated() {
    let job = read(EXAMPLES[0]);
    let options = FigureOptions {
        view: View::try_new(30.0, 60.0).unwrap(),
        ..FigureOptions::default()
    };
    let a = figures(&job, options);
    let b = figures(&job, FigureOptions::default());
    assert!(a[1].panels[0]
        .title
        .as_deref()
        .unwrap()
        .contains("azimuth 30°, elevation 60°"));
    assert_ne!(render_svg(&a[1]), render_svg(&b[1]));
    // The map over (u, v) does not depend on the view.
    assert_eq!(a[1].panels[1], b[1].panels[1]);
}

#[test]
fn numbers_of_the_net_are_indexed_row_by_row() {
    // The terrain's net has 6 rows of 5 points: point 7 is row 1, column 2.
    let job = read(EXAMPLES[0]);
    let number = |point| {
        all_figures(
            &job,
            Alpha::try_new(0.5).unwrap(),
            &FigureOptions {
                number: NumberChoice {
                    point,
                    axis: Axis::Z,
                },
                ..FigureOptions::default()
            },
        )
    };
    let figs = number(7).unwrap();
    let svg = render_svg(&figs[0]);
    // Row 1, column 2 has crisp height 106.03 (column by column, point 7
    // would be row 1, column 1, at 104.22).
    assert!(
        svg.contains(">crisp 106<"),
        "the crisp height of row 1, column 2"
    );
    assert!(matches!(
        number(30),
        Err(Error::NoSuchPoint {
            point: 30,
            count: 30
        })
    ));
}

/// A fuzzy surface job of `n × n` control points (a smooth hill), bicubic.
fn big_net(n: usize, samples: usize) -> Job {
    let text = many_points::net(n, samples).to_string();
    t2spline_io::parse_job(&text, "big.json").unwrap()
}

#[test]
fn large_nets_draw_a_capped_grid_whatever_the_samples() {
    let small = figures(&big_net(40, 5), FigureOptions::default());
    let large = figures(&big_net(40, 400), FigureOptions::default());
    for (a, b) in small.iter().zip(&large) {
        assert_eq!(
            render_svg(a),
            render_svg(b),
            "{}: figures do not depend on the job's samples",
            a.name
        );
    }
    let Mark::Mesh { facets } = &small[4].panels[0]
        .items
        .iter()
        .find(|i| i.key == "surfaces")
        .unwrap()
        .mark
    else {
        panic!()
    };
    // Stage 4 draws the crisp surface on the capped grid: 48 × 48 quadrilaterals.
    assert_eq!(
        facets.iter().filter(|f| !f.points.is_empty()).count(),
        48 * 48
    );
    assert!(small[1]
        .notes
        .iter()
        .any(|n| n.contains("interval bars left out")));
}

/// The number after `prefix` in `text` (`−` read as a minus sign).
fn number_after(text: &str, prefix: &str) -> f64 {
    let at = text
        .find(prefix)
        .unwrap_or_else(|| panic!("{prefix:?} in {text:?}"))
        + prefix.len();
    let n: String = text[at..]
        .replace('−', "-")
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | 'e' | '+'))
        .collect();
    n.parse()
        .unwrap_or_else(|_| panic!("a number after {prefix:?} in {text:?}"))
}

#[test]
fn terrain_figures_hold_what_the_core_says() {
    let alpha = Alpha::try_new(0.5).unwrap();
    for path in [
        "examples/fuzzy-terrain.json",
        "examples/salish-sea-seabed.json",
    ] {
        let job = read(path);
        let figs = all_figures(&job, alpha, &FigureOptions::default()).unwrap();
        let by = |name: &str| figs.iter().find(|f| f.name == name).unwrap();
        for name in TERRAIN_FIGURE_NAMES {
            let svg = render_svg(by(name));
            let texts = texts(&svg);
            for entry in &by(name).legend {
                assert!(
                    texts.contains(&entry.label),
                    "{path} {name}: {:?}",
                    entry.label
                );
            }
        }
        // The width at a plan point is Σ R·(right − left) of the heights'
        // cuts with R ≥ 0 summing to 1: at most the widest cut at α, at
        // least the narrowest.
        let t2spline::job::Model::Surface(s) = &job.model else {
            panic!()
        };
        let cut_widths: Vec<f64> = s
            .points()
            .iter()
            .map(|p| p.coords()[2].alpha_cut(alpha).upper().width())
            .collect();
        let widest = cut_widths.iter().copied().fold(0.0, f64::max);
        let narrowest = cut_widths.iter().copied().fold(f64::INFINITY, f64::min);
        let width = by("envelope-width");
        let bar = width.colorbar.as_ref().unwrap();
        let (max, label) = &bar.marks[0];
        assert!(
            *max <= widest * (1.0 + 1e-12) && *max >= narrowest,
            "{path}: {max} {widest}"
        );
        assert_eq!(
            number_after(label, "max "),
            number_after(&width.subtitle, "largest width ")
        );
        // Lower function at 0.5 (h ≥ 0.5 in both jobs): three panels.
        assert_eq!(width.panels.len(), 3, "{path}");
        // The bands nest: upper ⊇ primary ⊇ lower, so their areas do.
        let shore = by("shoreline");
        let note = &shore.notes[0];
        let areas = ["upper ", "primary ", "lower "].map(|k| number_after(note, k));
        assert!(
            areas[0] >= areas[1] && areas[1] >= areas[2],
            "{path}: {areas:?}"
        );
        let measures = by("terrain-measures");
        if path.contains("salish") {
            // The seabed crosses z = 0: bands and a crisp shoreline.
            assert!(areas[2] > 0.0, "{path}: {areas:?}");
            let crisp = shore.panels[0]
                .items
                .iter()
                .find(|i| i.key == "crisp")
                .unwrap();
            assert!(matches!(crisp.mark, Mark::Line { .. }));
            // 320 control points: the surface area is left out, and said so.
            assert_eq!(measures.panels.len(), 3);
            assert!(measures
                .notes
                .iter()
                .any(|n| n.contains("Surface area left out")));
        } else {
            // The terrain lies some 100 above z = 0: no band.
            assert_eq!(areas, [0.0; 3]);
            assert_eq!(measures.panels.len(), 4);
            // Nothing lies below z = 0: the volume below is 0 at every level.
            let Mark::Line { points, .. } = &measures.panels[0].items[2].mark else {
                panic!()
            };
            assert!(points.iter().all(|p| p[0] == 0.0), "{points:?}");
        }
    }
}

#[test]
fn a_surface_that_is_not_a_terrain_says_why() {
    let job = read("examples/fuzzy-cylinder.json");
    let why = terrain_left_out(&job)
        .unwrap()
        .expect("the cylinder is not a terrain");
    assert!(why.contains("fuzzy"), "{why}");
    assert_eq!(
        terrain_left_out(&read("examples/fuzzy-terrain.json")).unwrap(),
        None
    );
}
