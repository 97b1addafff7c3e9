"""The installed plugin, found the way ParaView finds plugins: pvbatch started with PV_PLUGIN_PATH
naming the installed plugin's folder loads it at start-up, with no LoadPlugin call; the Ambient
Scattering representation then renders, its scattering table found in the installed folder.

usage: PV_PLUGIN_PATH=FOLDER pvbatch --force-offscreen-rendering TestPVInstalledPlugin.py OUTPUT.png
"""
import os
import sys

from paraview.simple import (ColorBy, CreateView, Delete, GetOpacityTransferFunction, Render,
                             SaveScreenshot, Show, Wavelet)

output = sys.argv[1]
failures = []
folder = os.environ.get("PV_PLUGIN_PATH", "")
if not folder:
    failures.append("PV_PLUGIN_PATH is not set")
data = Wavelet(WholeExtent=[-24, 24, -24, 24, -24, 24])
view = CreateView("RenderView")
display = Show(data, view)
try:
    display.SetRepresentationType("Ambient Scattering")
except Exception as e:  # the representation is unknown when the plugin did not load
    failures.append("no Ambient Scattering representation: %s" % e)
if display.GetProperty("LightingModel") is None:
    failures.append("the representation has no LightingModel: the plugin did not load")
else:
    ColorBy(display, ("POINTS", "RTData"))
    GetOpacityTransferFunction("RTData").Points = [37, 0, 0.5, 0, 277, 0.8, 0.5, 0]
    Render(view)
    SaveScreenshot(output, view, ImageResolution=[128, 128])
    mapper = None
    volumes = view.GetRenderer().GetVolumes()
    volumes.InitTraversal()
    volume = volumes.GetNextVolume()
    mapper = volume.GetMapper() if volume else None
    if mapper is None or mapper.GetClassName() != "vtkAmbientScatteringVolumeMapper":
        failures.append("the view does not render with vtkAmbientScatteringVolumeMapper")
    else:
        # The shipped table, loaded from the installed plugin's folder (the mapper's PrintSelf
        # prints its table's).
        loaded = [line.split(":", 1)[1].strip() for line in str(mapper).splitlines()
                  if line.strip().startswith("LoadedFileName:")]
        if not loaded or not os.path.realpath(loaded[0]).startswith(os.path.realpath(folder)):
            failures.append("the scattering table came from %s, not the installed folder %s"
                            % (loaded, folder))
# The view goes first, while its window is still there (left to the interpreter's exit, the
# order of teardown can leave a GL context current that is gone).
Delete(display)
Delete(view)
print("plugin folder", folder, "picture", output)
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
