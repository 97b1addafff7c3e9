"""Plain VTK under MPI: the example Examples/Python/ambient_scattering_mpi.py on 1 process and on
2 (mpirun), the pieces lit as parts of the whole (the mapper's WholeExtent and Controller, a
vtkMPIController): the 2-process picture agrees with the 1-process one (PSNR >= 45 dB), and with
each piece lit alone (--per-piece) it does not (< 35 dB: the light from above crosses the
pieces' boundary, so the check can fail).

usage: python3 TestPythonMPI.py MPIRUN EXAMPLE OUTPUT_DIR
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def run(mpirun, example, out, processes, *options):
    path = os.path.join(out, "mpi_%d%s.png" % (processes, "".join(options).replace("-", "_")))
    command = [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(processes),
               sys.executable, example, path] + list(options)
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=300)
    sys.stdout.write(result.stdout)
    if result.returncode != 0 or ("%d process(es)" % processes) not in result.stdout:
        raise RuntimeError("%s failed (exit %d)" % (" ".join(command), result.returncode))
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(np.float64)


def psnr(a, b):
    mse = np.mean((a - b) ** 2)
    return float("inf") if mse == 0 else 10.0 * np.log10(255.0 ** 2 / mse)


def main(mpirun, example, out):
    os.makedirs(out, exist_ok=True)
    one = run(mpirun, example, out, 1)
    two = run(mpirun, example, out, 2)
    alone = run(mpirun, example, out, 2, "--per-piece")
    failures = 0
    lit = np.mean(one.max(axis=1) > 8)
    checks = [
        (lit > 0.1, "the volume is drawn (%.2f of the pixels lit)" % lit),
        (psnr(one, two) >= 45.0, "2 processes agree with 1: %.1f dB (largest difference %d/255)"
         % (psnr(one, two), np.abs(one - two).max())),
        (psnr(one, alone) < 35.0, "each piece lit alone differs from 1 process: %.1f dB"
         % psnr(one, alone)),
    ]
    for ok, text in checks:
        print(("ok:     " if ok else "FAILED: ") + text)
        failures += 0 if ok else 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
