"""The swap test: a VTK user's script with vtkGPUVolumeRayCastMapper (ShadeOn) and the same
script with only the mapper replaced by vtkAmbientScatteringVolumeMapper, on real volumes, under
the lights an ordinary VTK scene has: the automatic headlight, a vtkLightKit, two vtkLights of
intensity 1. In VTK light units (irradiance 4 pi x intensity x colour) the ambient-scattering
picture's mean brightness must be within 0.5-3x VTK's (the default, extended model adds the
multiple scattering VTK's single-scattering shading lacks: up to 2.3x on the embryo; the paper's
model stayed within 2x); without the 4 pi it is at 2-12 %.

Usage: TestSwapMapper.py DATA_DIR (the folder with embryo.slc and wdas_cloud_sixteenth.vdb)."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkSLCReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkLightKit,
                                         vtkRenderWindow, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

import ambientscattering

SKIP = 77  # ctest's SKIP_RETURN_CODE for this test


def mean_brightness(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.Update()
    pixels = bytes(memoryview(grab.GetOutput().GetPointData().GetScalars()))
    return sum(pixels) / len(pixels)


def user_script(reader, make_mapper, lighting):
    """What a VTK user writes: a shaded volume property, a camera, the renderer's lights."""
    lo, hi = reader.GetOutput().GetScalarRange()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.9, 0.6, 0.4)
    color.AddRGBPoint(hi, 1.0, 1.0, 0.95)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo + 0.2 * (hi - lo), 0.0)
    opacity.AddPoint(hi, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    mapper = make_mapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    if lighting == "light kit":
        vtkLightKit().AddLightsToRenderer(renderer)
    elif lighting == "two lights":
        for position in ((-1.0, 1.0, 1.0), (1.0, 0.3, 0.5)):
            light = vtkLight()
            light.SetLightTypeToCameraLight()
            light.SetPosition(*position)
            light.SetFocalPoint(0.0, 0.0, 0.0)
            light.SetIntensity(1.0)
            renderer.AddLight(light)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(128, 128)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(20)
    renderer.ResetCameraClippingRange()
    errors = []
    mapper.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
    window.Render()
    brightness = mean_brightness(window)
    window.Finalize()
    return brightness, len(errors)


def main(data):
    files = ("embryo.slc", "wdas_cloud_sixteenth.vdb")
    if not all(os.path.isfile(os.path.join(data, f)) for f in files):
        print("skipped: %s lacks %s" % (data, " or ".join(files)))
        return SKIP
    failures = []
    for name in files:
        path = os.path.join(data, name)
        reader = vtkSLCReader() if name.endswith(".slc") else \
            ambientscattering.vtkOpenVDBImageReader()
        reader.SetFileName(path)
        reader.Update()
        for lighting in ("headlight", "light kit", "two lights"):
            vtk, _ = user_script(reader, vtkGPUVolumeRayCastMapper, lighting)
            ours, errors = user_script(
                reader, ambientscattering.vtkAmbientScatteringVolumeMapper, lighting)
            ratio = ours / vtk if vtk > 0 else 0.0
            print("%-26s %-10s VTK shaded %6.2f  ambient scattering %6.2f  ratio %.2f"
                  % (name, lighting, vtk, ours, ratio))
            if vtk < 1.0:
                failures.append("%s, %s: VTK's picture is blank" % (name, lighting))
            if errors or not 0.5 <= ratio <= 3.0:
                failures.append("%s, %s: ratio %.2f, %d errors" % (name, lighting, ratio, errors))
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
