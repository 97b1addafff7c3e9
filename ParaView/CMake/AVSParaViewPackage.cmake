# Finds Debian's ParaView 5.11 (paraview-dev) beside the system VTK 9.1 (libvtk9-dev).
#
# ParaView's CMake package describes the Python modules of python3-paraview, and checks that
# they exist; but python3-paraview cannot be installed beside python3-vtk9, which the main build
# needs (both own /usr/lib/python3/dist-packages/vtkmodules). So the package is unpacked into
# the build folder (apt-get download, dpkg -x: AVS_PARAVIEW_PYTHON_ROOT, also the PYTHONPATH of
# the pvbatch tests), and a private copy of ParaView's CMake package is written whose Python
# targets point there, all others at the installed ParaView. Nothing outside the build changes.

set(AVS_PARAVIEW_SYSTEM_CMAKE_DIR "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11"
  CACHE PATH "ParaView's installed CMake package (paraview-dev)")
set(AVS_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview" CACHE PATH
  "Where python3-paraview is unpacked (its usr/lib/python3/dist-packages is the pvbatch PYTHONPATH)")
if (NOT EXISTS "${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}/paraview-config.cmake")
  message(FATAL_ERROR "ParaView 5.11 is not installed (no ${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}): "
    "apt-get install --no-install-recommends paraview paraview-dev, or run ./avs paraview")
endif ()

# python3-paraview, the version of the installed paraview, unpacked once.
set(AVS_PARAVIEW_PYTHONPATH "${AVS_PARAVIEW_PYTHON_ROOT}/usr/lib/python3/dist-packages")
if (NOT EXISTS "${AVS_PARAVIEW_PYTHONPATH}/paraview/simple.py")
  execute_process(COMMAND dpkg-query -W -f=\${Version} paraview
    OUTPUT_VARIABLE _avs_paraview_version RESULT_VARIABLE _avs_rc)
  if (NOT _avs_rc EQUAL 0 OR NOT _avs_paraview_version)
    message(FATAL_ERROR "cannot tell the version of the installed paraview package")
  endif ()
  set(_avs_download "${CMAKE_BINARY_DIR}/python3-paraview-deb")
  file(REMOVE_RECURSE "${_avs_download}")
  file(MAKE_DIRECTORY "${_avs_download}")
  message(STATUS "Unpacking python3-paraview ${_avs_paraview_version} into ${AVS_PARAVIEW_PYTHON_ROOT}")
  execute_process(COMMAND apt-get download "python3-paraview=${_avs_paraview_version}"
    WORKING_DIRECTORY "${_avs_download}" RESULT_VARIABLE _avs_rc OUTPUT_QUIET ERROR_QUIET)
  file(GLOB _avs_deb "${_avs_download}/python3-paraview_*.deb")
  if (NOT _avs_rc EQUAL 0 OR NOT _avs_deb)
    message(FATAL_ERROR "apt-get download python3-paraview=${_avs_paraview_version} failed "
      "(is apt-get update done? ./avs paraview does it)")
  endif ()
  execute_process(COMMAND dpkg -x "${_avs_deb}" "${AVS_PARAVIEW_PYTHON_ROOT}" RESULT_VARIABLE _avs_rc)
  if (NOT _avs_rc EQUAL 0 OR NOT EXISTS "${AVS_PARAVIEW_PYTHONPATH}/paraview/simple.py")
    message(FATAL_ERROR "dpkg -x ${_avs_deb} failed")
  endif ()
  file(REMOVE_RECURSE "${_avs_download}")
endif ()

# The private copy of the CMake package: where the installed files compute their prefix from
# their own location, they are told the installed location instead.
set(_avs_copy "${CMAKE_BINARY_DIR}/paraview-cmake")
file(GLOB_RECURSE _avs_files RELATIVE "${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}"
  "${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}/*")
foreach (_avs_file IN LISTS _avs_files)
  set(_avs_from "${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}/${_avs_file}")
  set(_avs_to "${_avs_copy}/${_avs_file}")
  if (NOT _avs_file MATCHES "\\.cmake$")
    configure_file("${_avs_from}" "${_avs_to}" COPYONLY)
    continue ()
  endif ()
  file(READ "${_avs_from}" _avs_text)
  get_filename_component(_avs_origin_dir "${_avs_from}" DIRECTORY)
  string(REPLACE "get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)"
    "get_filename_component(_IMPORT_PREFIX \"${_avs_from}\" PATH)" _avs_text "${_avs_text}")
  # Installed files that python3-paraview ships (Python modules, pvpython, the wrapping
  # hierarchies) are taken from its unpacked copy.
  string(REGEX MATCHALL "\\\$\\{(_IMPORT_PREFIX|_vtk_module_import_prefix)\\}/[^\" ;]+"
    _avs_paths "${_avs_text}")
  if (_avs_paths)
    list(REMOVE_DUPLICATES _avs_paths)
  endif ()
  foreach (_avs_path IN LISTS _avs_paths)
    string(REGEX REPLACE "^[^}]*}/" "" _avs_rel "${_avs_path}")
    if (NOT EXISTS "/usr/${_avs_rel}" AND EXISTS "${AVS_PARAVIEW_PYTHON_ROOT}/usr/${_avs_rel}")
      string(REPLACE "${_avs_path}" "${AVS_PARAVIEW_PYTHON_ROOT}/usr/${_avs_rel}" _avs_text
        "${_avs_text}")
    endif ()
  endforeach ()
  # Packages made by configure_package_config_file (VTK-m's) climb from their own folder.
  string(REPLACE "get_filename_component(PACKAGE_PREFIX_DIR \"\${CMAKE_CURRENT_LIST_DIR}/"
    "get_filename_component(PACKAGE_PREFIX_DIR \"${_avs_origin_dir}/" _avs_text "${_avs_text}")
  string(REPLACE "set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")"
    "set(_vtk_module_import_prefix \"${_avs_origin_dir}\")" _avs_text "${_avs_text}")
  file(WRITE "${_avs_to}.tmp" "${_avs_text}")
  configure_file("${_avs_to}.tmp" "${_avs_to}" COPYONLY)
  file(REMOVE "${_avs_to}.tmp")
endforeach ()

# Only the modules the plugin needs (all of them would need Qt5 development files too).
find_package(ParaView 5.11 REQUIRED COMPONENTS RemotingViews RemotingServerManager
  PATHS "${_avs_copy}" NO_DEFAULT_PATH)
