"""The user guide's parameter pictures: grids of ambient scattering on a procedural cloud.

    ./avs python Utilities/avs-doc-pictures.py Documentation/Images

Writes into the folder given (default Documentation/Images), one PNG montage each, panels of
160 x 160 pixels with 1-pixel dark gutters, read left to right and top to bottom:

    parameters_albedo_anisotropy.png  rows albedo 0.3, 0.6, 0.9; columns g = -0.6, 0, 0.4, 0.8
    parameters_radius.png             ambient radius 0.5x, 1x (automatic), 2x, 4x the automatic one
    parameters_models.png             the paper's model, the extended model (same exposure)
    parameters_exposure.png           exposure 0.25, 0.5, 1, 2 with the shoulder, 2 with clamp

and prints one line per picture naming its panels in order. The scene: a 96^3 cumulus made
here (puffs on a flat base, edges broken by smooth noise), white, lit by one warm directional
light from behind and to the left (about 60 degrees from the line of sight), seen at a
three-quarter view on a dark blue-grey background. Every parameter not named is the mapper's
default (albedo 0.8, g = 0, automatic radius, extended model, exposure 0.5, shoulder).
"""
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

import ambientscattering

PANEL = 160            # pixels per side of a panel
GUTTER = (20, 20, 24)  # the dark 1-pixel lines between panels
N = 96                 # voxels per side of the cloud


def smooth_noise(rng, sigma):
    """Gaussian white noise low-passed by a Gaussian of sigma voxels, scaled to unit spread."""
    k = np.fft.fftfreq(N)
    kz, ky, kx = np.meshgrid(k, k, np.fft.rfftfreq(N), indexing="ij")
    gauss = np.exp(-2.0 * (np.pi * sigma) ** 2 * (kx * kx + ky * ky + kz * kz))
    field = np.fft.irfftn(np.fft.rfftn(rng.standard_normal((N, N, N))) * gauss, s=(N, N, N))
    return field / field.std()


def cloud():
    """A cumulus: puffs of random sizes heaped on a flat base, their edges eaten by noise."""
    rng = np.random.default_rng(7)
    z, y, x = np.mgrid[-1:1:N * 1j, -1:1:N * 1j, -1:1:N * 1j]
    shape = np.full(x.shape, -1.0)
    for _ in range(18):
        c = rng.uniform(-1, 1, 3) * (0.45, 0.2, 0.3) + (0.0, -0.1, 0.0)
        r = rng.uniform(0.16, 0.32) * (1.2 - 0.6 * (c[1] + 0.3))  # larger puffs below
        distance = np.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2)
        shape = np.maximum(shape, 1.0 - distance / r)
    shape = np.minimum(shape, (y + 0.45) / 0.1)  # the flat base
    noise = sum(w * smooth_noise(rng, sigma) for w, sigma in ((0.6, 4.0), (0.3, 2.0), (0.1, 1.0)))
    density = np.clip(2.5 * (shape + 0.3 * noise), 0.0, 1.0)
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    scalars = numpy_to_vtk(density.astype(np.float32).ravel(), deep=1)
    scalars.SetName("density")
    image.GetPointData().SetScalars(scalars)
    return image


def automatic_radius(image):
    """The mapper's automatic ambient radius: 1/64 of the box diagonal (spacing 1 here)."""
    b = image.GetBounds()
    return float(np.linalg.norm([b[1] - b[0], b[3] - b[2], b[5] - b[4]])) / 64.0


