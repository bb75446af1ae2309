"""Reads `t2spline export` files back with software that is not ours and
compares every curve with `t2spline run`'s samples.

DXF is read by ezdxf, STEP and IGES by OpenCASCADE (cadquery-ocp), OBJ by the
small reader below, written from the OBJ specification ("Free-form
curve/surface attributes": `cstype rat bspline`, `deg`, `curv`, `parm u`).
The DXF numbers are also evaluated by the de Boor evaluator below
("dxf-data"), which tells the file's accuracy apart from ezdxf's evaluator
(it normalizes knots to [0, 1] and loses up to about 1e-9 of the size there).
Every exported curve (crisp, defuzzified, six layers; each piece of a curve
that jumps) is evaluated at the parameters of `t2spline run` and must agree
with the run's sampled curve to 1e-9, relative to the largest coordinate of
the job's curves. Names are checked too: DXF layers, STEP entity names, IGES
name properties, OBJ groups.

    python peer/cad/check_cad.py --bin target/release/t2spline --cases 60

Cases: the shipped examples, and random jobs in 2-D and 3-D of degree 1-5
with clamped, unclamped and repeated knots (interior multiplicities up to
the degree, and of full multiplicity, where the curve jumps), and knots of
full multiplicity at an end of the domain with knots beyond it ("outside":
control points that act only outside the domain).
"""

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path

import ezdxf
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_BSplineCurve, GeomAbs_BSplineSurface
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.StepToGeom import StepToGeom
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

NAMES = ["crisp", "defuzzified", "upper_left", "primary_left", "lower_left",
         "lower_right", "primary_right", "upper_right"]
TOLERANCE = 1e-9
ROOT = Path(__file__).resolve().parents[2]


# ---- evaluation: a piece is (start, end, f) with f(t) -> (x, y, z) ----------

def pick(pieces, t):
    """The piece whose domain holds t; at a jump the right one (t2spline's rule)."""
    pieces = sorted(pieces, key=lambda p: p[0])
    for i, (a, b, f) in enumerate(pieces):
        if a <= t < b or (i == len(pieces) - 1 and a <= t <= b):
            return f
    raise AssertionError(f"no piece holds t = {t}: {[(a, b) for a, b, _ in pieces]}")


