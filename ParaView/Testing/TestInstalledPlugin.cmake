# The plugin as ParaView finds installed plugins (ctest: ParaView.InstalledPlugin): installs the
# plugin build into a fresh prefix, checks ParaView's layout there
# (lib/paraview-X.Y/plugins/AmbientScattering: the plugin, the modules it needs and the scattering
# table), and runs TestPVInstalledPlugin.py in pvbatch with PV_PLUGIN_PATH naming that folder.
#
#   cmake -DBUILD=<plugin build> -DWORK=<scratch> -DSUBDIR=<paraview-X.Y/plugins> -DLIBDIR=<lib>
#         -DPVBATCH=<pvbatch> -DSCRIPT=<TestPVInstalledPlugin.py> -DPYTHON=<interpreter>
#         -DCHECKER=<CheckPicture.py> -P TestInstalledPlugin.cmake
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE status OUTPUT_QUIET)
if (NOT status EQUAL 0)
  message(FATAL_ERROR "FAILED: cmake --install of the plugin build")
endif ()
set(folder "${WORK}/prefix/${LIBDIR}/${SUBDIR}/AmbientScattering")
foreach (file IN ITEMS AmbientScattering.so libvtkRenderingAmbientScattering.so
    scattering_table.avst)
  if (NOT EXISTS "${folder}/${file}")
    message(FATAL_ERROR "FAILED: ${folder} lacks ${file}")
  endif ()
endforeach ()
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PV_PLUGIN_PATH=${folder}" "${PVBATCH}"
  --force-offscreen-rendering "${SCRIPT}" "${WORK}/installed_plugin.png"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if (NOT status EQUAL 0)
  message(FATAL_ERROR "FAILED: pvbatch with PV_PLUGIN_PATH (exit status ${status})")
endif ()
execute_process(COMMAND "${PYTHON}" "${CHECKER}" "${WORK}/installed_plugin.png"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if (NOT status EQUAL 0)
  message(FATAL_ERROR "FAILED: the installed plugin's picture shows nothing drawn")
endif ()
