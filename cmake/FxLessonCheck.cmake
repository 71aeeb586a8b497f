# fx_lesson_check(<test> SCRIPT <script> LESSONS <target>... [ARGS <arg>...] [OUT <folder>]
#                 [LABEL <label>] [TIMEOUT <seconds>])
#
# A check that runs a script against one or more lesson executables. The script gets the lessons'
# executables in the order given, then ARGS, then (with OUT) a scratch folder in the build tree. The
# test exists only where every lesson it needs is built (a build may leave a lesson out), so the
# `if(TARGET ...)` guard is written once, here.
function(fx_lesson_check name)
  cmake_parse_arguments(PARSE_ARGV 1 check "" "SCRIPT;OUT;LABEL;TIMEOUT" "LESSONS;ARGS")
  if(NOT check_SCRIPT OR NOT check_LESSONS)
    message(FATAL_ERROR "fx_lesson_check(${name}): SCRIPT and LESSONS are required")
  endif()
  set(executables "")
  foreach(lesson IN LISTS check_LESSONS)
    if(NOT TARGET ${lesson})
      return()
    endif()
    list(APPEND executables "$<TARGET_FILE:${lesson}>")
  endforeach()
  set(out "")
  if(check_OUT)
    set(out "${CMAKE_CURRENT_BINARY_DIR}/${check_OUT}")
  endif()
  if(NOT check_LABEL)
    set(check_LABEL smoke)
  endif()
  if(NOT check_TIMEOUT)
    set(check_TIMEOUT 300)
  endif()
  add_test(NAME ${name} COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/${check_SCRIPT}" ${executables} ${check_ARGS} ${out})
  set_tests_properties(${name} PROPERTIES LABELS ${check_LABEL} TIMEOUT ${check_TIMEOUT})
endfunction()
