//! The memory samples are written into: an ordinary vector for small outputs,
//! and on Linux an anonymous mapping advised to use transparent huge pages
//! for large ones.
//!
//! Fresh output memory costs a page fault on first write, one per 4 KiB page:
//! 24 MB of a surface's three coordinates at 10⁶ points are 6 000 faults,
//! which took three times as long as computing the values. A large buffer
//! ([`LARGE_BYTES`] or more) is therefore mapped on its own
//! (`mmap(MAP_PRIVATE | MAP_ANONYMOUS)` through `memmap2`) at a 2 MiB
//! boundary, rounded up to whole 2 MiB pages, and advised with
//! `madvise(MADV_HUGEPAGE)` (`mapping.rs`): where the system offers
//! transparent huge pages (`/sys/kernel/mm/transparent_hugepage/enabled` set
//! to `always` or `madvise`) one fault then maps 2 MiB, and where it does not
//! the advice is ignored and the buffer behaves as an ordinary allocation.
//! Nothing is written before the engine writes: each page is first touched
//! by the thread that fills it, with no zero-filling pass. The mappings of
//! dropped buffers are kept for the next large output, up to
//! [`CACHE_BYTES`](super::memory::CACHE_BYTES) (`mapping.rs` says why);
//! [`release_cached_memory`] returns them. Elsewhere than Linux, and below
//! [`LARGE_BYTES`], a buffer is a `Vec<f64>` from the global allocator.
//!
//! There is no `unsafe` here: `memmap2` maps and advises, `bytemuck` sees the
//! page-aligned bytes as `f64`s (every bit pattern is a valid `f64`).

use std::fmt;
use std::ops::{Deref, DerefMut};

#[cfg(target_os = "linux")]
use crate::sampling::mapping::Mapping;

/// Buffers of at least this many bytes (4 MiB, 2¹⁹ values) are mapped with
/// huge pages on Linux; smaller ones are ordinary vectors. The mapping is
/// rounded up to whole 2 MiB pages, so a buffer at this size wastes at most a
/// third of its memory, and a page table of its own pays from about here.
pub const LARGE_BYTES: usize = 4 << 20;

/// Where the fresh output of a sampling call comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Fresh {
    /// Ordinary vectors (what a caller converts to `Vec<f64>` for free).
    Vectors,
    /// Large buffers mapped with huge pages where the system offers them.
    HugePages,
}

/// One channel of samples: a slice of `f64` that owns its memory, as a
/// `Vec<f64>` does (it dereferences to `[f64]`), held either in an ordinary
/// vector or, for large outputs on Linux, in a mapping with transparent huge
/// pages (see the module's documentation). Which of the two is invisible to
/// the values.
///
/// # Examples
/// ```
/// # use t2spline::sampling::SampleBuffer;
/// let b = SampleBuffer::from(vec![1.0, 2.0]);
/// assert_eq!(&b[..], [1.0, 2.0]);
/// assert_eq!(b.iter().sum::<f64>(), 3.0);
/// assert_eq!(b.into_vec(), vec![1.0, 2.0]);
/// ```
pub struct SampleBuffer {
    memory: Memory,
}

enum Memory {
    Vector(Vec<f64>),
    /// The first `len` values of a mapping.
    #[cfg(target_os = "linux")]
    Mapped {
        mapping: Mapping,
        len: usize,
    },
}

impl SampleBuffer {
    /// An empty buffer (allocates nothing).
    #[must_use]
    pub fn new() -> Self {
        SampleBuffer::from(Vec::new())
    }

