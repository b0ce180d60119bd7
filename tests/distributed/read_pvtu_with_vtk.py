# SPDX-License-Identifier: MIT
"""Reads a .pvtu with VTK's own parallel reader, removes the ghost cells
and prints the number of cells and points left (exit status 3 when the
VTK Python module is missing)."""
import sys

try:
    from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader
    from vtkmodules.vtkFiltersParallel import vtkRemoveGhosts
except ImportError as e:
    print(e, file=sys.stderr)
    sys.exit(3)

reader = vtkXMLPUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
ghosts = vtkRemoveGhosts()
ghosts.SetInputConnection(reader.GetOutputPort())
ghosts.Update()
grid = ghosts.GetOutput()
print(reader.GetOutput().GetNumberOfCells(), grid.GetNumberOfCells())
