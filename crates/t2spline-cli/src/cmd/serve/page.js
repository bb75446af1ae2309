"use strict";
// The page of `t2spline serve`: the job is edited here, as the JSON of a job
// file; every change is sent to the server (`POST /api/run`, `/api/region`),
// which runs it with the project's core and answers `t2spline run`'s bytes.
// One request is in flight at a time and only the latest job waits behind it,
// so a drag never queues stale work. Drawing is plain SVG.

const SVG = "http://www.w3.org/2000/svg";
const TOKEN = new URLSearchParams(location.search).get("token") || "";
const W = 800, H = 600, PAD = 30;
const LAYERS = ["upper_left", "primary_left", "lower_left", "lower_right", "primary_right", "upper_right"];
const COLOURS = { upper: "#1f77b4", primary: "#2ca02c", lower: "#9467bd" };
const $ = id => document.getElementById(id);

const state = {
  job: null, name: "job.json", saveable: false,
  undo: [], redo: [],
  result: null, regions: null, shownText: null, problems: [],
  inFlight: false, pending: false, selected: 0,
  view: null, drag: null, lastDownload: null, ms: null, requests: 0,
  azimuth: -0.6, elevation: 0.5,
};

// ---- the job -------------------------------------------------------------

const jobText = () => JSON.stringify(state.job, null, 2) + "\n";
const isSurface = () => state.job && Array.isArray(state.job.points[0]);
const coords = () => (state.job.points[0].z ? ["x", "y", "z"] : ["x", "y"]);

/** The seven values of a fuzzy number, in their order. */
function seven(n) {
  return [n.upper[0], n.primary[0], n.lower[0], n.crisp, n.lower[1], n.primary[1], n.upper[1]];
}

/** Writes the seven values back into the number `n`. */
function setSeven(n, v) {
  n.upper = [v[0], v[6]]; n.primary = [v[1], v[5]]; n.lower = [v[2], v[4]]; n.crisp = v[3];
}

/** `v` rounded to a grid of `step` (monotone: the order of values is kept). */
function snap(v, step) {
  const digits = Math.max(0, Math.min(12, -Math.floor(Math.log10(step))));
  return Number((Math.round(v / step) * step).toFixed(digits));
}

/** Records the job for undo, before a change. */
function remember() {
  state.undo.push(jobText());
  if (state.undo.length > 500) state.undo.shift();
  state.redo = [];
}

/** A change of the job: recorded, applied, recomputed. */
function edit(change, refit) {
  remember();
  change(state.job);
  if (refit) state.view = null;
  syncFields();
  schedule();
}

function undo() {
  if (!state.undo.length) return;
  state.redo.push(jobText());
  state.job = JSON.parse(state.undo.pop());
  afterJump();
}

function redo() {
  if (!state.redo.length) return;
  state.undo.push(jobText());
  state.job = JSON.parse(state.redo.pop());
  afterJump();
}

function afterJump() {
  state.selected = Math.min(state.selected, state.job.points.length - 1);
  state.view = null;
  syncFields();
  schedule();
}

// ---- the server ----------------------------------------------------------

async function api(path, body) {
  const r = await fetch(path, {
    method: body === undefined ? "GET" : "POST",
    headers: { "X-T2spline-Token": TOKEN },
    body,
  });
  const text = await r.text();
  return { status: r.status, text };
}

/** Asks for a run of the current job; coalesced behind one in flight. */
function schedule() {
  if (state.inFlight) { state.pending = true; return; }
  state.inFlight = true;
  state.pending = false;
  compute(jobText()).finally(() => {
    state.inFlight = false;
    if (state.pending) schedule();
  });
}

/** The points of the membership map: a grid of cells over the view. */
function mapGrid() {
  const v = state.view || fitView();
  const nx = 64, ny = 48, xs = [], ys = [];
  for (let i = 0; i < nx; i++) xs.push(Number(v.x((i + 0.5) * W / nx).toPrecision(6)));
  for (let j = 0; j < ny; j++) ys.push(Number(v.y((j + 0.5) * H / ny).toPrecision(6)));
  let csv = coords().length === 3 ? "x,y,z\n" : "x,y\n";
  const z = coords().length === 3 ? "," + 0 : "";
  for (const y of ys) for (const x of xs) csv += x + "," + y + z + "\n";
  return { nx, ny, csv };
}

