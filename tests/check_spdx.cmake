# SPDX-License-Identifier: MIT
# Fails when a source file lacks its licence line (LICENSE: MIT), so a file added later is not
# left without one. Run as a test: cmake -DSOURCE_DIR=... -P check_spdx.cmake
set(missing "")
foreach(folder sandcore scene bench view gui app tools shaders tests examples scripts cmake)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${folder}/*.hpp" "${SOURCE_DIR}/${folder}/*.cpp" "${SOURCE_DIR}/${folder}/*.vert"
       "${SOURCE_DIR}/${folder}/*.frag" "${SOURCE_DIR}/${folder}/*.cmake" "${SOURCE_DIR}/${folder}/CMakeLists.txt")
  foreach(file ${files})
    file(STRINGS "${file}" head LIMIT_COUNT 3)
    string(FIND "${head}" "SPDX-License-Identifier: MIT" at)
    if(at EQUAL -1)
      file(RELATIVE_PATH relative "${SOURCE_DIR}" "${file}")
      list(APPEND missing "${relative}")
    endif()
  endforeach()
endforeach()
if(missing)
  list(JOIN missing "\n  " listed)
  message(FATAL_ERROR "files without the line 'SPDX-License-Identifier: MIT' in their first three lines:\n  ${listed}")
endif()
