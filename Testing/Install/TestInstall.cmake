# The installed package, the way a user consumes it (ctest: Install.Package). Installs the build
# into a fresh prefix, moves the tree elsewhere (it must be relocatable), builds the Consumer
# project with find_package(AmbientScattering) against the moved tree in each way users write
# it (the order of the two find_package calls, VTK's components, VTK_LIBRARIES or targets) and
# runs each, then runs
# TestInstalledPython.py with only the moved tree's Python folder on PYTHONPATH and nothing of the
# source or build folders in the environment.
#
#   cmake -DBUILD=<build dir> -DSOURCE=<source dir> -DWORK=<scratch dir> -DPYTHON=<interpreter>
#         -DPYTHON_DESTINATION=<lib/python3/dist-packages> [-DSANITIZER_LINK_FLAG=<flag>]
#         [-DCONSUMERS=short]
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

# The consumers, in the ways users write them (Testing/Install/Consumer/CMakeLists.txt): the
# package found before or after VTK, VTK's targets named or ${VTK_LIBRARIES} linked, with the
# README's components, the ones most VTK applications ask for (ImagingCore and IOImage too:
# the consumer uses a VTK source, so a VTK_LIBRARIES the package replaced fails to link), and
# with ParallelMPI.
set(readme "RenderingOpenGL2,RenderingVolumeOpenGL2,InteractionStyle")
set(common "RenderingCore,RenderingOpenGL2,RenderingVolumeOpenGL2,ImagingCore,IOImage,InteractionStyle")
set(mpi "RenderingOpenGL2,RenderingVolumeOpenGL2,InteractionStyle,ParallelMPI")
set(consumers
  "readme|avs-first|targets|${readme}"
  "common-vtk-first|vtk-first|libraries|${common}"
  "common-avs-first|avs-first|libraries|${common}"
  "mpi-vtk-first|vtk-first|targets|${mpi}"
  "mpi-avs-first|avs-first|libraries|${mpi}")
if (CONSUMERS STREQUAL "short")
  # (The sanitizer build: the orders' CMake logic is the same there; two consumers check that
  # the installed, instrumented libraries render in either order.)
  list(SUBLIST consumers 0 2 consumers)
endif ()
foreach (consumer IN LISTS consumers)
  string(REPLACE "|" ";" fields "${consumer}")
  list(POP_FRONT fields name order link components) # (commas: run() would split a list)
  set(dir "${WORK}/consumer-${name}")
  message("consumer ${name}: ${order}, ${link}, VTK components ${components}")
  run("configuring the consumer ${name}" ${clean} "${CMAKE_COMMAND}"
    -S "${SOURCE}/Testing/Install/Consumer" -B "${dir}" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DAVS_CONSUMER_ORDER=${order}"
    "-DAVS_CONSUMER_LINK=${link}" "-DAVS_CONSUMER_COMPONENTS=${components}" ${consumer_options})
  run("building the consumer ${name}" ${clean} "${CMAKE_COMMAND}" --build "${dir}")
  run("the consumer ${name}'s frame" ${clean} ${consumer_environment} "${dir}/RenderOneFrame"
    "${prefix}")
endforeach ()
run("the installed Python package" ${clean} ${PYTHON_ENVIRONMENT}
  "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}"
  "PYTHONDONTWRITEBYTECODE=1" "${PYTHON}" "${SOURCE}/Testing/Install/TestInstalledPython.py"
  "${prefix}")
message("PASSED: installed, moved, found, built against and run")