/** The map's cells, shaded by the upper grade (`t2spline membership`'s CSV). */
function drawMap(svg) {
  const g = el("g", { id: "membership-map" }, svg);
  const rows = state.map.text.trim().split("\n").slice(1);
  const { nx, ny } = state.map.grid;
  const column = state.map.text.split("\n")[0].split(",").indexOf("upper");
  rows.forEach((row, k) => {
    const grade = Number(row.split(",")[column]);
    if (!(grade > 0)) return;
    const i = k % nx, j = Math.floor(k / nx);
    el("rect", { x: (i * W / nx).toFixed(2), y: (j * H / ny).toFixed(2), width: (W / nx + 0.3).toFixed(2),
                 height: (H / ny + 0.3).toFixed(2), fill: "#1f77b4", "fill-opacity": (0.45 * grade).toFixed(3) }, g);
  });
}

/** The regions' tolerance: a quarter of a pixel of the view (at 1000 px). */
function regionTolerance() {
  const v = state.view || fitView();
  return (W / v.s / 4000).toPrecision(2);
}

async function compute(text) {
  const start = performance.now();
  state.requests += 1;
  const curve = !isSurface();
  const grid = curve && coords().length === 2 && $("show-map").checked ? mapGrid() : null;
  const [run, region, map] = await Promise.all([
    api("/api/run", text),
    curve ? api("/api/region?tolerance=" + regionTolerance(), text) : Promise.resolve(null),
    grid ? api("/api/membership", JSON.stringify({ job: text, points: grid.csv })) : Promise.resolve(null),
  ]);
  state.map = map && map.status === 200 ? { grid, text: map.text } : null;
  state.ms = performance.now() - start;
  if (run.status === 200) {
    state.result = JSON.parse(run.text);
    state.resultText = run.text;
    state.regions = region && region.status === 200 ? JSON.parse(region.text) : null;
    state.problems = [];
  } else {
    let problems;
    try { problems = JSON.parse(run.text).problems; } catch (e) { problems = [run.text]; }
    state.problems = problems;
  }
  state.shownText = text;
  draw();
}

// ---- drawing -------------------------------------------------------------

function el(name, attrs, parent) {
  const e = document.createElementNS(SVG, name);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}

/** The screen transform of the plane view, fitted to the job's feet. */
function fitView() {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of state.job.points) {
    x0 = Math.min(x0, p.x.upper[0]); x1 = Math.max(x1, p.x.upper[1]);
    y0 = Math.min(y0, p.y.upper[0]); y1 = Math.max(y1, p.y.upper[1]);
  }
  if (state.result && state.result.curves) {
    for (const q of state.result.curves.crisp) {
      x0 = Math.min(x0, q[0]); x1 = Math.max(x1, q[0]); y0 = Math.min(y0, q[1]); y1 = Math.max(y1, q[1]);
    }
  }
  const span = Math.max(x1 - x0, y1 - y0, 1e-9);
  const mx = (x1 - x0) * 0.1 + span * 0.02, my = (y1 - y0) * 0.1 + span * 0.02;
  x0 -= mx; x1 += mx; y0 -= my; y1 += my;
  const s = Math.min((W - 2 * PAD) / (x1 - x0), (H - 2 * PAD) / (y1 - y0));
  const ox = PAD + ((W - 2 * PAD) - s * (x1 - x0)) / 2, oy = PAD + ((H - 2 * PAD) - s * (y1 - y0)) / 2;
  const step = Math.pow(10, Math.floor(Math.log10(span)) - 3);
  return {
    s, step,
    X: x => ox + (x - x0) * s,
    Y: y => H - (oy + (y - y0) * s),
    x: px => x0 + (px - ox) / s,
    y: py => y0 + (H - py - oy) / s,
  };
}

function polyline(points, v, attrs, parent) {
  const d = points.map(p => v.X(p[0]).toFixed(2) + "," + v.Y(p[1]).toFixed(2)).join(" ");
  return el("polyline", Object.assign({ points: d, fill: "none" }, attrs), parent);
}

