"""The Python package: importable by the system interpreter, classes wrapped, table loads."""
import math
import sys

import ambientscattering


def main():
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    for name in ("vtkAmbientScatteringTable", "vtkVolumeReferenceRenderer",
                 "vtkEmissionAbsorptionVolumeMapper", "vtkAmbientOcclusionVolumeMapper",
                 "vtkAmbientScatteringVolumeMapper"):
        check(hasattr(ambientscattering, name), "missing class " + name)

    table = ambientscattering.vtkAmbientScatteringTable()
    check(table.GetDefaultFileName() != "", "no default table")
    check(table.Load(), "the shipped table does not load")
    check(table.IsLoaded(), "not loaded")
    check(abs(table.GetForwardTransport(2.0, 0.3, 0.0) - math.exp(-4.0)) < 1e-6,
          "F(tau, g, 0) != exp(-2 tau)")
    check(table.GetInScattering(0.2, 1.0, 0.5, 0.9) > 0.0, "A should be positive")
    check("Generator" in str(table), "PrintSelf incomplete")

    # A missing file is an error (reported, not raised) and keeps the loaded table.
    errors = []
    table.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    table.SetFileName("/nonexistent/table.avst")
    check(not table.Load(), "loading a missing file succeeded")
    check(len(errors) == 1, "no error event for a missing file")
    check(table.IsLoaded(), "the loaded table was dropped")

    # The scattering model (paper / extended), by its Python-visible names.
    for cls in (ambientscattering.vtkAmbientScatteringVolumeMapper,
                ambientscattering.vtkVolumeReferenceRenderer):
        m = cls()
        check(m.GetScatteringModel() == cls.ExtendedModel == 1, "the extended model is not the default")
        m.SetScatteringModelToPaper()
        check(m.GetScatteringModel() == cls.PaperModel == 0, "no paper's model")
        m.SetScatteringModelToExtended()
        check(m.GetScatteringModel() == cls.ExtendedModel == 1, "no extended model")
        check(m.GetScatteringModelAsString() == "Extended", "model name")
        check("ScatteringModel: Extended" in str(m), "PrintSelf lacks the model")
        m.SetScatteringModel(7)
        check(m.GetScatteringModel() == cls.ExtendedModel, "the model is not clamped")
        check(m.GetDiffusionVolumeMaximumDimension() == 64, "the diffusion grid's default")
        m.SetDiffusionVolumeMaximumDimension(1)
        check(m.GetDiffusionVolumeMaximumDimension() == 2, "the diffusion grid is not clamped")
        check("DiffusionVolumeMaximumDimension: 2" in str(m), "PrintSelf lacks the diffusion grid")

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
