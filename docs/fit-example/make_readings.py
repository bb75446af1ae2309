"""Makes examples/beach-readings.csv: a beach profile surveyed 20 times.

The scenario: a cross-shore beach profile from the dune crest to the waterline,
13 stations placed where the slope changes (as surveyors do), each surveyed 20
times with an RTK-GNSS receiver on a pole. Horizontal positions scatter
symmetrically (pole tilt, sigma 0.12 m). Heights scatter a little (sigma 2 cm)
and read low by the depth the pole sinks into the sand: deep in the soft dry
sand of the dune, hardly at all on the wet, firm beach. So the height errors are
skewed downwards, by an amount that changes along the profile.

The readings are rounded to millimetres, as the receiver records them, and
written one per row (`station,x,y`: distance from the dune crest and height
above datum, in metres), the rows of a station together. The file is made
once and kept in the repository; t2spline turns it into fuzzy data points
(`t2spline fuzzify`, see docs/fit-example/README.md).

Run from the repository root (numpy only; seeded, so the output is the same
every time):
    python3 docs/fit-example/make_readings.py > examples/beach-readings.csv
"""

import numpy as np

READINGS = 20
RNG = np.random.default_rng(20240607)

# (distance from the dune crest [m], true height above datum [m], mean sinkage of the pole [m])
STATIONS = [
    (0.0, 6.10, 0.10),    # dune crest, soft dry sand
    (4.0, 5.85, 0.14),
    (8.5, 4.90, 0.18),    # dune face: steep, loose
    (12.0, 3.70, 0.20),
    (15.5, 2.95, 0.12),   # dune toe
    (21.0, 2.70, 0.08),   # back of the berm
    (28.0, 2.55, 0.06),
    (33.0, 2.10, 0.05),   # berm crest, scarp below it
    (36.0, 1.55, 0.04),
    (45.0, 1.20, 0.03),   # beach face, firm wet sand
    (58.0, 0.80, 0.02),
    (72.0, 0.45, 0.015),
    (86.0, 0.05, 0.01),   # waterline
]

print("station,x,y")
for i, (x, z, sink) in enumerate(STATIONS, start=1):
    xs = x + RNG.normal(0.0, 0.12, READINGS)
    zs = z + RNG.normal(0.0, 0.02, READINGS) - RNG.exponential(sink, READINGS)
    for a, b in zip(xs, zs):
        print(f"S{i:02d},{a:.3f},{b:.3f}")
