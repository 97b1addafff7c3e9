# The installed package, the way a user consumes it (ctest: Install.Package). Installs the build
# into a fresh prefix, moves the tree elsewhere (it must be relocatable), builds the Consumer
# project with find_package(AmbientScattering) against the moved tree and runs it, then runs
# TestInstalledPython.py with only the moved tree's Python folder on PYTHONPATH and nothing of the
# source or build folders in the environment.
#
#   cmake -DBUILD=<build dir> -DSOURCE=<source dir> -DWORK=<scratch dir> -DPYTHON=<interpreter>
#         -DPYTHON_DESTINATION=<lib/python3/dist-packages> [-DSANITIZER_LINK_FLAG=<flag>]
#         [-DPYTHON_ENVIRONMENT=<VAR=value;...>] -P TestInstall.cmake
#
# In the sanitizer build the installed libraries need the sanitizer runtimes: the consumer links
# them (SANITIZER_LINK_FLAG), with leak checking off in it (the module's own tests check leaks
# with the project's suppressions), and Python runs with the Python tests' environment
# (PYTHON_ENVIRONMENT: the runtime preloaded).
function (run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "FAILED: ${what} (exit status ${status})")
  endif ()
endfunction ()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
run("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/installed")
file(RENAME "${WORK}/installed" "${WORK}/moved")
set(prefix "${WORK}/moved")
foreach (file IN ITEMS lib/cmake/ambientscattering/AmbientScatteringConfig.cmake
    lib/cmake/ambientscattering/AmbientScatteringConfigVersion.cmake
    share/ambientscattering/scattering_table.avst "${PYTHON_DESTINATION}/ambientscattering/__init__.py")
  if (NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "FAILED: the installed tree lacks ${file}")
  endif ()
endforeach ()

# The environment of both: the display, and nothing that points into the source or build tree.
set(clean env -i "PATH=/usr/bin:/bin" "HOME=${WORK}" "DISPLAY=$ENV{DISPLAY}")
if (DEFINED ENV{XAUTHORITY})
  list(APPEND clean "XAUTHORITY=$ENV{XAUTHORITY}")
endif ()

set(consumer_options)
set(consumer_environment)
if (SANITIZER_LINK_FLAG)
  set(consumer_options "-DCMAKE_EXE_LINKER_FLAGS=${SANITIZER_LINK_FLAG}")
  set(consumer_environment "ASAN_OPTIONS=detect_leaks=0")
endif ()

run("configuring the consumer" ${clean} "${CMAKE_COMMAND}" -S "${SOURCE}/Testing/Install/Consumer"
  -B "${WORK}/consumer" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
  ${consumer_options})
run("building the consumer" ${clean} "${CMAKE_COMMAND}" --build "${WORK}/consumer")
run("the consumer's frame" ${clean} ${consumer_environment} "${WORK}/consumer/RenderOneFrame"
  "${prefix}")
run("the installed Python package" ${clean} ${PYTHON_ENVIRONMENT}
  "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}"
  "PYTHONDONTWRITEBYTECODE=1" "${PYTHON}" "${SOURCE}/Testing/Install/TestInstalledPython.py"
  "${prefix}")
message("PASSED: installed, moved, found, built against and run")
