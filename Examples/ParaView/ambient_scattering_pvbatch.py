"""A volume with the "Ambient Scattering" representation, off screen.

usage: pvbatch --force-offscreen-rendering ambient_scattering_pvbatch.py PLUGIN OUTPUT.png
(PLUGIN: the path ./avs paraview prints; ParaView's Python on PYTHONPATH, see Documentation/ParaView.md)
"""
import sys
import time

from paraview.simple import (AddLight, ColorBy, CreateView, GetOpacityTransferFunction,
                             LoadPlugin, Render, SaveScreenshot, Show, Wavelet)

plugin, output = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())

data = Wavelet(WholeExtent=[-32, 32, -32, 32, -32, 32])  # or OpenDataFile("cloud.vdb")
view = CreateView("RenderView")
display = Show(data, view)
display.SetRepresentationType("Ambient Scattering")
ColorBy(display, ("POINTS", "RTData"))
GetOpacityTransferFunction("RTData").Points = [37, 0, 0.5, 0, 150, 0, 0.5, 0, 277, 1, 0.5, 0]
display.LightingModel = "Ambient Scattering"  # or "Emission-Absorption", "Ambient Occlusion"
display.Albedo = 0.8
display.ScatteringAnisotropy = 0.4  # the panel's "Anisotropy"
display.AmbientRadius = 0.0  # automatic
sun = AddLight(view=view)  # a light of the Lights panel, beside the light kit
sun.Coords = "Scene"
sun.Position = [1.0, 2.0, 1.0]
sun.Intensity = 0.8

start = time.time()
Render(view)
SaveScreenshot(output, view, ImageResolution=[256, 256])
print("%s rendered in %.2f s" % (output, time.time() - start))
