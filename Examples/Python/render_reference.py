"""Render a volume with the CPU reference ray caster of the ambientscattering package.

    ./avs python Examples/Python/render_reference.py [OUTPUT.png]

Builds a small structured volume (VTK's wavelet source), lights it with a directional light and
a point light inside it, and writes the ambient-scattering picture as PNG.
"""
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkVolumeProperty)

import ambientscattering

output = sys.argv[1] if len(sys.argv) > 1 else "reference.png"

source = vtkRTAnalyticSource()
source.SetWholeExtent(-20, 20, -20, 20, -20, 20)
source.Update()
lo, hi = source.GetOutput().GetScalarRange()

color = vtkColorTransferFunction()
color.AddRGBPoint(lo, 0.3, 0.4, 1.0)
color.AddRGBPoint(hi, 1.0, 0.8, 0.5)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(lo, 0.0)
opacity.AddPoint(lo + 0.55 * (hi - lo), 0.0)
opacity.AddPoint(hi, 0.8)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(4.0)

renderer = vtkRenderer()  # carries the lights and the camera
sun = vtkLight()
sun.SetPositional(False)
sun.SetPosition(-1, 1, 1)
sun.SetFocalPoint(0, 0, 0)
sun.SetIntensity(1.2)
renderer.AddLight(sun)
lamp = vtkLight()
lamp.SetPositional(True)
lamp.SetConeAngle(180)
lamp.SetPosition(0, 0, 0)
lamp.SetIntensity(3.0)
lamp.SetAttenuationValues(1, 0, 0.01)
renderer.AddLight(lamp)
renderer.GetActiveCamera().SetPosition(25, 30, 75)
renderer.GetActiveCamera().SetFocalPoint(0, 0, 0)

reference = ambientscattering.vtkVolumeReferenceRenderer()
reference.SetInputConnection(source.GetOutputPort())
reference.SetVolumeProperty(prop)
reference.SetRenderer(renderer)
reference.SetRenderModeToAmbientScattering()
reference.SetAlbedo(0.8)
reference.SetAnisotropy(0.4)
reference.SetImageSize(128, 128)

writer = vtkPNGWriter()
writer.SetInputConnection(reference.GetOutputPort())
writer.SetFileName(output)
writer.Write()
print(output)