def read_dxf(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors, [e.message for e in auditor.errors]
    curves = {}
    for e in doc.modelspace():
        assert e.dxftype() == "SPLINE", e.dxftype()
        spline = e.construction_tool()
        p = spline.degree
        # The file's knots give the domain; ezdxf evaluates on its own
        # (normalized) knots, an affine map of them, which leaves the curve
        # unchanged.
        raw, own = list(e.knots), list(spline.knots())
        assert len(raw) == len(own)
        a, b = raw[p], raw[len(raw) - p - 1]
        lo, hi = own[p], own[len(own) - p - 1]
        f = (lambda s, a, b, lo, hi: lambda t: tuple(s.point(lo + (t - a) * (hi - lo) / (b - a))))(
            spline, a, b, lo, hi)
        curves.setdefault(e.dxf.layer, []).append((a, b, f))
    return curves


def read_dxf_data(path):
    """The DXF file's numbers as ezdxf reads them, evaluated by de Boor's
    algorithm below: the accuracy of the file itself, apart from ezdxf's
    evaluator (which works on knots normalized to [0, 1])."""
    curves = {}
    for e in ezdxf.readfile(path).modelspace():
        knots, p = list(e.knots), e.dxf.degree
        weights = list(e.weights) or [1.0] * len(e.control_points)
        points = [(x, y, z, w) for (x, y, z), w in zip(e.control_points, weights)]
        a, b = knots[p], knots[len(knots) - p - 1]
        curves.setdefault(e.dxf.layer, []).append(
            (a, b, (lambda k, q, d: lambda t: de_boor(k, q, d, t))(knots, points, p)))
    return curves


def ocp_edges(shape):
    out = []
    explorer = TopExp_Explorer(shape, TopAbs_EDGE)
    while explorer.More():
        edge = TopoDS.Edge(explorer.Current())
        # The edge as a CAD program sees it: its curve, range and placement.
        curve = BRepAdaptor_Curve(edge)
        assert curve.GetType() == GeomAbs_BSplineCurve, curve.GetType()
        assert curve.BSpline().IsRational() or curve.BSpline().Weight(1) == 1.0
        f = (lambda c: lambda t: (lambda q: (q.X(), q.Y(), q.Z()))(c.Value(t)))(curve)
        out.append((curve.FirstParameter(), curve.LastParameter(), f))
        explorer.Next()
    return out


def read_step(path):
    reader = STEPControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    # The file as a CAD program opens it: one product, a wire frame of curves.
    assert reader.TransferRoots() == 1
    edges = len(ocp_edges(reader.OneShape()))
    model = reader.Model()
    curves = {}
    for i in range(1, model.NbEntities() + 1):
        entity = model.Value(i)
        if entity.DynamicType().Name() != "StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve":
            continue
        # OCCT's own translation of the entity (the one its reader uses).
        curve = StepToGeom.MakeBSplineCurve_s(entity)
        f = (lambda c: lambda t: (lambda q: (q.X(), q.Y(), q.Z()))(c.Value(t)))(curve)
        curves.setdefault(entity.Name().ToCString(), []).append(
            (curve.FirstParameter(), curve.LastParameter(), f))
    # OCCT may cut a curve at C0 knots into several edges, never fewer.
    assert edges >= sum(map(len, curves.values())), edges
    return curves


def read_iges(path):
    reader = IGESControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    curves = {}
    for i in range(1, reader.NbRootsForTransfer() + 1):
        entity = reader.RootForTransfer(i)
        assert entity.TypeNumber() == 126, entity.TypeNumber()
        assert entity.HasName(), "no name property"
        assert reader.TransferOneRoot(i)
        # OCCT cuts a curve at C0 knots into several edges of one curve.
        curves.setdefault(entity.NameValue().ToCString(), []).extend(
            ocp_edges(reader.Shape(reader.NbShapes())))
    return curves


def read_obj(path):
    """OBJ free-form curves: v x y z w; cstype rat bspline; deg p; curv u0 u1 i...; parm u ...; end."""
    vertices, curves = [], {}
    group, state = "default", {}
    for raw in Path(path).read_text().splitlines():
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        key, args = words[0], words[1:]
        if key == "v":
            x, y, z = map(float, args[:3])
            vertices.append((x, y, z, float(args[3]) if len(args) > 3 else 1.0))
        elif key == "g":
            group = args[0]
        elif key == "cstype":
            assert args == ["rat", "bspline"], args
        elif key == "deg":
            state["deg"] = int(args[0])
            state["deg2"] = int(args[1]) if len(args) > 1 else None
        elif key == "surf":
            state["range"] = tuple(map(float, args[:4]))
            state["points"] = [vertices[int(i) - 1 if int(i) > 0 else int(i)] for i in args[4:]]
        elif key == "curv":
            state["range"] = (float(args[0]), float(args[1]))
            state["points"] = [vertices[int(i) - 1 if int(i) > 0 else int(i)] for i in args[2:]]
        elif key == "parm":
            state["knots" if args[0] == "u" else "knots_v"] = list(map(float, args[1:]))
        elif key == "end" and "knots_v" in state:
            # A surface: control points with the u index varying fastest.
            p, q, ku, kv = state["deg"], state["deg2"], state["knots"], state["knots_v"]
            nu, nv = len(ku) - p - 1, len(kv) - q - 1
            flat = state["points"]
            assert len(flat) == nu * nv, (len(flat), nu, nv)
            net = [[flat[j * nu + i] for j in range(nv)] for i in range(nu)]
            u0, u1, v0, v1 = state["range"]
            curves.setdefault(group, []).append(
                (u0, u1, v0, v1,
                 (lambda a, b, n_, p_, q_: lambda u, v: de_boor_surface(a, b, n_, p_, q_, u, v))(
                     ku, kv, net, p, q)))
            state = {}
        elif key == "end":
            p, knots, points = state["deg"], state["knots"], state["points"]
            assert len(knots) == len(points) + p + 1
            a, b = state["range"]
            curves.setdefault(group, []).append(
                (a, b, (lambda k, q, d: lambda t: de_boor(k, q, d, t))(knots, points, p)))
            state = {}
    return curves


def de_boor_h(knots, hpoints, p, t):
    """A B-spline of homogeneous points (w·x, w·y, w·z, w) at t by de Boor's
    algorithm; at an interior knot the span to the right, at the end of the
    domain the last non-empty span."""
    n = len(hpoints)
    span = p
    while span < n - 1 and knots[span + 1] <= t:
        span += 1
    while span > p and knots[span] == knots[span + 1]:
        span -= 1
    d = [list(q) for q in hpoints[span - p:span + 1]]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = span - p + j
            den = knots[i + p - r + 1] - knots[i]
            a = 0.0 if den == 0 else (t - knots[i]) / den
            d[j] = [(1 - a) * u + a * v for u, v in zip(d[j - 1], d[j])]
    return d[p]


def homogeneous(x, y, z, w):
    return (w * x, w * y, w * z, w)


def de_boor(knots, points, p, t):
    """A rational B-spline curve of points (x, y, z, w) at t."""
    x, y, z, w = de_boor_h(knots, [homogeneous(*q) for q in points], p, t)
    return (x / w, y / w, z / w)


def de_boor_surface(ku, kv, net, p, q, u, v):
    """A rational tensor-product surface of net[i][j] = (x, y, z, w) at (u, v):
    each column along u first, then the results along v."""
    columns = [de_boor_h(ku, [homogeneous(*net[i][j]) for i in range(len(net))], p, u)
               for j in range(len(net[0]))]
    x, y, z, w = de_boor_h(kv, columns, q, v)
    return (x / w, y / w, z / w)


def ocp_faces(shape):
    """The faces of a shape as (u0, u1, v0, v1, f): the face's parameter
    bounds and its surface."""
    out = []
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    while explorer.More():
        surface = BRepAdaptor_Surface(TopoDS.Face(explorer.Current()), True)
        assert surface.GetType() == GeomAbs_BSplineSurface, surface.GetType()
        f = (lambda s_: lambda u, v: (lambda q: (q.X(), q.Y(), q.Z()))(s_.Value(u, v)))(surface)
        out.append((surface.FirstUParameter(), surface.LastUParameter(),
                    surface.FirstVParameter(), surface.LastVParameter(), f))
        explorer.Next()
    return out


def read_step_surfaces(path):
    reader = STEPControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    assert reader.TransferRoots() == 1
    faces = len(ocp_faces(reader.OneShape()))
    model = reader.Model()
    surfaces = {}
    for i in range(1, model.NbEntities() + 1):
        entity = model.Value(i)
        if entity.DynamicType().Name() != "StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface":
            continue
        surface = StepToGeom.MakeBSplineSurface_s(entity)
        u0, u1, v0, v1 = surface.Bounds()
        f = (lambda s_: lambda u, v: (lambda q: (q.X(), q.Y(), q.Z()))(s_.Value(u, v)))(surface)
        surfaces.setdefault(entity.Name().ToCString(), []).append((u0, u1, v0, v1, f))
    assert faces >= sum(map(len, surfaces.values())), faces
    return surfaces


def read_iges_surfaces(path):
    reader = IGESControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    surfaces = {}
    for i in range(1, reader.NbRootsForTransfer() + 1):
        entity = reader.RootForTransfer(i)
        assert entity.TypeNumber() == 128, entity.TypeNumber()
        assert entity.HasName(), "no name property"
        assert reader.TransferOneRoot(i)
        surfaces.setdefault(entity.NameValue().ToCString(), []).extend(
            ocp_faces(reader.Shape(reader.NbShapes())))
    return surfaces


def pick_patch(patches, u, v):
    """The patch that holds (u, v); at a shared edge the one to the right
    (larger parameter), as for curves."""
    def holds(a, b, t, last):
        return a <= t < b or (last and a <= t <= b)
    u_last = max(p[1] for p in patches)
    v_last = max(p[3] for p in patches)
    for u0, u1, v0, v1, f in patches:
        if holds(u0, u1, u, u1 == u_last) and holds(v0, v1, v, v1 == v_last):
            return f
    raise AssertionError(f"no patch holds {(u, v)}: {[p[:4] for p in patches]}")


SURFACE_READERS = {"step": read_step_surfaces, "iges": read_iges_surfaces, "obj": read_obj}


READERS = {"dxf": read_dxf, "dxf-data": read_dxf_data, "step": read_step, "iges": read_iges,
           "obj": read_obj}


# ---- jobs --------------------------------------------------------------------

def number(rng, c):
    left = sorted(rng.uniform(0, 1.5) * rng.choice([0, 1, 1]) for _ in range(3))
    right = sorted(rng.uniform(0, 1.5) * rng.choice([0, 1, 1]) for _ in range(3))
    return {"crisp": c, "upper": [c - left[2], c + right[2]],
            "primary": [c - left[1], c + right[1]], "lower": [c - left[0], c + right[0]],
            "lower_height": rng.choice([1.0, rng.uniform(0.2, 1.0)])}


def knots(rng, n, p, kind):
    """None (the default, clamped uniform) or a knot vector of the kind asked."""
    k = p + 1
    if kind == "clamped":
        return None
    if kind == "unclamped":
        return sorted(rng.uniform(-3, 5) for _ in range(n + k))
    if kind == "outside":
        # A knot of full multiplicity k at an end of the domain [U[p], U[n]]
        # with knots beyond it (at the end, the start or both; needs
        # n >= k + 2p): the control points beyond act outside the domain
        # only, and t2spline cuts them off before writing. Order 3 at the
        # end: (0, 0, 0, 0.5, 0.5, 0.5, 1) with domain [0, 0.5].
        side = rng.choice(["end", "start", "both"])
        before = rng.randint(1, p) if side in ("start", "both") else 0
        after = rng.randint(1, p) if side in ("end", "both") else 0
        a, b = 0.0, round(rng.uniform(0.4, 0.9), 3)
        interior = sorted({round(rng.uniform(a + 0.01, b - 0.01), 4)
                           for _ in range(n - k - before - after)})
        while len(interior) < n - k - before - after:
            interior = sorted(set(interior) | {round(rng.uniform(a + 0.01, b - 0.01), 4)})
        return (sorted(rng.uniform(-1, -0.01) for _ in range(before)) + [a] * k + interior
                + [b] * k + sorted(rng.uniform(b + 0.01, 1.5) for _ in range(after)))
    # Interior multiplicities up to p; a "jump" adds one knot of full
    # multiplicity k at 0.5, a sample parameter.
    interior = n - k
    values = [0.5] * k if kind == "jump" else []
    used = {0.5}
    while len(values) < interior:
        v = round(rng.uniform(0.05, 0.95), 3)
        if v in used:
            continue
        used.add(v)
        values.extend([v] * min(rng.randint(1, p), interior - len(values)))
    return [0.0] * k + sorted(values) + [1.0] * k


def extra_points(p, kind):
    """Control points beyond the order that a kind of knot vector needs."""
    return {"jump": p + 1, "outside": 2 * p}.get(kind, 0)


def random_job(rng, case):
    dim = 2 + case % 2
    p = 1 + (case // 2) % 5
    kind = ["clamped", "unclamped", "repeated", "jump", "outside"][(case // 10) % 5]
    n = p + 1 + rng.randint(0, 6) + extra_points(p, kind)
    axes = "xyz"[:dim]
    walk = [0.0] * dim
    points = []
    for _ in range(n):
        walk = [w + rng.uniform(-3, 3) for w in walk]
        points.append({a: number(rng, walk[i]) for i, a in enumerate(axes)})
    job = {"degree": p, "alpha": rng.uniform(0, 1), "samples": 201,
           "weights": [rng.uniform(0.2, 5) for _ in range(n)], "points": points}
    u = knots(rng, n, p, kind)
    if u is not None:
        job["knots"] = u
    return job, f"random {dim}-D degree {p} {kind}"


def random_surface(rng, case, folder):
    """A fuzzy surface (docs/method.md §8) of degrees 1-4 in each direction, knots of
    one kind per direction, for the surface example."""
    degree = [1 + case % 4, 1 + (case // 4) % 4]
    every = ["clamped", "unclamped", "repeated", "jump", "outside"]
    kinds = [every[(case // 4) % 5], every[(case // 4 + 1 + case % 2) % 5]]
    shape = [p + 1 + rng.randint(0, 3) + extra_points(p, kind)
             for p, kind in zip(degree, kinds)]
    points = [[{a: number(rng, base) for a, base in zip("xyz", (i + rng.uniform(-0.3, 0.3),
                                                                j + rng.uniform(-0.3, 0.3),
                                                                rng.uniform(-1, 1)))}
               for j in range(shape[1])] for i in range(shape[0])]
    job = {"degree": degree, "knots": [knots(rng, n, p, k) for n, p, k in zip(shape, degree, kinds)],
           "weights": [[rng.uniform(0.2, 5) for _ in range(shape[1])] for _ in range(shape[0])],
           "points": points, "alpha": rng.uniform(0, 1), "samples": [23, 19], "folder": str(folder)}
    return job, f"surface degree {degree}, knots {kinds[0]} × {kinds[1]}"


def check_surfaces(example, job, label, worst):
    """Our surface files read back, against our run's samples."""
    out = json.loads(subprocess.run([example], input=json.dumps(job), check=True,
                                    capture_output=True, text=True).stdout)
    reference = out["surfaces"]
    scale = max(1.0, max(abs(x) for grid in reference.values() for row in grid
                         for pt in row for x in pt))
    for fmt, reader in SURFACE_READERS.items():
        exported = reader(Path(job["folder"]) / f"surfaces.{fmt}")
        assert sorted(exported) == sorted(NAMES), (label, fmt, sorted(exported))
        key = f"{fmt} surfaces"
        for name in NAMES:
            for a, u in enumerate(out["u"]):
                for b, v in enumerate(out["v"]):
                    got = pick_patch(exported[name], u, v)(u, v)
                    want = reference[name][a][b]
                    error = math.dist(got, want) / scale
                    if error > worst.get(key, (0.0, ""))[0]:
                        worst[key] = (error, f"{label}: {name} at ({u}, {v})")
                    assert error <= TOLERANCE, f"{label}, {fmt}, {name}, ({u}, {v}): {got} vs {want}"
        worst[key + " files"] = (worst.get(key + " files", (0, ""))[0] + 1, "")


# ---- the check ---------------------------------------------------------------

def check(binary, job_path, label, folder, worst):
    run = json.loads(subprocess.run([binary, "run", job_path, "--samples", "201"],
                                    check=True, capture_output=True, text=True).stdout)
    curves = run["curves"]
    reference = {"crisp": curves["crisp"], "defuzzified": curves["defuzzified"],
                 **curves["layers"]}
    scale = max(1.0, max(abs(x) for pts in reference.values() for pt in pts for x in pt))
    dim = run["dimension"]
    for fmt, reader in READERS.items():
        out = Path(folder) / f"curves.{fmt.split('-')[0]}"
        if fmt != "dxf-data":
            subprocess.run([binary, "export", job_path, "-o", str(out)], check=True,
                           capture_output=True, env={**os.environ, "SOURCE_DATE_EPOCH": "0"})
        exported = reader(out)
        assert sorted(exported) == sorted(NAMES), (label, fmt, sorted(exported))
        for name in NAMES:
            for t, want in zip(curves["params"], reference[name]):
                got = pick(exported[name], t)(t)
                want = list(want) + [0.0] * (3 - dim)
                error = math.dist(got, want) / scale
                if error > worst[fmt][0]:
                    worst[fmt] = (error, f"{label}: {name} at t = {t}")
                assert error <= TOLERANCE, f"{label}, {fmt}, {name}, t = {t}: {got} vs {want}"
        worst[fmt + " files"] = (worst.get(fmt + " files", (0, ""))[0] + 1, "")


#: `--units`: the millimetres in one unit, DXF's `$INSUNITS` code and the
#: comment of an OBJ file.
UNITS = {"mm": (1.0, 4), "cm": (10.0, 5), "m": (1000.0, 6), "in": (25.4, 1), "ft": (304.8, 2)}


def shape_points(shape):
    """Points of every edge of an OCCT shape, at five parameters each."""
    out = []
    for a, b, f in ocp_edges(shape):
        out.extend(f(a + (b - a) * k / 4) for k in range(5))
    return out


def check_units(binary, job_path, folder):
    """Each unit as the readers take it: OCCT converts STEP and IGES to
    millimetres on transfer, so each point is the millimetre file's times
    the unit's length; ezdxf reads `$INSUNITS`; OBJ says it in a comment."""
    reference = {}
    for unit, (mm, code) in UNITS.items():
        for fmt in ("step", "igs", "dxf", "obj"):
            out = Path(folder) / f"units-{unit}.{fmt}"
            subprocess.run([binary, "export", job_path, "-o", str(out), "--units", unit],
                           check=True, capture_output=True)
            if fmt == "dxf":
                assert ezdxf.readfile(out).header["$INSUNITS"] == code, (unit, fmt)
                continue
            if fmt == "obj":
                assert f"units: {unit} " in out.read_text(), (unit, fmt)
                continue
            reader = STEPControl_Reader() if fmt == "step" else IGESControl_Reader()
            assert reader.ReadFile(str(out)) == IFSelect_RetDone
            reader.TransferRoots()
            points = shape_points(reader.OneShape())
            if unit == "mm":
                reference[fmt] = points
                continue
            want = reference[fmt]
            assert len(points) == len(want), (unit, fmt)
            scale = max(1.0, max(abs(x) for p in want for x in p))
            for got, base in zip(points, want):
                error = math.dist(got, [mm * x for x in base]) / (mm * scale)
                assert error <= TOLERANCE, f"{unit}, {fmt}: {got} vs {base} x {mm}"
    return len(UNITS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--cases", type=int, default=60)
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--surface-example",
                        help="the example program that exports fuzzy surfaces (until t2spline reads surface jobs)")
    parser.add_argument("--surface-cases", type=int, default=32)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    worst = {fmt: (0.0, "") for fmt in READERS}
    passed = failed = 0
    kinds = {}
    with tempfile.TemporaryDirectory() as folder:
        jobs = [(str(ROOT / "examples/paper-alg-1-1.json"), "examples/paper-alg-1-1.json"),
                (str(ROOT / "fixtures/spiral-3d.json"), "fixtures/spiral-3d.json")]
        # The beach example, from its readings to a fitted job, as the README does.
        beach = Path(folder) / "beach-job.json"
        subprocess.run([args.bin, "fit", str(ROOT / "examples/beach-readings.csv"),
                        "--tolerance", "0.02", "-q", "-o", str(beach)], check=True)
        job = json.loads(beach.read_text())
        job["alpha"] = 0.5
        beach.write_text(json.dumps(job))
        jobs.append((str(beach), "examples/beach-readings.csv, fitted"))
        for case in range(args.cases):
            job, label = random_job(rng, case)
            path = Path(folder) / f"job{case}.json"
            path.write_text(json.dumps(job))
            jobs.append((str(path), f"case {case} ({label})"))
        units = check_units(args.bin, jobs[0][0], folder)
        print(f"units: {units} units, each read back as STEP, IGES, DXF and OBJ readers take it")
        for path, label in jobs:
            try:
                check(args.bin, path, label, folder, worst)
                passed += 1
                kind = label.split("(")[-1].rstrip(")").rsplit(" ", 1)[-1] if "random" in label else "shipped"
                kinds[kind] = kinds.get(kind, 0) + 1
            # A reader's own exception (OpenCASCADE's Standard_Failure when it
            # refuses an entity) is a failed case too, not the end of the check.
            except Exception as e:  # noqa: BLE001
                failed += 1
                detail = e.stderr if isinstance(e, subprocess.CalledProcessError) else repr(e)
                print(f"FAIL {label}: {detail}", file=sys.stderr)
        if args.surface_example:
            for case in range(args.surface_cases):
                job, label = random_surface(rng, case, folder)
                try:
                    check_surfaces(args.surface_example, job, f"surface case {case} ({label})", worst)
                    passed += 1
                    kinds["surface"] = kinds.get("surface", 0) + 1
                except Exception as e:  # noqa: BLE001 (as for curves)
                    failed += 1
                    detail = e.stderr if isinstance(e, subprocess.CalledProcessError) else repr(e)
                    print(f"FAIL surface case {case} ({label}): {detail}", file=sys.stderr)
    for fmt in list(READERS) + [f"{f} surfaces" for f in SURFACE_READERS]:
        if fmt not in worst:
            continue
        error, where = worst[fmt]
        files = worst.get(fmt + " files", (0, ""))[0]
        print(f"{fmt}: {files} files read back, largest relative difference {error:.2e} ({where})")
    print("jobs by kind: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())))
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
