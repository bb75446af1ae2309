"""Writes matplotlib's sample grid of real topography and bathymetry,
`topobathy.npz`, as a raster that `t2spline fuzzify --block` reads: the
heights as a `.npy` array of metres, and the `--origin` and `--spacing` of
its cells in spherical Mercator metres (EPSG:3857), on which the grid is
regular.

    python examples/salish-sea/topobathy_raster.py OUT.npy

prints the options for `t2spline fuzzify`, e.g.

    --origin=-14026255.8,6114162.3 --spacing=3711.1,3711.1

The file ships with matplotlib (`matplotlib.cbook.get_sample_data`), which
docs/terrain.md describes. Needs numpy and matplotlib (the `plot` extra).
"""

import math
import sys

import numpy as np
from matplotlib import cbook

# The sphere of spherical Mercator (EPSG:3857), in metres.
RADIUS = 6378137.0


def mercator(longitude: np.ndarray, latitude: np.ndarray) -> tuple:
    """Spherical Mercator metres of degrees east (0-360 or -180-180) and
    north."""
    lam = np.radians(np.where(longitude > 180.0, longitude - 360.0, longitude))
    phi = np.radians(latitude)
    return RADIUS * lam, RADIUS * np.log(np.tan(math.pi / 4 + phi / 2))


def main() -> int:
    out = sys.argv[1]
    data = cbook.get_sample_data("topobathy.npz")
    heights = np.asarray(data["topo"], dtype=np.float64)  # rows: latitude, south first
    x, _ = mercator(data["longitude"].astype(np.float64), 0.0)
    _, y = mercator(0.0, data["latitude"].astype(np.float64))
    rows, columns = heights.shape
    dx = (x[-1] - x[0]) / (columns - 1)
    dy = (y[-1] - y[0]) / (rows - 1)
    # The sample stores its coordinates in float32: the cell centres lie
    # within a few metres of the regular grid (cells of 3.7 km).
    off = max(np.abs(x - (x[0] + dx * np.arange(columns))).max(),
              np.abs(y - (y[0] + dy * np.arange(rows))).max())
    if off > 0.01 * min(dx, dy):
        raise SystemExit(f"the grid is not regular in EPSG:3857: a cell is {off:.1f} m off")
    np.save(out, heights)
    print(f"--origin={x[0]:.1f},{y[0]:.1f} --spacing={dx:.1f},{dy:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
