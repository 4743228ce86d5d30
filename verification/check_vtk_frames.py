#!/usr/bin/python3
"""Opens a run's last frame of each VTK series (blocks, contacts, bolts) with VTK's own
vtkXMLPolyDataReader and compares the cell and point counts and one array's values with
verification/vtk_frames.py, the independent reader. Exits 0 having checked, 1 on a
difference, and 77 (skipped) when the vtk module (Debian's python3-vtk9) is absent.
Usage: verification/check_vtk_frames.py DIR"""
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtk_frames  # noqa: E402

SKIP = 77

# The series, and the array compared in each (point data for contacts, cell data otherwise).
SERIES = [("blocks.pvd", "cell", "area"), ("contacts.pvd", "point", "normal_force"),
          ("bolts.pvd", "cell", "force")]


def last_frame(run, index):
    frames = [d.get("file") for d in ET.parse(os.path.join(run, index)).getroot().iter("DataSet")]
    return os.path.join(run, frames[-1])


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    try:
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    except ImportError:
        print("check_vtk_frames: the vtk module is absent (python3-vtk9); skipped")
        return SKIP
    run = sys.argv[1]
    failures = 0
    for index, where, name in SERIES:
        if not os.path.exists(os.path.join(run, index)):
            continue
        path = last_frame(run, index)
        ours = vtk_frames.read_vtp(path)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        if reader.GetErrorCode() != 0:
            print("%s: VTK's reader reports error %d" % (path, reader.GetErrorCode()))
            failures += 1
            continue
        data = reader.GetOutput()
        cells = sum(len(c[1]) for c in (ours["verts"], ours["lines"], ours["polys"]) if c)
        arrays = data.GetCellData() if where == "cell" else data.GetPointData()
        array = arrays.GetArray(name)
        count, values = (ours["cell_data"] if where == "cell" else ours["point_data"])[name]
        theirs = [array.GetValue(i) for i in range(array.GetNumberOfValues())] if array else None
        # Exact: both read the same bits (binary) or the same shortest round-trip text.
        same = (data.GetNumberOfPoints() == len(ours["points"]) and
                data.GetNumberOfCells() == cells and theirs is not None and
                len(theirs) == len(values) and
                all(a == b or (math.isnan(a) and math.isnan(b)) for a, b in zip(theirs, values)))
        print("%s: %d points, %d cells, %s %d values: %s" % (
            os.path.relpath(path, run), data.GetNumberOfPoints(), data.GetNumberOfCells(), name,
            len(values), "same" if same else "DIFFERENT"))
        failures += 0 if same else 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
