"""avs-bench-ranks: what each MPI process holds and sends for light across the pieces.

Runs the ambient-scattering mapper on 1, 2, 4 and 8 processes (mpirun, on however many cores
there are: the figures are sizes and counts, the times are those of an oversubscribed machine),
each process rendering its piece of one wavelet (--voxels N per axis, default 128, float32),
split into blocks as VTK's vtkExtentTranslator splits it (ParaView's split), with the light
across the pieces (WholeExtent, Controller, UpdatePieceLighting before each render). Each process
measures:

- its piece's bytes and the light grid's (LightVolumeMaximumDimension, --light-grid, default
  128: the whole capped per axis, 4 bytes a point);
- its resident memory (VmRSS) after the frames, and its baseline: VmRSS once its window has
  drawn an empty frame, before the data (the interpreter, VTK and the GL context);
- the mapper's GPU bytes (GetGPUMemoryBytes; llvmpipe keeps them in host memory, so they are in
  the resident memory too);
- what UpdatePieceLighting communicated (GetLastPieceLightingCalls, ...Bytes, ...Seconds) for
  a change (the first render's new data, then an opacity change) and for a frame (a camera move),
  each after a barrier (the call's own time, not the wait for a slower process's frame).

Printed: one `ranks` line per process count (the largest over its processes) and a Markdown
table of them (Documentation/ParaView.md).

usage: ./avs python Utilities/avs-bench-ranks.py [--voxels N] [--light-grid N] [--size S]
           [--ranks 1,2,4,8]
"""
import json
import os
import shutil
import subprocess
import sys

WORKER = "--worker"


def option(name, default):
    if name in sys.argv:
        return sys.argv[sys.argv.index(name) + 1]
    return default


def resident_mib(field="VmRSS"):
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return 0.0


def worker():
    from mpi4py import MPI  # noqa: F401 (starts MPI)
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
    from vtkmodules.vtkCommonExecutionModel import vtkExtentTranslator
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    from vtkmodules.vtkParallelMPI import vtkMPIController
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                             vtkRenderer, vtkVolume, vtkVolumeProperty)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    import ambientscattering

    controller = vtkMPIController()
    controller.Initialize()
    vtkMultiProcessController.SetGlobalController(controller)
    rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    voxels = int(option("--voxels", "128"))
    size = int(option("--size", "128"))
    light_grid = int(option("--light-grid", "128"))

    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    window.Render()
    baseline = resident_mib()

    half = voxels // 2
    whole = [-half, voxels - 1 - half] * 3
    extent = [0] * 6
    vtkExtentTranslator().PieceToExtentThreadSafe(rank, ranks, 0, whole, extent,
                                                  vtkExtentTranslator.BLOCK_MODE, 0)
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(*whole)
    source.UpdateExtent(extent)
    piece = vtkImageData()
    piece.ShallowCopy(source.GetOutput())
    piece_bytes = piece.GetPointData().GetScalars().GetNumberOfValues() * 4

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
    mapper.SetInputData(piece)
    mapper.SetLightVolumeMaximumDimension(light_grid)
    mapper.SetWholeExtent(*whole)
    mapper.SetController(controller)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    sun = vtkLight()
    sun.SetPositional(False)
    sun.SetPosition(0.2, 0.1, 1.0)
    sun.SetFocalPoint(0, 0, 0)
    renderer.AddLight(sun)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(4 * voxels, -voxels, voxels / 4)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera(whole)

    def update():
        # (After a barrier: the time is the call's own, not the wait for a slower frame.)
        controller.Barrier()
        mapper.UpdatePieceLighting(volume)
        return dict(calls=mapper.GetLastPieceLightingCalls(),
                    bytes=mapper.GetLastPieceLightingBytes(),
                    seconds=mapper.GetLastPieceLightingSeconds())

    changes = [update()]  # new data
    window.Render()
    opacity.AddPoint(200, 0.3)  # an opacity change
    changes.append(update())
    window.Render()
    frames = []
    for _ in range(3):  # camera moves
        camera.Azimuth(3.0)
        frames.append(update())
        window.Render()
    row = dict(rank=rank, ranks=ranks, piece_bytes=piece_bytes,
               light_grid_bytes=4 * min(voxels, light_grid) ** 3,
               baseline_mib=baseline, rss_mib=resident_mib(), hwm_mib=resident_mib("VmHWM"),
               gpu_bytes=mapper.GetGPUMemoryBytes(), change=changes[-1],
               first_change=changes[0], frame=frames[-1],
               frames_drawn=mapper.GetNumberOfRenderedFrames())
    print("row " + json.dumps(row), flush=True)
    controller.Finalize()


def main():
    counts = [int(n) for n in option("--ranks", "1,2,4,8").split(",")]
    mpirun = shutil.which("mpirun") or shutil.which("mpiexec")
    forwarded = [a for a in sys.argv[1:] if a != WORKER]
    lines = []
    mib = 1024.0 * 1024.0
    print("| ranks | piece MiB | light grid MiB | resident MiB (baseline) | resident − baseline − "
          "piece − light grid MiB | GPU MiB | change: calls, bytes sent, s | frame: calls, bytes, "
          "s |")
    print("|---|---|---|---|---|---|---|---|")
    for count in counts:
        command = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(count),
                   sys.executable, os.path.abspath(__file__), WORKER] + forwarded
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True, timeout=1800)
        rows = [json.loads(line[4:]) for line in result.stdout.splitlines()
                if line.startswith("row ")]
        if result.returncode != 0 or len(rows) != count:
            sys.stdout.write(result.stdout)
            raise SystemExit("%d processes failed (exit %d)" % (count, result.returncode))

        def most(key, sub=None):
            return max((r[key][sub] if sub else r[key]) for r in rows)

        rest = max(r["rss_mib"] - r["baseline_mib"] - (r["piece_bytes"] + r["light_grid_bytes"])
                   / mib for r in rows)
        line = ("ranks %d piece_mib %.1f light_grid_mib %.1f rss_mib %.0f baseline_mib %.0f "
                "rest_mib %.0f gpu_mib %.1f change_calls %d change_bytes %.0f change_s %.3f "
                "first_change_s %.3f frame_calls %d frame_bytes %.0f frame_s %.4f"
                % (count, most("piece_bytes") / mib, most("light_grid_bytes") / mib,
                   most("rss_mib"), most("baseline_mib"), rest, most("gpu_bytes") / mib,
                   most("change", "calls"), most("change", "bytes"), most("change", "seconds"),
                   most("first_change", "seconds"), most("frame", "calls"),
                   most("frame", "bytes"), most("frame", "seconds")))
        lines.append(line)
        print("| %d | %.1f | %.1f | %.0f (%.0f) | %.0f | %.1f | %d, %.0f, %.3f | %d, %.0f, %.4f |"
              % (count, most("piece_bytes") / mib, most("light_grid_bytes") / mib,
                 most("rss_mib"), most("baseline_mib"), rest, most("gpu_bytes") / mib,
                 most("change", "calls"), most("change", "bytes"), most("change", "seconds"),
                 most("frame", "calls"), most("frame", "bytes"), most("frame", "seconds")),
              flush=True)
    for line in lines:
        print(line)


if __name__ == "__main__":
    if WORKER in sys.argv:
        worker()
    else:
        main()
