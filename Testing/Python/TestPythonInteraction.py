"""Interaction from Python, with the calls application code makes on vtkGPUVolumeRayCastMapper:
AutoAdjustSampleDistances, ImageSampleDistance and its range, LockSampleDistanceToInputSpacing
exist on all three mappers with VTK's defaults; a drag through an interactor renders interactive
frames at a coarser image sample distance without rebuilding the headlight's light volume, and
the still frame after it is exact and rebuilds it."""
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingUI import vtkGenericRenderWindowInteractor
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

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

    # The API, with VTK's defaults and clamps, on every mapper.
    for name in ("vtkEmissionAbsorptionVolumeMapper", "vtkAmbientOcclusionVolumeMapper",
                 "vtkAmbientScatteringVolumeMapper"):
        m = getattr(ambientscattering, name)()
        check(m.GetAutoAdjustSampleDistances() == 1, name + ": AutoAdjustSampleDistances default")
        check(m.GetImageSampleDistance() == 1.0, name + ": ImageSampleDistance default")
        check(m.GetMinimumImageSampleDistance() == 1.0, name + ": minimum default")
        check(m.GetMaximumImageSampleDistance() == 10.0, name + ": maximum default")
        check(m.GetLockSampleDistanceToInputSpacing() == 0, name + ": lock default")
        m.AutoAdjustSampleDistancesOff()
        check(m.GetAutoAdjustSampleDistances() == 0, name + ": AutoAdjustSampleDistancesOff")
        m.SetAutoAdjustSampleDistances(1)
        m.SetImageSampleDistance(2.0)
        m.SetMinimumImageSampleDistance(0.5)
        m.SetMaximumImageSampleDistance(500.0)
        check(m.GetImageSampleDistance() == 2.0, name + ": SetImageSampleDistance")
        check(m.GetMinimumImageSampleDistance() == 0.5, name + ": SetMinimumImageSampleDistance")
        check(m.GetMaximumImageSampleDistance() == 100.0, name + ": maximum not clamped to 100")
        m.LockSampleDistanceToInputSpacingOn()
        check(m.GetLockSampleDistanceToInputSpacing() == 1, name + ": lock on")
        check(m.GetLastImageSampleDistance() == 1.0, name + ": last distance before a frame")
        check(m.GetNumberOfInteractiveFrames() == 0, name + ": interactive frames before a frame")

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

    def scene(mapper):
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(64, 64)
        renderer = vtkRenderer()
        window.AddRenderer(renderer)
        headlight = vtkLight()
        headlight.SetLightTypeToHeadlight()
        headlight.SetIntensity(20.0)
        renderer.AddLight(headlight)
        renderer.GetActiveCamera().SetPosition(20, 30, 80)
        renderer.GetActiveCamera().SetFocalPoint(0, 0, 0)
        mapper.SetInputConnection(source.GetOutputPort())
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        renderer.AddVolume(volume)
        renderer.ResetCameraClippingRange()
        return window, renderer

    mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
    mapper.SetMaximumImageSampleDistance(4.0)
    window, renderer = scene(mapper)
    interactor = vtkGenericRenderWindowInteractor()
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    interactor.SetRenderWindow(window)
    interactor.SetDesiredUpdateRate(10000.0)  # more than any frame meets: the maximum distance
    interactor.Initialize()  # a still frame
    check(mapper.GetNumberOfLightVolumeRebuilds() == 1, "first frame: one light volume")
    interactor.SetEventInformation(32, 32)
    interactor.LeftButtonPressEvent()
    for i in range(1, 4):
        interactor.SetEventInformation(32 + 5 * i, 32 + i)
        interactor.MouseMoveEvent()
    check(mapper.GetNumberOfInteractiveFrames() == 3, "three interactive frames")
    check(mapper.GetLastImageSampleDistance() == 4.0, "interactive frames not at the maximum")
    check(mapper.GetNumberOfLightVolumeRebuilds() == 1, "light volume rebuilt while dragging")
    interactor.LeftButtonReleaseEvent()
    check(mapper.GetLastImageSampleDistance() == 1.0, "still frame not at full resolution")
    check(mapper.GetNumberOfLightVolumeRebuilds() == 2, "still frame did not rebuild the headlight")
    still = picture(window)

    fresh = ambientscattering.vtkAmbientScatteringVolumeMapper()
    other, other_renderer = scene(fresh)
    other_renderer.GetActiveCamera().DeepCopy(renderer.GetActiveCamera())
    other_renderer.ResetCameraClippingRange()
    renderer.ResetCameraClippingRange()
    window.Render()
    other.Render()
    check(sum(still) > 1000, "blank still frame")
    check(picture(window) == picture(other), "still frame differs from a frame without interaction")

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
