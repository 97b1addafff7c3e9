"""vtkAmbientScatteringVolumeMapper's path-traced refinement, checked against the CPU path tracer.

- The GPU estimator agrees with vtkVolumeReferenceRenderer's path tracer pixel by pixel: a
  z-test per pixel and channel of the two means with their sample variances, at a family-wise
  level of 1 % with the Sidak correction (as Mitsuba tests its integrators), on two scenes that
  use what the mapper draws: a directional light and an attenuated spot, a clipping plane,
  cropping, a label map, anisotropy and emission; two independent components with NaN voxels, a
  binary mask and a point light; and on the wavelet with surfaces inside the medium (ShadeOn,
  a sharper specular lobe, VolumetricScatteringBlending 0.5, lit on one side), whose surface
  events both path tracers trace.
- Its RMSE against a converged picture falls as 1/sqrt(spp); the picture shown is never worse
  than the ambient-scattering picture and reaches half its RMSE; the shown picture is the
  reference blend (Rendering/Core/Refinement.h) of the buffers.
- A camera move, a light, the property and the data restart it; the exposure does not; the
  interactor's reduced frames and other image sample distances add nothing; it stops at
  MaximumSamplesPerPixel; opaque geometry ends the camera paths; a split volume is not refined
  (a warning says so).
"""
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import (vtkImageData, vtkPiecewiseFunction, vtkPlane,
                                           vtkPlaneCollection)
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkLight,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import ambientscattering

FAILURES = []


def check(condition, what):
    if not condition:
        FAILURES.append(what)
        print("FAIL:", what)


def light(positional, position, intensity, color=(1, 1, 1), cone=30.0, attenuation=(1, 0, 0)):
    l = vtkLight()
    l.SetLightTypeToSceneLight()
    l.SetPositional(positional)
    l.SetPosition(*position)
    l.SetFocalPoint(0, 0, 0)
    l.SetIntensity(intensity)
    l.SetColor(*color)
    l.SetConeAngle(cone)
    l.SetAttenuationValues(*attenuation)
    return l


def wavelet_scene(size):
    """A wavelet lit by a directional light and an attenuated spot, clipped and cropped."""
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-16, 15, -16, 15, -16, 15)
    source.Update()
    lo, hi = source.GetOutput().GetScalarRange()
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.2, 0.3, 1.0)
    color.AddRGBPoint(hi, 1.0, 0.7, 0.3)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(150, 0.0)
    opacity.AddPoint(hi, 0.6)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(2.0)
    renderer = vtkRenderer()
    camera = renderer.GetActiveCamera()
    camera.SetPosition(10, 20, 80)
    camera.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light(False, (1, 1, 1), 0.8))
    renderer.AddLight(light(True, (-30, 10, 30), 1.0, (1, 0.8, 0.6), 25.0, (0, 0, 0.001)))
    planes = vtkPlaneCollection()
    plane = vtkPlane()
    plane.SetOrigin(4, 0, 0)
    plane.SetNormal(-1, 0.3, 0)
    planes.AddItem(plane)
    # A label map: label 1 (x < -4) has its own colour and opacity.
    z, y, x = np.mgrid[-16:16, -16:16, -16:16]
    mask = vtkImageData()
    mask.SetExtent(-16, 15, -16, 15, -16, 15)
    mask.GetPointData().SetScalars(numpy_to_vtk((x < -4).astype(np.uint8).ravel(), deep=1))
    label_color = vtkColorTransferFunction()
    label_color.AddRGBPoint(lo, 0.2, 1.0, 0.3)
    label_color.AddRGBPoint(hi, 0.9, 1.0, 0.3)
    label_opacity = vtkPiecewiseFunction()
    label_opacity.AddPoint(lo, 0.0)
    label_opacity.AddPoint(hi, 0.9)
    prop.SetLabelColor(1, label_color)
    prop.SetLabelScalarOpacity(1, label_opacity)
    settings = dict(Albedo=0.8, Anisotropy=0.4, EmissionWeight=0.3, MaskBlendFactor=0.8)
    cropping = (-16, 15, -16, 15, -16, 6)  # the top slab cropped away (sub-volume below z = 6)
    return source, (mask, "LabelMap"), prop, renderer, planes, cropping, settings