    /// `n` zeros, in a mapping with huge pages when they take at least
    /// [`LARGE_BYTES`] on Linux (as the sampling calls allocate), else in a
    /// zeroed vector. Nothing is written: the pages are first touched by
    /// whoever writes them.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::sampling::{SampleBuffer, LARGE_BYTES};
    /// let small = SampleBuffer::zeros(10);
    /// assert!(!small.is_mapped() && small.iter().all(|&x| x == 0.0));
    /// let large = SampleBuffer::zeros(LARGE_BYTES / 8);
    /// assert_eq!(large.is_mapped(), cfg!(target_os = "linux"));
    /// assert!(large.iter().all(|&x| x == 0.0));
    /// ```
    #[must_use]
    pub fn zeros(n: usize) -> Self {
        #[cfg(target_os = "linux")]
        if is_large(n) {
            if let Some(mapping) = Mapping::zeroed(n) {
                return SampleBuffer {
                    memory: Memory::Mapped { mapping, len: n },
                };
            }
        }
        SampleBuffer::from(vec![0.0; n])
    }

    /// `n` values for a caller that overwrites every one (as the sampling
    /// engine does): [`SampleBuffer::zeros`], except that a large buffer may
    /// be the mapping of a dropped one, holding its old values (any `f64`).
    /// For the `_into_slices` sampling calls.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::sampling::{benchmark_curve, Params, SampleBuffer};
    /// let c = benchmark_curve();
    /// let n = 1_000_000;
    /// let mut buffer = SampleBuffer::for_overwrite(7 * 2 * n);
    /// let mut out: Vec<&mut [f64]> = buffer.chunks_mut(n).collect();
    /// c.sample_layers_into_slices(Params::Uniform(n), &mut out)?;
    /// assert!((buffer[0] + 0.3).abs() < 1e-12); // x of upper_left at t = 0: c − 0.3, c = 0
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn for_overwrite(n: usize) -> Self {
        SampleBuffer::fresh(n, Fresh::HugePages)
    }

    /// `n` values from `fresh`, for the engine to overwrite: with
    /// `Fresh::HugePages` a large buffer is a mapping (cached or new),
    /// anything else a zeroed vector.
    pub(crate) fn fresh(n: usize, fresh: Fresh) -> Self {
        #[cfg(target_os = "linux")]
        if fresh == Fresh::HugePages && is_large(n) {
            if let Some(mapping) = Mapping::for_overwrite(n) {
                return SampleBuffer {
                    memory: Memory::Mapped { mapping, len: n },
                };
            }
        }
        let _ = fresh;
        SampleBuffer::from(vec![0.0; n])
    }

    /// This buffer made `n` values long for the engine to overwrite, keeping
    /// its memory where it has room (values it held stay, new ones are
    /// zero). Without room it is replaced by [`SampleBuffer::fresh`] (an
    /// empty buffer is the common case): growing would copy values the
    /// engine overwrites and zero the rest on one thread.
    pub(crate) fn resize(&mut self, n: usize, fresh: Fresh) {
        match &mut self.memory {
            Memory::Vector(v) if n <= v.capacity() => v.resize(n, 0.0),
            #[cfg(target_os = "linux")]
            Memory::Mapped { mapping, len } if n <= mapping.capacity() => *len = n,
            _ => *self = SampleBuffer::fresh(n, fresh),
        }
    }

    /// Whether the values live in a mapping advised to use huge pages (false
    /// for small buffers, and always false elsewhere than Linux).
    #[must_use]
    pub fn is_mapped(&self) -> bool {
        match self.memory {
            Memory::Vector(_) => false,
            #[cfg(target_os = "linux")]
            Memory::Mapped { .. } => true,
        }
    }

    /// The values as a vector: without a copy for an ordinary vector, copied
    /// out of a mapping.
    #[must_use]
    pub fn into_vec(mut self) -> Vec<f64> {
        match &mut self.memory {
            Memory::Vector(v) => std::mem::take(v),
            #[cfg(target_os = "linux")]
            Memory::Mapped { .. } => self.to_vec(),
        }
    }
}

/// Whether `n` values make a large buffer ([`LARGE_BYTES`] or more).
#[cfg(target_os = "linux")]
fn is_large(n: usize) -> bool {
    n.saturating_mul(size_of::<f64>()) >= LARGE_BYTES
}

