//! Command-line arguments, as given (clap derive); validation happens in `cmd/`.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Args, Parser, Subcommand, ValueEnum};
use t2spline::TypeReduction;

/// Normal type-2 fuzzy rational B-spline curves: model uncertain control points,
/// cut, type-reduce and defuzzify them (Algorithm 1.1 of Zakaria, Wahab and
/// Gobithaasan), and measure how far the crisp type-2 solution moves.
#[derive(Debug, Parser)]
#[command(name = "t2spline", version, propagate_version = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run the four stages on a job file and write the result as JSON (also
    /// CSV, Parquet); or on many job files in parallel.
    Run(RunArgs),
    /// Check a job file and report every problem in it.
    Validate(ValidateArgs),
    /// Draw the figures of every stage (SVG and/or PNG) into a folder.
    Plot(PlotArgs),
    /// Write a self-contained HTML report with an alpha slider into a folder.
    Report(ReportArgs),
    /// Fit a fuzzy curve to fuzzy data points (or to repeated readings, CSV)
    /// and write it as a job file.
    Fit(FitArgs),
    /// Turn repeated readings of stations (CSV; of a curve or of a net), or
    /// a raster in blocks, into fuzzy data points for `fit`: median,
    /// quartiles, 10th-90th percentiles, extremes widened by the
    /// instrument's accuracy.
    Fuzzify(FuzzifyArgs),
    /// Write the exact curves of a run (crisp, defuzzified, six layers) as
    /// rational B-splines in a CAD file: DXF, STEP, IGES or OBJ.
    Export(ExportArgs),
    /// The membership grades of points in the fuzzy curve or surface as a
    /// set: CSV with the columns x,y[,z],upper,primary,lower.
    Membership(MembershipArgs),
    /// The region a fuzzy curve can occupy at a level, as GeoJSON polygons
    /// (one Feature per membership function; 3-D curves per plane).
    Region(RegionArgs),
    /// The fuzzy value at a station: the y-intervals of a curve at x = X0, or
    /// the z-intervals of a surface at (X0, Y0), at each level (JSON).
    Section(SectionArgs),
    /// The envelope of a fuzzy surface: the least and greatest height above
    /// every cell of a plan grid, at each level and for each membership
    /// function (CSV, Parquet, or a GeoTIFF a GIS opens).
    Envelope(EnvelopeArgs),
    /// The fuzzy contour of a fuzzy surface: where the surface can cross a
    /// height at each level, per membership function, as GeoJSON polygons,
    /// beside the crisp surface's contour.
    Contour(ContourArgs),
    /// The uncertainty of what is measured on a fuzzy curve (arc length,
    /// area, derivative, tangent angle and curvature) or on a fuzzy surface
    /// of crisp plan (the volumes above and below a datum, the plan area
    /// below it, the surface area; with --against, the cut and fill between
    /// two surfaces of one plan map), as intervals over the control points
    /// inside their cuts, at each level (JSON).
    Measure(MeasureArgs),
    /// Time the sampling engine: one line per case with the median of 5 runs.
    Bench(BenchArgs),
    /// A live editor of the job in the browser, on this computer only: prints
    /// the page's address (with its per-run token) and serves it until Ctrl-C.
    Serve(ServeArgs),
}

