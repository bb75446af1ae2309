//! The report's page: the figures that do not change with the slider, and
//! the sections in order (contents, the bar, one section per figure with its
//! caption, downloads and tables, the job, the data block).

use t2spline::job::{Job, RunOutput};
use t2spline::{Alpha, Axis, Layer};

use super::computed::Computed;
use super::data_block::DataBlock;
use super::file_stops::thinned_note;
use super::frames::static_svg;
use super::page::{Page, Section};
use super::stops::Stops;
use super::tables::{self, number_text, rounded};
use super::terrain_frames::TerrainFrames;
use super::{pack, reductions};
use crate::error::Error;
use crate::figures::curve::{
    membership_figure, reductions_figure, section_figure, stage1_figure, sweep_figure, CurveScene,
};
use crate::figures::surface::{self, SurfaceScene};
use crate::figures::{measures_figure, FigureOptions, MEASURES_MAX_POINTS};
use crate::{data, set_view};

/// The figures of a report that do not change with the slider, as SVG.
pub(super) struct Still {
    /// Stage 1 (the layers, and for a curve the region at level 0).
    stage1: String,
    /// The distance along t for several alphas (curves).
    sweep: Option<String>,
    /// The type reductions compared (curves).
    compared: Option<String>,
    /// The membership map and the station section (plane curves).
    set_figures: Option<(String, String)>,
    /// The fuzzy length and area (curves of at most
    /// [`MEASURES_MAX_POINTS`] control points).
    measures: Option<String>,
    /// A terrain's fuzzy volumes and areas, or (a surface that is not a
    /// terrain) why its terrain figures are left out.
    terrain: Option<Result<String, String>>,
}

impl Still {
    /// The still figures of `job`, drawn from the start's `figure_run`.
    pub(super) fn draw(
        job: &Job,
        figure_run: &RunOutput,
        start: Alpha,
        options: &FigureOptions,
        terrain: &TerrainFrames,
    ) -> Result<Still, Error> {
        let heights = job.model.heights();
        let terrain = match terrain {
            _ if !job.model.is_surface() => None,
            TerrainFrames::Drawn { measures, .. } => Some(Ok(static_svg(measures))),
            TerrainFrames::LeftOut(reason) => Some(Err(reason.clone())),
        };
        let (stage1, sweep, compared, set_figures, measures) = if job.model.is_surface() {
            let scene = SurfaceScene::new(figure_run, &heights, options.view, options.aspect);
            (
                static_svg(&surface::stage1_figure(&scene)),
                None,
                None,
                None,
                None,
            )
        } else {
            let scene = CurveScene::new(figure_run, &heights, options.aspect);
            let zero = set_view::regions(&job.model, Alpha::ZERO, &scene.axes())?;
            let fuzzy_weights = job.model.has_fuzzy_weights();
            let set_figures = match job.model {
                t2spline::job::Model::Planar(_) if !fuzzy_weights => Some((
                    static_svg(&membership_figure(job, &scene)?),
                    static_svg(&section_figure(job, &scene, options.station)?),
                )),
                _ => None,
            };
            // Beyond MEASURES_MAX_POINTS the largest length and the area are
            // branch-and-bound brackets, too slow for a page (`t2spline measure`
            // gives them), and the section is left out; with fuzzy weights
            // there is no set view yet (docs/method.md §16).
            let measures = (job.model.control_point_count() <= MEASURES_MAX_POINTS
                && !fuzzy_weights)
                .then(|| measures_figure(job).map(|f| static_svg(&f)))
                .transpose()?;
            (
                static_svg(&stage1_figure(&scene, &zero)),
                Some(static_svg(&sweep_figure(job)?)),
                Some(static_svg(&reductions_figure(job, start, options.aspect)?)),
                set_figures,
                measures,
            )
        };
        Ok(Still {
            stage1,
            sweep,
            compared,
            set_figures,
            measures,
            terrain,
        })
    }
}