/// Returns the memory that the mappings of dropped sample buffers keep for
/// reuse (at most [`CACHE_BYTES`](super::memory::CACHE_BYTES)) to the
/// system; the next large output is then mapped anew. Does nothing where
/// buffers are ordinary vectors (elsewhere than Linux).
///
/// # Examples
/// ```
/// # use t2spline::sampling::{benchmark_curve, release_cached_memory, Params};
/// drop(benchmark_curve().sample_layers(Params::Uniform(1_000_000))?); // 112 MB, kept
/// release_cached_memory(); // unmapped
/// # Ok::<(), t2spline::Error>(())
/// ```
pub fn release_cached_memory() {
    #[cfg(target_os = "linux")]
    crate::sampling::mapping::release();
}

impl Default for SampleBuffer {
    fn default() -> Self {
        SampleBuffer::new()
    }
}

impl From<Vec<f64>> for SampleBuffer {
    /// Takes the vector without copying it.
    fn from(v: Vec<f64>) -> Self {
        SampleBuffer {
            memory: Memory::Vector(v),
        }
    }
}

impl Deref for SampleBuffer {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        match &self.memory {
            Memory::Vector(v) => v,
            #[cfg(target_os = "linux")]
            Memory::Mapped { mapping, len } => mapping.values(*len),
        }
    }
}

impl DerefMut for SampleBuffer {
    fn deref_mut(&mut self) -> &mut [f64] {
        match &mut self.memory {
            Memory::Vector(v) => v,
            #[cfg(target_os = "linux")]
            Memory::Mapped { mapping, len } => mapping.values_mut(*len),
        }
    }
}

impl AsRef<[f64]> for SampleBuffer {
    fn as_ref(&self) -> &[f64] {
        self
    }
}

impl AsMut<[f64]> for SampleBuffer {
    fn as_mut(&mut self) -> &mut [f64] {
        self
    }
}

impl<'a> IntoIterator for &'a SampleBuffer {
    type Item = &'a f64;
    type IntoIter = std::slice::Iter<'a, f64>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl Drop for SampleBuffer {
    /// Keeps a mapping for the next large output (see `mapping.rs`).
    fn drop(&mut self) {
        #[cfg(target_os = "linux")]
        if let Memory::Mapped { mapping, .. } =
            std::mem::replace(&mut self.memory, Memory::Vector(Vec::new()))
        {
            mapping.recycle();
        }
    }
}

impl Clone for SampleBuffer {
    /// A buffer of the same kind (mapped or not) holding the same values.
    fn clone(&self) -> Self {
        let fresh = if self.is_mapped() {
            Fresh::HugePages
        } else {
            Fresh::Vectors
        };
        let mut copy = SampleBuffer::fresh(self.len(), fresh);
        copy.copy_from_slice(self);
        copy
    }
}

impl PartialEq for SampleBuffer {
    /// Equal values (however they are held).
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl PartialEq<[f64]> for SampleBuffer {
    fn eq(&self, other: &[f64]) -> bool {
        **self == *other
    }
}

impl PartialEq<Vec<f64>> for SampleBuffer {
    fn eq(&self, other: &Vec<f64>) -> bool {
        **self == **other
    }
}

impl fmt::Debug for SampleBuffer {
    /// The values, as a `Vec<f64>` prints them.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&**self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2²⁰ values (8 MB): large.
    const N: usize = 1 << 20;

    #[test]
    fn small_buffers_are_vectors_and_large_ones_mapped_on_linux() {
        assert!(!SampleBuffer::fresh(1000, Fresh::HugePages).is_mapped());
        assert!(!SampleBuffer::fresh(N, Fresh::Vectors).is_mapped());
        assert!(!SampleBuffer::zeros(1000).is_mapped());
        let large = SampleBuffer::zeros(N);
        assert_eq!(large.is_mapped(), cfg!(target_os = "linux"));
        assert_eq!(large.len(), N);
        assert!(large.iter().all(|&x| x == 0.0));
        // At a 2 MiB boundary, so that huge pages can back it from the start.
        #[cfg(target_os = "linux")]
        assert_eq!(
            large.as_ptr() as usize % crate::sampling::mapping::HUGE_PAGE,
            0
        );
    }

