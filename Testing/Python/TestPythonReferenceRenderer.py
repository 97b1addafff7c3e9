"""A VTK pipeline in Python: a structured volume rendered by vtkVolumeReferenceRenderer with
the renderer's lights and camera, checked pixel by pixel; bad input gives an error, not a crash."""
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkVolumeProperty)

import ambientscattering


def main():
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    source = vtkRTAnalyticSource()  # a structured float field on a 21^3 grid
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    source.Update()
    lo, hi = source.GetOutput().GetScalarRange()

    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.2, 0.3, 1.0)
    color.AddRGBPoint(hi, 1.0, 0.7, 0.3)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(hi, 0.4)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(2.0)

    renderer = vtkRenderer()
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 60)
    camera.SetFocalPoint(0, 0, 0)
    sun = vtkLight()
    sun.SetPositional(False)
    sun.SetPosition(1, 1, 1)
    sun.SetFocalPoint(0, 0, 0)
    sun.SetIntensity(0.8)
    renderer.AddLight(sun)

    filt = ambientscattering.vtkVolumeReferenceRenderer()
    filt.SetInputConnection(source.GetOutputPort())
    filt.SetVolumeProperty(prop)
    filt.SetRenderer(renderer)
    filt.SetImageSize(40, 40)
    progress = []
    filt.AddObserver("ProgressEvent", lambda obj, event: progress.append(obj.GetProgress()))

    totals = {}
    for mode in ("EmissionAbsorption", "AmbientOcclusion", "AmbientScattering"):
        getattr(filt, "SetRenderModeTo" + mode)()
        filt.Update()
        out = filt.GetOutput()
        check(out.GetDimensions() == (40, 40, 1), mode + ": wrong size")
        rgb = out.GetPointData().GetScalars()
        total = sum(rgb.GetComponent(i, c) for i in range(rgb.GetNumberOfTuples()) for c in range(3))
        totals[mode] = total
        check(total > 0, mode + ": blank picture")
        # The volume fills the centre; the corners are background.
        check(out.GetScalarComponentAsDouble(0, 0, 0, 0) == 0, mode + ": corner not background")
        centre = sum(out.GetScalarComponentAsDouble(20, 20, 0, c) for c in range(3))
        check(centre > 0, mode + ": centre empty")
        radiance = out.GetPointData().GetArray("Radiance")
        check(radiance is not None and radiance.GetNumberOfComponents() == 4, mode + ": no radiance")
        check(0.0 < radiance.GetComponent(20 * 40 + 20, 3) <= 1.0, mode + ": bad alpha")
    check(progress and max(progress) == 1.0, "no progress events")
    # The modes' totals against each other: occlusion only darkens the emission-absorption
    # picture; ambient scattering, lit by one light of intensity 0.8 and shown through its
    # display transform, is another picture than either.
    print("pixel totals:", totals)
    check(totals["AmbientOcclusion"] < 0.97 * totals["EmissionAbsorption"],
          "AO is not darker than EA (%s)" % totals)
    check(abs(totals["AmbientScattering"] - totals["EmissionAbsorption"])
          > 0.05 * totals["EmissionAbsorption"], "AS is EA's picture (%s)" % totals)

    # The path tracer, the ground truth, from the same pipeline: deterministic for a seed.
    filt.SetRenderModeToPathTracing()
    filt.SetSamplesPerPixel(8)
    filt.SetSeed(7)
    filt.Update()
    traced = filt.GetOutput().GetPointData().GetArray("Radiance")
    first = [traced.GetComponent(i, 0) for i in range(traced.GetNumberOfTuples())]
    check(sum(first) > 0, "path tracing: blank picture")
    filt.Modified()
    filt.Update()
    traced = filt.GetOutput().GetPointData().GetArray("Radiance")
    check(first == [traced.GetComponent(i, 0) for i in range(traced.GetNumberOfTuples())],
          "path tracing: the same seed gave another picture")

    # The four modes side by side, as a user compares them (avs-demo --reference does for
    # three): every mode's output has the same arrays, so vtkImageAppend takes them in any order
    # (VTK 9.1's crashed on outputs whose arrays differ).
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    pictures = {}
    for mode in ("AmbientScattering", "PathTracing", "EmissionAbsorption", "AmbientOcclusion"):
        getattr(filt, "SetRenderModeTo" + mode)()
        filt.Update()
        copy = vtkImageData()
        copy.DeepCopy(filt.GetOutput())
        pd = copy.GetPointData()
        names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
        check(names == ["RGB", "Radiance", "RadianceSecondMoment"],
              mode + ": arrays %s" % names)
        second = pd.GetArray("RadianceSecondMoment")
        radiance = pd.GetArray("Radiance")
        if mode != "PathTracing" and second is not None:
            # No variance: the second moment is the square of the radiance.
            check(all(abs(second.GetComponent(i, c) - radiance.GetComponent(i, c) ** 2) < 1e-6
                      for i in range(0, second.GetNumberOfTuples(), 37) for c in range(4)),
                  mode + ": second moment is not the squared radiance")
        pictures[mode] = copy
        append.AddInputData(copy)
    append.Update()
    side = append.GetOutput()
    check(side.GetDimensions() == (160, 40, 1), "side by side: size %s" % (side.GetDimensions(),))
    for k, mode in enumerate(("AmbientScattering", "PathTracing", "EmissionAbsorption",
                              "AmbientOcclusion")):
        check(all(side.GetScalarComponentAsDouble(40 * k + x, 20, 0, c)
                  == pictures[mode].GetScalarComponentAsDouble(x, 20, 0, c)
                  for x in range(40) for c in range(3)), "side by side: %s's panel" % mode)
    check(side.GetPointData().GetArray("RadianceSecondMoment") is not None,
          "side by side: the second moment was dropped")
    filt.SetSamplesPerPixel(8)

    # More albedo, more scattered light.
    filt.SetRenderModeToAmbientScattering()
    filt.SetAlbedo(0.2)
    filt.Update()
    rgb = filt.GetOutput().GetPointData().GetScalars()
    dim = sum(rgb.GetComponent(i, 0) for i in range(rgb.GetNumberOfTuples()))
    filt.SetAlbedo(1.0)
    filt.Update()
    rgb = filt.GetOutput().GetPointData().GetScalars()
    bright = sum(rgb.GetComponent(i, 0) for i in range(rgb.GetNumberOfTuples()))
    check(bright > dim, "albedo does not brighten the scattering")

    # Bad input: an empty image.
    errors = []
    filt.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    filt.SetInputData(vtkImageData())
    filt.Update()
    check(len(errors) == 1, "no error for an empty image")
    check(filt.GetOutput().GetNumberOfPoints() == 0, "output not empty after an error")

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
