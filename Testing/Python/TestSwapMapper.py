"""The swap test: a VTK user's script with vtkGPUVolumeRayCastMapper (ShadeOn) and the same script
with only the mapper replaced by vtkAmbientScatteringVolumeMapper at its defaults, on real volumes,
under the lights an ordinary VTK scene has: the automatic headlight, a vtkLightKit, two vtkLights of
intensity 1. Inside the volume's footprint (the pixels either picture draws), the default
ambient-scattering picture must have

- a mean brightness within 0.5-2x VTK's (the extended model's linear radiance is 2-3x VTK's Phong
  shading there: the display transform's exposure and shoulder bring it back);
- at most 2 % of its pixels saturated in any channel (VTK's: none);
- at least half the detail of the paper's model shown at its own best exposure (the largest linear
  exposure that saturates at most 2 %), the detail being the mean absolute Laplacian of the
  luminance: a transform that flattened the picture would fail here.

Volumes: the embryo, the hydrogen orbital, the smoke and the cloud from the shared data folder
(skipped where absent), a CT-like head made here (a phantom with skin, skull, orbits and brain in
Hounsfield-like units, int16) and a real T1 MRI brain, Colin 27 as Debian's mricron-data ships it
(ch2bet.nii.gz, brain only, so its gyri show). The volumes found are checked; with fewer than
four (the shared data folder absent) the test then reports itself skipped.

Usage: TestSwapMapper.py DATA_DIR [MRI_FILE]"""
import math
import os
import sys

import numpy as np
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkNIFTIImageReader, vtkSLCReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkLightKit,
                                         vtkRenderWindow, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

import ambientscattering

SKIP = 77  # ctest's SKIP_RETURN_CODE for this test
MRI = "/usr/share/mricron/templates/ch2bet.nii.gz"
SIZE = 128
LIGHTINGS = ("headlight", "light kit", "two lights")


def ct_head(n=112):
    """A CT-like head: air, skin and soft tissue, a skull of varying thickness with orbits and a
    nose, brain with ventricles, Hounsfield-like int16 values, blurred as a scanner blurs, with
    mild noise."""
    z, y, x = np.mgrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j]

    def inside(cx, cy, cz, a, b, c):
        return ((x - cx) / a) ** 2 + ((y - cy) / b) ** 2 + ((z - cz) / c) ** 2

    v = np.full(x.shape, -1000.0)
    head = inside(0, 0, 0, 0.72, 0.9, 0.85)
    v[head <= 1] = 40.0                                      # skin, muscle
    v[(head <= 0.93) & (head > 0.86)] = -90.0                 # fat under the skin
    skull = inside(0, 0, 0.02, 0.66, 0.83, 0.78)
    bumps = 0.02 * np.sin(9 * x) * np.cos(7 * y) * np.sin(8 * z + 1)
    v[(skull <= 1 + bumps) & (skull > 0.8 + bumps)] = 1300.0  # bone
    brain = skull <= 0.8 + bumps
    v[brain] = 35.0
    v[brain & (np.sin(14 * x) * np.sin(14 * y + 1) * np.sin(14 * z) > 0.4)] = 45.0  # grey, white
    for side in (-1, 1):
        v[inside(side * 0.13, 0.05, 0.1, 0.07, 0.25, 0.12) <= 1] = 5.0  # ventricles
        orbit = inside(side * 0.3, 0.75, 0.1, 0.17, 0.2, 0.15)
        v[orbit <= 1] = -80.0                                 # orbit: fat
        v[inside(side * 0.3, 0.8, 0.1, 0.11, 0.11, 0.11) <= 1] = 15.0  # eyeball
    nose = inside(0, 0.88, -0.12, 0.09, 0.16, 0.22)
    v[nose <= 1] = 40.0
    # The scanner's blur (partial volumes at the edges, not steps), then its noise.
    for axis in range(3):
        for _ in range(2):
            v = 0.25 * np.roll(v, 1, axis) + 0.5 * v + 0.25 * np.roll(v, -1, axis)
    v += np.random.default_rng(1).normal(0.0, 8.0, v.shape)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(2.0, 2.0, 2.0)
    scalars = numpy_to_vtk(v.astype(np.int16).ravel(), deep=1)
    scalars.SetName("density")
    image.GetPointData().SetScalars(scalars)
    return image


def read(reader, path):
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def volumes(data, mri):
    """(name, image) of every volume found."""
    shared = (("embryo.slc", vtkSLCReader), ("hydrogen.vti", vtkXMLImageDataReader),
              ("openvdb_smoke1.vdb", ambientscattering.vtkOpenVDBImageReader),
              ("wdas_cloud_sixteenth.vdb", ambientscattering.vtkOpenVDBImageReader))
    for name, reader in shared:
        path = os.path.join(data, name)
        if os.path.isfile(path):
            yield name, read(reader(), path)
        else:
            print("not found, left out: %s" % path)
    yield "CT-like head (made here)", ct_head()
    if os.path.isfile(mri):
        yield "MRI brain " + os.path.basename(mri), read(vtkNIFTIImageReader(), mri)
    else:
        print("not found, left out: %s (Debian package mricron-data)" % mri)


