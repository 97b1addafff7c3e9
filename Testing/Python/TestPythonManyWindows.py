"""Fifty render windows opened, rendered and closed in sequence in one process, each with an
ambient-scattering mapper: every picture shows the volume. Each window opens and closes its own X
connection; an X server that resets when its last client leaves (Xvfb without -noreset) refuses
the next one now and then, and VTK aborts the process ("bad X server connection")."""
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

import ambientscattering

WINDOWS = 50
SIZE = 48


def brightness(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    return sum(scalars.GetValue(i) for i in range(scalars.GetNumberOfValues()))


def main():
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-12, 12, -12, 12, -12, 12)
    source.Update()
    lo, hi = source.GetOutput().GetScalarRange()
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.3, 0.4, 1.0)
    color.AddRGBPoint(hi, 1.0, 0.8, 0.5)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(lo + 0.5 * (hi - lo), 0.0)
    opacity.AddPoint(hi, 0.6)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(3.0)

    failures = []
    least = None
    for i in range(WINDOWS):
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(SIZE, SIZE)
        renderer = vtkRenderer()
        window.AddRenderer(renderer)
        sun = vtkLight()
        sun.SetPositional(False)
        sun.SetPosition(-1, 1, 1)
        sun.SetFocalPoint(0, 0, 0)
        sun.SetIntensity(20.0)
        renderer.AddLight(sun)
        mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        errors = []
        mapper.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        renderer.AddVolume(volume)
        renderer.GetActiveCamera().SetPosition(20, 30, 80)
        renderer.GetActiveCamera().SetFocalPoint(0, 0, 0)
        renderer.ResetCameraClippingRange()
        window.Render()
        value = brightness(window)
        least = value if least is None else min(least, value)
        if errors or mapper.GetNumberOfRenderedFrames() != 1 or value < 1000:
            failures.append("window %d: errors %d, frames %d, brightness %d"
                            % (i, len(errors), mapper.GetNumberOfRenderedFrames(), value))
        # Close it: the window's X connection goes with it.
        renderer.RemoveVolume(volume)
        mapper.ReleaseGraphicsResources(window)
        window.Finalize()
        del volume, mapper, renderer, window

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok: %d windows, least brightness %d" % (WINDOWS, least))
    return 0


if __name__ == "__main__":
    sys.exit(main())
