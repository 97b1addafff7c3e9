"""The installed Python package, with nothing of the source or build tree on any path: it imports
from the installed tree, finds the shipped table there, and renders a frame.
Usage: TestInstalledPython.py PREFIX"""
import os
import sys

prefix = os.path.realpath(sys.argv[1])
import ambientscattering  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderWindow,  # noqa: E402
                                         vtkRenderer, vtkVolume, vtkVolumeProperty)

failures = []
where = os.path.realpath(ambientscattering.__file__)
if not where.startswith(prefix):
    failures.append("the package comes from %s, not %s" % (where, prefix))
table = ambientscattering.vtkAmbientScatteringTable.GetDefaultFileName()
if not os.path.realpath(table).startswith(prefix):
    failures.append("the table %r is not in the installed tree" % table)
image = vtkImageData()
image.SetDimensions(24, 24, 24)
image.AllocateScalars(10, 1)  # VTK_FLOAT
scalars = image.GetPointData().GetScalars()
for k in range(24):
    for j in range(24):
        for i in range(24):
            r = ((i - 11.5) ** 2 + (j - 11.5) ** 2 + (k - 11.5) ** 2) ** 0.5
            scalars.SetValue((k * 24 + j) * 24 + i, 1.0 if r < 9 else 0.0)
color = vtkColorTransferFunction()
color.AddRGBPoint(0, 1, 0.8, 0.6)
color.AddRGBPoint(1, 1, 0.8, 0.6)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(0, 0)
opacity.AddPoint(1, 0.3)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
mapper.SetInputData(image)
errors = []
mapper.AddObserver("ErrorEvent", lambda *args: errors.append(args))
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
renderer = vtkRenderer()
renderer.AddVolume(volume)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(48, 48)
window.AddRenderer(renderer)
renderer.ResetCamera()
window.Render()
if errors or mapper.GetNumberOfRenderedFrames() != 1:
    failures.append("no frame (%d errors)" % len(errors))
window.Finalize()
print("package", where, "table", table)
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
