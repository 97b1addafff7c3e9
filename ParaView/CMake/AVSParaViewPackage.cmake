# Finds Debian's ParaView (paraview-dev: 5.11 on Debian 12, 5.13 on Debian 13, 6.1 on testing)
# beside the system VTK (libvtk9-dev).
#
# ParaView's CMake package describes the Python modules of python3-paraview, and checks that
# they exist. On Debian 12 python3-paraview cannot be installed beside python3-vtk9, which the
# main build needs (both own /usr/lib/python3/dist-packages/vtkmodules): there, and wherever it is
# not installed, the package is unpacked into the build folder (apt-get download, dpkg -x:
# AVS_PARAVIEW_PYTHON_ROOT, also the PYTHONPATH of the pvbatch tests). A private copy of
# ParaView's CMake package is written whose Python targets point at the files that exist: the
# unpacked copy's, and, where the package names a module without its ABI suffix (Debian's
# ParaView 6.1: paraview/modules/X.so for X.cpython-314-x86_64-linux-gnu.so), the suffixed file.
# Nothing outside the build changes.

file(GLOB _avs_paraview_dirs "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-*")
set(_avs_newest "")
foreach (_avs_dir IN LISTS _avs_paraview_dirs)
  if (EXISTS "${_avs_dir}/paraview-config.cmake")
    string(REGEX REPLACE ".*/paraview-" "" _avs_version "${_avs_dir}")
    if (NOT _avs_newest OR _avs_version VERSION_GREATER _avs_newest_version)
      set(_avs_newest "${_avs_dir}")
      set(_avs_newest_version "${_avs_version}")
    endif ()
  endif ()
endforeach ()
set(AVS_PARAVIEW_SYSTEM_CMAKE_DIR "${_avs_newest}"
  CACHE PATH "ParaView's installed CMake package (paraview-dev)")
set(AVS_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview" CACHE PATH
  "Where python3-paraview is unpacked (its usr/lib/python3/dist-packages is the pvbatch PYTHONPATH)")
if (NOT EXISTS "${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}/paraview-config.cmake")
  message(FATAL_ERROR "ParaView is not installed (no /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/"
    "cmake/paraview-*): apt-get install --no-install-recommends paraview paraview-dev, or run "
    "./avs paraview")
endif ()

# paraview.simple is a module up to ParaView 5.13, a package from 6.0 on.
function (_avs_has_paraview_python folder result)
  if (EXISTS "${folder}/paraview/simple.py" OR EXISTS "${folder}/paraview/simple/__init__.py")
    set(${result} TRUE PARENT_SCOPE)
  else ()
    set(${result} FALSE PARENT_SCOPE)
  endif ()
endfunction ()

# python3-paraview: the installed one, else the version of the installed paraview, unpacked once.
_avs_has_paraview_python("/usr/lib/python3/dist-packages" _avs_system_python)
if (_avs_system_python)
  set(AVS_PARAVIEW_PYTHONPATH "")
  set(AVS_PARAVIEW_PYTHON_ROOT "/")
else ()
  set(AVS_PARAVIEW_PYTHONPATH "${AVS_PARAVIEW_PYTHON_ROOT}/usr/lib/python3/dist-packages")
  _avs_has_paraview_python("${AVS_PARAVIEW_PYTHONPATH}" _avs_unpacked)
endif ()
if (NOT _avs_system_python AND NOT _avs_unpacked)
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
  _avs_has_paraview_python("${AVS_PARAVIEW_PYTHONPATH}" _avs_unpacked)
  if (NOT _avs_rc EQUAL 0 OR NOT _avs_unpacked)
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
    if (EXISTS "/usr/${_avs_rel}")
      continue ()
    endif ()
    foreach (_avs_root IN ITEMS "${AVS_PARAVIEW_PYTHON_ROOT}/usr" "/usr")
      if (EXISTS "${_avs_root}/${_avs_rel}")
        string(REPLACE "${_avs_path}" "${_avs_root}/${_avs_rel}" _avs_text "${_avs_text}")
        break ()
      endif ()
      # A Python extension named without its ABI suffix: the one file that has one.
      if (_avs_rel MATCHES "\\.so$")
        string(REGEX REPLACE "\\.so$" "" _avs_stem "${_avs_rel}")
        file(GLOB _avs_suffixed "${_avs_root}/${_avs_stem}.cpython-*.so")
        list(LENGTH _avs_suffixed _avs_count)
        if (_avs_count EQUAL 1)
          string(REPLACE "${_avs_path}" "${_avs_suffixed}" _avs_text "${_avs_text}")
          break ()
        endif ()
      endif ()
    endforeach ()
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

# Only the modules the plugin needs (all of them would need Qt's development files too).
find_package(ParaView REQUIRED COMPONENTS RemotingViews RemotingServerManager
  PATHS "${_avs_copy}" NO_DEFAULT_PATH)
if (ParaView_VERSION VERSION_LESS 5.11)
  message(FATAL_ERROR "ParaView ${ParaView_VERSION} is older than 5.11, the oldest the plugin "
    "is built for")
endif ()
message(STATUS "ParaView ${ParaView_VERSION} (VTK ${VTK_VERSION}) from ${AVS_PARAVIEW_SYSTEM_CMAKE_DIR}")
