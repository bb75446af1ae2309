"""t2spline from Python, as a notebook in one file.

Run it as a script, ``python docs/python-example.py [OUT_DIR]`` (figures go to
OUT_DIR, by default ``t2spline-example/``), or open it in Jupyter or VS Code,
where every ``# %%`` starts a cell. It needs ``pip install .[plot]`` at the
repository root. The test suite runs it (``python/tests/test_docs.py``) and
CI type-checks it with ``mypy --strict``.
"""

# %%
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # in a notebook: leave this out, figures show inline

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

import t2spline  # noqa: E402
import t2spline.plot  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
OUT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("t2spline-example")
OUT.mkdir(parents=True, exist_ok=True)

# %% [markdown]
# ## 1. The paper's Algorithm 1.1, from the shipped job file
#
# `t2spline.run` takes a job file (or a dict with its keys) and returns what
# `t2spline run` writes, with numpy arrays: the same numbers, bit for bit.

# %%
result = t2spline.run(ROOT / "examples" / "paper-alg-1-1.json")
crisp = result["curves"]["crisp"]
print(f"{crisp.shape[0]} samples of a {result['dimension']}-D curve of order {result['order']}")
print(f"alpha = {result['alpha']} ({result['regime']}): "
      f"max distance {result['error']['max']:.4f}, rms {result['error']['rms']:.4f}")
t2spline.plot.stages(result).savefig(OUT / "stages.png", dpi=90)

# %% [markdown]
# ## 2. Uncertain measurements as numpy arrays
#
# A path measured at seven stations. Every coordinate is an interval of
# plausible values around the reading, wider to the right (a biased
# instrument): the upper, primary and lower feet are three nested intervals.

# %%
stations = np.array([[0.0, 0.0], [1.0, 1.8], [2.2, 2.6], [3.5, 2.4],
                     [4.6, 1.2], [5.5, 1.6], [6.5, 2.9]])
spread = np.array([-0.25, 0.45])                      # [left, right] at the outer level
curve = t2spline.FuzzyCurve(
    crisp=stations,
    upper=stations[..., None] + spread,
    primary=stations[..., None] + 0.6 * spread,
    lower=stations[..., None] + 0.25 * spread,
    lower_height=0.5,                                 # one h for every number
    degree=3,
)
print(curve)

layers = curve.sample(400)                            # seven (400, 2) arrays, by the Rust engine
stacked = np.stack([layers["upper_left"], layers["primary_left"], layers["lower_left"],
                    layers["crisp"], layers["lower_right"], layers["primary_right"],
                    layers["upper_right"]])
assert np.all(np.diff(stacked, axis=0) >= 0), "layer curves keep the docs/method.md §1 order"

# %% [markdown]
# ## 3. The solution as alpha varies
#
# Stages 2–4 at each alpha: the defuzzified curve moves towards the wider
# (right) spreads; at alpha = h the type reduction changes from three-term
# to two-term means, so the distance jumps there (docs/method.md §3).

# %%
alphas = np.linspace(0.0, 1.0, 101)
distances = np.array([curve.solve(float(a)).distance()["max"] for a in alphas])
fig = Figure(figsize=(6, 3.5), layout="constrained")
ax = fig.subplots()
ax.plot(alphas, distances, color=t2spline.plot.SOLUTION)
ax.axvline(0.5, color=t2spline.plot.GREY, linestyle=":", label="h = 0.5")
ax.set_xlabel("alpha")
ax.set_ylabel("max |D(t) − C(t)|")
ax.legend()
fig.savefig(OUT / "distance-vs-alpha.png", dpi=90)
print(f"distance at alpha = 0.5: {distances[50]:.4f}, just above: {distances[51]:.4f}")

solution = curve.solve(0.3)
samples = solution.sample(400)
print("type-reduced left/right and defuzzified curves:",
      samples["type_reduced"]["left"].shape, samples["defuzzified"].shape)

# %% [markdown]
# ## 4. One fuzzy number and its membership functions

# %%
x = curve.point(3)[1]                                 # y of station 3
print(x)
print("cut at 0.3:", x.alpha_cut(0.3))
print("defuzzified at 0.3:", round(x.defuzzify(0.3), 4))
fig = Figure(figsize=(5, 3.5), layout="constrained")
t2spline.plot.membership(fig.subplots(), x).legend(fontsize="small")
fig.savefig(OUT / "number.png", dpi=90)

# %% [markdown]
# ## 5. Fitting a fuzzy curve to fuzzy data
#
# Twelve fuzzy readings of a curve; `fit` interpolates them with one
# parametrization for all seven layers, and keeps the control points valid
# fuzzy numbers.

# %%
readings = curve.eval_layers(curve.uniform_params(12))  # (12, 7, 2)
fitted, summary = t2spline.fit(
    crisp=readings[:, 3],
    upper=np.stack([readings[:, 0], readings[:, 6]], axis=-1),
    primary=np.stack([readings[:, 1], readings[:, 5]], axis=-1),
    lower=np.stack([readings[:, 2], readings[:, 4]], axis=-1),
    lower_height=0.5,
    degree=3,
)
print(f"fitted {summary['control_points']} control points, condition {summary['condition']:.1e}, "
      f"largest crisp deviation {summary['deviations']['crisp']['max']:.1e}")
print(f"done: figures in {OUT}/")
