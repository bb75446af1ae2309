"""Large samples in the engine's own memory: numpy arrays that view a
huge-page mapping on Linux (owned through the array's base), writable, alive
as long as any view is, never shared by two results, and the same numbers as
small samples of the same parameters."""

from __future__ import annotations

import gc
import os
import sys

import numpy as np

import t2spline

LINUX = sys.platform.startswith("linux")


def owner(a: np.ndarray) -> object:
    """The object at the end of an array's chain of bases."""
    base: object = a
    while isinstance(base, np.ndarray) and base.base is not None:
        base = base.base
    return base


def test_a_large_curve_sample_views_the_engines_mapping() -> None:
    c = t2spline.benchmark_curve()
    n = 400_000  # 7 layers × 2 coordinates × 3.2 MB
    s = c.sample(n)
    crisp = s["crisp"]
    assert crisp.shape == (n, 2) and crisp.dtype == np.float64
    kind = type(owner(crisp)).__name__
    assert kind == ("_SampleMemory" if LINUX else "ndarray"), kind
    # All seven layers are views of one buffer.
    assert owner(s["upper_left"]) is owner(s["upper_right"])
    # The same numbers as a small sample at some of the same parameters
    # (more than the curve's 7 spans, so that both use the power form).
    at = np.unique(np.r_[0, 1, 1234, np.linspace(0, n - 1, 50).astype(int)])
    few = c.sample(s["params"][at])
    for layer in ["upper_left", "primary_left", "crisp", "lower_right", "upper_right"]:
        np.testing.assert_array_equal(s[layer][at], few[layer])
    # Writable, and alive while a view is.
    upper = s["upper_left"]
    del s, crisp
    gc.collect()
    upper[0, 0] = 5.0
    assert upper[0, 0] == 5.0
    assert np.isfinite(upper[1:]).all()


def test_results_never_share_memory_and_dropped_memory_is_refilled() -> None:
    c = t2spline.benchmark_curve().crisp_curve()
    n = 1_000_000  # 8 MB per coordinate
    first = c.sample(n)
    second = c.sample(n)
    assert not np.shares_memory(first, second)
    np.testing.assert_array_equal(first, second)
    expected = first.copy()
    first[:] = np.nan
    del first
    gc.collect()
    # A new result may take the dropped mapping: every value is written again.
    third = c.sample(n)
    np.testing.assert_array_equal(third, expected)
    np.testing.assert_array_equal(second, expected)


def test_a_large_surface_grid_views_the_engines_mapping() -> None:
    s = t2spline.benchmark_surface()
    g = s.sample(800, 800)  # 7 layers × 3 coordinates × 5.1 MB
    crisp = g["crisp"]
    assert crisp.shape == (800, 800, 3)
    kind = type(owner(crisp)).__name__
    assert kind == ("_SampleMemory" if LINUX else "ndarray"), kind
    a, b = np.array([0, 17, 799]), np.array([0, 401, 799])
    few = s.sample(g["u"][a], g["v"][b])
    for layer in ["upper_left", "crisp", "upper_right"]:
        np.testing.assert_array_equal(g[layer][np.ix_(a, b)], few[layer])
    flat = s.crisp_surface().sample(800, 800)
    np.testing.assert_array_equal(flat, crisp)


def resident_bytes() -> int:
    """This process's resident memory (Linux: /proc/self/statm)."""
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    return pages * os.sysconf("SC_PAGE_SIZE")


def test_dropped_samples_are_kept_until_released() -> None:
    if not LINUX:
        t2spline.release_cached_memory()  # does nothing elsewhere
        return
    t2spline.release_cached_memory()
    before = resident_bytes()
    layers = t2spline.benchmark_curve().sample(1_000_000)  # 112 MB of samples
    grown = resident_bytes()
    assert grown - before > 100_000_000, (before, grown)
    del layers
    gc.collect()
    # Kept for the next large output: still resident.
    assert resident_bytes() - before > 100_000_000
    t2spline.release_cached_memory()
    assert resident_bytes() - before < 20_000_000, (before, resident_bytes())