/// The page of `job`'s report (file text `job_text`): its sections around
/// the frames `c`, the still figures and the data block.
#[allow(clippy::too_many_arguments)]
pub(super) fn page(
    job: &Job,
    job_text: &str,
    start: Alpha,
    options: &FigureOptions,
    stops: &Stops,
    c: &Computed,
    still: &Still,
    block: &DataBlock,
) -> Result<String, Error> {
    let heights = job.model.heights();
    let start_run = c.start_run()?;
    let table_html: Vec<String> = block
        .tables
        .iter()
        .map(|t| tables::html(t, start_run))
        .collect();
    let mut page = Page::default();
    let contents: Vec<(&str, &str)> = [
        ("number", "One number"),
        ("stage1", "Stage 1"),
        ("stage2", "Stage 2"),
        ("stage3", "Stage 3"),
        ("stage4", "Stage 4"),
        ("distance", "Distance and α"),
        ("measures", "Measures"),
        ("terrain", "Terrain"),
        ("membership", "Membership"),
        ("section", "Section"),
        ("reductions", "Type reductions"),
        ("job", "The job"),
    ]
    .into_iter()
    .filter(|(id, _)| *id != "reductions" || still.compared.is_some())
    .filter(|(id, _)| *id != "measures" || still.measures.is_some())
    .filter(|(id, _)| *id != "terrain" || still.terrain.is_some())
    .filter(|(id, _)| !matches!(*id, "membership" | "section") || still.set_figures.is_some())
    .collect();
    page.header(job.description.as_deref(), start_run, &heights, &contents);
    page.controls(
        stops,
        &heights,
        start_run,
        &reductions::selector(job.type_reduction),
        thinned_note(job).as_deref(),
    );
    let number_caption = format!(
        "Coordinate {} of control point {}: its upper (UMF), primary and lower (LMF) membership functions, the cut at α and the paper's type-reduced triangle with its centroid, and below the axis the other reductions (none uses α). Other numbers: t2spline report --point {} --axis x|y|z.",
        options.number.axis.name(),
        options.number.point_name(&job.model),
        if job.model.is_surface() { "I,J" } else { "I" }
    );
    let captions = if job.model.is_surface() {
        SURFACE_CAPTIONS
    } else {
        CURVE_CAPTIONS
    };
    let compared_caption = format!(
        "The solution curve of every type reduction and its distance to the crisp curve; the paper's at the starting α = {}. Each equals t2spline run --type-reduction NAME.",
        number_text(Some(start.get()))
    );
    for s in [
        Section { id: "number", title: "One fuzzy number (paper Figs. 3.1, 4.1–4.4)", svg: &block.figures[0].svg, figure: "number", caption: &number_caption, csv: None, tables: vec![] },
        Section { id: "stage1", title: captions[0], svg: &still.stage1, figure: "stage1-fuzzy", caption: "Does not depend on α.", csv: Some("stage1-layers.csv"), tables: vec![fuzzy_points_table(job, start_run)] },
        Section { id: "stage2", title: "Stage 2: alpha-cut (Fig. 5.2)", svg: &block.figures[1].svg, figure: "stage2-alpha-cut", caption: "Cut ends of every number at α; a lower end is null above its height h.", csv: Some("stage2-alpha-cut.csv"), tables: vec![table_html[0].clone()] },
        Section { id: "stage3", title: "Stage 3: type reduction (Fig. 5.3)", svg: &block.figures[2].svg, figure: "stage3-type-reduced", caption: captions[1], csv: Some("stage3-type-reduced.csv"), tables: vec![table_html[1].clone()] },
        Section { id: "stage4", title: "Stage 4: defuzzification and distance (Fig. 5.4)", svg: &block.figures[3].svg, figure: "stage4-defuzzified", caption: captions[2], csv: Some("stage4-defuzzified.csv"), tables: vec![table_html[2].clone(), table_html[3].clone()] },
        Section { id: "distance", title: "The distance as α varies", svg: &block.figures[4].svg, figure: "distance-alpha", caption: "Largest and rms distance against α for the paper's type reduction, with both sides of every h; the vertical line is the slider's α.", csv: None, tables: vec![] },
    ] {
        page.section(&s);
    }
    match (&still.terrain, block.figures.get(5), block.figures.get(6)) {
        (Some(Ok(measures)), Some(width), Some(shoreline)) => {
            for s in [
                Section { id: "terrain", title: "Envelope width (docs/method.md §12)", svg: &width.svg, figure: "envelope-width", caption: "How far apart the least and the greatest height of every surface whose heights lie inside their cuts are above each plan point, at the slider's α, per membership function (a function without a cut there is empty); blank cells are NODATA. t2spline envelope --alpha A gives the numbers.", csv: None, tables: vec![] },
                Section { id: "shoreline", title: "Fuzzy shoreline at z = 0 (docs/method.md §13)", svg: &shoreline.svg, figure: "shoreline", caption: "Where a surface whose heights lie inside their cuts can cross the datum z = 0 at the slider's α, per membership function, over the crisp surface's contour lines; the black line is the crisp surface's shoreline. t2spline contour --z 0 --alpha A gives the polygons (on a finer grid).", csv: None, tables: vec![] },
                Section { id: "terrain-measures", title: "Fuzzy volumes and areas (docs/method.md §14)", svg: measures, figure: "terrain-measures", caption: "The volumes below and above z = 0, the plan area below it and the surface area as type-2 fuzzy numbers: at each level the upper, primary and lower functions' intervals; the crisp surface's values marked. Does not depend on the slider; t2spline measure prints the intervals.", csv: None, tables: vec![] },
            ] {
                page.section(&s);
            }
        }
        (Some(Err(reason)), _, _) => page.note_section(
            "terrain",
            "Terrain figures",
            &format!("The envelope width, the fuzzy shoreline and the fuzzy volumes are drawn for terrains (x and y crisp, the surface the graph of a height); they are left out here: {reason}"),
        ),
        _ => {}
    }
    if let Some(measures) = &still.measures {
        page.section(&Section {
            id: "measures",
            title: "The fuzzy length and area (docs/method.md §11)",
            svg: measures,
            figure: "measures",
            caption: "The arc length and the area of every curve whose control points lie inside their cuts, as type-2 fuzzy numbers: at each level α the upper, primary and lower functions' intervals (the extension principle); the crisp curve's values marked. A layer curve's length is not a bound. Does not depend on the slider; t2spline measure prints the intervals.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some(sweep) = &still.sweep {
        page.section(&Section {
            id: "sweep",
            title: "Where along the curve the solution moves",
            svg: sweep,
            figure: "alpha-sweep",
            caption: "‖D(t) − C(t)‖ against t for several α, the paper's type reduction; does not depend on the slider.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some((map, section)) = &still.set_figures {
        page.section(&Section {
            id: "membership",
            title: "The fuzzy curve as a set: membership in the plane",
            svg: map,
            figure: "membership",
            caption: "The grade of every point of the plane, upper and lower: the largest α at which some curve with control points inside their cuts passes through it. The outlines are the regions at α = 0.2, 0.4, 0.6 and 0.8; stage 2 shades the region at the slider's α. Does not depend on the slider.",
            csv: None,
            tables: vec![],
        });
        page.section(&Section {
            id: "section",
            title: "The fuzzy value of y at a station",
            svg: section,
            figure: "section",
            caption: "The upper, primary and lower membership of y at the station (t2spline report --station X0), drawn as one fuzzy number, cut at the starting α; t2spline section prints its intervals.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some(compared) = &still.compared {
        page.section(&Section {
            id: "reductions",
            title: "The type reductions compared (docs/method.md §9)",
            svg: compared,
            figure: "reductions",
            caption: &compared_caption,
            csv: None,
            tables: vec![],
        });
    }
    page.job(job_text);
    page.finish(&pack::pack(&block.json));
    Ok(page.html)
}

/// Titles of the stage 1 section, captions of the stage 3 and 4 sections.
const CURVE_CAPTIONS: [&str; 3] = [
    "Stage 1: the fuzzy control points and layer curves (Fig. 5.1)",
    "Each control point becomes a type-1 triangle (left, crisp, right); with the centroid or alpha-planes, left and right are the centroid interval [c_l, c_r], which need not contain crisp; with Nie–Tan they are its one value.",
    "The distance between the crisp and the defuzzified curve at equal t, over the whole domain; the right panel magnifies its largest value, with both curves computed anew there.",
];

/// [`CURVE_CAPTIONS`] of a surface job.
const SURFACE_CAPTIONS: [&str; 3] = [
    "Stage 1: the fuzzy control net and layer surfaces",
    "Each control point becomes a type-1 triangle (left, crisp, right), or with the centroid or alpha-planes the interval [c_l, c_r], with Nie–Tan one value; the map shows how far apart the left and right surfaces are.",
    "The crisp surface coloured by its distance to the defuzzified one at equal (u, v); the map marks where the distance is largest (error.max_at).",
];

/// The stage-1 table: every number's seven values and height (the first
/// [`tables::MAX_TABLE_POINTS`] points).
fn fuzzy_points_table(job: &Job, r: &RunOutput) -> String {
    use std::fmt::Write as _;
    let n = r.control_points.crisp.len();
    let shown = n.min(tables::MAX_TABLE_POINTS);
    let open = if n == shown { " open" } else { "" };
    let mut s = format!("<details class=\"table\"{open}><summary>Fuzzy control points (the job)</summary>\n<div class=\"scroll\"><table id=\"table-fuzzy\"><thead><tr><th>point</th><th>coord.</th><th>weight</th>");
    for l in Layer::ALL {
        let _ = write!(s, "<th>{}</th>", l.name().replace('_', "."));
    }
    s.push_str("<th>h</th></tr></thead><tbody>\n");
    let cell =
        |v: Option<f64>| format!("<td data-value=\"{}\">{}</td>", number_text(v), rounded(v));
    for k in 0..shown {
        for (a, axis) in Axis::ALL.iter().take(r.dimension).enumerate() {
            let _ = write!(
                s,
                "<tr><th scope=\"row\">{k}</th><th scope=\"row\">{}</th>{}",
                axis.name(),
                cell(r.spline.weights().get(k).copied())
            );
            for l in Layer::ALL {
                let points = r
                    .control_points
                    .layers
                    .get(l)
                    .unwrap_or(&r.control_points.crisp);
                s.push_str(&cell(points.coord(a).get(k).copied()));
            }
            let h = data::number(&job.model, k, *axis)
                .ok()
                .map(|x| x.height().get());
            let _ = writeln!(s, "{}</tr>", cell(h));
        }
    }
    s.push_str("</tbody></table></div>\n");
    if n > shown {
        let _ = writeln!(
            s,
            "<p class=\"note\">The first {shown} control points; all {n} are in the job below.</p>"
        );
    }
    s.push_str("</details>\n");
    s
}
