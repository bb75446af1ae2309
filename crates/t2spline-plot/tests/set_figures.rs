//! Figures of the fuzzy curve as a set (docs/method.md §10): the regions
//! stages 1 and 2 shade are the polygons the core computes, holes included
//! (a closed curve's annulus), and the SVG fills them so; the membership map
//! is the core's grid and its contours the core's regions; the section
//! figure draws the core's grades and intervals.

use std::path::Path;

use t2spline::job::{Job, Model};
use t2spline::{Alpha, FuzzyCurve, Membership};
use t2spline_plot::{all_figures, fit_layout, render_svg, Figure, FigureOptions, Mark, Xy};

fn read(job: &str) -> Job {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    t2spline_io::read_job(&root.join(job)).unwrap()
}

fn planar(job: &Job) -> &FuzzyCurve<2> {
    match &job.model {
        Model::Planar(c) => c,
        _ => panic!("a plane curve"),
    }
}

fn figures(job: &Job, alpha: f64, options: &FigureOptions) -> Vec<Figure> {
    all_figures(job, Alpha::try_new(alpha).unwrap(), options).unwrap()
}

fn named<'a>(figs: &'a [Figure], name: &str) -> &'a Figure {
    figs.iter().find(|f| f.name == name).unwrap()
}

fn item<'a>(fig: &'a Figure, panel: usize, key: &str) -> &'a Mark {
    &fig.panels[panel]
        .items
        .iter()
        .find(|i| i.key == key)
        .unwrap_or_else(|| panic!("{}: no item {key}", fig.name))
        .mark
}

/// The core's region at the figures' tolerance (1e-4 of the crisp control
/// points' diagonal), as the rings a figure draws.
fn core_rings(c: &FuzzyCurve<2>, m: Membership, alpha: f64) -> Option<Vec<Vec<Xy>>> {
    let tolerance = c.default_tolerance() * 100.0;
    let r = c
        .region(m, Alpha::try_new(alpha).unwrap(), Some(tolerance))
        .unwrap()?;
    Some(
        r.polygons()
            .iter()
            .flat_map(|g| std::iter::once(g.exterior.clone()).chain(g.holes.clone()))
            .collect(),
    )
}

fn drawn_rings(mark: &Mark) -> Option<Vec<Vec<Xy>>> {
    match mark {
        Mark::Region { rings, .. } => Some(rings.clone()),
        Mark::Empty => None,
        other => panic!("not a region: {other:?}"),
    }
}

#[test]
fn stages_1_and_2_shade_the_cores_regions() {
    let job = read("examples/paper-alg-1-1.json");
    let c = planar(&job);
    for alpha in [0.3, 0.8] {
        let figs = figures(&job, alpha, &FigureOptions::default());
        for (name, level) in [("stage1-fuzzy", 0.0), ("stage2-alpha-cut", alpha)] {
            let fig = named(&figs, name);
            for (key, m) in [
                ("region-upper", Membership::Upper),
                ("region-lower", Membership::Lower),
            ] {
                assert_eq!(
                    drawn_rings(item(fig, 0, key)),
                    core_rings(c, m, level),
                    "{name} at {alpha}: {key}"
                );
            }
            // No band between layer curves is left.
            assert!(fig.panels[0]
                .items
                .iter()
                .all(|i| !i.key.starts_with("band")));
            assert!(fig.legend.iter().all(|e| !e.label.contains("between")));
        }
        // Above h = 0.6 the lower function has no cut anywhere.
        let lower = item(named(&figs, "stage2-alpha-cut"), 0, "region-lower");
        assert_eq!(matches!(lower, Mark::Empty), alpha > 0.6, "alpha {alpha}");
    }
}

/// The sub-paths of an SVG path `d` of `M`, `L` and `Z` commands, in pixels.
fn subpaths(d: &str) -> Vec<Vec<[f64; 2]>> {
    d.split('Z')
        .filter(|s| !s.trim().is_empty())
        .map(|s| {
            s.split(['M', 'L'])
                .filter(|p| !p.trim().is_empty())
                .map(|p| {
                    let v: Vec<f64> = p.split_whitespace().map(|x| x.parse().unwrap()).collect();
                    [v[0], v[1]]
                })
                .collect()
        })
        .collect()
}

