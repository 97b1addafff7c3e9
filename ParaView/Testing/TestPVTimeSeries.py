"""A time series plays in pvbatch with the "Ambient Scattering" representation.

Writes two file series of .vti images: a wavelet whose centre moves from step to step (5
steps), and a static one (the same image in every file). Plays each with TimeSeriesScene.py
(SaveAnimation, then the first step again) with pvbatch on 1 rank and under `mpirun -np 2`, and
checks: every step draws the volume; the moving series' steps differ from one another (the
pictures follow the data); going back to the first step gives its picture again, bit for bit;
the static series gives the same picture at every step, bit for bit (nothing flickers); and on 2
ranks every step agrees with 1 rank (PSNR >= 35 dB: the light crosses the ranks' pieces, as in
TestPVDistributed.py).

usage: AVS_PARAVIEW_PYTHONPATH=... python3 TestPVTimeSeries.py PVBATCH MPIRUN PLUGIN OUTPUT_DIR
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import avs_pvtesting as t  # noqa: E402

from vtkmodules.vtkIOXML import vtkXMLImageDataWriter  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402

SCENE = os.path.join(HERE, "TimeSeriesScene.py")
STEPS = 5
EXTENT = [-20, 20, -20, 20, -20, 20]


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


def play(pvbatch, mpirun, plugin, files, prefix, ranks):
    """Runs the scene; returns the steps' pictures and the first step's again."""
    command = [pvbatch, "--force-offscreen-rendering", SCENE, plugin, prefix] + files
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
    checks.finish()


if __name__ == "__main__":
    main(*sys.argv[1:5])
