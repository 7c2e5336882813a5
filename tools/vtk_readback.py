#!/usr/bin/env python3
"""Reads Talus ParaView output back with VTK's own readers and prints it as JSON.

Usage: vtk_readback.py FILE...   (FILE: .vtu, .pvtu or .pvd)

For a .vtu or .pvtu (pieces joined): {"points", "cells", "cell_types", "bounds", "point_data", "cell_data"}, each data
array as {"components", "type", "values"} with the values flattened tuple by tuple.
For a .pvd: {"type", "timesteps", "files", "cells"}: the collection parsed as XML and every
frame it names read with VTK (its number of cells).
Output: {"FILE": {...}, ...} on stdout. Exit status 3 when the vtk Python module is missing
(Debian: apt-get install python3-vtk9), 2 when VTK reports an error reading a file.
"""
import json
import os
import sys

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
except ImportError as e:  # pragma: no cover - reported by the C++ test
    print(f"vtk_readback.py: cannot import VTK ({e}); install python3-vtk9 "
          "(scripts/install-deps.sh)", file=sys.stderr)
    sys.exit(3)


class ErrorCatcher:
    def __init__(self):
        self.messages = []

    def __call__(self, obj, event, *args):
        self.messages.append(f"{obj.GetClassName()}: {event}")


def watched(reader):
    catcher = ErrorCatcher()
    reader.AddObserver(vtkCommand.ErrorEvent, catcher)
    reader.AddObserver(vtkCommand.WarningEvent, catcher)
    return catcher


def arrays(data):
    out = {}
    for k in range(data.GetNumberOfArrays()):
        a = data.GetAbstractArray(k)
        n, c = a.GetNumberOfTuples(), a.GetNumberOfComponents()
        values = [a.GetComponent(t, j) for t in range(n) for j in range(c)]
        out[a.GetName()] = {"components": c, "type": a.GetDataTypeAsString(), "values": values}
    return out


def read_vtu(path):
    reader = vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtkXMLUnstructuredGridReader()
    catcher = watched(reader)
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if catcher.messages or reader.GetErrorCode() != 0:
        print(f"vtk_readback.py: VTK could not read {path}: {catcher.messages}", file=sys.stderr)
        sys.exit(2)
    return {
        "points": grid.GetNumberOfPoints(),
        "cells": grid.GetNumberOfCells(),
        "cell_types": [grid.GetCellType(k) for k in range(grid.GetNumberOfCells())],
        "bounds": list(grid.GetBounds()) if grid.GetNumberOfPoints() else [],
        "point_data": arrays(grid.GetPointData()),
        "cell_data": arrays(grid.GetCellData()),
    }


def read_pvd(path):
    # VTK's Python wheels ship no .pvd reader (ParaView has it); a .pvd is plain XML, so it is
    # parsed here and every frame it names is opened with VTK's .vtu (or .pvtu) reader.
    import xml.etree.ElementTree as ET
    root = ET.parse(path).getroot()
    base = os.path.dirname(path)
    timesteps, files, cells = [], [], []
    for ds in root.iter("DataSet"):
        timesteps.append(float(ds.get("timestep")))
        files.append(ds.get("file"))
        cells.append(read_vtu(os.path.join(base, ds.get("file")))["cells"])
    return {"type": root.get("type"), "timesteps": timesteps, "files": files, "cells": cells}


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 1
    result = {}
    for path in argv[1:]:
        result[path] = read_pvd(path) if path.endswith(".pvd") else read_vtu(path)
    json.dump(result, sys.stdout)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