/// Even–odd inside test over all rings, as SVG's `fill-rule="evenodd"`.
fn even_odd(rings: &[Vec<[f64; 2]>], p: [f64; 2]) -> bool {
    let mut inside = false;
    for r in rings {
        for (a, b) in r.iter().zip(r.iter().cycle().skip(1)) {
            if (a[1] > p[1]) != (b[1] > p[1])
                && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            {
                inside = !inside;
            }
        }
    }
    inside
}

#[test]
fn a_closed_curves_annulus_is_drawn_with_its_hole() {
    let job = read("fixtures/circle.json");
    let c = planar(&job);
    let figs = figures(&job, 0.5, &FigureOptions::default());
    let fig = named(&figs, "stage1-fuzzy");
    let rings = drawn_rings(item(fig, 0, "region-upper")).unwrap();
    assert_eq!(rings, core_rings(c, Membership::Upper, 0.0).unwrap());
    assert_eq!(rings.len(), 2, "an exterior and a hole");
    // The SVG: one path per region, both rings, filled by the even-odd rule;
    // the centre of the circle is in the hole, the circle itself filled.
    let svg = render_svg(fig);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let paths: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("fill-rule") == Some("evenodd"))
        .collect();
    assert_eq!(paths.len(), 2, "the upper and the lower region");
    let upper = subpaths(paths[0].attribute("d").unwrap());
    assert_eq!(upper.len(), 2);
    assert_eq!(paths[0].attribute("fill"), Some("#0072b2"));
    let layout = fit_layout(&[fig]);
    let pl = &layout.panels[0];
    for (p, filled) in [
        ([0.0, 0.0], false),
        ([0.5, 0.5], false),
        ([1.0, 0.0], true),
        ([0.0, -1.05], true),
        ([-0.75, 0.75], true),
        ([0.75, 0.75], true),
        ([1.3, 0.0], false),
    ] {
        assert_eq!(even_odd(&upper, pl.to_px(p)), filled, "{p:?}");
        assert_eq!(
            c.region(Membership::Upper, Alpha::ZERO, None)
                .unwrap()
                .unwrap()
                .contains(p),
            filled
        );
    }
}

#[test]
fn the_membership_map_is_the_cores_grid_with_its_regions_as_contours() {
    let job = read("examples/paper-alg-1-1.json");
    let c = planar(&job);
    let figs = figures(&job, 0.8, &FigureOptions::default());
    let fig = named(&figs, "membership");
    assert_eq!(fig.panels.len(), 2);
    for (k, m) in [(0, Membership::Upper), (1, Membership::Lower)] {
        let Mark::Tiles { tiles } = item(fig, k, "map") else {
            panic!("tiles")
        };
        // Each tile's colour is the grade at its cells' centres, rounded to a
        // tenth; probe the centre of every tile's first cell against the core.
        let mut probed = 0;
        for (step, (color, rects)) in tiles.iter().enumerate() {
            assert_eq!(*color, t2spline_plot::viridis(step as f64 / 10.0));
            for [a, _] in rects.iter().step_by(25) {
                // A point of the tile's first cell, near its corner: at most
                // a cell's diagonal (0.04) from the cell's centre.
                let centre = [a[0] + 1e-3, a[1] + 1e-3];
                let g = c.membership(&centre).unwrap();
                let grade = match m {
                    Membership::Lower => g.lower,
                    _ => g.upper,
                };
                // The step rounds the cell's grade to a tenth; the grade at
                // the probe differs from the centre's by the slope (at most
                // 1 / 0.3 here) times that diagonal.
                assert!(
                    (grade * 10.0 - step as f64).abs() <= 0.5 + 1.5,
                    "{m:?} at {centre:?}: grade {grade}, step {step}"
                );
                probed += 1;
            }
        }
        assert!(probed > 20, "{probed}");
        // The contours are the regions at 0.2, 0.4, 0.6, 0.8: every vertex of
        // the core's outlines is drawn (those at 0.8 only for the upper).
        let Mark::Line { points, .. } = item(fig, k, "contour") else {
            panic!("contour")
        };
        let tolerance = c.default_tolerance() * 100.0;
        let mut expected = 0;
        for a in [0.2, 0.4, 0.6, 0.8] {
            if let Some(r) = c
                .region(m, Alpha::try_new(a).unwrap(), Some(tolerance))
                .unwrap()
            {
                for g in r.polygons() {
                    for ring in std::iter::once(&g.exterior).chain(&g.holes) {
                        expected += ring.len() + 1;
                        assert!(points.contains(&ring[0]));
                    }
                }
            }
        }
        let drawn = points.iter().filter(|p| p[0].is_finite()).count();
        assert_eq!(drawn, expected, "{m:?}");
        // The crisp curve is drawn last, on top.
        assert_eq!(fig.panels[k].items.last().unwrap().key, "curve-crisp");
    }
}

