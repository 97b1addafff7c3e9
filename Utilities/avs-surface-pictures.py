"""The guide's pictures of surfaces inside the medium (ShadeOn in ambient scattering).

    ./avs python Utilities/avs-surface-pictures.py Documentation/Images [SAMPLES]

Writes surfaces_ct.png and surfaces_jet.png into the folder given: four panels of 200 x 200
pixels, left to right: vtkGPUVolumeRayCastMapper with ShadeOn | vtkAmbientScatteringVolumeMapper
with ShadeOff (VolumetricScatteringBlending 2, the unshaded picture) | the same with ShadeOn at
its defaults | the CPU path tracer of the same hybrid medium (vtkVolumeReferenceRenderer,
SAMPLES paths per pixel, default 256, through ambient scattering's exposure and shoulder). The
scenes are the swap test's (Testing/Python/TestSwapMapper.py): its CT-like head and its jet
flow field with the transfer function that picks out the shear layer, the user's script with a
vtkLightKit, 30 degrees of azimuth and 20 of elevation. Prints each panel's mean and detail
(the swap test's measure).
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing",
                                "Python"))
import TestSwapMapper as swap  # noqa: E402

import ambientscattering  # noqa: E402

swap.SIZE = 200
LIGHTING = "light kit"


def path_traced(image, feature, samples):
    """The user's scene (its renderer's lights and camera, its property) through
    vtkVolumeReferenceRenderer's path tracer, as 0-255 RGB rows bottom first."""
    mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
    captured = {}

    def trace(renderer):
        ref = ambientscattering.vtkVolumeReferenceRenderer()
        ref.SetInputData(image)
        ref.SetVolumeProperty(renderer.GetVolumes().GetLastProp().GetProperty())
        ref.SetRenderer(renderer)
        ref.SetImageSize(swap.SIZE, swap.SIZE)
        ref.SetRenderModeToPathTracing()
        ref.SetSamplesPerPixel(samples)
        ref.SetExposure(mapper.GetExposure())
        ref.SetToneMappingToShoulder()
        ref.Update()
        rgb = vtk_to_numpy(ref.GetOutput().GetPointData().GetScalars())
        captured["picture"] = rgb.reshape(swap.SIZE, swap.SIZE, -1)[..., :3].astype(float)

    swap.user_script(image, mapper, LIGHTING, feature, inspect=trace)
    return captured["picture"]


def write(panels, path):
    gutter = np.full((swap.SIZE, 2, 3), 20.0)
    row = []
    for p in panels:
        row += [p, gutter]
    pixels = np.clip(np.concatenate(row[:-1], axis=1), 0, 255).astype(np.uint8)
    h, w, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels.reshape(-1, 3), deep=1))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def main(folder, samples):
    os.makedirs(folder, exist_ok=True)
    for name, image, feature in (("ct", swap.ct_head(), False), ("jet", swap.jet(), True)):
        vtk = swap.user_script(image, vtkGPUVolumeRayCastMapper(), LIGHTING, feature)[0]
        off = ambientscattering.vtkAmbientScatteringVolumeMapper()
        off.SetVolumetricScatteringBlending(2.0)
        unshaded = swap.user_script(image, off, LIGHTING, feature)[0]
        shaded = swap.user_script(
            image, ambientscattering.vtkAmbientScatteringVolumeMapper(), LIGHTING, feature)[0]
        traced = path_traced(image, feature, samples)
        panels = [vtk, unshaded, shaded, traced]
        footprint = np.any([p.max(axis=-1) > 2 for p in panels[:3]], axis=0)
        for label, p in zip(("VTK ShadeOn", "AS ShadeOff", "AS ShadeOn", "path tracer"), panels):
            print("%s %-12s mean %6.1f detail %.4f" % (name, label, p[footprint].mean(),
                                                      swap.detail(p, footprint)))
        # Rows of the window come bottom first; a PNG's top first.
        write([p[::-1] for p in panels], os.path.join(folder, "surfaces_%s.png" % name))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "Documentation/Images",
         int(sys.argv[2]) if len(sys.argv) > 2 else 256)
