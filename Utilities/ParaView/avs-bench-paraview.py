"""The peer in the benchmark: ParaView's own volumetric scattering against ours, in pvbatch.

The scene of avs-bench-mappers (the nebula it writes with --write-scene, its transfer functions,
its four lights, its camera turning 3 degrees per frame; ours at its sample distance, half a
voxel, jittering off; ParaView's vtkMultiBlockVolumeMapper has no sample-distance setting and
uses its automatic one, which for a still frame is also derived from the voxel spacing): ParaView's "Volume" representation (vtkMultiBlockVolumeMapper, VTK 9.2) unshaded
(emission-absorption), then with its volumetric scattering (Shade on, GlobalIlluminationReach
1.0, VolumetricScatteringBlending 2.0: scattering only) with 1 and with 4 lights; and this
project's "Ambient Scattering" representation with 1 and 4 lights. Medians over the frames after
a warm-up frame; printed as avs-bench-mappers prints (bench NAME VALUE s, ratio NAME VALUE).

With --time-series, the time series of avs-bench-mappers instead (BenchTimeSeries.h), 4 steps
unless --steps says otherwise: the scene moved 3 voxels along x per step (its values rewritten in place, the producer marked modified,
as a source delivers a step), the camera still, each case timed from the new step to the
finished frame; medians over the steps after the first, printed as timestep_pv_* lines.

usage: pvbatch --force-offscreen-rendering avs-bench-paraview.py PLUGIN SCENE.vti [--size N]
       [--frames N] [--time-series [--steps N]]
       (./avs bench runs it after avs-bench-mappers, with its options)
"""
import sys
import time

import numpy

from paraview import simple as pv
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (wraps vtkMultiBlockVolumeMapper)

COLORS = [0.0, 0.25, 0.35, 0.9, 0.5, 0.9, 0.5, 0.4, 1.0, 1.0, 0.95, 0.8]
OPACITY = [0.0, 0.0, 0.5, 0.0, 0.05, 0.0, 0.5, 0.0, 0.5, 0.25, 0.5, 0.0, 1.0, 0.6, 0.5, 0.0]
# avs-bench-mappers' lights: directional, a point light at the centre, two more directional.
LIGHTS = [dict(Type="Directional", Position=[-1, 1, 0.5], Intensity=0.4),
          dict(Type="Positional", Position=[0, 0, 0], FocalPoint=[0, 0, -1], ConeAngle=180,
               Intensity=0.8),
          dict(Type="Directional", Position=[1, 0.2, -0.3], Intensity=0.4),
          dict(Type="Directional", Position=[0.1, -1, 0.4], Intensity=0.4)]


