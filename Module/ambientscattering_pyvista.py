"""Ambient scattering for PyVista users.

    import pyvista as pv
    from ambientscattering import pyvista as avs_pv

    plotter = pv.Plotter()
    actor = avs_pv.add_volume(plotter, grid, cmap="bone", opacity="sigmoid")
    plotter.show()

add_volume takes what pyvista.Plotter.add_volume takes (scalars, cmap, opacity, clim, ...) and
returns the same actor, whose mapper is then vtkAmbientScatteringVolumeMapper: PyVista builds the
transfer functions and the volume property as it always does, and the picture is lit by the
plotter's lights (its light kit by default) with ambient scattering. The mapper's parameters can
be given as keywords (albedo, anisotropy, ambient_radius, exposure, tone_mapping, auto_exposure,
light_scale, scattering_model) or set on actor.GetMapper() afterwards.
"""
import ambientscattering as _avs

# The mapper's settings this helper takes as keywords, and their setters.
_SETTINGS = {
    "albedo": "SetAlbedo",
    "anisotropy": "SetAnisotropy",
    "ambient_radius": "SetAmbientRadius",
    "emission_weight": "SetEmissionWeight",
    "light_scale": "SetLightScale",
    "exposure": "SetExposure",
    "tone_mapping": "SetToneMapping",
    "auto_exposure": "SetAutoExposure",
    "scattering_model": "SetScatteringModel",
    "sample_distance": "SetSampleDistance",
}


def scattering_mapper(actor, **settings):
    """Replaces the mapper of a volume actor that PyVista made by vtkAmbientScatteringVolumeMapper
    on the same input and array, with `settings` (see the module's description). Returns it."""
    old = actor.GetMapper()
    mapper = _avs.vtkAmbientScatteringVolumeMapper()
    if old is not None:
        if old.GetNumberOfInputConnections(0):
            mapper.SetInputConnection(old.GetInputConnection(0, 0))
        else:
            mapper.SetInputDataObject(old.GetInputDataObject(0, 0))
        mapper.SetScalarMode(old.GetScalarMode())
        mapper.SetBlendMode(old.GetBlendMode())
        if old.GetArrayAccessMode() == 1 and old.GetArrayName():
            mapper.SelectScalarArray(old.GetArrayName())
        elif old.GetArrayId() >= 0:
            mapper.SelectScalarArray(old.GetArrayId())
    for key, value in settings.items():
        if key not in _SETTINGS:
            raise TypeError("unknown ambient-scattering setting %r (one of %s)"
                            % (key, ", ".join(sorted(_SETTINGS))))
        if key == "tone_mapping" and isinstance(value, str):
            value = {"clamp": 0, "shoulder": 1}[value.lower()]
        if key == "scattering_model" and isinstance(value, str):
            value = {"paper": 0, "extended": 1}[value.lower()]
        getattr(mapper, _SETTINGS[key])(value)
    actor.SetMapper(mapper)
    return mapper


def add_volume(plotter, volume, **kwargs):
    """pyvista.Plotter.add_volume, rendered with ambient scattering. The keywords of
    scattering_mapper go to the mapper, all others to PyVista."""
    settings = {k: kwargs.pop(k) for k in list(kwargs) if k in _SETTINGS}
    actor = plotter.add_volume(volume, **kwargs)
    scattering_mapper(actor, **settings)
    return actor