    #[test]
    fn a_mapped_buffer_holds_what_is_written_and_converts_to_a_vector() {
        let mut b = SampleBuffer::fresh(N + 3, Fresh::HugePages);
        for (i, x) in b.iter_mut().enumerate() {
            *x = i as f64 * 0.5;
        }
        let copy = b.clone();
        assert_eq!(copy.is_mapped(), b.is_mapped());
        assert_eq!(copy, b);
        let v = b.into_vec();
        assert_eq!(v.len(), N + 3);
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as f64 * 0.5));
        assert_eq!(copy, v);
    }

    #[test]
    fn resizing_keeps_memory_while_it_has_room() {
        let mut b = SampleBuffer::fresh(N, Fresh::HugePages);
        let at = b.as_ptr();
        b[N - 1] = 7.0;
        b.resize(N - 10, Fresh::HugePages);
        assert_eq!((b.len(), b.as_ptr()), (N - 10, at));
        b.resize(3 * N, Fresh::HugePages);
        assert_eq!(b.len(), 3 * N);
        // A vector with room keeps its values and memory; without, it is
        // replaced: by a mapping when large.
        let mut v = SampleBuffer::from(Vec::with_capacity(5));
        v.resize(3, Fresh::HugePages);
        v.copy_from_slice(&[1.0; 3]);
        let at = v.as_ptr();
        v.resize(5, Fresh::HugePages);
        assert_eq!((v.as_ptr(), v.is_mapped()), (at, false));
        assert_eq!(v, vec![1.0, 1.0, 1.0, 0.0, 0.0]);
        v.resize(6, Fresh::HugePages);
        assert_eq!(v, vec![0.0; 6]);
        let mut empty = SampleBuffer::new();
        empty.resize(N, Fresh::HugePages);
        assert_eq!(empty.is_mapped(), cfg!(target_os = "linux"));
        empty.resize(2 * N, Fresh::Vectors);
        assert!(!empty.is_mapped());
    }

    #[test]
    fn threads_fill_disjoint_parts_of_one_mapped_buffer() {
        let mut b = SampleBuffer::fresh(N, Fresh::HugePages);
        std::thread::scope(|s| {
            for (k, chunk) in b.chunks_mut(N / 4 + 1).enumerate() {
                s.spawn(move || chunk.iter_mut().for_each(|x| *x = k as f64));
            }
        });
        assert!(b
            .iter()
            .enumerate()
            .all(|(i, &x)| x == (i / (N / 4 + 1)) as f64));
        // And the buffer moves to another thread and is dropped there.
        std::thread::spawn(move || assert_eq!(b.len(), N))
            .join()
            .unwrap();
    }

    /// Other tests of this binary map and drop buffers at the same time, so
    /// this one looks for its own mapping by address and size only.
    #[cfg(target_os = "linux")]
    #[test]
    fn dropped_mappings_are_reused_for_overwriting_never_as_zeros() {
        use crate::sampling::mapping::cached_bytes;
        // An odd size no other test asks for.
        let n = 5 * N + 12_345;
        let mut b = SampleBuffer::fresh(n, Fresh::HugePages);
        b.fill(3.0);
        let at = b.as_ptr();
        drop(b);
        assert!(cached_bytes() >= n * 8);
        // Zeros are always new memory.
        let z = SampleBuffer::zeros(n);
        assert!(z.iter().all(|&x| x == 0.0));
        assert_ne!(z.as_ptr(), at);
        // A buffer to overwrite may be the dropped one (unless another test
        // took it first), with its values.
        let again = SampleBuffer::for_overwrite(n);
        if again.as_ptr() == at {
            assert!(again.iter().all(|&x| x == 3.0));
        }
        drop(again);
        release_cached_memory();
        // More than the cache holds is unmapped on drop.
        let huge = SampleBuffer::fresh(super::super::memory::CACHE_BYTES / 8 + 1, Fresh::HugePages);
        drop(huge);
        assert!(cached_bytes() <= super::super::memory::CACHE_BYTES);
    }
}
