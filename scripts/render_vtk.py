#!/usr/bin/env python3
"""Render a `cdem run` / `cdem fem` VTK frame to a PNG, off screen.

Reference viewer for the VTK output of this project (docs/method.md section 5):
the mesh warped by its displacement, coloured by |u| or by a cell field
(`szz`, ...), and optionally the "opened joints": CDEM gives every element its
own copy of each corner node, so copies that share a reference position but
have moved apart mark a joint that opened or slipped. For every point the gap
is the largest distance between its displacement and that of another copy at
the same reference position, `gap_i = max_j |u_i - u_j|` (m). Springs that
hold deform a little too (`F / K_n`, micrometres on the paper slope), so only
gaps above `--gap-min` are drawn (default 1e-3 of the largest |u|).

Setup (own virtual environment, never committed):

    python3 -m venv /tmp/viz-venv
    /tmp/viz-venv/bin/pip install -r scripts/requirements-viz.txt

Off-screen rendering needs no display: this script selects VTK's EGL render
window (`VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow`, unless already set),
which on a machine without a GPU renders with Mesa's llvmpipe (Debian:
`apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri`). Without EGL, install
`libosmesa6` and run with `VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow`.

Usage:

    cargo run --release -- run verification/cases/slope/slope.toml --out /tmp/slope-out
    /tmp/viz-venv/bin/python scripts/render_vtk.py /tmp/slope-out/final.vtu -o /tmp/slope-umag.png
    /tmp/viz-venv/bin/python scripts/render_vtk.py /tmp/slope-out/run.pvd --field szz -o /tmp/slope-szz.png

    cargo run --release -- run verification/cases/slope-slip/slope-slip.toml --out /tmp/slip-out
    /tmp/viz-venv/bin/python scripts/render_vtk.py /tmp/slip-out/failure.pvd --joints --scale 10 -o /tmp/slip.png

Options: `--frame K` picks a `.pvd` frame (Python index, default -1: the
last); `--scale` the displacement magnification (default: largest |u| drawn
as 5 % of the model's diagonal); `--view front|iso`; `--clim LO HI`;
`--edges`; `--size W H`. Prints what it drew (frame, scale, field range,
number of opened-joint points, largest gap).
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

import numpy as np  # noqa: E402
import pyvista as pv  # noqa: E402

DISPLACEMENT = "displacement"
# Point array of |u|; no "|" in names or titles: VTK's text renderer drops it.
UMAG = "umag"


def frame_of(path: Path, index: int) -> tuple[Path, str]:
    """The `.vtu` to draw and a label: the file itself, or frame `index` of a `.pvd`."""
    if path.suffix != ".pvd":
        return path, path.name
    sets = ET.parse(path).getroot().findall("./Collection/DataSet")
    if not sets:
        sys.exit(f"{path}: no DataSet in the collection")
    try:
        ds = sets[index]
    except IndexError:
        sys.exit(f"{path}: frame {index} out of range ({len(sets)} frames)")
    file = path.parent / ds.get("file")
    return file, f"{path.name} frame {index % len(sets)} of {len(sets)} (step {float(ds.get('timestep', 'nan')):.0f})"


def joint_gaps(points: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Per point, the largest |u_i - u_j| over the other points at the same
    reference position (0 for a point without copies)."""
    scale = max(float(np.ptp(points, axis=0).max()), 1.0)
    key = np.round(points / (1e-9 * scale)).astype(np.int64)
    _, group, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    group = group.ravel()
    order = np.argsort(group, kind="stable")
    starts = np.concatenate(([0], np.cumsum(counts)[:-1]))
    rank = np.empty(len(points), dtype=np.int64)
    rank[order] = np.arange(len(points)) - np.repeat(starts, counts)
    # Padded table: members[g, r] = point index, -1 where a group is shorter.
    members = np.full((len(counts), counts.max()), -1, dtype=np.int64)
    members[group, rank] = np.arange(len(points))
    valid = members >= 0
    uu = u[np.where(valid, members, 0)]
    dist = np.linalg.norm(uu[:, :, None, :] - uu[:, None, :, :], axis=-1)
    dist = np.where(valid[:, :, None] & valid[:, None, :], dist, 0.0)
    return dist.max(axis=2)[group, rank]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input", type=Path, help=".vtu, or .pvd (draws its last frame unless --frame)")
    ap.add_argument("-o", "--out", type=Path, default=Path("render.png"), help="PNG to write (default render.png)")
    ap.add_argument("--frame", type=int, default=-1, help="frame of a .pvd, Python index (default -1)")
    ap.add_argument("--field", default="umag", help="'umag' (|u|, point data) or a cell field: sxx syy szz syz sxz sxy material")
    ap.add_argument("--scale", type=float, default=None, help="displacement magnification (default: max |u| shown as 5%% of the diagonal)")
    ap.add_argument("--joints", action="store_true", help="draw opened joints (separated node copies) as glyphs")
    ap.add_argument("--gap-min", type=float, default=None, help="smallest gap drawn (m; default 1e-3 * max |u|)")
    ap.add_argument("--view", choices=["front", "iso"], default="front", help="front: the x-z section (plane strain); iso: 3D")
    ap.add_argument("--clim", type=float, nargs=2, default=None, metavar=("LO", "HI"), help="colour range of the field")
    ap.add_argument("--edges", action="store_true", help="draw element edges")
    ap.add_argument("--size", type=int, nargs=2, default=(1600, 900), metavar=("W", "H"), help="image size in pixels")
    args = ap.parse_args()

    vtu, label = frame_of(args.input, args.frame)
    grid = pv.read(vtu)
    if DISPLACEMENT not in grid.point_data:
        sys.exit(f"{vtu}: no point array '{DISPLACEMENT}' (arrays: {list(grid.point_data)})")
    u = np.asarray(grid.point_data[DISPLACEMENT])
    umag = np.linalg.norm(u, axis=1)
    grid.point_data[UMAG] = umag
    u_max = float(umag.max())
    diag = float(grid.length)
    scale = args.scale if args.scale is not None else (0.05 * diag / u_max if u_max > 0 else 1.0)
    warped = grid.warp_by_vector(DISPLACEMENT, factor=scale)

    if args.field == "umag":
        scalars, title, preference = UMAG, "displacement (m)", "point"
    elif args.field in grid.cell_data:
        unit = "" if args.field == "material" else " (Pa)"
        scalars, title, preference = args.field, args.field + unit, "cell"
    else:
        sys.exit(f"{vtu}: no field '{args.field}' (cell fields: {list(grid.cell_data)}; or 'umag')")
    values = warped.point_data[scalars] if preference == "point" else warped.cell_data[scalars]

    pl = pv.Plotter(off_screen=True, window_size=list(args.size))
    pl.set_background("white")
    pl.add_mesh(
        warped,
        scalars=scalars,
        preference=preference,
        cmap="viridis" if args.field != "szz" else "viridis_r",
        clim=args.clim,
        show_edges=args.edges,
        edge_color="grey",
        scalar_bar_args={"title": title, "color": "black", "vertical": True, "position_x": 0.86, "position_y": 0.2},
    )
    n_open, gap_max = 0, 0.0
    if args.joints:
        gap = joint_gaps(np.asarray(grid.points), u)
        gap_max = float(gap.max())
        gap_min = args.gap_min if args.gap_min is not None else 1e-3 * u_max
        opened = gap > gap_min
        n_open = int(opened.sum())
        if n_open:
            cloud = pv.PolyData(np.asarray(warped.points)[opened])
            cloud.point_data["gap (m)"] = gap[opened]
            pl.add_mesh(
                cloud,
                scalars="gap (m)",
                cmap="autumn_r",
                render_points_as_spheres=True,
                point_size=max(4, args.size[0] // 250),
                scalar_bar_args={"title": "joint gap (m)", "color": "black", "vertical": True, "position_x": 0.05, "position_y": 0.2},
            )
    text = f"{label}\ndisplacement x {scale:.3g}, largest displacement {u_max:.4g} m"
    if args.joints:
        text += f"\nopened joints: {n_open} node copies with gap > {gap_min:.3g} m (max gap {gap_max:.4g} m)"
    pl.add_text(text, position="upper_left", font_size=10, color="black")
    if args.view == "front":
        pl.view_xz()
        pl.enable_parallel_projection()
    else:
        # From the front (-y), right and above: x to the right, z up.
        pl.view_vector((0.6, -1.0, 0.5), viewup=(0.0, 0.0, 1.0))
    pl.reset_camera()
    pl.camera.zoom(1.1 if args.view == "front" else 1.0)
    pl.screenshot(str(args.out))
    pl.close()
    print(
        f"{args.out}: {label}; {grid.n_cells} cells, {grid.n_points} points; scale {scale:.4g}; "
        f"{title} in [{float(np.min(values)):.4g}, {float(np.max(values)):.4g}]"
        + (f"; opened joints {n_open} points (gap > {gap_min:.3g} m), max gap {gap_max:.4g} m" if args.joints else "")
    )


if __name__ == "__main__":
    main()
