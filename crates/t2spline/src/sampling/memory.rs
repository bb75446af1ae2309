//! The memory limits of the sampling engine.

/// The most memory the mappings of dropped sample buffers keep for reuse
/// (Linux; 256 MiB: the 21 coordinates of a fuzzy surface's seven layers at
/// 10⁶ points are 168 MB); [`release_cached_memory`](super::buffer::release_cached_memory) returns it.
pub const CACHE_BYTES: usize = 256 << 20;
/// The most memory the output arrays of one request to the engine may take,
/// in bytes (8 GiB): the front ends refuse the points asked for before
/// anything is allocated when the output would need more.
pub const MAX_OUTPUT_BYTES: u64 = 8 << 30;