def main(plugin, scene, size=512, frames=10, steps=0):
    pv.LoadPlugin(plugin, remote=False, ns=globals())
    reader = pv.XMLImageDataReader(FileName=[scene])
    reader.UpdatePipeline()
    from paraview import servermanager
    image = servermanager.Fetch(reader)
    spacing = image.GetSpacing()
    if steps:
        # The series' image, its values rewritten at every step by `move`.
        from vtkmodules.util.numpy_support import vtk_to_numpy
        data = pv.TrivialProducer()
        data.GetClientSideObject().SetOutput(image)
        dims = image.GetDimensions()
        values = vtk_to_numpy(image.GetPointData().GetArray("density"))
        original = values.reshape(dims[2], dims[1], dims[0]).copy()

        def move(step):
            values.reshape(dims[2], dims[1], dims[0])[...] = numpy.roll(original, 3 * step, axis=2)
            image.GetPointData().GetArray("density").Modified()
            image.Modified()
            data.MarkModified(data)
    else:
        data = reader
    sample_distance = 0.5 * spacing[0]
    view = pv.CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    view.UseLight = 0
    lights = []
    for spec in LIGHTS:
        light = pv.AddLight(view=view)
        light.Coords = "Scene"
        light.FocalPoint = spec.get("FocalPoint", [0, 0, 0])
        for key in ("Type", "Position", "Intensity", "ConeAngle"):
            if key in spec:
                setattr(light, key, spec[key])
        lights.append(light)
    display = pv.Show(data, view)
    pv.ColorBy(display, ("POINTS", "density"))
    lut = pv.GetColorTransferFunction("density")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.Discretize = 0
    lut.RGBPoints = COLORS
    pv.GetOpacityTransferFunction("density").Points = OPACITY
    display.ScalarOpacityUnitDistance = 2.0 / 48.0
    pv.Render(view)  # (paraview.simple resets the camera at the first render)
    print("# scene: %s, %d x %d pixels, sample distance %g, %d frames per case"
          % (scene, size, size, sample_distance, frames))

    def measure(name, representation, light_count, scattering=False):
        for i, light in enumerate(lights):
            light.Enable = 1 if i < light_count else 0
        display.SetRepresentationType(representation)
        # (Shade is shared by both representations: ours warns that it has no meaning there.)
        display.Shade = 1 if scattering else 0
        if representation == "Volume":
            display.GlobalIlluminationReach = 1.0 if scattering else 0.0
            display.VolumetricScatteringBlending = 2.0 if scattering else 0.0
        else:
            display.AmbientScatteringSampleDistance = sample_distance
            display.AmbientScatteringJittering = 0
        view.CameraPosition = [0.5, 0.7, 4.2]
        view.CameraFocalPoint = [0, 0, 0]
        view.CameraViewUp = [0, 1, 0]
        start = time.time()  # the first frame: with the precomputation, where there is one
        pv.Render(view)
        view.GetRenderWindow().WaitForCompletion()
        first = time.time() - start
        times = []
        camera = view.GetActiveCamera()
        for _ in range(frames):
            camera.Azimuth(3.0)
            start = time.time()
            pv.Render(view)
            view.GetRenderWindow().WaitForCompletion()
            times.append(time.time() - start)
        times.sort()
        median = times[len(times) // 2]
        print("bench %s %.4f s" % (name, median))
        print("bench first_%s %.4f s" % (name, first))
        return median

    def play(name, representation, light_count, scattering=False):
        """The median step of the series (after the first), from the new data to the frame."""
        for i, light in enumerate(lights):
            light.Enable = 1 if i < light_count else 0
        display.SetRepresentationType(representation)
        display.Shade = 1 if scattering else 0
        if representation == "Volume":
            display.GlobalIlluminationReach = 1.0 if scattering else 0.0
            display.VolumetricScatteringBlending = 2.0 if scattering else 0.0
        else:
            display.AmbientScatteringSampleDistance = sample_distance
            display.AmbientScatteringJittering = 0
        view.CameraPosition = [0.5, 0.7, 4.2]
        view.CameraFocalPoint = [0, 0, 0]
        view.CameraViewUp = [0, 1, 0]
        times = []
        for step in range(steps):
            start = time.time()
            move(step)
            pv.Render(view)
            view.GetRenderWindow().WaitForCompletion()
            if step > 0:
                times.append(time.time() - start)
        times.sort()
        median = times[len(times) // 2]
        print("bench timestep_%s %.4f s" % (name, median))
        return median

    if steps:
        print("# time series: %d steps, the volume moved 3 voxels along x per step, camera still"
              % steps)
        pv_ea = play("pv_ea", "Volume", 1)
        pv_vs1 = play("pv_scattering1", "Volume", 1, scattering=True)
        as1 = play("pv_as1", "Ambient Scattering", 1)
        pv_vs4 = play("pv_scattering4", "Volume", 4, scattering=True)
        as4 = play("pv_as4", "Ambient Scattering", 4)
        print("ratio timestep_pv_scattering1_over_pv_ea %.2f" % (pv_vs1 / pv_ea))
        print("ratio timestep_pv_as1_over_pv_scattering1 %.2f" % (as1 / pv_vs1))
        print("ratio timestep_pv_as4_over_pv_scattering4 %.2f" % (as4 / pv_vs4))
        pv.Delete(display)
        pv.Delete(view)
        return

    pv_ea = measure("frame_pv_ea", "Volume", 1)
    pv_vs1 = measure("frame_pv_scattering1", "Volume", 1, scattering=True)
    pv_vs4 = measure("frame_pv_scattering4", "Volume", 4, scattering=True)
    as1 = measure("frame_pv_as1", "Ambient Scattering", 1)
    as4 = measure("frame_pv_as4", "Ambient Scattering", 4)
    print("ratio pv_scattering1_over_pv_ea %.2f" % (pv_vs1 / pv_ea))
    print("ratio pv_scattering4_over_pv_ea %.2f" % (pv_vs4 / pv_ea))
    print("ratio pv_as1_over_pv_ea %.2f" % (as1 / pv_ea))
    print("ratio pv_as4_over_pv_ea %.2f" % (as4 / pv_ea))
    print("ratio pv_scattering1_over_as1 %.2f" % (pv_vs1 / as1))
    print("ratio pv_scattering4_over_as4 %.2f" % (pv_vs4 / as4))
    pv.Delete(display)
    pv.Delete(view)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    # (ParaView's volumetric scattering takes 25 s per step of the 256^3 nebula with one light on
    # llvmpipe: the series' steps default to 4 here, not avs-bench-mappers' 20.)
    options = {"--size": 512, "--frames": 10, "--steps": 4}  # avs-bench-mappers' others ignored
    rest = sys.argv[3:]
    for i, arg in enumerate(rest[:-1]):
        if arg in options:
            options[arg] = max(3 if arg == "--steps" else 2, int(rest[i + 1]))
    main(sys.argv[1], sys.argv[2], options["--size"], options["--frames"],
         options["--steps"] if "--time-series" in rest else 0)
