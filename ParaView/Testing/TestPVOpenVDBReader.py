"""pvbatch test of the plugin's OpenVDB reader (AVSOpenVDBImageReader).

Opens a .vdb file through the reader the plugin registers: ParaView's reader factory offers it
for .vdb files (beside ParaView's own), it reads the grid into image data with the file's
transform (the test cloud: 64^3 voxels of a fog volume named density, rotated 20 degrees about
y), and the "Ambient Scattering" representation renders it lit. A missing file is an error in
the reader's output, not a crash.

usage: pvbatch --force-offscreen-rendering TestPVOpenVDBReader.py PLUGIN FILE.vdb OUTPUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import avs_pvtesting as t  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview import simple as pv  # noqa: E402


def main(plugin, path, out):
    os.makedirs(out, exist_ok=True)
    checks = t.Checks()
    pv.LoadPlugin(plugin, remote=False, ns=globals())

    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    readers = factory.GetPossibleReaders(path, servermanager.ActiveConnection.Session)
    # (group, name, description) triplets
    names = [readers.GetString(i) for i in range(1, readers.GetNumberOfStrings(), 3)]
    checks.check("AVSOpenVDBImageReader" in names,
                 "the reader factory offers AVSOpenVDBImageReader for .vdb (%s)" % names)

    types = factory.GetSupportedFileTypes(servermanager.ActiveConnection.Session)
    checks.check("OpenVDB Files (Ambient Scattering reader) (*.vdb)" in types,
                 "the File > Open dialog lists 'OpenVDB Files (Ambient Scattering reader)'")

    # paraview.simple's function for the proxy, named after its label (LoadPlugin added it).
    make_reader = globals()["OpenVDBImageReaderAmbientScattering"]
    reader = make_reader(FileName=path)
    reader.UpdatePipeline()
    info = reader.GetDataInformation()
    checks.check(info.GetDataSetTypeAsString() == "vtkImageData",
                 "image data out (%s)" % info.GetDataSetTypeAsString())
    extent = info.GetExtent()
    dims = [extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1]
    checks.check(max(dims) <= 64 and min(dims) >= 16,
                 "the cloud's active voxel box %s, within the 64^3 it was written into" % dims)
    array = reader.PointData["density"] if "density" in reader.PointData.keys() else None
    checks.check(array is not None, "a point array named density (%s)"
                 % list(reader.PointData.keys()))
    if array is not None:
        lo, hi = array.GetRange()
        checks.check(lo == 0.0 and 0.5 < hi <= 1.0, "density range [%g, %g]" % (lo, hi))
    image = servermanager.Fetch(reader)
    direction = [image.GetDirectionMatrix().GetElement(i, j) for i in range(3) for j in range(3)]
    angle = math.degrees(math.atan2(direction[2], direction[0]))
    checks.check(abs(abs(angle) - 20.0) < 0.01,
                 "the file's rotation kept in the direction matrix (%.3f degrees about y)" % angle)

    view = pv.CreateView("RenderView")
    view.ViewSize = [128, 128]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    display = pv.Show(reader, view)
    display.SetRepresentationType("Ambient Scattering")
    pv.ColorBy(display, ("POINTS", "density"))
    lut = pv.GetColorTransferFunction("density")
    lut.RGBPoints = [0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]
    opacity = pv.GetOpacityTransferFunction("density")
    opacity.Points = [0.0, 0.0, 0.5, 0.0, 1.0, 0.8, 0.5, 0.0]
    display.ScalarOpacityUnitDistance = 0.05
    pv.Render(view)
    view.ResetCamera()
    shot = os.path.join(out, "pv_openvdb_cloud.png")
    pv.SaveScreenshot(shot, view, ImageResolution=[128, 128], TransparentBackground=0)
    rgb = t.read_png(shot)[0]
    lit = t.lit_fraction(rgb)
    checks.check(lit > 0.05, "the cloud is rendered (%.2f of the picture lit)" % lit)
    display.LightingModel = "Emission-Absorption"
    shot_ea = os.path.join(out, "pv_openvdb_cloud_ea.png")
    pv.SaveScreenshot(shot_ea, view, ImageResolution=[128, 128], TransparentBackground=0)
    checks.check(t.psnr(rgb, t.read_png(shot_ea)[0]) < 40.0,
                 "lit by the light kit: the ambient-scattering picture is not emission-absorption's")

    missing = make_reader(FileName=os.path.join(out, "no such file.vdb"))
    missing.UpdatePipeline()
    checks.check(missing.GetDataInformation().GetNumberOfPoints() == 0,
                 "a missing file gives an empty output")

    pv.Delete(display)
    pv.Delete(view)
    checks.finish()


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
