//! The one description of the keys of job and data files (docs/jobs.md) and
//! of the rule texts that more than one reader of the job text uses: the
//! typed one-pass reading ([`valid`](super::valid)), the validator
//! ([`parse`](super::parse), [`common`](super::common),
//! [`point`](super::point), [`surface`](super::surface)) and the scan of the
//! text for NaN and infinity ([`non_finite`](super::non_finite)), which the
//! Python binding uses for a job given as a dict. A key, or the form of a
//! fuzzy number, is taught here once; each reader takes its names, their
//! order (that of the messages' lists of known keys) and its rule words from
//! here, so that no two of them can disagree.
//!
//! A leaf: it imports nothing of the crate.

/// The top-level keys of a job file, curve or surface, in the order of
/// docs/jobs.md (and of the list of known keys in messages).
pub(crate) const TOP_KEYS: &[&str] = &[
    "description",
    "order",
    "degree",
    "weights",
    "knots",
    "alpha",
    "type_reduction",
    "lower_height",
    "samples",
    "closed",
    "units",
    "points",
];

/// The top-level keys of a data file for `t2spline fit`: those of a job but
/// `closed`, `units` and the two the fit computes ([`FIT_MAKES`]).
pub(crate) const DATA_KEYS: &[&str] = &[
    "description",
    "order",
    "degree",
    "alpha",
    "type_reduction",
    "lower_height",
    "samples",
    "points",
];

/// The keys of a job that a data file may not have: the fit makes them.
pub(crate) const FIT_MAKES: &[&str] = &["weights", "knots"];

/// Why a data file may not give [`FIT_MAKES`].
pub(crate) const FIT_MAKES_RULE: &str =
    "not allowed in a data file: the fit makes the weights (all 1) and the knots";

/// The keys of a point, one per axis, in the order x, y, z.
pub(crate) const POINT_KEYS: [&str; 3] = ["x", "y", "z"];

/// The keys of a fuzzy number in the form of docs/method.md §1: the
/// [`FUZZY_NUMBER_REQUIRED`] required ones first (`crisp`, then the pairs
/// `[left, right]` of the upper, primary and lower membership functions),
/// then its own `lower_height`, optional. A bare number stands for a crisp
/// number.
pub(crate) const FUZZY_NUMBER_KEYS: [&str; 5] =
    ["crisp", "upper", "primary", "lower", "lower_height"];

/// How many of [`FUZZY_NUMBER_KEYS`], from the first, every fuzzy number
/// given as an object must have.
pub(crate) const FUZZY_NUMBER_REQUIRED: usize = 4;

/// What a fuzzy number is, for a message about a value of another type.
pub(crate) const FUZZY_NUMBER_EXPECTED: &str =
    "a fuzzy number (a JSON object, or a number for a crisp one)";

/// The keys of a surface's `knots`, one per direction.
pub(crate) const KNOT_DIRECTIONS: [&str; 2] = ["u", "v"];

/// How a closed curve closes, for the message of one that does not
/// (docs/method.md §11).
pub(crate) const CLOSURE_RULE: &str = "a closed curve with clamped knots repeats its first control point as its last; with periodic knots (the first 2p spans as long as the last 2p) its last p points repeat its first p";

/// Why NaN and infinity, which JSON cannot hold but `json.dumps` and other
/// writers put in its place as the words `NaN`, `Infinity` and `-Infinity`,
/// are refused wherever a number belongs.
pub(crate) const NOT_FINITE_RULE: &str = "is not a finite number (NaN and infinity are refused)";
