# Finds OpenVDB through the FindOpenVDB.cmake that Debian's libopenvdb-dev installs (it is not on
# CMake's module path): sets OpenVDB_FOUND and the target OpenVDB::openvdb. Used by the project
# and by the ParaView plugin (ParaView/), which build the same IO/OpenVDB module.
find_path(AVS_OPENVDB_CMAKE_DIR FindOpenVDB.cmake
  PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB" /usr/lib/cmake/OpenVDB
        /usr/local/lib/cmake/OpenVDB /usr/local/lib64/cmake/OpenVDB)
if (AVS_OPENVDB_CMAKE_DIR)
  list(APPEND CMAKE_MODULE_PATH "${AVS_OPENVDB_CMAKE_DIR}")
  find_package(OpenVDB QUIET)
endif ()
