"""pvbatch script of the distributed test (TestPVDistributed.py runs it on 1 and 2 ranks).

A wavelet whose pieces ParaView splits along z, seen from the side, lit from above (+z): the
upper piece shades the lower one, so the picture shows whether the light crosses the pieces'
boundary. Renders the "Ambient Scattering" representation (LightAcrossRanks as given) or
ParaView's own volume representation (plain, or with its volumetric scattering) and saves
the picture; prints how many ranks rendered it. "scattering-zoomed" looks closely at the upper
piece alone.

usage: [mpirun -np N] pvbatch --force-offscreen-rendering DistributedScene.py PLUGIN OUTPUT.png
           KIND (scattering | scattering-per-rank | scattering-zoomed | volume | volume-scattering)
"""
import sys

from paraview import servermanager as sm
from paraview import simple as pv

SIZE = [200, 200]
EXTENT = [-24, 24, -24, 24, -24, 24]
OPACITY = [37.0, 0.0, 0.5, 0.0, 130.0, 0.0, 0.5, 0.0, 277.0, 0.9, 0.5, 0.0]
SUN = [0.2, 0.1, 1.0]  # directional, scene coordinates: from above
CAMERA = dict(position=[160.0, -30.0, 10.0], focal_point=[0.0, 0.0, 0.0], view_up=[0.0, 0.0, 1.0],
              view_angle=30.0)
# Close on the upper piece: the lower piece is outside the view, so its rank's renderer culls
# the volume (the ranks must not wait for each other while rendering).
ZOOMED = dict(position=[60.0, -10.0, 20.0], focal_point=[0.0, 0.0, 20.0], view_up=[0.0, 0.0, 1.0],
              view_angle=10.0)


def main(plugin, out, kind):
    pv.LoadPlugin(plugin, remote=True, ns=globals())
    ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    wavelet = pv.Wavelet(WholeExtent=EXTENT)
    if kind == "scattering-blocks":
        halves = [pv.ExtractSubset(Input=wavelet, VOI=EXTENT[:4] + [z0, z1])
                  for z0, z1 in ((EXTENT[4], 0), (0, EXTENT[5]))]
        wavelet = pv.GroupDatasets(Input=halves)
    view = pv.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseLight = 0  # the one light below
    display = pv.Show(wavelet, view)
    display.SetRepresentationType("Volume" if kind.startswith("volume") else "Ambient Scattering")
    pv.ColorBy(display, ("POINTS", "RTData"))
    lut = pv.GetColorTransferFunction("RTData")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.Discretize = 0
    lut.RGBPoints = [37.0, 1.0, 1.0, 1.0, 277.0, 1.0, 1.0, 1.0]
    pv.GetOpacityTransferFunction("RTData").Points = OPACITY
    display.ScalarOpacityUnitDistance = 1.0
    if kind == "volume-scattering":
        display.Shade = 1
        display.GlobalIlluminationReach = 1.0
        display.VolumetricScatteringBlending = 2.0
    elif kind.startswith("scattering"):
        display.LightAcrossRanks = 0 if kind == "scattering-per-rank" else 1
        display.AmbientScatteringJittering = 0
    sun = pv.AddLight(view=view)
    sun.Coords = "Scene"
    sun.Type = "Directional"
    sun.Position = SUN
    camera = ZOOMED if kind.endswith("-zoomed") else CAMERA
    view.CameraPosition = camera["position"]
    view.CameraFocalPoint = camera["focal_point"]
    view.CameraViewUp = camera["view_up"]
    view.CameraViewAngle = camera["view_angle"]
    pv.Render(view)
    pv.SaveScreenshot(out, view, ImageResolution=SIZE, TransparentBackground=0)
    print("rendered %s on %d rank(s) into %s" % (kind, ranks, out))
    # Deleted here: left to the interpreter's exit, the view outlives the GL contexts.
    pv.Delete(display)
    pv.Delete(view)


if __name__ == "__main__":
    main(*sys.argv[1:4])
