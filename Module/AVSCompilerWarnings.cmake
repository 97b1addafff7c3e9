# Warning flags for every target of the project: the build is warning-free with -Wall -Wextra.
add_library(avs_warnings INTERFACE)
if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(avs_warnings INTERFACE -Wall -Wextra)
  if (AVS_WARNINGS_AS_ERRORS)
    target_compile_options(avs_warnings INTERFACE -Werror)
  endif ()
endif ()
option(AVS_WARNINGS_AS_ERRORS "Turn compiler warnings into errors" OFF)
