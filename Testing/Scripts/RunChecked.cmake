# Runs a test's command and checks its exit status as well as its output: ctest's
# PASS_REGULAR_EXPRESSION alone ignores the exit status (a crash, or LeakSanitizer's failing exit
# after the pass line, would pass).
#
#   cmake -DEXPECT=zero|nonzero [-DMATCH=REGEX] [-DPICTURE=FILE.png -DPYTHON=INTERPRETER]
#         -P RunChecked.cmake COMMAND [ARGUMENTS...]
#
# EXPECT: the exit status wanted (zero: success; nonzero: a test that must fail, such as the
# soak with a leak injected); MATCH: a regular expression the output must contain; PICTURE: a PNG
# the command writes, which must show something drawn (Testing/Scripts/CheckPicture.py).
set(command)
set(collect OFF)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach (i RANGE ${last})
  if (collect)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif (CMAKE_ARGV${i} MATCHES "RunChecked\\.cmake$")
    set(collect ON)
  endif ()
endforeach ()
if (NOT command)
  message(FATAL_ERROR "RunChecked.cmake: no command")
endif ()
if (PICTURE)
  file(REMOVE "${PICTURE}") # a picture left from an earlier run proves nothing
endif ()
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
message("${output}")
set(failed "")
if (EXPECT STREQUAL "nonzero")
  if (status EQUAL 0)
    string(APPEND failed "the command succeeded; it must fail. ")
  endif ()
elseif (NOT status EQUAL 0)
  string(APPEND failed "exit status ${status}. ")
endif ()
if (MATCH AND NOT output MATCHES "${MATCH}")
  string(APPEND failed "the output lacks /${MATCH}/. ")
endif ()
if (PICTURE)
  execute_process(COMMAND "${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/CheckPicture.py" "${PICTURE}"
    RESULT_VARIABLE picture OUTPUT_VARIABLE said ERROR_VARIABLE said)
  message("${said}")
  if (NOT picture EQUAL 0)
    string(APPEND failed "the picture ${PICTURE} shows nothing drawn. ")
  endif ()
endif ()
if (failed)
  message(FATAL_ERROR "FAILED: ${failed}")
endif ()