/// Arguments of `t2spline run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// The job file (JSON, see docs/jobs.md); `-` reads standard input. Several
    /// job files run in parallel, one result each (see `-o`).
    #[arg(value_name = "JOB", required_unless_present = "jobs")]
    pub job: Vec<PathBuf>,
    /// Also run every `*.json` file in this folder (in name order), as if
    /// each were named after `run`.
    #[arg(long, value_name = "DIR")]
    pub jobs: Option<PathBuf>,
    /// Write the result here instead of standard output (`-` is standard
    /// output). With several jobs: the folder for `NAME.json` per job (from
    /// the job file `NAME.json`) and `summary.csv`, created if missing; left
    /// out with `--parquet FILE.parquet` or `--jsonl FILE`, no file per job
    /// is written and the summary goes beside the table.
    #[arg(short, long, value_name = "OUT.json|DIR")]
    pub output: Option<PathBuf>,
    /// The level alpha in [0, 1]; overrides the job file.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// Number of uniform parameters to sample the curves at (at least 2); for
    /// a surface `U,V` (or `N` for both directions); overrides the job file.
    #[arg(long, value_name = "N|U,V", value_delimiter = ',', num_args = 1)]
    pub samples: Option<Vec<u64>>,
    /// Also write the sampled curves as CSV files (one per curve family) into
    /// this folder, creating it if needed; with several jobs into its
    /// subfolder `NAME/` per job.
    #[arg(long, value_name = "DIR")]
    pub csv: Option<PathBuf>,
    /// Also write the sampled curves as one Apache Parquet table into this
    /// file; with several jobs, the folder for `NAME.parquet` per job and
    /// `summary.parquet`, or a `FILE.parquet` for one table of every job's
    /// samples (columns `job`, `alpha`, one schema whatever the regime; the
    /// summary then in the `--output` folder).
    #[arg(long, value_name = "FILE|DIR")]
    pub parquet: Option<PathBuf>,
    /// Also write the sampled curves as JSON Lines into this file: a line per
    /// job and parameter with the keys `job`, `alpha` and the columns of the
    /// one Parquet table of many jobs (`null` where a job lacks one).
    #[arg(long, value_name = "FILE")]
    pub jsonl: Option<PathBuf>,
    /// Also compute the derivatives of orders 1 to K of the crisp and the
    /// defuzzified curve at the sample parameters, and their arc lengths
    /// (result keys `curves.derivatives`, `curves.arc_length`); K from 1 to 16.
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub derivatives: Option<i64>,
    #[command(flatten)]
    pub reduction: ReductionArg,
}

/// `--type-reduction`, shared by the commands that run a job (`run`, `plot`,
/// `report`, `export`).
#[derive(Debug, Args)]
pub struct ReductionArg {
    /// The type reduction of stages 3–4; overrides the job file's
    /// `type_reduction`: `paper` (the paper's, uses alpha; default),
    /// `centroid` (interval type-2 centroid, Karnik–Mendel), `nie-tan`, or
    /// `alpha-planes` (general type-2). Only `paper` uses alpha. A report
    /// holds all four and opens on this one.
    #[arg(long, value_name = "NAME",
          value_parser = PossibleValuesParser::new(TypeReduction::ALL.map(TypeReduction::name))
              .try_map(|s| s.parse::<TypeReduction>()))]
    pub type_reduction: Option<TypeReduction>,
}

/// Arguments of `t2spline serve`.
#[derive(Debug, Args)]
pub struct ServeArgs {
    /// The job file to edit (saved over only when the page asks); without
    /// one, the shipped example `examples/paper-alg-1-1.json`.
    pub job: Option<PathBuf>,
    /// The port on 127.0.0.1 (0: a free one).
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub port: u16,
}

/// Arguments of `t2spline validate`.
#[derive(Debug, Args)]
pub struct ValidateArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
}

/// File formats of `t2spline plot`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// SVG only (vector, for papers).
    Svg,
    /// PNG only (1920 pixels wide for one panel).
    Png,
    /// Both.
    Both,
}

/// Coordinates for `--axis`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum AxisArg {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
    /// The third coordinate (3-D jobs).
    Z,
}

/// A control point for `--point`: an index, or a row and column of a net.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointArg {
    /// `I`: the index (of a surface: row-major, `i·nv + j`).
    Index(usize),
    /// `I,J`: row `i` and column `j` of a surface's net.
    Net(usize, usize),
}

impl std::str::FromStr for PointArg {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let index = |t: &str| {
            t.trim()
                .parse::<usize>()
                .map_err(|_| format!("`{s}` is not I or I,J with whole numbers from 0"))
        };
        match s.split_once(',') {
            Some((i, j)) => Ok(PointArg::Net(index(i)?, index(j)?)),
            None => Ok(PointArg::Index(index(s)?)),
        }
    }
}

