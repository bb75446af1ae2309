//! The files of the set view (docs/method.md §10): query points read from
//! CSV, their grades written as CSV, regions as GeoJSON, station sections as
//! JSON; a surface's envelope (§12) as a table and as a GeoTIFF, its fuzzy
//! contour (§13) as GeoJSON.

mod contour_geojson;
mod envelope_table;
mod geojson;
mod geotiff;
mod membership_csv;
mod points;
mod section_json;

pub use contour_geojson::write_contour_geojson;
#[cfg(feature = "parquet")]
pub use envelope_table::write_envelope_parquet;
pub use envelope_table::{membership_name, write_envelope_csv, ENVELOPE_COLUMNS};
pub use geojson::{write_region_geojson, RegionFeature};
pub use geotiff::{write_envelope_geotiff, Crs, CrsKind, GEOGRAPHIC_CODES};
pub use membership_csv::write_membership_csv;
pub use points::{parse_points, read_points, QueryPoints, MAX_QUERY_POINTS};
pub use section_json::{write_section_json, Station};