function draw() {
  const svg = $("plot");
  svg.textContent = "";
  showNumbers();
  if (!state.job) return;
  if (isSurface()) { drawSurface(svg); return; }
  if (!state.view) state.view = fitView();
  const v = state.view, r = state.result;
  if ($("show-map").checked && state.map) drawMap(svg);
  const regions = el("g", { id: "regions" }, svg);
  if ($("show-regions").checked && state.regions) {
    for (const f of state.regions.features) {
      if (f.properties.plane !== "xy") continue;
      const colour = COLOURS[f.properties.membership];
      let d = "";
      for (const poly of f.geometry.coordinates) for (const ring of poly) {
        d += "M" + ring.map(p => v.X(p[0]).toFixed(2) + "," + v.Y(p[1]).toFixed(2)).join("L") + "Z";
      }
      el("path", { d, fill: colour, "fill-opacity": 0.12, stroke: colour, "stroke-opacity": 0.5,
                   "stroke-width": 0.8, "fill-rule": "evenodd", "data-membership": f.properties.membership }, regions);
    }
  }
  if (r && r.curves && $("show-layers").checked) {
    const g = el("g", { id: "layers" }, svg);
    for (const name of LAYERS) {
      const c = COLOURS[name.split("_")[0]];
      polyline(r.curves.layers[name], v, { stroke: c, "stroke-width": 1, "stroke-opacity": 0.7, "data-layer": name }, g);
      const cut = r.curves.alpha_cut[name];
      if (cut) polyline(cut, v, { stroke: "#ff7f0e", "stroke-width": 1, "stroke-dasharray": "4 3", "data-cut": name }, g);
    }
  }
  // The control polygon.
  polyline(state.job.points.map(p => [p.x.crisp, p.y.crisp]), v, { stroke: "#999", "stroke-dasharray": "3 3" }, svg);
  if (r && r.curves) {
    polyline(r.curves.crisp, v, { id: "crisp-curve", stroke: "#111", "stroke-width": 2 }, svg);
    polyline(r.curves.defuzzified, v, { id: "solution-curve", stroke: "#d62728", "stroke-width": 2 }, svg);
  }
  drawHandles(svg, v);
}

const FOOT = ["upper", "primary", "lower", "crisp", "lower", "primary", "upper"];

function drawHandles(svg, v) {
  const g = el("g", { id: "handles" }, svg);
  state.job.points.forEach((p, i) => {
    const cx = v.X(p.x.crisp), cy = v.Y(p.y.crisp);
    const feet = el("g", { "data-point": i }, g);
    ["x", "y"].forEach((c, ci) => {
      const vals = seven(p[c]);
      const at = k => ci === 0 ? [v.X(vals[k]), cy] : [cx, v.Y(vals[k])];
      const [ax, ay] = at(0), [bx, by] = at(6);
      el("line", { x1: ax, y1: ay, x2: bx, y2: by, stroke: "#bbb" }, feet);
      for (let k = 0; k < 7; k++) {
        if (k === 3) continue;
        const [hx, hy] = at(k);
        const kind = FOOT[k], side = k < 3 ? "left" : "right";
        const r = 5, attrs = { class: "handle " + kind, "data-point": i, "data-coord": c, "data-foot": k,
                               id: `h-${i}-${c}-${kind}-${side}` };
        let shape;
        if (kind === "upper") shape = el("rect", Object.assign({ x: hx - r, y: hy - r, width: 2 * r, height: 2 * r }, attrs), feet);
        else if (kind === "primary") shape = el("polygon", Object.assign({ points: `${hx},${hy - r} ${hx + r},${hy} ${hx},${hy + r} ${hx - r},${hy}` }, attrs), feet);
        else shape = el("polygon", Object.assign({ points: `${hx},${hy - r} ${hx + r},${hy + r} ${hx - r},${hy + r}` }, attrs), feet);
        shape.addEventListener("pointerdown", startDrag);
      }
    });
    const dot = el("circle", { cx, cy, r: 7, class: "handle crisp" + (i === state.selected ? " selected" : ""),
                               id: `h-${i}-crisp`, "data-point": i }, g);
    dot.addEventListener("pointerdown", startDrag);
  });
}

