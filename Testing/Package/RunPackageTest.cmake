# Driver of the package-outside-project test (see CMakeLists.txt). Arguments:
# BUILD_DIR (this build), WORK_DIR (scratch, emptied first), SOURCE_DIR (this folder),
# DOC (the guide's C++ page, whose section "Build against the installed package" is
# checked and run).

# Runs one command; fails the test with its output unless it succeeds.
function (run working_directory)
  execute_process(COMMAND ${ARGN}
    WORKING_DIRECTORY "${working_directory}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}\n${out}\n${err}")
  endif ()
  set(run_output "${out}" PARENT_SCOPE)
endfunction ()

# The fenced blocks of the guide's "## Build against the installed package" section, by
# language (a fence may carry more words after the language, e.g. "```sh runnable").
set(heading "## Build against the installed package")
file(READ "${DOC}" doc)
string(FIND "${doc}" "\n${heading}\n" begin)
if (begin LESS 0)
  message(FATAL_ERROR "${DOC}: no '${heading}' section")
endif ()
math(EXPR begin "${begin} + 1")
string(SUBSTRING "${doc}" ${begin} -1 section)
string(FIND "${section}" "\n## " end) # the next section
if (end GREATER 0)
  string(SUBSTRING "${section}" 0 ${end} section)
endif ()
foreach (language IN ITEMS cmake cpp sh)
  string(REGEX MATCH "```${language}[^\n]*\n([^`]*)```" block "${section}")
  if (NOT block)
    message(FATAL_ERROR "${DOC}, ${heading}: no ${language} block")
  endif ()
  set(doc_${language} "${CMAKE_MATCH_1}")
endforeach ()
file(READ "${SOURCE_DIR}/Project/CMakeLists.txt" project_cmake)
file(READ "${SOURCE_DIR}/Project/main.cxx" project_cpp)
foreach (language IN ITEMS cmake cpp)
  if (NOT doc_${language} STREQUAL project_${language})
    message(FATAL_ERROR "${DOC}, ${heading}: the ${language} block differs from Testing/Package/Project:\n"
      "--- ${DOC}\n${doc_${language}}--- Project\n${project_${language}}")
  endif ()
endforeach ()

# The guide's commands, line by line, in a folder holding my-project (the example)
# and build (this build tree).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
file(COPY "${SOURCE_DIR}/Project/" DESTINATION "${WORK_DIR}/my-project")
file(CREATE_LINK "${BUILD_DIR}" "${WORK_DIR}/build" SYMBOLIC)
string(REPLACE "\n" ";" commands "${doc_sh}")
foreach (command IN LISTS commands)
  if (command STREQUAL "")
    continue ()
  endif ()
  message(STATUS "$ ${command}")
  run("${WORK_DIR}" sh -c "${command}")
endforeach ()
message(STATUS "${run_output}")
if (NOT run_output MATCHES "^1000 medial balls, radius")
  message(FATAL_ERROR "unexpected output of the example: ${run_output}")
endif ()

# Every installed header compiles on its own, from the prefix only.
file(GLOB headers RELATIVE "${WORK_DIR}/medialaxis-install/include/medialaxis"
  "${WORK_DIR}/medialaxis-install/include/medialaxis/*.h")
set(sources)
foreach (header IN LISTS headers)
  string(REPLACE ".h" ".cxx" source "${header}")
  file(WRITE "${WORK_DIR}/headers/${source}" "#include \"${header}\"\n")
  list(APPEND sources "${source}")
endforeach ()
list(LENGTH headers count)
string(REPLACE ";" " " sources "${sources}")
file(WRITE "${WORK_DIR}/headers/CMakeLists.txt"
  "cmake_minimum_required(VERSION 3.16)\nproject(medial-headers LANGUAGES CXX)\n"
  "find_package(medialaxis REQUIRED)\nadd_library(headers OBJECT ${sources})\n"
  "target_link_libraries(headers PRIVATE \${medialaxis_MODULES})\n")
run("${WORK_DIR}" "${CMAKE_COMMAND}" -S headers -B headers/build
  "-DCMAKE_PREFIX_PATH=${WORK_DIR}/medialaxis-install")
run("${WORK_DIR}" "${CMAKE_COMMAND}" --build headers/build)
message(STATUS "${count} installed headers compile on their own")
message("package test: ok")
