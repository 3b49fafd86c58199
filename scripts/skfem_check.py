#!/usr/bin/env python3
"""Independent cross-check of `cdem fem` with scikit-fem (references/skfem.md).

Solves linear elastostatics under gravity on the committed gmsh meshes of the
column and slope cases with trilinear hexahedra (ElementVector(ElementHex1)),
2x2x2 Gauss quadrature (intorder=3), the consistent gravity load
int N_c rho g dV, the scene's materials and boundary groups (each fixes the
listed components to zero), and writes references/skfem.json.

The column and slope cases are solved UNPERTURBED (the Rust test sets
perturbation.ratio = 0 before comparing). The case "slope_perturbed" is
solved on the slope's PERTURBED nodes: node perturbation is cdem's own
(seeded SplitMix64), so the script runs `cdem fem` on slope.toml and takes
the perturbed node coordinates it exports (the points of final.vtu, written
with full precision, in mesh-node order), then solves with scikit-fem on
those coordinates. Only the coordinates come from cdem; the solution is
scikit-fem's.

Usage (from the repository root):
    python -m venv /tmp/skfem-venv
    /tmp/skfem-venv/bin/pip install -r scripts/requirements.txt
    cargo build --release
    /tmp/skfem-venv/bin/python scripts/skfem_check.py [--out references/skfem.json] [--cdem target/release/cdem]
"""

import argparse
import dataclasses
import json
import logging
import platform
import subprocess
import sys
import tempfile
import tomllib
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import meshio
import numpy as np
import scipy
import skfem
from skfem import Basis, BilinearForm, ElementHex1, ElementVector, LinearForm, MeshHex, condense, solve
from skfem.helpers import ddot, div, sym_grad

ROOT = Path(__file__).resolve().parent.parent

# Case name -> (scene file, points (m) where u is reported, points whose
# containing element's average sigma_zz is reported).
CASES = {
    "column": (
        "verification/cases/column/column-merged.toml",
        [[0.0, 0.0, 40.0], [2.0, 2.0, 40.0], [4.0, 4.0, 20.0], [2.0, 2.0, 4.0]],
        [[1.0, 1.0, 1.0], [3.0, 3.0, 21.0], [1.0, 3.0, 39.0]],
    ),
    "slope": (
        "verification/cases/slope/slope.toml",
        [[56.0, 0.0, 40.0], [80.0, 2.0, 40.0], [20.0, 0.0, 20.0], [38.0, 0.0, 30.0], [0.0, 2.0, 20.0], [40.0, 0.0, 10.0]],
        [[79.0, 1.0, 1.0], [30.0, 1.0, 10.0], [21.0, 1.0, 20.5], [60.0, 1.0, 39.5]],
    ),
}
# The perturbed slope: the scene whose perturbed node coordinates `cdem fem` exports.
PERTURBED = {
    "slope_perturbed": (
        "verification/cases/slope/slope.toml",
        [[56.0, 0.0, 40.0], [80.0, 2.0, 40.0], [20.0, 0.0, 20.0], [38.0, 0.0, 30.0], [0.0, 2.0, 20.0], [40.0, 0.0, 10.0]],
        [[79.0, 1.0, 1.0], [30.0, 1.0, 10.0], [21.0, 1.0, 20.5], [60.0, 1.0, 39.5]],
    ),
}
AXES = {"x": 0, "y": 1, "z": 2}


