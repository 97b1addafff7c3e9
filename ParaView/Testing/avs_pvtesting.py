"""Helpers of the plugin's pvbatch tests: pictures as bytes, PSNR, the checks' bookkeeping."""
import math
import sys

from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def read_png(path):
    """The RGB bytes and size of a PNG file."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    n = scalars.GetNumberOfComponents()
    data = bytes(memoryview(scalars))
    rgb = bytes(b for i, b in enumerate(data) if i % n < 3) if n != 3 else data
    return rgb, (width, height)


def grab_window(window, path):
    """Writes what a VTK render window shows into a PNG file and returns its RGB bytes."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return read_png(path)


def psnr(a, b):
    """PSNR in dB of two RGB byte strings of the same size (inf when equal)."""
    if len(a) != len(b):
        raise ValueError("pictures of different sizes: %d and %d bytes" % (len(a), len(b)))
    squared = sum((x - y) * (x - y) for x, y in zip(a, b))
    if squared == 0:
        return float("inf")
    return 10.0 * math.log10(255.0 * 255.0 * len(a) / squared)


def largest_difference(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def lit_fraction(rgb, threshold=8):
    """Share of the pixels brighter than `threshold` in some channel (on a black background)."""
    pixels = len(rgb) // 3
    lit = sum(1 for i in range(pixels) if max(rgb[3 * i:3 * i + 3]) > threshold)
    return lit / pixels


class Checks:
    """Collects failed checks; finish() reports them and sets the exit status."""

    def __init__(self):
        self.failures = []

    def check(self, condition, what):
        print(("ok:     " if condition else "FAILED: ") + what)
        if not condition:
            self.failures.append(what)

    def finish(self):
        if self.failures:
            print("%d check(s) failed:\n  %s" % (len(self.failures), "\n  ".join(self.failures)))
            sys.exit(1)
        print("all checks passed")
        sys.exit(0)
