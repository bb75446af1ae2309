"""Writes the two surface examples, examples/fuzzy-terrain.json and
examples/fuzzy-cylinder.json, with one control point per line.

Run from the repository root: python3 docs/surface-examples/make_examples.py
"""

import json
import math


def number(crisp, upper, primary, lower):
    return {"crisp": crisp, "upper": upper, "primary": primary, "lower": lower}


def crisp(c):
    return number(c, [c, c], [c, c], [c, c])


def write(path, head, rows, weights=None):
    """The job `head` with `points` (and `weights`) one point per line."""
    lines = ["{"]
    for key, value in head.items():
        lines.append(f"  {json.dumps(key)}: {json.dumps(value, ensure_ascii=False)},")
    if weights is not None:
        lines.append(f'  "weights": {json.dumps(weights)},')
    lines.append('  "points": [')
    for i, row in enumerate(rows):
        lines.append("    [")
        for j, p in enumerate(row):
            comma = "," if j < len(row) - 1 else ""
            lines.append(f"      {json.dumps(p)}{comma}")
        lines.append("    ]" + ("," if i < len(rows) - 1 else ""))
    lines.append("  ]")
    lines.append("}")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def terrain():
    """A 6 x 5 net of spot heights levelled from a benchmark at (100, 100)."""
    bench = (100.0, 100.0)
    rows = []
    for i in range(6):
        x = 100.0 * i
        row = []
        for j in range(5):
            y = 100.0 * j
            hill = 6.0 * math.exp(-((x - 300.0) ** 2 + (y - 250.0) ** 2) / (2 * 140.0**2))
            z = round(100.0 + 0.02 * x + 0.01 * y + hill, 2)
            # Levelling error grows with the square root of the distance
            # levelled; readings on vegetation over-read the ground, so the
            # spreads reach further below the reading than above it.
            d = math.hypot(x - bench[0], y - bench[1])
            s = round(0.12 * math.sqrt(d / 100.0), 3)
            r = lambda v: round(v, 3)
            zn = number(
                z,
                [r(z - 3 * s), r(z + 2 * s)],
                [r(z - 2 * s), r(z + 1.25 * s)],
                [r(z - s), r(z + 0.5 * s)],
            )
            row.append({"x": crisp(x), "y": crisp(y), "z": zn})
        rows.append(row)
    head = {
        "description": (
            "Fuzzy terrain patch: a 6 x 5 net of spot heights over 500 m x 400 m "
            "(x east, y north, z height [m]), levelled from the benchmark BM1 at "
            "(100, 100). Positions are crisp; each height is a fuzzy number whose "
            "spreads grow with the square root of the distance levelled from BM1 "
            "(s = 0.12 m x sqrt(d / 100 m), zero at BM1) and reach further below "
            "the reading than above it (upper -3s..+2s, primary -2s..+1.25s, lower "
            "-s..+0.5s), as readings on vegetation over-read the ground. The "
            "defuzzified surface therefore lies below the crisp one, further the "
            "farther from BM1. Biquadratic, clamped uniform knots."
        ),
        "order": [3, 3],
        "alpha": 0.5,
        "lower_height": 0.6,
        "samples": [51, 41],
    }
    write("examples/fuzzy-terrain.json", head, rows)


def cylinder():
    """A quarter cylinder of fuzzy radius: rational quadratic in u, linear in v."""
    r, height = 2.5, 3.0
    w = math.sqrt(2.0) / 2.0

    def radial(c):
        # Spreads proportional to the coordinate: every stage scales it by a
        # constant factor (crisp 0 stays crisp).
        f = lambda k: round(k * c, 12)
        return number(c, [f(0.94), f(1.09)], [f(0.96), f(1.06)], [f(0.98), f(1.03)])

    rows = []
    for x, y in [(r, 0.0), (r, r), (0.0, r)]:
        rows.append([{"x": radial(x), "y": radial(y), "z": crisp(z)} for z in (0.0, height)])
    head = {
        "description": (
            "Quarter of a cylindrical tank wall, nominal radius 2.5 m, height 3 m, "
            "axis the z axis: rational quadratic in u (weights 1, sqrt(2)/2, 1, so "
            "the crisp surface is exactly the cylinder of radius 2.5) and linear in "
            "v. The as-built radius is uncertain: x and y of every control point "
            "carry spreads proportional to the coordinate (upper -6 %..+9 %, "
            "primary -4 %..+6 %, lower -2 %..+3 %, one lower height 0.6), so each "
            "control point moves radially and every stage scales x and y by one "
            "factor. The defuzzified surface is again a cylinder, of radius "
            "kappa x 2.5 with kappa = 1 + (rho - lambda)/3 from the type-reduced "
            "factors (closed form in crates/t2spline-io/tests/surface_examples.rs): "
            "at alpha 0.5, lambda = 0.01778, rho = 0.02667, kappa = 1.002963, radius "
            "2.50741 m, and the distance to the crisp surface is 0.00741 m everywhere."
        ),
        "order": [3, 2],
        "alpha": 0.5,
        "lower_height": 0.6,
        "samples": [31, 5],
    }
    write("examples/fuzzy-cylinder.json", head, rows, weights=[[1, 1], [w, w], [1, 1]])


if __name__ == "__main__":
    terrain()
    cylinder()