/** A drag of a handle: the crisp point moves its whole number, a foot its one value. */
function startDrag(ev) {
  ev.preventDefault();
  const t = ev.target;
  const i = Number(t.dataset.point);
  state.selected = i;
  syncFields();
  const svg = $("plot");
  const box = svg.getBoundingClientRect();
  const toSvg = e => [(e.clientX - box.left) * W / box.width, (e.clientY - box.top) * H / box.height];
  const v = state.view;
  const before = jobText();
  const start = toSvg(ev);
  const p = state.job.points[i];
  const origin = { x: seven(p.x), y: seven(p.y) };
  const coord = t.dataset.coord, foot = t.dataset.foot === undefined ? null : Number(t.dataset.foot);
  let moved = false;
  const move = e => {
    const [px, py] = toSvg(e);
    if (foot === null) {
      const dx = v.x(px) - v.x(start[0]), dy = v.y(py) - v.y(start[1]);
      setSeven(p.x, origin.x.map(a => snap(a + dx, v.step)));
      setSeven(p.y, origin.y.map(a => snap(a + dy, v.step)));
    } else {
      const vals = origin[coord].slice();
      let value = snap(coord === "x" ? v.x(px) : v.y(py), v.step);
      // The seven values stay ordered: the foot stops at its neighbours.
      if (foot > 0) value = Math.max(value, vals[foot - 1]);
      if (foot < 6) value = Math.min(value, vals[foot + 1]);
      vals[foot] = value;
      setSeven(p[coord], vals);
    }
    moved = true;
    draw();
    schedule();
  };
  const up = () => {
    window.removeEventListener("pointermove", move);
    window.removeEventListener("pointerup", up);
    if (moved) {
      state.undo.push(before);
      state.redo = [];
    }
    draw();
  };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
  draw();
}

// ---- surfaces: a view-only projection ------------------------------------

function drawSurface(svg) {
  const r = state.result;
  if (!r || !r.surfaces) return;
  const grids = [["crisp", "#111"], ["defuzzified", "#d62728"]];
  const ca = Math.cos(state.azimuth), sa = Math.sin(state.azimuth);
  const ce = Math.cos(state.elevation), se = Math.sin(state.elevation);
  const project = q => {
    const x = q[0] * ca - q[1] * sa, y = q[0] * sa + q[1] * ca;
    return [x, q[2] * ce - y * se];
  };
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const row of r.surfaces.crisp) for (const q of row) {
    const [a, b] = project(q);
    x0 = Math.min(x0, a); x1 = Math.max(x1, a); y0 = Math.min(y0, b); y1 = Math.max(y1, b);
  }
  const s = Math.min((W - 2 * PAD) / Math.max(x1 - x0, 1e-9), (H - 2 * PAD) / Math.max(y1 - y0, 1e-9));
  const v = { X: a => PAD + (a - x0) * s, Y: b => H - PAD - (b - y0) * s };
  for (const [name, colour] of grids) {
    const grid = r.surfaces[name].map(row => row.map(project));
    const g = el("g", { id: "surface-" + name }, svg);
    for (const row of grid) polyline(row, v, { stroke: colour, "stroke-width": 1 }, g);
    for (let j = 0; j < grid[0].length; j++) polyline(grid.map(row => row[j]), v, { stroke: colour, "stroke-width": 1 }, g);
  }
}

function rotateSurface(ev) {
  if (!isSurface()) return;
  const x = ev.clientX, y = ev.clientY, a = state.azimuth, e = state.elevation;
  const move = m => {
    state.azimuth = a + (m.clientX - x) * 0.01;
    state.elevation = Math.max(-1.5, Math.min(1.5, e + (m.clientY - y) * 0.01));
    draw();
  };
  const up = () => { window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up); };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
}

// ---- numbers and fields --------------------------------------------------

function fmt(x) {
  if (x === null || x === undefined) return "–";
  if (Array.isArray(x)) return "(" + x.map(fmt).join(", ") + ")";
  return Number(x).toPrecision(4);
}

function setNumber(id, value) {
  const e = $(id);
  e.textContent = fmt(value);
  e.dataset.value = JSON.stringify(value === undefined ? null : value);
}

