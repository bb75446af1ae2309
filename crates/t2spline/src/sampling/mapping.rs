//! Large sample buffers on Linux: anonymous mappings at 2 MiB boundaries,
//! advised to use transparent huge pages, and a small cache of the mappings
//! of dropped buffers for the next large output.
//!
//! A fresh anonymous mapping is zero, and the system zeroes each page when it
//! is first touched: for a huge page, 2 MiB at once. That zeroing is the
//! floor of a first write into new memory (about as long as writing the
//! samples themselves, measured in docs/performance.md), so the mappings of
//! dropped buffers are kept, up to [`CACHE_BYTES`] in all, and handed to the
//! next output that fits: its pages are then resident, and the engine
//! overwrites every value. A cached mapping is never handed out as zeros
//! ([`Mapping::zeroed`] always maps anew).

use std::sync::Mutex;

use super::memory::CACHE_BYTES;

/// The size of a transparent huge page on x86-64 and (with 4 KiB base
/// pages) aarch64.
pub(crate) const HUGE_PAGE: usize = 2 << 20;

/// The mappings of dropped buffers, most recent last.
static CACHE: Mutex<Vec<Mapping>> = Mutex::new(Vec::new());

/// A mapping with room for `capacity` values from byte `start` (a 2 MiB
/// boundary).
pub(crate) struct Mapping {
    map: memmap2::MmapMut,
    start: usize,
    capacity: usize,
}

impl Mapping {
    /// A zero mapping with room for `n` values at a 2 MiB boundary, advised
    /// to use huge pages; `None` if the system refuses it.
    pub(crate) fn zeroed(n: usize) -> Option<Mapping> {
        let bytes = n
            .checked_mul(size_of::<f64>())?
            .checked_next_multiple_of(HUGE_PAGE)?;
        // One huge page more, to start at a 2 MiB boundary wherever the
        // system places the mapping; pages never touched cost no memory.
        let map = memmap2::MmapMut::map_anon(bytes.checked_add(HUGE_PAGE)?).ok()?;
        let address = map.as_ptr() as usize;
        let start = address.next_multiple_of(HUGE_PAGE) - address;
        // Advice only: where huge pages are off it is ignored (or refused
        // with an error, which changes nothing either).
        let _ = map.advise_range(memmap2::Advice::HugePage, start, bytes);
        Some(Mapping {
            map,
            start,
            capacity: bytes / size_of::<f64>(),
        })
    }

    /// A mapping with room for `n` values whose contents the caller
    /// overwrites: the smallest cached one that fits without wasting more
    /// than half again as much, else a new one.
    pub(crate) fn for_overwrite(n: usize) -> Option<Mapping> {
        let fits = |m: &Mapping| m.capacity >= n && m.capacity - n <= n / 2 + HUGE_PAGE / 8;
        if let Ok(mut cache) = CACHE.lock() {
            let best = cache
                .iter()
                .enumerate()
                .filter(|(_, m)| fits(m))
                .min_by_key(|(_, m)| m.capacity)
                .map(|(i, _)| i);
            if let Some(i) = best {
                return Some(cache.swap_remove(i));
            }
        }
        Mapping::zeroed(n)
    }

    /// Keeps this mapping for a later output, dropping the oldest cached
    /// ones beyond [`CACHE_BYTES`] (a mapping larger than that is unmapped).
    pub(crate) fn recycle(self) {
        let Ok(mut cache) = CACHE.lock() else {
            return; // A poisoned cache is not used: the mapping is unmapped.
        };
        cache.push(self);
        let mut kept = 0;
        let mut keep = cache.len();
        for (i, m) in cache.iter().enumerate().rev() {
            kept += m.map.len();
            if kept > CACHE_BYTES {
                break;
            }
            keep = i;
        }
        // `keep` is the first mapping that fits; the older ones go.
        drop(cache.drain(..keep));
    }

    /// Room, in values.
    pub(crate) fn capacity(&self) -> usize {
        self.capacity
    }

    /// The first `len` values (`len ≤ capacity`).
    pub(crate) fn values(&self, len: usize) -> &[f64] {
        let end = self.start + len * size_of::<f64>();
        bytemuck::cast_slice(&self.map[self.start..end])
    }

    /// The first `len` values, to write (`len ≤ capacity`).
    pub(crate) fn values_mut(&mut self, len: usize) -> &mut [f64] {
        let end = self.start + len * size_of::<f64>();
        bytemuck::cast_slice_mut(&mut self.map[self.start..end])
    }
}

/// Unmaps every cached mapping.
pub(crate) fn release() {
    let taken = CACHE.lock().map(|mut c| std::mem::take(&mut *c));
    drop(taken);
}

/// The bytes cached now (for the tests).
#[cfg(test)]
pub(crate) fn cached_bytes() -> usize {
    CACHE
        .lock()
        .map_or(0, |c| c.iter().map(|m| m.map.len()).sum())
}