/// Scaling of curve panels for `--aspect`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum AspectArg {
    /// One unit has the same length on both axes (shapes are true).
    Equal,
    /// Each axis fitted to its data (for elongated data).
    Auto,
}

/// What the figures show, shared by `plot` and `report`.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// The control point whose fuzzy number the `number` figure shows, from
    /// 0: `I` on a curve; `I,J` (row I, column J of the net) or the row-major
    /// index `I·nv + J` on a surface.
    #[arg(long, value_name = "I|I,J", default_value = "0")]
    pub point: PointArg,
    /// The coordinate whose fuzzy number the `number` figure shows.
    #[arg(long, value_enum, default_value_t = AxisArg::X)]
    pub axis: AxisArg,
    /// How curve panels are scaled: `equal` keeps one unit the same length on
    /// both axes; `auto` fits each axis to its data, for elongated curves
    /// whose spreads would otherwise not show.
    #[arg(long, value_enum, default_value_t = AspectArg::Equal)]
    pub aspect: AspectArg,
    /// The direction the 3-D views of a surface job look from, as
    /// `AZIMUTH,ELEVATION` in degrees: azimuth from the +x axis toward +y,
    /// elevation above the x–y plane in [-90, 90].
    #[arg(
        long,
        value_name = "AZ,EL",
        default_value = "-60,30",
        allow_hyphen_values = true
    )]
    pub view: t2spline_plot::View,
    /// The station `x = X0` of the `section` figure (plane curves only):
    /// the fuzzy value of y there. Default: x of the crisp curve at the
    /// middle of its domain.
    #[arg(long, value_name = "X0", allow_hyphen_values = true)]
    pub station: Option<f64>,
}

/// Arguments of `t2spline plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
    /// The folder to write the figures into (created if missing).
    #[arg(short, long, value_name = "DIR")]
    pub output: PathBuf,
    /// Which files to write per figure [default: both, or svg where the
    /// command was built without PNG, as the Python package's is].
    #[arg(long, value_enum)]
    pub format: Option<FormatArg>,
    #[command(flatten)]
    pub figures: FigureArgs,
    /// The level alpha in [0, 1]; overrides the job file.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    #[command(flatten)]
    pub reduction: ReductionArg,
}

/// Arguments of `t2spline report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
    /// The folder to write `report.html` into (created if missing).
    #[arg(short, long, value_name = "DIR")]
    pub output: PathBuf,
    /// The alpha the slider starts at; overrides the job file (default: the
    /// job's alpha, else 0.5).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    #[command(flatten)]
    pub figures: FigureArgs,
    #[command(flatten)]
    pub reduction: ReductionArg,
}

/// Arguments of `t2spline fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// The data file: the keys of a job file except `weights` and `knots`; its
    /// points are fuzzy data points. `-` reads standard input.
    pub data: PathBuf,
    /// Write the job file here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "JOB.json")]
    pub output: Option<PathBuf>,
    /// How the data points get their parameters, from the crisp values:
    /// chord length, centripetal (square roots of the chords) or uniform.
    #[arg(long, value_name = "METHOD", default_value = "chord",
          value_parser = clap::builder::PossibleValuesParser::new(["chord", "centripetal", "uniform"]))]
    pub parametrization: String,
    /// Approximate the data by least squares with M control points (the end
    /// points interpolated) instead of interpolating them; for a net (a
    /// surface), M,N control points in u and v (M alone: M in both); with
    /// `--closed`, M distinct control points and no end points.
    #[arg(long, value_name = "M[,N]")]
    pub control_points: Option<String>,
    /// How the six non-crisp layers are fitted: `valid` fits the spreads as
    /// nested non-negative quantities, so the control points are always valid
    /// fuzzy numbers; `independent` fits each layer on its own and refuses to
    /// write a job whose control points break the order.
    #[arg(long, value_name = "MODE", default_value = "valid",
          value_parser = clap::builder::PossibleValuesParser::new(["valid", "independent"]))]
    pub fuzzy_fit: String,
    /// Fit a closed curve: the data points are a loop (the chord from the
    /// last back to the first counts; a last point repeating the first is
    /// the same point), the knots periodic, the first p control points
    /// repeated at the end, and the job says `"closed": true`. Curves only.
    #[arg(long)]
    pub closed: bool,
    /// Do not print the report on standard error.
    #[arg(short, long)]
    pub quiet: bool,
    /// The level alpha in [0, 1] to carry into the fitted job (in place of
    /// the data file's), so that `run` can run it.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// How readings become fuzzy numbers, when the data file is a readings
    /// file (CSV).
    #[command(flatten)]
    pub readings: ReadingsArgs,
}

