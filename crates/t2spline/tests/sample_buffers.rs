//! Large outputs in huge-page mappings (`SampleBuffer`): the same bytes as
//! ordinary vectors, on one and on two threads, fresh and reused, for curves
//! and surfaces; small outputs stay ordinary vectors.

use t2spline::sampling::{
    benchmark_curve, benchmark_surface, CurveSamples, Grid, LayerSamples, Params, SampleBuffer,
    LARGE_BYTES,
};
use t2spline::Layer;

/// Enough parameters for one coordinate to be a large buffer.
const N: usize = LARGE_BYTES / 8 + 1000;

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
}

/// Bit patterns, so that `-0.0` and `0.0` differ and NaN equals itself.
fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn a_large_crisp_curve_is_mapped_and_identical_to_vectors_on_any_threads() {
    let curve = benchmark_curve().crisp_curve();
    // The reference: ordinary vectors from the sampler, on one thread.
    let reference = pool(1)
        .install(|| curve.sampler().sample(Params::Uniform(N)))
        .unwrap();
    for threads in [1, 2] {
        let fresh = pool(threads)
            .install(|| curve.sample_soa(Params::Uniform(N)))
            .unwrap();
        for (d, expected) in reference.iter().enumerate() {
            assert_eq!(fresh.coords()[d].is_mapped(), cfg!(target_os = "linux"));
            assert_eq!(bits(fresh.coord(d)), bits(expected), "threads = {threads}");
        }
        // Reused: the same mapping, the same bytes; then a shorter job that
        // fits in it, and the small one a vector would hold.
        let mut out = fresh;
        let addresses = |s: &CurveSamples<2>| {
            let mut at: Vec<*const f64> = s.coords().iter().map(|c| c.as_ptr()).collect();
            at.sort();
            at
        };
        let at = addresses(&out);
        pool(threads)
            .install(|| curve.sample_soa_into(Params::Uniform(N), &mut out))
            .unwrap();
        assert_eq!(addresses(&out), at);
        assert_eq!(bits(out.coord(1)), bits(&reference[1]));
        pool(threads)
            .install(|| curve.sample_soa_into(Params::Uniform(N - 7), &mut out))
            .unwrap();
        let shorter = curve.sampler().sample(Params::Uniform(N - 7)).unwrap();
        assert_eq!(bits(out.coord(0)), bits(&shorter[0]));
    }
    let small = curve.sample_soa(Params::Uniform(1000)).unwrap();
    assert!(small.coords().iter().all(|c| !c.is_mapped()));
}

#[test]
fn seven_large_layers_are_the_bytes_of_the_slices_version() {
    let curve = benchmark_curve();
    let d = 2;
    let mut buffer = vec![0.0; 7 * d * N];
    {
        let mut out: Vec<&mut [f64]> = buffer.chunks_mut(N).collect();
        pool(1)
            .install(|| curve.sample_layers_into_slices(Params::Uniform(N), &mut out))
            .unwrap();
    }
    for threads in [1, 2] {
        let fresh = pool(threads)
            .install(|| curve.sample_layers(Params::Uniform(N)))
            .unwrap();
        let mut reused = LayerSamples::empty();
        pool(threads)
            .install(|| curve.sample_layers_into(Params::Uniform(N), &mut reused))
            .unwrap();
        for (k, layer) in Layer::ALL.into_iter().enumerate() {
            for axis in 0..d {
                let expected = bits(&buffer[(k * d + axis) * N..][..N]);
                assert_eq!(bits(fresh[layer].coord(axis)), expected, "{layer:?}");
                assert_eq!(bits(reused[layer].coord(axis)), expected, "{layer:?}");
            }
        }
    }
}

#[test]
fn a_large_surface_grid_is_mapped_and_identical_to_vectors_on_any_threads() {
    let surface = benchmark_surface();
    let crisp = surface.crisp_surface();
    let side = Params::Uniform(800); // 640 000 points: 5.1 MB per coordinate
    let reference = pool(1)
        .install(|| crisp.grid_sampler().sample(side, side))
        .unwrap();
    let mut layers_reference = vec![SampleBuffer::new(); 21];
    {
        let mut out: Vec<&mut [f64]> = layers_reference
            .iter_mut()
            .map(|b| {
                *b = SampleBuffer::zeros(800 * 800);
                &mut **b
            })
            .collect();
        pool(1)
            .install(|| surface.sample_layers_into_slices(side, side, &mut out))
            .unwrap();
    }
    for threads in [1, 2] {
        let fresh = pool(threads)
            .install(|| crisp.sample_grid(side, side))
            .unwrap();
        let mut reused = Grid::buffer(CurveSamples::empty());
        pool(threads)
            .install(|| crisp.sample_grid_into(side, side, &mut reused))
            .unwrap();
        for (axis, expected) in reference.iter().enumerate() {
            assert_eq!(
                fresh.samples().coords()[axis].is_mapped(),
                cfg!(target_os = "linux")
            );
            assert_eq!(bits(fresh.samples().coord(axis)), bits(expected));
            assert_eq!(bits(reused.samples().coord(axis)), bits(expected));
        }
        let layers = pool(threads)
            .install(|| surface.sample_layers(side, side))
            .unwrap();
        for (k, layer) in Layer::ALL.into_iter().enumerate() {
            for axis in 0..3 {
                assert_eq!(
                    bits(layers.samples()[layer].coord(axis)),
                    bits(&layers_reference[k * 3 + axis]),
                    "{layer:?}, threads = {threads}"
                );
            }
        }
    }
}

#[test]
fn the_slices_version_of_surface_layers_checks_its_slices() {
    let surface = benchmark_surface();
    let mut buffer = vec![0.0; 20 * 6];
    let mut out: Vec<&mut [f64]> = buffer.chunks_mut(6).collect();
    let e = surface
        .sample_layers_into_slices(Params::Uniform(2), Params::Uniform(3), &mut out)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "output slices (one per coordinate of each layer): expected 21, got 20"
    );
}
