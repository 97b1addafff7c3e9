"""A time series plays in pvbatch with the "Ambient Scattering" representation.

Writes two file series of .vti images: a wavelet whose centre moves from step to step (5
steps), and a static one (the same image in every file). Plays each with TimeSeriesScene.py
(SaveAnimation, then the first step again) with pvbatch on 1 rank and under `mpirun -np 2`, and
checks: every step draws the volume; the moving series' steps differ from one another (the
pictures follow the data); going back to the first step gives its picture again, bit for bit;
the static series gives the same picture at every step, bit for bit (nothing flickers); and on 2
ranks every step agrees with 1 rank (PSNR >= 35 dB: the light crosses the ranks' pieces, as in
TestPVDistributed.py). Then the display across ranks: the moving series lit by a dim spot light
with Auto Exposure on (which brightens it; the exposure metered from the light over the whole
image, the same on every rank, where each piece's own would differ; the tone
curve applied on each rank before IceT composites) on 2 and 4 ranks agrees with 1 rank at every
step (>= 35 dB) and shows no seam where the pieces meet: on those pixels (the pieces' inner
faces projected by the scene's camera) it departs from the 1-rank picture by at most SEAM/255 on
average, where (on 4 ranks) each rank lit alone departs more than twice as far (so the measure
sees a seam).

usage: AVS_PARAVIEW_PYTHONPATH=... python3 TestPVTimeSeries.py PVBATCH MPIRUN PLUGIN OUTPUT_DIR
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import avs_pvtesting as t  # noqa: E402

from vtkmodules.vtkCommonExecutionModel import vtkExtentTranslator  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

SCENE = os.path.join(HERE, "TimeSeriesScene.py")
STEPS = 5
EXTENT = [-20, 20, -20, 20, -20, 20]
# TimeSeriesScene.py's picture size and camera.
SIZE = [160, 160]
CAMERA = dict(position=[90.0, 45.0, 75.0], focal_point=[0.0, 0.0, 0.0], view_up=[0.0, 0.0, 1.0],
              view_angle=30.0)
# The largest mean difference from the 1-rank picture where the pieces meet (of 255).
SEAM = 3.0


def write_series(folder, moving):
    """The series' files: the wavelet centred at x = -8, -4, 0, 4, 8 (or at 0 throughout)."""
    os.makedirs(folder, exist_ok=True)
    files = []
    for step in range(STEPS):
        source = vtkRTAnalyticSource()
        source.SetWholeExtent(*EXTENT)
        source.SetCenter(4.0 * (step - STEPS // 2) if moving else 0.0, 0.0, 0.0)
        writer = vtkXMLImageDataWriter()
        path = os.path.join(folder, "step_%d.vti" % step)
        writer.SetFileName(path)
        writer.SetInputConnection(source.GetOutputPort())
        writer.Write()
        files.append(path)
    return files


def boundary_pixels(ranks):
    """The pixels where the ranks' pieces meet, as TimeSeriesScene.py's camera sees them: the
    pieces as ParaView splits the image (VTK's vtkExtentTranslator, block mode), the planes of
    their inner faces sampled inside the image's box and projected."""
    translator = vtkExtentTranslator()
    planes = set()
    for rank in range(ranks):
        extent = [0] * 6
        translator.PieceToExtentThreadSafe(rank, ranks, 0, EXTENT, extent,
                                           vtkExtentTranslator.BLOCK_MODE, 0)
        for axis in range(3):
            if extent[2 * axis] > EXTENT[2 * axis]:
                planes.add((axis, extent[2 * axis]))
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(*SIZE)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*CAMERA["position"])
    camera.SetFocalPoint(*CAMERA["focal_point"])
    camera.SetViewUp(*CAMERA["view_up"])
    camera.SetViewAngle(CAMERA["view_angle"])
    pixels = set()
    n = 81
    for axis, value in planes:
        for i in range(n):
            for j in range(n):
                u = EXTENT[0] + (EXTENT[1] - EXTENT[0]) * i / (n - 1.0)
                v = EXTENT[0] + (EXTENT[1] - EXTENT[0]) * j / (n - 1.0)
                point = [u, v]
                point.insert(axis, float(value))
                renderer.SetWorldPoint(point + [1.0])
                renderer.WorldToDisplay()
                x, y, _ = renderer.GetDisplayPoint()
                if 0 <= x < SIZE[0] and 0 <= y < SIZE[1]:
                    pixels.add((int(x), int(y)))
    return sorted(pixels)


def seam(picture, truth, pixels):
    """Mean difference (of 255) between a picture and the 1-rank one on the pixels where the
    pieces meet (those lit in the 1-rank picture): a seam is a band that departs from it there."""
    total, count = 0, 0
    for x, y in pixels:
        i = 3 * (y * SIZE[0] + x)
        if max(truth[i:i + 3]) > 8:
            total += sum(abs(picture[i + c] - truth[i + c]) for c in range(3)) / 3.0
            count += 1
    return total / max(count, 1)


def play(pvbatch, mpirun, plugin, files, prefix, ranks, options=()):
    """Runs the scene; returns the steps' pictures and the first step's again."""
    command = [pvbatch, "--force-offscreen-rendering", SCENE, plugin, prefix] + list(options) \
        + files
    if ranks > 1:
        command = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
    environment = dict(os.environ, PYTHONPATH=os.environ["AVS_PARAVIEW_PYTHONPATH"])
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=300, env=environment)
    sys.stdout.write(result.stdout)
    expected = "saved %d time steps on %d rank(s)" % (STEPS, ranks)
    if result.returncode != 0 or expected not in result.stdout:
        raise RuntimeError("%s failed (exit %d, no '%s')" % (" ".join(command),
                                                             result.returncode, expected))
    steps = [t.read_png("%s.%04d.png" % (prefix, k))[0] for k in range(STEPS)]
    return steps, t.read_png(prefix + ".again.png")[0]


