"""pvbatch test of the plugin's "Ambient Scattering" representation.

Loads the plugin, shows a wavelet with the representation (ParaView's colour map, opacity
function, scalar selection, a light of the Lights panel, the camera), renders off screen and
compares the picture with the one the VTK-side mapper renders of the same scene, in the same
process, with ParaView's VTK: a plain vtkRenderer and vtkVolume whose mapper is a new instance of
the class the representation renders with (the plugin's vtkAmbientScatteringVolumeMapper). Then
checks that Albedo, ScatteringAnisotropy (the panel's "Anisotropy"), LightingModel, a moved
light and ParaView's light kit change the picture, and that undoing them gives it back; and that
ParaView's Shade, Specular and Volumetric Scattering Blending drive the surfaces inside the medium
(Shade changes the picture, so does Specular with it, and a blending of 2 gives the unshaded
picture back).

usage: pvbatch --force-offscreen-rendering TestPVAmbientScattering.py PLUGIN OUTPUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import avs_pvtesting as t  # noqa: E402

from paraview import simple as pv  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight,  # noqa: E402
                                         vtkRenderWindow, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: E402,F401

SIZE = [160, 160]
EXTENT = [-16, 16, -16, 16, -16, 16]
COLORS = [37.0, 0.2, 0.4, 1.0, 157.0, 1.0, 1.0, 1.0, 277.0, 1.0, 0.5, 0.1]
OPACITY = [37.0, 0.0, 0.5, 0.0, 140.0, 0.0, 0.5, 0.0, 277.0, 0.8, 0.5, 0.0]
UNIT_DISTANCE = 2.0
CAMERA = dict(position=[60.0, 40.0, 90.0], focal_point=[0.0, 0.0, 0.0], view_up=[0.0, 1.0, 0.0],
              view_angle=30.0)
SUN = dict(position=[1.0, 2.0, 1.0], focal_point=[0.0, 0.0, 0.0], intensity=1.0)


def main(plugin, out):
    os.makedirs(out, exist_ok=True)
    checks = t.Checks()
    pv.LoadPlugin(plugin, remote=False, ns=globals())

    # --- ParaView: the representation, the colour map, a scene light, the camera.
    wavelet = pv.Wavelet(WholeExtent=EXTENT)
    view = pv.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseLight = 0  # no light kit: the one light below
    display = pv.Show(wavelet, view)
    available = display.GetProperty("Representation").Available
    checks.check("Ambient Scattering" in available,
                 "'Ambient Scattering' in the Representation menu of image data")
    display.SetRepresentationType("Ambient Scattering")
    pv.ColorBy(display, ("POINTS", "RTData"))
    lut = pv.GetColorTransferFunction("RTData")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.Discretize = 0
    lut.RGBPoints = COLORS
    opacity = pv.GetOpacityTransferFunction("RTData")
    opacity.Points = OPACITY
    display.ScalarOpacityUnitDistance = UNIT_DISTANCE
    display.InterpolationType = "Linear"
    sun = pv.AddLight(view=view)
    sun.Coords = "Scene"
    sun.Type = "Directional"
    sun.Position = SUN["position"]
    sun.FocalPoint = SUN["focal_point"]
    sun.Intensity = SUN["intensity"]
    sun.DiffuseColor = [1.0, 1.0, 1.0]
    pv.Render(view)  # paraview.simple resets the camera at a view's first render: done here
    view.CameraPosition = CAMERA["position"]
    view.CameraFocalPoint = CAMERA["focal_point"]
    view.CameraViewUp = CAMERA["view_up"]
    view.CameraViewAngle = CAMERA["view_angle"]
    view.CameraParallelProjection = 0
    for name, value in (("LightingModel", "Ambient Scattering"), ("Albedo", 0.8),
                        ("Exposure", 0.5), ("ToneMapping", "Shoulder"), ("AutoExposure", 0),
                        ("ScatteringAnisotropy", 0.0), ("AmbientRadius", 0.0),
                        ("LightScale", 1.0), ("EmissionWeight", 0.0),
                        ("LightVolumeMaximumDimension", 128), ("MaximumGPUMemory", 0),
                        ("ScatteringModel", "Extended"), ("DiffusionVolumeMaximumDimension", 64)):
        checks.check(display.GetPropertyValue(name) == value,
                     "%s defaults to %r (got %r)" % (name, value, display.GetPropertyValue(name)))

    def render(name):
        path = os.path.join(out, name + ".png")
        pv.Render(view)
        pv.SaveScreenshot(path, view, ImageResolution=SIZE, TransparentBackground=0)
        return t.read_png(path)[0]

    base = render("pv_ambient_scattering")
    volumes = view.GetRenderer().GetVolumes()
    volumes.InitTraversal()
    volume = volumes.GetNextVolume()
    mapper = volume.GetMapper() if volume else None
    checks.check(mapper is not None and mapper.GetClassName() == "vtkAmbientScatteringVolumeMapper",
                 "the view renders with vtkAmbientScatteringVolumeMapper (got %s)"
                 % (mapper.GetClassName() if mapper else None))
    checks.check(t.lit_fraction(base) > 0.15,
                 "the volume covers the picture (%.2f lit)" % t.lit_fraction(base))
    # The GPU memory budget reaches the mapper (its PrintSelf: pvbatch wraps it as the
    # vtkVolumeMapper it derives from).
    display.MaximumGPUMemory = 512
    pv.Render(view)
    checks.check(mapper is not None and "MaximumGPUMemory: 512" in str(mapper),
                 "MaximumGPUMemory reaches the mapper")
    display.MaximumGPUMemory = 0
    # The paper's model is a different picture, and back to the extended one the same.
    display.ScatteringModel = "Paper"
    paper = render("pv_ambient_scattering_paper")
    checks.check(mapper is not None and "ScatteringModel: Paper" in str(mapper),
                 "ScatteringModel reaches the mapper")
    checks.check(t.psnr(base, paper) < 45.0, "the paper's model is another picture")
    display.ScatteringModel = "Extended"
    checks.check(t.psnr(base, render("pv_ambient_scattering_extended")) > 50.0,
                 "back to the extended model, its picture")
    # The diffusion grid reaches the mapper: a coarser one changes the diffuse light a little.
    display.DiffusionVolumeMaximumDimension = 8
    coarse = render("pv_ambient_scattering_diffusion8")
    checks.check(mapper is not None and "DiffusionVolumeMaximumDimension: 8" in str(mapper),
                 "DiffusionVolumeMaximumDimension reaches the mapper")
    checks.check(t.psnr(base, coarse) < 80.0 and t.lit_fraction(coarse) > 0.15,
                 "a coarser diffusion grid renders another picture (%.1f dB)"
                 % t.psnr(base, coarse))
    display.DiffusionVolumeMaximumDimension = 64
    # The path-traced refinement: every still render adds a sample, up to the maximum, and the
    # picture moves away from ambient scattering; a camera move restarts it.
    display.PathTracedRefinement = 1
    display.MaximumSamplesPerPixel = 20  # (the picture leaves ambient scattering from 16)
    samples = []
    for _ in range(24):
        pv.Render(view)
        display.UpdatePropertyInformation()
        samples.append(display.GetPropertyValue("SamplesPerPixelInfo"))
    checks.check(samples[:20] == list(range(1, 21)) and samples[20:] == [20] * 4,
                 "each still render adds a sample up to MaximumSamplesPerPixel (%s)" % samples)
    checks.check(mapper is not None and "PathTracedRefinement: On" in str(mapper),
                 "PathTracedRefinement reaches the mapper")
    refined = render("pv_ambient_scattering_refined")
    checks.check(t.psnr(base, refined) < 60.0 and t.lit_fraction(refined) > 0.15,
                 "the refined picture is another picture (%.1f dB)" % t.psnr(base, refined))
    view.CameraPosition = [p * 1.01 for p in view.CameraPosition]
    pv.Render(view)
    display.UpdatePropertyInformation()
    checks.check(display.GetPropertyValue("SamplesPerPixelInfo") == 1, "a camera move restarts")
    view.CameraPosition = [p / 1.01 for p in view.CameraPosition]
    display.PathTracedRefinement = 0
    checks.check(t.psnr(base, render("pv_ambient_scattering_unrefined")) > 50.0,
                 "off again, the ambient-scattering picture")

    # --- The VTK side: the same scene with ParaView's VTK and the plugin's mapper class.
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(*EXTENT)
    reference_mapper = mapper.NewInstance()
    reference_mapper.SetInputConnection(source.GetOutputPort())
    colors = vtkColorTransferFunction()
    for i in range(0, len(COLORS), 4):
        colors.AddRGBPoint(*COLORS[i:i + 4])
    scalar_opacity = vtkPiecewiseFunction()
    for i in range(0, len(OPACITY), 4):
        scalar_opacity.AddPoint(*OPACITY[i:i + 4])
    prop = vtkVolumeProperty()
    prop.SetColor(colors)
    prop.SetScalarOpacity(scalar_opacity)
    prop.SetScalarOpacityUnitDistance(UNIT_DISTANCE)
    prop.SetInterpolationTypeToLinear()
    reference_volume = vtkVolume()
    reference_volume.SetMapper(reference_mapper)
    reference_volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    renderer.AddVolume(reference_volume)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(*SUN["position"])
    light.SetFocalPoint(*SUN["focal_point"])
    light.SetIntensity(SUN["intensity"])
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*CAMERA["position"])
    camera.SetFocalPoint(*CAMERA["focal_point"])
    camera.SetViewUp(*CAMERA["view_up"])
    camera.SetViewAngle(CAMERA["view_angle"])
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*SIZE)
    window.AddRenderer(renderer)
    window.Render()
    reference = t.grab_window(window, os.path.join(out, "vtk_ambient_scattering.png"))[0]
    # Done with the VTK-side window: its GL resources go while its context is still there.
    renderer.RemoveAllViewProps()
    reference_mapper.ReleaseGraphicsResources(window)
    window.Finalize()
    del window, renderer, reference_volume, reference_mapper
    match = t.psnr(base, reference)
    checks.check(match >= 35.0, "ParaView's picture against the VTK-side mapper's: %.1f dB "
                 "PSNR (>= 35), largest difference %d/255"
                 % (match, t.largest_difference(base, reference)))

    # --- The panel's parameters and the light change the picture; undoing them restores it.
    def changes(name, apply, undo, what):
        apply()
        changed = render(name)
        undo()
        again = render(name + "_undone")
        difference = t.psnr(base, changed)
        largest = t.largest_difference(base, changed)
        checks.check(difference < 40.0 and largest >= 10,
                     "%s changes the picture (%.1f dB PSNR to the first, largest difference "
                     "%d/255)" % (what, difference, largest))
        restored = t.psnr(base, again)
        checks.check(restored >= 50.0, "undoing it restores the picture (%.1f dB)" % restored)
        return changed

    def setter(name, value):
        return lambda: display.SetPropertyWithName(name, value)

    changes("pv_albedo", setter("Albedo", 0.3), setter("Albedo", 0.8), "Albedo 0.8 -> 0.3")
    # The display transform reaches the mapper and changes the picture.
    changes("pv_exposure", setter("Exposure", 1.5), setter("Exposure", 0.5), "Exposure 0.5 -> 1.5")
    display.ToneMapping = "Clamp (none)"
    pv.Render(view)
    checks.check(mapper is not None and "ToneMapping: Clamp" in str(mapper),
                 "ToneMapping reaches the mapper")
    display.ToneMapping = "Shoulder"
    # Under the view's own tone mapping (a vtkToneMappingPass in ParaView's passes) the volume
    # hands over its radiance without its shoulder; without it, the shoulder is back.
    for on, curve in ((1, "LastToneMapping: 0"), (0, "LastToneMapping: 1")):
        view.UseToneMapping = on
        pv.Render(view)
        checks.check(mapper is not None and curve in str(mapper),
                     "the view's tone mapping %s: the mapper's %s" % ("on" if on else "off", curve))
    display.AutoExposure = 1
    pv.Render(view)
    checks.check(mapper is not None and "AutoExposure: On" in str(mapper),
                 "AutoExposure reaches the mapper")
    display.AutoExposure = 0
    changes("pv_anisotropy", setter("ScatteringAnisotropy", 0.8),
            setter("ScatteringAnisotropy", 0.0), "Anisotropy 0 -> 0.8")
    # Surfaces inside the medium: ParaView's own shading properties.
    changes("pv_shade", setter("Shade", 1), setter("Shade", 0), "Shade 0 -> 1")
    display.Shade = 1
    shaded = render("pv_shaded")
    display.Specular = 0.6
    specular = render("pv_shaded_specular")
    display.Specular = 0.0
    checks.check(t.psnr(shaded, specular) < 45.0,
                 "with Shade, Specular 0 -> 0.6 changes the picture (%.1f dB)"
                 % t.psnr(shaded, specular))
    display.VolumetricScatteringBlending = 2.0
    pure = render("pv_shaded_blending2")
    checks.check(mapper is not None and "VolumetricScatteringBlending: 2" in str(mapper),
                 "VolumetricScatteringBlending reaches the mapper")
    checks.check(t.psnr(base, pure) >= 50.0,
                 "with Shade, VolumetricScatteringBlending 2 gives the unshaded picture (%.1f dB)"
                 % t.psnr(base, pure))
    display.VolumetricScatteringBlending = 0.0
    display.Shade = 0
    ea = changes("pv_emission_absorption", setter("LightingModel", "Emission-Absorption"),
                 setter("LightingModel", "Ambient Scattering"),
                 "LightingModel -> Emission-Absorption")
    changes("pv_ambient_occlusion", setter("LightingModel", "Ambient Occlusion"),
            setter("LightingModel", "Ambient Scattering"), "LightingModel -> Ambient Occlusion")

    def move_light():
        sun.Position = [-2.0, -1.0, 1.0]

    def put_back_light():
        sun.Position = SUN["position"]

    changes("pv_moved_light", move_light, put_back_light, "moving the light")
    changes("pv_light_kit", lambda: setattr(view, "UseLight", 1),
            lambda: setattr(view, "UseLight", 0), "turning ParaView's light kit on")

    # Emission-absorption ignores the lights: its picture is the same with the light moved.
    display.LightingModel = "Emission-Absorption"
    move_light()
    ea_moved = render("pv_emission_absorption_moved_light")
    put_back_light()
    display.LightingModel = "Ambient Scattering"
    checks.check(t.psnr(ea, ea_moved) >= 50.0,
                 "emission-absorption ignores the light (%.1f dB)" % t.psnr(ea, ea_moved))
    # The view goes first, while every window is still there (left to the interpreter's exit,
    # the order of teardown is undefined and can leave a GL context current that is gone).
    pv.Delete(display)
    pv.Delete(view)
    checks.finish()


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
