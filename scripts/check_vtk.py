"""Checks cdem's VTK output with VTK's own cell validator (an independent reader).

Usage: python scripts/check_vtk.py FILE.vtu [FILE.vtu ...]

Reads each file with VTK's XML reader and runs vtkCellValidator on every cell
(tolerance 1e-8 of the cell's size); prints, per file, the number of cells by
type and the number that fail with the validator's states; exits 1 if any cell
fails. Dependencies: scripts/requirements-viz.txt (pyvista brings vtk).
"""

import sys

import vtk

STATES = {
    1: "WrongNumberOfPoints",
    2: "IntersectingEdges",
    4: "IntersectingFaces",
    8: "NoncontiguousEdges",
    16: "Nonconvex",
    32: "FacesAreOrientedIncorrectly",
    64: "NonPlanarFaces",
    128: "DegenerateFaces",
    256: "CoincidentPoints",
}


def check(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    validator = vtk.vtkCellValidator()
    validator.SetInputData(grid)
    validator.SetTolerance(1e-8)
    validator.Update()
    states = validator.GetOutput().GetCellData().GetArray("ValidityState")
    by_type, failed, reasons = {}, 0, {}
    for c in range(grid.GetNumberOfCells()):
        t = grid.GetCellType(c)
        by_type[t] = by_type.get(t, 0) + 1
        s = int(states.GetTuple1(c))
        if s != 0:
            failed += 1
            for bit, name in STATES.items():
                if s & bit:
                    reasons[name] = reasons.get(name, 0) + 1
    print(f"{path}: {grid.GetNumberOfCells()} cells {by_type}, {failed} fail VTK's cell checks {reasons}")
    return failed


if __name__ == "__main__":
    bad = sum(check(p) for p in sys.argv[1:])
    sys.exit(1 if bad else 0)
