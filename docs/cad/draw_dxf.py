"""Draws docs/images/beach-export-dxf.png: the DXF file that `t2spline export`
wrote for the beach example, rendered by ezdxf's drawing add-on (matplotlib),
an independent DXF renderer; nothing of t2spline draws it.

Made by (from the repository root):

    cargo build --release --bin t2spline
    target/release/t2spline fuzzify examples/beach-readings.csv --tolerance 0.02 --alpha 0.5 -o out/beach-data.json
    target/release/t2spline fit out/beach-data.json -o out/beach-job.json
    target/release/t2spline run out/beach-job.json -o out/beach-result.json
    target/release/t2spline export out/beach-job.json -o out/beach.dxf
    python3 -m venv docs/.venv && docs/.venv/bin/pip install -r docs/cad/requirements.txt
    docs/.venv/bin/python docs/cad/draw_dxf.py out/beach.dxf docs/images/beach-export-dxf.png

The drawing keeps the DXF's equal scale in x and y: the whole profile (86 m
by 6 m) on top, the dune face below at a larger scale, both from the same
SPLINE entities. Colours are the layers' (AutoCAD colour index).
"""

import sys

import ezdxf
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from ezdxf.addons.drawing import Frontend, RenderContext  # noqa: E402
from ezdxf.addons.drawing.config import BackgroundPolicy, Configuration  # noqa: E402
from ezdxf.addons.drawing.matplotlib import MatplotlibBackend  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

# The layer colours t2spline writes (AutoCAD colour index 7 draws black on white).
LEGEND = [("crisp", "black"), ("defuzzified", "#ff0000"), ("upper_left, upper_right", "#0000ff"),
          ("primary_left, primary_right", "#00ff00"), ("lower_left, lower_right", "#ff7f00")]


def main(dxf_path, png_path):
    doc = ezdxf.readfile(dxf_path)
    auditor = doc.audit()
    assert not auditor.has_errors, [e.message for e in auditor.errors]
    fig, (whole, dune) = plt.subplots(2, 1, figsize=(10, 6.4), gridspec_kw={"height_ratios": [1, 2.6]})
    config = Configuration(background_policy=BackgroundPolicy.WHITE)
    for ax in (whole, dune):
        backend = MatplotlibBackend(ax, adjust_figure=False)
        Frontend(RenderContext(doc), backend, config=config).draw_layout(doc.modelspace())
        ax.set_aspect("equal", adjustable="box")
        # The backend hides the axes; a reader of the picture wants the scale.
        ax.set_axis_on()
        ax.xaxis.set_visible(True)
        ax.yaxis.set_visible(True)
        for spine in ax.spines.values():
            spine.set_visible(True)
        ax.grid(color="#dddddd", linewidth=0.5)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    whole.set_xlim(-2, 88)
    whole.set_ylim(-0.5, 7)
    whole.set_title("examples/beach-readings.csv → fuzzify → fit → export: out/beach.dxf (8 SPLINE entities)", fontsize=10)
    dune.set_xlim(-1, 17)
    dune.set_ylim(2.3, 6.4)
    dune.set_title("the dune face at a larger scale (same entities)", fontsize=10)
    dune.legend(handles=[Line2D([], [], color=c, label=f"layer {n}") for n, c in LEGEND],
                loc="upper right", fontsize=8)
    fig.text(0.01, 0.005, "Drawn by ezdxf's drawing add-on (matplotlib) from the DXF file alone.",
             fontsize=7, color="#555555")
    fig.tight_layout()
    fig.savefig(png_path, dpi=150)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
