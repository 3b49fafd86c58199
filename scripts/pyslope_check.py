#!/usr/bin/env python3
"""Independent Bishop cross-check of `cdem lem` with pySlope (Bishop only).

pySlope models a single slope of height H and horizontal length L that faces
+x, inside an external boundary it sizes itself; it has no lower bound for slip
circles. So, for each case:

1. pySlope's own entry-exit search (`analyse_slope`), with its Bishop tightened
   (tolerance=1e-6, max_iterations=200, 50 slices). Reported twice: the minimum
   as shipped, and the minimum among the circles that respect the case's lower
   bound (a filter we apply to pySlope's list of analysed circles).
2. pySlope's Bishop on our critical Bishop circle (from a `cdem lem` JSON),
   with 50 and 500 slices: the same circle through two codes.
3. Timing: pySlope's Bishop on the circles of our default 20 x 20 x 10 grid
   (centres and radii generated here exactly as src/lem/search.rs does).
   `--time-grid CASE` does only this and prints one JSON line: `cdem perf
   --pyslope PYTHON` runs it to time pySlope beside our search.

Coordinates are reported in our frame (the section facing -x): pySlope's
crest (tx, ty) maps to our crest (cx, cz) by x = cx + (tx - x_p),
z = z_p - ty + cz.

Setup (its own venv; pySlope pulls in django and plotly):
    python3 -m venv /tmp/pyslope-venv
    /tmp/pyslope-venv/bin/pip install -r scripts/requirements-lem.txt
Run (from the crate root):
    cargo run --release -- lem verification/lem/acads-1a.toml --out /tmp/acads-1a.json
    cargo run --release -- lem verification/lem/paper-slope.toml --out /tmp/paper-slope.json
    /tmp/pyslope-venv/bin/python scripts/pyslope_check.py \
        --ours acads_1a=/tmp/acads-1a.json --ours paper_slope=/tmp/paper-slope.json \
        --out references/pyslope.json
"""

import argparse
import json
import math
import os
import platform
import sys
import time
from importlib import metadata

os.environ.setdefault("TQDM_DISABLE", "1")

import pyslope as ps  # noqa: E402

# name: (H, L, c kPa, phi deg, gamma kN/m^3, lower bound below the toe (m), our toe, our crest)
CASES = {
    "acads_1a": (10.0, 20.0, 3.0, 19.6, 20.0, 5.0, (30.0, 25.0), (50.0, 35.0)),
    "paper_slope": (20.0, 36.0, 16.0, 18.0, 20.6, 20.0, (20.0, 20.0), (56.0, 40.0)),
    # docs/method.md section 3 quotes pySlope 1.064 for a 30 deg slope of the same height.
    "paper_30deg": (20.0, 20.0 / math.tan(math.radians(30.0)), 16.0, 18.0, 20.6, 20.0, (20.0, 20.0), (20.0 + 20.0 / math.tan(math.radians(30.0)), 40.0)),
}


def make_slope(h, length, c, phi, gamma, depth, slices):
    s = ps.Slope(height=h, length=length)
    s.set_materials(ps.Material(unit_weight=gamma, friction_angle=phi, cohesion=c, depth_to_bottom=h + depth))
    s.update_analysis_options(slices=slices, tolerance=1e-6, max_iterations=200)
    return s


class Frame:
    def __init__(self, s, toe, crest):
        (self.tx, self.ty), self.crest, self.toe = s._top_coord, crest, toe

    def to_ours(self, x, z):
        return self.crest[0] + (self.tx - x), z - self.ty + self.crest[1]

    def to_pyslope(self, x, z):
        return self.tx - (x - self.crest[0]), z + self.ty - self.crest[1]


def respects_lower_bound(p, z_lb_p):
    """The lowest point of the slip arc (pySlope frame) is not below z_lb_p."""
    (lx, _), (rx, _) = p["l_c"], p["r_c"]
    lowest = p["c_y"] - p["radius"] if lx <= p["c_x"] <= rx else min(p["l_c"][1], p["r_c"][1])
    return lowest >= z_lb_p - 1e-9


def circle_ours(fr, p):
    xc, zc = fr.to_ours(p["c_x"], p["c_y"])
    ent = fr.to_ours(*p["l_c"])  # pySlope's left point is on the crest side
    ext = fr.to_ours(*p["r_c"])
    return {"fs": p["FOS"], "xc": xc, "zc": zc, "r": p["radius"], "entry": list(ent), "exit": list(ext)}


