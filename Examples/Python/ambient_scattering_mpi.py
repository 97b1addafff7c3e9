"""Ambient volume scattering under MPI with plain VTK (no ParaView).

Every process renders its own piece of an image, lit as a part of the whole: the mapper's
WholeExtent says where the piece lies, its Controller (a vtkMPIController) joins the processes,
and UpdatePieceLighting, called on every process before each render, sums the pieces' shares of
the light (so light and shadows cross the pieces' boundaries). Process 0 then composites the
pictures, back to front, into a PNG (sort-last compositing: what IceT does in ParaView).

    ./avs python --np 2 Examples/Python/ambient_scattering_mpi.py [OUTPUT.png] [--per-piece]

(`./avs python --np N` runs `mpirun -np N` with the built package on PYTHONPATH.) With
--per-piece every process lights its piece alone (no WholeExtent, no Controller): the shadows
then stop at the pieces' boundaries.
"""
import sys

import numpy as np
from mpi4py import MPI  # noqa: F401 (starts MPI; Debian's python3-mpi4py)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkParallelMPI import vtkMPIController
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderWindow,
                                         vtkRenderer, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

import ambientscattering

args = [a for a in sys.argv[1:] if not a.startswith("--")]
output = args[0] if args else "ambient_scattering_mpi.png"
per_piece = "--per-piece" in sys.argv

controller = vtkMPIController()
controller.Initialize()  # (MPI started by mpi4py)
vtkMultiProcessController.SetGlobalController(controller)
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()

# This process's piece: a slab of the whole along z (neighbours share their faces' points).
WHOLE = (-30, 30, -30, 30, -30, 30)
SPACING = 1.0
z0, z1 = WHOLE[4], WHOLE[5]
low = z0 + (z1 - z0) * rank // ranks
high = z0 + (z1 - z0) * (rank + 1) // ranks
source = vtkRTAnalyticSource()
source.SetWholeExtent(*WHOLE)
source.UpdateExtent(WHOLE[0:4] + (low, high))
piece = vtkImageData()
piece.ShallowCopy(source.GetOutput())

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
mapper.SetAmbientRadius(3.0)  # world units; the same on every process
mapper.SetUseJittering(False)  # the same samples on every process
if not per_piece:
    mapper.SetWholeExtent(*WHOLE)  # where the piece lies
    mapper.SetController(controller)  # who holds the other pieces

volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

renderer = vtkRenderer()
renderer.AddVolume(volume)
renderer.SetBackground(0, 0, 0)
renderer.SetBackgroundAlpha(0.0)  # the pictures are composited: transparent where empty
sun = vtkLight()  # from above: the upper slab shades the lower one
sun.SetPositional(False)
sun.SetPosition(0.2, 0.1, 1.0)
sun.SetFocalPoint(0, 0, 0)
renderer.AddLight(sun)
# The same camera everywhere: placed on the whole's bounds, not the piece's.
camera = renderer.GetActiveCamera()
camera.SetPosition(160, -30, 10)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera([SPACING * e for e in WHOLE])

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetAlphaBitPlanes(True)
window.SetMultiSamples(0)
window.SetSize(200, 200)
window.AddRenderer(renderer)

# Every process, before every render: the collective update of the shared light (it
# communicates only when a piece, the opacity or the radius changed).
mapper.UpdatePieceLighting(volume)
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.SetInputBufferTypeToRGBA()
grab.ReadFrontBufferOff()
grab.Update()
rgba = grab.GetOutput().GetPointData().GetScalars()  # premultiplied colour and alpha

# Sort-last compositing on process 0: the pieces from back to front (slabs along z: by their
# distance from the camera along z), each over the ones behind it.
gathered = vtkUnsignedCharArray()
controller.Gather(rgba, gathered, 0)
if rank == 0:
    pixels = vtk_to_numpy(gathered).reshape(ranks, -1, 4).astype(np.float64) / 255.0
    centres = [(z0 + (z1 - z0) * (r + 0.5) / ranks) * SPACING for r in range(ranks)]
    order = sorted(range(ranks), key=lambda r: -abs(camera.GetPosition()[2] - centres[r]))
    picture = np.zeros(pixels.shape[1:])
    for r in order:
        picture = pixels[r] + (1.0 - pixels[r][:, 3:4]) * picture
    image = vtkImageData()
    image.SetDimensions(200, 200, 1)
    colours = np.clip(np.rint(picture[:, :3] * 255.0), 0, 255).astype(np.uint8)
    image.GetPointData().SetScalars(numpy_to_vtk(colours, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(output)
    writer.SetInputData(image)
    writer.Write()
    print("wrote %s: %d process(es)%s" % (output, ranks, ", each piece lit alone"
                                          if per_piece else ", light across the pieces"))
controller.Finalize()
