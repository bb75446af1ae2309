//! Readings files: repeated measurements of stations, one reading per row, as
//! a spreadsheet exports them.
//!
//! ```text
//! station,x,y            (or station,x,y,z)
//! dune crest,0.118,6.02
//! dune crest,-0.07,5.987
//! …
//! ```
//!
//! Rules, each reported with its line and column (all problems at once, as
//! for job files):
//! - the header is `station,x,y` or `station,x,y,z` (any case, spaces
//!   around names ignored); the separator is a comma or a semicolon, decided
//!   by the header; in a semicolon file a decimal comma (`1,25`) is read as
//!   a decimal point, as spreadsheets in many locales write numbers;
//! - every row has exactly the header's columns; values are finite numbers
//!   within [`MAX_MAGNITUDE`](t2spline::MAX_MAGNITUDE);
//! - the rows of a station may stand anywhere (a log in time order
//!   interleaves stations); stations come in the order of their first row
//!   and become the data points in that order, each with its readings in
//!   file order, so a file gives what the same file sorted by station gives;
//! - every station has at least [`MIN_READINGS`] readings;
//! - CRLF or LF line ends, a UTF-8 byte-order mark and RFC 4180 quoting
//!   (`"dune, crest"`, `"1,25"`) are accepted.
//!
//! Limits, checked before the memory they guard is allocated: the file size
//! of job files ([`MAX_FILE_BYTES`](crate::job::MAX_FILE_BYTES)),
//! [`MAX_ROWS`] readings (rows after the header, blank lines not counted;
//! splitting stops at the first row past the limit) and
//! [`MAX_POINTS`](crate::job::MAX_POINTS) stations.
//! The statistics that turn readings into fuzzy numbers are the core's
//! ([`t2spline::fit::fuzzify`]); this module only reads.

// The input decides the indices here: no indexing that can panic (`get`,
// iterators, `split_first`), as ARCHITECTURE.md explains.
#![cfg_attr(not(test), deny(clippy::indexing_slicing))]

mod curve;
mod data;
mod fields;
mod net;
mod npy;
mod options;
mod raster;
pub(crate) mod tokens;

pub use curve::{is_readings, parse_readings, read_readings, ReadingsFile};
pub use data::{data_json, data_json_text};
pub use fields::MAX_ROWS;
pub use net::{parse_net_readings, NetReadings, StationSource};
pub use npy::{parse_npy, read_npy, MAX_NPY_BYTES};
pub use options::{
    fuzzify_net, fuzzify_readings, ReadingsError, ReadingsOption, ReadingsOptions, DEFAULT_DEGREE,
};
pub use raster::{parse_ascii_grid, parse_grid_csv, Raster, RasterGeometry, MAX_RASTER_CELLS};
