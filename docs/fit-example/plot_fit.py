"""Draws docs/images/fit-measurements.png from the real output of t2spline.

Stand-in until `t2spline plot` exists: it reads only what `t2spline fit` and
`t2spline run --csv` wrote, and the data file, and computes nothing but the
offsets it plots. Made by (from the repository root):

    cargo build --release --bin t2spline
    target/release/t2spline fuzzify examples/beach-readings.csv --tolerance 0.02 --alpha 0.5 -o examples/fit-measurements.json
    target/release/t2spline fit examples/fit-measurements.json -o out/fit-job.json
    target/release/t2spline run out/fit-job.json --csv out/fit-csv -o out/fit-result.json
    python3 -m venv docs/.venv && docs/.venv/bin/pip install -r docs/fit-example/requirements.txt
    docs/.venv/bin/python docs/fit-example/plot_fit.py examples/fit-measurements.json out/fit-csv docs/images/fit-measurements.png
"""

import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right", "upper_right"]
COLOURS = {"upper": "#9ecae1", "primary": "#3182bd", "lower": "#08519c"}


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main(data_path, csv_dir, out_path):
    with open(data_path) as f:
        data = json.load(f)
    layers = read_csv(f"{csv_dir}/stage1-layers.csv")
    stage4 = read_csv(f"{csv_dir}/stage4-defuzzified.csv")
    points = data["points"]

    fig, (top, bottom) = plt.subplots(
        2, 1, figsize=(10, 7.2), gridspec_kw={"height_ratios": [3, 2]}, constrained_layout=True
    )

    # Top: the profile, its data and the seven layer curves.
    for membership, width in [("upper", 1.0), ("primary", 2.2), ("lower", 4.0)]:
        for p in points:
            x, y = p["x"], p["y"]
            top.plot(x[membership], [y["crisp"]] * 2, color=COLOURS[membership], lw=width, solid_capstyle="butt")
            top.plot([x["crisp"]] * 2, y[membership], color=COLOURS[membership], lw=width, solid_capstyle="butt")
    for name in LAYERS:
        if name == "crisp":
            continue
        membership = name.split("_")[0]
        style = "--" if name.endswith("left") else "-"
        top.plot(layers[f"{name}_x"], layers[f"{name}_y"], style, color=COLOURS[membership], lw=1.0,
                 label=f"{name.replace('_', '.')} layer")
    top.plot(layers["crisp_x"], layers["crisp_y"], color="black", lw=1.6, label="crisp curve")
    top.plot(stage4["defuzzified_x"], stage4["defuzzified_y"], ":", color="#d62728", lw=1.6,
             label=f"defuzzified, alpha = {data['alpha']}")
    top.plot([p["x"]["crisp"] for p in points], [p["y"]["crisp"] for p in points], "o", color="black", ms=3.5,
             label="median of 20 readings")
    top.set_xlabel("distance from the dune crest x [m]")
    top.set_ylabel("height y [m]")
    top.set_title("Beach profile from 13 stations surveyed 20 times: cubic interpolation, valid fuzzy fit")
    top.legend(fontsize=7.5, ncol=2, loc="upper right")
    top.grid(alpha=0.3)

    # Bottom: height offsets of the layers from the crisp value, data and fit.
    for name in LAYERS:
        if name == "crisp":
            continue
        membership = name.split("_")[0]
        offset = [y - c for y, c in zip(layers[f"{name}_y"], layers["crisp_y"])]
        bottom.plot(layers["crisp_x"], offset, color=COLOURS[membership], lw=1.2)
        side = 0 if name.endswith("left") else 1
        bottom.plot([p["x"]["crisp"] for p in points],
                    [p["y"][membership][side] - p["y"]["crisp"] for p in points],
                    "o" if side else "s", mfc="none", color=COLOURS[membership], ms=4)
    bottom.axhline(0.0, color="black", lw=0.8)
    bottom.set_xlabel("distance from the dune crest x [m]")
    bottom.set_ylabel("height minus crisp [m]")
    bottom.set_title("Height spreads: data (markers) and fitted layer curves (lines); "
                     "the pole sinks into soft sand, so heights read low", fontsize=9.5)
    bottom.grid(alpha=0.3)

    fig.savefig(out_path, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:4])