def components_scene(size):
    """Two independent components, NaN voxels, a label map and a point light."""
    n = 24
    z, y, x = np.mgrid[0:n, 0:n, 0:n].astype(np.float64)
    c = (n - 1) / 2.0
    r = np.sqrt((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2)
    a = np.clip(1.0 - r / 11.0, 0, 1)
    b = 0.5 + 0.5 * np.sin(0.5 * x) * np.cos(0.4 * y)
    a[(x + y + z) % 13 == 0] = np.nan
    data = np.stack([a.ravel(), b.ravel()], axis=1).astype(np.float32)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(1.0, 1.0, 1.0)
    image.SetOrigin(-c, -c, -c)
    scalars = numpy_to_vtk(data, deep=1)
    scalars.SetName("values")
    image.GetPointData().SetScalars(scalars)
    mask = vtkImageData()
    mask.SetDimensions(n, n, n)
    mask.SetSpacing(1.0, 1.0, 1.0)
    mask.SetOrigin(-c, -c, -c)
    keep = numpy_to_vtk(((x - c) + 0.6 * (y - c) < 6).astype(np.uint8).ravel(), deep=1)
    mask.GetPointData().SetScalars(keep)
    prop = vtkVolumeProperty()
    prop.IndependentComponentsOn()
    for comp, (rgb, top) in enumerate((((1.0, 0.5, 0.2), 0.5), ((0.3, 0.6, 1.0), 0.25))):
        color = vtkColorTransferFunction()
        color.AddRGBPoint(0.0, *rgb)
        color.AddRGBPoint(1.0, *rgb)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0.0, 0.0)
        opacity.AddPoint(1.0, top)
        prop.SetColor(comp, color)
        prop.SetScalarOpacity(comp, opacity)
        prop.SetScalarOpacityUnitDistance(comp, 1.5)
    prop.SetComponentWeight(1, 0.7)
    renderer = vtkRenderer()
    camera = renderer.GetActiveCamera()
    camera.SetPosition(-20, 15, 55)
    camera.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light(True, (25, 20, 20), 2.0, (1, 1, 0.9), 90.0, (0.5, 0.02, 0.0)))
    settings = dict(Albedo=0.9, Anisotropy=-0.2, EmissionWeight=0.0)
    return image, (mask, "Binary"), prop, renderer, None, None, settings


def surface_scene(size):
    """The wavelet with ShadeOn: surface events (Rendering/Core/SurfaceShading.h)."""
    data, mask, prop, renderer, planes, cropping, settings = wavelet_scene(size)
    prop.ShadeOn()
    prop.SetSpecular(0.4)
    prop.SetSpecularPower(20.0)
    renderer.TwoSidedLightingOff()
    settings["VolumetricScatteringBlending"] = 0.5
    return data, mask, prop, renderer, planes, cropping, settings


def configure(target, data, mask, planes, cropping, settings):
    if isinstance(data, vtkImageData):
        target.SetInputData(data)
    else:
        target.SetInputConnection(data.GetOutputPort())
    if mask is not None:
        target.SetMaskInput(mask[0])
        getattr(target, "SetMaskTypeTo" + mask[1])()
    if planes is not None:
        target.SetClippingPlanes(planes)
    if cropping is not None:
        target.SetCropping(True)
        target.SetCroppingRegionPlanes(*cropping)
        target.SetCroppingRegionFlagsToSubVolume()
    for name, value in settings.items():
        getattr(target, "Set" + name)(value)


def gpu_window(scene, size):
    data, mask, prop, renderer, planes, cropping, settings = scene
    mapper = ambientscattering.vtkAmbientScatteringVolumeMapper()
    configure(mapper, data, mask, planes, cropping, settings)
    mapper.SetPathTracedRefinement(True)
    mapper.SetExposure(1.0)
    mapper.SetToneMappingToClamp()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    renderer.SetBackground(0, 0, 0)
    window = vtkRenderWindow()
    window.SetSize(size, size)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    return window, mapper, volume