function showNumbers() {
  const r = state.result, bad = state.problems.length > 0;
  const status = $("status");
  status.className = bad ? "bad" : "";
  status.textContent = bad ? state.problems.join("\n") : "";
  document.body.dataset.state = bad ? "problems" : (r ? "ok" : "loading");
  if (r) {
    const regime = r.regime === undefined ? null : r.regime;
    $("m-regime").textContent = regime === null ? "– (alpha not used)" : regime;
    $("m-regime").dataset.value = JSON.stringify(regime);
    setNumber("m-max", r.error.max);
    setNumber("m-max-at", r.error.max_at);
    setNumber("m-rms", r.error.rms);
  }
  $("m-time").textContent = state.ms === null ? "" : state.ms.toFixed(1) + " ms";
  const a = state.job && state.job.alpha;
  $("alpha-value").textContent = a === undefined || a === null ? "" :
    (state.job.type_reduction === "paper" ? String(a) : String(a) + " (not used)");
  $("alpha-value").dataset.value = a === undefined ? "" : String(a);
  $("undo").disabled = !state.undo.length;
  $("redo").disabled = !state.redo.length;
}

/** The fields show the job. */
function syncFields() {
  const j = state.job;
  if (!j) return;
  const surface = isSurface();
  for (const id of ["curve-fields", "point-fields"]) $(id).hidden = surface;
  $("alpha").value = j.alpha === undefined ? 0.5 : j.alpha;
  $("reduction").value = j.type_reduction || "paper";
  if (surface) return;
  $("order").value = j.degree + 1;
  const heights = new Set();
  for (const p of j.points) for (const c of coords()) heights.add(p[c].lower_height);
  $("lower-height").value = heights.size === 1 ? [...heights][0] : "";
  $("lower-height").placeholder = heights.size === 1 ? "" : "mixed";
  const i = state.selected;
  $("point-index").textContent = String(i);
  $("weight").value = j.weights[i];
  const z = $("z-fields");
  z.textContent = "";
  if (j.points[i].z) {
    const names = ["upper left", "primary left", "lower left", "crisp", "lower right", "primary right", "upper right"];
    seven(j.points[i].z).forEach((value, k) => {
      const label = document.createElement("label");
      label.textContent = "z " + names[k] + " ";
      const input = document.createElement("input");
      input.type = "number"; input.step = "any"; input.value = value; input.id = "z-" + k;
      input.addEventListener("change", () => {
        const x = Number(input.value);
        if (!Number.isFinite(x)) return;
        edit(job => { const vals = seven(job.points[i].z); vals[k] = x; setSeven(job.points[i].z, vals); });
      });
      label.appendChild(input);
      z.appendChild(label);
    });
  }
}

/** A new point halfway between `a` and `b` (every value averaged: still ordered). */
function between(a, b) {
  const out = {};
  for (const c of Object.keys(a)) {
    const n = JSON.parse(JSON.stringify(a[c]));
    setSeven(n, seven(a[c]).map((x, k) => (x + seven(b[c])[k]) / 2));
    out[c] = n;
  }
  return out;
}

function insertPoint() {
  edit(job => {
    const i = state.selected, pts = job.points;
    const next = i + 1 < pts.length ? pts[i + 1] : null;
    const prev = i > 0 ? pts[i - 1] : null;
    let p;
    if (next) p = between(pts[i], next);
    else { // past the last: the last mirrored over its neighbour's step
      p = JSON.parse(JSON.stringify(pts[i]));
      for (const c of Object.keys(p)) {
        const d = prev ? pts[i][c].crisp - prev[c].crisp : 1;
        setSeven(p[c], seven(pts[i][c]).map(x => x + d));
      }
    }
    pts.splice(i + 1, 0, p);
    job.weights.splice(i + 1, 0, next ? (job.weights[i] + job.weights[i + 1]) / 2 : job.weights[i]);
    delete job.knots; // clamped uniform for the new number of points
    state.selected = i + 1;
  }, true);
}

function deletePoint() {
  if (state.job.points.length <= 2) return;
  edit(job => {
    job.points.splice(state.selected, 1);
    job.weights.splice(state.selected, 1);
    delete job.knots;
    state.selected = Math.min(state.selected, job.points.length - 1);
  }, true);
}

function download() {
  const text = jobText();
  state.lastDownload = { name: state.name, text };
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  a.download = state.name.replace(/^.*[\\/]/, "") || "job.json";
  document.body.appendChild(a);
  a.click();
  a.remove();
}

/**
 * Saves over the job file. When the file changed on disk since it was read
 * (409, `changed`), the user chooses: overwrite it, or load it as it is now
 * (undo brings the page's job back).
 */
