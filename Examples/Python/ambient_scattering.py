"""Ambient volume scattering in a VTK pipeline, rendered off screen to a PNG.

    ./avs python Examples/Python/ambient_scattering.py [OUTPUT.png]
"""
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

import ambientscattering

output = sys.argv[1] if len(sys.argv) > 1 else "ambient_scattering.png"

source = vtkRTAnalyticSource()  # any vtkImageData with one-component point scalars
source.SetWholeExtent(-30, 30, -30, 30, -30, 30)

color = vtkColorTransferFunction()
color.AddRGBPoint(37, 0.3, 0.4, 1.0)
color.AddRGBPoint(277, 1.0, 0.8, 0.5)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(37, 0.0)
opacity.AddPoint(160, 0.0)
opacity.AddPoint(277, 0.8)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(4.0)

mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
mapper.SetInputConnection(source.GetOutputPort())
mapper.SetAlbedo(0.8)        # share of extinction that scatters
mapper.SetAnisotropy(0.4)    # forward scattering
mapper.SetExposure(0.5)      # the display: radiance x exposure, then a shoulder (the defaults)
mapper.SetToneMappingToShoulder()
mapper.SetAmbientRadius(3.0)  # world units; 0 = automatic

volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

renderer = vtkRenderer()
renderer.AddVolume(volume)
sun = vtkLight()             # the renderer's lights light the volume
sun.SetPositional(False)
sun.SetPosition(-1, 1, 1)
sun.SetFocalPoint(0, 0, 0)
sun.SetIntensity(1.0)
renderer.AddLight(sun)
lamp = vtkLight()            # a point light inside the volume
lamp.SetPositional(True)
lamp.SetConeAngle(180)
lamp.SetPosition(0, 0, 0)
lamp.SetIntensity(3.0)
lamp.SetAttenuationValues(1, 0, 0.01)
renderer.AddLight(lamp)
renderer.GetActiveCamera().SetPosition(40, 50, 140)
renderer.GetActiveCamera().SetFocalPoint(0, 0, 0)
renderer.ResetCameraClippingRange()

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(256, 256)
window.AddRenderer(renderer)
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(output)
writer.Write()
print(output, "rendered in", mapper.GetNumberOfRenderedFrames(), "frame(s)")