def buffers(mapper, size):
    a, m, m2 = vtkFloatArray(), vtkFloatArray(), vtkFloatArray()
    if not mapper.GetRefinementBuffers(a, m, m2):
        return None
    return [vtk_to_numpy(x).reshape(size, size, 4).astype(np.float64) for x in (a, m, m2)]


def cpu_path_traced(scene, size, spp, seed):
    data, mask, prop, renderer, planes, cropping, settings = scene
    ref = ambientscattering.vtkVolumeReferenceRenderer()
    configure(ref, data, mask, planes, cropping, settings)
    ref.SetVolumeProperty(prop)
    ref.SetRenderer(renderer)
    ref.SetImageSize(size, size)
    ref.SetRenderModeToPathTracing()
    ref.SetSamplesPerPixel(spp)
    ref.SetSeed(seed)
    ref.Update()
    pd = ref.GetOutput().GetPointData()
    mean = vtk_to_numpy(pd.GetArray("Radiance")).reshape(size, size, 4).astype(np.float64)
    second = vtk_to_numpy(pd.GetArray("RadianceSecondMoment")).reshape(size, size, 4)
    return mean, second.astype(np.float64)


def refine(window, mapper, samples):
    """Renders until `samples` samples per pixel; False when a frame adds none."""
    window.Render()
    while mapper.GetSamplesPerPixel() < samples:
        before = mapper.GetSamplesPerPixel()
        window.Render()
        if mapper.GetSamplesPerPixel() <= before:
            return False
    return True


def z_test(name, gpu, n_gpu, cpu, n_cpu, alpha=0.01):
    """Per pixel and channel, the two means' difference over its standard error; Sidak."""
    mg, m2g = gpu
    mc, m2c = cpu
    vg = np.maximum(m2g - mg * mg, 0) * n_gpu / (n_gpu - 1)
    vc = np.maximum(m2c - mc * mc, 0) * n_cpu / (n_cpu - 1)
    se = np.sqrt(vg / n_gpu + vc / n_cpu)
    d = mg - mc
    tested = se > 0
    m = int(tested.sum())
    z = np.abs(d[tested]) / se[tested]
    p = np.array([math.erfc(v / math.sqrt(2.0)) for v in z])
    level = 1.0 - (1.0 - alpha) ** (1.0 / max(m, 1))
    fails = int((p < level).sum())
    print(f"{name}: {m} tests, Sidak level {level:.3g}, smallest p {p.min():.3g}, "
          f"largest |z| {z.max():.2f}, mean z {np.mean(d[tested] / se[tested]):+.3f}, "
          f"sd z {np.std(d[tested] / se[tested]):.3f}")
    check(m > 1000, f"{name}: the scene has material in enough pixels ({m})")
    check(fails == 0, f"{name}: {fails} pixel channels reject the GPU = CPU hypothesis")
    check(np.abs(d[~tested]).max(initial=0.0) < 1e-6,
          f"{name}: pixels without variance agree")
    check(abs(np.std(d[tested] / se[tested]) - 1.0) < 0.1, f"{name}: z has unit spread")


