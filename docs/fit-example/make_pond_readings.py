"""Makes docs/fit-example/pond-readings.csv: the shore of a round pond surveyed 12 times.

The scenario: a pond whose shoreline is a circle of radius 20 m about
(100, 50) (in metres, a local grid), staked at 16 stations around it, each
surveyed 12 times with an RTK-GNSS receiver on a pole. Positions scatter
symmetrically (pole tilt, sigma 0.10 m in each coordinate). The stations are
a loop: `t2spline fit --closed` fits a closed curve through them, and
`t2spline measure` gives the area the shoreline encloses (the true value is
pi * 20^2 = 1256.64 m^2).

The readings are rounded to millimetres and written one per row
(`station,x,y`), the rows of a station together.

Run from the repository root (numpy only; seeded, so the output is the same
every time):
    python3 docs/fit-example/make_pond_readings.py > docs/fit-example/pond-readings.csv
"""

import numpy as np

STATIONS = 16
READINGS = 12
RADIUS = 20.0
CENTRE = (100.0, 50.0)
SIGMA = 0.10
RNG = np.random.default_rng(20261207)

print("station,x,y")
for k in range(STATIONS):
    angle = 2 * np.pi * k / STATIONS
    x0 = CENTRE[0] + RADIUS * np.cos(angle)
    y0 = CENTRE[1] + RADIUS * np.sin(angle)
    for _ in range(READINGS):
        x, y = x0 + RNG.normal(0, SIGMA), y0 + RNG.normal(0, SIGMA)
        print(f"P{k + 1:02d},{x:.3f},{y:.3f}")