#[test]
fn the_section_draws_the_cores_grades_and_intervals() {
    let job = read("examples/paper-alg-1-1.json");
    let c = planar(&job);
    let options = FigureOptions {
        station: Some(3.5),
        ..FigureOptions::default()
    };
    let figs = figures(&job, 0.5, &options);
    let fig = named(&figs, "section");
    assert!(fig.title.contains("x = 3.5"));
    for (key, pick) in [("umf", 0), ("primary", 1), ("lmf", 2)] {
        let Mark::Line { points, .. } = item(fig, 0, key) else {
            panic!("{key}")
        };
        assert!(points.len() > 60);
        for p in points.iter().step_by(7) {
            let g = c.membership(&[3.5, p[0]]).unwrap();
            assert_eq!(
                p[1],
                [g.upper, g.primary, g.lower][pick],
                "{key} at y = {}",
                p[0]
            );
        }
    }
    // The cut ends at alpha are the core's section.
    let s = c
        .sections(
            3.5,
            &[Alpha::try_new(0.5).unwrap()],
            Some(c.default_tolerance() * 100.0),
        )
        .unwrap();
    let Mark::Markers { points, .. } = item(fig, 0, "cut-umf") else {
        panic!("cut")
    };
    let ends: Vec<Xy> = s[0]
        .upper
        .as_ref()
        .unwrap()
        .iter()
        .flat_map(|iv| [[iv[0], 0.5], [iv[1], 0.5]])
        .collect();
    assert_eq!(points, &ends);
}

#[test]
fn a_station_the_curve_passes_twice_has_two_intervals() {
    // The circle passes x = 0 at the top and the bottom.
    let job = read("fixtures/circle.json");
    let options = FigureOptions {
        station: Some(0.0),
        ..FigureOptions::default()
    };
    let figs = figures(&job, 0.5, &options);
    let fig = named(&figs, "section");
    let Mark::Markers { points, .. } = item(fig, 0, "cut-umf") else {
        panic!("cut")
    };
    assert_eq!(points.len(), 4, "two intervals: {points:?}");
    assert!(points[1][0] < 0.0 && points[2][0] > 0.0);
    assert!(fig.subtitle.contains("more than once"));
    // Between the two, at the centre, every grade is 0.
    let Mark::Line { points, .. } = item(fig, 0, "umf") else {
        panic!("umf")
    };
    let centre = points
        .iter()
        .min_by(|a, b| a[0].abs().total_cmp(&b[0].abs()))
        .unwrap();
    assert_eq!(centre[1], 0.0);
}

#[test]
fn space_curves_and_surfaces_have_no_figures_of_the_plane() {
    for (job, count) in [
        ("fixtures/spiral-3d.json", 9),
        // The six figures of a surface and the three of a terrain.
        ("examples/fuzzy-terrain.json", 9),
    ] {
        let figs = figures(&read(job), 0.5, &FigureOptions::default());
        assert_eq!(figs.len(), count, "{job}");
        assert!(figs
            .iter()
            .all(|f| f.name != "membership" && f.name != "section"));
    }
    // A 3-D curve's stage 1 shades each projection's region.
    let figs = figures(
        &read("fixtures/spiral-3d.json"),
        0.5,
        &FigureOptions::default(),
    );
    let s1 = named(&figs, "stage1-fuzzy");
    for k in 0..3 {
        assert!(
            matches!(item(s1, k, "region-upper"), Mark::Region { .. }),
            "panel {k}"
        );
    }
    // Surface legends speak of envelopes, never of a region.
    let figs = figures(
        &read("examples/fuzzy-terrain.json"),
        0.5,
        &FigureOptions::default(),
    );
    for f in &figs {
        assert!(
            f.legend.iter().all(|e| !e.label.contains("region")),
            "{}",
            f.name
        );
    }
}