def blend(a, m, m2, n, radius=2):
    """Rendering/Core/Refinement.h: A + w_s r_s + w_d (r - r_s), r = M - A."""
    if n < 16:
        return a.copy()
    h, w, _ = a.shape
    r = m - a
    # The samples' variance, at least that of hits and misses as likely as A says.
    hit = np.clip(a[..., 3:4], 0, 1)
    least = np.concatenate([a[..., :3] ** 2 * (1 - hit) / np.maximum(hit, 1e-30),
                            hit * (1 - hit)], axis=-1) / n
    least = np.where(hit > 0, least, 0.0)
    v = np.maximum(np.maximum(m2 - m * m, 0) / (n - 1), least).sum(-1)

    def window_mean(x):
        pad = [(radius, radius), (radius, radius)] + [(0, 0)] * (x.ndim - 2)
        xp = np.pad(x, pad, mode="edge")
        out = np.zeros_like(x)
        for dy in range(-radius, radius + 1):
            for dx in range(-radius, radius + 1):
                out += xp[radius + dy:radius + dy + h, radius + dx:radius + dx + w]
        return out / (2 * radius + 1) ** 2

    count = (2 * radius + 1) ** 2
    residual = window_mean(r)
    smooth = (residual ** 2).sum(-1)
    vbar = window_mean(v)
    smooth_bias2 = np.maximum(smooth - 2 * vbar / count, 0)
    smooth_weight = np.where(smooth_bias2 + vbar / count > 0,
                             smooth_bias2 / np.maximum(smooth_bias2 + vbar / count, 1e-30), 1.0)
    detail_bias2 = np.maximum(window_mean((r ** 2).sum(-1)) - smooth - 2 * vbar, 0)
    noise = np.maximum(vbar, v)
    detail_weight = np.where(detail_bias2 + noise > 0,
                             detail_bias2 / np.maximum(detail_bias2 + noise, 1e-30), 1.0)
    return a + smooth_weight[..., None] * residual + detail_weight[..., None] * (r - residual)


def framebuffer(window, size, depth=False):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    if depth:
        grab.SetInputBufferTypeToZBuffer()
    else:
        grab.SetInputBufferTypeToRGBA()
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(np.float64)
    return pixels.reshape(size, size) if depth else pixels.reshape(size, size, 4) / 255.0


