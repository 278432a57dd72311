# SPDX-License-Identifier: MIT
# Fails when a test source does not follow the one naming scheme, <subject>_test.cpp.
# Run as a test: cmake -DSOURCE_DIR=... -P check_test_names.cmake
file(GLOB_RECURSE sources "${SOURCE_DIR}/tests/*.cpp")
set(problems "")
foreach(source ${sources})
  get_filename_component(name "${source}" NAME)
  if(NOT name MATCHES "_test\\.cpp$" AND NOT name STREQUAL "doctest_main.cpp")
    file(RELATIVE_PATH relative "${SOURCE_DIR}" "${source}")
    list(APPEND problems "${relative}")
  endif()
endforeach()
if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "test files not named <subject>_test.cpp:\n  ${text}")
endif()
message(STATUS "every test file is named <subject>_test.cpp")
