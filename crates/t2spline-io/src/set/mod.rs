//! The files of the set view (docs/method.md §10): query points read from
//! CSV, their grades written as CSV, regions as GeoJSON, station sections as
//! JSON.

mod geojson;
mod membership_csv;
mod points;
mod section_json;

pub use geojson::{write_region_geojson, RegionFeature};
pub use membership_csv::write_membership_csv;
pub use points::{parse_points, read_points, QueryPoints, MAX_QUERY_POINTS};
pub use section_json::{write_section_json, Station};