def main():
    spp = 256
    # 1. The estimator against the CPU path tracer.
    for name, make, size in (("wavelet", wavelet_scene, 64), ("components", components_scene, 48),
                             ("surfaces", surface_scene, 48)):
        scene = make(size)
        window, mapper, _ = gpu_window(scene, size)
        window.Render()
        check(refine(window, mapper, spp), f"{name}: every still frame adds a sample")
        got = buffers(mapper, size)
        check(got is not None, f"{name}: the buffers are read back")
        n_gpu = mapper.GetSamplesPerPixel()
        cpu = cpu_path_traced(scene, size, spp, 5)
        z_test(name, got[1:], n_gpu, cpu, spp)

    # 2. Convergence, the picture shown, and what restarts it (the wavelet).
    size = 48
    scene = wavelet_scene(size)
    truth, _ = cpu_path_traced(scene, size, 2048, 9)
    window, mapper, volume = gpu_window(scene, size)
    window.Render()
    ambient_rmse = None
    raw, shown = {}, {}
    for n in (4, 8, 16, 32, 64, 128, 256):
        check(refine(window, mapper, n), f"refines to {n} samples")
        fb = framebuffer(window, size)  # (its render adds a sample too)
        a, m, m2 = buffers(mapper, size)
        n = mapper.GetSamplesPerPixel()
        rmse = lambda x: float(np.sqrt(((x - truth) ** 2).mean()))  # noqa: E731
        ambient_rmse = rmse(a)
        raw[n] = rmse(m)
        picture = blend(a, m, m2, n)
        shown[n] = rmse(picture)
        # What the framebuffer shows (exposure 1, clamp, black background): the blend.
        expected = np.clip(picture, 0, 1)
        check(np.abs(fb[..., :3] - expected[..., :3]).max() <= 2.5 / 255,
              f"{n} samples: the framebuffer shows the refined picture "
              f"(largest difference {np.abs(fb[..., :3] - expected[..., :3]).max() * 255:.1f}/255)")
        print(f"{n:4d} spp: RMSE ambient {ambient_rmse:.4f}, path-traced mean {raw[n]:.4f}, "
              f"shown {shown[n]:.4f}")
        check(shown[n] <= ambient_rmse * 1.001,
              f"{n} samples: the picture shown is not worse than ambient scattering")
    counts = sorted(raw)
    slope = np.polyfit(np.log(counts), np.log([raw[c] for c in counts]), 1)[0]
    print(f"RMSE of the mean against spp: slope {slope:.3f} (1/sqrt(spp): -0.5)")
    check(-0.6 < slope < -0.4, f"the mean's RMSE falls as 1/sqrt(spp) (slope {slope:.3f})")
    check(shown[counts[-1]] <= 0.5 * ambient_rmse,
          "the refined picture reaches half the ambient-scattering RMSE")

    def samples_after(action):
        action()
        window.Render()
        return mapper.GetSamplesPerPixel()

    data, mask, prop, renderer, planes, cropping, settings = scene
    camera = renderer.GetActiveCamera()
    before = mapper.GetSamplesPerPixel()
    check(samples_after(lambda: mapper.SetExposure(0.5)) == before + 1,
          "a new exposure keeps the samples")
    check(samples_after(lambda: camera.Azimuth(10)) == 1, "a camera move restarts")
    refine(window, mapper, 8)
    check(samples_after(lambda: renderer.GetLights().GetItemAsObject(0).SetIntensity(0.5)) == 1,
          "a light restarts")
    refine(window, mapper, 8)
    check(samples_after(lambda: prop.GetScalarOpacity().AddPoint(200, 0.3)) == 1,
          "the transfer function restarts")
    refine(window, mapper, 8)
    source = mapper.GetInputAlgorithm()
    check(samples_after(lambda: source.SetMaximum(200.0)) == 1, "new data restarts")
    refine(window, mapper, 8)
    # Reduced frames: the interactor's (under a second allotted) and other sample distances.
    window.SetDesiredUpdateRate(30.0)
    check(samples_after(lambda: None) == 8, "an interactive frame adds nothing")
    window.SetDesiredUpdateRate(0.0001)
    check(samples_after(lambda: None) == 9, "the next still frame goes on")
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetImageSampleDistance(2.0)
    check(samples_after(lambda: None) == 9, "image sample distance 2 adds nothing")
    mapper.SetImageSampleDistance(1.0)
    # The majorants do not depend on empty-space skipping.
    mapper.SetEmptySpaceSkipping(False)
    check(samples_after(lambda: None) == 10, "refines without empty-space skipping")
    mapper.SetEmptySpaceSkipping(True)
    mapper.SetMaximumSamplesPerPixel(12)
    for _ in range(10):
        window.Render()
    check(mapper.GetSamplesPerPixel() == 12, "it stops at MaximumSamplesPerPixel")
    mapper.SetMaximumSamplesPerPixel(1024)

    # Opaque geometry in front of the volume's left part ends the camera paths there.
    plane = vtkPlaneSource()
    plane.SetOrigin(-60, -60, 30)
    plane.SetPoint1(-2, -60, 30)
    plane.SetPoint2(-60, 60, 30)
    actor = vtkActor()
    geometry_mapper = vtkPolyDataMapper()
    geometry_mapper.SetInputConnection(plane.GetOutputPort())
    actor.SetMapper(geometry_mapper)
    renderer.AddActor(actor)
    window.Render()
    check(mapper.GetSamplesPerPixel() == 1, "new geometry restarts")
    refine(window, mapper, 16)
    depth = framebuffer(window, size, depth=True)
    a, m, m2 = buffers(mapper, size)
    covered = depth < 1.0
    print(f"the plane covers {int(covered.sum())} of {size * size} pixels")
    check(covered.sum() > 100 and (~covered).sum() > 100, "the plane covers part of the view")
    check(np.abs(m[covered]).max() == 0.0, "no path starts behind the opaque plane")
    check(m[~covered][..., 3].max() > 0.5, "paths beside the plane still meet the volume")

    # A split volume is not refined, with a warning.
    warnings = []
    mapper.AddObserver("WarningEvent", lambda *args: warnings.append(1))
    mapper.SetPartitions(2, 1, 1)
    window.Render()
    window.Render()
    check(mapper.GetSamplesPerPixel() == 0, "a split volume is not refined")
    check(len(warnings) == 1, f"one warning says so ({len(warnings)})")

    if FAILURES:
        print(f"{len(FAILURES)} check(s) failed")
        return 1
    print("all checks passed")
    return 0



if __name__ == "__main__":
    sys.exit(main())