def perturbed_points(cdem, scene_path):
    """The perturbed node coordinates (3, n) of `cdem fem SCENE`: the points of its final.vtu."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "fem"
        subprocess.run([str(cdem), "fem", str(ROOT / scene_path), "--out", str(out)], check=True, capture_output=True)
        root = ET.parse(out / "final.vtu").getroot()
        text = root.find("./UnstructuredGrid/Piece/Points/DataArray").text
    return np.array([float(v) for v in text.split()]).reshape(-1, 3).T


@BilinearForm
def stiffness(u, v, w):
    return w["lam"] * div(u) * div(v) + 2.0 * w["mu"] * ddot(sym_grad(u), sym_grad(v))


@LinearForm
def gravity_load(v, w):
    return w["rho"] * (w["g0"] * v[0] + w["g1"] * v[1] + w["g2"] * v[2])


def solve_case(scene_path, u_points, s_points, points=None):
    scene = tomllib.loads((ROOT / scene_path).read_text())
    # skfem logs "Failure to orient a boundary." for facet sets it cannot
    # orient; orientation is not used here (only the facets' nodes are).
    logging.getLogger("skfem").setLevel(logging.ERROR)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mesh = MeshHex.load(str((ROOT / scene_path).parent / scene["mesh"]["file"]))
    if points is not None:
        # The same mesh with cdem's perturbed coordinates, node for node
        # (mesh-node order; a node moves at most ratio x its shortest edge).
        assert points.shape == mesh.p.shape, f"{points.shape} points for a mesh of {mesh.p.shape}"
        moved = np.linalg.norm(points - mesh.p, axis=0).max()
        assert 0.0 < moved < 0.5, f"perturbed points moved up to {moved} m: not the same node order"
        mesh = dataclasses.replace(mesh, doflocs=points)
    basis = Basis(mesh, ElementVector(ElementHex1()), intorder=3)  # 2x2x2 Gauss
    assert basis.X.shape[1] == 8, "expected the 2x2x2 Gauss rule"

    nel, nqp = basis.dx.shape
    lam, mu, rho = np.full(nel, np.nan), np.full(nel, np.nan), np.full(nel, np.nan)
    for m in scene["material"]:
        e, nu = m["youngs_modulus"], m["poisson_ratio"]
        cells = mesh.subdomains[m["group"]]
        lam[cells] = e * nu / ((1 + nu) * (1 - 2 * nu))
        mu[cells] = e / (2 * (1 + nu))
        rho[cells] = m["density"]
    assert np.all(np.isfinite(lam)), "every element needs a material"
    g = scene.get("loads", {}).get("gravity", [0.0, 0.0, -9.81])
    q = lambda a: np.repeat(a[:, None], nqp, axis=1)  # element-constant -> quadrature points

    K = stiffness.assemble(basis, lam=q(lam), mu=q(mu))
    f = gravity_load.assemble(basis, rho=q(rho), g0=g[0], g1=g[1], g2=g[2])
    fixed = []
    for b in scene.get("boundary", []):
        dofs = basis.get_dofs(mesh.boundaries[b["group"]])
        for a in b["fix"]:
            fixed.append(dofs.nodal[f"u^{AXES[a] + 1}"])
    D = np.unique(np.concatenate(fixed))
    u = solve(*condense(K, f, D=D))
    residual = K @ u - f
    free = np.setdiff1d(np.arange(K.shape[0]), D)
    rel_residual = float(np.linalg.norm(residual[free]) / np.linalg.norm(f[free]))

    # Element-average stress: sum_q w_q detJ_q sigma_q / sum_q w_q detJ_q.
    grad = basis.interpolate(u).grad  # (3, 3, nel, nqp)
    eps = 0.5 * (grad + grad.transpose(1, 0, 2, 3))
    tr = eps[0, 0] + eps[1, 1] + eps[2, 2]
    szz = q(lam) * tr + 2 * q(mu) * eps[2, 2]
    dx = basis.dx
    szz_el = (szz * dx).sum(axis=1) / dx.sum(axis=1)

    p = mesh.p  # (3, nnodes)
    uz = u[basis.nodal_dofs[2]]
    top = np.isclose(p[2], p[2].max())

    def node_at(x):
        d = np.linalg.norm(p - np.array(x)[:, None], axis=0)
        i = int(np.argmin(d))
        # Perturbed: the node nearest to the named point (its coordinates are recorded).
        assert d[i] < (0.5 if points is not None else 1e-9), f"no mesh node at {x}"
        return i

    def element_containing(x):
        # Hexahedra of these meshes are extruded quads; the point is taken
        # strictly inside one element's bounding box, nearest centroid.
        centroids = p[:, mesh.t].mean(axis=1)
        return int(np.argmin(np.linalg.norm(centroids - np.array(x)[:, None], axis=0)))

    return {
        "scene": scene_path,
        "elements": int(nel),
        "nodes": int(p.shape[1]),
        "free_dofs": int(len(free)),
        "relative_residual": rel_residual,
        "max_abs_uz": float(np.abs(uz).max()),
        "min_uz": float(uz.min()),
        "top_mean_uz": float(uz[top].mean()),
        "rms_uz": float(np.sqrt(np.mean(uz**2))),
        "min_element_szz": float(szz_el.min()),
        "max_element_szz": float(szz_el.max()),
        "rms_element_szz": float(np.sqrt(np.mean(szz_el**2))),
        "u_at_nodes": [
            {"x": [float(c) for c in p[:, node_at(x)]], "u": [float(u[basis.nodal_dofs[k][node_at(x)]]) for k in range(3)]}
            for x in u_points
        ],
        "szz_of_element_nearest": [
            {"x": x, "centroid": [float(c) for c in p[:, mesh.t[:, e]].mean(axis=1)], "szz": float(szz_el[e])}
            for x in s_points
            for e in [element_containing(x)]
        ],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="references/skfem.json")
    ap.add_argument("--cdem", default="target/release/cdem", help="the cdem binary that exports the perturbed nodes")
    args = ap.parse_args()
    cases = {name: solve_case(*spec) for name, spec in CASES.items()}
    for name, (scene, u_points, s_points) in PERTURBED.items():
        cases[name] = solve_case(scene, u_points, s_points, perturbed_points(ROOT / args.cdem, scene))
        cases[name]["perturbed"] = True
    result = {
        "what": "scikit-fem solution of the committed column and slope meshes, unperturbed, and of the slope on "
        "the perturbed node coordinates cdem exports (slope_perturbed): trilinear hexahedra, "
        "2x2x2 Gauss (intorder=3), consistent gravity load, element-average sigma_zz = "
        "sum_q w_q detJ_q sigma_zz_q / sum_q w_q detJ_q (Pa), displacements in m",
        "command": "python scripts/skfem_check.py" + ("" if args.out == "references/skfem.json" else f" --out {args.out}"),
        "python": platform.python_version(),
        "scikit_fem": skfem.__version__,
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "meshio": meshio.__version__,
        "cases": cases,
    }
    out = ROOT / args.out
    out.write_text(json.dumps(result, indent=2) + "\n")
    for name, c in result["cases"].items():
        print(f"{name}: max|u_z| {c['max_abs_uz']:.10e} m, min element sigma_zz {c['min_element_szz']:.10e} Pa, "
              f"residual {c['relative_residual']:.1e}", file=sys.stderr)
    print(f"wrote {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
