"""An imported VDB grid rendered with vtkAmbientScatteringVolumeMapper from Python: the reader
lists the grid, the picture is lit, and a bad file name gives an error, not an exception."""
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

import ambientscattering


def main(path):
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    reader = ambientscattering.vtkOpenVDBImageReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    check(reader.GetNumberOfGrids() == 1, "grid count")
    check(reader.GetGridName(0) == "density", "grid name")
    check(reader.GetGridClass(0) == "fog volume", "grid class")
    reader.Update()
    image = reader.GetOutput()
    check(image.GetNumberOfPoints() > 0, "nothing read")
    lo, hi = image.GetScalarRange()
    check(lo == 0.0 and hi > 0.5, "value range %s" % ((lo, hi),))

    mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0.0, 1.0, 1.0, 1.0)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(1.2, 0.6)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.08)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    sun = vtkLight()
    sun.SetPositional(False)
    sun.SetPosition(0, 1, 0.5)
    sun.SetFocalPoint(0, 0, 0)
    sun.SetIntensity(0.95)
    renderer.AddLight(sun)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(64, 64)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = grab.GetOutput().GetPointData().GetScalars()
    total = sum(pixels.GetComponent(i, c) for i in range(pixels.GetNumberOfTuples()) for c in range(3))
    check(total > 1000, "blank picture")
    check(mapper.GetNumberOfRenderedFrames() == 1, "not rendered")

    bad = ambientscattering.vtkOpenVDBImageReader()
    errors = []
    bad.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    bad.SetFileName(path + ".missing")
    bad.Update()
    check(errors and bad.GetOutput().GetNumberOfPoints() == 0, "missing file accepted")

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
