"""The three GPU mappers in a Python pipeline: rendered off screen, pictures checked; the
ambient-scattering picture responds to its lights; bad input gives an error, not a crash."""
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

import ambientscattering


def picture(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    return [scalars.GetComponent(i, c) for i in range(scalars.GetNumberOfTuples()) for c in range(3)]


def main():
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-16, 16, -16, 16, -16, 16)
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

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(64, 64)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    sun = vtkLight()
    sun.SetPositional(False)
    sun.SetPosition(-1, 1, 1)
    sun.SetFocalPoint(0, 0, 0)
    sun.SetIntensity(1.6)
    renderer.AddLight(sun)
    renderer.GetActiveCamera().SetPosition(20, 30, 80)
    renderer.GetActiveCamera().SetFocalPoint(0, 0, 0)

    for name in ("vtkEmissionAbsorptionVolumeMapper", "vtkAmbientOcclusionVolumeMapper",
                 "vtkAmbientScatteringVolumeMapper"):
        mapper = getattr(ambientscattering, name)()
        mapper.SetInputConnection(source.GetOutputPort())
        errors = []
        mapper.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        renderer.AddVolume(volume)
        renderer.ResetCameraClippingRange()
        window.Render()
        pixels = picture(window)
        check(not errors, name + ": errors")
        check(mapper.GetNumberOfRenderedFrames() == 1, name + ": not rendered")
        check(sum(pixels) > 1000, name + ": blank picture")
        centre = (32 * 64 + 32) * 3
        check(sum(pixels[centre:centre + 3]) > 0, name + ": centre empty")
        check(sum(pixels[0:3]) == 0, name + ": corner not background")
        if name == "vtkAmbientScatteringVolumeMapper":
            sun.SetIntensity(0.4)
            window.Render()
            check(sum(picture(window)) < 0.5 * sum(pixels), "dimmer light, same picture")
            check(mapper.GetNumberOfLightVolumeRebuilds() == 1, "intensity rebuilt a light volume")
            # Bad input: an empty image.
            mapper.SetInputData(vtkImageData())
            window.Render()
            check(len(errors) >= 1, "no error for an empty image")
            check(sum(picture(window)) == 0, "something drawn for an empty image")
        renderer.RemoveVolume(volume)

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