/// How readings become fuzzy data points (`fuzzify`, and `fit` of a
/// readings file).
#[derive(Debug, Args)]
pub struct ReadingsArgs {
    /// The instrument's accuracy T: the upper membership function reaches T
    /// beyond the smallest and the largest reading [default: 0].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// The height of the lower membership function, in (0, 1] [default: 0.5:
    /// the quartiles hold half of the readings].
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub lower_height: Option<f64>,
    /// The degree of the curve to fit, carried into the data file
    /// [default: 3]; for a net `P,Q` (along u, along v), or `P` for both
    /// [default: 3,3].
    #[arg(
        long,
        value_name = "P|P,Q",
        conflicts_with = "order",
        value_delimiter = ',',
        num_args = 1
    )]
    pub degree: Option<Vec<u64>>,
    /// The order of the curve to fit (degree + 1), instead of --degree; for
    /// a net `KU,KV`, or `K` for both.
    #[arg(long, value_name = "K|KU,KV", value_delimiter = ',', num_args = 1)]
    pub order: Option<Vec<u64>>,
}

/// Arguments of `t2spline fuzzify`.
#[derive(Debug, Args)]
pub struct FuzzifyArgs {
    /// The readings file: a header `station,x,y` or `station,x,y,z` (the
    /// stations of a curve) or `row,col,x,y,z` (the stations of a net), then
    /// one reading per row, the rows of a station in any order (comma or
    /// semicolon separated); with --block, a raster: a CSV `x,y,z` grid, an
    /// ESRI ASCII grid `.asc` or a numpy `.npy` array. `-` reads standard
    /// input.
    pub readings: PathBuf,
    /// Read a raster of single readings whose K × K blocks of cells are the
    /// readings of the stations of a net (x, y the block's centre, z the
    /// cells' values); rows and columns past the last whole block are left
    /// out, with a note.
    #[arg(long, value_name = "K")]
    pub block: Option<u64>,
    /// For a `.npy` raster: the centre of the cell at row 0, column 0.
    #[arg(
        long,
        value_name = "X0,Y0",
        value_delimiter = ',',
        num_args = 1,
        allow_hyphen_values = true
    )]
    pub origin: Option<Vec<f64>>,
    /// For a `.npy` raster: the step in x per column and in y per row (DY
    /// negative when row 0 is the north edge).
    #[arg(
        long,
        value_name = "DX,DY",
        value_delimiter = ',',
        num_args = 1,
        allow_hyphen_values = true
    )]
    pub spacing: Option<Vec<f64>>,
    /// Write the data file here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "DATA.json")]
    pub output: Option<PathBuf>,
    /// The level alpha in [0, 1] to carry into the data file (and so into the
    /// fitted job).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// How readings become fuzzy numbers.
    #[command(flatten)]
    pub rule: ReadingsArgs,
}

/// CAD formats of `t2spline export`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum CadFormatArg {
    /// AutoCAD DXF (R2000): SPLINE entities, one layer per curve.
    Dxf,
    /// STEP (AP214): rational B_SPLINE_CURVE_WITH_KNOTS entities.
    Step,
    /// IGES 5.3: entity 126.
    Iges,
    /// Wavefront OBJ: rational B-spline curves.
    Obj,
}

