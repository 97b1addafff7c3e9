# Python wrapping: every module of the project goes into one package, `ambientscattering`,
# importable by the system interpreter that VTK was built for (Debian: /usr/bin/python3).
#
#   avs_wrap_python(MODULES <module>... PACKAGE <name>)
#
# The package lives in <build>/<AVS_PYTHON_DESTINATION>/<name> and is installed to the same
# folder under the prefix; `./avs python` and the tests put that folder on PYTHONPATH.
function (avs_wrap_python)
  cmake_parse_arguments(PARSE_ARGV 0 _avs "" "PACKAGE" "MODULES")
  set(_destination "${AVS_PYTHON_DESTINATION}")
  vtk_module_wrap_python(
    MODULES            ${_avs_MODULES}
    TARGET             AVS::Python
    WRAPPED_MODULES    _wrapped
    PYTHON_PACKAGE     "${_avs_PACKAGE}"
    MODULE_DESTINATION "${_destination}"
    LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    CMAKE_DESTINATION  "${CMAKE_INSTALL_LIBDIR}/cmake/ambientscattering"
    INSTALL_HEADERS    OFF
    BUILD_STATIC       OFF)

  # The package's __init__.py imports the VTK modules ours depend on, then each wrapped module.
  set(_imports "")
  foreach (_module IN LISTS _wrapped)
    get_property(_library TARGET "${_module}" PROPERTY OUTPUT_NAME)
    if (NOT _library)
      string(REPLACE "::" ";" _parts "${_module}")
      list(GET _parts 1 _library)
      set(_library "vtk${_library}")
    endif ()
    string(APPEND _imports "from .${_library} import *  # noqa: F401,F403\n")
  endforeach ()
  set(AVS_PYTHON_IMPORTS "${_imports}")
  configure_file("${CMAKE_CURRENT_FUNCTION_LIST_DIR}/ambientscattering__init__.py.in"
    "${CMAKE_BINARY_DIR}/${_destination}/${_avs_PACKAGE}/__init__.py" @ONLY)
  # ambientscattering.pyvista: the helper for PyVista users (imported on demand).
  configure_file("${CMAKE_CURRENT_FUNCTION_LIST_DIR}/ambientscattering_pyvista.py"
    "${CMAKE_BINARY_DIR}/${_destination}/${_avs_PACKAGE}/pyvista.py" COPYONLY)
  install(FILES "${CMAKE_BINARY_DIR}/${_destination}/${_avs_PACKAGE}/__init__.py"
    "${CMAKE_BINARY_DIR}/${_destination}/${_avs_PACKAGE}/pyvista.py"
    DESTINATION "${_destination}/${_avs_PACKAGE}")
endfunction ()
