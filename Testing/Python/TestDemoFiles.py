"""./avs demo FILE as a newcomer meets it: on files nobody tuned (dense, thin, small and
elongated volumes made here, the repository's test cloud and the real volumes of the shared data
folder) every panel shows the data whole, and the ambient-scattering panel reads as well as the
emission-absorption one: its brightness 0.5-2 times the EA panel's over the data's pixels, at most
2 % of them saturated, no data pixel on the frame's edge; the progress lines are ended before
the result lines.

    TestDemoFiles.py AVS_DEMO WORK_DIR [FILE_OR_FOLDER ...]

Folders contribute the volumes the demo reads (.vti, .vtk, .slc, .nhdr, .nrrd, .vdb); a missing
folder or file is skipped with a line (the shared data folder is absent outside the project)."""
import os
import re
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

EXTENSIONS = ('.vti', '.vtk', '.slc', '.nhdr', '.nrrd', '.vdb')
SIZE = 128


def write_volume(path, dims, spacing, values):
    image = vtkImageData()
    image.SetDimensions(*dims)
    image.SetSpacing(*spacing)
    array = numpy_to_vtk(np.ascontiguousarray(values.ravel(order='F'), dtype=np.float32), deep=1)
    array.SetName('density')
    image.GetPointData().SetScalars(array)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def made_volumes(folder):
    """Volumes of the kinds a user brings: dense, thin, small, elongated."""
    rng = np.random.default_rng(7)
    files = []

    def grid(n):
        axis = (np.arange(n) - 0.5 * (n - 1)) / (0.5 * n)
        return np.meshgrid(axis, axis, axis, indexing='ij')

    x, y, z = grid(48)
    r = np.sqrt(x * x + y * y + z * z)
    dense = np.where(np.maximum(np.maximum(abs(x), abs(y)), abs(z)) < 0.7, 1000.0, 0.0)
    dense += 50.0 * rng.random(dense.shape)
    files.append(('dense block', os.path.join(folder, 'dense.vti'), (48, 48, 48), (1, 1, 1), dense))
    thin = np.exp(-4.0 * r * r) * (0.8 + 0.2 * rng.random(r.shape))
    files.append(('thin cloud', os.path.join(folder, 'thin.vti'), (48, 48, 48), (0.02, 0.02, 0.02),
                  thin))
    xs, ys, zs = grid(8)
    small = np.clip(1.0 - np.sqrt(xs * xs + ys * ys + zs * zs), 0.0, 1.0)
    files.append(('small', os.path.join(folder, 'small.vti'), (8, 8, 8), (1, 1, 1), small))
    u = np.linspace(0.0, 1.0, 160)
    v = (np.arange(20) - 9.5) / 10.0
    lu, lv, lw = np.meshgrid(u, v, v, indexing='ij')
    tube = np.exp(-3.0 * (lv * lv + lw * lw)) * (0.6 + 0.4 * np.sin(12.0 * lu) ** 2)
    files.append(('elongated', os.path.join(folder, 'elongated.vti'), (160, 20, 20), (1, 1, 1), tube))
    for _, path, dims, spacing, values in files:
        write_volume(path, dims, spacing, values)
    return [(name, path) for name, path, _, _, _ in files]


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(float)


def luminance(rgb):
    return 0.2126 * rgb[:, :, 0] + 0.7152 * rgb[:, :, 1] + 0.0722 * rgb[:, :, 2]


def main():
    demo, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    cases = made_volumes(work)
    for item in sys.argv[3:]:
        if os.path.isdir(item):
            cases += [(name, os.path.join(item, name)) for name in sorted(os.listdir(item))
                      if name.lower().endswith(EXTENSIONS)]
        elif os.path.isfile(item):
            cases.append((os.path.basename(item), item))
        else:
            print('skipped (not here): %s' % item)
    failures = []
    for name, path in cases:
        output = os.path.join(work, re.sub(r'[^A-Za-z0-9_]+', '_', name))
        run = subprocess.run([demo, '--size', str(SIZE), '--output', output, path],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=300)
        if run.returncode != 0:
            failures.append('%s: avs-demo exited with %d:\n%s' % (name, run.returncode, run.stdout))
            continue
        # Every progress line is ended before a result or an error line.
        for line in run.stdout.split('\n'):
            if '\r' in line and ('.png' in line or 'avs-demo:' in line or 'exposure' in line):
                failures.append('%s: a progress line runs into other output: %r' % (name, line))
        ea = read_png(os.path.join(output, 'ea.png'))
        ao = read_png(os.path.join(output, 'ao.png'))
        ambient = read_png(os.path.join(output, 'as.png'))
        data = luminance(ea) > 2.0
        pixels = int(data.sum())
        if pixels < 0.01 * SIZE * SIZE:
            failures.append('%s: the emission-absorption panel shows almost nothing (%d pixels)'
                            % (name, pixels))
            continue
        ratio = luminance(ambient)[data].mean() / luminance(ea)[data].mean()
        saturated = float((ambient[data] >= 255.0).any(axis=1).mean())
        edge = np.zeros(data.shape, bool)
        edge[0, :] = edge[-1, :] = edge[:, 0] = edge[:, -1] = True
        cut = [panel for panel, picture in (('EA', ea), ('AO', ao), ('AS', ambient))
               if (luminance(picture)[edge] > 2.0).any()]
        print('%-30s brightness AS/EA %.2f, AS saturated %.1f %%, %d data pixels%s'
              % (name, ratio, 100.0 * saturated, pixels, ', cut off: ' + ' '.join(cut) if cut else ''))
        if not 0.5 <= ratio <= 2.0:
            failures.append('%s: ambient scattering is %.2f times as bright as EA' % (name, ratio))
        if saturated > 0.02:
            failures.append('%s: %.1f %% of the ambient-scattering panel saturated'
                            % (name, 100.0 * saturated))
        if cut:
            failures.append('%s: the volume runs off the frame in %s' % (name, ', '.join(cut)))
    if failures:
        print('FAILED:\n  ' + '\n  '.join(failures))
        return 1
    print('passed: %d files' % len(cases))
    return 0


if __name__ == '__main__':
    sys.exit(main())