/// Arguments of `t2spline export`.
#[derive(Debug, Args)]
pub struct ExportArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
    /// The file to write (`-` is standard output).
    #[arg(short, long, value_name = "FILE")]
    pub output: PathBuf,
    /// The format [default: from the extension of FILE: .dxf, .step/.stp,
    /// .iges/.igs, .obj].
    #[arg(long, value_enum)]
    pub format: Option<CadFormatArg>,
    /// The level alpha in [0, 1] of the defuzzified curve; overrides the job
    /// file.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// The unit of the coordinates that the file records (the numbers are
    /// written as they are) [default: the job's `units`, else mm].
    #[arg(long, value_name = "UNIT", value_parser = ["mm", "cm", "m", "in", "ft"])]
    pub units: Option<String>,
    #[command(flatten)]
    pub reduction: ReductionArg,
}

/// Arguments of `t2spline membership`.
#[derive(Debug, Args)]
pub struct MembershipArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
    /// The points: CSV with the header x,y (or x,y,z), one point per row;
    /// `-` reads standard input.
    pub points: PathBuf,
    /// Write the grades here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// The levels of `measure`, `section` and `region`.
#[derive(Debug, Args)]
pub struct LevelsArg {
    /// One level alpha in [0, 1] [default: the job's alpha].
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// N levels equally spaced from 0 to 1 (at least 2) instead of one
    /// [default without --alpha: the job's alpha, else 11 (measure,
    /// section)].
    #[arg(long, value_name = "N", conflicts_with = "alpha")]
    pub levels: Option<u64>,
}

/// Arguments of `t2spline region`.
#[derive(Debug, Args)]
pub struct RegionArgs {
    /// The job file (a curve); `-` reads standard input.
    pub job: PathBuf,
    #[command(flatten)]
    pub levels: LevelsArg,
    /// Write the GeoJSON here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// The largest distance between the outline and the true region [default:
    /// 1e-6 of the diagonal of the crisp control points' bounding box].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
}

/// Arguments of `t2spline section`.
#[derive(Debug, Args)]
pub struct SectionArgs {
    /// The job file; `-` reads standard input.
    pub job: PathBuf,
    /// The station of a plane curve: the vertical line x = X0.
    #[arg(
        long,
        value_name = "X0",
        allow_hyphen_values = true,
        conflicts_with = "at"
    )]
    pub x: Option<f64>,
    /// The station of a surface: the vertical line through (X0, Y0).
    #[arg(long, value_name = "X0,Y0", allow_hyphen_values = true)]
    pub at: Option<String>,
    #[command(flatten)]
    pub levels: LevelsArg,
    /// Write the JSON here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// The largest error of an interval end (plane curves) [default: 1e-6 of
    /// the diagonal of the crisp control points' bounding box].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
}

