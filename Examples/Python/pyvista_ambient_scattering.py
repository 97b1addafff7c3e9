"""Ambient scattering from PyVista: PyVista's add_volume, with the mapper replaced by
vtkAmbientScatteringVolumeMapper (ambientscattering.pyvista). Usage: pyvista_ambient_scattering.py
OUTPUT.png (Debian 13 and later ship python3-pyvista)."""
import sys

import pyvista as pv

from ambientscattering import pyvista as avs_pv

output = sys.argv[1] if len(sys.argv) > 1 else "pyvista_ambient_scattering.png"

grid = pv.Wavelet(extent=(-32, 31, -32, 31, -32, 31))  # a structured field on a 64^3 grid
plotter = pv.Plotter(off_screen=True, window_size=(256, 256))
actor = avs_pv.add_volume(plotter, grid, scalars="RTData", cmap="magma", opacity="sigmoid",
                          albedo=0.8, anisotropy=0.3, show_scalar_bar=False)
plotter.camera_position = "iso"
plotter.screenshot(output)
mapper = actor.GetMapper()
print(output, "rendered by", mapper.GetClassName(), "in", mapper.GetNumberOfRenderedFrames(),
      "frame(s)")
plotter.close()