def main(pvbatch, mpirun, plugin, out):
    out = os.path.join(out, "timeseries")
    checks = t.Checks()
    moving = write_series(os.path.join(out, "moving"), True)
    static = write_series(os.path.join(out, "static"), False)
    one, again = play(pvbatch, mpirun, plugin, moving, os.path.join(out, "moving_1"), 1)
    for k, picture in enumerate(one):
        checks.check(t.lit_fraction(picture) > 0.1, "step %d is drawn (%.2f of the pixels lit)"
                     % (k + 1, t.lit_fraction(picture)))
    for k in range(1, STEPS):
        d = t.psnr(one[k - 1], one[k])
        checks.check(d < 30.0, "step %d differs from step %d: %.1f dB" % (k + 1, k, d))
    checks.check(again == one[0], "the first step again gives its picture, bit for bit "
                 "(largest difference %d/255)" % t.largest_difference(again, one[0]))
    still, still_again = play(pvbatch, mpirun, plugin, static, os.path.join(out, "static_1"), 1)
    for k in range(1, STEPS):
        checks.check(still[k] == still[0], "static series: step %d is step 1's picture, bit for "
                     "bit (largest difference %d/255)"
                     % (k + 1, t.largest_difference(still[k], still[0])))
    checks.check(still_again == still[0], "static series: the first step again is the same")
    two, two_again = play(pvbatch, mpirun, plugin, moving, os.path.join(out, "moving_2"), 2)
    for k in range(STEPS):
        d = t.psnr(one[k], two[k])
        checks.check(d >= 35.0, "2 ranks agree with 1 rank at step %d: %.1f dB (largest "
                     "difference %d/255)" % (k + 1, d, t.largest_difference(one[k], two[k])))
    checks.check(two_again == two[0], "2 ranks: the first step again gives its picture, bit for "
                 "bit (largest difference %d/255)" % t.largest_difference(two_again, two[0]))
    # The display across ranks: Auto Exposure on (every rank meters the whole, so every rank
    # exposes the same) and the tone curve applied before IceT composites; 2 and 4 ranks against
    # 1, and no seam where the pieces meet (against 4 ranks each lit alone, whose seam shows).
    # A dim spot light: what each rank would meter of its own piece differs.
    auto = ["--auto-exposure", "--spot"]
    one_auto, _ = play(pvbatch, mpirun, plugin, moving, os.path.join(out, "auto_1"), 1, auto)
    one_spot, _ = play(pvbatch, mpirun, plugin, moving, os.path.join(out, "spot_1"), 1, ["--spot"])
    brighter = sum(one_auto[0]) / max(sum(one_spot[0]), 1)
    checks.check(brighter > 1.2, "Auto Exposure brightens the dim spot light's picture %.2fx"
                 % brighter)
    # (Each rank lit alone on 4 ranks only: that the measure sees a seam needs showing once.)
    for ranks in (2, 4):
        pixels = boundary_pixels(ranks)
        many, _ = play(pvbatch, mpirun, plugin, moving, os.path.join(out, "auto_%d" % ranks),
                       ranks, auto)
        alone = None
        if ranks == 4:
            alone, _ = play(pvbatch, mpirun, plugin, moving,
                            os.path.join(out, "auto_alone_%d" % ranks), ranks,
                            auto + ["--per-rank"])
        for k in range(STEPS):
            d = t.psnr(one_auto[k], many[k])
            on = seam(many[k], one_auto[k], pixels)
            off = seam(alone[k], one_auto[k], pixels) if alone else None
            contrast = off is None or (off > 2.0 * on and off > SEAM)
            checks.check(d >= 35.0 and on <= SEAM and contrast,
                         "Auto Exposure on %d ranks, step %d: %.1f dB against 1 rank; where the "
                         "pieces meet (%d pixels) %.2f/255 from 1 rank's picture%s"
                         % (ranks, k + 1, d, len(pixels), on,
                            "" if off is None else " (each rank lit alone: %.2f)" % off))
    checks.finish()


if __name__ == "__main__":
    main(*sys.argv[1:5])