def search(name, iterations):
    h, length, c, phi, gamma, depth, toe, crest = CASES[name]
    s = make_slope(h, length, c, phi, gamma, depth, 50)
    s.update_analysis_options(iterations=iterations)
    fr = Frame(s, toe, crest)
    t0 = time.perf_counter()
    s.analyse_slope()
    wall = time.perf_counter() - t0
    planes = s._search  # sorted by FOS, failed ones removed
    z_lb = fr.to_pyslope(0.0, toe[1] - depth)[1]
    ok = [p for p in planes if respects_lower_bound(p, z_lb)]
    return {
        "iterations": iterations,
        "circles_with_fs": len(planes),
        "wall_s": wall,
        "min_as_shipped": circle_ours(fr, planes[0]) if planes else None,
        "min_above_lower_bound": circle_ours(fr, ok[0]) if ok else None,
    }


def on_circle(name, circle, slices):
    h, length, c, phi, gamma, depth, toe, crest = CASES[name]
    s = make_slope(h, length, c, phi, gamma, depth, slices)
    fr = Frame(s, toe, crest)
    x, z = fr.to_pyslope(circle["xc"], circle["zc"])
    s.add_single_circular_plane(x, z, circle["r"])
    s.analyse_slope()
    return s.get_min_FOS() if s._search else None


def dist_to_polyline(p, q):
    best = math.inf
    for a, b in zip(p, p[1:]):
        ab = (b[0] - a[0], b[1] - a[1])
        t = ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)
        t = min(max(t, 0.0), 1.0)
        best = min(best, math.hypot(a[0] + t * ab[0] - q[0], a[1] + t * ab[1] - q[1]))
    return best


def our_grid(name, nx=20, nz=20, nr=10):
    """The circles of src/lem/search.rs's default grid (our frame)."""
    h, length, _, _, _, depth, toe, crest = CASES[name]
    ground = [(toe[0] - 2 * length, toe[1]), toe, crest, (crest[0] + 2 * length, crest[1])]
    wf = max(crest[0] - toe[0], h)
    xr = (toe[0] - 0.25 * wf, crest[0] + 0.25 * wf)
    zr = (toe[1] + 0.5 * h, crest[1] + max(h, wf))
    lin = lambda r, i, n: r[0] + (r[1] - r[0]) * i / (n - 1)  # noqa: E731
    z_min = toe[1] - depth
    out = []
    for i in range(nx):
        for j in range(nz):
            xc, zc = lin(xr, i, nx), lin(zr, j, nz)
            lo, hi = dist_to_polyline(ground, (xc, zc)), zc - z_min
            if hi > lo:
                out += [(xc, zc, lo + (hi - lo) * (q + 1) / nr) for q in range(nr)]
    return out


def time_grid(name):
    h, length, c, phi, gamma, depth, toe, crest = CASES[name]
    s = make_slope(h, length, c, phi, gamma, depth, 50)
    fr = Frame(s, toe, crest)
    circles = our_grid(name)
    t0 = time.perf_counter()
    for xc, zc, r in circles:
        x, z = fr.to_pyslope(xc, zc)
        s.add_single_circular_plane(x, z, r)
    t1 = time.perf_counter()
    s.analyse_slope()
    t2 = time.perf_counter()
    return {"grid": "20x20x10", "trial_circles": len(circles), "circles_with_fs": len(s._search), "add_planes_s": t1 - t0, "bishop_s": t2 - t1, "total_s": t2 - t0}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ours", action="append", default=[], help="CASE=PATH of a `cdem lem` JSON")
    ap.add_argument("--iterations", type=int, default=10000, help="pySlope trial circles (its `iterations`)")
    ap.add_argument("--out", default="references/pyslope.json")
    ap.add_argument("--time-grid", metavar="CASE", choices=sorted(CASES), help="only time our grid on CASE: print one JSON line (`cdem perf --pyslope`)")
    args = ap.parse_args()
    if args.time_grid:
        print(json.dumps({"case": args.time_grid, "pyslope_version": metadata.version("pyslope"), **time_grid(args.time_grid)}))
        return
    ours = dict(a.split("=", 1) for a in args.ours)
    result = {
        "pyslope_version": metadata.version("pyslope"),
        "numpy_version": metadata.version("numpy"),
        "python_version": platform.python_version(),
        "command": " ".join(["python"] + [os.path.relpath(sys.argv[0])] + sys.argv[1:]),
        "settings": {"slices": 50, "tolerance": 1e-6, "max_iterations": 200},
        "cases": {},
    }
    for name in CASES:
        case = {"search": search(name, args.iterations)}
        if name in ours:
            with open(ours[name]) as f:
                crit = json.load(f)["critical"]["bishop"]
            case["our_bishop_circle"] = {k: crit[k] for k in ("xc", "zc", "r", "fs")}
            case["pyslope_on_our_circle"] = {"slices_50": on_circle(name, crit, 50), "slices_500": on_circle(name, crit, 500)}
            case["timing_our_grid"] = time_grid(name)
        result["cases"][name] = case
        print(name, json.dumps(case, indent=1))
    with open(args.out, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    print("wrote", args.out)


if __name__ == "__main__":
    main()
