//! The report's data block: JSON compressed with zlib (RFC 1950) and written
//! as base64, which the page decompresses with the browser's own
//! `DecompressionStream("deflate")`. Figure parts and number texts compress
//! to a quarter or less, so a report holds four times as many stops.

use base64::Engine as _;
use serde_json::Value;

/// `value` as JSON, compressed and in base64.
#[must_use]
pub fn pack(value: &Value) -> String {
    let json = value.to_string();
    let compressed = miniz_oxide::deflate::compress_to_vec_zlib(json.as_bytes(), 6);
    base64::engine::general_purpose::STANDARD.encode(compressed)
}

/// The bytes [`pack`] adds for `value`: an estimate of its cost in a report.
#[must_use]
pub fn packed_len(value: &Value) -> usize {
    let json = value.to_string();
    miniz_oxide::deflate::compress_to_vec_zlib(json.as_bytes(), 6).len() * 4 / 3
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_data_decompress_to_the_json() {
        let v = serde_json::json!({"a": [1.5, 2.5], "s": "x".repeat(1000)});
        let text = pack(&v);
        assert!(text.len() < 200, "{}", text.len());
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(&text)
            .unwrap();
        let json = miniz_oxide::inflate::decompress_to_vec_zlib(&bytes).unwrap();
        assert_eq!(serde_json::from_slice::<Value>(&json).unwrap(), v);
        assert!(packed_len(&v) >= text.len() - 4);
    }
}
