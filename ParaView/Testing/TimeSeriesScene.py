"""pvbatch script of the time-series test (TestPVTimeSeries.py runs it on 1 and 2 ranks).

Opens a file series of .vti images (ParaView's XML image reader gives it time steps), shows it
with the "Ambient Scattering" representation lit by one light, plays it with SaveAnimation (one
picture per time step, as a user saves an animation), then goes back to the first time step and
saves that picture again. Prints how many steps it saved on how many ranks. --auto-exposure
turns the representation's Auto Exposure on (the display transform's exposure metered from the
lights over the whole image); --spot lights it with a dim spot light (intensity 0.5, a 35 degree
cone on the centre: what it meters depends on the box metered) instead of the directional one;
--per-rank turns Light Across Ranks off.

usage: [mpirun -np N] pvbatch --force-offscreen-rendering TimeSeriesScene.py PLUGIN OUTPUT_PREFIX
           [--auto-exposure] [--spot] [--per-rank] FILE.vti...
"""
import sys

from paraview import servermanager as sm
from paraview import simple as pv

SIZE = [160, 160]
COLORS = [37.0, 0.2, 0.4, 1.0, 157.0, 1.0, 1.0, 1.0, 277.0, 1.0, 0.5, 0.1]
OPACITY = [37.0, 0.0, 0.5, 0.0, 130.0, 0.0, 0.5, 0.0, 277.0, 0.9, 0.5, 0.0]


def main(plugin, prefix, arguments):
    files = [a for a in arguments if not a.startswith("--")]
    pv.LoadPlugin(plugin, remote=True, ns=globals())
    ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    reader = pv.XMLImageDataReader(FileName=files)
    times = list(reader.TimestepValues)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    view = pv.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseLight = 0
    display = pv.Show(reader, view)
    display.SetRepresentationType("Ambient Scattering")
    pv.ColorBy(display, ("POINTS", "RTData"))
    lut = pv.GetColorTransferFunction("RTData")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.Discretize = 0
    lut.RGBPoints = COLORS
    pv.GetOpacityTransferFunction("RTData").Points = OPACITY
    display.ScalarOpacityUnitDistance = 1.0
    display.AmbientScatteringJittering = 0
    display.AutoExposure = 1 if "--auto-exposure" in arguments else 0
    display.LightAcrossRanks = 0 if "--per-rank" in arguments else 1
    sun = pv.AddLight(view=view)
    sun.Coords = "Scene"
    if "--spot" in arguments:
        sun.Type = "Positional"
        sun.Position = [30.0, 15.0, 40.0]
        sun.FocalPoint = [0.0, 0.0, 0.0]
        sun.ConeAngle = 35.0
        sun.Intensity = 0.5
    else:
        sun.Type = "Directional"
        sun.Position = [0.2, 1.0, 0.6]
    pv.Render(view)  # (paraview.simple resets the camera at its first render)
    view.CameraPosition = [90.0, 45.0, 75.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    # The animation: one picture per time step (PREFIX.0000.png, ...).
    pv.SaveAnimation(prefix + ".png", view, ImageResolution=SIZE, TransparentBackground=0,
                     FrameWindow=[0, len(times) - 1])
    # Back to the first step.
    scene.AnimationTime = times[0]
    view.ViewTime = times[0]
    pv.Render(view)
    pv.SaveScreenshot(prefix + ".again.png", view, ImageResolution=SIZE, TransparentBackground=0)
    print("saved %d time steps on %d rank(s)" % (len(times), ranks))
    pv.Delete(display)
    pv.Delete(view)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