/// Arguments of `t2spline envelope`.
#[derive(Debug, Args)]
pub struct EnvelopeArgs {
    /// The job file (a surface); `-` reads standard input.
    pub job: PathBuf,
    /// The grid: NX cells along x and NY along y.
    #[arg(long, value_name = "NX,NY")]
    pub grid: String,
    /// The levels: N equally spaced from 0 to 1 (at least 2) [default: 11].
    #[arg(long, value_name = "N", conflicts_with = "alpha")]
    pub levels: Option<u64>,
    /// One level alpha in [0, 1] instead of --levels.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<f64>,
    /// The plan extent of the grid [default: the surface's].
    #[arg(long, value_name = "X0,Y0,X1,Y1", allow_hyphen_values = true)]
    pub extent: Option<String>,
    /// The coordinate reference system of x and y, recorded in a GeoTIFF:
    /// EPSG:CODE, optionally :projected or :geographic (without it, common
    /// geographic codes such as 4326 and 4258 are geographic, others
    /// projected).
    #[arg(long, value_name = "EPSG:CODE")]
    pub crs: Option<String>,
    /// Write the envelope here instead of a CSV table on standard output:
    /// `.tif`/`.tiff` a GeoTIFF, `.csv` or `.parquet` a long table (`-` is
    /// standard output).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// Arguments of `t2spline contour`.
#[derive(Debug, Args)]
pub struct ContourArgs {
    /// The job file (a surface); `-` reads standard input.
    pub job: PathBuf,
    /// The height Z0 whose crossings are traced (e.g. 0, the shoreline).
    #[arg(long, value_name = "Z0", allow_hyphen_values = true)]
    pub z: f64,
    #[command(flatten)]
    pub levels: LevelsArg,
    /// The grid: NX cells along x and NY along y [default: 8 cells per
    /// shortest knot span, 16 to 1024 a side].
    #[arg(long, value_name = "NX,NY")]
    pub grid: Option<String>,
    /// The plan extent of the grid [default: the surface's].
    #[arg(long, value_name = "X0,Y0,X1,Y1", allow_hyphen_values = true)]
    pub extent: Option<String>,
    /// Write the GeoJSON here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "OUT.geojson")]
    pub output: Option<PathBuf>,
}

/// Arguments of `t2spline measure`.
#[derive(Debug, Args)]
pub struct MeasureArgs {
    /// The job file (a curve or a surface of crisp x and y); `-` reads
    /// standard input.
    pub job: PathBuf,
    #[command(flatten)]
    pub levels: LevelsArg,
    /// Curves: parameters at which to measure the derivative, the tangent angle
    /// (plane curves) and the curvature, comma-separated.
    #[arg(long, value_name = "T1,T2,...", allow_hyphen_values = true)]
    pub at: Option<String>,
    /// The order of the derivative at each parameter of --at (1 to 64).
    #[arg(long, value_name = "K", default_value_t = 1)]
    pub order: u64,
    /// Surfaces: the height Z0 of the plane the volumes and the plan area
    /// below are measured from (default 0).
    #[arg(long, value_name = "Z0", allow_hyphen_values = true)]
    pub datum: Option<f64>,
    /// Surfaces: leave out the surface area (a convex minimisation and a
    /// vertex search per level; the volumes cost far less).
    #[arg(long)]
    pub no_area: bool,
    /// Surfaces: a second surface job of the same plan map (the same
    /// degrees, knots, weights and crisp x and y; e.g. the last survey):
    /// adds the cut and fill, the volumes where the job's surface lies above
    /// and below this one.
    #[arg(long, value_name = "JOB2")]
    pub against: Option<PathBuf>,
    /// Write the JSON here instead of standard output (`-` is standard
    /// output).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// Arguments of `t2spline bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// What to time: `crisp` (the crisp curve), `fuzzy` (all seven layer
    /// curves), `sweep` (stages 1–4 at 11 alpha levels, every curve),
    /// `surface` (the crisp surface on a √N × √N grid), `surface-fuzzy` (all
    /// seven layer surfaces on that grid), or `all`.
    #[arg(long, value_name = "CASE", default_value = "all", value_parser = ["crisp", "fuzzy", "sweep", "surface", "surface-fuzzy", "all"])]
    pub case: String,
    /// Parameter values per run (uniform over the domain).
    #[arg(long, value_name = "N", default_value_t = 1_000_000)]
    pub points: u64,
    /// Threads the sampling engine may use (default: one per core).
    #[arg(long, value_name = "T")]
    pub threads: Option<u64>,
    /// Time this job's curve or surface instead of the built-in ones (a
    /// curve of degree 3 with ten points; a bicubic 8 × 8 surface); with
    /// `all`, only the cases of the job's kind run.
    #[arg(long, visible_alias = "job", value_name = "JOB.json")]
    pub curve: Option<PathBuf>,
    /// Write every run into the output arrays of the previous one instead of
    /// fresh ones (times evaluation and stores without the page faults of new
    /// memory); the lines end in `output=reused`.
    #[arg(long)]
    pub reuse: bool,
    /// Time every case both ways in one run, into fresh arrays and then into
    /// reused ones, and print the ratio of the two medians after each pair
    /// (`ratio <case> fresh/reused=<R>`).
    #[arg(long, conflicts_with = "reuse")]
    pub compare: bool,
}
