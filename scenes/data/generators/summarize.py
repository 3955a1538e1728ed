"""Print a summary of every generated data set: bounds, points, cells, cell
types, arrays with component counts and per-component min/max. Fails on any
VTK warning or error while reading.

    /usr/bin/python3 summarize.py [folder] [--markdown]
"""
import glob
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))


class Errors(vtk.vtkOutputWindow):
    """Collects warnings and errors instead of printing them."""
    def __init__(self):
        self.messages = []

    def DisplayText(self, text):
        self.messages.append(text)

    DisplayErrorText = DisplayWarningText = DisplayGenericWarningText = DisplayText


def read(path):
    ext = os.path.splitext(path)[1]
    reader = {'.vti': vtk.vtkXMLImageDataReader, '.vtu': vtk.vtkXMLUnstructuredGridReader,
              '.vtk': vtk.vtkDataSetReader}[ext]()
    reader.SetFileName(path)
    if ext == '.vtk':
        reader.ReadAllTensorsOn()
        reader.ReadAllScalarsOn()
        reader.ReadAllVectorsOn()
    reader.Update()
    return reader.GetOutput()


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    folder = args[0] if args else os.path.join(HERE, '..', 'generated')
    markdown = '--markdown' in sys.argv
    errors = Errors()
    vtk.vtkOutputWindow.SetInstance(errors)
    failed = False
    for path in sorted(glob.glob(os.path.join(folder, '*.vt?'))):
        errors.messages.clear()
        ds = read(path)
        name = os.path.basename(path)
        b = ds.GetBounds()
        types = {}
        for i in range(ds.GetNumberOfCells()):
            t = vtk.vtkCellTypes.GetClassNameFromTypeId(ds.GetCellType(i))
            types[t] = types.get(t, 0) + 1
        kinds = ', '.join('%d %s' % (n, t.replace('vtk', '')) for t, n in sorted(types.items()))
        head = ('%s (%s, %d bytes)\n  bounds x [%.4g, %.4g] y [%.4g, %.4g] z [%.4g, %.4g]\n'
                '  points %d, cells %d: %s'
                % (name, ds.GetClassName(), os.path.getsize(path), *b,
                   ds.GetNumberOfPoints(), ds.GetNumberOfCells(), kinds))
        if markdown:
            print('### %s\n\n%s, %d bytes. Bounds x [%.4g, %.4g], y [%.4g, %.4g], z [%.4g, %.4g]. '
                  '%d points, %d cells (%s).\n'
                  % (name, ds.GetClassName(), os.path.getsize(path), *b,
                     ds.GetNumberOfPoints(), ds.GetNumberOfCells(), kinds))
            print('| data | array | comps | active | min per component | max per component |')
            print('|---|---|---|---|---|---|')
        else:
            print(head)
        for where, data in (('point', ds.GetPointData()), ('cell', ds.GetCellData())):
            active = data.GetTensors()
            for i in range(data.GetNumberOfArrays()):
                a = data.GetArray(i)
                x = vtk_to_numpy(a).reshape(a.GetNumberOfTuples(), -1)
                is_active = active is not None and active.GetName() == a.GetName()
                lo = ' '.join('%.3g' % v for v in x.min(0))
                hi = ' '.join('%.3g' % v for v in x.max(0))
                if markdown:
                    print('| %s | %s | %d | %s | %s | %s |' % (where, a.GetName(), a.GetNumberOfComponents(),
                                                             'tensors' if is_active else '', lo, hi))
                else:
                    print('  %s data "%s" (%d comps)%s\n    min %s\n    max %s'
                          % (where, a.GetName(), a.GetNumberOfComponents(),
                             ' [active tensors]' if is_active else '', lo, hi))
        if markdown:
            print()
        if errors.messages:
            failed = True
            print('  VTK MESSAGES WHILE READING:', *errors.messages, sep='\n    ')
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
