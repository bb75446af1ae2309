"""Makes examples/fit-measurements.json: a beach profile surveyed 20 times.

The scenario: a cross-shore beach profile from the dune crest to the waterline,
13 stations placed where the slope changes (as surveyors do), each surveyed 20
times with an RTK-GNSS receiver on a pole. Horizontal positions scatter
symmetrically (pole tilt, sigma 0.12 m). Heights scatter a little (sigma 2 cm)
and read low by the depth the pole sinks into the sand: deep in the soft dry
sand of the dune, hardly at all on the wet, firm beach. So the height errors are
skewed downwards, by an amount that changes along the profile.

Each coordinate of each station becomes one normal type-2 fuzzy number:
  crisp   = the median reading
  lower   = [25th, 75th percentile]   (half of the readings: lower_height 0.5)
  primary = [10th, 90th percentile]
  upper   = [min - 0.02, max + 0.02]  (all readings, widened by the receiver's
                                       stated precision of 2 cm)
Values are rounded to millimetres, as recorded.

Run from the repository root (numpy only; seeded, so the output is the same
every time):
    python3 docs/fit-example/make_data.py > examples/fit-measurements.json
"""

import json

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


def fuzzy(readings, tolerance=0.02):
    q = np.percentile(readings, [10, 25, 50, 75, 90])
    r = lambda v: round(float(v), 3)
    return {
        "crisp": r(q[2]),
        "upper": [r(readings.min() - tolerance), r(readings.max() + tolerance)],
        "primary": [r(q[0]), r(q[4])],
        "lower": [r(q[1]), r(q[3])],
    }


points = []
for x, z, sink in STATIONS:
    xs = x + RNG.normal(0.0, 0.12, READINGS)
    zs = z + RNG.normal(0.0, 0.02, READINGS) - RNG.exponential(sink, READINGS)
    points.append({"x": fuzzy(xs), "y": fuzzy(zs)})

data = {
    "description": (
        "Cross-shore beach profile, dune crest to waterline: 13 stations, each surveyed 20 times "
        "with RTK-GNSS on a pole (x: distance from the crest [m], y: height above datum [m]). "
        "Per coordinate: crisp = median, lower = quartiles, primary = 10th-90th percentiles, "
        "upper = all readings +- 2 cm. Heights read low where the pole sinks into soft sand. "
        "Made by docs/fit-example/make_data.py."
    ),
    "degree": 3,
    "alpha": 0.5,
    "lower_height": 0.5,
    "samples": 201,
    "points": points,
}

# One point per line, as in the other examples.
lines = [",\n".join("    " + json.dumps(p) for p in points)]
head = {k: v for k, v in data.items() if k != "points"}
text = json.dumps(head, indent=2)[:-2] + ',\n  "points": [\n' + lines[0] + "\n  ]\n}\n"
assert json.loads(text) == data
print(text, end="")