class Scene:
    """One window, one volume; render(**settings) sets mapper parameters and returns a panel."""

    def __init__(self, image):
        color = vtkColorTransferFunction()
        color.AddRGBPoint(0.0, 1.0, 1.0, 1.0)
        color.AddRGBPoint(1.0, 1.0, 1.0, 1.0)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0.0, 0.0)
        opacity.AddPoint(1.0, 0.5)
        prop = vtkVolumeProperty()
        prop.SetColor(color)
        prop.SetScalarOpacity(opacity)
        prop.SetScalarOpacityUnitDistance(1.4)
        prop.SetInterpolationTypeToLinear()

        self.mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
        self.mapper.SetInputData(image)
        volume = vtkVolume()
        volume.SetMapper(self.mapper)
        volume.SetProperty(prop)

        renderer = vtkRenderer()
        renderer.SetBackground(0.15, 0.16, 0.2)
        renderer.AddVolume(volume)
        sun = vtkLight()                 # from behind the cloud and to its left, a little above
        sun.SetPositional(False)
        sun.SetPosition(-1.0, 0.6, -0.2)
        sun.SetFocalPoint(0.0, 0.0, 0.0)
        sun.SetColor(1.0, 0.95, 0.85)
        sun.SetIntensity(2.5)
        renderer.AddLight(sun)
        camera = renderer.GetActiveCamera()
        focus = np.array([0.5 * (N - 1) + 3.0, 0.5 * (N - 1) - 2.0, 0.5 * (N - 1) - 2.0])
        camera.SetFocalPoint(*focus)
        camera.SetPosition(*(focus + (80.0, 36.0, 120.0)))  # a three-quarter view, a little above
        camera.SetViewUp(0.0, 1.0, 0.0)
        camera.SetViewAngle(30.0)
        renderer.ResetCameraClippingRange()

        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetMultiSamples(0)
        self.window.SetSize(PANEL, PANEL)
        self.window.AddRenderer(renderer)

    def render(self, albedo=0.8, g=0.0, radius=0.0, model="extended", exposure=0.5,
               curve="shoulder"):
        m = self.mapper
        m.SetAlbedo(albedo)
        m.SetAnisotropy(g)
        m.SetAmbientRadius(radius)
        if model == "paper":
            m.SetScatteringModelToPaper()
        else:
            m.SetScatteringModelToExtended()
        m.SetExposure(exposure)
        if curve == "clamp":
            m.SetToneMappingToClamp()
        else:
            m.SetToneMappingToShoulder()
        self.window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.SetInputBufferTypeToRGB()
        grab.ReadFrontBufferOff()
        grab.Update()
        pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
        return pixels.reshape(PANEL, PANEL, 3)[::-1]  # VTK's rows run bottom-up


def montage(rows):
    """Panels (a list of rows of equal length) side by side, 1-pixel gutters between them."""
    h, w = len(rows), len(rows[0])
    out = np.empty((h * PANEL + h - 1, w * PANEL + w - 1, 3), np.uint8)
    out[:] = GUTTER
    for i, row in enumerate(rows):
        for j, panel in enumerate(row):
            top, left = i * (PANEL + 1), j * (PANEL + 1)
            out[top:top + PANEL, left:left + PANEL] = panel
    return out


def write_png(pixels, path):
    """An RGB array (rows top-down) to a PNG file."""
    h, w, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels[::-1].reshape(-1, 3).copy(), deep=1))
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()


def main(folder):
    os.makedirs(folder, exist_ok=True)
    start = time.time()
    image = cloud()
    scene = Scene(image)
    r = automatic_radius(image)

    panels = []

    def picture(name, rows, describe):
        panels.extend(s for row in rows for s in row)
        write_png(montage([[scene.render(**s) for s in row] for row in rows]),
                  os.path.join(folder, name))
        print("%s: %s" % (name, describe))

    albedos, gs = (0.3, 0.6, 0.9), (-0.6, 0.0, 0.4, 0.8)
    picture("parameters_albedo_anisotropy.png",
            [[dict(albedo=a, g=g) for g in gs] for a in albedos],
            "rows albedo %s (top to bottom), columns g = %s (left to right)"
            % (", ".join(map(str, albedos)), ", ".join(map(str, gs))))
    scales = (0.5, 1.0, 2.0, 4.0)
    picture("parameters_radius.png",
            [[dict(radius=0.0 if s == 1.0 else s * r) for s in scales]],
            "ambient radius " + ", ".join("%gx (%.2f%s)" % (s, s * r, ", automatic" * (s == 1))
                                          for s in scales))
    picture("parameters_models.png", [[dict(model="paper"), dict(model="extended")]],
            "the paper's model, the extended model (exposure 0.5, shoulder)")
    exposures = (0.25, 0.5, 1.0, 2.0)
    picture("parameters_exposure.png",
            [[dict(exposure=e) for e in exposures] + [dict(exposure=2.0, curve="clamp")]],
            "exposure " + ", ".join("%g shoulder" % e for e in exposures) + ", 2 clamp")
    print("%d panels in %.1f s" % (len(panels), time.time() - start))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join("Documentation", "Images"))