def grab(window):
    g = vtkWindowToImageFilter()
    g.SetInput(window)
    g.SetInputBufferTypeToRGB()
    g.ReadFrontBufferOff()
    g.Update()
    out = g.GetOutput()
    w, h, _ = out.GetDimensions()
    return vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, 3).astype(float)


def user_script(image, mapper, lighting):
    """What a VTK user writes: a shaded volume property, a camera, the renderer's lights.
    Returns the picture (rows x columns x RGB, 0-255) and the number of errors."""
    lo, hi = image.GetScalarRange()
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
    mapper.SetInputData(image)
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
    window.SetSize(SIZE, SIZE)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(20)
    renderer.GetActiveCamera().Zoom(1.4)
    renderer.ResetCameraClippingRange()
    errors = []
    mapper.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
    window.Render()
    picture = grab(window)
    window.Finalize()
    return picture, len(errors)


def saturated(picture, footprint):
    """The share of the footprint's pixels with a channel at 255."""
    return ((picture >= 254.5).any(axis=-1) & footprint).sum() / max(footprint.sum(), 1)


def detail(picture, footprint):
    """The mean absolute Laplacian of the luminance over the footprint's inner pixels, relative
    to their mean luminance. (The Laplacian alone grows with the exposure: the paper's model at
    its best exposure is up to 2x brighter than VTK's picture, which the default is measured
    against, so the absolute figure would compare exposures. Relative to the mean it compares
    structure, and a curve that flattens gradations still lowers it.)"""
    y = (0.2126 * picture[..., 0] + 0.7152 * picture[..., 1] + 0.0722 * picture[..., 2]) / 255.0
    lap = np.zeros_like(y)
    lap[1:-1, 1:-1] = y[:-2, 1:-1] + y[2:, 1:-1] + y[1:-1, :-2] + y[1:-1, 2:] - 4 * y[1:-1, 1:-1]
    inner = footprint.copy()
    inner[0, :] = inner[-1, :] = inner[:, 0] = inner[:, -1] = False
    if not inner.any() or y[inner].mean() <= 0:
        return 0.0
    return np.abs(lap[inner]).mean() / y[inner].mean()


def paper_at_best_exposure(image, lighting, footprint):
    """The paper's model without tone curve at the largest exposure that saturates at most 2 %
    of the footprint: from a dim picture, the exposure that puts its 98th percentile of
    max(R, G, B) at 254, lowered by a tenth until the saturation is within 2 %."""
    def paper(exposure):
        mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
        mapper.SetScatteringModelToPaper()
        mapper.SetToneMappingToClamp()
        mapper.SetExposure(exposure)
        return user_script(image, mapper, lighting)[0]

    dim = 0.125
    peak = np.percentile(paper(dim).max(axis=-1)[footprint], 98) / dim
    exposure = 254.0 / max(peak, 1e-6)
    for _ in range(8):
        picture = paper(exposure)
        if saturated(picture, footprint) <= 0.02:
            return exposure, picture
        exposure *= 0.9
    return exposure, picture


def main(data, mri):
    failures = []
    found = 0
    print("%-34s %-10s %6s %6s %5s %6s %6s %6s %6s" % ("volume", "lights", "VTK", "ours", "ratio",
                                                       "sat %", "detail", "paper", "(exp)"))
    for name, image in volumes(data, mri):
        found += 1
        for lighting in LIGHTINGS:
            vtk, _ = user_script(image, vtkGPUVolumeRayCastMapper(), lighting)
            ours, errors = user_script(
                image, ambientscattering.vtkAmbientScatteringVolumeMapper(), lighting)
            footprint = (vtk.max(axis=-1) > 2) | (ours.max(axis=-1) > 2)
            if footprint.sum() < 200:
                failures.append("%s, %s: footprint of %d pixels" % (name, lighting,
                                                                    footprint.sum()))
                continue
            ratio = ours[footprint].mean() / max(vtk[footprint].mean(), 1e-6)
            share = saturated(ours, footprint)
            exposure, paper = paper_at_best_exposure(image, lighting, footprint)
            ours_detail, paper_detail = detail(ours, footprint), detail(paper, footprint)
            print("%-34s %-10s %6.1f %6.1f %5.2f %6.2f %6.4f %6.4f %6.2f"
                  % (name, lighting, vtk[footprint].mean(), ours[footprint].mean(), ratio,
                     100 * share, ours_detail, paper_detail, exposure))
            what = "%s, %s" % (name, lighting)
            if errors:
                failures.append("%s: %d errors" % (what, errors))
            if not 0.5 <= ratio <= 2.0:
                failures.append("%s: brightness %.2f x VTK's (0.5-2)" % (what, ratio))
            if share > 0.02:
                failures.append("%s: %.1f %% saturated (at most 2 %%)" % (what, 100 * share))
            if ours_detail < 0.5 * paper_detail:
                failures.append("%s: detail %.4f, under half the paper's model's %.4f"
                                % (what, ours_detail, paper_detail))
            if saturated(vtk, footprint) > 0.0:
                print("  (VTK's picture saturates %.1f %%)" % (100 * saturated(vtk, footprint)))
    for f in failures:
        print("FAILED:", f)
    if failures:
        return 1
    if found < 4:
        print("skipped: only %d volumes found (four or more with the shared data folder %s)"
              % (found, data))
        return SKIP
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else MRI))