async function save(overwrite) {
  const r = await api("/api/save" + (overwrite ? "?overwrite=1" : ""), jobText());
  if (r.status === 200) {
    $("status").textContent = "saved over " + state.name;
    return;
  }
  const answer = JSON.parse(r.text);
  if (r.status === 409 && answer.changed) {
    const ask = state.name + " changed on disk since it was read.\n" +
      "OK: overwrite it with this page's job.\n" +
      "Cancel: load the file as it is now (undo brings this job back).";
    if (confirm(ask)) return save(true);
    const fresh = await api("/api/job?reload=1");
    if (fresh.status !== 200) {
      $("status").textContent = JSON.parse(fresh.text).problems.join("\n");
      return;
    }
    await load(JSON.parse(fresh.text).text, state.name);
    $("status").textContent = "loaded " + state.name + " as it is on disk";
    return;
  }
  $("status").textContent = answer.problems.join("\n");
}

/** Loads a job's text: its canonical form is what the page edits. */
async function load(text, name) {
  const r = await api("/api/canonical", text);
  if (r.status !== 200) {
    state.problems = JSON.parse(r.text).problems;
    showNumbers();
    return;
  }
  if (state.job) remember();
  state.job = JSON.parse(r.text);
  state.name = name;
  if (!isSurface() && (state.job.type_reduction || "paper") === "paper" && state.job.alpha === undefined) {
    state.job.alpha = 0.5; // a run needs one; the download carries it
  }
  $("job-name").textContent = name;
  state.selected = 0;
  state.view = null;
  state.result = null;
  state.resultText = null;
  state.shownText = null;
  syncFields();
  schedule();
}

function numberField(id, change) {
  $(id).addEventListener("change", () => {
    const x = Number($(id).value);
    if ($(id).value === "" || !Number.isFinite(x)) return;
    edit(job => change(job, x), true);
  });
}

async function main() {
  const start = await api("/api/job");
  if (start.status !== 200) {
    $("status").textContent = JSON.parse(start.text).problems.join("\n");
    return;
  }
  const j = JSON.parse(start.text);
  state.saveable = j.saveable;
  $("save").hidden = !j.saveable;
  $("alpha").addEventListener("input", () => {
    const a = Number($("alpha").value);
    // One entry per slider gesture in the history.
    if (!state.sliding) { remember(); state.sliding = true; }
    state.job.alpha = a;
    showNumbers();
    schedule();
  });
  $("alpha").addEventListener("change", () => { state.sliding = false; });
  $("reduction").addEventListener("change", () => edit(job => { job.type_reduction = $("reduction").value; }));
  numberField("order", (job, k) => { job.degree = Math.round(k) - 1; delete job.knots; });
  numberField("lower-height", (job, h) => {
    for (const p of job.points) for (const c of Object.keys(p)) p[c].lower_height = h;
  });
  numberField("weight", (job, w) => { job.weights[state.selected] = w; });
  $("insert").addEventListener("click", insertPoint);
  $("delete").addEventListener("click", deletePoint);
  $("undo").addEventListener("click", undo);
  $("redo").addEventListener("click", redo);
  $("download").addEventListener("click", download);
  $("save").addEventListener("click", () => save(false));
  $("show-regions").addEventListener("change", draw);
  $("show-layers").addEventListener("change", draw);
  $("show-map").addEventListener("change", schedule);
  $("plot").addEventListener("pointerdown", rotateSurface);
  $("open").addEventListener("change", () => {
    const f = $("open").files[0];
    if (f) f.text().then(t => load(t, f.name));
  });
  document.addEventListener("keydown", e => {
    if (!(e.ctrlKey || e.metaKey) || e.target.tagName === "INPUT") return;
    if (e.key === "z") { e.preventDefault(); undo(); }
    if (e.key === "y") { e.preventDefault(); redo(); }
  });
  await load(j.text, j.name);
}

// For scripts and the browser test.
window.t2splineServe = {
  idle: () => !state.inFlight && !state.pending && state.shownText === jobText(),
  jobText,
  result: () => state.resultText,
  problems: () => state.problems,
  lastDownload: () => state.lastDownload,
  map: () => state.map && { points: state.map.grid.csv, grades: state.map.text },
  requests: () => state.requests,
  load,
};

main();
